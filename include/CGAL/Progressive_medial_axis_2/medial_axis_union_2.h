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

#ifndef CGAL_PROGRESSIVE_MEDIAL_AXIS_2_MEDIAL_AXIS_UNION_2_H
#define CGAL_PROGRESSIVE_MEDIAL_AXIS_2_MEDIAL_AXIS_UNION_2_H

#include <CGAL/license/Progressive_medial_axis_2.h>

#include <CGAL/Progressive_medial_axis_traits_2.h>
#include <CGAL/Progressive_medial_axis_2.h>
#include <CGAL/Progressive_medial_axis_2/Medial_axis_2.h>
#include <CGAL/Progressive_medial_axis_2/internal/Union.h>

#include <chrono>

namespace CGAL {

/*!
\ingroup PkgProgressiveMedialAxis2Ref

The medial axis of the union of two polygons, from their medial axes (the
paper's Fig. 24): `a` and `b` are the axes of two whole polygons (holes
allowed; from `CGAL::medial_axis_2()`, the last step of a
`Progressive_medial_axis_2`, or `CGAL::medial_axis_union_2()` itself, so
that unions can be merged on, each along the union's polygon as it numbers
it) with disjoint interiors whose boundaries share
one or more chains of edges: the same points, in opposite directions.  The
union must be a valid polygon (its rings may touch at vertices).  Chains of
any length are merged, and several chains make the union enclose holes.

The result is the axis of the union, the same as `CGAL::medial_axis_2()` of
the union gives.  Its polygon is numbered as follows (the ids of its
generators refer to it; `shape_rings()` and `point()` give it): the outer
ring first, counter-clockwise, then the holes, clockwise (in OGC's form: a
hole that touches the outer ring or another hole at a point is a ring of its
own; the lobes of a pinched union stay in the outer ring); each ring starts
at the union vertex that comes first in input order (the vertices of `a`
before those of `b`, by ring and index), and the holes come in the order of
those vertices.

Cost: the two axes are copied into the result and the union's rings are
found and validated, in time linear in the sizes of `a` and `b`; the merges
themselves cost in proportion to the cells that touch the shared chains.
`a` and `b` are left as they are.

Two cases are computed in one shot of the union polygon instead
(`CGAL::medial_axis_2()`, which itself has a way out), with the same
numbering, and `statistics->recomputed` is then 1; this costs a one-shot of
the union instead of the local merges:
- a ring shared as a whole (one polygon fills a hole of the other exactly):
  the last merge along it would close a crack whose two ends are inside the
  union, which the merge does not do;
- a T (a vertex inside an edge) that the union has and neither polygon has,
  or a T on a shared edge (one polygon splits there an edge that the other
  has whole): the merges would have to split that edge's cell;
- merges that meet an anomaly (a bug of the merge, counted in
  `statistics->anomalies`; 0 on every shape tried), where the axis could be
  wrong near it.

Where a polygon has a T of its own, the union's ring through the edge gets
the place as a vertex (the union is noded there, as GEOS's overlays are),
and the merges go on as usual.  A T that only the union has is noded too:
where the union's ring touched its own edge there, the clockwise loop
between its two passes of the place becomes a hole (OGC's form), numbered
as above (the added vertex ranks as the T's vertex).  A third polygon
merged with such a union shares an edge split there only if it has the
vertex there too.

Throws `Progressive_medial_axes::Input_error`, with one line naming the
problem, when an axis is not the axis of a whole polygon, when the polygons
share no edge, when they overlap, or when the union is not a valid polygon.

\tparam Traits a model of `ProgressiveMedialAxisTraits_2` whose kernel is `K`.
*/
template <class K, class Traits>
Medial_axis_2<K> medial_axis_union_2(const Medial_axis_2<K>& a, const Medial_axis_2<K>& b, const Traits& traits,
                                     Progressive_medial_axes::Medial_axis_union_statistics* statistics = nullptr)
{
  typedef Progressive_medial_axes::internal::Medial_axis_access Access;
  if(!Access::data(a) || !Access::data(b))
    throw Progressive_medial_axes::Input_error("the union of an empty medial axis");
  Progressive_medial_axes::internal::Medial_axis_union<Traits> driver(*Access::data(a), *Access::data(b), traits);
  Progressive_medial_axes::Medial_axis_union_statistics stats;
  auto data = driver.run(stats);
  if(!data || stats.anomalies != 0 ||
     Progressive_medial_axes::internal::union_way_out_forced().load(std::memory_order_relaxed)) {
    // (a ring shared as a whole, which the merges do not close, or a bug of
    // the merge: no wrong axis is returned, the union polygon's axis is
    // computed in one shot, from its rings in the same numbering)
    const auto t0 = std::chrono::steady_clock::now();
    Progressive_medial_axis_statistics one_shot;
    Medial_axis_2<K> redone =
        Progressive_medial_axes::internal::one_shot_medial_axis(driver.rings(), traits, CHECK_INPUT, &one_shot);
    stats.recomputed = 1;
    stats.undecided_ties = one_shot.undecided_ties;
    stats.merge_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if(statistics) *statistics = stats;
    return redone;
  }
  if(statistics) *statistics = stats;
  return Access::make<K>(std::shared_ptr<const typename decltype(data)::element_type>(data));
}

/*!
\ingroup PkgProgressiveMedialAxis2Ref
`medial_axis_union_2()` with the default traits `Progressive_medial_axis_traits_2<K>`
(every decision exact).
*/
template <class K>
Medial_axis_2<K> medial_axis_union_2(const Medial_axis_2<K>& a, const Medial_axis_2<K>& b)
{
  return medial_axis_union_2(a, b, Progressive_medial_axis_traits_2<K>());
}

} // namespace CGAL

#endif // CGAL_PROGRESSIVE_MEDIAL_AXIS_2_MEDIAL_AXIS_UNION_2_H
