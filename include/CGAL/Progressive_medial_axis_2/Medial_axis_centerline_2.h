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

#ifndef CGAL_PROGRESSIVE_MEDIAL_AXIS_2_MEDIAL_AXIS_CENTERLINE_2_H
#define CGAL_PROGRESSIVE_MEDIAL_AXIS_2_MEDIAL_AXIS_CENTERLINE_2_H

#include <CGAL/license/Progressive_medial_axis_2.h>

#include <CGAL/Progressive_medial_axis_2/Medial_axis_significance_2.h>

#include <boost/container/vector.hpp>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <deque>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <numeric>
#include <queue>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Progressive_medial_axes {
namespace internal {

// Calls f(a, b) for every edge of the input polygon of ma, in double.
template <class Medial_axis, class F>
void for_each_input_edge(const Medial_axis& ma, const F& f)
{
  for(std::size_t r = 0; r < ma.number_of_input_rings(); ++r) {
    const std::size_t n = ma.input_ring_size(r);
    for(std::size_t i = 0; i < n; ++i)
      f(Medial_axis::to_xy(ma.point({int(r), int(i)})), Medial_axis::to_xy(ma.point({int(r), int((i + 1) % n)})));
  }
}

} // namespace internal
} // namespace Progressive_medial_axes

/*!
\ingroup PkgProgressiveMedialAxis2Ref

The centerline of a shape: paths along its pruned medial axis, made by
`medial_axis_centerline_2()`.

A shape without holes has one path: the longest path of the pruned axis
between two of its ends.  With holes (a braided river: channels around
islands), a hydrologist expects every channel: the centerline is the pruned
axis without its side branches, that is the cycles around the holes, the
curves that join them, and the paths from them to the two ends of the
longest path (the two ends farthest apart along the axis: the river's
source and mouth).  It is then given as several paths, the maximal chains
between its junctions.

A path is a sequence of parts of medial curves; with `extend`, a path that
ends at an end of the centerline is prolonged from it, along the curve's
direction there, by a straight segment up to the boundary of the shape.
*/
template <class K>
class Medial_axis_centerline_2
{
public:
  typedef Medial_axis_2<K> Medial_axis;
  typedef typename Medial_axis::Halfedge_handle Halfedge_handle;
  typedef std::pair<double, double> Point;

  /// A part of a medial curve, walked from arc length `from` to `to`
  /// (both from `halfedge.source()`; `from > to` walks it backwards).
  struct Piece {
    Halfedge_handle halfedge;
    double from = 0, to = 0;
    double length() const { return std::fabs(to - from); }
  };
  /// The pieces of a path: a random-access range over storage that the
  /// centerline and its copies share (valid as long as one of them lives).
  /// One array holds the pieces of all the paths: a plate of 100,000 holes
  /// has 300,000 paths of a few pieces each.
  class Piece_range
  {
  public:
    typedef const Piece* const_iterator;
    typedef const_iterator iterator;
    const_iterator begin() const { return b_; }
    const_iterator end() const { return e_; }
    std::size_t size() const { return std::size_t(e_ - b_); }
    bool empty() const { return b_ == e_; }
    const Piece& operator[](std::size_t i) const { return b_[i]; }
    const Piece& front() const { return *b_; }
    const Piece& back() const { return e_[-1]; }

  private:
    friend class Medial_axis_centerline_2;
    const Piece *b_ = nullptr, *e_ = nullptr;
  };
  /// One path of the centerline.
  struct Path {
    Piece_range pieces;
    bool has_start_extension = false, has_end_extension = false;
    Point start_extension, end_extension;  ///< the points on the boundary that the extensions reach
    bool closed = false;                   ///< a cycle around a hole
  };
  /// A sample of the width profile.
  struct Width_sample {
    double s;     ///< arc length from the start of the path (extension included)
    double x, y;  ///< the point
    double width; ///< twice the radius of the maximal disk there
    std::size_t path; ///< index of the path
  };

  const std::vector<Path>& paths() const { return paths_; }
  bool is_empty() const { return paths_.empty(); }

  /// The first and last point of a path.
  Point start_point(const Path& p) const
  {
    if(p.has_start_extension) return p.start_extension;
    return point_of(p.pieces.front(), p.pieces.front().from);
  }

  /// The length of a path, extensions included.
  double length(const Path& p) const
  {
    double l = 0;
    for(const Piece& x : p.pieces) l += x.length();
    if(p.has_start_extension) l += distance(p.start_extension, point_of(p.pieces.front(), p.pieces.front().from));
    if(p.has_end_extension) l += distance(p.end_extension, point_of(p.pieces.back(), p.pieces.back().to));
    return l;
  }
  /// The total length of the centerline.
  double length() const
  {
    double l = 0;
    for(const Path& p : paths_) l += length(p);
    return l;
  }

  /// The paths as polylines within `tolerance` of the curves.
  std::vector<std::vector<Point> > polylines(double tolerance) const
  {
    std::vector<std::vector<Point> > out;
    for(const Path& p : paths_) {
      std::vector<Point> line;
      if(p.has_start_extension) line.push_back(p.start_extension);
      for(std::size_t i = 0; i < p.pieces.size(); ++i) {
        const Piece& x = p.pieces[i];
        std::vector<Point> part = x.halfedge.polyline(tolerance, (std::min)(x.from, x.to), (std::max)(x.from, x.to));
        if(x.from > x.to) std::reverse(part.begin(), part.end());
        // consecutive pieces share their end point: written once
        line.insert(line.end(), part.begin() + (i == 0 ? 0 : 1), part.end());
      }
      if(p.has_end_extension) line.push_back(p.end_extension);
      out.push_back(line);
    }
    return out;
  }

  /// The width profile: arc length, point and width (2R) at every vertex of
  /// the centerline and at least every tenth of the local width.  On an
  /// extension the width is twice the distance to the boundary (O(n) per
  /// sample; an extension has a few dozen samples).
  std::vector<Width_sample> width_profile() const
  {
    std::vector<Width_sample> out;
    for(std::size_t k = 0; k < paths_.size(); ++k) {
      const Path& p = paths_[k];
      double s = 0;
      if(p.has_start_extension)
        s = sample_segment(out, k, s, p.start_extension, point_of(p.pieces.front(), p.pieces.front().from), false);
      for(const Piece& x : p.pieces) {
        const double L = x.length();
        const double dir = x.to >= x.from ? 1.0 : -1.0;
        double t = 0;
        while(true) {
          const double at = x.from + dir * t;
          const double r = x.halfedge.radius_at(at);
          const auto q = x.halfedge.point_at(at);
          if(t > 0 || out.empty() || out.back().path != k)   // a piece starts where the last one ends
            out.push_back(Width_sample{s + t, q.first, q.second, 2 * r, k});
          if(t >= L) break;
          const double step = (std::max)(0.1 * 2 * r, L * 1e-4);
          t = (std::min)(L, t + step);
        }
        s += L;
      }
      if(p.has_end_extension)
        sample_segment(out, k, s, point_of(p.pieces.back(), p.pieces.back().to), p.end_extension, true);
    }
    return out;
  }

  /// \cond
  explicit Medial_axis_centerline_2(const Medial_axis& ma) : ma_(ma) {}
  std::vector<Path> paths_;
  // The pieces of all the paths, one after the other, written in parallel.
  void set_pieces(Path& p, std::size_t b, std::size_t e) const
  {
    p.pieces.b_ = pieces_.begin() + b;
    p.pieces.e_ = pieces_.begin() + e;
  }
  Progressive_medial_axes::internal::Written_once_array<Piece> pieces_;
  static Point point_of(const Piece& x, double s)
  {
    if(s <= 0) return Medial_axis::to_xy(x.halfedge.source().point());
    if(s >= x.halfedge.length()) return Medial_axis::to_xy(x.halfedge.target().point());
    return x.halfedge.point_at(s);
  }
  static double distance(const Point& a, const Point& b) { return std::hypot(a.first - b.first, a.second - b.second); }
  // the distance from q to the boundary of the input polygon, O(n)
  double distance_to_boundary(const Point& q) const
  {
    double best = std::numeric_limits<double>::infinity();
    Progressive_medial_axes::internal::for_each_input_edge(ma_, [&](const Point& a, const Point& b) {
      best = (std::min)(best, Progressive_medial_axes::internal::distance_to_segment(q, a, b));
    });
    return best;
  }
  /// \endcond

private:
  // samples of the straight segment a-b (an extension), from s on
  double sample_segment(std::vector<Width_sample>& out, std::size_t k, double s, const Point& a, const Point& b,
                        bool skip_first) const
  {
    const double L = distance(a, b);
    double t = 0;
    bool first = true;
    while(true) {
      const double f = L > 0 ? t / L : 1;
      const Point q(a.first + (b.first - a.first) * f, a.second + (b.second - a.second) * f);
      const double w = 2 * distance_to_boundary(q);
      if(!(first && skip_first)) out.push_back(Width_sample{s + t, q.first, q.second, w, k});
      first = false;
      if(t >= L) break;
      t = (std::min)(L, t + (std::max)(0.1 * w, L / 64));
    }
    return s + L;
  }

  Medial_axis ma_;
};

namespace Progressive_medial_axes {
namespace internal {

// The first point of the boundary of the input polygon of ma hit by the ray
// from p in the unit direction d (p itself if none, which cannot happen
// from inside the shape).
template <class Medial_axis>
std::pair<double, double> shoot_ray(const Medial_axis& ma, const std::pair<double, double>& p,
                                    const std::pair<double, double>& d)
{
  double best = std::numeric_limits<double>::infinity();
  for_each_input_edge(ma, [&](const std::pair<double, double>& a, const std::pair<double, double>& b) {
    const double ex = b.first - a.first, ey = b.second - a.second;
    const double den = d.first * ey - d.second * ex;
    if(den == 0) return;
    const double wx = a.first - p.first, wy = a.second - p.second;
    const double t = (wx * ey - wy * ex) / den;   // along the ray
    const double u = (wx * d.second - wy * d.first) / den;   // along the edge
    if(t > 0 && u >= 0 && u <= 1 && t < best) best = t;
  });
  if(best == std::numeric_limits<double>::infinity()) return p;
  return std::make_pair(p.first + best * d.first, p.second + best * d.second);
}

} // namespace internal
} // namespace Progressive_medial_axes

/*!
\ingroup PkgProgressiveMedialAxis2Ref

The centerline of a pruned medial axis (see `Medial_axis_centerline_2`),
extended to the boundary with `extend`.  The two ends farthest apart come
from two shortest-path searches on the graph of the junctions and ends of
the pruned axis (each chain of curves between them is one link there; an
axis without ends, such as that of a plate with holes, needs no search).
The paths, the chains between the junctions and ends, are then walked in
parallel where TBB is linked.  Their directions and their order depend on
the axis alone (neither on the threads nor on how the axis was computed):
a path starts at its end that comes first, the first end of the
centerline before the others, those by their points (x, then y); the
paths come in the order of their first ends, then of their last ends,
then of the middles of the kept parts of their first curves (a path from
a junction back to it, and a cycle without junction, run the way whose
first curve has the smaller middle).  So a path that reaches the first
end starts there, and the first path does.  (Two junctions or ends at one
point in double, which exact decisions can give where branch points are
closer than the rounding, are ordered by how the axis was computed.)  The searches start
from, and break their ties by, that order of points too.  O(m + k log k)
for m kept curves and k junctions and ends, plus O(n) per extended end.
*/
template <class K>
Medial_axis_centerline_2<K> medial_axis_centerline_2(const Pruned_medial_axis_2<K>& pruned, bool extend = false)
{
  typedef Medial_axis_centerline_2<K> Centerline;
  typedef typename Centerline::Piece Piece;
  typedef typename Centerline::Path Path;
  typedef typename Pruned_medial_axis_2<K>::Curve Curve;
  typedef typename Centerline::Point Point;
  Centerline out(pruned.medial_axis());
  const auto& curves = pruned.curves();
  if(curves.empty()) return out;

  // the graph: the nodes of the significance's graph at the ends of the
  // kept curves, and a node per cut end (the pruned axis keeps them).  When
  // few of the nodes are kept, they are numbered again, in the same order,
  // so that the arrays below have the size of the pruned axis rather than
  // that of the whole axis.
  typedef typename Pruned_medial_axis_2<K>::Link Link;
  typename Pruned_medial_axis_2<K>::Link_vector renumbered;
  int n_nodes = pruned.number_of_nodes_;
  if(8 * pruned.links_.size() < std::size_t(n_nodes)) {
    std::vector<int> ids;
    ids.reserve(2 * pruned.links_.size());
    for(const Link& l : pruned.links_) {
      ids.push_back(l.a);
      ids.push_back(l.b);
    }
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
    auto id = [&](int v) { return int(std::lower_bound(ids.begin(), ids.end(), v) - ids.begin()); };
    renumbered.reserve(pruned.links_.size());
    for(const Link& l : pruned.links_) renumbered.push_back(Link{id(l.a), id(l.b), l.length});
    n_nodes = int(ids.size());
  }
  const auto& links = renumbered.empty() ? pruned.links_ : renumbered;
  using Progressive_medial_axes::internal::parallel_parts;
  using Progressive_medial_axes::internal::prefetch;
  // The graph by node: its degree, and the exclusive or of its outgoing
  // halves and of the nodes at their other ends.  The half 2 l walks link
  // l from its node a to its node b, 2 l + 1 from b to a; a loop gives its
  // node both halves and the node itself twice.  At a node of degree 2 a
  // walk then goes on without a list of the node's links: its next half is
  // the node's exclusive or of halves with the one it came in by (as an
  // outgoing half), and its next node the node's exclusive or of nodes with
  // the one it came from.  One record is read by step.  Set up in parts of
  // the nodes, in parallel: each part reads all the links.
  struct Node_state { int degree, halves, nodes; };
  const std::size_t parts = Progressive_medial_axes::internal::number_of_parts(links.size());
  boost::container::vector<Node_state> node(std::size_t(n_nodes), boost::container::default_init);
  parallel_parts(std::size_t(n_nodes), parts, [&](std::size_t, std::size_t b, std::size_t e) {
    for(std::size_t v = b; v < e; ++v) node[v] = Node_state{0, 0, 0};
    for(int i = 0; i < int(links.size()); ++i) {
      const Link& l = links[std::size_t(i)];
      if(std::size_t(l.a) - b < e - b) {
        Node_state& x = node[std::size_t(l.a)];
        ++x.degree;
        x.halves ^= 2 * i;
        x.nodes ^= l.b;
      }
      if(std::size_t(l.b) - b < e - b) {
        Node_state& x = node[std::size_t(l.b)];
        ++x.degree;
        x.halves ^= 2 * i + 1;
        x.nodes ^= l.a;
      }
    }
  });
  auto degree = [&](int v) { return node[std::size_t(v)].degree; };
  // the node that half h leads to from its node v
  auto end_of = [&](int h, int v) {
    const Link& l = links[std::size_t(h >> 1)];
    return l.a ^ l.b ^ v;
  };
  // one step of a walk on through the node `to`, of degree 2, reached from
  // the node `from` by half h
  auto step = [&](int& from, int& h, int& to) {
    const Node_state& x = node[std::size_t(to)];
    h = x.halves ^ h ^ 1;
    const int next = x.nodes ^ from;
    from = to;
    to = next;
  };
  // The junctions and ends (the nodes of degree neither 0 nor 2), and their
  // outgoing halves in the order of the links (and of the halves).  Set up
  // like the states.
  std::vector<int> key_of(std::size_t(n_nodes), -1), keys;
  for(int v = 0; v < n_nodes; ++v)
    if(degree(v) != 2 && degree(v) != 0) {
      key_of[std::size_t(v)] = int(keys.size());
      keys.push_back(v);
    }
  std::vector<int> key_first(keys.size() + 1, 0);
  for(std::size_t i = 0; i < keys.size(); ++i) key_first[i + 1] = key_first[i] + degree(keys[i]);
  std::vector<int> key_half(std::size_t(key_first.back()));
  {
    std::vector<int> fill(key_first.begin(), key_first.end() - 1);
    parallel_parts(keys.size(), parts, [&](std::size_t, std::size_t b, std::size_t e) {
      for(int i = 0; i < int(links.size()); ++i) {
        const Link& l = links[std::size_t(i)];
        // (a node that is not a key is -1: out of every part)
        const std::size_t ka = std::size_t(key_of[std::size_t(l.a)]), kb = std::size_t(key_of[std::size_t(l.b)]);
        if(ka - b < e - b) key_half[std::size_t(fill[ka]++)] = 2 * i;
        if(kb - b < e - b) key_half[std::size_t(fill[kb]++)] = 2 * i + 1;
      }
    });
  }

  // The orders that do not depend on how the axis was computed (the node
  // numbers do): the keys by their points, and where that leaves a tie, the
  // middles of curves.
  auto piece_of = [&](int h) {   // the kept curve of a half, walked in its direction
    const Curve& c = curves[std::size_t(h >> 1)];
    Piece p;
    p.halfedge = c.halfedge;
    p.from = c.begin;
    p.to = c.end;
    if(h & 1) std::swap(p.from, p.to);
    return p;
  };
  auto start_point_of = [&](int h) {   // the point of the node a half leaves
    const Curve& c = curves[std::size_t(h >> 1)];
    return (h & 1) ? c.end_point() : c.begin_point();
  };
  auto middle_of = [&](int h) {
    const Piece p = piece_of(h);
    return p.halfedge.point_at(0.5 * (p.from + p.to));
  };
  std::vector<Point> key_point(keys.size());
  Progressive_medial_axes::internal::parallel_blocks(keys.size(), [&](std::size_t b, std::size_t e) {
    for(std::size_t i = b; i < e; ++i) key_point[i] = start_point_of(key_half[std::size_t(key_first[i])]);
  }, std::is_floating_point<typename Medial_axis_2<K>::FT>::value);
  std::vector<int> keys_by_point(keys.size());
  {
    // (sorted with their points: a sort of indices reading the points would
    // read them in no order)
    std::vector<std::pair<Point, int> > sorted(keys.size());
    for(std::size_t i = 0; i < keys.size(); ++i) sorted[i] = std::make_pair(key_point[i], int(i));
    std::sort(sorted.begin(), sorted.end());
    for(std::size_t r = 0; r < keys.size(); ++r) keys_by_point[r] = sorted[r].second;
  }

  // from an end (if there is none, the centerline is the cycles of the
  // first junction, or without junction the first node on a curve, by
  // point; nodes of the significance's graph that are not kept have no
  // curve)
  int start = -1, some = -1;
  for(int i : keys_by_point) {
    if(start < 0 && degree(keys[std::size_t(i)]) == 1) start = keys[std::size_t(i)];
    if(some < 0) some = keys[std::size_t(i)];
  }
  if(some < 0) {   // cycles without junction: their node of smallest point
    Point best;
    for(int i = 0; i < int(links.size()); ++i)
      for(int h : {2 * i, 2 * i + 1}) {
        const Point q = start_point_of(h);
        const int v = (h & 1) ? links[std::size_t(i)].b : links[std::size_t(i)].a;
        if(some < 0 || q < best) {
          best = q;
          some = v;
        }
      }
  }
  int end_a = some, end_b = some;
  if(start >= 0) {
    // The two searches run on the graph of the junctions and ends only: each
    // chain of nodes of degree 2 between them (most nodes, for example the
    // curves around a hole) is one link there, of the chain's total length.
    struct Key_link { int node; double length; };
    std::vector<Key_link> key_near(key_half.size());
    for(std::size_t i = 0; i < keys.size(); ++i)
      for(int k = key_first[i]; k < key_first[i + 1]; ++k) {
        // follow the chain to the next junction or end (a chain entered from
        // a junction cannot close on itself without one)
        int from = keys[i], h = key_half[std::size_t(k)];
        int to = end_of(h, from);
        double length = links[std::size_t(h >> 1)].length;
        while(key_of[std::size_t(to)] < 0) {
          step(from, h, to);
          length += links[std::size_t(h >> 1)].length;
        }
        key_near[std::size_t(k)] = Key_link{key_of[std::size_t(to)], length};
      }
    // the end farthest from an end, along the curves (Dijkstra); on a tie the
    // first by point
    auto farthest = [&](int source) {
      std::vector<double> dist(keys.size(), std::numeric_limits<double>::infinity());
      typedef std::pair<double, int> Item;
      std::priority_queue<Item, std::vector<Item>, std::greater<Item> > q;
      dist[std::size_t(key_of[std::size_t(source)])] = 0;
      q.push(Item(0, key_of[std::size_t(source)]));
      while(!q.empty()) {
        const Item it = q.top();
        q.pop();
        if(it.first > dist[std::size_t(it.second)]) continue;
        for(int k = key_first[std::size_t(it.second)]; k < key_first[std::size_t(it.second) + 1]; ++k) {
          const int o = key_near[std::size_t(k)].node;
          const double d = it.first + key_near[std::size_t(k)].length;
          if(d < dist[std::size_t(o)]) {
            dist[std::size_t(o)] = d;
            q.push(Item(d, o));
          }
        }
      }
      int best = source;
      double best_dist = 0;
      for(int k : keys_by_point) {
        const std::size_t i = std::size_t(k);
        if(degree(keys[i]) == 1 && dist[i] > best_dist && dist[i] != std::numeric_limits<double>::infinity()) {
          best = keys[i];
          best_dist = dist[i];
        }
      }
      return best;
    };
    end_a = farthest(start);
    end_b = farthest(end_a);
  }
  const bool a_is_end = degree(end_a) == 1, b_is_end = degree(end_b) == 1;
  // the links at the two ends
  const int end_link_a = a_is_end ? node[std::size_t(end_a)].halves >> 1 : -1;
  const int end_link_b = b_is_end ? node[std::size_t(end_b)].halves >> 1 : -1;

  // peel the side branches: remove the ends other than end_a and end_b
  // (a node's one link left is its exclusive or of halves)
  std::vector<char> removed_link(links.size(), 0);
  std::deque<int> leaves;
  for(int v : keys)
    if(degree(v) == 1 && v != end_a && v != end_b) leaves.push_back(v);
  while(!leaves.empty()) {
    const int v = leaves.front();
    leaves.pop_front();
    Node_state& x = node[std::size_t(v)];
    if(x.degree != 1) continue;
    const int h = x.halves, o = x.nodes;
    removed_link[std::size_t(h >> 1)] = 1;
    x = Node_state{0, 0, 0};
    Node_state& y = node[std::size_t(o)];
    y.halves ^= h ^ 1;
    y.nodes ^= v;
    if(--y.degree == 1 && o != end_a && o != end_b) leaves.push_back(o);
  }
  auto live = [&](int h) { return !removed_link[std::size_t(h >> 1)]; };
  // the live outgoing half of a node whose curve has the smallest middle,
  // by a scan of the links (for a node of degree 2, once)
  auto first_live_half = [&](int v) {
    int best = -1;
    Point best_middle;
    for(int i = 0; i < int(links.size()); ++i) {
      if(removed_link[std::size_t(i)]) continue;
      for(int h : {2 * i, 2 * i + 1}) {
        if(((h & 1) ? links[std::size_t(i)].b : links[std::size_t(i)].a) != v) continue;
        const Point m = middle_of(h);
        if(best < 0 || m < best_middle) {
          best = h;
          best_middle = m;
        }
      }
    }
    return best;
  };
  // a junction or end of the component of end_a, if it has one (end_a can
  // be a node of degree 2 when the axis has no end)
  int root = end_a;
  if(degree(end_a) == 2) {
    int h = first_live_half(end_a), from = end_a, v = end_of(h, end_a);
    while(degree(v) == 2 && v != end_a) step(from, h, v);
    root = v;
  }
  // The paths: the maximal chains between nodes of degree other than 2, of
  // the component of end_a only.  A chain is walked from its start (a live
  // outgoing half at a junction or an end) that comes first in the order:
  // root's, then by node, then by half; then each path is turned to start
  // at its end that comes first by point (root first), and the paths are
  // put in that order (below).  So the path at end_a (root) starts there.
  // A step of a walk is a read that depends on the step before it (a
  // random place in memory, for most steps): the walks are interleaved,
  // Lanes at a time, so that their reads overlap.  Each chain is met from
  // both of its starts; the later one skips it (or, when both were walked
  // at once, drops it).
  if(degree(root) == 2) {   // a cycle without a junction
    std::vector<int> halves;
    int h = first_live_half(root), from = root, v = end_of(h, root);
    while(true) {
      halves.push_back(h);
      if(v == root) break;
      step(from, h, v);
    }
    out.pieces_ = Progressive_medial_axes::internal::Written_once_array<Piece>(halves.size());
    for(std::size_t i = 0; i < halves.size(); ++i) out.pieces_.write(i, piece_of(halves[i]));
    Path path;
    path.closed = true;
    out.set_pieces(path, 0, halves.size());
    out.paths_.push_back(path);
  } else {
    std::vector<int> starts, start_key;
    auto add_starts = [&](int v) {
      const int i = key_of[std::size_t(v)];
      for(int k = key_first[std::size_t(i)]; k < key_first[std::size_t(i) + 1]; ++k)
        if(live(key_half[std::size_t(k)])) {
          starts.push_back(key_half[std::size_t(k)]);
          start_key.push_back(i);
        }
    };
    add_starts(root);
    const std::size_t root_starts = starts.size();
    for(int v : keys)
      if(v != root && degree(v) != 2) add_starts(v);
    // whether the start at position i comes before the outgoing half f of
    // the key t in the order of the walks (root's, then by node, then by
    // half; the paths are put in the order of points after)
    const int root_key = key_of[std::size_t(root)];
    auto before = [&](std::size_t i, int f, int t) {
      const bool ri = i < root_starts, rf = t == root_key;
      if(ri != rf) return ri;
      return start_key[i] != t ? start_key[i] < t : starts[i] < f;
    };
    // a start whose chain is walked (written and read by the parts at
    // once: a part that misses a mark walks the chain again and drops it)
    std::unique_ptr<std::atomic<char>[]> done(new std::atomic<char>[2 * links.size()]());
    // by part, the halves of its kept chains, one after the other
    std::vector<std::vector<int> > seq(parts);
    struct Chain { std::size_t part, begin, end; int to; };   // to: the key at its end
    std::vector<Chain> chains(starts.size(), Chain{0, 0, 0, -1});   // by start
    parallel_parts(starts.size(), parts, [&](std::size_t part, std::size_t b, std::size_t e) {
      std::vector<int>& out_seq = seq[part];
      out_seq.reserve(links.size() / parts);
      constexpr int Lanes = 16;
      struct Lane { int at = -1, h = 0, from = 0, to = 0; std::vector<int> halves; };
      Lane lanes[Lanes];
      std::size_t next_start = b;
      int busy = 0;
      auto load = [&](Lane& x) {
        while(next_start < e && done[std::size_t(starts[next_start])].load(std::memory_order_relaxed)) ++next_start;
        if(next_start == e) {
          x.at = -1;
          return;
        }
        x.at = int(next_start);
        x.h = starts[next_start];
        x.from = keys[std::size_t(start_key[next_start++])];
        x.to = end_of(x.h, x.from);
        prefetch(&node[std::size_t(x.to)]);
        x.halves.clear();
        ++busy;
      };
      for(Lane& x : lanes) load(x);
      while(busy > 0)
        for(Lane& x : lanes) {
          if(x.at < 0) continue;
          x.halves.push_back(x.h);
          if(degree(x.to) == 2) {
            step(x.from, x.h, x.to);
            prefetch(&node[std::size_t(x.to)]);
            continue;
          }
          // the chain ends at the key of x.to, by its outgoing half f
          const int f = x.h ^ 1, t = key_of[std::size_t(x.to)];
          if(before(std::size_t(x.at), f, t)) {
            done[std::size_t(f)].store(1, std::memory_order_relaxed);
            chains[std::size_t(x.at)] = Chain{part, out_seq.size(), out_seq.size() + x.halves.size(), t};
            out_seq.insert(out_seq.end(), x.halves.begin(), x.halves.end());
          }
          --busy;
          load(x);
        }
    });
    // the chains of the component of root (the axis of a polygon whose
    // ring touches itself can have several components), by keys
    std::vector<int> component(keys.size());
    std::iota(component.begin(), component.end(), 0);
    auto find = [&](int x) {
      while(component[std::size_t(x)] != x) x = component[std::size_t(x)] = component[std::size_t(component[std::size_t(x)])];
      return x;
    };
    for(std::size_t i = 0; i < chains.size(); ++i)
      if(chains[i].to >= 0) component[std::size_t(find(start_key[i]))] = find(chains[i].to);
    std::vector<std::size_t> kept;
    const int root_component = find(root_key);
    for(std::size_t i = 0; i < chains.size(); ++i)
      if(chains[i].to >= 0 && find(start_key[i]) == root_component) kept.push_back(i);
    // Each path from its end that comes first, in that order: root, then by
    // the point of its key (a path from a key back to it, from the end whose
    // curve has the smaller middle), and the paths by their first end, then
    // their last, then the middle of their first curve.
    std::vector<int> key_rank(keys.size());
    for(std::size_t r = 0; r < keys.size(); ++r) key_rank[std::size_t(keys_by_point[r])] = int(r);
    auto rank = [&](int k) { return k == root_key ? -1 : key_rank[std::size_t(k)]; };
    struct Oriented { int first, last; std::size_t chain; bool reversed; };
    // the middle of the first curve of a chain, read forward or reversed
    auto first_middle_of = [&](const Chain& c, bool reversed) {
      const std::vector<int>& halves = seq[c.part];
      return middle_of(reversed ? halves[c.end - 1] ^ 1 : halves[c.begin]);
    };
    std::vector<Oriented> order(kept.size());
    for(std::size_t i = 0; i < kept.size(); ++i) {
      const Chain& c = chains[kept[i]];
      const int a = rank(start_key[kept[i]]), b = rank(c.to);
      const bool reversed = a == b ? first_middle_of(c, true) < first_middle_of(c, false) : b < a;
      order[i] = Oriented{(std::min)(a, b), (std::max)(a, b), kept[i], reversed};
    }
    auto first_middle = [&](const Oriented& o) { return first_middle_of(chains[o.chain], o.reversed); };
    std::sort(order.begin(), order.end(), [](const Oriented& x, const Oriented& y) {
      return std::make_pair(x.first, x.last) < std::make_pair(y.first, y.last);
    });
    for(std::size_t i = 0; i < order.size();) {   // (several paths between two keys: by their first curves)
      std::size_t j = i + 1;
      while(j < order.size() && order[j].first == order[i].first && order[j].last == order[i].last) ++j;
      if(j - i > 1) {
        std::vector<std::pair<Point, Oriented> > tied;
        for(std::size_t k = i; k < j; ++k) tied.emplace_back(first_middle(order[k]), order[k]);
        std::sort(tied.begin(), tied.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
        for(std::size_t k = i; k < j; ++k) order[k] = tied[k - i].second;
      }
      i = j;
    }
    // the paths, their pieces written in parallel (the curves read in no
    // order: asked for ahead)
    out.paths_.resize(order.size());
    std::vector<std::size_t> offset(order.size() + 1, 0);
    for(std::size_t i = 0; i < order.size(); ++i)
      offset[i + 1] = offset[i] + (chains[order[i].chain].end - chains[order[i].chain].begin);
    out.pieces_ = Progressive_medial_axes::internal::Written_once_array<Piece>(offset.back());
    Progressive_medial_axes::internal::parallel_blocks(order.size(), [&](std::size_t b, std::size_t e) {
      for(std::size_t i = b; i < e; ++i) {
        const Chain& c = chains[order[i].chain];
        const std::vector<int>& halves = seq[c.part];
        const std::size_t n = c.end - c.begin;
        for(std::size_t j = 0; j < n; ++j) {
          const std::size_t at = order[i].reversed ? c.end - 1 - j : c.begin + j;
          const std::size_t ahead = order[i].reversed ? at - 16 : at + 16;   // (wraps below 0: then too large)
          if(ahead < halves.size()) prefetch(&curves[std::size_t(halves[ahead] >> 1)]);
          out.pieces_.write(offset[i] + j, piece_of(order[i].reversed ? halves[at] ^ 1 : halves[at]));
        }
        out.set_pieces(out.paths_[i], offset[i], offset[i + 1]);
      }
    });
  }

  if(extend) {
    const auto& ma = pruned.medial_axis();
    for(Path& p : out.paths_) {
      if(p.closed) continue;
      // the node where the path starts and ends: an end of the centerline?
      const Piece& f = p.pieces.front();
      const Piece& b = p.pieces.back();
      auto is_end_at = [&](const Piece& x, double s) {
        for(int v : {end_a, end_b}) {
          if(!(v == end_a ? a_is_end : b_is_end)) continue;
          const int l = v == end_a ? end_link_a : end_link_b;
          const Curve& c = curves[l];
          if(c.halfedge == x.halfedge && (links[l].a == v ? c.begin : c.end) == s) return true;
        }
        return false;
      };
      if(is_end_at(f, f.from)) {
        auto t = f.halfedge.tangent_at(f.from);
        if(f.to > f.from) t = std::make_pair(-t.first, -t.second);
        p.start_extension =
          Progressive_medial_axes::internal::shoot_ray(ma, Centerline::point_of(f, f.from), t);
        p.has_start_extension = true;
      }
      if(is_end_at(b, b.to)) {
        auto t = b.halfedge.tangent_at(b.to);
        if(b.to < b.from) t = std::make_pair(-t.first, -t.second);
        p.end_extension = Progressive_medial_axes::internal::shoot_ray(ma, Centerline::point_of(b, b.to), t);
        p.has_end_extension = true;
      }
    }
  }
  return out;
}

} // namespace CGAL

#endif // CGAL_PROGRESSIVE_MEDIAL_AXIS_2_MEDIAL_AXIS_CENTERLINE_2_H
