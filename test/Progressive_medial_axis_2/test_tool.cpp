// Tests the command-line tool progressive_medial_axis as other programs use
// it: exit statuses and one-line errors on bad input and usage, --pairs
// against the oracle program sdg_pairs at several --step values (on the
// shape written by --shape-out), and the other outputs.
//
//   test_tool TOOL SDG_PAIRS

#include <pma_test/compare_curves.h>

#include <nlohmann/json.hpp>

#include <sys/wait.h>
#include <unistd.h>
#ifdef __GLIBC__
#include <gnu/libc-version.h>
#endif

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <map>
#include <iostream>
#include <sstream>
#include <string>
#include <tuple>

#include <pma_test/check.h>
#include <vector>

namespace {

std::string tool, sdg_pairs, tmp;

std::string slurp(const std::string& path)
{
  std::ifstream f(path);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

struct Result {
  int status;
  std::string out, err;
};

// Runs a command line (arguments already quoted as needed).
Result run(const std::string& args)
{
  std::string cmd = args + " > " + tmp + "/out.txt 2> " + tmp + "/err.txt";
  int rc = std::system(cmd.c_str());
  Result r;
  r.status = WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
  r.out = slurp(tmp + "/out.txt");
  r.err = slurp(tmp + "/err.txt");
  return r;
}

std::size_t count_lines(const std::string& s)
{
  std::size_t n = 0;
  for(char c : s) n += (c == '\n');
  return n;
}

void check_bad_input(const std::string& file, const std::string& fragment)
{
  Result r = run(tool + " --pairs " + file);
  CHECK(r.status == 2, file << ": exit status " << r.status << ", expected 2");
  CHECK(count_lines(r.err) == 1, file << ": error is not one line: " << r.err);
  CHECK(r.err.find(fragment) != std::string::npos, file << ": error '" << r.err << "' lacks '" << fragment << "'");
  CHECK(r.out.empty(), file << ": printed output despite the error");
}

void bad_inputs(const std::string& data)
{
  const std::string dir = data + "/invalid/";
  const char* cases[][2] = {
    {"malformed.wkt", "malformed WKT at line 1"},
    {"empty.wkt", "empty polygon"},
    {"not_polygon.wkt", "not a polygon"},
    {"non_finite.wkt", "non-finite coordinate: ring 0 vertex 2"},
    {"unclosed.wkt", "unclosed ring: ring 0"},
    {"too_few_distinct.wkt", "fewer than 3 distinct vertices"},
    {"zero_length_edge.wkt", "zero-length edge: ring 0 vertex 2"},
    {"spike.wkt", "spike: ring 0 vertex 4"},
    {"crossing.wkt", "self-intersection: ring 0 edge 0"},
    {"t_crossing.wkt", "self-intersection: ring 1 vertex 0 crosses ring 0 edge 1"},
    {"hole_outside.wkt", "hole 1 (ring 1) is not inside the outer ring"},
    {"malformed.geojson", "malformed JSON"},
  };
  for(const auto& c : cases) check_bad_input(dir + c[0], c[1]);
  check_bad_input(dir + "no_such_file.wkt", "cannot read file");
}

void usage_errors(const std::string& data)
{
  const std::string shape = data + "/syn_comb50.wkt";
  for(const std::string& args : {std::string(""), std::string("--no-such-option ") + shape,
                                 std::string("--step abc ") + shape, std::string("--step -3 ") + shape,
                                 std::string("--frames 5 ") + shape, std::string("--traits foo ") + shape,
                                 shape + " " + shape}) {
    Result r = run(tool + " " + args);
    CHECK(r.status == 2, "'" << args << "': exit status " << r.status << ", expected 2");
    CHECK(!r.err.empty(), "'" << args << "': no message");
  }
  Result h = run(tool + " --help");
  CHECK(h.status == 0 && h.out.find("--pairs") != std::string::npos, "--help");
}

// --pairs at --step K against the oracle on the shape of step K (with
// `extra` options, such as --union, on the shape that --shape-out writes).
void pairs_against_oracle(const std::string& file, const std::vector<long>& steps, const std::string& extra = "")
{
  for(long k : steps) {
    std::string shape = tmp + "/shape.wkt";
    // (ids refer to the shape of step K, or to the union; else to the input)
    const bool written = k >= 0 || extra.find("--union") != std::string::npos;
    std::string args = tool + " --pairs " + extra + " " + (k >= 0 ? "--step " + std::to_string(k) + " " : "") +
                       (written ? "--shape-out " + shape + " " : "") + file;
    Result ours = run(args);
    CHECK(ours.status == 0, args << ": exit status " << ours.status << ": " << ours.err);
    Result theirs = run(sdg_pairs + " " + (written ? shape : file));
    CHECK(theirs.status == 0, "sdg_pairs: " << theirs.err);
    std::istringstream a(ours.out), b(theirs.out);
    std::vector<pma_test::Oracle_curve> ca = pma_test::parse_pairs(a), cb = pma_test::parse_pairs(b);
    // bounding-box diagonal of the shape compared
    std::string wkt = slurp(written ? shape : file);
    double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
    {
      std::string t;
      for(char c : wkt) t += (c == '(' || c == ')' || c == ',') ? ' ' : c;
      std::istringstream s(t);
      std::string word;
      s >> word;   // POLYGON
      double x, y;
      while(s >> x >> y) {
        x0 = std::min(x0, x); x1 = std::max(x1, x);
        y0 = std::min(y0, y); y1 = std::max(y1, y);
      }
    }
    pma_test::Curve_diff d = pma_test::compare_curves(ca, cb, std::hypot(x1 - x0, y1 - y0));
    CHECK(!ca.empty() && d.ok(), file << " step " << k << ": --pairs differs from sdg_pairs (tool | oracle)\n" << d.report());
  }
}

// --progressive boundary: the pairs of a full run and of --step K against
// the oracle (on the shape --shape-out writes), its --stats, the viewer.
void boundary_evolution(const std::string& data)
{
  for(const char* f : {"syn_comb50", "syn_maze20", "syn_spiral20", "syn_cheese1k"})
    pairs_against_oracle(data + "/" + f + ".wkt", {-1, 0, 1, 17, 100, 400}, "--progressive boundary");
  for(const char* f : {"syn_two_holes", "syn_pinch", "syn_island", "syn_t_hole_hole", "c1m_NOR_55654", "l10m_RUS_30511"})
    pairs_against_oracle(data + "/touching/" + f + ".wkt", {-1, 0, 2, 50, 400}, "--progressive boundary");
  // a step whose cut would surround a small hole: computed in one shot
  // (step 146's shape has a point between two segments, whose two tangent
  // circles the oracle took for one until the forty-seventh session)
  pairs_against_oracle(data + "/touching/c1m_PNG_21.wkt", {145, 146, 147, 148}, "--progressive boundary");
  const std::string shape = data + "/syn_maze20.wkt";
  Result r = run(tool + " --stats --progressive boundary " + shape);
  std::map<std::string, std::string> v;
  std::istringstream in(r.out);
  std::string key, value;
  while(in >> key >> value) v[key] = value;
  CHECK(r.status == 0 && v["mode"] == "boundary" && v.count("time_first_step") && v.count("time_evolution") &&
          v.count("cut_steps") && v.count("split_steps") && v.count("recomputed_steps") && v["steps"] == v["steps_done"] &&
          std::atol(v["cut_steps"].c_str()) > 0,
        "--stats --progressive boundary: " << r.out);
  Result g = run(tool + " --stats --step 10 " + shape);
  CHECK(g.status == 0 && g.out.find("mode region\n") != std::string::npos && g.out.find("time_first_step ") != std::string::npos,
        "--stats --step: " << g.out);
  Result u = run(tool + " --progressive sideways " + shape);
  CHECK(u.status == 2 && u.err.find("--progressive must be region or boundary") != std::string::npos,
        "--progressive sideways: exit status " << u.status << ": " << u.err);
  Result h = run(tool + " --progressive boundary --html " + tmp + "/boundary.html --frames 5 " + shape);
  const std::string page = slurp(tmp + "/boundary.html");
  std::size_t svgs = 0;
  for(std::size_t p = 0; (p = page.find("<svg", p)) != std::string::npos; ++p) ++svgs;
  CHECK(h.status == 0 && svgs == 5, "--progressive boundary --html: exit status " << h.status << ", " << svgs << " pictures");
}

// --union: the axis of the union of two polygons that share edges, from
// their two axes, against the oracle on the union that --shape-out writes;
// its --stats; the errors.
void union_of_two(const std::string& data)
{
  const std::string d = data + "/union/";
  for(const char* p : {"star", "ring", "chain2", "chain40", "hole_filled", "t_notch", "t_both_sides", "t_union", "t_shared",
                        "t_shared_crossed", "t_shared_two_places", "touch_at_smallest"}) {
    pairs_against_oracle(d + p + "_a.wkt", {-1}, "--union " + d + p + "_b.wkt");
    pairs_against_oracle(d + p + "_b.wkt", {-1}, "--union " + d + p + "_a.wkt");
  }
  // --union given twice: the union of a and b, merged again with c (along
  // two edges of the first union, whose vertex between them is then inside)
  for(const std::string& three : {"--union " + d + "three_b.wkt --union " + d + "three_c.wkt " + d + "three_a.wkt",
                                  "--union " + d + "three_a.wkt --union " + d + "three_b.wkt " + d + "three_c.wkt",
                                  "--union " + d + "three_c.wkt --union " + d + "three_b.wkt " + d + "three_a.wkt"}) {
    const std::size_t at = three.rfind(' ');
    pairs_against_oracle(three.substr(at + 1), {-1}, three.substr(0, at));
    // (the union of all three: a vertex of each, and no place inside a chain)
    Result t = run(tool + " " + three.substr(0, at) + " --shape-out " + tmp + "/three.wkt " + three.substr(at + 1));
    const std::string u = slurp(tmp + "/three.wkt");
    CHECK(t.status == 0 && u.find("0 0") != std::string::npos && u.find("4.5 0") != std::string::npos &&
            u.find("3 4.5") != std::string::npos && u.find("2 1") == std::string::npos && u.find("2 2") == std::string::npos,
          three << ": the union written is " << u << t.err);
  }
  {
    Result t = run(tool + " --stats --union " + d + "three_b.wkt --union " + d + "three_c.wkt " + d + "three_a.wkt");
    CHECK(t.status == 0 && t.out.find("\nunions 2\n") != std::string::npos && t.out.find("\nunion_shared_edges 4\n") != std::string::npos &&
            t.out.find("\nunion_chains 2\n") != std::string::npos && t.out.find("\nunion_recomputed 0\n") != std::string::npos,
          "--union twice --stats: " << t.out << t.err);
    t = run(tool + " --union " + d + "three_b.wkt --union " + d + "star_a.wkt " + d + "three_a.wkt");
    CHECK(t.status == 2 && count_lines(t.err) == 1 &&
            t.err.find("three_a.wkt, " + d + "three_b.wkt and " + d + "star_a.wkt: the polygons share no edge") != std::string::npos,
          "--union twice, the second sharing no edge: exit status " << t.status << ", '" << t.err << "'");
  }
  Result r = run(tool + " --stats --union " + d + "ring_b.wkt " + d + "ring_a.wkt");
  CHECK(r.status == 0 && r.out.find("\nunion_shared_edges 2\n") != std::string::npos &&
          r.out.find("\nunion_chains 2\n") != std::string::npos && r.out.find("\ntime_union_merge ") != std::string::npos &&
          r.out.find("\nmode oneshot\n") != std::string::npos && r.out.find("\nundecided_ties 0\n") != std::string::npos &&
          r.out.find("\nanomalies 0\n") != std::string::npos && r.out.find("\nunion_recomputed 0\n") != std::string::npos,
        "--union --stats: " << r.out << r.err);
  // a hole filled exactly: a whole ring shared, computed in one shot
  r = run(tool + " --stats --union " + d + "hole_filled_b.wkt " + d + "hole_filled_a.wkt");
  CHECK(r.status == 0 && r.out.find("\nunion_recomputed 1\n") != std::string::npos &&
          r.out.find("\nunion_chains 1\n") != std::string::npos && r.out.find("\nunion_shared_edges 4\n") != std::string::npos,
        "--union --stats of a hole filled: " << r.out << r.err);
  // T's: in a part (merged), in the union only, and on a shared edge (both in one shot)
  for(const auto& t : std::vector<std::pair<std::string, int> >{{"t_notch", 0}, {"t_union", 1}, {"t_shared", 1},
                                                                 {"t_shared_crossed", 1}}) {
    r = run(tool + " --stats --union " + d + t.first + "_b.wkt " + d + t.first + "_a.wkt");
    CHECK(r.status == 0 && r.out.find("\nunion_recomputed " + std::to_string(t.second) + "\n") != std::string::npos &&
            r.out.find("\nanomalies 0\n") != std::string::npos,
          "--union --stats of " << t.first << ": " << r.out << r.err);
  }
  // OGC's form: the two holes that touch the union's outer ring at one point
  // inside its edge are rings of their own, and the outer ring is noded
  // there; where a vertex of b lies inside an edge of a (t_union), that edge
  // is noded, and the loop between the ring's two passes is a hole
  for(const auto& t : std::vector<std::tuple<std::string, std::size_t, std::string> >{{"t_two_holes", 3, "2 0, 4 0"},
                                                                                       {"t_union", 2, "0 2.5, 1 2, 0 2"}}) {
    r = run(tool + " --union " + d + std::get<0>(t) + "_b.wkt --shape-out " + tmp + "/u.wkt " + d + std::get<0>(t) + "_a.wkt");
    const std::string u = slurp(tmp + "/u.wkt");
    std::size_t parentheses = 0;
    for(char c : u) parentheses += c == '(';
    CHECK(r.status == 0 && parentheses == 1 + std::get<1>(t) && u.find(std::get<2>(t)) != std::string::npos,
          "--union of " << std::get<0>(t) << ": " << u << r.err);
  }
  const std::vector<std::pair<std::string, std::string> > bad = {
    {"--union " + d + "star_a.wkt " + d + "star_a.wkt", "the polygons overlap"},
    {"--union " + data + "/syn_comb50.wkt " + d + "star_a.wkt", "the polygons share no edge"},
    {"--union " + data + "/syn_comb50.wkt " + data + "/invalid/crossing.wkt", "crossing.wkt: self-intersection"}};
  for(const auto& b : bad) {
    Result e = run(tool + " " + b.first);
    CHECK(e.status == 2 && e.err.find(b.second) != std::string::npos && count_lines(e.err) == 1,
          b.first << ": exit status " << e.status << ", message '" << e.err << "'");
  }
  Result u = run(tool + " --union " + d + "star_b.wkt --step 3 " + d + "star_a.wkt");
  CHECK(u.status == 2, "--union with --step: exit status " << u.status);
}

void outputs(const std::string& data)
{
  const std::string shape = data + "/syn_spiral20.wkt";
  Result r = run(tool + " --branches --stats --svg " + tmp + "/a.svg --geojson " + tmp + "/a.geojson --wkt-out " +
                 tmp + "/a.wkt --frames 3 --frames-prefix " + tmp + "/frame " + shape);
  CHECK(r.status == 0, "outputs: " << r.err);
  std::istringstream lines(r.out);
  std::string line;
  std::size_t branches = 0;
  bool stats = false;
  while(std::getline(lines, line)) {
    std::istringstream w(line);
    std::string head;
    w >> head;
    if(head == "branch") {
      std::vector<std::string> f;
      std::string x;
      while(w >> x) f.push_back(x);
      CHECK(f.size() >= 6, "branch line with fewer than 3 generators: " << line);
      ++branches;
    }
    if(head == "max_n_v") stats = true;
  }
  CHECK(branches > 0, "no branch lines");
  CHECK(stats, "--stats has no max_n_v line");
  // the one-shot's task tree: the span is at most the work
  {
    Result t = run(tool + " --stats --threads 2 " + shape);
    std::map<std::string, double> v;
    std::istringstream in(t.out);
    std::string key, value;
    while(in >> key >> value) v[key] = std::strtod(value.c_str(), nullptr);
    CHECK(t.status == 0 && v.count("dc_parts") && v.count("time_work") && v.count("time_span") &&
            v.count("time_parts_sum") && v.count("time_parts_max") && v.count("time_parts_join") && v["dc_parts"] >= 1 &&
            v.count("undecided_ties") && v["undecided_ties"] == 0 &&
            v["time_span"] <= v["time_work"] && v["time_parts_max"] <= v["time_parts_sum"],
          "--stats task tree: " << t.out);
  }
  CHECK(slurp(tmp + "/a.svg").find("<svg") == 0, "SVG");
  // the progressive viewer: one page with the frames (seen in a browser by the html_viewer test)
  Result h = run(tool + " --html " + tmp + "/viewer.html --frames 4 " + shape);
  const std::string page = slurp(tmp + "/viewer.html");
  std::size_t svgs = 0;
  for(std::size_t p = 0; (p = page.find("<svg", p)) != std::string::npos; ++p) ++svgs;
  CHECK(h.status == 0 && page.find("<!DOCTYPE html>") == 0 && svgs == 4 && page.find("type=\"range\"") != std::string::npos,
        "--html: exit status " << h.status << ", " << svgs << " pictures");
  Result hm = run(tool + " --html " + tmp + "/viewer.html " + data + "/invalid/multipolygon_two.wkt");
  CHECK(hm.status == 2, "--html on two polygons: exit status " << hm.status);
  CHECK(slurp(tmp + "/a.geojson").find("{\"type\":\"FeatureCollection\"") == 0, "GeoJSON");
  CHECK(slurp(tmp + "/a.wkt").find("MULTILINESTRING (") == 0, "WKT axis");
  for(const char* f : {"/frame_000.svg", "/frame_001.svg", "/frame_002.svg"})
    CHECK(slurp(tmp + f).find("<svg") == 0, "frame " << f);

  // GeoJSON input gives the same pairs as WKT input
  {
    std::ofstream g(tmp + "/square.geojson");
    g << "{\"type\":\"Polygon\",\"coordinates\":[[[0,0],[2,0],[2,1],[0,1],[0,0]]]}";
  }
  {
    std::ofstream w(tmp + "/square.wkt");
    w << "POLYGON ((0 0, 2 0, 2 1, 0 1, 0 0))";
  }
  Result g = run(tool + " --pairs " + tmp + "/square.geojson");
  Result w = run(tool + " --pairs " + tmp + "/square.wkt");
  CHECK(g.status == 0 && g.out == w.out && !g.out.empty(), "GeoJSON input");
}

// The components of the curves of a WKT MULTILINESTRING, joined where their
// end points are written identically.
int wkt_components(const std::string& wkt, int* lines)
{
  std::vector<std::pair<std::string, std::string> > ends;
  std::size_t pos = wkt.find('(');
  while((pos = wkt.find('(', pos + 1)) != std::string::npos) {
    const std::size_t close = wkt.find(')', pos);
    const std::string body = wkt.substr(pos + 1, close - pos - 1);
    const std::size_t comma = body.find(','), last = body.rfind(',');
    ends.emplace_back(body.substr(0, comma), body.substr(last + 1 + (body[last + 1] == ' ' ? 1 : 0)));
    pos = close;
  }
  std::map<std::string, std::string> parent;
  std::function<std::string(const std::string&)> find = [&](const std::string& x) -> std::string {
    if(parent[x] == x) return x;
    return parent[x] = find(parent[x]);
  };
  for(const auto& e : ends) {
    if(!parent.count(e.first)) parent[e.first] = e.first;
    if(!parent.count(e.second)) parent[e.second] = e.second;
    parent[find(e.first)] = find(e.second);
  }
  int c = 0;
  for(const auto& kv : parent)
    if(find(kv.first) == kv.first) ++c;
  *lines = int(ends.size());
  return c;
}

// Pruning, centerline, width profile, inscribed circle (issue 14).
void analysis_outputs(const std::string& data)
{
  {
    std::ofstream w(tmp + "/rect.wkt");
    w << "POLYGON ((0 0, 10 0, 10 2, 0 2, 0 0))";
  }
  const std::string rect = tmp + "/rect.wkt";
  // a 10 x 2 rectangle: ET = EDF - R reaches 0.5 on the middle line at
  // 0.5 + 1 - sqrt(2) from each branch point; only that curve stays, cut
  Result p = run(tool + " --pairs --branches --prune et=0.5 " + rect);
  CHECK(p.status == 0, "--prune: " << p.err);
  std::istringstream pl(p.out);
  std::string head, a, b;
  double len = 0;
  pl >> head >> a >> b >> len;
  CHECK(head == "pair" && a == "e0.0" && b == "e0.2" && count_lines(p.out) == 1, "--prune et=0.5: " << p.out);
  CHECK(std::fabs(len - (8 - 2 * (1.5 - std::sqrt(2.0)))) < 1e-9, "--prune et=0.5: kept length " << len);
  Result c = run(tool + " --inscribed-circle " + rect);
  CHECK(c.status == 0 && c.out == "circle 1 1 1\n", "--inscribed-circle: " << c.out << c.err);
  Result l = run(tool + " --stats --centerline " + tmp + "/cl.wkt --extend --width " + tmp + "/w.csv " + rect);
  CHECK(l.status == 0, "--centerline: " << l.err);
  const std::string cl = slurp(tmp + "/cl.wkt");
  {
    // from one end of the rectangle to the other along y = 1, through the
    // cut points where ET = sqrt(2) + s - 1 reaches the default threshold
    // R = 1: s = 2 - sqrt(2) from the branch points (1, 1) and (9, 1)
    std::vector<double> xs;
    std::string body = cl.substr(std::min(cl.size(), cl.find('(') + 1));
    std::istringstream in(body);
    double x, y;
    char sep;
    bool on_line = true;
    while(in >> x >> y) {
      xs.push_back(x);
      on_line = on_line && y == 1;
      in >> sep;
    }
    if(xs.size() == 4 && xs[0] > xs[3]) std::reverse(xs.begin(), xs.end());
    const double c = 3 - std::sqrt(2.0);
    CHECK(cl.find("LINESTRING (") == 0 && xs.size() == 4 && on_line && xs[0] == 0 && xs[3] == 10 &&
            std::fabs(xs[1] - c) < 1e-12 && std::fabs(xs[2] - (10 - c)) < 1e-12,
          "--centerline --extend: " << cl);
  }
  std::istringstream wl(slurp(tmp + "/w.csv"));
  std::string row;
  std::getline(wl, row);
  CHECK(row == "s,x,y,width", "--width header: " << row);
  int rows = 0;
  double last = -1;
  while(std::getline(wl, row)) {
    double s, x, y, w;
    char c1, c2, c3;
    std::istringstream r(row);
    r >> s >> c1 >> x >> c2 >> y >> c3 >> w;
    CHECK(r && y == 1 && s > last && w >= 0 && w <= 2 + 1e-12, "--width row: " << row);
    if(x > 1.6 && x < 8.4) CHECK(std::fabs(w - 2) < 1e-12, "--width: width " << w << " at x=" << x);
    last = s;
    ++rows;
  }
  CHECK(rows >= 40, "--width: " << rows << " rows");
  const std::size_t at = l.out.find("\ncenterline_length ");
  CHECK(at != std::string::npos && std::fabs(std::atof(l.out.c_str() + at + 19) - 10) < 1e-12,
        "--stats: centerline_length of the extended centerline");
  CHECK(l.out.find("\ntime_prune ") != std::string::npos, "--stats lacks time_prune");
  CHECK(l.out.find("\npruned_curves ") == std::string::npos, "--stats: pruned_curves without --prune");
  Result s = run(tool + " --stats --prune ratio=0.3 " + rect);
  CHECK(s.out.find("\npruned_curves ") != std::string::npos && s.out.find("\ntime_prune ") != std::string::npos,
        "--stats with --prune");

  // a pruned axis with parabolas: SVG draws them as quadratic Beziers, and
  // curves meet at identical coordinates in the WKT output
  const std::string spiral = data + "/syn_spiral20.wkt";
  Result q = run(tool + " --prune et=0.05 --svg " + tmp + "/p.svg --wkt-out " + tmp + "/p.wkt --geojson " + tmp +
                 "/p.geojson " + spiral);
  CHECK(q.status == 0, "--prune on the spiral: " << q.err);
  const std::string svg = slurp(tmp + "/p.svg");
  CHECK(svg.find("Q") != std::string::npos, "SVG without quadratic Bezier curves");
  int lines = 0;
  const int components = wkt_components(slurp(tmp + "/p.wkt"), &lines);
  CHECK(lines > 10 && components == 1, "pruned WKT: " << lines << " curves in " << components << " components");
  CHECK(slurp(tmp + "/p.geojson").find("\"et\":[") != std::string::npos, "pruned GeoJSON without et");

  for(const std::string& args : {std::string("--prune foo"), std::string("--prune et=-1"),
                                 std::string("--prune ratio=1.5"), std::string("--prune et=1,size=2"),
                                 std::string("--tolerance 0")}) {
    Result r = run(tool + " " + args + " " + rect);
    CHECK(r.status == 2 && count_lines(r.err) == 2, "'" << args << "': exit status " << r.status << ", " << r.err);
  }
}

// The text of the rings of a WKT POLYGON file, "((...), (...))".
std::string polygon_text(const std::string& file)
{
  std::string w = slurp(file);
  return w.substr(w.find('('), w.rfind(')') - w.find('(') + 1);
}

// The pairs of the output lines that start with prefix p<k>:, without it.
std::vector<pma_test::Oracle_curve> pairs_of_polygon(const std::string& out, std::size_t k, std::size_t* lines = nullptr)
{
  const std::string prefix = "p" + std::to_string(k) + ":";
  std::istringstream in(out);
  std::string line, kept;
  std::size_t n = 0;
  while(std::getline(in, line)) {
    std::string t;
    std::istringstream w(line);
    std::string word;
    bool mine = false;
    while(w >> word) {
      if(word.compare(0, prefix.size(), prefix) == 0) {
        mine = true;
        word = word.substr(prefix.size());
      }
      t += (t.empty() ? "" : " ") + word;
    }
    if(mine) {
      kept += t + "\n";
      ++n;
    }
  }
  if(lines) *lines = n;
  std::istringstream k_in(kept);
  return pma_test::parse_pairs(k_in);
}

// The value of `key` in --stats output, or "" if absent.
std::string stats_value(const std::string& out, const std::string& key)
{
  std::istringstream s(out);
  std::string k, v;
  while(s >> k >> v)
    if(k == key) return v;
  return "";
}

// Several polygons in one file (MULTIPOLYGON, GEOMETRYCOLLECTION, GeoJSON
// FeatureCollection): one axis per polygon, ids p<k>:, each against the
// oracle, the same with 1 and 2 threads, the input properties in GeoJSON.
void several_polygons(const std::string& data)
{
  const std::vector<std::string> files = {data + "/syn_comb50.wkt", data + "/syn_spiral20.wkt", data + "/syn_maze20.wkt",
                                          data + "/syn_cheese1k.wkt"};
  std::string multi = "MULTIPOLYGON (" + polygon_text(files[0]) + ", " + polygon_text(files[1]) + ")";
  std::ofstream(tmp + "/multi.wkt") << "GEOMETRYCOLLECTION (" << multi << ", POLYGON EMPTY, POLYGON " << polygon_text(files[2])
                                    << ", POLYGON " << polygon_text(files[3]) << ")\n";
  auto outputs_to = [](const std::string& name) {
    return " --geojson " + tmp + "/" + name + ".geojson --svg " + tmp + "/" + name + ".svg --wkt-out " + tmp + "/" + name +
           ".wkt ";
  };
  Result ours = run(tool + " --pairs --stats --inscribed-circle --threads 2" + outputs_to("multi2") + tmp + "/multi.wkt");
  CHECK(ours.status == 0, "several polygons: exit status " << ours.status << ": " << ours.err);
  CHECK(ours.out.find("\npolygons 4\n") != std::string::npos, "several polygons: --stats has no 'polygons 4'");
  Result one = run(tool + " --pairs --stats --inscribed-circle --threads 1" + outputs_to("multi1") + tmp + "/multi.wkt");
  // The outputs of several polygons on one and two threads: the same bytes
  // (the curves sorted and directed from the axis alone, whatever the parts
  // of the one-shots; the GeoJSON of two threads formatted on every thread
  // and written in order, the other by one writer).  In the GeoJSON, the
  // polygons come in input order, and every curve's end at a branch point
  // has the branch point's radius (the vertex's own).
  for(const char* out : {".geojson", ".svg", ".wkt"})
    CHECK(!slurp(tmp + "/multi1" + out).empty() && slurp(tmp + "/multi1" + out) == slurp(tmp + "/multi2" + out),
          "several polygons: the " << out << " output on one and two threads differ");
  try {
    const auto doc = nlohmann::json::parse(slurp(tmp + "/multi2.geojson"));
    long last = -1;
    std::map<std::string, std::string> branch_radius;   // by polygon and coordinates
    std::multimap<std::string, std::string> end_radius;    // every curve's two ends
    for(const auto& f : doc.at("features")) {
      const auto& pr = f.at("properties");
      const long k = pr.at("polygon").get<long>();
      CHECK(k >= last && k < 4, "several polygons, GeoJSON: polygon " << k << " after " << last);
      last = k;
      const auto& xy = f.at("geometry").at("coordinates");
      if(pr.at("kind") == "branch")
        branch_radius[std::to_string(k) + xy.dump()] = pr.at("radius").dump();
      else
        for(std::size_t e = 0; e < 2; ++e)
          end_radius.emplace(std::to_string(k) + (e ? xy.back() : xy.front()).dump(), pr.at("radius")[e].dump());
    }
    CHECK(last == 3 && branch_radius.size() > 100, "several polygons, GeoJSON: " << branch_radius.size() << " branch points");
    for(const auto& b : branch_radius) {
      const auto ends = end_radius.equal_range(b.first);
      std::size_t curves = 0;
      for(auto e = ends.first; e != ends.second; ++e, ++curves)
        CHECK(e->second == b.second, "several polygons, GeoJSON: branch point " << b.first << " of radius " << b.second
                                     << ", a curve's end there " << e->second);
      CHECK(curves >= 3, "several polygons, GeoJSON: branch point " << b.first << " ends " << curves << " curves");
    }
  } catch(const std::exception& e) {
    CHECK(false, "several polygons, GeoJSON: " << e.what());
  }
  // Pruned axes and centerlines too: the same bytes on one and two threads
  // (the significance's curves directed from their end of smaller (x, y),
  // whatever half-edge the axis lists; the kept parts sorted and directed as
  // the whole curves; the centerline's paths started and ordered by points)
  for(const std::string& f : {tmp + "/multi.wkt", files[3], data + "/c1m_GBR_0.wkt"}) {
    const bool one_polygon = f != tmp + "/multi.wkt";
    std::string outs[2];
    for(int t = 1; t <= 2; ++t) {
      const std::string name = "pruned" + std::to_string(t);
      Result r = run(tool + " --pairs --prune ratio=0.2 --threads " + std::to_string(t) + outputs_to(name) +
                     (one_polygon ? "--centerline " + tmp + "/" + name + ".cl --extend --width " + tmp + "/" + name + ".csv " : "") + f);
      CHECK(r.status == 0 && r.out.find("pair ") != std::string::npos, f << " --prune on " << t << " threads: " << r.err);
      outs[t - 1] = r.out;
      for(const char* out : {".geojson", ".svg", ".wkt", ".cl", ".csv"})
        if(one_polygon || (out != std::string(".cl") && out != std::string(".csv"))) outs[t - 1] += slurp(tmp + "/" + name + out);
    }
    CHECK(outs[0] == outs[1], f << ": --prune, --centerline and --width on one and two threads differ");
  }
  // The GeoJSON or the WKT alone (each polygon's curves sorted when it is
  // written, and written in pieces of 2,048 curves or branch points on every
  // thread: the 26,773 curves of c1m_GBR_0 are 14 pieces) against the same
  // output beside the other outputs (every polygon's curves sorted first):
  // the same bytes, on one and two threads.
  {
    const std::string gbr = data + "/c1m_GBR_0.wkt";
    Result all = run(tool + " --threads 2" + outputs_to("gbr_all") + gbr);
    CHECK(all.status == 0, "c1m_GBR_0 with every output: " << all.err);
    for(const std::string& format : {"geojson", "wkt"}) {
      const std::string with_others = slurp(tmp + "/gbr_all." + format);
      CHECK(with_others.size() > 500000, "c1m_GBR_0: " << with_others.size() << " bytes of " << format);
      for(int t = 1; t <= 2; ++t) {
        const std::string out = tmp + "/gbr" + std::to_string(t) + "." + format;
        Result r = run(tool + " --threads " + std::to_string(t) + (format == "wkt" ? " --wkt-out " : " --geojson ") + out +
                       " " + gbr);
        CHECK(r.status == 0 && slurp(out) == with_others,
              "c1m_GBR_0: the " << format << " alone on " << t << " threads differs from it beside the other outputs");
      }
    }
  }
  auto without_times = [](const std::string& out) {
    std::istringstream in(out);
    std::string line, kept;
    while(std::getline(in, line))
      if(line.compare(0, 5, "pair ") == 0 || line.compare(0, 7, "circle ") == 0 || line.compare(0, 9, "polygons ") == 0)
        kept += line + "\n";   // (the event counts depend on the parts, so on the threads)
    return kept;
  };
  CHECK(one.status == 0 && without_times(one.out) == without_times(ours.out),
        "several polygons: the output with 1 thread differs from the output with 2");
  for(std::size_t k = 0; k < files.size(); ++k) {
    std::size_t lines = 0;
    const auto ca = pairs_of_polygon(ours.out, k, &lines);
    Result theirs = run(sdg_pairs + " " + files[k]);
    std::istringstream b(theirs.out);
    const auto cb = pma_test::parse_pairs(b);
    pma_test::Curve_diff d = pma_test::compare_curves(ca, cb, 1.0);
    CHECK(theirs.status == 0 && !ca.empty() && d.ok(),
          "several polygons: p" << k << " (" << files[k] << ") differs from sdg_pairs\n" << d.report());
    const std::string circle = "circle p" + std::to_string(k) + " ";
    CHECK(ours.out.find("\n" + circle) != std::string::npos || ours.out.compare(0, circle.size(), circle) == 0,
          "several polygons: no line '" << circle << "X Y R'");
  }

  // GeoJSON: a FeatureCollection of a MultiPolygon feature (two parts, one
  // with a hole), a feature without geometry, a point and a line (skipped
  // with a warning) and a Polygon feature; the output features carry their
  // input feature's properties
  std::ofstream(tmp + "/fc.geojson") << R"({"type": "FeatureCollection", "features": [
    {"type": "Feature", "properties": {"name": "A", "length": "input's", "pop": 12},
     "geometry": {"type": "MultiPolygon", "coordinates": [[[[0, 0], [4, 0], [4, 3], [0, 3], [0, 0]], [[1, 1], [1, 2], [2, 2], [2, 1], [1, 1]]],
                                                          [[[10, 0], [13, 0], [13, 3], [10, 0]]]]}},
    {"type": "Feature", "properties": {"name": "nowhere"}, "geometry": null},
    {"type": "Feature", "properties": {"name": "label"}, "geometry": {"type": "Point", "coordinates": [2, 2]}},
    {"type": "Feature", "properties": {"name": "road"}, "geometry": {"type": "LineString", "coordinates": [[0, 0], [9, 9]]}},
    {"type": "Feature", "properties": {"name": "B", "tags": {"x": [1, 2]}},
     "geometry": {"type": "Polygon", "coordinates": [[[20, 0], [22, 0], [21, 1], [20, 0]]]}}]})";
  Result g = run(tool + " --pairs --geojson " + tmp + "/fc_axis.geojson " + tmp + "/fc.geojson");
  CHECK(g.status == 0, "FeatureCollection: exit status " << g.status << ": " << g.err);
  // (polygons this small are one part each: their features come in one
  // order, and the file of two threads is the one writer's byte for byte)
  for(int t = 1; t <= 2; ++t) {
    Result r = run(tool + " --threads " + std::to_string(t) + " --geojson " + tmp + "/fc_axis" + std::to_string(t) +
                   ".geojson " + tmp + "/fc.geojson");
    CHECK(r.status == 0, "FeatureCollection on " << t << " threads: exit status " << r.status << ": " << r.err);
  }
  CHECK(!slurp(tmp + "/fc_axis1.geojson").empty() && slurp(tmp + "/fc_axis1.geojson") == slurp(tmp + "/fc_axis2.geojson"),
        "FeatureCollection: the GeoJSON of one and two threads differ");
  CHECK(count_lines(g.err) == 1 && g.err.find("warning: " + tmp + "/fc.geojson: skipped 2 point and line geometries") !=
                                       std::string::npos && g.err.find("(the first: Point in feature 2)") != std::string::npos,
        "FeatureCollection: the skipped point and line: " << g.err);
  Result gs = run(tool + " --stats " + tmp + "/fc.geojson");
  CHECK(gs.status == 0 && stats_value(gs.out, "polygons") == "3" && stats_value(gs.out, "skipped_geometries") == "2",
        "FeatureCollection --stats: polygons " << stats_value(gs.out, "polygons") << ", skipped_geometries "
        << stats_value(gs.out, "skipped_geometries"));
  // nothing but points and lines: the first is named
  std::ofstream(tmp + "/points.geojson") << R"({"type": "FeatureCollection", "features": [
    {"type": "Feature", "geometry": {"type": "Point", "coordinates": [2, 2]}}]})";
  check_bad_input(tmp + "/points.geojson", "not a polygon: found Point in feature 0");
  std::size_t per_polygon[3] = {0, 0, 0};
  for(std::size_t k = 0; k < 3; ++k) pairs_of_polygon(g.out, k, &per_polygon[k]);
  try {
    const auto doc = nlohmann::json::parse(slurp(tmp + "/fc_axis.geojson"));
    CHECK(doc.at("type") == "FeatureCollection", "FeatureCollection output: type");
    std::size_t curves[3] = {0, 0, 0}, branches = 0;
    for(const auto& f : doc.at("features")) {
      const auto& pr = f.at("properties");
      const long k = pr.at("polygon").get<long>();
      CHECK(k >= 0 && k < 3, "FeatureCollection output: polygon " << k);
      if(k < 0 || k > 2) continue;
      CHECK(pr.at("name") == (k < 2 ? "A" : "B"), "FeatureCollection output: polygon " << k << " has name " << pr.at("name"));
      if(k < 2) CHECK(pr.at("pop") == 12, "FeatureCollection output: 'pop' lost");
      else CHECK(pr.at("tags").at("x").size() == 2, "FeatureCollection output: 'tags' lost");
      for(const auto& id : pr.at("generators"))
        CHECK(id.get<std::string>().rfind("p" + std::to_string(k) + ":", 0) == 0, "FeatureCollection output: id " << id);
      if(pr.at("kind") == "curve") {
        ++curves[k];
        CHECK(pr.at("length").is_number() && pr.at("radius").size() == 2, "FeatureCollection output: curve properties");
      } else {
        ++branches;
        CHECK(pr.at("kind") == "branch" && pr.at("radius").is_number(), "FeatureCollection output: branch properties");
      }
    }
    for(std::size_t k = 0; k < 3; ++k)
      CHECK(curves[k] == per_polygon[k] && curves[k] > 0,
            "FeatureCollection output: polygon " << k << " has " << curves[k] << " curves, --pairs " << per_polygon[k]);
    CHECK(branches > 0, "FeatureCollection output: no branch point");
  } catch(const std::exception& e) {
    CHECK(false, "FeatureCollection output: " << e.what());
  }

  // an invalid polygon among several is named; progressive runs need one polygon
  std::ofstream(tmp + "/bad.wkt") << "MULTIPOLYGON (((0 0, 1 0, 1 1, 0 0)), ((2 2, 4 2, 2 4, 4 4, 2 2)))\n";
  Result bad = run(tool + " --pairs " + tmp + "/bad.wkt");
  CHECK(bad.status == 2 && count_lines(bad.err) == 1 &&
          bad.err.find("polygon 1: self-intersection: ring 0 edge") != std::string::npos,
        "invalid polygon 1: exit status " << bad.status << ", " << bad.err);
  Result step = run(tool + " --step 2 " + tmp + "/multi.wkt");
  CHECK(step.status == 2, "--step on several polygons: exit status " << step.status);
}

// --repair (when the tool has GEOS): invalid polygons are computed, their
// axes are those of the polygons --repaired-out writes, against the oracle.
void repair(const std::string& data)
{
  Result h = run(tool + " --help");
  if(h.out.find("--repair") == std::string::npos) return;
  Result probe = run(tool + " --repair " + data + "/syn_comb50.wkt");
  if(probe.status == 2 && probe.err.find("needs GEOS") != std::string::npos) {
    std::cout << "repair: this build has no GEOS, not tested\n";
    return;
  }
  for(const char* f : {"crossing.wkt", "overlap.wkt", "spike.wkt", "zero_length_edge.wkt", "hole_outside.wkt",
                       "hole_in_hole.wkt", "t_crossing.wkt", "crossing_hole_groups.wkt", "holes_around_island.wkt"}) {
    const std::string file = data + "/invalid/" + f, fixed = tmp + "/repaired.wkt";
    Result r = run(tool + " --repair --repaired-out " + fixed + " --pairs --stats " + file);
    CHECK(r.status == 0, f << " --repair: exit status " << r.status << ": " << r.err);
    CHECK(r.out.find("\nrepaired_polygons 1\n") != std::string::npos, f << " --repair: no 'repaired_polygons 1'");
    Result theirs = run(sdg_pairs + " " + fixed);
    if(theirs.status != 0) {   // several polygons: compared one by one in several_polygons()
      CHECK(r.out.find("pair p0:") != std::string::npos, f << " --repair: " << theirs.err);
      continue;
    }
    std::istringstream a(r.out), b(theirs.out);
    pma_test::Curve_diff d = pma_test::compare_curves(pma_test::parse_pairs(a), pma_test::parse_pairs(b), 10.0);
    CHECK(d.ok(), f << " --repair: the pairs differ from sdg_pairs on the repaired polygon\n" << d.report());
  }
  // local repairs with GEOS's structure semantics, the rings left untouched kept
  // as given: a hole outside the outer ring becomes a polygon (with the holes
  // inside it united with it), one inside another hole adds nothing,
  // zero-length edges and spikes are dropped; the outer ring inside a hole
  // leaves nothing; the groups of rings that cross are found in one pass and
  // each mended at once (two groups of holes, a hole across the outer ring,
  // a hole left as given), but holes whose union encloses an island are
  // left to GEOS on the whole polygon.  As GEOS 3.11 does, a hole is a hole
  // if it meets the outer ring as given, else a polygon: one inside a hole
  // across the outer ring adds nothing, one outside it that crosses such a
  // hole is a polygon (the areas of GEOS on the whole polygon)
  for(const auto& c : std::vector<std::array<std::string, 2> >{
        {"hole_outside.wkt", "MULTIPOLYGON (((0 0, 4 0, 4 4, 0 4, 0 0)), ((5 5, 6 5, 6 6, 5 5)))"},
        {"hole_outside_nested.wkt", "MULTIPOLYGON (((0 0, 4 0, 4 4, 0 4, 0 0)), ((6 1, 9 1, 9 4, 6 4, 6 1)))"},
        {"hole_in_hole.wkt", "POLYGON ((0 0, 10 0, 10 10, 0 10, 0 0), (1 1, 1 9, 9 9, 9 1, 1 1))"},
        {"spike.wkt", "POLYGON ((0 0, 4 0, 4 4, 2 4, 2 5, 0 4, 0 0))"},
        {"zero_length_edge.wkt", "POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0))"},
        {"spike_hole.wkt", "POLYGON ((0 0, 10 0, 10 10, 0 10, 0 0), (1 1, 1 3, 3 3, 3 1, 1 1))"},
        {"crossing_hole_groups.wkt",
         "POLYGON ((0 20, 20 20, 20 7, 18 7, 18 5, 20 5, 20 0, 0 0, 0 20), (1 4, 3 4, 3 6, 6 6, 6 3, 4 3, 4 1, 1 1, 1 4), "
         "(8 10, 9 10, 9 11, 11 11, 11 9, 10 9, 10 8, 8 8, 8 10), (14 14, 14 15, 15 15, 15 14, 14 14))"},
        {"holes_around_island.wkt",
         "MULTIPOLYGON (((0 20, 20 20, 20 0, 0 0, 0 20), (1 3, 1 1, 3 1, 3 2, 4 2, 4 4, 2 4, 2 3, 1 3), "
         "(5 15, 5 5, 15 5, 15 6, 17 6, 17 14, 15 14, 15 15, 5 15)), ((8 12, 14 12, 14 8, 8 8, 8 12)))"},
        {"hole_in_hole_across_outer.wkt", "POLYGON ((0 10, 10 10, 10 8, 6 8, 6 2, 10 2, 10 0, 0 0, 0 10))"},
        {"hole_outside_across_hole.wkt",
         "MULTIPOLYGON (((0 10, 10 10, 10 6, 8 6, 8 4, 10 4, 10 0, 0 0, 0 10)), ((12 3, 14 3, 14 7, 12 7, 12 3)))"}}) {
    Result r = run(tool + " --repair --repaired-out " + tmp + "/dropped.wkt " + data + "/invalid/" + c[0]);
    CHECK(r.status == 0 && slurp(tmp + "/dropped.wkt") == c[1] + "\n",
          c[0] << " --repair: " << r.err << slurp(tmp + "/dropped.wkt"));
  }
  // a one-shot run repairs each polygon in the task that computes it, a
  // progressive one repairs first: the same polygon, the same axis
  for(const char* f : {"spike.wkt", "overlap.wkt", "hole_in_hole.wkt", "spike_hole.wkt"}) {
    Result one = run(tool + " --repair --pairs " + data + "/invalid/" + f);
    Result progressive = run(tool + " --repair --progressive region --pairs " + data + "/invalid/" + f);
    CHECK(one.status == 0 && progressive.status == 0 && one.out == progressive.out && one.out.find("pair ") == 0,
          f << " --repair: one-shot and progressive differ: " << one.err << progressive.err);
  }
  Result empty = run(tool + " --repair " + data + "/invalid/outer_inside_hole.wkt");
  CHECK(empty.status == 2 && empty.err.find("no polygon of positive area is left") != std::string::npos,
        "outer_inside_hole.wkt --repair: " << empty.err);
  // a valid polygon is not touched
  Result v = run(tool + " --repair --stats --pairs " + data + "/syn_comb50.wkt");
  Result w = run(tool + " --pairs " + data + "/syn_comb50.wkt");
  CHECK(v.status == 0 && v.out.find("\nrepaired_polygons 0\n") != std::string::npos &&
          v.out.compare(0, w.out.size(), w.out) == 0, "--repair changed a valid polygon");
  Result u = run(tool + " --repaired-out " + tmp + "/x.wkt " + data + "/syn_comb50.wkt");
  CHECK(u.status == 2, "--repaired-out without --repair: exit status " << u.status);
}

// A large input (over 512 KB) runs again with glibc's malloc on transparent
// huge pages where the kernel gives them on request: the axis is the
// oracle's and the same as without; GLIBC_TUNABLES that names the setting
// turns it off, and other tunables the user set are kept.
// The file `path` made at least `bytes` long by blanks after its commas.
void pad_with_blanks(const std::string& path, const std::string& out, std::size_t bytes)
{
  const std::string text = slurp(path);
  const std::size_t commas = std::count(text.begin(), text.end(), ',');
  const std::string blanks(bytes / (std::max)(commas, std::size_t(1)) + 1, ' ');
  std::ofstream f(out);
  for(char c : text) {
    f << c;
    if(c == ',') f << blanks;
  }
}

// A large input (over 512 KB, INPUT and --union's file together) runs again
// with glibc's malloc on transparent huge pages where the kernel gives them
// on request: the axis is the oracle's and the same as without;
// GLIBC_TUNABLES that names the setting turns it off, and another tunable the
// user set does not.  Every run starts with GLIBC_TUNABLES cleared or set
// here, so a tunable exported around the tests does not change what is
// expected.  `sanitized`: the tool is built with a sanitizer (its own
// allocator: never huge pages).
void huge_pages(const std::string& data, bool sanitized)
{
  const std::string file = tmp + "/large.wkt";
  {
    std::ofstream f(tmp + "/small.wkt");
    f.precision(17);
    // (2,000 vertices, the file made large by blanks between them: the size
    // decides, and the sanitized build runs this too)
    const int n = 2000;
    const double pi = 3.14159265358979323846;
    f << "POLYGON ((";
    for(int i = 0; i <= n; ++i) {
      const double t = 2 * pi * (i % n) / n, r = 1 + 0.25 * std::sin(7 * t) + 0.05 * std::sin(31 * t);
      f << (i ? ", " : "") << r * std::cos(t) << " " << r * std::sin(t);
    }
    f << "))\n";
  }
  pad_with_blanks(tmp + "/small.wkt", file, 600 * 1024);
  CHECK(slurp(file).size() > 512 * 1024, "the large input is too small: " << slurp(file).size() << " bytes");
  pairs_against_oracle(file, {-1});
  const std::string cleared = "env -u GLIBC_TUNABLES ";
  const Result on = run(cleared + tool + " --stats --pairs " + file);
  const Result off = run("GLIBC_TUNABLES=glibc.malloc.hugetlb=0 " + tool + " --stats --pairs " + file);
  const Result kept = run("GLIBC_TUNABLES=glibc.malloc.trim_threshold=268435456 " + tool + " --stats --pairs " + file);
  for(const Result* r : {&on, &off, &kept}) CHECK(r->status == 0, "huge pages: exit status " << r->status << ": " << r->err);
  auto pairs = [](const std::string& out) { return out.substr(0, out.find("input_vertices ")); };
  CHECK(!pairs(on.out).empty() && pairs(on.out) == pairs(off.out) && pairs(on.out) == pairs(kept.out),
        "huge pages: --pairs differ with and without");
  CHECK(stats_value(off.out, "huge_pages") == "0", "GLIBC_TUNABLES=glibc.malloc.hugetlb=0: huge_pages " << stats_value(off.out, "huge_pages"));
  // --union: a small INPUT and a large other file
  const std::string d = data + "/union/";
  pad_with_blanks(d + "star_b.wkt", tmp + "/star_b_large.wkt", 600 * 1024);
  const Result union_small = run(cleared + tool + " --stats --pairs --union " + d + "star_b.wkt " + d + "star_a.wkt");
  const Result union_large = run(cleared + tool + " --stats --pairs --union " + tmp + "/star_b_large.wkt " + d + "star_a.wkt");
  CHECK(union_small.status == 0 && union_large.status == 0 && !pairs(union_small.out).empty() &&
          pairs(union_small.out) == pairs(union_large.out),
        "huge pages, --union: " << union_small.err << union_large.err);
  CHECK(stats_value(union_small.out, "huge_pages") == "0", "--union of small files: huge_pages " << stats_value(union_small.out, "huge_pages"));
  // where the kernel gives huge pages on request (THP "madvise") and glibc
  // has the setting (2.35), a large input gets them
  const std::string thp = slurp("/sys/kernel/mm/transparent_hugepage/enabled");
  const char* preload = std::getenv("LD_PRELOAD");
  int major = 0, minor = 0;
#ifdef __GLIBC__
  std::sscanf(gnu_get_libc_version(), "%d.%d", &major, &minor);
#endif
  const bool expected = (major > 2 || (major == 2 && minor >= 35)) && thp.find("[madvise]") != std::string::npos && !sanitized &&
                        !(preload && *preload);
  const std::string v = stats_value(on.out, "huge_pages"), w = stats_value(kept.out, "huge_pages"),
                    u = stats_value(union_large.out, "huge_pages");
  CHECK(v == "0" || v == "1", "huge_pages missing from --stats");
  CHECK(v == (expected ? "1" : "0"), "a large input: huge_pages " << v << ", expected " << expected);
  CHECK(w == v, "with another tunable set: huge_pages " << w << ", without " << v);
  CHECK(u == v, "--union with a large file: huge_pages " << u << ", a large input " << v);
  // a small input never
  const Result small = run(cleared + tool + " --stats " + data + "/syn_comb50.wkt");
  CHECK(small.status == 0 && stats_value(small.out, "huge_pages") == "0",
        "a small input: huge_pages " << stats_value(small.out, "huge_pages"));
}

// The tool's build with fused multiply-add (TOOL.fma, where CMake made it and
// the CPU runs it) gives the same output, bit for bit, as the baseline build
// on shapes that take every stage of the filtered traits, the double model,
// region growing, boundary evolution, touching rings, --union and the
// one-shot's way out; --stats names the build that ran (`instruction_set`):
// PMA_TOOL_INSTRUCTION_SET=x86-64 the baseline, =x86-64+fma that build where
// the CPU has it, unset that build for a large input only; another value is
// a usage error.
void instruction_sets(const std::string& data)
{
  bool fma_runs = false, chooses = false;
#if defined(__x86_64__) && defined(__linux__) && defined(__GLIBC__) && defined(__GNUC__)
  chooses = true;
  __builtin_cpu_init();
  const char* preload = std::getenv("LD_PRELOAD");
  fma_runs = __builtin_cpu_supports("avx") && __builtin_cpu_supports("fma") && !(preload && *preload) &&
             access((tool + ".fma").c_str(), X_OK) == 0;
#endif
  const std::string base = "env -u GLIBC_TUNABLES PMA_TOOL_INSTRUCTION_SET=x86-64 " + tool,
                    with_fma = "env -u GLIBC_TUNABLES PMA_TOOL_INSTRUCTION_SET=x86-64+fma " + tool,
                    plain = "env -u GLIBC_TUNABLES -u PMA_TOOL_INSTRUCTION_SET " + tool;
  const std::string d = data + "/";
  const std::vector<std::string> compared = {"--pairs --branches " + d + "syn_comb50.wkt", "--pairs --branches " + d + "syn_star2k.wkt",
       "--pairs --branches --threads 2 " + d + "c1m_GBR_0.wkt", "--pairs --branches --step 400 " + d + "syn_maze20.wkt",
       "--pairs --branches --progressive boundary --step 60 " + d + "syn_spiral20.wkt",
       "--pairs --branches --traits epick " + d + "double_model/grid_perturbed_crop37.wkt",
       "--pairs --branches --traits epick --threads 2 " + d + "c1m_GBR_0.wkt",
       "--pairs --branches " + d + "glyphs/DejaVuSans_at_0.wkt", "--pairs --branches " + d + "quantized/l10m_ESH_202_0.wkt",
       "--pairs --branches " + d + "touching/c1m_PNG_21.wkt", "--pairs --branches --threads 2 " + d + "regressions/circle_hole_parts_stop.wkt",
       "--pairs --branches --union " + d + "union/star_b.wkt " + d + "union/star_a.wkt",
       "--inscribed-circle --prune ratio=0.5 --pairs " + d + "syn_cheese1k.wkt"};
  // (only where the other build runs: else both would be this one)
  for(const std::string& args : fma_runs ? compared : std::vector<std::string>()) {
    const Result a = run(base + " " + args), b = run(with_fma + " " + args);
    CHECK(a.status == 0 && b.status == 0 && !a.out.empty() && a.out == b.out,
          "the x86-64 and x86-64+fma builds differ: " << args << ": " << a.err << b.err);
  }
  const std::string small = d + "syn_comb50.wkt", large = tmp + "/comb_large.wkt";
  pad_with_blanks(small, large, 600 * 1024);
#ifdef __x86_64__
  const std::string baseline = "x86-64";
#else
  const std::string baseline = "default";
#endif
  const std::string runs_fma = fma_runs ? "x86-64+fma" : baseline;
  auto level = [&](const std::string& cmd, const std::string& file) {
    const Result r = run(cmd + " --stats " + file);
    CHECK(r.status == 0, cmd << " --stats " << file << ": exit status " << r.status << ": " << r.err);
    return stats_value(r.out, "instruction_set");
  };
  CHECK(level(base, large) == baseline, "PMA_TOOL_INSTRUCTION_SET=x86-64: instruction_set " << level(base, large));
  CHECK(level(with_fma, small) == runs_fma, "PMA_TOOL_INSTRUCTION_SET=x86-64+fma: instruction_set " << level(with_fma, small)
                                                                                              << ", expected " << runs_fma);
  CHECK(level(plain, small) == baseline, "a small input: instruction_set " << level(plain, small));
  CHECK(level(plain, large) == runs_fma, "a large input: instruction_set " << level(plain, large) << ", expected " << runs_fma);
  if(chooses) {
    const Result bad = run("env PMA_TOOL_INSTRUCTION_SET=avx9 " + tool + " " + small);
    CHECK(bad.status == 2 && bad.err.find("PMA_TOOL_INSTRUCTION_SET must be x86-64 or x86-64+fma") != std::string::npos,
          "PMA_TOOL_INSTRUCTION_SET=avx9: exit status " << bad.status << ": " << bad.err);
  }
}

} // namespace

// A plate: a square with 75 x 75 small hexagonal holes (33,754 vertices,
// over the 32,768 from which a one-shot on two threads splits its
// triangulation).  Its outer ring has no chord, so the triangulation is
// split along a path through holes; the axis is the oracle's, and the same
// on one thread, which does not split.
void split_along_holes()
{
  const std::string f = tmp + "/plate.wkt";
  {
    std::ofstream out(f);
    out.precision(17);
    const int k = 75;
    out << "POLYGON ((0 0, " << k << " 0, " << k << " " << k << ", 0 " << k << ", 0 0)";
    for(int i = 0; i < k; ++i)
      for(int j = 0; j < k; ++j) {
        // (moved and turned a little from cell to cell: no three points on a line)
        const double cx = i + 0.5 + 0.1 * std::sin(1.3 * i + 0.7 * j), cy = j + 0.5 + 0.1 * std::cos(0.9 * i - 1.1 * j);
        const double turn = 0.2 + 0.05 * std::sin(double(i * k + j));
        out << ", (";
        for(int v = 0; v <= 6; ++v) {   // clockwise
          const double a = turn - (v % 6) * 3.14159265358979323846 / 3;
          out << (v ? ", " : "") << cx + 0.3 * std::cos(a) << " " << cy + 0.3 * std::sin(a);
        }
        out << ")";
      }
    out << ")\n";
  }
  Result two = run(tool + " --threads 2 --stats " + f);
  const std::string holes = stats_value(two.out, "triangulation_split_holes");
  CHECK(two.status == 0 && stats_value(two.out, "triangulation_split") == "1" && !holes.empty() && std::stol(holes) > 0,
        f << " on two threads: triangulation_split " << stats_value(two.out, "triangulation_split")
          << ", triangulation_split_holes " << holes);
  // (the one-shot's triangles are not region growing's: `steps` counted
  // from a triangulation of the rings rebuilt from the axis)
  // (with --repair, the one-shot is given the polygon as valid and its rings
  // in the repairs' task: it does not split the triangulation, and counts
  // the steps itself)
  Result step = run(tool + " --stats --step 0 " + f);
  for(const std::string options : {"", " --repair"}) {
    Result r = options.empty() ? two : run(tool + " --threads 2 --stats" + options + " " + f);
    if(!options.empty() && r.status != 0 && r.err.find("needs GEOS") != std::string::npos) continue;
    CHECK(step.status == 0 && r.status == 0 && !stats_value(r.out, "steps").empty() &&
            stats_value(r.out, "steps") == stats_value(step.out, "steps"),
          f << ": steps " << stats_value(r.out, "steps") << " in one shot on two threads" << options << ", "
            << stats_value(step.out, "steps") << " at --step 0");
  }
  Result p1 = run(tool + " --threads 1 --pairs --branches " + f), p2 = run(tool + " --threads 2 --pairs --branches " + f);
  CHECK(p1.status == 0 && p2.status == 0 && !p1.out.empty() && p1.out == p2.out,
        f << ": the pairs and branch points on one and two threads differ");
  pairs_against_oracle(f, {-1}, "--threads 2");
}

int main(int argc, char** argv)
{
  // --sanitized: TOOL is built with a sanitizer
  const bool sanitized = argc == 5 && std::string(argv[4]) == "--sanitized";
  if(argc != 4 && !sanitized) {
    std::cerr << "usage: test_tool TOOL SDG_PAIRS DATA_DIR [--sanitized]\n";
    return 2;
  }
  tool = argv[1];
  sdg_pairs = argv[2];
  const std::string data = argv[3];
  char dir[] = "/tmp/pma_test_tool_XXXXXX";
  if(!mkdtemp(dir)) return 2;
  tmp = dir;

  bad_inputs(data);
  usage_errors(data);
  pairs_against_oracle(data + "/syn_comb50.wkt", {-1, 0, 1, 17, 100, 150});
  pairs_against_oracle(data + "/syn_maze20.wkt", {-1, 3, 120, 400});
  pairs_against_oracle(data + "/syn_spiral20.wkt", {-1, 50});
  // rings touching at vertices (OGC touching holes, pinches, inverted islands):
  // synthetic shapes and real outlines with such vertices (OpenStreetMap, ODbL)
  for(const char* f : {"syn_hole_corner", "syn_hole_corner_ccw", "syn_hole_edge_vertex", "syn_two_holes",
                       "syn_three_holes", "syn_pinch", "syn_island", "syn_island_min", "syn_reflex_touch",
                       "syn_hole_at_reflex", "syn_pinch_small", "syn_touch_at_smallest", "c1m_AUS_33982", "c1m_NGA_47424", "c1m_USA_24161", "c1m_NOR_55654",
                       // a vertex inside an edge (T's)
                       "syn_t_self", "syn_t_hole_edge", "syn_t_two_holes_one_point", "syn_t_hole_hole", "syn_t_notch", "l10m_RUS_30511",
                       "syn_t_both_sides", "syn_t_both_sides_two_holes", "syn_t_both_sides_square"})
    pairs_against_oracle(data + "/touching/" + f + ".wkt", {-1, 1, 2, 3, 5, 50, 400});
  pairs_against_oracle(data + "/touching/c1m_PNG_21.wkt", {-1, 3000});
  // parts that cross thousands of cells a triangle on two threads: the
  // divide and conquer stops, boundary evolution computes the axis (the
  // oracle test compares it), the same pairs as on one thread
  {
    const std::string f = data + "/regressions/circle_hole_parts_stop.wkt";
    Result two = run(tool + " --threads 2 --stats " + f);
    CHECK(two.status == 0 && stats_value(two.out, "oneshot_dc_abandoned") == "1" &&
            stats_value(two.out, "oneshot_boundary_evolution") == "1",
          f << " on two threads: oneshot_dc_abandoned " << stats_value(two.out, "oneshot_dc_abandoned")
            << ", oneshot_boundary_evolution " << stats_value(two.out, "oneshot_boundary_evolution"));
    Result p1 = run(tool + " --threads 1 --pairs " + f), p2 = run(tool + " --threads 2 --pairs " + f);
    CHECK(p1.status == 0 && p2.status == 0 && !p1.out.empty() && p1.out == p2.out,
          f << ": the pairs on one and two threads differ");
  }
  split_along_holes();
  // a one-shot's `steps` (counted from its triangles, or from a
  // triangulation of its own) is the progressive run's
  // (--repair: each polygon checked apart, and given to the one-shot as valid)
  const bool with_geos = run(tool + " --repair " + data + "/syn_comb50.wkt").status == 0;
  for(const std::string f : {"/syn_cheese1k.wkt", "/touching/syn_pinch.wkt", "/touching/c1m_PNG_21.wkt"}) {
    Result step = run(tool + " --stats --step 0 " + data + f);
    for(const std::string options : {"", " --threads 1", " --threads 2", " --repair"}) {
      if(options == " --repair" && !with_geos) continue;
      Result one = run(tool + " --stats" + options + " " + data + f);
      CHECK(one.status == 0 && step.status == 0 && !stats_value(one.out, "steps").empty() &&
              stats_value(one.out, "steps") == stats_value(step.out, "steps"),
            f << ": steps " << stats_value(one.out, "steps") << " in one shot" << options << ", "
              << stats_value(step.out, "steps") << " at --step 0");
    }
  }
  outputs(data);
  boundary_evolution(data);
  analysis_outputs(data);
  several_polygons(data);
  union_of_two(data);
  repair(data);
  huge_pages(data, sanitized);
  instruction_sets(data);

  std::system((std::string("rm -rf ") + tmp).c_str());
  return pma_test::report("test_tool");
}
