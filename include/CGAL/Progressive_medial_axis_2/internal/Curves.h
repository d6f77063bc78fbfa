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
//
// The geometry of a medial curve in double precision, for output: its
// length and a polyline within a tolerance.  A curve is a line segment, or
// an arc of the parabola of a focus (a reflex vertex) and a directrix (the
// line of a segment).  Everything is computed in a frame scaled to the
// curve, so that coordinates near 1e300 or 1e-300 neither overflow nor
// underflow.

#ifndef CGAL_PROGRESSIVE_MEDIAL_AXIS_2_INTERNAL_CURVES_H
#define CGAL_PROGRESSIVE_MEDIAL_AXIS_2_INTERNAL_CURVES_H

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace CGAL {
namespace Progressive_medial_axes {
namespace internal {

/// The distance from q to the segment from a to b, in double, computed in a
/// frame scaled to the points so that neither squares nor products overflow.
inline double distance_to_segment(const std::pair<double, double>& q, const std::pair<double, double>& a,
                                  const std::pair<double, double>& b)
{
  const double sc = (std::max)({std::fabs(a.first), std::fabs(a.second), std::fabs(b.first), std::fabs(b.second),
                                std::fabs(q.first), std::fabs(q.second)});
  if(!(sc > 0)) return 0;
  const double ax = a.first / sc, ay = a.second / sc, bx = b.first / sc, by = b.second / sc;
  const double px = q.first / sc, py = q.second / sc;
  const double dx = bx - ax, dy = by - ay, l2 = dx * dx + dy * dy;
  double t = l2 > 0 ? ((px - ax) * dx + (py - ay) * dy) / l2 : 0;
  t = (std::min)(1.0, (std::max)(0.0, t));
  return std::hypot(px - ax - t * dx, py - ay - t * dy) * sc;
}

/// A medial curve from `a` to `b`: a segment, or an arc of a parabola.
struct Curve {
  typedef std::pair<double, double> Point;
  Point a, b;
  bool parabolic = false;
  // the parabola, in a frame along the directrix: the foot (fx, fy) of the
  // focus, the unit direction t of the directrix, the unit normal n towards
  // the focus, the height h of the focus; all lengths divided by `scale`
  double fx = 0, fy = 0, tx = 1, ty = 0, nx = 0, ny = 1, h = 1, scale = 1;

  /// Sets the parabola of the focus p and the line through q0, q1.
  void set_parabola(const Point& p, const Point& q0, const Point& q1)
  {
    scale = (std::max)({std::fabs(p.first), std::fabs(p.second), std::fabs(q0.first), std::fabs(q0.second),
                        std::fabs(q1.first), std::fabs(q1.second), std::fabs(a.first), std::fabs(a.second),
                        std::fabs(b.first), std::fabs(b.second)});
    if(!(scale > 0) || !std::isfinite(scale)) return;
    const double px = p.first / scale, py = p.second / scale;
    const double ax = q0.first / scale, ay = q0.second / scale;
    const double dx = q1.first / scale - ax, dy = q1.second / scale - ay;
    const double len = std::sqrt(dx * dx + dy * dy);   // (scaled: no overflow, and faster than hypot)
    if(!(len > 0)) return;
    tx = dx / len;
    ty = dy / len;
    nx = -ty;
    ny = tx;
    const double s = (px - ax) * tx + (py - ay) * ty;
    fx = ax + s * tx;
    fy = ay + s * ty;
    h = (px - ax) * nx + (py - ay) * ny;
    parabolic = h > 0;
  }

  /// Abscissa along the directrix of a point (scaled frame).
  double abscissa(const Point& q) const { return (q.first / scale - fx) * tx + (q.second / scale - fy) * ty; }

  /// The point of the parabola at abscissa x (scaled frame), unscaled.
  Point at(double x) const
  {
    const double y = (x * x + h * h) / (2.0 * h);
    return Point((fx + x * tx + y * nx) * scale, (fy + x * ty + y * ny) * scale);
  }

  // arc length from the vertex of the parabola to abscissa x (scaled frame)
  double arc(double x) const
  {
    const double s = std::sqrt(x * x + h * h);   // (scaled)
    return (x * s + h * h * std::asinh(x / h)) / (2.0 * h);
  }

  double length() const
  {
    if(!parabolic) {
      const double sc = (std::max)({std::fabs(a.first), std::fabs(a.second), std::fabs(b.first), std::fabs(b.second)});
      if(!(sc > 0)) return 0;
      const double dx = b.first / sc - a.first / sc, dy = b.second / sc - a.second / sc;
      return std::sqrt(dx * dx + dy * dy) * sc;   // (scaled)
    }
    return std::fabs(arc(abscissa(b)) - arc(abscissa(a))) * scale;
  }

  // abscissa (scaled frame) of the point at arc length s from a, on a
  // parabolic arc: Newton's method on the arc length (convex in |x|, slope
  // sqrt(x^2 + h^2) / h >= 1), kept inside a bracket that shrinks
  double abscissa_at_length(double s) const
  {
    const double xa = abscissa(a), xb = abscissa(b);
    const double target = s / scale, a0 = arc(xa);
    const double dir = xb >= xa ? 1.0 : -1.0;
    double lo = 0, hi = std::fabs(xb - xa);
    double u = (std::min)(hi, target);   // the arc is at least as long as the abscissa span
    for(int i = 0; i < 100; ++i) {
      const double x = xa + dir * u;
      const double f = std::fabs(arc(x) - a0) - target;
      if(f < 0) lo = u;
      else hi = u;
      double next = u - f * h / std::sqrt(x * x + h * h);   // (scaled)
      if(!(next > lo && next < hi)) next = 0.5 * (lo + hi);
      if(next == u || hi - lo <= 1e-15 * (std::fabs(xa) + std::fabs(xb) + h)) break;
      u = next;
    }
    return xa + dir * u;
  }

  /// The point at parameter u in [0, 1]: the abscissa goes linearly from a
  /// to b on a parabolic arc, the point itself on a segment.
  Point point_at_parameter(double u) const
  {
    if(!parabolic)
      return Point(a.first + (b.first - a.first) * u, a.second + (b.second - a.second) * u);
    const double xa = abscissa(a), xb = abscissa(b);
    return at(xa + (xb - xa) * u);
  }

  /// The parameter (see point_at_parameter()) of the point at arc length s
  /// from a, clamped to [0, 1].
  double parameter_at_length(double s) const
  {
    const double L = length();
    if(!(s > 0)) return 0;
    if(!(s < L)) return 1;
    if(!parabolic) return s / L;
    const double xa = abscissa(a), xb = abscissa(b);
    return (abscissa_at_length(s) - xa) / (xb - xa);
  }

  /// The point at arc length s from a (0 <= s <= length()).
  Point point_at_length(double s) const
  {
    if(!(s > 0)) return a;
    if(!(s < length())) return b;
    if(!parabolic) return point_at_parameter(parameter_at_length(s));
    return at(abscissa_at_length(s));
  }

  /// The unit tangent at arc length s, in the direction from a to b.
  Point tangent_at_length(double s) const
  {
    double dx, dy;
    if(!parabolic) {
      dx = b.first - a.first;
      dy = b.second - a.second;
    } else {
      const double x = abscissa_at_length((std::min)((std::max)(s, 0.0), length()));
      const double dir = abscissa(b) >= abscissa(a) ? 1.0 : -1.0;
      const double slope = x / h;   // dy/dx of y = (x^2 + h^2) / (2h)
      dx = dir * (tx + slope * nx);
      dy = dir * (ty + slope * ny);
    }
    const double n = std::hypot(dx, dy);
    return n > 0 ? Point(dx / n, dy / n) : Point(0, 0);
  }

  /// The part of the curve between arc lengths s0 < s1 from a.
  Curve part(double s0, double s1) const
  {
    Curve c = *this;
    const Point p0 = point_at_length(s0), p1 = point_at_length(s1);
    c.a = p0;
    c.b = p1;
    return c;
  }

  /// The control point of the quadratic Bezier curve from a to b that is
  /// this curve: a parabolic arc is exactly such a curve (the middle of the
  /// chord for a segment).
  Point bezier_control_point() const
  {
    if(!parabolic) return Point(0.5 * (a.first + b.first), 0.5 * (a.second + b.second));
    // in the frame of the directrix the arc is x -> (x, (x^2 + h^2) / (2h)),
    // a polynomial of degree 2: its control point lies on the tangent at a,
    // above the middle abscissa
    const double x0 = abscissa(a), x1 = abscissa(b);
    const double xc = 0.5 * (x0 + x1);
    const double yc = (x0 * x0 + h * h) / (2.0 * h) + (x0 / h) * (xc - x0);
    return Point((fx + xc * tx + yc * nx) * scale, (fy + xc * ty + yc * ny) * scale);
  }

  /// Points from a to b whose polyline stays within `tolerance` of the
  /// curve: a segment gives its two ends; a parabolic arc is cut into
  /// pieces whose sagitta (width^2 / (16 h) for a piece of width w of a
  /// parabola of height h) is at most the tolerance.  A tolerance <= 0
  /// stands for 1e-9 times the largest coordinate of the curve.  At most
  /// 10^8 points.
  std::vector<Point> polyline(double tolerance) const
  {
    std::vector<Point> out;
    out.push_back(a);
    if(parabolic) {
      const double x1 = abscissa(a), x2 = abscissa(b);
      const double relative = tolerance > 0 ? tolerance / scale : 1e-9;
      const double step = std::sqrt(16.0 * h * relative);
      const double pieces = std::ceil(std::fabs(x2 - x1) / step);
      const long n = pieces > 1e8 ? 100000000L : (std::max)(1L, long(pieces));
      for(long i = 1; i < n; ++i) out.push_back(at(x1 + (x2 - x1) * double(i) / double(n)));
    }
    out.push_back(b);
    return out;
  }
};

/// The points of one curve by parameter (see Curve::point_at_parameter()),
/// and the arc length from `a` to them, for many evaluations along it (the
/// cuts of pruning): what does not depend on the parameter is computed once.
struct Curve_parameterization {
  typedef Curve::Point Point;
  const Curve& c;
  double xa = 0, xb = 0, arc_a = 0, length = 0;
  explicit Curve_parameterization(const Curve& curve) : c(curve)
  {
    if(c.parabolic) {
      xa = c.abscissa(c.a);
      xb = c.abscissa(c.b);
      arc_a = c.arc(xa);
    } else
      length = c.length();
  }
  double length_at(double u) const
  {
    if(!c.parabolic) return length * u;
    return std::fabs(c.arc(xa + (xb - xa) * u) - arc_a) * c.scale;
  }
  Point point_at(double u) const
  {
    if(!c.parabolic) return c.point_at_parameter(u);
    return c.at(xa + (xb - xa) * u);   // (Curve::point_at_parameter() with the abscissas kept)
  }
};

} // namespace internal
} // namespace Progressive_medial_axes
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_MEDIAL_AXIS_2_INTERNAL_CURVES_H
