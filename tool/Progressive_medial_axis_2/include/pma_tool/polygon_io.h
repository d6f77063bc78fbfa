// Copyright (c) 2026 The Progressive_medial_axis_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// The command-line tool's input and output of polygons (not part of the
// library): reading a polygon with holes from WKT or GeoJSON, writing it as
// WKT.  Errors are reported as the library's Input_error.

#ifndef PMA_TOOL_POLYGON_IO_H
#define PMA_TOOL_POLYGON_IO_H

#include <CGAL/Progressive_medial_axis_2/Input_error.h>

#include <CGAL/assertions.h>
#include <CGAL/number_utils.h>

#include <nlohmann/json.hpp>
#ifdef PMA_TOOL_WITH_SIMDJSON
#include <simdjson.h>
#endif

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <istream>
#include <limits>
#include <ostream>
#include <sstream>
#include <string>
#include <system_error>
#include <vector>

namespace pma_tool {

using CGAL::Progressive_medial_axes::Input_error;
using CGAL::Progressive_medial_axes::Rings;

/// One polygon of the input, with the properties of the GeoJSON feature it comes
/// from: their JSON text (an object, members in input order), empty if there are none.
template <class Point_2>
struct Input_polygon
{
  Rings<Point_2> rings;
  std::string properties;
};

/// The geometries a reader skipped: points and lines (`Point`, `MultiPoint`,
/// `LineString`, `MultiLineString`, in WKT or GeoJSON), which bound no area and so
/// have no medial axis.  Real collections hold them beside the polygons (labels,
/// roads, rivers); they are skipped rather than the whole input rejected.  Input
/// that holds no polygon at all is still an error.
struct Skipped_geometries
{
  std::size_t count = 0;
  /// The first one skipped, as the reader names it: its type, and for GeoJSON
  /// in a collection, where it is (`LineString in feature 1`).
  std::string first;

  void add(const std::string& what)
  {
    if(count++ == 0)
      first = what;
  }
  /// The error for input that held no polygon: the first geometry skipped, if any.
  [[noreturn]] void throw_no_polygon() const
  {
    if(count > 0)
      throw Input_error("not a polygon: found " + first);
    throw Input_error("empty polygon");
  }
};

namespace internal {

/// Whether `type` (a WKT keyword in upper case, or a GeoJSON type) is a point or
/// line type, skipped by the readers (see Skipped_geometries).
inline bool is_point_or_line_type(const std::string& type)
{
  for(const char* t : {"POINT", "MULTIPOINT", "LINESTRING", "MULTILINESTRING", "Point", "MultiPoint", "LineString",
                       "MultiLineString"})
    if(type == t)
      return true;
  return false;
}

using CGAL::Progressive_medial_axes::internal::format_coordinate;
using CGAL::Progressive_medial_axes::internal::format_point;

// ------------------------------------------------------------------ common helpers

/// Reads all of `in` into a string.
inline std::string read_all(std::istream& in)
{
  std::ostringstream buffer;
  if(in.rdbuf() != nullptr && in.peek() != std::istream::traits_type::eof())
    buffer << in.rdbuf();
  if(in.bad())
    throw Input_error("cannot read input: read error");
  return buffer.str();
}

/// The 1-based line and column (in bytes) of `pos` in `[begin, ...)`, as text.
inline std::string line_column(const char* begin, const char* pos)
{
  std::size_t line = 1;
  const char* line_start = begin;
  for(const char* c = begin; c < pos; ++c)
    if(*c == '\n') {
      ++line;
      line_start = c + 1;
    }
  return "line " + std::to_string(line) + ", column " +
         std::to_string(static_cast<std::size_t>(pos - line_start) + 1);
}

/// `begin`, past a UTF-8 byte order mark if the text `[begin, end)` starts with one.
inline const char* after_byte_order_mark(const char* begin, const char* end)
{
  return (end - begin >= 3 && std::memcmp(begin, "\xEF\xBB\xBF", 3) == 0) ? begin + 3 : begin;
}

inline bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v'; }
inline bool is_digit(char c) { return c >= '0' && c <= '9'; }
inline bool is_alpha(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); }
inline char to_upper(char c) { return (c >= 'a' && c <= 'z') ? static_cast<char>(c - 'a' + 'A') : c; }

/// Case-insensitive comparison of `[p, e)` with the upper-case word `word`.
inline bool equals_word(const char* p, const char* e, const char* word)
{
  for(; *word != '\0'; ++p, ++word)
    if(p == e || to_upper(*p) != *word)
      return false;
  return p == e;
}

/// The result of scanning a number.
struct Scanned_number
{
  enum Status { NOT_A_NUMBER, FINITE, NON_FINITE };
  Status status = NOT_A_NUMBER;
  double value = 0;
  const char* end = nullptr; // one past the token
};

/// Converts the decimal number `[begin, end)` (syntax already checked: optional sign,
/// digits with an optional point, optional exponent) exactly as `strtod` does in the C
/// locale, whatever the current locale. Returns false on overflow.
inline bool convert_decimal(const char* begin, const char* end, double& value)
{
  const char* p = begin;
  bool negative = false;
  if(p != end && (*p == '+' || *p == '-')) {
    negative = (*p == '-');
    ++p;
  }
#if defined(__cpp_lib_to_chars) && __cpp_lib_to_chars >= 201611L
  std::from_chars_result r = std::from_chars(p, end, value, std::chars_format::general);
  if(r.ec == std::errc() && r.ptr == end) {
    if(negative)
      value = -value;
    return true;
  }
  // Out of range: decide between overflow and underflow (to zero, since values that
  // round to a subnormal number are converted) from the decimal exponent `lead` of the
  // leading nonzero digit of the mantissa.
  const char* q = p;
  const char* point = nullptr;
  const char* first_nonzero = nullptr;
  for(; q != end && *q != 'e' && *q != 'E'; ++q) {
    if(*q == '.')
      point = q;
    else if(first_nonzero == nullptr && *q != '0')
      first_nonzero = q;
  }
  if(point == nullptr)
    point = q;
  if(first_nonzero == nullptr) { // zero: cannot be out of range
    value = negative ? -0.0 : 0.0;
    return true;
  }
  long lead = (first_nonzero < point) ? static_cast<long>(point - first_nonzero) - 1
                                      : -static_cast<long>(first_nonzero - point);
  long exponent = 0;
  if(q != end) {
    ++q;
    bool negative_exponent = false;
    if(q != end && (*q == '+' || *q == '-')) {
      negative_exponent = (*q == '-');
      ++q;
    }
    for(; q != end; ++q)
      if(exponent < 1000000)
        exponent = exponent * 10 + (*q - '0');
    if(negative_exponent)
      exponent = -exponent;
  }
  if(lead + exponent > 0)
    return false;
  value = negative ? -0.0 : 0.0;
  return true;
#else
  // Fallback for standard libraries without floating-point from_chars: strtod, which
  // depends on the decimal point of the current C locale.
  std::string token(begin, end);
  errno = 0;
  value = std::strtod(token.c_str(), nullptr);
  return std::isfinite(value);
#endif
}

/// Scans a number at `p` (not past `e`): `[+-]? (digits [. digits] | . digits)
/// ([eE] [+-]? digits)?`, or `[+-]? (nan | inf | infinity)` (any case) which gives a
/// non-finite result, as do numbers too large for a double.
inline Scanned_number scan_number(const char* p, const char* e)
{
  Scanned_number result;
  const char* start = p;
  if(p != e && (*p == '-' || *p == '+'))
    ++p;
  // Non-finite words.
  if(p != e && is_alpha(*p)) {
    const char* w = p;
    while(w != e && is_alpha(*w))
      ++w;
    if(equals_word(p, w, "NAN") || equals_word(p, w, "INF") || equals_word(p, w, "INFINITY")) {
      result.status = Scanned_number::NON_FINITE;
      result.end = w;
    }
    return result;
  }
  const char* digits = p;
  while(p != e && is_digit(*p))
    ++p;
  std::size_t integer_digits = static_cast<std::size_t>(p - digits);
  std::size_t fraction_digits = 0;
  if(p != e && *p == '.') {
    const char* f = ++p;
    while(p != e && is_digit(*p))
      ++p;
    fraction_digits = static_cast<std::size_t>(p - f);
  }
  if(integer_digits + fraction_digits == 0)
    return result;
  if(p != e && (*p == 'e' || *p == 'E')) {
    const char* x = p + 1;
    if(x != e && (*x == '+' || *x == '-'))
      ++x;
    const char* d = x;
    while(x != e && is_digit(*x))
      ++x;
    if(x != d) // as strtod: an exponent without digits is not part of the number
      p = x;
  }
  result.end = p;
  result.status = convert_decimal(start, p, result.value) ? Scanned_number::FINITE
                                                          : Scanned_number::NON_FINITE;
  return result;
}

inline std::string ring_vertex(std::size_t ring, std::size_t vertex)
{
  return "ring " + std::to_string(ring) + " vertex " + std::to_string(vertex);
}

/// Checks a ring as written (with its closing point) and drops the closing point.
template <class Point_2>
void finish_ring(std::vector<Point_2>& ring, const std::vector<double>& xy, std::size_t index)
{
  std::size_t n = xy.size() / 2;
  if(n < 4)
    throw Input_error("ring " + std::to_string(index) + " has fewer than 4 points (" +
                      std::to_string(n) + " written; a closed ring needs at least 4)",
                      static_cast<int>(index));
  if(xy[0] != xy[2 * n - 2] || xy[1] != xy[2 * n - 1])
    throw Input_error("unclosed ring: ring " + std::to_string(index) + " (first point " +
                      format_point(xy[0], xy[1]) + ", last point " +
                      format_point(xy[2 * n - 2], xy[2 * n - 1]) + ")",
                      static_cast<int>(index));
  ring.clear();
  ring.reserve(n - 1);
  for(std::size_t i = 0; i + 1 < n; ++i)
    ring.push_back(Point_2(xy[2 * i], xy[2 * i + 1]));
}

// ------------------------------------------------------------------ WKT

/// A recursive-descent WKT reader over a buffer, accepting `POLYGON`, `MULTIPOLYGON`
/// and `GEOMETRYCOLLECTION`s of them (nested), each possibly `EMPTY`.
template <class Point_2>
class Wkt_polygon_reader
{
public:
  Wkt_polygon_reader(const char* begin, const char* end) : m_begin(begin), m_p(begin), m_end(end) {}

  /// The polygons; with `skipped`, also what was skipped (see Skipped_geometries).
  std::vector<Input_polygon<Point_2> > read(Skipped_geometries* skipped = nullptr)
  {
    m_p = after_byte_order_mark(m_p, m_end);
    skip_space();
    if(m_p == m_end)
      throw Input_error("empty input: no polygon found");
    skip_srid();
    geometry(0);
    expect_end();
    if(m_out.empty())
      m_skipped.throw_no_polygon();
    if(skipped != nullptr)
      *skipped = m_skipped;
    return std::move(m_out);
  }

private:
  // POLYGON ... | MULTIPOLYGON ... | GEOMETRYCOLLECTION (geometry, ...), each possibly EMPTY
  void geometry(int depth)
  {
    skip_space();
    const char* kw_begin = m_p;
    std::string keyword = read_word();
    if(keyword.empty())
      error(kw_begin, "expected 'POLYGON'");
    // Z, M and ZM coordinates (a tag after the keyword, or glued to it as
    // in POLYGONZ): the third and fourth values are read and ignored, as
    // GEOS's two-dimensional operations ignore them
    int dimension = 0;   // values per point; 0: as the polygon's first point has (2 to 4)
    const std::size_t n = keyword.size();
    for(const char* dim : {"ZM", "Z", "M"}) {
      const std::size_t d = std::strlen(dim);
      if(n > d && keyword.compare(n - d, d, dim) == 0) {
        const std::string base = keyword.substr(0, n - d);
        if(base == "POLYGON" || base == "MULTIPOLYGON" || base == "GEOMETRYCOLLECTION" || is_point_or_line_type(base)) {
          dimension = 2 + int(d);
          keyword = base;
          break;
        }
      }
    }
    const bool point_or_line = is_point_or_line_type(keyword);
    if(!point_or_line && keyword != "POLYGON" && keyword != "MULTIPOLYGON" && keyword != "GEOMETRYCOLLECTION")
      throw Input_error("not a polygon: found " + keyword);
    if(point_or_line)
      m_skipped.add(keyword);
    if(depth > 64)
      error(kw_begin, "collections nested too deep");
    skip_space();
    if(m_p != m_end && is_alpha(*m_p)) {
      const char* w = m_p;
      std::string tag = read_word();
      if(dimension == 0 && (tag == "Z" || tag == "M" || tag == "ZM")) {
        dimension = 2 + int(tag.size());
        skip_space();
        w = m_p;
        tag = read_word();   // (none before the '(')
      }
      if(tag == "EMPTY")
        return;
      if(!tag.empty() || m_p == m_end || *m_p != '(')
        error(w, "expected '(' or 'EMPTY'");
    }
    if(point_or_line) {   // read and dropped
      skip_list(0);
      return;
    }
    if(keyword == "POLYGON") {
      read_polygon_text(dimension);
      return;
    }
    m_multi = true;
    expect('(', "expected '(' or 'EMPTY'");
    for(;;) {
      if(keyword == "GEOMETRYCOLLECTION") {
        geometry(depth + 1);
      } else {
        skip_space();
        if(m_p != m_end && is_alpha(*m_p)) { // MULTIPOLYGON (EMPTY, ...)
          const char* w = m_p;
          if(read_word() != "EMPTY")
            error(w, "expected '('");
        } else {
          read_polygon_text(dimension);
        }
      }
      if(!next_in_list())
        return;
    }
  }

private:
  [[noreturn]] void error(const char* at, const std::string& what) const
  {
    throw Input_error("malformed WKT at " + line_column(m_begin, at) + ": " + what);
  }

  // The list of a point or line geometry, read and dropped: '(' item (','
  // item)* ')', an item a list, EMPTY, or a point of 2 to 4 numbers.  (This
  // covers POINT, LINESTRING and both forms of MULTIPOINT.)
  void skip_list(int depth)
  {
    if(depth > 3)
      error(m_p, "lists nested too deep");
    expect('(', "expected '(' or 'EMPTY'");
    for(;;) {
      skip_space();
      if(m_p != m_end && *m_p == '(') {
        skip_list(depth + 1);
      } else if(m_p != m_end && is_alpha(*m_p) && !scan_number(m_p, m_end).end) {
        const char* w = m_p;
        if(read_word() != "EMPTY")
          error(w, "expected '(', 'EMPTY' or a number");
      } else {
        for(int values = 0; values < 4; ++values) {   // a point: 2 to 4 numbers
          skip_space();
          const Scanned_number x = scan_number(m_p, m_end);
          if(x.status == Scanned_number::NOT_A_NUMBER) {
            if(values < 2)
              error(m_p, "expected a number");
            break;
          }
          m_p = x.end;
        }
      }
      if(!next_in_list())
        return;
    }
  }

  void skip_space()
  {
    while(m_p != m_end && is_space(*m_p))
      ++m_p;
  }

  // PostGIS's extended WKT (ST_AsEWKT) starts with `SRID=<integer>;`: the
  // reference system is not needed here, so it is read and dropped
  void skip_srid()
  {
    const char* w = m_p;
    if(read_word() != "SRID") {
      m_p = w;
      return;
    }
    skip_space();
    expect('=', "expected '=' after SRID");
    skip_space();
    if(m_p != m_end && *m_p == '-')
      ++m_p;
    const char* digits = m_p;
    while(m_p != m_end && is_digit(*m_p))
      ++m_p;
    if(m_p == digits)
      error(m_p, "expected the SRID's number");
    expect(';', "expected ';' after the SRID");
  }

  std::string read_word()
  {
    std::string word;
    while(m_p != m_end && is_alpha(*m_p))
      word.push_back(to_upper(*m_p++));
    return word;
  }

  void expect(char c, const char* what)
  {
    skip_space();
    if(m_p == m_end || *m_p != c)
      error(m_p, what);
    ++m_p;
  }

  // After an item of a list: true past a ',' (another item follows), false
  // past the closing ')'.
  bool next_in_list()
  {
    skip_space();
    if(m_p != m_end && *m_p == ',') {
      ++m_p;
      return true;
    }
    expect(')', "expected ',' or ')'");
    return false;
  }

  void expect_end()
  {
    skip_space();
    if(m_p != m_end)
      error(m_p, "unexpected text after the polygon");
  }

  // '(' ring (',' ring)* ')', one more polygon, of `dimension` values per
  // point (0: as many as its first point has)
  void read_polygon_text(int dimension)
  {
    const std::string prefix = m_multi ? "polygon " + std::to_string(m_out.size()) + ": " : std::string();
    Input_polygon<Point_2> polygon;
    Rings<Point_2>& rings = polygon.rings;
    expect('(', "expected '('");
    std::vector<double> xy;
    for(;;) {
      try {
        read_ring_text(xy, rings.size(), dimension);
        rings.emplace_back();
        finish_ring(rings.back(), xy, rings.size() - 1);
      } catch(const Input_error& e) {
        if(prefix.empty() || std::strncmp(e.what(), "malformed WKT", 13) == 0)
          throw;
        throw Input_error(prefix + e.what(), e.ring(), e.vertex());
      }
      if(!next_in_list()) {
        m_out.push_back(std::move(polygon));
        return;
      }
    }
  }

  // '(' x y [z [m]] (',' x y [z [m]])* ')': keeps x and y; sets `dimension`
  // from the first point where it is 0
  void read_ring_text(std::vector<double>& xy, std::size_t ring, int& dimension)
  {
    xy.clear();
    skip_space();
    if(m_p != m_end && is_alpha(*m_p)) {
      const char* w = m_p;
      if(read_word() == "EMPTY")
        throw Input_error("ring " + std::to_string(ring) + " is empty", static_cast<int>(ring));
      error(w, "expected '('");
    }
    expect('(', "expected '('");
    for(;;) {
      std::size_t vertex = xy.size() / 2;
      read_coordinate(xy, ring, vertex);
      if(m_p == m_end || !is_space(*m_p)) {
        skip_space();
        error(m_p, "expected a space and a second coordinate");
      }
      read_coordinate(xy, ring, vertex);
      int values = 2;
      for(;;) {   // the z and m values, which only need to be numbers
        const char* after = m_p;
        skip_space();
        if(m_p == after)
          break;
        const Scanned_number z = scan_number(m_p, m_end);
        if(z.status == Scanned_number::NOT_A_NUMBER)
          break;
        m_p = z.end;
        ++values;
      }
      if(dimension == 0 && values <= 4)
        dimension = values;
      if(values != dimension)
        throw Input_error(ring_vertex(ring, vertex) + " has " + std::to_string(values) + " coordinates, expected " +
                          (dimension == 0 ? std::string("2, 3 or 4") : std::to_string(dimension)) + " (at " +
                          line_column(m_begin, m_p) + ")",
                          static_cast<int>(ring), static_cast<int>(vertex));
      if(!next_in_list())
        return;
    }
  }

  void read_coordinate(std::vector<double>& xy, std::size_t ring, std::size_t vertex)
  {
    skip_space();
    Scanned_number n = scan_number(m_p, m_end);
    if(n.status == Scanned_number::NOT_A_NUMBER)
      error(m_p, "expected a number");
    if(n.status == Scanned_number::NON_FINITE)
      throw Input_error("non-finite coordinate: " + ring_vertex(ring, vertex),
                        static_cast<int>(ring), static_cast<int>(vertex));
    xy.push_back(n.value);
    m_p = n.end;
  }

  const char* m_begin;
  const char* m_p;
  const char* m_end;
  bool m_multi = false;
  std::vector<Input_polygon<Point_2> > m_out;
  Skipped_geometries m_skipped;
};

// ------------------------------------------------------------------ GeoJSON

/// Reads GeoJSON with nlohmann-json (Debian's `nlohmann-json3-dev`): the document is
/// parsed into a tree that keeps the order of object members (`ordered_json`, so that
/// a feature's properties are written back as they were read), then walked.  Numbers
/// are converted by the parser as `strtod` converts them in the C locale.
template <class Point_2>
class Geojson_polygons_reader
{
public:
  typedef nlohmann::ordered_json Json;

  Geojson_polygons_reader(const char* begin, const char* end) : m_begin(begin), m_end(end) {}

  /// The polygons; with `skipped`, also what was skipped (see Skipped_geometries).
  std::vector<Input_polygon<Point_2> > read(Skipped_geometries* skipped = nullptr)
  {
    const char* p = after_byte_order_mark(m_begin, m_end);
    const char* q = p;
    while(q != m_end && is_space(*q))
      ++q;
    if(q == m_end)
      throw Input_error("empty input: no polygon found");
    Json doc;
    try {
      doc = Json::parse(p, m_end);
    } catch(const Json::parse_error& e) {
      // "[json.exception.parse_error.101] parse error at line 1, column 5: ..." -> "malformed JSON at line 1, column 5: ..."
      std::string what = e.what();
      const std::string at = "parse error at ";
      std::size_t k = what.find(at);
      throw Input_error("malformed JSON" + (k == std::string::npos ? ": " + what : " at " + what.substr(k + at.size())));
    } catch(const Json::exception& e) { // a number out of the range of double
      std::string what = e.what();
      std::size_t k = what.find("] ");
      throw Input_error("malformed JSON: " + (k == std::string::npos ? what : what.substr(k + 2)));
    }
    if(!doc.is_object())
      throw Input_error("malformed GeoJSON: expected a GeoJSON object");
    const std::string type = type_of(doc, "the document");
    if(type == "FeatureCollection") {
      m_multi = true;
      const Json& features = member(doc, "features", "the FeatureCollection");
      if(!features.is_array())
        throw Input_error("malformed GeoJSON: \"features\" is not an array");
      for(std::size_t f = 0; f < features.size(); ++f)
        feature(features[f], "feature " + std::to_string(f));
    } else if(type == "Feature") {
      feature(doc, "the Feature");
    } else {
      geometry(doc, std::string(), "the geometry");
    }
    if(m_out.empty())
      m_skipped.throw_no_polygon();
    if(skipped != nullptr)
      *skipped = m_skipped;
    return std::move(m_out);
  }

private:
  std::string type_of(const Json& j, const std::string& where) const
  {
    if(!j.is_object())
      throw Input_error("malformed GeoJSON: " + where + " is not an object");
    auto t = j.find("type");
    if(t == j.end())
      throw Input_error("malformed GeoJSON: " + where + " is an object without a \"type\"");
    if(!t->is_string())
      throw Input_error("malformed GeoJSON: the \"type\" of " + where + " is not a string");
    return t->template get<std::string>();
  }

  const Json& member(const Json& j, const char* name, const std::string& where) const
  {
    auto m = j.find(name);
    if(m == j.end())
      throw Input_error("malformed GeoJSON: " + where + " has no \"" + name + "\"");
    return *m;
  }

  void feature(const Json& f, const std::string& where)
  {
    const std::string type = type_of(f, where);
    if(type != "Feature")
      throw Input_error("not a polygon: " + where + " is a " + type + ", not a Feature");
    auto g = f.find("geometry");
    if(g == f.end() || g->is_null()) // a feature without location: no polygon
      return;
    std::string properties;
    auto pr = f.find("properties");
    if(pr != f.end() && pr->is_object())
      properties = pr->dump();
    geometry(*g, properties, where);
  }

  void geometry(const Json& g, const std::string& properties, const std::string& where)
  {
    const std::string type = type_of(g, where);
    if(type == "Polygon") {
      polygon(member(g, "coordinates", "the Polygon"), properties);
    } else if(type == "MultiPolygon") {
      m_multi = true;
      const Json& c = member(g, "coordinates", "the MultiPolygon");
      if(!c.is_array())
        throw Input_error("malformed GeoJSON: the coordinates of a MultiPolygon are not an array");
      for(const Json& p : c)
        polygon(p, properties);
    } else if(type == "GeometryCollection") {
      m_multi = true;
      const Json& gs = member(g, "geometries", "the GeometryCollection");
      if(!gs.is_array())
        throw Input_error("malformed GeoJSON: \"geometries\" is not an array");
      for(const Json& x : gs)
        geometry(x, properties, where);
    } else if(type == "Feature" || type == "FeatureCollection") {
      throw Input_error("malformed GeoJSON: a " + type + " inside " + where);
    } else if(is_point_or_line_type(type)) {
      m_skipped.add(type + (m_multi ? " in " + where : std::string()));
    } else {
      throw Input_error("not a polygon: found " + type + (m_multi ? " in " + where : std::string()));
    }
  }

  // An array of rings, each an array of positions.  An empty array is an empty
  // polygon, which is skipped.
  void polygon(const Json& c, const std::string& properties)
  {
    const std::size_t index = m_out.size();
    const std::string prefix = m_multi ? "polygon " + std::to_string(index) + ": " : std::string();
    if(!c.is_array())
      throw Input_error(prefix + "malformed GeoJSON: the coordinates of a Polygon are not an array");
    if(c.empty())
      return;
    Input_polygon<Point_2> out;
    out.properties = properties;
    std::vector<double> xy;
    for(std::size_t r = 0; r < c.size(); ++r) {
      const Json& ring = c[r];
      if(!ring.is_array())
        throw Input_error(prefix + "malformed GeoJSON: ring " + std::to_string(r) + " is not an array",
                          static_cast<int>(r));
      xy.clear();
      for(std::size_t i = 0; i < ring.size(); ++i) {
        const Json& pos = ring[i];
        if(!pos.is_array() || pos.size() < 2)
          throw Input_error(prefix + "malformed GeoJSON: " + ring_vertex(r, i) + " is not a position of 2 numbers",
                            static_cast<int>(r), static_cast<int>(i));
        // (a third value, the altitude of RFC 7946, or more: read as numbers
        // and ignored, as GEOS's two-dimensional operations ignore them)
        for(std::size_t k = 0; k < pos.size(); ++k) {
          if(!pos[k].is_number())
            throw Input_error(prefix + "malformed GeoJSON: " + ring_vertex(r, i) + ": expected a number",
                              static_cast<int>(r), static_cast<int>(i));
          if(k >= 2)
            continue;
          const double v = pos[k].template get<double>();
          if(!std::isfinite(v))
            throw Input_error(prefix + "non-finite coordinate: " + ring_vertex(r, i), static_cast<int>(r),
                              static_cast<int>(i));
          xy.push_back(v);
        }
      }
      out.rings.emplace_back();
      try {
        finish_ring(out.rings.back(), xy, r);
      } catch(const Input_error& e) {
        throw Input_error(prefix + e.what(), e.ring(), e.vertex());
      }
    }
    m_out.push_back(std::move(out));
  }

  const char* m_begin;
  const char* m_end;
  bool m_multi = false;
  std::vector<Input_polygon<Point_2> > m_out;
  Skipped_geometries m_skipped;
};

#ifdef PMA_TOOL_WITH_SIMDJSON
/// The GeoJSON reader's fast path, over simdjson's DOM parser (Debian's
/// `libsimdjson-dev`).  On the 168 MB of `countries-land-10m` it takes about a
/// quarter of the time of nlohmann-json's tree (RESULTS.md).
///
/// It reads valid GeoJSON and nothing else: on anything unusual (malformed JSON,
/// an integer beyond 64 bits, a member written twice, a GeoJSON or ring error)
/// `read()` returns false, and `Geojson_polygons_reader` reads the text again and
/// says what is wrong.  So the errors are those of the nlohmann-json reader, word
/// for word; and where this reader returns true, its result is the other's:
/// - the same members (nlohmann-json keeps the last of repeated names and this
///   reader would find the first, hence the check for repeated ones);
/// - the same numbers: both convert correctly rounded, and both read `-0` as the
///   integer 0 and `-0.0` as the double -0.0;
/// - the same properties: the feature's object converted to nlohmann-json's
///   tree as its own parser builds it, then written by it.
/// The test of the input layer and the readers' fuzzer compare the two readers.
template <class Point_2>
class Geojson_polygons_fast_reader
{
  struct Give_up {};
  typedef simdjson::dom::element Element;
  typedef simdjson::dom::object Object;
  typedef nlohmann::ordered_json Json;

public:
  Geojson_polygons_fast_reader(const char* begin, const char* end) : m_begin(begin), m_end(end) {}

  /// The polygons (and with `skipped`, what was skipped), as
  /// `Geojson_polygons_reader::read()` gives them; false if that reader has to read
  /// the text (an error, or input this one leaves to it).
  bool read(std::vector<Input_polygon<Point_2> >& out, Skipped_geometries* skipped = nullptr)
  {
    try {
      const char* p = after_byte_order_mark(m_begin, m_end);
      simdjson::dom::parser parser;
      Element doc;
      if(parser.parse(simdjson::padded_string(p, static_cast<std::size_t>(m_end - p))).get(doc) != simdjson::SUCCESS)
        return false;
      Object o = object(doc);
      const std::string_view type = member(o, "type").get_string();
      if(type == "FeatureCollection") {
        m_multi = true;
        m_where = IN_FEATURE;
        for(Element f : member(o, "features").get_array()) {
          feature(object(f));
          ++m_feature;
        }
      } else if(type == "Feature") {
        m_where = IN_THE_FEATURE;
        feature(o);
      } else {
        geometry(o, std::string());
      }
    } catch(const simdjson::simdjson_error&) {
      return false;
    } catch(const Give_up&) {
      return false;
    } catch(const Input_error&) {
      return false;
    }
    if(m_out.empty())
      return false;
    out = std::move(m_out);
    if(skipped != nullptr)
      *skipped = m_skipped;
    return true;
  }

private:
  // `e` as an object whose members read here are not repeated
  static Object object(Element e)
  {
    Object o = e.get_object();
    static const char* const names[] = { "type", "features", "geometry", "properties", "coordinates", "geometries" };
    int seen[6] = { 0, 0, 0, 0, 0, 0 };
    for(simdjson::dom::key_value_pair m : o)
      for(int i = 0; i < 6; ++i)
        if(m.key == names[i] && ++seen[i] > 1)
          throw Give_up();
    return o;
  }

  // the member `name` of `o` (simdjson throws if there is none)
  static Element member(Object o, const char* name) { return o.at_key(name); }

  // the member `name` of `o`, unless it is missing or null
  static bool optional_member(Object o, const char* name, Element& m)
  {
    return o.at_key(name).get(m) == simdjson::SUCCESS && !m.is_null();
  }

  // `e` as nlohmann-json's parser builds it (a repeated name keeps its first
  // place and its last value)
  static Json to_json(Element e)
  {
    switch(e.type()) {
    case simdjson::dom::element_type::OBJECT: {
      Json j = Json::object();
      for(simdjson::dom::key_value_pair m : Object(e))
        j[std::string(m.key)] = to_json(m.value);
      return j;
    }
    case simdjson::dom::element_type::ARRAY: {
      Json j = Json::array();
      for(Element x : simdjson::dom::array(e))
        j.push_back(to_json(x));
      return j;
    }
    case simdjson::dom::element_type::INT64: return Json(std::int64_t(e));
    case simdjson::dom::element_type::UINT64: return Json(std::uint64_t(e));
    case simdjson::dom::element_type::DOUBLE: return Json(double(e));
    case simdjson::dom::element_type::STRING: return Json(std::string(std::string_view(e)));
    case simdjson::dom::element_type::BOOL: return Json(bool(e));
    default: return Json();
    }
  }

  void feature(Object f)
  {
    if(std::string_view(member(f, "type").get_string()) != "Feature")
      throw Give_up();
    Element g, pr;
    if(!optional_member(f, "geometry", g)) // a feature without location: no polygon
      return;
    std::string properties;
    if(optional_member(f, "properties", pr) && pr.is_object())
      properties = to_json(pr).dump();
    geometry(object(g), properties);
  }

  void geometry(Object g, const std::string& properties)
  {
    const std::string_view type = member(g, "type").get_string();
    if(type == "Polygon") {
      polygon(member(g, "coordinates").get_array(), properties);
    } else if(type == "MultiPolygon") {
      m_multi = true;
      for(Element p : member(g, "coordinates").get_array())
        polygon(p.get_array(), properties);
    } else if(type == "GeometryCollection") {
      m_multi = true;
      for(Element x : member(g, "geometries").get_array())
        geometry(object(x), properties);
    } else if(is_point_or_line_type(std::string(type))) {
      // named as the other reader names it
      std::string what(type);
      if(m_multi)
        what += m_where == IN_FEATURE ? " in feature " + std::to_string(m_feature)
                                      : m_where == IN_THE_FEATURE ? " in the Feature" : " in the geometry";
      m_skipped.add(what);
    } else {
      throw Give_up();
    }
  }

  void polygon(simdjson::dom::array c, const std::string& properties)
  {
    if(c.size() == 0) // an empty polygon, skipped
      return;
    Input_polygon<Point_2> out;
    out.properties = properties;
    std::vector<double> xy;
    std::size_t r = 0;
    for(Element ring : c) {
      xy.clear();
      for(Element pos : ring.get_array()) {
        simdjson::dom::array a = pos.get_array();
        if(a.size() < 2)
          throw Give_up();
        std::size_t k = 0;
        for(Element x : a) {
          const double v = x.get_double(); // (also an integer, converted; throws if not a number)
          if(k++ < 2)
            xy.push_back(v);   // (an altitude and more: ignored, as by the other reader)
        }
      }
      out.rings.emplace_back();
      finish_ring(out.rings.back(), xy, r);
      ++r;
    }
    m_out.push_back(std::move(out));
  }

  const char* m_begin;
  const char* m_end;
  std::vector<Input_polygon<Point_2> > m_out;
  Skipped_geometries m_skipped;
  // where the geometry being read is, to name a skipped one
  bool m_multi = false;
  enum { IN_THE_GEOMETRY, IN_THE_FEATURE, IN_FEATURE } m_where = IN_THE_GEOMETRY;
  std::size_t m_feature = 0;
};
#endif

/// Reads GeoJSON: with the fast reader where it is built in and reads the text,
/// with `Geojson_polygons_reader` otherwise.
template <class Point_2>
std::vector<Input_polygon<Point_2> > read_geojson(const char* begin, const char* end,
                                                  Skipped_geometries* skipped = nullptr)
{
#ifdef PMA_TOOL_WITH_SIMDJSON
  std::vector<Input_polygon<Point_2> > out;
  if(Geojson_polygons_fast_reader<Point_2>(begin, end).read(out, skipped))
    return out;
#endif
  return Geojson_polygons_reader<Point_2>(begin, end).read(skipped);
}

inline bool has_extension(const std::string& path, const char* extension)
{
  std::size_t n = std::strlen(extension);
  if(path.size() < n)
    return false;
  for(std::size_t i = 0; i < n; ++i)
    if(to_upper(path[path.size() - n + i]) != to_upper(extension[i]))
      return false;
  return true;
}

} // namespace internal

namespace internal {

// The only polygon of `polygons`.
template <class Point_2>
Rings<Point_2> only_polygon(std::vector<Input_polygon<Point_2> >&& polygons)
{
  if(polygons.size() != 1)
    throw Input_error("not a polygon: found " + std::to_string(polygons.size()) + " polygons");
  return std::move(polygons.front().rings);
}

inline std::string read_file(const std::string& path)
{
  std::error_code ec;
  if(std::filesystem::is_directory(path, ec))
    throw Input_error("cannot read file '" + path + "': " + std::strerror(EISDIR));
  errno = 0;
  std::ifstream in(path, std::ios::in | std::ios::binary);
  if(!in) {
    int error = errno;
    throw Input_error("cannot read file '" + path + "': " + (error != 0 ? std::strerror(error) : "cannot open"));
  }
  std::string text;
  in.seekg(0, std::ios::end);
  std::streamoff size = in.tellg();
  if(size >= 0) {
    in.seekg(0, std::ios::beg);
    text.resize(static_cast<std::size_t>(size));
    if(size > 0)
      in.read(&text[0], size);
    if(in.bad() || in.gcount() != size)
      throw Input_error("cannot read file '" + path + "': read error");
  } else {
    in.clear();
    in.seekg(0, std::ios::beg);
    std::ostringstream buffer;
    buffer << in.rdbuf();
    if(in.bad())
      throw Input_error("cannot read file '" + path + "': read error");
    text = buffer.str();
  }
  return text;
}

} // namespace internal

/*!

Reads polygons with holes written as WKT: a `POLYGON ((x y, x y, ...), (...), ...)`, the
first ring being the outer ring and the others the holes, a `MULTIPOLYGON` or a
`GEOMETRYCOLLECTION` of them (collections may nest). Keywords are case-insensitive,
white space (including newlines) is arbitrary, and numbers are read as `strtod` reads
them in the C locale (whatever the current locale). Empty polygons are skipped; the
others are returned in input order (parts of a `MULTIPOLYGON` in order). Points and
lines (`POINT`, `MULTIPOINT`, `LINESTRING`, `MULTILINESTRING`, anywhere in the input)
are skipped too, and counted in `*skipped` if it is given (see `Skipped_geometries`);
if nothing but points and lines is found, the first one is named in the error.

The rings are checked to be closed (first point equal to the last one), to have at
least 4 points as written and finite coordinates; the closing point is dropped. Vertex
order is kept exactly as written. The geometric validity is *not* checked: call
`validate_polygon_rings()` for that. Errors in a polygon of a `MULTIPOLYGON` or a
collection start with `polygon <k>: `.

Z, M and ZM coordinates (tagged, as in `POLYGON Z`, or not) are read and their third
and fourth values ignored: the polygon is its projection to the plane, as in GEOS's
two-dimensional operations. PostGIS's extended WKT is read too: a leading
`SRID=<integer>;` is dropped.

\throws Input_error for malformed WKT (with line and column), input without a polygon,
points of one polygon with different numbers of values, other geometry types (curves,
surfaces), trailing text, non-finite x or y, unclosed rings and rings with fewer than 4
points.

\tparam Point_2 a point type constructible from two `double`s.
*/
template <class Point_2>
std::vector<Input_polygon<Point_2> > read_wkt_polygons(std::istream& in, Skipped_geometries* skipped = nullptr)
{
  std::string text = internal::read_all(in);
  return internal::Wkt_polygon_reader<Point_2>(text.data(), text.data() + text.size()).read(skipped);
}

/// Reads one polygon as `read_wkt_polygons()` does (a `MULTIPOLYGON` or a collection
/// holding exactly one polygon is accepted), and throws `Input_error` for more.
template <class Point_2>
Rings<Point_2> read_wkt_polygon(std::istream& in)
{
  return internal::only_polygon(read_wkt_polygons<Point_2>(in));
}

/*!

Reads polygons with holes written as GeoJSON (RFC 7946): a `Polygon`, `MultiPolygon` or
`GeometryCollection` geometry, a `Feature` or a `FeatureCollection` of them. Features
without geometry (`null`), empty polygons, points and lines are skipped (the latter
counted in `*skipped`, as by `read_wkt_polygons()`). Each polygon carries the
`properties` of its feature. Parsing is done by nlohmann-json; numbers are converted as
`strtod` converts them. Checks and result are as for `read_wkt_polygons()`. A position
may hold an altitude (and more numbers), which is ignored.

\throws Input_error for malformed JSON (with line and column), unknown types, a
`Feature` or `FeatureCollection` inside a geometry,
input without a polygon, positions of fewer than 2 numbers, numbers out of the range of
`double`, unclosed rings and rings with fewer than 4 points.

\tparam Point_2 a point type constructible from two `double`s.
*/
template <class Point_2>
std::vector<Input_polygon<Point_2> > read_geojson_polygons(std::istream& in, Skipped_geometries* skipped = nullptr)
{
  std::string text = internal::read_all(in);
  return internal::read_geojson<Point_2>(text.data(), text.data() + text.size(), skipped);
}

/// Reads one polygon as `read_geojson_polygons()` does, and throws `Input_error` for more.
template <class Point_2>
Rings<Point_2> read_geojson_polygon(std::istream& in)
{
  return internal::only_polygon(read_geojson_polygons<Point_2>(in));
}

/*!

Reads polygons with holes from the file `path`, as GeoJSON if its name ends with
`.geojson` or `.json` and as WKT if it ends with `.wkt` (case-insensitive). For any
other name, the format is guessed from the contents: GeoJSON if the first non-blank
character is `{`, WKT otherwise.

\throws Input_error `"cannot read file '<path>': <reason>"` if the file cannot be read,
and the errors of `read_wkt_polygons()` and `read_geojson_polygons()`.
*/
template <class Point_2>
std::vector<Input_polygon<Point_2> > read_polygons_file(const std::string& path, Skipped_geometries* skipped = nullptr)
{
  const std::string text = internal::read_file(path);
  const char* b = text.data();
  const char* e = b + text.size();
  bool geojson;
  if(internal::has_extension(path, ".geojson") || internal::has_extension(path, ".json")) {
    geojson = true;
  } else if(internal::has_extension(path, ".wkt")) {
    geojson = false;
  } else {
    const char* p = internal::after_byte_order_mark(b, e);
    while(p != e && internal::is_space(*p))
      ++p;
    geojson = (p != e && *p == '{');
  }
  if(geojson)
    return internal::read_geojson<Point_2>(b, e, skipped);
  return internal::Wkt_polygon_reader<Point_2>(b, e).read(skipped);
}

/// Reads one polygon as `read_polygons_file()` does, and throws `Input_error` for more.
template <class Point_2>
Rings<Point_2> read_polygon_file(const std::string& path)
{
  return internal::only_polygon(read_polygons_file<Point_2>(path));
}

/*!

Writes `rings` as WKT, `POLYGON ((x y, ..., x0 y0), (...))`, each ring closed by
repeating its first point and each coordinate written as by `printf("%.17g")` in the C
locale (whatever the current locale), so that reading the text back gives the same
`double`s. No newline is written after the polygon. An empty `rings` is written
`POLYGON EMPTY`.

\pre Every ring is non-empty.
*/
template <class Point_2>
void write_wkt_polygon(std::ostream& out, const Rings<Point_2>& rings)
{
  if(rings.empty()) {
    out << "POLYGON EMPTY";
    return;
  }
  std::string text = "POLYGON (";
  char buf[64];
  auto append = [&](const Point_2& p) {
    double c[2] = { CGAL::to_double(p.x()), CGAL::to_double(p.y()) };
    for(int i = 0; i < 2; ++i) {
      if(i == 1)
        text.push_back(' ');
#if defined(__cpp_lib_to_chars) && __cpp_lib_to_chars >= 201611L
      std::to_chars_result r = std::to_chars(buf, buf + sizeof(buf), c[i], std::chars_format::general, 17);
      text.append(buf, r.ptr);
#else
      std::snprintf(buf, sizeof(buf), "%.17g", c[i]);
      text.append(buf);
#endif
    }
  };
  for(std::size_t r = 0; r < rings.size(); ++r) {
    CGAL_precondition(!rings[r].empty());
    text += (r == 0) ? "(" : ", (";
    for(const Point_2& p : rings[r]) {
      append(p);
      text += ", ";
    }
    append(rings[r].front());
    text += ")";
  }
  text += ")";
  out.write(text.data(), static_cast<std::streamsize>(text.size()));
}

/// Writes `polygons` as one WKT `POLYGON` if there is one, as a `MULTIPOLYGON`
/// otherwise, coordinates as by `write_wkt_polygon()`.
template <class Point_2>
void write_wkt_polygons(std::ostream& out, const std::vector<Rings<Point_2> >& polygons)
{
  if(polygons.size() == 1) {
    write_wkt_polygon(out, polygons[0]);
    return;
  }
  out << "MULTIPOLYGON (";
  for(std::size_t k = 0; k < polygons.size(); ++k) {
    std::ostringstream one;
    write_wkt_polygon(one, polygons[k]);
    out << (k ? ", " : "") << one.str().substr(8);   // without "POLYGON "
  }
  out << ")";
}

} // namespace pma_tool

#endif // PMA_TOOL_POLYGON_IO_H
