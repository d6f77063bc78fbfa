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
// The two local updates of boundary evolution (Liu et al. 2016, section
// 6.2) that are not merges: a triangle cut out of the shape, and a flat
// vertex put back into a boundary edge.
//
// The cut.  The shape Omega has the boundary edge uw (its cell C, the
// boundary half-edge b from u to w) and v is a point inside Omega such that
// the triangle T = (u, v, w) lies in Omega and u, v, w turn right (v is a
// reflex corner of Omega' = Omega \ T).  The new generators are the
// segments e1 = uv and e2 = vw and the reflex point v; the cell C goes, and
// so does the point cell of u (of w) if u (w) stops being reflex.  This is
// the insertion of new sites in the style of Sugihara and Iri's
// topology-oriented incremental method (the paper's reference [13]):
//
//   1. A vertex of the old axis is in conflict when its open maximal disk
//      meets e1 or e2 (an exact predicate of the traits), or when it is a
//      vertex of a cell that goes.  Let Z be the union of the new cells (of
//      e1, v, e2) in Omega': it is a topological disk along the chain
//      u-v-w, bounded on the other side by the "front", a curve from u to w.
//      The conflict vertices are the old vertices in Z.
//   2. The front is found by walking: it starts at u in the cell F_0 next
//      to the new edge e1 (the point cell of u if u stays reflex, else the
//      edge before u) and follows the cycle of the current cell through
//      conflict vertices until the first kept vertex x; the edge y -> x it
//      arrives by is crossed by the front, which goes on in the cell on the
//      other side of that edge.  The walk ends at the corner w.  Only cells
//      that touch Z are visited.
//   3. On each crossed edge a new vertex is made: the disk tangent to its
//      two cells and to the new generator closest to it.  Along the front
//      the new generator runs e1, v, e2 (in that order, v's cell lies
//      between the normals to e1 and e2 at v): the exact position of the
//      disk's centre against those normals (the foot of the centre on e1,
//      on e2) picks it.  Where it changes inside a cell, a vertex on the
//      normal at v is made.  The conflict vertices and the edges between
//      them go, the crossed edges are shortened to their kept part, and the
//      front edges, the normals at v and the boundary edges e1, e2 are
//      linked in.
//
// Invariant (checked before anything changes): every edge at a vertex in
// conflict goes (both its ends are in conflict) or is crossed by the front.
// In a simply connected shape it always holds: each old cell is crossed by
// the front at most once, an old edge with both ends kept lies outside Z
// and one with both ends in conflict lies inside it.  (A cell split by the
// front into two parts would make, with a path through Z, a loop in the
// interior around a point of the boundary chain.)  With holes, the new
// cells can surround a small hole near the chain: Z is then not a disk, a
// second front runs around the hole's cells, and the check fails; the cut
// then changes nothing and says so (the driver computes that step in one
// shot).  Every cell of the old axis other than C and the point cells of
// u and w keeps a part next to its generator: a cell is star-shaped from
// its generator, and a point whose
// new nearest boundary point is on the chain has the points between it and
// its old foot closer to their old generator.  A kept vertex whose disk is
// tangent to the chain (four or more generators at one point) stays, and
// the new vertex on its edge is at the same point: that edge has length
// zero and is marked so.
//
// With inexact decisions (the double model) the walk can meet an event
// that no exact decision meets: it then throws Merge_anomaly in strict
// mode, and the engine redoes the cut with exact decisions.  Every check
// that can fail runs before the structure changes, so that a failure with
// exact decisions (a bug; asserted in debug builds) also leaves the
// structure as it was, and the step is computed in one shot.
//
// The split.  A vertex v put back on the boundary edge uw (u, v, w
// collinear, v between) splits the cell C in two along the normal at v:
// the normal starts at v and ends on the edge of C's cycle whose end
// points have their feet on uw on both sides of v's (the feet are
// monotone along the cycle, since a segment's cell is swept by the normals
// to the segment).

#ifndef CGAL_PROGRESSIVE_MEDIAL_AXIS_2_INTERNAL_MEDIAL_CUT_H
#define CGAL_PROGRESSIVE_MEDIAL_AXIS_2_INTERNAL_MEDIAL_CUT_H

#include <CGAL/Progressive_medial_axis_2/internal/Halfedge_structure.h>
#include <CGAL/Progressive_medial_axis_2/internal/Merge.h>
#include <CGAL/assertions.h>
#include <CGAL/enum.h>

#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Progressive_medial_axes {
namespace internal {

/// What a cut or a split did.
struct Cut_statistics {
  std::size_t crossings = 0;        ///< edges of the old axis crossed by the front
  std::size_t removed_vertices = 0; ///< vertices of the old axis in conflict
  bool redone_exactly = false;      ///< the double model met an anomaly and redid it with exact decisions
  bool enclosed = false;            ///< the new cells would enclose old ones: not done (see Medial_cut::cut())
};

template <class Traits>
class Medial_cut
{
public:
  typedef typename Traits::Point_2 Point_2;
  typedef typename Traits::FT FT;
  typedef typename Traits::Site_2 Site_2;
  typedef typename Traits::Event_time_2 Time;
  typedef Halfedge_structure<Point_2, FT> Hds;

  Medial_cut(Hds& hds, const std::vector<Point_2>& points, const Traits& traits)
    : hds_(hds), points_(points), traits_(traits), compare_(traits.compare_event_time_2_object())
  {}

  /// In strict mode a cut throws Merge_anomaly at an inconsistency (only
  /// inexact decisions lead there) instead of asserting.
  void set_strict(bool strict) { strict_ = strict; }

  const Cut_statistics& statistics() const { return stats_; }

  /// The vertices whose cells changed in the last cut or split (for the
  /// double model's check of its new vertices).
  const std::vector<int>& changed_vertices() const { return changed_; }

  /// Cuts the triangle (u, v, w) out of the shape: `b` is the boundary
  /// half-edge from u to w, `v` an input point such that the triangle lies
  /// in the shape and turns right at v.  Returns the new boundary half-edges
  /// from u to v and from v to w; or NO_INDEX twice, the structure
  /// unchanged, where the new cells would enclose cells of the old axis
  /// (the front is not one curve from u to w).
  std::pair<int, int> cut(int b, int v)
  {
    return guarded([&] { return cut_impl(b, v); });
  }

  /// Puts the input point `v` back into the boundary edge `b` from u to w
  /// (v inside the segment uw).  Returns the new boundary half-edges from
  /// u to v and from v to w.
  std::pair<int, int> split(int b, int v)
  {
    return guarded([&] { return split_impl(b, v); });
  }

private:
  enum State : signed char { UNKNOWN = 0, KEPT = 1, CONFLICT = 2 };
  enum Edge_mark : char { GONE = 1, CROSSED = 2 };

  // Runs a cut or a split.  Every check that can fail runs before the
  // structure changes: on a failure, a strict (double) model throws, so
  // that the engine redoes the step with exact decisions; an exact model
  // returns NO_INDEX twice, the structure unchanged, and the driver computes
  // the step in one shot (a failure there is a bug, asserted in debug builds).
  template <class Op>
  std::pair<int, int> guarded(const Op& op)
  {
    try {
      return op();
    } catch(Merge_anomaly&) {
      end_marks();
      if(strict_) throw;
    } catch(Uncertain_decision&) {
      end_marks();
      if(strict_) throw;
    } catch(...) {
      end_marks();
      throw;
    }
    stats_.enclosed = true;
    return std::make_pair(NO_INDEX, NO_INDEX);
  }

  std::pair<int, int> split_impl(int b, int v)
  {
    stats_ = Cut_statistics();
    changed_.clear();
    const int C = hds_.face_of(b);
    const int vU = hds_.source(b), vW = hds_.target(b);
    const int U = input_of(vU), W = input_of(vW), V = v;
    const Site_2 line = Site_2::segment(points_[U], points_[W]);
    require(!chds().face(C).is_point &&
            traits_.orientation_2_object()(points_[U], points_[V], points_[W]) == COLLINEAR);
    const Time fv = traits_.compute_foot_time_2_object()(line, points_[V]);
    // the edge of C's cycle (from w back to u) where the feet pass v's
    int h = hds_.next(b);
    Comparison_result at_y = LARGER;
    std::size_t guard = 0;
    for(;; h = hds_.next(h)) {
      require(h != b && ++guard <= hds_.halfedge_capacity());
      const int y = hds_.target(h);
      if(y == vU) { at_y = SMALLER; break; }
      Time t;
      if(input_of(y) != NO_INDEX) {   // (a corner on the cell, where rings touch)
        t = traits_.compute_foot_time_2_object()(line, points_[input_of(y)]);
      } else {
        const Site_2* s = vertex_sites(y);
        require(traits_.compute_disk_foot_time_2_object()(line, s[0], s[1], s[2], t));
      }
      at_y = compare_(t, fv);
      if(at_y != LARGER) break;
    }
    const int G = face_across(h);
    const int C1 = hds_.new_face(false, U, V), C2 = hds_.new_face(false, V, W);
    const int vV = hds_.new_corner(V);
    const int z = hds_.new_pending_vertex(G, C1, C2);
    const int y = hds_.target(h);
    // h (a -> y) becomes a -> z in C2; h2 (z -> y) in C1
    const int h2 = hds_.new_edge(C1, G);
    hds_.he(h2).vertex = y;
    hds_.he(Hds::twin(h2)).vertex = z;
    const int after_h = hds_.next(h), before_twin = hds_.prev(Hds::twin(h));
    hds_.he(h).vertex = z;
    hds_.link(before_twin, Hds::twin(h2));
    hds_.link(Hds::twin(h2), Hds::twin(h));
    hds_.set_zero_length(h2, at_y == EQUAL);
    if(hds_.is_zero_length(h)) hds_.set_zero_length(h, false);
    if(chds().vertex(y).halfedge == h) hds_.vertex(y).halfedge = h2;
    // the new boundary edges and the normal at v
    const int b1 = hds_.new_edge(C1, OUTSIDE), b2 = hds_.new_edge(C2, OUTSIDE);
    hds_.he(b1).vertex = vV; hds_.he(Hds::twin(b1)).vertex = vU;
    hds_.he(b2).vertex = vW; hds_.he(Hds::twin(b2)).vertex = vV;
    const int nz = hds_.new_edge(C1, C2);
    hds_.he(nz).vertex = z; hds_.he(Hds::twin(nz)).vertex = vV;
    // C2: b2, C's cycle from next(b) to h, the normal down to v
    const int first2 = hds_.next(b), last1 = hds_.prev(b);
    hds_.link(b2, first2);
    for(int e = first2;; e = hds_.next(e)) {
      hds_.he(e).face = C2;
      if(e == h) break;
    }
    hds_.link(h, Hds::twin(nz));
    hds_.link(Hds::twin(nz), b2);
    // C1: b1, the normal up to z, h2, C's cycle from after h to the end
    hds_.link(b1, nz);
    hds_.link(nz, h2);
    if(after_h != b) {
      hds_.link(h2, after_h);
      for(int e = after_h;; e = hds_.next(e)) {
        hds_.he(e).face = C1;
        if(e == last1) break;
      }
      hds_.link(last1, b1);
    } else {
      hds_.link(h2, b1);   // y is u
    }
    hds_.face(C1).halfedge = b1;
    hds_.face(C2).halfedge = b2;
    const int outside = Hds::twin(b);
    hds_.link(hds_.prev(outside), Hds::twin(b2));
    hds_.link(Hds::twin(b2), Hds::twin(b1));
    hds_.link(Hds::twin(b1), hds_.next(outside));
    hds_.vertex(vV).halfedge = b1;
    hds_.vertex(z).halfedge = h;
    hds_.vertex(vU).halfedge = Hds::twin(b1);
    hds_.vertex(vW).halfedge = b2;
    hds_.delete_edge(b);
    hds_.delete_face(C);
    stats_.crossings = 1;
    changed_.push_back(y);
    return std::make_pair(b1, b2);
  }

  std::pair<int, int> cut_impl(int b, int v)
  {
    stats_ = Cut_statistics();
    changed_.clear();
    const int C = hds_.face_of(b);
    const int vU = hds_.source(b), vW = hds_.target(b);
    const int U = input_of(vU), W = input_of(vW), V = v;
    e1_ = Site_2::segment(points_[U], points_[V]);
    e2_ = Site_2::segment(points_[V], points_[W]);
    pv_ = Site_2::point(points_[V]);
    U_ = U;
    W_ = W;
    typename Traits::Orientation_2 orientation = traits_.orientation_2_object();
    require(!chds().face(C).is_point && orientation(points_[U], points_[V], points_[W]) == RIGHT_TURN);

    begin_marks();
    std::vector<int>& gone_faces = gone_faces_;
    gone_faces.clear();
    gone_faces.push_back(C);

    // The cells at u: F_0, the cell next to e1 after the cut, and h0, the
    // half-edge of its cycle that leaves u.
    int h0 = Hds::twin(hds_.prev(b));
    int F0 = hds_.face_of(h0);
    if(is_point_at(F0, U)) {
      const int into_u = hds_.prev(h0);      // the normal between the edge before u and u's cell
      const int A = face_across(into_u);
      require(!chds().face(A).is_point && chds().face(A).p1 == U);
      if(orientation(points_[chds().face(A).p0], points_[U], points_[V]) != RIGHT_TURN) {
        gone_faces.push_back(F0);             // u stops being reflex
        h0 = Hds::twin(into_u);
        F0 = A;
      }
    }
    // The cells at w: F_k, the cell next to e2, and h_end, the half-edge of
    // its cycle that arrives at w.
    int h_end = Hds::twin(hds_.next(b));
    int Fk = hds_.face_of(h_end);
    int flat_after_w = NO_INDEX;   // the edge after w, where it continues e2 on its line
    if(is_point_at(Fk, W)) {
      const int out_of_w = hds_.next(h_end);  // the normal between w's cell and the edge after w
      const int B = face_across(out_of_w);
      require(!chds().face(B).is_point && chds().face(B).p0 == W);
      const Orientation turn = orientation(points_[V], points_[W], points_[chds().face(B).p1]);
      if(turn != RIGHT_TURN) {
        gone_faces.push_back(Fk);
        h_end = Hds::twin(out_of_w);
        Fk = B;
        if(turn == COLLINEAR) flat_after_w = B;
      }
    }
    // every vertex and edge of a cell that goes is gone (but the corners u, w)
    for(int f : gone_faces) {
      const int s = chds().face(f).halfedge;
      int h = s;
      do {
        mark_edge(h);
        const int x = hds_.target(h);
        if(x != vU && x != vW) set_state(x, CONFLICT);
        h = hds_.next(h);
      } while(h != s);
    }

    // The walk along the front.
    std::vector<int>& crossings = crossings_;
    crossings.clear();
    std::size_t guard = 0;
    for(int h = h0;;) {
      require(++guard <= 4 * hds_.halfedge_capacity());
      const int x = hds_.target(h);
      if(x == vW) {
        require(h == h_end);
        mark_edge(h);
        break;
      }
      require(x != vU);
      if(in_conflict(x)) {
        mark_edge(h);
        h = hds_.next(h);
      } else {
        require(!edge_marked(h));
        crossings.push_back(h);
        h = hds_.next(Hds::twin(h));
      }
    }
    // The invariant: every edge at a vertex in conflict goes, or is crossed
    // by the front (its other end is kept).  Where it fails, the new cells
    // surround a part of the old axis (the cells of a small hole near the
    // chain): their union is not a disk, and the cut is not done here.
    for(int h : crossings) {
      require(!edge_marked(h));
      edge_mark_[std::size_t(h >> 1)] = CROSSED;
    }
    bool local = true;
    for(int x : touched_) {
      if(state_[std::size_t(x)] != CONFLICT) continue;
      const int s = chds().vertex(x).halfedge;
      int h = s;
      do {
        local = local && edge_mark_[std::size_t(h >> 1)] != 0;
        h = Hds::twin(hds_.next(h));
      } while(h != s && local);
      if(!local) break;
    }
    for(int h : crossings) edge_mark_[std::size_t(h >> 1)] = 0;
    if(!local) {
      if(strict_) throw Merge_anomaly();   // perhaps an inexact decision: redone exactly
      end_marks();
      stats_.enclosed = true;
      return std::make_pair(NO_INDEX, NO_INDEX);
    }
    const int k = int(crossings.size());
    stats_.crossings = std::size_t(k);

    // The new cells.
    const int E1 = hds_.new_face(false, U, V);
    const int PV = hds_.new_face(true, V, V);
    const int E2 = hds_.new_face(false, V, W);
    const int N[3] = {E1, PV, E2};
    const int vV = hds_.new_corner(V);

    // The generator of each crossing: e1, v or e2, in this order along the front.
    // Where w becomes flat (the edge B after w continues e2 on its line),
    // a crossing on an edge of B's cell is e2's: B's cell lies beyond the
    // normal at w, v's beyond the normal to e2 at v, e2's cell between
    // them.  The test of v below cannot tell: the disk tangent to B's line
    // through v touches the line at v, outside B, and its foot on e2 is
    // v's own (a polygon of land-10m whose cut made a hole's vertex flat
    // took v there: RESULTS.md, thirty-second session).
    std::vector<int>& gen = gen_;
    gen.assign(std::size_t(k), 0);
    int g = 0;
    for(int i = 0; i < k; ++i) {
      const int h = crossings[std::size_t(i)];
      if(flat_after_w != NO_INDEX && (hds_.face_of(h) == flat_after_w || face_across(h) == flat_after_w))
        g = 2;
      const Site_2 F = site(hds_.face_of(h)), G = site(face_across(h));
      if(g == 0) {
        Time t;
        if(!(traits_.compute_disk_foot_time_2_object()(e1_, F, e1_, G, t) && compare_(t, end_time(e1_)) == SMALLER))
          g = 1;
      }
      if(g == 1) {
        Time t;
        if(!(traits_.compute_disk_foot_time_2_object()(e2_, F, pv_, G, t) && compare_(t, start_time(e2_)) != LARGER))
          g = 2;
      }
      gen[std::size_t(i)] = g;
    }

    // The crossing vertices, on the crossed edges.
    std::vector<int>& cv = cross_vertices_;
    cv.assign(std::size_t(k), NO_INDEX);
    for(int i = 0; i < k; ++i) {
      const int h = crossings[std::size_t(i)];
      cv[std::size_t(i)] = hds_.new_pending_vertex(hds_.face_of(h), N[gen[std::size_t(i)]], face_across(h));
    }

    // The front, arc by arc: arc i runs in the cell F_i from a_i (u, or the
    // crossing vertex i-1) to b_i (the crossing vertex i, or w).
    std::vector<int> segs[3];   // the front edges along each new cell, in order (F on the left)
    int t1 = NO_INDEX, t2 = NO_INDEX;
    for(int i = 0; i <= k; ++i) {
      const int F = i < k ? hds_.face_of(crossings[std::size_t(i)]) : hds_.face_of(h_end);
      const int a = i == 0 ? vU : cv[std::size_t(i - 1)];
      const int bb = i == k ? vW : cv[std::size_t(i)];
      int ga = i == 0 ? 0 : gen[std::size_t(i - 1)];
      const int gb = i == k ? 2 : gen[std::size_t(i)];
      CGAL_assertion(ga <= gb);
      std::vector<int> arc;
      int from = a;
      while(ga < gb) {
        const int t = hds_.new_pending_vertex(F, N[ga], N[ga + 1]);
        (ga == 0 ? t1 : t2) = t;
        arc.push_back(front_edge(F, N[ga], from, t));
        segs[ga].push_back(arc.back());
        from = t;
        ++ga;
      }
      arc.push_back(front_edge(F, N[gb], from, bb));
      segs[gb].push_back(arc.back());
      // the cycle of F
      const int before = i == 0 ? hds_.prev(h0) : Hds::twin(crossings[std::size_t(i - 1)]);
      const int after = i == k ? hds_.next(h_end) : crossings[std::size_t(i)];
      hds_.link(before, arc.front());
      for(std::size_t j = 0; j + 1 < arc.size(); ++j) hds_.link(arc[j], arc[j + 1]);
      hds_.link(arc.back(), after);
      hds_.face(F).halfedge = arc.front();
    }
    CGAL_assertion(t1 != NO_INDEX && t2 != NO_INDEX);
    // the crossed edges keep their part on the kept side
    for(int i = 0; i < k; ++i) {
      const int h = crossings[std::size_t(i)];
      hds_.he(Hds::twin(h)).vertex = cv[std::size_t(i)];
      hds_.vertex(cv[std::size_t(i)]).halfedge = Hds::twin(h);
      hds_.set_zero_length(h, same_disk(cv[std::size_t(i)], hds_.target(h)));
      changed_.push_back(hds_.target(h));
    }

    // The boundary edges e1 and e2, the normals at v, the cycles of the new cells.
    const int e1b = hds_.new_edge(E1, OUTSIDE), e2b = hds_.new_edge(E2, OUTSIDE);
    hds_.he(e1b).vertex = vV; hds_.he(Hds::twin(e1b)).vertex = vU;
    hds_.he(e2b).vertex = vW; hds_.he(Hds::twin(e2b)).vertex = vV;
    const int n1 = hds_.new_edge(E1, PV), n2 = hds_.new_edge(PV, E2);
    hds_.he(n1).vertex = t1; hds_.he(Hds::twin(n1)).vertex = vV;
    hds_.he(n2).vertex = t2; hds_.he(Hds::twin(n2)).vertex = vV;
    // E1: e1b, n1, the front back to u
    hds_.link(e1b, n1);
    link_back(n1, segs[0], e1b);
    // PV: n1 reversed, n2, the front back to t1
    hds_.link(Hds::twin(n1), n2);
    link_back(n2, segs[1], Hds::twin(n1));
    // E2: e2b, the front back to t2, n2 reversed
    link_back(e2b, segs[2], Hds::twin(n2));
    hds_.link(Hds::twin(n2), e2b);
    hds_.face(E1).halfedge = e1b;
    hds_.face(PV).halfedge = n2;
    hds_.face(E2).halfedge = e2b;
    // the outside, along u, v, w
    const int outside = Hds::twin(b);
    hds_.link(hds_.prev(outside), Hds::twin(e2b));
    hds_.link(Hds::twin(e2b), Hds::twin(e1b));
    hds_.link(Hds::twin(e1b), hds_.next(outside));
    hds_.vertex(vV).halfedge = e1b;
    hds_.vertex(vU).halfedge = Hds::twin(e1b);
    hds_.vertex(vW).halfedge = e2b;

    // What goes.
    for(int e : marked_edges_) hds_.delete_edge(e);
    for(int x : touched_)
      if(state_[std::size_t(x)] == CONFLICT) {
        hds_.delete_vertex(x);
        ++stats_.removed_vertices;
      }
    for(int f : gone_faces) hds_.delete_face(f);
    end_marks();
    return std::make_pair(e1b, e2b);
  }

  const Hds& chds() const { return hds_; }
  int input_of(int v) const { return chds().vertex(v).input_point(); }
  int face_across(int h) const { return hds_.face_of(Hds::twin(h)); }
  bool is_point_at(int f, int point) const
  {
    const Hds_face& x = chds().face(f);
    return x.is_point && x.p0 == point;
  }

  void require(bool ok) const
  {
    if(ok) return;
    if(strict_) throw Merge_anomaly();
    CGAL_assertion_msg(false, "inconsistent cut");
    throw Merge_anomaly();
  }

  Site_2 site(int f) const
  {
    const Hds_face& x = chds().face(f);
    return x.is_point ? Site_2::point(points_[x.p0]) : Site_2::segment(points_[x.p0], points_[x.p1]);
  }
  // the site of a generator of a vertex's triple
  Site_2 triple_site(const int p[2]) const { return generator_site<Site_2>(points_, p); }
  // the generators that define vertex x (counter-clockwise around it)
  const Site_2* vertex_sites(int x)
  {
    require(!chds().vertex(x).is_corner());
    const auto& t = chds().disk(x).triple;
    require(t[0][0] != NO_INDEX);
    for(int i = 0; i < 3; ++i) sites_[i] = triple_site(t[i]);
    return sites_;
  }

  Time start_time(const Site_2& line) const { return traits_.compute_start_time_2_object()(line); }
  Time end_time(const Site_2& line) const { return traits_.compute_end_time_2_object()(line); }

  // ---- marks on vertices and edges, reset at the end ----
  void begin_marks()
  {
    if(state_.size() < hds_.vertex_capacity()) state_.resize(hds_.vertex_capacity(), UNKNOWN);
    if(edge_mark_.size() < hds_.halfedge_capacity() / 2) edge_mark_.resize(hds_.halfedge_capacity() / 2, 0);
    touched_.clear();
    marked_edges_.clear();
  }
  void end_marks()
  {
    for(int x : touched_) state_[std::size_t(x)] = UNKNOWN;
    for(int e : marked_edges_) edge_mark_[std::size_t(e >> 1)] = 0;
    for(int h : crossings_)
      if(std::size_t(h >> 1) < edge_mark_.size()) edge_mark_[std::size_t(h >> 1)] = 0;
    touched_.clear();
    marked_edges_.clear();
    crossings_.clear();
  }
  void set_state(int x, State s)
  {
    if(state_[std::size_t(x)] == UNKNOWN) touched_.push_back(x);
    state_[std::size_t(x)] = s;
  }
  void mark_edge(int h)
  {
    if(edge_mark_[std::size_t(h >> 1)]) return;
    edge_mark_[std::size_t(h >> 1)] = GONE;
    marked_edges_.push_back(h & ~1);
  }
  bool edge_marked(int h) const { return edge_mark_[std::size_t(h >> 1)] != 0; }

  // Whether vertex x lies in the new cells: its open disk meets e1 or e2.
  bool in_conflict(int x)
  {
    if(state_[std::size_t(x)] != UNKNOWN) return state_[std::size_t(x)] == CONFLICT;
    bool c = false;
    if(input_of(x) == NO_INDEX) {
      try {
        const Site_2* s = vertex_sites(x);
        c = meets(s, e1_, U_) || meets(s, e2_, W_);
      } catch(Uncertain_decision&) {
        // the generators that defined x give no disk (where more than three
        // meet): three consecutive ones around it, as resolve_vertex() does
        if(strict_) throw;
        c = meets_by_neighbours(x);
      }
    }
    set_state(x, c ? CONFLICT : KEPT);
    return c;
  }

  bool meets_by_neighbours(int x)
  {
    std::vector<int> faces;
    const int h0 = chds().vertex(x).halfedge;
    int h = h0;
    do {
      faces.push_back(hds_.face_of(h));
      h = Hds::twin(hds_.next(h));
    } while(h != h0 && faces.size() < 64);
    const std::size_t d = faces.size();
    for(std::size_t i = 0; i < d; ++i) {
      const int a = faces[(i + 2) % d], b = faces[(i + 1) % d], c = faces[i];
      if(a < 0 || b < 0 || c < 0) continue;
      const Site_2 s[3] = {site(a), site(b), site(c)};
      try {
        return meets(s, e1_, U_) || meets(s, e2_, W_);
      } catch(Uncertain_decision&) {
      }
    }
    throw Uncertain_decision();
  }

  // Whether the open disk of the sites `s` meets the new segment `e`, one
  // of whose ends is the old corner `corner` (Uncertain_decision if the
  // sites give no disk).  A disk through the corner
  // (the point generator there is one of its sites: a tie of the general
  // test, common) meets it exactly when the segment leaves the corner into
  // the disk: the centre's foot on the segment lies beyond the corner.
  bool meets(const Site_2* s, const Site_2& e, int corner)
  {
    for(int i = 0; i < 3; ++i)
      if(s[i].is_point && s[i].p == points_[corner]) {
        Time t;
        if(!traits_.compute_disk_foot_time_2_object()(e, s[0], s[1], s[2], t)) throw Uncertain_decision();
        return corner == U_ ? compare_(t, start_time(e)) == LARGER : compare_(t, end_time(e)) == SMALLER;
      }
    return traits_.do_intersect_disk_segment_2_object()(s[0], s[1], s[2], e);
  }

  // A new edge of the front from `from` to `to`, the kept cell F on its left.
  int front_edge(int F, int n, int from, int to)
  {
    const int h = hds_.new_edge(F, n);
    hds_.he(h).vertex = to;
    hds_.he(Hds::twin(h)).vertex = from;
    hds_.vertex(to).halfedge = h;
    if(same_disk(from, to)) hds_.set_zero_length(h, true);
    return h;
  }

  // Links `first`, the twins of `segs` in reverse order, then `last`.
  void link_back(int first, const std::vector<int>& segs, int last)
  {
    int p = first;
    for(auto it = segs.rbegin(); it != segs.rend(); ++it) {
      hds_.link(p, Hds::twin(*it));
      p = Hds::twin(*it);
    }
    hds_.link(p, last);
  }

  // Whether two vertices are one disk (four or more generators at a point).
  bool same_disk(int v, int w)
  {
    if(chds().vertex(v).is_corner() || chds().vertex(w).is_corner())
      return false;
    const auto &a = chds().disk(v), &b = chds().disk(w);
    if(a.triple[0][0] == NO_INDEX || b.triple[0][0] == NO_INDEX)
      return false;
    return traits_.equal_medial_disks_2_object()(
      triple_site(a.triple[0]), triple_site(a.triple[1]), triple_site(a.triple[2]),
      triple_site(b.triple[0]), triple_site(b.triple[1]), triple_site(b.triple[2]));
  }

  Hds& hds_;
  const std::vector<Point_2>& points_;
  const Traits& traits_;
  typename Traits::Compare_event_time_2 compare_;
  bool strict_ = false;
  Cut_statistics stats_;
  Site_2 e1_, e2_, pv_;
  int U_ = NO_INDEX, W_ = NO_INDEX;
  Site_2 sites_[3];
  std::vector<signed char> state_;
  std::vector<char> edge_mark_;
  std::vector<int> touched_, marked_edges_, gone_faces_, crossings_, gen_, cross_vertices_, changed_;
};

} // namespace internal
} // namespace Progressive_medial_axes
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_MEDIAL_AXIS_2_INTERNAL_MEDIAL_CUT_H
