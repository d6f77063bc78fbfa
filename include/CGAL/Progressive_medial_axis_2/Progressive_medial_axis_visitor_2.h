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

#ifndef CGAL_PROGRESSIVE_MEDIAL_AXIS_2_PROGRESSIVE_MEDIAL_AXIS_VISITOR_2_H
#define CGAL_PROGRESSIVE_MEDIAL_AXIS_2_PROGRESSIVE_MEDIAL_AXIS_VISITOR_2_H

#include <CGAL/license/Progressive_medial_axis_2.h>

#include <CGAL/Progressive_medial_axis_2/Merge_statistics.h>

#include <cstddef>
#include <optional>

namespace CGAL {

/*!
\ingroup PkgProgressiveMedialAxis2Ref
Counters and timings of a progressive computation.  Per-step figures (the
queue size of every step, times) are given to a visitor, see
`ProgressiveMedialAxisVisitor_2`.
*/
struct Progressive_medial_axis_statistics {
  std::size_t input_vertices = 0;
  std::size_t holes = 0;
  std::size_t triangles = 0;
  std::size_t merges = 0;          ///< merges done (one per shared edge of each triangle added)
  double validation_seconds = 0;   ///< the check of the input (0 when skipped)
  double triangulation_seconds = 0;
  double merge_seconds = 0;        ///< total time spent building step 0 and in refinement steps
  double first_step_seconds = 0;   ///< from the validated polygon to the axis of step 0 (triangulation or curve evolution included)
  double evolution_seconds = 0;    ///< boundary evolution: the discrete curve evolution
  std::size_t cuts = 0;            ///< boundary evolution: triangles cut out of the shape
  std::size_t splits = 0;          ///< boundary evolution: straight vertices put back into an edge
  std::size_t recomputed_steps = 0; ///< boundary evolution: cuts whose new cells would enclose old ones (a small hole near the cut), computed in one shot instead
  std::size_t switches = 0;        ///< switch critical points traversed
  std::size_t vanishings = 0;      ///< vanishing critical points traversed
  std::size_t anomalies = 0;       ///< events forced to keep the topology valid (0: exact decisions never force one, and the double model redoes such merges)
  std::size_t undecided_ties = 0;  ///< ties between two vanishings of one disk that the merge could not decide, and took the one computed first (see `Merge_statistics::undecided_ties`; 0 on every shape tried)
  std::size_t redone_merges = 0;   ///< merges of the double model redone with exact decisions: after an anomaly, or a decision within its estimated rounding error
  std::size_t max_queue = 0;       ///< n_v: the largest priority queue of any merge
  // The task tree of a one-shot divide and conquer (`CGAL::medial_axis_2()`):
  // its work is validation + triangulation + `triangulation_parallel_seconds`
  // + `parts_seconds_sum` + `join_seconds`, its span (the longest chain of
  // dependent tasks) validation + triangulation - min(validation,
  // `overlapped_seconds`) + `parts_seconds_max` + `join_seconds`.
  double overlapped_seconds = 0;   ///< one shot: the part of the triangulation that ran while another thread validated the input (the points' Delaunay triangulation; 0 when sequential)
  std::size_t split_triangulations = 0; ///< one shot: 1 where the polygon was triangulated in two sides at once, cut along a chord of its outer ring or a path through holes (large polygons checked by the one-shot, two threads or more), else 0
  std::size_t split_triangulation_holes = 0; ///< one shot: where the triangulation was split along a path through holes, the holes it went through (0 for a chord, or no split)
  double triangulation_parallel_seconds = 0; ///< one shot: the time the two sides' triangulations ran beside each other (their summed times less the wall time; 0 unless split)
  std::size_t parts = 0;           ///< one shot: parts of the divide and conquer
  double parts_seconds_sum = 0;    ///< one shot: the tasks of all parts (built independently), summed
  double parts_seconds_max = 0;    ///< one shot: the longest task of a part
  double join_seconds = 0;         ///< one shot: joining the parts and the merges between them (sequential); with boundary evolution, also its steps
  std::size_t boundary_evolution_one_shots = 0; ///< one shot: 1 where boundary evolution computed the axis (finely sampled boundaries, see `medial_axis_2()`), else 0
  std::size_t abandoned_divide_and_conquers = 0; ///< one shot: 1 where the divide and conquer stopped because the merges of a part crossed hundreds of cells a triangle, and boundary evolution computed the axis (or, where it did no better, the divide and conquer again without stopping), else 0
  std::size_t region_growing_one_shots = 0; ///< one shot: 1 where the divide and conquer (or boundary evolution) met an anomaly and region growing computed the axis again (see `medial_axis_2()`; with exact decisions, for the double model too), else 0
  std::optional<std::size_t> region_growing_steps; ///< one shot: the steps that region growing takes on the same polygon (`Progressive_medial_axis_2::number_of_steps()`), counted from the one-shot's own triangulation (which is region growing's unless the polygon was triangulated in two sides), where the process asked for it (`Progressive_medial_axes::internal::one_shots_count_region_growing_steps()`, set by the tool's `--stats`: without it, a second triangulation of every polygon); else empty
};

/*!
\ingroup PkgProgressiveMedialAxis2Ref
The default visitor of `Progressive_medial_axis_2`: does nothing.
\cgalModels `ProgressiveMedialAxisVisitor_2`
*/
struct Default_progressive_medial_axis_visitor {
  void on_switch() {}
  void on_vanish() {}
  void on_merge(const Progressive_medial_axes::Merge_statistics&) {}
  void on_step(std::size_t /*step*/, std::size_t /*n_v*/) {}
};

} // namespace CGAL

#endif // CGAL_PROGRESSIVE_MEDIAL_AXIS_2_PROGRESSIVE_MEDIAL_AXIS_VISITOR_2_H
