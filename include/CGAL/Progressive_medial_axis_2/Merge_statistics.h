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

#ifndef CGAL_PROGRESSIVE_MEDIAL_AXIS_2_MERGE_STATISTICS_H
#define CGAL_PROGRESSIVE_MEDIAL_AXIS_2_MERGE_STATISTICS_H

#include <CGAL/license/Progressive_medial_axis_2.h>

#include <cstddef>

namespace CGAL {
namespace Progressive_medial_axes {

/*!
\ingroup PkgProgressiveMedialAxis2Ref
What one merge did: its critical points (paper, section 5) and the largest
size of its priority queue.  Given to the visitor's `on_merge()`.
*/
struct Merge_statistics {
  std::size_t switches = 0;     ///< switch points traversed
  std::size_t vanishings = 0;   ///< vanishing points traversed
  std::size_t max_queue = 0;    ///< n_v: the largest number of live vanishing candidates
  std::size_t anomalies = 0;    ///< events forced to keep the topology valid (0 with exact decisions)
  std::size_t undecided_ties = 0; ///< vanishing candidates of a disk that has two (the merge's list holds one generator on both sides of two nodes) whose check of the tip's place on the disk was left undecided, within the margin of its computation in doubles: the candidate stayed, and of the two the one computed first was taken, maybe wrongly (0 on every shape tried)
  bool redone_exactly = false;  ///< the double model met an anomaly and the merge was redone with exact decisions
};

} // namespace Progressive_medial_axes
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_MEDIAL_AXIS_2_MERGE_STATISTICS_H
