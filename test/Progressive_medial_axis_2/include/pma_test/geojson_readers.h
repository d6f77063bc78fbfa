// The tool's two GeoJSON readers compared (pma_tool/polygon_io.h): where the
// fast one (simdjson) reads a text, the nlohmann-json one must read the same
// polygons, bit for bit, with the same properties; where the nlohmann-json one
// throws, the fast one must give up.  Used by test_input and fuzz_readers.

#ifndef PMA_TEST_GEOJSON_READERS_H
#define PMA_TEST_GEOJSON_READERS_H

#include <pma_tool/polygon_io.h>

#include <cstring>
#include <string>
#include <vector>

namespace pma_test {

/// What differs between the two readers on `text` (empty if nothing); `fast_read`
/// tells whether the fast reader read it (false where it is not built in).
template <class Point_2>
std::string geojson_readers_differ(const std::string& text, bool& fast_read)
{
  fast_read = false;
#ifdef PMA_TOOL_WITH_SIMDJSON
  typedef std::vector<pma_tool::Input_polygon<Point_2> > Polygons;
  const char* b = text.data();
  const char* e = b + text.size();
  Polygons fast, slow;
  pma_tool::Skipped_geometries fast_skipped, slow_skipped;
  fast_read = pma_tool::internal::Geojson_polygons_fast_reader<Point_2>(b, e).read(fast, &fast_skipped);
  if(!fast_read)
    return std::string();
  try {
    slow = pma_tool::internal::Geojson_polygons_reader<Point_2>(b, e).read(&slow_skipped);
  } catch(const pma_tool::Input_error& error) {
    return std::string("the fast reader reads what the other rejects: ") + error.what();
  }
  if(fast_skipped.count != slow_skipped.count || fast_skipped.first != slow_skipped.first)
    return "the readers skipped " + std::to_string(fast_skipped.count) + " (" + fast_skipped.first + ") and " +
           std::to_string(slow_skipped.count) + " (" + slow_skipped.first + ") geometries";
  if(fast.size() != slow.size())
    return "the readers read " + std::to_string(fast.size()) + " and " + std::to_string(slow.size()) + " polygons";
  for(std::size_t k = 0; k < fast.size(); ++k) {
    if(fast[k].properties != slow[k].properties)
      return "polygon " + std::to_string(k) + ": properties " + fast[k].properties + " and " + slow[k].properties;
    bool same = fast[k].rings.size() == slow[k].rings.size();
    for(std::size_t r = 0; same && r < fast[k].rings.size(); ++r) {
      same = fast[k].rings[r].size() == slow[k].rings[r].size();
      for(std::size_t i = 0; same && i < fast[k].rings[r].size(); ++i) {
        const double c[4] = { CGAL::to_double(fast[k].rings[r][i].x()), CGAL::to_double(fast[k].rings[r][i].y()),
                              CGAL::to_double(slow[k].rings[r][i].x()), CGAL::to_double(slow[k].rings[r][i].y()) };
        same = std::memcmp(c, c + 2, 2 * sizeof(double)) == 0;
      }
    }
    if(!same)
      return "polygon " + std::to_string(k) + ": the rings differ";
  }
#else
  (void)text;
#endif
  return std::string();
}

} // namespace pma_test

#endif // PMA_TEST_GEOJSON_READERS_H
