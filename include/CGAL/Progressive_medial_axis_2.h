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

#ifndef CGAL_PROGRESSIVE_MEDIAL_AXIS_2_H
#define CGAL_PROGRESSIVE_MEDIAL_AXIS_2_H

#include <CGAL/license/Progressive_medial_axis_2.h>

#include <CGAL/Progressive_medial_axis_traits_2.h>
#include <CGAL/Progressive_medial_axis_2/Medial_axis_2.h>
#include <CGAL/Progressive_medial_axis_2/Input_error.h>
#include <CGAL/Progressive_medial_axis_2/Progressive_medial_axis_visitor_2.h>
#include <CGAL/Progressive_medial_axis_2/validate_polygon.h>
#include <CGAL/Progressive_medial_axis_2/internal/Input_conversion.h>
#include <CGAL/Progressive_medial_axis_2/internal/Medial_axis_engine.h>
#include <CGAL/Progressive_medial_axis_2/internal/Region_growing.h>
#include <CGAL/Progressive_medial_axis_2/internal/Boundary_evolution.h>
#include <CGAL/Progressive_medial_axis_2/internal/Divide_and_conquer.h>
#include <CGAL/Progressive_medial_axis_2/internal/Split_triangulation.h>

#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_with_holes_2.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <exception>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>
#include <type_traits>
#include <vector>

#ifdef CGAL_PMA2_USE_TBB
#include <tbb/parallel_invoke.h>
#include <tbb/task_arena.h>
#endif

namespace CGAL {

namespace Progressive_medial_axes {
namespace internal {

// The event counts of a divide and conquer into the statistics.
inline void copy_counts(Progressive_medial_axis_statistics& s, const Divide_and_conquer_counts& c)
{
  s.merges = c.merges;
  s.switches = c.switches;
  s.vanishings = c.vanishings;
  s.anomalies = c.anomalies;
  s.undecided_ties = c.undecided_ties;
  s.redone_merges = c.redone_merges;
  s.max_queue = c.max_queue;
}

} // namespace internal
} // namespace Progressive_medial_axes

/*!
\ingroup PkgProgressiveMedialAxis2Ref
Whether the constructors of `Progressive_medial_axis_2` check the input
polygon.  A valid polygon with holes is a precondition; with `CHECK_INPUT`
(the default) an invalid one throws `Progressive_medial_axes::Input_error`,
with `TRUST_INPUT` the check (O(n log n)) is skipped and invalid input has
undefined results.  `Progressive_medial_axes::validate_polygon()` runs the
check alone.
*/
enum Medial_axis_input_check { CHECK_INPUT, TRUST_INPUT };

/*!
\ingroup PkgProgressiveMedialAxis2Ref
The two progressive modes of the paper (Liu et al., 2016, section 6), the
driver of a `Progressive_medial_axis_2`.
*/
enum Progressive_medial_axis_driver {
  /// section 6.1: triangles of a constrained Delaunay triangulation added
  /// one by one, breadth first from the largest
  REGION_GROWING,
  /// section 6.2: the boundary simplified by discrete curve evolution, then
  /// refined vertex by vertex
  BOUNDARY_EVOLUTION
};

/*!
\ingroup PkgProgressiveMedialAxis2Ref

A progressive medial axis (Liu et al., 2016, section 6): a coarse shape's
medial axis at step 0, refined step by step until it is the medial axis of
the polygon.  After any step, `medial_axis()` is the medial axis of
`current_shape()`; after the last step it is that of the polygon.  Two
drivers decide the steps (`Progressive_medial_axis_driver`):

<b>Region growing</b> (the default, section 6.1).  The polygon is cut into
triangles by a constrained Delaunay triangulation.  Step 0 is the medial
axis of one triangle (the largest); every further step merges the next
triangle of a breadth-first traversal of the triangulation's dual graph
into the grown shape, with the topology-oriented merge along the shared
edge.

<b>Boundary evolution</b> (section 6.2).  The boundary is simplified by
discrete curve evolution (Latecki and Lakaemper): a vertex of least
relevance K = beta l1 l2 / (l1 + l2) (beta the turning angle, l1 and l2 the
lengths of its two edges relative to the total boundary length) is
removed, its two edges replaced by one segment, as long as the shape stays
valid; every ring down to a triangle.  Holes are not filled: they are
there from step 0 on, as triangles.  Step 0 is the medial axis of the
coarsest shape (computed in one shot); every further step puts back one
vertex, the last removed first: a triangle added outside the shape (a
merge), cut out of it (a local update of the cells the two new edges
touch), or a straight vertex put back into an edge.  The shapes look like
the whole outline at a lower resolution.

The input is any \cgal polygon (`Polygon_2`, `Polygon_with_holes_2`, of any
kernel and container) or a range of rings (ranges of points of a \cgal
kernel: the outer ring, then the holes); its points are converted to the
traits' kernel.

Thread safety: the const member functions, and the const functions of the
axis returned by `medial_axis()`, may be called from several threads at once;
`refine()` needs exclusive access.

\tparam Traits a model of `ProgressiveMedialAxisTraits_2`; the default,
`Progressive_medial_axis_traits_2<Exact_predicates_inexact_constructions_kernel>`,
takes every decision exactly.
*/
template <class Traits_ = Progressive_medial_axis_traits_2<Exact_predicates_inexact_constructions_kernel> >
class Progressive_medial_axis_2
{
public:
  typedef Traits_ Traits;
  typedef typename Traits::Kernel Kernel;
  typedef typename Kernel::Point_2 Point_2;
  typedef typename Kernel::FT FT;
  typedef CGAL::Polygon_2<Kernel> Polygon_2;
  typedef CGAL::Polygon_with_holes_2<Kernel> Polygon_with_holes_2;
  typedef CGAL::Medial_axis_2<Kernel> Medial_axis;
  typedef Progressive_medial_axis_statistics Statistics;

  /// Builds the progressive medial axis of a simple polygon (of any kernel)
  /// and computes step 0.  Throws `Progressive_medial_axes::Input_error` if
  /// the polygon is not valid.
  template <class K2, class Container>
  explicit Progressive_medial_axis_2(const CGAL::Polygon_2<K2, Container>& polygon, const Traits& traits = Traits(),
                                     Medial_axis_input_check check = CHECK_INPUT)
    : traits_(traits)
  {
    init(Progressive_medial_axes::internal::rings_of<Kernel>(polygon), check);
  }

  /// Builds the progressive medial axis of a polygon with holes.
  template <class K2, class Container>
  explicit Progressive_medial_axis_2(const CGAL::Polygon_with_holes_2<K2, Container>& polygon,
                                     const Traits& traits = Traits(), Medial_axis_input_check check = CHECK_INPUT)
    : traits_(traits)
  {
    init(Progressive_medial_axes::internal::rings_of<Kernel>(polygon), check);
  }

  /// Builds it from a range of rings (ring 0 the outer ring, then the
  /// holes), each a range of points of a \cgal kernel.
  template <class Ring_range>
  explicit Progressive_medial_axis_2(const Ring_range& rings, const Traits& traits = Traits(),
                                     Medial_axis_input_check check = CHECK_INPUT)
    : traits_(traits)
  {
    init(Progressive_medial_axes::internal::rings_of<Kernel>(rings), check);
  }

  /// Builds the progressive medial axis of `polygon` (a `Polygon_2`, a
  /// `Polygon_with_holes_2` or a range of rings, as above) with the driver
  /// `driver`, and computes step 0.
  template <class Input>
  Progressive_medial_axis_2(const Input& polygon, Progressive_medial_axis_driver driver,
                            const Traits& traits = Traits(), Medial_axis_input_check check = CHECK_INPUT)
    : traits_(traits), driver_kind_(driver)
  {
    init(Progressive_medial_axes::internal::rings_of<Kernel>(polygon), check);
  }

  Progressive_medial_axis_2(const Progressive_medial_axis_2&) = delete;
  Progressive_medial_axis_2& operator=(const Progressive_medial_axis_2&) = delete;

  /// Number of refinement steps of the whole computation.  With region
  /// growing, a step merges one triangle, or a few when one alone would make
  /// the shape touch itself at a vertex (see the user manual); with boundary
  /// evolution it puts back one vertex.
  std::size_t number_of_steps() const { return number_of_steps_; }
  /// The driver that decides the steps.
  Progressive_medial_axis_driver driver() const { return driver_kind_; }
  /// Steps done so far (0 right after construction).
  std::size_t current_step() const { return step_; }
  /// Whether every step has been done.
  bool is_complete() const { return step_ == number_of_steps_; }
  /// Whether the medial axis was given away by `release_medial_axis()`;
  /// the object can then not be refined nor read.
  bool is_released() const { return !data_; }

  /// Does one refinement step.  Returns false if the axis was already
  /// complete (or released).
  bool refine()
  {
    Default_progressive_medial_axis_visitor v;
    return refine(v);
  }

  /// Does one refinement step, reporting its events to `visitor`, a model
  /// of `ProgressiveMedialAxisVisitor_2`.
  template <class Visitor>
  bool refine(Visitor& visitor)
  {
    if(is_complete() || is_released())
      return false;
    const auto start = std::chrono::steady_clock::now();
    ++step_;
    Counting_visitor<Visitor> counting{visitor, stats_};
    const std::size_t n_v = region_ ? region_->step(step_, counting) : boundary_->step(step_, counting);
    if(boundary_) stats_.recomputed_steps = boundary_->recomputed_steps();
    if(n_v > stats_.max_queue) stats_.max_queue = n_v;
    stats_.merge_seconds += seconds_since(start);
    visitor.on_step(step_, n_v);
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

  /// The medial axis of the current shape.  It changes with each step
  /// (handles taken from it are then no longer valid).
  const Medial_axis& medial_axis() const
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if(engine_) engine_->resolve_pending();
    return view_;
  }

  /// Gives the medial axis away; the object can then not be refined any more.
  Medial_axis release_medial_axis()
  {
    medial_axis();
    Medial_axis out = std::move(view_);
    view_ = Medial_axis();
    region_.reset();
    boundary_.reset();
    engine_.reset();
    data_.reset();
    return out;
  }

  /// The current shape (the union of the triangles merged so far), as a
  /// polygon with holes: outer boundary counter-clockwise, holes clockwise.
  Polygon_with_holes_2 current_shape() const
  {
    const Medial_axis& ma = medial_axis();
    Polygon_with_holes_2 result;
    const auto rings = ma.shape_rings();
    for(std::size_t r = 0; r < rings.size(); ++r) {
      Polygon_2 ring;
      for(const auto& v : rings[r]) ring.push_back(ma.point(v));
      if(r == 0) result = Polygon_with_holes_2(ring);
      else result.add_hole(ring);
    }
    return result;
  }

  const Statistics& statistics() const { return stats_; }
  const Traits& traits() const { return traits_; }

private:
  typedef Progressive_medial_axes::internal::Medial_axis_engine<Traits> Engine;
  typedef typename Engine::Data Data;
  typedef Progressive_medial_axes::internal::Region_growing<Traits> Region_driver;
  typedef Progressive_medial_axes::internal::Boundary_evolution<Traits> Boundary_driver;

  // Passes the events on, counting them.
  template <class Visitor>
  struct Counting_visitor {
    Visitor& visitor;
    Statistics& stats;
    void on_switch() { ++stats.switches; visitor.on_switch(); }
    void on_vanish() { ++stats.vanishings; visitor.on_vanish(); }
    void on_merge(const Progressive_medial_axes::Merge_statistics& m)
    {
      ++stats.merges;
      stats.anomalies += m.anomalies;
      stats.undecided_ties += m.undecided_ties;
      stats.redone_merges += m.redone_exactly ? 1 : 0;
      visitor.on_merge(m);
    }
    void on_cut(bool is_cut, const Progressive_medial_axes::internal::Cut_statistics& c)
    {
      ++(is_cut ? stats.cuts : stats.splits);
      stats.redone_merges += c.redone_exactly ? 1 : 0;
    }
  };

  static double seconds_since(std::chrono::steady_clock::time_point t)
  {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
  }

  void init(const std::vector<std::vector<Point_2> >& rings, Medial_axis_input_check check)
  {
    auto t0 = std::chrono::steady_clock::now();
    std::vector<std::pair<int, int> > on_edges;   // the vertices inside an edge, found by the check
    if(check == CHECK_INPUT) {
      Progressive_medial_axes::internal::validate_and_find_vertices_on_edges(rings, &on_edges);
      stats_.validation_seconds = seconds_since(t0);
    }

    const auto first = std::chrono::steady_clock::now();
    data_ = std::make_shared<Data>();
    auto set_points = [&] { Progressive_medial_axes::internal::set_points(*data_, rings, traits_.orientation_2_object()); };
    if(driver_kind_ == REGION_GROWING) {
      set_points();
    } else {
      // the curve evolution needs only the rings: it runs while the
      // engine's data is set (in parallel where oneTBB is linked)
      std::vector<typename Boundary_driver::Removal> removals;
      auto evolve = [&] {
        const auto t = std::chrono::steady_clock::now();
        removals = Boundary_driver::evolve(rings, check == CHECK_INPUT ? &on_edges : nullptr);
        stats_.evolution_seconds = seconds_since(t);
      };
#ifdef CGAL_PMA2_USE_TBB
      tbb::parallel_invoke(evolve, set_points);
#else
      evolve();
      set_points();
#endif
      engine_.reset(new Engine(*data_, traits_));
      boundary_.reset(new Boundary_driver(*engine_, std::move(removals)));
      number_of_steps_ = boundary_->number_of_steps();
    }
    stats_.input_vertices = data_->points.size();
    stats_.holes = rings.size() - 1;

    if(driver_kind_ == REGION_GROWING) {
      t0 = std::chrono::steady_clock::now();
      engine_.reset(new Engine(*data_, traits_));
      region_.reset(new Region_driver(*engine_));
      stats_.triangles = region_->number_of_triangles();
      stats_.triangulation_seconds = seconds_since(t0);
      number_of_steps_ = region_->number_of_steps();
    }

    if(region_) data_->hds.reserve_for_points(data_->points.size());   // (the boundary driver's start() does)
    const auto t1 = std::chrono::steady_clock::now();
    if(region_) {
      region_->start();
      stats_.merge_seconds = seconds_since(t1);
    } else {
      boundary_->start();
      stats_.triangles = boundary_->number_of_triangles();
      Progressive_medial_axes::internal::copy_counts(stats_, boundary_->start_counts());
      stats_.merge_seconds = seconds_since(t1);
    }
    view_ = Medial_axis(std::shared_ptr<const Data>(data_));
    stats_.first_step_seconds = seconds_since(first);
  }

  Traits traits_;
  std::shared_ptr<Data> data_;
  std::unique_ptr<Engine> engine_;
  Progressive_medial_axis_driver driver_kind_ = REGION_GROWING;
  std::unique_ptr<Region_driver> region_;
  std::unique_ptr<Boundary_driver> boundary_;
  Medial_axis view_;
  mutable std::mutex mutex_;
  std::size_t step_ = 0, number_of_steps_ = 0;
  Statistics stats_;
};

namespace Progressive_medial_axes {
namespace internal {

/// A one-shot cut into `probe_seeds` parts or more (from 128 triangles on)
/// first measures what its merges cost (Divide_and_conquer::probe(): the
/// first triangles of `probe_seeds` parts, a sixteenth of all, but at least
/// `min_probe_triangles_per_part` and at most `max_probe_triangles_per_part`
/// a part; fewer were blind to glyphs of 1,000 to 2,000 triangles, where a
/// merge's cost grows with the part for the first few dozen triangles).
/// The divide and conquer goes on from the triangles probed, so the probe
/// costs nothing where it keeps the divide and conquer; when it dropped them,
/// the probe was kept to 1,024 triangles or more, which left glyphs of a few
/// hundred triangles 3 times slower than needed (RESULTS.md, "Small
/// polygons probed too", twentieth session)...
constexpr std::size_t probe_seeds = 4;
constexpr std::size_t min_probe_triangles_per_part = 32;
constexpr std::size_t max_probe_triangles_per_part = 48;
/// ... and where a merge crosses `boundary_evolution_events_per_merge`
/// cells or more on average, and `boundary_evolution_events_per_thread`
/// per thread of the task arena, computes the axis by boundary evolution
/// instead: the boundary simplified by discrete curve evolution, the
/// coarsest shape's axis in one shot, then every vertex put back, the last
/// removed first (Boundary_evolution.h).  Each vertex comes back next to
/// edges of about its own scale, so a step crosses few cells however finely
/// the boundary is sampled: 3 to 5 events a step.  On 2 threads, glyphs
/// whose probe gave 15 events a merge or more took 0.06 to 1.02 times as
/// long (a geometric mean of 0.31 or less); country outlines gave up to 13
/// and would have taken up to twice as long: the divide and conquer runs
/// in parallel, boundary evolution puts vertices back one at a time, and on
/// cocircular vertices (a regular polygon) its steps cross all the cells
/// around the centre (RESULTS.md, "Finely sampled curves", nineteenth
/// session).  So 20 on two threads; on one thread 18: there, of 164 probed
/// shapes, those measuring 18 or more took 0.04 to 0.96 times as long by
/// boundary evolution, some from 12 on up to 1.33 times (RESULTS.md, "Small
/// polygons probed too", twentieth session).
constexpr double boundary_evolution_events_per_merge = 18;
constexpr double boundary_evolution_events_per_thread = 10;

// Counts the work of boundary evolution's steps.
struct Boundary_evolution_counts {
  Divide_and_conquer_counts merges;
  std::size_t cuts = 0, splits = 0, crossings = 0;
  void on_switch() { merges.on_switch(); }
  void on_vanish() { merges.on_vanish(); }
  void on_merge(const Merge_statistics& m) { merges.add(m); }
  void on_cut(bool is_cut, const Cut_statistics& c)
  {
    ++(is_cut ? cuts : splits);
    crossings += c.crossings + c.removed_vertices;
    merges.redone_merges += c.redone_exactly ? 1 : 0;
  }
  std::size_t events() const { return merges.switches + merges.vanishings + crossings; }
};

/// The axis of `rings` by boundary evolution, all steps done, into `data`
/// (empty), unless its events (switches, vanishings and the edges its cuts
/// cross) exceed `budget`: then false, and `data` is to be dropped.
template <class Traits>
bool one_shot_by_boundary_evolution(const std::vector<std::vector<typename Traits::Kernel::Point_2> >& rings,
                                    const Traits& traits, double budget,
                                    Medial_axis_data<typename Traits::Point_2, typename Traits::FT>& data,
                                    Progressive_medial_axis_statistics& stats)
{
  typedef Boundary_evolution<Traits> Driver;
  const auto t0 = std::chrono::steady_clock::now();
  auto removals = Driver::evolve(rings);
  const auto t1 = std::chrono::steady_clock::now();
  set_points(data, rings, traits.orientation_2_object());
  Medial_axis_engine<Traits> engine(data, traits);
  Driver driver(engine, std::move(removals));
  driver.start();
  const Divide_and_conquer_counts& start = driver.start_counts();
  const auto t2 = std::chrono::steady_clock::now();
  Boundary_evolution_counts steps;
  const double start_events = double(start.switches + start.vanishings);
  // (a step whose cut is not local computes its axis again in one shot,
  // whose events the step does not report: charged as 4 a point)
  const double recomputed_events = 4 * double(data.points.size());
  for(std::size_t k = 1; k <= driver.number_of_steps(); ++k) {
    if(start_events + double(steps.events()) + recomputed_events * double(driver.recomputed_steps()) > budget)
      return false;
    driver.step(k, steps);
  }
  engine.resolve_pending();
  auto seconds = [](std::chrono::steady_clock::time_point a, std::chrono::steady_clock::time_point b) {
    return std::chrono::duration<double>(b - a).count();
  };
  Divide_and_conquer_counts all = start;
  all.add(steps.merges);
  copy_counts(stats, all);
  stats.evolution_seconds = seconds(t0, t1);
  stats.cuts = steps.cuts;
  stats.splits = steps.splits;
  stats.recomputed_steps = driver.recomputed_steps();
  stats.parts = start.parts;
  stats.parts_seconds_sum = start.parts_seconds_sum;
  stats.parts_seconds_max = start.parts_seconds_max;
  // (the steps, one after the other, are sequential like the join)
  stats.join_seconds = start.join_seconds + seconds(t2, std::chrono::steady_clock::now());
  stats.boundary_evolution_one_shots = 1;
  return true;
}

/// Whether one-shots count the steps region growing would take on their
/// polygon (`Progressive_medial_axis_statistics::region_growing_steps`),
/// from their own triangles where those are region growing's (off by
/// default; about 2% of a one-shot of c1m_CHN_0).  The tool's `--stats`
/// prints that count: computed apart, it triangulated every polygon a second
/// time, and a whole-world file of 4.8 million vertices took 19.6 s with
/// `--stats` against 16.7 s without (RESULTS.md, sixty-seventh session).
inline std::atomic<bool>& one_shots_count_region_growing_steps()
{
  static std::atomic<bool> on(false);
  return on;
}

/// For tests of the one-shot's way out below (one_shot_by_region_growing()):
/// while set, every one-shot takes it, as if its merges had met an anomaly.
inline std::atomic<bool>& one_shot_way_out_forced()
{
  static std::atomic<bool> forced(false);
  return forced;
}

/// For tests of the divide and conquer stopped (see
/// `abandon_events_per_triangle`): while 1, every one-shot that probes its
/// parts stops its divide and conquer after a few triangles; while 2, the
/// boundary evolution that follows gives up at once too, and the one-shot
/// runs again without stopping.
inline std::atomic<int>& one_shot_abandon_forced()
{
  static std::atomic<int> forced(0);
  return forced;
}

/// Whether a one-shot whose merges met `anomalies` anomalies takes the way
/// out below.
inline bool one_shot_takes_way_out(std::size_t anomalies)
{
  return anomalies != 0 || one_shot_way_out_forced().load(std::memory_order_relaxed);
}

/// The axis of `rings` by region growing, all steps done, into `data`
/// (empty): the one-shot's way out where the divide and conquer or boundary
/// evolution met an anomaly.  Such an anomaly is a bug, not a rounding
/// error (it happens with exact decisions too): a merge that closes a ring
/// around a small hole, where the cell of one generator touches the
/// separator from both sides, can take the vanishing of the wrong one of
/// two neighbouring cells (RESULTS.md, "A merge anomaly on real data",
/// thirty-first session).  Region growing closes its rings along other
/// diagonals.  Throws `std::runtime_error` if it meets an anomaly too: no
/// axis is better than a wrong one.
///
/// With the double model, the anomaly more likely comes from a decision
/// that the rounding errors got wrong without tripping its checks, and
/// region growing in doubles would meet it too: the way out takes exact
/// decisions, the double model's fallback.  (On a grid moved off by 1e-6,
/// where edges are nearly parallel, the double model's decisions were
/// wrong before any anomaly until its disks carried error estimates;
/// RESULTS.md, forty-second and forty-third sessions.)
template <class Traits>
void one_shot_by_region_growing(const std::vector<std::vector<typename Traits::Kernel::Point_2> >& rings,
                                const Traits& traits,
                                Medial_axis_data<typename Traits::Point_2, typename Traits::FT>& data,
                                Progressive_medial_axis_statistics& stats)
{
  typedef typename Exact_fallback<Traits>::type Fallback;
  if constexpr(!std::is_void<Fallback>::value) {
    (void)traits;
    one_shot_by_region_growing(rings, Fallback(), data, stats);
    return;
  }
  set_points(data, rings, traits.orientation_2_object());
  Medial_axis_engine<Traits> engine(data, traits);
  Region_growing<Traits> driver(engine);
  data.hds.reserve_for_points(data.points.size());
  driver.start();
  Boundary_evolution_counts counts;   // (its merge counts; region growing has no cuts)
  for(std::size_t k = 1; k <= driver.number_of_steps(); ++k)
    driver.step(k, counts);
  engine.resolve_pending();
  if(counts.merges.anomalies != 0)
    throw std::runtime_error("internal error: the merges of this polygon are inconsistent (" +
                             std::to_string(counts.merges.anomalies) +
                             " anomalies in the divide and conquer and in region growing); please report the input");
  copy_counts(stats, counts.merges);
  stats.boundary_evolution_one_shots = 0;
  stats.region_growing_one_shots = 1;
}

// The one-shot of `rings`.  Where `owned` is not null it is `rings`, which
// the caller gives up: its memory is given back as soon as the engine has
// its own copy of the points (before the triangulation and the parts, where
// the peak is: 13 MiB of a plate of 100,000 holes, 600,000 points), and
// the drivers that start again from the rings rebuild them (input_rings()).
template <class Traits>
Medial_axis_2<typename Traits::Kernel>
one_shot_medial_axis(const std::vector<std::vector<typename Traits::Kernel::Point_2> >& rings,
                     std::vector<std::vector<typename Traits::Kernel::Point_2> >* owned, const Traits& traits,
                     Medial_axis_input_check check, Progressive_medial_axis_statistics* statistics,
                     std::size_t parts, std::size_t probe_limit)
{
  CGAL_precondition(owned == nullptr || owned == &rings);
  typedef typename Traits::Kernel Kernel;
  typedef Medial_axis_engine<Traits> Engine;
  typedef typename Engine::Data Data;
  auto seconds_since = [](std::chrono::steady_clock::time_point t) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
  };
  Progressive_medial_axis_statistics stats;
  // (on the heap, freed as soon as the triangles are read)
  auto triangulation = std::make_unique<Ring_triangulation<Kernel> >();
  // a large polygon on two threads or more: triangulated in two sides at
  // once where a chord, or a path through holes, cuts it (Split_triangulation.h)
  std::unique_ptr<Split_triangulation<Kernel> > split;
  auto t0 = std::chrono::steady_clock::now();
  bool overlap = false;
  bool has_t = false;   // a point of the polygon lies inside one of its edges
#ifdef CGAL_PMA2_USE_TBB
  {
    std::size_t vertices = 0;
    for(const auto& ring : rings) vertices += ring.size();
    const bool parallel =
      std::is_floating_point<typename Kernel::FT>::value && tbb::this_task_arena::max_concurrency() > 1;
    // (the split needs the check's answer on T's, and exact double coordinates)
    const bool may_split = check == CHECK_INPUT && std::is_same<typename Kernel::FT, double>::value;
    // The validation (a sweep) and the Delaunay triangulation of the points
    // (which any finite points have) run at the same time; the constraints
    // wait for a valid polygon.  (Small polygons stay on this thread.)
    overlap = check == CHECK_INPUT && parallel && (vertices >= min_overlap_vertices || tbb_running());
    if(parallel && may_split && vertices >= split_triangulation_min_vertices().load(std::memory_order_relaxed))
      split = std::make_unique<Split_triangulation<Kernel> >();
    if(overlap || split)
      for(const auto& ring : rings)
        for(const auto& p : ring)
          if(!std::isfinite(CGAL::to_double(p.x())) || !std::isfinite(CGAL::to_double(p.y()))) {
            overlap = false;
            split.reset();
          }
  }
#endif
  // the split's phase 1 (the chord, then both sides' points), or nothing
  auto split_points = [&] {
    // (beside the check, the side of the thread that checks the polygon is
    // the smaller one: see split_triangulation_caller_share)
    if(split && split->find_cut(rings, overlap ? split_triangulation_caller_share : 0.5))
      split->insert_points(rings);
    else
      split.reset();
  };
  if(check == CHECK_INPUT) {
#ifdef CGAL_PMA2_USE_TBB
    if(overlap) {
      std::exception_ptr invalid;
      tbb::parallel_invoke(
        [&] {
          try {
            has_t = validate_and_find_vertices_on_edges(rings);
          } catch(...) {
            invalid = std::current_exception();
          }
          stats.validation_seconds = seconds_since(t0);
        },
        [&] {
          const auto t1 = std::chrono::steady_clock::now();
          split_points();
          if(!split)
            triangulation->insert_points(rings);
          stats.overlapped_seconds = seconds_since(t1);
        });
      if(invalid)
        std::rethrow_exception(invalid);
    }
#endif
    if(!overlap) {
      has_t = validate_and_find_vertices_on_edges(rings);
      stats.validation_seconds = seconds_since(t0);
    }
  }
  if(has_t)   // (a point in an edge: the whole polygon, see Split_triangulation.h)
    split.reset();
  double split_seconds = 0;   // the split's phase 1 where it did not run beside the validation
  if(split && !overlap) {
    t0 = std::chrono::steady_clock::now();
    split_points();
    split_seconds = seconds_since(t0);
  }
  auto data = std::make_shared<Data>();
  // (a split triangulation's cut is found only where no two points are at
  // one place: then no corners are to be linked where rings touch)
  set_points(*data, rings, traits.orientation_2_object(), split ? POINTS_DISTINCT : POINTS_MAY_REPEAT);
  stats.input_vertices = data->points.size();
  stats.holes = rings.size() - 1;
  // the rings, for the drivers that start again from them (rebuilt once,
  // from the points, if the caller gave them up)
  std::vector<std::vector<typename Kernel::Point_2> > rebuilt;
  auto input = [&]() -> const std::vector<std::vector<typename Kernel::Point_2> >& {
    if(owned == nullptr) return rings;
    if(rebuilt.empty())
      rebuilt = input_rings(*data);
    return rebuilt;
  };
  if(owned != nullptr)
    free_vector(*owned);

  t0 = std::chrono::steady_clock::now();
  std::vector<Triangle> triangles;
  if(split && split->finish(*data, triangles)) {
    stats.split_triangulations = 1;
    stats.split_triangulation_holes = split->holes_on_cut();
    stats.triangulation_parallel_seconds = split->parallel_seconds();
  } else {   // (where the sides could not be finished, the whole polygon from its points)
    triangles = triangulation->finish(*data);
  }
  // (the memory they free is given back to the system once the divide and
  // conquer has prepared its parts: see Divide_and_conquer::run())
  split.reset();
  triangulation.reset();
  stats.triangles = triangles.size();
  stats.triangulation_seconds = stats.overlapped_seconds + split_seconds + seconds_since(t0);
  // the steps of region growing, whose triangles are these unless split
  // (triangulate_rings() of the same points), counted once the
  // triangulation is freed
  if(stats.split_triangulations == 0 && !triangles.empty() &&
     one_shots_count_region_growing_steps().load(std::memory_order_relaxed))
    stats.region_growing_steps = growth_steps(triangles, data->points).size() - 1;

  t0 = std::chrono::steady_clock::now();
  Engine engine(*data, traits);
  const std::size_t T = triangles.size();
  const auto how = one_shot_parts<Traits>(parts, T);
  Divide_and_conquer<Traits> driver(engine, std::move(triangles));
  // the axis by boundary evolution of `given`, with the way out, unless
  // its events exceed `budget` (what the divide and conquer would cost on
  // these threads): then null
  const double threads = double(arena_threads());
  auto by_boundary_evolution = [&](const std::vector<std::vector<typename Kernel::Point_2> >& given,
                                   double budget) -> std::shared_ptr<const Data> {
    auto evolved = std::make_shared<Data>();
    if(!one_shot_by_boundary_evolution(given, traits, budget, *evolved, stats))
      return nullptr;
    if(one_shot_takes_way_out(stats.anomalies)) {
      evolved = std::make_shared<Data>();
      one_shot_by_region_growing(given, traits, *evolved, stats);
    }
    stats.merge_seconds = seconds_since(t0);
    if(statistics)
      *statistics = stats;
    return evolved;
  };
  // (the one-shot probes its parts, and may stop them: see below)
  const bool probes = parts == 0 && how.first >= probe_seeds;
  if(probes) {
    // (the probe's decisions are counted in the filter statistics, its
    // merges in the divide and conquer's where that is kept)
    const std::size_t limit = (std::min)(max_probe_triangles_per_part,
                                         (std::max)(min_probe_triangles_per_part, T / (16 * probe_seeds)));
    const double events = driver.probe(how.first, probe_seeds, limit);
    if(events >= (std::max)(boundary_evolution_events_per_merge, boundary_evolution_events_per_thread * threads)) {
      // boundary evolution, unless it does more work than the divide and
      // conquer would at the probe's rate: then the divide and conquer
      release_free_memory(data->points.size());
      if(auto evolved = by_boundary_evolution(input(), events * double(T) / threads))
        return Medial_axis_access::make<Kernel>(evolved);
    }
  }
  if(parts != 0 && probe_limit != 0)   // (the divide and conquer goes on from the triangles probed)
    driver.probe(how.first, probe_seeds, probe_limit);
  // where the probe missed parts whose merges cross thousands of cells a
  // triangle: boundary evolution (see abandon_events_per_triangle)
  const int forced = one_shot_abandon_forced().load(std::memory_order_relaxed);
  if(probes)
    driver.abandon_above(forced != 0 ? 0 : abandon_events_per_triangle, forced != 0 ? 0 : abandon_slack_triangles);
  data->hds.reserve_for_points(data->points.size());
  const Divide_and_conquer_counts counts = divide_and_conquer(driver, how.first, how.second);
  if(driver.abandoned()) {
    const std::vector<std::vector<typename Kernel::Point_2> >& given = input();   // (rebuilt from `data` if given up)
    data.reset();
    release_free_memory(stats.input_vertices);
    stats.abandoned_divide_and_conquers = 1;
    if(auto evolved =
         by_boundary_evolution(given, forced == 2 ? 0 : double(abandon_events_per_triangle) * double(T) / threads))
      return Medial_axis_access::make<Kernel>(evolved);
    // boundary evolution did no better (the budget of the divide and
    // conquer at that rate): the one-shot again, without stopping
    Medial_axis_2<Kernel> axis = one_shot_medial_axis(given, nullptr, traits, check, statistics, how.first, 0);
    if(statistics)
      statistics->abandoned_divide_and_conquers = 1;
    return axis;
  }
  stats.merge_seconds = seconds_since(t0);
  copy_counts(stats, counts);
  stats.parts = counts.parts;
  stats.parts_seconds_sum = counts.parts_seconds_sum;
  stats.parts_seconds_max = counts.parts_seconds_max;
  stats.join_seconds = counts.join_seconds;
  if(one_shot_takes_way_out(counts.anomalies)) {
    // (a bug of the merge: see one_shot_by_region_growing())
    auto redone = std::make_shared<Data>();
    one_shot_by_region_growing(input(), traits, *redone, stats);
    stats.merge_seconds = seconds_since(t0);
    if(statistics)
      *statistics = stats;
    return Medial_axis_access::make<Kernel>(std::shared_ptr<const Data>(redone));
  }
  if(statistics)
    *statistics = stats;
  // (a small polygon's arrays cost a copy of a few KB here; a large one's
  // would double the peak for a while, and their empty room is not backed)
  if(data->points.size() <= 1024)
    data->hds.shrink_to_fit();
  return Medial_axis_access::make<Kernel>(std::shared_ptr<const Data>(data));
}

template <class Traits>
Medial_axis_2<typename Traits::Kernel>
one_shot_medial_axis(const std::vector<std::vector<typename Traits::Kernel::Point_2> >& rings, const Traits& traits,
                     Medial_axis_input_check check, Progressive_medial_axis_statistics* statistics,
                     std::size_t parts = 0,         // 0: default_parts()
                     std::size_t probe_limit = 0)   // (tests) with `parts`: probe this many triangles a part first
{
  return one_shot_medial_axis(rings, nullptr, traits, check, statistics, parts, probe_limit);
}

/// The one-shot of `rings`, whose memory is given back once the engine has
/// copied them (see above).
template <class Traits>
Medial_axis_2<typename Traits::Kernel>
one_shot_medial_axis(std::vector<std::vector<typename Traits::Kernel::Point_2> >&& rings, const Traits& traits,
                     Medial_axis_input_check check, Progressive_medial_axis_statistics* statistics)
{
  return one_shot_medial_axis(rings, &rings, traits, check, statistics, 0, 0);
}

} // namespace internal
} // namespace Progressive_medial_axes

/*!
\ingroup PkgProgressiveMedialAxis2Ref
Computes the medial axis of a polygon in one shot: a `CGAL::Polygon_2` or
`CGAL::Polygon_with_holes_2` of any kernel, or a range of rings.  Throws
`Progressive_medial_axes::Input_error` if the polygon is not valid.

The computation is the divide and conquer of the paper (section 6.4): the
triangles of a constrained Delaunay triangulation are cut into connected
parts whose axes are computed independently and merged along the diagonals
between them.  Where the boundary is sampled so finely against the shape's
width that a merge would cross dozens of cells (measured on a few
triangles of four parts first, from 128 triangles on), the axis is
computed by boundary evolution instead, all its steps done (see the user
manual, "One shot: divide and conquer"); `statistics` then says so.  Where
the measure missed such triangles and the merges of a part cross hundreds
of cells a triangle, the divide and conquer stops and boundary evolution
computes the axis (or, where it does no better, the divide and conquer
runs again without stopping); `statistics` says so too.  When
the package is linked with oneTBB
(`CGAL_LINKED_WITH_TBB`, the CMake target `CGAL::TBB_support`), the parts
are computed in parallel, on the threads of the current `tbb::task_arena`
(all hardware threads by default; run the call inside a
`tbb::task_arena(n).execute()` to use n), for traits over a kernel of
doubles (`Epick`, `Simple_cartesian<double>`): the exact number types of
`Epeck` and `CORE::Expr` share state between threads, and run sequentially.
Called outside any task arena (where oneTBB does not run yet), it starts
oneTBB only where the work pays for it: it builds the parts on the calling
thread, one after the other, until the parts left would take about 16 ms
or more there, and builds those in parallel; below 4,096 vertices it also
checks the polygon on the calling thread, before the triangulation.
Without oneTBB it runs sequentially.  The result is the same in all cases.  For a polygon of
262,144 points or more, it gives the memory that glibc keeps free back to
the system (`malloc_trim()`) once the triangulation is freed and the
parts are prepared, once all parts have started, and after the last part
moved into the result.

If `statistics` is given, it receives the input size, the times of the
phases and the counts of the merges and their events.
*/
template <class Polygon, class Traits>
Medial_axis_2<typename Traits::Kernel> medial_axis_2(const Polygon& polygon, const Traits& traits,
                                                    Medial_axis_input_check check = CHECK_INPUT,
                                                    Progressive_medial_axis_statistics* statistics = nullptr)
{
  typedef std::vector<std::vector<typename Traits::Kernel::Point_2> > Rings;
  if constexpr(std::is_same<Polygon, Rings>::value)   // (rings of the traits' points: not copied)
    return Progressive_medial_axes::internal::one_shot_medial_axis(polygon, traits, check, statistics);
  else
    return Progressive_medial_axes::internal::one_shot_medial_axis(
      Progressive_medial_axes::internal::rings_of<typename Traits::Kernel>(polygon), traits, check, statistics);
}

/*!
\ingroup PkgProgressiveMedialAxis2Ref
The same, for rings of the traits' points that the caller gives up (a
moved-from vector): their memory is given back as soon as the computation
has its own copy of the points, before the triangulation and the parts,
where the peak of its memory is.  (The other overload makes that copy of a
`Polygon_2` or `Polygon_with_holes_2`, and gives it back the same way.)
*/
template <class Traits>
Medial_axis_2<typename Traits::Kernel> medial_axis_2(std::vector<std::vector<typename Traits::Kernel::Point_2> >&& rings,
                                                    const Traits& traits,
                                                    Medial_axis_input_check check = CHECK_INPUT,
                                                    Progressive_medial_axis_statistics* statistics = nullptr)
{
  return Progressive_medial_axes::internal::one_shot_medial_axis(std::move(rings), traits, check, statistics);
}

/*!
\ingroup PkgProgressiveMedialAxis2Ref
One-shot medial axis with the default traits of the polygon's kernel:
`Progressive_medial_axis_traits_2<Epeck>` for an `Epeck` polygon,
`Progressive_medial_axis_traits_2<Epick>` for any other (every decision exact
in both).
*/
template <class Polygon>
auto medial_axis_2(const Polygon& polygon)
{
  typedef typename Progressive_medial_axes::internal::Default_traits_of_input<Polygon>::type Traits;
  return medial_axis_2(polygon, Traits());
}

} // namespace CGAL

#endif // CGAL_PROGRESSIVE_MEDIAL_AXIS_2_H
