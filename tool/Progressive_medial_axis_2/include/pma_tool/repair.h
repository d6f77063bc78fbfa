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

#include <CGAL/Polygon_2_algorithms.h>
#include <CGAL/box_intersection_d.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <string>
#include <vector>

#ifdef PMA_TOOL_WITH_GEOS
#include <geos_c.h>
#include <dlfcn.h>
#include <cstdarg>
#include <cstdio>
#include <memory>
#endif

namespace pma_tool {

#ifdef PMA_TOOL_WITH_GEOS
namespace internal {

// GEOS's C API, loaded when it is first needed (dlopen, dlsym) instead of
// linked: linking libgeos_c made every run of the tool load and relocate
// GEOS, about 2 ms of the 6 ms that the tool takes on a triangle, for the
// few runs that repair.  Null members if GEOS (libgeos_c.so.1) is missing.
#define PMA_TOOL_GEOS_FUNCTIONS(X) \
  X(GEOSContext_setErrorMessageHandler_r) \
  X(GEOSCoordSeq_create_r) \
  X(GEOSCoordSeq_getSize_r) \
  X(GEOSCoordSeq_getXY_r) \
  X(GEOSCoordSeq_setXY_r) \
  X(GEOSDifference_r) \
  X(GEOSGeomTypeId_r) \
  X(GEOSGeom_createCollection_r) \
  X(GEOSGeom_createLinearRing_r) \
  X(GEOSGeom_createPolygon_r) \
  X(GEOSGeom_destroy_r) \
  X(GEOSGeom_getCoordSeq_r) \
  X(GEOSGetExteriorRing_r) \
  X(GEOSGetGeometryN_r) \
  X(GEOSGetInteriorRingN_r) \
  X(GEOSGetNumGeometries_r) \
  X(GEOSGetNumInteriorRings_r) \
  X(GEOSMakeValidParams_create_r) \
  X(GEOSMakeValidParams_destroy_r) \
  X(GEOSMakeValidParams_setKeepCollapsed_r) \
  X(GEOSMakeValidParams_setMethod_r) \
  X(GEOSMakeValidWithParams_r) \
  X(GEOSUnaryUnion_r) \
  X(GEOS_finish_r) \
  X(GEOS_init_r) \
  X(GEOSisEmpty_r) \

struct Geos_api {
#define PMA_TOOL_GEOS_MEMBER(f) decltype(&::f) f = nullptr;
  PMA_TOOL_GEOS_FUNCTIONS(PMA_TOOL_GEOS_MEMBER)
#undef PMA_TOOL_GEOS_MEMBER
  bool loaded = false;

  static Geos_api load()
  {
    Geos_api a;
    void* lib = dlopen("libgeos_c.so.1", RTLD_NOW | RTLD_LOCAL);
    if(!lib) lib = dlopen("libgeos_c.so", RTLD_NOW | RTLD_LOCAL);
    if(!lib) return a;
    bool all = true;
#define PMA_TOOL_GEOS_LOAD(f) \
  a.f = reinterpret_cast<decltype(&::f)>(dlsym(lib, #f)); \
  all = all && a.f != nullptr;
    PMA_TOOL_GEOS_FUNCTIONS(PMA_TOOL_GEOS_LOAD)
#undef PMA_TOOL_GEOS_LOAD
    a.loaded = all;
    return a;
  }
};

// (loaded once, by the first caller; thread-safe)
inline const Geos_api& geos()
{
  static const Geos_api api = Geos_api::load();
  return api;
}

} // namespace internal
#endif

/// True if this build of the tool can repair polygons (GEOS 3.10 or
/// later was found when it was built, and libgeos_c can be loaded now).
inline bool can_repair()
{
#ifdef PMA_TOOL_WITH_GEOS
  return internal::geos().loaded;
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
  Geos_context() : h_(geos().GEOS_init_r())
  {
    geos().GEOSContext_setErrorMessageHandler_r(h_, &Geos_context::on_error, &error_);
  }
  ~Geos_context() { geos().GEOS_finish_r(h_); }
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

// Removes the zero-area parts that the structure method drops, in place:
// repeated consecutive vertices (zero-length edges) and spikes (a vertex whose
// two edges are collinear and fold back), until none is left; a hole that
// collapses is dropped.  Local and exact (the area does not change), where
// MakeValid takes minutes on a polygon of a million vertices with one spike.
// False if the outer ring collapses.
template <class Point_2>
bool remove_folds(CGAL::Progressive_medial_axes::Rings<Point_2>& rings)
{
  typedef typename CGAL::Kernel_traits<Point_2>::Kernel K;
  const K k;
  auto fold = [&](const Point_2& a, const Point_2& g, const Point_2& c) {
    return a == g || g == c ||
           (k.orientation_2_object()(a, g, c) == CGAL::COLLINEAR &&
            k.compare_xy_2_object()(a, g) == k.compare_xy_2_object()(c, g));
  };
  for(std::size_t r = 0; r < rings.size(); ++r) {
    std::vector<Point_2> out;   // a stack: every triple below its top is fold-free
    auto settle = [&]() {
      while(out.size() >= 2 && out[out.size() - 1] == out[out.size() - 2]) out.pop_back();
      while(out.size() >= 3 && fold(out[out.size() - 3], out[out.size() - 2], out[out.size() - 1])) {
        out.erase(out.end() - 2);
        while(out.size() >= 2 && out[out.size() - 1] == out[out.size() - 2]) out.pop_back();
      }
    };
    for(const Point_2& p : rings[r]) {
      out.push_back(p);
      settle();
    }
    // around the closing point: rotate the start away and settle again
    for(std::size_t turn = 0; out.size() >= 3 && turn < out.size(); ++turn) {
      const std::size_t m = out.size();
      if(!fold(out[m - 1], out[0], out[1]) && !fold(out[m - 2], out[m - 1], out[0])) break;
      std::rotate(out.begin(), out.begin() + 1, out.end());
      settle();
    }
    rings[r].swap(out);
  }
  auto collapsed = [](const std::vector<Point_2>& ring) { return ring.size() < 3; };
  if(collapsed(rings[0])) return false;
  rings.erase(std::remove_if(rings.begin() + 1, rings.end(), collapsed), rings.end());
  return true;
}

#ifdef PMA_TOOL_WITH_GEOS
// GEOS's MakeValid (structure method) of each polygon of `input`, and the
// union of the results if `union_all` (else `input` holds one polygon),
// minus the union of the polygons of `subtract`, each made valid.
template <class Point_2>
std::vector<CGAL::Progressive_medial_axes::Rings<Point_2> >
geos_make_valid(const std::vector<CGAL::Progressive_medial_axes::Rings<Point_2> >& input, bool union_all,
                const std::vector<CGAL::Progressive_medial_axes::Rings<Point_2> >& subtract = {})
{
  typedef CGAL::Progressive_medial_axes::Input_error Input_error;
  internal::Geos_context context;
  GEOSContextHandle_t h = context.handle();
  auto fail = [&](const char* what) -> Input_error {
    return Input_error(std::string("repair failed: ") + what + (context.error().empty() ? "" : ": " + context.error()));
  };
  auto ring = [&](const std::vector<Point_2>& r) {
    GEOSCoordSequence* seq = geos().GEOSCoordSeq_create_r(h, static_cast<unsigned>(r.size() + 1), 2);
    if(!seq) throw fail("GEOSCoordSeq_create");
    for(std::size_t i = 0; i <= r.size(); ++i) {
      const Point_2& p = r[i % r.size()];
      geos().GEOSCoordSeq_setXY_r(h, seq, static_cast<unsigned>(i), CGAL::to_double(p.x()), CGAL::to_double(p.y()));
    }
    GEOSGeometry* g = geos().GEOSGeom_createLinearRing_r(h, seq);   // takes the sequence
    if(!g) throw fail("GEOSGeom_createLinearRing");
    return g;
  };
  auto destroy = [h](GEOSGeometry* g) { geos().GEOSGeom_destroy_r(h, g); };
  typedef std::unique_ptr<GEOSGeometry, decltype(destroy)> Owned;
  // the polygons made valid, and their union if `unite`
  auto make_valid = [&](const std::vector<CGAL::Progressive_medial_axes::Rings<Point_2> >& polygons, bool unite) {
    GEOSMakeValidParams* p = geos().GEOSMakeValidParams_create_r(h);
    geos().GEOSMakeValidParams_setMethod_r(h, p, GEOS_MAKE_VALID_STRUCTURE);
    geos().GEOSMakeValidParams_setKeepCollapsed_r(h, p, 0);
    std::vector<Owned> made;
    for(const auto& rings : polygons) {
      std::vector<GEOSGeometry*> holes;
      GEOSGeometry* shell = ring(rings[0]);
      for(std::size_t r = 1; r < rings.size(); ++r) holes.push_back(ring(rings[r]));
      Owned polygon(geos().GEOSGeom_createPolygon_r(h, shell, holes.data(), static_cast<unsigned>(holes.size())), destroy);
      if(!polygon) throw fail("GEOSGeom_createPolygon");
      made.emplace_back(geos().GEOSMakeValidWithParams_r(h, polygon.get(), p), destroy);
      if(!made.back()) {
        geos().GEOSMakeValidParams_destroy_r(h, p);
        throw fail("GEOSMakeValid");
      }
    }
    geos().GEOSMakeValidParams_destroy_r(h, p);
    if(!unite) return std::move(made[0]);
    std::vector<GEOSGeometry*> parts;
    for(Owned& g : made) parts.push_back(g.release());   // the collection takes them
    Owned all(geos().GEOSGeom_createCollection_r(h, GEOS_GEOMETRYCOLLECTION, parts.data(), static_cast<unsigned>(parts.size())),
              destroy);
    if(!all) throw fail("GEOSGeom_createCollection");
    Owned u(geos().GEOSUnaryUnion_r(h, all.get()), destroy);
    if(!u) throw fail("GEOSUnaryUnion");
    return u;
  };
  Owned valid = make_valid(input, union_all);
  if(!subtract.empty()) {
    Owned minus = make_valid(subtract, true);
    valid.reset(geos().GEOSDifference_r(h, valid.get(), minus.get()));
    if(!valid) throw fail("GEOSDifference");
  }

  std::vector<CGAL::Progressive_medial_axes::Rings<Point_2> > out;
  auto read_ring = [&](const GEOSGeometry* g, std::vector<Point_2>& r) {
    const GEOSCoordSequence* seq = geos().GEOSGeom_getCoordSeq_r(h, g);
    unsigned n = 0;
    if(!seq || !geos().GEOSCoordSeq_getSize_r(h, seq, &n)) throw fail("GEOSGeom_getCoordSeq");
    for(unsigned i = 0; i + 1 < n; ++i) {   // the closing point is dropped
      double x = 0, y = 0;
      geos().GEOSCoordSeq_getXY_r(h, seq, i, &x, &y);
      r.push_back(Point_2(x, y));
    }
  };
  // the polygons of the result, in order (collections are walked, other types dropped)
  std::vector<const GEOSGeometry*> stack(1, valid.get());
  std::vector<const GEOSGeometry*> polygons;
  while(!stack.empty()) {
    const GEOSGeometry* g = stack.back();
    stack.pop_back();
    const int type = geos().GEOSGeomTypeId_r(h, g);
    if(type == GEOS_POLYGON) {
      if(!geos().GEOSisEmpty_r(h, g)) polygons.push_back(g);
    } else if(type == GEOS_MULTIPOLYGON || type == GEOS_GEOMETRYCOLLECTION) {
      const int n = geos().GEOSGetNumGeometries_r(h, g);
      for(int i = n - 1; i >= 0; --i) stack.push_back(geos().GEOSGetGeometryN_r(h, g, i));
    }
  }
  for(const GEOSGeometry* g : polygons) {
    out.emplace_back(1);
    read_ring(geos().GEOSGetExteriorRing_r(h, g), out.back()[0]);
    const int n = geos().GEOSGetNumInteriorRings_r(h, g);
    for(int i = 0; i < n; ++i) {
      out.back().emplace_back();
      read_ring(geos().GEOSGetInteriorRingN_r(h, g, i), out.back().back());
    }
  }
  return out;
}

#endif

// Whether ring `hole` (disjoint from `outer`'s boundary but maybe at
// vertices) lies inside ring `outer`: at its first vertex off that boundary.
template <class Point_2>
bool inside(const std::vector<Point_2>& hole, const std::vector<Point_2>& outer)
{
  typedef typename CGAL::Kernel_traits<Point_2>::Kernel K;
  for(const Point_2& p : hole) {
    const CGAL::Bounded_side b = CGAL::bounded_side_2(outer.begin(), outer.end(), p, K());
    if(b != CGAL::ON_BOUNDARY) return b == CGAL::ON_BOUNDED_SIDE;
  }
  return false;
}

// The groups of rings whose edges cross or overlap (a ring alone if two of
// its own edges do), all found in one pass: the boxes of all the edges
// (CGAL's box_self_intersection_d), then the exact test on the pairs whose
// boxes meet.  A contact at one point (rings touching at a vertex, a vertex
// in another edge) is valid and left out; so are the contacts the validator
// rejects at such points (wedges that cross there), left to its next round.
// Each group is sorted, the groups by their first ring.  `meets_outer[r]`
// says whether hole r meets the outer ring itself (crosses it, overlaps it
// or touches it).
template <class Point_2>
std::vector<std::vector<std::size_t> >
crossing_groups(const CGAL::Progressive_medial_axes::Rings<Point_2>& rings, std::vector<char>& meets_outer)
{
  typedef typename CGAL::Kernel_traits<Point_2>::Kernel K;
  typedef std::pair<std::uint32_t, std::uint32_t> Edge;   // ring, first vertex
  typedef CGAL::Box_intersection_d::Box_with_info_d<double, 2, Edge> Box;
  const K k;
  const auto orientation = k.orientation_2_object();
  const auto compare_xy = k.compare_xy_2_object();
  const auto do_intersect = k.do_intersect_2_object();
  std::size_t edges = 0;
  for(const auto& ring : rings) edges += ring.size();
  std::vector<Box> boxes;
  boxes.reserve(edges);
  for(std::size_t r = 0; r < rings.size(); ++r)
    for(std::size_t i = 0; i < rings[r].size(); ++i)
      boxes.emplace_back(rings[r][i].bbox() + rings[r][(i + 1) % rings[r].size()].bbox(),
                         Edge(std::uint32_t(r), std::uint32_t(i)));
  std::vector<std::size_t> parent(rings.size());   // union-find over the rings
  for(std::size_t r = 0; r < parent.size(); ++r) parent[r] = r;
  auto find = [&](std::size_t r) {
    while(parent[r] != r) r = parent[r] = parent[parent[r]];
    return r;
  };
  std::vector<char> bad(rings.size(), 0);
  meets_outer.assign(rings.size(), 0);
  auto cross_or_overlap = [&](const Point_2& a, const Point_2& b, const Point_2& c, const Point_2& d) {
    const CGAL::Orientation o1 = orientation(a, b, c), o2 = orientation(a, b, d);
    if(o1 == CGAL::COLLINEAR && o2 == CGAL::COLLINEAR) {   // on one line: do they share more than a point?
      const Point_2& lo1 = compare_xy(a, b) == CGAL::SMALLER ? a : b;
      const Point_2& hi1 = &lo1 == &a ? b : a;
      const Point_2& lo2 = compare_xy(c, d) == CGAL::SMALLER ? c : d;
      const Point_2& hi2 = &lo2 == &c ? d : c;
      const Point_2& lo = compare_xy(lo1, lo2) == CGAL::SMALLER ? lo2 : lo1;
      const Point_2& hi = compare_xy(hi1, hi2) == CGAL::SMALLER ? hi1 : hi2;
      return compare_xy(lo, hi) == CGAL::SMALLER;
    }
    if(o1 == CGAL::COLLINEAR || o2 == CGAL::COLLINEAR || o1 == o2) return false;
    const CGAL::Orientation o3 = orientation(c, d, a), o4 = orientation(c, d, b);
    return o3 != CGAL::COLLINEAR && o4 != CGAL::COLLINEAR && o3 != o4;
  };
  // (a cutoff of 1,000 boxes, not CGAL's default 10: a third faster on a
  // polygon of a million vertices)
  auto test = [&](const Box& x, const Box& y) {
    const std::size_t r = x.info().first, s = y.info().first, i = x.info().second, j = y.info().second;
    const std::size_t n = rings[r].size();
    if(r == s && ((i + 1) % n == j || (j + 1) % n == i)) return;   // neighbours: a spike at most, removed before
    const Point_2 &a = rings[r][i], &b = rings[r][(i + 1) % n], &c = rings[s][j], &d = rings[s][(j + 1) % rings[s].size()];
    if((r == 0) != (s == 0) && !meets_outer[r + s] && do_intersect(typename K::Segment_2(a, b), typename K::Segment_2(c, d)))
      meets_outer[r + s] = 1;
    if(!cross_or_overlap(a, b, c, d)) return;
    bad[r] = bad[s] = 1;
    parent[find(r)] = find(s);
  };
  CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), test, CGAL::Box_intersection_d::Box_traits_d<Box>(), 1000);
  std::vector<std::vector<std::size_t> > groups;
  std::vector<std::size_t> group_of(rings.size(), std::size_t(-1));
  for(std::size_t r = 0; r < rings.size(); ++r) {
    if(!bad[r]) continue;
    std::size_t& g = group_of[find(r)];
    if(g == std::size_t(-1)) {
      g = groups.size();
      groups.emplace_back();
    }
    groups[g].push_back(r);
  }
  return groups;
}

// The check of `rings` (rings may touch, the nesting is left out) and the
// ring directly enclosing each ring (Polygon_rings_validator::parents());
// empty, with the check's message in `error`, if it fails.
template <class Point_2>
std::vector<long> checked_parents(const CGAL::Progressive_medial_axes::Rings<Point_2>& rings, std::string& error)
{
  typedef typename CGAL::Kernel_traits<Point_2>::Kernel K;
  try {
    CGAL::Progressive_medial_axes::internal::Polygon_rings_validator<K> validator(rings, true);
    validator.run(false);
    return validator.parents();
  } catch(const CGAL::Progressive_medial_axes::Input_error& e) {
    error = e.what();
  }
  return {};
}

// The rings an error message names ("ring 3 edge 5 ... ring 7 edge 0").
inline std::vector<std::size_t> rings_named(const std::string& message)
{
  std::vector<std::size_t> out;
  for(std::size_t at = message.find("ring "); at != std::string::npos; at = message.find("ring ", at + 5)) {
    std::size_t k = at + 5, r = 0;
    if(k >= message.size() || !std::isdigit(static_cast<unsigned char>(message[k]))) continue;
    for(; k < message.size() && std::isdigit(static_cast<unsigned char>(message[k])); ++k) r = 10 * r + std::size_t(message[k] - '0');
    if(std::find(out.begin(), out.end(), r) == out.end()) out.push_back(r);
  }
  return out;
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
dropped).  The result is that of GEOS 3.11's structure method (a hole
disjoint from the outer ring becomes a polygon, a hole inside another one
adds nothing), computed locally where it can be: zero-length edges and
spikes (zero-area folds) are removed, misplaced holes are dropped or become
polygons, holes that cross or overlap each other (or themselves) are
replaced by their union made valid, and an outer ring that crosses itself or
a hole is made valid minus those holes, by GEOS on those rings only (the
groups of rings that cross are found together, in one pass; as in GEOS, a
hole that meets the outer ring as given is a hole, one apart from it a
polygon, even if the holes met each other; one known difference: holes
apart from the outer ring united with one that only touches it from
outside make one polygon, where GEOS drops the touching one); the
rings left untouched keep their vertices as given.  GEOS repairs the whole
polygon only where these do not suffice.  Throws `Input_error` if GEOS fails or the build has
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
  typedef CGAL::Progressive_medial_axes::Rings<Point_2> Rings;
  // Local repairs first, each exact or done by GEOS on a few rings only,
  // then the check again; GEOS on the whole polygon where they do not
  // suffice.  The area stays that of the structure method: the outer ring
  // made valid, minus the union of the holes made valid.
  Rings work = rings;
  std::vector<Rings> extra;   // pieces of the outer ring split off by its repair (with their holes)
  if(!internal::remove_folds(work)) return internal::geos_make_valid(std::vector<Rings>{rings}, false);
  bool batched = false;   // (see below)
  // As GEOS 3.11's structure method (GeometryFixer) does, each hole is a
  // hole if it meets the outer ring as given (made valid), else a polygon of
  // its own; the outer ring is then made valid minus the holes.
  const std::vector<Point_2> outer = work[0];
  bool outer_mended = false;
  for(int round = 0; round < 64; ++round) {
    std::string error;
    const std::vector<long> parent = internal::checked_parents(work, error);
    if(error.empty()) {
      // As GEOS's structure method does: a hole inside another hole adds
      // nothing (the holes are united), a hole disjoint from the outer ring
      // becomes a polygon of its own (holes inside it are united with it);
      // one inside a piece of the outer ring split off is a hole of that
      // piece.  The outer ring inside a hole: left to GEOS.
      if(parent[0] >= 0) break;
      std::vector<Rings> out(1), outside;
      for(std::size_t r = 0; r < work.size(); ++r) {
        if(r == 0 || parent[r] == 0) {
          out[0].push_back(std::move(work[r]));
        } else if(parent[r] < 0) {
          Rings* piece = nullptr;
          for(Rings& x : extra)
            if(!piece && internal::inside(work[r], x[0])) piece = &x;
          if(piece) piece->push_back(std::move(work[r]));
          else outside.push_back(Rings{std::move(work[r])});
        }
      }
      if(outer_mended && !outside.empty()) {
        // a hole that meets the outer ring as given, now in what the outer
        // ring lost to the holes, adds nothing
        Rings probe(1, outer);
        for(const Rings& x : outside) probe.push_back(x[0]);
        std::vector<char> meets;
        internal::crossing_groups(probe, meets);
        // the others: inside it or not, by the check's nesting where the
        // outer ring as given is valid (one sweep), else one by one
        Rings apart(1, outer);
        std::vector<std::size_t> which;
        for(std::size_t q = 0; q < outside.size(); ++q)
          if(!meets[q + 1]) {
            apart.push_back(outside[q][0]);
            which.push_back(q);
          }
        std::string invalid;
        const std::vector<long> nesting = internal::checked_parents(apart, invalid);
        std::vector<Rings> kept;
        for(std::size_t k = 0; k < which.size(); ++k) {
          Rings& x = outside[which[k]];
          if(!(nesting.empty() ? internal::inside(x[0], outer) : nesting[k + 1] == 0)) kept.push_back(std::move(x));
        }
        outside.swap(kept);
      }
      for(Rings& x : outside) extra.push_back(std::move(x));
      bool valid = true;
      for(Rings& x : extra) {
        try {
          CGAL::Progressive_medial_axes::validate_polygon(x);
        } catch(const Input_error&) {
          valid = false;
        }
        out.push_back(std::move(x));
      }
      if(!valid) return internal::geos_make_valid(std::vector<Rings>{rings}, false);
      return out;
    }
    // The rings to mend, in groups mended together: all the groups of rings
    // that cross or overlap, found in one pass, as long as that mends some;
    // then the rings each error names, one error at a time.  (Russia in
    // land-10m, a million vertices and 190,000 holes, took 9 rounds and 4 s
    // one error at a time; the pass costs about one and a half checks.)
    const bool batch = !batched;
    std::vector<std::vector<std::size_t> > groups;
    std::vector<char> meets_outer;
    if(batch) groups = internal::crossing_groups(work, meets_outer);
    if(groups.empty()) {
      batched = true;
      groups.push_back(internal::rings_named(error));
      if(groups[0].empty()) break;
      meets_outer.assign(work.size(), 0);
      if(std::find(groups[0].begin(), groups[0].end(), std::size_t(0)) != groups[0].end())
        for(std::size_t r : groups[0]) meets_outer[r] = 1;
    }
    Rings next(1);                  // the outer ring (next[0]) and the holes of its piece
    Rings mended;                   // the holes mended
    std::vector<char> done(work.size(), 0);
    bool give_up = false;
    for(std::vector<std::size_t> group : groups) {
      const bool with_outer = std::find(group.begin(), group.end(), std::size_t(0)) != group.end();
      if(with_outer)   // (holes apart from the outer ring as given, met by its holes only, stay: polygons)
        group.erase(std::remove_if(group.begin(), group.end(),
                                   [&](std::size_t r) { return r != 0 && !meets_outer[r] && !internal::inside(work[r], outer); }),
                    group.end());
      std::vector<Rings> holes;
      for(std::size_t r : group)
        if(r != 0) holes.push_back(Rings{work[r]});
      if(with_outer) {
        outer_mended = true;
        // the outer ring: made valid, minus the holes it meets; the largest
        // piece is the outer ring from now on, the others are split off
        std::vector<Rings> pieces = internal::geos_make_valid(std::vector<Rings>{Rings{work[0]}}, false, holes);
        if(pieces.empty()) {
          give_up = true;
          break;
        }
        std::size_t main = 0;
        for(std::size_t q = 1; q < pieces.size(); ++q)
          if(pieces[q][0].size() > pieces[main][0].size()) main = q;
        next = std::move(pieces[main]);
        for(std::size_t q = 0; q < pieces.size(); ++q)
          if(q != main) extra.push_back(std::move(pieces[q]));
      } else {
        // holes that cross or overlap each other (or themselves): their union,
        // made valid, replaces them, if it has no islands (else, found in one
        // pass, the group is left to the rounds that follow)
        std::vector<Rings> merged = internal::geos_make_valid(holes, true);
        if(std::any_of(merged.begin(), merged.end(), [](const Rings& m) { return m.size() > 1; })) {
          if(batch) continue;
          give_up = true;
          break;
        }
        for(Rings& m : merged) mended.push_back(std::move(m[0]));
      }
      for(std::size_t r : group) done[r] = 1;
    }
    if(give_up) break;
    if(std::find(done.begin(), done.end(), char(1)) == done.end()) {   // (only groups with islands)
      batched = true;
      continue;
    }
    if(!done[0]) next[0] = std::move(work[0]);
    for(std::vector<Point_2>& m : mended) next.push_back(std::move(m));
    for(std::size_t r = 1; r < work.size(); ++r)
      if(!done[r]) next.push_back(std::move(work[r]));
    work.swap(next);
    if(!internal::remove_folds(work)) break;
  }
  return internal::geos_make_valid(std::vector<Rings>{rings}, false);
#endif
}

} // namespace pma_tool

#endif // PMA_TOOL_REPAIR_H
