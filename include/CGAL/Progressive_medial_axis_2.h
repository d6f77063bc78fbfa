// Copyright (c) 2026 The Progressive_medial_axis_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_PROGRESSIVE_MEDIAL_AXIS_2_H
#define CGAL_PROGRESSIVE_MEDIAL_AXIS_2_H

#include <CGAL/Progressive_medial_axis_traits_2.h>
#include <CGAL/Progressive_medial_axis_2/Medial_axis_2.h>
#include <CGAL/Progressive_medial_axis_2/Input_error.h>
#include <CGAL/Progressive_medial_axis_2/validate_polygon.h>
#include <CGAL/Progressive_medial_axis_2/internal/Merge.h>
#include <CGAL/Progressive_medial_axis_2/internal/Triangulate.h>
#include <CGAL/Progressive_medial_axis_2/internal/Growth_order.h>

#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_with_holes_2.h>

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <memory>
#include <vector>

namespace CGAL {

/*!
\ingroup PkgProgressiveMedialAxis2Ref
Counters and timings of a progressive computation.
*/
struct Progressive_medial_axis_statistics {
  std::size_t input_vertices = 0;
  std::size_t holes = 0;
  std::size_t triangles = 0;
  std::size_t merges = 0;          ///< merges done (one per shared edge of each triangle added)
  double validation_seconds = 0;
  double triangulation_seconds = 0;
  double merge_seconds = 0;       ///< total time spent in refinement steps
  std::size_t switches = 0;       ///< switch critical points traversed
  std::size_t vanishings = 0;     ///< vanishing critical points traversed
  std::size_t anomalies = 0;      ///< events forced to keep the topology valid (0 with exact decisions)
  std::size_t max_queue = 0;      ///< n_v: the largest priority queue of any merge
  std::vector<std::uint32_t> queue_per_step; ///< n_v of each merge, in step order
};

/*!
\ingroup PkgProgressiveMedialAxis2Ref
The default visitor of `Progressive_medial_axis_2`: does nothing.  A visitor
has `on_step(step, n_v)`, called after each refinement step with the step
number (1 for the first merge) and the largest queue size of that merge.
*/
struct Default_progressive_medial_axis_visitor {
  void on_step(std::size_t /*step*/, std::size_t /*n_v*/) {}
};

/*!
\ingroup PkgProgressiveMedialAxis2Ref

A region-growing progressive medial axis (Liu et al., 2016, section 6.1).

The polygon is cut into triangles by a constrained Delaunay triangulation.
Step 0 is the medial axis of one triangle (the largest); every further step
merges the next triangle of a breadth-first traversal of the triangulation's
dual graph into the grown shape, with the topology-oriented merge along the
shared edge.  After any step, `medial_axis()` is the exact-topology medial
axis of `current_shape()`; after the last step it is that of the polygon.

\tparam Traits a model of `ProgressiveMedialAxisTraits_2`; the default,
`Progressive_medial_axis_filtered_traits_2<>`, takes every decision exactly.
*/
template <class Traits_ = Progressive_medial_axis_filtered_traits_2<> >
class Progressive_medial_axis_2
{
public:
  typedef Traits_ Traits;
  typedef typename Traits::Kernel Kernel;
  typedef typename Traits::Point_2 Point_2;
  typedef typename Traits::FT FT;
  typedef CGAL::Polygon_2<Kernel> Polygon_2;
  typedef CGAL::Polygon_with_holes_2<Kernel> Polygon_with_holes_2;
  typedef CGAL::Medial_axis_2<Traits> Medial_axis;
  /// Rings: the outer ring first, then the holes; closing point not repeated.
  typedef std::vector<std::vector<Point_2> > Rings;

  /// Builds the progressive medial axis of a simple polygon and computes step 0.
  /// Throws `CGAL::PMA2::Input_error` if the polygon is not valid.
  explicit Progressive_medial_axis_2(const Polygon_2& polygon, const Traits& traits = Traits())
    : traits_(traits)
  {
    Rings rings(1);
    rings[0].assign(polygon.vertices_begin(), polygon.vertices_end());
    init(rings);
  }

  /// Builds the progressive medial axis of a polygon with holes.
  explicit Progressive_medial_axis_2(const Polygon_with_holes_2& polygon, const Traits& traits = Traits())
    : traits_(traits)
  {
    Rings rings;
    rings.emplace_back(polygon.outer_boundary().vertices_begin(), polygon.outer_boundary().vertices_end());
    for(auto h = polygon.holes_begin(); h != polygon.holes_end(); ++h)
      rings.emplace_back(h->vertices_begin(), h->vertices_end());
    init(rings);
  }

  /// Builds it from rings (ring 0 the outer ring, then the holes).
  explicit Progressive_medial_axis_2(const Rings& rings, const Traits& traits = Traits())
    : traits_(traits)
  {
    init(rings);
  }

  Progressive_medial_axis_2(const Progressive_medial_axis_2&) = delete;
  Progressive_medial_axis_2& operator=(const Progressive_medial_axis_2&) = delete;

  /// Number of refinement steps of the whole computation.  A step merges
  /// one triangle, or a few when one alone would make the shape touch itself
  /// at a vertex (see the user manual).
  std::size_t number_of_steps() const { return steps_.empty() ? 0 : steps_.size() - 1; }
  /// Steps done so far (0 right after construction).
  std::size_t current_step() const { return step_; }
  bool is_complete() const { return step_ == number_of_steps(); }

  /// Does one refinement step.  Returns false if the axis was already complete.
  bool refine()
  {
    Default_progressive_medial_axis_visitor v;
    return refine(v);
  }

  template <class Visitor>
  bool refine(Visitor& visitor)
  {
    if(is_complete())
      return false;
    auto start = std::chrono::steady_clock::now();
    ++step_;
    std::size_t step_queue = 0;
    for(int t : steps_[step_]) {
      const PMA2::internal::Triangle& T = triangles_[t];
      // the edges it shares with the grown shape: merge along the first one,
      // then along the others, whose two sides are then in the same shape
      int shared[3], ns = 0;
      for(int e = 0; e < 3; ++e)
        if(T.nbr[e] >= 0 && added_[T.nbr[e]]) shared[ns++] = e;
      CGAL_assertion(ns > 0);
      build_triangle(t, shared[0]);
      added_[t] = 1;
      for(int k = 0; k < ns; ++k) {
        const int e = shared[k], u = T.nbr[e];
        int eu = 0;
        while(triangles_[u].nbr[eu] != t) ++eu;
        PMA2::internal::Merge_statistics ms = merger_->merge(tri_he_[3 * u + eu], tri_he_[3 * t + e]);
        stats_.switches += ms.switches;
        stats_.vanishings += ms.vanishings;
        stats_.anomalies += ms.anomalies;
        ++stats_.merges;
        step_queue = (std::max)(step_queue, ms.max_queue);
      }
    }
    if(step_queue > stats_.max_queue) stats_.max_queue = step_queue;
    stats_.queue_per_step.push_back(std::uint32_t(step_queue));
    stats_.merge_seconds += seconds_since(start);
    visitor.on_step(step_, step_queue);
    return true;
  }

  /// Runs all remaining steps.
  void refine_all()
  {
    Default_progressive_medial_axis_visitor v;
    refine_all(v);
  }

  template <class Visitor>
  void refine_all(Visitor& visitor)
  {
    while(refine(visitor)) {}
  }

  /// Runs steps until `current_step() == step` (or the end).
  void refine_to(std::size_t step)
  {
    while(step_ < step && refine()) {}
  }

  /// The medial axis of the current shape.
  const Medial_axis& medial_axis() const { return axis_; }

  /// Gives up the medial axis (the object cannot be refined any more).
  Medial_axis release_medial_axis()
  {
    merger_.reset();
    steps_.clear();
    step_ = 0;
    return std::move(axis_);
  }

  /// The current shape (the union of the triangles merged so far), as a
  /// polygon with holes: outer boundary counter-clockwise, holes clockwise.
  Polygon_with_holes_2 current_shape() const
  {
    std::vector<std::vector<int> > cycles = axis_.boundary_cycles();
    Polygon_with_holes_2 result;
    bool first = true;
    for(const std::vector<int>& c : cycles) {
      Polygon_2 ring;
      for(int i : c) ring.push_back(axis_.points()[i]);
      if(first || ring.orientation() == COUNTERCLOCKWISE) {
        result = Polygon_with_holes_2(ring);
        first = false;
      } else {
        result.add_hole(ring);
      }
    }
    return result;
  }

  const Progressive_medial_axis_statistics& statistics() const { return stats_; }
  const Traits& traits() const { return traits_; }

private:
  typedef PMA2::internal::Halfedge_structure<Point_2, FT> Hds;

  static double seconds_since(std::chrono::steady_clock::time_point t)
  {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
  }

  void init(const Rings& rings)
  {
    auto t0 = std::chrono::steady_clock::now();
    PMA2::validate_polygon_rings<Kernel>(rings);
    stats_.validation_seconds = seconds_since(t0);

    // Points, with their ring, index and successor along the ring with the
    // interior on the left.
    typename Kernel::Orientation_2 orientation = traits_.orientation_2_object();
    std::size_t n = 0;
    for(const auto& r : rings) n += r.size();
    axis_.points_.reserve(n);
    axis_.info_.resize(n);
    std::vector<int> ring_start;
    for(std::size_t r = 0; r < rings.size(); ++r) {
      ring_start.push_back(int(axis_.points_.size()));
      const auto& ring = rings[r];
      int base = int(axis_.points_.size());
      int m = int(ring.size());
      // orientation of the ring at its lexicographically smallest vertex
      int lo = 0;
      for(int i = 1; i < m; ++i)
        if(ring[i].x() < ring[lo].x() || (ring[i].x() == ring[lo].x() && ring[i].y() < ring[lo].y())) lo = i;
      Orientation o = orientation(ring[(lo + m - 1) % m], ring[lo], ring[(lo + 1) % m]);
      bool ccw = (o == LEFT_TURN);
      bool reversed = (r == 0) ? !ccw : ccw;   // holes run clockwise inside
      for(int i = 0; i < m; ++i) {
        axis_.points_.push_back(ring[i]);
        typename Medial_axis::Point_info& info = axis_.info_[base + i];
        info.ring = int(r);
        info.index = i;
        info.reversed = reversed;
        info.next = reversed ? base + (i + m - 1) % m : base + (i + 1) % m;
      }
    }
    ring_start.push_back(int(axis_.points_.size()));
    stats_.input_vertices = n;
    stats_.holes = rings.size() - 1;

    t0 = std::chrono::steady_clock::now();
    triangles_ = PMA2::internal::triangulate_rings(axis_.points_, ring_start);
    stats_.triangles = triangles_.size();
    steps_ = PMA2::internal::Growth_order(triangles_, n, largest_triangle()).steps();
    stats_.triangulation_seconds = seconds_since(t0);

    added_.assign(triangles_.size(), 0);
    tri_he_.assign(3 * triangles_.size(), PMA2::internal::NO_INDEX);
    axis_.hds_.reserve(2 * n + 16, 4 * n + 16);
    merger_.reset(new PMA2::internal::Medial_merge<Traits>(axis_.hds_, axis_.points_, traits_));
    step_ = 0;
    auto t1 = std::chrono::steady_clock::now();
    build_triangle(steps_[0][0], -1);
    added_[steps_[0][0]] = 1;
    stats_.merge_seconds = seconds_since(t1);
  }

  // The triangle of largest area: the start of the growth.
  int largest_triangle() const
  {
    int start = 0;
    double best = -1;
    for(std::size_t t = 0; t < triangles_.size(); ++t) {
      const PMA2::internal::Triangle& T = triangles_[t];
      std::pair<double, double> a = Medial_axis::to_xy(axis_.points_[T.v[0]]);
      std::pair<double, double> b = Medial_axis::to_xy(axis_.points_[T.v[1]]);
      std::pair<double, double> c = Medial_axis::to_xy(axis_.points_[T.v[2]]);
      double area = (b.first - a.first) * (c.second - a.second) - (b.second - a.second) * (c.first - a.first);
      if(area > best) { best = area; start = int(t); }
    }
    return start;
  }

  // The medial axis of one triangle: three bisectors meeting at the
  // incentre.  Each corner is a vertex of its own, except the two ends of the
  // edge `attach` (-1 for none), which are the corners of the grown shape
  // across that edge: the triangle is merged along it next.
  void build_triangle(int t, int attach)
  {
    Hds& hds = axis_.hds_;
    const PMA2::internal::Triangle& T = triangles_[t];
    const int i0 = T.v[0], i1 = T.v[1], i2 = T.v[2];
    int V[3];
    for(int i = 0; i < 3; ++i) V[i] = PMA2::internal::NO_INDEX;
    if(attach >= 0) {
      // the shape's half-edge across the edge runs from v[attach+2] to v[attach+1]
      const int u = T.nbr[attach];
      int eu = 0;
      while(triangles_[u].nbr[eu] != t) ++eu;
      const int h = tri_he_[3 * u + eu];
      V[(attach + 1) % 3] = hds.target(h);
      V[(attach + 2) % 3] = hds.source(h);
    }
    for(int i = 0; i < 3; ++i)
      if(V[i] == PMA2::internal::NO_INDEX) V[i] = hds.new_vertex(axis_.points_[T.v[i]], FT(0), T.v[i]);
    const int V0 = V[0], V1 = V[1], V2 = V[2];
    const int Fa = hds.new_face(false, i0, i1);   // edge 2 of the triangle
    const int Fb = hds.new_face(false, i1, i2);   // edge 0
    const int Fc = hds.new_face(false, i2, i0);   // edge 1
    const int VI = hds.new_pending_vertex(Fa, Fb, Fc);   // the incentre
    const int ba = hds.new_edge(Fa, PMA2::internal::OUTSIDE);
    const int bb = hds.new_edge(Fb, PMA2::internal::OUTSIDE);
    const int bc = hds.new_edge(Fc, PMA2::internal::OUTSIDE);
    hds.he(ba).vertex = V1; hds.he(ba ^ 1).vertex = V0;
    hds.he(bb).vertex = V2; hds.he(bb ^ 1).vertex = V1;
    hds.he(bc).vertex = V0; hds.he(bc ^ 1).vertex = V2;
    const int s1 = hds.new_edge(Fa, Fb);   // V1 -> I in Fa
    const int s2 = hds.new_edge(Fb, Fc);   // V2 -> I in Fb
    const int s0 = hds.new_edge(Fc, Fa);   // V0 -> I in Fc
    hds.he(s1).vertex = VI; hds.he(s1 ^ 1).vertex = V1;
    hds.he(s2).vertex = VI; hds.he(s2 ^ 1).vertex = V2;
    hds.he(s0).vertex = VI; hds.he(s0 ^ 1).vertex = V0;
    hds.link(ba, s1); hds.link(s1, s0 ^ 1); hds.link(s0 ^ 1, ba);
    hds.link(bb, s2); hds.link(s2, s1 ^ 1); hds.link(s1 ^ 1, bb);
    hds.link(bc, s0); hds.link(s0, s2 ^ 1); hds.link(s2 ^ 1, bc);
    hds.link(ba ^ 1, bc ^ 1); hds.link(bc ^ 1, bb ^ 1); hds.link(bb ^ 1, ba ^ 1);
    hds.face(Fa).halfedge = ba;
    hds.face(Fb).halfedge = bb;
    hds.face(Fc).halfedge = bc;
    hds.vertex(VI).halfedge = s1;
    if(hds.vertex(V0).halfedge == PMA2::internal::NO_INDEX) hds.vertex(V0).halfedge = bc;
    if(hds.vertex(V1).halfedge == PMA2::internal::NO_INDEX) hds.vertex(V1).halfedge = ba;
    if(hds.vertex(V2).halfedge == PMA2::internal::NO_INDEX) hds.vertex(V2).halfedge = bb;
    tri_he_[3 * t + 2] = ba;
    tri_he_[3 * t + 0] = bb;
    tri_he_[3 * t + 1] = bc;
  }

  Traits traits_;
  Medial_axis axis_;
  std::unique_ptr<PMA2::internal::Medial_merge<Traits> > merger_;
  std::vector<PMA2::internal::Triangle> triangles_;
  std::vector<std::vector<int> > steps_;   // triangles added by each step
  std::vector<char> added_;
  std::vector<int> tri_he_;                // boundary half-edge of each triangle edge
  std::size_t step_ = 0;
  Progressive_medial_axis_statistics stats_;
};

/*!
\ingroup PkgProgressiveMedialAxis2Ref
Computes the medial axis of a polygon (one shot).  Throws
`CGAL::PMA2::Input_error` if the polygon is not valid.
*/
template <class Traits>
Medial_axis_2<Traits> medial_axis_2(const typename Progressive_medial_axis_2<Traits>::Polygon_2& polygon,
                                    const Traits& traits)
{
  Progressive_medial_axis_2<Traits> pma(polygon, traits);
  pma.refine_all();
  return pma.release_medial_axis();
}

template <class Traits>
Medial_axis_2<Traits> medial_axis_2(const typename Progressive_medial_axis_2<Traits>::Polygon_with_holes_2& polygon,
                                    const Traits& traits)
{
  Progressive_medial_axis_2<Traits> pma(polygon, traits);
  pma.refine_all();
  return pma.release_medial_axis();
}

/// One-shot medial axis with the default (filtered, exact-decision) traits.
template <class K>
Medial_axis_2<Progressive_medial_axis_filtered_traits_2<K> > medial_axis_2(const Polygon_2<K>& polygon)
{
  return medial_axis_2<Progressive_medial_axis_filtered_traits_2<K> >(polygon, Progressive_medial_axis_filtered_traits_2<K>());
}

} // namespace CGAL

#endif // CGAL_PROGRESSIVE_MEDIAL_AXIS_2_H
