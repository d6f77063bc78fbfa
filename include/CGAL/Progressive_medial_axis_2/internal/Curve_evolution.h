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
// only order the steps (ties by the smaller vertex index).  An indexed
// 4-ary min-heap orders them, one entry per vertex whose key changes when
// a neighbour goes: O(n log n) for n vertices, plus the validity checks.
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
// The triangle test looks for live vertices in horizontal rows about two
// edges high, each sorted by x, rebuilt when the number of live vertices
// falls to a quarter (CGAL's spatial searching would serve, but its kd-tree
// does not shrink with removals; a uniform grid over the bounding box puts
// many vertices in a cell where they lie along curves, as outlines' do).  Decisions use the exact
// orientation of Epick for a kernel of doubles.

#ifndef CGAL_PROGRESSIVE_MEDIAL_AXIS_2_INTERNAL_CURVE_EVOLUTION_H
#define CGAL_PROGRESSIVE_MEDIAL_AXIS_2_INTERNAL_CURVE_EVOLUTION_H

#include <CGAL/Progressive_medial_axis_2/Input_error.h>
#include <CGAL/Progressive_medial_axis_2/validate_polygon.h>
#include <CGAL/Progressive_medial_axis_2/internal/Input_conversion.h>
#include <CGAL/assertions.h>

#include <boost/align/aligned_allocator.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <type_traits>
#include <utility>
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
  /// `vertices_on_edges` lists the vertices that lie inside an edge (T's,
  /// as (ring, index)), as the validator finds them; without it, the
  /// validator is run here.
  explicit Curve_evolution(const Rings<Point_2>& rings, const Kernel& kernel = Kernel(), bool fill_holes = true,
                           const std::vector<std::pair<int, int> >* vertices_on_edges = nullptr)
    : rings_(rings), fill_holes_(fill_holes)
  {
    (void)kernel;
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
    pinned_.assign(std::size_t(n), 0);
    // the vertices inside an edge of the input stay
    auto pin = [&](const std::vector<std::pair<int, int> >& on) {
      for(const auto& rv : on) pinned_[std::size_t(begin_[std::size_t(rv.first)] + rv.second)] = 1;
    };
    if(vertices_on_edges) {
      pin(*vertices_on_edges);
    } else {
      std::vector<std::pair<int, int> > on;
      validate_and_find_vertices_on_edges(rings_, &on);
      pin(on);
    }
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
    pos_.assign(std::size_t(n) + rings_.size(), -1);
    // every vertex and hole at most once in the heap: no reallocation
    heap_storage_.resize(std::size_t(n) + rings_.size() + heap_pad);
    heap_ = heap_storage_.data() + heap_pad;
    removals_.reserve(std::size_t(n));
    build_grid();
    for(;;) {
      std::size_t removed_in_round = 0;
      // the queue of the round, built at once (Floyd)
      heap_size_ = 0;
      for(int g = 0; g < n; ++g)
        if(alive_[std::size_t(g)] && !pinned_[std::size_t(g)] && size_[std::size_t(ring_of_[std::size_t(g)])] > 3) {
          pos_[std::size_t(g)] = int(heap_size_);
          heap_[heap_size_++] = Item{relevance(g), g};
        }
      for(int r = 1; r < int(size_.size()) && fill_holes_; ++r)
        if(size_[std::size_t(r)] == 3) {
          pos_[std::size_t(n + r)] = int(heap_size_);
          heap_[heap_size_++] = Item{fill_relevance(r), n + r};
        }
      for(std::size_t i = heap_size_ / 4 + 1; i-- > 0;)
        if(i < heap_size_) sift_down(i);
      while(heap_size_ > 0) {
        const Item top = pop();
        if(top.id >= n) {
          const int r = top.id - n;
          if(size_[std::size_t(r)] != 3) continue;
          fill(r, top.key);
          ++removed_in_round;
          continue;
        }
        const std::size_t g = std::size_t(top.id);
        if(!alive_[g] || size_[std::size_t(ring_of_[g])] <= 3 || !removable(top.id))
          continue;
        remove(top.id, top.key);
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
  typedef Exact_predicates_kernel_for<Kernel> EK;

  // ---- the indexed 4-ary min-heap of vertices (ids < n) and of holes to
  // fill (id n + ring), by (relevance, id)
  struct Item {
    double key;
    int id;   // 16 bytes with the padding: 4 entries fill a cache line
    bool operator<(const Item& o) const { return key < o.key || (key == o.key && id < o.id); }
  };
  void place(std::size_t i, const Item& it)
  {
    heap_[i] = it;
    pos_[std::size_t(it.id)] = int(i);
  }
  void sift_up(std::size_t i)
  {
    const Item it = heap_[i];
    while(i > 0) {
      const std::size_t p = (i - 1) / 4;
      if(!(it < heap_[p])) break;
      place(i, heap_[p]);
      i = p;
    }
    place(i, it);
  }
  void sift_down(std::size_t i)
  {
    const Item it = heap_[i];
    const std::size_t m = heap_size_;
    for(;;) {
      const std::size_t c = 4 * i + 1;
      if(c >= m) break;
      std::size_t best = c;
      const std::size_t e = (std::min)(c + 4, m);
      for(std::size_t j = c + 1; j < e; ++j)
        if(heap_[j] < heap_[best]) best = j;
      if(!(heap_[best] < it)) break;
      place(i, heap_[best]);
      i = best;
    }
    place(i, it);
  }
  Item pop()
  {
    const Item top = heap_[0];
    pos_[std::size_t(top.id)] = -1;
    const Item last = heap_[--heap_size_];
    if(heap_size_ > 0) {
      place(0, last);
      sift_down(0);
    }
    return top;
  }
  // inserts `id` with `key`, or moves it there if it is queued
  void set_key(int id, double key)
  {
    const int at = pos_[std::size_t(id)];
    if(at < 0) {
      heap_[heap_size_] = Item{key, id};
      pos_[std::size_t(id)] = int(heap_size_);
      sift_up(heap_size_++);
      return;
    }
    const Item old = heap_[std::size_t(at)];
    heap_[std::size_t(at)].key = key;
    if(heap_[std::size_t(at)] < old) sift_up(std::size_t(at));
    else sift_down(std::size_t(at));
  }

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
    const double l1 = std::sqrt(ax * ax + ay * ay) * scale_, l2 = std::sqrt(bx * bx + by * by) * scale_;
    return l1 + l2 > 0 ? beta * l1 * l2 / (l1 + l2) : 0;
  }

  // a vertex queued again, its neighbours having changed
  void requeue(int g)
  {
    if(pinned_[std::size_t(g)]) return;
    set_key(g, relevance(g));
  }

  // the relevance of filling hole r, a triangle: the least of its vertices'
  double fill_relevance(int r) const
  {
    const int g = first_alive(r);
    return (std::min)({relevance(g), relevance(next_[std::size_t(g)]), relevance(prev_[std::size_t(g)])});
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

  Orientation orientation(const Point_2& a, const Point_2& b, const Point_2& c) const
  {
    return typename EK::type().orientation_2_object()(EK::point(a), EK::point(b), EK::point(c));
  }
  // the same on vertices (for a kernel of doubles, from the copies of their
  // coordinates, without reading the input's points)
  Orientation orientation(int a, int b, int c) const
  {
    if constexpr(std::is_floating_point<typename Kernel::FT>::value) {
      typedef typename EK::type::Point_2 P;
      return typename EK::type().orientation_2_object()(P(x_[std::size_t(a)], y_[std::size_t(a)]),
                                                        P(x_[std::size_t(b)], y_[std::size_t(b)]),
                                                        P(x_[std::size_t(c)], y_[std::size_t(c)]));
    } else {
      return orientation(point(a), point(b), point(c));
    }
  }

  // whether vertex p lies in the closed triangle of vertices (a, b, c), of orientation o
  bool in_closed_triangle(int p, int a, int b, int c, Orientation o) const
  {
    if(o == COLLINEAR) {
      // the triangle is the segment (a, c), b between them
      if(orientation(a, c, p) != COLLINEAR) return false;
      const Point_2 &pa = point(a), &pc = point(c), &pp = point(p);
      const Point_2& lo = (std::min)(pa, pc, [](const Point_2& s, const Point_2& t) { return CGAL::compare_xy(s, t) == SMALLER; });
      const Point_2& hi = (std::max)(pa, pc, [](const Point_2& s, const Point_2& t) { return CGAL::compare_xy(s, t) == SMALLER; });
      return CGAL::compare_xy(lo, pp) != LARGER && CGAL::compare_xy(pp, hi) != LARGER;
    }
    return orientation(a, b, p) != -o && orientation(b, c, p) != -o && orientation(c, a, p) != -o;
  }

  bool removable(int v) const
  {
    const int u = prev_[std::size_t(v)], w = next_[std::size_t(v)];
    if(pinned_[std::size_t(u)] || pinned_[std::size_t(v)] || pinned_[std::size_t(w)]) return false;
    const Orientation o = orientation(u, v, w);
    if(size_[std::size_t(ring_of_[std::size_t(v)])] == 4 && orientation(u, w, next_[std::size_t(w)]) == COLLINEAR)
      return false;
    // live vertices in the triangle's bounding box
    const double x0 = (std::min)({x_[std::size_t(u)], x_[std::size_t(v)], x_[std::size_t(w)]});
    const double x1 = (std::max)({x_[std::size_t(u)], x_[std::size_t(v)], x_[std::size_t(w)]});
    const double y0 = (std::min)({y_[std::size_t(u)], y_[std::size_t(v)], y_[std::size_t(w)]});
    const double y1 = (std::max)({y_[std::size_t(u)], y_[std::size_t(v)], y_[std::size_t(w)]});
    int j0 = row_of(y0), j1 = row_of(y1);
    if constexpr(!std::is_floating_point<typename Kernel::FT>::value) {
      // (coordinates rounded from exact numbers: a row more on each side)
      j0 = (std::max)(0, j0 - 1);
      j1 = (std::min)(rows_ - 1, j1 + 1);
    }
    const double tx[3] = {x_[std::size_t(u)], x_[std::size_t(v)], x_[std::size_t(w)]};
    const double ty[3] = {y_[std::size_t(u)], y_[std::size_t(v)], y_[std::size_t(w)]};
    const double dy = 1e-6 * row_height_ + 1e-14 * (std::fabs(y0) + std::fabs(y1));
    const double slack = 1e-6 * row_height_ + 1e-14 * (std::fabs(x0) + std::fabs(x1));
    for(int j = j0; j <= j1; ++j) {
      // the triangle's x-range within the row's band, both a little wider
      // (rows are found in double; the test itself is exact)
      const double b0 = (std::max)(y0, gy0_ + double(j) * row_height_ - dy);
      const double b1 = (std::min)(y1, gy0_ + double(j + 1) * row_height_ + dy);
      double lo = HUGE_VAL, hi = -HUGE_VAL;
      for(int e = 0; e < 3 && j0 < j1; ++e) {   // (one row: the whole x-range)
        const double ax = tx[e], ay = ty[e], bx = tx[(e + 1) % 3], by = ty[(e + 1) % 3];
        if(ay >= b0 && ay <= b1) { lo = (std::min)(lo, ax); hi = (std::max)(hi, ax); }
        for(double yb : {b0, b1})
          if((ay - yb) * (by - yb) <= 0 && ay != by) {
            const double xb = ax + (bx - ax) * ((yb - ay) / (by - ay));
            lo = (std::min)(lo, xb);
            hi = (std::max)(hi, xb);
          }
      }
      if(lo > hi) { lo = x0; hi = x1; }
      lo -= slack;
      hi += slack;
      const double* gx = grid_x_.data();
      const std::size_t last = row_start_[std::size_t(j) + 1];
      for(std::size_t it = std::size_t(std::lower_bound(gx + row_start_[std::size_t(j)], gx + last, lo) - gx);
          it != last && gx[it] <= hi; ++it) {
        const int g = grid_g_[it];
        if(y_[std::size_t(g)] < y0 - dy || y_[std::size_t(g)] > y1 + dy) continue;
        if(g == u || g == v || g == w || !alive_[std::size_t(g)]) continue;
        if(in_closed_triangle(g, u, v, w, o)) return false;
      }
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
    if(--live_ * 4 < grid_capacity_) build_grid();
    if(size_[std::size_t(r)] > 3) {
      requeue(u);
      requeue(w);
    } else if(r > 0 && fill_holes_) {
      set_key(int(x_.size()) + r, fill_relevance(r));
    }
  }

  // ---- the live vertices in horizontal rows about two edges high, each
  // row sorted by x (a query scans the triangle's x-range in each row it
  // crosses); dead vertices are skipped until the next rebuild.  The row
  // height follows the live edges' mean length, so that a row holds few
  // vertices where they lie along curves.
  int row_of(double y) const { return std::clamp(int((y - gy0_) / row_height_), 0, rows_ - 1); }

  void build_grid()
  {
    double y0 = HUGE_VAL, y1 = -HUGE_VAL, length = 0;
    std::size_t count = 0;
    for(std::size_t g = 0; g < x_.size(); ++g)
      if(alive_[g]) {
        y0 = (std::min)(y0, y_[g]);
        y1 = (std::max)(y1, y_[g]);
        // (an estimate of the length, without overflow)
        length += std::fabs(x_[std::size_t(next_[g])] - x_[g]) + std::fabs(y_[std::size_t(next_[g])] - y_[g]);
        ++count;
      }
    const double h = (std::max)(y1 - y0, 1e-300);
    const double mean = count > 0 ? length / double(count) : h;
    gy0_ = y0;
    rows_ = int((std::min)(double(4 * count + 1), (std::min)(1e7, h / (std::max)(2 * mean, h * 1e-7)))) + 1;
    row_height_ = h / double(rows_);
    if(!(row_height_ > 0)) row_height_ = 1;
    row_start_.assign(std::size_t(rows_) + 1, 0);
    row_.resize(x_.size());
    for(std::size_t g = 0; g < x_.size(); ++g)
      if(alive_[g]) {
        row_[g] = row_of(y_[g]);
        ++row_start_[std::size_t(row_[g]) + 1];
      }
    for(int r = 0; r < rows_; ++r) row_start_[std::size_t(r) + 1] += row_start_[std::size_t(r)];
    grid_g_.resize(count);
    std::vector<std::size_t> fill(row_start_.begin(), row_start_.end() - 1);
    for(std::size_t g = 0; g < x_.size(); ++g)
      if(alive_[g]) grid_g_[fill[std::size_t(row_[g])]++] = int(g);
    for(int r = 0; r < rows_; ++r)
      std::sort(grid_g_.begin() + std::ptrdiff_t(row_start_[std::size_t(r)]), grid_g_.begin() + std::ptrdiff_t(row_start_[std::size_t(r) + 1]),
                [this](int a, int b) { return x_[std::size_t(a)] < x_[std::size_t(b)]; });
    grid_x_.resize(count);
    for(std::size_t i = 0; i < count; ++i) grid_x_[i] = x_[std::size_t(grid_g_[i])];
    grid_capacity_ = count;
  }

  const Rings<Point_2>& rings_;
  std::vector<int> begin_, ring_of_, prev_, next_;
  std::vector<std::size_t> size_;
  std::vector<double> x_, y_;
  std::vector<char> alive_, pinned_;
  double scale_ = 1;
  // The heap: the children of entry i are 4i+1 to 4i+4, 64 bytes that
  // start on a cache line (the storage is aligned to 64 bytes and the heap
  // starts 3 entries in).
  static constexpr std::size_t heap_pad = 3;
  std::vector<Item, boost::alignment::aligned_allocator<Item, 64> > heap_storage_;
  Item* heap_ = nullptr;
  std::size_t heap_size_ = 0;
  std::vector<int> pos_;   // the place of each vertex (and hole) in the heap, or -1
  std::vector<Removal> removals_;
  bool fill_holes_ = true;
  bool ran_ = false;
  std::size_t live_ = 0, grid_capacity_ = 0;
  double gy0_ = 0, row_height_ = 1;
  int rows_ = 1;
  std::vector<std::size_t> row_start_;
  std::vector<int> row_;
  std::vector<double> grid_x_;   // the rows one after the other: x (searched apart, it is compact) and vertex
  std::vector<int> grid_g_;
};

} // namespace internal
} // namespace Progressive_medial_axes
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_MEDIAL_AXIS_2_INTERNAL_CURVE_EVOLUTION_H
