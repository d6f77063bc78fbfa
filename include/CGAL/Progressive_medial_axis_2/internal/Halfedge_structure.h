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
// The half-edge structure that stores a medial axis: faces are generator
// cells, edges are medial curves, normals at reflex vertices and boundary
// edges, vertices are branch points, junctions and polygon vertices.
// Indices, not pointers; deleted elements go to free lists and are reused.

#ifndef CGAL_PROGRESSIVE_MEDIAL_AXIS_2_INTERNAL_HALFEDGE_STRUCTURE_H
#define CGAL_PROGRESSIVE_MEDIAL_AXIS_2_INTERNAL_HALFEDGE_STRUCTURE_H

#include <CGAL/assertions.h>
#include <CGAL/Progressive_medial_axis_2/internal/Inlining.h>

#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Progressive_medial_axes {
namespace internal {

/// Frees the memory of a vector (`clear()` keeps it).
template <class Vector>
void free_vector(Vector& v)
{
  Vector().swap(v);
}

constexpr int NO_INDEX = -1;
/// Face index of the outside of the shape (the twins of boundary half-edges).
constexpr int OUTSIDE = -1;
/// Face index marking a deleted half-edge.
constexpr int DELETED = -2;

/// A generator cell.  A segment generator goes from input point `p0` to
/// `p1` with the shape on its left; a point generator (reflex vertex) is the
/// input point `p0`.
/// (12 bytes, not 16: the flags share the words of the points, whose
/// indices take 31 bits as in Hds_vertex; 4.4 MiB of the peak of a one-shot
/// of a plate of 100,000 holes, RESULTS.md, fifty-fourth session.)
struct Hds_face {
  int halfedge;              // one half-edge of its counter-clockwise cycle
  int p0 : 31;
  bool is_point : 1;
  int p1 : 31;
  bool alive : 1;

  Hds_face() : halfedge(NO_INDEX), p0(NO_INDEX), is_point(false), p1(NO_INDEX), alive(true) {}
};

struct Hds_halfedge {
  int next = NO_INDEX, prev = NO_INDEX;
  int face = DELETED;        // the face on its left, OUTSIDE, or DELETED
  int vertex = NO_INDEX;     // target vertex
};

/// Indices of half-edges, disks and input points stored in a vertex take 31
/// bits (the flags take the 32nd): the structure holds at most this many
/// half-edges, and the input at most this many points.
constexpr std::size_t max_vertex_field_index = std::size_t(1) << 30;

/// A vertex: a polygon vertex (a corner), or a vertex with a disk of its
/// own (a branch point or a junction), whose disk is a record of its own
/// (Hds_disk).  A corner's disk is its input point with radius zero: the
/// structure keeps no record for it.  Corners are about a third of the
/// vertices of a one-shot (600,004 of 1,951,055 on a plate of 100,000
/// holes), and their 48 bytes of disk were 8% of the peak memory of the
/// tool on it (RESULTS.md, "Corners without a disk", thirty-sixth session).
struct Hds_vertex {
  int halfedge : 31;         // a half-edge whose target is this vertex
  bool pending : 1;          // its disk is not computed yet
  int slot : 31;             // >= 0: index of its disk; < 0: the corner of input point -1 - slot
  bool alive : 1;

  Hds_vertex() : halfedge(NO_INDEX), pending(false), slot(NO_INDEX), alive(true) {}
  bool is_corner() const { return slot < 0; }
  /// The index of the polygon vertex, if it is one (else NO_INDEX).
  int input_point() const { return slot < 0 ? -1 - slot : NO_INDEX; }
  void set_input_point(int i)
  {
    CGAL_precondition(i >= 0 && slot < 0);
    slot = -1 - i;
  }
};

/// The disk of a vertex that is not a corner.
template <class Point_2, class FT>
struct Hds_disk {
  // Coordinates and radius are computed when they are needed (see
  // resolve_vertex()): most vertices of a progressive run are removed again
  // before anyone looks at them.
  Point_2 point;
  FT radius = FT(0);
  // the generators that define the vertex, counter-clockwise: input point
  // indices (p0, p1), with p0 == p1 for a point generator
  int triple[3][2] = {{NO_INDEX, NO_INDEX}, {NO_INDEX, NO_INDEX}, {NO_INDEX, NO_INDEX}};
};

/// The traits site of a generator (p[0], p[1]) of a disk's triple, of the
/// input points `points` (p[0] == p[1] for a point generator).
template <class Site_2, class Point_2>
Site_2 generator_site(const std::vector<Point_2>& points, const int p[2])
{
  return p[0] == p[1] ? Site_2::point(points[std::size_t(p[0])])
                      : Site_2::segment(points[std::size_t(p[0])], points[std::size_t(p[1])]);
}

template <class Point_2, class FT>
class Halfedge_structure
{
public:
  typedef Hds_face Face;
  typedef Hds_halfedge Halfedge;
  typedef Hds_vertex Vertex;
  typedef Hds_disk<Point_2, FT> Disk;

  static int twin(int h) { return h ^ 1; }

  // Non-const access is a (possible) change: recorded when journaling.
  Halfedge& he(int h) { record(log_he_, halfedges_, h, saved_.he); return halfedges_[h]; }
  const Halfedge& he(int h) const { return halfedges_[h]; }
  Vertex& vertex(int v) { record(log_v_, vertices_, v, saved_.v); return vertices_[v]; }
  const Vertex& vertex(int v) const { return vertices_[v]; }
  /// The disk of a vertex that is not a corner.
  Disk& disk(int v)
  {
    CGAL_assertion(!vertices_[v].is_corner());
    const int d = vertices_[v].slot;
    record(log_d_, disks_, d, saved_.d);
    return disks_[d];
  }
  const Disk& disk(int v) const
  {
    CGAL_assertion(!vertices_[v].is_corner());
    return disks_[vertices_[v].slot];
  }
  /// The centre of the disk of vertex `v`, whose input points are `points`.
  const Point_2& point(int v, const std::vector<Point_2>& points) const
  {
    const Vertex& x = vertices_[v];
    return x.is_corner() ? points[std::size_t(x.input_point())] : disks_[x.slot].point;
  }
  /// The radius of the disk of vertex `v` (0 at a corner).  (By value: a
  /// zero shared by all corners would be one reference-counted number that
  /// threads copy at once where FT is CORE::Expr.)
  FT radius(int v) const
  {
    const Vertex& x = vertices_[v];
    return x.is_corner() ? FT(0) : disks_[x.slot].radius;
  }
  Face& face(int f) { record(log_f_, faces_, f, saved_.f); return faces_[f]; }
  const Face& face(int f) const { return faces_[f]; }

  int next(int h) const { return halfedges_[h].next; }
  int prev(int h) const { return halfedges_[h].prev; }
  int target(int h) const { return halfedges_[h].vertex; }
  int source(int h) const { return halfedges_[twin(h)].vertex; }
  int face_of(int h) const { return halfedges_[h].face; }
  bool is_deleted(int h) const { return halfedges_[h].face == DELETED; }

  /// Whether the edge of `h` has length zero: its two end vertices are one
  /// point, where four or more generators meet (set by the merge, which
  /// knows it exactly: the edge was opened and closed at equal event times).
  bool is_zero_length(int h) const { return !zero_length_.empty() && zero_length_[h >> 1] != 0; }
  void set_zero_length(int h, bool z)
  {
    if(zero_length_.empty()) {
      if(!z) return;
      make_zero_length_flags();
    }
    record(log_zero_, zero_length_, h >> 1, saved_.he / 2);
    zero_length_[h >> 1] = z ? 1 : 0;
  }

  std::size_t halfedge_capacity() const { return halfedges_.size(); }
  std::size_t vertex_capacity() const { return vertices_.size(); }
  std::size_t face_capacity() const { return faces_.size(); }
  std::size_t disk_capacity() const { return disks_.size(); }
  /// The disk record `d` (not recorded by the journal).
  Disk& disk_record(std::size_t d) { CGAL_precondition(!journal_); return disks_[d]; }
  std::size_t number_of_vertices() const { return vertices_.size() - free_vertices_.size(); }
  std::size_t number_of_faces() const { return faces_.size() - free_faces_.size(); }

  CGAL_PMA2_ALWAYS_INLINE void link(int h, int n)
  {
    he(h).next = n;
    he(n).prev = h;
  }

  /// A new edge; returns the even half-edge of the pair.  Faces and
  /// vertices are set by the caller.
  int new_edge(int left_face, int right_face)
  {
    if(free_edges_.empty()) {
      // (a new pair lies beyond the journal's saved sizes: nothing to record)
      const int h = int(halfedges_.size());
      require_indexable(halfedges_.size() + 2);
      Halfedge left, right;
      left.face = left_face;
      right.face = right_face;
      halfedges_.push_back(left);
      halfedges_.push_back(right);
      if(!zero_length_.empty()) zero_length_.push_back(0);
      return h;
    }
    const int h = pop(free_edges_, FREE_EDGES);
    he(h) = Halfedge();
    he(h + 1) = Halfedge();
    if(is_zero_length(h)) set_zero_length(h, false);
    he(h).face = left_face;
    he(h + 1).face = right_face;
    return h;
  }

  void delete_edge(int h)
  {
    int e = h & ~1;
    CGAL_assertion(halfedges_[e].face != DELETED);
    he(e).face = DELETED;
    he(e + 1).face = DELETED;
    push(free_edges_, FREE_EDGES, e);
  }

  /// A new vertex at the polygon vertex `input_point` (a corner).
  int new_corner(int input_point)
  {
    const int v = new_vertex_slot();
    vertex(v).slot = -1 - input_point;
    return v;
  }

  /// A vertex whose coordinates will be computed when first needed: the
  /// centre of the disk tangent to the generators of the faces `a, b, c`
  /// (counter-clockwise around it).
  int new_pending_vertex(int a, int b, int c)
  {
    const int v = new_vertex_slot();
    const int d = take_slot(disks_, FREE_DISKS);
    Vertex& x = vertex(v);
    x.slot = d;
    x.pending = true;
    pending_.push_back(v);
    Disk& y = disk(v);
    const int f[3] = {a, b, c};
    for(int i = 0; i < 3; ++i) {
      y.triple[i][0] = faces_[f[i]].p0;
      y.triple[i][1] = faces_[f[i]].p1;
    }
    if constexpr(std::is_floating_point<FT>::value)
      y.radius = FT(0);   // (no centre hint)
    return v;
  }

  /// Where FT is a floating-point type, a pending vertex keeps, until its
  /// disk is computed, an enclosure of its centre that the merge found when
  /// it made the vertex: within `err` of (x, y) in each coordinate.  It is
  /// kept in the disk's centre and radius, which a pending vertex does not
  /// use yet (the radius holds -err: a negative zero or below marks it).
  /// Switch times at the vertex are then computed from it (see
  /// Medial_merge::collect_switches()): about two thirds of the switch
  /// times of a one-shot of a real outline are at a vertex made by a
  /// vanishing event (RESULTS.md, fortieth session).
  void set_centre_hint(int v, double x, double y, double err)
  {
    static_assert(std::is_floating_point<FT>::value, "centre hints need a floating-point FT");
    CGAL_precondition(vertices_[v].pending && !vertices_[v].is_corner() && err >= 0);
    Disk& d = disk(v);
    d.point = Point_2(x, y);
    d.radius = -err;
  }
  /// The centre hint of vertex `v` (see set_centre_hint()), if it has one.
  bool centre_hint(int v, double& x, double& y, double& err) const
  {
    static_assert(std::is_floating_point<FT>::value, "centre hints need a floating-point FT");
    const Vertex& w = vertices_[v];
    if(!w.pending || w.is_corner()) return false;
    const Disk& d = disks_[w.slot];
    if(!std::signbit(d.radius)) return false;
    x = d.point.x();
    y = d.point.y();
    err = -d.radius;
    return true;
  }

  void delete_vertex(int v)
  {
    CGAL_assertion(vertices_[v].alive);
    vertex(v).alive = false;
    push(free_vertices_, FREE_VERTICES, v);
    if(!vertices_[v].is_corner())
      push(free_disks_, FREE_DISKS, vertices_[v].slot);
  }

  int new_face(bool is_point, int p0, int p1)
  {
    const int f = take_slot(faces_, FREE_FACES);
    Face& x = face(f);
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
    face(f).alive = false;
    push(free_faces_, FREE_FACES, f);
  }

  /// Removes a vertex of degree two that is not a polygon vertex: its two
  /// edges separate the same two cells and become one edge.
  bool remove_degree_two_vertex(int v)
  {
    const Vertex& x = vertices_[v];
    if(!x.alive || x.is_corner())
      return false;
    int h1 = x.halfedge;          // arrives at v
    int h2 = next(h1);            // leaves v
    if(next(twin(h2)) != twin(h1) || (h1 & ~1) == (h2 & ~1))
      return false;
    int t1 = twin(h1), t2 = twin(h2);
    int w = target(h2);
    if(is_zero_length(h1) && !is_zero_length(h2))
      set_zero_length(h1, false);
    he(h1).vertex = w;
    link(h1, next(h2));
    link(prev(t2), t1);
    if(vertices_[w].halfedge == h2)
      vertex(w).halfedge = h1;
    int f = face_of(h2), g = face_of(t2);
    if(f >= 0 && faces_[f].halfedge == h2) face(f).halfedge = h1;
    if(g >= 0 && faces_[g].halfedge == t2) face(g).halfedge = t1;
    delete_edge(h2);
    delete_vertex(v);
    return true;
  }

  // ---- the journal ----
  // Between begin_journal() and end_journal() every change is recorded, so
  // that rollback() can restore the structure as it was at begin_journal():
  // the double-precision model redoes with exact decisions a merge that met
  // an anomaly.

  void begin_journal()
  {
    journal_ = true;
    saved_ = Sizes{halfedges_.size(), vertices_.size(), faces_.size(), disks_.size(), pending_.size()};
  }

  void end_journal()
  {
    journal_ = false;
    saved_ = Sizes();
    log_he_.clear();
    log_v_.clear();
    log_d_.clear();
    log_f_.clear();
    log_zero_.clear();
    log_free_.clear();
  }

  /// Restores the structure as it was at begin_journal(); the journal goes on.
  void rollback()
  {
    CGAL_precondition(journal_);
    for(auto it = log_free_.rbegin(); it != log_free_.rend(); ++it) {
      std::vector<int>& list = free_list(it->list);
      if(it->pushed) list.pop_back();
      else list.push_back(it->index);
    }
    undo(log_he_, halfedges_);
    undo(log_v_, vertices_);
    undo(log_d_, disks_);
    undo(log_f_, faces_);
    undo(log_zero_, zero_length_);
    halfedges_.resize(saved_.he);
    if(!zero_length_.empty()) zero_length_.resize(saved_.he / 2);
    vertices_.resize(saved_.v);
    disks_.resize(saved_.d);
    faces_.resize(saved_.f);
    pending_.resize(saved_.pending);
    log_he_.clear();
    log_v_.clear();
    log_d_.clear();
    log_f_.clear();
    log_zero_.clear();
    log_free_.clear();
  }

  /// The vertices created pending since begin_journal().
  std::vector<int> pending_in_journal() const
  {
    return std::vector<int>(pending_.begin() + std::ptrdiff_t(saved_.pending), pending_.end());
  }

  /// The vertices created pending since the last call (some may be dead or
  /// resolved since).
  std::vector<int> take_pending()
  {
    std::vector<int> p;
    p.swap(pending_);
    return p;
  }

  /// The shifts of the indices of a structure appended by append().
  struct Offsets {
    int halfedge = 0, vertex = 0, face = 0, disk = 0;
  };

  /// Moves the elements of `other` (built on its own, for example by
  /// another thread) to the end of this structure; their indices grow by
  /// the returned offsets.  The cost is linear in the size of `other`.
  /// Neither structure may be journaling.  Each array of `other` is freed
  /// as soon as it is copied: the two structures hold one array twice at
  /// most, not all of `other`.  With `keep_other`, `other` is emptied
  /// instead, keeping its arrays for the next structure built in it.
  Offsets append(Halfedge_structure& other, bool keep_other = false)
  {
    // (kept arrays are emptied by other.clear() at the end)
    auto release = [keep_other](auto& v) {
      if(!keep_other) free_vector(v);
    };
    CGAL_precondition(!journal_ && !other.journal_);
    require_indexable(halfedges_.size() + other.halfedges_.size());
    const Offsets o{int(halfedges_.size()), int(vertices_.size()), int(faces_.size()), int(disks_.size())};
    auto shift = [](int& i, int by) { if(i >= 0) i += by; };
    if(!zero_length_.empty() || !other.zero_length_.empty()) {   // (see zero_length_)
      zero_length_.resize(halfedges_.size() / 2, 0);
      zero_length_.insert(zero_length_.end(), other.zero_length_.begin(), other.zero_length_.end());
      zero_length_.resize((halfedges_.size() + other.halfedges_.size()) / 2, 0);
    }
    release(other.zero_length_);
    halfedges_.reserve(halfedges_.size() + other.halfedges_.size());
    for(Halfedge h : other.halfedges_) {
      shift(h.next, o.halfedge);
      shift(h.prev, o.halfedge);
      shift(h.vertex, o.vertex);
      shift(h.face, o.face);   // OUTSIDE and DELETED stay
      halfedges_.push_back(h);
    }
    release(other.halfedges_);
    vertices_.reserve(vertices_.size() + other.vertices_.size());
    for(Vertex v : other.vertices_) {
      if(v.halfedge >= 0) v.halfedge = v.halfedge + o.halfedge;   // (bit-fields)
      if(v.slot >= 0) v.slot = v.slot + o.disk;
      vertices_.push_back(v);
    }
    release(other.vertices_);
    disks_.reserve(disks_.size() + other.disks_.size());
    for(Disk& d : other.disks_) disks_.push_back(std::move(d));
    release(other.disks_);
    faces_.reserve(faces_.size() + other.faces_.size());
    for(Face f : other.faces_) {
      shift(f.halfedge, o.halfedge);
      faces_.push_back(f);
    }
    for(int e : other.free_edges_) free_edges_.push_back(e + o.halfedge);
    for(int v : other.free_vertices_) free_vertices_.push_back(v + o.vertex);
    for(int f : other.free_faces_) free_faces_.push_back(f + o.face);
    for(int d : other.free_disks_) free_disks_.push_back(d + o.disk);
    for(int v : other.pending_) pending_.push_back(v + o.vertex);
    if(keep_other)
      other.clear();
    else
      other = Halfedge_structure();
    return o;
  }

  /// Whether the structure is combinatorially valid, between two operations
  /// (a merge's open edges have no end vertex yet):
  /// - the free lists hold exactly the deleted edges, vertices and faces,
  ///   each once, and no live vertex has a free or shared disk;
  /// - every live half-edge has a live face (or OUTSIDE) and a live target,
  ///   and live `next` and `prev` that are each other's inverse, on the
  ///   same face, with the target of a half-edge the source of its next;
  /// - every live face's half-edge is on it, and its cycle holds every
  ///   half-edge of the face (one cycle a face);
  /// - every live vertex's half-edge ends at it, and turning around it
  ///   (`twin(next(h))`) meets every half-edge that ends there (a vertex's
  ///   neighbourhood is one fan).
  /// If not, and `why` is given, it gets the first problem found, in one
  /// line.  Linear in the size of the structure.  (A check for tests and
  /// debugging: no operation calls it.)
  bool is_valid(std::string* why = nullptr) const
  {
    auto fail = [why](const std::string& s) {
      if(why) *why = s;
      return false;
    };
    auto str = [](long i) { return std::to_string(i); };
    const int H = int(halfedges_.size()), V = int(vertices_.size()), F = int(faces_.size()), D = int(disks_.size());
    if(H % 2 != 0) return fail("an odd number of half-edges (" + str(H) + ")");
    if(!zero_length_.empty() && zero_length_.size() != halfedges_.size() / 2)
      return fail("the zero-length flags are " + str(long(zero_length_.size())) + " for " + str(H / 2) + " edges");
    // the free lists: each element once, and exactly the deleted ones (with
    // `complete`, every element `is_free()` says is deleted must be listed;
    // a disk is free when no live vertex has it, checked below)
    for(int e = 0; e < H; e += 2)
      if(is_deleted(e) != is_deleted(e + 1)) return fail("edge " + str(e) + " is deleted on one side only");
    std::vector<char> listed;
    auto check_free = [&](const std::vector<int>& list, int size, const char* what, auto is_free,
                          bool complete) -> bool {
      listed.assign(std::size_t(size), 0);
      for(int i : list) {
        if(i < 0 || i >= size) return fail(std::string("free ") + what + " " + str(i) + " out of range");
        if(listed[std::size_t(i)]++) return fail(std::string("free ") + what + " " + str(i) + " listed twice");
        if(!is_free(i)) return fail(std::string("free ") + what + " " + str(i) + " is in use");
      }
      for(int i = 0; complete && i < size; ++i)
        if(is_free(i) && !listed[std::size_t(i)]) return fail(std::string("deleted ") + what + " " + str(i) + " is not free");
      return true;
    };
    if(!check_free(free_edges_, H, "edge", [&](int e) { return e % 2 == 0 && is_deleted(e); }, true) ||
       !check_free(free_vertices_, V, "vertex", [&](int v) { return !vertices_[v].alive; }, true) ||
       !check_free(free_faces_, F, "face", [&](int f) { return !faces_[f].alive; }, true) ||
       !check_free(free_disks_, D, "disk", [](int) { return true; }, false))
      return false;
    for(int v = 0; v < V; ++v) {
      const Vertex& x = vertices_[v];
      if(!x.alive || x.is_corner()) continue;
      if(x.slot >= D) return fail("vertex " + str(v) + " has disk " + str(x.slot) + " out of range");
      if(listed[std::size_t(x.slot)]++) return fail("vertex " + str(v) + " has a free or shared disk " + str(x.slot));
    }
    // the half-edges
    auto live = [&](int h) { return h >= 0 && h < H && !is_deleted(h); };
    std::size_t in_faces = 0, live_halfedges = 0;
    for(int h = 0; h < H; ++h) {
      if(is_deleted(h)) continue;
      ++live_halfedges;
      const int f = face_of(h), v = target(h), n = next(h), p = prev(h);
      if(f != OUTSIDE && (f < 0 || f >= F || !faces_[f].alive))
        return fail("half-edge " + str(h) + " is on face " + str(f) + ", not a live one");
      if(f != OUTSIDE) ++in_faces;
      if(v < 0 || v >= V || !vertices_[v].alive) return fail("half-edge " + str(h) + " ends at no live vertex");
      if(!live(n) || !live(p)) return fail("half-edge " + str(h) + " has no live next or prev");
      if(prev(n) != h || next(p) != h) return fail("half-edge " + str(h) + ": next and prev are not inverse");
      if(face_of(n) != f) return fail("half-edge " + str(h) + " and its next are on different faces");
      if(source(n) != v) return fail("half-edge " + str(h) + " does not end where its next starts");
    }
    // the faces: one cycle each
    std::size_t cycles = 0;
    for(int f = 0; f < F; ++f) {
      if(!faces_[f].alive) continue;
      const int h0 = faces_[f].halfedge;
      if(!live(h0) || face_of(h0) != f) return fail("face " + str(f) + " has no half-edge of its own");
      int h = h0;
      do {
        ++cycles;
        if(cycles > in_faces) return fail("the cycle of face " + str(f) + " does not close");
        h = next(h);
      } while(h != h0);
    }
    if(cycles != in_faces) return fail("a face has half-edges off its cycle");
    // the vertices: one fan each
    std::size_t fans = 0;
    for(int v = 0; v < V; ++v) {
      if(!vertices_[v].alive) continue;
      const int h0 = vertices_[v].halfedge;
      if(!live(h0) || target(h0) != v) return fail("vertex " + str(v) + " has no half-edge ending at it");
      int h = h0;
      do {
        ++fans;
        if(fans > live_halfedges) return fail("the half-edges around vertex " + str(v) + " do not close");
        h = twin(next(h));
      } while(h != h0);
    }
    if(fans != live_halfedges) return fail("a vertex has half-edges off its fan");
    return true;
  }

  /// Empties the structure, keeping the memory of its arrays.
  void clear()
  {
    CGAL_precondition(!journal_);
    halfedges_.clear();
    vertices_.clear();
    disks_.clear();
    faces_.clear();
    zero_length_.clear();
    free_edges_.clear();
    free_vertices_.clear();
    free_disks_.clear();
    free_faces_.clear();
    pending_.clear();
  }

  /// Reserves room for the axis of `points` input points: about 2 faces
  /// and 4 vertices a point, 3 of them with disks.  The axes of the 78,000
  /// polygons of 3 to 40 points of a world map (land-10m) used at most
  /// 12.2 half-edges, 3.4 vertices, 2.4 disks and 2.0 faces a point (none
  /// more than 12 n + 2 half-edges), so the constant is small: with 16 more
  /// faces, vertices and disks (96 more half-edges), a triangle reserved
  /// 11 times what it used, 2 KB more a polygon: a quarter of the peak of a file
  /// of 72,000 islands (RESULTS.md, sixtieth session).
  void reserve_for_points(std::size_t points)
  {
    const std::size_t faces = 2 * points + 4;
    reserve(faces, 4 * points + 4, 3 * points + 4, 6 * faces);
  }

  /// Reserves room for the axis of a part of `triangles` triangles of a
  /// divide and conquer, built in a structure of its own (on two threads or
  /// more).  The parts of the outlines, plates, mazes and stars of the
  /// benchmarks held at most 8.3 half-edges, 2.6 vertices, 1.7 disks and 1.6
  /// faces a triangle at once; a part that needs more grows its arrays.
  /// Reserved as for as many points (reserve_for_points()), the structures of
  /// the parts waiting to be moved into the result, and of those kept for
  /// the next parts, took half as much again: 1.8 MiB of the peak of a plate
  /// of 100,000 holes on two threads, 4 to 6 MiB of c1m_DEU_0's (RESULTS.md,
  /// fifty-fourth session).
  void reserve_for_triangles(std::size_t triangles)
  {
    const std::size_t t = triangles + 8;
    reserve(t * 13 / 8, t * 21 / 8, t * 7 / 4, t * 17 / 2);
  }

  /// Gives back what the arrays reserved beyond what they hold.  Reserved
  /// for the most an axis of that many points used, a small polygon's
  /// arrays are about half empty at the end, and a file of many small
  /// polygons keeps all their axes (reserve_for_points()).
  void shrink_to_fit()
  {
    halfedges_.shrink_to_fit();
    vertices_.shrink_to_fit();
    disks_.shrink_to_fit();
    faces_.shrink_to_fit();
    zero_length_.shrink_to_fit();
  }

private:
  void reserve(std::size_t faces, std::size_t vertices, std::size_t disks, std::size_t halfedges)
  {
    faces_.reserve(faces);
    vertices_.reserve(vertices);
    disks_.reserve(disks);
    halfedges_.reserve(halfedges);
  }

  // (out of line: once per structure at most)
  CGAL_PMA2_NOINLINE void make_zero_length_flags() { zero_length_.assign(halfedges_.size() / 2, 0); }

  enum Free_list { FREE_EDGES, FREE_VERTICES, FREE_DISKS, FREE_FACES };
  struct Free_change {
    Free_list list;
    bool pushed;
    int index;
  };
  struct Sizes {
    std::size_t he = 0, v = 0, f = 0, d = 0, pending = 0;
  };
  std::vector<int>& free_list(Free_list which)
  {
    switch(which) {
    case FREE_EDGES: return free_edges_;
    case FREE_VERTICES: return free_vertices_;
    case FREE_DISKS: return free_disks_;
    default: return free_faces_;
    }
  }
  // An element of `a` from the free list `which`, or a new one.
  template <class T>
  int take_slot(std::vector<T>& a, Free_list which)
  {
    std::vector<int>& list = free_list(which);
    if(!list.empty())
      return pop(list, which);
    a.emplace_back();
    return int(a.size()) - 1;
  }
  // A vertex record, from the free list or new (the caller sets its slot).
  int new_vertex_slot()
  {
    const int v = take_slot(vertices_, FREE_VERTICES);
    Vertex& x = vertex(v);
    x.pending = false;
    x.halfedge = NO_INDEX;
    x.alive = true;
    return v;
  }

  // Records the value of element i of `a` before a change, if it existed
  // when the journal began (later elements are removed by the rollback).
  template <class T>
  void record(std::vector<std::pair<int, T> >& log, const std::vector<T>& a, int i, std::size_t saved)
  {
    if(journal_ && std::size_t(i) < saved) append(log, i, a[i]);
  }
  // (out of line: the accessors that record, he() and the others, are
  // called for every change of the structure, and only a progressive
  // driver journals; with the append inline, the compiler did not inline
  // them: 4.6% more instructions on a one-shot of c1m_CHN_0)
  template <class T>
  CGAL_PMA2_NOINLINE static void append(std::vector<std::pair<int, T> >& log, int i, const T& value)
  {
    log.emplace_back(i, value);
  }
  template <class T>
  static void undo(std::vector<std::pair<int, T> >& log, std::vector<T>& a)
  {
    for(auto it = log.rbegin(); it != log.rend(); ++it) a[it->first] = it->second;
  }
  // Refuses a structure of more half-edges than a vertex's 31-bit field indexes.
  static void require_indexable(std::size_t halfedges)
  {
    if(halfedges > max_vertex_field_index)
      throw std::length_error("Progressive_medial_axis_2: more half-edges than a vertex can index");
  }
  int pop(std::vector<int>& list, Free_list which)
  {
    const int i = list.back();
    list.pop_back();
    if(journal_) log_free_.push_back(Free_change{which, false, i});
    return i;
  }
  void push(std::vector<int>& list, Free_list which, int i)
  {
    list.push_back(i);
    if(journal_) log_free_.push_back(Free_change{which, true, i});
  }

  std::vector<Halfedge> halfedges_;
  std::vector<Vertex> vertices_;
  std::vector<Disk> disks_;
  std::vector<Face> faces_;
  // Per edge (half-edge pair), whether it has length zero; empty while no
  // edge has (else as long as the pairs).  Only four or more generators on
  // one circle make such edges: an axis without them (a plate of 100,000
  // holes) saves the array (3.2 MB there) and its upkeep in new_edge()
  // (RESULTS.md, seventy-fifth session; c1m_CHN_0's axis has some).
  std::vector<char> zero_length_;
  std::vector<int> free_edges_, free_vertices_, free_disks_, free_faces_;
  std::vector<int> pending_;

  bool journal_ = false;
  Sizes saved_;
  std::vector<std::pair<int, Halfedge> > log_he_;
  std::vector<std::pair<int, Vertex> > log_v_;
  std::vector<std::pair<int, Disk> > log_d_;
  std::vector<std::pair<int, Face> > log_f_;
  std::vector<std::pair<int, char> > log_zero_;
  std::vector<Free_change> log_free_;
};

/// Computes the coordinates and radius of a pending vertex: the disk tangent
/// to the generators that defined it, or else to three consecutive
/// generators around it (cocircular ones).  `points` are the input points,
/// `site(f)` gives the traits site of face f.
template <class Traits, class Hds, class Site_of>
void resolve_vertex(Hds& hds, int v, const std::vector<typename Traits::Point_2>& points, const Traits& traits,
                    const Site_of& site)
{
  typedef typename Traits::Site_2 Site_2;
  const Hds& chds = hds;
  if(!chds.vertex(v).pending)
    return;
  typename Hds::Disk& x = hds.disk(v);
  auto point_site = [&](const int p[2]) { return generator_site<Site_2>(points, p); };
  bool done = false;
  if(x.triple[0][0] != NO_INDEX)
    done = traits.construct_medial_disk_2_object()(point_site(x.triple[0]), point_site(x.triple[1]),
                                                   point_site(x.triple[2]), x.point, x.radius);
  const int h0 = chds.vertex(v).halfedge;
  if(!done) {
    // the faces around v, clockwise: three consecutive ones
    std::vector<int> faces;
    int h = h0;
    do {
      faces.push_back(chds.face_of(h));
      h = Hds::twin(chds.next(h));
    } while(h != h0 && faces.size() < 64);
    const std::size_t d = faces.size();
    for(std::size_t i = 0; i < d && !done; ++i) {
      int a = faces[(i + 2) % d], b = faces[(i + 1) % d], c = faces[i];
      if(a < 0 || b < 0 || c < 0) continue;
      done = traits.construct_medial_disk_2_object()(site(a), site(b), site(c), x.point, x.radius);
    }
  }
  if(!done) {
    // no disk from the generators (only with inexact decisions): take a
    // neighbouring vertex whose position is known
    int h = h0;
    do {
      const int y = chds.source(h);
      if(!chds.vertex(y).pending) {
        x.point = chds.point(y, points);
        x.radius = chds.radius(y);
        break;
      }
      h = Hds::twin(chds.next(h));
    } while(h != h0);
  }
  hds.vertex(v).pending = false;
}

} // namespace internal
} // namespace Progressive_medial_axes
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_MEDIAL_AXIS_2_INTERNAL_HALFEDGE_STRUCTURE_H
