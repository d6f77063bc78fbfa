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
// The union driver: the medial axis of the union of two polygons with
// disjoint interiors, from their two medial axes (Liu et al. 2016, Fig. 24).
// Their boundaries share chains of edges (same points, opposite directions);
// every shared edge is a segment generator of both axes, and the union's axis
// is what the engine's merge gives along each shared edge in turn: the same
// merge that region growing does along a diagonal of a triangle.
//
// The steps:
//   1. Corners.  A corner of a polygon is one of its vertices as a sector of
//      its interior (where rings touch, one place holds several corners; the
//      engine's point indices are corners).  A corner whose outgoing edge is
//      shared continues, across that edge, into the corner of the other
//      polygon at the same place whose incoming edge is the same edge.  The
//      corners so chained form a corner of the union; a closed chain of
//      corners is a point inside the union (a vertex inside a shared chain).
//      This is topology only: no angle is computed.
//   2. The union's boundary cycles are traced from corner to corner along the
//      edges that are not shared.  Where a cycle passes a place twice with a
//      clockwise loop between (a hole touching the outer ring or another
//      hole at a point), the loop is made a ring of its own, as OGC has it
//      (split_clockwise_loops()).  The counter-clockwise cycle that holds the
//      smallest point is the outer ring (other counter-clockwise cycles, the
//      lobes of a pinched union, are spliced into it where they touch it),
//      the clockwise ones are holes.  The union is validated as any input.
//   3. The two structures are copied into one (the inputs are left as they
//      are: this is linear in their size, and the only part of the cost that
//      is not local) and their point indices renumbered to the union's.
//   4. The merges, chain after chain, each edge of a chain after the one
//      before it.  The first merge of the first chain joins the two
//      components; the first merge of each further chain closes a ring
//      around a hole of the union.  After the merge along an edge PQ of a
//      chain, Q is a corner of 360 degrees (the next edge of the chain lies
//      on both sides of the shape: a slit), reflex, with a point cell; the
//      merge along the next edge starts at that tip, makes Q a point inside
//      the union and removes its cell (Medial_merge::initialize_slit()).
//      Each merge costs in proportion to the cells it touches.
//
// Not merged: a ring shared as a whole (one polygon fills a hole of the
// other exactly).  Whatever the order, the last merge along it closes a
// crack whose two ends are tips: when the retracting tip reaches the far
// end, the cells of the tip and of that end are one point's cell, and that
// point is no generator of the union; its cell has to be shared out among
// its neighbours (the removal of a point site), which the merge does not do.
// Such a union is found and validated as any other, and its axis computed
// in one shot of its polygon instead (CGAL::medial_axis_union_2()).
//
// T's (a vertex inside an edge).  Where a polygon has one, its axis has
// split the edge there and added a corner at the place (triangulate_rings());
// these corners are corners like the others here, so the union's ring
// through that edge has a vertex there too (the union is noded, as GEOS's
// overlays are; the edge ids of that ring after it are one higher).  A T
// that neither polygon has but the union has (a vertex of one polygon inside
// an edge of the other that is not shared) is not merged either: the cells
// of that edge would have to be split.  The union polygon is noded there
// (and a ring that touched its own edge there split into OGC's form, see
// build_points()), and its axis computed in one shot.  So is a union where
// a polygon splits an edge that the other has whole (a T on a shared edge):
// the union is then traced with a copy of the other polygon noded there.
//
// Where the merges meet an anomaly (a bug; none on any shape tried), or
// where a ring is shared as a whole or the union has a T of its own (above),
// CGAL::medial_axis_union_2() computes the union's axis in one shot of
// rings() (the union polygon, in the numbering of the ids), as the one-shot
// computes its own again by region growing: no axis the merges may have
// got wrong is returned.
//
// The union's points are its rings' (the numbering that the ids refer to),
// followed by the places inside shared chains, which are no vertices of the
// union (no cell of the result refers to them; this is checked).

#ifndef CGAL_PROGRESSIVE_MEDIAL_AXIS_2_INTERNAL_UNION_H
#define CGAL_PROGRESSIVE_MEDIAL_AXIS_2_INTERNAL_UNION_H

#include <CGAL/Exact_rational.h>
#include <CGAL/Progressive_medial_axis_2/Input_error.h>
#include <CGAL/Progressive_medial_axis_2/Medial_axis_2.h>
#include <CGAL/Progressive_medial_axis_2/validate_polygon.h>
#include <CGAL/Progressive_medial_axis_2/internal/Input_conversion.h>
#include <CGAL/Progressive_medial_axis_2/internal/Medial_axis_engine.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cstddef>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Progressive_medial_axes {

/*!
\ingroup PkgProgressiveMedialAxis2Ref
What `CGAL::medial_axis_union_2()` did.
*/
struct Medial_axis_union_statistics {
  std::size_t shared_edges = 0;   ///< edges the two polygons share (each merged once)
  std::size_t chains = 0;         ///< maximal chains of shared edges
  std::size_t switches = 0;       ///< switch points of the merges
  std::size_t vanishings = 0;     ///< vanishing points of the merges
  std::size_t anomalies = 0;      ///< events the merges forced to keep the topology valid (a bug, as in `Merge_statistics::anomalies`; 0 on every shape tried): the axis is then computed again (`recomputed`), and this counts what the merges met
  std::size_t undecided_ties = 0; ///< ties of two vanishings left undecided in the computation of the axis returned: by the merges, or by the one-shot where it was computed again (see `Merge_statistics::undecided_ties`; 0 on every shape tried)
  std::size_t recomputed = 0;     ///< 1 if the union's axis was computed in one shot of the union polygon (`CGAL::medial_axis_2()`, same numbering) instead of by the merges alone: where a ring is shared as a whole (one polygon fills a hole of the other exactly), which the merges do not close, or where the merges met an anomaly; else 0
  double join_seconds = 0;        ///< finding the shared chains, the union's rings and its validation, copying the two structures
  double merge_seconds = 0;       ///< the merges alone (with the one-shot, where the axis was computed again)
};

namespace internal {

/// For tests of the union's way out (`CGAL::medial_axis_union_2()`): while
/// set, every union computes its axis again, as if its merges had met an
/// anomaly.
inline std::atomic<bool>& union_way_out_forced()
{
  static std::atomic<bool> forced(false);
  return forced;
}

// Hash of an edge given by the coordinates of its ends (as doubles; equal
// points have equal doubles, and candidates are compared exactly).
struct Edge_key_hash {
  std::size_t operator()(const std::array<double, 4>& k) const
  {
    std::size_t h = 0;
    for(double d : k) h = h * 1000003u ^ std::hash<double>()(d);
    return h;
  }
};

template <class Traits>
class Medial_axis_union
{
public:
  typedef typename Traits::Kernel Kernel;
  typedef typename Kernel::Point_2 Point_2;
  typedef Medial_axis_engine<Traits> Engine;
  typedef typename Engine::Data Data;
  typedef typename Data::Hds Hds;

  Medial_axis_union(const Data& a, const Data& b, const Traits& traits) : traits_(traits)
  {
    in_[0] = &a;
    in_[1] = &b;
    for(int x = 0; x < 2; ++x) count_corners(x);
  }

  std::shared_ptr<Data> run(Medial_axis_union_statistics& stats)
  {
    auto t0 = std::chrono::steady_clock::now();
    for(int x = 0; x < 2; ++x) check_complete(x);
    node_split_shared_edges();
    find_shared_edges();
    group_corners();
    std::vector<std::vector<std::pair<int, int> > > rings = union_rings();
    auto data = std::make_shared<Data>();
    build_points(*data, rings);
    stats.chains = chains_.size();
    stats.shared_edges = 0;
    for(const auto& c : chains_) stats.shared_edges += c.size();
    if(one_shot_needed_) {   // (no merges: see one_shot_needed())
      stats.join_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      return nullptr;
    }
    join(*data);
    stats.join_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

    t0 = std::chrono::steady_clock::now();
    Engine engine(*data, traits_);
    Null_merge_visitor visitor;
    for(const std::vector<int>& chain : chains_) {
      for(int k : chain) {
        const Merge_statistics s = engine.merge(boundary_[0][std::size_t(k)], boundary_[1][std::size_t(shared_[0][std::size_t(k)])] + offset_, visitor);
        stats.switches += s.switches;
        stats.vanishings += s.vanishings;
        stats.anomalies += s.anomalies;
        stats.undecided_ties += s.undecided_ties;
      }
    }
    engine.resolve_pending();
    stats.merge_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    check_result(*data);
    return data;
  }

  /// Whether the merges cannot give the union's axis: where a ring is
  /// shared as a whole (one polygon fills a hole of the other exactly),
  /// where a vertex of the union lies inside an edge of the union (a T that
  /// neither polygon has), or where a polygon splits a shared edge at a T
  /// that the other does not have (see node_split_shared_edges()): the
  /// merged cells of that edge would have to be split there.  run() then validates the union but merges nothing and
  /// returns null, and the caller computes the union's axis in one shot of
  /// rings().
  bool one_shot_needed() const { return one_shot_needed_; }

  /// The union polygon's rings (once run() has found them): the numbering
  /// that the result's ids refer to.
  const std::vector<std::vector<Point_2> >& rings() const { return rings_; }

private:
  const Point_2& place(int x, int k) const { return in_[x]->points[std::size_t(k)]; }
  int next(int x, int k) const { return in_[x]->info[std::size_t(k)].next; }
  // The corners of polygon x: its input vertices, then the corners its
  // axis added where one of its vertices lies inside one of its edges (a T:
  // the edge is split there, see triangulate_rings()).  The split place is a
  // vertex of the union's ring through that edge: the union polygon is
  // noded there, as GEOS's overlays node theirs.  Where x is itself a union
  // that merges gave, its points end with the places inside its shared
  // chains, which are no corners (they have no edge: see build_points()).
  int corners(int x) const { return corners_[x]; }
  void count_corners(int x)
  {
    const Data& d = *in_[x];
    int n = int(d.points.size());
    while(n > d.ring_start.back() && d.info[std::size_t(n) - 1].next < 0) --n;
    corners_[x] = n;
  }
  static const char* name(int x) { return x == 0 ? "the first polygon" : "the second polygon"; }
  std::string where(int x, int k) const
  {
    const Point_info& i = in_[x]->info[std::size_t(k)];
    const std::string ring = std::string(name(x)) + " ring " + std::to_string(i.ring);
    if(origin_[x].empty() || i.ring < 0)
      return ring + " vertex " + std::to_string(i.index);
    // a noded copy: named as the polygon was given
    const int o = origin_[x][std::size_t(i.ring)][std::size_t(i.index)];
    return o >= 0 ? ring + " vertex " + std::to_string(o) : ring + " edge " + std::to_string(-1 - o) + ", at a T inside it";
  }
  std::array<double, 4> key(const Point_2& p, const Point_2& q) const
  {
    return {{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(q.x()), CGAL::to_double(q.y())}};
  }

  // The axis of a whole polygon (not of a step of a progressive run): every
  // polygon edge is a cell with its boundary half-edge on the border.  Notes
  // the boundary half-edge of every edge (by the corner it starts at).
  void check_complete(int x)
  {
    const Input_error not_whole(std::string("the medial axis of ") + name(x) +
                                " is not the axis of a whole polygon (a step of a progressive computation?)");
    const Hds& hds = in_[x]->hds;
    boundary_[x].assign(std::size_t(corners(x)), NO_INDEX);
    int found = 0;
    for(int h = 0; h < int(hds.halfedge_capacity()); ++h) {
      if(hds.is_deleted(h) || hds.face_of(h ^ 1) != OUTSIDE || hds.face_of(h) < 0) continue;
      const Hds_face& f = hds.face(hds.face_of(h));
      if(f.is_point || f.p0 < 0 || f.p0 >= corners(x) || next(x, f.p0) != f.p1 || boundary_[x][std::size_t(f.p0)] != NO_INDEX)
        throw not_whole;
      boundary_[x][std::size_t(f.p0)] = h;
      ++found;
    }
    if(found != corners(x))
      throw not_whole;
  }

  // shared_[x][k]: the edge of the other polygon that is the edge from
  // corner k of polygon x, reversed (by the corner it starts at), or NO_INDEX.
  void find_shared_edges()
  {
    std::unordered_multimap<std::array<double, 4>, int, Edge_key_hash> edges_b;
    edges_b.reserve(std::size_t(corners(1)));
    for(int m = 0; m < corners(1); ++m) edges_b.emplace(key(place(1, m), place(1, next(1, m))), m);
    shared_[0].assign(std::size_t(corners(0)), NO_INDEX);
    shared_[1].assign(std::size_t(corners(1)), NO_INDEX);
    auto find_b = [&](const Point_2& p, const Point_2& q) {
      auto range = edges_b.equal_range(key(p, q));
      for(auto it = range.first; it != range.second; ++it)
        if(place(1, it->second) == p && place(1, next(1, it->second)) == q) return it->second;
      return int(NO_INDEX);
    };
    bool any = false;
    for(int k = 0; k < corners(0); ++k) {
      const Point_2 &p = place(0, k), &q = place(0, next(0, k));
      const int same = find_b(p, q);
      if(same != NO_INDEX)
        throw Input_error("the polygons overlap: the edge from " + where(0, k) + " is also an edge of " + where(1, same) +
                          ", in the same direction");
      const int m = find_b(q, p);
      if(m != NO_INDEX) {
        shared_[0][std::size_t(k)] = m;
        shared_[1][std::size_t(m)] = k;
        any = true;
      }
    }
    if(!any)
      throw Input_error("the polygons share no edge: a union is merged along common chains of edges (the same points, in opposite directions)");
    // the chains, in the order of the first polygon's edges
    for(int k = 0; k < corners(0); ++k) {
      if(shared_[0][std::size_t(k)] == NO_INDEX || shared_[0][std::size_t(prev(0, k))] != NO_INDEX) continue;
      chains_.emplace_back();
      for(int e = k; shared_[0][std::size_t(e)] != NO_INDEX; e = next(0, e)) chains_.back().push_back(e);
    }
    std::vector<char> in_chain(std::size_t(corners(0)), 0);
    for(const auto& c : chains_)
      for(int e : c) in_chain[std::size_t(e)] = 1;
    const std::size_t cyclic_from = chains_.size();
    for(int k = 0; k < corners(0); ++k) {   // whole rings shared (a hole filled exactly)
      if(shared_[0][std::size_t(k)] == NO_INDEX || in_chain[std::size_t(k)]) continue;
      chains_.emplace_back();
      for(int e = k; !in_chain[std::size_t(e)]; e = next(0, e)) {
        in_chain[std::size_t(e)] = 1;
        chains_.back().push_back(e);
      }
    }
    // A ring shared as a whole (the second polygon fills a hole of the
    // first exactly, or the other way round): its last edge would be a crack
    // with both ends inside the union, which the merge does not close.  The
    // union is found and validated all the same, and its axis computed in
    // one shot (see one_shot_needed()).
    if(chains_.size() > cyclic_from) one_shot_needed_ = true;
  }

  // The ends of input edge `index` of ring `ring` of polygon x (as written),
  // in the direction of x's interior.
  std::pair<int, int> input_edge_ends(int x, int ring, int index) const
  {
    const Data& d = *in_[x];
    const int base = d.ring_start[std::size_t(ring)], m = d.ring_start[std::size_t(ring) + 1] - base;
    const int from = base + index, to = base + (index + 1) % m;
    return d.info[std::size_t(base)].reversed ? std::make_pair(to, from) : std::make_pair(from, to);
  }

  // Calls f(edge_ring, edge_index, from, to, c) for each half of an input
  // edge that polygon x splits at a T of its own (see corners()): the edge
  // as written, its ends in the direction of x's interior, and the corner at
  // the T's place.  (The halves of a split edge keep its input edge; at a T
  // the corners' outgoing edges are re-linked, so an added corner need not
  // start a half of the edge it splits: the halves are found by their ends.)
  template <class F>
  void for_each_split_half(int x, const F& f) const
  {
    const Data& d = *in_[x];
    if(corners(x) == d.ring_start.back()) return;
    for(int k = 0; k < corners(x); ++k) {
      const Point_info& i = d.info[std::size_t(k)];
      const std::pair<int, int> e = input_edge_ends(x, i.edge_ring, i.edge_index);
      const int from = e.first, to = e.second;
      const bool split_at_k = !(place(x, k) == place(x, from));
      if(!split_at_k && place(x, next(x, k)) == place(x, to)) continue;
      f(i.edge_ring, i.edge_index, from, to, split_at_k ? k : next(x, k));
    }
  }

  // An edge that one polygon splits at a T of its own and that the other
  // polygon has whole, reversed, or splits at other places: a T on a shared
  // edge.  The two do not share that edge edge for edge.  The union is found
  // with a copy of the other polygon noded there (the place added to the
  // edge as a vertex), and at its own T's too (as a polygon's own T's are in
  // a merged union; a copy has no split edges, see set_points()); in_[y]
  // then points to that copy, and messages name the vertices as given.  Its axis is
  // computed in one shot: the merges would have to split that edge's cell.
  void node_split_shared_edges()
  {
    // for each polygon y, the places to add inside its edges: (ring, written index of the edge) -> places
    std::map<std::pair<int, int>, std::vector<Point_2> > add[2];
    auto node = [&](int y, int edge_ring, int edge_index, const Point_2& t) {
      add_once(add[y][std::make_pair(edge_ring, edge_index)], t);
    };
    // each polygon's split input edges: (ring, written index) -> its ends (in
    // the direction of the interior) and the places of its T's
    struct Split_edge {
      int from, to;
      std::vector<Point_2> at;
    };
    std::map<std::pair<int, int>, Split_edge> split[2];
    for(int x = 0; x < 2; ++x)
      for_each_split_half(x, [&](int edge_ring, int edge_index, int from, int to, int c) {
        Split_edge& e = split[x].emplace(std::make_pair(edge_ring, edge_index), Split_edge{from, to, {}}).first->second;
        add_once(e.at, place(x, c));
      });
    // the other polygon's input edge with the same ends, reversed, is noded at
    // the T's it does not have (whether it is split elsewhere or not)
    for(int x = 0; x < 2; ++x) {
      const int y = 1 - x;
      if(split[x].empty()) continue;
      std::unordered_multimap<std::array<double, 4>, std::pair<int, int>, Edge_key_hash> edges_y;   // y's input edges by their ends
      const Data& dy = *in_[y];
      for(int r = 0; r + 1 < int(dy.ring_start.size()); ++r)
        for(int i = 0; i < dy.ring_start[std::size_t(r) + 1] - dy.ring_start[std::size_t(r)]; ++i) {
          const std::pair<int, int> e = input_edge_ends(y, r, i);
          edges_y.emplace(key(place(y, e.first), place(y, e.second)), std::make_pair(r, i));
        }
      for(const auto& se : split[x]) {
        const Point_2 &p = place(x, se.second.from), &q = place(x, se.second.to);
        auto range = edges_y.equal_range(key(q, p));
        for(auto it = range.first; it != range.second; ++it) {
          const std::pair<int, int> e = input_edge_ends(y, it->second.first, it->second.second);
          if(!(place(y, e.first) == q && place(y, e.second) == p)) continue;
          auto other = split[y].find(it->second);
          for(const Point_2& t : se.second.at)
            if(other == split[y].end() || std::find(other->second.at.begin(), other->second.at.end(), t) == other->second.at.end())
              node(y, it->second.first, it->second.second, t);
        }
      }
    }
    for(int y = 0; y < 2; ++y) {   // a noded copy is noded at its own T's too
      if(add[y].empty()) continue;
      for(const auto& se : split[y])
        for(const Point_2& t : se.second.at) node(y, se.first.first, se.first.second, t);
    }
    for(int y = 0; y < 2; ++y) {
      if(add[y].empty()) continue;
      noded_[y] = std::make_shared<Data>();
      set_points(*noded_[y], with_nodes(input_rings(*in_[y]), add[y], &origin_[y]), traits_.orientation_2_object());
      in_[y] = noded_[y].get();
      count_corners(y);
      prev_[y].clear();
      one_shot_needed_ = true;
    }
  }

  // Adds place p to the places `at` unless it is there already.
  static void add_once(std::vector<Point_2>& at, const Point_2& p)
  {
    if(std::find(at.begin(), at.end(), p) == at.end()) at.push_back(p);
  }

  // `rings` with places added inside their edges: `add` maps an edge (the
  // ring and index of its first vertex) to places inside it, in any order.
  // With `origin`, what each vertex of the result was: its index in `rings`,
  // or -1 - e for a place added inside edge e.
  static std::vector<std::vector<Point_2> > with_nodes(const std::vector<std::vector<Point_2> >& rings,
                                                       const std::map<std::pair<int, int>, std::vector<Point_2> >& add,
                                                       std::vector<std::vector<int> >* origin = nullptr)
  {
    std::vector<std::vector<Point_2> > noded;
    if(origin) origin->assign(rings.size(), std::vector<int>());
    for(std::size_t r = 0; r < rings.size(); ++r) {
      const std::size_t m = rings[r].size();
      noded.emplace_back();
      for(std::size_t i = 0; i < m; ++i) {
        const Point_2& b = rings[r][(i + 1) % m];
        noded.back().push_back(rings[r][i]);
        if(origin) (*origin)[r].push_back(int(i));
        auto it = add.find(std::make_pair(int(r), int(i)));
        if(it == add.end()) continue;
        std::vector<Point_2> at = it->second;   // in order along the edge, towards b
        std::sort(at.begin(), at.end(), [&](const Point_2& u, const Point_2& v) {
          return Kernel().collinear_are_strictly_ordered_along_line_2_object()(u, v, b);
        });
        noded.back().insert(noded.back().end(), at.begin(), at.end());
        if(origin) (*origin)[r].insert((*origin)[r].end(), at.size(), -1 - int(i));
      }
    }
    return noded;
  }

  int prev(int x, int k) const
  {
    if(prev_[x].empty()) {
      prev_[x].assign(std::size_t(corners(x)), NO_INDEX);
      for(int i = 0; i < corners(x); ++i) prev_[x][std::size_t(next(x, i))] = i;
    }
    return prev_[x][std::size_t(k)];
  }

  // The corner of the other polygon that corner k of x continues into,
  // across its outgoing edge (which is shared).
  std::pair<int, int> across(int x, int k) const
  {
    return std::make_pair(1 - x, next(1 - x, shared_[x][std::size_t(k)]));
  }

  // group_[x][k]: the corner of the union that corner k of polygon x is part of.
  void group_corners()
  {
    for(int x = 0; x < 2; ++x) group_[x].assign(std::size_t(corners(x)), NO_INDEX);
    for(int x = 0; x < 2; ++x)
      for(int k = 0; k < corners(x); ++k) {
        if(shared_[x][std::size_t(prev(x, k))] != NO_INDEX) continue;   // incoming edge shared: not a first corner
        const int g = int(groups_.size());
        groups_.push_back(Group{x, k, x, k, false});
        std::pair<int, int> c(x, k);
        group_[x][std::size_t(k)] = g;
        while(shared_[c.first][std::size_t(c.second)] != NO_INDEX) {
          c = across(c.first, c.second);
          group_[c.first][std::size_t(c.second)] = g;
        }
        groups_[std::size_t(g)].last_x = c.first;
        groups_[std::size_t(g)].last = c.second;
      }
    for(int x = 0; x < 2; ++x)   // closed chains of corners: points inside the union
      for(int k = 0; k < corners(x); ++k) {
        if(group_[x][std::size_t(k)] != NO_INDEX) continue;
        const int g = int(groups_.size());
        groups_.push_back(Group{x, k, x, k, true});
        std::pair<int, int> c(x, k);
        do {
          group_[c.first][std::size_t(c.second)] = g;
          c = across(c.first, c.second);
        } while(group_[c.first][std::size_t(c.second)] == NO_INDEX);
      }
  }

  // The group that follows group g along the union's boundary.
  int next_group(int g) const
  {
    const Group& G = groups_[std::size_t(g)];
    return group_[G.last_x][std::size_t(next(G.last_x, G.last))];
  }

  bool counterclockwise(const std::vector<int>& cycle) const
  {
    return ring_counterclockwise(cycle.size(), [&](std::size_t i) -> const Point_2& { return group_place(cycle[i]); },
                                 traits_.orientation_2_object());
  }
  const Point_2& group_place(int g) const { return place(groups_[std::size_t(g)].first_x, groups_[std::size_t(g)].first); }
  bool smaller(const Point_2& p, const Point_2& q) const { return p.x() < q.x() || (p.x() == q.x() && p.y() < q.y()); }

  // The union's rings (outer ring first), as (polygon, corner) of the first
  // corner of each of their groups.
  std::vector<std::vector<std::pair<int, int> > > union_rings()
  {
    std::vector<std::vector<int> > cycles;
    std::vector<char> seen(groups_.size(), 0);
    for(int g = 0; g < int(groups_.size()); ++g) {
      if(seen[std::size_t(g)] || groups_[std::size_t(g)].closed) continue;
      cycles.emplace_back();
      for(int h = g; !seen[std::size_t(h)]; h = next_group(h)) {
        seen[std::size_t(h)] = 1;
        cycles.back().push_back(h);
      }
    }
    split_clockwise_loops(cycles, [&](int g) -> const Point_2& { return group_place(g); });
    std::vector<char> ccw(cycles.size());
    for(std::size_t i = 0; i < cycles.size(); ++i) ccw[i] = counterclockwise(cycles[i]);
    // the outer ring: the counter-clockwise cycle with the smallest point
    // (the outer candidate's smallest point kept, not found again for each cycle)
    std::size_t outer = cycles.size();
    const Point_2* outer_min = nullptr;
    for(std::size_t i = 0; i < cycles.size(); ++i) {
      if(!ccw[i]) continue;
      const Point_2& m = min_place(cycles[i]);
      if(outer == cycles.size() || smaller(m, *outer_min)) {
        outer = i;
        outer_min = &m;
      }
    }
    if(outer == cycles.size())
      throw Input_error("the union is not a valid polygon: it has no outer ring");
    std::swap(cycles[0], cycles[outer]);
    // lobes (the union is pinched): spliced into the outer ring where they touch it
    splice_lobes(cycles, [&](int u, int v) { return group_place(u) == group_place(v); },
                 [&](const std::vector<int>& c) { return counterclockwise(c); });
    for(std::size_t i = 1; i < cycles.size(); ++i)
      if(counterclockwise(cycles[i]))
        throw Input_error("the union is not a valid polygon: its interior is not connected (at " +
                          where(groups_[std::size_t(cycles[i][0])].first_x, groups_[std::size_t(cycles[i][0])].first) + ")");
    // each ring from its first corner in input order (the first polygon's,
    // then the second's), the holes in the order of those corners
    auto rank = [&](int g) { return std::make_pair(groups_[std::size_t(g)].first_x, groups_[std::size_t(g)].first); };
    in_input_order(cycles, rank);
    std::vector<std::vector<std::pair<int, int> > > rings;
    for(const std::vector<int>& c : cycles) {
      rings.emplace_back();
      for(int g : c) rings.back().push_back(rank(g));
    }
    return rings;
  }
  // Each cycle rotated to start at its element of smallest rank (its first
  // corner in input order), and the cycles after the first (the holes)
  // sorted by the ranks of their first elements.
  template <class Rank>
  static void in_input_order(std::vector<std::vector<int> >& cycles, const Rank& rank)
  {
    for(std::vector<int>& c : cycles)
      std::rotate(c.begin(), std::min_element(c.begin(), c.end(), [&](int u, int v) { return rank(u) < rank(v); }), c.end());
    std::sort(cycles.begin() + 1, cycles.end(), [&](const std::vector<int>& u, const std::vector<int>& v) { return rank(u[0]) < rank(v[0]); });
  }

  // OGC's form of the union's rings.  Where a cycle passes one place twice
  // and the loop between the two passes runs clockwise (a hole that touches
  // the outer ring at a point, or two holes that touch), that loop becomes a
  // ring of its own, a hole.  A loop that runs counter-clockwise (a lobe of a
  // pinched union) stays in its cycle: one polygon has no other form for it.
  // Each cycle is walked from its smallest place, which lies on its outer
  // side (its convex hull); a stack holds the walk with the loops taken out,
  // and the sums of its edges' cross products give each loop's area,
  // exactly (for points of doubles).  Linear in the size of the cycles that
  // pass a place twice, but for places passed many times.
  //
  // `place(i)` is the place of element i of a cycle.
  template <class Place>
  void split_clockwise_loops(std::vector<std::vector<int> >& cycles, const Place& place) const
  {
    typedef std::array<double, 2> Key;
    struct Key_hash {
      std::size_t operator()(const Key& k) const { return std::hash<double>()(k[0]) * 1000003u ^ std::hash<double>()(k[1]); }
    };
    auto key_of = [&](int g) { return Key{{CGAL::to_double(place(g).x()), CGAL::to_double(place(g).y())}}; };
    // (the type named: with gmpxx an expression would refer to dead temporaries)
    auto cross = [&](int u, int v) -> CGAL::Exact_rational {
      const Point_2 &p = place(u), &q = place(v);
      return CGAL::Exact_rational(CGAL::to_double(p.x())) * CGAL::Exact_rational(CGAL::to_double(q.y())) -
             CGAL::Exact_rational(CGAL::to_double(p.y())) * CGAL::Exact_rational(CGAL::to_double(q.x()));
    };
    const std::size_t count = cycles.size();
    for(std::size_t i = 0; i < count; ++i) {
      std::unordered_multimap<Key, std::size_t, Key_hash> at;   // place -> positions in the cycle, then in the stack
      at.reserve(cycles[i].size());
      bool twice = false;
      for(std::size_t k = 0; k < cycles[i].size(); ++k) {
        const int g = cycles[i][k];
        auto range = at.equal_range(key_of(g));
        for(auto it = range.first; it != range.second && !twice; ++it) twice = place(cycles[i][it->second]) == place(g);
        at.emplace(key_of(g), k);
      }
      if(!twice) continue;
      std::vector<int> c = cycles[i];
      std::rotate(c.begin(), std::min_element(c.begin(), c.end(), [&](int u, int v) { return smaller(place(u), place(v)); }), c.end());
      std::vector<std::size_t> passes;   // of the smallest place
      for(std::size_t k = 0; k < c.size(); ++k)
        if(place(c[k]) == place(c[0])) passes.push_back(k);
      if(passes.size() > 1) {
        // A hole touches the cycle at its smallest place: the walk between
        // two passes of it is a loop.  Start where a counter-clockwise one
        // ends, so that it comes last, and stays; the others are taken out.
        for(std::size_t a = 0; a < passes.size(); ++a) {
          const std::size_t b = a + 1 < passes.size() ? passes[a + 1] : c.size();
          CGAL::Exact_rational twice_area = 0;
          for(std::size_t k = passes[a]; k < b; ++k) twice_area += cross(c[k], c[(k + 1) % c.size()]);
          if(CGAL::is_positive(twice_area)) {
            std::rotate(c.begin(), c.begin() + std::ptrdiff_t(b % c.size()), c.end());
            break;
          }
        }
      }
      at.clear();
      std::vector<int> stack;
      std::vector<CGAL::Exact_rational> sum;   // sum[t]: cross products of the stack's edges up to stack[t]
      for(int g : c) {
        std::size_t j = stack.size();   // the latest position of g's place in the stack
        auto range = at.equal_range(key_of(g));
        for(auto it = range.first; it != range.second; ++it)
          if(it->second < stack.size() && place(stack[it->second]) == place(g) && (j == stack.size() || it->second > j))
            j = it->second;
        if(j < stack.size() && CGAL::is_negative(CGAL::Exact_rational(sum.back() + cross(stack.back(), g) - sum[j]))) {
          // a clockwise loop, stack[j] .. the top: a ring of its own
          cycles.emplace_back(stack.begin() + std::ptrdiff_t(j), stack.end());
          stack.resize(j);
          sum.resize(j);
        }
        sum.push_back(stack.empty() ? CGAL::Exact_rational(0) : CGAL::Exact_rational(sum.back() + cross(stack.back(), g)));
        at.emplace(key_of(g), stack.size());
        stack.push_back(g);
      }
      cycles[i].swap(stack);
    }
  }
  const Point_2& min_place(const std::vector<int>& cycle) const
  {
    const Point_2* m = &group_place(cycle[0]);
    for(int g : cycle)
      if(smaller(group_place(g), *m)) m = &group_place(g);
    return *m;
  }

  // The union's points: its rings, validated, then the places inside the
  // shared chains; and the union corner of every corner of the two polygons.
  void build_points(Data& data, const std::vector<std::vector<std::pair<int, int> > >& rings)
  {
    std::vector<std::vector<Point_2> >& points = rings_;
    points.clear();
    for(const auto& r : rings) {
      points.emplace_back();
      for(const auto& c : r) points.back().push_back(place(c.first, c.second));
    }
    bool t = false;
    std::vector<std::pair<int, int> > on, edges;
    try {
      t = validate_and_find_vertices_on_edges(points, &on, &edges);
    } catch(const Input_error& e) {
      throw Input_error(std::string("the union is not a valid polygon: ") + e.what());
    }
    if(t) {
      // A T that only the union has.  The merges along the shared chains
      // would have to split the edge's cells there (see one_shot_needed()).
      // The union polygon is noded there instead (the place added to the
      // edge as a vertex, as GEOS's overlays do) and put in OGC's form: where
      // a ring touched its own edge, it now passes the place twice, and a
      // clockwise loop between the two passes becomes a hole.  The rings are
      // then numbered as union_rings() numbers them: each from its vertex
      // that comes first in input order (an added place is the T's vertex),
      // the holes in the order of those vertices.
      std::map<std::pair<int, int>, std::vector<Point_2> > add;
      std::vector<std::pair<Point_2, std::pair<int, int> > > rank_at;   // a T's place, its first corner in input order
      for(std::size_t i = 0; i < on.size(); ++i) {
        const Point_2& p = points[std::size_t(on[i].first)][std::size_t(on[i].second)];
        const std::pair<int, int>& r = rings[std::size_t(on[i].first)][std::size_t(on[i].second)];
        add_once(add[edges[i]], p);
        auto it = std::find_if(rank_at.begin(), rank_at.end(), [&](const auto& x) { return x.first == p; });
        if(it == rank_at.end()) rank_at.emplace_back(p, r);
        else it->second = (std::min)(it->second, r);
      }
      std::vector<std::vector<int> > origin;
      const std::vector<std::vector<Point_2> > noded = with_nodes(points, add, &origin);
      std::vector<Point_2> flat;
      std::vector<std::pair<int, int> > rank;   // of each point of flat
      std::vector<std::vector<int> > cycles;
      for(std::size_t r = 0; r < noded.size(); ++r) {
        cycles.emplace_back();
        for(std::size_t j = 0; j < noded[r].size(); ++j) {
          const Point_2& p = noded[r][j];
          const int o = origin[r][j];
          cycles.back().push_back(int(flat.size()));
          flat.push_back(p);
          rank.push_back(o >= 0 ? rings[r][std::size_t(o)]
                                : std::find_if(rank_at.begin(), rank_at.end(), [&](const auto& x) { return x.first == p; })->second);
        }
      }
      split_clockwise_loops(cycles, [&](int i) -> const Point_2& { return flat[std::size_t(i)]; });
      in_input_order(cycles, [&](int i) { return rank[std::size_t(i)]; });
      points.clear();
      for(const std::vector<int>& c : cycles) {
        points.emplace_back();
        for(int i : c) points.back().push_back(flat[std::size_t(i)]);
      }
      one_shot_needed_ = true;
      return;
    }
    set_points(data, points, traits_.orientation_2_object());
    // a group's union corner: the union point whose outgoing edge is the
    // group's (an edge leaves one corner only)
    std::unordered_map<std::array<double, 4>, int, Edge_key_hash> by_edge;
    by_edge.reserve(data.points.size());
    for(int u = 0; u < int(data.points.size()); ++u)
      by_edge.emplace(key(data.points[std::size_t(u)], data.points[std::size_t(data.info[std::size_t(u)].next)]), u);
    std::vector<int> corner_of(groups_.size(), NO_INDEX);
    for(std::size_t g = 0; g < groups_.size(); ++g) {
      const Group& G = groups_[g];
      if(G.closed) {
        corner_of[g] = int(data.points.size());
        data.points.push_back(place(G.first_x, G.first));
        data.info.emplace_back();   // ring -1: not a vertex of the union
        continue;
      }
      auto it = by_edge.find(key(place(G.last_x, G.last), place(G.last_x, next(G.last_x, G.last))));
      CGAL_assertion(it != by_edge.end());
      corner_of[g] = it->second;
    }
    for(int x = 0; x < 2; ++x) {
      map_[x].assign(in_[x]->points.size(), NO_INDEX);
      for(int k = 0; k < corners(x); ++k) map_[x][std::size_t(k)] = corner_of[std::size_t(group_[x][std::size_t(k)])];
    }
  }

  // The two structures in one, renumbered.
  void join(Data& data)
  {
    data.hds = in_[0]->hds;
    Hds b = in_[1]->hds;
    const std::size_t faces_a = data.hds.face_capacity(), vertices_a = data.hds.vertex_capacity(),
                      disks_a = data.hds.disk_capacity();
    const typename Hds::Offsets o = data.hds.append(b);
    offset_ = o.halfedge;
    auto renumber = [&](int x, int& i) {
      if(i >= 0) i = std::size_t(i) < map_[x].size() ? map_[x][std::size_t(i)] : NO_INDEX;
    };
    for(std::size_t f = 0; f < data.hds.face_capacity(); ++f) {
      Hds_face& F = data.hds.face(int(f));
      const int x = f < faces_a ? 0 : 1;
      int p[2] = {F.p0, F.p1};   // (bit-fields)
      renumber(x, p[0]);
      renumber(x, p[1]);
      F.p0 = p[0];
      F.p1 = p[1];
    }
    for(std::size_t v = 0; v < data.hds.vertex_capacity(); ++v) {
      auto& V = data.hds.vertex(int(v));
      if(!V.is_corner()) continue;
      // (every corner has a point of the union: build_points() gives one to
      // the closed chains of corners too)
      int input_point = V.input_point();
      renumber(v < vertices_a ? 0 : 1, input_point);
      V.set_input_point(input_point);
    }
    for(std::size_t d = 0; d < data.hds.disk_capacity(); ++d) {
      const int x = d < disks_a ? 0 : 1;
      for(auto& t : data.hds.disk_record(d).triple) {
        renumber(x, t[0]);
        renumber(x, t[1]);
      }
    }
  }

  // No cell and no vertex of the result refers to a place inside a shared
  // chain, and no shared edge is left on the border.
  void check_result(const Data& data) const
  {
    const int n = data.ring_start.back();
    for(std::size_t f = 0; f < data.hds.face_capacity(); ++f) {
      const Hds_face& F = data.hds.face(int(f));
      CGAL_assertion_msg(!F.alive || (F.p0 < n && F.p1 < n), "a cell of a point inside a shared chain is left");
      CGAL_USE(F);
    }
    for(std::size_t v = 0; v < data.hds.vertex_capacity(); ++v) {
      const auto& V = data.hds.vertex(int(v));
      CGAL_assertion_msg(!V.alive || V.halfedge == NO_INDEX || V.input_point() < n, "a corner inside a shared chain is left");
      CGAL_USE(V);
    }
    CGAL_USE(n);
  }

  struct Group {
    int first_x, first;   // its first corner (incoming edge not shared)
    int last_x, last;     // its last corner (outgoing edge not shared)
    bool closed;          // a point inside the union
  };

  const Traits& traits_;
  const Data* in_[2];
  int corners_[2];
  std::shared_ptr<Data> noded_[2];   // copies noded at T's on shared edges (see node_split_shared_edges())
  std::vector<std::vector<int> > origin_[2];   // of a noded copy's vertices, by ring (see with_nodes())
  std::vector<int> boundary_[2], shared_[2], group_[2], map_[2];
  mutable std::vector<int> prev_[2];
  std::vector<Group> groups_;
  std::vector<std::vector<int> > chains_;
  std::vector<std::vector<Point_2> > rings_;   // the union polygon
  bool one_shot_needed_ = false;
  int offset_ = 0;
};

} // namespace internal
} // namespace Progressive_medial_axes
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_MEDIAL_AXIS_2_INTERNAL_UNION_H
