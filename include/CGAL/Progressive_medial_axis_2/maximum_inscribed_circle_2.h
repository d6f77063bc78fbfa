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

#ifndef CGAL_PROGRESSIVE_MEDIAL_AXIS_2_MAXIMUM_INSCRIBED_CIRCLE_2_H
#define CGAL_PROGRESSIVE_MEDIAL_AXIS_2_MAXIMUM_INSCRIBED_CIRCLE_2_H

#include <CGAL/license/Progressive_medial_axis_2.h>

#include <CGAL/Progressive_medial_axis_2/Medial_axis_2.h>
#include <CGAL/enum.h>
#include <CGAL/number_utils.h>

namespace CGAL {

/*!
\ingroup PkgProgressiveMedialAxis2Ref
The largest disk inside a shape: its centre, its radius and the vertex of
the medial axis at its centre.
*/
template <class K>
struct Maximum_inscribed_circle_2 {
  typename Medial_axis_2<K>::Vertex_handle vertex; ///< the vertex of the axis at the centre (null for an empty axis)
  typename K::Point_2 center;                      ///< the centre
  typename K::FT radius = 0;                       ///< the radius
};

/*!
\ingroup PkgProgressiveMedialAxis2Ref

The maximum inscribed circle of the shape of `ma` (at a step of a
progressive computation, of the current shape).

The radius is largest at a vertex of the axis: along every medial curve the
radius is a convex function of arc length, so its maximum on a curve is at
an end.  The centre is the vertex of largest radius, a branch point except
where the largest disk slides along the bisector of two parallel edges (the
radius is constant there and the ends of that curve tie).  Ties are broken
by the smallest (x, y).  Radii and points are the axis' own: exact and
correctly rounded like every branch point, compared exactly.  O(n) in the
size of the axis.
*/
template <class K>
Maximum_inscribed_circle_2<K> maximum_inscribed_circle_2(const Medial_axis_2<K>& ma)
{
  Maximum_inscribed_circle_2<K> best;
  bool found = false;
  for(const auto& v : ma.vertices()) {
    if(found) {
      const Comparison_result c = CGAL::compare(v.radius(), best.radius);
      if(c == SMALLER) continue;
      if(c == EQUAL && CGAL::compare_xy(v.point(), best.center) != SMALLER) continue;
    }
    found = true;
    best.vertex = v;
    best.center = v.point();
    best.radius = v.radius();
  }
  return best;
}

} // namespace CGAL

#endif // CGAL_PROGRESSIVE_MEDIAL_AXIS_2_MAXIMUM_INSCRIBED_CIRCLE_2_H
