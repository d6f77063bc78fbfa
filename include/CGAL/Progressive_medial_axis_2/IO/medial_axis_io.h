// Copyright (c) 2026 The Progressive_medial_axis_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Naming and text output of a medial axis: canonical generator ids, the
// shape's rings, the list of medial curves and of branch points.

#ifndef CGAL_PROGRESSIVE_MEDIAL_AXIS_2_IO_MEDIAL_AXIS_IO_H
#define CGAL_PROGRESSIVE_MEDIAL_AXIS_2_IO_MEDIAL_AXIS_IO_H

#include <CGAL/Progressive_medial_axis_2/Medial_axis_2.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <ostream>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace PMA2 {

/*!
\ingroup PkgProgressiveMedialAxis2IO

Canonical names of the generators of a medial axis (package documentation,
"Canonical ids"): `e<r>.<i>` for the edge from vertex i to vertex i+1 of ring
r, `v<r>.<i>` for the reflex vertex i of ring r.

In `INPUT` mode the rings and vertex indices are those of the input polygon
(valid once the axis is complete).  In `SHAPE` mode they are those of the
shape whose axis this is, as returned by `shape_rings()`: ring 0 its outer
boundary counter-clockwise from its vertex of smallest input index, then its
holes clockwise from their vertex of smallest input index, in the order of
that index.  Intermediate steps of a progressive computation must be named
in `SHAPE` mode.
*/
template <class Medial_axis>
class Generator_names
{
public:
  enum Mode { INPUT, SHAPE };

  Generator_names(const Medial_axis& ma, Mode mode) : ma_(ma), mode_(mode)
  {
    if(mode == SHAPE) {
      rings_ = shape_rings(ma);
      for(std::size_t r = 0; r < rings_.size(); ++r)
        for(std::size_t i = 0; i < rings_[r].size(); ++i)
          position_[rings_[r][i]] = std::make_pair(int(r), int(i));
    }
  }

  std::string operator()(const typename Medial_axis::Generator& g) const
  {
    if(mode_ == INPUT)
      return g.id();
    const auto& pos = position_.at(ma_.halfedge_structure().face(g.face_index()).p0);
    return (g.is_point() ? "v" : "e") + std::to_string(pos.first) + "." + std::to_string(pos.second);
  }

  /// The shape's rings as internal point indices (SHAPE mode).
  const std::vector<std::vector<int> >& rings() const { return rings_; }

  /// Ring cycles of the shape of `ma`, in canonical order.
  static std::vector<std::vector<int> > shape_rings(const Medial_axis& ma)
  {
    std::vector<std::vector<int> > cycles = ma.boundary_cycles();
    for(std::vector<int>& c : cycles)
      std::rotate(c.begin(), std::min_element(c.begin(), c.end()), c.end());
    // the outer cycle is counter-clockwise: find it by signed area
    std::size_t outer = 0;
    double best = -1e300;
    for(std::size_t i = 0; i < cycles.size(); ++i) {
      double a = 0;
      const std::vector<int>& c = cycles[i];
      for(std::size_t j = 0; j < c.size(); ++j) {
        auto p = Medial_axis::to_xy(ma.points()[c[j]]);
        auto q = Medial_axis::to_xy(ma.points()[c[(j + 1) % c.size()]]);
        a += p.first * q.second - p.second * q.first;
      }
      if(a > best) { best = a; outer = i; }
    }
    std::swap(cycles[0], cycles[outer]);
    std::sort(cycles.begin() + 1, cycles.end(),
              [](const std::vector<int>& x, const std::vector<int>& y) { return x.front() < y.front(); });
    return cycles;
  }

private:
  const Medial_axis& ma_;
  Mode mode_;
  std::vector<std::vector<int> > rings_;
  std::map<int, std::pair<int, int> > position_;
};

/// One medial curve, named.
struct Named_curve {
  std::string a, b;   // a < b
  double length;
};

/// One branch point, named: its generators sorted, its centre and radius.
struct Named_branch {
  std::vector<std::string> generators;
  double x, y, r;
};

/// The medial curves of `ma`, sorted.
template <class Medial_axis, class Names>
std::vector<Named_curve> named_curves(const Medial_axis& ma, const Names& names)
{
  std::vector<Named_curve> out;
  for(const auto& e : ma.edges()) {
    std::string a = names(e.first_generator()), b = names(e.second_generator());
    if(b < a) std::swap(a, b);
    out.push_back(Named_curve{a, b, e.length()});
  }
  std::sort(out.begin(), out.end(), [](const Named_curve& x, const Named_curve& y) {
    if(x.a != y.a) return x.a < y.a;
    if(x.b != y.b) return x.b < y.b;
    return x.length < y.length;
  });
  return out;
}

/// The branch points of `ma` (vertices where three or more curves meet).
/// Branch points joined by a curve shorter than `merge_distance` (the
/// representation of a point of degree four or more) are reported once,
/// with all their generators.
template <class Medial_axis, class Names>
std::vector<Named_branch> named_branches(const Medial_axis& ma, const Names& names, double merge_distance)
{
  typedef typename Medial_axis::Hds Hds;
  const Hds& hds = ma.halfedge_structure();
  const int nv = int(hds.vertex_capacity());
  std::vector<int> parent(nv);
  for(int i = 0; i < nv; ++i) parent[i] = i;
  auto find = [&](int x) {
    while(parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  std::vector<char> is_branch(nv, 0);
  for(const auto& v : ma.vertices())
    if(v.kind() == Medial_axis::BRANCH_POINT) is_branch[v.index()] = 1;
  for(const auto& e : ma.edges()) {
    int s = e.source().index(), t = e.target().index();
    if(is_branch[s] && is_branch[t] && e.length() <= merge_distance)
      parent[find(s)] = find(t);
  }
  std::map<int, std::pair<std::set<std::string>, int> > groups;
  for(const auto& v : ma.vertices()) {
    if(!is_branch[v.index()]) continue;
    auto& g = groups[find(v.index())];
    if(g.first.empty()) g.second = v.index();
    for(const auto& gen : v.generators()) g.first.insert(names(gen));
  }
  std::vector<Named_branch> out;
  for(const auto& kv : groups) {
    const int v = kv.second.second;
    auto p = Medial_axis::to_xy(ma.vertex_point(v));
    out.push_back(Named_branch{std::vector<std::string>(kv.second.first.begin(), kv.second.first.end()),
                               p.first, p.second, CGAL::to_double(ma.vertex_radius(v))});
  }
  std::sort(out.begin(), out.end(), [](const Named_branch& x, const Named_branch& y) {
    if(x.generators != y.generators) return x.generators < y.generators;
    return std::make_pair(x.x, x.y) < std::make_pair(y.x, y.y);
  });
  return out;
}

inline std::string format_double(double v)
{
  char buf[40];
  std::snprintf(buf, sizeof(buf), "%.17g", v);
  return buf;
}

/// Writes one line `pair A B L` per medial curve.
inline void write_pairs(std::ostream& out, const std::vector<Named_curve>& curves)
{
  for(const Named_curve& c : curves)
    out << "pair " << c.a << ' ' << c.b << ' ' << format_double(c.length) << '\n';
}

/// Writes one line `branch A B C ... x y r` per branch point.
inline void write_branches(std::ostream& out, const std::vector<Named_branch>& branches)
{
  for(const Named_branch& b : branches) {
    out << "branch";
    for(const std::string& g : b.generators) out << ' ' << g;
    out << ' ' << format_double(b.x) << ' ' << format_double(b.y) << ' ' << format_double(b.r) << '\n';
  }
}

/// Diagonal of the bounding box of the medial axis's polygon points.
template <class Medial_axis>
double bbox_diagonal(const Medial_axis& ma)
{
  double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
  for(const auto& p : ma.points()) {
    auto q = Medial_axis::to_xy(p);
    x0 = (std::min)(x0, q.first); x1 = (std::max)(x1, q.first);
    y0 = (std::min)(y0, q.second); y1 = (std::max)(y1, q.second);
  }
  return std::hypot(x1 - x0, y1 - y0);
}

} // namespace PMA2
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_MEDIAL_AXIS_2_IO_MEDIAL_AXIS_IO_H
