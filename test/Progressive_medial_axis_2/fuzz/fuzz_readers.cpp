// libFuzzer harness for the tool's readers: WKT and GeoJSON text, of one or
// several polygons, then the geometric check of each polygon read.  Any
// exception other than Input_error, any crash, leak or undefined behaviour
// (the harness is built with AddressSanitizer and UBSan) is a failure, and so
// is a text that the two GeoJSON readers (simdjson's and nlohmann-json's, where
// simdjson is built in) read differently.
//
// Mutated bytes are rarely valid GeoJSON, and the fast reader reads only valid
// GeoJSON (it leaves the rest to the other reader): of 1,520 inputs a 120 s
// run kept, it read 24.  So every input is also read as the choices of a
// GeoJSON text, written here (Geojson_writer): collections, features and
// geometries with their members in any order, properties with nested values,
// escaped and non-ASCII strings and repeated names, numbers at the edges of
// what the readers convert, any white space, and at times a byte-order
// mark.  Both readers must read it the same, and the fast one must read it
// unless it holds what that reader leaves to the other (a number beyond 64
// bits or beyond the doubles).
//
//   fuzz_readers [libFuzzer options] [CORPUS_DIR ...]

#include <pma_tool/polygon_io.h>
#include <pma_test/geojson_readers.h>
#include <CGAL/Progressive_medial_axis_2/validate_polygon.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

namespace {

// A valid GeoJSON text from the fuzzer's bytes, read as choices (0, the
// plainest, once they run out).  Written by hand: the point is to choose the spelling
// (order of members, white space, number formats, escapes), which a JSON
// library writing a tree would fix.
class Geojson_writer
{
public:
  Geojson_writer(const std::uint8_t* data, std::size_t size) : m_p(data), m_end(data + size) {}

  std::string text()
  {
    if(choice(16) == 15) m_out = "\xef\xbb\xbf";   // a UTF-8 byte-order mark, which both readers skip
    m_out += space();
    switch(choice(5)) {
    case 0: {
      std::vector<std::string> members = { "\"type\"" + colon() + "\"FeatureCollection\"" };
      std::string features = "[";
      const int n = 1 + choice(3);
      for(int i = 0; i < n; ++i) features += (i ? comma() : space()) + feature();
      members.push_back("\"features\"" + colon() + features + space() + "]");
      extras(members);
      m_out += object(members);
      break;
    }
    case 1: m_out += feature(); break;
    default: m_out += geometry(0); break;
    }
    m_out += space();
    return m_out;
  }

  /// false where the text holds what the fast reader leaves to the other one
  bool fast_reads() const { return !m_leave && m_polygons > 0; }

private:
  int choice(int n)
  {
    if(m_p == m_end) return 0;
    return int(*m_p++ % unsigned(n));
  }
  std::uint64_t bits()
  {
    std::uint64_t b = 0;
    for(int i = 0; i < 8; ++i) b = (b << 8) | std::uint64_t(choice(256));
    return b;
  }
  std::string space()
  {
    static const char* const spaces[] = { "", "", "", " ", "\n", "\t", "\r\n", "  " };
    return spaces[choice(8)];
  }
  std::string colon() { return space() + ":" + space(); }
  std::string comma() { return space() + "," + space(); }
  // the members in an order chosen from the bytes
  std::string object(std::vector<std::string> members)
  {
    std::string o = "{" + space();
    for(std::size_t i = 0; i < members.size(); ++i) {
      std::swap(members[i], members[i + std::size_t(choice(int(members.size() - i)))]);
      o += (i ? comma() : std::string()) + members[i];
    }
    return o + space() + "}";
  }
  // members the readers skip
  void extras(std::vector<std::string>& members)
  {
    if(choice(4) == 3) members.push_back("\"bbox\"" + colon() + "[" + number() + comma() + number() + "]");
    if(choice(4) == 3) members.push_back("\"id\"" + colon() + value(1));
  }
  std::string feature()
  {
    std::vector<std::string> members = { "\"type\"" + colon() + "\"Feature\"" };
    switch(choice(4)) {
    case 0: break;   // no properties
    case 1: members.push_back("\"properties\"" + colon() + "null"); break;
    default: members.push_back("\"properties\"" + colon() + properties(0)); break;
    }
    members.push_back("\"geometry\"" + colon() + (choice(8) == 7 ? std::string("null") : geometry(0)));
    extras(members);
    return object(members);
  }
  std::string geometry(int depth)
  {
    std::vector<std::string> members;
    if(choice(16) == 15) {   // a point or a line: both readers skip it and name the first alike
      static const char* const types[] = { "Point", "MultiPoint", "LineString", "MultiLineString" };
      const int t = choice(4);
      std::string c = "[" + space() + number() + comma() + number() + space() + "]";
      static const int levels[] = { 0, 1, 1, 2 };   // of arrays around a position
      for(int level = 0; level < levels[t]; ++level) c = "[" + space() + c + space() + "]";
      members = { "\"type\"" + colon() + "\"" + types[t] + "\"", "\"coordinates\"" + colon() + c };
      extras(members);
      return object(members);
    }
    const int kind = choice(depth < 2 ? 3 : 2);
    if(kind == 0) {
      members = { "\"type\"" + colon() + "\"Polygon\"", "\"coordinates\"" + colon() + polygon() };
    } else if(kind == 1) {
      std::string c = "[" + space();
      const int n = choice(3) + 1;
      for(int i = 0; i < n; ++i) c += (i ? comma() : std::string()) + polygon();
      members = { "\"type\"" + colon() + "\"MultiPolygon\"", "\"coordinates\"" + colon() + c + space() + "]" };
    } else {
      std::string g = "[" + space();
      const int n = choice(3);
      for(int i = 0; i < n; ++i) g += (i ? comma() : std::string()) + geometry(depth + 1);
      members = { "\"type\"" + colon() + "\"GeometryCollection\"", "\"geometries\"" + colon() + g + space() + "]" };
    }
    extras(members);
    return object(members);
  }
  std::string polygon()
  {
    const int rings = choice(6) == 5 ? 0 : 1 + choice(3);   // (an empty polygon is skipped)
    if(rings > 0) ++m_polygons;
    std::string p = "[" + space();
    for(int r = 0; r < rings; ++r) {
      const int n = 3 + choice(5);
      std::string first;
      p += (r ? comma() : std::string()) + "[" + space();
      for(int i = 0; i < n; ++i) {
        std::string pos = "[" + space() + number() + comma() + number();
        if(choice(32) == 31) {   // an altitude, at times a fourth number: both readers ignore them
          pos += comma() + number();
          if(choice(4) == 3) pos += comma() + number();
        }
        pos += space() + "]";
        if(i == 0) first = pos;
        p += (i ? comma() : std::string()) + pos;
      }
      p += comma() + first + space() + "]";   // closed
    }
    return p + space() + "]";
  }
  // a number as JSON writes it, in one of several spellings
  std::string number()
  {
    char b[64];
    switch(choice(64)) {
    case 1: case 2: case 3: case 4: case 5: case 6: case 7: case 8: {   // any double
      double d;
      const std::uint64_t u = bits();
      std::memcpy(&d, &u, sizeof d);
      if(!std::isfinite(d)) d = 0;
      std::snprintf(b, sizeof b, choice(2) ? "%.17g" : "%.17e", d);
      if(std::strchr(b, 'e') && choice(2)) *std::strchr(b, 'e') = 'E';
      return b;
    }
    case 9: case 10: case 11: case 12: {   // an integer of 64 bits, signed or not
      const std::uint64_t u = bits();
      if(choice(2)) std::snprintf(b, sizeof b, "%llu", static_cast<unsigned long long>(u));
      else std::snprintf(b, sizeof b, "%lld", static_cast<long long>(u));
      return b;
    }
    case 13: case 14: case 15: case 16: {   // at the edges
      static const char* const edges[] = { "-0", "-0.0", "0e0", "1e308", "4.9e-324", "2.2250738585072014e-308",
                                           "9007199254740993", "18446744073709551615", "-9223372036854775808",
                                           "9223372036854775808", "0.1", "1E+2", "1.7976931348623157e308" };
      return edges[choice(13)];
    }
    case 63: {   // beyond 64 bits or beyond the doubles: left to the other reader
      m_leave = true;
      static const char* const beyond[] = { "18446744073709551616", "-9223372036854775809", "1e309", "-1e400" };
      return beyond[choice(4)];
    }
    default: {   // a small grid coordinate, as real data has
      std::snprintf(b, sizeof b, choice(2) ? "%d" : "%d.5", choice(256) - 128);
      return b;
    }
    }
  }
  std::string string()
  {
    static const char* const parts[] = { "a", "Z", "0", " ", "\\\"", "\\\\", "\\/", "\\n", "\\t", "\\u00e9",
                                         "\\u0000", "\\ud83d\\ude00", "\xc3\xa9", "\xe2\x82\xac", "\xf0\x9f\x98\x80", "name" };
    std::string s = "\"";
    const int n = choice(5);
    for(int i = 0; i < n; ++i) s += parts[choice(16)];
    return s + "\"";
  }
  std::string value(int depth)
  {
    switch(choice(depth < 3 ? 8 : 6)) {
    case 0: return "null";
    case 1: return choice(2) ? "true" : "false";
    case 2: case 3: return number();
    case 4: case 5: return string();
    case 6: {
      std::string a = "[" + space();
      const int n = choice(4);
      for(int i = 0; i < n; ++i) a += (i ? comma() : std::string()) + value(depth + 1);
      return a + space() + "]";
    }
    default: return properties(depth + 1);
    }
  }
  // an object of any members, names repeated at times
  std::string properties(int depth)
  {
    std::vector<std::string> members;
    const int n = choice(5);
    for(int i = 0; i < n; ++i) members.push_back(string() + colon() + value(depth + 1));
    return object(members);
  }

  const std::uint8_t* m_p;
  const std::uint8_t* m_end;
  std::string m_out;
  bool m_leave = false;
  int m_polygons = 0;
};

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  typedef CGAL::Epick::Point_2 Point;
  const std::string text(reinterpret_cast<const char*>(data), size);
  bool fast_read = false;
  if(!pma_test::geojson_readers_differ<Point>(text, fast_read).empty()) __builtin_trap();
  {
    Geojson_writer writer(data, size);
    const std::string geojson = writer.text();
    const std::string difference = pma_test::geojson_readers_differ<Point>(geojson, fast_read);
    if(!difference.empty()) {
      std::fprintf(stderr, "%s\non the GeoJSON text\n%s\n", difference.c_str(), geojson.c_str());
      __builtin_trap();
    }
#ifdef PMA_TOOL_WITH_SIMDJSON
    if(writer.fast_reads() && !fast_read) {
      std::fprintf(stderr, "the fast reader leaves a valid GeoJSON text to the other one:\n%s\n", geojson.c_str());
      __builtin_trap();
    }
#endif
  }
  for(int format = 0; format < 2; ++format) {
    std::istringstream in(text);
    try {
      const auto polygons = format == 0 ? pma_tool::read_wkt_polygons<Point>(in) : pma_tool::read_geojson_polygons<Point>(in);
      for(const auto& p : polygons) {
        if(p.rings.empty()) __builtin_trap();   // a polygon read has an outer ring
        try {
          CGAL::Progressive_medial_axes::validate_polygon(p.rings);
        } catch(const CGAL::Progressive_medial_axes::Input_error&) {
        }
      }
    } catch(const CGAL::Progressive_medial_axes::Input_error& e) {
      if(std::string(e.what()).empty()) __builtin_trap();   // every error says what is wrong
    }
  }
  return 0;
}
