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
// The topology-oriented merge of two medial axes along a shared segment
// (Liu et al. 2016, Algorithms 1-5).
//
// Picture the separator C = PQ as a slit whose free end, the tip v_C,
// retracts from P to Q.  The cell of the tip is bounded by the cells listed
// in `L` (the mating list Phi(v_C)), in counter-clockwise order around the
// tip, from the cell C+ of C on one side to the cell C- on the other:
//
//     L = [C+, g_1, ..., g_m, C-]
//
// Between two consecutive generators g_i, g_i+1 a new medial curve is being
// traced by the corner of the tip's cell; it is an "open" edge of the
// half-edge structure whose end vertex is not known yet.  The events are
//   - switch points: the tip passes the foot of a vertex of the cell of C+
//     (or C-); the generator beyond it enters L next to C+ (or C-);
//   - vanishing points: the tip reaches the disk tangent to g_i-1, g_i,
//     g_i+1; g_i leaves L, a branch point is created.
// Switch points are known, in order, from the cells of C+ and C-; vanishing
// points live in a priority queue, recomputed for the neighbours after each
// event.  Every decision is topological except the order of events, which is
// asked of the traits.  The cost is proportional to the number of cells that
// touch the separator.
//
// Holes.  When both sides of the separator belong to one shape (the merge
// that closes a ring around a hole), the shape swept by the retracting tip is
// not simply connected, and the paper's lemmas, which assume it is, do not
// apply as such: a generator can meet the tip's cell twice, on both sides of
// a hole.  The merge stays correct because everything it does is local to the
// union of the two cells of the separator, which is always a topological disk
// around the separator.  The invariant it keeps (asserted in debug builds):
// two consecutive generators of L are distinct, and no vanishing candidate is
// formed from a triple whose outer two generators coincide (the disk would
// have to touch one generator at two points).  The paper removes holes with an
// "augmented domain" (a two-sheet cover of a maximal disk); this design does
// without it, and is tested against the oracle on shapes with 1 to 10^3 holes.
//
// Zero-length edges.  When four or more generators meet at one point, events
// happen at equal times and the merge leaves edges of length zero between
// vertices that are one point.  An open edge is traced by a corner of the
// tip's cell, which moves whenever the tip does (it stays equidistant from
// the tip), so an edge has length zero exactly when it is closed at the time
// it was opened: the merge records that, with the exact comparison of the
// two times, and the view contracts such edges (a degree-4 point is one
// vertex).  This holds while the tip moves strictly between P and Q.  At
// P, when P becomes reflex, the tip and the new point generator of P are one
// point and do not fix the corners; at Q, the tip's cell shrinks to the
// corner Q (convex) or becomes the cell of Q (reflex), and the events at or
// beyond that time are the last of that collapse.  There, an edge opened and
// closed at one time has length zero only when its two vertices are the same
// disk, which the traits decide exactly.
//
// Orientation conventions: every face cycle is counter-clockwise (face on
// the left).  An open edge between consecutive nodes A, B of L is stored as
// the half-edge of A, from its start vertex to its (future) end vertex.

#ifndef CGAL_PROGRESSIVE_MEDIAL_AXIS_2_INTERNAL_MERGE_H
#define CGAL_PROGRESSIVE_MEDIAL_AXIS_2_INTERNAL_MERGE_H

#include <CGAL/Progressive_medial_axis_2/Merge_statistics.h>
#include <CGAL/Progressive_medial_axis_2/internal/Halfedge_structure.h>
#include <CGAL/Progressive_medial_axis_2/internal/Medial_constructions.h>
#include <CGAL/assertions.h>
#include <CGAL/enum.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <type_traits>
#include <utility>
#include <vector>

#ifdef CGAL_PMA2_TRACE
#include <iostream>
#define CGAL_PMA2_TRACE_MSG(x) (std::cerr << x << "\n")
#else
#define CGAL_PMA2_TRACE_MSG(x) ((void)0)
#endif

namespace CGAL {
namespace Progressive_medial_axes {

namespace internal {

/// Thrown by a merge in strict mode at its first anomaly: an event that no
/// exact computation meets (a generator that should have left the list, a
/// switch that does not match the list).  Only inexact decisions lead there.
struct Merge_anomaly {};

/// A merge visitor that does nothing; a visitor has on_switch() and
/// on_vanish(), called at every switch and vanishing point of a merge.
struct Null_merge_visitor {
  void on_switch() {}
  void on_vanish() {}
};

/// The traits' hint of a disk's centre (`Traits::Disk_hint`, optional in
/// the concept), or an empty type where they have none.
template <class Traits, class = void>
struct Disk_hint_of {
  static constexpr bool exists = false;
  struct type {};
};
template <class Traits>
struct Disk_hint_of<Traits, std::void_t<typename Traits::Disk_hint> > {
  static constexpr bool exists = true;
  typedef typename Traits::Disk_hint type;
};

template <class Traits>
class Medial_merge
{
public:
  typedef typename Traits::Point_2 Point_2;
  typedef typename Traits::FT FT;
  typedef typename Traits::Site_2 Site_2;
  typedef typename Traits::Event_time_2 Time;
  typedef Halfedge_structure<Point_2, FT> Hds;

  Medial_merge(Hds& hds, const std::vector<Point_2>& points, const Traits& traits)
    : hds_(hds), points_(points), traits_(traits),
      compare_(traits.compare_event_time_2_object())
  {}

  /// The vertices of the two cells of the last merge's separator that are
  /// still alive: their incident cells changed.
  template <class F>
  void for_each_switch_vertex(const F& f) const
  {
    for(int w : switch_vertex_plus_) if(chds().vertex(w).alive) f(w);
    for(int w : switch_vertex_minus_) if(chds().vertex(w).alive) f(w);
  }

  /// In strict mode a merge throws Merge_anomaly at its first anomaly,
  /// instead of forcing events to keep the topology valid.
  void set_strict(bool strict) { strict_ = strict; }

  /// Site of a face.
  Site_2 site(int f) const
  {
    const Hds_face& x = chds().face(f);
    return x.is_point ? Site_2::point(points_[x.p0])
                      : Site_2::segment(points_[x.p0], points_[x.p1]);
  }

  /// Merges the two cells of a separator.  `hp` is the boundary half-edge,
  /// from P to Q, of the separator's cell C+ on one side; `hm` is the
  /// boundary half-edge, from Q to P, of its cell C- on the other side.  The
  /// two cells and the separator disappear; the medial axis of the union is
  /// left in the structure.
  Merge_statistics merge(int hp, int hm)
  {
    Null_merge_visitor v;
    return merge(hp, hm, v);
  }

  template <class Visitor>
  Merge_statistics merge(int hp, int hm, Visitor& visitor)
  {
    stats_ = Merge_statistics();
    Cp_ = hds_.face_of(hp);
    Cm_ = hds_.face_of(hm);
    vP_ = hds_.source(hp);
    vQ_ = hds_.target(hp);
    // When both sides of the separator belong to one shape (the merge that
    // closes a ring around a hole), an endpoint can be reached through two
    // corners of the boundary, stored as two vertices: they become one.
    unify_corners(hds_.target(hm), vP_);
    unify_corners(hds_.source(hm), vQ_);
    CGAL_precondition(hds_.source(hm) == vQ_ && hds_.target(hm) == vP_);
    P_ = chds().vertex(vP_).input_point();
    Q_ = chds().vertex(vQ_).input_point();
    line_ = Site_2::segment(points_[P_], points_[Q_]);
    site_p_ = site(Cp_);
    site_m_ = site(Cm_);

    plus_.clear();
    for(int h = hds_.next(hp); h != hp; h = hds_.next(h)) plus_.push_back(h);
    minus_.clear();
    for(int h = hds_.next(hm); h != hm; h = hds_.next(h)) minus_.push_back(h);
    CGAL_assertion(plus_.size() >= 2 && minus_.size() >= 2);

    // The corners of the merged shape at P and Q.  A corner of 360 degrees
    // (the boundary comes back along the same segment: the merge along one
    // edge of a chain, before the next one is merged) is reflex at Q; at P
    // it is the tip of the slit that this merge closes (see initialize_slit()).
    const int o_plus = Hds::twin(hp), o_minus = Hds::twin(hm);
    const int a = input_of(hds_.target(hds_.next(o_plus)));
    const int b = input_of(hds_.source(hds_.prev(o_minus)));
    const int c = input_of(hds_.target(hds_.next(o_minus)));
    const int e = input_of(hds_.source(hds_.prev(o_plus)));
    typename Traits::Orientation_2 orientation = traits_.orientation_2_object();
    const bool slit_P = hds_.next(o_plus) == o_minus;
    const Orientation turn_P = slit_P ? RIGHT_TURN : orientation(points_[a], points_[P_], points_[b]);
    const Orientation turn_Q = c == e ? RIGHT_TURN : orientation(points_[c], points_[Q_], points_[e]);

    reserve_lists();
    nodes_.clear();
    events_.clear();
    heap_.clear();
    live_events_ = 0;
    CGAL_PMA2_TRACE_MSG("merge P=" << P_ << " Q=" << Q_ << " turns " << int(turn_P) << " " << int(turn_Q));
    start_ = traits_.compute_start_time_2_object()(line_);
    end_ = traits_.compute_end_time_2_object()(line_);
    times_.clear();
    times_.push_back(START_TIME);
    nodes_.push_back(Node{Cp_, NO_INDEX, 1, NO_INDEX, NO_INDEX, 0});
    nodes_.push_back(Node{Cm_, 0, NO_INDEX, NO_INDEX, NO_INDEX, 0});

    if(slit_P)
      initialize_slit();
    else
      initialize(turn_P);
    collect_switches();
    run_events(turn_Q == RIGHT_TURN, visitor);
    if(turn_Q == RIGHT_TURN)
      terminate_reflex();
    else
      terminate_convex();

    // The boundary: splice the outer cycles at P and Q.
    const int before_P = hds_.prev(o_minus), after_P = hds_.next(o_plus);
    const int before_Q = hds_.prev(o_plus), after_Q = hds_.next(o_minus);
    hds_.link(before_P, after_P);
    hds_.link(before_Q, after_Q);

    // Delete the cells of C+ and C-.
    for(int h : plus_) hds_.delete_edge(h);
    for(int h : minus_) hds_.delete_edge(h);
    hds_.delete_edge(hp);
    hds_.delete_edge(hm);
    hds_.delete_face(Cp_);
    hds_.delete_face(Cm_);

    // A switch vertex left with two edges of the same two cells is no longer a vertex.
    for(int w : switch_vertex_plus_) hds_.remove_degree_two_vertex(w);
    for(int w : switch_vertex_minus_) hds_.remove_degree_two_vertex(w);
    if(slit_P) finish_slit();
    return stats_;
  }

private:
  struct Node {
    int face;
    int prev, next;
    int right_he;   // open edge to the next node: half-edge of this face, start -> end
    int event;      // current vanishing candidate
    int opened;     // when right_he was opened (an index of times_)
  };
  // Where the traits have a Disk_hint and FT is a floating-point type, the
  // centre of the disk of each vanishing event is kept with the vertex
  // that the event makes, and the switch times at that vertex are computed
  // from it (see Halfedge_structure::set_centre_hint()).
  typedef typename Disk_hint_of<Traits>::type Disk_hint;
  static constexpr bool Hints = Disk_hint_of<Traits>::exists && std::is_floating_point<FT>::value;
  struct Event {
    Time time;
    int node;
    bool valid;
    Disk_hint hint;   // (where the traits have one) the centre of the event's disk,
    int hint_faces[2];   // tangent to these faces and the node's
  };
  struct Switch {
    // (the time is computed afterwards, in the switch's place in its list)
    Switch(int v, int n, int o, int tn, int to) : vertex(v), gnew(n), gold(o), te_new(tn), te_old(to) {}
    int vertex;
    int gnew, gold;        // generator entering L, generator it goes next to
    int te_new, te_old;    // half-edges of those generators along the consumed cell
    Time time;
  };

  int input_of(int v) const { return chds().vertex(v).input_point(); }
  // read-only access (the journal of the double model records writes only)
  const Hds& chds() const { return hds_; }

#ifdef CGAL_PMA2_TRACE
  template <class T>
  static auto approx_impl(const T& t, int) -> decltype(t.to_double()) { return t.to_double(); }
  template <class T>
  static auto approx_impl(const T& t, long) -> decltype(double(t.t)) { return t.t; }   // (Double_time)
  template <class T>
  static double approx_impl(const T& t, ...) { return CGAL::to_double(t); }
  template <class T>
  static double approx(const T& t) { return approx_impl(t, 0); }
  std::string face_string(int face) const
  {
    const Hds_face& f = hds_.face(face);
    return (f.is_point ? "p" : "s") + std::to_string(f.p0) + (f.is_point ? "" : "-" + std::to_string(f.p1));
  }
  std::string list_string() const
  {
    std::string out;
    for(int n = 0; n != NO_INDEX; n = nodes_[n].next) {
      const Hds_face& f = hds_.face(nodes_[n].face);
      out += (n == 0 ? "[C+" : n == 1 ? "C-]" : (f.is_point ? "p" : "s") + std::to_string(f.p0) + (f.is_point ? "" : "-" + std::to_string(f.p1)));
      out += " ";
    }
    return out;
  }
#endif

  const Point_2& vertex_point(int v) const
  {
    resolve_vertex(hds_, v, points_, traits_, [this](int f) { return site(f); });
    return chds().point(v, points_);
  }

  // Moves every half-edge of vertex `from` to vertex `to` (two corners of one
  // polygon vertex) and deletes `from`.
  void unify_corners(int from, int to)
  {
    if(from == to)
      return;
    CGAL_assertion(chds().vertex(from).input_point() == chds().vertex(to).input_point());
    const int h0 = chds().vertex(from).halfedge;
    int h = h0;
    do {
      CGAL_assertion(hds_.target(h) == from);
      hds_.he(h).vertex = to;
      h = Hds::twin(hds_.next(h));
    } while(h != h0);
    hds_.delete_vertex(from);
  }

  bool is_point_at(int f, int point) const
  {
    const Hds_face& x = chds().face(f);
    return x.is_point && x.p0 == point;
  }

  int face_across(int h) const { return hds_.face_of(Hds::twin(h)); }

  int insert_after(int n, int face)
  {
    int id = int(nodes_.size());
    int nx = nodes_[n].next;
    nodes_.push_back(Node{face, n, nx, NO_INDEX, NO_INDEX, now_index()});
    nodes_[n].next = id;
    nodes_[nx].prev = id;
    return id;
  }

  void unlink_node(int n)
  {
    nodes_[nodes_[n].prev].next = nodes_[n].next;
    nodes_[nodes_[n].next].prev = nodes_[n].prev;
  }

  // The open edge of node n ends now, at vertex v (or at time t).
  void close_edge(int n, int v) { close_edge(n, v, now()); }
  void close_edge(int n, int v, const Time& t)
  {
    const int h = nodes_[n].right_he;
    hds_.he(h).vertex = v;
    if(compare_(t, time_at(times_[std::size_t(nodes_[n].opened)])) != EQUAL)
      return;
    if(compare_(t, start_) == LARGER && compare_(t, end_) == SMALLER)
      hds_.set_zero_length(h, true);
    else if(same_disk(hds_.source(h), v))
      hds_.set_zero_length(h, true);
  }

  // Whether two vertices defined by generator triples are one disk.
  bool same_disk(int v, int w) const
  {
    if(chds().vertex(v).is_corner() || chds().vertex(w).is_corner())
      return false;
    const typename Hds::Disk &a = chds().disk(v), &b = chds().disk(w);
    if(a.triple[0][0] == NO_INDEX || b.triple[0][0] == NO_INDEX)
      return false;
    return traits_.equal_medial_disks_2_object()(triple_site(a.triple[0]), triple_site(a.triple[1]),
                                                 triple_site(a.triple[2]), triple_site(b.triple[0]),
                                                 triple_site(b.triple[1]), triple_site(b.triple[2]));
  }

  // The site of a generator of a vertex's triple (input points p[0], p[1]).
  CGAL_PMA2_ALWAYS_INLINE Site_2 triple_site(const int p[2]) const { return generator_site<Site_2>(points_, p); }

  // A new edge between `left` and `right`, leaving vertex `start`; its end is set later.
  int open_edge(int start, int left, int right)
  {
    int h = hds_.new_edge(left, right);
    hds_.he(Hds::twin(h)).vertex = start;
    hds_.face(left).halfedge = h;
    hds_.face(right).halfedge = Hds::twin(h);
    return h;
  }

  // ---- initialization at P (Algorithm 3) ----
  void initialize(Orientation turn_P)
  {
    const int k = int(plus_.size());
    const int H1 = face_across(plus_[k - 1]);   // neighbour of C+ at P
    const int H2 = face_across(minus_[0]);      // neighbour of C- at P
    int first_open, last_open_twin;
    if(turn_P != RIGHT_TURN || is_point_at(H1, P_) || is_point_at(H2, P_)) {
      // Convex or flat corner, or P was already reflex on one side.
      CGAL_assertion(turn_P == RIGHT_TURN || (!is_point_at(H1, P_) && !is_point_at(H2, P_)));
      int n1 = insert_after(0, H1);
      insert_after(n1, H2);
      int h = open_edge(vP_, H1, H2);
      nodes_[n1].right_he = h;
      first_open = h;
      last_open_twin = Hds::twin(h);
    } else {
      // P becomes reflex: a new point generator between the two edges.
      int Pm = hds_.new_face(true, P_, P_);
      int n1 = insert_after(0, H1);
      int nm = insert_after(n1, Pm);
      insert_after(nm, H2);
      int h1 = open_edge(vP_, H1, Pm);
      int h2 = open_edge(vP_, Pm, H2);
      nodes_[n1].right_he = h1;
      nodes_[nm].right_he = h2;
      hds_.link(Hds::twin(h1), h2);
      first_open = h1;
      last_open_twin = Hds::twin(h2);
    }
    const int te_k = Hds::twin(plus_[k - 1]);
    const int te_1 = Hds::twin(minus_[0]);
    hds_.link(hds_.prev(te_k), first_open);
    hds_.link(last_open_twin, hds_.next(te_1));
    hds_.vertex(vP_).halfedge = last_open_twin;
  }

  // ---- initialization at P, the tip of a slit ----
  // P is a corner of 360 degrees: the separator PQ is the next edge of a
  // chain of shared edges whose previous edge was merged (a union of two
  // axes, CGAL::medial_axis_union_2()).  After this merge P is a point inside
  // the shape, no generator: its point cell, which is the tip's cell at the
  // start (the tip of the retracting slit is at P), goes.  Its cycle is
  //   n+ (vP -> w_0, the normal of C+), f_1 (w_0 -> w_1), ..., f_m (w_m-1 -> w_m),
  //   n- (w_m -> vP, the normal of C-),
  // with g_i across f_i.  L starts as [C+, g_1, ..., g_m, C-]: the wall
  // between g_i and g_i+1, which ends at w_i, goes on as the open edge
  // between them (as at a switch point, all at the start time); C+ and C-
  // are walked from w_0 and w_m (their normals at P dropped).  At the end the
  // point cell, its edges, vP, w_0 and w_m are deleted, and w_1 ... w_m-1
  // have two edges of the same two cells left.
  void initialize_slit()
  {
    const int Pc = face_across(plus_.back());
    // (each of C+, C- keeps an edge: their normals at P and Q are parallel)
    if(!is_point_at(Pc, P_) || face_across(minus_.front()) != Pc || plus_.size() < 2 || minus_.size() < 2)
      throw Merge_anomaly();
    slit_cycle_.clear();
    const int n_plus = Hds::twin(plus_.back()), n_minus = Hds::twin(minus_.front());
    for(int h = hds_.next(n_plus); h != n_minus; h = hds_.next(h)) slit_cycle_.push_back(h);   // f_1 .. f_m
    const int m = int(slit_cycle_.size());
    plus_.pop_back();
    minus_.erase(minus_.begin());
    if(m < 1 || face_across(plus_.back()) != face_across(slit_cycle_.front()) ||
       face_across(minus_.front()) != face_across(slit_cycle_.back()))
      throw Merge_anomaly();
    slit_face_ = Pc;
    slit_w0_ = hds_.source(slit_cycle_.front());
    slit_wm_ = hds_.target(slit_cycle_.back());
    slit_inner_.clear();
    int prev = 0;
    std::vector<int> nodes;
    for(int f : slit_cycle_) {
      prev = insert_after(prev, face_across(f));
      nodes.push_back(prev);
    }
    for(int i = 0; i + 1 < m; ++i) {
      const int w = hds_.target(slit_cycle_[std::size_t(i)]);
      const int te_a = Hds::twin(slit_cycle_[std::size_t(i)]), te_b = Hds::twin(slit_cycle_[std::size_t(i + 1)]);
      const int h = open_edge(w, face_across(slit_cycle_[std::size_t(i)]), face_across(slit_cycle_[std::size_t(i + 1)]));
      hds_.link(hds_.prev(te_a), h);
      hds_.link(Hds::twin(h), hds_.next(te_b));
      hds_.vertex(w).halfedge = Hds::twin(h);
      nodes_[std::size_t(nodes[std::size_t(i)])].right_he = h;
      slit_inner_.push_back(w);
    }
    slit_cycle_.push_back(n_plus);
    slit_cycle_.push_back(n_minus);
    for(int n : nodes) update_candidate(n);
  }

  void finish_slit()
  {
    for(int h : slit_cycle_) hds_.delete_edge(h);
    hds_.delete_face(slit_face_);
    hds_.delete_vertex(vP_);
    hds_.delete_vertex(slit_w0_);
    hds_.delete_vertex(slit_wm_);
    for(int w : slit_inner_) hds_.remove_degree_two_vertex(w);
  }

  // Whether the generators of faces f[0..2] are those of the triple of a
  // disk, in the same cyclic order.
  bool same_triple(const int (&triple)[3][2], const int (&f)[3]) const
  {
    int p[3][2];
    for(int i = 0; i < 3; ++i) {
      const Hds_face& x = chds().face(f[i]);
      p[i][0] = x.p0;
      p[i][1] = x.p1;
    }
    for(int r = 0; r < 3; ++r) {
      bool same = true;
      for(int i = 0; i < 3 && same; ++i)
        same = p[(i + r) % 3][0] == triple[i][0] && p[(i + r) % 3][1] == triple[i][1];
      if(same) return true;
    }
    return false;
  }

  // The switch time at vertex w of the cell of face `fc` (site `c`), whose
  // disk is tangent to the generators of faces fc, fa and fb in that order:
  // from the centre kept with w where it has one (Disk_hint), else from the
  // sites.
  bool switch_time_at(int w, const Site_2& c, int fc, int fa, int fb, Time& t) const
  {
    typename Traits::Compute_switch_time_2 switch_time = traits_.compute_switch_time_2_object();
    if constexpr(Hints) {
      double x, y, err;
      const int f[3] = {fc, fa, fb};
      if(chds().centre_hint(w, x, y, err) && same_triple(chds().disk(w).triple, f))
        return switch_time(line_, c, site(fa), site(fb), t, Disk_hint::from_doubles(x, y, err));
    }
    return switch_time(line_, c, site(fa), site(fb), t);
  }

  // ---- the switch points of both cells, in order along the separator ----
  void collect_switches()
  {
    const int k = int(plus_.size());
    switch_vertex_plus_.assign(k > 0 ? k - 1 : 0, NO_INDEX);
    sw_plus_.clear();
    // C+ cell walk: e_1 leaves Q, ..., e_k arrives at P; vertex w_j = target(e_j).
    const int jmin = is_point_at(face_across(plus_[0]), Q_) ? 2 : 1;
    for(int j = 1; j <= k - 1; ++j)
      switch_vertex_plus_[j - 1] = hds_.target(plus_[j - 1]);
    for(int j = k - 1; j >= jmin; --j) {
      const int w = hds_.target(plus_[j - 1]);
      const int G = face_across(plus_[j - 1]), Gp = face_across(plus_[j]);
      Switch& s = sw_plus_.emplace_back(w, G, Gp, Hds::twin(plus_[j - 1]), Hds::twin(plus_[j]));
      if(!switch_time_at(w, site_p_, Cp_, G, Gp, s.time))
        s.time = traits_.compute_foot_time_2_object()(line_, vertex_point(w));
    }
    const int km = int(minus_.size());
    switch_vertex_minus_.assign(km > 0 ? km - 1 : 0, NO_INDEX);
    sw_minus_.clear();
    // C- cell walk: e'_1 leaves P, ..., e'_k' arrives at Q; vertex w'_j = target(e'_j).
    const int jmax = is_point_at(face_across(minus_[km - 1]), Q_) ? km - 2 : km - 1;
    for(int j = 1; j <= km - 1; ++j)
      switch_vertex_minus_[j - 1] = hds_.target(minus_[j - 1]);
    for(int j = 1; j <= jmax; ++j) {
      const int w = hds_.target(minus_[j - 1]);
      const int Gp = face_across(minus_[j - 1]), G = face_across(minus_[j]);
      Switch& s = sw_minus_.emplace_back(w, G, Gp, Hds::twin(minus_[j]), Hds::twin(minus_[j - 1]));
      if(!switch_time_at(w, site_m_, Cm_, Gp, G, s.time))
        s.time = traits_.compute_foot_time_2_object()(line_, vertex_point(w));
    }
  }

  // ---- the priority queue of vanishing candidates ----
  bool event_after(int a, int b) const
  {
    Comparison_result r = compare_(events_[a].time, events_[b].time);
    if(r != EQUAL) return r == LARGER;
    return a > b;
  }

  void invalidate(int n)
  {
    int ev = nodes_[n].event;
    if(ev != NO_INDEX && events_[ev].valid) {
      events_[ev].valid = false;
      --live_events_;
    }
    nodes_[n].event = NO_INDEX;
  }

  void update_candidate(int n)
  {
    invalidate(n);
    const int a = nodes_[n].prev, c = nodes_[n].next;
    if(a == 0 || c == 1)
      return;                     // next to C+ or C-: such a generator leaves by a switch
    const int fa = nodes_[a].face, fb = nodes_[n].face, fc = nodes_[c].face;
    if(fa == fc)
      return;
    // (the time is computed in its place in the queue: copying or moving
    // an event time costs about as much as the queue's other work for it;
    // an event that is dropped leaves nothing behind, and every merge
    // clears the queue first)
    const int ev = int(events_.size());
    Event& e = events_.emplace_back();
    bool found;
    if constexpr(Hints)
      found = traits_.compute_vanishing_time_2_object()(line_, site(fa), site(fb), site(fc), e.time, e.hint);
    else
      found = traits_.compute_vanishing_time_2_object()(line_, site(fa), site(fb), site(fc), e.time);
    if(!found || traits_.is_event_in_past_2_object()(e.time, now(), line_)) {
      events_.pop_back();
      return;
    }
    if(const int twice = twice_around(n); twice != 0 && tip_excludes(n, twice)) {
      events_.pop_back();
      return;
    }
    e.node = n;
    e.valid = true;
    e.hint_faces[0] = fa;
    e.hint_faces[1] = fc;
    nodes_[n].event = ev;
    CGAL_PMA2_TRACE_MSG("    candidate node " << n << " (" << face_string(fa) << " " << face_string(fb) << " " << face_string(fc)
                        << ") t=" << approx(e.time));
    heap_.push_back(ev);
    std::push_heap(heap_.begin(), heap_.end(), [this](int x, int y) { return event_after(x, y); });
    ++live_events_;
    stats_.max_queue = (std::max)(stats_.max_queue, live_events_);
  }

  // Whether the vanishing of node n is the wrong one of the two that a
  // generator G, which L holds on both sides of n and its neighbour, makes
  // (`twice`, from twice_around(n), says on which side of n G is).  In a
  // merge that closes a ring around a hole, the cell of one generator G can
  // touch the tip's cell on both sides of the hole (a small hole near a long
  // edge G: G's cell wraps around the hole's cells), and L then holds G
  // twice: [G X Y G].  The vanishing of X (the triple G X Y) and that of Y
  // (X Y G) are then one cyclic order of the same three generators: the
  // same disk D, at the same time, and only one of them can happen.  Taking
  // the other, the merge goes on with L in an order that no later event
  // undoes, silently or with anomalies (RESULTS.md: "A merge anomaly on real
  // data", thirty-first session; "Region growing's wrong axis mended",
  // forty-eighth session).
  //
  // The rule.  At the time of a vanishing of n between a and c, the tip of
  // the separator is on the circle of D, in the arc from c to a
  // (counter-clockwise): the cells around the new vertex are a, n, c and the
  // tip's.  Counter-clockwise from the point f where D touches G, the circle
  // meets X's contact point x, then Y's, y (they are one point where X is
  // the end point of Y, or the other way round).  So Y vanishes (G X Y, tip)
  // when the tip comes after f and before x, and X vanishes (X Y G, tip)
  // when it comes after y and before f.  Three points of a circle are in
  // counter-clockwise order along it exactly when they make a
  // counter-clockwise triangle, so each is one orientation.  (Until the
  // fiftieth session the rule asked only on which side of f the tip's foot
  // on G's line lies, as if x and y were f's antipode.  Where they are not,
  // that took the wrong vanishing: a triangular hole 0.0013 from a long
  // edge, whose disk touches the hole's corner and its edge at one point
  // far from f's antipode; regression shape l10m_SWE_tie_far_from_antipode,
  // RESULTS.md, fiftieth session.)
  //
  // Where G is a segment and X or Y is the point at an end of G, this is
  // decided exactly, without numbers: a disk tangent to G and through its
  // end Y touches G at Y, so every edge between the cells of Y and G is a
  // piece of G's normal at Y; the disks centred along that normal are
  // nested, so it is one edge, and Y cannot have G on both sides: the other
  // one vanishes.  (There the contacts of G and of that point are one, and
  // the orientations below are 0.)  Elsewhere the tip and the contact points
  // are computed in doubles from the disk's centre and radius (the traits'
  // construction), and the orientations decide only with a clear margin;
  // else both candidates stay, the one computed first is taken, and
  // `undecided_ties` counts it.
  CGAL_PMA2_NOINLINE bool tip_excludes(int n, int twice)
  {
    const int a = nodes_[n].prev, c = nodes_[n].next;
    const int fa = nodes_[a].face, fb = nodes_[n].face, fc = nodes_[c].face;
    const int G = twice == G_BEFORE ? fa : fc, X = twice == G_BEFORE ? fb : fa, Y = twice == G_BEFORE ? fc : fb;
    if(end_point_between(G, twice == G_BEFORE ? fc : fa))
      return true;
    if(end_point_between(G, fb))   // (the other vanishing would leave n between the two G's)
      return false;
    // (both candidates stay)
    auto undecided = [this] {
      ++stats_.undecided_ties;
      return false;
    };
    Point_2 centre;
    FT radius;
    if(!traits_.construct_medial_disk_2_object()(site(fa), site(fb), site(fc), centre, radius))
      return undecided();
    const double cx = CGAL::to_double(centre.x()), cy = CGAL::to_double(centre.y()), r = CGAL::to_double(radius);
    const Point_2 &P = points_[P_], &Q = points_[Q_];
    const double px = CGAL::to_double(P.x()), py = CGAL::to_double(P.y());
    double ux = CGAL::to_double(Q.x()) - px, uy = CGAL::to_double(Q.y()) - py;
    const double lu = std::sqrt(ux * ux + uy * uy);
    if(!(lu > 0 && r > 0))
      return undecided();
    ux /= lu; uy /= lu;
    // the tip: where the separator's line leaves the disk
    const double wx = cx - px, wy = cy - py;
    const double m = wx * ux + wy * uy;
    const double h2 = r * r - (wx * wx + wy * wy - m * m);
    const double s = m + std::sqrt((std::max)(h2, 0.0));
    const double tx = px + s * ux, ty = py + s * uy;
    // where D touches a generator: the point, or the foot of the centre on
    // the segment's line (the disk touches the segment itself)
    auto contact = [&](int face, double& x, double& y) {
      const Hds_face& h = chds().face(face);
      const Point_2& p0 = points_[h.p0];
      x = CGAL::to_double(p0.x());
      y = CGAL::to_double(p0.y());
      if(h.is_point) return true;
      const Point_2& p1 = points_[h.p1];
      const double dx = CGAL::to_double(p1.x()) - x, dy = CGAL::to_double(p1.y()) - y, l2 = dx * dx + dy * dy;
      if(!(l2 > 0)) return false;
      const double t = ((cx - x) * dx + (cy - y) * dy) / l2;
      x += t * dx;
      y += t * dy;
      return true;
    };
    double fx, fy, xx, xy, yx, yy;
    if(!contact(G, fx, fy) || !contact(X, xx, xy) || !contact(Y, yx, yy))
      return undecided();
    // > 0: counter-clockwise along the circle from (ax, ay), (bx, by) comes before (ex, ey)
    auto ccw = [](double ax, double ay, double bx, double by, double ex, double ey) {
      return (bx - ax) * (ey - ay) - (by - ay) * (ex - ax);
    };
    const double y_vanishes = ccw(fx, fy, tx, ty, xx, xy), x_vanishes = ccw(fx, fy, yx, yy, tx, ty);
    // (a point's error: the tip's grows like sqrt(h2)'s where the line
    // nearly touches the disk; an orientation's, of points 2r apart at most)
    const double margin = 8 * r * (1e-6 * (r + std::sqrt(wx * wx + wy * wy)) + 1e-12 * (std::abs(cx) + std::abs(cy)));
    const bool y_clear = y_vanishes > margin && x_vanishes < -margin, x_clear = x_vanishes > margin && y_vanishes < -margin;
    CGAL_PMA2_TRACE_MSG("    tie of two vanishings at node " << n << " (" << face_string(fa) << " " << face_string(fb) << " "
                        << face_string(fc) << "): G " << face_string(G) << ", orientations " << y_vanishes << " (Y) "
                        << x_vanishes << " (X), margin " << margin << ": "
                        << (y_clear ? "Y vanishes" : x_clear ? "X vanishes" : "undecided"));
    if(!y_clear && !x_clear)
      return undecided();
    // (n is X where G comes before it)
    return twice == G_BEFORE ? y_clear : x_clear;
  }

  // Whether face y is the point at an end of the segment of face g.
  bool end_point_between(int g, int y) const
  {
    const Hds_face &G = chds().face(g), &Y = chds().face(y);
    return !G.is_point && Y.is_point && (Y.p0 == G.p0 || Y.p0 == G.p1);
  }

  // Where L holds one generator G on both sides of node n and its
  // neighbour: G_BEFORE for [G n Y G], G_AFTER for [G X n G], 0 if neither
  // (n's neighbours are not C+ or C-).
  enum { G_BEFORE = 1, G_AFTER = 2 };
  CGAL_PMA2_ALWAYS_INLINE int twice_around(int n) const
  {
    const int a = nodes_[n].prev, c = nodes_[n].next;
    if(c != 1 && nodes_[nodes_[c].next].face == nodes_[a].face)
      return G_BEFORE;
    if(a != 0 && nodes_[nodes_[a].prev].face == nodes_[c].face)
      return G_AFTER;
    return 0;
  }

  // Drops the vanishing of node m where a change two nodes away made L hold
  // its neighbour's generator twice around it (see tip_excludes()).
  CGAL_PMA2_ALWAYS_INLINE void recheck_twice(int m)
  {
    if(m <= 1)
      return;   // (C+ or C-)
    const int ev = nodes_[m].event;
    if(ev == NO_INDEX || !events_[ev].valid)
      return;
    if(const int twice = twice_around(m); twice != 0 && tip_excludes(m, twice))
      invalidate(m);
  }

  int top_event()
  {
    while(!heap_.empty() && !events_[heap_.front()].valid) {
      std::pop_heap(heap_.begin(), heap_.end(), [this](int x, int y) { return event_after(x, y); });
      heap_.pop_back();
    }
    return heap_.empty() ? NO_INDEX : heap_.front();
  }

  void pop_event()
  {
    int ev = heap_.front();
    std::pop_heap(heap_.begin(), heap_.end(), [this](int x, int y) { return event_after(x, y); });
    heap_.pop_back();
    if(events_[ev].valid) {
      events_[ev].valid = false;
      --live_events_;
      nodes_[events_[ev].node].event = NO_INDEX;
    }
  }

  // (t: where the time is kept, see time_at())
  void advance_time(int t)
  {
    if(compare_(time_at(t), now()) == LARGER)
      times_.push_back(t);
  }

  // ---- the sweep (Algorithm 5) ----
  template <class Visitor>
  void run_events(bool q_reflex, Visitor& visitor)
  {
    const Time& t_end = end_;
    std::size_t ip = 0, im = 0;
    for(;;) {
      int which = -1;
      const Time* best = nullptr;
      if(ip < sw_plus_.size()) {
        which = 0;
        best = &sw_plus_[ip].time;
      }
      if(im < sw_minus_.size() && (best == nullptr || compare_(sw_minus_[im].time, *best) == SMALLER)) {
        which = 1;
        best = &sw_minus_[im].time;
      }
      int ev = top_event();
      if(ev != NO_INDEX) {
        if(q_reflex && compare_(events_[ev].time, t_end) == LARGER) {
          // beyond Q: the tip never gets there
          pop_event();
          continue;
        }
        if(best == nullptr || compare_(events_[ev].time, *best) == SMALLER)
          which = 2;
      }
      if(which < 0)
        break;
      CGAL_PMA2_TRACE_MSG("  event " << (which == 0 ? "switch+" : which == 1 ? "switch-" : "vanish") << " t="
                          << approx(which == 0 ? sw_plus_[ip].time : which == 1 ? sw_minus_[im].time : events_[ev].time)
                          << " L=" << list_string());
      if(which == 0) {
        advance_time(time_ref(SWITCH_PLUS_TIME, ip));
        switch_plus(sw_plus_[ip++]);
        visitor.on_switch();
      } else if(which == 1) {
        advance_time(time_ref(SWITCH_MINUS_TIME, im));
        switch_minus(sw_minus_[im++]);
        visitor.on_switch();
      } else {
        const int n = events_[ev].node;
        pop_event();                    // (marks the event, keeps its record)
        advance_time(time_ref(EVENT_TIME, std::size_t(ev)));
        vanish(n, ev);
        visitor.on_vanish();
      }
    }
  }

  // Algorithm 1 on the C+ side: gold leaves Phi(C+), gnew enters L after C+.
  void switch_plus(const Switch& s)
  {
    ++stats_.switches;
    const int first = nodes_[0].next;
    if(strict_ && nodes_[first].face != s.gold) throw Merge_anomaly();
    CGAL_assertion(nodes_[first].face == s.gold);
    const int n = insert_after(0, s.gnew);
    const int h = open_edge(s.vertex, s.gnew, s.gold);
    hds_.link(hds_.prev(s.te_new), h);
    hds_.link(Hds::twin(h), hds_.next(s.te_old));
    hds_.vertex(s.vertex).halfedge = Hds::twin(h);
    nodes_[n].right_he = h;
    update_candidate(first);
    recheck_twice(nodes_[first].next);
  }

  // Algorithm 1 on the C- side: gold leaves Phi(C-), gnew enters L before C-.
  void switch_minus(const Switch& s)
  {
    ++stats_.switches;
    const int last = nodes_[1].prev;
    if(strict_ && nodes_[last].face != s.gold) throw Merge_anomaly();
    CGAL_assertion(nodes_[last].face == s.gold);
    insert_after(last, s.gnew);
    const int h = open_edge(s.vertex, s.gold, s.gnew);
    hds_.link(hds_.prev(s.te_old), h);
    hds_.link(Hds::twin(h), hds_.next(s.te_new));
    hds_.vertex(s.vertex).halfedge = Hds::twin(h);
    nodes_[last].right_he = h;
    nodes_[last].opened = now_index();
    update_candidate(last);
    recheck_twice(nodes_[last].prev);
  }

  // Algorithm 2: the generator of node n leaves L at a new branch point
  // (at event `ev`, if it has one).
  void vanish(int n, int ev = NO_INDEX)
  {
    ++stats_.vanishings;
    const int a = nodes_[n].prev, c = nodes_[n].next;
    const int fa = nodes_[a].face, fc = nodes_[c].face;
    const int v = hds_.new_pending_vertex(fa, nodes_[n].face, fc);
    if constexpr(Hints) {
      // (the disk of the event, if the node's neighbours are those of the event)
      const Event* e = ev != NO_INDEX ? &events_[std::size_t(ev)] : nullptr;
      double x, y, err;
      if(e != nullptr && e->hint.valid && e->hint_faces[0] == fa && e->hint_faces[1] == fc &&
         e->hint.to_doubles(x, y, err))
        hds_.set_centre_hint(v, x, y, err);
    }
    const int AB = nodes_[a].right_he, BC = nodes_[n].right_he;
    close_edge(a, v);
    close_edge(n, v);
    const int AC = open_edge(v, fa, fc);
    hds_.link(AB, AC);
    hds_.link(BC, Hds::twin(AB));
    hds_.link(Hds::twin(AC), Hds::twin(BC));
    hds_.vertex(v).halfedge = AB;
    nodes_[a].right_he = AC;
    nodes_[a].opened = now_index();
    invalidate(n);
    unlink_node(n);
    if(strict_ && nodes_[a].face == nodes_[c].face) throw Merge_anomaly();
    CGAL_assertion(nodes_[a].face != nodes_[c].face);
    update_candidate(a);
    update_candidate(c);
    recheck_twice(nodes_[a].prev);
    recheck_twice(nodes_[c].next);
  }

  // ---- termination at Q (Algorithm 4) ----
  // Convex or flat corner: the tip's cell shrinks to Q; one open edge ends there.
  void terminate_convex()
  {
    // Topologically the list must be [C+, E1_out, E2_in, C-] now.
    while(nodes_[nodes_[0].next].next != nodes_[1].prev &&
          nodes_[0].next != nodes_[1].prev) {
      if(strict_) throw Merge_anomaly();
      ++stats_.anomalies;
      vanish(nodes_[nodes_[0].next].next);
    }
    const int n1 = nodes_[0].next;
    CGAL_assertion(nodes_[n1].next == nodes_[1].prev && n1 != 1);
    const int h = nodes_[n1].right_he;
    hds_.he(h).vertex = vQ_;   // an edge to the corner Q has length: its start is a disk of positive radius
    const int te_1 = Hds::twin(plus_[0]);
    const int te_k = Hds::twin(minus_.back());
    hds_.link(h, hds_.next(te_1));
    hds_.link(hds_.prev(te_k), Hds::twin(h));
    hds_.vertex(vQ_).halfedge = h;
  }

  // Reflex corner: the tip's cell becomes the cell of the reflex vertex Q.
  void terminate_reflex()
  {
    const int F1 = face_across(plus_[0]);
    const int Fk = face_across(minus_.back());
    const bool q1 = is_point_at(F1, Q_), q2 = is_point_at(Fk, Q_);
    const int Qm = q1 ? F1 : (q2 ? Fk : hds_.new_face(true, Q_, Q_));

    std::vector<int>& g = chain_nodes_;
    g.clear();
    for(int n = nodes_[0].next; n != 1; n = nodes_[n].next) g.push_back(n);
    const int m = int(g.size());
    // chain edge i (0-based) runs from b_i to b_i+1 with Qm on its left
    std::vector<int>& ch = chain_edges_;
    ch.assign(m, NO_INDEX);
    for(int i = 0; i < m; ++i)
      ch[i] = hds_.new_edge(Qm, nodes_[g[i]].face);
    // start vertex b_0
    const int b0 = q1 ? hds_.target(plus_[0]) : vQ_;
    const int bm = q2 ? hds_.target(minus_[minus_.size() - 2]) : vQ_;
    hds_.he(Hds::twin(ch[0])).vertex = b0;
    hds_.he(ch[m - 1]).vertex = bm;
    for(int i = 0; i + 1 < m; ++i) {
      const int o = nodes_[g[i]].right_he;
      const int v = hds_.new_pending_vertex(Qm, nodes_[g[i]].face, nodes_[g[i + 1]].face);
      close_edge(g[i], v, end_);
      hds_.he(ch[i]).vertex = v;
      hds_.he(Hds::twin(ch[i + 1])).vertex = v;
      hds_.link(ch[i], ch[i + 1]);
      hds_.link(o, Hds::twin(ch[i]));
      hds_.link(Hds::twin(ch[i + 1]), Hds::twin(o));
      hds_.vertex(v).halfedge = o;
    }
    for(int i = 0; i < m; ++i) {
      hds_.face(nodes_[g[i]].face).halfedge = Hds::twin(ch[i]);
      // a chain edge between two disks that are one (Q's cell and three
      // consecutive generators on one circle) has length zero
      if(same_disk(hds_.source(ch[i]), hds_.target(ch[i]))) hds_.set_zero_length(ch[i], true);
    }
    hds_.face(Qm).halfedge = ch[0];

    int q_out, q_in;
    const int te_1 = Hds::twin(plus_[0]);
    if(q1) {
      // b_0 is the top of the old normal of C+ at Q
      const int te_2 = Hds::twin(plus_[1]);
      hds_.link(hds_.prev(te_1), ch[0]);
      hds_.link(Hds::twin(ch[0]), hds_.next(te_2));
      q_out = hds_.next(te_1);
    } else {
      hds_.link(Hds::twin(ch[0]), hds_.next(te_1));
      q_out = ch[0];
    }
    const int tk = Hds::twin(minus_.back());
    if(q2) {
      const int tk1 = Hds::twin(minus_[minus_.size() - 2]);
      hds_.link(ch[m - 1], hds_.next(tk));
      hds_.link(hds_.prev(tk1), Hds::twin(ch[m - 1]));
      q_in = hds_.prev(tk);
    } else {
      hds_.link(hds_.prev(tk), Hds::twin(ch[m - 1]));
      q_in = ch[m - 1];
    }
    hds_.link(q_in, q_out);
    hds_.vertex(vQ_).halfedge = q_in;
    if(q1) hds_.vertex(b0).halfedge = hds_.prev(ch[0]);
    if(q2) hds_.vertex(bm).halfedge = ch[m - 1];
  }

  Hds& hds_;
  const std::vector<Point_2>& points_;
  const Traits& traits_;
  typename Traits::Compare_event_time_2 compare_;

  Merge_statistics stats_;
  int Cp_ = NO_INDEX, Cm_ = NO_INDEX, vP_ = NO_INDEX, vQ_ = NO_INDEX, P_ = NO_INDEX, Q_ = NO_INDEX;
  Site_2 line_, site_p_, site_m_;
  Time start_, end_;
  // The sweep's times so far, the last one now; the nodes refer to them by
  // index.  Each is kept where the sweep found it, in the switch lists or
  // the events, which a merge only appends to (the candidates it drops at
  // once aside), and referred to here: (index << 2) | list.  A time of the
  // filtered traits is 208 bytes; copied here, the copies and the pages
  // they took (times_ grown by doubling) were 8% of the tool's time on a
  // 20,000-gon, whose joins have tens of thousands of events (RESULTS.md,
  // fifty-ninth session).
  enum { START_TIME, SWITCH_PLUS_TIME, SWITCH_MINUS_TIME, EVENT_TIME };
  std::vector<int> times_;
  static int time_ref(int list, std::size_t index) { return int(index << 2) | list; }
  const Time& time_at(int t) const
  {
    const std::size_t i = std::size_t(t >> 2);
    switch(t & 3) {
    case START_TIME: return start_;
    case SWITCH_PLUS_TIME: return sw_plus_[i].time;
    case SWITCH_MINUS_TIME: return sw_minus_[i].time;
    default: return events_[i].time;
    }
  }
  const Time& now() const { return time_at(times_.back()); }
  int now_index() const { return int(times_.size()) - 1; }

  // Reserves the merge's lists for the cells of C+ and C- (plus_, minus_),
  // so that they do not grow by doubling in a long merge: each doubling
  // copies the records (an event is 288 bytes with the filtered traits) and
  // takes fresh pages, and a page fault costs about 10 microseconds on the
  // 2-core VM of RESULTS.md.  A merge makes a switch at each vertex of C+
  // and C-, which inserts a node into L and makes one candidate; a
  // vanishing removes a node and makes two.  The lists keep their capacity
  // from merge to merge.
  template <class V>
  static void reserve_at_least(V& v, std::size_t n)
  {
    if(n > v.capacity())
      v.reserve((std::max)(n, 2 * v.capacity()));
  }
  void reserve_lists()
  {
    const std::size_t cells = plus_.size() + minus_.size();
    reserve_at_least(sw_plus_, plus_.size());
    reserve_at_least(sw_minus_, minus_.size());
    reserve_at_least(nodes_, cells + 4);
    reserve_at_least(events_, 3 * cells + 8);
    reserve_at_least(heap_, 3 * cells + 8);
    reserve_at_least(times_, 2 * cells + 8);
  }
  bool strict_ = false;

  std::vector<int> plus_, minus_;
  std::vector<int> switch_vertex_plus_, switch_vertex_minus_;
  std::vector<Switch> sw_plus_, sw_minus_;
  std::vector<Node> nodes_;
  std::vector<Event> events_;
  std::vector<int> heap_;
  std::size_t live_events_ = 0;
  std::vector<int> chain_nodes_, chain_edges_;
  // the point cell of P when P is the tip of a slit (initialize_slit())
  int slit_face_ = NO_INDEX, slit_w0_ = NO_INDEX, slit_wm_ = NO_INDEX;
  std::vector<int> slit_cycle_, slit_inner_;
};

} // namespace internal
} // namespace Progressive_medial_axes
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_MEDIAL_AXIS_2_INTERNAL_MERGE_H
