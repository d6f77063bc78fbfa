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
// The boundary-evolution driver (Liu et al. 2016, section 6.2): the
// polygon is simplified by discrete curve evolution (Curve_evolution.h);
// step 0 is the medial axis of the coarsest shape, and every later step
// undoes one removal, the last one first.  A removal of vertex v between u
// and w replaced the edges uv and vw by uw; putting v back
//   - adds the triangle (u, v, w) outside the shape if u, v, w turn left
//     (the interior on the left): a merge along uw, the engine's merge;
//   - cuts the triangle out of the shape if they turn right: the local
//     update of Medial_cut (in the style of Sugihara and Iri);
//   - splits the edge uw at v if they are collinear (Medial_cut::split).
//
// Holes.  The evolution simplifies every hole down to a triangle but does
// not fill it: a hole is there from step 0 on, as a triangle, and grows
// vertex by vertex like the outer ring.  (Filling a triangular hole would
// make its return the insertion of a hole into the interior, whose
// conflict region need not contain a vertex of the axis: finding it is a
// point location, not a local walk.)  The outer ring's evolution stops
// where the holes block it.
//
// The axis of the coarsest shape is computed by the one-shot divide and
// conquer over a constrained Delaunay triangulation of that shape (in
// parallel with oneTBB, on the threads of the current task arena); so is the
// axis of a step whose cut is not local (the new cells would surround the
// cells of a small hole, see Medial_cut.h), which is rare.

#ifndef CGAL_PROGRESSIVE_MEDIAL_AXIS_2_INTERNAL_BOUNDARY_EVOLUTION_H
#define CGAL_PROGRESSIVE_MEDIAL_AXIS_2_INTERNAL_BOUNDARY_EVOLUTION_H

#include <CGAL/Progressive_medial_axis_2/internal/Curve_evolution.h>
#include <CGAL/Progressive_medial_axis_2/internal/Divide_and_conquer.h>
#include <CGAL/Progressive_medial_axis_2/internal/Medial_axis_engine.h>
#include <CGAL/Progressive_medial_axis_2/internal/Triangulate.h>

#include <array>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Progressive_medial_axes {
namespace internal {

template <class Traits>
class Boundary_evolution
{
public:
  typedef Medial_axis_engine<Traits> Engine;
  typedef typename Traits::Kernel Kernel;
  typedef typename Kernel::Point_2 Point_2;

  typedef typename Curve_evolution<Kernel>::Removal Removal;

  /// The curve evolution of `rings` (holes kept as triangles);
  /// `vertices_on_edges` as the validator found them, if it ran (else the
  /// evolution finds them).  It needs only the rings: it may run while the
  /// engine's data is set from them.
  static std::vector<Removal> evolve(const std::vector<std::vector<Point_2> >& rings,
                                     const std::vector<std::pair<int, int> >* vertices_on_edges = nullptr)
  {
    Curve_evolution<Kernel> evolution(rings, Kernel(), false, vertices_on_edges);
    evolution.run();
    return evolution.take_removals();
  }

  /// The driver over `engine`, whose data was set from the rings that
  /// `evolve()` simplified into `removals`.
  Boundary_evolution(Engine& engine, std::vector<Removal>&& removals)
    : engine_(engine), removals_(std::move(removals)), info_(engine.data().info)
  {}

  std::size_t number_of_steps() const { return removals_.size(); }
  /// Vertices of the coarsest shape.
  std::size_t number_of_coarse_vertices() const { return coarse_vertices_; }
  /// Triangles of the coarsest shape's triangulation.
  std::size_t number_of_triangles() const { return triangles_; }
  const Divide_and_conquer_counts& start_counts() const { return start_counts_; }

  /// Builds step 0: the axis of the coarsest shape.
  void start()
  {
    const std::size_t n = engine_.data().points.size();
    alive_.assign(n, 1);
    for(const auto& r : removals_) alive_[std::size_t(global(r.ring, r.vertex))] = 0;
    for(char a : alive_) coarse_vertices_ += a ? 1 : 0;
    start_counts_ = build();
  }

  /// Cuts that were not local (see Medial_cut::cut()): the axis of the
  /// step was computed again in one shot.
  std::size_t recomputed_steps() const { return recomputed_; }

  /// Does step k >= 1: puts back the vertex of removal m - k.  Returns the
  /// largest queue size n_v of its merge (0 for a cut or a split).
  template <class Visitor>
  std::size_t step(std::size_t k, Visitor& visitor)
  {
    const auto& r = removals_[removals_.size() - k];
    const auto& data = engine_.data();
    const int V = global(r.ring, r.vertex);
    int U = global(r.ring, r.prev), W = global(r.ring, r.next);
    if(data.info[std::size_t(V)].reversed) std::swap(U, W);
    alive_[std::size_t(V)] = 1;
    const int b = out_[std::size_t(U)];
    CGAL_assertion(b != NO_INDEX && engine_.hds().vertex(engine_.hds().target(b)).input_point() == W);
    const auto& p = data.points;
    const Orientation turn = engine_.traits().orientation_2_object()(p[std::size_t(U)], p[std::size_t(V)], p[std::size_t(W)]);
    std::size_t n_v = 0;
    std::pair<int, int> sides;
    if(turn == LEFT_TURN) {
      const int tri[3] = {W, U, V};   // counter-clockwise: the triangle lies right of uw
      const std::array<int, 3> s = engine_.add_triangle_across(tri, 2, b);
      const Merge_statistics ms = engine_.merge(b, s[2], visitor);
      visitor.on_merge(ms);
      n_v = ms.max_queue;
      sides = std::make_pair(s[0], s[1]);
    } else {
      Cut_statistics cs;
      sides = turn == RIGHT_TURN ? engine_.cut(b, V, cs) : engine_.split(b, V, cs);
      visitor.on_cut(turn == RIGHT_TURN, cs);
      if(sides.first == NO_INDEX) {
        // the new cells enclose old ones (a small hole near the cut): the
        // axis of this step in one shot
        ++recomputed_;
        build();
        return 0;
      }
    }
    out_[std::size_t(U)] = sides.first;
    out_[std::size_t(V)] = sides.second;
    return n_v;
  }

private:
  int global(int ring, int index) const { return engine_.data().ring_start[std::size_t(ring)] + index; }

  // Computes the axis of the shape of the live points in one shot, into the
  // engine's (emptied) structure.
  Divide_and_conquer_counts build()
  {
    auto& data = engine_.data();
    const std::size_t n = alive_.size();
    data.hds = typename Engine::Hds();
    data.hds.reserve_for_points(n);
    // the input points alone (without those a triangulation added at T's)
    data.points.resize(n);
    data.info = info_;
    // the successors in this shape: the next live point along the polygon
    std::vector<int> coarse_next(n, -1);
    for(std::size_t g = 0; g < n; ++g) {
      if(!alive_[g]) continue;
      int s = data.info[g].next;
      while(!alive_[std::size_t(s)]) s = data.info[std::size_t(s)].next;
      coarse_next[g] = s;
    }
    for(std::size_t g = 0; g < n; ++g) data.info[g].next = coarse_next[g];
    std::vector<Triangle> triangles = triangulate_rings<Kernel>(data);
    triangles_ = triangles.size();
    // back to the whole polygon, but where the triangulation split an edge
    // at a T (those places are never evolved: the same in both)
    for(std::size_t g = 0; g < n; ++g)
      if(data.info[g].next == coarse_next[g]) data.info[g] = info_[g];
    const Divide_and_conquer_counts counts = divide_and_conquer(engine_, std::move(triangles));
    // the boundary half-edge leaving each corner
    const auto& hds = engine_.hds();
    out_.assign(data.points.size(), NO_INDEX);
    for(int h = 0; h < int(hds.halfedge_capacity()); ++h)
      if(!hds.is_deleted(h) && hds.face_of(h) >= 0 && hds.face_of(h ^ 1) == OUTSIDE)
        out_[std::size_t(hds.vertex(hds.source(h)).input_point())] = h;
    return counts;
  }

  Engine& engine_;
  std::vector<Removal> removals_;
  std::vector<Point_info> info_;   // the input points' information, as set_points() made it
  std::vector<char> alive_;        // the points of the current shape
  std::size_t recomputed_ = 0;
  std::vector<int> out_;   // the boundary half-edge leaving each corner of the current shape
  std::size_t coarse_vertices_ = 0, triangles_ = 0;
  Divide_and_conquer_counts start_counts_;
};

} // namespace internal
} // namespace Progressive_medial_axes
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_MEDIAL_AXIS_2_INTERNAL_BOUNDARY_EVOLUTION_H
