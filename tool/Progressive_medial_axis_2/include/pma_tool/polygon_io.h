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

namespace internal {

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
/// non-finite result, as do numbers too large for a double. With `json`, the JSON
/// grammar is used instead (no leading '+', no leading zeros, digits on both sides of
/// the point) and the non-finite words are `NaN`, `Infinity` and `-Infinity`.
inline Scanned_number scan_number(const char* p, const char* e, bool json)
{
  Scanned_number result;
  const char* start = p;
  if(p != e && (*p == '-' || (*p == '+' && !json)))
    ++p;
  // Non-finite words.
  if(p != e && is_alpha(*p)) {
    const char* w = p;
    while(w != e && is_alpha(*w))
      ++w;
    if(json ? (std::string(p, w) == "Infinity" || (p == start && std::string(p, w) == "NaN"))
            : (equals_word(p, w, "NAN") || equals_word(p, w, "INF") ||
               equals_word(p, w, "INFINITY"))) {
      result.status = Scanned_number::NON_FINITE;
      result.end = w;
    }
    return result;
  }
  const char* digits = p;
  while(p != e && is_digit(*p))
    ++p;
  std::size_t integer_digits = static_cast<std::size_t>(p - digits);
  if(json && (integer_digits == 0 || (integer_digits > 1 && *digits == '0')))
    return result;
  std::size_t fraction_digits = 0;
  if(p != e && *p == '.') {
    const char* f = ++p;
    while(p != e && is_digit(*p))
      ++p;
    fraction_digits = static_cast<std::size_t>(p - f);
    if(json && fraction_digits == 0)
      return result;
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
    else if(json)
      return result;
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

/// A recursive-descent WKT reader over a buffer, accepting
/// `POLYGON ((x y, ...), ...)` and a `MULTIPOLYGON` holding exactly one polygon.
template <class Point_2>
class Wkt_polygon_reader
{
public:
  Wkt_polygon_reader(const char* begin, const char* end) : m_begin(begin), m_p(begin), m_end(end) {}

  Rings<Point_2> read()
  {
    if(m_end - m_p >= 3 && std::memcmp(m_p, "\xEF\xBB\xBF", 3) == 0) // UTF-8 byte order mark
      m_p += 3;
    skip_space();
    if(m_p == m_end)
      throw Input_error("empty input: no polygon found");
    const char* kw_begin = m_p;
    std::string keyword = read_word();
    if(keyword.empty())
      error(kw_begin, "expected 'POLYGON'");
    bool multi = false;
    if(keyword == "MULTIPOLYGON")
      multi = true;
    else if(keyword == "POLYGONZ" || keyword == "POLYGONM" || keyword == "POLYGONZM" ||
            keyword == "MULTIPOLYGONZ" || keyword == "MULTIPOLYGONM" || keyword == "MULTIPOLYGONZM")
      throw Input_error("only 2D coordinates are supported");
    else if(keyword != "POLYGON")
      throw Input_error("not a polygon: found " + keyword);

    skip_space();
    if(m_p != m_end && is_alpha(*m_p)) {
      const char* w = m_p;
      std::string tag = read_word();
      if(tag == "Z" || tag == "M" || tag == "ZM")
        throw Input_error("only 2D coordinates are supported");
      if(tag == "EMPTY") {
        expect_end();
        throw Input_error("empty polygon");
      }
      error(w, "expected '(' or 'EMPTY'");
    }

    Rings<Point_2> rings;
    if(multi) {
      expect('(', "expected '(' or 'EMPTY'");
      skip_space();
      if(m_p != m_end && is_alpha(*m_p)) { // MULTIPOLYGON (EMPTY)
        const char* w = m_p;
        if(read_word() == "EMPTY")
          throw Input_error("empty polygon");
        error(w, "expected '('");
      }
      read_polygon_text(rings);
      skip_space();
      if(m_p != m_end && *m_p == ',')
        throw Input_error("not a polygon: found MULTIPOLYGON with more than one polygon");
      expect(')', "expected ',' or ')'");
    } else {
      read_polygon_text(rings);
    }
    expect_end();
    return rings;
  }

private:
  [[noreturn]] void error(const char* at, const std::string& what) const
  {
    throw Input_error("malformed WKT at " + line_column(m_begin, at) + ": " + what);
  }

  void skip_space()
  {
    while(m_p != m_end && is_space(*m_p))
      ++m_p;
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

  void expect_end()
  {
    skip_space();
    if(m_p != m_end)
      error(m_p, "unexpected text after the polygon");
  }

  // '(' ring (',' ring)* ')'
  void read_polygon_text(Rings<Point_2>& rings)
  {
    expect('(', "expected '('");
    std::vector<double> xy;
    for(;;) {
      read_ring_text(xy, rings.size());
      rings.emplace_back();
      finish_ring(rings.back(), xy, rings.size() - 1);
      skip_space();
      if(m_p != m_end && *m_p == ',') {
        ++m_p;
        continue;
      }
      expect(')', "expected ',' or ')'");
      return;
    }
  }

  // '(' x y (',' x y)* ')'
  void read_ring_text(std::vector<double>& xy, std::size_t ring)
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
      const char* after = m_p;
      skip_space();
      if(m_p != after && scan_number(m_p, m_end, false).status != Scanned_number::NOT_A_NUMBER)
        throw Input_error("only 2D coordinates are supported (" + ring_vertex(ring, vertex) +
                          " has a third coordinate, at " + line_column(m_begin, m_p) + ")",
                          static_cast<int>(ring), static_cast<int>(vertex));
      if(m_p != m_end && *m_p == ',') {
        ++m_p;
        continue;
      }
      expect(')', "expected ',' or ')'");
      return;
    }
  }

  void read_coordinate(std::vector<double>& xy, std::size_t ring, std::size_t vertex)
  {
    skip_space();
    Scanned_number n = scan_number(m_p, m_end, false);
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
};

// ------------------------------------------------------------------ GeoJSON

/// A small JSON scanner for GeoJSON. The whole document is first checked against the
/// JSON grammar (`skip_value`, without building a tree); the GeoJSON structure is then
/// navigated by scanning the members of the objects of interest, and the coordinates
/// are converted directly from the text.
template <class Point_2>
class Geojson_polygon_reader
{
  struct Member
  {
    std::string key;
    const char* value;
  };

public:
  Geojson_polygon_reader(const char* begin, const char* end) : m_begin(begin), m_end(end) {}

  Rings<Point_2> read()
  {
    const char* p = m_begin;
    if(m_end - p >= 3 && std::memcmp(p, "\xEF\xBB\xBF", 3) == 0)
      p += 3;
    p = skip_space(p);
    if(p == m_end)
      throw Input_error("empty input: no polygon found");
    const char* root = p;
    p = skip_space(skip_value(p, 0));
    if(p != m_end)
      json_error(p, "unexpected text after the JSON value");
    Rings<Point_2> rings;
    read_object(root, rings, 0);
    return rings;
  }

private:
  // ---------------------------------------------------------------- JSON syntax

  [[noreturn]] void json_error(const char* at, const std::string& what) const
  {
    throw Input_error("malformed JSON at " + line_column(m_begin, at) + ": " + what);
  }

  [[noreturn]] void geojson_error(const char* at, const std::string& what) const
  {
    throw Input_error("malformed GeoJSON at " + line_column(m_begin, at) + ": " + what);
  }

  const char* skip_space(const char* p) const
  {
    while(p != m_end && (*p == ' ' || *p == '\t' || *p == '\n' || *p == '\r'))
      ++p;
    return p;
  }

  static int hex_value(char c)
  {
    if(c >= '0' && c <= '9') return c - '0';
    if(c >= 'a' && c <= 'f') return c - 'a' + 10;
    if(c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
  }

  static void append_utf8(std::string& s, unsigned long cp)
  {
    if(cp < 0x80) {
      s.push_back(static_cast<char>(cp));
    } else if(cp < 0x800) {
      s.push_back(static_cast<char>(0xC0 | (cp >> 6)));
      s.push_back(static_cast<char>(0x80 | (cp & 0x3F)));
    } else if(cp < 0x10000) {
      s.push_back(static_cast<char>(0xE0 | (cp >> 12)));
      s.push_back(static_cast<char>(0x80 | ((cp >> 6) & 0x3F)));
      s.push_back(static_cast<char>(0x80 | (cp & 0x3F)));
    } else {
      s.push_back(static_cast<char>(0xF0 | (cp >> 18)));
      s.push_back(static_cast<char>(0x80 | ((cp >> 12) & 0x3F)));
      s.push_back(static_cast<char>(0x80 | ((cp >> 6) & 0x3F)));
      s.push_back(static_cast<char>(0x80 | (cp & 0x3F)));
    }
  }

  unsigned long read_hex4(const char* p) const
  {
    if(m_end - p < 4)
      json_error(p, "invalid \\u escape");
    unsigned long v = 0;
    for(int i = 0; i < 4; ++i) {
      int h = hex_value(p[i]);
      if(h < 0)
        json_error(p + i, "invalid \\u escape");
      v = v * 16 + static_cast<unsigned long>(h);
    }
    return v;
  }

  // Scans the string starting at the quote `p`; returns one past the closing quote and
  // appends its decoded contents to `out` if not null.
  const char* scan_string(const char* p, std::string* out) const
  {
    CGAL_precondition(p != m_end && *p == '"');
    ++p;
    for(;;) {
      if(p == m_end)
        json_error(p, "unterminated string");
      char c = *p;
      if(c == '"')
        return p + 1;
      if(static_cast<unsigned char>(c) < 0x20)
        json_error(p, "control character in string");
      if(c != '\\') {
        if(out) out->push_back(c);
        ++p;
        continue;
      }
      ++p;
      if(p == m_end)
        json_error(p, "unterminated string");
      switch(*p) {
      case '"': case '\\': case '/':
        if(out) out->push_back(*p);
        ++p;
        break;
      case 'b': if(out) out->push_back('\b'); ++p; break;
      case 'f': if(out) out->push_back('\f'); ++p; break;
      case 'n': if(out) out->push_back('\n'); ++p; break;
      case 'r': if(out) out->push_back('\r'); ++p; break;
      case 't': if(out) out->push_back('\t'); ++p; break;
      case 'u': {
        unsigned long cp = read_hex4(p + 1);
        p += 5;
        if(cp >= 0xD800 && cp < 0xDC00 && m_end - p >= 6 && p[0] == '\\' && p[1] == 'u') {
          unsigned long low = read_hex4(p + 2);
          if(low >= 0xDC00 && low < 0xE000) {
            cp = 0x10000 + ((cp - 0xD800) << 10) + (low - 0xDC00);
            p += 6;
          }
        }
        if(out) append_utf8(*out, cp);
        break;
      }
      default:
        json_error(p, "invalid escape in string");
      }
    }
  }

  const char* skip_literal(const char* p, const char* word) const
  {
    std::size_t n = std::strlen(word);
    if(static_cast<std::size_t>(m_end - p) < n || std::memcmp(p, word, n) != 0)
      json_error(p, "expected a JSON value");
    return p + n;
  }

  // Checks the JSON value at `p` and returns one past its end.
  const char* skip_value(const char* p, int depth) const
  {
    if(depth > 512)
      json_error(p, "nesting too deep");
    p = skip_space(p);
    if(p == m_end)
      json_error(p, "expected a JSON value");
    switch(*p) {
    case '{': {
      p = skip_space(p + 1);
      if(p != m_end && *p == '}')
        return p + 1;
      for(;;) {
        if(p == m_end || *p != '"')
          json_error(p, "expected a member name");
        p = skip_space(scan_string(p, nullptr));
        if(p == m_end || *p != ':')
          json_error(p, "expected ':'");
        p = skip_space(skip_value(p + 1, depth + 1));
        if(p != m_end && *p == ',') {
          p = skip_space(p + 1);
          continue;
        }
        if(p != m_end && *p == '}')
          return p + 1;
        json_error(p, "expected ',' or '}'");
      }
    }
    case '[': {
      p = skip_space(p + 1);
      if(p != m_end && *p == ']')
        return p + 1;
      for(;;) {
        p = skip_space(skip_value(p, depth + 1));
        if(p != m_end && *p == ',') {
          ++p;
          continue;
        }
        if(p != m_end && *p == ']')
          return p + 1;
        json_error(p, "expected ',' or ']'");
      }
    }
    case '"':
      return scan_string(p, nullptr);
    case 't': return skip_literal(p, "true");
    case 'f': return skip_literal(p, "false");
    case 'n': return skip_literal(p, "null");
    default: {
      // Numbers, and the non-standard NaN / Infinity (rejected later as non-finite).
      Scanned_number n = scan_number(p, m_end, true);
      if(n.status == Scanned_number::NOT_A_NUMBER)
        json_error(p, "expected a JSON value");
      return n.end;
    }
    }
  }

  // ---------------------------------------------------------------- GeoJSON structure

  // The members of the (already checked) object at `p`.
  std::vector<Member> members(const char* p) const
  {
    std::vector<Member> result;
    p = skip_space(p + 1);
    if(*p == '}')
      return result;
    for(;;) {
      Member m;
      p = skip_space(scan_string(p, &m.key));
      m.value = skip_space(p + 1);
      result.push_back(m);
      p = skip_space(skip_value(m.value, 1));
      if(*p == '}')
        return result;
      p = skip_space(p + 1);
    }
  }

  static const char* find(const std::vector<Member>& ms, const char* key)
  {
    for(const Member& m : ms)
      if(m.key == key)
        return m.value;
    return nullptr;
  }

  std::string type_of(const char* object, const std::vector<Member>& ms) const
  {
    const char* t = find(ms, "type");
    if(t == nullptr)
      geojson_error(object, "object without a \"type\" member");
    if(*t != '"')
      geojson_error(t, "\"type\" is not a string");
    std::string type;
    scan_string(t, &type);
    return type;
  }

  // The number of elements of the (already checked) array at `p`.
  std::size_t array_size(const char* p) const
  {
    p = skip_space(p + 1);
    if(*p == ']')
      return 0;
    std::size_t n = 0;
    for(;;) {
      ++n;
      p = skip_space(skip_value(p, 1));
      if(*p == ']')
        return n;
      ++p;
    }
  }

  const char* expect_array(const char* p, const char* what) const
  {
    if(*p != '[')
      geojson_error(p, std::string("expected an array for ") + what);
    return p;
  }

  void read_object(const char* p, Rings<Point_2>& rings, int level)
  {
    if(*p != '{')
      geojson_error(p, "expected a GeoJSON object");
    std::vector<Member> ms = members(p);
    std::string type = type_of(p, ms);
    if(type == "Polygon") {
      const char* c = find(ms, "coordinates");
      if(c == nullptr)
        geojson_error(p, "Polygon without \"coordinates\"");
      read_polygon_coordinates(expect_array(c, "\"coordinates\""), rings);
    } else if(type == "MultiPolygon") {
      const char* c = find(ms, "coordinates");
      if(c == nullptr)
        geojson_error(p, "MultiPolygon without \"coordinates\"");
      std::size_t n = array_size(expect_array(c, "\"coordinates\""));
      if(n == 0)
        throw Input_error("empty polygon");
      if(n > 1)
        throw Input_error("not a polygon: found MultiPolygon with more than one polygon");
      const char* first = skip_space(c + 1);
      read_polygon_coordinates(expect_array(first, "a polygon"), rings);
    } else if(type == "Feature" && level < 2) {
      const char* g = find(ms, "geometry");
      if(g == nullptr || *g == 'n')
        throw Input_error("not a polygon: found a Feature without geometry");
      read_geometry(g, rings);
    } else if(type == "FeatureCollection" && level == 0) {
      const char* f = find(ms, "features");
      if(f == nullptr)
        geojson_error(p, "FeatureCollection without \"features\"");
      std::size_t n = array_size(expect_array(f, "\"features\""));
      if(n != 1)
        throw Input_error("not a polygon: found FeatureCollection with " + std::to_string(n) +
                          " features (exactly one Polygon feature is supported)");
      const char* feature = skip_space(f + 1);
      if(*feature != '{')
        geojson_error(feature, "expected a Feature object");
      std::vector<Member> fms = members(feature);
      if(type_of(feature, fms) != "Feature")
        geojson_error(feature, "expected a Feature object");
      read_object(feature, rings, 1);
    } else {
      throw Input_error("not a polygon: found " + type);
    }
  }

  void read_geometry(const char* g, Rings<Point_2>& rings)
  {
    if(*g != '{')
      geojson_error(g, "expected a geometry object");
    std::vector<Member> ms = members(g);
    std::string type = type_of(g, ms);
    if(type == "Feature" || type == "FeatureCollection")
      geojson_error(g, "expected a geometry object, found " + type);
    read_object(g, rings, 2);
  }

  // [ ring, ... ] with ring = [ [x, y], ... ]
  void read_polygon_coordinates(const char* p, Rings<Point_2>& rings)
  {
    p = skip_space(p + 1);
    if(*p == ']')
      throw Input_error("empty polygon");
    std::vector<double> xy;
    for(;;) {
      std::size_t ring = rings.size();
      p = read_ring_coordinates(expect_array(p, "a ring"), xy, ring);
      rings.emplace_back();
      finish_ring(rings.back(), xy, ring);
      p = skip_space(p);
      if(*p == ']')
        return;
      p = skip_space(p + 1);
    }
  }

  // Returns one past the ring's closing bracket.
  const char* read_ring_coordinates(const char* p, std::vector<double>& xy, std::size_t ring)
  {
    xy.clear();
    p = skip_space(p + 1);
    if(*p == ']')
      return p + 1;
    for(;;) {
      std::size_t vertex = xy.size() / 2;
      if(*p != '[')
        geojson_error(p, "expected a position [x, y]");
      const char* position = p;
      p = skip_space(p + 1);
      std::size_t count = 0;
      while(*p != ']') {
        Scanned_number n = scan_number(p, m_end, true);
        if(n.status == Scanned_number::NOT_A_NUMBER)
          geojson_error(p, "expected a number");
        if(n.status == Scanned_number::NON_FINITE)
          throw Input_error("non-finite coordinate: " + ring_vertex(ring, vertex),
                            static_cast<int>(ring), static_cast<int>(vertex));
        if(count == 2)
          throw Input_error("only 2D coordinates are supported (" + ring_vertex(ring, vertex) +
                            " has a third coordinate, at " + line_column(m_begin, p) + ")",
                            static_cast<int>(ring), static_cast<int>(vertex));
        xy.push_back(n.value);
        ++count;
        p = skip_space(n.end);
        if(*p == ',')
          p = skip_space(p + 1);
      }
      if(count < 2)
        geojson_error(position, "a position needs 2 coordinates");
      p = skip_space(p + 1);
      if(*p == ']')
        return p + 1;
      p = skip_space(p + 1); // ','
    }
  }

  const char* m_begin;
  const char* m_end;
};

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

/*!

Reads a polygon with holes written as WKT: `POLYGON ((x y, x y, ...), (...), ...)`, the
first ring being the outer ring and the others the holes. The keyword is
case-insensitive, white space (including newlines) is arbitrary, and numbers are read as
`strtod` reads them in the C locale (whatever the current locale). A `MULTIPOLYGON`
holding exactly one polygon is accepted.

The rings are checked to be closed (first point equal to the last one), to have at
least 4 points as written and finite coordinates; the closing point is dropped. Vertex
order is kept exactly as written. The geometric validity is *not* checked: call
`validate_polygon_rings()` for that.

\throws Input_error for malformed WKT (with line and column), `POLYGON EMPTY`, Z/M/ZM
coordinates, other geometry types, a `MULTIPOLYGON` with more than one polygon,
trailing text, non-finite numbers, unclosed rings and rings with fewer than 4 points.

\tparam Point_2 a point type constructible from two `double`s.
*/
template <class Point_2>
Rings<Point_2> read_wkt_polygon(std::istream& in)
{
  std::string text = internal::read_all(in);
  return internal::Wkt_polygon_reader<Point_2>(text.data(), text.data() + text.size()).read();
}

/*!

Reads a polygon with holes written as GeoJSON: a `Polygon` geometry object, a `Feature`
whose geometry is a `Polygon`, or a `FeatureCollection` holding exactly one such
`Feature`; a `MultiPolygon` holding exactly one polygon is accepted in place of a
`Polygon`. Numbers are converted exactly as `strtod` converts them in the C locale.
Checks and result are as for `read_wkt_polygon()`.

\throws Input_error for malformed JSON (with line and column), other GeoJSON types,
collections of several features, coordinates with more than 2 dimensions, non-finite
numbers, unclosed rings and rings with fewer than 4 points.

\tparam Point_2 a point type constructible from two `double`s.
*/
template <class Point_2>
Rings<Point_2> read_geojson_polygon(std::istream& in)
{
  std::string text = internal::read_all(in);
  return internal::Geojson_polygon_reader<Point_2>(text.data(), text.data() + text.size()).read();
}

/*!

Reads a polygon with holes from the file `path`, as GeoJSON if its name ends with
`.geojson` or `.json` and as WKT if it ends with `.wkt` (case-insensitive). For any
other name, the format is guessed from the contents: GeoJSON if the first non-blank
character is `{`, WKT otherwise.

\throws Input_error `"cannot read file '<path>': <reason>"` if the file cannot be read,
and the errors of `read_wkt_polygon()` and `read_geojson_polygon()`.
*/
template <class Point_2>
Rings<Point_2> read_polygon_file(const std::string& path)
{
  std::error_code ec;
  if(std::filesystem::is_directory(path, ec))
    throw Input_error("cannot read file '" + path + "': " + std::strerror(EISDIR));
  errno = 0;
  std::ifstream in(path, std::ios::in | std::ios::binary);
  if(!in) {
    int error = errno;
    throw Input_error("cannot read file '" + path + "': " +
                      (error != 0 ? std::strerror(error) : "cannot open"));
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

  const char* b = text.data();
  const char* e = b + text.size();
  bool geojson;
  if(internal::has_extension(path, ".geojson") || internal::has_extension(path, ".json")) {
    geojson = true;
  } else if(internal::has_extension(path, ".wkt")) {
    geojson = false;
  } else {
    const char* p = b;
    if(e - p >= 3 && std::memcmp(p, "\xEF\xBB\xBF", 3) == 0)
      p += 3;
    while(p != e && internal::is_space(*p))
      ++p;
    geojson = (p != e && *p == '{');
  }
  if(geojson)
    return internal::Geojson_polygon_reader<Point_2>(b, e).read();
  return internal::Wkt_polygon_reader<Point_2>(b, e).read();
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

} // namespace pma_tool

#endif // PMA_TOOL_POLYGON_IO_H
