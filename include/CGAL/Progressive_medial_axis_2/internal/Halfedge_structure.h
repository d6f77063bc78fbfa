// Copyright (c) 2026 The Progressive_medial_axis_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// The half-edge structure that stores a medial axis: faces are generator
// cells, edges are medial curves, normals at reflex vertices and boundary
// edges, vertices are branch points, junctions and polygon vertices.
// Indices, not pointers; deleted elements go to free lists and are reused.

#ifndef CGAL_PROGRESSIVE_MEDIAL_AXIS_2_INTERNAL_HALFEDGE_STRUCTURE_H
#define CGAL_PROGRESSIVE_MEDIAL_AXIS_2_INTERNAL_HALFEDGE_STRUCTURE_H

#include <CGAL/assertions.h>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace PMA2 {
namespace internal {

constexpr int NO_INDEX = -1;
/// Face index of the outside of the shape (the twins of boundary half-edges).
constexpr int OUTSIDE = -1;
/// Face index marking a deleted half-edge.
constexpr int DELETED = -2;

/// A generator cell.  A segment generator goes from input point `p0` to
/// `p1` with the shape on its left; a point generator (reflex vertex) is the
/// input point `p0`.
struct Hds_face {
  int halfedge = NO_INDEX;   // one half-edge of its counter-clockwise cycle
  int p0 = NO_INDEX, p1 = NO_INDEX;
  bool is_point = false;
  bool alive = true;
};

struct Hds_halfedge {
  int next = NO_INDEX, prev = NO_INDEX;
  int face = DELETED;        // the face on its left, OUTSIDE, or DELETED
  int vertex = NO_INDEX;     // target vertex
};

template <class Point_2, class FT>
struct Hds_vertex {
  // Coordinates and radius are computed on first use (see
  // resolve_vertex()): most vertices of a progressive run are removed again
  // before anyone looks at them.
  mutable Point_2 point;
  mutable FT radius = FT(0);
  mutable bool pending = false;
  // the generators that define a pending vertex, counter-clockwise: input
  // point indices (p0, p1), with p0 == p1 for a point generator
  int triple[3][2] = {{NO_INDEX, NO_INDEX}, {NO_INDEX, NO_INDEX}, {NO_INDEX, NO_INDEX}};
  int halfedge = NO_INDEX;   // a half-edge whose target is this vertex
  int input_point = NO_INDEX; // index of the polygon vertex, if it is one
  bool alive = true;
};

template <class Point_2, class FT>
class Halfedge_structure
{
public:
  typedef Hds_face Face;
  typedef Hds_halfedge Halfedge;
  typedef Hds_vertex<Point_2, FT> Vertex;

  static int twin(int h) { return h ^ 1; }

  Halfedge& he(int h) { return halfedges_[h]; }
  const Halfedge& he(int h) const { return halfedges_[h]; }
  Vertex& vertex(int v) { return vertices_[v]; }
  const Vertex& vertex(int v) const { return vertices_[v]; }
  Face& face(int f) { return faces_[f]; }
  const Face& face(int f) const { return faces_[f]; }

  int next(int h) const { return halfedges_[h].next; }
  int prev(int h) const { return halfedges_[h].prev; }
  int target(int h) const { return halfedges_[h].vertex; }
  int source(int h) const { return halfedges_[twin(h)].vertex; }
  int face_of(int h) const { return halfedges_[h].face; }
  bool is_alive_halfedge(int h) const { return halfedges_[h].face != DELETED; }

  std::size_t halfedge_capacity() const { return halfedges_.size(); }
  std::size_t vertex_capacity() const { return vertices_.size(); }
  std::size_t face_capacity() const { return faces_.size(); }
  std::size_t number_of_vertices() const { return vertices_.size() - free_vertices_.size(); }
  std::size_t number_of_faces() const { return faces_.size() - free_faces_.size(); }
  std::size_t number_of_halfedges() const { return halfedges_.size() - 2 * free_edges_.size(); }

  void link(int h, int n)
  {
    halfedges_[h].next = n;
    halfedges_[n].prev = h;
  }

  /// A new edge; returns the even half-edge of the pair.  Faces and
  /// vertices are set by the caller.
  int new_edge(int left_face, int right_face)
  {
    int h;
    if(!free_edges_.empty()) {
      h = free_edges_.back();
      free_edges_.pop_back();
      halfedges_[h] = Halfedge();
      halfedges_[h + 1] = Halfedge();
    } else {
      h = int(halfedges_.size());
      halfedges_.resize(halfedges_.size() + 2);
    }
    halfedges_[h].face = left_face;
    halfedges_[h + 1].face = right_face;
    return h;
  }

  void delete_edge(int h)
  {
    int e = h & ~1;
    CGAL_assertion(halfedges_[e].face != DELETED);
    halfedges_[e].face = DELETED;
    halfedges_[e + 1].face = DELETED;
    free_edges_.push_back(e);
  }

  int new_vertex(const Point_2& p, const FT& r, int input_point = NO_INDEX)
  {
    int v;
    if(!free_vertices_.empty()) {
      v = free_vertices_.back();
      free_vertices_.pop_back();
    } else {
      v = int(vertices_.size());
      vertices_.emplace_back();
    }
    Vertex& x = vertices_[v];
    x.point = p;
    x.radius = r;
    x.pending = false;
    x.halfedge = NO_INDEX;
    x.input_point = input_point;
    x.alive = true;
    return v;
  }

  /// A vertex whose coordinates will be computed when first needed: the
  /// centre of the disk tangent to the generators of the faces `a, b, c`
  /// (counter-clockwise around it).
  int new_pending_vertex(int a, int b, int c)
  {
    int v = new_vertex(Point_2(), FT(0));
    Vertex& x = vertices_[v];
    x.pending = true;
    const int f[3] = {a, b, c};
    for(int i = 0; i < 3; ++i) {
      x.triple[i][0] = faces_[f[i]].p0;
      x.triple[i][1] = faces_[f[i]].p1;
    }
    return v;
  }

  void delete_vertex(int v)
  {
    CGAL_assertion(vertices_[v].alive);
    vertices_[v].alive = false;
    free_vertices_.push_back(v);
  }

  int new_face(bool is_point, int p0, int p1)
  {
    int f;
    if(!free_faces_.empty()) {
      f = free_faces_.back();
      free_faces_.pop_back();
    } else {
      f = int(faces_.size());
      faces_.emplace_back();
    }
    Face& x = faces_[f];
    x.halfedge = NO_INDEX;
    x.is_point = is_point;
    x.p0 = p0;
    x.p1 = is_point ? p0 : p1;
    x.alive = true;
    return f;
  }

  void delete_face(int f)
  {
    CGAL_assertion(faces_[f].alive);
    faces_[f].alive = false;
    free_faces_.push_back(f);
  }

  /// Number of edges at vertex `v` (walks around it).
  int degree(int v) const
  {
    int h0 = vertices_[v].halfedge;
    int h = h0, d = 0;
    do {
      ++d;
      h = twin(next(h));
    } while(h != h0 && d < 1000000);
    return d;
  }

  /// Removes a vertex of degree two that is not a polygon vertex: its two
  /// edges separate the same two cells and become one edge.
  bool remove_degree_two_vertex(int v)
  {
    Vertex& x = vertices_[v];
    if(!x.alive || x.input_point != NO_INDEX)
      return false;
    int h1 = x.halfedge;          // arrives at v
    int h2 = next(h1);            // leaves v
    if(next(twin(h2)) != twin(h1) || (h1 & ~1) == (h2 & ~1))
      return false;
    int t1 = twin(h1), t2 = twin(h2);
    int w = target(h2);
    halfedges_[h1].vertex = w;
    link(h1, next(h2));
    link(prev(t2), t1);
    if(vertices_[w].halfedge == h2)
      vertices_[w].halfedge = h1;
    int f = face_of(h2), g = face_of(t2);
    if(f >= 0 && faces_[f].halfedge == h2) faces_[f].halfedge = h1;
    if(g >= 0 && faces_[g].halfedge == t2) faces_[g].halfedge = t1;
    delete_edge(h2);
    delete_vertex(v);
    return true;
  }

  void reserve(std::size_t faces, std::size_t vertices)
  {
    faces_.reserve(faces);
    vertices_.reserve(vertices);
    halfedges_.reserve(6 * faces);
  }

private:
  std::vector<Halfedge> halfedges_;
  std::vector<Vertex> vertices_;
  std::vector<Face> faces_;
  std::vector<int> free_edges_, free_vertices_, free_faces_;
};

/// Computes the coordinates and radius of a pending vertex: the disk tangent
/// to the generators that defined it, or else to three consecutive
/// generators around it (cocircular ones).  `site(f)` gives the traits site
/// of face f, `point_site(p0, p1)` the site of input points (p0 == p1 for a
/// point).
template <class Traits, class Hds, class Site_of, class Point_site>
void resolve_vertex(const Hds& hds, int v, const Traits& traits, const Site_of& site,
                    const Point_site& point_site)
{
  const typename Hds::Vertex& x = hds.vertex(v);
  if(!x.pending)
    return;
  bool done = false;
  if(x.triple[0][0] != NO_INDEX)
    done = traits.construct_medial_disk_2_object()(point_site(x.triple[0][0], x.triple[0][1]),
                                                   point_site(x.triple[1][0], x.triple[1][1]),
                                                   point_site(x.triple[2][0], x.triple[2][1]), x.point, x.radius);
  // the faces around v, clockwise
  std::vector<int> faces;
  int h0 = x.halfedge, h = h0;
  do {
    faces.push_back(hds.face_of(h));
    h = Hds::twin(hds.next(h));
  } while(h != h0 && faces.size() < 64);
  const std::size_t d = faces.size();
  for(std::size_t i = 0; i < d && !done; ++i) {
    int a = faces[(i + 2) % d], b = faces[(i + 1) % d], c = faces[i];
    if(a < 0 || b < 0 || c < 0) continue;
    done = traits.construct_medial_disk_2_object()(site(a), site(b), site(c), x.point, x.radius);
  }
  if(!done) {
    // no disk from the generators (only with inexact decisions): take a
    // neighbouring vertex whose position is known
    h = h0;
    do {
      const typename Hds::Vertex& y = hds.vertex(hds.source(h));
      if(!y.pending) {
        x.point = y.point;
        x.radius = y.radius;
        break;
      }
      h = Hds::twin(hds.next(h));
    } while(h != h0);
  }
  x.pending = false;
}

} // namespace internal
} // namespace PMA2
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_MEDIAL_AXIS_2_INTERNAL_HALFEDGE_STRUCTURE_H
