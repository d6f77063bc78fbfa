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
// The region-growing driver (Liu et al. 2016, section 6.1): the polygon is
// cut into the triangles of a constrained Delaunay triangulation; step 0 is
// the axis of the largest triangle, and every later step adds the next
// triangle of a breadth-first traversal of the triangles' adjacency (or a
// few, see Growth_order.h), merging it along each side it shares with the
// grown shape.  It only asks the engine to add triangles and to merge.

#ifndef CGAL_PROGRESSIVE_MEDIAL_AXIS_2_INTERNAL_REGION_GROWING_H
#define CGAL_PROGRESSIVE_MEDIAL_AXIS_2_INTERNAL_REGION_GROWING_H

#include <CGAL/Progressive_medial_axis_2/internal/Medial_axis_engine.h>
#include <CGAL/Progressive_medial_axis_2/internal/Triangulate.h>
#include <CGAL/Progressive_medial_axis_2/internal/Growth_order.h>

#include <CGAL/number_utils.h>

#include <array>
#include <cstddef>
#include <algorithm>
#include <vector>

namespace CGAL {
namespace Progressive_medial_axes {
namespace internal {

// The first point at the place of each point (empty if no two points share one).
template <class Point>
std::vector<int> growth_places(const std::vector<Point>& points)
{
  std::vector<int> order(points.size());
  for(std::size_t i = 0; i < order.size(); ++i) order[i] = int(i);
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    const Point &p = points[std::size_t(a)], &q = points[std::size_t(b)];
    return p.x() < q.x() || (p.x() == q.x() && (p.y() < q.y() || (p.y() == q.y() && a < b)));
  });
  std::vector<int> place(points.size());
  bool shared = false;
  for(std::size_t k = 0; k < order.size(); ++k) {
    const bool same = k > 0 && points[std::size_t(order[k])] == points[std::size_t(order[k - 1])];
    place[std::size_t(order[k])] = same ? place[std::size_t(order[k - 1])] : order[k];
    shared = shared || same;
  }
  if(!shared) place.clear();
  return place;
}

// The triangle of largest area: the start of the growth.
template <class Point>
int largest_triangle(const std::vector<Triangle>& triangles, const std::vector<Point>& points)
{
  int start = 0;
  double best = -1;
  for(std::size_t t = 0; t < triangles.size(); ++t) {
    const Triangle& T = triangles[t];
    const double ax = CGAL::to_double(points[T.v[0]].x()), ay = CGAL::to_double(points[T.v[0]].y());
    const double bx = CGAL::to_double(points[T.v[1]].x()), by = CGAL::to_double(points[T.v[1]].y());
    const double cx = CGAL::to_double(points[T.v[2]].x()), cy = CGAL::to_double(points[T.v[2]].y());
    const double area = (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
    if(area > best) {
      best = area;
      start = int(t);
    }
  }
  return start;
}

/// The triangles region growing adds at each step, from `triangles` (those
/// of triangulate_rings()) of the polygon of `points`.
template <class Point>
Growth_steps growth_steps(const std::vector<Triangle>& triangles, const std::vector<Point>& points)
{
  return Growth_order(triangles, points.size(), largest_triangle(triangles, points), growth_places(points)).take_steps();
}

template <class Traits>
class Region_growing
{
public:
  typedef Medial_axis_engine<Traits> Engine;

  /// Triangulates the polygon of the engine's points and orders the triangles.
  explicit Region_growing(Engine& engine)
    : engine_(engine)
  {
    auto& data = engine.data();
    triangles_ = triangulate_rings<typename Traits::Kernel>(data);
    steps_ = growth_steps(triangles_, data.points);
    added_.assign(triangles_.size(), 0);
    sides_.assign(triangles_.size(), std::array<int, 3>{{NO_INDEX, NO_INDEX, NO_INDEX}});
  }

  std::size_t number_of_triangles() const { return triangles_.size(); }
  /// Number of steps after step 0.
  std::size_t number_of_steps() const { return steps_.size() == 0 ? 0 : steps_.size() - 1; }

  /// Builds step 0: the axis of the first triangle.
  void start()
  {
    const int t = *steps_.begin(0);
    const int none[3] = {NO_INDEX, NO_INDEX, NO_INDEX};
    sides_[t] = engine_.add_triangle(triangles_[t].v, none);
    added_[t] = 1;
  }

  /// Does step k >= 1: adds its triangles, merging each along the sides it
  /// shares with the grown shape (along the first one, then along the
  /// others, whose two sides are then in the same shape).  Returns the
  /// largest queue size n_v of its merges.
  template <class Visitor>
  std::size_t step(std::size_t k, Visitor& visitor)
  {
    std::size_t n_v = 0;
    for(const int* it = steps_.begin(k); it != steps_.end(k); ++it) {
      const int t = *it;
      const Triangle& T = triangles_[t];
      int shared[3], ns = 0;
      for(int e = 0; e < 3; ++e)
        if(T.nbr[e] >= 0 && added_[T.nbr[e]]) shared[ns++] = e;
      if(ns == 0) {   // the first triangle of another connected part of the interior
        const int none[3] = {NO_INDEX, NO_INDEX, NO_INDEX};
        sides_[t] = engine_.add_triangle(T.v, none);
        added_[t] = 1;
        continue;
      }
      // placed at the corners of the grown shape along the first shared side
      const int first = T.nbr[shared[0]];
      sides_[t] = engine_.add_triangle_across(T.v, shared[0], sides_[first][side_towards(triangles_, first, t)]);
      added_[t] = 1;
      for(int i = 0; i < ns; ++i) {
        const int e = shared[i], u = T.nbr[e];
        const Merge_statistics ms = engine_.merge(sides_[u][side_towards(triangles_, u, t)], sides_[t][e], visitor);
        visitor.on_merge(ms);
        if(ms.max_queue > n_v) n_v = ms.max_queue;
      }
    }
    return n_v;
  }

private:
  Engine& engine_;
  std::vector<Triangle> triangles_;
  Growth_steps steps_;   // triangles added by each step
  std::vector<char> added_;
  std::vector<std::array<int, 3> > sides_; // boundary half-edge of each side of each added triangle
};

} // namespace internal
} // namespace Progressive_medial_axes
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_MEDIAL_AXIS_2_INTERNAL_REGION_GROWING_H
