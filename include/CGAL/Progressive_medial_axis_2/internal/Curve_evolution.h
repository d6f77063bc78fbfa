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
// Discrete curve evolution (Latecki and Lakaemper, "Convexity rule for shape
// decomposition based on discrete contour evolution", CVIU 73(3), 1999) of
// a polygon with holes: the simplification that the boundary-evolved
// progressive medial axis (paper section 6.2) undoes step by step.
//
// A step removes one vertex v of a ring: its two edges (u, v) and (v, w) are
// replaced by the segment (u, w); or it fills a hole that has become a
// triangle.  The step taken is the one of least relevance
//
//     K(v) = beta(v) l1 l2 / (l1 + l2),
//
// beta(v) the turning angle at v (0 for a straight vertex, pi for a spike),
// l1 = |uv| and l2 = |vw| divided by the total length of all rings (so that
// K does not depend on the scale); a triangular hole has the least relevance
// of its three vertices.  Relevances are computed in double: they
// only order the steps.  A priority queue with lazy deletion orders them
// (an entry is current while its vertex is alive and its neighbours have
// not changed since it was pushed): O(n log n) for n vertices, plus the
// validity checks.
//
// Validity.  Every shape of the evolution is a valid polygon with holes
// (OGC): a removal never makes a ring cross or touch itself or another ring,
// never lets a hole leave the shell, and never leaves a ring with fewer than
// three vertices or a zero area.  The removal of v replaces the boundary
// along the triangle T = (u, v, w) by its third side; since the shape is
// valid, an edge that meets T without having an endpoint in T would have to
// cross (u, v) or (v, w), or to pass through u or w.  So the removal is
// allowed (decided with the exact predicates of the kernel) when
//   - no live vertex other than these occurrences of u, v and w lies in the
//     closed triangle T (this also forbids a removal at a point where rings
//     touch, and a new edge through a vertex), and
//   - none of u, v, w lies inside an edge of the input (a "T"; such
//     vertices are never removed, and the edges next to them stay), and
//   - a ring of four vertices does not become three collinear ones.
// A removal refused now may be allowed once a vertex inside its triangle is
// gone: when the queue runs empty, the vertices of the rings that still have
// more than three are queued again, until a round removes nothing.
// Filling a hole is always allowed.  The evolution ends with the outer ring
// alone, normally a triangle.  A ring touched inside an edge keeps that
// vertex and its neighbours, and a hole that then remains makes the outer
// ring keep the vertices it blocks.
//
// In the refinement (the steps undone in reverse order), a hole appears as
// a triangle cut out of the interior of the shape of the previous step, and
// then grows vertex by vertex like the outer ring.
//
// The triangle test looks for live vertices in a uniform grid rebuilt when
// the number of live vertices halves (CGAL's spatial searching would serve,
// but its kd-tree does not shrink with removals, and a grid on the live
// vertices keeps a query proportional to the triangle's area).

#ifndef CGAL_PROGRESSIVE_MEDIAL_AXIS_2_INTERNAL_CURVE_EVOLUTION_H
#define CGAL_PROGRESSIVE_MEDIAL_AXIS_2_INTERNAL_CURVE_EVOLUTION_H

#include <CGAL/Progressive_medial_axis_2/Input_error.h>
#include <CGAL/Progressive_medial_axis_2/validate_polygon.h>
#include <CGAL/assertions.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <queue>
#include <vector>

namespace CGAL {
namespace Progressive_medial_axes {
namespace internal {

template <class Kernel>
class Curve_evolution
{
public:
  typedef typename Kernel::Point_2 Point_2;

  /// A step: vertex `vertex` of ring `ring` (input indices) removed; its
  /// neighbours at that time were `prev` and `next`.  With `vertex` = -1
  /// (and `prev` = `next` = -1), the hole `ring`, a triangle, was filled.
  struct Removal {
    int ring;
    int vertex;
    int prev;
    int next;
    double relevance;
  };

  /// `rings` must be a valid polygon with holes (touching rings allowed).
  /// With `fill_holes` false, a hole stops at a triangle and stays.
  explicit Curve_evolution(const Rings<Point_2>& rings, const Kernel& kernel = Kernel(), bool fill_holes = true)
    : rings_(rings), orientation_(kernel.orientation_2_object()), fill_holes_(fill_holes)
  {
    for(const auto& r : rings_) {
      begin_.push_back(int(x_.size()));
      for(const Point_2& p : r) {
        x_.push_back(CGAL::to_double(p.x()));
        y_.push_back(CGAL::to_double(p.y()));
      }
    }
    begin_.push_back(int(x_.size()));
    const int n = int(x_.size());
    ring_of_.resize(std::size_t(n));
    prev_.resize(std::size_t(n));
    next_.resize(std::size_t(n));
    for(int r = 0; r + 1 < int(begin_.size()); ++r)
      for(int g = begin_[std::size_t(r)]; g < begin_[std::size_t(r) + 1]; ++g) {
        ring_of_[std::size_t(g)] = r;
        prev_[std::size_t(g)] = g == begin_[std::size_t(r)] ? begin_[std::size_t(r) + 1] - 1 : g - 1;
        next_[std::size_t(g)] = g + 1 == begin_[std::size_t(r) + 1] ? begin_[std::size_t(r)] : g + 1;
      }
    size_.resize(rings_.size());
    for(std::size_t r = 0; r < rings_.size(); ++r) size_[r] = rings_[r].size();
    alive_.assign(std::size_t(n), 1);
    stamp_.assign(std::size_t(n), 0);
    pinned_.assign(std::size_t(n), 0);
    // the vertices inside an edge of the input stay
    Polygon_rings_validator<Kernel> validator(rings_, true, kernel);
    validator.run();
    for(const auto& rv : validator.vertices_on_edges()) pinned_[std::size_t(begin_[std::size_t(rv.first)] + rv.second)] = 1;
    double length = 0;
    for(int g = 0; g < n; ++g) length += distance(g, next_[std::size_t(g)]);
    scale_ = length > 0 ? 1 / length : 1;
  }

  /// Runs the evolution (once).
  void run()
  {
    if(ran_) return;
    ran_ = true;
    const int n = int(x_.size());
    live_ = std::size_t(n);
    build_grid();
    for(;;) {
      std::size_t removed_in_round = 0;
      for(int g = 0; g < n; ++g)
        if(alive_[std::size_t(g)] && size_[std::size_t(ring_of_[std::size_t(g)])] > 3) push(g);
      for(int r = 1; r < int(size_.size()) && fill_holes_; ++r)
        if(size_[std::size_t(r)] == 3) push_fill(r);
      while(!queue_.empty()) {
        const Entry e = queue_.top();
        queue_.pop();
        if(e.vertex < 0) {
          const int r = -1 - e.vertex;
          if(size_[std::size_t(r)] != 3) continue;
          fill(r, e.relevance);
          ++removed_in_round;
          continue;
        }
        const std::size_t g = std::size_t(e.vertex);
        if(!alive_[g] || e.stamp != stamp_[g] || size_[std::size_t(ring_of_[g])] <= 3 || !removable(e.vertex))
          continue;
        remove(e.vertex, e.relevance);
        ++removed_in_round;
      }
      if(removed_in_round == 0) break;
    }
  }

  const std::vector<Removal>& removals() const { return removals_; }

  /// The rings after the first `k` steps (vertices in input order; filled
  /// holes left out, so later holes move forward).
  Rings<Point_2> shape(std::size_t k) const
  {
    std::vector<char> gone(x_.size(), 0), filled(rings_.size(), 0);
    for(std::size_t i = 0; i < k && i < removals_.size(); ++i) {
      if(removals_[i].vertex < 0)
        filled[std::size_t(removals_[i].ring)] = 1;
      else
        gone[std::size_t(begin_[std::size_t(removals_[i].ring)] + removals_[i].vertex)] = 1;
    }
    Rings<Point_2> out;
    for(std::size_t r = 0; r < rings_.size(); ++r) {
      if(filled[r]) continue;
      out.emplace_back();
      for(std::size_t i = 0; i < rings_[r].size(); ++i)
        if(!gone[std::size_t(begin_[r]) + i]) out.back().push_back(rings_[r][i]);
    }
    return out;
  }

private:
  struct Entry {
    double relevance;
    std::uint32_t stamp;
    int vertex;
    bool operator<(const Entry& o) const   // std::priority_queue pops the largest
    {
      return relevance != o.relevance ? relevance > o.relevance : vertex > o.vertex;
    }
  };

  double distance(int a, int b) const
  {
    return std::hypot(x_[std::size_t(b)] - x_[std::size_t(a)], y_[std::size_t(b)] - y_[std::size_t(a)]);
  }

  double relevance(int g) const
  {
    const int u = prev_[std::size_t(g)], w = next_[std::size_t(g)];
    const double ax = x_[std::size_t(g)] - x_[std::size_t(u)], ay = y_[std::size_t(g)] - y_[std::size_t(u)];
    const double bx = x_[std::size_t(w)] - x_[std::size_t(g)], by = y_[std::size_t(w)] - y_[std::size_t(g)];
    const double beta = std::fabs(std::atan2(ax * by - ay * bx, ax * bx + ay * by));
    const double l1 = std::hypot(ax, ay) * scale_, l2 = std::hypot(bx, by) * scale_;
    return l1 + l2 > 0 ? beta * l1 * l2 / (l1 + l2) : 0;
  }

  void push(int g)
  {
    if(pinned_[std::size_t(g)]) return;
    queue_.push(Entry{relevance(g), ++stamp_[std::size_t(g)], g});
  }

  // queues the filling of hole r, a triangle
  void push_fill(int r)
  {
    const int g = first_alive(r);
    const double k = (std::min)({relevance(g), relevance(next_[std::size_t(g)]), relevance(prev_[std::size_t(g)])});
    queue_.push(Entry{k, 0, -1 - r});
  }

  int first_alive(int r) const
  {
    int g = begin_[std::size_t(r)];
    while(!alive_[std::size_t(g)]) ++g;
    return g;
  }

  void fill(int r, double k)
  {
    removals_.push_back(Removal{r, -1, -1, -1, k});
    const int a = first_alive(r), b = next_[std::size_t(a)], c = next_[std::size_t(b)];
    for(int g : {a, b, c}) {
      alive_[std::size_t(g)] = 0;
      grid_erase(g);
      --live_;
    }
    size_[std::size_t(r)] = 0;
    if(live_ * 4 < grid_capacity_) build_grid();
  }

  const Point_2& point(int g) const
  {
    const int r = ring_of_[std::size_t(g)];
    return rings_[std::size_t(r)][std::size_t(g - begin_[std::size_t(r)])];
  }

  // whether p lies in the closed triangle (a, b, c), of orientation o
  bool in_closed_triangle(const Point_2& p, const Point_2& a, const Point_2& b, const Point_2& c, Orientation o) const
  {
    if(o == COLLINEAR) {
      // the triangle is the segment (a, c), b between them
      if(orientation_(a, c, p) != COLLINEAR) return false;
      const Point_2& lo = (std::min)(a, c, [](const Point_2& s, const Point_2& t) { return CGAL::compare_xy(s, t) == SMALLER; });
      const Point_2& hi = (std::max)(a, c, [](const Point_2& s, const Point_2& t) { return CGAL::compare_xy(s, t) == SMALLER; });
      return CGAL::compare_xy(lo, p) != LARGER && CGAL::compare_xy(p, hi) != LARGER;
    }
    return orientation_(a, b, p) != -o && orientation_(b, c, p) != -o && orientation_(c, a, p) != -o;
  }

  bool removable(int v) const
  {
    const int u = prev_[std::size_t(v)], w = next_[std::size_t(v)];
    if(pinned_[std::size_t(u)] || pinned_[std::size_t(v)] || pinned_[std::size_t(w)]) return false;
    const Point_2 &pu = point(u), &pv = point(v), &pw = point(w);
    const Orientation o = orientation_(pu, pv, pw);
    if(size_[std::size_t(ring_of_[std::size_t(v)])] == 4 && orientation_(pu, pw, point(next_[std::size_t(w)])) == COLLINEAR)
      return false;
    // live vertices in the triangle's bounding box
    const double x0 = (std::min)({x_[std::size_t(u)], x_[std::size_t(v)], x_[std::size_t(w)]});
    const double x1 = (std::max)({x_[std::size_t(u)], x_[std::size_t(v)], x_[std::size_t(w)]});
    const double y0 = (std::min)({y_[std::size_t(u)], y_[std::size_t(v)], y_[std::size_t(w)]});
    const double y1 = (std::max)({y_[std::size_t(u)], y_[std::size_t(v)], y_[std::size_t(w)]});
    const int i0 = cell_x(x0), i1 = cell_x(x1), j0 = cell_y(y0), j1 = cell_y(y1);
    for(int j = j0; j <= j1; ++j)
      for(int i = i0; i <= i1; ++i)
        for(int g : grid_[std::size_t(j) * std::size_t(nx_) + std::size_t(i)]) {
          if(g == u || g == v || g == w) continue;
          const double px = x_[std::size_t(g)], py = y_[std::size_t(g)];
          if(px < x0 || px > x1 || py < y0 || py > y1) continue;
          if(in_closed_triangle(point(g), pu, pv, pw, o)) return false;
        }
    return true;
  }

  void remove(int v, double k)
  {
    const int u = prev_[std::size_t(v)], w = next_[std::size_t(v)];
    const int r = ring_of_[std::size_t(v)];
    removals_.push_back(Removal{r, v - begin_[std::size_t(r)], u - begin_[std::size_t(r)], w - begin_[std::size_t(r)], k});
    alive_[std::size_t(v)] = 0;
    next_[std::size_t(u)] = w;
    prev_[std::size_t(w)] = u;
    --size_[std::size_t(r)];
    grid_erase(v);
    if(--live_ * 4 < grid_capacity_) build_grid();
    if(size_[std::size_t(r)] > 3) {
      push(u);
      push(w);
    } else if(r > 0 && fill_holes_) {
      push_fill(r);
    }
  }

  // ---- the grid of live vertices
  int cell_x(double x) const { return std::clamp(int((x - gx0_) * inv_cell_), 0, nx_ - 1); }
  int cell_y(double y) const { return std::clamp(int((y - gy0_) * inv_cell_), 0, ny_ - 1); }

  void build_grid()
  {
    double x0 = HUGE_VAL, x1 = -HUGE_VAL, y0 = HUGE_VAL, y1 = -HUGE_VAL;
    std::size_t count = 0;
    for(std::size_t g = 0; g < x_.size(); ++g)
      if(alive_[g]) {
        x0 = (std::min)(x0, x_[g]); x1 = (std::max)(x1, x_[g]);
        y0 = (std::min)(y0, y_[g]); y1 = (std::max)(y1, y_[g]);
        ++count;
      }
    // about two vertices per cell
    const double w = (std::max)(x1 - x0, 1e-300), h = (std::max)(y1 - y0, 1e-300);
    const double cell = (std::max)(std::sqrt(w * h * 2 / double((std::max)(count, std::size_t(1)))), (std::max)(w, h) / 4096);
    gx0_ = x0;
    gy0_ = y0;
    inv_cell_ = 1 / cell;
    nx_ = (std::max)(1, (std::min)(4096, int(w / cell) + 1));
    ny_ = (std::max)(1, (std::min)(4096, int(h / cell) + 1));
    grid_.assign(std::size_t(nx_) * std::size_t(ny_), std::vector<int>());
    slot_.assign(x_.size(), -1);
    for(std::size_t g = 0; g < x_.size(); ++g)
      if(alive_[g]) {
        std::vector<int>& c = grid_[cell_of(int(g))];
        slot_[g] = int(c.size());
        c.push_back(int(g));
      }
    grid_capacity_ = count;
  }
  std::size_t cell_of(int g) const
  {
    return std::size_t(cell_y(y_[std::size_t(g)])) * std::size_t(nx_) + std::size_t(cell_x(x_[std::size_t(g)]));
  }
  void grid_erase(int g)
  {
    std::vector<int>& c = grid_[cell_of(g)];
    const int s = slot_[std::size_t(g)];
    c[std::size_t(s)] = c.back();
    slot_[std::size_t(c.back())] = s;
    c.pop_back();
  }

  const Rings<Point_2>& rings_;
  typename Kernel::Orientation_2 orientation_;
  std::vector<int> begin_, ring_of_, prev_, next_;
  std::vector<std::size_t> size_;
  std::vector<double> x_, y_;
  std::vector<char> alive_, pinned_;
  std::vector<std::uint32_t> stamp_;
  double scale_ = 1;
  std::priority_queue<Entry> queue_;
  std::vector<Removal> removals_;
  bool fill_holes_ = true;
  bool ran_ = false;
  std::size_t live_ = 0, grid_capacity_ = 0;
  double gx0_ = 0, gy0_ = 0, inv_cell_ = 1;
  int nx_ = 1, ny_ = 1;
  std::vector<std::vector<int> > grid_;
  std::vector<int> slot_;
};

} // namespace internal
} // namespace Progressive_medial_axes
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_MEDIAL_AXIS_2_INTERNAL_CURVE_EVOLUTION_H
