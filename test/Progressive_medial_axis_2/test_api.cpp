// The public C++ interface as a CGAL user meets it: every public overload
// and accessor, with the kernels a user has (Epick, Epeck,
// Epeck_with_sqrt), simple polygons and polygons with holes, one-shot and
// progressive use, navigation by handles, and the fixed bugs of issue 8,
// each checked through the public interface only.
//
//   test_api [TOOL DATA_DIR]      (with the tool: current_shape() against --shape-out)
//   test_api --threads            (only the concurrency part, for ThreadSanitizer)

#include <CGAL/Progressive_medial_axis_2.h>
#include <CGAL/Progressive_medial_axis_2/Accuracy.h>
#include <CGAL/Progressive_medial_axis_2/Medial_axis_centerline_2.h>
#include <CGAL/Progressive_medial_axis_2/Medial_axis_significance_2.h>
#include <CGAL/Progressive_medial_axis_2/maximum_inscribed_circle_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel_with_sqrt.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/CORE_Expr.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/task_arena.h>
#endif

#include <pma_test/check.h>
#include <pma_test/random_polygons.h>
#include <pma_tool/medial_axis_io.h>
#include <pma_tool/polygon_io.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <list>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <unistd.h>
#include <vector>

namespace {

std::string data_dir;   // the test data (second argument)

typedef CGAL::Exact_predicates_inexact_constructions_kernel Epick;
typedef CGAL::Exact_predicates_exact_constructions_kernel Epeck;
typedef CGAL::Exact_predicates_exact_constructions_kernel_with_sqrt Epeck_sqrt;

// The L-shaped hexagon: one reflex vertex at (1, 1).
template <class K>
CGAL::Polygon_2<K> l_shape()
{
  CGAL::Polygon_2<K> p;
  const int xy[6][2] = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  for(const auto& c : xy) p.push_back(typename K::Point_2(c[0], c[1]));
  return p;
}

// A 10 x 6 plate with two holes.
template <class K>
CGAL::Polygon_with_holes_2<K> plate()
{
  typedef typename K::Point_2 P;
  CGAL::Polygon_2<K> outer, a, b;
  for(const P& p : {P(0, 0), P(10, 0), P(10, 6), P(0, 6)}) outer.push_back(p);
  for(const P& p : {P(2, 2), P(2, 4), P(4, 4), P(4, 2)}) a.push_back(p);
  for(const P& p : {P(6, 2), P(7, 4), P(8, 2)}) b.push_back(p);
  CGAL::Polygon_with_holes_2<K> r(outer);
  r.add_hole(a);
  r.add_hole(b);
  return r;
}

// The set of named curves of an axis (names of the complete axis).
template <class MA>
std::multiset<std::string> pairs(const MA& ma)
{
  pma_tool::Generator_names<MA> names(ma, pma_tool::Generator_names<MA>::INPUT);
  std::multiset<std::string> out;
  for(const auto& c : pma_tool::named_curves(ma, names)) out.insert(c.a + " " + c.b);
  return out;
}

// One-shot and progressive computation with input of kernel K, both with
// default traits, against the Epick reference.
template <class K>
void kernels_case(const char* name, const std::multiset<std::string>& simple_ref,
                  const std::multiset<std::string>& holes_ref)
{
  const auto a = CGAL::medial_axis_2(l_shape<K>());
  CHECK(pairs(a) == simple_ref, name << ": one-shot, simple polygon");
  const auto b = CGAL::medial_axis_2(plate<K>());
  CHECK(pairs(b) == holes_ref, name << ": one-shot, polygon with holes");
  CGAL::Progressive_medial_axis_2<> p(plate<K>());
  p.refine_all();
  CHECK(pairs(p.medial_axis()) == holes_ref, name << ": progressive with default traits");
  // a range of rings of points of K
  std::vector<std::vector<typename K::Point_2> > rings(1);
  for(const auto& q : l_shape<K>()) rings[0].push_back(q);
  CHECK(pairs(CGAL::medial_axis_2(rings)) == simple_ref, name << ": one-shot from a range of rings");
}

void kernels()
{
  const auto simple_ref = pairs(CGAL::medial_axis_2(l_shape<Epick>()));
  const auto holes_ref = pairs(CGAL::medial_axis_2(plate<Epick>()));
  CHECK(simple_ref.size() == 9, "the L shape has 9 medial curves (as the oracle says), got " << simple_ref.size());
  kernels_case<Epeck>("Epeck input", simple_ref, holes_ref);
  kernels_case<Epeck_sqrt>("Epeck_with_sqrt input", simple_ref, holes_ref);
  // the traits over each kernel
  typedef CGAL::Progressive_medial_axis_traits_2<Epeck> Epeck_traits;
  const CGAL::Medial_axis_2<Epeck> e = CGAL::medial_axis_2(plate<Epeck>(), Epeck_traits());
  CHECK(pairs(e) == holes_ref, "Epeck traits");
  static_assert(Epeck_traits::Has_exact_decisions, "Epeck traits decide exactly");
  static_assert(CGAL::Progressive_medial_axis_traits_2<Epick>::Has_exact_decisions, "Epick traits decide exactly");
  static_assert(!CGAL::Progressive_medial_axis_traits_2<CGAL::Simple_cartesian<double> >::Has_exact_decisions,
                "the double model is asked for explicitly");
  typedef CGAL::Progressive_medial_axis_traits_2<CGAL::Simple_cartesian<double> > Double_traits;
  CHECK(pairs(CGAL::medial_axis_2(plate<Epick>(), Double_traits())) == holes_ref, "double model");
  // rings given up (a moved-from vector): the same axis, and the rings emptied
  const CGAL::Polygon_with_holes_2<Epick> given_plate = plate<Epick>();
  std::vector<std::vector<Epick::Point_2> > given;
  given.emplace_back(given_plate.outer_boundary().begin(), given_plate.outer_boundary().end());
  for(const auto& hole : given_plate.holes()) given.emplace_back(hole.begin(), hole.end());
  CHECK(pairs(CGAL::medial_axis_2(std::move(given), CGAL::Progressive_medial_axis_traits_2<Epick>())) == holes_ref,
        "one-shot of rings given up");
  CHECK(given.empty(), "the rings given up to the one-shot are emptied");
  typedef CGAL::Progressive_medial_axis_traits_2<CGAL::Simple_cartesian<CORE::Expr> > Core_traits;
  CHECK(pairs(CGAL::medial_axis_2(l_shape<Epick>(), Core_traits())) == simple_ref, "CORE::Expr model");
  // the CORE::Expr model writes no Core_Diagnostics file into the working
  // directory (syn_ngon64, a regular 64-gon, used to)
  if(!data_dir.empty()) {
    char dir[] = "/tmp/pma_api_core_XXXXXX";
    char cwd[4096];
    const auto ngon = pma_tool::read_polygon_file<Epick::Point_2>(data_dir + "/syn_ngon64.wkt");
    CHECK(mkdtemp(dir) != nullptr && getcwd(cwd, sizeof(cwd)) != nullptr && chdir(dir) == 0, "temporary directory");
    const auto exact = CGAL::medial_axis_2(ngon, Core_traits());
    CHECK(exact.number_of_edges() == CGAL::medial_axis_2(ngon).number_of_edges(), "CORE::Expr model on a 64-gon");
    CHECK(access("Core_Diagnostics", F_OK) != 0, "the CORE::Expr model wrote a Core_Diagnostics file");
    std::remove("Core_Diagnostics");
    CHECK(chdir(cwd) == 0, "back to the working directory");
    rmdir(dir);
  }
  // a polygon with another container
  CGAL::Polygon_2<Epick, std::list<Epick::Point_2> > listed;
  for(const auto& q : l_shape<Epick>()) listed.push_back(q);
  CHECK(pairs(CGAL::medial_axis_2(listed)) == simple_ref, "Polygon_2 with a std::list container");
  // exact input whose points round to one double: an error, not a crash
  std::vector<std::vector<Epeck::Point_2> > close(1);
  close[0] = {Epeck::Point_2(0, 0), Epeck::Point_2(4, 0), Epeck::Point_2(Epeck::FT(2) + Epeck::FT(1e-30), 2),
              Epeck::Point_2(2, 2), Epeck::Point_2(0, 4)};
  bool error = false;
  try {
    CGAL::medial_axis_2(close);   // default traits of Epeck: exact coordinates, valid polygon
  } catch(const CGAL::Progressive_medial_axes::Input_error&) {
    error = true;
  }
  CHECK(!error, "exact input with points 1e-30 apart is valid with Epeck traits");
  error = false;
  try {
    CGAL::medial_axis_2(close, CGAL::Progressive_medial_axis_traits_2<Epick>());
  } catch(const CGAL::Progressive_medial_axes::Input_error& e) {
    error = std::string(e.what()).find("zero-length edge: ring 0") != std::string::npos;
  }
  CHECK(error, "consecutive points that round to one double are reported with Epick traits");
}

// Significance, pruning, centerline and inscribed circle on the axis of
// every traits model and of a progressive step: the same answers.
template <class K>
void analysis_case(const CGAL::Medial_axis_2<K>& ma, const std::string& name, double radius, std::size_t kept,
                   std::size_t paths)
{
  const auto c = CGAL::maximum_inscribed_circle_2(ma);
  CHECK(std::fabs(CGAL::to_double(c.radius) - radius) <= 1e-12 * radius,
        name << ": inscribed circle of radius " << CGAL::to_double(c.radius) << ", expected " << radius);
  const CGAL::Medial_axis_significance_2<K> sig(ma);
  const auto pruned = CGAL::prune_medial_axis_2(sig, 0.3 * radius);
  CHECK(pruned.curves().size() == kept, name << ": " << pruned.curves().size() << " kept curves, expected " << kept);
  const auto centerline = CGAL::medial_axis_centerline_2(pruned, true);
  CHECK(centerline.paths().size() == paths,
        name << ": " << centerline.paths().size() << " centerline paths, expected " << paths);
}

void analysis()
{
  const auto ref = CGAL::medial_axis_2(plate<Epick>());
  const double radius = CGAL::to_double(CGAL::maximum_inscribed_circle_2(ref).radius);
  const CGAL::Medial_axis_significance_2<Epick> sig(ref);
  const auto pruned = CGAL::prune_medial_axis_2(sig, 0.3 * radius);
  const std::size_t kept = pruned.curves().size();
  const std::size_t paths = CGAL::medial_axis_centerline_2(pruned, true).paths().size();
  CHECK(kept > 4 && paths > 1, "plate: " << kept << " kept curves, " << paths << " centerline paths");
  analysis_case(CGAL::medial_axis_2(plate<Epeck>(), CGAL::Progressive_medial_axis_traits_2<Epeck>()), "Epeck traits",
                radius, kept, paths);
  analysis_case(CGAL::medial_axis_2(plate<Epick>(),
                                    CGAL::Progressive_medial_axis_traits_2<CGAL::Simple_cartesian<double> >()),
                "double model", radius, kept, paths);
  analysis_case(CGAL::medial_axis_2(plate<Epick>(),
                                    CGAL::Progressive_medial_axis_traits_2<CGAL::Simple_cartesian<CORE::Expr> >()),
                "CORE::Expr model", radius, kept, paths);
  // at a progressive step: the axis of the current shape
  CGAL::Progressive_medial_axis_2<> p(plate<Epick>());
  p.refine_to(p.number_of_steps() / 2);
  const auto& step = p.medial_axis();
  const auto c = CGAL::maximum_inscribed_circle_2(step);
  double best = 0;
  for(const auto& v : step.vertices()) best = std::max(best, CGAL::to_double(v.radius()));
  CHECK(c.vertex && CGAL::to_double(c.radius) == best, "progressive step: the inscribed circle");
  const CGAL::Medial_axis_significance_2<Epick> step_sig(step);
  CHECK(!CGAL::prune_medial_axis_2(step_sig, 0.1 * best).curves().empty(), "progressive step: pruning");
}

// Navigation by handles, on the plate.
void navigation()
{
  const auto ma = CGAL::medial_axis_2(plate<Epick>());
  typedef std::remove_const<decltype(ma)>::type MA;
  std::size_t faces = 0, medial = 0;
  for(const auto& f : ma.faces()) {
    ++faces;
    // the cell boundary is a cycle; each half-edge has f on its left
    const auto ccb = f.ccb();
    CHECK(!ccb.empty(), "a cell has a boundary");
    for(std::size_t i = 0; i < ccb.size(); ++i) {
      CHECK(ccb[i].face() == f, "half-edge of the cell's boundary has the cell on its left");
      CHECK(ccb[i].next() == ccb[(i + 1) % ccb.size()], "next() walks the cell");
      CHECK(ccb[i].next().prev() == ccb[i], "prev() undoes next()");
      CHECK(ccb[i].opposite().opposite() == ccb[i], "opposite() is an involution");
      CHECK(ccb[i].target() == ccb[(i + 1) % ccb.size()].source(), "consecutive half-edges meet");
      if(ccb[i].kind() == MA::MEDIAL_CURVE) ++medial;
    }
    int own = 0;
    for(const auto& h : ccb) own += (h.kind() == MA::BOUNDARY_EDGE);
    CHECK(own == (f.is_point() ? 0 : 1), "a segment's cell holds its segment, a point's none: " << f.id());
  }
  CHECK(faces == ma.number_of_faces(), "faces()");
  CHECK(medial == 2 * ma.number_of_edges(), "every medial curve bounds two cells");
  // around every vertex: counter-clockwise, consistent with the cells
  for(const auto& v : ma.vertices()) {
    const auto in = v.incident_halfedges();
    CHECK(int(in.size()) >= v.degree(), "incident half-edges include the curves");
    for(const auto& h : in) CHECK(h.target() == v, "incident half-edges end at the vertex");
    const auto gens = v.generators();
    CHECK(gens.size() >= 1, "a vertex touches cells");
  }
  // one cycle per hole
  CHECK(long(ma.number_of_edges()) - long(ma.number_of_vertices()) + 1 == 2, "two holes, two cycles");
  // handles stay valid when the axis moves
  MA moved;
  std::vector<MA::Vertex_handle> before;
  for(const auto& v : ma.vertices()) before.push_back(v);
  const auto p0 = before.front().point();
  MA copy = ma;
  moved = std::move(copy);
  CHECK(before.front().point() == p0, "handles stay valid after the axis is moved");
  CHECK(moved.number_of_edges() == ma.number_of_edges(), "a moved axis is the same axis");
  CHECK(MA().number_of_vertices() == 0 && MA().number_of_edges() == 0, "an empty axis");
}

// Vertex::generators() is counter-clockwise: on the L shape, the branch
// point (1.5, 0.5) touches e0.0 (below), e0.1 (right), e0.2 (above).
void generators_counter_clockwise()
{
  const auto ma = CGAL::medial_axis_2(l_shape<Epick>());
  bool found = false;
  for(const auto& v : ma.vertices()) {
    if(v.point() != Epick::Point_2(1.5, 0.5)) continue;
    found = true;
    std::vector<std::string> g;
    for(const auto& f : v.generators()) g.push_back(f.id());
    CHECK(g.size() == 3, "degree 3");
    const std::string s = g[0] + " " + g[1] + " " + g[2];
    CHECK(s == "e0.0 e0.1 e0.2" || s == "e0.1 e0.2 e0.0" || s == "e0.2 e0.0 e0.1",
          "generators counter-clockwise: got " << s);
  }
  CHECK(found, "the branch point (1.5, 0.5)");
}

// A point where four generators meet (the centre of a square) is one vertex.
void degree_four()
{
  CGAL::Polygon_2<Epick> square;
  for(const auto& p : {Epick::Point_2(0, 0), Epick::Point_2(2, 0), Epick::Point_2(2, 2), Epick::Point_2(0, 2)})
    square.push_back(p);
  const auto ma = CGAL::medial_axis_2(square);
  typedef std::remove_const<decltype(ma)>::type MA;
  int branch = 0;
  for(const auto& v : ma.vertices()) {
    if(v.kind() != MA::BRANCH_POINT) continue;
    ++branch;
    CHECK(v.degree() == 4 && v.generators().size() == 4, "the centre has degree 4");
    CHECK(v.point() == Epick::Point_2(1, 1) && v.radius() == 1, "the centre and its radius");
  }
  CHECK(branch == 1, "one branch point, got " << branch);
  CHECK(ma.number_of_edges() == 4, "four curves, got " << ma.number_of_edges());
}

// Halfedge_handle::source_radius() and target_radius() are the radii of the
// vertex handles (also where edges of length zero join several vertices at
// one point: rectilinear polygons and the centre of a square), and
// input_rings() is the input polygon as given, ring by ring.
template <class Traits>
void radii_and_rings(const std::string& model)
{
  std::vector<std::vector<pma_test::Ring> > inputs;
  inputs.push_back({pma_test::Ring{{0, 0}, {2, 0}, {2, 2}, {0, 2}}});
  for(std::uint64_t seed = 1; seed <= 4; ++seed) inputs.push_back({pma_test::random_rectilinear_polygon(seed, 40, seed % 2 == 0)});
  inputs.push_back(pma_test::random_polygon_with_holes(3, 20, 6));
  std::size_t edges = 0, wrong_radii = 0, wrong_rings = 0;
  for(const auto& rings : inputs) {
    const auto ma = CGAL::medial_axis_2(rings, Traits());
    for(const auto& e : ma.edges()) {
      ++edges;
      for(const auto& h : {e, e.opposite()})
        if(h.source_radius() != h.source().radius() || h.target_radius() != h.target().radius()) ++wrong_radii;
    }
    const auto got = ma.input_rings();
    bool same = got.size() == rings.size() && ma.number_of_input_rings() == rings.size();
    for(std::size_t r = 0; same && r < rings.size(); ++r) {
      same = got[r].size() == rings[r].size() && ma.input_ring_size(r) == rings[r].size();
      for(std::size_t i = 0; same && i < rings[r].size(); ++i)
        same = CGAL::to_double(got[r][i].x()) == rings[r][i].x() && CGAL::to_double(got[r][i].y()) == rings[r][i].y() &&
               got[r][i] == ma.point({int(r), int(i)});
    }
    if(!same) ++wrong_rings;
  }
  CHECK(wrong_radii == 0, model << ": " << wrong_radii << " half-edges whose source_radius() or target_radius() is not their vertex's radius");
  CHECK(wrong_rings == 0, model << ": input_rings() differs from the input on " << wrong_rings << " polygons");
  CHECK(edges > 200, model << ": only " << edges << " curves");
  CHECK(CGAL::Medial_axis_2<Epick>().input_rings().empty(), "input_rings() of an empty axis");
}

// Curves: polylines within tolerance, no silent cap, lengths far from 1.
void curves()
{
  const auto ma = CGAL::medial_axis_2(l_shape<Epick>());
  typedef std::remove_const<decltype(ma)>::type MA;
  for(const auto& e : ma.edges()) {
    if(e.curve_kind() != MA::PARABOLIC_ARC) continue;
    CHECK(e.polyline(0).size() > 2, "polyline(0) is not the chord of a parabola");
    CHECK(e.polyline(1e-12).size() > 10000, "a fine polyline is not capped at 10,000 points");
    CHECK(std::fabs(e.length() - 0.42577062416473832) < 1e-12, "parabola length, got " << e.length());
  }
  double reference = 0;
  for(const auto& e : ma.edges()) reference += e.length();
  for(double scale : {1e300, 1e-300}) {
    CGAL::Polygon_2<Epick> p;
    for(const auto& q : l_shape<Epick>()) p.push_back(Epick::Point_2(q.x() * scale, q.y() * scale));
    const auto big = CGAL::medial_axis_2(p);
    double total = 0;
    for(const auto& e : big.edges()) {
      CHECK(std::isfinite(e.length()) && e.length() > 0, "length at scale " << scale << ": " << e.length());
      total += e.length() / scale;
      for(const auto& q : e.polyline(1e-3 * scale))
        CHECK(std::isfinite(q.first) && std::isfinite(q.second), "polyline at scale " << scale);
    }
    CHECK(std::fabs(total - reference) < 1e-12 * reference,
          "scale-invariant total length at scale " << scale << ": " << total << " vs " << reference);
  }
}

// shape_rings() splices a lobe (a counter-clockwise cycle: a part of the
// interior that meets the rest at one place) into the ring it touches, as an
// input ring that touches itself: into the outer ring, and, where it touches
// only a hole, into that hole (an island in a hole, forty-eighth session;
// before, it was written as a hole inside the hole).
void lobes()
{
  // places: the outer square 0-3, a clockwise hole 4-7, and an island 8-10
  // inside the hole, whose vertex 8 is at the place of the hole's vertex 6;
  // a lobe 11-13 of the outer ring at the place of its vertex 1
  const double xy[14][2] = {{0, 0}, {10, 0}, {10, 10}, {0, 10}, {2, 2}, {2, 8}, {5, 8}, {8, 2},
                            {5, 8}, {4, 6}, {6, 6}, {10, 0}, {12, -1}, {12, 1}};
  auto same_place = [&](int u, int v) { return xy[u][0] == xy[v][0] && xy[u][1] == xy[v][1]; };
  auto ccw = [&](const std::vector<int>& c) {
    double a = 0;
    for(std::size_t i = 0; i < c.size(); ++i) {
      const double* p = xy[c[i]];
      const double* q = xy[c[(i + 1) % c.size()]];
      a += p[0] * q[1] - p[1] * q[0];
    }
    return a > 0;
  };
  std::vector<std::vector<int> > cycles = {{0, 1, 2, 3}, {4, 5, 6, 7}, {8, 9, 10}, {11, 12, 13}};
  CHECK(ccw(cycles[0]) && !ccw(cycles[1]) && ccw(cycles[2]) && ccw(cycles[3]), "the test's orientations");
  CGAL::Progressive_medial_axes::internal::splice_lobes(cycles, same_place, ccw);
  const std::vector<std::vector<int> > expected = {{0, 11, 12, 13, 1, 2, 3}, {4, 5, 8, 9, 10, 6, 7}};
  CHECK(cycles == expected, "lobes spliced into the outer ring and into the hole they touch ("
                                << cycles.size() << " cycles)");
}

// The half-edge structure's flags of edges of length zero, an array made
// at the first such edge: appending a structure with flags to one without
// and the other way, a rollback of the first flag set in a journal, and an
// edge reused after deletion.
void zero_length_flags()
{
  typedef CGAL::Progressive_medial_axes::internal::Halfedge_structure<Epick::Point_2, double> Hds;
  Hds a, b, c, d;
  const int e0 = a.new_edge(0, 0), e1 = a.new_edge(0, 0);
  const int f0 = b.new_edge(0, 0), f1 = b.new_edge(0, 0);
  b.set_zero_length(f1 + 1, true);
  CHECK(!a.is_zero_length(e0) && !a.is_zero_length(e1 + 1) && !b.is_zero_length(f0) && b.is_zero_length(f1),
        "zero-length flags: set on one half-edge, read on its twin");
  const auto o = a.append(b);
  CHECK(!a.is_zero_length(e0) && !a.is_zero_length(e1) && !a.is_zero_length(f0 + o.halfedge) &&
          a.is_zero_length(f1 + o.halfedge + 1),
        "zero-length flags: a structure with flags appended to one without");
  const int g0 = c.new_edge(0, 0);
  const auto p = a.append(c);
  CHECK(!a.is_zero_length(g0 + p.halfedge) && a.is_zero_length(f1 + o.halfedge) && !a.is_zero_length(e1),
        "zero-length flags: a structure without flags appended to one with");
  const int h0 = d.new_edge(0, 0);
  d.begin_journal();
  const int h1 = d.new_edge(0, 0);
  d.set_zero_length(h0, true);
  d.set_zero_length(h1, true);
  CHECK(d.is_zero_length(h0) && d.is_zero_length(h1), "zero-length flags: set in a journal");
  d.rollback();
  d.end_journal();
  const int h2 = d.new_edge(0, 0);
  CHECK(!d.is_zero_length(h0) && h2 == h1 && !d.is_zero_length(h2),
        "zero-length flags: the first flags rolled back, and a pair made after the rollback");
  d.set_zero_length(h2, true);
  d.delete_edge(h2);
  const int h3 = d.new_edge(0, 0);
  CHECK(h3 == h2 && !d.is_zero_length(h3) && !d.is_zero_length(h0), "zero-length flags: an edge reused");
}

// The half-edge structure's check of itself (is_valid()): it accepts the
// axis of a triangle, built as the engine builds it, and refuses each of
// seven corruptions of it.
void structure_validity()
{
  typedef CGAL::Progressive_medial_axes::internal::Halfedge_structure<Epick::Point_2, double> Hds;
  using CGAL::Progressive_medial_axes::internal::OUTSIDE;
  struct Triangle {
    Hds hds;
    int V[3], F[3], I, b[3], s[3];
    Triangle()
    {
      for(int i = 0; i < 3; ++i) V[i] = hds.new_corner(i);
      for(int i = 0; i < 3; ++i) F[i] = hds.new_face(false, i, (i + 1) % 3);   // side V[i] -> V[i+1]
      I = hds.new_pending_vertex(F[0], F[1], F[2]);
      for(int i = 0; i < 3; ++i) {
        b[i] = hds.new_edge(F[i], OUTSIDE);   // V[i] -> V[i+1]
        hds.he(b[i]).vertex = V[(i + 1) % 3];
        hds.he(b[i] ^ 1).vertex = V[i];
      }
      for(int i = 0; i < 3; ++i) {
        s[i] = hds.new_edge(F[(i + 2) % 3], F[i]);   // V[i] -> I, F[i-1] on its left
        hds.he(s[i]).vertex = I;
        hds.he(s[i] ^ 1).vertex = V[i];
      }
      for(int i = 0; i < 3; ++i) {   // F[i]: b[i], s[i+1] up to I, twin(s[i]) down to V[i]
        const int j = (i + 1) % 3;
        hds.link(b[i], s[j]);
        hds.link(s[j], s[i] ^ 1);
        hds.link(s[i] ^ 1, b[i]);
      }
      for(int i = 0; i < 3; ++i) hds.link(b[(i + 1) % 3] ^ 1, b[i] ^ 1);   // outside, clockwise
      for(int i = 0; i < 3; ++i) {
        hds.face(F[i]).halfedge = b[i];
        hds.vertex(V[i]).halfedge = b[(i + 2) % 3];
      }
      hds.vertex(I).halfedge = s[0];
    }
  };
  std::string why;
  {
    Triangle t;
    CHECK(t.hds.is_valid(&why), "structure check: a triangle's axis is valid: " << why);
  }
  auto refused = [&](const char* what, auto corrupt) {
    Triangle t;
    corrupt(t);
    why.clear();
    CHECK(!t.hds.is_valid(&why) && !why.empty(), "structure check: " << what << " is refused");
  };
  refused("next without its prev", [](Triangle& t) { t.hds.he(t.b[0]).next = t.b[1]; });
  refused("a half-edge on another face than its next", [](Triangle& t) { t.hds.he(t.b[0]).face = t.F[1]; });
  refused("a face whose half-edge is another's", [](Triangle& t) { t.hds.face(t.F[0]).halfedge = t.b[1]; });
  refused("a vertex whose half-edge ends elsewhere", [](Triangle& t) { t.hds.vertex(t.I).halfedge = t.b[0]; });
  refused("a deleted vertex still in use", [](Triangle& t) { t.hds.delete_vertex(t.I); });
  refused("a deleted edge off the free list", [](Triangle& t) {
    using CGAL::Progressive_medial_axes::internal::DELETED;
    t.hds.he(t.b[0]).face = DELETED;
    t.hds.he(t.b[0] ^ 1).face = DELETED;
  });
  CHECK(why.find("is not free") != std::string::npos, "structure check: the free lists are checked first: " << why);
  refused("a half-edge ending where its next does not start", [](Triangle& t) { t.hds.he(t.s[0]).vertex = t.V[1]; });
  // and the axes of every step of a progressive run
  CGAL::Progressive_medial_axis_2<> pma(pma_test::random_polygon_with_holes(5, 40, 4));
  std::size_t invalid = 0;
  do invalid += !pma.medial_axis().is_valid(true);
  while(pma.refine());
  CHECK(invalid == 0, "structure check: " << invalid << " steps of a progressive run with an invalid structure");
}

// The progressive object: steps, current_shape() with its holes at every
// step, release.
void progressive(const std::string& tool, const std::string& data)
{
  // many holes: a hole cycle can come before the outer one
  const auto rings = pma_test::random_polygon_with_holes(11, 12, 30);
  CGAL::Progressive_medial_axis_2<> pma(rings);
  std::size_t wrong = 0;
  do {
    const auto shape = pma.current_shape();
    const auto axis_rings = pma.medial_axis().shape_rings();
    if(shape.number_of_holes() + 1 != axis_rings.size()) ++wrong;
    if(shape.outer_boundary().orientation() != CGAL::COUNTERCLOCKWISE) ++wrong;
    for(auto h = shape.holes_begin(); h != shape.holes_end(); ++h)
      if(h->orientation() != CGAL::CLOCKWISE) ++wrong;
    const long cycles = long(pma.medial_axis().number_of_edges()) - long(pma.medial_axis().number_of_vertices()) + 1;
    if(cycles != long(shape.number_of_holes())) ++wrong;
  } while(pma.refine());
  CHECK(wrong == 0, wrong << " steps with a wrong current_shape()");
  CHECK(pma.current_shape().number_of_holes() == 30, "the final shape has the 30 holes");
  CHECK(pma.is_complete() && !pma.is_released(), "complete");
  const std::size_t steps = pma.number_of_steps();
  const auto axis = pma.release_medial_axis();
  CHECK(axis.number_of_edges() > 0, "the released axis");
  CHECK(pma.is_released() && pma.number_of_steps() == steps && pma.current_step() == steps,
        "after release: steps kept, released");
  CHECK(!pma.refine(), "a released object is not refined");

  // refine_to, statistics, the visitor
  struct Counter : CGAL::Default_progressive_medial_axis_visitor {
    std::size_t switches = 0, vanishings = 0, merges = 0, steps = 0;
    void on_switch() { ++switches; }
    void on_vanish() { ++vanishings; }
    void on_merge(const CGAL::Progressive_medial_axes::Merge_statistics&) { ++merges; }
    void on_step(std::size_t, std::size_t) { ++steps; }
  } counter;
  CGAL::Progressive_medial_axis_2<> p2(plate<Epick>(), CGAL::Progressive_medial_axis_traits_2<Epick>(), CGAL::TRUST_INPUT);
  p2.refine_to(3);
  CHECK(p2.current_step() == 3, "refine_to");
  p2.refine_all(counter);
  CHECK(counter.steps == p2.number_of_steps() - 3, "visitor steps");
  CHECK(counter.switches + counter.vanishings > 0 && counter.merges >= counter.steps, "visitor events");
  const auto& s = p2.statistics();
  CHECK(s.input_vertices == 11 && s.holes == 2 && s.triangles > 0 && s.validation_seconds == 0,
        "statistics (input not validated)");

  // the shape at a step equals the tool's --shape-out
  if(!tool.empty()) {
    const std::string file = data + "/syn_cheese1k.wkt";
    const auto input = pma_tool::read_polygon_file<Epick::Point_2>(file);
    CGAL::Progressive_medial_axis_2<> p3(input);
    char dir[] = "/tmp/pma_api_XXXXXX";
    CHECK(mkdtemp(dir) != nullptr, "temporary directory");
    for(std::size_t k : {std::size_t(5), p3.number_of_steps() / 3, p3.number_of_steps() - 1}) {
      p3.refine_to(k);
      const std::string out = std::string(dir) + "/shape.wkt";
      const std::string cmd = tool + " --step " + std::to_string(k) + " --shape-out " + out + " " + file;
      CHECK(std::system(cmd.c_str()) == 0, cmd);
      const auto theirs = pma_tool::read_polygon_file<Epick::Point_2>(out);
      const auto ours = p3.current_shape();
      CHECK(theirs.size() == ours.number_of_holes() + 1, "step " << k << ": rings");
      std::vector<std::vector<Epick::Point_2> > mine{std::vector<Epick::Point_2>(ours.outer_boundary().begin(),
                                                                                 ours.outer_boundary().end())};
      for(auto h = ours.holes_begin(); h != ours.holes_end(); ++h) mine.emplace_back(h->begin(), h->end());
      CHECK(mine == theirs, "step " << k << ": current_shape() equals the tool's --shape-out");
    }
    std::remove((std::string(dir) + "/shape.wkt").c_str());
    rmdir(dir);
  }
}

// Accuracy: E(x) of the exact model equals its floor.
void accuracy()
{
  const auto ma = CGAL::medial_axis_2(plate<Epick>());
  const auto e = CGAL::Progressive_medial_axes::branch_point_errors(ma);
  const auto f = CGAL::Progressive_medial_axes::floor_branch_point_errors(ma);
  CHECK(!e.empty() && e.size() == f.size(), "one E(x) per branch point");
  const auto s = CGAL::Progressive_medial_axes::accuracy_statistics(e);
  CHECK(s.count == e.size() && s.max < 1e-12, "E(x) of exact branch points: " << s.max);
  CHECK(CGAL::Progressive_medial_axes::medial_point_error(1, 1, {{false, 0, 0, 2, 0}, {false, 2, 2, 0, 2}}) == 0,
        "E(x) of the centre of a strip");
}

// Bad input: a clear error.
void bad_input()
{
  std::vector<std::vector<Epick::Point_2> > bowtie{{Epick::Point_2(0, 0), Epick::Point_2(1, 1), Epick::Point_2(1, 0),
                                                    Epick::Point_2(0, 1)}};
  bool error = false;
  try {
    CGAL::Progressive_medial_axes::validate_polygon(bowtie);
  } catch(const CGAL::Progressive_medial_axes::Input_error& e) {
    error = e.ring() == 0 && std::string(e.what()).find("ring 0") != std::string::npos;
  }
  CHECK(error, "validate_polygon() names the ring");

  // The one-shot checks its input while another thread triangulates the
  // points: every kind of invalid polygon gets validate_polygon()'s error
  // (on two threads, where the two run at the same time).
  typedef Epick::Point_2 P;
  const std::vector<std::pair<std::string, std::vector<std::vector<P> > > > invalid{
    {"crossing", bowtie},
    {"zero-length edge", {{P(0, 0), P(4, 0), P(4, 4), P(4, 4), P(0, 4)}}},
    {"spike", {{P(0, 0), P(4, 0), P(4, 2), P(7, 2), P(5, 2), P(4, 3), P(0, 4)}}},
    {"hole outside", {{P(0, 0), P(4, 0), P(4, 4), P(0, 4)}, {P(5, 5), P(6, 5), P(6, 6)}}},
    {"crossing rings", {{P(0, 0), P(4, 0), P(4, 4), P(0, 4)}, {P(1, 1), P(5, 1), P(5, 2), P(1, 2)}}},
    {"too few vertices", {{P(0, 0), P(4, 0)}}},
    {"not finite", {{P(0, 0), P(4, 0), P(std::nan(""), 4)}}}};
  auto message = [](const auto& f) {
    try {
      f();
    } catch(const CGAL::Progressive_medial_axes::Input_error& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  // Each as it is and with `extra` more vertices on the closing edge of its
  // first ring (outside a task arena, only a polygon of min_overlap_vertices
  // or more is checked beside the triangulation).
  const int extra = int(CGAL::Progressive_medial_axes::internal::min_overlap_vertices) + 100;
  for(const auto& [name, small] : invalid)
    for(bool large : {false, true}) {
      auto rings = small;
      if(large && rings[0].size() >= 3) {
        const P a = rings[0].back(), b = rings[0].front();
        for(int i = 1; i <= extra; ++i)
          rings[0].push_back(P(a.x() + (b.x() - a.x()) * i / (extra + 1.0), a.y() + (b.y() - a.y()) * i / (extra + 1.0)));
      }
      const std::string expected = message([&] { CGAL::Progressive_medial_axes::validate_polygon(rings); });
      // called outside any task arena, and in one of two threads
      const std::string plain = message([&] { CGAL::medial_axis_2(rings); });
      std::string in_arena = plain;
#ifdef CGAL_LINKED_WITH_TBB
      tbb::task_arena(2).execute([&] { in_arena = message([&] { CGAL::medial_axis_2(rings); }); });
#endif
      for(const std::string& got : {plain, in_arena})
        CHECK(!expected.empty() && got == expected,
              "one-shot on invalid input (" << name << (large ? ", " + std::to_string(extra) + " more vertices" : "") << "): " << got);
    }
}

// Concurrency: 4 threads read one result, 4 threads build 4 results.
// Outside any task arena, a one-shot of a polygon too small to cut into
// parts neither checks its input beside the triangulation nor starts
// oneTBB; it gives the axis that two threads give.  (Run first: the first
// use of oneTBB attaches the main thread to an arena for good.)
void one_shot_without_tbb()
{
#ifdef CGAL_LINKED_WITH_TBB
  using CGAL::Progressive_medial_axes::internal::tbb_running;
  const auto rings = pma_test::random_polygon_with_holes(11, 12, 0);
  CHECK(!tbb_running(), "oneTBB does not run before the first one-shot");
  const auto alone = CGAL::medial_axis_2(rings);
  CHECK(!tbb_running(), "a one-shot of " << rings[0].size() << " vertices does not start oneTBB");
  std::size_t edges = 0, vertices = 0;
  tbb::task_arena(2).execute([&] {
    const auto ma = CGAL::medial_axis_2(rings);
    edges = ma.number_of_edges();
    vertices = ma.number_of_vertices();
  });
  CHECK(alone.number_of_edges() == edges && alone.number_of_vertices() == vertices && edges > 0,
        "the one-shot without oneTBB has the size of the one on two threads");
#endif
}

void threads()
{
  const auto rings = pma_test::random_polygon_with_holes(5, 20, 12);
  CGAL::Progressive_medial_axis_2<> shared(rings);
  shared.refine_to(shared.number_of_steps() / 2);
  const auto& ma = shared.medial_axis();
  std::vector<double> sums(8, 0);
  std::vector<std::thread> pool;
  for(int t = 0; t < 4; ++t)
    pool.emplace_back([&, t] {
      double s = 0;
      for(const auto& v : ma.vertices()) s += CGAL::to_double(v.radius()) + v.degree();
      for(const auto& e : ma.edges()) s += e.length();
      sums[t] = s;
    });
  for(int t = 4; t < 8; ++t)
    pool.emplace_back([&, t] {
      const auto r = pma_test::random_polygon_with_holes(100 + t, 16, 8);
      CGAL::Progressive_medial_axis_2<> own(r);
      own.refine_all();
      double s = 0;
      for(const auto& e : own.medial_axis().edges()) s += e.length();
      sums[t] = s;
    });
  for(auto& th : pool) th.join();
  CHECK(sums[0] == sums[1] && sums[1] == sums[2] && sums[2] == sums[3], "concurrent readers agree");
  for(int t = 4; t < 8; ++t) CHECK(sums[t] > 0, "concurrent builders");
  // the one-shot divide and conquer, whose parts run on the threads of TBB
  // (when linked with it), gives the progressive result
  const auto big = pma_test::random_polygon_with_holes(7, 60, 20);
  CGAL::Progressive_medial_axis_2<> progressive(big);
  progressive.refine_all();
  const auto one_shot = CGAL::medial_axis_2(big);
  CHECK(one_shot.number_of_edges() == progressive.medial_axis().number_of_edges() &&
          one_shot.number_of_vertices() == progressive.medial_axis().number_of_vertices(),
        "the parallel one-shot axis has the size of the progressive one");
#ifdef CGAL_LINKED_WITH_TBB
  // in a task arena of two threads the parts run in parallel from the
  // start: parts built in structures of their own, moved into the result
  // and their structures reused for the next parts
  const auto large = pma_test::random_polygon_with_holes(8, 400, 60);
  CGAL::Progressive_medial_axis_2<> large_progressive(large);
  large_progressive.refine_all();
  std::size_t edges = 0, vertices = 0;
  CGAL::Progressive_medial_axis_statistics stats;
  tbb::task_arena(2).execute([&] {
    const auto a = CGAL::medial_axis_2(large, CGAL::Progressive_medial_axis_traits_2<CGAL::Epick>(),
                                       CGAL::CHECK_INPUT, &stats);
    edges = a.number_of_edges();
    vertices = a.number_of_vertices();
  });
  CHECK(stats.parts >= 4 && edges == large_progressive.medial_axis().number_of_edges() &&
          vertices == large_progressive.medial_axis().number_of_vertices(),
        "the one-shot in parallel parts (" << stats.parts << ") has the size of the progressive axis");
#endif
}

} // namespace

int main(int argc, char** argv)
{
  if(argc > 1 && std::string(argv[1]) == "--threads") {
    threads();
    return pma_test::report("test_api --threads");
  }
  if(argc > 2) data_dir = argv[2];
  one_shot_without_tbb();
  kernels();
  analysis();
  navigation();
  generators_counter_clockwise();
  degree_four();
  radii_and_rings<CGAL::Progressive_medial_axis_traits_2<Epick> >("default traits");
  radii_and_rings<CGAL::Progressive_medial_axis_traits_2<CGAL::Simple_cartesian<double> > >("double model");
  curves();
  lobes();
  zero_length_flags();
  structure_validity();
  progressive(argc > 2 ? argv[1] : "", argc > 2 ? argv[2] : "");
  accuracy();
  bad_input();
  threads();
  return pma_test::report("test_api");
}
