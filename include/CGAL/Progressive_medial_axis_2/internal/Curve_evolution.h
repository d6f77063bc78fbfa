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
// only order the steps (ties by the smaller vertex index; relevances
// closer than a float's precision, 2^-24 of themselves, count as ties).
// An indexed 8-ary min-heap orders them, one entry per vertex whose key
// changes when a neighbour goes: O(n log n) for n vertices, plus the
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
// The triangle test looks for live vertices in horizontal rows about two
// edges high, each sorted by x, rebuilt when the number of live vertices
// falls to a quarter (CGAL's spatial searching would serve, but its kd-tree
// does not shrink with removals; a uniform grid over the bounding box puts
// many vertices in a cell where they lie along curves, as outlines' do).  Decisions use the exact
// orientation of Epick for a kernel of doubles.
//
// In parallel.  A removal of v reads and changes only v, its neighbours
// u and w, and the vertices in the triangle (u, v, w).  The plane is cut
// into P vertical slabs with as many vertices each (P depends only on the
// number of vertices n: 1 below 65,536, else the largest power of two
// not above n / 32,768, at most 16; always 1 for kernels of exact numbers).
// A vertex is interior to its slab if both its neighbours lie in it; the
// others (next to an edge that crosses a slab boundary) are frozen.  First,
// every slab runs the evolution of its interior vertices on its own (own
// queue, own rows: in parallel with oneTBB, one task per slab), until it has
// a thirty-second of its vertices left: such a removal reads and writes the
// slab's vertices only, since its triangle lies in the slab.  The edges
// that cross slab boundaries never change then (their ends are frozen), so
// a ring that spans slabs keeps a frozen vertex in each slab it meets; a
// slab removes a vertex of such a ring only while it has four of the
// ring's vertices or more (the ring then keeps at least four).  The slabs'
// removals are merged by relevance (any interleaving is a valid sequence:
// they touch disjoint vertices), and the evolution goes on over the whole
// shape, in one queue, as above.  The result differs from the sequential
// evolution only near slab boundaries, among the removals of the first
// phase (the fine details); the coarse shapes, the last thirty-second of
// the evolution and more, come from one queue over the whole shape.  The
// result is the same whatever the number of threads.

#ifndef CGAL_PROGRESSIVE_MEDIAL_AXIS_2_INTERNAL_CURVE_EVOLUTION_H
#define CGAL_PROGRESSIVE_MEDIAL_AXIS_2_INTERNAL_CURVE_EVOLUTION_H

#include <CGAL/Progressive_medial_axis_2/Input_error.h>
#include <CGAL/Progressive_medial_axis_2/validate_polygon.h>
#include <CGAL/Progressive_medial_axis_2/internal/Input_conversion.h>
#include <CGAL/assertions.h>

#include <boost/align/aligned_allocator.hpp>

#if defined(CGAL_LINKED_WITH_TBB) && !defined(CGAL_PMA2_NO_TBB)
#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>
#endif

#ifndef CGAL_PMA2_EVOLUTION_SLAB_VERTICES
#define CGAL_PMA2_EVOLUTION_SLAB_VERTICES 32768
#endif

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
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
    std::size_t n = 0;
    for(const auto& r : rings_) n += r.size();
    v_.resize(n);
    begin_.reserve(rings_.size() + 1);
    for(int r = 0, g = 0; r < int(rings_.size()); ++r) {
      begin_.push_back(g);
      const int b = g, e = g + int(rings_[std::size_t(r)].size());
      for(const Point_2& p : rings_[std::size_t(r)]) {
        Vertex& x = v_[std::size_t(g)];
        x.x = CGAL::to_double(p.x());
        x.y = CGAL::to_double(p.y());
        x.prev = g == b ? e - 1 : g - 1;
        x.next = g + 1 == e ? b : g + 1;
        x.ring_flags = unsigned(r) << FLAG_BITS | ALIVE;
        ++g;
      }
    }
    begin_.push_back(int(n));
    size_.resize(rings_.size());
    for(std::size_t r = 0; r < rings_.size(); ++r) size_[r] = rings_[r].size();
    // the vertices inside an edge of the input stay
    auto pin = [&](const std::vector<std::pair<int, int> >& on) {
      for(const auto& rv : on) v_[std::size_t(begin_[std::size_t(rv.first)] + rv.second)].ring_flags |= PINNED;
    };
    if(vertices_on_edges) {
      pin(*vertices_on_edges);
    } else {
      std::vector<std::pair<int, int> > on;
      validate_and_find_vertices_on_edges(rings_, &on);
      pin(on);
    }
    double length = 0;
    for(const Vertex& x : v_) {
      const double dx = v_[std::size_t(x.next)].x - x.x, dy = v_[std::size_t(x.next)].y - x.y;
      length += std::sqrt(dx * dx + dy * dy);
    }
    if(!std::isfinite(length)) {   // (coordinates near the limits of double)
      length = 0;
      for(const Vertex& x : v_) length += std::hypot(v_[std::size_t(x.next)].x - x.x, v_[std::size_t(x.next)].y - x.y);
    }
    scale_ = length > 0 ? 1 / length : 1;
  }

  /// Runs the evolution (once).  `parts`: the number of slabs of the
  /// first phase (0: chosen from the number of vertices, see above).
  void run(int parts = 0)
  {
    if(ran_) return;
    ran_ = true;
    const int n = int(v_.size());
    pos_.assign(std::size_t(n) + rings_.size(), -1);
    removals_.reserve(std::size_t(n));
    int P = parts > 0 ? parts : default_parts(std::size_t(n));
    if constexpr(!std::is_floating_point<typename Kernel::FT>::value) P = 1;   // (lazy exact numbers are not shared)
    std::vector<std::vector<Removal> > slabs;
    if(P > 1 && n > 0) slabs = run_in_slabs(P);
    // the whole shape, in rounds (while the slabs' removals are merged)
    for(std::size_t r = 0; r < rings_.size(); ++r) size_[r] = 0;
    for(const Vertex& x : v_)
      if(x.ring_flags & ALIVE) ++size_[std::size_t(x.ring())];
    if(slabs.empty()) {
      Part whole(*this, -HUGE_VAL, HUGE_VAL, &removals_);
      whole.run_rounds();
      return;
    }
    std::vector<Removal> rest;
    auto whole = [&] {
      Part part(*this, -HUGE_VAL, HUGE_VAL, &rest);
      part.run_rounds();
    };
    auto merge = [&] { merge_by_relevance(slabs); };
#if defined(CGAL_LINKED_WITH_TBB) && !defined(CGAL_PMA2_NO_TBB)
    tbb::parallel_invoke(whole, merge);
#else
    whole();
    merge();
#endif
    removals_.insert(removals_.end(), rest.begin(), rest.end());
  }

  /// The number of slabs of the first phase for n vertices: the largest
  /// power of two, at most 16, with CGAL_PMA2_EVOLUTION_SLAB_VERTICES
  /// (32,768; the tests set it lower) vertices per slab or more.
  static int default_parts(std::size_t n)
  {
    const std::size_t per_slab = CGAL_PMA2_EVOLUTION_SLAB_VERTICES;
    int p = 1;
    while(p < 16 && std::size_t(2 * p) * per_slab <= n) p *= 2;
    return p;
  }

  const std::vector<Removal>& removals() const { return removals_; }
  /// The steps, moved out (shape() then no longer works).
  std::vector<Removal> take_removals() { return std::move(removals_); }

  /// The rings after the first `k` steps (vertices in input order; filled
  /// holes left out, so later holes move forward).
  Rings<Point_2> shape(std::size_t k) const
  {
    std::vector<char> gone(v_.size(), 0), filled(rings_.size(), 0);
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

  // ---- a vertex: its coordinates in double, its neighbours in the current
  // shape, its ring, and whether it is alive and pinned (32 bytes: what a
  // step reads of a vertex is one cache line)
  enum { ALIVE = 1, PINNED = 2, FLAG_BITS = 2 };
  struct Vertex {
    double x, y;
    int prev, next;
    int slot;          // its place in the rows of its part, while alive
    unsigned ring_flags;   // ring << FLAG_BITS | flags
    int ring() const { return int(ring_flags >> FLAG_BITS); }
    unsigned flags() const { return ring_flags & ((1u << FLAG_BITS) - 1); }
  };
  // the rows one after the other: a live vertex's coordinates and id (-1
  // once it is gone), so that a query does not read the vertices
  struct Entry {
    double x, y;
    int g;
  };
  bool alive(int g) const { return (v_[std::size_t(g)].ring_flags & ALIVE) != 0; }
  bool pinned(int g) const { return (v_[std::size_t(g)].ring_flags & PINNED) != 0; }

  // An entry of a queue packs the relevance, rounded to a float, above the
  // id: one integer comparison orders by (relevance, id), and the 8
  // children of an entry fill one cache line.
  struct Item {
    std::uint64_t bits;
    Item() = default;
    Item(double key, int id) : bits(std::uint64_t(float_bits(key)) << 32 | std::uint32_t(id)) {}
    int id() const { return int(std::uint32_t(bits)); }
    double key() const
    {
      const std::uint32_t b = std::uint32_t(bits >> 32);
      float f;
      std::memcpy(&f, &b, sizeof f);
      return double(f);
    }
    bool operator<(const Item& o) const { return bits < o.bits; }
    // relevances are at least 0: their float bits are in the same order
    static std::uint32_t float_bits(double key)
    {
      const float f = float(key);
      std::uint32_t b;
      std::memcpy(&b, &f, sizeof b);
      return b;
    }
  };

  // ---- a part of the plane, x in [x_lo, x_hi) (a slab of the first phase,
  // or the whole plane): its vertices' queue, rows and removals.  A part
  // writes only the records of its own vertices.
  class Part
  {
  public:
    Part(Curve_evolution& e, double x_lo, double x_hi, std::vector<Removal>* out)
      : e_(e), x_lo_(x_lo), x_hi_(x_hi), slab_(x_lo > -HUGE_VAL || x_hi < HUGE_VAL), out_(out)
    {
      for(int g = 0; g < int(e_.v_.size()); ++g)
        if(mine(g) && (e_.v_[std::size_t(g)].ring_flags & ALIVE)) members_.push_back(g);
      live_ = members_.size();
      // every vertex (and hole: a slab's have three vertices or more in it)
      // at most once in the queue: no reallocation
      heap_storage_.resize(members_.size() + (slab_ ? members_.size() / 3 : e_.rings_.size()) + heap_pad + 1);
      heap_ = heap_storage_.data() + heap_pad;
    }

    // The sequential evolution (the whole plane): rounds until one removes nothing.
    void run_rounds()
    {
      const int n = int(e_.v_.size());
      auto& size = e_.size_;
      build_grid();
      for(;;) {
        std::size_t removed_in_round = 0;
        // the queue of the round, built at once (Floyd)
        heap_size_ = 0;
        for(int g : members_) {
          const Vertex& x = e_.v_[std::size_t(g)];
          if(x.flags() == ALIVE && size[std::size_t(x.ring())] > 3) push(g, e_.relevance(g));
        }
        for(int r = 1; r < int(size.size()) && e_.fill_holes_; ++r)
          if(size[std::size_t(r)] == 3) push(n + r, e_.fill_relevance(r));
        heapify();
        while(heap_size_ > 0)
          removed_in_round += step();
        if(removed_in_round == 0) break;
      }
    }

    // The first phase of a slab: its interior vertices, in one pass, until
    // a thirty-second of its vertices is left.
    void run_slab(const std::vector<int>& span_of)
    {
      span_of_ = &span_of;
      for(int g : members_) {
        const int s = span_of[std::size_t(e_.v_[std::size_t(g)].ring())];
        if(s >= 0) {
          if(std::size_t(s) >= span_count_.size()) span_count_.resize(std::size_t(s) + 1, 0);
          ++span_count_[std::size_t(s)];
        }
      }
      build_grid();
      heap_size_ = 0;
      for(int g : members_)
        if(!e_.pinned(g) && interior(g) && ring_allows(g)) push(g, e_.relevance(g));
      heapify();
      const std::size_t stop = (std::max)(std::size_t(3), members_.size() / 32);
      while(heap_size_ > 0 && live_ > stop) step();
    }

  private:
    bool mine(int g) const { const double x = e_.v_[std::size_t(g)].x; return x >= x_lo_ && x < x_hi_; }
    // both neighbours in the part (always, for the whole plane)
    bool interior(int g) const
    {
      const Vertex& x = e_.v_[std::size_t(g)];
      return !slab_ || (mine(x.prev) && mine(x.next));
    }
    // whether the ring of g may lose a vertex: it has more than three; in a
    // slab, for a ring that spans slabs, the slab has four of them or more
    bool ring_allows(int g) const
    {
      const int r = e_.v_[std::size_t(g)].ring();
      if(slab_) {
        const int s = (*span_of_)[std::size_t(r)];
        if(s >= 0) return span_count_[std::size_t(s)] >= 4;
      }
      return e_.size_[std::size_t(r)] > 3;
    }

    // One step: pops the least entry and removes its vertex (or fills its
    // hole) if allowed.  Returns whether it did.
    std::size_t step()
    {
      const int n = int(e_.v_.size());
      const Item top = pop();
#if defined(__GNUC__)
      // the vertex that comes next, while this one is tested
      if(heap_size_ > 0 && heap_[0].id() < n) __builtin_prefetch(&e_.v_[std::size_t(heap_[0].id())]);
#endif
      if(top.id() >= n) {
        const int r = top.id() - n;
        if(e_.size_[std::size_t(r)] != 3) return 0;
        fill(r, top.key());
        return 1;
      }
      std::size_t done = 0;
      const Vertex& x = e_.v_[std::size_t(top.id())];
      if((x.ring_flags & ALIVE) && ring_allows(top.id()) && removable(top.id())) {
        remove(top.id(), top.key());
        done = 1;
      }
#if defined(__GNUC__)
      // what the test of the next vertex reads: its neighbours and its
      // place in the rows (while the queue is updated)
      if(heap_size_ > 0 && heap_[0].id() < n) {
        const Vertex& y = e_.v_[std::size_t(heap_[0].id())];
        if(y.ring_flags & ALIVE) {
          __builtin_prefetch(&e_.v_[std::size_t(y.prev)]);
          __builtin_prefetch(&e_.v_[std::size_t(y.next)]);
          __builtin_prefetch(&grid_[std::size_t(y.slot)]);
        }
      }
#endif
      return done;
    }

    // ---- the indexed 8-ary min-heap of vertices (ids < n) and of holes to
    // fill (id n + ring), by (relevance, id); the places of the entries are
    // in the evolution's pos_ (a part writes those of its own entries)
    static constexpr std::size_t arity = 8;
    // The storage is aligned to 64 bytes and the heap starts 7 entries in:
    // the children of entry i, 8i+1 to 8i+8, are one cache line.
    static constexpr std::size_t heap_pad = arity - 1;
    void push(int id, double key)
    {
      e_.pos_[std::size_t(id)] = int(heap_size_);
      heap_[heap_size_++] = Item(key, id);
    }
    void heapify()
    {
      for(std::size_t i = heap_size_ / arity + 1; i-- > 0;)
        if(i < heap_size_) sift_down(i);
    }
    void place(std::size_t i, const Item& it)
    {
      heap_[i] = it;
      e_.pos_[std::size_t(it.id())] = int(i);
    }
    void sift_up(std::size_t i)
    {
      const Item it = heap_[i];
      while(i > 0) {
        const std::size_t p = (i - 1) / arity;
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
        const std::size_t c = arity * i + 1;
        if(c >= m) break;
        std::size_t best;
        if(c + arity <= m) {
          // the least of 8 by a tournament of conditional moves (the
          // branches of a loop are mispredicted: the children are in random order)
          const Item* ch = heap_ + c;
          std::uint64_t v[4];
          std::size_t k[4];
          for(std::size_t j = 0; j < 4; ++j) {
            const bool right = ch[2 * j + 1].bits < ch[2 * j].bits;
            v[j] = right ? ch[2 * j + 1].bits : ch[2 * j].bits;
            k[j] = 2 * j + (right ? 1 : 0);
          }
          for(std::size_t j = 0; j < 2; ++j) {
            const bool right = v[2 * j + 1] < v[2 * j];
            v[j] = right ? v[2 * j + 1] : v[2 * j];
            k[j] = right ? k[2 * j + 1] : k[2 * j];
          }
          best = c + (v[1] < v[0] ? k[1] : k[0]);
        } else {
          best = c;
          for(std::size_t j = c + 1; j < m; ++j)
            best = heap_[j] < heap_[best] ? j : best;
        }
        if(!(heap_[best] < it)) break;
        place(i, heap_[best]);
        i = best;
      }
      place(i, it);
    }
    Item pop()
    {
      const Item top = heap_[0];
      e_.pos_[std::size_t(top.id())] = -1;
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
      const int at = e_.pos_[std::size_t(id)];
      if(at < 0) {
        heap_[heap_size_] = Item(key, id);
        e_.pos_[std::size_t(id)] = int(heap_size_);
        sift_up(heap_size_++);
        return;
      }
      const Item old = heap_[std::size_t(at)];
      heap_[std::size_t(at)] = Item(key, id);
      if(heap_[std::size_t(at)] < old) sift_up(std::size_t(at));
      else sift_down(std::size_t(at));
    }

    // a vertex queued again, its neighbours having changed
    void requeue(int g)
    {
      if(e_.pinned(g) || !interior(g)) return;
      set_key(g, e_.relevance(g));
    }

    void kill(int g)
    {
      Vertex& x = e_.v_[std::size_t(g)];
      x.ring_flags &= ~unsigned(ALIVE);
      grid_[std::size_t(x.slot)].g = -1;
      --live_;
    }

    void fill(int r, double k)
    {
      out_->push_back(Removal{r, -1, -1, -1, k});
      const int a = e_.first_alive(r), b = e_.v_[std::size_t(a)].next, c = e_.v_[std::size_t(b)].next;
      for(int g : {a, b, c}) kill(g);
      e_.size_[std::size_t(r)] = 0;
      if(live_ * 4 < grid_capacity_) build_grid();
    }

    bool removable(int v) const
    {
      const auto& vs = e_.v_;
      const Vertex& V = vs[std::size_t(v)];
      const int u = V.prev, w = V.next;
      const Vertex &U = vs[std::size_t(u)], &W = vs[std::size_t(w)];
      if((U.ring_flags | V.ring_flags | W.ring_flags) & PINNED) return false;
#if defined(__GNUC__)
      // what a removal reads next: the new relevances of u and w and their
      // places in the queue
      __builtin_prefetch(&vs[std::size_t(U.prev)]);
      __builtin_prefetch(&vs[std::size_t(W.next)]);
      __builtin_prefetch(&e_.pos_[std::size_t(u)]);
      __builtin_prefetch(&e_.pos_[std::size_t(w)]);
#endif
      const Orientation o = e_.orientation(u, v, w);
      // (a ring that spans slabs has five vertices or more in the first phase)
      if(e_.size_[std::size_t(V.ring())] == 4 && (!slab_ || (*span_of_)[std::size_t(V.ring())] < 0) &&
         e_.orientation(u, w, W.next) == COLLINEAR)
        return false;
      // live vertices in the triangle's bounding box
      const double tx[3] = {U.x, V.x, W.x};
      const double ty[3] = {U.y, V.y, W.y};
      const int ts[3] = {U.slot, V.slot, W.slot};
      const double x0 = (std::min)({tx[0], tx[1], tx[2]}), x1 = (std::max)({tx[0], tx[1], tx[2]});
      const double y0 = (std::min)({ty[0], ty[1], ty[2]}), y1 = (std::max)({ty[0], ty[1], ty[2]});
      int j0 = row_of(y0), j1 = row_of(y1);
      if constexpr(!std::is_floating_point<typename Kernel::FT>::value) {
        // (coordinates rounded from exact numbers: a row more on each side)
        j0 = (std::max)(0, j0 - 1);
        j1 = (std::min)(rows_ - 1, j1 + 1);
      }
      const double dy = 1e-6 * row_height_ + 1e-14 * (std::fabs(y0) + std::fabs(y1));
      const double slack = 1e-6 * row_height_ + 1e-14 * (std::fabs(x0) + std::fabs(x1));
      const Entry* ge = grid_.data();
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
        // the entries of the row with x in [lo, hi]: a contiguous range, found
        // from the slot of a triangle vertex in the row (its neighbours in
        // the array are near in the plane), else by a binary search
        const std::size_t first = row_start_[std::size_t(j)], last = row_start_[std::size_t(j) + 1];
        std::size_t a = last;
        for(int e = 0; e < 3; ++e)
          if(row_of(ty[e]) == j && tx[e] >= lo && tx[e] <= hi) { a = std::size_t(ts[e]); break; }
        std::size_t b;
        if(a == last) {
          a = std::size_t(std::lower_bound(ge + first, ge + last, lo, [](const Entry& t, double x) { return t.x < x; }) - ge);
          b = a;
        } else {
          b = a;
          while(a > first && ge[a - 1].x >= lo) --a;
        }
        while(b != last && ge[b].x <= hi) ++b;
        for(std::size_t it = a; it != b; ++it) {
          const Entry& P = ge[it];
          if(P.y < y0 - dy || P.y > y1 + dy) continue;
          if(P.g < 0 || P.g == u || P.g == v || P.g == w) continue;
          if(e_.in_closed_triangle(P, u, v, w, o)) return false;
        }
      }
      return true;
    }

    void remove(int v, double k)
    {
      auto& vs = e_.v_;
      Vertex& V = vs[std::size_t(v)];
      const int u = V.prev, w = V.next;
      const int r = V.ring();
      const int b = e_.begin_[std::size_t(r)];
      out_->push_back(Removal{r, v - b, u - b, w - b, k});
      kill(v);
      vs[std::size_t(u)].next = w;
      vs[std::size_t(w)].prev = u;
      if(live_ * 4 < grid_capacity_) build_grid();
      const int s = slab_ ? (*span_of_)[std::size_t(r)] : -1;
      if(s >= 0) {   // a ring that spans slabs
        if(--span_count_[std::size_t(s)] >= 4) {
          requeue(u);
          requeue(w);
        }
        return;
      }
      std::size_t& size = e_.size_[std::size_t(r)];
      if(--size > 3) {
        requeue(u);
        requeue(w);
      } else if(r > 0 && e_.fill_holes_) {
        set_key(int(vs.size()) + r, e_.fill_relevance(r));
      }
    }

    // ---- the live vertices of the part in horizontal rows about two edges
    // high, each row sorted by x (a query scans the triangle's x-range in
    // each row it crosses); dead vertices are skipped until the next
    // rebuild.  The row height follows the live edges' mean length, so that
    // a row holds few vertices where they lie along curves.
    int row_of(double y) const { return std::clamp(int((y - gy0_) / row_height_), 0, rows_ - 1); }

    void build_grid()
    {
      auto& vs = e_.v_;
      // the live members, compacted
      std::size_t count = 0;
      for(int g : members_)
        if(vs[std::size_t(g)].ring_flags & ALIVE) members_[count++] = g;
      members_.resize(count);
      double y0 = HUGE_VAL, y1 = -HUGE_VAL, length = 0;
      for(int g : members_) {
        const Vertex& x = vs[std::size_t(g)];
        y0 = (std::min)(y0, x.y);
        y1 = (std::max)(y1, x.y);
        // (an estimate of the length, without overflow)
        length += std::fabs(vs[std::size_t(x.next)].x - x.x) + std::fabs(vs[std::size_t(x.next)].y - x.y);
      }
      const double h = (std::max)(y1 - y0, 1e-300);
      const double mean = count > 0 ? length / double(count) : h;
      gy0_ = y0;
      rows_ = int((std::min)(double(4 * count + 1), (std::min)(1e7, h / (std::max)(2 * mean, h * 1e-7)))) + 1;
      row_height_ = h / double(rows_);
      if(!(row_height_ > 0)) row_height_ = 1;
      row_start_.assign(std::size_t(rows_) + 1, 0);
      std::vector<int> row(count);
      for(std::size_t i = 0; i < count; ++i) {
        row[i] = row_of(vs[std::size_t(members_[i])].y);
        ++row_start_[std::size_t(row[i]) + 1];
      }
      for(int r = 0; r < rows_; ++r) row_start_[std::size_t(r) + 1] += row_start_[std::size_t(r)];
      grid_.resize(count);
      std::vector<std::size_t> fill(row_start_.begin(), row_start_.end() - 1);
      for(std::size_t i = 0; i < count; ++i) {
        const Vertex& x = vs[std::size_t(members_[i])];
        grid_[fill[std::size_t(row[i])]++] = Entry{x.x, x.y, members_[i]};
      }
      for(int r = 0; r < rows_; ++r)
        std::sort(grid_.begin() + std::ptrdiff_t(row_start_[std::size_t(r)]), grid_.begin() + std::ptrdiff_t(row_start_[std::size_t(r) + 1]),
                  [](const Entry& a, const Entry& b) { return a.x < b.x; });
      for(std::size_t i = 0; i < count; ++i) vs[std::size_t(grid_[i].g)].slot = int(i);
      grid_capacity_ = count;
    }

    Curve_evolution& e_;
    double x_lo_, x_hi_;
    bool slab_;
    std::vector<Removal>* out_;
    std::vector<int> members_;   // the part's vertices (the live ones after a rebuild of the rows)
    std::size_t live_ = 0, grid_capacity_ = 0;
    std::vector<Item, boost::alignment::aligned_allocator<Item, 64> > heap_storage_;
    Item* heap_ = nullptr;
    std::size_t heap_size_ = 0;
    double gy0_ = 0, row_height_ = 1;
    int rows_ = 1;
    std::vector<std::size_t> row_start_;
    std::vector<Entry> grid_;
    const std::vector<int>* span_of_ = nullptr;   // (slabs) the rings that span slabs: their index, or -1
    std::vector<int> span_count_;                 // (slabs) this slab's vertices of each such ring
  };

  // The first phase: P slabs of as many vertices each, in parallel; their
  // removals, slab by slab.
  std::vector<std::vector<Removal> > run_in_slabs(int P)
  {
    std::vector<double> xs;
    xs.reserve(v_.size());
    for(const Vertex& x : v_) xs.push_back(x.x);
    std::vector<double> cut(std::size_t(P) + 1);
    cut[0] = -HUGE_VAL;
    cut[std::size_t(P)] = HUGE_VAL;
    for(int p = 1; p < P; ++p) {
      auto m = xs.begin() + std::ptrdiff_t(xs.size() * std::size_t(p) / std::size_t(P));
      std::nth_element(xs.begin(), m, xs.end());
      cut[std::size_t(p)] = *m;
    }
    for(int p = 1; p < P; ++p) cut[std::size_t(p)] = (std::max)(cut[std::size_t(p)], cut[std::size_t(p) - 1]);
    // the rings that span slabs
    auto slab_of = [&](double x) { return int(std::upper_bound(cut.begin() + 1, cut.end() - 1, x) - cut.begin()) - 1; };
    std::vector<int> span_of(rings_.size(), -1);
    int spans = 0;
    for(std::size_t r = 0; r < rings_.size(); ++r) {
      const int b = begin_[r], e = begin_[r + 1];
      if(b == e) continue;
      const int s0 = slab_of(v_[std::size_t(b)].x);
      for(int g = b + 1; g < e; ++g)
        if(slab_of(v_[std::size_t(g)].x) != s0) {
          span_of[r] = spans++;
          break;
        }
    }
    std::vector<std::vector<Removal> > out{std::size_t(P)};
    auto run_slab = [&](std::size_t p) {
      out[p].reserve(v_.size() / std::size_t(P) + 16);
      Part part(*this, cut[p], cut[p + 1], &out[p]);
      part.run_slab(span_of);
    };
#if defined(CGAL_LINKED_WITH_TBB) && !defined(CGAL_PMA2_NO_TBB)
    tbb::parallel_for(std::size_t(0), std::size_t(P), run_slab, tbb::simple_partitioner());
#else
    for(std::size_t p = 0; p < std::size_t(P); ++p) run_slab(p);
#endif
    return out;
  }

  // The slabs' removals into removals_, merged by relevance: the least of
  // the slabs' next removals first (any interleaving is valid: they touch
  // disjoint vertices).
  void merge_by_relevance(const std::vector<std::vector<Removal> >& out)
  {
    const int P = int(out.size());
    std::vector<std::size_t> at(std::size_t(P), 0);
    for(;;) {
      int best = -1;
      for(int p = 0; p < P; ++p)
        if(at[std::size_t(p)] < out[std::size_t(p)].size() &&
           (best < 0 || out[std::size_t(p)][at[std::size_t(p)]].relevance < out[std::size_t(best)][at[std::size_t(best)]].relevance))
          best = p;
      if(best < 0) break;
      removals_.push_back(out[std::size_t(best)][at[std::size_t(best)]++]);
    }
  }

  double relevance(int g) const
  {
    const Vertex& b = v_[std::size_t(g)];
    const Vertex& a = v_[std::size_t(b.prev)];
    const Vertex& c = v_[std::size_t(b.next)];
    const double ax = b.x - a.x, ay = b.y - a.y;
    const double bx = c.x - b.x, by = c.y - b.y;
    const double beta = turning_angle(std::fabs(ax * by - ay * bx), ax * bx + ay * by);
    const double l1 = std::sqrt(ax * ax + ay * ay) * scale_, l2 = std::sqrt(bx * bx + by * by) * scale_;
    return l1 + l2 > 0 ? beta * l1 * l2 / (l1 + l2) : 0;
  }

  // atan2(s, c) for s >= 0, in [0, pi], to a relative error of 3e-8 (the
  // keys are floats; std::atan2 took a seventh of the evolution): Cephes'
  // atanf polynomial (S. L. Moshier) on [0, tan(pi / 8)] after reduction.
  static double turning_angle(double s, double c)
  {
    const double pi = 3.14159265358979323846;
    if(s == 0) return c >= 0 ? 0 : pi;
    const double a = std::fabs(c);
    const bool swap = s > a;   // atan(t) for t = min / max of (s, a), in [0, 1]
    double t = swap ? a / s : s / a, base = 0;
    if(t > 0.41421356237309504880) {
      base = pi / 4;
      t = (t - 1) / (t + 1);
    }
    const double z = t * t;
    double r = base + ((((8.05374449538e-2 * z - 1.38776856032e-1) * z + 1.99777106478e-1) * z - 3.33329491539e-1) * z * t + t);
    if(swap) r = pi / 2 - r;
    return c < 0 ? pi - r : r;
  }

  // the relevance of filling hole r, a triangle: the least of its vertices'
  double fill_relevance(int r) const
  {
    const int g = first_alive(r);
    return (std::min)({relevance(g), relevance(v_[std::size_t(g)].next), relevance(v_[std::size_t(g)].prev)});
  }

  int first_alive(int r) const
  {
    int g = begin_[std::size_t(r)];
    while(!alive(g)) ++g;
    return g;
  }

  const Point_2& point(int g) const
  {
    const int r = v_[std::size_t(g)].ring();
    return rings_[std::size_t(r)][std::size_t(g - begin_[std::size_t(r)])];
  }

  Orientation orientation(const Point_2& a, const Point_2& b, const Point_2& c) const
  {
    return Exact_orientation<Kernel>()(a, b, c);
  }
  // the same on vertices (for a kernel of doubles, from the copies of their
  // coordinates, without reading the input's points)
  Orientation orientation(int a, int b, int c) const
  {
    if constexpr(std::is_floating_point<typename Kernel::FT>::value) {
      typedef typename EK::type::Point_2 P;
      const Vertex &va = v_[std::size_t(a)], &vb = v_[std::size_t(b)], &vc = v_[std::size_t(c)];
      return typename EK::type().orientation_2_object()(P(va.x, va.y), P(vb.x, vb.y), P(vc.x, vc.y));
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

  // whether the vertex of row entry p lies in the closed triangle of
  // vertices (a, b, c), of orientation o
  bool in_closed_triangle(const Entry& p, int a, int b, int c, Orientation o) const
  {
    if constexpr(std::is_floating_point<typename Kernel::FT>::value) {
      if(o != COLLINEAR) {
        typedef typename EK::type::Point_2 P;
        const Vertex &va = v_[std::size_t(a)], &vb = v_[std::size_t(b)], &vc = v_[std::size_t(c)];
        const P pa(va.x, va.y), pb(vb.x, vb.y), pc(vc.x, vc.y), pp(p.x, p.y);
        const auto orient = typename EK::type().orientation_2_object();
        return orient(pa, pb, pp) != -o && orient(pb, pc, pp) != -o && orient(pc, pa, pp) != -o;
      }
    }
    return in_closed_triangle(p.g, a, b, c, o);
  }

  const Rings<Point_2>& rings_;
  std::vector<Vertex> v_;
  std::vector<int> begin_;
  std::vector<std::size_t> size_;   // live vertices of each ring (of local rings only, in the first phase)
  double scale_ = 1;
  std::vector<int> pos_;   // the place of each vertex (and hole) in its part's queue, or -1
  std::vector<Removal> removals_;
  bool fill_holes_ = true;
  bool ran_ = false;
};

} // namespace internal
} // namespace Progressive_medial_axes
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_MEDIAL_AXIS_2_INTERNAL_CURVE_EVOLUTION_H
