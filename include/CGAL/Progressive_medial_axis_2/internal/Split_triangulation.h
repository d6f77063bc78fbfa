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
// The triangulation of a large polygon in two sides, on two threads.
//
// CGAL triangulates in parallel only in 3D, and the triangulation was the
// one-shot's longest sequential phase (0.13 s of 0.63 s on a 128,000-vertex
// outline; RESULTS.md, twenty-sixth session).  So the polygon is cut into
// two polygons along a chord of its outer ring: a segment between two
// vertices of the outer ring, about half the ring apart, that lies inside
// the polygon and touches its boundary at its ends only.  Each side (its
// half of the outer ring closed by the chord, and the holes inside it) is
// triangulated on its own (Ring_triangulation), the two at the same time,
// and the two sets of triangles are joined across the chord: the triangle
// on each side of it becomes the other's neighbour.  That is a
// triangulation of the polygon, but not Delaunay near the chord: the
// chord's ends are fans of long, thin triangles, and the divide and
// conquer's merges along their long diagonals cross many cells (a chord
// across a Chinese outline made the merges 0.1 s slower, 18%).  So Lawson's
// edge flips, from the chord, make it the constrained Delaunay
// triangulation of the polygon again (the same one as triangulated whole,
// up to the choice among cocircular points).
//
// The chord is looked for among pairs of outer-ring vertices drawn from a
// fixed pseudo-random sequence: vertex i and vertex i + m/2 +- m/10 of the m.
// A pair is a chord where the segment leaves each end strictly inside the
// polygon's angle there and no edge of any ring crosses or touches it
// (exact orientations, after a bounding-box test; an edge on the chord's
// line inside its box is taken as touching).  Real outlines have such pairs
// (7% of random pairs on a Chinese outline, 0.5% to 2% on Canadian and
// South African ones), a star-shaped polygon with a small kernel may have
// none: then, after 256 pairs, the polygon is triangulated whole.  Most
// pairs are rejected early, so that costs 0.4 to 7 ms on outlines of
// 20,000 to 110,000 vertices, while another thread checks the polygon.
// The sides' times follow their sizes (a 60:40 cut of a Chinese outline
// took 105 and 63 ms to insert), so the search goes on to the chord of the
// 256 pairs nearest the share asked for, or one within m/32 of it.  The
// calling thread triangulates side 1, another thread side 0.  Where the
// check of the polygon runs beside (the one-shot), the thread that checks
// it takes side 0 only then, so side 1 gets split_triangulation_caller_share
// of the outer ring; an even cut left the calling thread waiting 16 to 29
// ms for the other on country outlines of 80,000 to 128,000 vertices
// (RESULTS.md, sixty-first session).
// A hole goes to the side that holds its first vertex: a ray from it
// crosses that side's boundary an odd number of times (the holes sorted
// by height, each edge of the side looks at those at its heights).
//
// Where the outer ring has no chord (fewer than 16 vertices, as a plate's
// square with 100,000 holes, or every pair blocked by holes), the cut is a
// path through holes: from vertex a of the outer ring to vertex b, along
// the segment ab, whose crossings with the rings' edges give the holes it
// passes through, in order (it may meet the outer ring only at a and b,
// and each hole in one stretch).  The path goes from a to an end of the
// first edge of the first hole that ab crosses, along that hole's ring to
// an end of the last edge ab crosses there, on to the next hole, and from
// the last one to b.  Each of its segments joins two vertices near those
// edges (ends of the edges, or up to eight vertices around them along
// their rings) that see each other: the segment leaves both strictly inside the
// polygon's angle, no edge but the four at its ends crosses or touches it
// (exact orientations, the edges in a grid of cells of about one edge
// each), nor does any segment of the path before it.  The two sides are
// then simple polygons: side 0 is the outer ring from a to b, then the
// path back, each hole of the path from its exit to its entry along its
// ring; side 1 the outer ring from b to a, then the path, each hole from
// its entry to its exit (every ring with the interior on its left).  The
// joins and the flips are as for a chord, from every segment of the path.
// The share is the outer ring's, as for a chord; a path that leaves a side
// less than a quarter of the points is not taken.  Where the sides'
// triangles are not n + 2h - 2 (n points, h holes), as a triangulation of
// the polygon has, the polygon is triangulated whole.
//
// The split is only for polygons whose rings do not touch: where two
// points are at one place, or a point lies in an edge (a "T"), the polygon
// is triangulated whole, as the corners of such places need all their
// rings, and a T whose point and edge fall on different sides would go
// unseen by both.  Points at one place are looked for with the cut (2 to
// 3 ms on 128,000 points); T's are found by the check of the polygon, both
// beside the sides' Delaunay triangulations, which are then done in vain.
// So the one-shot splits only polygons it checks itself (CHECK_INPUT).

#ifndef CGAL_PROGRESSIVE_MEDIAL_AXIS_2_INTERNAL_SPLIT_TRIANGULATION_H
#define CGAL_PROGRESSIVE_MEDIAL_AXIS_2_INTERNAL_SPLIT_TRIANGULATION_H

#include <CGAL/Progressive_medial_axis_2/internal/Input_conversion.h>
#include <CGAL/Progressive_medial_axis_2/internal/Triangulate.h>

#if defined(CGAL_LINKED_WITH_TBB) && !defined(CGAL_PMA2_NO_TBB)
#include <tbb/task_group.h>
#endif

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <random>
#include <tuple>
#include <utility>
#include <vector>

namespace CGAL {
namespace Progressive_medial_axes {
namespace internal {

/// From this many vertices on, a one-shot run on two threads or more
/// triangulates the polygon in two sides (a setting, so that tests can
/// lower it).  Below it the triangulation takes a few milliseconds.
inline std::atomic<std::size_t>& split_triangulation_min_vertices()
{
  static std::atomic<std::size_t> vertices(std::size_t(1) << 15);
  return vertices;
}

/// Whether a cut is looked for first as a path through holes, then as a
/// chord (a setting, so that tests can take that way on polygons that have
/// chords too).
inline std::atomic<bool>& split_triangulation_paths_first()
{
  static std::atomic<bool> paths_first(false);
  return paths_first;
}

/// The pairs of vertices tried as a chord.
constexpr int split_triangulation_tries = 256;

/// The share of the outer ring that goes to the side the calling thread
/// triangulates (side 1) where the other thread first checks the polygon.
/// The check took 0.28 to 0.45 of the time of the two sides' Delaunay
/// triangulations on five country outlines, and the chord's search 0.03:
/// by those times the two threads end together at shares of 0.59 to 0.66
/// (0.72 on one outline whose side 0 held more holes); the side that
/// the calling thread builds also takes a little more time a vertex
/// (RESULTS.md, sixty-first session).
constexpr double split_triangulation_caller_share = 0.6;

template <class Kernel>
class Split_triangulation
{
  typedef Exact_predicates_kernel_for<Kernel> TK;
  typedef typename TK::type K;
  typedef typename K::Point_2 Point;
  typedef std::chrono::steady_clock Clock;

public:
  /// Looks for a cut of `rings`, a chord of the outer ring or else a path
  /// through holes, that leaves about `caller_share` of the outer ring's
  /// vertices to side 1, and places the other holes; false if none was
  /// found.  Needs finite coordinates only: it runs while the polygon is
  /// being checked, and its result is used once the polygon is valid.
  template <class Point_2>
  bool find_cut(const std::vector<std::vector<Point_2> >& rings, double caller_share = 0.5);

  /// The holes that the cut goes through (0 for a chord).
  std::size_t holes_on_cut() const { return path_holes_.size(); }

  /// Phase 1: the Delaunay triangulation of each side's points, the two at
  /// the same time (after find_cut()), side 1 on the calling thread.
  template <class Point_2>
  void insert_points(const std::vector<std::vector<Point_2> >& rings);

  /// Phase 2, on the valid polygon of `data` (set_points() of the same
  /// rings): the triangles of both sides, joined across the cut, into
  /// `out`.  False (and `out` unchanged) where the polygon's rings touch.
  template <class Data>
  bool finish(const Data& data, std::vector<Triangle>& out);

  /// The time the two sides' tasks ran beside each other (their summed
  /// times less the wall time of the phases that ran them).
  double parallel_seconds() const { return parallel_seconds_; }

private:
  // Lawson's flips from the edges (triangle, side) `edges`: every diagonal
  // whose triangles' circle holds the opposite vertex is flipped, and the
  // four edges around it looked at again; edges of the polygon never are.
  // (An edge given is looked at where it is when its turn comes: a flip
  // that moved it looked at it again.)
  template <class Point_2>
  static void make_delaunay(const std::vector<Point_2>& points, std::vector<Triangle>& tris,
                            std::vector<std::pair<int, int> > edges);

  // A chord (i, j) of the outer ring, (j - i) mod m near `target`, or false.
  template <class Point_2>
  bool find_chord(const std::vector<std::vector<Point_2> >& rings, std::size_t target);
  // A path from vertex i to vertex j of the outer ring, (j - i) mod m near
  // `target`, through the holes that the segment ij crosses, or false.
  template <class Point_2>
  bool find_path(const std::vector<std::vector<Point_2> >& rings, std::size_t target);
  // The boundary of side s, with the interior on its left: global indices
  // of its points, in order (closed: the last one's successor is the first).
  std::vector<std::size_t> side_boundary(int s) const;
  // the ring of the point of global index g
  std::size_t ring_of(std::size_t g) const
  {
    return std::size_t(std::upper_bound(ring_start_.begin(), ring_start_.end(), g) - ring_start_.begin()) - 1;
  }

  // whether the segments pq and uw cross or touch (or lie on one line,
  // overlapping); a bounding-box test first
  static bool meets(const Point& p, const Point& q, const Point& u, const Point& w)
  {
    if((std::max)(x(u), x(w)) < (std::min)(x(p), x(q)) || (std::min)(x(u), x(w)) > (std::max)(x(p), x(q)) ||
       (std::max)(y(u), y(w)) < (std::min)(y(p), y(q)) || (std::min)(y(u), y(w)) > (std::max)(y(p), y(q)))
      return false;
    const auto orientation = K().orientation_2_object();
    const Orientation ou = orientation(p, q, u), ow = orientation(p, q, w);
    if(ou == ow && ou != COLLINEAR) return false;   // both on one side of the line
    if(ou == COLLINEAR && ow == COLLINEAR) return true;   // on the line, in the box
    return orientation(u, w, p) != orientation(u, w, q);   // crosses or touches
  }
  // whether the direction from p towards q is strictly inside the polygon's
  // angle at p, whose ring goes u, p, w with the interior on its left
  static bool strictly_inside_angle(const Point& u, const Point& p, const Point& w, const Point& q)
  {
    const auto orientation = K().orientation_2_object();
    const bool left_of_in = orientation(u, p, q) == LEFT_TURN, left_of_out = orientation(p, w, q) == LEFT_TURN;
    return orientation(u, p, w) == LEFT_TURN ? left_of_in && left_of_out : left_of_in || left_of_out;
  }

  // f and g at the same time: g on the calling thread, f on another one
  // if one is free (else on this one, after g)
  template <class F, class G>
  void run_both(const F& f, const G& g)
  {
    const auto t0 = Clock::now();
    double seconds[2] = {0, 0};
    auto timed = [&](const auto& task, int s) {
      const auto t = Clock::now();
      task();
      seconds[s] = std::chrono::duration<double>(Clock::now() - t).count();
    };
#if defined(CGAL_LINKED_WITH_TBB) && !defined(CGAL_PMA2_NO_TBB)
    tbb::task_group group;
    group.run([&] { timed(f, 0); });
    timed(g, 1);
    group.wait();
#else
    timed(f, 0);
    timed(g, 1);
#endif
    const double wall = std::chrono::duration<double>(Clock::now() - t0).count();
    parallel_seconds_ += (std::max)(0.0, seconds[0] + seconds[1] - wall);
  }
  // (coordinates compared as doubles: for kernels of doubles, where this
  // is exact; the one-shot splits only there)
  static double x(const Point& p) { return CGAL::to_double(p.x()); }
  static double y(const Point& p) { return CGAL::to_double(p.y()); }
  // the vertex after / before vertex k of the outer ring, going with the
  // interior on the left
  std::size_t after(std::size_t k) const { return ccw_ ? (k + 1) % m_ : (k + m_ - 1) % m_; }
  std::size_t before(std::size_t k) const { return ccw_ ? (k + m_ - 1) % m_ : (k + 1) % m_; }

  std::size_t m_ = 0;          // vertices of the outer ring
  bool ccw_ = true;            // the outer ring is counter-clockwise as given
  std::size_t a_ = 0, b_ = 0;  // the cut's ends (indices in the outer ring)
  // the cut's points (global indices): a, then the entry and exit points
  // of each hole it goes through (p_1, q_1, ..., p_k, q_k), then b; its
  // segments are a p_1, q_1 p_2, ..., q_k b (a b for a chord)
  std::vector<std::size_t> cut_;
  std::vector<std::size_t> path_holes_;   // the rings of those holes, in order from a
  std::vector<char> hole_forward_;        // per such hole: its next point has the interior on its left
  std::vector<std::size_t> boundary_[2];  // side_boundary() of each side, once the cut is found
  // per ring: 0 side 0 (the outer ring from a to b, then the cut), 1
  // side 1 (from b to a), 2 on the cut (split between both)
  std::vector<char> side_of_ring_;
  std::vector<std::size_t> ring_start_;
  Ring_triangulation<Kernel> side_[2];
  double parallel_seconds_ = 0;
};

template <class Kernel>
template <class Point_2>
bool Split_triangulation<Kernel>::find_cut(const std::vector<std::vector<Point_2> >& rings, double caller_share)
{
  const K k;
  const auto orientation = k.orientation_2_object();
  m_ = rings[0].size();
  cut_.clear();
  path_holes_.clear();
  if(m_ < 3)
    return false;
  for(const auto& ring : rings)   // (the check of the polygon, running beside this, rejects such rings)
    if(ring.size() < 3)
      return false;
  ring_start_.assign(1, 0);
  for(const auto& ring : rings) ring_start_.push_back(ring_start_.back() + ring.size());
  const std::size_t n = ring_start_.back();
  auto at = [&](std::size_t r, std::size_t i) -> Point { return TK::point(rings[r][i]); };
  ccw_ = ring_counterclockwise(m_, [&](std::size_t i) { return at(0, i); }, orientation);
  // (the share asked for, as a number of edges of the outer ring after the
  // chord's or the path's first end: a cut (i, j) leaves the (j - i) mod m
  // edges of the outer ring after i to side 0 if the ring is
  // counter-clockwise, to side 1 if not)
  CGAL_precondition(caller_share >= 0.375 && caller_share <= 0.625);
  const std::size_t to_side_1 = std::size_t(double(m_) * caller_share);
  const std::size_t target = ccw_ ? m_ - to_side_1 : to_side_1;
  const bool paths_first = split_triangulation_paths_first().load(std::memory_order_relaxed);
  bool found = false, path = false;
  for(int attempt = 0; attempt < 2 && !found; ++attempt) {
    if((attempt == 0) != paths_first)
      found = m_ >= 16 && find_chord(rings, target);
    else
      found = path = rings.size() > 1 && find_path(rings, target);
  }
  if(!found)
    return false;
  // points at one place (rings that touch): the whole polygon, whose
  // triangulation links their corners (found here, not by the sides'
  // triangulations, which would then be done in vain)
  std::vector<Point> all;
  all.reserve(n);
  for(std::size_t r = 0; r < rings.size(); ++r)
    for(std::size_t i = 0; i < rings[r].size(); ++i) all.push_back(at(r, i));
  if(!repeated_points(all).empty())
    return false;

  // The holes not on the cut: the side whose boundary (the outer ring from
  // a to b, then the cut back from b to a; or the outer ring from b to a,
  // then the cut) a ray from the hole's first vertex to the right crosses an
  // odd number of times.  The vertices sorted by height give the holes
  // whose ray meets an edge.
  side_of_ring_.assign(rings.size(), 0);
  for(const std::size_t h : path_holes_) side_of_ring_[h] = 2;
  std::vector<std::pair<double, std::size_t> > starts;
  for(std::size_t r = 1; r < rings.size(); ++r)
    if(side_of_ring_[r] != 2) starts.emplace_back(y(at(r, 0)), r);
  std::sort(starts.begin(), starts.end());
  std::vector<char> odd(rings.size(), 0);
  bool on_boundary = false;
  std::size_t tests = 4 * n;   // (at most: tall edges and many holes would make it quadratic)
  auto count = [&](const Point& u, const Point& w) {
    const bool up = y(u) < y(w);
    const Point& lo = up ? u : w;
    const Point& hi = up ? w : u;
    // the starts with lo.y <= y < hi.y
    auto s = std::lower_bound(starts.begin(), starts.end(), std::make_pair(y(lo), std::size_t(0)));
    for(; s != starts.end() && s->first < y(hi); ++s) {
      if(tests == 0) {
        on_boundary = true;   // (no split)
        return;
      }
      --tests;
      const Orientation o = orientation(lo, hi, at(s->second, 0));
      if(o == COLLINEAR) on_boundary = true;
      else if(o == LEFT_TURN) odd[s->second] ^= 1;
    }
  };
  std::size_t side_points[2] = {0, 0};
  {
    for(int s = 0; s < 2; ++s) {
      boundary_[s] = side_boundary(s);   // (global indices, closed)
      side_points[s] = boundary_[s].size();
    }
    const std::vector<std::size_t>& boundary = boundary_[0];
    for(std::size_t i = 0; i < boundary.size() && !on_boundary; ++i)
      if(!starts.empty()) count(all[boundary[i]], all[boundary[(i + 1) % boundary.size()]]);
  }
  if(on_boundary)
    return false;
  for(std::size_t r = 1; r < rings.size(); ++r)
    if(side_of_ring_[r] != 2) {
      side_of_ring_[r] = odd[r] ? 0 : 1;
      side_points[int(side_of_ring_[r])] += rings[r].size();
    }
  // (a path through holes takes the outer ring's share, not the holes':
  // where the holes fall mostly on one side, the split would not pay)
  if(path && 4 * (std::min)(side_points[0], side_points[1]) < n)
    return false;
  return true;
}

template <class Kernel>
std::vector<std::size_t> Split_triangulation<Kernel>::side_boundary(int s) const
{
  // side 0: the outer ring from a to b, then the cut back from b to a (each
  // hole of the path from its exit to its entry); side 1: the outer ring
  // from b to a, then the cut from a to b (each hole from its entry to its
  // exit); every ring with the interior on its left
  std::vector<std::size_t> out;
  const std::size_t from = s == 0 ? a_ : b_, to = s == 0 ? b_ : a_;
  for(std::size_t e = from;; e = after(e)) {
    out.push_back(e);
    if(e == to) break;
  }
  const std::size_t k = path_holes_.size();
  for(std::size_t j = 0; j < k; ++j) {
    const std::size_t h = s == 0 ? k - 1 - j : j;   // (the path's holes, in the side's order)
    const std::size_t r = path_holes_[h], base = ring_start_[r], m = ring_start_[r + 1] - base;
    // cut_ = a, p_1, q_1, ..., p_k, q_k, b (global indices; entry p, exit q)
    const std::size_t entry = cut_[1 + 2 * h] - base, exit = cut_[2 + 2 * h] - base;
    const std::size_t first = s == 0 ? exit : entry, last = s == 0 ? entry : exit;
    for(std::size_t i = first;; i = hole_forward_[h] ? (i + 1) % m : (i + m - 1) % m) {
      out.push_back(base + i);
      if(i == last) break;
    }
  }
  return out;
}

template <class Kernel>
template <class Point_2>
bool Split_triangulation<Kernel>::find_chord(const std::vector<std::vector<Point_2> >& rings, std::size_t target)
{
  auto at = [&](std::size_t r, std::size_t i) -> Point { return TK::point(rings[r][i]); };
  // whether the direction from vertex i towards q is strictly inside the
  // polygon's angle at i
  auto inside_angle = [&](std::size_t i, const Point& q) {
    return strictly_inside_angle(at(0, before(i)), at(0, i), at(0, after(i)), q);
  };
  // whether no edge of any ring crosses or touches the segment pq, but the
  // four edges at its ends i and j (vertices of the outer ring)
  // (at most 16 n edges looked at in all, for outlines where many pairs
  // are rejected late)
  const std::size_t n = ring_start_.back();
  std::size_t budget = 16 * n;
  auto clear = [&](std::size_t i, std::size_t j, const Point& p, const Point& q) {
    for(std::size_t r = 0; r < rings.size(); ++r) {
      const std::size_t m = rings[r].size();
      for(std::size_t e = 0; e < m; ++e) {
        if(budget == 0)
          return false;
        --budget;
        const std::size_t f = e + 1 == m ? 0 : e + 1;
        if(r == 0 && (e == i || e == j || f == i || f == j)) continue;
        if(meets(p, q, at(r, e), at(r, f)))
          return false;
      }
    }
    return true;
  };

  // (the chord found nearest the share asked for, or the first within m/32
  // of it)
  std::minstd_rand random(std::uint_fast32_t(m_ * 2654435761u + ring_start_.back()));
  std::size_t best = m_;   // how far the best chord's (j - i) mod m is from the target
  for(int t = 0; t < split_triangulation_tries && best > m_ / 32 && budget > 0; ++t) {
    const std::size_t i = std::size_t(random()) % m_;
    const std::size_t spread = m_ / 10;
    const std::size_t j = (i + target - spread + std::size_t(random()) % (2 * spread + 1)) % m_;
    const std::size_t length = (j + m_ - i) % m_;
    const std::size_t uneven = length > target ? length - target : target - length;
    if(uneven >= best) continue;
    const Point p = at(0, i), q = at(0, j);
    if(inside_angle(i, q) && inside_angle(j, p) && clear(i, j, p, q)) {
      a_ = i;
      b_ = j;
      best = uneven;
    }
  }
  if(best == m_)
    return false;
  cut_ = {a_, b_};
  return true;
}

template <class Kernel>
template <class Point_2>
bool Split_triangulation<Kernel>::find_path(const std::vector<std::vector<Point_2> >& rings, std::size_t target)
{
  const K k;
  const auto orientation = k.orientation_2_object();
  const std::size_t n = ring_start_.back();
  auto at = [&](std::size_t r, std::size_t i) -> Point { return TK::point(rings[r][i]); };
  // the point after the point g in its ring's order
  auto index_next = [&](std::size_t g) {
    const std::size_t r = ring_of(g);
    return g + 1 == ring_start_[r + 1] ? ring_start_[r] : g + 1;
  };
  auto point = [&](std::size_t g) {
    const std::size_t r = ring_of(g);
    return at(r, g - ring_start_[r]);
  };
  // the orientation of the holes met, found when needed: 1 where the next
  // vertex (index + 1) has the interior on the left, -1 where the previous one has
  std::vector<signed char> forward(rings.size(), 0);
  forward[0] = ccw_ ? 1 : -1;
  auto step = [&](std::size_t r) {
    if(forward[r] == 0)
      forward[r] = ring_counterclockwise(rings[r].size(), [&](std::size_t i) { return at(r, i); }, orientation) ? -1 : 1;
    return forward[r];
  };
  // the global index of the point d places after the point g along its ring
  // (with the interior on the left)
  auto along = [&](std::size_t g, long d) {
    const std::size_t r = ring_of(g), m = rings[r].size();
    const long i = long(g - ring_start_[r]) + d * step(r);
    return ring_start_[r] + std::size_t(((i % long(m)) + long(m)) % long(m));
  };

  // The edges in a grid of cells (about one edge a cell), for the tests of
  // the path's short segments.
  double xlo = x(at(0, 0)), xhi = xlo, ylo = y(at(0, 0)), yhi = ylo;
  for(std::size_t i = 0; i < m_; ++i) {
    const Point p = at(0, i);
    xlo = (std::min)(xlo, x(p));
    xhi = (std::max)(xhi, x(p));
    ylo = (std::min)(ylo, y(p));
    yhi = (std::max)(yhi, y(p));
  }
  const double width = xhi - xlo, height = yhi - ylo;
  if(!(width > 0 && height > 0 && std::isfinite(width) && std::isfinite(height)))
    return false;
  const double cell = std::sqrt(width * height / double(n));
  const std::size_t nx = std::size_t(std::clamp(width / cell, 1.0, 4096.0)),
                    ny = std::size_t(std::clamp(height / cell, 1.0, 4096.0));
  auto column = [&](double v) { return std::size_t(std::clamp((v - xlo) / width * double(nx), 0.0, double(nx - 1))); };
  auto row = [&](double v) { return std::size_t(std::clamp((v - ylo) / height * double(ny), 0.0, double(ny - 1))); };
  // (the edge from the point g to the next point of its ring; cells in rows
  // of nx, the edges of cell c at [first[c], first[c + 1]))
  std::vector<std::uint32_t> first(nx * ny + 1, 0), edges;
  auto each_cell = [&](const Point& u, const Point& w, const auto& f) {
    const std::size_t c0 = column((std::min)(x(u), x(w))), c1 = column((std::max)(x(u), x(w)));
    const std::size_t r0 = row((std::min)(y(u), y(w))), r1 = row((std::max)(y(u), y(w)));
    for(std::size_t r = r0; r <= r1; ++r)
      for(std::size_t c = c0; c <= c1; ++c) f(r * nx + c);
  };
  {
    // (long edges across many cells, as the spikes of a star, would make
    // the grid large: no path then)
    std::size_t entries = 0;
    for(std::size_t r = 0; r < rings.size() && entries <= 8 * n; ++r)
      for(std::size_t i = 0, m = rings[r].size(); i < m; ++i) {
        const Point u = at(r, i), w = at(r, i + 1 == m ? 0 : i + 1);
        entries += (column((std::max)(x(u), x(w))) - column((std::min)(x(u), x(w))) + 1) *
                   (row((std::max)(y(u), y(w))) - row((std::min)(y(u), y(w))) + 1);
      }
    if(entries > 8 * n)
      return false;
  }
  for(int pass = 0; pass < 2; ++pass) {
    for(std::size_t r = 0; r < rings.size(); ++r)
      for(std::size_t i = 0, m = rings[r].size(); i < m; ++i)
        each_cell(at(r, i), at(r, i + 1 == m ? 0 : i + 1), [&](std::size_t c) {
          if(pass == 0) ++first[c + 1];
          else edges[first[c]++] = std::uint32_t(ring_start_[r] + i);
        });
    if(pass == 0) {
      for(std::size_t c = 0; c < nx * ny; ++c) first[c + 1] += first[c];
      edges.resize(first[nx * ny]);
    } else {   // (each first[c] moved to the end of its cell)
      for(std::size_t c = nx * ny; c > 0; --c) first[c] = first[c - 1];
      first[0] = 0;
    }
  }

  // whether the segment between the points g and h (global indices, on any
  // rings) leaves each strictly inside the polygon's angle there, and no
  // edge but the four at its ends, and no segment of the path so far,
  // crosses or touches it
  std::vector<std::size_t> path;
  auto open_segment = [&](std::size_t g, std::size_t h) {
    if(g == h)
      return false;
    const Point p = point(g), q = point(h);
    if(!strictly_inside_angle(point(along(g, -1)), p, point(along(g, 1)), q) ||
       !strictly_inside_angle(point(along(h, -1)), q, point(along(h, 1)), p))
      return false;
    bool hit = false;
    each_cell(p, q, [&](std::size_t c) {
      for(std::uint32_t i = first[c]; i < first[c + 1] && !hit; ++i) {
        const std::size_t e = edges[i], f = index_next(e);
        if(e == g || e == h || f == g || f == h) continue;
        hit = meets(p, q, point(e), point(f));
      }
    });
    for(std::size_t i = 0; i + 1 < path.size() && !hit; i += 2) hit = meets(p, q, point(path[i]), point(path[i + 1]));
    return !hit;
  };

  std::minstd_rand random(std::uint_fast32_t(m_ * 2246822519u + n));
  const int tries = m_ <= 8 ? int(m_) : 8;
  for(int t = 0; t < tries; ++t) {
    const std::size_t i = m_ <= 8 ? std::size_t(t) % m_ : std::size_t(random()) % m_;
    const std::size_t spread = m_ / 10;
    const std::size_t j = (i + target - spread + (spread == 0 ? 0 : std::size_t(random()) % (2 * spread + 1))) % m_;
    if(i == j)
      continue;
    const Point p = at(0, i), q = at(0, j);
    // the holes that the segment pq crosses, in their order along it: each
    // with the first and the last edge it crosses (the path enters the hole
    // at an end of the first, and leaves it at an end of the last)
    struct Crossing {
      double t;
      std::size_t ring, edge;
    };
    std::vector<Crossing> crossings;
    bool blocked = false;
    const double dx = x(q) - x(p), dy = y(q) - y(p);
    for(std::size_t r = 0; r < rings.size() && !blocked; ++r)
      for(std::size_t e = 0, m = rings[r].size(); e < m && !blocked; ++e) {
        const std::size_t f = e + 1 == m ? 0 : e + 1;
        if(r == 0 && (e == i || e == j || f == i || f == j)) continue;
        const Point u = at(r, e), w = at(r, f);
        if(!meets(p, q, u, w)) continue;
        if(r == 0 || (orientation(p, q, u) == COLLINEAR && orientation(p, q, w) == COLLINEAR)) {
          blocked = true;   // (it leaves the polygon, or runs along an edge)
          break;
        }
        const double ex = x(w) - x(u), ey = y(w) - y(u);
        const double den = dx * ey - dy * ex;
        const double s = den != 0 ? ((x(u) - x(p)) * ey - (y(u) - y(p)) * ex) / den : 0;
        crossings.push_back({s, r, e});
      }
    if(blocked)
      continue;   // (with no crossing at all, ab is a chord: a path of one segment)
    if(!(strictly_inside_angle(at(0, before(i)), p, at(0, after(i)), q) &&
         strictly_inside_angle(at(0, before(j)), q, at(0, after(j)), p)))
      continue;
    std::sort(crossings.begin(), crossings.end(), [](const Crossing& u, const Crossing& w) { return u.t < w.t; });
    std::vector<std::array<std::size_t, 3> > holes;   // ring, first edge, last edge
    std::vector<char> seen(rings.size(), 0);
    for(const Crossing& c : crossings) {
      if(!holes.empty() && holes.back()[0] == c.ring) {
        holes.back()[2] = c.edge;
      } else if(seen[c.ring]) {
        blocked = true;   // (a hole met again after another one)
        break;
      } else {
        seen[c.ring] = 1;
        holes.push_back({c.ring, c.edge, c.edge});
      }
    }
    if(blocked)
      continue;
    // The segments of the path, from a to the first hole, from each hole to
    // the next, and from the last one to b: each between the ends of an
    // edge crossed (or up to eight vertices around them along its ring) that
    // see each other.
    auto near = [&](std::size_t r, std::size_t e) {
      const std::size_t m = rings[r].size();
      std::vector<std::size_t> out;
      for(long d = 0; d < 10 && std::size_t(d) < m; ++d) {
        // (the edge's two ends first, then alternately further away)
        const long shift = (d % 2 == 0 ? -(d / 2) : 1 + d / 2);
        out.push_back(ring_start_[r] + std::size_t(((long(e) + shift) % long(m) + long(m)) % long(m)));
      }
      return out;
    };
    path.clear();
    std::vector<std::size_t> from = {i};   // (the outer ring's points are numbered first)
    for(std::size_t h = 0; h <= holes.size() && !blocked; ++h) {
      const std::vector<std::size_t> to = h < holes.size() ? near(holes[h][0], holes[h][1]) : std::vector<std::size_t>{j};
      bool joined = false;
      for(std::size_t u = 0; u < from.size() && !joined; ++u)
        for(std::size_t w = 0; w < to.size() && !joined; ++w)
          if(open_segment(from[u], to[w])) {
            path.push_back(from[u]);
            path.push_back(to[w]);
            joined = true;
          }
      if(!joined) {
        blocked = true;
        break;
      }
      if(h < holes.size()) {
        from = near(holes[h][0], holes[h][2]);
        from.erase(std::remove(from.begin(), from.end(), path.back()), from.end());
      }
    }
    if(blocked)
      continue;
    a_ = i;
    b_ = j;
    cut_ = path;   // a, p_1, q_1, ..., p_k, q_k, b
    path_holes_.clear();
    hole_forward_.clear();
    for(const auto& h : holes) {
      path_holes_.push_back(h[0]);
      hole_forward_.push_back(step(h[0]) > 0);
    }
    return true;
  }
  return false;
}

template <class Kernel>
template <class Point_2>
void Split_triangulation<Kernel>::insert_points(const std::vector<std::vector<Point_2> >& rings)
{
  std::vector<std::pair<Point, int> > points[2];
  for(int s = 0; s < 2; ++s) {
    // the side's boundary (the outer ring's part, and the path's), then its holes
    const std::vector<std::size_t>& boundary = boundary_[s];
    std::size_t holes_points = 0;
    for(std::size_t r = 1; r < rings.size(); ++r)
      if(side_of_ring_[r] == s) holes_points += rings[r].size();
    points[s].reserve(boundary.size() + holes_points);
    for(const std::size_t g : boundary) {
      const std::size_t r = ring_of(g);
      points[s].emplace_back(TK::point(rings[r][g - ring_start_[r]]), int(g));
    }
  }
  for(std::size_t r = 1; r < rings.size(); ++r)
    if(side_of_ring_[r] != 2)
      for(std::size_t i = 0; i < rings[r].size(); ++i)
        points[int(side_of_ring_[r])].emplace_back(TK::point(rings[r][i]), int(ring_start_[r] + i));
  run_both([&] { side_[0].insert_points(points[0]); }, [&] { side_[1].insert_points(points[1]); });
}

template <class Kernel>
template <class Data>
bool Split_triangulation<Kernel>::finish(const Data& data, std::vector<Triangle>& out)
{
  const std::size_t n = ring_start_.back();
  if(data.points.size() != n || data.info[0].reversed == ccw_)
    return false;
  // every successor the one along its ring: no corners were linked anew
  // where rings touch
  for(std::size_t r = 0; r + 1 < ring_start_.size(); ++r) {
    const std::size_t base = ring_start_[r], m = ring_start_[r + 1] - base;
    for(std::size_t i = 0; i < m; ++i) {
      const Point_info& info = data.info[base + i];
      if(std::size_t(info.next) != base + (info.reversed ? (i + m - 1) % m : (i + 1) % m))
        return false;
    }
  }
  // each side's boundary, then its holes
  for(std::size_t h = 0; h < path_holes_.size(); ++h)
    if(data.info[ring_start_[path_holes_[h]]].reversed == hole_forward_[h])
      return false;
  std::vector<int> next[2];
  for(int s = 0; s < 2; ++s) {
    next[s].assign(n, -1);
    const std::vector<std::size_t>& boundary = boundary_[s];
    for(std::size_t i = 0; i < boundary.size(); ++i)
      next[s][boundary[i]] = int(boundary[i + 1 == boundary.size() ? 0 : i + 1]);
  }
  for(std::size_t r = 1; r + 1 < ring_start_.size(); ++r)
    if(side_of_ring_[r] != 2)
      for(std::size_t k = ring_start_[r]; k < ring_start_[r + 1]; ++k) next[int(side_of_ring_[r])][k] = data.info[k].next;
  int count[2] = {-1, -1};
  run_both([&] { count[0] = side_[0].constrain_plain(next[0]); },
           [&] { count[1] = side_[1].constrain_plain(next[1]); });
  if(count[0] < 0 || count[1] < 0)
    return false;
  // (each side writes its triangles into one array: no copy, and the
  // array's fresh pages are touched by both threads)
  std::vector<Triangle> triangles(std::size_t(count[0] + count[1]));
  run_both([&] { side_[0].write_plain(triangles.data(), 0); },
           [&] { side_[1].write_plain(triangles.data() + count[0], count[0]); });

  // (a triangulation of the polygon has n + 2 h - 2 triangles: otherwise
  // a side was not what the cut meant, and the polygon is triangulated whole)
  if(std::size_t(count[0] + count[1]) + 2 != n + 2 * (ring_start_.size() - 2))
    return false;

  // the join: the triangle on each side of each segment of the cut (an
  // edge of both sides across which neither has a neighbour) gets the other
  // one; then the flips, from all of them
  std::vector<char> on_cut(n, 0);
  for(const std::size_t g : cut_) on_cut[g] = 1;
  std::vector<std::pair<std::uint64_t, std::size_t> > keys;   // the segments' ends, and their index
  auto key = [](std::size_t u, std::size_t w) {
    return (std::uint64_t((std::min)(u, w)) << 32) | std::uint64_t((std::max)(u, w));
  };
  for(std::size_t j = 0; j + 1 < cut_.size(); j += 2) keys.emplace_back(key(cut_[j], cut_[j + 1]), j / 2);
  std::sort(keys.begin(), keys.end());
  const std::size_t segments = keys.size();
  std::vector<std::pair<int, int> > found[2];   // per side and segment: triangle, edge
  for(int s = 0; s < 2; ++s) {
    found[s].assign(segments, std::make_pair(-1, -1));
    const std::size_t from = s == 0 ? 0 : std::size_t(count[0]), to = s == 0 ? std::size_t(count[0]) : triangles.size();
    for(std::size_t t = from; t < to; ++t)
      for(int e = 0; e < 3; ++e) {
        const Triangle& tri = triangles[t];
        const std::size_t u = std::size_t(tri.v[(e + 1) % 3]), w = std::size_t(tri.v[(e + 2) % 3]);
        if(tri.nbr[e] >= 0 || !on_cut[u] || !on_cut[w]) continue;
        const auto it = std::lower_bound(keys.begin(), keys.end(), std::make_pair(key(u, w), std::size_t(0)));
        if(it != keys.end() && it->first == key(u, w)) found[s][it->second] = std::make_pair(int(t), e);
      }
  }
  std::vector<std::pair<int, int> > flips;
  for(std::size_t j = 0; j < segments; ++j) {
    const auto [t0, e0] = found[0][j];
    const auto [t1, e1] = found[1][j];
    CGAL_assertion(t0 >= 0 && t1 >= 0);
    if(t0 < 0 || t1 < 0)
      return false;
    triangles[std::size_t(t0)].nbr[e0] = t1;
    triangles[std::size_t(t1)].nbr[e1] = t0;
    flips.emplace_back(t0, e0);
  }
  make_delaunay(data.points, triangles, std::move(flips));
  out = std::move(triangles);
  return true;
}

template <class Kernel>
template <class Point_2>
void Split_triangulation<Kernel>::make_delaunay(const std::vector<Point_2>& points, std::vector<Triangle>& tris,
                                                std::vector<std::pair<int, int> > edges)
{
  const auto in_circle = K().side_of_oriented_circle_2_object();
  auto at = [&](int v) -> Point { return TK::point(points[std::size_t(v)]); };
  int t, e;
  while(!edges.empty()) {
    std::tie(t, e) = edges.back();
    edges.pop_back();
    const int u = tris[std::size_t(t)].nbr[e];
    if(u < 0) continue;   // a polygon edge
    Triangle& T = tris[std::size_t(t)];
    Triangle& U = tris[std::size_t(u)];
    const int f = side_towards(tris, u, t);
    // T = (a, b, c) from its vertex e, U = (d, c, b) from its vertex f
    const int a = T.v[e], b = T.v[(e + 1) % 3], c = T.v[(e + 2) % 3], d = U.v[f];
    if(in_circle(at(a), at(b), at(c), at(d)) != ON_POSITIVE_SIDE) continue;
    const int ab = T.nbr[(e + 2) % 3], ca = T.nbr[(e + 1) % 3];
    const int bd = U.nbr[(f + 1) % 3], dc = U.nbr[(f + 2) % 3];
    // the diagonal a d: T = (a, b, d), U = (a, d, c)
    T = Triangle{{a, b, d}, {bd, u, ab}};
    U = Triangle{{a, d, c}, {dc, ca, t}};
    if(bd >= 0) tris[std::size_t(bd)].nbr[side_towards(tris, bd, u)] = t;
    if(ca >= 0) tris[std::size_t(ca)].nbr[side_towards(tris, ca, t)] = u;
    edges.emplace_back(t, 0);
    edges.emplace_back(t, 2);
    edges.emplace_back(u, 0);
    edges.emplace_back(u, 1);
  }
}

} // namespace internal
} // namespace Progressive_medial_axes
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_MEDIAL_AXIS_2_INTERNAL_SPLIT_TRIANGULATION_H
