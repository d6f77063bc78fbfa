// Copyright (c) 2026 The Progressive_medial_axis_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// The command-line tool's --repair (not part of the library): an invalid
// polygon is turned into valid polygons by GEOS (GEOSMakeValid, as PostGIS
// and Shapely do), through its reentrant C API.  GEOS is an optional
// dependency of the tool only (PMA_TOOL_WITH_GEOS); the header-only library
// never uses it.

#ifndef PMA_TOOL_REPAIR_H
#define PMA_TOOL_REPAIR_H

#include <CGAL/Progressive_medial_axis_2/Input_error.h>
#include <CGAL/Progressive_medial_axis_2/validate_polygon.h>

#include <CGAL/number_utils.h>

#include <string>
#include <vector>

#ifdef PMA_TOOL_WITH_GEOS
#include <geos_c.h>
#include <cstdarg>
#include <cstdio>
#include <memory>
#endif

namespace pma_tool {

/// True if this build of the tool can repair polygons.
inline bool can_repair()
{
#ifdef PMA_TOOL_WITH_GEOS
  return true;
#else
  return false;
#endif
}

#ifdef PMA_TOOL_WITH_GEOS
namespace internal {

// One GEOS context per call: the reentrant API is then safe on any thread.
class Geos_context
{
public:
  Geos_context() : h_(GEOS_init_r())
  {
    GEOSContext_setErrorMessageHandler_r(h_, &Geos_context::on_error, &error_);
  }
  ~Geos_context() { GEOS_finish_r(h_); }
  Geos_context(const Geos_context&) = delete;
  Geos_context& operator=(const Geos_context&) = delete;
  GEOSContextHandle_t handle() const { return h_; }
  const std::string& error() const { return error_; }

private:
  static void on_error(const char* message, void* userdata) { *static_cast<std::string*>(userdata) = message; }
  GEOSContextHandle_t h_;
  std::string error_;
};

} // namespace internal
#endif

namespace internal {

// The structure method's result where the only problem is holes outside the
// outer ring or inside another hole (their area is outside the shell or
// already removed: the result is the polygon without them), without GEOS:
// MakeValid costs seconds on polygons with tens of thousands of holes, and
// renumbers every ring.  False if there is another problem, or if the outer
// ring lies inside a hole (the result is then empty, or other polygons).
template <class Point_2>
bool drop_misplaced_holes(const CGAL::Progressive_medial_axes::Rings<Point_2>& rings,
                          CGAL::Progressive_medial_axes::Rings<Point_2>& out)
{
  typedef typename CGAL::Kernel_traits<Point_2>::Kernel K;
  std::vector<std::size_t> misplaced;
  bool outer_inside = false;
  try {
    CGAL::Progressive_medial_axes::internal::Polygon_rings_validator<K> validator(rings, true);
    validator.run(false);
    misplaced = validator.misplaced_holes(&outer_inside);
  } catch(const CGAL::Progressive_medial_axes::Input_error&) {
    return false;
  }
  if(misplaced.empty() || outer_inside) return false;
  out.clear();
  for(std::size_t r = 0, m = 0; r < rings.size(); ++r) {
    if(m < misplaced.size() && misplaced[m] == r) {
      ++m;
      continue;
    }
    out.push_back(rings[r]);
  }
  return true;
}

} // namespace internal

/*!
Turns the polygon with holes `rings` (any orientation, possibly invalid:
crossings, overlapping edges, spikes, zero-length edges, holes outside the
shell) into valid polygons covering the same area, with GEOS's
`GEOSMakeValidWithParams` and its `structure` method (GEOS 3.10 and later):
the area is that of the outer ring minus the holes, collapsed parts (spikes,
rings of no area) are dropped.  Polygons of the result are returned in the
order GEOS gives them, each as rings (outer ring first, closing point
dropped).  Where the only problem is holes outside the outer ring or inside
another hole, the result is the polygon without them, its rings as given
(GEOS is not called).  Throws `Input_error` if GEOS fails or the build has
no GEOS.
*/
template <class Point_2>
std::vector<CGAL::Progressive_medial_axes::Rings<Point_2> >
repair_polygon(const CGAL::Progressive_medial_axes::Rings<Point_2>& rings)
{
  typedef CGAL::Progressive_medial_axes::Input_error Input_error;
#ifndef PMA_TOOL_WITH_GEOS
  (void)rings;
  throw Input_error("--repair needs GEOS: this build of the tool has none (install libgeos-dev and rebuild)");
#else
  {
    CGAL::Progressive_medial_axes::Rings<Point_2> without;
    if(internal::drop_misplaced_holes(rings, without)) return {without};
  }
  internal::Geos_context context;
  GEOSContextHandle_t h = context.handle();
  auto fail = [&](const char* what) -> Input_error {
    return Input_error(std::string("repair failed: ") + what + (context.error().empty() ? "" : ": " + context.error()));
  };
  auto ring = [&](const std::vector<Point_2>& r) {
    GEOSCoordSequence* seq = GEOSCoordSeq_create_r(h, static_cast<unsigned>(r.size() + 1), 2);
    if(!seq) throw fail("GEOSCoordSeq_create");
    for(std::size_t i = 0; i <= r.size(); ++i) {
      const Point_2& p = r[i % r.size()];
      GEOSCoordSeq_setXY_r(h, seq, static_cast<unsigned>(i), CGAL::to_double(p.x()), CGAL::to_double(p.y()));
    }
    GEOSGeometry* g = GEOSGeom_createLinearRing_r(h, seq);   // takes the sequence
    if(!g) throw fail("GEOSGeom_createLinearRing");
    return g;
  };
  auto destroy = [h](GEOSGeometry* g) { GEOSGeom_destroy_r(h, g); };
  std::vector<GEOSGeometry*> holes;
  GEOSGeometry* shell = ring(rings[0]);
  for(std::size_t r = 1; r < rings.size(); ++r) holes.push_back(ring(rings[r]));
  std::unique_ptr<GEOSGeometry, decltype(destroy)> polygon(
    GEOSGeom_createPolygon_r(h, shell, holes.data(), static_cast<unsigned>(holes.size())), destroy);
  if(!polygon) throw fail("GEOSGeom_createPolygon");

  GEOSMakeValidParams* p = GEOSMakeValidParams_create_r(h);
  GEOSMakeValidParams_setMethod_r(h, p, GEOS_MAKE_VALID_STRUCTURE);
  GEOSMakeValidParams_setKeepCollapsed_r(h, p, 0);
  std::unique_ptr<GEOSGeometry, decltype(destroy)> valid(GEOSMakeValidWithParams_r(h, polygon.get(), p), destroy);
  GEOSMakeValidParams_destroy_r(h, p);
  if(!valid) throw fail("GEOSMakeValid");

  std::vector<CGAL::Progressive_medial_axes::Rings<Point_2> > out;
  auto read_ring = [&](const GEOSGeometry* g, std::vector<Point_2>& r) {
    const GEOSCoordSequence* seq = GEOSGeom_getCoordSeq_r(h, g);
    unsigned n = 0;
    if(!seq || !GEOSCoordSeq_getSize_r(h, seq, &n)) throw fail("GEOSGeom_getCoordSeq");
    for(unsigned i = 0; i + 1 < n; ++i) {   // the closing point is dropped
      double x = 0, y = 0;
      GEOSCoordSeq_getXY_r(h, seq, i, &x, &y);
      r.push_back(Point_2(x, y));
    }
  };
  // the polygons of the result, in order (collections are walked, other types dropped)
  std::vector<const GEOSGeometry*> stack(1, valid.get());
  std::vector<const GEOSGeometry*> polygons;
  while(!stack.empty()) {
    const GEOSGeometry* g = stack.back();
    stack.pop_back();
    const int type = GEOSGeomTypeId_r(h, g);
    if(type == GEOS_POLYGON) {
      if(!GEOSisEmpty_r(h, g)) polygons.push_back(g);
    } else if(type == GEOS_MULTIPOLYGON || type == GEOS_GEOMETRYCOLLECTION) {
      const int n = GEOSGetNumGeometries_r(h, g);
      for(int i = n - 1; i >= 0; --i) stack.push_back(GEOSGetGeometryN_r(h, g, i));
    }
  }
  for(const GEOSGeometry* g : polygons) {
    out.emplace_back(1);
    read_ring(GEOSGetExteriorRing_r(h, g), out.back()[0]);
    const int n = GEOSGetNumInteriorRings_r(h, g);
    for(int i = 0; i < n; ++i) {
      out.back().emplace_back();
      read_ring(GEOSGetInteriorRingN_r(h, g, i), out.back().back());
    }
  }
  return out;
#endif
}

} // namespace pma_tool

#endif // PMA_TOOL_REPAIR_H
