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
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_with_holes_2.h>
#include <CGAL/enum.h>

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

template <class K, class Range>
std::vector<typename K::Point_2> ring_of(const Range& ring)
{
  std::vector<typename K::Point_2> out;
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
  for(const auto& r : rings) out.push_back(ring_of<K>(r));
  return out;
}

/// Fills the points of `data`: ring by ring, with each point's ring,
/// index and successor along the ring with the interior on its left (the
/// outer ring counter-clockwise, holes clockwise; the orientation of a
/// ring is read at its lexicographically smallest vertex, a convex one).
template <class Data, class Point_2, class Orientation>
void set_points(Data& data, const std::vector<std::vector<Point_2> >& rings, const Orientation& orientation)
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
    int lo = 0;
    for(int i = 1; i < m; ++i)
      if(ring[i].x() < ring[lo].x() || (ring[i].x() == ring[lo].x() && ring[i].y() < ring[lo].y())) lo = i;
    const bool ccw = orientation(ring[(lo + m - 1) % m], ring[lo], ring[(lo + 1) % m]) == LEFT_TURN;
    const bool reversed = (r == 0) ? !ccw : ccw;   // holes run clockwise inside
    for(int i = 0; i < m; ++i) {
      data.points.push_back(ring[i]);
      Point_info& info = data.info[base + i];
      info.ring = int(r);
      info.index = i;
      info.reversed = reversed;
      info.next = reversed ? base + (i + m - 1) % m : base + (i + 1) % m;
    }
  }
  data.ring_start.push_back(int(data.points.size()));
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
