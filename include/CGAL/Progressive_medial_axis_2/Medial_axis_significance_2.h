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

#ifndef CGAL_PROGRESSIVE_MEDIAL_AXIS_2_MEDIAL_AXIS_SIGNIFICANCE_2_H
#define CGAL_PROGRESSIVE_MEDIAL_AXIS_2_MEDIAL_AXIS_SIGNIFICANCE_2_H

#include <CGAL/license/Progressive_medial_axis_2.h>

#include <CGAL/Progressive_medial_axis_2/Medial_axis_2.h>

#include <CGAL/assertions.h>

#include <boost/container/vector.hpp>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <cstddef>
#include <functional>
#include <limits>
#include <memory>
#include <stdexcept>
#include <utility>
#include <vector>

namespace CGAL {

/*!
\ingroup PkgProgressiveMedialAxis2Ref

The significance of the points of a medial axis by the *extended grassfire
transform* (Liu, Chambers, Letscher and Ju, "Extended grassfire transform on
medial axes of 2D shapes", Computer-Aided Design 43(11), 2011).

Fire starts at time 0 at every end of the axis (a convex polygon vertex,
where the radius \f$R\f$ is 0) and runs along the axis at unit speed (arc
length).  A vertex of the axis catches fire when all but one of its curves
have burnt up to it, at the time the last of them arrives, and the fire goes
on into the remaining curve.  Two fronts that meet inside a curve (or at a
vertex) stop there.  The *extended distance function* \f$EDF(x)\f$ is the
time the fire reaches \f$x\f$; it is infinite on the points that never burn:
the cycles of the axis around the holes, the curves that join them, and the
vertices where a branch reaches them.  The *erosion thickness*
\f$ET(x) = EDF(x) - R(x)\f$ is at least 0 and never decreases in the
direction the fire runs.  A branch made by a wiggle of the boundary of size
\f$\delta\f$ has an erosion thickness of about \f$\delta\f$ at most, however
long it is: this is what makes pruning by \f$ET\f$ stable.

Algorithm (linear in the size of the axis, no priority queue): the fire
on a tree depends only on the arrival times, so it is computed by two passes
over the axis as a graph, as the eccentricities of a tree are.
1. Leaves are peeled off (Kahn's order): a vertex goes when all its curves
   but one lead to vertices gone before it; that curve leads to its
   *parent* (found without reading the neighbours: a vertex keeps the
   exclusive or of its curves not yet peeled, of their other ends and of
   the bits of their lengths).  What is never peeled is the 2-core of the
   axis, the cycles around holes and the paths between them: it never
   burns.  A tree without cycle ends at a *root*, peeled last with no
   parent.  In this order every vertex gets `up(v)`, the latest arrival of
   the fronts of its children, and the two latest arrivals with the curve
   of the first.
2. In the reverse order every vertex gets `down(v)`, the time the front from
   its parent's side would arrive (infinite below the 2-core): the latest
   arrival at the parent from all its other curves, plus the curve's length.
3. A vertex catches fire at the latest of its arrivals but the latest one
   (0 at an end) and sends its front into the curve of the latest one (on a
   tie, the parent's; between children, the first child peeled).  The times
   do not depend on how ties are broken.  Steps 2 and 3 are one pass: a
   vertex's `down(v)` needs only its parent's, and then all its arrivals
   are known.
Invariants: the ignition time of a vertex is no earlier than any front it
gets; every curve at a vertex that burns carries a front from one end at
least (the curves of the 2-core carry none); a curve with fronts
from both ends holds the meeting point, at arc length
\f$(L + t_w - t_u)/2\f$ from the end \f$u\f$ that caught fire at \f$t_u\f$.
In a component of the axis without cycle, exactly one point (a vertex or such
a meeting point) burns last.  This is the fire the definition describes:
a front that is not the latest at a vertex always arrives, and the latest
never does (the vertex sent its own front into that curve first).

Along a curve the radius is a convex function of arc length (linear on the
bisector of two segments, \f$\sqrt{d^2 + s^2}\f$ on that of two points, the
height above the directrix on a parabola), so \f$ET\f$ is concave along a
curve: the set where it is above a threshold is one interval.

Lengths and times are in double precision (they are sums of arc lengths of
parabolas, which are not algebraic); the axis itself stays exact.  Each
curve's length is taken from its end of smaller (x, y), so the lengths and
times do not depend on how the axis was computed (for a one-shot, on the
number of threads), only on the axis.  Which curve a vertex sends its
front into where two fronts reach it at the same time in double (a
symmetric shape) still does: the first child peeled, or the parent.

\tparam K the kernel of the axis.
*/
template <class K>
class Medial_axis_significance_2
{
public:
  typedef Medial_axis_2<K> Medial_axis;
  typedef typename Medial_axis::Vertex_handle Vertex_handle;
  typedef typename Medial_axis::Halfedge_handle Halfedge_handle;

  /// How the fire runs along a curve.
  enum Burning {
    NOT_BURNING,  ///< the curve never burns (it joins points that never burn)
    FROM_SOURCE,  ///< one front runs from the source of the curve's half-edge to its target
    FROM_TARGET,  ///< one front runs from the target to the source
    FROM_BOTH     ///< fronts from both ends meet inside the curve
  };

  /// Computes the extended distance function of `ma` (a copy of the handle
  /// to the axis is kept).
  explicit Medial_axis_significance_2(const Medial_axis& ma) : ma_(ma)
  {
    build();
    burn();
  }

  const Medial_axis& medial_axis() const { return ma_; }

  /// The infinite time of the points that never burn.
  static double infinity() { return std::numeric_limits<double>::infinity(); }

  /// The extended distance function at a vertex of the axis.
  double extended_distance(const Vertex_handle& v) const { return vertices_[vertex_index(v)].time; }
  /// The radius at a vertex (in double).
  double radius(const Vertex_handle& v) const { return vertices_[vertex_index(v)].radius; }
  /// The erosion thickness at a vertex (infinite where it never burns).
  double erosion_thickness(const Vertex_handle& v) const
  {
    const Node& n = vertices_[vertex_index(v)];
    return n.time == infinity() ? infinity() : (std::max)(0.0, n.time - n.radius);
  }

  /// How the fire runs along the curve of `h`, relative to `h`.
  Burning burning(const Halfedge_handle& h) const
  {
    const Arc& a = arcs_[edge_index(h)];
    const bool su = a.start[0] != infinity(), sw = a.start[1] != infinity();
    Burning b = su ? (sw ? FROM_BOTH : FROM_SOURCE) : (sw ? FROM_TARGET : NOT_BURNING);
    if(!same_direction(h) && (b == FROM_SOURCE || b == FROM_TARGET)) b = (b == FROM_SOURCE ? FROM_TARGET : FROM_SOURCE);
    return b;
  }

  /// The extended distance function at arc length `s` from `h.source()`
  /// along the curve of `h` (0 <= s <= h.length()).
  double extended_distance(const Halfedge_handle& h, double s) const
  {
    const Arc& a = arcs_[edge_index(h)];
    const double from_u = same_direction(h) ? s : a.length - s;
    return time_along(a, from_u);
  }

  /// The erosion thickness at arc length `s` from `h.source()`.
  double erosion_thickness(const Halfedge_handle& h, double s) const
  {
    const double t = extended_distance(h, s);
    return t == infinity() ? infinity() : (std::max)(0.0, t - h.radius_at(s));
  }

  /// The latest finite time at which a point of the axis burns.
  double last_burning_time() const { return last_time_; }

  /// The largest radius at a vertex of a medial curve, in double: the
  /// radius of `maximum_inscribed_circle_2()` rounded to double, without
  /// another pass over the axis (0 for an axis without curves).
  double largest_radius() const { return largest_radius_; }

  /// \cond
  // The graph of the axis, for pruning and centerlines: vertices and curves
  // by index.
  // (plain records, in vectors that do not initialise them: build() writes
  // every field once, the nodes in parallel)
  struct Node {
    double radius;
    double time;         // infinite until it catches fire (every node that does
                         // catches fire at a finite time)
    double out_length;   // the length of its curve `out`
    int vertex;          // its id number in the axis
    int out;             // the curve the fire goes on into (-1 if none)
    int far;             // the node at its other end (-1 if none)
    bool meets;          // whether a front from its other end meets this one inside it
  };
  struct Arc {
    int halfedge;  // the id number of the half-edge, oriented from node u to node w
    int u, w;
    double length;
    // the time a front enters the curve from u (start[0]) and from w
    // (start[1]), infinite if none
    double start[2];
  };
  typedef boost::container::vector<Node> Node_vector;
  typedef boost::container::vector<Arc> Arc_vector;
  const Node_vector& nodes() const { return vertices_; }
  const Arc_vector& arcs() const { return arcs_; }
  // the nodes that catch fire, in an order in which every node comes before
  // the node its front runs to (the other end of its curve `out`, unless
  // the fronts meet inside that curve)
  const std::vector<int>& order_of_fire() const { return order_; }
  Vertex_handle vertex(int node) const { return ma_.vertex_of_id(std::size_t(vertices_[node].vertex)); }
  Halfedge_handle halfedge(const Arc& a) const { return ma_.halfedge_of_id(std::size_t(a.halfedge)); }
  int vertex_index(const Vertex_handle& v) const { return checked(v.id_number() < vertex_map_.size() ? vertex_map_[v.id_number()] : -1); }
  int edge_index(const Halfedge_handle& h) const
  {
    // the arcs are in the order of the id numbers of their pairs of
    // half-edges (each arc's half-edge from its end of smaller (x, y))
    const int e = int(h.id_number() & ~std::size_t(1));
    const auto it = std::lower_bound(arcs_.begin(), arcs_.end(), e, [](const Arc& a, int k) { return (a.halfedge & ~1) < k; });
    return checked(it != arcs_.end() && (it->halfedge & ~1) == e ? int(it - arcs_.begin()) : -1);
  }
  static int checked(int i)
  {
    if(i < 0) throw std::invalid_argument("Medial_axis_significance_2: not a vertex or a medial curve of the axis");
    return i;
  }
  bool same_direction(const Halfedge_handle& h) const { return arcs_[edge_index(h)].halfedge == int(h.id_number()); }
  static double time_along(const Arc& a, double from_u)
  {
    return (std::min)(a.start[0] + from_u, a.start[1] + (a.length - from_u));
  }
  /// \endcond

private:
  // The graph from the arrays of the axis (Medial_axis_2::medial_curve_graph()).
  void build()
  {
    using Progressive_medial_axes::internal::parallel_blocks;
    using Progressive_medial_axes::internal::parallel_filled;
    boost::container::vector<int> curves;
    boost::container::vector<std::array<int, 2> > ends;
    boost::container::vector<double> lengths;
    boost::container::vector<std::array<double, 2> > radii;
    ma_.medial_curve_graph(curves, ends, lengths, &radii);
    const std::size_t m = curves.size();
    vertex_map_ = parallel_filled(ma_.vertex_id_bound(), -1);
    // Nodes in the order in which the curves reach them, numbered in one
    // pass that reads only the ends and writes, for each node, its first
    // end (2 k + 0 or 1 for the source or target of curve k); the records
    // are written after it, in parallel.  Without branches: whether a curve
    // reaches a node first follows no pattern a branch predictor could
    // learn.  (There are up to 2 m + 1 nodes, usually about m: the pass
    // writes the entries of first_end up to the number of nodes only.)
    boost::container::vector<int> first_end(2 * m + 1, boost::container::default_init);
    int n_nodes = 0;
    for(std::size_t k = 0; k < m; ++k)
      for(std::size_t s = 0; s < 2; ++s) {
        const std::size_t v = std::size_t(ends[k][s]);
        const int i = vertex_map_[v];
        vertex_map_[v] = i < 0 ? n_nodes : i;
        first_end[std::size_t(n_nodes)] = int(2 * k + s);   // kept if the node is new
        n_nodes += int(i < 0);
      }
    arcs_.resize(m, boost::container::default_init);
    parallel_blocks(m, [&](std::size_t b, std::size_t e) {
      for(std::size_t k = b; k < e; ++k) {
        Arc& a = arcs_[k];
        a.halfedge = curves[k];
        a.u = vertex_map_[std::size_t(ends[k][0])];
        a.w = vertex_map_[std::size_t(ends[k][1])];
        a.length = lengths[k];
        a.start[0] = a.start[1] = infinity();
      }
    });
    const std::size_t n = std::size_t(n_nodes);
    vertices_.resize(n, boost::container::default_init);
    std::atomic<double> largest(0.0);
    parallel_blocks(n, [&](std::size_t b, std::size_t e) {
      double r = 0;
      for(std::size_t i = b; i < e; ++i) {
        const std::size_t o = std::size_t(first_end[i]);
        Node& x = vertices_[i];
        x.radius = radii[o / 2][o % 2];
        x.time = infinity();
        x.vertex = ends[o / 2][o % 2];
        x.out = x.far = -1;
        x.out_length = 0;
        x.meets = false;
        r = (std::max)(r, x.radius);
      }
      for(double l = largest.load(); r > l && !largest.compare_exchange_weak(l, r);) {}
    });
    largest_radius_ = largest.load();
  }

  // The two passes of the class documentation.  Peeling follows a chain from
  // each end up the tree as long as the next node is ready, then the scan
  // takes the next end by index: the nodes visited in a row are then
  // neighbours on the axis rather than ends spread over the whole shape.
  // A node keeps the exclusive or of the indices of its curves not yet
  // peeled, of the nodes at their other ends and of the bits of their
  // lengths: when one curve is left, these are its curve to the parent, the
  // parent and the length, found without reading the curve or the
  // neighbours (one dependent read per step of a chain instead of two).
  void burn()
  {
    const double inf = infinity(), none = -inf;
    const std::size_t n = vertices_.size();
    // what the passes read of a node, in one record (48 bytes), set up in
    // parallel (fresh memory: its first touch costs)
    struct State {
      double top1, top2;     // the two latest arrivals from the children
      double down;           // the arrival from the parent's side
      std::uint64_t length;  // until peeled, the exclusive or of the bits of the
                             // lengths of the curves not yet peeled; then those of
                             // the curve to the parent
      int top1_child;        // the child of top1
      int link;              // the same for the indices of the curves (-1 at a root)
      int parent;            // the same for the nodes at their other ends
      int left;              // curves not yet peeled, -1 once peeled, 0 once ignited
    };
    auto bits = [](double x) {
      std::uint64_t b;
      std::memcpy(&b, &x, sizeof b);
      return b;
    };
    auto parent_length = [](const State& x) {
      double l;
      std::memcpy(&l, &x.length, sizeof l);
      return l;
    };
    std::unique_ptr<State[]> st(new State[n]);
    Progressive_medial_axes::internal::parallel_blocks(n, [&](std::size_t b, std::size_t e) {
      for(std::size_t v = b; v < e; ++v) {
        State& x = st[v];
        x.top1 = x.top2 = x.down = none;
        x.top1_child = -1;
        x.left = 0;
        x.link = x.parent = 0;
        x.length = 0;
      }
    });
    // the curves at each node and their exclusive or, from the curves (a
    // loop (u == w) counts twice, is never peeled, and its two ends cancel)
    for(std::size_t k = 0; k < arcs_.size(); ++k) {
      const Arc& a = arcs_[k];
      const std::uint64_t l = bits(a.length);
      State& x = st[std::size_t(a.u)];
      ++x.left;
      x.link ^= int(k);
      x.parent ^= a.w;
      x.length ^= l;
      State& y = st[std::size_t(a.w)];
      ++y.left;
      y.link ^= int(k);
      y.parent ^= a.u;
      y.length ^= l;
    }
    std::vector<int> peel;
    peel.reserve(n);
    // pass 1: peeling, from each end up as long as the next node is ready
    // (for the ends further on, the record of the node at the other end of
    // their curve is fetched ahead)
    using Progressive_medial_axes::internal::prefetch;
    // (an end not yet peeled is a node with 0 or 1 curves left: a node of
    // higher degree is peeled as soon as it has one left, so the scan reads
    // only the states)
    auto end_to_peel = [&](std::size_t v) { return unsigned(st[v].left) <= 1; };
    for(std::size_t v0 = 0; v0 < n; ++v0) {
      if(v0 + 8 < n && end_to_peel(v0 + 8)) prefetch(&st[std::size_t(st[v0 + 8].parent)]);
      if(!end_to_peel(v0)) continue;
      int v = int(v0);
      while(v >= 0) {
        peel.push_back(v);
        State& x = st[std::size_t(v)];
        int next = -1;
        if(x.left == 1) {   // else a root: every curve leads to a child
          const int p = x.parent;
          const double up = (x.top1 == none ? 0.0 : x.top1) + parent_length(x);
          State& y = st[std::size_t(p)];
          if(up > y.top1) {
            y.top2 = y.top1;
            y.top1 = up;
            y.top1_child = v;
          } else if(up > y.top2)
            y.top2 = up;
          y.link ^= x.link;
          y.parent ^= v;
          y.length ^= x.length;
          if(--y.left == 1) next = p;
        } else
          x.link = x.parent = -1;
        x.left = -1;
        v = next;
      }
    }
    // pass 2, from the parents down, and ignition in the same pass: a node's
    // arrival from its parent's side needs only the parent's, and then all
    // its arrivals are known.  Below the 2-core the parent's side never
    // sends a front (the arrival from there is infinite).  A node ignites at
    // the latest arrival but one, into the curve of the latest.
    auto to = Progressive_medial_axes::internal::parallel_filled(n, -1);   // the node the front of a node reaches, if it burns (compact, for the last pass)
    last_time_ = 0;
    for(std::size_t i = peel.size(); i-- > 0;) {
      if(i >= 8) {
        prefetch(&st[std::size_t(peel[i - 8])]);
        prefetch(&vertices_[std::size_t(peel[i - 8])]);
      }
      if(i >= 4 && st[std::size_t(peel[i - 4])].link >= 0)   // the curve its fire mostly runs into
        prefetch(&arcs_[std::size_t(st[std::size_t(peel[i - 4])].link)]);
      const int v = peel[i];
      State& x = st[std::size_t(v)];
      if(x.parent >= 0) {   // else a root
        // (the parent is peeled (left -1) or, before this node, ignited
        // (left 0); a node of the 2-core has at least two curves left)
        const State& y = st[std::size_t(x.parent)];
        double t;
        if(y.left > 0) t = inf;
        else {
          t = (std::max)(y.down, y.top1_child == v ? y.top2 : y.top1);
          if(t == none) t = 0;   // the parent is an end
        }
        x.down = t + parent_length(x);
      }
      Node& nv = vertices_[std::size_t(v)];
      double t;
      if(x.parent >= 0 && x.down >= x.top1) {
        nv.out = x.link;
        nv.far = x.parent;
        nv.out_length = parent_length(x);
        if(x.down != inf) to[std::size_t(v)] = x.parent;
        t = x.top1;
      } else {
        const State& c = st[std::size_t(x.top1_child)];
        nv.out = c.link;
        nv.far = to[std::size_t(v)] = x.top1_child;
        nv.out_length = parent_length(c);
        t = (std::max)(x.down, x.top2);
      }
      x.left = 0;
      nv.time = t == none ? 0.0 : t;
      last_time_ = (std::max)(last_time_, nv.time);
      Arc& a = arcs_[std::size_t(nv.out)];
      a.start[a.u == v ? 0 : 1] = nv.time;
      if(a.start[0] != inf && a.start[1] != inf) {
        last_time_ = (std::max)(last_time_, 0.5 * (a.start[0] + a.start[1] + a.length));
        // the fronts meet inside: neither runs to the other end
        vertices_[std::size_t(a.u)].meets = vertices_[std::size_t(a.w)].meets = true;
        to[std::size_t(a.u)] = to[std::size_t(a.w)] = -1;
      }
    }
    // the order of fire: a node after every node whose front reaches it,
    // again along the tree as far as possible (the fronts still to arrive
    // at each node are counted in a small array of their own)
    st.reset();
    auto waiting = Progressive_medial_axes::internal::parallel_filled(n, 0);
    for(std::size_t v = 0; v < n; ++v) {
      const int w = to[v];
      if(w >= 0) ++waiting[std::size_t(w)];
    }
    order_.clear();
    order_.reserve(peel.size());
    for(int v0 : peel) {
      if(waiting[std::size_t(v0)] != 0) continue;
      int v = v0;
      while(v >= 0) {
        waiting[std::size_t(v)] = -1;
        order_.push_back(v);
        const int w = to[std::size_t(v)];
        v = (w >= 0 && --waiting[std::size_t(w)] == 0) ? w : -1;
      }
    }
    CGAL_assertion(order_.size() == peel.size());
  }

  Medial_axis ma_;
  Node_vector vertices_;
  Arc_vector arcs_;
  std::vector<int> order_;
  boost::container::vector<int> vertex_map_;   // by id number
  double last_time_ = 0;
  double largest_radius_ = 0;
};

/*!
\ingroup PkgProgressiveMedialAxis2Ref

A pruned medial axis: the parts of the curves of an axis that
`prune_medial_axis_2()` keeps.  A kept curve is a part of a curve of the
axis, between two arc lengths from the source of its half-edge; an end that
is not cut is the exact vertex of the axis, a cut end is computed in double.
*/
template <class K>
class Pruned_medial_axis_2
{
public:
  typedef Medial_axis_2<K> Medial_axis;
  typedef typename Medial_axis::Vertex_handle Vertex_handle;
  typedef typename Medial_axis::Halfedge_handle Halfedge_handle;

  /// A kept part of a curve.
  struct Curve {
    Halfedge_handle halfedge;  ///< the curve, directed from its end of smaller (x, y)
    double begin = 0, end = 0; ///< the kept part, arc lengths from `halfedge.source()`
    double full_length = 0;    ///< `halfedge.length()`
    double et_begin = 0, et_end = 0; ///< the erosion thickness at both ends (may be infinite)
    bool cut_at_begin() const { return begin > 0; }
    bool cut_at_end() const { return end < full_length; }
    double length() const { return end - begin; }
    Vertex_handle source() const { return halfedge.source(); } ///< `halfedge.source()`
    Vertex_handle target() const { return halfedge.target(); } ///< `halfedge.target()`
    std::pair<double, double> begin_point() const
    {
      return cut_at_begin() ? halfedge.point_at(begin) : Medial_axis::to_xy(halfedge.source_point());
    }
    std::pair<double, double> end_point() const
    {
      return cut_at_end() ? halfedge.point_at(end) : Medial_axis::to_xy(halfedge.target_point());
    }
  };

  const Medial_axis& medial_axis() const { return ma_; }
  /// The kept parts of curves (a random-access range).
  const Progressive_medial_axes::internal::Written_once_array<Curve>& curves() const { return curves_; }
  /// Whether a vertex of the axis is kept.
  bool is_kept(const Vertex_handle& v) const { return v.id_number() < kept_.size() && kept_[v.id_number()]; }
  /// The kept vertices (a random-access range).
  const Progressive_medial_axes::internal::Written_once_array<Vertex_handle>& vertices() const { return vertices_; }
  /// The points that stand alone: for each component of the axis without
  /// cycle whose last burning point falls below the thresholds, that point
  /// (the pruned axis of that component).
  const std::vector<std::pair<double, double> >& isolated_points() const { return points_; }
  /// Number of curves of the axis that are dropped or cut.
  std::size_t number_of_pruned_curves() const { return pruned_; }

  /// \cond
  Pruned_medial_axis_2(const Medial_axis& ma) : ma_(ma) {}
  Progressive_medial_axes::internal::Written_once_array<Curve> curves_;
  Progressive_medial_axes::internal::Written_once_array<Vertex_handle> vertices_;
  std::vector<char> kept_;   // by id number
  std::vector<std::pair<double, double> > points_;
  std::size_t pruned_ = 0;
  // for the centerline, a graph: by kept curve, the nodes at its ends (those
  // of the significance's graph, and a node of its own at each cut end) and
  // its length; and the number of nodes
  struct Link { int a, b; double length; };
  typedef boost::container::vector<Link> Link_vector;
  Link_vector links_;
  int number_of_nodes_ = 0;
  /// \endcond

private:
  Medial_axis ma_;
};

/*!
\ingroup PkgProgressiveMedialAxis2Ref

Prunes a medial axis by its erosion thickness: keeps the points `x` with
\f$ET(x) \geq\f$ `et` and \f$ET(x) \geq\f$ `ratio` \f$\cdot EDF(x)\f$ (a
threshold of 0 or less is not applied) that are connected to the points
that never burn or that burn last.

`et` is in the units of the input, "drop what wiggles less than `et`", for
example the positional accuracy of a data set; `ratio`, between 0 and 1, is
free of scale.  The pruned axis is connected in each component of the axis
and keeps every cycle, so it has the topology of the shape.  A curve that
crosses a threshold is cut there (the cut point is found in double
precision by bisection on the curve, where the condition is concave); the
rest of the curve stays exact.  Linear in the size of the axis, plus a
bisection per cut curve.
*/
template <class K>
Pruned_medial_axis_2<K> prune_medial_axis_2(const Medial_axis_significance_2<K>& sig, double et, double ratio = 0)
{
  typedef Medial_axis_significance_2<K> Sig;
  typedef typename Sig::Node Node;
  typedef typename Sig::Arc Arc;
  typedef typename Pruned_medial_axis_2<K>::Curve Curve;
  const double inf = Sig::infinity();
  const auto& nodes = sig.nodes();
  const auto& arcs = sig.arcs();
  typedef typename Pruned_medial_axis_2<K>::Link Link;
  Pruned_medial_axis_2<K> out(sig.medial_axis());
  out.number_of_nodes_ = int(nodes.size());
  // the curves that the fire reaches, before those it never reaches
  std::vector<Curve> fired;
  std::vector<Link> fired_links;

  // the condition at a point of arc a, at arc length x from its node u, in
  // the form f >= 0 (f is concave along the curve)
  auto margin = [&](double time, double radius) {
    if(time == inf) return inf;
    const double thickness = time - radius;
    double m = inf;
    if(et > 0) m = (std::min)(m, thickness - et);
    if(ratio > 0) m = (std::min)(m, thickness - ratio * time);
    return m;
  };
  auto margin_at_vertex = [&](int v) { return margin(nodes[v].time, nodes[v].radius); };
  auto et_of = [&](double time, double radius) { return time == inf ? inf : (std::max)(0.0, time - radius); };
  typedef Progressive_medial_axes::internal::Curve Geometry;
  typedef Progressive_medial_axes::internal::Curve_parameterization Parameterization;
  typedef std::pair<double, double> Point;
  // margin at parameter p of curve c of arc a, whose first generator is
  // the segment g0 g1 (g0 == g1 for a point), p from the burning end (u if
  // from_u), 0..1
  auto margin_at_parameter = [&](const Arc& a, const Parameterization& c, const Point& g0, const Point& g1, double p,
                                 double start_time, bool from_u) {
    const double q = from_u ? p : 1 - p;   // parameter from u
    const double s = c.length_at(q);
    const double x = from_u ? s : a.length - s;  // arc length from the burning end
    const double r = Progressive_medial_axes::internal::distance_to_segment(c.point_at(q), g0, g1);
    return margin(start_time + x, r);
  };
  // the arc length from u of the first point where the condition holds,
  // walking from the burning end (u if from_u) towards the other end, where
  // it holds; the condition fails at the burning end
  auto cut = [&](const Arc& a, double start_time, bool from_u, double p_end) {
    const auto h = sig.halfedge(a);
    const Geometry w = h.geometry();
    const Parameterization c(w);
    // (the distance to the generator on the left of h: Halfedge_handle::distance_to_point())
    const Point g0 = Sig::Medial_axis::to_xy(h.face().source()), g1 = Sig::Medial_axis::to_xy(h.face().target());
    // parameters from the burning end: the condition fails at lo, holds at
    // hi; the Illinois variant of the false position method (the margin is
    // smooth and concave), with bisection steps if it stalls
    double lo = 0, hi = p_end;
    double flo = margin_at_parameter(a, c, g0, g1, lo, start_time, from_u);
    double fhi = margin_at_parameter(a, c, g0, g1, hi, start_time, from_u);
    if(!(flo < 0)) hi = lo;
    int side = 0;
    for(int i = 0; i < 100 && hi - lo > 1e-13 * p_end; ++i) {
      double mid = (flo < 0 && fhi >= 0 && fhi - flo > 0) ? lo + (hi - lo) * (-flo) / (fhi - flo) : 0.5 * (lo + hi);
      if(!(mid > lo && mid < hi) || i % 8 == 7) mid = 0.5 * (lo + hi);
      const double f = margin_at_parameter(a, c, g0, g1, mid, start_time, from_u);
      if(f >= 0) {
        hi = mid;
        fhi = f;
        if(side == 1) flo *= 0.5;
        side = 1;
      } else {
        lo = mid;
        flo = f;
        if(side == -1) fhi *= 0.5;
        side = -1;
      }
      if(f == 0) break;
    }
    const double q = from_u ? hi : 1 - hi;
    return c.length_at(q);
  };

  // Which curves the fire reaches are kept, and how, in one pass over the
  // nodes, in the reverse of the order of fire (not of their times: a curve
  // can be shorter than the precision of a time).  Nodes that never burn are
  // kept; a node is kept if the whole curve it sends its front into is, and
  // the node at its other end.  The pass reads the nodes only: the curves it
  // keeps, and their cuts, are made after it, in parallel.
  std::vector<char> kept(nodes.size(), 0);
  for(int v = 0; v < int(nodes.size()); ++v)
    if(nodes[v].time == inf) kept[v] = 1;
  std::vector<char> arc_done(arcs.size(), 0);
  // a kept curve that the fire reaches: whole, cut at the end where its
  // front enters (the node's front, from_u or not), or where the fronts
  // from both ends meet inside it, cut at either end or not (the ends kept)
  struct Kept_arc { int arc; int node; bool meets, from_u, keep_u, keep_w; double meet; };
  std::vector<Kept_arc> to_make;
  const std::vector<int>& order = sig.order_of_fire();
  for(auto it = order.rbegin(); it != order.rend(); ++it) {
    const int v = *it;
    const Node& n = nodes[v];
    if(n.meets) {
      // fronts meet inside this curve: the meeting point burns last
      if(arc_done[n.out]) continue;   // done from its other end
      arc_done[n.out] = 1;
      const Arc& a = arcs[n.out];
      const double m = (std::max)(0.0, (std::min)(a.length, 0.5 * (a.length + a.start[1] - a.start[0])));
      const double rm = sig.halfedge(a).radius_at(m);
      if(margin(Sig::time_along(a, m), rm) < 0) {
        out.points_.push_back(sig.halfedge(a).point_at(m));
        continue;
      }
      const bool keep_u = margin_at_vertex(a.u) >= 0, keep_w = margin_at_vertex(a.w) >= 0;
      if(keep_u) kept[a.u] = 1;
      if(keep_w) kept[a.w] = 1;
      to_make.push_back(Kept_arc{n.out, v, true, false, keep_u, keep_w, m});
      continue;
    }
    // the front runs to the far end (from the node's own record: the curve
    // is read only for what is kept)
    if(!kept[n.far]) continue;
    // the condition at the far end, reached by this curve's front
    if(margin(n.time + n.out_length, nodes[n.far].radius) < 0) continue;
    const bool keep = margin_at_vertex(v) >= 0;
    if(keep) kept[v] = 1;
    to_make.push_back(Kept_arc{n.out, v, false, arcs[n.out].u == v, keep, keep, 0});
  }
  // the curves, and their cuts (a bisection each), in parallel where the
  // numbers are doubles
  std::vector<Curve> made(to_make.size());
  Progressive_medial_axes::internal::parallel_blocks(to_make.size(), [&](std::size_t b, std::size_t e) {
    for(std::size_t i = b; i < e; ++i) {
      const Kept_arc& x = to_make[i];
      const Arc& a = arcs[std::size_t(x.arc)];
      double from = 0, to = a.length;
      if(x.meets) {
        const double pmeet = sig.halfedge(a).geometry().parameter_at_length(x.meet);
        if(!x.keep_u) from = cut(a, a.start[0], true, pmeet);
        if(!x.keep_w) to = cut(a, a.start[1], false, 1 - pmeet);
      } else if(!x.keep_u) {
        const double c = cut(a, nodes[std::size_t(x.node)].time, x.from_u, 1);
        if(x.from_u) from = c;
        else to = c;
      }
      Curve& c = made[i];
      c.halfedge = sig.halfedge(a);
      c.full_length = a.length;
      c.begin = (std::max)(0.0, from);
      c.end = (std::min)(a.length, to);
      c.et_begin = c.begin > 0 ? et_of(Sig::time_along(a, c.begin), c.halfedge.radius_at(c.begin))
                               : et_of(nodes[a.u].time, nodes[a.u].radius);
      c.et_end = c.end < a.length ? et_of(Sig::time_along(a, c.end), c.halfedge.radius_at(c.end))
                                  : et_of(nodes[a.w].time, nodes[a.w].radius);
    }
  }, std::is_floating_point<typename Sig::Medial_axis::FT>::value);
  std::size_t whole = 0;   // kept curves that are not cut
  for(std::size_t i = 0; i < made.size(); ++i) {
    const Curve& c = made[i];
    const Arc& a = arcs[std::size_t(to_make[i].arc)];
    if(c.end > c.begin || (c.begin == 0 && c.end == a.length)) {
      fired.push_back(c);
      whole += std::size_t(!c.cut_at_begin() && !c.cut_at_end());
      const int u = c.cut_at_begin() ? out.number_of_nodes_++ : a.u;
      const int w = c.cut_at_end() ? out.number_of_nodes_++ : a.w;
      fired_links.push_back({u, w, c.length()});
    }
  }
  // The curves that no front enters, whole.  Their ends never burn (every
  // curve at a node that burns carries a front), so their records are
  // written without reading the nodes.  They are most of the axis of a
  // shape with many holes: counted, then written in parallel parts, in the
  // order of the arcs.
  const std::size_t before = fired.size();
  Progressive_medial_axes::internal::parallel_compact(
    arcs.size(), before, [&](std::size_t i) { return arcs[i].start[0] == inf && arcs[i].start[1] == inf; },
    [&](std::size_t total) {
      out.curves_ = Progressive_medial_axes::internal::Written_once_array<Curve>(total);
      out.links_.resize(total, boost::container::default_init);
      for(std::size_t k = 0; k < before; ++k) {
        out.curves_.write(k, fired[k]);
        out.links_[k] = fired_links[k];
      }
    },
    [&](std::size_t i, std::size_t k) {
      const Arc& a = arcs[i];
      Curve c;
      c.halfedge = sig.halfedge(a);
      c.begin = 0;
      c.end = c.full_length = a.length;
      c.et_begin = c.et_end = inf;
      out.curves_.write(k, c);
      out.links_[k] = {a.u, a.w, a.length};
    });
  whole += out.curves_.size() - before;
  // the kept vertices, in the order of the nodes, the same way
  out.kept_.assign(sig.medial_axis().vertex_id_bound(), 0);
  Progressive_medial_axes::internal::parallel_compact(
    nodes.size(), 0, [&](std::size_t v) { return kept[v] != 0; },
    [&](std::size_t total) { out.vertices_ = Progressive_medial_axes::internal::Written_once_array<typename Sig::Vertex_handle>(total); },
    [&](std::size_t v, std::size_t k) {
      out.vertices_.write(k, sig.vertex(int(v)));
      out.kept_[std::size_t(nodes[v].vertex)] = 1;   // (distinct nodes have distinct vertices)
    });
  out.pruned_ = arcs.size() - whole;
  return out;
}

} // namespace CGAL

#endif // CGAL_PROGRESSIVE_MEDIAL_AXIS_2_MEDIAL_AXIS_SIGNIFICANCE_2_H
