// Copyright (c) 2026 The Progressive_medial_axis_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Pictures and exchange formats of a medial axis: SVG, GeoJSON, WKT.

#ifndef CGAL_PROGRESSIVE_MEDIAL_AXIS_2_IO_MEDIAL_AXIS_DRAWING_H
#define CGAL_PROGRESSIVE_MEDIAL_AXIS_2_IO_MEDIAL_AXIS_DRAWING_H

#include <CGAL/Progressive_medial_axis_2/IO/medial_axis_io.h>

#include <algorithm>
#include <cmath>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace PMA2 {

namespace internal {

struct Box {
  double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
  void add(double x, double y)
  {
    x0 = (std::min)(x0, x); x1 = (std::max)(x1, x);
    y0 = (std::min)(y0, y); y1 = (std::max)(y1, y);
  }
  double diagonal() const { return std::hypot(x1 - x0, y1 - y0); }
};

template <class Medial_axis>
Box shape_box(const Medial_axis& ma)
{
  Box b;
  for(const auto& c : ma.boundary_cycles())
    for(int i : c) {
      auto p = Medial_axis::to_xy(ma.points()[i]);
      b.add(p.first, p.second);
    }
  return b;
}

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
\ingroup PkgProgressiveMedialAxis2IO
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
  internal::Box box = internal::shape_box(ma);
  if(show_input)
    for(const auto& r : ma.input_rings())
      for(int i : r) {
        auto p = Medial_axis::to_xy(ma.points()[i]);
        box.add(p.first, p.second);
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
  // a filled path of closed rings of point indices
  auto rings_path = [&](const auto& rings, const char* style) {
    out << "<path " << style << " fill-rule=\"evenodd\" d=\"";
    for(const auto& c : rings) {
      for(std::size_t i = 0; i < c.size(); ++i) {
        auto p = Medial_axis::to_xy(ma.points()[c[i]]);
        std::snprintf(buf, sizeof(buf), "%c%.2f %.2f", i == 0 ? 'M' : 'L', X(p.first), Y(p.second));
        out << buf;
      }
      out << 'Z';
    }
    out << "\"/>\n";
  };
  if(show_input)
    rings_path(ma.input_rings(), "fill=\"#f4f4f4\" stroke=\"#b0b0b0\" stroke-width=\"0.6\"");
  rings_path(ma.boundary_cycles(), "fill=\"#e8eef7\" stroke=\"#203040\" stroke-width=\"0.8\"");
  for(int kind = 0; kind < 2; ++kind) {
    out << "<path fill=\"none\" stroke=\"" << (kind == 0 ? "#1f5fbf" : "#c0392b")
        << "\" stroke-width=\"1\" d=\"";
    for(const auto& e : ma.edges()) {
      if((e.kind() == Medial_axis::PARABOLIC_ARC) != (kind == 1)) continue;
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
\ingroup PkgProgressiveMedialAxis2IO
Writes the medial axis as a GeoJSON FeatureCollection: one LineString per
medial curve (properties: the two generator ids, `line` or `parabola`, the
length) sampled within `tolerance` (default 1e-6 of the shape's diagonal),
and one Point per branch point (properties: generator ids, radius).
*/
template <class Medial_axis, class Names>
void write_geojson(std::ostream& out, const Medial_axis& ma, const Names& names, double tolerance = -1)
{
  if(tolerance <= 0) tolerance = 1e-6 * internal::shape_box(ma).diagonal();
  out << "{\"type\":\"FeatureCollection\",\"features\":[\n";
  bool first = true;
  for(const auto& e : ma.edges()) {
    std::string a = names(e.first_generator()), b = names(e.second_generator());
    if(b < a) std::swap(a, b);
    out << (first ? "" : ",\n") << "{\"type\":\"Feature\",\"properties\":{\"generators\":[\"" << a << "\",\"" << b
        << "\"],\"curve\":\"" << (e.kind() == Medial_axis::PARABOLIC_ARC ? "parabola" : "line")
        << "\",\"length\":" << format_double(e.length()) << "},\"geometry\":{\"type\":\"LineString\",\"coordinates\":[";
    auto pl = e.polyline(tolerance);
    for(std::size_t i = 0; i < pl.size(); ++i)
      out << (i ? "," : "") << '[' << format_double(pl[i].first) << ',' << format_double(pl[i].second) << ']';
    out << "]}}";
    first = false;
  }
  for(const auto& br : named_branches(ma, names, 1e-12 * internal::shape_box(ma).diagonal())) {
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
\ingroup PkgProgressiveMedialAxis2IO
Writes the medial axis as one WKT MULTILINESTRING, curves sampled within
`tolerance` (default 1e-6 of the shape's diagonal).
*/
template <class Medial_axis>
void write_wkt_axis(std::ostream& out, const Medial_axis& ma, double tolerance = -1)
{
  if(tolerance <= 0) tolerance = 1e-6 * internal::shape_box(ma).diagonal();
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

} // namespace PMA2
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_MEDIAL_AXIS_2_IO_MEDIAL_AXIS_DRAWING_H
