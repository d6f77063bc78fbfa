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
// The engine of the package: the data of a medial axis (input points, the
// half-edge structure of the generator cells) and the two operations that
// every driver builds on:
//   - add_triangle(): the medial axis of one triangle, a new component;
//   - merge(): the topology-oriented merge of two cells along the segment
//     they share (Merge.h).
// Drivers (region growing, and the ones to come: divide and conquer,
// boundary evolution) decide which triangles to add and which segments to
// merge along; they never write into the half-edge structure themselves.
// The view (Medial_axis_2) reads the same data.

#ifndef CGAL_PROGRESSIVE_MEDIAL_AXIS_2_INTERNAL_MEDIAL_AXIS_ENGINE_H
#define CGAL_PROGRESSIVE_MEDIAL_AXIS_2_INTERNAL_MEDIAL_AXIS_ENGINE_H

#include <CGAL/Progressive_medial_axis_2/internal/Halfedge_structure.h>
#include <CGAL/Progressive_medial_axis_2/internal/Merge.h>
#include <CGAL/Progressive_medial_axis_2/internal/Medial_cut.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <memory>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Progressive_medial_axes {
namespace internal {

/// An input point: its ring (0 the outer ring, k the k-th hole), its index
/// in the ring as written, and its successor along the ring with the
/// interior on the left.
struct Point_info {
  int ring : 31;
  bool reversed : 1;      // the ring was given in the other orientation
  int index = -1;
  int next = -1;
  // the input edge from this point to `next` (ring, index as written); where
  // rings touch, `next` joins the corners of the interior (see set_points())
  int edge_ring = -1, edge_index = -1;

  // (20 bytes, not 24: 2.4 MB of the peak of a one-shot of 600,000 points)
  Point_info() : ring(-1), reversed(false) {}
};

/// The data of a medial axis: the input points and the half-edge structure.
template <class Point_2, class FT>
struct Medial_axis_data {
  typedef Halfedge_structure<Point_2, FT> Hds;
  Hds hds;
  std::vector<Point_2> points;
  std::vector<Point_info> info;
  std::vector<int> ring_start;   // the points of ring r are [ring_start[r], ring_start[r+1])
};

/// The model with exact decisions that redoes a merge of the traits
/// `Traits` when it meets an anomaly: none by default (see the traits).
template <class Traits>
struct Exact_fallback {
  typedef void type;
};

// Counts the events of a merge that may be undone, to report them once it stands.
struct Recording_merge_visitor {
  std::size_t switches = 0, vanishings = 0;
  void on_switch() { ++switches; }
  void on_vanish() { ++vanishings; }
  template <class Visitor>
  void replay(Visitor& v) const
  {
    for(std::size_t i = 0; i < switches; ++i) v.on_switch();
    for(std::size_t i = 0; i < vanishings; ++i) v.on_vanish();
  }
};

template <class Traits>
class Medial_axis_engine
{
public:
  typedef typename Traits::Point_2 Point_2;
  typedef typename Traits::FT FT;
  typedef typename Traits::Site_2 Site_2;
  typedef Medial_axis_data<Point_2, FT> Data;
  typedef typename Data::Hds Hds;

  Medial_axis_engine(Data& data, const Traits& traits)
    : Medial_axis_engine(data.hds, data.points, traits)
  {
    data_ = &data;
  }

  /// An engine that works on a structure of its own over shared input
  /// points (a part of a divide and conquer, built by another thread).
  Medial_axis_engine(Hds& hds, const std::vector<Point_2>& points, const Traits& traits)
    : hds_(hds), points_(points), traits_(traits), merge_(hds, points, traits), cut_(hds, points, traits)
  {
    if constexpr(Has_fallback) {
      exact_merge_.reset(new Medial_merge<Fallback>(hds, points, exact_traits_));
      exact_cut_.reset(new Medial_cut<Fallback>(hds, points, exact_traits_));
      merge_.set_strict(true);
      cut_.set_strict(true);
    }
  }

  /// The data, for an engine built on it.
  Data& data() { return *data_; }
  const Data& data() const { return *data_; }
  Hds& hds() { return hds_; }
  const std::vector<Point_2>& points() const { return points_; }
  const Traits& traits() const { return traits_; }

  int source(int h) const { return hds_.source(h); }
  int target(int h) const { return hds_.target(h); }

  /// Adds the medial axis of the triangle of input points `v[0], v[1],
  /// v[2]` (counter-clockwise) as a new component: three bisectors meeting
  /// at the incentre.  `corner[i]` is an existing vertex of the structure to
  /// use as the corner at `v[i]` (a corner of the shape across the side the
  /// triangle will be merged along), or NO_INDEX for a new one.  Returns the
  /// boundary half-edges of the sides: side i runs from `v[i+1]` to
  /// `v[i+2]`, with the triangle on its left.
  std::array<int, 3> add_triangle(const int v[3], const int corner[3])
  {
    Hds& hds = hds_;
    int V[3];
    for(int i = 0; i < 3; ++i)
      V[i] = corner[i] != NO_INDEX ? corner[i] : hds.new_corner(v[i]);
    const int Fa = hds.new_face(false, v[0], v[1]);   // side 2
    const int Fb = hds.new_face(false, v[1], v[2]);   // side 0
    const int Fc = hds.new_face(false, v[2], v[0]);   // side 1
    const int VI = hds.new_pending_vertex(Fa, Fb, Fc); // the incentre
    const int ba = hds.new_edge(Fa, OUTSIDE);
    const int bb = hds.new_edge(Fb, OUTSIDE);
    const int bc = hds.new_edge(Fc, OUTSIDE);
    hds.he(ba).vertex = V[1]; hds.he(ba ^ 1).vertex = V[0];
    hds.he(bb).vertex = V[2]; hds.he(bb ^ 1).vertex = V[1];
    hds.he(bc).vertex = V[0]; hds.he(bc ^ 1).vertex = V[2];
    const int s1 = hds.new_edge(Fa, Fb);   // V1 -> I in Fa
    const int s2 = hds.new_edge(Fb, Fc);   // V2 -> I in Fb
    const int s0 = hds.new_edge(Fc, Fa);   // V0 -> I in Fc
    hds.he(s1).vertex = VI; hds.he(s1 ^ 1).vertex = V[1];
    hds.he(s2).vertex = VI; hds.he(s2 ^ 1).vertex = V[2];
    hds.he(s0).vertex = VI; hds.he(s0 ^ 1).vertex = V[0];
    hds.link(ba, s1); hds.link(s1, s0 ^ 1); hds.link(s0 ^ 1, ba);
    hds.link(bb, s2); hds.link(s2, s1 ^ 1); hds.link(s1 ^ 1, bb);
    hds.link(bc, s0); hds.link(s0, s2 ^ 1); hds.link(s2 ^ 1, bc);
    hds.link(ba ^ 1, bc ^ 1); hds.link(bc ^ 1, bb ^ 1); hds.link(bb ^ 1, ba ^ 1);
    hds.face(Fa).halfedge = ba;
    hds.face(Fb).halfedge = bb;
    hds.face(Fc).halfedge = bc;
    hds.vertex(VI).halfedge = s1;
    if(hds.vertex(V[0]).halfedge == NO_INDEX) hds.vertex(V[0]).halfedge = bc;
    if(hds.vertex(V[1]).halfedge == NO_INDEX) hds.vertex(V[1]).halfedge = ba;
    if(hds.vertex(V[2]).halfedge == NO_INDEX) hds.vertex(V[2]).halfedge = bb;
    return {{bb, bc, ba}};
  }

  /// Adds the triangle `v` next to the grown shape: its side `e` (from
  /// `v[e+1]` to `v[e+2]`) lies on the shape's boundary half-edge `h`
  /// (from `v[e+2]` to `v[e+1]`), whose end vertices become the triangle's
  /// corners there.  The sides are returned as by add_triangle(); the merge
  /// along `h` is left to the caller.
  std::array<int, 3> add_triangle_across(const int v[3], int e, int h)
  {
    int corner[3] = {NO_INDEX, NO_INDEX, NO_INDEX};
    corner[(e + 1) % 3] = target(h);
    corner[(e + 2) % 3] = source(h);
    return add_triangle(v, corner);
  }

  /// Merges the two cells of the segment PQ shared by two components (or
  /// by two sides of one): `hp` is the boundary half-edge from P to Q of
  /// one side, `hm` the boundary half-edge from Q to P of the other.
  template <class Visitor>
  Merge_statistics merge(int hp, int hm, Visitor& visitor)
  {
    if constexpr(Has_fallback) {
      // Inexact decisions: a merge that meets an anomaly is undone and
      // redone with exact decisions (as VRONI recovers at a higher level
      // of precision).
      Recording_merge_visitor recording;
      Merge_statistics s;
      if(try_inexactly([&] {
           s = merge_.merge(hp, hm, recording);
           check_new_vertices();
         })) {
        recording.replay(visitor);
        return s;
      }
      s = exact_merge_->merge(hp, hm, visitor);
      s.redone_exactly = true;
      return s;
    } else {
      return merge_.merge(hp, hm, visitor);
    }
  }

  /// Cuts the triangle (u, v, w) out of the shape: `b` is the boundary
  /// half-edge from u to w, `v` an input point inside the shape where u, v,
  /// w turn right (Medial_cut.h).  Returns the new boundary half-edges from
  /// u to v and from v to w.
  std::pair<int, int> cut(int b, int v, Cut_statistics& stats) { return local_update(true, b, v, stats); }

  /// Puts the input point `v` back into the boundary edge `b` (from u to w,
  /// v inside the segment uw).  Returns the new boundary half-edges.
  std::pair<int, int> split(int b, int v, Cut_statistics& stats) { return local_update(false, b, v, stats); }

  /// Computes the coordinates and radius of every vertex created since the
  /// last call that is still alive and pending.
  void resolve_pending()
  {
    Hds& hds = hds_;
    for(int v : hds.take_pending())
      if(hds.vertex(v).alive && hds.vertex(v).pending) resolve(v);
  }

  // The double model's check of a merge: every vertex it created or whose
  // cells it changed (the vertices of the two cells of the separator) is the centre of a disk that touches the generators of all the
  // cells around it (within a relative 1e-9), on the segments themselves;
  // else the merge is redone with exact decisions.  This catches the events
  // that a wrong decision on nearly degenerate input created.
  void check_new_vertices()
  {
    std::vector<int> vertices = hds_.pending_in_journal();
    merge_.for_each_switch_vertex([&](int w) { vertices.push_back(w); });
    check_vertices(vertices);
  }

  void check_vertices(const std::vector<int>& vertices)
  {
    Hds& hds = hds_;
    for(int v : vertices) {
      const auto& x = static_cast<const Hds&>(hds).vertex(v);
      if(!x.alive || x.is_corner() || x.halfedge == NO_INDEX) continue;
      const auto& disk = static_cast<const Hds&>(hds).disk(v);
      Point_2 c = disk.point;
      FT r = disk.radius;
      if(x.pending) {
        auto site_of = [&](const int p[2]) { return generator_site<Site_2>(points_, p); };
        if(!traits_.construct_medial_disk_2_object()(site_of(disk.triple[0]), site_of(disk.triple[1]), site_of(disk.triple[2]), c, r))
          throw Uncertain_decision();
      }
      const double cx = CGAL::to_double(c.x()), cy = CGAL::to_double(c.y()), rr = CGAL::to_double(r);
      double scale = std::fabs(cx) + std::fabs(cy) + rr;
      const int h0 = x.halfedge;
      int h = h0;
      do {
        const int f = hds.face_of(h);
        if(f >= 0) {
          const auto& F = static_cast<const Hds&>(hds).face(f);
          const double ax = CGAL::to_double(points_[F.p0].x()), ay = CGAL::to_double(points_[F.p0].y());
          const double bx = CGAL::to_double(points_[F.p1].x()), by = CGAL::to_double(points_[F.p1].y());
          scale = (std::max)(scale, (std::max)((std::max)(std::fabs(ax), std::fabs(ay)), (std::max)(std::fabs(bx), std::fabs(by))));
          const double d = distance_to_segment(cx, cy, ax, ay, bx, by);
          if(!(std::fabs(d - rr) <= 1e-9 * scale)) throw Uncertain_decision();
        }
        h = Hds::twin(hds.next(h));
      } while(h != h0);
    }
  }

  static double distance_to_segment(double px, double py, double ax, double ay, double bx, double by)
  {
    const double dx = bx - ax, dy = by - ay, l2 = dx * dx + dy * dy;
    double t = l2 > 0 ? ((px - ax) * dx + (py - ay) * dy) / l2 : 0;
    t = t < 0 ? 0 : (t > 1 ? 1 : t);
    const double ex = px - ax - t * dx, ey = py - ay - t * dy;
    return std::sqrt(ex * ex + ey * ey);
  }

  void resolve(int v)
  {
    resolve_vertex(hds_, v, points_, traits_, [this](int f) { return merge_.site(f); });
  }

private:
  // A cut or a split; with inexact decisions, undone and redone with exact
  // decisions when it meets an anomaly (as a merge is).
  std::pair<int, int> local_update(bool is_cut, int b, int v, Cut_statistics& stats)
  {
    if constexpr(Has_fallback) {
      std::pair<int, int> r;
      if(try_inexactly([&] {
           r = is_cut ? cut_.cut(b, v) : cut_.split(b, v);
           std::vector<int> vertices = hds_.pending_in_journal();
           vertices.insert(vertices.end(), cut_.changed_vertices().begin(), cut_.changed_vertices().end());
           check_vertices(vertices);
         })) {
        stats = cut_.statistics();
        return r;
      }
      r = is_cut ? exact_cut_->cut(b, v) : exact_cut_->split(b, v);
      stats = exact_cut_->statistics();
      stats.redone_exactly = true;
      return r;
    } else {
      const std::pair<int, int> r = is_cut ? cut_.cut(b, v) : cut_.split(b, v);
      stats = cut_.statistics();
      return r;
    }
  }

  // Runs `op` (a change of the structure with inexact decisions) under the
  // journal; undoes it and returns false if it met an anomaly or a decision
  // too close to call.
  template <class Op>
  bool try_inexactly(const Op& op)
  {
    hds_.begin_journal();
    try {
      op();
      hds_.end_journal();
      return true;
    } catch(Merge_anomaly&) {
    } catch(Uncertain_decision&) {
    } catch(...) {
      hds_.rollback();
      hds_.end_journal();
      throw;
    }
    hds_.rollback();
    hds_.end_journal();
    return false;
  }

  typedef typename Exact_fallback<Traits>::type Fallback;
  static constexpr bool Has_fallback = !std::is_void<Fallback>::value;
  typedef typename std::conditional<Has_fallback, Fallback, Traits>::type Fallback_traits;

  Hds& hds_;
  const std::vector<Point_2>& points_;
  Data* data_ = nullptr;
  const Traits& traits_;
  Medial_merge<Traits> merge_;
  Fallback_traits exact_traits_;
  std::unique_ptr<Medial_merge<Fallback_traits> > exact_merge_;
  Medial_cut<Traits> cut_;
  std::unique_ptr<Medial_cut<Fallback_traits> > exact_cut_;
};

} // namespace internal
} // namespace Progressive_medial_axes
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_MEDIAL_AXIS_2_INTERNAL_MEDIAL_AXIS_ENGINE_H
