// Copyright (c) 2026 The Progressive_medial_axis_2 authors.
// All rights reserved.
//
// This file is part of CGAL (www.cgal.org).
//
// $URL$
// $Id$
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s)     : The Progressive_medial_axis_2 authors

#ifndef CGAL_PROGRESSIVE_MEDIAL_AXIS_2_INPUT_ERROR_H
#define CGAL_PROGRESSIVE_MEDIAL_AXIS_2_INPUT_ERROR_H

#include <CGAL/license/Progressive_medial_axis_2.h>

/// \file Input_error.h
/// Definitions shared by the input layer of `Progressive_medial_axis_2`: the
/// exception reporting bad input, and the ring representation of a polygon with holes
/// used by the validation
/// (`validate_polygon.h`).

#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Progressive_medial_axes {

/*!
\ingroup PkgProgressiveMedialAxis2IO

Exception thrown for bad input a user can cause: a file that cannot be read or parsed,
or a polygon that is not a valid polygon with holes.

`what()` is one line naming the problem and where it is, for example
`"self-intersection: ring 0 edge 12 (vertices 12-13) crosses ring 2 edge 4 (vertices 4-5)"`
or `"malformed WKT at line 1, column 17: expected ',' or ')'"`.

Rings are numbered as in `Rings`: ring 0 is the outer ring, ring `k` the `k`-th hole,
in input order; vertices are numbered from 0 within their ring, in the order written.
*/
class Input_error : public std::runtime_error
{
public:
  /// Creates an error with message `what`, optionally locating it at vertex `vertex`
  /// of ring `ring` (-1 when not applicable).
  explicit Input_error(const std::string& what, int ring = -1, int vertex = -1)
    : std::runtime_error(what), m_ring(ring), m_vertex(vertex)
  {}

  /// The ring the problem is located in (the first one named in the message), or -1.
  int ring() const { return m_ring; }

  /// The vertex of `ring()` the problem is located at, or -1.
  int vertex() const { return m_vertex; }

private:
  int m_ring;
  int m_vertex;
};

/*!
\ingroup PkgProgressiveMedialAxis2IO

A polygon with holes given as rings of points: ring 0 is the outer ring, ring `k` the
`k`-th hole, in input order. The closing duplicate point of each ring is not stored
(a ring with `n` vertices has `n` edges, edge `i` going from vertex `i` to vertex
`(i+1) mod n`). Vertex order is exactly as written in the input; rings are never
reordered or reoriented, and either orientation is accepted for any ring.
*/
template <class Point_2>
using Rings = std::vector<std::vector<Point_2> >;

namespace internal {

/// Formats `d` with the fewest significant digits (at most 17) that read back as
/// exactly `d`, independently of the C locale; used in error messages.
inline std::string format_coordinate(double d)
{
  char buf[64];
#if defined(__cpp_lib_to_chars) && __cpp_lib_to_chars >= 201611L
  std::to_chars_result r = std::to_chars(buf, buf + sizeof(buf), d);
  return std::string(buf, r.ptr);
#else
  for(int precision = 15; precision <= 17; ++precision) {
    std::snprintf(buf, sizeof(buf), "%.*g", precision, d);
    if(precision == 17 || std::strtod(buf, nullptr) == d)
      break;
  }
  return std::string(buf);
#endif
}

/// Formats the point `(x, y)` for an error message.
inline std::string format_point(double x, double y)
{
  return "(" + format_coordinate(x) + ", " + format_coordinate(y) + ")";
}

} // namespace internal

} // namespace Progressive_medial_axes
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_MEDIAL_AXIS_2_INPUT_ERROR_H
