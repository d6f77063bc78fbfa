// Copyright (c) 2026 The Progressive_medial_axis_2 authors.
// All rights reserved.
//
// This file is part of CGAL (www.cgal.org).
//
// $URL$
// $Id$
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s)     : The Progressive_medial_axis_2 authors
//
// The shape decomposition of the region-growing driver: a constrained
// Delaunay triangulation of the polygon and the adjacency of its triangles.

#ifndef CGAL_PROGRESSIVE_MEDIAL_AXIS_2_INTERNAL_TRIANGULATE_H
#define CGAL_PROGRESSIVE_MEDIAL_AXIS_2_INTERNAL_TRIANGULATE_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/number_utils.h>
#include <CGAL/Progressive_medial_axis_2/Input_error.h>
#include <CGAL/Progressive_medial_axis_2/internal/Input_conversion.h>
#include <CGAL/Progressive_medial_axis_2/internal/Medial_axis_engine.h>

#include <algorithm>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Progressive_medial_axes {
namespace internal {

/// A triangle of the decomposition: its vertices (indices of input points,
/// counter-clockwise) and, across edge i (opposite vertex i), the index of
/// the neighbouring triangle inside the polygon, or -1 across the boundary.
struct Triangle {
  int v[3];
  int nbr[3];
};

/// The side of triangle u shared with its neighbour t.
inline int side_towards(const std::vector<Triangle>& triangles, int u, int t)
{
  int e = 0;
  while(triangles[std::size_t(u)].nbr[e] != t) ++e;
  return e;
}

/// Triangulates the polygon of the points of `data` (its edges: each point
/// to its successor `info[i].next`), in the kernel of the points (with exact
/// predicates): distinct input points stay distinct.
///
/// Where a point lies inside an edge (a "T": an OGC hole touching the outer
/// ring inside one of its edges), the triangulation splits that edge's
/// constraint there.  Such an edge is found as a constraint that is not an
/// edge of the triangulation, and split in `data` too: a new point at the
/// place (after the input points, named after the first input point there,
/// the halves keeping the edge's id), then the corners at that place are
/// linked again (link_touching_corners()).  The place becomes one where
/// rings touch at vertices; the interior sectors on the edge's side are less
/// than pi, so the new point is never a reflex corner.  This costs nothing
/// where there is no T, and needs no validation (TRUST_INPUT).
///
/// Points whose successor is -1 are not part of the polygon (the vertices
/// that boundary evolution removed from its coarse shape) and are left out.
///
/// In two phases: the Delaunay triangulation of the points, which any finite
/// points have (the one-shot builds it while another thread validates the
/// input), then the edges as constraints and the triangles inside, which
/// need a valid polygon.
template <class Kernel>
class Ring_triangulation
{
  typedef Exact_predicates_kernel_for<Kernel> TK;
  typedef typename TK::type K;
  typedef Triangulation_vertex_base_with_info_2<int, K> Vb;
  typedef Triangulation_face_base_with_info_2<int, K> Fbi;
  typedef Constrained_triangulation_face_base_2<K, Fbi> Fb;
  typedef Triangulation_data_structure_2<Vb, Fb> Tds;
  typedef Constrained_Delaunay_triangulation_2<K, Tds, Exact_predicates_tag> CDT;
  typedef typename CDT::Vertex_handle Vertex_handle;

public:
  /// Phase 1 from the rings: their points, numbered in order over the rings
  /// (as set_points() numbers them).  The coordinates must be finite.
  template <class Point_2>
  void insert_points(const std::vector<std::vector<Point_2> >& rings)
  {
    std::vector<std::pair<typename K::Point_2, int> > pts;
    std::size_t n = 0;
    for(const auto& ring : rings) n += ring.size();
    pts.reserve(n);
    int i = 0;
    for(const auto& ring : rings)
      for(const Point_2& p : ring) pts.emplace_back(TK::point(p), i++);
    insert_points(pts);
  }

  /// Phase 1 from points already paired with their indices.
  void insert_points(std::vector<std::pair<typename K::Point_2, int> >& points)
  {
    cdt_.insert(points.begin(), points.end());
    inserted_ = true;
  }

  /// Phase 2 (and phase 1 from `data` if not done): the triangles inside the
  /// valid polygon of `data`, whose points are those of phase 1.
  template <class Data>
  std::vector<Triangle> finish(Data& data);

  /// Phase 2 for a polygon whose points are distinct and lie inside no
  /// edge (used for the sides of a split triangulation,
  /// Split_triangulation.h), in two steps.  First its edges: i -> `next[i]`
  /// (-1: i is not a point of it), its points those of phase 1 (done).
  /// Returns the number of triangles inside, or -1 where two points of
  /// phase 1 are at one place or an edge passes through a point (which
  /// finish() handles).
  int constrain_plain(const std::vector<int>& next);
  /// Then the triangles, into `out`, their indices (and neighbours) from
  /// `offset` on.
  void write_plain(Triangle* out, int offset)
  {
    write_inside(out, offset, [](Face_handle f, int i) { return f->vertex(i)->info(); });
  }

private:
  typedef typename CDT::Face_handle Face_handle;
  // Constrains the edges i -> next(i) of the n points (next(i) < 0: no
  // edge); the indices i of those that were not edges of the Delaunay
  // triangulation already.
  template <class Next>
  std::vector<std::size_t> constrain(const std::vector<Vertex_handle>& handle, std::size_t n, const Next& next);
  // The nesting level of every face: 0 outside, 1 inside the outer ring, 2
  // in a hole...; the faces inside (odd levels) get -2 - their index among
  // them.  Returns their number.
  int number_inside();
  // The triangles inside, into `out` (numbered from `offset`); `vertex(f,
  // i)` names the vertex i of face f.
  template <class Vertex_name>
  void write_inside(Triangle* out, int offset, const Vertex_name& vertex);

  CDT cdt_;
  bool inserted_ = false;
};

template <class Kernel>
template <class Next>
std::vector<std::size_t> Ring_triangulation<Kernel>::constrain(const std::vector<Vertex_handle>& handle,
                                                               std::size_t n, const Next& next)
{
  // Most edges of a polygon are edges of the Delaunay triangulation of its
  // points already: those are marked constrained on both sides here, which
  // is all that CDT::insert_constraint() would do for them, without its
  // work stack (two blocks of the heap for each call).  The others are
  // inserted, and looked at by the caller for points they pass through.
  // (On a 128,000-vertex outline the constraints took 11 ms instead of 26,
  // the search for such points 0.2 ms instead of 12.)
  CDT& cdt = cdt_;
  std::vector<std::size_t> inserted;
  for(std::size_t i = 0; i < n; ++i) {
    const int j = next(i);
    if(j < 0) continue;
    const Vertex_handle a = handle[i], b = handle[std::size_t(j)];
    Face_handle f;
    int e;
    if(cdt.dimension() == 2 && cdt.is_edge(a, b, f, e)) {
      f->set_constraint(e, true);
      f->neighbor(e)->set_constraint(cdt.mirror_index(f, e), true);
    } else {
      cdt.insert_constraint(a, b);
      inserted.push_back(i);
    }
  }
  return inserted;
}

template <class Kernel>
int Ring_triangulation<Kernel>::number_inside()
{
  CDT& cdt = cdt_;
  for(auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f) f->info() = -1;
  // (One stack, reused by every region: a queue allocated for each region
  // made the flood of a plate of 100,000 holes take 82 ms instead of 73.)
  std::vector<Face_handle> border, current, stack;
  auto flood = [&](Face_handle start, int level) {
    if(start->info() != -1) return;
    start->info() = level;
    stack.push_back(start);
    while(!stack.empty()) {
      const auto f = stack.back();
      stack.pop_back();
      for(int i = 0; i < 3; ++i) {
        const auto n = f->neighbor(i);
        if(n->info() != -1) continue;
        if(f->is_constrained(i)) {
          border.push_back(n);
        } else {
          n->info() = level;
          stack.push_back(n);
        }
      }
    }
  };
  border.push_back(cdt.infinite_face());
  for(int level = 0; !border.empty(); ++level) {
    current.swap(border);
    border.clear();
    for(const auto f : current) flood(f, level);
  }
  int count = 0;
  for(auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if(f->info() % 2 == 1) {
      f->info() = -2 - count;   // remember the triangle's index
      ++count;
    }
  }
  return count;
}

template <class Kernel>
template <class Vertex_name>
void Ring_triangulation<Kernel>::write_inside(Triangle* out, int offset, const Vertex_name& vertex)
{
  CDT& cdt = cdt_;
  for(auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if(f->info() > -2) continue;
    Triangle& t = out[-2 - f->info()];
    for(int i = 0; i < 3; ++i) {
      t.v[i] = vertex(f, i);
      auto n = f->neighbor(i);
      bool inside = !cdt.is_infinite(n) && n->info() <= -2;
      t.nbr[i] = (inside && !cdt.is_constrained(std::make_pair(f, i))) ? offset - 2 - n->info() : -1;
    }
  }
}

template <class Kernel>
int Ring_triangulation<Kernel>::constrain_plain(const std::vector<int>& next)
{
  CGAL_precondition(inserted_);
  CDT& cdt = cdt_;
  const std::size_t n = next.size();
  std::vector<Vertex_handle> handle(n);
  std::size_t in = 0;
  for(std::size_t i = 0; i < n; ++i) in += next[i] >= 0 ? 1 : 0;
  if(cdt.number_of_vertices() != in)   // points at one place
    return -1;
  for(auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) handle[std::size_t(v->info())] = v;
  for(const std::size_t i : constrain(handle, n, [&](std::size_t i) { return next[i]; }))
    if(!cdt.is_edge(handle[i], handle[std::size_t(next[i])]))   // an edge through a point
      return -1;
  return number_inside();
}

template <class Kernel>
template <class Data>
std::vector<Triangle> Ring_triangulation<Kernel>::finish(Data& data)
{
  auto& points = data.points;
  auto& info = data.info;
  CDT& cdt = cdt_;
  if(!inserted_) {
    std::vector<std::pair<typename K::Point_2, int> > pts;
    pts.reserve(points.size());
    for(std::size_t i = 0; i < points.size(); ++i)
      if(info[i].next >= 0) pts.emplace_back(TK::point(points[i]), int(i));
    insert_points(pts);
  }
  std::vector<Vertex_handle> handle(points.size());
  for(auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v)
    handle[v->info()] = v;
  // input points at one place (where rings touch): the triangulation keeps
  // one of them; the triangles get the corner of their sector below
  std::map<Vertex_handle, std::vector<int> > touching;
  for(std::size_t i = 0; i < points.size(); ++i)
    if(handle[i] == Vertex_handle() && info[i].next >= 0) {
      handle[i] = cdt.insert(TK::point(points[i]));
      std::vector<int>& at = touching[handle[i]];
      if(at.empty()) at.push_back(handle[i]->info());
      at.push_back(int(i));
    }
  const std::size_t n = points.size();
  const std::vector<std::size_t> inserted = constrain(handle, n, [&](std::size_t i) { return info[i].next; });

  // T's: an edge whose constraint passes through other points
  const K k;
  bool split = false;
  for(const std::size_t i : inserted) {
    const Vertex_handle a = handle[i], b = handle[std::size_t(info[i].next)];
    if(cdt.is_edge(a, b)) continue;
    int last = int(i);
    const int after = info[i].next;
    for(Vertex_handle u = a; u != b;) {
      // the next point of the edge: the neighbour of u strictly between u and b on the segment
      Vertex_handle w;
      auto c = cdt.incident_vertices(u), c0 = c;
      do {
        if(!cdt.is_infinite(c) && (Vertex_handle(c) == b ||
                                   (k.orientation_2_object()(u->point(), c->point(), b->point()) == COLLINEAR &&
                                    k.collinear_are_strictly_ordered_along_line_2_object()(u->point(), c->point(), b->point())))) {
          w = c;
          break;
        }
      } while(++c != c0);
      if(w == Vertex_handle())
        throw Input_error("an edge of the polygon could not be triangulated (do its rings cross?)");
      if(w != b) {   // a new point at w's place, on the edge from `last`
        const int s = int(points.size());
        std::vector<int>& at = touching[w];
        if(at.empty()) at.push_back(w->info());
        Point_info x = info[i];
        const int first = *std::min_element(at.begin(), at.end());
        x.ring = info[std::size_t(first)].ring;
        x.index = info[std::size_t(first)].index;
        x.next = after;
        points.push_back(points[std::size_t(w->info())]);
        info.push_back(x);
        info[std::size_t(last)].next = s;
        handle.push_back(w);
        at.push_back(s);
        last = s;
        split = true;
      }
      u = w;
    }
  }
  if(split)
    link_touching_corners(data, [&](const typename Kernel::Point_2& p, const typename Kernel::Point_2& q,
                                    const typename Kernel::Point_2& r) {
      return k.orientation_2_object()(TK::point(p), TK::point(q), TK::point(r));
    });

  const int count = number_inside();
  // The corner of the sector of face f at its vertex i, a place where rings
  // touch: turning clockwise about it, the first constrained edge leads to the
  // successor of that corner (see link_touching_corners()).
  auto corner = [&](typename CDT::Face_handle f, int i) {
    const typename CDT::Vertex_handle v = f->vertex(i);
    const std::vector<int>& at = touching.at(v);
    while(!cdt.is_constrained(std::make_pair(f, CDT::cw(i)))) {
      f = f->neighbor(CDT::cw(i));
      i = f->index(v);
    }
    const typename CDT::Vertex_handle w = f->vertex(CDT::ccw(i));
    for(int c : at)
      if(handle[std::size_t(info[std::size_t(c)].next)] == w) return c;
    CGAL_assertion_msg(false, "no corner for the sector");
    return at.front();
  };
  std::vector<Triangle> tris(static_cast<std::size_t>(count));
  write_inside(tris.data(), 0, [&](Face_handle f, int i) {
    return touching.empty() || !touching.count(f->vertex(i)) ? f->vertex(i)->info() : corner(f, i);
  });
  return tris;
}

/// Both phases of Ring_triangulation at once.
template <class Kernel, class Data>
std::vector<Triangle> triangulate_rings(Data& data)
{
  return Ring_triangulation<Kernel>().finish(data);
}

} // namespace internal
} // namespace Progressive_medial_axes
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_MEDIAL_AXIS_2_INTERNAL_TRIANGULATE_H
