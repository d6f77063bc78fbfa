// Copyright (c) 2026 The Progressive_medial_axis_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// The command-line tool's names and text output of a medial axis (not part
// of the library): canonical generator ids, the list of medial curves and
// of branch points.  Written on the public interface of Medial_axis_2.

#ifndef PMA_TOOL_MEDIAL_AXIS_IO_H
#define PMA_TOOL_MEDIAL_AXIS_IO_H

#include <CGAL/Progressive_medial_axis_2/Medial_axis_2.h>
#include <CGAL/Progressive_medial_axis_2/Medial_axis_significance_2.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <functional>
#include <cmath>
#include <cstdio>
#include <map>
#include <ostream>
#include <set>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace pma_tool {

/*
Canonical names of the generators of a medial axis (package documentation,
"Canonical ids"): `e<r>.<i>` for the edge from vertex i to vertex i+1 of ring
r, `v<r>.<i>` for the reflex vertex i of ring r.

In `INPUT` mode the rings and vertex indices are those of the input polygon
(valid once the axis is complete).  In `SHAPE` mode they are those of the
shape whose axis this is, as returned by `Medial_axis_2::shape_rings()`:
ring 0 its outer boundary counter-clockwise from its vertex of smallest input
index, then its holes clockwise from their vertex of smallest input index,
in the order of that index.  Intermediate steps of a progressive
computation must be named in `SHAPE` mode.
*/
template <class Medial_axis>
class Generator_names
{
public:
  typedef typename Medial_axis::Input_vertex Input_vertex;
  enum Mode { INPUT, SHAPE };

  Generator_names(const Medial_axis& ma, Mode mode) : mode_(mode)
  {
    if(mode == SHAPE) {
      rings_ = ma.shape_rings();
      // A generator is named by the position of its source.  Where a vertex
      // lies inside an edge (a T), the second half of the edge starts at that
      // vertex's place, so one input vertex occurs twice (never as a point
      // generator: no sector there is reflex); the occurrence followed by
      // the edge's target names the edge.
      // A point generator where rings touch is named after the first
      // position of its place, as in INPUT mode.
      typedef std::pair<double, double> Place;
      std::map<Place, Occurrence> first;
      for(std::size_t r = 0; r < rings_.size(); ++r)
        for(std::size_t i = 0; i < rings_[r].size(); ++i) {
          const Occurrence o{int(r), int(i), rings_[r][(i + 1) % rings_[r].size()]};
          position_[rings_[r][i]].push_back(o);
          first.emplace(Medial_axis::to_xy(ma.point(rings_[r][i])), o);
        }
      for(auto& p : position_) point_position_[p.first] = first.at(Medial_axis::to_xy(ma.point(p.first)));
    }
  }

  std::string operator()(const typename Medial_axis::Face_handle& g) const
  {
    if(mode_ == INPUT)
      return g.id();
    if(g.is_point()) {
      const Occurrence& pos = point_position_.at(g.source_vertex());
      return "v" + std::to_string(pos.ring) + "." + std::to_string(pos.index);
    }
    const std::vector<Occurrence>& at = position_.at(g.source_vertex());
    const Occurrence* pos = &at.front();
    for(const Occurrence& o : at)
      if(!g.is_point() && o.next == g.target_vertex()) pos = &o;
    return (g.is_point() ? "v" : "e") + std::to_string(pos->ring) + "." + std::to_string(pos->index);
  }

  /// The shape's rings (SHAPE mode).
  const std::vector<std::vector<Input_vertex> >& rings() const { return rings_; }

private:
  Mode mode_;
  std::vector<std::vector<Input_vertex> > rings_;
  struct Occurrence { int ring, index; Input_vertex next; };
  std::map<Input_vertex, std::vector<Occurrence> > position_;
  std::map<Input_vertex, Occurrence> point_position_;
};

/// A medial curve of an output, or the part of it that a pruning keeps:
/// arc lengths `begin` to `end` from the source of `h` (for a part that is
/// not `whole`; a whole part is the curve of `h`, its length computed where
/// an output needs it), with the erosion thickness at both ends when the
/// axis is pruned.
template <class Medial_axis>
struct Axis_part {
  typename Medial_axis::Halfedge_handle h;
  double begin = 0, end = 0;
  bool whole = true;
  bool cut_begin = false, cut_end = false;   // (by a pruning)
  bool with_et = false;
  double et_begin = 0, et_end = 0;
  double length() const { return whole ? h.length() : end - begin; }
  /// The radius at the start and at the end: at an end that is a vertex of
  /// the axis, the vertex's (correctly rounded with exact decisions), not
  /// the distance from a point of the curve computed in double, which
  /// differs from it in the last bits and with the direction of the curve.
  double radius_at_begin() const
  {
    return cut_begin ? h.radius_at(begin) : CGAL::to_double(h.source_radius());
  }
  double radius_at_end() const
  {
    return cut_end ? h.radius_at(end) : CGAL::to_double(h.target_radius());
  }
  std::vector<std::pair<double, double> > polyline(double tolerance) const
  {
    return whole ? h.polyline(tolerance) : h.polyline(tolerance, begin, end);
  }
  std::array<std::pair<double, double>, 3> bezier() const
  {
    return whole ? h.quadratic_bezier(0, h.length()) : h.quadratic_bezier(begin, end);
  }
};

/// The parts `parts` in an order and a direction that depend on the axis
/// alone, not on how it was computed (the parts of a one-shot, so the number
/// of threads, decide which half-edge of a curve the structure lists, and
/// where): each curve directed with the smaller of its two generators on its
/// left, sorted by its generators, and the curves of the same two generators
/// by their ends.  So the outputs of one input are the same bytes on any
/// number of threads, where the axis is (with exact decisions: its vertices
/// correctly rounded).  A generator's key is point or edge, then its first
/// and its last input vertex: where a vertex lies inside an edge, the part
/// of the edge from there starts at that vertex, as the vertex's own edge
/// does, and ends elsewhere.  (Two generators of one key, which no valid
/// polygon has, would have their curve directed from its end of smaller
/// (x, y).)  A part cut by a pruning and turned round keeps its place on
/// the curve: its arc lengths are taken from the other end.  The parts are
/// permuted in place (a copy of them would be 56 bytes a
/// curve more at the peak of a pruned output of 1.5 million curves).
template <class Medial_axis>
void canonical_order(std::vector<Axis_part<Medial_axis> >& parts)
{
  typedef std::array<int, 5> Key;
  typedef std::array<int, 10> Generators;
  auto generator_key = [](const typename Medial_axis::Face_handle& f) {
    const auto a = f.source_vertex(), b = f.target_vertex();
    return Key{{f.is_point() ? 1 : 0, a.ring, a.index, b.ring, b.index}};
  };
  std::vector<std::pair<Generators, std::size_t> > keyed;
  keyed.reserve(parts.size());
  for(std::size_t i = 0; i < parts.size(); ++i) {
    Axis_part<Medial_axis>& p = parts[i];
    const Key f = generator_key(p.h.first_generator()), g = generator_key(p.h.second_generator());
    bool flip = g < f;
    if(f == g) {
      const auto c = p.h.geometry();
      flip = c.b < c.a;
    }
    Generators k;
    std::copy(f.begin(), f.end(), k.begin() + (flip ? 5 : 0));
    std::copy(g.begin(), g.end(), k.begin() + (flip ? 0 : 5));
    keyed.emplace_back(k, i);
    if(flip) {
      p.h = p.h.opposite();
      if(!p.whole) {
        const double length = p.h.length(), begin = p.begin, end = p.end;
        p.begin = p.cut_end ? length - end : 0;
        p.end = p.cut_begin ? length - begin : length;
      }
      std::swap(p.cut_begin, p.cut_end);
      std::swap(p.et_begin, p.et_end);
    }
  }
  std::sort(keyed.begin(), keyed.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
  // (two generators may share several curves: those in the order of their ends)
  for(std::size_t i = 0; i < keyed.size();) {
    std::size_t j = i + 1;
    while(j < keyed.size() && keyed[j].first == keyed[i].first) ++j;
    if(j - i > 1)
      std::sort(keyed.begin() + std::ptrdiff_t(i), keyed.begin() + std::ptrdiff_t(j), [&](const auto& x, const auto& y) {
        const auto a = parts[x.second].h.geometry(), b = parts[y.second].h.geometry();
        return std::make_pair(a.a, a.b) < std::make_pair(b.a, b.b);
      });
    i = j;
  }
  // parts[i] = the old parts[keyed[i].second], cycle by cycle (a position
  // done is marked by its own index)
  for(std::size_t i = 0; i < keyed.size(); ++i) {
    if(keyed[i].second == i) continue;
    Axis_part<Medial_axis> first = parts[i];
    std::size_t j = i;
    while(keyed[j].second != i) {
      const std::size_t from = keyed[j].second;
      parts[j] = parts[from];
      keyed[j].second = j;
      j = from;
    }
    parts[j] = first;
    keyed[j].second = j;
  }
}

/// Every medial curve of `ma`, whole, in the order and the direction of
/// canonical_order().
template <class Medial_axis>
std::vector<Axis_part<Medial_axis> > axis_parts(const Medial_axis& ma)
{
  std::vector<Axis_part<Medial_axis> > out;
  out.reserve(ma.number_of_edges());   // (a vector grown by doubling holds up to 3 times the curves)
  for(const auto& e : ma.edges()) {
    Axis_part<Medial_axis> p;
    p.h = e;
    out.push_back(p);
  }
  canonical_order(out);
  return out;
}

/// The kept parts of a pruned axis, in the order and the direction of
/// canonical_order().
template <class K>
std::vector<Axis_part<CGAL::Medial_axis_2<K> > > axis_parts(const CGAL::Pruned_medial_axis_2<K>& pruned)
{
  std::vector<Axis_part<CGAL::Medial_axis_2<K> > > out;
  out.reserve(pruned.curves().size());
  for(const auto& c : pruned.curves()) {
    Axis_part<CGAL::Medial_axis_2<K> > p;
    p.h = c.halfedge;
    p.cut_begin = c.cut_at_begin();
    p.cut_end = c.cut_at_end();
    p.whole = !p.cut_begin && !p.cut_end;
    if(!p.whole) {
      p.begin = c.begin;
      p.end = c.end;
    }
    p.with_et = true;
    p.et_begin = c.et_begin;
    p.et_end = c.et_end;
    out.push_back(p);
  }
  canonical_order(out);
  return out;
}

/// The axis of one polygon of the input, as the outputs show it: its curves
/// (or their kept parts), the branch points it keeps (all if `keep` is
/// empty), the generators' names, the properties of the input feature (JSON
/// object text, or empty) and the polygon's index (-1 when the input has one).
template <class Medial_axis>
struct Axis_layer {
  const Medial_axis* ma = nullptr;
  std::vector<Axis_part<Medial_axis> > parts;
  std::function<bool(const typename Medial_axis::Vertex_handle&)> keep;
  std::function<std::string(const typename Medial_axis::Face_handle&)> names;
  std::string properties;
  long polygon = -1;
};

/// The names `names` with `prefix` in front (`p<k>:` for the k-th polygon of several).
template <class Names>
auto prefixed_names(Names names, std::string prefix)
{
  return [names = std::move(names), prefix = std::move(prefix)](const auto& g) { return prefix + names(g); };
}

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

/// The curves (or kept parts of curves) `parts`, sorted.
template <class Medial_axis, class Names>
std::vector<Named_curve> named_curves(const std::vector<Axis_part<Medial_axis> >& parts, const Names& names)
{
  std::vector<Named_curve> out;
  for(const auto& p : parts) {
    std::string a = names(p.h.first_generator()), b = names(p.h.second_generator());
    if(b < a) std::swap(a, b);
    out.push_back(Named_curve{a, b, p.length()});
  }
  std::sort(out.begin(), out.end(), [](const Named_curve& x, const Named_curve& y) {
    if(x.a != y.a) return x.a < y.a;
    if(x.b != y.b) return x.b < y.b;
    return x.length < y.length;
  });
  return out;
}

/// The medial curves of `ma`, sorted.
template <class Medial_axis, class Names>
std::vector<Named_curve> named_curves(const Medial_axis& ma, const Names& names)
{
  return named_curves(axis_parts(ma), names);
}

/// The branch points of `ma` (vertices where three or more curves meet)
/// that `keep` keeps (all if it is empty).
/// Branch points joined by a curve shorter than `merge_distance` are
/// reported once, with all their generators (a point where four or more
/// generators meet is one vertex already; this also merges the nearly
/// coincident vertices of the double model).
template <class Medial_axis, class Names>
std::vector<Named_branch> named_branches(const Medial_axis& ma, const Names& names, double merge_distance,
                                         const std::function<bool(const typename Medial_axis::Vertex_handle&)>& keep = {})
{
  typedef typename Medial_axis::Vertex_handle Vertex;
  std::map<Vertex, Vertex> parent;
  for(const auto& v : ma.vertices())
    if(v.kind() == Medial_axis::BRANCH_POINT && (!keep || keep(v))) parent[v] = v;
  auto find = [&](Vertex x) {
    while(parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  for(const auto& e : ma.edges()) {
    const Vertex s = e.source(), t = e.target();
    if(parent.count(s) && parent.count(t) && e.length() <= merge_distance) parent[find(s)] = find(t);
  }
  // a group is reported at its member of smallest (x, y, r), so that the
  // output does not depend on the order of the vertices in memory
  struct Group {
    std::set<std::string> generators;
    std::tuple<double, double, double> at;
  };
  std::map<Vertex, Group> groups;
  for(const auto& kv : parent) {
    const auto p = Medial_axis::to_xy(kv.first.point());
    const std::tuple<double, double, double> at(p.first, p.second, CGAL::to_double(kv.first.radius()));
    const auto inserted = groups.emplace(find(kv.first), Group{{}, at});
    Group& g = inserted.first->second;
    if(at < g.at) g.at = at;
    for(const auto& gen : kv.first.generators()) g.generators.insert(names(gen));
  }
  std::vector<Named_branch> out;
  for(const auto& kv : groups)
    out.push_back(Named_branch{std::vector<std::string>(kv.second.generators.begin(), kv.second.generators.end()),
                               std::get<0>(kv.second.at), std::get<1>(kv.second.at), std::get<2>(kv.second.at)});
  std::sort(out.begin(), out.end(), [](const Named_branch& x, const Named_branch& y) {
    if(x.generators != y.generators) return x.generators < y.generators;
    return std::make_pair(x.x, x.y) < std::make_pair(y.x, y.y);
  });
  return out;
}

/// The text of `v` as `printf("%.17g")` writes it in the C locale, for
/// streams: `out << Double_text(v)`.  By std::to_chars where the library
/// has it (the same characters on 7 million doubles tried; 4.6 times faster
/// than snprintf, which was a quarter of a run that writes GeoJSON,
/// RESULTS.md, sixty-seventh session), and no string on the heap.
struct Double_text {
  char text[40];
  std::size_t size;
  explicit Double_text(double v)
  {
#if defined(__cpp_lib_to_chars) && __cpp_lib_to_chars >= 201611L
    const std::to_chars_result r = std::to_chars(text, text + sizeof(text), v, std::chars_format::general, 17);
    size = std::size_t(r.ptr - text);
#else
    size = std::size_t(std::snprintf(text, sizeof(text), "%.17g", v));
#endif
  }
};

inline std::ostream& operator<<(std::ostream& out, const Double_text& d)
{
  return out.write(d.text, std::streamsize(d.size));
}

inline std::string format_double(double v)
{
  const Double_text d(v);
  return std::string(d.text, d.size);
}

/// Writes one line `pair A B L` per medial curve.
inline void write_pairs(std::ostream& out, const std::vector<Named_curve>& curves)
{
  for(const Named_curve& c : curves)
    out << "pair " << c.a << ' ' << c.b << ' ' << Double_text(c.length) << '\n';
}

/// Writes one line `branch A B C ... x y r` per branch point.
inline void write_branches(std::ostream& out, const std::vector<Named_branch>& branches)
{
  for(const Named_branch& b : branches) {
    out << "branch";
    for(const std::string& g : b.generators) out << ' ' << g;
    out << ' ' << Double_text(b.x) << ' ' << Double_text(b.y) << ' ' << Double_text(b.r) << '\n';
  }
}

/// Bounding box of points given as doubles.
struct Box {
  double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
  void add(double x, double y)
  {
    x0 = (std::min)(x0, x); x1 = (std::max)(x1, x);
    y0 = (std::min)(y0, y); y1 = (std::max)(y1, y);
  }
  double diagonal() const { return std::hypot(x1 - x0, y1 - y0); }
};

/// The box of the input polygon of `ma`.
template <class Medial_axis>
Box input_box(const Medial_axis& ma)
{
  Box b;
  for(std::size_t r = 0; r < ma.number_of_input_rings(); ++r)
    for(std::size_t i = 0; i < ma.input_ring_size(r); ++i) {
      typename Medial_axis::Input_vertex v;
      v.ring = int(r);
      v.index = int(i);
      auto p = Medial_axis::to_xy(ma.point(v));
      b.add(p.first, p.second);
    }
  return b;
}

/// The box of the shape of `ma` (at a step, the current shape).
template <class Medial_axis>
Box shape_box(const Medial_axis& ma)
{
  Box b;
  for(const auto& ring : ma.shape_rings())
    for(const auto& v : ring) {
      auto p = Medial_axis::to_xy(ma.point(v));
      b.add(p.first, p.second);
    }
  return b;
}

/// Diagonal of the bounding box of the input polygon.
template <class Medial_axis>
double bbox_diagonal(const Medial_axis& ma)
{
  return input_box(ma).diagonal();
}

} // namespace pma_tool

#endif // PMA_TOOL_MEDIAL_AXIS_IO_H
