// Copyright (c) 2026 The Progressive_medial_axis_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// The command-line tool's pictures and exchange formats of a medial axis
// (not part of the library): SVG, GeoJSON, WKT.

#ifndef PMA_TOOL_MEDIAL_AXIS_DRAWING_H
#define PMA_TOOL_MEDIAL_AXIS_DRAWING_H

#include <pma_tool/medial_axis_io.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <functional>
#include <cmath>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace pma_tool {

namespace internal {

inline std::string xml_escape(const std::string& s)
{
  std::string r;
  for(char c : s) {
    if(c == '<') r += "&lt;";
    else if(c == '>') r += "&gt;";
    else if(c == '&') r += "&amp;";
    else r += c;
  }
  return r;
}

} // namespace internal

/*!
Draws the shapes of the layers and the curves of their medial axes (all of
them, or the kept parts of a pruned axis) as an SVG picture of about `width`
pixels: the shapes filled, straight curves in blue (`L`), parabolic arcs in
red, each as the quadratic Bezier curve that is that arc (`Q`), and the
branch points that each layer keeps as dots.  `title` is written in a
corner.  With `show_input`, the outline of the whole input polygon is drawn
in grey behind (useful for the steps of a progressive computation).
*/
template <class Medial_axis>
void write_svg(std::ostream& out, const std::vector<Axis_layer<Medial_axis> >& layers, const std::string& title,
               double width = 1000, bool show_input = false)
{
  Box box;
  for(const auto& l : layers) {
    const Box b = shape_box(*l.ma);
    box.add(b.x0, b.y0);
    box.add(b.x1, b.y1);
    if(show_input) {
      const Box in = input_box(*l.ma);
      box.add(in.x0, in.y0);
      box.add(in.x1, in.y1);
    }
  }
  double w = box.x1 - box.x0, h = box.y1 - box.y0;
  if(!(w > 0)) w = 1;
  if(!(h > 0)) h = 1;
  const double scale = width / (std::max)(w, h);
  const double margin = 10;
  const double W = w * scale + 2 * margin, H = h * scale + 2 * margin;
  auto X = [&](double x) { return margin + (x - box.x0) * scale; };
  auto Y = [&](double y) { return margin + (box.y1 - y) * scale; };
  char buf[160];
  out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << W << "\" height=\"" << H
      << "\" viewBox=\"0 0 " << W << ' ' << H << "\">\n";
  out << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  // a filled path of closed rings of polygon vertices
  auto rings_path = [&](const Medial_axis& ma, const auto& rings, const char* style) {
    out << "<path " << style << " fill-rule=\"evenodd\" d=\"";
    for(const auto& c : rings) {
      for(std::size_t i = 0; i < c.size(); ++i) {
        auto p = Medial_axis::to_xy(ma.point(c[i]));
        std::snprintf(buf, sizeof(buf), "%c%.2f %.2f", i == 0 ? 'M' : 'L', X(p.first), Y(p.second));
        out << buf;
      }
      out << 'Z';
    }
    out << "\"/>\n";
  };
  for(const auto& l : layers) {
    const Medial_axis& ma = *l.ma;
    if(show_input) {
      std::vector<std::vector<typename Medial_axis::Input_vertex> > input(ma.number_of_input_rings());
      for(std::size_t r = 0; r < input.size(); ++r)
        for(std::size_t i = 0; i < ma.input_ring_size(r); ++i) {
          typename Medial_axis::Input_vertex v;
          v.ring = int(r);
          v.index = int(i);
          input[r].push_back(v);
        }
      rings_path(ma, input, "fill=\"#f4f4f4\" stroke=\"#b0b0b0\" stroke-width=\"0.6\"");
    }
    rings_path(ma, ma.shape_rings(), "fill=\"#e8eef7\" stroke=\"#203040\" stroke-width=\"0.8\"");
  }
  for(int kind = 0; kind < 2; ++kind) {
    out << "<path fill=\"none\" stroke=\"" << (kind == 0 ? "#1f5fbf" : "#c0392b")
        << "\" stroke-width=\"1\" d=\"";
    for(const auto& l : layers)
      for(const auto& p : l.parts) {
        const bool parabola = p.h.curve_kind() == Medial_axis::PARABOLIC_ARC;
        if(parabola != (kind == 1)) continue;
        const auto b = p.bezier();
        if(parabola)
          std::snprintf(buf, sizeof(buf), "M%.2f %.2fQ%.2f %.2f %.2f %.2f", X(b[0].first), Y(b[0].second),
                        X(b[1].first), Y(b[1].second), X(b[2].first), Y(b[2].second));
        else
          std::snprintf(buf, sizeof(buf), "M%.2f %.2fL%.2f %.2f", X(b[0].first), Y(b[0].second), X(b[2].first),
                        Y(b[2].second));
        out << buf;
      }
    out << "\"/>\n";
  }
  out << "<g fill=\"#202020\">\n";
  for(const auto& l : layers) {
    // (sorted, as the curves are: the same picture on any number of threads
    // is the same bytes)
    std::vector<std::pair<double, double> > points;
    for(const auto& v : l.ma->vertices())
      if(v.kind() == Medial_axis::BRANCH_POINT && (!l.keep || l.keep(v))) points.push_back(Medial_axis::to_xy(v.point()));
    std::sort(points.begin(), points.end());
    for(const auto& p : points) {
      std::snprintf(buf, sizeof(buf), "<circle cx=\"%.2f\" cy=\"%.2f\" r=\"1.2\"/>\n", X(p.first), Y(p.second));
      out << buf;
    }
  }
  out << "</g>\n";
  if(!title.empty())
    out << "<text x=\"" << margin << "\" y=\"" << H - margin / 2
        << "\" font-family=\"sans-serif\" font-size=\"14\" fill=\"#203040\">"
        << internal::xml_escape(title) << "</text>\n";
  out << "</svg>\n";
}

/// Draws the shape of `ma` and its whole medial axis (see above).
template <class Medial_axis>
void write_svg(std::ostream& out, const Medial_axis& ma, const std::string& title, double width = 1000,
               bool show_input = false)
{
  std::vector<Axis_layer<Medial_axis> > layers(1);
  layers[0].ma = &ma;
  layers[0].parts = axis_parts(ma);
  write_svg(out, layers, title, width, show_input);
}

/// The distance within which the polylines of a shape of box diagonal
/// `diagonal` follow its curves: `tolerance`, or where it is not positive,
/// 1e-6 of the diagonal.
inline double polyline_tolerance(double tolerance, double diagonal)
{
  return tolerance > 0 ? tolerance : 1e-6 * diagonal;
}

/// polyline_tolerance() of the shape of `ma` (its box found only where
/// `tolerance` is not positive).
template <class Medial_axis>
double shape_tolerance(const Medial_axis& ma, double tolerance)
{
  return tolerance > 0 ? tolerance : polyline_tolerance(tolerance, shape_box(ma).diagonal());
}

/// The members that each feature of the layer `l` starts its properties
/// with: the input feature's properties without the names of ours, then
/// `polygon` where there are several.
template <class Medial_axis>
std::string inherited_properties(const Axis_layer<Medial_axis>& l)
{
  std::string inherited;
  if(!l.properties.empty()) {
    nlohmann::ordered_json props = nlohmann::ordered_json::parse(l.properties);
    for(const char* own : {"kind", "generators", "curve", "length", "radius", "et", "polygon"}) props.erase(own);
    if(!props.empty()) {
      inherited = props.dump();
      inherited = inherited.substr(1, inherited.size() - 2) + ",";
    }
  }
  if(l.polygon >= 0) inherited += "\"polygon\":" + std::to_string(l.polygon) + ",";
  return inherited;
}

/// The branch points of the layer `l` that write_geojson() lists, where
/// `diagonal` is the diagonal of the box of its shape.
template <class Medial_axis>
std::vector<Named_branch> geojson_branches(const Axis_layer<Medial_axis>& l, double diagonal)
{
  return named_branches(*l.ma, l.names, 1e-12 * diagonal, l.keep);
}

/// The features of the curves `begin` to `end` (excluded) of the layer `l`
/// of write_geojson(), sampled within `tol` (positive), each after ",\n"
/// unless `first` (which is then cleared).  Layers, or pieces of a layer,
/// written apart (on several threads) and put together in order give
/// write_geojson()'s text.
template <class Medial_axis>
void write_geojson_curves(std::ostream& out, const Axis_layer<Medial_axis>& l, double tol, std::size_t begin,
                          std::size_t end, bool& first)
{
  auto number = [](double v) { return std::isfinite(v) ? format_double(v) : std::string("null"); };
  const std::string inherited = inherited_properties(l);
  for(std::size_t k = begin; k < end; ++k) {
    const auto& p = l.parts[k];
    std::string a = l.names(p.h.first_generator()), b = l.names(p.h.second_generator());
    if(b < a) std::swap(a, b);
    out << (first ? "" : ",\n") << "{\"type\":\"Feature\",\"properties\":{" << inherited
        << "\"kind\":\"curve\",\"generators\":[\"" << a << "\",\"" << b << "\"],\"curve\":\""
        << (p.h.curve_kind() == Medial_axis::PARABOLIC_ARC ? "parabola" : "line")
        << "\",\"length\":" << Double_text(p.length()) << ",\"radius\":[" << number(p.radius_at_begin())
        << ',' << number(p.radius_at_end()) << ']';
    if(p.with_et) out << ",\"et\":[" << number(p.et_begin) << ',' << number(p.et_end) << ']';
    out << "},\"geometry\":{\"type\":\"LineString\",\"coordinates\":[";
    auto pl = p.polyline(tol);
    for(std::size_t i = 0; i < pl.size(); ++i)
      out << (i ? "," : "") << '[' << Double_text(pl[i].first) << ',' << Double_text(pl[i].second) << ']';
    out << "]}}";
    first = false;
  }
}

/// The features of the branch points `begin` to `end` (excluded) of
/// `branches`, those of the layer `l` (geojson_branches()), as
/// write_geojson_curves() writes those of its curves.
template <class Medial_axis>
void write_geojson_branches(std::ostream& out, const Axis_layer<Medial_axis>& l,
                            const std::vector<Named_branch>& branches, std::size_t begin, std::size_t end, bool& first)
{
  const std::string inherited = inherited_properties(l);
  for(std::size_t k = begin; k < end; ++k) {
    const Named_branch& br = branches[k];
    out << (first ? "" : ",\n") << "{\"type\":\"Feature\",\"properties\":{" << inherited
        << "\"kind\":\"branch\",\"generators\":[";
    for(std::size_t i = 0; i < br.generators.size(); ++i)
      out << (i ? "," : "") << '"' << br.generators[i] << '"';
    out << "],\"radius\":" << Double_text(br.r) << "},\"geometry\":{\"type\":\"Point\",\"coordinates\":["
        << Double_text(br.x) << ',' << Double_text(br.y) << "]}}";
    first = false;
  }
}

/// The features of one layer of write_geojson() (see write_geojson_curves()).
template <class Medial_axis>
void write_geojson_features(std::ostream& out, const Axis_layer<Medial_axis>& l, double tolerance, bool& first)
{
  const double diagonal = shape_box(*l.ma).diagonal();
  write_geojson_curves(out, l, polyline_tolerance(tolerance, diagonal), 0, l.parts.size(), first);
  const std::vector<Named_branch> branches = geojson_branches(l, diagonal);
  write_geojson_branches(out, l, branches, 0, branches.size(), first);
}

/// The text before and after the features of write_geojson().
constexpr const char* geojson_head = "{\"type\":\"FeatureCollection\",\"features\":[\n";
constexpr const char* geojson_tail = "\n]}\n";

/*!
Writes the curves of the layers' medial axes as a GeoJSON FeatureCollection
(RFC 7946): one LineString per curve, sampled within `tolerance` (default
1e-6 of the shape's diagonal), and one Point per branch point the layer
keeps.  Every feature carries the properties of the input feature its
polygon comes from, then its own (which replace input properties of the same
name): `kind` (`curve` or `branch`), `generators` (ids), and for a curve
`curve` (`line` or `parabola`), `length`, `radius` (at both ends) and, for a
pruned axis, `et` (the erosion thickness at both ends, null where infinite);
for a branch point `radius`; `polygon` (the polygon's index) when the input
has several.
*/
template <class Medial_axis>
void write_geojson(std::ostream& out, const std::vector<Axis_layer<Medial_axis> >& layers, double tolerance = -1)
{
  out << geojson_head;
  bool first = true;
  for(const auto& l : layers) write_geojson_features(out, l, tolerance, first);
  out << geojson_tail;
}

/// Writes the points of a polyline as WKT: `(x y, x y, ...)`.
inline void write_wkt_points(std::ostream& out, const std::vector<std::pair<double, double> >& pl)
{
  out << '(';
  for(std::size_t i = 0; i < pl.size(); ++i)
    out << (i ? ", " : "") << Double_text(pl[i].first) << ' ' << Double_text(pl[i].second);
  out << ')';
}

/// Writes polylines as one WKT MULTILINESTRING.
inline void write_wkt_lines(std::ostream& out, const std::vector<std::vector<std::pair<double, double> > >& lines,
                            bool multi = true)
{
  out << (multi ? "MULTILINESTRING " : "LINESTRING ");
  if(lines.empty()) {
    out << "EMPTY\n";
    return;
  }
  if(multi) out << '(';
  bool first = true;
  for(const auto& pl : lines) {
    if(!first) out << ", ";
    write_wkt_points(out, pl);
    first = false;
  }
  out << (multi ? ")\n" : "\n");
}

/// The text of write_wkt_axis(): before the first polyline, before each
/// other one (write_wkt_points()), after the last, and without any.
constexpr const char* wkt_axis_head = "MULTILINESTRING (";
constexpr const char* wkt_axis_separator = ", ";
constexpr const char* wkt_axis_tail = ")\n";
constexpr const char* wkt_axis_empty = "MULTILINESTRING EMPTY\n";

/*!
Writes the curves of the layers' medial axes as one WKT MULTILINESTRING,
sampled within `tolerance` (default 1e-6 of each shape's diagonal).  Each
polyline is written as soon as it is sampled: kept until all were, the
polylines of a whole-world file were 1.4 GB of the peak (RESULTS.md,
seventy-first session).
*/
template <class Medial_axis>
void write_wkt_axis(std::ostream& out, const std::vector<Axis_layer<Medial_axis> >& layers, double tolerance = -1)
{
  bool any = false;
  for(const auto& l : layers) any = any || !l.parts.empty();
  if(!any) {
    out << wkt_axis_empty;
    return;
  }
  out << wkt_axis_head;
  bool first = true;
  for(const auto& l : layers) {
    if(l.parts.empty()) continue;
    const double tol = shape_tolerance(*l.ma, tolerance);
    for(const auto& p : l.parts) {
      if(!first) out << wkt_axis_separator;
      write_wkt_points(out, p.polyline(tol));
      first = false;
    }
  }
  out << wkt_axis_tail;
}

} // namespace pma_tool

#endif // PMA_TOOL_MEDIAL_AXIS_DRAWING_H
