// Test-only comparison of two lists of medial curves (canonical ids, algorithm.md
// section 7), and a parser for the "pair A B L" lines the command-line tools print.

#ifndef PMA_TEST_COMPARE_CURVES_H
#define PMA_TEST_COMPARE_CURVES_H

#include <pma_test/sdg_oracle.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <istream>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace pma_test {

struct Curve_diff
{
  std::vector<std::string> only_in_a, only_in_b, length_mismatch;

  bool ok() const { return only_in_a.empty() && only_in_b.empty() && length_mismatch.empty(); }

  /// A multi-line human-readable report (empty when ok()).
  std::string report() const
  {
    std::ostringstream out;
    if(!only_in_a.empty()) {
      out << only_in_a.size() << " curve(s) only in a:\n";
      for(const std::string& s : only_in_a) out << "  " << s << "\n";
    }
    if(!only_in_b.empty()) {
      out << only_in_b.size() << " curve(s) only in b:\n";
      for(const std::string& s : only_in_b) out << "  " << s << "\n";
    }
    if(!length_mismatch.empty()) {
      out << length_mismatch.size() << " length mismatch(es):\n";
      for(const std::string& s : length_mismatch) out << "  " << s << "\n";
    }
    return out.str();
  }
};

namespace compare_detail {

inline std::string format_length(double v)
{
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%.17g", v);
  return buf;
}

inline std::string describe(const std::string& a, const std::string& b, double l)
{
  return a + " " + b + " " + format_length(l);
}

} // namespace compare_detail

/// Multiset comparison keyed by the pair (a, b) (order inside the pair does not matter).
/// Curves shorter than tol_degenerate = 1e-9 * bbox_diagonal may be present in one list and
/// not in the other; all other curves must match one-to-one by pair (multiplicity counts),
/// and matched lengths must agree within length_tol * bbox_diagonal. Within one pair the
/// curves of a and b are matched so as to report as few problems as possible (a dynamic
/// programme over the lengths in sorted order, which is optimal in one dimension); a
/// degenerate curve may be matched with a non-degenerate one whose length agrees.
inline Curve_diff compare_curves(const std::vector<Oracle_curve>& a,
                                 const std::vector<Oracle_curve>& b, double bbox_diagonal,
                                 double length_tol = 1e-6)
{
  using compare_detail::describe;
  using compare_detail::format_length;
  const double tol_degenerate = 1e-9 * bbox_diagonal;
  const double tol_length = length_tol * bbox_diagonal;
  typedef std::pair<std::string, std::string> Key;
  std::map<Key, std::pair<std::vector<double>, std::vector<double> > > by_key;
  for(const Oracle_curve& c : a) {
    const Key k = (c.b < c.a) ? Key(c.b, c.a) : Key(c.a, c.b);
    by_key[k].first.push_back(c.length);
  }
  for(const Oracle_curve& c : b) {
    const Key k = (c.b < c.a) ? Key(c.b, c.a) : Key(c.a, c.b);
    by_key[k].second.push_back(c.length);
  }

  Curve_diff diff;
  for(auto& kv : by_key) {
    const Key& k = kv.first;
    std::vector<double> la = kv.second.first, lb = kv.second.second;
    std::sort(la.begin(), la.end());
    std::sort(lb.begin(), lb.end());
    const std::size_t p = la.size(), q = lb.size();
    auto optional = [&](double l) { return l < tol_degenerate; }; // NaN is never optional
    auto agree = [&](double x, double y) { return std::abs(x - y) <= tol_length; };
    // cost[i][j]: fewest problems matching la[i..] with lb[j..]
    std::vector<std::vector<std::size_t> > cost(p + 1, std::vector<std::size_t>(q + 1, 0));
    for(std::size_t i = p + 1; i-- > 0;)
      for(std::size_t j = q + 1; j-- > 0;) {
        if(i == p && j == q) continue;
        std::size_t best = static_cast<std::size_t>(-1);
        if(i < p) best = (std::min)(best, cost[i + 1][j] + (optional(la[i]) ? 0 : 1));
        if(j < q) best = (std::min)(best, cost[i][j + 1] + (optional(lb[j]) ? 0 : 1));
        if(i < p && j < q) best = (std::min)(best, cost[i + 1][j + 1] + (agree(la[i], lb[j]) ? 0 : 1));
        cost[i][j] = best;
      }
    // follow an optimal path and report
    std::size_t i = 0, j = 0;
    while(i < p || j < q) {
      if(i < p && j < q && cost[i][j] == cost[i + 1][j + 1] + (agree(la[i], lb[j]) ? 0 : 1)) {
        if(!agree(la[i], lb[j]))
          diff.length_mismatch.push_back(k.first + " " + k.second + " " + format_length(la[i]) +
                                         " vs " + format_length(lb[j]));
        ++i;
        ++j;
      } else if(i < p && cost[i][j] == cost[i + 1][j] + (optional(la[i]) ? 0 : 1)) {
        if(!optional(la[i])) diff.only_in_a.push_back(describe(k.first, k.second, la[i]));
        ++i;
      } else {
        if(!optional(lb[j])) diff.only_in_b.push_back(describe(k.first, k.second, lb[j]));
        ++j;
      }
    }
  }
  return diff;
}

/// Parses lines "pair A B L" (other lines are ignored) as printed by the command-line
/// tools; A and B are put in std::string order.
inline std::vector<Oracle_curve> parse_pairs(std::istream& in)
{
  std::vector<Oracle_curve> curves;
  std::string line;
  while(std::getline(in, line)) {
    std::istringstream ls(line);
    std::string tag, a, b;
    double l;
    if(!(ls >> tag) || tag != "pair") continue;
    if(!(ls >> a >> b >> l)) continue;
    if(b < a) std::swap(a, b);
    curves.push_back(Oracle_curve{a, b, l});
  }
  return curves;
}

} // namespace pma_test

#endif // PMA_TEST_COMPARE_CURVES_H
