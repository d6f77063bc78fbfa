// make_degenerate: writes degenerate shapes (exact ties: integer grids, repeated
// coordinates, exact mirror symmetry, cocircular points) as WKT POLYGONs, one file each.
//
//   make_degenerate OUTDIR [--scale10]        (OUTDIR is created if missing)
//
// The shapes come from test/.../pma_test/degenerate_shapes.h, which checks every one of
// them (simple rings, no contact between rings, holes inside); the sizes are those of the
// degenerate benchmark table (a 60 x 60 grid polygon with 42 holes and about 672
// vertices, ...); --scale10 writes them about 10 times larger (grid shapes with 10 times
// the vertices and holes, on a larger grid; the Hilbert curve and the Koch snowflakes two
// orders higher, 16 times the vertices, since one order multiplies them by 4).
// Deterministic: for a grid shape, of the seeds 1..16 the one whose vertex count is
// nearest to the target is taken (ties: the smaller seed). Prints one line per file:
// name, vertices, holes. Coordinates are written by pma_tool::write_wkt_polygon with 17
// significant digits: a coordinate rounded to 6 decimals, 0.1 say, reads
// 0.10000000000000001, which is read back as the same double as "0.1".
#include <pma_test/degenerate_shapes.h>

#include <pma_tool/polygon_io.h>

#include <cstdint>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace {

using pma_test::Ring;

bool write(const std::string& dir, const std::string& name, const std::vector<Ring>& rings)
{
  const std::string path = dir + "/" + name + ".wkt";
  std::ofstream out(path);
  pma_tool::write_wkt_polygon(out, rings);
  out << "\n";
  out.close();
  if(!out) {
    std::fprintf(stderr, "make_degenerate: cannot write %s\n", path.c_str());
    return false;
  }
  std::printf("%-28s vertices %8zu holes %5zu\n", name.c_str(), pma_test::vertex_count(rings),
              rings.size() - 1);
  return true;
}

// A grid shape of the table: grid size, options, the vertex count aimed at.
struct Grid_spec
{
  const char* name;
  int n, n10; // grid size, grid size with --scale10
  int feature;
  double fill;
  double falloff;
  int holes;
  bool keep_flat_vertices;
  bool cut_45;
  std::size_t target_vertices;
  double perturb_eps; // > 0: the shape is perturbed() by that much
};

std::vector<Ring> make_grid(const Grid_spec& s, int n, int holes, std::uint64_t seed)
{
  pma_test::Grid_cell_options o;
  o.feature = s.feature;
  o.fill = s.fill;
  o.falloff = s.falloff;
  o.holes = holes;
  o.keep_flat_vertices = s.keep_flat_vertices;
  return s.cut_45 ? pma_test::grid_cell_polygon_45(seed, n, o)
                  : pma_test::grid_cell_polygon(seed, n, holes != 0, o);
}

} // namespace

int main(int argc, char** argv)
{
  if(argc < 2 || argc > 3 || (argc == 3 && std::string(argv[2]) != "--scale10")) {
    std::fprintf(stderr, "usage: make_degenerate OUTDIR [--scale10]\n");
    return 1;
  }
  const std::string dir = argv[1];
  const bool scale10 = (argc == 3);
  const std::string suffix = scale10 ? "_x10" : "";
  try {
    std::filesystem::create_directories(dir);
    // Grid parameters found by trying: `feature` 0 and a low fill near the percolation
    // threshold give ragged outer rings with many vertices; feature 1 and fill 0.6 a
    // rounder blob. The vertex count grows about linearly with the grid size (the outer
    // ring dominates), hence n10 about 6 to 10 times n.
    const Grid_spec grids[] = {
      // name                    n   n10 feat fill falloff holes flat  45  target perturb
      {"grid60_holes42",          60,  250, 1, 0.60, 8,  42, false, false,   672, 0},
      {"grid60_holes2",           60,  270, 0, 0.38, 2,   2, false, false,   792, 0},
      {"grid150_holes54",        150,  900, 0, 0.38, 2,  54, false, false,  4682, 0},
      {"grid45_holes21",         105,  550, 1, 0.60, 12, 21, false, true,   1956, 0},
      {"grid_refined_holes223",  350, 1800, 0, 0.40, 2, 223, true,  false, 22422, 0},
      {"grid_perturbed_holes15", 100,  600, 0, 0.40, 2,  15, false, false,  2268, 1e-6},
    };
    for(const Grid_spec& s : grids) {
      const int n = scale10 ? s.n10 : s.n;
      const int holes = scale10 ? 10 * s.holes : s.holes;
      const std::size_t target = scale10 ? 10 * s.target_vertices : s.target_vertices;
      std::vector<Ring> best;
      std::size_t best_diff = 0;
      for(std::uint64_t seed = 1; seed <= 16; ++seed) {
        std::vector<Ring> rings = make_grid(s, n, holes, seed);
        const std::size_t v = pma_test::vertex_count(rings);
        const std::size_t diff = v > target ? v - target : target - v;
        if(best.empty() || diff < best_diff) {
          best.swap(rings);
          best_diff = diff;
        }
      }
      if(s.perturb_eps > 0) best = pma_test::perturbed(best, 1, s.perturb_eps);
      if(!write(dir, std::string(s.name) + suffix, best)) return 1;
    }
    const int koch_step = scale10 ? 2 : 0;
    for(int order : {4, 5, 6})
      if(!write(dir, "koch_nested_order" + std::to_string(order + koch_step) + "_6dec",
                pma_test::koch_snowflake_nested(order + koch_step, 6)))
        return 1;
    const int hilbert_order = scale10 ? 9 : 7;
    if(!write(dir, "hilbert_order" + std::to_string(hilbert_order),
              pma_test::hilbert_polygon(hilbert_order)))
      return 1;
    // the other kinds of the header, at sizes of the same range
    const int ngon = scale10 ? 10000 : 1000;
    if(!write(dir, "ngon" + std::to_string(ngon), pma_test::regular_ngon(ngon, 100.0, -1)) ||
       !write(dir, "ngon" + std::to_string(ngon) + "_6dec", pma_test::regular_ngon(ngon, 100.0, 6)) ||
       !write(dir, "ngon_holes" + suffix,
              pma_test::regular_ngon_with_holes(scale10 ? 640 : 64, 8, scale10 ? 320 : 32, 100.0, -1)))
      return 1;
    // 200 of the 324 integer points of the circle of radius 32045 (2,000 of the 2,916 of
    // radius 48612265): the others leave room for notches on the concyclic inner circle
    const int concyclic = scale10 ? 2000 : 200;
    if(!write(dir, "concyclic" + std::to_string(concyclic), pma_test::concyclic_polygon(1, concyclic)))
      return 1;
  } catch(const std::exception& e) {
    std::fprintf(stderr, "make_degenerate: %s\n", e.what());
    return 1;
  }
  return 0;
}
