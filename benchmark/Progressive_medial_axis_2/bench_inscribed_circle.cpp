// The maximum inscribed circle: ours (the vertex of largest radius of the
// exact medial axis) against GEOS's GEOSMaximumInscribedCircle_r (an
// iteration to a tolerance), at tolerances 1e-3 and 1e-6 of the bounding
// box diagonal, in the same run.  Benchmark-only code (GEOS is a peer here).
//
//   bench_inscribed_circle [--runs R] FILE.wkt ...
//
// Prints one Markdown table row per file and tolerance: times (median of R
// runs; ours: the one-shot axis on all hardware threads plus the circle;
// GEOS: the circle alone, the polygon already parsed), radii, and GEOS's
// radius error relative to ours.

#include <CGAL/Progressive_medial_axis_2.h>
#include <CGAL/Progressive_medial_axis_2/maximum_inscribed_circle_2.h>
#include <pma_tool/polygon_io.h>

#include <geos_c.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace {

double now() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }

double median(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

void geos_message(const char* fmt, ...)
{
  va_list ap;
  va_start(ap, fmt);
  std::vfprintf(stderr, fmt, ap);
  va_end(ap);
  std::fprintf(stderr, "\n");
}

} // namespace

int main(int argc, char** argv)
{
  int runs = 3;
  std::vector<std::string> files;
  for(int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if(a == "--runs" && i + 1 < argc) runs = std::max(1, std::atoi(argv[++i]));
    else files.push_back(a);
  }
  if(files.empty()) {
    std::cerr << "usage: bench_inscribed_circle [--runs R] FILE.wkt ...\n";
    return 2;
  }
  GEOSContextHandle_t ctx = GEOS_init_r();
  GEOSContext_setErrorHandler_r(ctx, geos_message);
  GEOSWKTReader* reader = GEOSWKTReader_create_r(ctx);
  std::printf("| shape | vertices | ours: axis + circle (s) | our radius | GEOS tolerance (of the diagonal) | GEOS time (s) "
              "| GEOS radius | GEOS radius error / our radius | ours / GEOS time |\n");
  std::printf("|---|---:|---:|---:|---|---:|---:|---:|---:|\n");
  for(const std::string& file : files) {
    typedef CGAL::Epick::Point_2 Point;
    const auto rings = pma_tool::read_polygon_file<Point>(file);
    std::size_t n = 0;
    double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
    for(const auto& r : rings)
      for(const Point& p : r) {
        ++n;
        x0 = std::min(x0, p.x());
        x1 = std::max(x1, p.x());
        y0 = std::min(y0, p.y());
        y1 = std::max(y1, p.y());
      }
    const double diagonal = std::hypot(x1 - x0, y1 - y0);
    // ours
    std::vector<double> times;
    double radius = 0, cx = 0, cy = 0;
    for(int k = 0; k < runs; ++k) {
      const double t0 = now();
      const auto axis = CGAL::medial_axis_2(rings);
      const auto c = CGAL::maximum_inscribed_circle_2(axis);
      times.push_back(now() - t0);
      radius = CGAL::to_double(c.radius);
      cx = CGAL::to_double(c.center.x());
      cy = CGAL::to_double(c.center.y());
    }
    const double ours = median(times);
    // GEOS, on the same polygon read from the same WKT
    std::ifstream in(file);
    std::stringstream text;
    text << in.rdbuf();
    GEOSGeometry* polygon = GEOSWKTReader_read_r(ctx, reader, text.str().c_str());
    if(!polygon) {
      std::cerr << file << ": GEOS cannot read it\n";
      continue;
    }
    for(double tolerance : {1e-3, 1e-6}) {
      std::vector<double> gt;
      double gr = 0;
      for(int k = 0; k < runs; ++k) {
        const double t0 = now();
        GEOSGeometry* line = GEOSMaximumInscribedCircle_r(ctx, polygon, tolerance * diagonal);
        gt.push_back(now() - t0);
        if(!line) break;
        GEOSGeomGetLength_r(ctx, line, &gr);
        GEOSGeom_destroy_r(ctx, line);
      }
      if(gt.size() < std::size_t(runs)) {
        std::cerr << file << ": GEOS failed\n";
        continue;
      }
      const double g = median(gt);
      std::printf("| %s | %zu | %.4f | %.10g | %g | %.4f | %.10g | %.2e | %.2f |\n",
                  file.substr(file.find_last_of('/') + 1).c_str(), n, ours, radius, tolerance, g, gr,
                  (radius - gr) / radius, ours / g);
    }
    (void)cx;
    (void)cy;
    GEOSGeom_destroy_r(ctx, polygon);
  }
  GEOSWKTReader_destroy_r(ctx, reader);
  GEOS_finish_r(ctx);
  return 0;
}
