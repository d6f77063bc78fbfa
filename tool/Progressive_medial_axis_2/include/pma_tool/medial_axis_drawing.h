// Copyright (c) 2026 The Progressive_medial_axis_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// The command-line tool's pictures and exchange formats of a medial axis
// (not part of the library): SVG, GeoJSON, WKT.

#ifndef PMA_TOOL_MEDIAL_AXIS_DRAWING_H
#define PMA_TOOL_MEDIAL_AXIS_DRAWING_H

#include <pma_tool/medial_axis_io.h>

#include <algorithm>
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
Draws the shape of `ma` and its medial axis as an SVG picture of about
`width` pixels: the shape filled, straight curves in blue, parabolic arcs in
red, branch points as dots.  `title` is written in a corner.  With
`show_input`, the outline of the whole input polygon is drawn in grey behind
(useful for the steps of a progressive computation).
*/
template <class Medial_axis>
void write_svg(std::ostream& out, const Medial_axis& ma, const std::string& title, double width = 1000,
               bool show_input = false)
{
  Box box = shape_box(ma);
  if(show_input) {
    const Box in = input_box(ma);
    box.add(in.x0, in.y0);
    box.add(in.x1, in.y1);
  }
  double w = box.x1 - box.x0, h = box.y1 - box.y0;
  if(!(w > 0)) w = 1;
  if(!(h > 0)) h = 1;
  const double scale = width / (std::max)(w, h);
  const double margin = 10;
  const double W = w * scale + 2 * margin, H = h * scale + 2 * margin;
  auto X = [&](double x) { return margin + (x - box.x0) * scale; };
  auto Y = [&](double y) { return margin + (box.y1 - y) * scale; };
  const double tol = 0.25 / scale;   // a quarter pixel
  char buf[128];
  out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << W << "\" height=\"" << H
      << "\" viewBox=\"0 0 " << W << ' ' << H << "\">\n";
  out << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  // a filled path of closed rings of polygon vertices
  auto rings_path = [&](const auto& rings, const char* style) {
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
  if(show_input) {
    std::vector<std::vector<typename Medial_axis::Input_vertex> > input(ma.number_of_input_rings());
    for(std::size_t r = 0; r < input.size(); ++r)
      for(std::size_t i = 0; i < ma.input_ring_size(r); ++i) {
        typename Medial_axis::Input_vertex v;
        v.ring = int(r);
        v.index = int(i);
        input[r].push_back(v);
      }
    rings_path(input, "fill=\"#f4f4f4\" stroke=\"#b0b0b0\" stroke-width=\"0.6\"");
  }
  rings_path(ma.shape_rings(), "fill=\"#e8eef7\" stroke=\"#203040\" stroke-width=\"0.8\"");
  for(int kind = 0; kind < 2; ++kind) {
    out << "<path fill=\"none\" stroke=\"" << (kind == 0 ? "#1f5fbf" : "#c0392b")
        << "\" stroke-width=\"1\" d=\"";
    for(const auto& e : ma.edges()) {
      if((e.curve_kind() == Medial_axis::PARABOLIC_ARC) != (kind == 1)) continue;
      auto pl = e.polyline(tol);
      for(std::size_t i = 0; i < pl.size(); ++i) {
        std::snprintf(buf, sizeof(buf), "%c%.2f %.2f", i == 0 ? 'M' : 'L', X(pl[i].first), Y(pl[i].second));
        out << buf;
      }
    }
    out << "\"/>\n";
  }
  out << "<g fill=\"#202020\">\n";
  for(const auto& v : ma.vertices()) {
    if(v.kind() != Medial_axis::BRANCH_POINT) continue;
    auto p = Medial_axis::to_xy(v.point());
    std::snprintf(buf, sizeof(buf), "<circle cx=\"%.2f\" cy=\"%.2f\" r=\"1.2\"/>\n", X(p.first), Y(p.second));
    out << buf;
  }
  out << "</g>\n";
  if(!title.empty())
    out << "<text x=\"" << margin << "\" y=\"" << H - margin / 2
        << "\" font-family=\"sans-serif\" font-size=\"14\" fill=\"#203040\">"
        << internal::xml_escape(title) << "</text>\n";
  out << "</svg>\n";
}

/*!
Writes the medial axis as a GeoJSON FeatureCollection: one LineString per
medial curve (properties: the two generator ids, `line` or `parabola`, the
length) sampled within `tolerance` (default 1e-6 of the shape's diagonal),
and one Point per branch point (properties: generator ids, radius).
*/
template <class Medial_axis, class Names>
void write_geojson(std::ostream& out, const Medial_axis& ma, const Names& names, double tolerance = -1)
{
  if(tolerance <= 0) tolerance = 1e-6 * shape_box(ma).diagonal();
  out << "{\"type\":\"FeatureCollection\",\"features\":[\n";
  bool first = true;
  for(const auto& e : ma.edges()) {
    std::string a = names(e.first_generator()), b = names(e.second_generator());
    if(b < a) std::swap(a, b);
    out << (first ? "" : ",\n") << "{\"type\":\"Feature\",\"properties\":{\"generators\":[\"" << a << "\",\"" << b
        << "\"],\"curve\":\"" << (e.curve_kind() == Medial_axis::PARABOLIC_ARC ? "parabola" : "line")
        << "\",\"length\":" << format_double(e.length()) << "},\"geometry\":{\"type\":\"LineString\",\"coordinates\":[";
    auto pl = e.polyline(tolerance);
    for(std::size_t i = 0; i < pl.size(); ++i)
      out << (i ? "," : "") << '[' << format_double(pl[i].first) << ',' << format_double(pl[i].second) << ']';
    out << "]}}";
    first = false;
  }
  for(const auto& br : named_branches(ma, names, 1e-12 * shape_box(ma).diagonal())) {
    out << (first ? "" : ",\n") << "{\"type\":\"Feature\",\"properties\":{\"generators\":[";
    for(std::size_t i = 0; i < br.generators.size(); ++i)
      out << (i ? "," : "") << '"' << br.generators[i] << '"';
    out << "],\"radius\":" << format_double(br.r) << "},\"geometry\":{\"type\":\"Point\",\"coordinates\":["
        << format_double(br.x) << ',' << format_double(br.y) << "]}}";
    first = false;
  }
  out << "\n]}\n";
}

/*!
Writes the medial axis as one WKT MULTILINESTRING, curves sampled within
`tolerance` (default 1e-6 of the shape's diagonal).
*/
template <class Medial_axis>
void write_wkt_axis(std::ostream& out, const Medial_axis& ma, double tolerance = -1)
{
  if(tolerance <= 0) tolerance = 1e-6 * shape_box(ma).diagonal();
  out << "MULTILINESTRING (";
  bool first = true;
  for(const auto& e : ma.edges()) {
    auto pl = e.polyline(tolerance);
    out << (first ? "(" : ", (");
    for(std::size_t i = 0; i < pl.size(); ++i)
      out << (i ? ", " : "") << format_double(pl[i].first) << ' ' << format_double(pl[i].second);
    out << ')';
    first = false;
  }
  out << ")\n";
}

} // namespace pma_tool

#endif // PMA_TOOL_MEDIAL_AXIS_DRAWING_H
