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
// The split is only for polygons whose rings do not touch: where two
// points are at one place, or a point lies in an edge (a "T"), the polygon
// is triangulated whole, as the corners of such places need all their
// rings, and a T whose point and edge fall on different sides would go
// unseen by both.  Points at one place are looked for with the chord (2 to
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
#include <atomic>
#include <chrono>
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
  /// Looks for a chord of the outer ring of `rings` that leaves about
  /// `caller_share` of its vertices to side 1, and places the holes; false
  /// if none was found.  Needs finite coordinates only: it runs while the
  /// polygon is being checked, and its result is used once the polygon is
  /// valid.
  template <class Point_2>
  bool find_chord(const std::vector<std::vector<Point_2> >& rings, double caller_share = 0.5);

  /// Phase 1: the Delaunay triangulation of each side's points, the two at
  /// the same time (after find_chord()), side 1 on the calling thread.
  template <class Point_2>
  void insert_points(const std::vector<std::vector<Point_2> >& rings);

  /// Phase 2, on the valid polygon of `data` (set_points() of the same
  /// rings): the triangles of both sides, joined across the chord, into
  /// `out`.  False (and `out` unchanged) where the polygon's rings touch.
  template <class Data>
  bool finish(const Data& data, std::vector<Triangle>& out);

  /// The time the two sides' tasks ran beside each other (their summed
  /// times less the wall time of the phases that ran them).
  double parallel_seconds() const { return parallel_seconds_; }

private:
  // Lawson's flips from the edge e of triangle t: every diagonal whose
  // triangles' circle holds the opposite vertex is flipped, and the four
  // edges around it looked at again; edges of the polygon never are.
  template <class Point_2>
  static void make_delaunay(const std::vector<Point_2>& points, std::vector<Triangle>& tris, int t, int e);

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
  std::size_t a_ = 0, b_ = 0;  // the chord's ends (indices in the outer ring)
  std::vector<char> side_of_ring_;   // 0: from a to b (then the chord), 1: from b to a
  std::vector<std::size_t> ring_start_;
  Ring_triangulation<Kernel> side_[2];
  double parallel_seconds_ = 0;
};

template <class Kernel>
template <class Point_2>
bool Split_triangulation<Kernel>::find_chord(const std::vector<std::vector<Point_2> >& rings, double caller_share)
{
  const K k;
  const auto orientation = k.orientation_2_object();
  m_ = rings[0].size();
  if(m_ < 16)
    return false;
  for(const auto& ring : rings)   // (the check of the polygon, running beside this, rejects such rings)
    if(ring.size() < 3)
      return false;
  ring_start_.assign(1, 0);
  for(const auto& ring : rings) ring_start_.push_back(ring_start_.back() + ring.size());
  auto at = [&](std::size_t r, std::size_t i) -> Point { return TK::point(rings[r][i]); };
  ccw_ = ring_counterclockwise(m_, [&](std::size_t i) { return at(0, i); }, orientation);

  // whether the direction from vertex i towards q is strictly inside the
  // polygon's angle at i
  auto inside_angle = [&](std::size_t i, const Point& q) {
    const Point p = at(0, i), u = at(0, before(i)), w = at(0, after(i));
    const bool left_of_in = orientation(u, p, q) == LEFT_TURN, left_of_out = orientation(p, w, q) == LEFT_TURN;
    return orientation(u, p, w) == LEFT_TURN ? left_of_in && left_of_out : left_of_in || left_of_out;
  };
  // whether no edge of any ring crosses or touches the segment pq, but the
  // four edges at its ends i and j (vertices of the outer ring)
  // (at most 16 n edges looked at in all, for outlines where many pairs
  // are rejected late)
  const std::size_t n = ring_start_.back();
  std::size_t budget = 16 * n;
  auto clear = [&](std::size_t i, std::size_t j, const Point& p, const Point& q) {
    const double xlo = (std::min)(x(p), x(q)), xhi = (std::max)(x(p), x(q));
    const double ylo = (std::min)(y(p), y(q)), yhi = (std::max)(y(p), y(q));
    for(std::size_t r = 0; r < rings.size(); ++r) {
      const std::size_t m = rings[r].size();
      for(std::size_t e = 0; e < m; ++e) {
        if(budget == 0)
          return false;
        --budget;
        const std::size_t f = e + 1 == m ? 0 : e + 1;
        if(r == 0 && (e == i || e == j || f == i || f == j)) continue;
        const Point u = at(r, e), w = at(r, f);
        if((std::max)(x(u), x(w)) < xlo || (std::min)(x(u), x(w)) > xhi || (std::max)(y(u), y(w)) < ylo ||
           (std::min)(y(u), y(w)) > yhi)
          continue;
        const Orientation ou = orientation(p, q, u), ow = orientation(p, q, w);
        if(ou == ow && ou != COLLINEAR) continue;   // both on one side of the line
        if(ou == COLLINEAR && ow == COLLINEAR) return false;   // on the line, in the box
        if(orientation(u, w, p) != orientation(u, w, q)) return false;   // crosses or touches
      }
    }
    return true;
  };

  // (the chord found nearest the share asked for, or the first within m/32
  // of it: a chord (i, j) leaves the (j - i) mod m edges of the outer ring
  // after i to side 0 if the ring is counter-clockwise, to side 1 if not)
  CGAL_precondition(caller_share >= 0.375 && caller_share <= 0.625);
  const std::size_t to_side_1 = std::size_t(double(m_) * caller_share);
  const std::size_t target = ccw_ ? m_ - to_side_1 : to_side_1;
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
  // points at one place (rings that touch): the whole polygon, whose
  // triangulation links their corners (found here, not by the sides'
  // triangulations, which would then be done in vain)
  {
    std::vector<Point> all;
    all.reserve(ring_start_.back());
    for(std::size_t r = 0; r < rings.size(); ++r)
      for(std::size_t i = 0; i < rings[r].size(); ++i) all.push_back(at(r, i));
    if(!repeated_points(all).empty())
      return false;
  }

  // The holes: the side whose boundary (the outer ring from a to b, then
  // the chord; or from b to a) a ray from the hole's first vertex to the
  // right crosses an odd number of times.  The vertices sorted by height
  // give the holes whose ray meets an edge.
  side_of_ring_.assign(rings.size(), 0);
  std::vector<std::pair<double, std::size_t> > starts;
  for(std::size_t r = 1; r < rings.size(); ++r) starts.emplace_back(y(at(r, 0)), r);
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
  if(!starts.empty()) {
    for(std::size_t e = a_; e != b_ && !on_boundary; e = after(e)) count(at(0, e), at(0, after(e)));
    count(at(0, b_), at(0, a_));
  }
  if(on_boundary)
    return false;
  for(std::size_t r = 1; r < rings.size(); ++r) side_of_ring_[r] = odd[r] ? 0 : 1;
  return true;
}

template <class Kernel>
template <class Point_2>
void Split_triangulation<Kernel>::insert_points(const std::vector<std::vector<Point_2> >& rings)
{
  std::vector<std::pair<Point, int> > points[2];
  std::size_t holes_points[2] = {0, 0};
  for(std::size_t r = 1; r < rings.size(); ++r) holes_points[int(side_of_ring_[r])] += rings[r].size();
  for(int s = 0; s < 2; ++s) {
    const std::size_t from = s == 0 ? a_ : b_, to = s == 0 ? b_ : a_;
    const std::size_t steps = ccw_ ? (to + m_ - from) % m_ : (from + m_ - to) % m_;   // after() from `from` to `to`
    points[s].reserve(steps + 1 + holes_points[s]);
    for(std::size_t e = from;; e = after(e)) {
      points[s].emplace_back(TK::point(rings[0][e]), int(e));
      if(e == to) break;
    }
  }
  for(std::size_t r = 1; r < rings.size(); ++r)
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
  std::vector<int> next[2];
  for(int s = 0; s < 2; ++s) {
    next[s].assign(n, -1);
    const std::size_t from = s == 0 ? a_ : b_, to = s == 0 ? b_ : a_;
    for(std::size_t e = from; e != to; e = after(e)) next[s][e] = data.info[e].next;
    next[s][to] = int(from);
  }
  for(std::size_t r = 1; r + 1 < ring_start_.size(); ++r)
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

  // the join: the triangle on each side of the chord (the edge a b, in
  // either direction, across which it has no neighbour) gets the other one
  auto on_chord = [&](std::size_t from, std::size_t to, int& edge) {
    for(std::size_t t = from; t < to; ++t)
      for(int e = 0; e < 3; ++e) {
        const Triangle& tri = triangles[t];
        const std::size_t u = std::size_t(tri.v[(e + 1) % 3]), w = std::size_t(tri.v[(e + 2) % 3]);
        if(tri.nbr[e] < 0 && ((u == a_ && w == b_) || (u == b_ && w == a_))) {
          edge = e;
          return int(t);
        }
      }
    return -1;
  };
  int edge[2] = {-1, -1};
  const int t0 = on_chord(0, std::size_t(count[0]), edge[0]);
  const int t1 = on_chord(std::size_t(count[0]), triangles.size(), edge[1]);
  CGAL_assertion(t0 >= 0 && t1 >= 0);
  if(t0 < 0 || t1 < 0)
    return false;
  triangles[std::size_t(t0)].nbr[edge[0]] = t1;
  triangles[std::size_t(t1)].nbr[edge[1]] = t0;
  make_delaunay(data.points, triangles, t0, edge[0]);
  out = std::move(triangles);
  return true;
}

template <class Kernel>
template <class Point_2>
void Split_triangulation<Kernel>::make_delaunay(const std::vector<Point_2>& points, std::vector<Triangle>& tris, int t,
                                                int e)
{
  const auto in_circle = K().side_of_oriented_circle_2_object();
  auto at = [&](int v) -> Point { return TK::point(points[std::size_t(v)]); };
  std::vector<std::pair<int, int> > edges(1, std::make_pair(t, e));
  while(!edges.empty()) {
    std::tie(t, e) = edges.back();
    edges.pop_back();
    const int u = tris[std::size_t(t)].nbr[e];
    if(u < 0) continue;   // a polygon edge (or the chord's: never, it is flipped or kept once)
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
