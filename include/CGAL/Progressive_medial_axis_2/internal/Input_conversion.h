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
// From the user's polygon to the engine's points: any CGAL polygon (simple
// or with holes, any kernel, any container) or range of rings of CGAL
// points, converted to the traits' kernel; ring orientations read once.

#ifndef CGAL_PROGRESSIVE_MEDIAL_AXIS_2_INTERNAL_INPUT_CONVERSION_H
#define CGAL_PROGRESSIVE_MEDIAL_AXIS_2_INTERNAL_INPUT_CONVERSION_H

#include <CGAL/Progressive_medial_axis_2/internal/Medial_axis_engine.h>

#include <CGAL/Cartesian_converter.h>
#include <CGAL/Exact_rational.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_with_holes_2.h>
#include <CGAL/enum.h>

#include <CGAL/assertions.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <iterator>
#include <type_traits>
#include <vector>

namespace CGAL {

template <class K> class Progressive_medial_axis_traits_2;

namespace Progressive_medial_axes {
namespace internal {

/// The kernel whose exact predicates decide on points of kernel K: K
/// itself, or Epick for a kernel of doubles (the same points, with exact
/// predicates), used by the validation and the triangulation.
template <class K, bool = std::is_floating_point<typename K::FT>::value>
struct Exact_predicates_kernel_for {
  typedef K type;
  static const typename K::Point_2& point(const typename K::Point_2& p) { return p; }
};
template <class K>
struct Exact_predicates_kernel_for<K, true> {
  typedef Exact_predicates_inexact_constructions_kernel type;
  static type::Point_2 point(const typename K::Point_2& p) { return type::Point_2(p.x(), p.y()); }
};

/// The orientation predicate of kernel K, exact: for a kernel of doubles
/// (Simple_cartesian<double>), that of Epick on the same points.
template <class K>
struct Exact_orientation {
  typedef Exact_predicates_kernel_for<K> EK;
  Orientation operator()(const typename K::Point_2& a, const typename K::Point_2& b,
                         const typename K::Point_2& c) const
  {
    return typename EK::type().orientation_2_object()(EK::point(a), EK::point(b), EK::point(c));
  }
};

// Whether P is the point type of a CGAL kernel.
template <class P, class = void>
struct Is_kernel_point : std::false_type {};
template <class P>
struct Is_kernel_point<P, std::void_t<typename Kernel_traits<P>::Kernel::Point_2> >
  : std::is_same<P, typename Kernel_traits<P>::Kernel::Point_2> {};

// Converts a point of any kernel to kernel K.
template <class K, class P>
typename K::Point_2 convert_point(const P& p)
{
  static_assert(Is_kernel_point<P>::value,
                "Progressive_medial_axis_2: the input must be a CGAL polygon or a range of rings of points of a "
                "CGAL kernel (Point_2 of Epick, Epeck, Simple_cartesian...)");
  typedef typename Kernel_traits<P>::Kernel K2;
  if constexpr(std::is_same<K2, K>::value) {
    return p;
  } else {
    return Cartesian_converter<K2, K>()(p);
  }
}

// Reserves `out` for the elements of `range` where counting them does not
// consume it (a forward range).
template <class Vector, class Range>
void reserve_for(Vector& out, const Range& range)
{
  if constexpr(std::is_base_of<std::forward_iterator_tag,
                               typename std::iterator_traits<decltype(std::begin(range))>::iterator_category>::value)
    out.reserve(std::size_t(std::distance(std::begin(range), std::end(range))));
}

template <class K, class Range>
std::vector<typename K::Point_2> ring_of(const Range& ring)
{
  std::vector<typename K::Point_2> out;
  reserve_for(out, ring);
  for(const auto& p : ring) out.push_back(convert_point<K>(p));
  return out;
}

/// The rings (outer ring, then holes) of a polygon, in kernel K.
template <class K, class K2, class C>
std::vector<std::vector<typename K::Point_2> > rings_of(const CGAL::Polygon_2<K2, C>& polygon)
{
  return {ring_of<K>(polygon.container())};
}

template <class K, class K2, class C>
std::vector<std::vector<typename K::Point_2> > rings_of(const CGAL::Polygon_with_holes_2<K2, C>& polygon)
{
  std::vector<std::vector<typename K::Point_2> > out;
  out.push_back(ring_of<K>(polygon.outer_boundary().container()));
  for(auto h = polygon.holes_begin(); h != polygon.holes_end(); ++h) out.push_back(ring_of<K>(h->container()));
  return out;
}

template <class K, class Ring_range>
std::vector<std::vector<typename K::Point_2> > rings_of(const Ring_range& rings)
{
  std::vector<std::vector<typename K::Point_2> > out;
  reserve_for(out, rings);
  for(const auto& r : rings) out.push_back(ring_of<K>(r));
  return out;
}

/*
  Where rings touch (the validation allows it: OGC holes touching the outer
  ring or each other, pinches, inverted islands), m input points lie at one
  place P.  The 2m edges at P bound m interior sectors (wedges) and m
  exterior ones, alternately.  Each interior sector becomes a corner of its
  own: an input point at P, whose `next` is the edge leaving P on the
  sector's clockwise side and whose predecessor is the edge entering P on
  its counterclockwise side.  The boundary cycles are thus re-linked at P,
  the edges themselves (and their ids, kept in `edge_ring`, `edge_index`)
  unchanged.  The sector that is reflex, if any (at most one: the angles add
  up to at most 2 pi), gets the first of the points in input order, so that
  its point generator is named after the first place the coordinates occur.
  Invariant: every input point is the corner of exactly one interior sector,
  and `next` is a permutation whose cycles are the boundary of the interior
  traversed with the interior on the left; distinct corners may share
  coordinates, but never a sector.  The triangulation gives each triangle
  at P the corner of its sector (triangulate_rings()).
*/
// The points of `points` whose coordinates occur more than once, sorted by
// (x, y, index).  For coordinates of doubles, a hash table finds them in
// linear time (a sort of all the points took 5 ms of 128,000); for other
// number types, a sort.
template <class Point>
std::vector<int> repeated_points(const std::vector<Point>& points)
{
  const int n = int(points.size());
  auto less_xy = [&](int a, int b) {
    const Point& p = points[std::size_t(a)];
    const Point& q = points[std::size_t(b)];
    return p.x() < q.x() || (p.x() == q.x() && (p.y() < q.y() || (p.y() == q.y() && a < b)));
  };
  std::vector<int> out;
  if constexpr(std::is_same<typename std::decay<decltype(points[0].x())>::type, double>::value) {
    int bits = 4;
    while((std::size_t(1) << bits) < 2 * std::size_t(n)) ++bits;
    const std::size_t mask = (std::size_t(1) << bits) - 1;
    std::vector<int> table(mask + 1, -1);
    std::vector<char> repeated(std::size_t(n), 0);
    auto hash = [&](const Point& p) {
      std::uint64_t x, y;
      const double px = p.x() + 0.0, py = p.y() + 0.0;   // (-0 and 0 alike)
      std::memcpy(&x, &px, sizeof x);
      std::memcpy(&y, &py, sizeof y);
      return std::size_t(((x * 0x9E3779B97F4A7C15ull) ^ y) * 0xC2B2AE3D27D4EB4Full >> (64 - bits));
    };
    for(int i = 0; i < n; ++i) {
      const Point& p = points[std::size_t(i)];
      for(std::size_t h = hash(p) & mask;; h = (h + 1) & mask) {
        const int j = table[h];
        if(j < 0) {
          table[h] = i;
          break;
        }
        if(points[std::size_t(j)] == p) {
          repeated[std::size_t(j)] = repeated[std::size_t(i)] = 1;
          break;
        }
      }
    }
    for(int i = 0; i < n; ++i)
      if(repeated[std::size_t(i)]) out.push_back(i);
    std::sort(out.begin(), out.end(), less_xy);
  } else {
    std::vector<int> order(std::size_t(n), 0);
    for(int i = 0; i < n; ++i) order[std::size_t(i)] = i;
    std::sort(order.begin(), order.end(), less_xy);
    for(int k = 0; k < n;) {
      int end = k + 1;
      while(end < n && points[std::size_t(order[std::size_t(end)])] == points[std::size_t(order[std::size_t(k)])]) ++end;
      if(end - k > 1) out.insert(out.end(), order.begin() + k, order.begin() + end);
      k = end;
    }
  }
  return out;
}

template <class Data, class Orientation>
void link_touching_corners(Data& data, const Orientation& orientation)
{
  typedef typename std::remove_reference<decltype(data.points[0])>::type Point;
  const int n = int(data.points.size());
  const std::vector<int> order = repeated_points(data.points);
  const int m_order = int(order.size());
  std::vector<int> prev;
  for(int k = 0; k < m_order;) {
    int end = k + 1;
    const Point& p = data.points[std::size_t(order[std::size_t(k)])];
    while(end < m_order && data.points[std::size_t(order[std::size_t(end)])] == p) ++end;
    if(prev.empty()) {   // predecessors along the cycles, once
      prev.assign(std::size_t(n), -1);
      for(int i = 0; i < n; ++i)
        if(data.info[std::size_t(i)].next >= 0) prev[std::size_t(data.info[std::size_t(i)].next)] = i;
    }
    // the edges at P: (the other end, the point at P, outgoing?), counterclockwise
    struct Ray { int to, at; bool outgoing; };
    std::vector<Ray> rays;
    std::vector<int> here;
    for(int j = k; j < end; ++j) {
      const int g = order[std::size_t(j)];
      here.push_back(g);
      rays.push_back(Ray{data.info[std::size_t(g)].next, g, true});
      rays.push_back(Ray{prev[std::size_t(g)], g, false});
    }
    auto upper = [&](const Point& q) {
      return q.y() > p.y() || (q.y() == p.y() && q.x() > p.x());
    };
    std::sort(rays.begin(), rays.end(), [&](const Ray& a, const Ray& b) {
      const Point& qa = data.points[std::size_t(a.to)];
      const Point& qb = data.points[std::size_t(b.to)];
      const bool ua = upper(qa), ub = upper(qb);
      if(ua != ub) return ua;
      return orientation(p, qa, qb) == LEFT_TURN;
    });
    // Outgoing and incoming edges alternate around P, unless an edge passes
    // through P (a "T" with corners on both of its sides): the place is then
    // linked after triangulate_rings() has split that edge at P.
    const std::size_t m = rays.size();
    bool alternate = true;
    for(std::size_t i = 0; i < m; ++i)
      alternate = alternate && rays[i].outgoing != rays[(i + 1) % m].outgoing;
    if(!alternate) {
      k = end;
      continue;
    }
    // sectors: an outgoing edge and the incoming edge counterclockwise after it
    struct Sector { int out_to, out_edge_ring, out_edge_index, in_from; bool reflex; };
    std::vector<Sector> sectors;
    for(std::size_t i = 0; i < m; ++i) {
      if(!rays[i].outgoing) continue;
      const Ray& in = rays[(i + 1) % m];
      CGAL_assertion(!in.outgoing);
      const Point_info& from = data.info[std::size_t(rays[i].at)];
      sectors.push_back(Sector{rays[i].to, from.edge_ring, from.edge_index, in.to,
                               orientation(p, data.points[std::size_t(rays[i].to)],
                                           data.points[std::size_t(in.to)]) == RIGHT_TURN});
    }
    std::stable_sort(sectors.begin(), sectors.end(), [](const Sector& a, const Sector& b) { return a.reflex > b.reflex; });
    std::sort(here.begin(), here.end());
    for(std::size_t s = 0; s < sectors.size(); ++s) {
      const int c = here[s];
      Point_info& info = data.info[std::size_t(c)];
      info.next = sectors[s].out_to;
      info.edge_ring = sectors[s].out_edge_ring;
      info.edge_index = sectors[s].out_edge_index;
      data.info[std::size_t(sectors[s].in_from)].next = c;
      prev[std::size_t(sectors[s].out_to)] = c;   // (for the places still to come)
      prev[std::size_t(c)] = sectors[s].in_from;
    }
    k = end;
  }
}

/// Whether the ring of the m points `at(0)`, ..., `at(m - 1)` runs
/// counter-clockwise: the turn at its lexicographically smallest vertex (a
/// convex one), or, where the ring passes that point more than once (it
/// touches itself there), the sign of its area (exact for points of doubles).
template <class At, class Orientation>
bool ring_counterclockwise(std::size_t m, const At& at, const Orientation& orientation)
{
  std::size_t lo = 0;
  for(std::size_t i = 1; i < m; ++i)
    if(at(i).x() < at(lo).x() || (at(i).x() == at(lo).x() && at(i).y() < at(lo).y())) lo = i;
  bool self_touch = false;
  for(std::size_t i = 0; i < m && !self_touch; ++i) self_touch = i != lo && at(i) == at(lo);
  if(!self_touch)
    return orientation(at((lo + m - 1) % m), at(lo), at((lo + 1) % m)) == LEFT_TURN;
  Exact_rational twice_area = 0;
  for(std::size_t i = 0; i < m; ++i) {
    const auto& a = at(i);
    const auto& b = at((i + 1) % m);
    twice_area += Exact_rational(CGAL::to_double(a.x())) * Exact_rational(CGAL::to_double(b.y())) -
                  Exact_rational(CGAL::to_double(a.y())) * Exact_rational(CGAL::to_double(b.x()));
  }
  return CGAL::sign(twice_area) == POSITIVE;
}

/// Whether the caller of set_points() knows that no two input points are at
/// one place.
enum Repeated_points { POINTS_MAY_REPEAT, POINTS_DISTINCT };

/// Fills the points of `data`: ring by ring, with each point's ring,
/// index and successor along the ring with the interior on its left (the
/// outer ring counter-clockwise, holes clockwise; the orientation of a
/// ring is read at its lexicographically smallest vertex, a convex one, or
/// from the sign of its area where the ring touches itself there).  With
/// POINTS_DISTINCT the search for corners at one place, which would find
/// none, is left out (1.4 ms of the 2.2 of 128,000 points; RESULTS.md,
/// seventy-fourth session).
template <class Data, class Point_2, class Orientation>
void set_points(Data& data, const std::vector<std::vector<Point_2> >& rings, const Orientation& orientation,
                Repeated_points repeated = POINTS_MAY_REPEAT)
{
  std::size_t n = 0;
  for(const auto& r : rings) n += r.size();
  data.points.reserve(n);
  data.info.resize(n);
  data.ring_start.clear();
  for(std::size_t r = 0; r < rings.size(); ++r) {
    const auto& ring = rings[r];
    const int base = int(data.points.size());
    data.ring_start.push_back(base);
    const int m = int(ring.size());
    const bool ccw = ring_counterclockwise(ring.size(), [&](std::size_t i) -> const Point_2& { return ring[i]; }, orientation);
    const bool reversed = (r == 0) ? !ccw : ccw;   // holes run clockwise inside
    for(int i = 0; i < m; ++i) {
      data.points.push_back(ring[i]);
      Point_info& info = data.info[base + i];
      info.ring = int(r);
      info.index = i;
      info.reversed = reversed;
      info.next = reversed ? base + (i + m - 1) % m : base + (i + 1) % m;
      info.edge_ring = int(r);
      info.edge_index = reversed ? (i + m - 1) % m : i;
    }
  }
  data.ring_start.push_back(int(data.points.size()));
  if(repeated == POINTS_MAY_REPEAT)
    link_touching_corners(data, orientation);
  else
    CGAL_expensive_assertion(repeated_points(data.points).empty());
}

/// The rings of the input polygon of `data` as set_points() took them
/// (without the points that the triangulation added inside edges).
template <class Point_2, class FT>
std::vector<std::vector<Point_2> > input_rings(const Medial_axis_data<Point_2, FT>& data)
{
  std::vector<std::vector<Point_2> > rings;
  rings.reserve(data.ring_start.size() - 1);
  for(std::size_t r = 0; r + 1 < data.ring_start.size(); ++r)
    rings.emplace_back(data.points.begin() + data.ring_start[r], data.points.begin() + data.ring_start[r + 1]);
  return rings;
}

// The kernel of the points of an input.
template <class Input, class = void>
struct Input_kernel {
  typedef typename std::iterator_traits<decltype(std::begin(*std::begin(std::declval<const Input&>())))>::value_type Point;
  typedef typename Kernel_traits<Point>::Kernel type;
};
template <class K2, class C>
struct Input_kernel<CGAL::Polygon_2<K2, C> > {
  typedef K2 type;
};
template <class K2, class C>
struct Input_kernel<CGAL::Polygon_with_holes_2<K2, C> > {
  typedef K2 type;
};

/// The default traits for an input: exact decisions on the exact
/// coordinates of an Epeck polygon, on doubles for any other.
template <class Input>
struct Default_traits_of_input {
  typedef typename Input_kernel<Input>::type K2;
  typedef typename std::conditional<std::is_same<K2, Exact_predicates_exact_constructions_kernel>::value,
                                    Exact_predicates_exact_constructions_kernel,
                                    Exact_predicates_inexact_constructions_kernel>::type K;
  typedef Progressive_medial_axis_traits_2<K> type;
};

} // namespace internal
} // namespace Progressive_medial_axes
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_MEDIAL_AXIS_2_INTERNAL_INPUT_CONVERSION_H
