// make_synthetic: writes synthetic test shapes as WKT POLYGONs on stdout.
//
//   make_synthetic holes-grid HOLES HOLE_VERTICES SEED
//       a square plate with HOLES star-shaped holes, one per unit cell of a
//       grid, each with HOLE_VERTICES vertices (random radii and angles)
//   make_synthetic star VERTICES SEED
//       a random star-shaped polygon around the origin
//   make_synthetic maze CELLS SEED
//       a rectilinear maze: the boundary of a random tree of corridors on
//       an integer grid, CELLS x CELLS cells
//
// Deterministic from SEED (own generator, independent of the standard
// library's distributions).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace {

struct Rng {
  std::uint64_t s;
  explicit Rng(std::uint64_t seed) : s(seed * 0x9E3779B97F4A7C15ull + 1) {}
  std::uint64_t next()
  {
    s ^= s << 13; s ^= s >> 7; s ^= s << 17;
    return s;
  }
  double uniform(double a, double b) { return a + (b - a) * double(next() >> 11) / 9007199254740992.0; }
  std::size_t below(std::size_t n) { return std::size_t(next() % n); }
};

typedef std::vector<std::pair<double, double> > Ring;

void print(const std::vector<Ring>& rings)
{
  std::printf("POLYGON (");
  for(std::size_t r = 0; r < rings.size(); ++r) {
    std::printf(r ? ", (" : "(");
    const Ring& ring = rings[r];
    for(std::size_t i = 0; i <= ring.size(); ++i) {
      const auto& p = ring[i % ring.size()];
      std::printf(i ? ", %.17g %.17g" : "%.17g %.17g", p.first, p.second);
    }
    std::printf(")");
  }
  std::printf(")\n");
}

// A star-shaped ring around (cx, cy): sorted random angles, radii in [rmin, rmax].
Ring star(Rng& rng, int n, double cx, double cy, double rmin, double rmax, bool clockwise)
{
  std::vector<double> a(n);
  for(int i = 0; i < n; ++i) a[i] = 2 * M_PI * (i + rng.uniform(0.1, 0.9)) / n;
  Ring ring;
  for(int i = 0; i < n; ++i) {
    double r = rng.uniform(rmin, rmax);
    ring.emplace_back(cx + r * std::cos(a[i]), cy + r * std::sin(a[i]));
  }
  if(clockwise) std::reverse(ring.begin(), ring.end());
  return ring;
}

int holes_grid(long holes, int hole_vertices, std::uint64_t seed)
{
  Rng rng(seed);
  long m = long(std::ceil(std::sqrt(double(holes))));
  std::vector<Ring> rings;
  rings.push_back(Ring{{0, 0}, {double(m), 0}, {double(m), double(m)}, {0, double(m)}});
  long made = 0;
  for(long i = 0; i < m && made < holes; ++i)
    for(long j = 0; j < m && made < holes; ++j, ++made)
      rings.push_back(star(rng, hole_vertices, i + 0.5, j + 0.5, 0.12, 0.4, true));
  print(rings);
  return 0;
}

// A maze: a random spanning tree of the cells, each cell a 2x2 block of a
// (2n+1)-grid with corridors of width 1; the polygon is the union of the
// corridor squares, traced as one ring.
int maze(int n, std::uint64_t seed)
{
  Rng rng(seed);
  const int W = 2 * n - 1;
  std::vector<char> open(W * W, 0);
  auto at = [&](int x, int y) -> char& { return open[y * W + x]; };
  std::vector<int> stack = {0};
  std::vector<char> seen(n * n, 0);
  seen[0] = 1;
  at(0, 0) = 1;
  while(!stack.empty()) {
    int c = stack.back();
    int cx = c % n, cy = c / n;
    std::vector<int> nb;
    const int d[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
    for(const auto& e : d) {
      int x = cx + e[0], y = cy + e[1];
      if(x >= 0 && y >= 0 && x < n && y < n && !seen[y * n + x]) nb.push_back(y * n + x);
    }
    if(nb.empty()) { stack.pop_back(); continue; }
    int u = nb[rng.below(nb.size())];
    int ux = u % n, uy = u / n;
    seen[u] = 1;
    at(2 * ux, 2 * uy) = 1;
    at(cx + ux, cy + uy) = 1;   // the square between them
    stack.push_back(u);
  }
  // trace the boundary of the union of open unit squares (x, y)..(x+1, y+1):
  // directed boundary edges with the interior on the left, then chain them
  std::vector<std::pair<std::pair<int, int>, std::pair<int, int> > > edges;
  for(int y = 0; y < W; ++y)
    for(int x = 0; x < W; ++x) {
      if(!at(x, y)) continue;
      auto opened = [&](int a, int b) { return a >= 0 && b >= 0 && a < W && b < W && at(a, b); };
      if(!opened(x, y - 1)) edges.push_back({{x, y}, {x + 1, y}});
      if(!opened(x + 1, y)) edges.push_back({{x + 1, y}, {x + 1, y + 1}});
      if(!opened(x, y + 1)) edges.push_back({{x + 1, y + 1}, {x, y + 1}});
      if(!opened(x - 1, y)) edges.push_back({{x, y + 1}, {x, y}});
    }
  std::sort(edges.begin(), edges.end());
  // a tree of corridors has no holes and no vertex touched twice: each
  // source has exactly one outgoing edge
  Ring ring;
  auto start = edges.front().first;
  auto cur = start;
  do {
    auto it = std::lower_bound(edges.begin(), edges.end(), std::make_pair(cur, std::make_pair(-1, -1)));
    ring.emplace_back(double(cur.first), double(cur.second));
    cur = it->second;
  } while(cur != start);
  // drop the collinear (flat) vertices
  Ring out;
  for(std::size_t i = 0; i < ring.size(); ++i) {
    const auto& a = ring[(i + ring.size() - 1) % ring.size()];
    const auto& b = ring[i];
    const auto& c = ring[(i + 1) % ring.size()];
    if((b.first - a.first) * (c.second - b.second) - (b.second - a.second) * (c.first - b.first) != 0)
      out.push_back(b);
  }
  print(std::vector<Ring>{out});
  return 0;
}

} // namespace

int main(int argc, char** argv)
{
  std::string kind = argc > 1 ? argv[1] : "";
  if(kind == "holes-grid" && argc == 5)
    return holes_grid(std::atol(argv[2]), std::atoi(argv[3]), std::strtoull(argv[4], nullptr, 10));
  if(kind == "star" && argc == 4) {
    Rng rng(std::strtoull(argv[3], nullptr, 10));
    print(std::vector<Ring>{star(rng, std::atoi(argv[2]), 0, 0, 0.2, 1.0, false)});
    return 0;
  }
  if(kind == "maze" && argc == 4)
    return maze(std::atoi(argv[2]), std::strtoull(argv[3], nullptr, 10));
  std::fprintf(stderr, "usage: make_synthetic holes-grid HOLES HOLE_VERTICES SEED | star VERTICES SEED | maze CELLS SEED\n");
  return 2;
}
