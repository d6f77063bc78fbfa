// Tests of the input layer of Progressive_medial_axis_2: WKT and GeoJSON readers, the
// WKT writer, and the geometric validation of polygons with holes.
//
// Reads only files under PMA_TEST_DATA (test/Progressive_medial_axis_2/data).

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2_algorithms.h>
#include <CGAL/intersections.h>
#include <CGAL/Exact_rational.h>
#include <CGAL/Simple_cartesian.h>

#include <CGAL/Progressive_medial_axis_2/Input_error.h>
#include <pma_tool/polygon_io.h>
#include <CGAL/Progressive_medial_axis_2/validate_polygon.h>
#include <CGAL/Progressive_medial_axis_2/internal/Curve_evolution.h>

#include <pma_test/check.h>
#include <pma_test/geojson_readers.h>

#include <chrono>
#include <clocale>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <limits>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#ifndef PMA_TEST_DATA
#  error "PMA_TEST_DATA must name the test data directory"
#endif

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_2 Point;
typedef CGAL::Progressive_medial_axes::Rings<Point> Rings;
using CGAL::Progressive_medial_axes::Input_error;


const int ANY = -2; // ring or vertex not checked

// Runs `f`, which must throw an Input_error whose one-line message contains `substring`
// and whose ring() and vertex() are `ring` and `vertex` (unless ANY).
bool throws_input_error(const std::function<void()>& f, const std::string& substring,
                        int ring, int vertex, std::string& diagnostic)
{
  try {
    f();
  } catch(const Input_error& e) {
    std::string what = e.what();
    if(what.find(substring) == std::string::npos)
      diagnostic = "message \"" + what + "\" does not contain \"" + substring + "\"";
    else if(what.find('\n') != std::string::npos)
      diagnostic = "message \"" + what + "\" is not one line";
    else if(ring != ANY && e.ring() != ring)
      diagnostic = "message \"" + what + "\": ring() is " + std::to_string(e.ring()) +
                   ", expected " + std::to_string(ring);
    else if(vertex != ANY && e.vertex() != vertex)
      diagnostic = "message \"" + what + "\": vertex() is " + std::to_string(e.vertex()) +
                   ", expected " + std::to_string(vertex);
    else
      return true;
    return false;
  } catch(const std::exception& e) {
    diagnostic = std::string("unexpected exception: ") + e.what();
    return false;
  }
  diagnostic = "no exception thrown, expected \"" + substring + "\"";
  return false;
}

// The statement throws an Input_error as throws_input_error() wants.
#define CHECK_INPUT_ERROR(statement, substring, ring, vertex)                                           \
  do {                                                                                                  \
    std::string diagnostic_;                                                                            \
    const bool thrown_ = throws_input_error([&]() { statement; }, substring, ring, vertex, diagnostic_); \
    REQUIRE(thrown_, #statement << ": " << diagnostic_);                                                \
  } while(0)

// The rings are a valid polygon.
#define CHECK_VALID(rings)                                                                \
  do {                                                                                    \
    std::string error_;                                                                   \
    try {                                                                                 \
      CGAL::Progressive_medial_axes::validate_polygon_rings<K>(rings);                    \
    } catch(const std::exception& e_) {                                                   \
      error_ = e_.what();                                                                 \
    }                                                                                     \
    REQUIRE(error_.empty(), #rings << " should be valid: " << error_);                   \
  } while(0)

void validate(const Rings& rings) { CGAL::Progressive_medial_axes::validate_polygon_rings<K>(rings); }

Rings read_wkt(const std::string& text)
{
  std::istringstream in(text);
  return pma_tool::read_wkt_polygon<Point>(in);
}

// how many texts the fast GeoJSON reader read (where simdjson is built in)
long fast_geojson_reads = 0;

// Compares the tool's two GeoJSON readers on `text` (pma_test/geojson_readers.h).
void check_geojson_readers(const std::string& text)
{
  bool fast_read = false;
  const std::string difference = pma_test::geojson_readers_differ<Point>(text, fast_read);
  CHECK(difference.empty(), difference << " on " << text);
  if(fast_read)
    ++fast_geojson_reads;
}

Rings read_geojson(const std::string& text)
{
  check_geojson_readers(text);
  std::istringstream in(text);
  return pma_tool::read_geojson_polygon<Point>(in);
}

std::string data(const std::string& name) { return std::string(PMA_TEST_DATA) + "/" + name; }

bool same_double(double a, double b) { return std::memcmp(&a, &b, sizeof(double)) == 0; }

bool same_rings(const Rings& a, const Rings& b)
{
  if(a.size() != b.size())
    return false;
  for(std::size_t r = 0; r < a.size(); ++r) {
    if(a[r].size() != b[r].size())
      return false;
    for(std::size_t i = 0; i < a[r].size(); ++i)
      if(!same_double(a[r][i].x(), b[r][i].x()) || !same_double(a[r][i].y(), b[r][i].y()))
        return false;
  }
  return true;
}

double seconds_since(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::vector<Point> square(double x0, double y0, double x1, double y1, bool ccw = true)
{
  std::vector<Point> s = { Point(x0, y0), Point(x1, y0), Point(x1, y1), Point(x0, y1) };
  if(!ccw)
    std::swap(s[1], s[3]);
  return s;
}

// ------------------------------------------------------------------ WKT reading

int test_wkt_reading()
{
  Rings r = read_wkt("POLYGON ((0 0, 1 0, 1 1, 0 1, 0 0))");
  REQUIRE(r.size() == 1 && r[0].size() == 4);
  REQUIRE(r[0][1] == Point(1, 0) && r[0][3] == Point(0, 1));

  // Keyword case, white space, newlines, number syntax as strtod, order kept.
  r = read_wkt("\n  polygon\t(\n( 0 0 ,\r\n+1.5E+00 0,1e0 1 , .5 5. ,0 0 ) ,\n (0.25 0.25,0.5 0.25,0.5 0.5,0.25 0.25))  \n");
  REQUIRE(r.size() == 2 && r[0].size() == 4 && r[1].size() == 3);
  REQUIRE(r[0][1] == Point(1.5, 0) && r[0][2] == Point(1, 1) && r[0][3] == Point(0.5, 5));
  REQUIRE(r[1][0] == Point(0.25, 0.25) && r[1][2] == Point(0.5, 0.5));
  r = read_wkt("PoLyGoN((0 0,1 0,1 1,0 0))");
  REQUIRE(r.size() == 1 && r[0].size() == 3);

  // Clockwise rings are kept as written.
  r = read_wkt("POLYGON ((0 0, 0 1, 1 1, 1 0, 0 0))");
  REQUIRE(r[0][1] == Point(0, 1) && r[0][3] == Point(1, 0));

  // A MULTIPOLYGON holding one polygon; a UTF-8 byte order mark.
  r = read_wkt("MULTIPOLYGON (((0 0, 4 0, 4 4, 0 0), (1 0.5, 3 0.5, 3 2, 1 0.5)))");
  REQUIRE(r.size() == 2 && r[1].size() == 3);
  r = read_wkt("\xEF\xBB\xBFPOLYGON ((0 0, 1 0, 1 1, 0 0))");
  REQUIRE(r.size() == 1);

  // Numbers convert exactly as strtod (in the C locale).
  r = read_wkt("POLYGON ((0.1 -0, 2.2250738585072014e-308 4.9406564584124654e-324, 1e-400 -1e-400, 0.1 -0))");
  REQUIRE(same_double(r[0][0].x(), 0.1) && same_double(r[0][0].y(), -0.0));
  REQUIRE(same_double(r[0][1].x(), 2.2250738585072014e-308));
  REQUIRE(same_double(r[0][1].y(), std::numeric_limits<double>::denorm_min()));
  REQUIRE(same_double(r[0][2].x(), 0.0) && same_double(r[0][2].y(), -0.0));
  {
    std::mt19937_64 rng(12345);
    for(int i = 0; i < 20000; ++i) {
      std::string token;
      if(rng() % 2) token += '-';
      int digits = 1 + static_cast<int>(rng() % 25);
      for(int d = 0; d < digits; ++d) token += static_cast<char>('0' + rng() % 10);
      if(rng() % 2) {
        token += '.';
        int fraction = static_cast<int>(rng() % 25);
        for(int d = 0; d < fraction; ++d) token += static_cast<char>('0' + rng() % 10);
      }
      if(rng() % 2)
        token += "e" + std::to_string(static_cast<int>(rng() % 700) - 350);
      double expected = std::strtod(token.c_str(), nullptr);
      if(!std::isfinite(expected))
        continue;
      Rings q = read_wkt("POLYGON ((" + token + " 0, 1 0, 1 1, " + token + " 0))");
      if(!same_double(q[0][0].x(), expected)) {
        std::fprintf(stderr, "number %s read as %.17g, strtod gives %.17g\n", token.c_str(),
                     q[0][0].x(), expected);
        REQUIRE(false);
      }
    }
  }

  // Errors, with line and column.
  CHECK_INPUT_ERROR(read_wkt("POLYGON ((0 0, 1 0; 1 1, 0 1, 0 0))"),
                    "malformed WKT at line 1, column 19: expected ',' or ')'", -1, -1);
  CHECK_INPUT_ERROR(read_wkt("POLYGON ((0 0,\n  1 0,\n  1 1 x, 0 0))"),
                    "malformed WKT at line 3, column 7: expected ',' or ')'", -1, -1);
  CHECK_INPUT_ERROR(read_wkt("POLYGON ((0 0, 1 0, 1 1, 0 0)"), "malformed WKT at line 1, column 30", -1, -1);
  CHECK_INPUT_ERROR(read_wkt("POLYGON ((0 0, 1 0, 1, 0 0))"), "malformed WKT at line 1, column 22", -1, -1);
  CHECK_INPUT_ERROR(read_wkt("POLYGON ((0 0, 1 0, 1 1, 0 0)) x"), "unexpected text after the polygon", -1, -1);
  CHECK_INPUT_ERROR(read_wkt("POLYGON (0 0, 1 0, 1 1, 0 0)"), "expected '('", -1, -1);
  CHECK_INPUT_ERROR(read_wkt("POLYGON (())"), "expected a number", -1, -1);
  CHECK_INPUT_ERROR(read_wkt(""), "no polygon", -1, -1);
  CHECK_INPUT_ERROR(read_wkt("   \n"), "no polygon", -1, -1);
  CHECK_INPUT_ERROR(read_wkt("(0 0, 1 0)"), "malformed WKT at line 1, column 1", -1, -1);
  CHECK_INPUT_ERROR(read_wkt("POLYGON EMPTY"), "empty polygon", -1, -1);
  CHECK_INPUT_ERROR(read_wkt("polygon empty"), "empty polygon", -1, -1);
  CHECK_INPUT_ERROR(read_wkt("MULTIPOLYGON EMPTY"), "empty polygon", -1, -1);
  // Z, M and ZM values are read and ignored: the polygon's projection to the plane
  const Rings flat = read_wkt("POLYGON ((0 0, 1 0, 1 1, 0 0))");
  for(const char* text : {"POLYGON Z ((0 0 0, 1 0 5, 1 1 0, 0 0 0))", "POLYGON M ((0 0 0, 1 0 0, 1 1 0, 0 0 0))",
                          "POLYGON ZM ((0 0 0 0, 1 0 0 0, 1 1 nan 0, 0 0 0 0))", "polygonz((0 0 1,1 0 1,1 1 -1e3,0 0 1))",
                          "POLYGON ((0 0 0, 1 0 0, 1 1 0, 0 0 0))", "POLYGON ((0 0 0 0, 1 0 0 0, 1 1 0 0, 0 0 0 0))",
                          "MULTIPOLYGON Z (((0 0 0, 1 0 0, 1 1 0, 0 0 0)))",
                          "GEOMETRYCOLLECTION Z (POLYGON Z ((0 0 0, 1 0 0, 1 1 0, 0 0 0)), POLYGON Z EMPTY)"})
    REQUIRE(same_rings(read_wkt(text), flat), text);
  // PostGIS's extended WKT: the SRID is dropped
  REQUIRE(same_rings(read_wkt("SRID=4326;POLYGON ((0 0, 1 0, 1 1, 0 0))"), flat));
  REQUIRE(same_rings(read_wkt("srid = -1 ; POLYGON Z ((0 0 0, 1 0 0, 1 1 0, 0 0 0))"), flat));
  CHECK_INPUT_ERROR(read_wkt("SRID=;POLYGON ((0 0, 1 0, 1 1, 0 0))"), "malformed WKT at line 1, column 6: expected the SRID's number",
                    -1, -1);
  CHECK_INPUT_ERROR(read_wkt("SRID=4326 POLYGON ((0 0, 1 0, 1 1, 0 0))"), "expected ';' after the SRID", -1, -1);
  CHECK_INPUT_ERROR(read_wkt("POLYGON Z EMPTY"), "empty polygon", -1, -1);
  CHECK_INPUT_ERROR(read_wkt("POLYGON ((0 0, 1 0, 1 1 7, 0 0))"), "ring 0 vertex 2 has 3 coordinates, expected 2", 0, 2);
  CHECK_INPUT_ERROR(read_wkt("POLYGON Z ((0 0, 1 0, 1 1, 0 0))"), "ring 0 vertex 0 has 2 coordinates, expected 3", 0, 0);
  CHECK_INPUT_ERROR(read_wkt("POLYGON ((0 0 0, 4 0 0, 4 4 0, 0 0 0), (1 1, 2 1, 2 2, 1 1))"),
                    "ring 1 vertex 0 has 2 coordinates, expected 3", 1, 0);
  CHECK_INPUT_ERROR(read_wkt("POLYGON ((0 0 0 0 0, 1 0, 1 1, 0 0))"), "ring 0 vertex 0 has 5 coordinates, expected 2, 3 or 4",
                    0, 0);
  CHECK_INPUT_ERROR(read_wkt("MULTIPOLYGON M (((0 0 0, 1 0 0, 1 1 0, 0 0 0)), ((0 0, 1 0, 1 1, 0 0)))"),
                    "polygon 1: ring 0 vertex 0 has 2 coordinates, expected 3", 0, 0);
  CHECK_INPUT_ERROR(read_wkt("POLYGON Z Z ((0 0 0, 1 0 0, 1 1 0, 0 0 0))"), "expected '(' or 'EMPTY'", -1, -1);
  CHECK_INPUT_ERROR(read_wkt("POLYGON ((0 0, 1 0, 1 inf, 0 0))"), "non-finite coordinate: ring 0 vertex 2", 0, 2);
  CHECK_INPUT_ERROR(read_wkt("LINESTRING (0 0, 1 1)"), "not a polygon: found LINESTRING", -1, -1);
  CHECK_INPUT_ERROR(read_wkt("point (0 0)"), "not a polygon: found POINT", -1, -1);
  CHECK_INPUT_ERROR(read_wkt("MULTIPOLYGON (((0 0, 1 0, 1 1, 0 0)), ((2 2, 3 2, 3 3, 2 2)))"),
                    "not a polygon: found 2 polygons", -1, -1);
  CHECK_INPUT_ERROR(read_wkt("POLYGON ((0 0, 1 0, nan 1, 0 0))"), "non-finite coordinate: ring 0 vertex 2", 0, 2);
  CHECK_INPUT_ERROR(read_wkt("POLYGON ((0 0, 1 0, 1 1, 0 0), (0 0, 1 0, 1 -inf, 0 0))"),
                    "non-finite coordinate: ring 1 vertex 2", 1, 2);
  CHECK_INPUT_ERROR(read_wkt("POLYGON ((0 0, 1 0, 1 Infinity, 0 0))"), "non-finite coordinate: ring 0 vertex 2", 0, 2);
  CHECK_INPUT_ERROR(read_wkt("POLYGON ((0 0, 1e400 0, 1 1, 0 0))"), "non-finite coordinate: ring 0 vertex 1", 0, 1);
  CHECK_INPUT_ERROR(read_wkt("POLYGON ((0 0, 1 0, 1 1, 0 1))"),
                    "unclosed ring: ring 0 (first point (0, 0), last point (0, 1))", 0, -1);
  CHECK_INPUT_ERROR(read_wkt("POLYGON ((0 0, 4 0, 4 4, 0 0), (1 1, 2 1, 2 2, 1.5 1))"),
                    "unclosed ring: ring 1 (first point (1, 1), last point (1.5, 1))", 1, -1);
  CHECK_INPUT_ERROR(read_wkt("POLYGON ((0 0, 1 0, 0 0))"), "ring 0 has fewer than 4 points", 0, -1);
  CHECK_INPUT_ERROR(read_wkt("POLYGON ((0 0, 4 0, 4 4, 0 0), (1 1))"), "ring 1 has fewer than 4 points", 1, -1);
  return 0;
}

// ------------------------------------------------------------------ WKT writing

int test_wkt_writing()
{
  Rings rings = { square(0, 0, 1, 1) };
  std::ostringstream out;
  pma_tool::write_wkt_polygon(out, rings);
  REQUIRE(out.str() == "POLYGON ((0 0, 1 0, 1 1, 0 1, 0 0))");

  rings.push_back({ Point(0.1, 0.2), Point(0.3, 0.2), Point(0.3, 0.4) });
  out.str("");
  pma_tool::write_wkt_polygon(out, rings);
  REQUIRE(out.str() == "POLYGON ((0 0, 1 0, 1 1, 0 1, 0 0), (0.10000000000000001 0.20000000000000001, "
                     "0.29999999999999999 0.20000000000000001, 0.29999999999999999 0.40000000000000002, "
                     "0.10000000000000001 0.20000000000000001))");
  REQUIRE(same_rings(read_wkt(out.str()), rings));

  out.str("");
  pma_tool::write_wkt_polygon(out, Rings());
  REQUIRE(out.str() == "POLYGON EMPTY");

  // Bit-exact round trip of random finite doubles, including subnormals and -0.
  std::mt19937_64 rng(42);
  Rings random_rings(3);
  for(auto& ring : random_rings)
    for(int i = 0; i < 2000; ++i) {
      double c[2];
      for(double& v : c) {
        do {
          std::uint64_t bits = rng();
          std::memcpy(&v, &bits, sizeof(double));
        } while(!std::isfinite(v));
      }
      ring.push_back(Point(c[0], c[1]));
    }
  random_rings[1][5] = Point(-0.0, std::numeric_limits<double>::denorm_min());
  random_rings[1][6] = Point(std::numeric_limits<double>::max(), -std::numeric_limits<double>::min());
  out.str("");
  pma_tool::write_wkt_polygon(out, random_rings);
  REQUIRE(same_rings(read_wkt(out.str()), random_rings));
  return 0;
}

// ------------------------------------------------------------------ GeoJSON

int test_geojson_reading()
{
  Rings r = read_geojson(R"({"type": "Polygon", "coordinates": [[[0, 0], [4, 0], [4, 4], [0, 4], [0, 0]],
                                                           [[1, 1], [1, 2], [2, 2], [2, 1], [1, 1]]]})");
  REQUIRE(r.size() == 2 && r[0].size() == 4 && r[1].size() == 4);
  REQUIRE(r[1][1] == Point(1, 2));

  // Member order, extra members, escapes in keys, number syntax.
  r = read_geojson(R"( {"bbox": [0, 0, 1, 1], "coordinates": [ [ [0.1, -0.0], [1E0, 0e5] , [1.5e+0, 1],
                      [0.1, -0.0] ] ], "crs": {"x": [true, false, null, "s\"\\\/\b\f\n\r\t\u00e9\ud83d\ude00"]},
                      "typ\u0065": "Polygon"} )");
  REQUIRE(r.size() == 1 && r[0].size() == 3);
  REQUIRE(same_double(r[0][0].x(), 0.1) && same_double(r[0][0].y(), -0.0));
  REQUIRE(r[0][1] == Point(1, 0) && r[0][2] == Point(1.5, 1));

  // Feature, FeatureCollection with one feature, MultiPolygon with one polygon.
  r = read_geojson(R"({"type": "Feature", "properties": {"name": "a", "n": [1, {"k": 2}]},
                       "geometry": {"type": "Polygon", "coordinates": [[[0, 0], [1, 0], [1, 1], [0, 0]]]}})");
  REQUIRE(r.size() == 1 && r[0].size() == 3);
  r = read_geojson(R"({"type": "FeatureCollection", "features": [{"type": "Feature", "properties": null,
                       "geometry": {"type": "Polygon", "coordinates": [[[0, 0], [1, 0], [1, 1], [0, 0]]]}}]})");
  REQUIRE(r.size() == 1 && r[0].size() == 3);
  r = read_geojson(R"({"type": "MultiPolygon", "coordinates": [[[[0, 0], [1, 0], [1, 1], [0, 0]]]]})");
  REQUIRE(r.size() == 1 && r[0].size() == 3);
  r = read_geojson(R"({"type": "Feature", "geometry": {"type": "MultiPolygon", "coordinates": [[[[0, 0], [1, 0], [1, 1], [0, 0]]]]}})");
  REQUIRE(r.size() == 1 && r[0].size() == 3);

  // Exact numbers: the WKT writer's output, converted to GeoJSON, reads back bit-exactly.
  {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(-1e6, 1e6);
    Rings ring(1);
    for(int i = 0; i < 1000; ++i)
      ring[0].push_back(Point(u(rng), std::ldexp(u(rng), -1040)));
    std::string text = "{\"type\": \"Polygon\", \"coordinates\": [[";
    char buf[64];
    for(std::size_t i = 0; i <= ring[0].size(); ++i) {
      const Point& p = ring[0][i % ring[0].size()];
      std::snprintf(buf, sizeof(buf), "%s[%.17g, %.17g]", i ? ", " : "", p.x(), p.y());
      text += buf;
    }
    text += "]]}";
    REQUIRE(same_rings(read_geojson(text), ring));
  }

  // The fast reader (simdjson) and the nlohmann-json one: numbers and properties as
  // nlohmann-json reads them (-0 an integer, -0.0 a double; a repeated name in the
  // properties keeps its first place and its last value); input the fast reader
  // leaves to the other (a repeated member, an integer beyond 64 bits) read as before.
  const long fast_before = fast_geojson_reads;
  r = read_geojson(R"({"type": "Feature", "properties": {"n": -0, "m": -0.0, "f": 1.0, "e": 1e2, "u": 18446744073709551615,
                       "i": -9223372036854775808, "s": "\u00e9\n\"", "d": 1, "x": [true, null, {}], "d": [2.5e-3]},
                       "geometry": {"type": "Polygon", "coordinates": [[[-0, -0.0], [1, 0], [1, 1], [-0, -0.0]]]}})");
  REQUIRE(r.size() == 1 && same_double(r[0][0].x(), 0.0) && same_double(r[0][0].y(), -0.0));
  r = read_geojson(R"({"type": "Polygon", "type": "LineString", "type": "Polygon", "coordinates": [[[0, 0], [1, 0], [1, 1], [0, 0]]]})");
  REQUIRE(r.size() == 1 && r[0].size() == 3);
  r = read_geojson(R"({"type": "Polygon", "coordinates": [[[0, 0], [18446744073709551616, 0], [1, 1], [0, 0]]]})");
  REQUIRE(r.size() == 1 && r[0][1] == Point(18446744073709551616.0, 0));
#ifdef PMA_TOOL_WITH_SIMDJSON
  // the fast reader read the first and left the two others (and reads those before)
  REQUIRE(fast_geojson_reads == fast_before + 1 && fast_before == 7, fast_before << " " << fast_geojson_reads);
#endif

  // Errors (the JSON syntax is nlohmann-json's, with its line and column).
  CHECK_INPUT_ERROR(read_geojson(R"({"type": "Polygon", "coordinates": [[[0, 0], [1, 0] [1, 1], [0, 0]]]})"),
                    "malformed JSON at line 1, column 53: syntax error", -1, -1);
  CHECK_INPUT_ERROR(read_geojson("{\"type\": \"Polygon\",\n \"coordinates\": [[[0, 0], [1, 0], [1, 1], [0, 0]]]"),
                    "malformed JSON at line 2, column 51", -1, -1);
  CHECK_INPUT_ERROR(read_geojson(R"({"type": "Polygon", "coordinates": [[[0, 0], [1, 0], [1, 1], [0, 0]]]} x)"),
                    "expected end of input", -1, -1);
  CHECK_INPUT_ERROR(read_geojson(R"({"type": "Polygon", "coordinates": [[[01, 0], [1, 0], [1, 1], [0, 0]]]})"),
                    "malformed JSON", -1, -1);
  CHECK_INPUT_ERROR(read_geojson(R"({"type": "Polygon" "coordinates": []})"), "expected '}'", -1, -1);
  CHECK_INPUT_ERROR(read_geojson(R"({"type": "Polygon", "coordinates": [[[0, 0], [1, "0"], [1, 1], [0, 0]]]})"),
                    "malformed GeoJSON: ring 0 vertex 1: expected a number", 0, 1);
  CHECK_INPUT_ERROR(read_geojson(R"({"type": "Polygon", "coordinates": [[[0, 0], [1], [1, 1], [0, 0]]]})"),
                    "ring 0 vertex 1 is not a position of 2 numbers", 0, 1);
  CHECK_INPUT_ERROR(read_geojson(R"({"coordinates": []})"), "without a \"type\"", -1, -1);
  CHECK_INPUT_ERROR(read_geojson(R"([1, 2])"), "expected a GeoJSON object", -1, -1);
  CHECK_INPUT_ERROR(read_geojson(""), "no polygon", -1, -1);
  CHECK_INPUT_ERROR(read_geojson(R"({"type": "Polygon", "coordinates": []})"), "empty polygon", -1, -1);
  CHECK_INPUT_ERROR(read_geojson(R"({"type": "MultiPolygon", "coordinates": []})"), "empty polygon", -1, -1);
  CHECK_INPUT_ERROR(read_geojson(R"({"type": "LineString", "coordinates": [[0, 0], [1, 1]]})"),
                    "not a polygon: found LineString", -1, -1);
  CHECK_INPUT_ERROR(read_geojson(R"({"type": "GeometryCollection", "geometries": []})"), "empty polygon", -1, -1);
  CHECK_INPUT_ERROR(read_geojson(R"({"type": "Feature", "geometry": {"type": "Point", "coordinates": [0, 0]}})"),
                    "not a polygon: found Point", -1, -1);
  CHECK_INPUT_ERROR(read_geojson(R"({"type": "Feature", "geometry": null})"), "empty polygon", -1, -1);
  CHECK_INPUT_ERROR(read_geojson(R"({"type": "FeatureCollection", "features": []})"), "empty polygon", -1, -1);
  // points and lines are skipped; with nothing else, the first is named
  REQUIRE(read_geojson(R"({"type": "FeatureCollection", "features": [{"type": "Feature", "geometry":
                      {"type": "Polygon", "coordinates": [[[0, 0], [1, 0], [1, 1], [0, 0]]]}}, {"type": "Feature",
                      "geometry": {"type": "LineString", "coordinates": [[0, 0], [1, 1]]}}]})").size() == 1);
  CHECK_INPUT_ERROR(read_geojson(R"({"type": "FeatureCollection", "features": [{"type": "Feature", "geometry": null},
                      {"type": "Feature", "geometry": {"type": "GeometryCollection", "geometries": [{"type": "MultiPoint",
                      "coordinates": [[0, 0]]}]}}, {"type": "Feature", "geometry": {"type": "LineString", "coordinates":
                      [[0, 0], [1, 1]]}}]})"),
                    "not a polygon: found MultiPoint in feature 1", -1, -1);
  CHECK_INPUT_ERROR(read_geojson(R"({"type": "MultiPolygon", "coordinates": [[[[0, 0], [1, 0], [1, 1], [0, 0]]], [[[2, 2], [3, 2], [3, 3], [2, 2]]]]})"),
                    "not a polygon: found 2 polygons", -1, -1);
  // an altitude, or more numbers, ignored
  REQUIRE(same_rings(read_geojson(R"({"type": "Polygon", "coordinates": [[[0, 0, 0], [1, 0, 2.5], [1, 1], [0, 0, 0, 7]]]})"),
                     read_geojson(R"({"type": "Polygon", "coordinates": [[[0, 0], [1, 0], [1, 1], [0, 0]]]})")));
  CHECK_INPUT_ERROR(read_geojson(R"({"type": "Polygon", "coordinates": [[[0, 0], [1, 0, "up"], [1, 1], [0, 0]]]})"),
                    "malformed GeoJSON: ring 0 vertex 1: expected a number", 0, 1);
  CHECK_INPUT_ERROR(read_geojson(R"({"type": "Polygon", "coordinates": [[[0, 0], [1, 0], [NaN, 1], [0, 0]]]})"),
                    "malformed JSON at line 1, column 55", -1, -1);
  CHECK_INPUT_ERROR(read_geojson(R"({"type": "Polygon", "coordinates": [[[0, 0], [1, 0], [1, 1e999], [0, 0]]]})"),
                    "malformed JSON: number overflow parsing '1e999'", -1, -1);
  CHECK_INPUT_ERROR(read_geojson(R"({"type": "Polygon", "coordinates": [[[0, 0], [1, 0], [1, 1], [0, 1]]]})"),
                    "unclosed ring: ring 0 (first point (0, 0), last point (0, 1))", 0, -1);
  CHECK_INPUT_ERROR(read_geojson(R"({"type": "Polygon", "coordinates": [[[0, 0], [1, 0], [0, 0]]]})"),
                    "ring 0 has fewer than 4 points", 0, -1);
  return 0;
}

// ------------------------------------------------------------------ several polygons

int test_multi_reading()
{
  typedef std::vector<pma_tool::Input_polygon<Point> > Polygons;
  auto wkt = [](const std::string& text) {
    std::istringstream in(text);
    return pma_tool::read_wkt_polygons<Point>(in);
  };
  auto geojson = [](const std::string& text) {
    check_geojson_readers(text);
    std::istringstream in(text);
    return pma_tool::read_geojson_polygons<Point>(in);
  };
  // WKT: MULTIPOLYGON, nested GEOMETRYCOLLECTION, EMPTY parts skipped, in input order
  Polygons p = wkt("MULTIPOLYGON (((0 0, 1 0, 1 1, 0 0)), EMPTY, ((2 2, 3 2, 3 3, 2 3, 2 2), (2.2 2.2, 2.2 2.4, 2.4 2.2, 2.2 2.2)))");
  REQUIRE(p.size() == 2 && p[0].rings.size() == 1 && p[1].rings.size() == 2 && p[1].rings[0].size() == 4);
  p = wkt("geometrycollection (POLYGON ((0 0, 1 0, 1 1, 0 0)), GEOMETRYCOLLECTION (MULTIPOLYGON (((5 5, 6 5, 6 6, 5 5)), "
          "((7 7, 8 7, 8 8, 7 7))), POLYGON EMPTY), MULTIPOLYGON EMPTY)");
  REQUIRE(p.size() == 3 && p[1].rings[0][0] == Point(5, 5) && p[2].rings[0][0] == Point(7, 7));
  CHECK_INPUT_ERROR(wkt("MULTIPOLYGON (((0 0, 1 0, 1 1, 0 0)), ((2 2, 3 2, 3 3, 2 3)))"),
                    "polygon 1: unclosed ring: ring 0", 0, -1);
  // points and lines skipped, counted, the first named; their text is still checked
  pma_tool::Skipped_geometries skipped;
  auto wkt_skipping = [&skipped](const std::string& text) {
    std::istringstream in(text);
    return pma_tool::read_wkt_polygons<Point>(in, &skipped);
  };
  p = wkt_skipping("GEOMETRYCOLLECTION (LINESTRING Z (0 0 1, 1 1 2), POLYGON ((0 0, 1 0, 1 1, 0 0)), POINT EMPTY, "
                   "MULTIPOINT (1 2, 3 4), MULTIPOINT ((1 2), EMPTY), MULTILINESTRING ((0 0, 1 1), (2 2, 3 3)), POINTM (1 2 3))");
  REQUIRE(p.size() == 1 && p[0].rings[0].size() == 3 && skipped.count == 6 && skipped.first == "LINESTRING");
  p = wkt_skipping("POLYGON ((0 0, 1 0, 1 1, 0 0))");
  REQUIRE(p.size() == 1 && skipped.count == 0);
  CHECK_INPUT_ERROR(wkt("GEOMETRYCOLLECTION (LINESTRING (0 0, 1 1), POINT (1 1))"), "not a polygon: found LINESTRING", -1, -1);
  CHECK_INPUT_ERROR(wkt("GEOMETRYCOLLECTION (POINT (1), POLYGON ((0 0, 1 0, 1 1, 0 0)))"),
                    "malformed WKT at line 1, column 29: expected a number", -1, -1);
  CHECK_INPUT_ERROR(wkt("GEOMETRYCOLLECTION (LINESTRING (0 0, 1 y), POLYGON ((0 0, 1 0, 1 1, 0 0)))"),
                    "malformed WKT at line 1, column 40: expected a number", -1, -1);
  CHECK_INPUT_ERROR(wkt("GEOMETRYCOLLECTION (POINT (1 2 3 4 5), POLYGON ((0 0, 1 0, 1 1, 0 0)))"),
                    "malformed WKT at line 1, column 36: expected ',' or ')'", -1, -1);
  CHECK_INPUT_ERROR(wkt("GEOMETRYCOLLECTION (CIRCULARSTRING (0 0, 1 1, 2 0), POLYGON ((0 0, 1 0, 1 1, 0 0)))"),
                    "not a polygon: found CIRCULARSTRING", -1, -1);
  CHECK_INPUT_ERROR(wkt("GEOMETRYCOLLECTION EMPTY"), "empty polygon", -1, -1);
  CHECK_INPUT_ERROR(wkt("MULTIPOLYGON (((0 0, 1 0, 1 1, 0 0))"), "malformed WKT at line 1, column 37", -1, -1);

  // GeoJSON: features, MultiPolygons and collections, properties kept (members in input order)
  p = geojson(R"({"type": "FeatureCollection", "features": [
    {"type": "Feature", "properties": {"name": "A", "z": 1, "a": [1, {"k": "v"}]},
     "geometry": {"type": "MultiPolygon", "coordinates": [[[[0, 0], [1, 0], [1, 1], [0, 0]]], [], [[[2, 2], [3, 2], [3, 3], [2, 2]]]]}},
    {"type": "Feature", "properties": null, "geometry": null},
    {"type": "Feature", "properties": {"name": "B \u00e9"}, "geometry": {"type": "GeometryCollection", "geometries": [
      {"type": "Polygon", "coordinates": [[[5, 5], [6, 5], [6, 6], [5, 5]]]}]}},
    {"type": "Feature", "geometry": {"type": "Polygon", "coordinates": [[[9, 9], [10, 9], [10, 10], [9, 9]]]}}]})");
  REQUIRE(p.size() == 4);
  REQUIRE(p[0].properties == R"({"name":"A","z":1,"a":[1,{"k":"v"}]})" && p[1].properties == p[0].properties);
  REQUIRE(p[2].properties == "{\"name\":\"B \xC3\xA9\"}" && p[2].rings[0][0] == Point(5, 5));
  REQUIRE(p[3].properties.empty() && p[3].rings[0][0] == Point(9, 9));
  // points and lines beside the polygons, skipped and named as both readers name them
  // (check_geojson_readers() compares the fast reader's count and name to the other's)
  const std::string mixed = R"({"type": "FeatureCollection", "features": [
    {"type": "Feature", "properties": {"name": "A"}, "geometry": {"type": "Polygon", "coordinates": [[[0, 0], [1, 0], [1, 1], [0, 0]]]}},
    {"type": "Feature", "properties": {"name": "road"}, "geometry": {"type": "MultiLineString", "coordinates": [[[0, 0], [1, 1]]]}},
    {"type": "Feature", "geometry": {"type": "GeometryCollection", "geometries": [{"type": "Point", "coordinates": [0, 0, 4]},
      {"type": "Polygon", "coordinates": [[[5, 5], [6, 5], [6, 6], [5, 5]]]}]}}]})";
  check_geojson_readers(mixed);
  {
    std::istringstream in(mixed);
    pma_tool::Skipped_geometries k;
    p = pma_tool::read_geojson_polygons<Point>(in, &k);
    REQUIRE(p.size() == 2 && p[0].properties == R"({"name":"A"})" && p[1].rings[0][0] == Point(5, 5));
    REQUIRE(k.count == 2 && k.first == "MultiLineString in feature 1");
  }
  for(const char* one : {R"({"type": "GeometryCollection", "geometries": [{"type": "LineString", "coordinates": [[0, 0], [1, 1]]},
                           {"type": "Polygon", "coordinates": [[[0, 0], [1, 0], [1, 1], [0, 0]]]}]})",
                         R"({"type": "Feature", "geometry": {"type": "GeometryCollection", "geometries": [{"type": "Polygon",
                           "coordinates": [[[0, 0], [1, 0], [1, 1], [0, 0]]]}, {"type": "Point", "coordinates": [0, 0]}]}})"}) {
    check_geojson_readers(one);
    std::istringstream in(one);
    pma_tool::Skipped_geometries k;
    REQUIRE(pma_tool::read_geojson_polygons<Point>(in, &k).size() == 1 && k.count == 1 &&
            (k.first == "LineString in the geometry" || k.first == "Point in the Feature"));
  }
  CHECK_INPUT_ERROR(geojson(R"({"type": "MultiPolygon", "coordinates": [[[[0, 0], [1, 0], [1, 1], [0, 0]]], [[[2, 2], [3, 2], [3, 3, null], [2, 2]]]]})"),
                    "polygon 1: malformed GeoJSON: ring 0 vertex 2: expected a number", 0, 2);
  CHECK_INPUT_ERROR(geojson(R"({"type": "FeatureCollection", "features": [{"type": "Polygon", "coordinates": []}]})"),
                    "feature 0 is a Polygon, not a Feature", -1, -1);
  return 0;
}

// ------------------------------------------------------------------ files

struct Invalid_file
{
  const char* name;
  bool geometric; // reads fine, fails validation
  const char* message;
  int ring, vertex;
};

int test_invalid_files()
{
  const Invalid_file files[] = {
    { "malformed.wkt", false, "malformed WKT at line 1, column 19: expected ',' or ')'", -1, -1 },
    { "empty.wkt", false, "empty polygon", -1, -1 },
    { "mixed_dimensions.wkt", false, "ring 0 vertex 2 has 3 coordinates, expected 2", 0, 2 },
    { "not_polygon.wkt", false, "not a polygon: found LINESTRING", -1, -1 },
    { "multipolygon_two.wkt", false, "not a polygon: found 2 polygons", -1, -1 },
    { "trailing_garbage.wkt", false, "malformed WKT at line 1, column 32: unexpected text after the polygon", -1, -1 },
    { "non_finite.wkt", false, "non-finite coordinate: ring 0 vertex 2", 0, 2 },
    { "unclosed.wkt", false, "unclosed ring: ring 0 (first point (0, 0), last point (0, 1))", 0, -1 },
    { "too_few_points.wkt", false, "ring 0 has fewer than 4 points", 0, -1 },
    { "too_few_distinct.wkt", true, "ring 0 has fewer than 3 distinct vertices", 0, -1 },
    { "zero_length_edge.wkt", true, "zero-length edge: ring 0 vertex 2 equals vertex 3", 0, 2 },
    { "spike.wkt", true, "spike: ring 0 vertex 4 folds back", 0, 4 },
    { "crossing.wkt", true, "self-intersection: ring 0 edge 0 (vertices 0-1) crosses ring 0 edge 2 (vertices 2-3)", 0, 0 },
    { "t_crossing.wkt", true, "self-intersection: ring 1 vertex 0 crosses ring 0 edge 1 (vertices 1-2) at (4, 1)", 1, 0 },
    { "overlap.wkt", true, "self-intersection: ring 0 edge 3 (vertices 3-0) overlaps ring 1 edge 2 (vertices 2-0)", 0, 3 },
    { "hole_outside.wkt", true, "hole 1 (ring 1) is not inside the outer ring", 1, -1 },
    { "hole_in_hole.wkt", true, "hole 2 (ring 2) lies inside hole 1 (ring 1)", 2, -1 },
    { "malformed.geojson", false, "malformed JSON at line 1, column 53: syntax error", -1, -1 },
    { "not_polygon.geojson", false, "not a polygon: found LineString", -1, -1 },
    { "empty.geojson", false, "empty polygon", -1, -1 },
    { "two_features.geojson", false, "not a polygon: found 2 polygons", -1, -1 },
    { "feature_without_geometry.geojson", false, "empty polygon", -1, -1 },
    { "unclosed.geojson", false, "unclosed ring: ring 0 (first point (0, 0), last point (0, 1))", 0, -1 },
    { "non_finite.geojson", false, "malformed JSON at line 1", -1, -1 },
    { "crossing.geojson", true, "self-intersection: ring 0 edge 0 (vertices 0-1) crosses ring 0 edge 2 (vertices 2-3)", 0, 0 },
  };
  for(const Invalid_file& f : files) {
    std::string path = data(std::string("invalid/") + f.name);
    if(f.geometric) {
      Rings rings;
      try {
        rings = pma_tool::read_polygon_file<Point>(path);
      } catch(const std::exception& e) {
        std::fprintf(stderr, "%s should read without error: %s\n", f.name, e.what());
        REQUIRE(false);
      }
      CHECK_INPUT_ERROR(validate(rings), f.message, f.ring, f.vertex);
    } else {
      CHECK_INPUT_ERROR(pma_tool::read_polygon_file<Point>(path), f.message, f.ring, f.vertex);
    }
  }

  // Unreadable files.
  CHECK_INPUT_ERROR(pma_tool::read_polygon_file<Point>(data("no_such_file.wkt")),
                    "cannot read file '" + data("no_such_file.wkt") + "': No such file or directory", -1, -1);
  CHECK_INPUT_ERROR(pma_tool::read_polygon_file<Point>(data("invalid")),
                    "cannot read file '" + data("invalid") + "': ", -1, -1);
  return 0;
}

int test_shipped_data()
{
  // coordinates with Z, M or ZM values, or an altitude: the same triangle
  const Rings flat = pma_tool::read_polygon_file<Point>(data("dimensions/flat.wkt"));
  for(const char* name : {"z_tagged.wkt", "z_untagged.wkt", "zm_multipolygon.wkt", "altitude.geojson"})
    REQUIRE(same_rings(pma_tool::read_polygon_file<Point>(data(std::string("dimensions/") + name)), flat), name);

  const char* names[] = { "syn_cheese1k.wkt", "syn_comb50.wkt", "syn_maze20.wkt", "syn_ngon64.wkt",
                          "syn_sliver500.wkt", "syn_spiral20.wkt", "syn_star2k.wkt", "c1m_GBR_0.wkt" };
  for(const char* name : names) {
    auto start = std::chrono::steady_clock::now();
    Rings rings;
    try {
      rings = pma_tool::read_polygon_file<Point>(data(name));
      validate(rings);
    } catch(const std::exception& e) {
      std::fprintf(stderr, "%s should be valid: %s\n", name, e.what());
      REQUIRE(false);
    }
    std::size_t n = 0;
    for(const auto& ring : rings)
      n += ring.size();
    std::printf("  %-18s %5zu rings %7zu vertices: read + validate %.3f s\n", name, rings.size(), n,
                seconds_since(start));
    REQUIRE(!rings.empty() && rings[0].size() >= 3);
    if(std::strcmp(name, "syn_cheese1k.wkt") == 0)
      REQUIRE(rings.size() == 1001);
  }
  return 0;
}

// ------------------------------------------------------------------ validation

int test_valid_polygons()
{
  Rings square_only = { square(0, 0, 4, 4) };
  CHECK_VALID(square_only);
  Rings with_hole = { square(0, 0, 4, 4), square(1, 1, 3, 3, false) };
  CHECK_VALID(with_hole);
  Rings hole_same_orientation = { square(0, 0, 4, 4), square(1, 1, 3, 3, true) };
  CHECK_VALID(hole_same_orientation);
  Rings clockwise = { square(0, 0, 4, 4, false) };
  CHECK_VALID(clockwise);
  Rings clockwise_with_holes = { square(0, 0, 10, 10, false), square(1, 1, 2, 2), square(3, 1, 4, 2, false),
                                 square(1, 3, 9, 9, false) };
  CHECK_VALID(clockwise_with_holes);
  Rings triangle = { { Point(0, 0), Point(1, 0), Point(0, 1) } };
  CHECK_VALID(triangle);
  // Vertices of angle pi (flat), including at the smallest vertex and on vertical edges.
  Rings flat = { { Point(0, 0), Point(2, 0), Point(4, 0), Point(4, 2), Point(4, 4), Point(0, 4), Point(0, 2) } };
  CHECK_VALID(flat);
  Rings flat_hole = { square(0, 0, 4, 4), { Point(1, 1), Point(1, 2), Point(1, 3), Point(3, 3), Point(2, 2) } };
  CHECK_VALID(flat_hole);
  // A hole whose vertex is very close to, but not on, the outer ring.
  double tiny = std::numeric_limits<double>::denorm_min();
  Rings close_hole = { square(0, 0, 4, 4), { Point(tiny, 2), Point(1, 1), Point(1, 3) } };
  CHECK_VALID(close_hole);
  Rings close_diagonal = { { Point(0, 0), Point(4, 0), Point(0, 4) },
                           { Point(1, 1), Point(2, std::nextafter(2.0, 0.0)), Point(1, 2) } };
  CHECK_VALID(close_diagonal);
  Rings close_diagonal_bad = { { Point(0, 0), Point(4, 0), Point(0, 4) },
                               { Point(1, 1), Point(2, std::nextafter(2.0, 3.0)), Point(1, 2) } };
  CHECK_INPUT_ERROR(validate(close_diagonal_bad), "self-intersection: ring 0 edge 1 (vertices 1-2) crosses ring 1 edge", 0, 1);
  // A hole vertex on the outer ring's edge (a T, OGC-valid).
  Rings on_diagonal = { { Point(0, 0), Point(4, 0), Point(0, 4) }, { Point(1, 1), Point(2, 2), Point(1, 2) } };
  CHECK_VALID(on_diagonal);
  // Holes side by side, sharing x or y coordinates, vertical edges aligned.
  Rings aligned = { square(0, 0, 10, 10), square(1, 1, 2, 2), square(1, 3, 2, 4), square(3, 1, 4, 2),
                    square(3, 3, 4, 4, false), square(2.5, 1, 2.75, 4) };
  CHECK_VALID(aligned);
  // A comb: many vertices sharing coordinates, and a spiral (deep, narrow corridors).
  Rings comb = read_wkt("POLYGON ((0 0, 9 0, 9 3, 8 3, 8 1, 7 1, 7 3, 6 3, 6 1, 5 1, 5 3, 4 3, 4 1, 3 1, 3 3, 2 3, 2 1, 1 1, 1 3, 0 3, 0 0))");
  CHECK_VALID(comb);
  return 0;
}

int test_invalid_polygons()
{
  double nan = std::numeric_limits<double>::quiet_NaN();
  double inf = std::numeric_limits<double>::infinity();

  CHECK_INPUT_ERROR(validate(Rings()), "empty polygon", -1, -1);
  CHECK_INPUT_ERROR(validate(Rings{ { Point(0, 0), Point(1, 0) } }), "ring 0 has fewer than 3 distinct vertices", 0, -1);
  CHECK_INPUT_ERROR(validate(Rings{ square(0, 0, 4, 4), { Point(1, 1), Point(2, 1) } }),
                    "ring 1 has fewer than 3 distinct vertices", 1, -1);
  CHECK_INPUT_ERROR(validate(Rings{ square(0, 0, 4, 4), { Point(1, 1), Point(2, 1), Point(1, 1), Point(2, 1) } }),
                    "ring 1 has fewer than 3 distinct vertices", 1, -1);
  CHECK_INPUT_ERROR(validate(Rings{ square(0, 0, 4, 4), { Point(1, 1), Point(2, 1), Point(nan, 2) } }),
                    "non-finite coordinate: ring 1 vertex 2", 1, 2);
  CHECK_INPUT_ERROR(validate(Rings{ { Point(0, 0), Point(1, -inf), Point(1, 1) } }),
                    "non-finite coordinate: ring 0 vertex 1", 0, 1);

  // Zero-length edges, including the closing edge.
  CHECK_INPUT_ERROR(validate(Rings{ { Point(0, 0), Point(4, 0), Point(4, 0), Point(4, 4) } }),
                    "zero-length edge: ring 0 vertex 1 equals vertex 2", 0, 1);
  CHECK_INPUT_ERROR(validate(Rings{ square(0, 0, 4, 4), { Point(1, 1), Point(2, 1), Point(2, 2), Point(1, 1) } }),
                    "zero-length edge: ring 1 vertex 3 equals vertex 0", 1, 3);

  // Repeated vertices: in one ring (a pinch), between rings (a hole touching the outer
  // ring at a vertex, two holes sharing a vertex): valid, the rings only touch there.
  const Rings touching[] = {
    { { Point(0, 0), Point(4, 0), Point(2, 2), Point(4, 4), Point(0, 4), Point(2, 2) } },
    { square(0, 0, 4, 4), { Point(4, 4), Point(2, 3), Point(3, 2) } },
    { square(0, 0, 10, 10), square(1, 1, 2, 2), square(2, 2, 3, 3) },
    { square(0, 0, 10, 10), { Point(0.1, 0.2), Point(0.3, 0.2), Point(0.3, 0.5) }, { Point(5, 5), Point(6, 5), Point(0.3, 0.5) } },
  };
  for(const Rings& r : touching) {
    try {
      validate(r);
    } catch(const Input_error& e) {
      CHECK(false, "rings touching at a vertex rejected: " << e.what());
    }
  }

  // Spikes (angle 0), including a degenerate triangle and a spike at the smallest vertex.
  CHECK_INPUT_ERROR(validate(Rings{ { Point(0, 0), Point(4, 0), Point(4, 4), Point(2, 4), Point(2, 6), Point(2, 5), Point(0, 4) } }),
                    "spike: ring 0 vertex 4 folds back", 0, 4);
  CHECK_INPUT_ERROR(validate(Rings{ { Point(0, 0), Point(1, 0), Point(2, 0) } }), "spike: ring 0 vertex 0 folds back", 0, 0);
  CHECK_INPUT_ERROR(validate(Rings{ square(0, 0, 10, 10), { Point(1, 1), Point(5, 1), Point(3, 1), Point(3, 3) } }),
                    "spike: ring 1 vertex 1 folds back", 1, 1);

  // Intersections within a ring.
  CHECK_INPUT_ERROR(validate(Rings{ { Point(0, 0), Point(2, 2), Point(2, 0), Point(0, 2) } }),
                    "self-intersection: ring 0 edge 0 (vertices 0-1) crosses ring 0 edge 2 (vertices 2-3)", 0, 0);
  // A vertex on an edge of its own ring, both edges on the interior side: two lobes
  // touching there (valid); crossing through the edge there: invalid.
  CHECK_VALID((Rings{ { Point(0, 0), Point(4, 0), Point(4, 4), Point(2, 0), Point(0, 4) } }));
  CHECK_INPUT_ERROR(validate(Rings{ { Point(0, 0), Point(4, 0), Point(4, 4), Point(2, 0), Point(2, -2), Point(0, -2) } }),
                    "self-intersection", 0, ANY);
  // Vertical edges crossing a horizontal one, a vertex on a vertical edge.
  CHECK_INPUT_ERROR(validate(Rings{ { Point(0, 0), Point(0, 4), Point(2, 4), Point(2, 1), Point(-1, 1), Point(-1, 0) } }),
                    "crosses", 0, ANY);
  CHECK_VALID((Rings{ { Point(0, 0), Point(4, 0), Point(4, 4), Point(2, 4), Point(4, 2), Point(0, 2) } }));
  CHECK_INPUT_ERROR(validate(Rings{ { Point(0, 0), Point(4, 0), Point(4, 4), Point(2, 4), Point(4, 2), Point(6, 2), Point(6, 1), Point(0, 1) } }),
                    "self-intersection", 0, ANY);
  // Collinear overlap of non-consecutive edges of one ring.
  CHECK_INPUT_ERROR(validate(Rings{ { Point(0, 0), Point(4, 0), Point(4, 2), Point(3, 2), Point(3, 0), Point(1, 0),
                                      Point(1, -1), Point(0, -1) } }),
                    "self-intersection", 0, ANY);

  // Intersections between rings.
  CHECK_INPUT_ERROR(validate(Rings{ square(0, 0, 4, 4), square(3, 1, 5, 3) }),
                    "self-intersection: ring 0 edge 1 (vertices 1-2) crosses ring 1 edge", 0, 1);
  // Holes with a vertex inside an edge of the outer ring (T's): valid; a hole
  // crossing the outer ring at two such vertices, or lying outside touching it: not.
  CHECK_VALID((Rings{ square(0, 0, 4, 4), { Point(4, 2), Point(2, 1), Point(2, 3) } }));
  CHECK_VALID((Rings{ square(0, 0, 4, 4), { Point(2, 0), Point(3, 1), Point(1, 1) } }));
  CHECK_VALID((Rings{ square(0, 0, 4, 4), { Point(2, 0), Point(1.5, 1), Point(1, 1) }, { Point(2, 0), Point(3, 1), Point(2.5, 1) } }));
  // vertices on both sides of the edge at a T: an exterior pocket of the outer ring
  // and a hole, both touching the bottom edge at (2, 0) (review finding): valid (it
  // was reported as a crossing, then as not supported)
  CHECK_VALID((Rings{ { Point(0, 0), Point(4, 0), Point(4, 4), Point(-2, 4), Point(-2, -3), Point(3, -3),
                        Point(3, -1), Point(2, 0), Point(1, -1) },
                      { Point(2, 0), Point(3, 1), Point(1, 1) } }));
  // ... and the same with the hole crossing the pocket's edge there: invalid
  CHECK_INPUT_ERROR(validate(Rings{ { Point(0, 0), Point(4, 0), Point(4, 4), Point(-2, 4), Point(-2, -3), Point(3, -3),
                                      Point(3, -1), Point(2, 0), Point(1, -1) },
                                    { Point(2, 0), Point(3, 1), Point(2.5, -0.5) } }),
                    "ring", ANY, ANY);
  CHECK_INPUT_ERROR(validate(Rings{ square(0, 0, 4, 4), { Point(4, 1), Point(5, 2), Point(4, 3), Point(3, 2) } }),
                    "self-intersection: ring 1 vertex 0 crosses ring 0 edge 1 (vertices 1-2) at (4, 1)", 1, 0);
  CHECK_INPUT_ERROR(validate(Rings{ square(0, 0, 4, 4), { Point(4, 2), Point(5, 1), Point(5, 3) } }),
                    "self-intersection: ring 1 vertex 0 crosses ring 0 edge 1 (vertices 1-2) at (4, 2)", 1, 0);
  CHECK_INPUT_ERROR(validate(Rings{ square(0, 0, 4, 4), { Point(1, 0), Point(3, 0), Point(2, 1) } }),
                    "overlaps", ANY, ANY);
  CHECK_INPUT_ERROR(validate(Rings{ square(0, 0, 10, 10), square(1, 1, 3, 3), square(2, 2, 4, 4) }),
                    "self-intersection: ring 1 edge", 1, ANY);
  CHECK_VALID((Rings{ square(0, 0, 10, 10), square(1, 1, 3, 3), { Point(3, 2), Point(5, 1), Point(5, 3) } }));
  CHECK_INPUT_ERROR(validate(Rings{ square(0, 0, 10, 10), square(1, 1, 3, 3), { Point(3, 2), Point(2, 1.6), Point(5, 3) } }),
                    "self-intersection", ANY, ANY);

  // Nesting.
  CHECK_INPUT_ERROR(validate(Rings{ square(0, 0, 4, 4), square(5, 5, 6, 6) }),
                    "hole 1 (ring 1) is not inside the outer ring", 1, -1);
  CHECK_INPUT_ERROR(validate(Rings{ square(0, 0, 4, 4), square(1, 1, 2, 2), square(-3, 1, -2, 2) }),
                    "hole 2 (ring 2) is not inside the outer ring", 2, -1);
  CHECK_INPUT_ERROR(validate(Rings{ square(1, 1, 2, 2), square(0, 0, 4, 4) }),
                    "hole 1 (ring 1) is not inside the outer ring", 1, -1);
  CHECK_INPUT_ERROR(validate(Rings{ square(0, 0, 10, 10), square(1, 1, 9, 9), square(2, 2, 3, 3, false) }),
                    "hole 2 (ring 2) lies inside hole 1 (ring 1)", 2, -1);
  CHECK_INPUT_ERROR(validate(Rings{ square(0, 0, 10, 10, false), square(4, 4, 5, 5), square(1, 1, 9, 9),
                                    square(2, 2, 3, 3, false) }),
                    "hole 1 (ring 1) lies inside hole 2 (ring 2)", 1, -1);
  // A hole inside a hole inside a hole: the innermost lies inside the middle one.
  CHECK_INPUT_ERROR(validate(Rings{ square(0, 0, 10, 10), square(1, 1, 9, 9, false), square(3, 3, 4, 4),
                                    square(2, 2, 8, 8) }),
                    "hole 2 (ring 2) lies inside hole 3 (ring 3)", 2, -1);
  return 0;
}

// ------------------------------------------------------------------ touching rings

void validate_touching(const Rings& rings)
{
  CGAL::Progressive_medial_axes::internal::Polygon_rings_validator<K>(rings, true).run();
}

// Rings touching at vertices (OGC-valid holes touching the shell or each other,
// pinches, inverted islands) pass the check that allows them; crossings at a
// shared vertex and overlaps there do not.  Without that allowance, a repeated
// vertex is reported only when nothing worse is wrong.
int test_touching_rings()
{
  const Rings shell = { square(0, 0, 4, 4) };
  const Rings valid[] = {
    { shell[0], { Point(0, 0), Point(1, 2), Point(2, 1) } },                         // hole at a shell corner
    { shell[0], { Point(0, 0), Point(2, 1), Point(1, 2) } },                         // the same, other orientation
    { { Point(0, 0), Point(2, 0), Point(4, 0), Point(4, 4), Point(0, 4) }, { Point(2, 0), Point(3, 1), Point(1, 1) } },
    { shell[0], square(1, 1, 2, 2), square(2, 2, 3, 3) },                             // two holes corner to corner
    { shell[0], square(1, 1, 2, 2), square(2, 2, 3, 3, false), { Point(2, 2), Point(3, 1), Point(3, 1.5) } },
    { { Point(0, 0), Point(2, 1), Point(4, 0), Point(4, 2), Point(2, 1), Point(0, 2) } },   // a pinch
    { { Point(0, 0), Point(6, 0), Point(6, 6), Point(0, 6), Point(0, 3), Point(2, 4), Point(4, 3), Point(2, 2),
        Point(0, 3) } },                                                              // an inverted island
    { { Point(0, 0), Point(6, -3), Point(6, 3), Point(0, 0), Point(3, 1), Point(4, 0), Point(3, -1) } },
  };
  for(const Rings& r : valid) {
    try {
      validate_touching(r);
    } catch(const Input_error& e) {
      std::ostringstream wkt;
      pma_tool::write_wkt_polygon(wkt, r);
      CHECK(false, "touching rings rejected: " << e.what() << "\n  " << wkt.str());
    }
  }
  CHECK_INPUT_ERROR(validate_touching(Rings{ { Point(0, 0), Point(6, -3), Point(6, 3), Point(0, 0), Point(3, -1),
                                               Point(4, 0), Point(3, 1) } }),
                    "self-intersection: ring 0 vertex 0 and ring 0 vertex 3 cross at (0, 0)", 0, 0);
  CHECK_INPUT_ERROR(validate_touching(Rings{ shell[0], { Point(0, 0), Point(-1, 2), Point(2, 1) } }),
                    "self-intersection: ring 0 vertex 0 and ring 1 vertex 0 cross at (0, 0)", 0, 0);
  CHECK_INPUT_ERROR(validate_touching(Rings{ shell[0], { Point(1, 1), Point(3, 1), Point(3, 3) },
                                             { Point(1, 1), Point(3, 2), Point(3, 3), Point(2, 3) } }),
                    "cross at (1, 1)", 1, 0);
  CHECK_INPUT_ERROR(validate_touching(Rings{ shell[0], { Point(2, 2), Point(3, 2), Point(3, 3) },
                                             { Point(2, 2), Point(3, 2), Point(2, 1) } }),
                    "self-intersection: ring 1 edge 0 (vertices 0-1) overlaps ring 2 edge 0 (vertices 0-1)", 1, 0);
  CHECK_INPUT_ERROR(validate_touching(Rings{ shell[0], { Point(0, 0), Point(-1, -2), Point(-2, -1) } }), "cross", ANY, ANY);
  // the most serious problem is named: a crossing rather than a vertex on an edge
  CHECK_INPUT_ERROR(validate(Rings{ { Point(0, 0), Point(4, 0), Point(4, 4), Point(2, 0), Point(2, -2), Point(0, -2) } }),
                    "self-intersection", ANY, ANY);
  CHECK_INPUT_ERROR(validate(Rings{ shell[0], { Point(0, 0), Point(3, 1), Point(1, 3) }, square(2, 2, 5, 3) }),
                    "self-intersection", ANY, ANY);

  return 0;
}

// ------------------------------------------------------------------ randomized cross-check

// An independent, quadratic validity test built on CGAL's own predicates and
// constructions (segment intersection, point in polygon).
bool brute_force_valid(const Rings& rings)
{
  if(rings.empty())
    return false;
  std::vector<Point> all;
  for(const auto& ring : rings) {
    if(ring.size() < 3)
      return false;
    all.insert(all.end(), ring.begin(), ring.end());
  }
  std::sort(all.begin(), all.end());
  if(std::adjacent_find(all.begin(), all.end()) != all.end())
    return false; // repeated vertex (or zero-length edge, or too few distinct vertices)
  std::vector<K::Segment_2> segments;
  std::vector<std::pair<std::size_t, std::size_t> > owner;
  for(std::size_t r = 0; r < rings.size(); ++r)
    for(std::size_t i = 0; i < rings[r].size(); ++i) {
      segments.push_back(K::Segment_2(rings[r][i], rings[r][(i + 1) % rings[r].size()]));
      owner.push_back(std::make_pair(r, i));
    }
  for(std::size_t a = 0; a < segments.size(); ++a)
    for(std::size_t b = a + 1; b < segments.size(); ++b) {
      if(!CGAL::do_intersect(segments[a], segments[b]))
        continue;
      std::size_t n = rings[owner[a].first].size();
      bool consecutive = owner[a].first == owner[b].first &&
                         ((owner[a].second + 1) % n == owner[b].second ||
                          (owner[b].second + 1) % n == owner[a].second);
      if(!consecutive)
        return false;
      // Consecutive edges: they must meet only at their common vertex s.
      const K::Segment_2& sa = segments[a];
      const K::Segment_2& sb = segments[b];
      Point s = (sa.target() == sb.source()) ? sa.target() : sa.source();
      Point x = (s == sa.target()) ? sa.source() : sa.target();
      Point y = (s == sb.source()) ? sb.target() : sb.source();
      if(CGAL::collinear(x, s, y) && !CGAL::collinear_are_ordered_along_line(x, s, y))
        return false; // a spike
    }
  for(std::size_t h = 1; h < rings.size(); ++h) {
    const Point& p = rings[h][0];
    if(CGAL::bounded_side_2(rings[0].begin(), rings[0].end(), p, K()) != CGAL::ON_BOUNDED_SIDE)
      return false;
    for(std::size_t g = 1; g < rings.size(); ++g)
      if(g != h && CGAL::bounded_side_2(rings[g].begin(), rings[g].end(), p, K()) == CGAL::ON_BOUNDED_SIDE)
        return false;
  }
  return true;
}

// The brute force when rings may touch at vertices: edges meet only at shared
// vertices or where a vertex lies inside an edge (a T), and near every such place
// each edge (both halves of one through a T) has the polygon's interior
// (by even-odd counting over all rings) on the side its ring's orientation
// (exact signed area) says: just off the edge, a point on the interior side is
// inside and one on the other side is not.  Holes lie in the outer ring and in no
// other hole.  Only for small integer coordinates (the offsets are then exact).
bool brute_force_valid_touching(const Rings& rings)
{
  if(rings.empty())
    return false;
  for(const auto& ring : rings) {
    if(ring.size() < 3)
      return false;
    for(std::size_t i = 0; i < ring.size(); ++i)
      if(ring[i] == ring[(i + 1) % ring.size()])
        return false;   // a zero-length edge
    std::vector<Point> sorted(ring);
    std::sort(sorted.begin(), sorted.end());
    if(std::unique(sorted.begin(), sorted.end()) - sorted.begin() < 3)
      return false;
  }
  std::vector<K::Segment_2> segments;
  std::vector<std::pair<std::size_t, std::size_t> > owner;
  std::map<Point, std::vector<std::pair<std::size_t, std::size_t> > > through;   // T's: the edges through a vertex
  for(std::size_t r = 0; r < rings.size(); ++r)
    for(std::size_t i = 0; i < rings[r].size(); ++i) {
      segments.push_back(K::Segment_2(rings[r][i], rings[r][(i + 1) % rings[r].size()]));
      owner.push_back(std::make_pair(r, i));
    }
  for(std::size_t a = 0; a < segments.size(); ++a)
    for(std::size_t b = a + 1; b < segments.size(); ++b) {
      const K::Segment_2& sa = segments[a];
      const K::Segment_2& sb = segments[b];
      const auto x = CGAL::intersection(sa, sb);
      if(!x)
        continue;
      const Point* p = boost::get<Point>(&*x);
      if(p == nullptr)
        return false;   // an overlap (or a fold of consecutive edges)
      std::size_t n = rings[owner[a].first].size();
      bool consecutive = owner[a].first == owner[b].first &&
                         ((owner[a].second + 1) % n == owner[b].second || (owner[b].second + 1) % n == owner[a].second);
      if(consecutive && n == 3 && *p != sa.source() && *p != sa.target())
        return false;
      const bool end_a = *p == sa.source() || *p == sa.target(), end_b = *p == sb.source() || *p == sb.target();
      if(!end_a && !end_b)
        return false;   // a crossing
      if(end_a != end_b)   // a vertex inside an edge (a T): checked below like a shared vertex
        through[*p].push_back(end_a ? owner[b] : owner[a]);
    }
  auto inside = [&](const Point& q) {   // even-odd over all rings
    int count = 0;
    for(const auto& ring : rings) {
      CGAL::Bounded_side b = CGAL::bounded_side_2(ring.begin(), ring.end(), q, K());
      if(b == CGAL::ON_BOUNDARY) return -1;
      if(b == CGAL::ON_BOUNDED_SIDE) ++count;
    }
    return count % 2;
  };
  std::vector<bool> ccw(rings.size());
  for(std::size_t r = 0; r < rings.size(); ++r) {
    CGAL::Exact_rational area = 0;
    for(std::size_t i = 0; i < rings[r].size(); ++i) {
      const Point& a = rings[r][i];
      const Point& b = rings[r][(i + 1) % rings[r].size()];
      area += CGAL::Exact_rational(a.x()) * CGAL::Exact_rational(b.y()) - CGAL::Exact_rational(a.y()) * CGAL::Exact_rational(b.x());
    }
    ccw[r] = area > 0;
  }
  std::map<Point, int> count;
  for(const auto& ring : rings)
    for(const Point& p : ring) ++count[p];
  for(const auto& t : through) ++count[t.first];
  // just off the edge from p to w: the interior on the side the ring says
  auto sides_agree = [&](const Point& p, const Point& w, bool outgoing, bool interior_left) {
    const double dx = w.x() - p.x(), dy = w.y() - p.y();
    const double along = std::ldexp(1.0, -14), off = std::ldexp(1.0, -40);
    const Point left(p.x() + dx * along - dy * off, p.y() + dy * along + dx * off);
    const Point right(p.x() + dx * along + dy * off, p.y() + dy * along - dx * off);
    // seen from p, the interior is on the left of the outgoing edge and on the
    // right of the incoming one when the ring has it on its left
    const bool want_left = outgoing == interior_left;
    return inside(want_left ? left : right) == 1 && inside(want_left ? right : left) == 0;
  };
  for(std::size_t r = 0; r < rings.size(); ++r) {
    const bool interior_left = (r == 0) == ccw[r];
    const std::size_t n = rings[r].size();
    for(std::size_t i = 0; i < n; ++i) {
      const Point& p = rings[r][i];
      if(count[p] < 2) continue;
      // the outgoing edge (p, next), then the incoming one seen from p (p, prev)
      if(!sides_agree(p, rings[r][(i + 1) % n], true, interior_left) ||
         !sides_agree(p, rings[r][(i + n - 1) % n], false, interior_left))
        return false;
    }
  }
  for(const auto& t : through)
    for(const auto& e : t.second) {
      const auto& ring = rings[e.first];
      const bool interior_left = (e.first == 0) == ccw[e.first];
      if(!sides_agree(t.first, ring[(e.second + 1) % ring.size()], true, interior_left) ||
         !sides_agree(t.first, ring[e.second], false, interior_left))
        return false;
    }
  for(std::size_t h = 1; h < rings.size(); ++h) {
    Point p = rings[h][0];
    for(std::size_t i = 0; i < rings[h].size() && count[p] > 1; ++i) p = rings[h][i];
    if(count[p] > 1)
      p = CGAL::midpoint(rings[h][0], rings[h][1]);
    if(CGAL::bounded_side_2(rings[0].begin(), rings[0].end(), p, K()) != CGAL::ON_BOUNDED_SIDE)
      return false;
    for(std::size_t g = 1; g < rings.size(); ++g)
      if(g != h && CGAL::bounded_side_2(rings[g].begin(), rings[g].end(), p, K()) == CGAL::ON_BOUNDED_SIDE)
        return false;
  }
  return true;
}

// Whether validate_polygon() accepts `rings` with their points converted to
// kernel K2.
template <class K2>
bool validate_polygon_accepts(const Rings& rings)
{
  CGAL::Progressive_medial_axes::Rings<typename K2::Point_2> converted;
  for(const auto& ring : rings) {
    converted.emplace_back();
    for(const Point& p : ring) converted.back().emplace_back(p.x(), p.y());
  }
  try {
    CGAL::Progressive_medial_axes::validate_polygon(converted);
  } catch(const Input_error&) {
    return false;
  }
  return true;
}

int test_random_against_brute_force()
{
  std::mt19937 rng(2024);
  auto uniform = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
  int valid = 0, invalid = 0, big_valid = 0, big_invalid = 0, touching_valid = 0, simple_small = 0, other_kernels = 0;
  std::map<std::string, int> classes; // error classes seen
  for(int trial = 0; trial < 80000; ++trial) {
    Rings rings;
    int mode = trial % 5;
    if(mode == 4) {
      // Squares and triangles of many sizes in a big square: nested and crossing holes.
      rings.push_back(square(0, 0, 40, 40, uniform(0, 1) == 1));
      const bool lattice = uniform(0, 1) == 1;   // holes on a lattice: many touch at corners
      int holes = lattice ? uniform(2, 8) : uniform(1, 4);
      for(int h = 0; h < holes; ++h) {
        int s = uniform(1, 20), x = uniform(1, 39 - s), y = uniform(1, 39 - s);
        if(lattice) {   // diamonds in the cells of a lattice: neighbours touch at corners
          x = 4 * uniform(1, 8);   // (the same cell twice is an overlap, kept as such)
          y = 4 * uniform(1, 8);
          rings.push_back({ Point(x + 2, y), Point(x + 4, y + 2), Point(x + 2, y + 4), Point(x, y + 2) });
          if(uniform(0, 1)) std::reverse(rings.back().begin(), rings.back().end());
          continue;
        }
        if(uniform(0, 2) == 0)
          rings.push_back({ Point(x, y), Point(x + s, y), Point(x, y + s) });
        else
          rings.push_back(square(x, y, x + s, y + s, uniform(0, 1) == 1));
      }
    } else if(mode == 0 || mode == 3) {
      // Fully random rings on a grid: many degeneracies on the small grid, mostly
      // crossings on the larger one.
      int nr = uniform(1, 3), size = (mode == 0) ? 5 : 40;
      for(int r = 0; r < nr; ++r) {
        rings.emplace_back();
        int n = uniform(3, mode == 0 ? 6 : 9);
        for(int i = 0; i < n; ++i)
          rings.back().push_back(Point(uniform(0, size), uniform(0, size)));
      }
    } else {
      // A star-shaped outer ring and small triangular or square holes; one time in 50,
      // a larger one (up to 150 vertices and 30 holes).
      const bool big = (trial % 50 == 1);
      const int scale = big ? 7 : 1;
      int n = big ? uniform(20, 150) : uniform(3, 10);
      std::vector<double> angles;
      for(int i = 0; i < n; ++i)
        angles.push_back(std::uniform_real_distribution<double>(0, 6.283185307179586)(rng));
      std::sort(angles.begin(), angles.end());
      rings.emplace_back();
      for(double a : angles) {
        double radius = uniform(3 * scale, 8 * scale);
        double x = 10 * scale + radius * std::cos(a), y = 10 * scale + radius * std::sin(a);
        if(!big) { // rounding makes degeneracies, and may break the star
          x = std::round(x);
          y = std::round(y);
        }
        rings.back().push_back(Point(x, y));
      }
      // The large polygons get holes in distinct cells of a grid inside the star.
      std::vector<int> cells(81);
      for(int c = 0; c < 81; ++c)
        cells[c] = c;
      std::shuffle(cells.begin(), cells.end(), rng);
      int holes = big ? uniform(0, 30) : uniform(0, 4);
      for(int h = 0; h < holes; ++h) {
        int x = uniform(3 * scale, 16 * scale), y = uniform(3 * scale, 16 * scale);
        int s = uniform(1, mode == 2 ? 7 : 3);
        if(big) {
          x = 52 + 4 * (cells[h] % 9);
          y = 52 + 4 * (cells[h] / 9);
        }
        if(uniform(0, 1))
          rings.push_back({ Point(x, y), Point(x + s, y), Point(x, y + s) });
        else
          rings.push_back(square(x, y, x + s, y + s, uniform(0, 1) == 1));
      }
      if(mode == 2 && !rings.back().empty()) // a random vertex moved
        rings[uniform(0, static_cast<int>(rings.size()) - 1)][0] =
          Point(uniform(2 * scale, 18 * scale), uniform(2 * scale, 18 * scale));
    }
    const bool strict = brute_force_valid(rings);
    bool integral = true;
    for(const auto& ring : rings)
      for(const Point& p : ring) integral = integral && p.x() == std::floor(p.x()) && p.y() == std::floor(p.y());
    // (the touching brute force needs integer coordinates; the others have no
    // repeated vertices but by accident)
    bool expected = integral ? brute_force_valid_touching(rings) : strict;
    bool got = true;
    std::string message;
    try {
      validate(rings);
    } catch(const Input_error& e) {
      got = false;
      message = e.what();
      std::string kind = message.substr(0, message.find(':'));
      if(kind.compare(0, 5, "hole ") == 0)
        kind = (message.find("lies inside") != std::string::npos) ? "hole inside hole" : "hole outside";
      else if(kind.compare(0, 5, "ring ") == 0)
        kind = "too few distinct vertices";
      else if(kind == "self-intersection")
        kind += (message.find(" cross at ") != std::string::npos) ? " (cross at a shared vertex)"
              : (message.find(" vertex ") != std::string::npos && message.find(" crosses ") != std::string::npos)
                ? " (vertex crosses an edge)"
              : (message.find("crosses") != std::string::npos) ? " (crosses)"
              : (message.find("overlaps") != std::string::npos) ? " (overlaps)" : " (other)";
      ++classes[kind];
    }
    touching_valid += (expected && !strict);
    // the validator's shortcut for small polygons: exactly the strictly
    // valid ones (no touching) of at most 64 vertices
    std::size_t vertices = 0;
    for(const auto& ring : rings) vertices += ring.size();
    const bool simple = CGAL::Progressive_medial_axes::internal::simple_small_polygon<K>(rings);
    simple_small += simple;
    if(simple != (strict && vertices <= 64)) {
      std::ostringstream wkt;
      pma_tool::write_wkt_polygon(wkt, rings);
      std::fprintf(stderr, "trial %d: simple_small_polygon says %d, brute force says %s (%zu vertices) for\n  %s\n", trial,
                   int(simple), strict ? "simple" : "not simple", vertices, wkt.str().c_str());
      REQUIRE(false);
    }
    if(got != expected) {
      std::ostringstream wkt;
      pma_tool::write_wkt_polygon(wkt, rings);
      std::fprintf(stderr, "trial %d: validate says %s (%s), brute force says %s for\n  %s\n", trial,
                   got ? "valid" : "invalid", message.c_str(), expected ? "valid" : "invalid", wkt.str().c_str());
      REQUIRE(false);
    }
    // validate_polygon() of the same rings in other kernels, which take the
    // shortcut and the validator through their own predicates: a kernel of
    // doubles converts the points to Epick, exact rationals (every fourth
    // trial: slower) use theirs
    const bool rational = trial % 4 == 0;
    const bool agree = validate_polygon_accepts<CGAL::Simple_cartesian<double> >(rings) == expected &&
                       (!rational || validate_polygon_accepts<CGAL::Simple_cartesian<CGAL::Exact_rational> >(rings) == expected);
    other_kernels += 1 + rational;
    if(!agree) {
      std::ostringstream wkt;
      pma_tool::write_wkt_polygon(wkt, rings);
      std::fprintf(stderr, "trial %d: validate_polygon() in another kernel does not say %s for\n  %s\n", trial,
                   expected ? "valid" : "invalid", wkt.str().c_str());
      REQUIRE(false);
    }
    (expected ? valid : invalid)++;
    if(trial % 50 == 1)
      (expected ? big_valid : big_invalid)++;
  }
  std::printf("  random polygons: %d valid, %d invalid, all agree with the brute force\n", valid, invalid);
  std::printf("    (of which larger polygons: %d valid, %d invalid)\n", big_valid, big_invalid);
  std::printf("    of which valid only because rings may touch at vertices: %d\n", touching_valid);
  std::printf("    accepted by the shortcut for small polygons: %d\n", simple_small);
  std::printf("    checked again by validate_polygon() in Simple_cartesian<double> and <Exact_rational>: %d\n", other_kernels);
  for(const auto& c : classes)
    std::printf("    %-36s %6d\n", c.first.c_str(), c.second);
  REQUIRE(valid > 1000 && invalid > 1000 && touching_valid > 1000 && simple_small > 1000);
  REQUIRE(classes.size() == 9 && !classes.count("self-intersection (other)")); // every class of geometric error but non-finite coordinates
  return 0;
}

// ------------------------------------------------------------------ performance

Rings star_polygon(std::size_t n, unsigned seed)
{
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> radius(0.5, 1.0);
  Rings rings(1);
  rings[0].reserve(n);
  for(std::size_t i = 0; i < n; ++i) {
    double a = 6.283185307179586 * static_cast<double>(i) / static_cast<double>(n);
    double r = (i % 2 == 0) ? 1.0 : radius(rng);
    rings[0].push_back(Point(r * std::cos(a), r * std::sin(a)));
  }
  return rings;
}

int test_performance()
{
  {
    Rings star = star_polygon(100000, 1);
    auto start = std::chrono::steady_clock::now();
    CHECK_VALID(star);
    std::printf("  validate star polygon, 1e5 vertices: %.3f s\n", seconds_since(start));
  }
  {
    Rings grid;
    grid.push_back(square(0, 0, 201, 201));
    for(int i = 0; i < 200; ++i)
      for(int j = 0; j < 200; ++j)
        grid.push_back(square(i + 1.25, j + 1.25, i + 1.75, j + 1.75, (i + j) % 2 == 0));
    auto start = std::chrono::steady_clock::now();
    CHECK_VALID(grid);
    std::printf("  validate 200x200 grid of square holes (40000 holes, 160004 vertices): %.3f s\n",
                seconds_since(start));
    // The same grid with one hole moved into its neighbour.
    grid[1 + 200 * 100 + 100] = square(101.5, 101.5, 102.5, 102.5);
    CHECK_INPUT_ERROR(validate(grid), "self-intersection", ANY, ANY);
  }
  {
    Rings star = star_polygon(1000000, 2);
    std::ostringstream out;
    pma_tool::write_wkt_polygon(out, star);
    std::string text = out.str();
    auto start = std::chrono::steady_clock::now();
    Rings back = read_wkt(text);
    double read_time = seconds_since(start);
    REQUIRE(same_rings(back, star));
    start = std::chrono::steady_clock::now();
    CHECK_VALID(back);
    double validate_time = seconds_since(start);
    std::printf("  star polygon, 1e6 vertices (%.1f MB of WKT): read %.3f s, validate %.3f s\n",
                static_cast<double>(text.size()) / 1e6, read_time, validate_time);
  }
  return 0;
}

// Random corruptions of valid inputs must give a polygon or an Input_error, nothing else.
int test_reader_fuzz()
{
  const std::string seeds[] = {
    "POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0), (1 1, 1 2, 2 2, 1 1))",
    "MULTIPOLYGON (((0.5 -1e3, 4 0, 4 4.25, 0.5 -1e3)))",
    R"({"type": "FeatureCollection", "features": [{"type": "Feature", "properties": {"a": [1, "x\u00e9"]},
        "geometry": {"type": "Polygon", "coordinates": [[[0, 0], [4, 0], [4, 4], [0, 0]], [[1, 1], [2, 1], [2, 2], [1, 1]]]}}]})",
  };
  const char alphabet[] = "()[]{},:\" -+.eE0123456789 \n\tPOLYGNMZEtruefalsn\\";
  std::mt19937 rng(99);
  int parsed = 0, rejected = 0;
  for(int trial = 0; trial < 30000; ++trial) {
    std::string text = seeds[trial % 3];
    int edits = 1 + static_cast<int>(rng() % 4);
    for(int k = 0; k < edits && !text.empty(); ++k) {
      std::size_t at = rng() % text.size();
      switch(rng() % 4) {
      case 0: text.erase(at, 1 + rng() % 3); break;
      case 1: text.insert(at, 1, alphabet[rng() % (sizeof(alphabet) - 1)]); break;
      case 2: text[at] = alphabet[rng() % (sizeof(alphabet) - 1)]; break;
      default: text.resize(at); break;
      }
    }
    try {
      Rings r = (trial % 3 == 2) ? read_geojson(text) : read_wkt(text);
      for(const auto& ring : r)
        REQUIRE(ring.size() >= 3);
      ++parsed;
      try {
        validate(r);
      } catch(const Input_error&) {
      }
    } catch(const Input_error& e) {
      REQUIRE(std::string(e.what()).find('\n') == std::string::npos);
      ++rejected;
    } catch(const std::exception& e) {
      std::fprintf(stderr, "unexpected exception %s for input\n%s\n", e.what(), text.c_str());
      REQUIRE(false);
    }
  }
  std::printf("  corrupted inputs: %d read, %d rejected\n", parsed, rejected);
  return 0;
}

// Reading does not depend on the C locale's decimal point.
int test_locale()
{
  const char* names[] = { "de_DE.UTF-8", "de_DE.utf8", "fr_FR.UTF-8", "fr_FR.utf8" };
  const char* set = nullptr;
  for(const char* name : names)
    if((set = std::setlocale(LC_NUMERIC, name)) != nullptr)
      break;
  if(set == nullptr) {
    std::printf("  (no locale with a decimal comma installed: locale test skipped)\n");
    return 0;
  }
  Rings r = read_wkt("POLYGON ((0.5 0, 1.25 0, 1 1.5, 0.5 0))");
  std::ostringstream out;
  pma_tool::write_wkt_polygon(out, r);
  std::setlocale(LC_NUMERIC, "C");
  REQUIRE(r[0][0] == Point(0.5, 0) && r[0][1] == Point(1.25, 0) && r[0][2] == Point(1, 1.5));
  REQUIRE(out.str() == "POLYGON ((0.5 0, 1.25 0, 1 1.5, 0.5 0))");
  return 0;
}

// ------------------------------------------------------------- curve evolution

// Runs the discrete curve evolution of `rings` and checks `checks` of its
// shapes (all of them with 0), with the validator and, with `brute`, the
// brute-force check.  Returns the number of rings left with more than three
// vertices, or -1 on a failure.  `parts`: the slabs of the first phase (0:
// as the evolution chooses; see Curve_evolution.h).
int check_evolution(const char* name, const Rings& rings, std::size_t checks, bool brute, bool fill_holes = true,
                    int parts = 0)
{
  CGAL::Progressive_medial_axes::internal::Curve_evolution<K> evolution(rings, K(), fill_holes);
  evolution.run(parts);
  const auto& removals = evolution.removals();
  const std::size_t steps = removals.size();
  std::vector<std::size_t> ks;
  if(checks == 0 || checks >= steps) {
    for(std::size_t k = 0; k <= steps; ++k) ks.push_back(k);
  } else {
    for(std::size_t i = 0; i <= checks; ++i) ks.push_back(steps * i / checks);
  }
  for(std::size_t k : ks) {
    const Rings shape = evolution.shape(k);
    bool ok = true;
    try {
      validate_touching(shape);
    } catch(const Input_error& e) {
      std::fprintf(stderr, "%s: shape after %zu of %zu removals is invalid: %s\n", name, k, steps, e.what());
      ok = false;
    }
    if(ok && brute && !brute_force_valid_touching(shape)) {
      std::fprintf(stderr, "%s: shape after %zu removals is invalid by brute force\n", name, k);
      ok = false;
    }
    if(!ok) return -1;
  }
  // each removal took a vertex whose neighbours were alive then
  std::vector<std::vector<char> > alive;
  for(const auto& r : rings) alive.emplace_back(r.size(), 1);
  for(const auto& rm : removals) {
    auto& a = alive[std::size_t(rm.ring)];
    if(rm.vertex < 0) {   // a triangular hole filled
      if(rm.ring == 0 || std::count(a.begin(), a.end(), 1) != 3) {
        std::fprintf(stderr, "%s: a filled ring that is not a triangular hole\n", name);
        return -1;
      }
      std::fill(a.begin(), a.end(), 0);
      continue;
    }
    if(!a[std::size_t(rm.vertex)] || !a[std::size_t(rm.prev)] || !a[std::size_t(rm.next)]) {
      std::fprintf(stderr, "%s: removal of a dead vertex or next to one\n", name);
      return -1;
    }
    a[std::size_t(rm.vertex)] = 0;
  }
  const Rings last = evolution.shape(steps);
  int larger = 0;
  for(const auto& r : last) {
    if(r.size() < 3) {
      std::fprintf(stderr, "%s: a ring with fewer than 3 vertices\n", name);
      return -1;
    }
    larger += r.size() > 3;
  }
  return larger;
}

template <class Evolution>
Rings evolution_end(const Evolution& e) { return e.shape(e.removals().size()); }

int test_curve_evolution()
{
  // shipped shapes: 40 shapes along each evolution (every shape of the small ones)
  const char* names[] = { "syn_cheese1k.wkt", "syn_comb50.wkt", "syn_maze20.wkt", "syn_ngon64.wkt",
                          "syn_sliver500.wkt", "syn_spiral20.wkt", "syn_star2k.wkt", "c1m_GBR_0.wkt",
                          "touching/c1m_AUS_33982.wkt", "touching/c1m_PNG_21.wkt", "touching/l10m_RUS_30511.wkt",
                          "touching/syn_island.wkt", "touching/syn_pinch.wkt", "touching/syn_t_self.wkt",
                          "touching/syn_t_notch.wkt", "touching/syn_three_holes.wkt", "touching/syn_hole_corner.wkt" };
  for(const char* name : names) {
    const Rings rings = pma_tool::read_polygon_file<Point>(data(name));
    std::size_t n = 0;
    for(const auto& r : rings) n += r.size();
    const auto start = std::chrono::steady_clock::now();
    CGAL::Progressive_medial_axes::internal::Curve_evolution<K> timed(rings);
    timed.run();
    const double seconds = seconds_since(start);
    const int larger = check_evolution(name, rings, n < 300 ? 0 : 40, false);
    REQUIRE(larger >= 0);
    // in 2 and in 5 slabs first (parallel where oneTBB is linked)
    for(int parts : {2, 5}) {
      const int in_slabs = check_evolution(name, rings, n < 300 ? 0 : 40, false, true, parts);
      REQUIRE(in_slabs >= 0);
      if(std::strncmp(name, "touching/", 9) != 0) REQUIRE(in_slabs == 0);
    }
    std::printf("  %-30s %7zu vertices %5zu rings: evolution %.3f s, %zu removals, %d rings left above 3 vertices\n",
                name, n, rings.size(), seconds, timed.removals().size(), larger);
    // without touching rings, the evolution ends with a triangle
    if(std::strncmp(name, "touching/", 9) != 0)
      REQUIRE(larger == 0 && evolution_end(timed).size() == 1);
  }
  // random polygons with holes, some touching: every shape checked, also by brute force
  std::mt19937 rng(77);
  auto uniform = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
  int tried = 0, checked = 0, left_larger = 0;
  for(int trial = 0; trial < 3000; ++trial) {
    Rings rings;
    const int n = uniform(3, 24);
    std::vector<double> angles;
    for(int i = 0; i < n; ++i) angles.push_back(std::uniform_real_distribution<double>(0, 6.283185307179586)(rng));
    std::sort(angles.begin(), angles.end());
    rings.emplace_back();
    for(double a : angles) {
      const double radius = uniform(10, 40);
      rings.back().push_back(Point(std::round(50 + radius * std::cos(a)), std::round(50 + radius * std::sin(a))));
    }
    const int holes = uniform(0, 5);
    for(int h = 0; h < holes; ++h) {
      const int x = 4 * uniform(9, 15), y = 4 * uniform(9, 15);   // diamonds of a lattice: may touch
      if(trial % 2)
        rings.push_back({ Point(x + 2, y), Point(x, y + 2), Point(x + 2, y + 4), Point(x + 4, y + 2) });
      else
        rings.push_back({ Point(x, y), Point(x, y + 3), Point(x + 1, y + 1), Point(x + 3, y) });
    }
    ++tried;
    try {
      validate_touching(rings);
    } catch(const Input_error&) {
      continue;
    }
    ++checked;
    const int larger = check_evolution("random", rings, 0, true);
    // as boundary evolution runs it: holes stop at triangles
    const int kept = check_evolution("random, holes kept", rings, 0, true, false);
    const int slabs = check_evolution("random, in slabs", rings, 0, true, trial % 3 == 0, 2 + trial % 3);
    if(larger < 0 || kept < 0 || slabs < 0) {
      std::fprintf(stderr, "  random trial %d failed\n", trial);
      REQUIRE(false);
    }
    left_larger += larger;
  }
  std::printf("  %d random polygons (%d valid) evolved (holes filled, and kept; and in 2 to 4 slabs first), every shape valid; %d rings left above 3 vertices\n", tried,
              checked, left_larger);
  REQUIRE(checked > 300);
  return 0;
}

int main()
{
  struct Test { const char* name; int (*run)(); };
  const Test tests[] = {
    { "WKT reading", test_wkt_reading },
    { "WKT writing", test_wkt_writing },
    { "GeoJSON reading", test_geojson_reading },
    { "several polygons", test_multi_reading },
    { "invalid files", test_invalid_files },
    { "shipped data", test_shipped_data },
    { "valid polygons", test_valid_polygons },
    { "invalid polygons", test_invalid_polygons },
    { "touching rings", test_touching_rings },
    { "random polygons", test_random_against_brute_force },
    { "curve evolution", test_curve_evolution },
    { "reader fuzz", test_reader_fuzz },
    { "performance", test_performance },
    { "locale", test_locale },
  };
  int failed = 0;
  for(const Test& t : tests) {
    std::printf("%s\n", t.name);
    std::fflush(stdout);
    if(t.run() != 0) {
      std::printf("  FAILED\n");
      ++failed;
    }
    std::fflush(stdout);
  }
  std::printf("%d of %zu test groups failed\n", failed, sizeof(tests) / sizeof(tests[0]));
  return failed == 0 ? pma_test::report("test_input") : 1;
}
