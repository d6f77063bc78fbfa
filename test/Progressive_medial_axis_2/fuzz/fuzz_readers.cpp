// libFuzzer harness for the tool's readers: WKT and GeoJSON text, of one or
// several polygons, then the geometric check of each polygon read.  Any
// exception other than Input_error, any crash, leak or undefined behaviour
// (the harness is built with AddressSanitizer and UBSan) is a failure, and so
// is a text that the two GeoJSON readers (simdjson's and nlohmann-json's, where
// simdjson is built in) read differently.
//
//   fuzz_readers [libFuzzer options] [CORPUS_DIR ...]

#include <pma_tool/polygon_io.h>
#include <pma_test/geojson_readers.h>
#include <CGAL/Progressive_medial_axis_2/validate_polygon.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  typedef CGAL::Epick::Point_2 Point;
  const std::string text(reinterpret_cast<const char*>(data), size);
  bool fast_read = false;
  if(!pma_test::geojson_readers_differ<Point>(text, fast_read).empty()) __builtin_trap();
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
