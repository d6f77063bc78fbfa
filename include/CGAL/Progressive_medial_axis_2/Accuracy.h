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
// The accuracy measure of Liu et al. (2016, section 6.3):
// E(x) = 1 - r_min / r_max for a branch point x, where the r_i are the true
// distances from x to its generators; and its floor, the error of the exact
// branch points correctly rounded to double.

#ifndef CGAL_PROGRESSIVE_MEDIAL_AXIS_2_ACCURACY_H
#define CGAL_PROGRESSIVE_MEDIAL_AXIS_2_ACCURACY_H

#include <CGAL/license/Progressive_medial_axis_2.h>

#include <CGAL/Progressive_medial_axis_2/Medial_axis_2.h>
#include <CGAL/Progressive_medial_axis_2/internal/Medial_constructions.h>
#include <CGAL/Progressive_medial_axis_2/internal/Mpfr_interval.h>
#include <CGAL/Progressive_medial_axis_traits_2.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace CGAL {
namespace Progressive_medial_axes {

/*!
\ingroup PkgProgressiveMedialAxis2Ref
A generator given by double coordinates: the point `(ax, ay)`, or the
segment from `(ax, ay)` to `(bx, by)`.
*/
struct Accuracy_site {
  bool is_point;
  double ax, ay, bx, by;
};

/*!
\ingroup PkgProgressiveMedialAxis2Ref
Summary statistics of E(x) over a set of branch points.
*/
struct Accuracy_statistics {
  std::size_t count = 0;
  double mean = 0;
  double standard_deviation = 0;
  double max = 0;
};

/*!
\ingroup PkgProgressiveMedialAxis2Ref
E(x) = 1 - r_min / r_max for the point `(x, y)`, where the r_i are its
distances to the generators `g` (to the closed segment for a segment).  The
distances are computed in 256-bit interval arithmetic, so that E(x) measures
the error of `(x, y)` and not that of its evaluation.  Returns 0 for fewer
than two generators.
*/
inline double medial_point_error(double x, double y, const std::vector<Accuracy_site>& g)
{
  typedef internal::Mpfr_interval I;
  if(g.size() < 2) return 0;
  internal::Mpfr_precision_scope scope(256);
  const I X(x), Y(y);
  I rmin, rmax;
  bool first = true;
  for(const Accuracy_site& s : g) {
    I r;
    if(s.is_point) {
      I dx = X - I(s.ax), dy = Y - I(s.ay);
      r = sqrt(dx * dx + dy * dy);
    } else {
      const I ax(s.ax), ay(s.ay), bx(s.bx), by(s.by);
      I ux = bx - ax, uy = by - ay, vx = X - ax, vy = Y - ay;
      I len2 = ux * ux + uy * uy;
      I dot = ux * vx + uy * vy;
      double t = dot.midpoint() / len2.midpoint();
      if(t <= 0) {
        r = sqrt(vx * vx + vy * vy);
      } else if(t >= 1) {
        I wx = X - bx, wy = Y - by;
        r = sqrt(wx * wx + wy * wy);
      } else {
        r = abs(ux * vy - uy * vx) / sqrt(len2);
      }
    }
    if(first) {
      rmin = rmax = r;
      first = false;
    } else {
      // compared at full precision (intervals that overlap are equal to 256 bits)
      Uncertain<Comparison_result> lo = compare(r, rmin), hi = compare(r, rmax);
      if(is_certain(lo) && get_certain(lo) == SMALLER) rmin = r;
      if(is_certain(hi) && get_certain(hi) == LARGER) rmax = r;
    }
  }
  if(!(rmax.sup() > 0)) return 0;
  // 1 - rmin / rmax, at full precision
  try {
    I e = (rmax - rmin) / rmax;
    return (std::max)(0.0, e.midpoint());
  } catch(Uncertain_conversion_exception&) {
    return 0;
  }
}

/*!
\ingroup PkgProgressiveMedialAxis2Ref
Mean, standard deviation and maximum of a set of E(x) values.
*/
inline Accuracy_statistics accuracy_statistics(const std::vector<double>& e)
{
  Accuracy_statistics s;
  s.count = e.size();
  if(e.empty()) return s;
  double sum = 0, sum2 = 0;
  for(double v : e) {
    sum += v;
    s.max = (std::max)(s.max, v);
  }
  s.mean = sum / double(e.size());
  for(double v : e) sum2 += (v - s.mean) * (v - s.mean);
  s.standard_deviation = std::sqrt(sum2 / double(e.size()));
  return s;
}

/*!
\ingroup PkgProgressiveMedialAxis2Ref
The generator of a cell of `Medial_axis_2<K>` as an `Accuracy_site`.
*/
template <class Face_handle>
Accuracy_site accuracy_site(const Face_handle& g)
{
  const double ax = CGAL::to_double(g.source().x()), ay = CGAL::to_double(g.source().y());
  const double bx = CGAL::to_double(g.target().x()), by = CGAL::to_double(g.target().y());
  return Accuracy_site{g.is_point(), ax, ay, bx, by};
}

/*!
\ingroup PkgProgressiveMedialAxis2Ref
E(x) for every branch point of `ma` (vertices where three or more medial
curves meet), using the branch point as stored and its generators, in the
order of `ma.vertices()`.
*/
template <class K>
std::vector<double> branch_point_errors(const Medial_axis_2<K>& ma)
{
  typedef Medial_axis_2<K> MA;
  std::vector<double> out;
  for(const auto& v : ma.vertices()) {
    if(v.kind() != MA::BRANCH_POINT) continue;
    std::vector<Accuracy_site> g;
    for(const auto& gen : v.generators()) g.push_back(accuracy_site(gen));
    auto p = MA::to_xy(v.point());
    out.push_back(medial_point_error(p.first, p.second, g));
  }
  return out;
}

/*!
\ingroup PkgProgressiveMedialAxis2Ref
The "floor" of the accuracy of double coordinates: E(x) of every branch
point of `ma` when x is the exact branch point (the disk tangent to three of
its generators, computed in 2048-bit interval arithmetic) correctly rounded
to double.  Same order as `branch_point_errors()`.
*/
template <class K>
std::vector<double> floor_branch_point_errors(const Medial_axis_2<K>& ma)
{
  typedef Medial_axis_2<K> MA;
  typedef internal::Mpfr_interval I;
  typedef internal::Site<CGAL::Epick::Point_2> Site;
  std::vector<double> out;
  for(const auto& v : ma.vertices()) {
    if(v.kind() != MA::BRANCH_POINT) continue;
    std::vector<Accuracy_site> g;
    for(const auto& gen : v.generators()) g.push_back(accuracy_site(gen));
    auto p = MA::to_xy(v.point());
    double x = p.first, y = p.second;
    // three consecutive generators around the vertex, counter-clockwise
    Site s[3];
    for(int i = 0; i < 3; ++i) {
      const Accuracy_site& a = g[i];
      s[i] = a.is_point ? Site::point(CGAL::Epick::Point_2(a.ax, a.ay))
                        : Site::segment(CGAL::Epick::Point_2(a.ax, a.ay), CGAL::Epick::Point_2(a.bx, a.by));
    }
    internal::Triple_relations rel = internal::triple_relations<CGAL::Epick>(s);
    for(mpfr_prec_t prec : {256, 2048}) {
      internal::Mpfr_precision_scope scope(prec);
      try {
        internal::To_nt_convert<I> cv;
        internal::Site_nt<I> sn[3] = {internal::site_nt<I>(s[0], cv), internal::site_nt<I>(s[1], cv),
                                      internal::site_nt<I>(s[2], cv)};
        internal::Circle_nt<I> c;
        if(internal::medial_circle(sn, rel, c) && c.x.rounds_to_one_double() && c.y.rounds_to_one_double()) {
          x = c.x.midpoint();
          y = c.y.midpoint();
          break;
        }
      } catch(Uncertain_conversion_exception&) {
      }
    }
    out.push_back(medial_point_error(x, y, g));
  }
  return out;
}

} // namespace Progressive_medial_axes
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_MEDIAL_AXIS_2_ACCURACY_H
