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
// The order in which region growing adds the triangles, grouped into steps.
//
// Triangles are taken breadth-first over the adjacency graph of the
// triangulation (which has one independent cycle per hole).  The grown shape
// must stay a valid polygon with holes after every step: no vertex may be
// touched twice by its boundary (a "pinch").  At a vertex v, the triangles of
// the triangulation around v form a fan (a path, since every vertex lies on
// the polygon's boundary); the grown shape pinches v exactly when its
// triangles around v form two or more separate runs of that fan.  So a step
// adds the next triangle of the traversal and, if that pinches a vertex, the
// triangles that fill the gap of the fan between the runs, one by one (each
// shares an edge with the shape grown so far), until no vertex is pinched.
// Closing such a gap is how a ring of triangles closes around a hole.
//
// Invariant (asserted after every step in debug builds): every vertex of the
// grown shape is met by exactly one run of its triangles, so the boundary of
// the grown shape is a set of disjoint simple cycles: the outer ring and one
// ring per hole.  Within a step, the shape may touch itself at a vertex for
// a while; the merges handle that: each corner is a vertex of the half-edge
// structure of its own, and a merge whose separator ends at a vertex reached
// by two corners makes them one (see Medial_merge::unify_corners).

#ifndef CGAL_PROGRESSIVE_MEDIAL_AXIS_2_INTERNAL_GROWTH_ORDER_H
#define CGAL_PROGRESSIVE_MEDIAL_AXIS_2_INTERNAL_GROWTH_ORDER_H

#include <CGAL/Progressive_medial_axis_2/internal/Triangulate.h>
#include <CGAL/assertions.h>

#include <deque>
#include <vector>

namespace CGAL {
namespace Progressive_medial_axes {
namespace internal {

/// The steps of a growth, flat: step k adds triangles[start[k]] to
/// triangles[start[k + 1] - 1], in the order they are merged.  (A vector
/// for each step cost a block of the heap for each triangle.)
struct Growth_steps {
  std::vector<int> triangles;
  std::vector<int> start;   // (one more entry than the steps)
  std::size_t size() const { return start.empty() ? 0 : start.size() - 1; }
  const int* begin(std::size_t k) const { return triangles.data() + start[k]; }
  const int* end(std::size_t k) const { return triangles.data() + start[k + 1]; }
};

class Growth_order
{
public:
  /// `start` is the first triangle (step 0).
  /// `place[i]` is the first input point at the place of point i (rings
  /// touch where it is not i): a part of the interior that the growth could
  /// not reach through triangle sides starts next to a place it reached.
  Growth_order(const std::vector<Triangle>& tris, std::size_t number_of_points, int start,
               const std::vector<int>& place = std::vector<int>())
    : tris_(tris), added_(tris.size(), 0), runs_(number_of_points, 0)
  {
    steps_.triangles.reserve(tris.size());
    steps_.start.reserve(tris.size() + 1);
    new_step();
    add(start);
    std::size_t next_start = 0;
    for(;;) {
      if(queue_.empty()) {
        // another connected part of the interior (the outer ring is pinched):
        // a step that starts it with a triangle of its own
        while(next_start < tris_.size() && added_[next_start]) ++next_start;
        if(next_start == tris_.size()) break;
        int t = int(next_start);
        if(!place.empty()) {
          std::vector<char> reached(number_of_points, 0);
          for(std::size_t u = 0; u < tris_.size(); ++u)
            if(added_[u])
              for(int i = 0; i < 3; ++i) reached[std::size_t(place[std::size_t(tris_[u].v[i])])] = 1;
          for(std::size_t u = next_start; u < tris_.size(); ++u)
            if(!added_[u] && (reached[std::size_t(place[std::size_t(tris_[u].v[0])])] ||
                              reached[std::size_t(place[std::size_t(tris_[u].v[1])])] ||
                              reached[std::size_t(place[std::size_t(tris_[u].v[2])])])) {
              t = int(u);
              break;
            }
        }
        new_step();
        add(t);
        continue;
      }
      int t = queue_.front();
      queue_.pop_front();
      for(int e = 0; e < 3; ++e) {
        int u = tris_[t].nbr[e];
        if(u < 0 || added_[u]) continue;
        new_step();
        add(u);
        close_pinches();
        CGAL_assertion(step_is_pinch_free(steps_.start.back()));
      }
    }
    steps_.start.push_back(int(steps_.triangles.size()));
  }

  /// The steps, moved out: step 0 holds the first triangle; each later step
  /// holds the triangles it adds, in the order they are merged.
  Growth_steps take_steps() { return std::move(steps_); }

private:
  // The fan position of triangle t at its corner i: the triangles before
  // (clockwise) and after (counter-clockwise) it around t.v[i].
  int cw_neighbour(int t, int i) const { return tris_[t].nbr[(i + 2) % 3]; }
  int ccw_neighbour(int t, int i) const { return tris_[t].nbr[(i + 1) % 3]; }
  bool in(int t) const { return t >= 0 && added_[t]; }
  void new_step() { steps_.start.push_back(int(steps_.triangles.size())); }

  void add(int t)
  {
    CGAL_assertion(!added_[t]);
    added_[t] = 1;
    steps_.triangles.push_back(t);
    queue_.push_back(t);
    for(int i = 0; i < 3; ++i) {
      int v = tris_[t].v[i];
      runs_[v] += 1 - int(in(cw_neighbour(t, i))) - int(in(ccw_neighbour(t, i)));
      if(runs_[v] >= 2) pinched_.push_back(std::make_pair(t, i));
    }
  }

  // Fills fan gaps until no vertex is pinched.  A pinch at v was recorded
  // with a triangle of one of v's runs; walking the fan from it towards the
  // gap finds the triangle to add.
  void close_pinches()
  {
    while(!pinched_.empty()) {
      std::pair<int, int> p = pinched_.back();
      int v = tris_[p.first].v[p.second];
      if(runs_[v] < 2) {
        pinched_.pop_back();
        continue;
      }
      int g = gap_triangle(p.first, v);
      CGAL_assertion(g >= 0);
      add(g);
    }
  }

  // The invariant kept between steps: no vertex of the triangles of a step
  // (those from `first` on) is touched twice by the boundary of the grown
  // shape.
  bool step_is_pinch_free(int first) const
  {
    for(std::size_t k = std::size_t(first); k < steps_.triangles.size(); ++k)
      for(int i = 0; i < 3; ++i)
        if(runs_[tris_[steps_.triangles[k]].v[i]] != 1) return false;
    return true;
  }

  static int corner_of(const Triangle& t, int v)
  {
    return t.v[0] == v ? 0 : (t.v[1] == v ? 1 : 2);
  }

  // A triangle of a gap of v's fan next to the run of t: walk
  // counter-clockwise over the run, then the first triangle of the gap, if
  // the fan has another run beyond it; otherwise the same clockwise.
  int gap_triangle(int t, int v) const
  {
    for(int dir = 0; dir < 2; ++dir) {
      int cur = t;
      // leave the run
      while(cur >= 0 && in(cur)) {
        int i = corner_of(tris_[cur], v);
        cur = dir == 0 ? ccw_neighbour(cur, i) : cw_neighbour(cur, i);
      }
      if(cur < 0) continue;   // the run ends at the boundary
      int candidate = cur;
      // is there another run further on?
      while(cur >= 0 && !in(cur)) {
        int i = corner_of(tris_[cur], v);
        cur = dir == 0 ? ccw_neighbour(cur, i) : cw_neighbour(cur, i);
      }
      if(cur >= 0) return candidate;
    }
    return -1;
  }

  const std::vector<Triangle>& tris_;
  std::vector<char> added_;
  std::vector<int> runs_;
  std::vector<std::pair<int, int> > pinched_;
  std::deque<int> queue_;
  Growth_steps steps_;
};

} // namespace internal
} // namespace Progressive_medial_axes
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_MEDIAL_AXIS_2_INTERNAL_GROWTH_ORDER_H
