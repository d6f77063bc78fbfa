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

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <queue>
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

Algorithm (linear in the size of the axis, after a priority queue on the
arrival times, O(n log n)): every end catches fire at time 0; popping the
earliest arrival of a front at a vertex counts one more burnt curve there;
with all but one counted, the vertex catches fire at that time and sends
its front into its remaining curve, unless a front already runs the other
way in it (the fronts then meet inside it).  Invariants: a vertex catches
fire at most once, at a time no earlier than any front counted there; every
curve carries at most one front from each end; a curve with fronts from
both ends holds the meeting point, at arc length \f$(L + t_w - t_u)/2\f$
from the end \f$u\f$ that caught fire at \f$t_u\f$.  In a component of the
axis without cycle, exactly one point (a vertex or such a meeting point)
burns last.

Along a curve the radius is a convex function of arc length (linear on the
bisector of two segments, \f$\sqrt{d^2 + s^2}\f$ on that of two points, the
height above the directrix on a parabola), so \f$ET\f$ is concave along a
curve: the set where it is above a threshold is one interval.

Lengths and times are in double precision (they are sums of arc lengths of
parabolas, which are not algebraic); the axis itself stays exact.

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
  explicit Medial_axis_significance_2(const Medial_axis& ma) : ma_(ma) { build(); burn(); }

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

  /// \cond
  // The graph of the axis, for pruning and centerlines: vertices and curves
  // by index.
  struct Node {
    Vertex_handle vertex;
    double radius = 0;
    double time = std::numeric_limits<double>::infinity();
    int first = 0, degree = 0;   // incident curves: incidence_[first, first + degree)
    int arrived = 0;             // curves burnt up to this vertex
    int out = -1;                // the curve the fire goes on into
    bool ignited = false;
    std::size_t rank = 0;        // the order in which the vertices catch fire
  };
  struct Arc {
    Halfedge_handle halfedge;  // oriented from node u to node w
    int u = -1, w = -1;
    double length = 0;
    // the time a front enters the curve from u (start[0]) and from w
    // (start[1]), infinite if none
    double start[2] = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
    bool arrived[2] = {false, false};   // a front burnt the whole curve up to u, to w
  };
  const std::vector<Node>& nodes() const { return vertices_; }
  const std::vector<Arc>& arcs() const { return arcs_; }
  // the curves at node v
  const int* arcs_begin(int v) const { return incidence_.data() + vertices_[v].first; }
  const int* arcs_end(int v) const { return incidence_.data() + vertices_[v].first + vertices_[v].degree; }
  int vertex_index(const Vertex_handle& v) const { return checked(vertex_map_.at(v.id_number())); }
  int edge_index(const Halfedge_handle& h) const { return checked(edge_map_.at(edge_key(h))); }
  static int checked(int i)
  {
    if(i < 0) throw std::invalid_argument("Medial_axis_significance_2: not a vertex or a medial curve of the axis");
    return i;
  }
  bool same_direction(const Halfedge_handle& h) const { return arcs_[edge_index(h)].halfedge == h; }
  static double time_along(const Arc& a, double from_u)
  {
    return (std::min)(a.start[0] + from_u, a.start[1] + (a.length - from_u));
  }
  /// \endcond

private:
  static std::size_t edge_key(const Halfedge_handle& h)
  {
    return (std::min)(h.id_number(), h.opposite().id_number());
  }

  // Arrays indexed by id numbers rather than hash maps: the ids are dense.
  void build()
  {
    vertex_map_.assign(ma_.vertex_id_bound(), -1);
    edge_map_.assign(ma_.halfedge_id_bound(), -1);
    // the vertices of the axis are the ends of its curves: one pass over the
    // curves finds them
    auto node = [&](const Vertex_handle& v) {
      int& i = vertex_map_[v.id_number()];
      if(i < 0) {
        i = int(vertices_.size());
        Node n;
        n.vertex = v;
        n.radius = CGAL::to_double(v.radius());
        vertices_.push_back(n);
      }
      return i;
    };
    for(const Halfedge_handle& h : ma_.edges()) {
      Arc a;
      a.halfedge = h;
      a.u = node(h.source());
      a.w = node(h.target());
      a.length = h.length();
      edge_map_[edge_key(h)] = int(arcs_.size());
      ++vertices_[a.u].degree;
      ++vertices_[a.w].degree;
      arcs_.push_back(a);
    }
    int first = 0;
    for(Node& n : vertices_) {
      n.first = first;
      first += n.degree;
      n.degree = 0;
    }
    incidence_.resize(std::size_t(first));
    for(int i = 0; i < int(arcs_.size()); ++i) {
      Node& u = vertices_[arcs_[i].u];
      incidence_[std::size_t(u.first + u.degree++)] = i;
      Node& w = vertices_[arcs_[i].w];
      incidence_[std::size_t(w.first + w.degree++)] = i;
    }
  }

  // the end of arc a at node v: 0 for u, 1 for w
  int end_of(const Arc& a, int v) const { return a.u == v ? 0 : 1; }

  void burn()
  {
    struct Event {
      double time;
      int arc, end;   // the front arrives at that end of that curve
      bool operator>(const Event& o) const { return time > o.time; }
    };
    std::vector<Event> heap;
    heap.reserve(arcs_.size());
    std::priority_queue<Event, std::vector<Event>, std::greater<Event> > queue(std::greater<Event>(), std::move(heap));
    std::size_t rank = 0;
    auto ignite = [&](int v, double t) {
      Node& n = vertices_[v];
      n.ignited = true;
      n.rank = rank++;
      n.time = t;
      last_time_ = (std::max)(last_time_, t);
      for(const int* ai = arcs_begin(v); ai != arcs_end(v); ++ai) {
        Arc& a = arcs_[*ai];
        const int end = end_of(a, v);
        if(a.arrived[end]) continue;
        // the remaining curve: the front enters it here
        n.out = *ai;
        a.start[end] = t;
        if(a.start[1 - end] == infinity()) queue.push(Event{t + a.length, *ai, 1 - end});
        else last_time_ = (std::max)(last_time_, 0.5 * (a.start[0] + a.start[1] + a.length));
        break;
      }
    };
    for(int v = 0; v < int(vertices_.size()); ++v)
      if(vertices_[v].degree == 1) ignite(v, 0.0);
    while(!queue.empty()) {
      const Event e = queue.top();
      queue.pop();
      Arc& a = arcs_[e.arc];
      const int v = e.end == 0 ? a.u : a.w;
      if(a.start[e.end] != infinity()) continue;   // the fronts met inside the curve
      a.arrived[e.end] = true;
      Node& n = vertices_[v];
      if(a.u == a.w) a.arrived[1 - e.end] = true;   // a loop reaches its vertex at both ends
      ++n.arrived;
      if(!n.ignited && n.arrived + 1 >= n.degree) ignite(v, e.time);
    }
  }

  Medial_axis ma_;
  std::vector<Node> vertices_;
  std::vector<Arc> arcs_;
  std::vector<int> incidence_;
  std::vector<int> vertex_map_, edge_map_;   // by id number
  double last_time_ = 0;
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
    Halfedge_handle halfedge;  ///< the curve, with its direction
    Vertex_handle source, target; ///< `halfedge.source()` and `halfedge.target()`
    double begin = 0, end = 0; ///< the kept part, arc lengths from `halfedge.source()`
    double full_length = 0;    ///< `halfedge.length()`
    double et_begin = 0, et_end = 0; ///< the erosion thickness at both ends (may be infinite)
    bool cut_at_begin() const { return begin > 0; }
    bool cut_at_end() const { return end < full_length; }
    double length() const { return end - begin; }
    std::pair<double, double> begin_point() const
    {
      return cut_at_begin() ? halfedge.point_at(begin) : Medial_axis::to_xy(source.point());
    }
    std::pair<double, double> end_point() const
    {
      return cut_at_end() ? halfedge.point_at(end) : Medial_axis::to_xy(target.point());
    }
  };

  const Medial_axis& medial_axis() const { return ma_; }
  /// The kept parts of curves.
  const std::vector<Curve>& curves() const { return curves_; }
  /// Whether a vertex of the axis is kept.
  bool is_kept(const Vertex_handle& v) const { return v.id_number() < kept_.size() && kept_[v.id_number()]; }
  /// The kept vertices.
  const std::vector<Vertex_handle>& vertices() const { return vertices_; }
  /// The points that stand alone: for each component of the axis without
  /// cycle whose last burning point falls below the thresholds, that point
  /// (the pruned axis of that component).
  const std::vector<std::pair<double, double> >& isolated_points() const { return points_; }
  /// Number of curves of the axis that are dropped or cut.
  std::size_t number_of_pruned_curves() const { return pruned_; }

  /// \cond
  Pruned_medial_axis_2(const Medial_axis& ma) : ma_(ma) {}
  std::vector<Curve> curves_;
  std::vector<Vertex_handle> vertices_;
  std::vector<char> kept_;   // by id number
  std::vector<std::pair<double, double> > points_;
  std::size_t pruned_ = 0;
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
  const std::vector<Node>& nodes = sig.nodes();
  const std::vector<Arc>& arcs = sig.arcs();
  Pruned_medial_axis_2<K> out(sig.medial_axis());

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
  // margin at parameter p of curve c of arc a, p from the burning end (u if
  // from_u), 0..1
  auto margin_at_parameter = [&](const Arc& a, const Geometry& c, double p, double start_time, bool from_u) {
    const double q = from_u ? p : 1 - p;   // parameter from u
    const double s = c.length_at_parameter(q);
    const double x = from_u ? s : a.length - s;  // arc length from the burning end
    const double r = a.halfedge.distance_to_point(c.point_at_parameter(q));
    return margin(start_time + x, r);
  };
  // the arc length from u of the first point where the condition holds,
  // walking from the burning end (u if from_u) towards the other end, where
  // it holds; the condition fails at the burning end
  auto cut = [&](const Arc& a, double start_time, bool from_u, double p_end) {
    const Geometry w = a.halfedge.geometry();
    // parameters from the burning end: the condition fails at lo, holds at
    // hi; the Illinois variant of the false position method (the margin is
    // smooth and concave), with bisection steps if it stalls
    double lo = 0, hi = p_end;
    double flo = margin_at_parameter(a, w, lo, start_time, from_u), fhi = margin_at_parameter(a, w, hi, start_time, from_u);
    if(!(flo < 0)) hi = lo;
    int side = 0;
    for(int i = 0; i < 100 && hi - lo > 1e-13 * p_end; ++i) {
      double mid = (flo < 0 && fhi >= 0 && fhi - flo > 0) ? lo + (hi - lo) * (-flo) / (fhi - flo) : 0.5 * (lo + hi);
      if(!(mid > lo && mid < hi) || i % 8 == 7) mid = 0.5 * (lo + hi);
      const double f = margin_at_parameter(a, w, mid, start_time, from_u);
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
    return w.length_at_parameter(q);
  };

  std::vector<char> kept(nodes.size(), 0);
  // nodes that never burn are kept; the others in the reverse of the order
  // in which they caught fire (not of their times: a curve can be shorter
  // than the precision of a time): a node is kept if the whole curve it
  // sends its front into is, and the node at its other end
  std::vector<int> order(nodes.size(), -1);   // by rank: the ranks are 0, 1, ... in the order of fire
  std::size_t ignited = 0;
  for(int v = 0; v < int(nodes.size()); ++v) {
    if(!nodes[v].ignited) kept[v] = 1;
    else {
      order[nodes[v].rank] = v;
      ++ignited;
    }
  }
  order.resize(ignited);
  std::reverse(order.begin(), order.end());
  std::vector<char> arc_done(arcs.size(), 0);
  auto add_curve = [&](const Arc& a, double b, double e) {
    Curve c;
    c.halfedge = a.halfedge;
    c.source = nodes[a.u].vertex;
    c.target = nodes[a.w].vertex;
    c.full_length = a.length;
    c.begin = (std::max)(0.0, b);
    c.end = (std::min)(a.length, e);
    c.et_begin = c.begin > 0 ? et_of(Sig::time_along(a, c.begin), a.halfedge.radius_at(c.begin))
                             : et_of(nodes[a.u].time, nodes[a.u].radius);
    c.et_end = c.end < a.length ? et_of(Sig::time_along(a, c.end), a.halfedge.radius_at(c.end))
                                : et_of(nodes[a.w].time, nodes[a.w].radius);
    if(c.end > c.begin || (c.begin == 0 && c.end == a.length)) out.curves_.push_back(c);
  };
  for(int v : order) {
    const Node& n = nodes[v];
    if(n.out < 0) {
      // fronts from every curve met here: the last burning point of its tree
      if(margin_at_vertex(v) >= 0) kept[v] = 1;
      else out.points_.push_back(Medial_axis_2<K>::to_xy(n.vertex.point()));
      continue;
    }
    const Arc& a = arcs[n.out];
    const bool from_u = (a.u == v);
    const int other = from_u ? a.w : a.u;
    const double start = a.start[from_u ? 0 : 1];
    if(a.start[from_u ? 1 : 0] != inf) {
      // fronts meet inside this curve: the meeting point burns last
      if(arc_done[n.out]) continue;   // done from its other end
      arc_done[n.out] = 1;
      const double m = (std::max)(0.0, (std::min)(a.length, 0.5 * (a.length + a.start[1] - a.start[0])));
      const double rm = a.halfedge.radius_at(m);
      if(margin(Sig::time_along(a, m), rm) < 0) {
        out.points_.push_back(a.halfedge.point_at(m));
        continue;
      }
      const double pmeet = a.halfedge.geometry().parameter_at_length(m);
      const bool keep_u = margin_at_vertex(a.u) >= 0, keep_w = margin_at_vertex(a.w) >= 0;
      const double b = keep_u ? 0 : cut(a, a.start[0], true, pmeet);
      const double e = keep_w ? a.length : cut(a, a.start[1], false, 1 - pmeet);
      if(keep_u) kept[a.u] = 1;
      if(keep_w) kept[a.w] = 1;
      add_curve(a, b, e);
      continue;
    }
    arc_done[n.out] = 1;
    if(!kept[other]) continue;
    // the condition at the far end, reached by this curve's front
    if(margin_at_parameter(a, a.halfedge.geometry(), 1, start, from_u) < 0) continue;
    if(margin_at_vertex(v) >= 0) {
      kept[v] = 1;
      add_curve(a, 0, a.length);
    } else {
      const double c = cut(a, start, from_u, 1);
      if(from_u) add_curve(a, c, a.length);
      else add_curve(a, 0, c);
    }
  }
  // curves between nodes that never burn
  for(std::size_t i = 0; i < arcs.size(); ++i)
    if(!arc_done[i] && arcs[i].start[0] == inf && arcs[i].start[1] == inf) add_curve(arcs[i], 0, arcs[i].length);
  out.kept_.assign(sig.medial_axis().vertex_id_bound(), 0);
  for(int v = 0; v < int(nodes.size()); ++v)
    if(kept[v]) {
      out.vertices_.push_back(nodes[v].vertex);
      out.kept_[nodes[v].vertex.id_number()] = 1;
    }
  std::size_t whole = 0;
  for(const Curve& c : out.curves_)
    if(!c.cut_at_begin() && !c.cut_at_end()) ++whole;
  out.pruned_ = arcs.size() - whole;
  return out;
}

} // namespace CGAL

#endif // CGAL_PROGRESSIVE_MEDIAL_AXIS_2_MEDIAL_AXIS_SIGNIFICANCE_2_H
