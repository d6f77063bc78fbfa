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
// The one-shot driver: divide and conquer over the triangles of a
// constrained Delaunay triangulation (Liu et al. 2016, section 6.4; every
// merge is the engine's topology-oriented merge along one diagonal).
//
// The cut.  The dual graph of the triangulation (a node per triangle, an
// arc per diagonal) is a tree for a simple polygon and has one independent
// cycle per hole.  The cycles are broken by a breadth-first spanning tree;
// the diagonals off the tree (exactly one per hole) are the "hole-closing"
// diagonals.  The tree is cut into `parts` connected subtrees of about
// equal size (a greedy bottom-up cut: a subtree is cut off as soon as it
// holds the target number of triangles; on several threads the last parts
// to start are smaller, see cut()).  Every part is a union of
// triangles joined along diagonals, so the axis of a part is computed by
// merges along single diagonals, whose two ends are polygon vertices: no
// merge ever meets a point that is not a vertex of the input.
//
// The merges, in three phases:
//   1. every part, independently (in parallel with oneTBB when the package
//      is linked with it, CGAL_LINKED_WITH_TBB; tbb::parallel_for over the
//      parts): its triangles in breadth-first order from the part's root,
//      each merged along the tree diagonal to its parent, and along every
//      hole-closing diagonal of the part as soon as both its triangles are
//      in, in a half-edge structure that the part owns (on one thread, all
//      parts in the result's structure, one after the other); the part's
//      vertices are then resolved (their disks constructed);
//      the first triangles of some parts may have been built by probe(),
//      each part in a structure of its own: that structure is appended to
//      the one the part is built in (the half-edges of its sides shifted),
//      and the part goes on from where the probe stopped;
//   2. each part's structure is appended to the result's structure as soon
//      as it and the parts before it are built, by the thread that built
//      the last of them, while the other threads go on building parts (one
//      copy of each part's records, linear in its size; no structure is
//      shared between threads, so no merge takes a lock); that thread then
//      merges the part with the parts before it: along the cut diagonal
//      above its root, to the part of the root's parent (an earlier part:
//      parts are numbered in the breadth-first order of their roots), which
//      joins two components, then along the hole-closing diagonals between
//      it and earlier parts.  Parts 0 to q are connected through their cut
//      diagonals (within each connected part of the interior), so both
//      sides of such a diagonal are then the same shape, and the merge
//      closes a ring around a hole.  On one thread, the parts are merged
//      so, part after part, once all are built;
//   3. the vertices made by these merges are resolved (their disks
//      constructed).
// The triangles are numbered part by part (number_by_part()), and each
// part's range of the triangles' arrays is given back to the system as
// soon as the part is built (release_part()); the arrays are freed when
// the last one is.
// Between merges a shape may touch itself at a polygon vertex (the fan of
// triangles around the vertex is interrupted by a diagonal not merged
// yet); every corner of such a vertex is a vertex of the structure of its
// own, and the merge along a diagonal that ends there makes the corners of
// its two sides one (Medial_merge::unify_corners).  After the last merge
// every fan is whole, so every polygon vertex has one corner.
//
// The result is the medial axis of the polygon, the same structure (up to
// numbering) as region growing gives after its last step.

#ifndef CGAL_PROGRESSIVE_MEDIAL_AXIS_2_INTERNAL_DIVIDE_AND_CONQUER_H
#define CGAL_PROGRESSIVE_MEDIAL_AXIS_2_INTERNAL_DIVIDE_AND_CONQUER_H

#include <CGAL/Progressive_medial_axis_2/internal/Medial_axis_engine.h>
#include <CGAL/Progressive_medial_axis_2/internal/Triangulate.h>
#include <CGAL/Progressive_medial_axis_2/Merge_statistics.h>

// CGAL_PMA2_NO_TBB turns the parallelism off where TBB is linked (for
// ThreadSanitizer, which cannot see the synchronisation inside an
// uninstrumented libtbb).
#if defined(CGAL_LINKED_WITH_TBB) && !defined(CGAL_PMA2_NO_TBB)
#define CGAL_PMA2_USE_TBB 1
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#endif

#if defined(__GLIBC__)
#include <malloc.h>
#endif
#if defined(__linux__)
#include <sys/mman.h>
#endif

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <vector>
#include <mutex>
#include <thread>
#include <type_traits>

namespace CGAL {
namespace Progressive_medial_axes {
namespace internal {

// The counters of the stages of a filtered traits are per thread: the
// counts of a part built by another thread are added to the caller's.
template <class Traits, class = void>
struct Thread_counters {
  template <class F>
  static void run_counted(std::thread::id, std::mutex&, const F& f) { f(); }
};
template <class Traits>
struct Thread_counters<Traits, std::void_t<decltype(Traits::filter_statistics())> > {
  typedef typename std::remove_reference<decltype(Traits::filter_statistics())>::type Counters;
  Counters others;   // what other threads counted
  template <class F>
  void run_counted(std::thread::id caller, std::mutex& m, const F& f)
  {
    const Counters before = Traits::filter_statistics();
    f();
    if(std::this_thread::get_id() == caller)
      return;
    const Counters after = Traits::filter_statistics();
    std::lock_guard<std::mutex> lock(m);
    others.add_difference(after, before);
  }
  void gather() { Traits::filter_statistics().add_difference(others, Counters()); }
};

/// Counts of the merges of a divide and conquer (or of a part of it).
struct Divide_and_conquer_counts {
  std::size_t merges = 0, switches = 0, vanishings = 0, anomalies = 0, undecided_ties = 0, redone_merges = 0, max_queue = 0;
  // the task tree: the parts' tasks (summed, longest) and the sequential join
  std::size_t parts = 0;
  double parts_seconds_sum = 0, parts_seconds_max = 0, join_seconds = 0;
  void add(const Divide_and_conquer_counts& o)
  {
    merges += o.merges;
    switches += o.switches;
    vanishings += o.vanishings;
    anomalies += o.anomalies;
    undecided_ties += o.undecided_ties;
    redone_merges += o.redone_merges;
    max_queue = (std::max)(max_queue, o.max_queue);
  }
  void add(const Merge_statistics& m)
  {
    ++merges;
    anomalies += m.anomalies;
    undecided_ties += m.undecided_ties;
    redone_merges += m.redone_exactly ? 1 : 0;
    max_queue = (std::max)(max_queue, m.max_queue);
  }
  void on_switch() { ++switches; }
  void on_vanish() { ++vanishings; }
};

/// How the parts of a one-shot run: on the calling thread, in parallel
/// (oneTBB), or in parallel only where it pays (see `min_parallel_seconds`).
enum Parts_mode { PARTS_SEQUENTIAL, PARTS_PARALLEL, PARTS_PARALLEL_IF_WORTH_IT };

/// A one-shot called where oneTBB does not run yet (outside any task arena)
/// builds its parts on the calling thread, one after the other, until the
/// parts left would take at least this long there (their triangles at the
/// rate of the parts built); those it builds in parallel.  Starting oneTBB
/// costs the calling thread its global start-up (about 0.8 ms a process in
/// the third session; `task_arena::initialize()` alone took 2.0 to 2.3 ms
/// in the thirty-fifth, on the 2-core VM of RESULTS.md), and the worker
/// then meets the code, the heap and the per-thread tables of constructions
/// cold.  On two polygons of a few hundred vertices of the degenerate
/// table (files under 16 KB, where the tool calls the one-shot outside its
/// arena) which started oneTBB after 4 ms of parts, the tool took 18% to
/// 20% less time without it (a nested Koch snowflake of 384 vertices, whose
/// parts took 11 ms in all, and a 320-vertex polygon with holes); with
/// 16 ms both run on one thread.  In the third session, with a cheaper start,
/// two threads had been faster on integer grids of 800 vertices (those now
/// stay on one thread through `min_overlap_vertices`; RESULTS.md, "Starting
/// oneTBB for small polygons", thirty-fifth session).
constexpr double min_parallel_seconds = 0.016;

/// From this many input points on, a one-shot gives the memory it freed back
/// to the system (release_free_memory()) once its parts are prepared (the
/// triangulation freed), once all its parts have started, and after the
/// last part moved into the result; and each part's triangles once the
/// part is built (release_part()).  Each release costs time: the pages
/// given back are faulted in again, one by one and zeroed by the system,
/// by whatever allocates next, and giving them back flushes the other
/// CPU's TLB.  From 65,536 on, the releases took 10% of the time of a
/// 128,000-vertex outline on two threads of the 2-core VM of RESULTS.md
/// for 7 MB (10%) less peak memory, so they start at 262,144 points, where
/// the peak is hundreds of megabytes: they lower the peak of a plate of
/// 100,000 holes (600,000 points) by 20%, 74 MB, for 8% more time
/// (RESULTS.md, thirty-eighth session).
constexpr std::size_t min_release_points = 262144;

/// A one-shot's divide and conquer stops (Divide_and_conquer::abandon_above())
/// where the merges of one part cross more than this many cells a triangle
/// (switches and vanishings), after a start of `abandon_slack_triangles`
/// triangles' worth, and boundary evolution computes the axis instead.  The
/// parts of every shape of the tests and benchmarks crossed at most 40 a
/// triangle (country outlines 6 to 32, glyphs up to 40); a circle of
/// 50,000 vertices with a rectangular hole near its edge, whose triangles
/// fan from the hole's long edges to thousands of vertices of the circle,
/// crossed 3,000 to 5,000 a triangle in its worst parts, where each merge
/// rebuilds the axis around the fan: 17.6 s by divide and conquer on 2
/// threads, 0.94 s by boundary evolution (RESULTS.md, "Parts that cross
/// thousands of cells a triangle", fifty-seventh session).
constexpr std::size_t abandon_events_per_triangle = 256;
constexpr std::size_t abandon_slack_triangles = 64;

/// Whether a one-shot of `min_release_points` or more gives the memory it
/// freed back to the system (on by default).  A program that goes on
/// computing after the axis, and lets glibc keep freed memory for that work,
/// turns it off: the tool does when it analyses the axis (significance,
/// pruning, centerline), whose arrays would otherwise fault in again the
/// pages given back (on c1m_CHN_0 the analysis took 0.050 s with them kept
/// and 0.063 s without).
inline std::atomic<bool>& release_memory_of_large_one_shots()
{
  static std::atomic<bool> on{true};
  return on;
}

/// Whether a one-shot of `points` input points gives memory back to the
/// system: from `min_release_points` on, if
/// release_memory_of_large_one_shots() says so.
inline bool gives_memory_back(std::size_t points)
{
  return points >= min_release_points && release_memory_of_large_one_shots().load(std::memory_order_relaxed);
}

/// In a one-shot of `points` input points, from `min_release_points` on and
/// if release_memory_of_large_one_shots() says so, gives the memory that the
/// allocator keeps free back to the system.  glibc keeps the blocks under
/// 128 KB that a program frees in its heaps for later requests, but the
/// structure of the axis is made of larger blocks,
/// which it maps afresh: the triangulation of a large polygon (its many
/// small blocks, about 140 bytes per input point) and the small blocks of
/// the parts' merges would otherwise stay in the process beside the axis
/// until it exits.  A 600,000-vertex plate with 100,000 holes peaked at
/// 452 MB on two threads without this, at 393 MB with it; a 128,000-vertex
/// outline at 96 MB and 71 MB; the time did not change (RESULTS.md, "The
/// peak memory of a one-shot, thirteenth session").  Elsewhere it does
/// nothing.
inline void release_free_memory(std::size_t points)
{
#if defined(__GLIBC__)
  if(gives_memory_back(points))
    malloc_trim(0);
#else
  (void)points;
#endif
}

/// Below this many vertices, a one-shot called where oneTBB does not run
/// yet checks the polygon before it triangulates it, on the calling thread,
/// rather than beside it on another thread.  The check takes about 0.3
/// microseconds a vertex, starting oneTBB 0.8 to 2.3 ms (see
/// `min_parallel_seconds`): with 512, integer grids of 670 and 806 vertices
/// started oneTBB for the check alone, and the tool took 23% to 26% more
/// time on them than with 4096, which keeps them on one thread (RESULTS.md,
/// "Starting oneTBB for small polygons", thirty-fifth session).
constexpr std::size_t min_overlap_vertices = 4096;

/// Whether the calling thread is in a oneTBB task arena (oneTBB runs).
inline bool tbb_running()
{
#ifdef CGAL_PMA2_USE_TBB
  return tbb::this_task_arena::current_thread_index() != tbb::task_arena::not_initialized;
#else
  return false;
#endif
}

/// The threads of the current task arena (1 without oneTBB).
inline std::size_t arena_threads()
{
#ifdef CGAL_PMA2_USE_TBB
  return std::size_t((std::max)(1, tbb::this_task_arena::max_concurrency()));
#else
  return 1;
#endif
}

/// Where a one-shot's parts run on several threads, the parts that start
/// last are cut smaller, but only if these smaller parts still hold this
/// many triangles (see `Divide_and_conquer::cut()`).  A setting, so that
/// the tests, whose polygons are small, can lower it and check that cut
/// against the oracle; 256 by default.
inline std::atomic<int>& divide_and_conquer_min_tail_target()
{
  static std::atomic<int> triangles{256};
  return triangles;
}

/// Gives the pages inside elements [b, e) of `v` back to the system (their
/// contents are lost: the caller reads them no more); the partial pages at
/// the two ends stay.  Linux (madvise MADV_DONTNEED); elsewhere nothing.
/// The standard library has no way to free part of a vector's memory.
template <class T>
void release_pages(std::vector<T>& v, std::size_t b, std::size_t e)
{
#if defined(__linux__)
  if(e <= b) return;
  const std::uintptr_t page = 4096;
  const std::uintptr_t first = (reinterpret_cast<std::uintptr_t>(v.data() + b) + page - 1) & ~(page - 1);
  const std::uintptr_t last = reinterpret_cast<std::uintptr_t>(v.data() + e) & ~(page - 1);
  if(first < last)
    madvise(reinterpret_cast<void*>(first), last - first, MADV_DONTNEED);
#else
  (void)v;
  (void)b;
  (void)e;
#endif
}

template <class Traits>
class Divide_and_conquer
{
public:
  typedef Medial_axis_engine<Traits> Engine;
  typedef typename Engine::Hds Hds;
  typedef typename Traits::Point_2 Point_2;

  /// `triangles` is the triangulation of the engine's polygon.
  Divide_and_conquer(Engine& engine, std::vector<Triangle> triangles)
    : engine_(engine), triangles_(std::move(triangles))
  {}

  /// Computes the axis into the engine's structure, cutting the spanning
  /// tree into about `parts` parts, built as `mode` says.  The task of each
  /// part is run as `run_part(task)`, in the thread that builds it (the
  /// caller can gather thread-local counters there).
  template <class Run_part>
  Divide_and_conquer_counts run(std::size_t parts, Parts_mode mode, const Run_part& run_part)
  {
    const int T = int(triangles_.size());
    Divide_and_conquer_counts counts;
    if(T == 0)
      return counts;
    if(!prepared_ || prepared_parts_ != parts)
      prepare(parts);
    // The memory that the triangulation freed is given back to the system
    // only now, once the arrays of the spanning tree and of the parts
    // (about 33 bytes a triangle) have taken pages of it: given back before,
    // those pages were faulted in again, zeroed by the system, and the
    // probe and prepare() took 17 ms of a 128,000-vertex outline on the
    // 2-core VM of RESULTS.md, against 7 ms now ("Page faults and the
    // sequential phases", thirty-fourth session).
    release_free_memory(engine_.points().size());
    const std::size_t P = roots_.size();

    // 1. the parts.  On one thread they are built one after the other in
    // the result's structure.  Otherwise part 0 is built there and each
    // other part in a structure of its own, moved into the result's in the
    // order of the parts, so that the numbering of the result does not
    // depend on which parts ran at the same time.  A part is moved as soon
    // as it and the parts before it are built, by the thread that built the
    // last of them, while other threads go on building parts: on two
    // threads, moving the parts after all were built had taken 30 ms of
    // the 36 ms join of a 128,000-vertex outline.  (Moving a part holds one
    // of its arrays twice for a moment; one thread has nothing to move.)
    bool one_thread = mode == PARTS_SEQUENTIAL || P == 1;
#ifdef CGAL_PMA2_USE_TBB
    one_thread = one_thread || tbb::this_task_arena::max_concurrency() == 1;
#else
    one_thread = true;
#endif
    // The diagonals between parts, each merged once both its parts are in
    // the result's structure.  For each part in turn: the cut diagonal to
    // the part of its root's parent (an earlier part: parts are numbered in
    // the breadth-first order of their roots), then the hole-closing
    // diagonals between it and earlier parts (those inside a part are
    // merged by the part).  Parts 0 to q are connected through their cut
    // diagonals, so a hole-closing diagonal of part q closes a ring of that
    // region, as in region growing.  On several threads the diagonals of
    // part q are merged as soon as it is moved, while other threads go on
    // building parts: merged after all parts, they and the vertices they
    // made had been the last 11 ms of a 128,000-vertex outline and the last
    // 92 ms of a plate of 100,000 holes, on one thread while the other
    // waited (RESULTS.md, "Page faults and the sequential phases",
    // thirty-fourth session).
    std::vector<std::vector<std::array<int, 2> > > joins(P);
    for(std::size_t p = 1; p < P; ++p) {
      const int r = roots_[p];
      if(parent_[std::size_t(r)] != NO_INDEX)   // (the first part of a connected part has none)
        joins[p].push_back({{parent_[std::size_t(r)], r}});
    }
    for(const auto& d : off_tree_) {
      const int a = part_[std::size_t(d[0])], b = part_[std::size_t(d[1])];
      if(a != b) joins[std::size_t((std::max)(a, b))].push_back(d);
    }
    // The half-edges of the two sides of each of those diagonals, each
    // written by the part that builds its triangle once it is built (in
    // that part's structure's numbering, shifted when the part is moved),
    // so that the part's triangles can go at once (release_part()).
    // `join_side_of[p]` lists the sides in part p: (q, index in joins[q],
    // which end).
    std::vector<std::vector<std::array<int, 2> > > join_sides(P);
    std::vector<std::vector<std::array<int, 3> > > join_side_of(P);
    for(std::size_t q = 1; q < P; ++q) {
      join_sides[q].assign(joins[q].size(), std::array<int, 2>{{NO_INDEX, NO_INDEX}});
      for(std::size_t j = 0; j < joins[q].size(); ++j)
        for(int end = 0; end < 2; ++end)
          join_side_of[std::size_t(part_[std::size_t(joins[q][j][std::size_t(end)])])].push_back(
            {{int(q), int(j), end}});
    }
    std::atomic<std::size_t> parts_built{0};
    std::vector<Hds> structures(P);
    std::vector<Divide_and_conquer_counts> part_counts(P);
    std::vector<double> part_seconds(P, 0);
    std::vector<typename Hds::Offsets> offsets(P);
    // the parts built, the next one to move, and whether a thread is moving
    // parts (under `moving_mutex`)
    std::vector<char> built(P, 0);
    std::size_t next_to_move = 1;
    bool moving = false;
    std::mutex moving_mutex;
    // The next part to start.  Parts start in their order, so that a part
    // is moved soon after it is built and few wait: with oneTBB's
    // parallel_for over the parts, a second thread took the second half of
    // them, which waited until the first thread had built the first half.
    std::atomic<std::size_t> next_to_start{0};
    // The structures of parts moved, emptied but with their arrays, for the
    // parts still to start (under `pool_mutex`), each reserved for the
    // largest part: a part built in one takes no new memory.  A one-shot of
    // many points gave the memory that parts freed back to the system after
    // every 8,192 triangles moved (`malloc_trim()`), and the next parts took
    // it again, one page fault per page: on two threads, 10% to 13% of the
    // time of a 128,000-vertex outline (RESULTS.md, "The parts' memory
    // reused", thirty-third session).  Now the memory is given back once all
    // parts have started and once they are all moved.
    std::vector<Hds> pool;
    std::mutex pool_mutex;
    bool pool_released = false;   // (only the thread moving parts sets it)
    const std::size_t largest = *std::max_element(size_.begin(), size_.end());
    // merges the diagonals of part q (it and the parts before it are in the
    // result's structure; their half-edges were numbered in their part's
    // structure, `offsets` says where it went)
    auto merge_joins = [&](std::size_t q, Divide_and_conquer_counts& c) {
      for(std::size_t j = 0; j < joins[q].size(); ++j) {
        const std::array<int, 2>& h = join_sides[q][j];
        CGAL_assertion(h[0] != NO_INDEX && h[1] != NO_INDEX);
        c.add(engine_.merge(h[0], h[1], c));
      }
    };
    // (by the thread that built part p, once it is built)
    auto record_join_sides = [&](std::size_t p) {
      for(const auto& x : join_side_of[p]) {
        const auto& d = joins[std::size_t(x[0])][std::size_t(x[1])];
        join_sides[std::size_t(x[0])][std::size_t(x[1])][std::size_t(x[2])] =
          side(d[std::size_t(x[2])], d[std::size_t(1 - x[2])]);
      }
    };
    Divide_and_conquer_counts join_counts;   // (only the thread moving parts adds)
    auto move_built_parts = [&](std::size_t p) {
      std::unique_lock<std::mutex> lock(moving_mutex);
      built[p] = 1;
      if(moving) return;   // that thread moves p too, if it is next
      moving = true;
      while(built[0] && next_to_move < P && built[next_to_move]) {
        const std::size_t q = next_to_move;
        lock.unlock();   // (only this thread touches the result's structure)
        const bool starting = next_to_start.load() < P;
        offsets[q] = engine_.hds().append(structures[q], starting);
        for(const auto& x : join_side_of[q])   // (the sides of part q, now in the result's numbering)
          join_sides[std::size_t(x[0])][std::size_t(x[1])][std::size_t(x[2])] += offsets[q].halfedge;
        if(starting) {
          std::lock_guard<std::mutex> pool_lock(pool_mutex);
          pool.push_back(std::move(structures[q]));
        } else if(!pool_released || q + 1 == P) {
          if(!pool_released) {
            std::lock_guard<std::mutex> pool_lock(pool_mutex);
            free_vector(pool);
            pool_released = true;
          }
          release_free_memory(engine_.points().size());
        }
        run_part([&] {
          merge_joins(q, join_counts);
          engine_.resolve_pending();   // (the vertices those merges made)
        });
        lock.lock();
        ++next_to_move;
      }
      moving = false;
    };
    auto build = [&](std::size_t p) {
      const auto t0 = std::chrono::steady_clock::now();
      bool stopped = abandoned();   // (see abandon_above(): the part is left as it is)
      if(!stopped) {
        run_part([&] {
          const bool own = p > 0 && !one_thread;
          Hds& hds = own ? structures[p] : engine_.hds();
          if(own) {
            {
              std::lock_guard<std::mutex> pool_lock(pool_mutex);
              if(!pool.empty()) {
                hds = std::move(pool.back());
                pool.pop_back();
              }
            }
            hds.reserve_for_triangles(largest);
          }
          Part_progress progress;
          if(p < probed_.size() && probed_[p])
            progress = take_probed(p, hds, part_counts[p]);
          Engine engine(hds, engine_.points(), engine_.traits());
          build_part(engine, int(p), part_counts[p], progress);
          stopped = abandoned();
          if(stopped)
            return;
          engine.resolve_pending();
          record_join_sides(p);
          release_part(p);
        });
      }
      if(++parts_built == P)   // (no part reads the triangles any more)
        free_triangles();
      if(!one_thread && !stopped)   // (a part stopped is never moved: nor are those after it)
        move_built_parts(p);
      part_seconds[p] = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    };
    bool parallel = !one_thread;
#ifdef CGAL_PMA2_USE_TBB
    if(parallel && mode == PARTS_PARALLEL_IF_WORTH_IT && !tbb_running()) {
      // the parts one after the other, until the ones left look worth
      // starting oneTBB for: their triangles at the rate of the parts done
      parallel = false;
      double seconds = 0;
      std::size_t done = 0;
      while(next_to_start < P && !parallel && !abandoned()) {
        const std::size_t p = next_to_start++;
        build(p);
        seconds += part_seconds[p];
        done += size_[p];
        parallel = next_to_start < P && seconds * double(std::size_t(T) - done) >= min_parallel_seconds * double(done);
      }
    }
    if(parallel) {
      const std::size_t workers = (std::min)(arena_threads(), P - next_to_start);
      tbb::parallel_for(std::size_t(0), workers, [&](std::size_t) {
        for(std::size_t p; (p = next_to_start++) < P;)
          build(p);
      }, tbb::simple_partitioner());
    } else
#endif
      for(std::size_t p; (p = next_to_start++) < P;)
        build(p);
    (void)parallel;
    for(const auto& c : part_counts) counts.add(c);
    counts.parts = P;
    for(double t : part_seconds) {
      counts.parts_seconds_sum += t;
      counts.parts_seconds_max = (std::max)(counts.parts_seconds_max, t);
    }
    if(abandoned())
      return counts;
    const auto t_join = std::chrono::steady_clock::now();

    // 2. on one thread, the diagonals between parts (on several, the
    // thread that moved each part merged them; the arrays of the triangles
    // were freed when the last part was built)
    if(one_thread)
      for(std::size_t q = 1; q < P; ++q) merge_joins(q, counts);
    CGAL_assertion(one_thread || next_to_move == P);
    counts.add(join_counts);
    engine_.resolve_pending();
    counts.join_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t_join).count();
    return counts;
  }

  std::size_t number_of_parts() const { return roots_.size(); }

  /// From now on, run() stops building parts as soon as the merges of one
  /// part have crossed more than `events_per_triangle` cells (switches and
  /// vanishings) a triangle of it, after a start of `slack_triangles`
  /// triangles' worth; abandoned() then says so, and the engine's structure
  /// is to be dropped.  (Without this call, it never stops; with 0 and 0,
  /// at the first merge that crosses a cell, for tests.)
  void abandon_above(std::size_t events_per_triangle, std::size_t slack_triangles)
  {
    may_abandon_ = true;
    abandon_rate_ = events_per_triangle;
    abandon_slack_ = slack_triangles;
  }
  bool abandoned() const { return abandoned_.load(std::memory_order_relaxed); }

  /// The mean number of events (switches and vanishings) of a merge where
  /// the axis grows one triangle at a time, as in a part: the first `limit`
  /// triangles of `seeds` parts spread over the tree (of a cut into `parts`
  /// parts, which run() then uses), built in structures of their own.
  /// Where the triangles are long and thin against the boundary edges
  /// around them (curves sampled finely against the width of the shape),
  /// every merge crosses the cells of all the short edges near its
  /// diagonal: 27 to 40 events a merge in the first 48 triangles of four
  /// parts of some glyphs whose curves were flattened into 32 or 80 segments,
  /// against 4 to 13 on the country outlines, integer grids, Koch
  /// snowflakes and regular polygons of the benchmarks (33 on regular
  /// polygons with regular holes; RESULTS.md, "Finely sampled curves",
  /// nineteenth session).  One part alone is not enough:
  /// the first part of c1m_USA_3 took 30 events a merge.  The triangles
  /// built are kept: run() goes on from them (take_probed() appends their
  /// structures to those the parts are built in), so a probe that keeps the
  /// divide and conquer costs nothing but that append.
  double probe(std::size_t parts, std::size_t seeds, std::size_t limit)
  {
    if(triangles_.empty())
      return 0;
    prepare(parts);
    Divide_and_conquer_counts counts;
    const std::size_t P = roots_.size(), S = (std::min)(seeds, P);
    probed_.resize(P);
    for(std::size_t i = 0; i < S; ++i) {
      const std::size_t p = i * P / S;
      auto probed = std::make_unique<Probed_part>();
      Engine engine(probed->hds, engine_.points(), engine_.traits());
      build_part(engine, int(p), probed->counts, probed->progress, limit);
      counts.add(probed->counts);
      probed_[p] = std::move(probed);
    }
    return counts.merges == 0 ? 0 : double(counts.switches + counts.vanishings) / double(counts.merges);
  }

private:
  // The spanning tree, its cut into about `parts` parts, and the arrays of
  // the triangles' sides.
  void prepare(std::size_t parts)
  {
    const std::size_t T = triangles_.size();
    // (the order is needed here only: freed before the parts take memory)
    std::vector<int> order;
    spanning_tree(order);
    cut(parts == 0 ? 1 : parts, order);
    number_by_part(order);
    sides_.assign(T, std::array<int, 3>{{NO_INDEX, NO_INDEX, NO_INDEX}});
    added_.assign(T, 0);
    probed_.clear();
    prepared_ = true;
    prepared_parts_ = parts;
  }

  // Breadth-first spanning tree of the dual graph from triangle 0: the
  // parent of each triangle, the `order`, and the diagonals off the tree.
  void spanning_tree(std::vector<int>& order)
  {
    const int T = int(triangles_.size());
    parent_.assign(std::size_t(T), NO_INDEX);
    off_tree_.clear();
    order.clear();
    order.reserve(std::size_t(T));
    std::vector<char> seen(std::size_t(T), 0);
    // a spanning forest: one tree per connected part of the interior (several
    // where the outer ring is pinched, touching itself at a vertex)
    int next_root = 0;
    for(std::size_t i = 0; i < std::size_t(T); ++i) {
      if(i == order.size()) {
        while(seen[std::size_t(next_root)]) ++next_root;
        seen[std::size_t(next_root)] = 1;
        order.push_back(next_root);
      }
      const int t = order[i];
      for(int e = 0; e < 3; ++e) {
        const int u = triangles_[std::size_t(t)].nbr[e];
        if(u < 0) continue;
        if(!seen[std::size_t(u)]) {
          seen[std::size_t(u)] = 1;
          parent_[std::size_t(u)] = t;
          order.push_back(u);
        } else if(u != parent_[std::size_t(t)] && parent_[std::size_t(u)] != t && t < u) {
          off_tree_.push_back({{t, u}});
        }
      }
    }
    CGAL_assertion(order.size() == std::size_t(T));
  }

  // Cuts the tree, whose triangles are in breadth-first `order`, bottom-up
  // into subtrees of at least T / parts triangles (the root's part takes
  // the rest).  roots_[0] is the root of the tree.
  //
  // Parts start in the order of their roots, so the last ones run while
  // the other threads finish theirs, and a thread can be left waiting for
  // up to a whole part: on two threads, the last part of c1m_CHN_0 (of 25)
  // ended 13 ms after the other thread's.  So where parts run on several
  // threads, the last `tail_parts` parts' worth of triangles in the
  // breadth-first order are cut into parts `tail_divisor` times smaller
  // (their subtrees hold only triangles after them in that order): the
  // threads end closer together, for a few more diagonals between parts.
  // On two threads (60 parts instead of 25 on c1m_CHN_0) the whole tool
  // took 0% to 3% less time on three real outlines, in runs of a noisy VM
  // (RESULTS.md, forty-first session).  This is done only where the
  // smaller parts still hold divide_and_conquer_min_tail_target() (256)
  // triangles or more (parts of 2,048): smaller parts take a few
  // milliseconds at most, and the cut of small polygons stays the one that
  // the probe's choice of a driver was measured on (a glyph of 646
  // triangles otherwise took the divide and conquer where boundary
  // evolution is cheaper).  The tail is at most half of the parts' worth:
  // with fewer than 2 * tail_parts parts (the four parts a thread of
  // default_parts() on two threads) it was every part, and on a 20,000-gon,
  // whose joins cross the cells near its centre, the 8 parts of two threads
  // became 53 parts of about 312 triangles, and the one-shot took 0.50 s;
  // with the tail at most half of the triangles (7 parts there) 0.35 s, and
  // without a tail 0.36 s (RESULTS.md, fifty-ninth session).
  static constexpr std::size_t tail_parts = 8;
  static constexpr int tail_divisor = 8;
  void cut(std::size_t parts, const std::vector<int>& order)
  {
    const int T = int(triangles_.size());
    const int target = (std::max)(1, int((std::size_t(T) + parts - 1) / parts));
    const int tail_target = target / tail_divisor;
    const int min_tail_target = (std::max)(1, divide_and_conquer_min_tail_target().load(std::memory_order_relaxed));
    const bool taper = parts > 1 && arena_threads() > 1 && tail_target >= min_tail_target;
    const std::size_t tail = (std::min)(tail_parts, parts / 2) * std::size_t(target);
    const std::size_t tail_from = taper ? order.size() - (std::min)(order.size(), tail) : order.size();
    std::vector<int> size(std::size_t(T), 1);
    std::vector<char> is_root(std::size_t(T), 0);
    for(std::size_t i = order.size(); i-- > 0;) {
      const int t = order[i];
      if(parent_[std::size_t(t)] == NO_INDEX || size[std::size_t(t)] >= (i >= tail_from ? tail_target : target))
        is_root[std::size_t(t)] = 1;
      else
        size[std::size_t(parent_[std::size_t(t)])] += size[std::size_t(t)];
    }
    roots_.clear();
    size_.clear();
    part_.assign(std::size_t(T), 0);
    for(int t : order) {
      if(is_root[std::size_t(t)]) {
        part_[std::size_t(t)] = int(roots_.size());
        roots_.push_back(t);
        size_.push_back(0);
      } else {
        part_[std::size_t(t)] = part_[std::size_t(parent_[std::size_t(t)])];
      }
      ++size_[std::size_t(part_[std::size_t(t)])];
    }
  }

  // Frees the arrays of the triangles (once every part is built).
  void free_triangles()
  {
    free_vector(parent_);
    free_vector(part_);
    free_vector(triangles_);
    free_vector(sides_);
    free_vector(added_);
    free_vector(off_tree_);
    probed_.clear();
  }

  // Gives the memory of part p's triangles back to the system once the part
  // is built (its range of the arrays: the triangles are numbered part by
  // part, see number_by_part()), where the one-shot gives memory back
  // (gives_memory_back(): not where the program goes on computing, whose
  // arrays would take those pages again, one fault each).  No part reads
  // another part's range after its `part_`, which is kept.  The peak of a
  // large one-shot is at the end of its last part, the whole axis beside
  // all the triangles' arrays (45 bytes a triangle); on a plate of 100,000
  // holes the arrays were 36 MB of it (RESULTS.md, thirty-seventh session).
  void release_part(std::size_t p)
  {
    if(!gives_memory_back(engine_.points().size())) return;
    const std::size_t b = start_[p], e = b + size_[p];
    release_pages(triangles_, b, e);
    release_pages(sides_, b, e);
    release_pages(parent_, b, e);
    release_pages(added_, b, e);
  }

  // Numbers the triangles part by part (part 0 first; in each part in the
  // breadth-first `order`), so that each part's triangles are a range of
  // the arrays (`start_`): in place, by the cycles of the permutation.  The
  // parts are built in the same order as before it, so the axis is numbered
  // the same.  (A second prepare() with another number of parts, which the
  // one-shot does not make, would start its tree from another triangle:
  // another cut, the same axis.)
  void number_by_part(const std::vector<int>& order)
  {
    const std::size_t T = triangles_.size(), P = roots_.size();
    start_.assign(P, 0);
    for(std::size_t p = 1; p < P; ++p) start_[p] = start_[p - 1] + size_[p - 1];
    std::vector<int> to(T);
    {
      std::vector<std::size_t> next(start_);
      for(int t : order) to[std::size_t(t)] = int(next[std::size_t(part_[std::size_t(t)])]++);
    }
    auto renamed = [&](int t) { return t < 0 ? t : to[std::size_t(t)]; };
    for(Triangle& x : triangles_)
      for(int& n : x.nbr) n = renamed(n);
    for(int& u : parent_) u = renamed(u);
    for(auto& d : off_tree_) d = {{renamed(d[0]), renamed(d[1])}};
    for(int& r : roots_) r = renamed(r);
    // each element to its place, cycle by cycle (to[t] < 0: placed)
    for(std::size_t t = 0; t < T; ++t) {
      while(to[t] >= 0 && std::size_t(to[t]) != t) {
        const std::size_t u = std::size_t(to[t]);
        std::swap(triangles_[t], triangles_[u]);
        std::swap(parent_[t], parent_[u]);
        std::swap(to[t], to[u]);
        to[u] = -1;
      }
      to[t] = -1;
    }
    for(std::size_t p = 0; p < P; ++p)
      std::fill(part_.begin() + std::ptrdiff_t(start_[p]), part_.begin() + std::ptrdiff_t(start_[p] + size_[p]), int(p));
  }

  int side_towards(int u, int t) const { return internal::side_towards(triangles_, u, t); }

  // The half-edge of triangle t's side along its diagonal with triangle u.
  int side(int t, int u) const { return sides_[std::size_t(t)][std::size_t(side_towards(t, u))]; }

  // Adds triangle t, merged along its tree diagonal to its parent (already
  // in the structure of `engine`), or as the first triangle of its part.
  void add(Engine& engine, int t, bool first, Divide_and_conquer_counts& counts)
  {
    const Triangle& T = triangles_[std::size_t(t)];
    if(first) {
      const int none[3] = {NO_INDEX, NO_INDEX, NO_INDEX};
      sides_[std::size_t(t)] = engine.add_triangle(T.v, none);
      return;
    }
    const int u = parent_[std::size_t(t)];
    const int e = side_towards(t, u);
    const int h = side(u, t);
    sides_[std::size_t(t)] = engine.add_triangle_across(T.v, e, h);
    counts.add(engine.merge(h, sides_[std::size_t(t)][std::size_t(e)], counts));
  }

  // Where the building of a part stands: its triangles added (in the
  // global breadth-first order: a parent comes before its children), and
  // the next neighbour to look at (side `side` of triangle queue[next]).
  struct Part_progress {
    std::vector<int> queue;
    std::size_t next = 0;
    int side = 0;
  };

  // The first triangles of a part, built by probe() in a structure of
  // their own.
  struct Probed_part {
    Hds hds;
    Part_progress progress;
    Divide_and_conquer_counts counts;
  };

  // Moves the triangles that probe() built of part p to the end of `hds`
  // (the half-edges of their sides shift with them) and their counts to
  // `counts`; returns where the part's building stands.
  Part_progress take_probed(std::size_t p, Hds& hds, Divide_and_conquer_counts& counts)
  {
    Probed_part& probed = *probed_[p];
    counts.add(probed.counts);
    const int shift = hds.append(probed.hds).halfedge;
    if(shift != 0)
      for(int t : probed.progress.queue)
        for(int& h : sides_[std::size_t(t)])
          if(h >= 0) h += shift;
    Part_progress progress = std::move(probed.progress);
    probed_[p].reset();
    return progress;
  }

  // Builds part p from where `progress` stands, until it is whole or holds
  // `limit` triangles.
  void build_part(Engine& engine, int p, Divide_and_conquer_counts& counts, Part_progress& progress,
                  std::size_t limit = (std::numeric_limits<std::size_t>::max)())
  {
    std::vector<int>& queue = progress.queue;
    if(queue.empty()) {
      const int root = roots_[std::size_t(p)];
      queue.push_back(root);
      add(engine, root, true, counts);
      added_[std::size_t(root)] = 1;
    }
    for(; progress.next < queue.size(); ++progress.next, progress.side = 0) {
      const int t = queue[progress.next];
      for(; progress.side < 3; ++progress.side) {
        const int u = triangles_[std::size_t(t)].nbr[progress.side];
        if(u < 0 || part_[std::size_t(u)] != p || parent_[std::size_t(u)] != t) continue;   // (part_ first: see release_part())
        if(queue.size() >= limit) return;   // (goes on from this side)
        add(engine, u, false, counts);
        added_[std::size_t(u)] = 1;
        queue.push_back(u);
        // a hole-closing diagonal of the part, as soon as both its sides are in
        for(int f = 0; f < 3; ++f) {
          const int w = triangles_[std::size_t(u)].nbr[f];
          if(w >= 0 && w != t && part_[std::size_t(w)] == p && added_[std::size_t(w)] && parent_[std::size_t(w)] != u)
            merge_along(engine, u, w, counts);
        }
        if(abandon(counts, queue.size())) return;
      }
    }
  }

  // Whether the parts stop (see abandon_above()): the part whose `counts`
  // are given, with `triangles` triangles, crossed too many cells, or
  // another part did.
  bool abandon(const Divide_and_conquer_counts& counts, std::size_t triangles)
  {
    if(!may_abandon_)
      return false;
    if(abandoned())
      return true;
    if(counts.switches + counts.vanishings <= abandon_rate_ * (triangles + abandon_slack_))
      return false;
    abandoned_.store(true, std::memory_order_relaxed);
    return true;
  }

  // Merges the sides of triangles t and u along their common diagonal.
  void merge_along(Engine& engine, int t, int u, Divide_and_conquer_counts& counts)
  {
    counts.add(engine.merge(side(t, u), side(u, t), counts));
  }

  Engine& engine_;
  std::vector<Triangle> triangles_;
  std::vector<int> parent_, roots_, part_;
  std::vector<std::size_t> size_;   // triangles of each part
  std::vector<std::size_t> start_;   // the first triangle of each part (see number_by_part())
  std::vector<std::array<int, 2> > off_tree_;
  std::vector<std::array<int, 3> > sides_;
  std::vector<char> added_;   // written by the part of each triangle only
  std::vector<std::unique_ptr<Probed_part> > probed_;   // by part: what probe() built of it
  bool prepared_ = false;   // whether prepare() made the cut into `prepared_parts_` parts
  std::size_t prepared_parts_ = 0;
  bool may_abandon_ = false;   // see abandon_above()
  std::size_t abandon_rate_ = 0, abandon_slack_ = 0;
  std::atomic<bool> abandoned_{false};
};

/// The number of parts of a one-shot of `triangles` triangles: parts of
/// about 4,096 triangles, at least four per thread of the current task
/// arena (on one thread too), and of at least 32 triangles.  Balanced
/// parts merged pairwise do less work than one part
/// grown a triangle at a time where many generators are cocircular: on one
/// thread, a regular 1000-gon took 279 ms in one part and 89 ms in four, a
/// Koch snowflake of 384 vertices 19.7 ms and 13.4 ms, country outlines
/// about 6% less, integer grids the same (RESULTS.md, 2026-11-26).  Small
/// parts also keep the threads busy to the end: with four parts per thread,
/// a thread that took the slowest part left the other idle for up to a
/// part's time (country outlines of 80,000 to 128,000 vertices on two
/// threads took 5% to 8% less time in 32 parts than in 8; RESULTS.md,
/// "More parts", fourteenth session).  Each part costs a little in the join,
/// which is why the parts of smaller polygons stay larger.  Large polygons
/// are no longer held to sixteen parts a thread: on several threads each
/// part is built in a structure of its own, kept beside the result's until
/// the parts before it are moved, and the emptied structures are kept for
/// the next parts, so a few parts' worth of memory sits beside the axis.
/// In parts of 4,096 triangles, on two threads, a plate of 170,000 holes
/// peaked 44 to 51 MiB lower (508 and 515 -> 464 MiB) and three of the
/// largest land-10m polygons 4 to 56 MiB lower (3% to 12%); on one thread a
/// plate of 100,000 holes peaked 10 MiB lower (not explained); the times stayed
/// within this VM's noise (RESULTS.md, "Smaller parts for large polygons",
/// fifty-third session).
inline std::size_t default_parts(std::size_t triangles)
{
  const std::size_t threads = arena_threads();
  const std::size_t by_size = (std::max)(triangles / 4096, 4 * threads);
  return (std::max)(std::size_t(1), (std::min)(by_size, triangles / 32));
}

/// Runs `driver` into its engine's structure (see below), gathering the
/// filter counters of the other threads into the caller's.
template <class Traits>
Divide_and_conquer_counts divide_and_conquer(Divide_and_conquer<Traits>& driver, std::size_t parts, Parts_mode mode)
{
  Thread_counters<Traits> counters;
  std::mutex mutex;
  const std::thread::id caller = std::this_thread::get_id();
  const Divide_and_conquer_counts counts =
    driver.run(parts, mode, [&](const auto& task) { counters.run_counted(caller, mutex, task); });
  if constexpr(!std::is_empty<Thread_counters<Traits> >::value)
    counters.gather();
  return counts;
}

/// How the parts of a one-shot of traits `Traits` with `parts` parts (0:
/// the default) run, and how many there are for `triangles` triangles.
template <class Traits>
std::pair<std::size_t, Parts_mode> one_shot_parts(std::size_t parts, std::size_t triangles)
{
  const bool doubles = std::is_floating_point<typename Traits::Kernel::FT>::value;
  const Parts_mode mode = !doubles ? PARTS_SEQUENTIAL : (parts != 0 ? PARTS_PARALLEL : PARTS_PARALLEL_IF_WORTH_IT);
  if(parts == 0)
    parts = doubles ? default_parts(triangles) : 1;
  return std::make_pair(parts, mode);
}

/// The axis of the polygon of `triangles` (its constrained Delaunay
/// triangulation) by divide and conquer, into the engine's structure, in
/// `parts` parts, or with 0 as many as default_parts() chooses.
/// Parts run in parallel only on a kernel of doubles (Epick, or
/// Simple_cartesian<double>): the number types of exact kernels (CORE::Expr,
/// the lazy numbers of Epeck) share state between threads in CGAL 5.5.
/// With the default number of parts, a call made where oneTBB does not run
/// yet builds parts on the calling thread and starts oneTBB only when the
/// parts left are worth it (see `min_parallel_seconds`); explicit parts
/// (the tests) always run in parallel.  The filter counters of the
/// other threads are added to the caller's.
template <class Traits>
Divide_and_conquer_counts divide_and_conquer(Medial_axis_engine<Traits>& engine, std::vector<Triangle> triangles,
                                             std::size_t parts = 0)
{
  const auto how = one_shot_parts<Traits>(parts, triangles.size());
  Divide_and_conquer<Traits> driver(engine, std::move(triangles));
  return divide_and_conquer(driver, how.first, how.second);
}

} // namespace internal
} // namespace Progressive_medial_axes
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_MEDIAL_AXIS_2_INTERNAL_DIVIDE_AND_CONQUER_H
