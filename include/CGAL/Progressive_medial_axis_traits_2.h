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

#ifndef CGAL_PROGRESSIVE_MEDIAL_AXIS_TRAITS_2_H
#define CGAL_PROGRESSIVE_MEDIAL_AXIS_TRAITS_2_H

#include <CGAL/license/Progressive_medial_axis_2.h>

#include <CGAL/Progressive_medial_axis_2/internal/Medial_constructions.h>
#include <CGAL/Progressive_medial_axis_2/internal/Mpfr_interval.h>
#include <CGAL/Progressive_medial_axis_2/internal/Double_double.h>
#include <CGAL/Progressive_medial_axis_2/internal/Axis_aligned_disk.h>
#include <CGAL/Progressive_medial_axis_2/internal/One_root_rational.h>
#include <CGAL/Progressive_medial_axis_2/internal/Nested_root_number.h>

#include <CGAL/Progressive_medial_axis_2/internal/Input_conversion.h>
#include <CGAL/Progressive_medial_axis_2/internal/Medial_axis_engine.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Interval_nt.h>
#include <CGAL/Lazy_exact_nt.h>
#include <CGAL/CORE_Expr.h>
#include <CGAL/enum.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <stdexcept>
#include <type_traits>
#include <cstdint>
#include <cstring>
#include <vector>

#include <boost/multiprecision/number.hpp>

namespace CGAL {

namespace Progressive_medial_axes {
namespace internal {

/// Whether two points are at one place.  With double coordinates they are
/// compared directly: the kernel's `==` (Epick's static filter) costs
/// several times more, and the relations of every event time's triple ask
/// it up to nine times.
template <class Point_2>
bool same_place(const Point_2& a, const Point_2& b)
{
  if constexpr(std::is_same<std::decay_t<decltype(a.x())>, double>::value)
    return a.x() == b.x() && a.y() == b.y();
  else
    return a == b;
}

/// A generator of the medial axis as the traits see it: a point, or a
/// segment from `p` to `q` with the shape on its left.
template <class Point_2_>
struct Site {
  typedef Point_2_ Point_2;
  bool is_point = true;
  Point_2 p, q;

  static Site point(const Point_2& a) { Site s; s.is_point = true; s.p = a; s.q = a; return s; }
  static Site segment(const Point_2& a, const Point_2& b) { Site s; s.is_point = false; s.p = a; s.q = b; return s; }
  const Point_2& source() const { return p; }
  const Point_2& target() const { return q; }

  friend bool operator==(const Site& a, const Site& b)
  {
    if(a.is_point != b.is_point) return false;
    return a.is_point ? same_place(a.p, b.p) : (same_place(a.p, b.p) && same_place(a.q, b.q));
  }
};

/// The square root of a CORE::Expr (non-negative).  CORE's floating filter
/// writes a warning into a file `Core_Diagnostics` of the current directory
/// when it takes the root of a node whose double approximation is negative,
/// which happens for a positive number that is tiny against the rounding
/// error of its computation.  The node's filter is then replaced by an
/// approximation 0 with an error bound of 1e300 (true, if useless: CORE
/// then evaluates the node exactly when its sign is needed), and the root
/// is taken without the warning.
template <>
struct Sqrt_hook<CORE::Expr> {
  static CORE::Expr apply(const CORE::Expr& x)
  {
    CORE::ExprRep& rep = const_cast<CORE::ExprRep&>(x.getRep());
    if(rep.ffVal.getValue() < 0.0 && x.sign() >= 0)
      rep.ffVal = CORE::filteredFp(0.0, 1e300, 1);
    return CORE::sqrt(x);
  }
};

/// The one-root stage's lines of segments with rational end points (the
/// exact ties of integer grids evaluate the same segments' lines again and
/// again: on a grid polygon of 47,000 vertices, computing them was half of
/// that stage's time; RESULTS.md, "The one-root stage's lines").
template <>
struct Oriented_line_hook<Small_one_root> {
  struct Entry {   // (default value: the segment from (0, 0) to (0, 0), unused)
    static constexpr unsigned max_bits = 8;
    static constexpr std::size_t misses_per_page = 8;   // (exact, in 128-bit rationals)
    Small_rational key[4];
    Line_nt<Small_one_root> line;
    bool holds(const Small_rational* c) const
    {
      return key[0] == c[0] && key[1] == c[1] && key[2] == c[2] && key[3] == c[3];
    }
    const Line_nt<Small_one_root>& value() const { return line; }
    void set(const Small_rational* c, const Line_nt<Small_one_root>& l)
    {
      std::copy(c, c + 4, key);
      line = l;
    }
  };
  static Line_nt<Small_one_root> apply(const Site_nt<Small_one_root>& s)
  {
    if(!(s.ax.is_rational() && s.ay.is_rational() && s.bx.is_rational() && s.by.is_rational()))
      return compute_oriented_line(s);
    const Small_rational c[4] = {s.ax.a(), s.ay.a(), s.bx.a(), s.by.a()};
    std::uint64_t h = 0x9e3779b97f4a7c15ull;
    for(const Small_rational& x : c)   // (the low 64 bits of each)
      h = mix_hash(mix_hash(h, std::uint64_t(x.numerator())), std::uint64_t(x.denominator()));
    static thread_local Cache_table<Entry> table;
    return table.value(h, c, [&] { return compute_oriented_line(s); });
  }
};

/// Whether the segments u and v lie on one line (exact predicates of `K`).
template <class K, class Site_>
bool on_one_line(const Site_& u, const Site_& v)
{
  const Exact_orientation<K> orientation;
  return orientation(u.p, u.q, v.p) == COLLINEAR && orientation(u.p, u.q, v.q) == COLLINEAR;
}

/// Exact symbolic relations of a triple, from exact predicates of `K`.
template <class K, class Site_>
Triple_relations triple_relations(const Site_ s[3])
{
  Exact_orientation<K> orientation;
  Triple_relations rel;
  // (computed for every event time: each symmetric relation once)
  for(int i = 0; i < 3; ++i)
    for(int j = i + 1; j < 3; ++j)
      rel.same[i][j] = rel.same[j][i] = (s[i] == s[j]);
  for(int i = 0; i < 3; ++i)
    for(int j = 0; j < 3; ++j) {
      if(i == j || s[j].is_point) continue;
      if(s[i].is_point) {
        rel.point_is_source[i][j] = same_place(s[i].p, s[j].p);
        rel.point_is_target[i][j] = same_place(s[i].p, s[j].q);
      } else if(same_place(s[i].q, s[j].p)) {
        const Orientation turn = orientation(s[i].p, s[i].q, s[j].q);
        rel.flat_join[i][j] = (turn == COLLINEAR);
        rel.corner_turn[i][j] = static_cast<signed char>(int(turn));
      }
    }
  if(s[0].is_point && s[1].is_point && s[2].is_point)
    rel.ppp_orientation = int(orientation(s[0].p, s[1].p, s[2].p));
  return rel;
}

/// Whether two triples are one disk wherever both have one, by their sites
/// alone: they share two sites, one of them a segment F, and differ in a
/// segment S of one and an endpoint P of S in the other, where F continues
/// S on its line (P is a flat vertex), and the third site X is off that
/// line.  Each construction then puts the centre on the common normal at P
/// (a flat join for S and F, a point at the end of F for P), at the one
/// distance where the disk touches X (Medial_constructions.h).  Two vertices
/// of a straight border are the ends of an edge of length 0: on a quantized
/// GIS outline the pair was the commonest tie of the exact stages.
template <class K, class Site_>
bool flat_vertex_swap(const Site_ s[3], const Site_ t[3])
{
  auto shared = [](const Site_& x, const Site_* u) { return x == u[0] || x == u[1] || x == u[2]; };
  const Site_* us = nullptr;
  const Site_* ut = nullptr;
  for(int i = 0; i < 3; ++i) {
    if(!shared(s[i], t)) {
      if(us != nullptr) return false;
      us = &s[i];
    }
    if(!shared(t[i], s)) {
      if(ut != nullptr) return false;
      ut = &t[i];
    }
  }
  if(us == nullptr || ut == nullptr || us->is_point == ut->is_point) return false;
  const Site_& S = us->is_point ? *ut : *us;
  const Site_& P = us->is_point ? *us : *ut;
  const Site_* other = us->is_point ? t : s;   // the triple with S
  if(!(P.p == S.p || P.p == S.q)) return false;
  Exact_orientation<K> orientation;
  auto on_line = [&](const typename K::Point_2& x) { return orientation(S.p, S.q, x) == COLLINEAR; };
  bool flat = false, clear = true;
  for(int i = 0; i < 3; ++i) {
    const Site_& x = other[i];
    if(&x == &S) continue;
    if(!x.is_point && ((x.p == P.p && S.q == P.p) || (x.q == P.p && S.p == P.p)) && on_one_line<K>(S, x))
      flat = true;
    else if(x.is_point ? on_line(x.p) : (x.p == P.p || x.q == P.p || on_one_line<K>(S, x)))
      clear = false;
  }
  return flat && clear;
}

/// Adds to `rel` the relations of the triple `s` that only ties need (see
/// Triple_relations: segments in the same direction, points on the lines of
/// segments, and with `separator` (of a vanishing time: only its chord
/// reads it), the separator on the line of a segment),
/// from exact predicates of `K`.  Returns whether it found one: a branch
/// that the double intervals could not decide may then be decided.
template <class K, class Site_>
bool refine_relations(const Site_ s[3], const Site_* separator, Triple_relations& rel)
{
  typedef Exact_predicates_kernel_for<K> EK;
  Exact_orientation<K> orientation;
  auto collinear = [&](const auto& a, const auto& b, const auto& c) { return orientation(a, b, c) == COLLINEAR; };
  bool found = false;
  for(int i = 0; i < 3; ++i) {
    if(s[i].is_point) continue;
    for(int j = 0; j < 3; ++j) {
      if(j == i) continue;
      if(s[j].is_point) {
        rel.point_on_line[j][i] = collinear(s[i].p, s[i].q, s[j].p);
        found = found || rel.point_on_line[j][i];
      } else if(j > i) {
        // parallel (equal slopes), and the same signs of dx and dy
        const typename EK::type::Segment_2 a(EK::point(s[i].p), EK::point(s[i].q)), b(EK::point(s[j].p), EK::point(s[j].q));
        rel.same_direction[i][j] = rel.same_direction[j][i] =
          typename EK::type().compare_slope_2_object()(a, b) == EQUAL && CGAL::compare(s[i].p.x(), s[i].q.x()) == CGAL::compare(s[j].p.x(), s[j].q.x()) &&
          CGAL::compare(s[i].p.y(), s[i].q.y()) == CGAL::compare(s[j].p.y(), s[j].q.y());
        found = found || rel.same_direction[i][j];
      }
    }
    if(separator != nullptr && on_one_line<K>(*separator, s[i]))
      rel.separator_on_line = found = true;
  }
  return found;
}

/// Decides in double intervals: `stage(rel)` returns 0 or 1 where it
/// decides, -1 (or throws Uncertain_conversion_exception) where a branch
/// stays undecided; it is then run again, once, with the relations of exact
/// ties that refine_relations() adds to `rel` for the triple `s` (none
/// without sites) and `separator`.  Returns the stage's answer, or -1.
/// Each run is in upward rounding.  The interval stage of the filtered
/// model and the double model's check of "no disk" decide so.
template <class K, class Site_, class Stage>
CGAL_PMA2_ALWAYS_INLINE int decide_in_intervals(const Site_* s, const Site_* separator, Triple_relations& rel,
                                                const Stage& stage)
{
  for(int attempt = 0; attempt < 2; ++attempt) {
    if(attempt == 1 && (s == nullptr || !refine_relations<K>(s, separator, rel)))
      break;
    Upward_rounding protection;
    try {
      const int r = stage(static_cast<const Triple_relations&>(rel));
      if(r >= 0)
        return r;
    } catch(Uncertain_conversion_exception&) {
    }
  }
  return -1;
}

template <class NT, class Site_, class Convert>
Site_nt<NT> site_nt(const Site_& s, const Convert& cv)
{
  Site_nt<NT> r;
  r.is_point = s.is_point;
  r.ax = cv(s.p.x()); r.ay = cv(s.p.y());
  r.bx = cv(s.q.x()); r.by = cv(s.q.y());
  r.axis_parallel = !s.is_point && (s.p.x() == s.q.x() || s.p.y() == s.q.y());
  r.double_coordinates = std::is_same<std::decay_t<decltype(s.p.x())>, double>::value;
  return r;
}

/// The scale of the coordinates of a disk and its sites, which the
/// tangency tolerance of plausible_circle() is relative to.
template <class NT>
NT plausible_scale(const Site_nt<NT> s[3], const Circle_nt<NT>& c)
{
  using std::fabs;
  NT scale = fabs(c.x) + fabs(c.y) + fabs(c.r);
  for(int i = 0; i < 3; ++i)
    scale = (std::max)(scale, (std::max)((std::max)(fabs(s[i].ax), fabs(s[i].ay)), (std::max)(fabs(s[i].bx), fabs(s[i].by))));
  return scale;
}

/// Whether a circle computed in double is tangent to its three sites, up to
/// a relative 1e-9 of the coordinates involved: a check against the wild
/// results of ill-conditioned constructions, not a proof.  With `vertex`,
/// the circle is a vertex of the result and must be tangent within 1e-9 of
/// its radius (and a few units in the last place of its centre): the double
/// model builds it with exact decisions otherwise.
template <class NT>
bool plausible_circle(const Site_nt<NT> s[3], const Triple_relations& rel, const Circle_nt<NT>& c, bool vertex = false)
{
  using std::fabs;
  const NT centre_scale = fabs(c.x) + fabs(c.y) + fabs(c.r);
  const NT scale = plausible_scale(s, c);
  const NT tolerance = vertex ? NT(1e-9) * fabs(c.r) + NT(32 * 2.220446049250313e-16) * centre_scale : NT(1e-9) * scale;
  if(!(c.r >= 0) || !std::isfinite(c.x) || !std::isfinite(c.y)) return false;
  for(int i = 0; i < 3; ++i) {
    NT d;
    if(s[i].is_point) {
      const NT dx = c.x - s[i].ax, dy = c.y - s[i].ay;
      d = std::sqrt(dx * dx + dy * dy);
    } else {
      const NT dx = s[i].bx - s[i].ax, dy = s[i].by - s[i].ay;
      const NT l2 = dx * dx + dy * dy;
      const NT f = dx * (c.x - s[i].ax) + dy * (c.y - s[i].ay);
      if(vertex && !(f > 0 && f < l2)) {
        // a vertex touches the segment itself: off its line's foot within
        // the segment, the distance is that to the nearer end
        const NT ex = c.x - (f > 0 ? s[i].bx : s[i].ax), ey = c.y - (f > 0 ? s[i].by : s[i].ay);
        d = std::sqrt(ex * ex + ey * ey);
      } else {
        d = fabs(dx * (c.y - s[i].ay) - dy * (c.x - s[i].ax)) / std::sqrt(l2);
      }
    }
    if(fabs(d - c.r) > tolerance) return false;
  }
  (void)rel;
  return true;
}

/// A first-order estimate of the error of a disk constructed in double
/// precision, for the double model: bounds `dc` on the error of each
/// coordinate of the centre and `dr` on that of the radius.  They come from
/// the residuals of the equations that define the disk (tangency to each
/// site, or a known contact point on the line of a segment), evaluated at
/// the computed disk, through the inverse of their Jacobian: the
/// construction's conditioning, which grows without bound where two segment
/// sites become parallel with their interiors on the same side, or where
/// the disk touches a segment's line close to a point site.  The fixed
/// margins alone missed such errors: on a grid moved off its integers by
/// 1e-6, vanishing times computed in double were off by up to 1e-7 of the
/// squared length of their separator (a tenth of the time itself), ten
/// times the margin of a near tie, while every disk passed
/// plausible_circle() (RESULTS.md, forty-third session).  Infinite where the Jacobian is singular at working
/// precision.  An estimate, not a proof.
inline void disk_error_estimate(const Site_nt<double> s[3], const Triple_relations& rel, const Circle_nt<double>& c,
                                double& dc, double& dr, double* largest_residual = nullptr)
{
  using std::fabs;
  const double inf = std::numeric_limits<double>::infinity();
  dc = dr = inf;
  if(largest_residual != nullptr) *largest_residual = inf;
  if(!(c.r > 0) || !std::isfinite(c.x) || !std::isfinite(c.y) || !std::isfinite(c.r)) return;
  // the unit direction of each segment site (one square root each: this
  // runs for every event time of the double model)
  double ux[3] = {0, 0, 0}, uy[3] = {0, 0, 0};
  for(int i = 0; i < 3; ++i) {
    if(s[i].is_point) continue;
    const double lx = s[i].bx - s[i].ax, ly = s[i].by - s[i].ay, l2 = lx * lx + ly * ly;
    if(!(l2 > 0)) return;
    const double inv = 1 / std::sqrt(l2);
    ux[i] = lx * inv; uy[i] = ly * inv;
  }
  const double inv_r = 1 / c.r;
  // rows (a, b, e) of the Jacobian in (x, y, r), the residual of each, and
  // the scale of the rounding errors of its evaluation
  double J[3][3], res[3], scale[3];
  int n = 0;
  auto point_row = [&](double px, double py) {
    // |v| - r as (|v|^2 - r^2) / 2r, and v / r for v / |v|: no square root,
    // equal to first order
    const double vx = c.x - px, vy = c.y - py;
    J[n][0] = vx * inv_r; J[n][1] = vy * inv_r; J[n][2] = -1;
    res[n] = (vx * vx + vy * vy - c.r * c.r) * (0.5 * inv_r);
    scale[n++] = fabs(vx) + fabs(vy) + c.r;
    return true;
  };
  auto line_row = [&](int i) {   // tangent to the line of s[i], interior side
    J[n][0] = -uy[i]; J[n][1] = ux[i]; J[n][2] = -1;
    res[n] = -uy[i] * (c.x - s[i].ax) + ux[i] * (c.y - s[i].ay) - c.r;
    scale[n++] = fabs(c.x - s[i].ax) + fabs(c.y - s[i].ay) + c.r;
    return true;
  };
  auto contact_rows = [&](double px, double py, int i) {   // touches the line of s[i] at (px, py)
    J[n][0] = ux[i]; J[n][1] = uy[i]; J[n][2] = 0;
    res[n] = ux[i] * (c.x - px) + uy[i] * (c.y - py);
    scale[n++] = fabs(c.x - px) + fabs(c.y - py);
    J[n][0] = -uy[i]; J[n][1] = ux[i]; J[n][2] = -1;
    res[n] = -uy[i] * (c.x - px) + ux[i] * (c.y - py) - c.r;
    scale[n++] = fabs(c.x - px) + fabs(c.y - py) + c.r;
    return true;
  };
  // Two segments that meet at a corner P (s[i] ends where s[j] starts): a
  // disk tangent to both lines has its centre on their bisector through P,
  // the line {c : (u_i + u_j).(c - P) = 0} for their unit directions.  The
  // difference of their two tangency equations, which it replaces, is
  // nearly singular where the corner is nearly flat (consecutive segments
  // of a finely sampled outline), while the constructions find such
  // centres accurately.  Used where the directions are less than 120
  // degrees apart (|u_i + u_j| > 1), at most twice (three corners would
  // drop every tangency).
  auto generic = [&]() {
    for(int i = 0; i < 3; ++i) {
      if(s[i].is_point) point_row(s[i].ax, s[i].ay);
      else line_row(i);
    }
    int replaced = 0;
    bool done[3] = {false, false, false};
    for(int i = 0; i < 3 && replaced < 2; ++i)
      for(int j = 0; j < 3 && replaced < 2; ++j) {
        if(i == j || done[i] || rel.corner_turn[i][j] == 0) continue;
        const double bx = ux[i] + ux[j], by = uy[i] + uy[j], b2 = bx * bx + by * by;
        if(!(b2 > 1)) continue;
        const double inv = 1 / std::sqrt(b2);
        J[i][0] = bx * inv; J[i][1] = by * inv; J[i][2] = 0;
        res[i] = (bx * (c.x - s[i].bx) + by * (c.y - s[i].by)) * inv;
        scale[i] = fabs(c.x - s[i].bx) + fabs(c.y - s[i].by);
        done[i] = true;
        ++replaced;
      }
    // So for two point sites: their perpendicular bisector, the difference
    // of their equations, which is nearly singular for nearly collinear
    // points far from the centre
    for(int i = 0; i < 3 && replaced < 2; ++i)
      for(int j = i + 1; j < 3 && replaced < 2; ++j) {
        if(done[i] || !s[i].is_point || !s[j].is_point) continue;
        const double bx = s[j].ax - s[i].ax, by = s[j].ay - s[i].ay, b2 = bx * bx + by * by;
        if(!(b2 > 0)) continue;
        const double inv = 1 / std::sqrt(b2);
        const double mx = c.x - (s[i].ax + bx / 2), my = c.y - (s[i].ay + by / 2);
        J[i][0] = bx * inv; J[i][1] = by * inv; J[i][2] = 0;
        res[i] = (bx * mx + by * my) * inv;
        scale[i] = fabs(mx) + fabs(my) + fabs(bx) + fabs(by);
        done[i] = true;
        ++replaced;
      }
    return true;
  };
  // the same cases as medial_circle_decided()
  bool rows = false;
  const int np = int(s[0].is_point) + int(s[1].is_point) + int(s[2].is_point);
  if(np == 3) rows = generic();
  else if(np == 2) {
    const int k = s[0].is_point ? (s[1].is_point ? 2 : 1) : 0, ip = (k + 1) % 3, iq = (k + 2) % 3;
    if(rel.point_is_target[ip][k]) rows = contact_rows(s[ip].ax, s[ip].ay, k) && point_row(s[iq].ax, s[iq].ay);
    else if(rel.point_is_source[iq][k]) rows = contact_rows(s[iq].ax, s[iq].ay, k) && point_row(s[ip].ax, s[ip].ay);
    else rows = generic();
  } else if(np == 1) {
    const int ip = s[0].is_point ? 0 : (s[1].is_point ? 1 : 2), i1 = (ip + 1) % 3, i2 = (ip + 2) % 3;
    if(rel.point_is_source[ip][i1]) rows = contact_rows(s[ip].ax, s[ip].ay, i1) && line_row(i2);
    else if(rel.point_is_target[ip][i2]) rows = contact_rows(s[ip].ax, s[ip].ay, i2) && line_row(i1);
    else if(rel.flat_join[i1][i2]) rows = contact_rows(s[i1].bx, s[i1].by, i1) && point_row(s[ip].ax, s[ip].ay);
    else rows = generic();
  } else {
    int joined = -1;
    for(int i = 0; i < 3 && joined < 0; ++i)
      if(rel.flat_join[i][(i + 1) % 3]) joined = i;
    if(joined >= 0) rows = contact_rows(s[joined].bx, s[joined].by, joined) && line_row((joined + 2) % 3);
    else rows = generic();
  }
  if(!rows || n != 3) return;
  if(largest_residual != nullptr)
    *largest_residual = (std::max)((std::max)(fabs(res[0]), fabs(res[1])), fabs(res[2]));
  // the inverse of J by its adjugate
  double A[3][3];
  for(int i = 0; i < 3; ++i)
    for(int j = 0; j < 3; ++j) {
      const int i1 = (j + 1) % 3, i2 = (j + 2) % 3, j1 = (i + 1) % 3, j2 = (i + 2) % 3;
      A[i][j] = J[i1][j1] * J[i2][j2] - J[i1][j2] * J[i2][j1];   // cofactor of J[j][i]
    }
  const double det = J[0][0] * A[0][0] + J[0][1] * A[1][0] + J[0][2] * A[2][0];
  if(!(fabs(det) > 1e-300) || !std::isfinite(det)) return;
  // each residual, plus the rounding errors of its evaluation (of the
  // differences from the centre as it is stored, a few units in the last
  // place of them); a factor 4 for the terms of higher order
  double e[3];
  for(int j = 0; j < 3; ++j) e[j] = fabs(res[j]) + 8 * 2.220446049250313e-16 * scale[j];
  double d[3];
  for(int i = 0; i < 3; ++i) d[i] = 4 * (fabs(A[i][0]) * e[0] + fabs(A[i][1]) * e[1] + fabs(A[i][2]) * e[2]) / fabs(det);
  dc = (std::max)(d[0], d[1]);
  dr = d[2];
  if(!std::isfinite(dc) || !std::isfinite(dr)) dc = dr = inf;
}

/// TIME_FOOT: the foot on the separator of the point of site s[0].
/// TIME_CONFLICT: not a time, but a number of the same algebraic kind whose
/// sign is asked: the squared distance from the centre of the disk tangent to
/// s[0], s[1], s[2] to the closed segment `line`, minus the squared radius
/// (negative: the open disk meets the segment; the cut of boundary
/// evolution, Medial_cut.h).
enum Time_kind : unsigned char { TIME_ZERO, TIME_END, TIME_SWITCH, TIME_VANISH, TIME_FOOT, TIME_CONFLICT };

/// A vertex of the separator's cell whose disk passes through an endpoint of
/// the separator (a reflex vertex there) lies on the normal at that endpoint:
/// its switch time is known exactly.  So does the vertex of the disk tangent
/// to `c` (a side of the separator) at an end where a segment continues it
/// on its line: for such a flat join the construction puts the centre on the
/// normal there.  Common where a diagonal of the triangulation joins two
/// vertices of a straight border (on a quantized GIS outline, these switch
/// times tied with the end of the separator and went to MPFR one by one).
/// `K` decides the collinearity exactly.
template <class K, class Site_>
Time_kind switch_time_kind(const Site_& line, const Site_& c, const Site_& a, const Site_& b)
{
  if((a.is_point && same_place(a.p, line.p)) || (b.is_point && same_place(b.p, line.p))) return TIME_ZERO;
  if((a.is_point && same_place(a.p, line.q)) || (b.is_point && same_place(b.p, line.q))) return TIME_END;
  if(!c.is_point) {
    // (flat joins as triple_relations() finds them: c then a, or b then c)
    const typename K::Point_2* z = nullptr;
    if(!a.is_point && same_place(a.p, c.q) && Exact_orientation<K>()(c.p, c.q, a.q) == COLLINEAR) z = &c.q;
    else if(!b.is_point && same_place(b.q, c.p) && Exact_orientation<K>()(b.p, b.q, c.q) == COLLINEAR) z = &c.p;
    if(z != nullptr && same_place(*z, line.p)) return TIME_ZERO;
    if(z != nullptr && same_place(*z, line.q)) return TIME_END;
  }
  return TIME_SWITCH;
}

/// Evaluates an event time in number type NT.  Returns false when a
/// vanishing event does not exist (for a switch time, when the disk cannot
/// be built: the caller then falls back on the stored vertex).  With `rad`,
/// the time is `t + sqrt(*rad)` (the square root of a vanishing time is not
/// taken; *rad = 0 for the other kinds).  Where the number type (intervals)
/// cannot decide a branch (of the disk, or of the last tests of a vanishing
/// time: does the disk touch the segments, does it meet the separator),
/// Uncertain_conversion_exception is thrown, or with `undecided`,
/// `*undecided` is set and false returned: where most undecided evaluations
/// of integer grids end.
template <class NT, class Site_, class Convert>
bool evaluate_time(Time_kind kind, const Site_& c, const Site_* s, const Triple_relations& rel,
                   const Convert& cv, NT& t, NT* rad = nullptr, bool* undecided = nullptr,
                   Circle_nt<NT>* circle_out = nullptr, bool check_plausible = true)
{
  auto outcome = [undecided](int found) {
    if(found >= 0 || undecided == nullptr)
      return certain_or_throw(found, "evaluate_time: undecided comparison");
    *undecided = true;
    return false;
  };
  if(rad != nullptr)
    *rad = NT(0);
  NT px = cv(c.p.x()), py = cv(c.p.y()), qx = cv(c.q.x()), qy = cv(c.q.y());
  switch(kind) {
  case TIME_ZERO:
    t = NT(0);
    return true;
  case TIME_END:
    t = (qx - px) * (qx - px) + (qy - py) * (qy - py);
    return true;
  case TIME_FOOT:
    t = (qx - px) * (cv(s[0].p.x()) - px) + (qy - py) * (cv(s[0].p.y()) - py);
    return true;
  default:
    break;
  }
  Site_nt<NT> sn[3] = {site_nt<NT>(s[0], cv), site_nt<NT>(s[1], cv), site_nt<NT>(s[2], cv)};
  Circle_nt<NT> circle;
  if(!outcome(medial_circle_decided(sn, rel, circle)))
    return false;
  if constexpr(std::is_floating_point<NT>::value) {
    // a circle built in floating point from nearly degenerate sites can be
    // far off: the decisions made on it would not be the exact ones (the
    // double model checks it itself, with disk_error_estimate())
    if(check_plausible && !plausible_circle(sn, rel, circle))
      throw Uncertain_decision();
  }
  if(circle_out != nullptr)
    *circle_out = circle;
  if(kind == TIME_SWITCH) {
    t = foot_position(px, py, qx, qy, circle);
    return true;
  }
  if(kind == TIME_CONFLICT) {
    t = conflict_value(px, py, qx, qy, circle);
    return true;
  }
  // a vanishing point needs a disk that touches the segments themselves
  const double tolerance = std::is_floating_point<NT>::value ? floating_contact_tolerance : 0.0;
  if(!outcome(touches_segments(sn, rel, circle, tolerance)))
    return false;
  if(rad != nullptr)
    return outcome(chord_far_end_parts(px, py, qx, qy, circle, t, *rad, rel.separator_on_line));
  return outcome(chord_far_end(px, py, qx, qy, circle, t, rel.separator_on_line));
}

struct Identity_convert {
  template <class T> const T& operator()(const T& x) const { return x; }
};

/// The exact value of a coordinate of an exact kernel (Epeck), as a Gmpq.
inline const Gmpq& exact_gmpq(const Gmpq& q) { return q; }
#ifdef CGAL_USE_GMPXX
inline Gmpq exact_gmpq(const ::mpq_class& q) { return Gmpq(q.get_mpq_t()); }
#endif
template <class ET>
Gmpq exact_gmpq(const Lazy_exact_nt<ET>& x)
{
  return exact_gmpq(CGAL::exact(x));
}
template <class Backend, boost::multiprecision::expression_template_option ET>
Gmpq exact_gmpq(const boost::multiprecision::number<Backend, ET>& q)
{
  return Gmpq(q.backend().data());
}

/// Converts a coordinate (a double, or an exact number of Epeck) to the
/// number type NT of a stage of the filtered traits: exactly, except for
/// the intervals, which enclose it.
template <class NT>
struct To_nt_convert {
  NT operator()(double x) const { return NT(x); }
  template <class T>
  NT operator()(const T& x) const
  {
    if constexpr(std::is_same<NT, Interval_nt<false> >::value || std::is_same<NT, Double_double_interval>::value)
      return NT(CGAL::to_interval(x));
    else if constexpr(std::is_same<NT, Double_double>::value) {
      const std::pair<double, double> i = CGAL::to_interval(x);
      if(i.first != i.second)
        throw Inexact_double_double_input();
      return NT(i.first);
    }
    else if constexpr(std::is_same<NT, Small_one_root>::value || std::is_same<NT, Small_nested_root_number>::value)
      return NT(Small_rational(exact_gmpq(x)));
    else if constexpr(std::is_same<NT, double>::value) return CGAL::to_double(x);
    else return NT(exact_gmpq(x));
  }
};

/// The mirror (reflection) that maps the point x to the point y != x,
/// exact, in GMP rationals: its axis is the bisector of x and y, and the
/// image of z is z - ((2z - x - y).n / |n|^2) n, with n = y - x.  A site's
/// image is its mirror image with the segment reversed, so that the shape
/// stays on its left.
template <class Point>
class Exact_mirror
{
  typedef Gmp_rational Q;
  struct Xy {
    Q x, y;
  };

public:
  Exact_mirror(const Point& x, const Point& y)
  {
    const Xy a = xy(x), b = xy(y);
    nx_ = b.x - a.x;
    ny_ = b.y - a.y;
    mx_ = a.x + b.x;
    my_ = a.y + b.y;
    nn_ = nx_ * nx_ + ny_ * ny_;
  }

  /// Whether w is the image of z.
  bool image(const Point& z, const Point& w) const
  {
    const Xy a = xy(z), b = xy(w);
    const Q d = dot(a);
    return nn_ * (a.x - b.x) == d * nx_ && nn_ * (a.y - b.y) == d * ny_;
  }
  /// Whether the site v is the image of the site u.
  template <class Site_>
  bool image(const Site_& u, const Site_& v) const
  {
    if(u.is_point != v.is_point)
      return false;
    return u.is_point ? image(u.p, v.p) : (image(u.q, v.p) && image(u.p, v.q));
  }
  /// Whether the segment v lies on the line of the image of the segment u.
  template <class Site_>
  bool on_image_line(const Site_& u, const Site_& v) const
  {
    const Xy a = apply(xy(u.p)), b = apply(xy(u.q));
    return on_line(a, b, xy(v.p)) && on_line(a, b, xy(v.q));
  }

private:
  static Xy xy(const Point& p)
  {
    To_nt_convert<Q> cv;
    return Xy{cv(p.x()), cv(p.y())};
  }
  static bool on_line(const Xy& a, const Xy& b, const Xy& z)
  {
    return (b.x - a.x) * (z.y - a.y) == (b.y - a.y) * (z.x - a.x);
  }
  Q dot(const Xy& z) const { return (Q(2) * z.x - mx_) * nx_ + (Q(2) * z.y - my_) * ny_; }
  Xy apply(const Xy& z) const
  {
    const Q f = dot(z) / nn_;
    return Xy{z.x - f * nx_, z.y - f * ny_};
  }

  Q nx_, ny_, mx_, my_, nn_;
};

/// The mirror that swaps two segments of the triple `s`, i and j, that are
/// not on one line, or false.
template <class K, class Site_>
std::optional<Exact_mirror<typename Site_::Point_2> > swapping_mirror(const Site_* s, int i, int j)
{
  typedef Exact_mirror<typename Site_::Point_2> Mirror;
  if(s[i].is_point || s[j].is_point || s[i] == s[j] || on_one_line<K>(s[i], s[j]))
    return std::nullopt;
  // (segments not on one line: one of the two pairs of ends is two points)
  const Mirror m = s[i].q != s[j].p ? Mirror(s[i].q, s[j].p) : Mirror(s[i].p, s[j].q);
  if(!m.image(s[i], s[j]))
    return std::nullopt;
  return m;
}

/// Whether two event times of one kind along the segment `line`, of the
/// triples `s` and `t`, are equal by a symmetry.  The disk of a triple
/// whose sites include a segment is tangent to the segment's line, on the
/// shape's side, with the others: its centre is at the same signed distance
/// from the lines of its segments.  It is so when:
/// 1. a mirror maps `s` onto `t` (in the reversed cyclic order, since a
///    mirror turns counter-clockwise into clockwise), which maps the disk of
///    `s` onto the disk of `t`, and either its axis is the line (it fixes
///    the line point by point: the two disks have the same foot on it and
///    the same chord), or it swaps two sites of `s` (the centre of a disk
///    that touches two points swapped by the mirror, or two segments not on
///    one line, is on the axis: on the other bisector of two segments' lines
///    the signed distances are opposite; so the mirror maps the disk onto
///    itself, and the two disks are one);
/// 2. one mirror swaps two segments of `s` and two of `t`: both disks are
///    then symmetric, so each touches the images of its segments too, and
///    with them two segments u and v whose lines are neither one line nor
///    mirror images of each other.  Both centres are then where the axis
///    meets the line of the points at equal signed distance from u and v,
///    which is not the axis: one point, one disk.
/// Symmetric shapes have such ties: DejaVuSerif-Bold `question`, whose hook
/// is symmetric about a diagonal of the triangulation and whose dot is a
/// rounded square, FreeMono's strokes with their round ends, regular
/// polygons, where many segments touch one circle.  The nested-root stage
/// decided them by algebra, at most of their time.  `K` decides
/// collinearity exactly.
template <class K, class Site_>
bool mirror_tie(const Site_& line, const Site_* s, const Site_* t)
{
  typedef typename Site_::Point_2 Point;
  typedef Exact_mirror<Point> Mirror;
  // 1.
  for(int k = 0; k < 3; ++k) {
    // the pairs (point, image) of this rotation
    std::pair<const Point*, const Point*> pairs[6];
    int n_pairs = 0;
    bool types = true;
    for(int j = 0; j < 3 && types; ++j) {
      const Site_& x = s[(k + 3 - j) % 3];
      const Site_& y = t[j];
      if(x.is_point != y.is_point) {
        types = false;
      } else if(x.is_point) {
        pairs[n_pairs++] = {&x.p, &y.p};
      } else {
        pairs[n_pairs++] = {&x.q, &y.p};
        pairs[n_pairs++] = {&x.p, &y.q};
      }
    }
    if(!types)
      continue;
    int moved = 0;
    while(moved < n_pairs && *pairs[moved].first == *pairs[moved].second)
      ++moved;
    if(moved == n_pairs)
      continue;
    const Mirror m(*pairs[moved].first, *pairs[moved].second);
    bool mirror = true;
    for(int i = 0; i < n_pairs && mirror; ++i)
      if(i != moved)
        mirror = m.image(*pairs[i].first, *pairs[i].second);
    if(!mirror)
      continue;
    if(m.image(line.p, line.p) && m.image(line.q, line.q))
      return true;
    for(int i = 0; i < 3; ++i)
      for(int j = 0; j < 3; ++j) {
        if(i == j || s[i].is_point != s[j].is_point || s[i] == s[j])
          continue;
        if(m.image(s[i], s[j]) && (s[i].is_point || !on_one_line<K>(s[i], s[j])))
          return true;
      }
  }
  // 2.
  for(int i = 0; i < 3; ++i)
    for(int j = i + 1; j < 3; ++j) {
      const std::optional<Mirror> m = swapping_mirror<K>(s, i, j);
      if(!m)
        continue;
      bool t_symmetric = false;
      for(int a = 0; a < 3 && !t_symmetric; ++a)
        for(int b = a + 1; b < 3 && !t_symmetric; ++b)
          t_symmetric = !t[a].is_point && !t[b].is_point && !on_one_line<K>(t[a], t[b]) && m->image(t[a], t[b]);
      if(!t_symmetric)
        continue;
      // the segments of s whose orbit (the segment and its image) meets t
      const Site_* shared[3];
      int n_shared = 0;
      for(int a = 0; a < 3; ++a) {
        if(s[a].is_point)
          continue;
        for(int b = 0; b < 3; ++b)
          if(t[b] == s[a] || m->image(s[a], t[b])) {
            shared[n_shared++] = &s[a];
            break;
          }
      }
      for(int a = 0; a < n_shared; ++a)
        for(int b = a + 1; b < n_shared; ++b)
          if(!on_one_line<K>(*shared[a], *shared[b]) && !m->on_image_line(*shared[a], *shared[b]))
            return true;
    }
  return false;
}

/// The function objects of the concept `ProgressiveMedialAxisTraits_2`,
/// written once on top of the primitives of a model `Model` (static member
/// functions):
///   bool time(Time_kind, const Site_2& line, const Site_2* s, Event_time_2& t)
///   Event_time_2 foot_time(const Site_2& line, const Point_2& p)
///   Comparison_result compare_times(const Event_time_2&, const Event_time_2&)
///   bool in_past(const Event_time_2& t, const Event_time_2& now, const Site_2& line)
///   bool disk(const Site_2* s, Point_2& centre, FT& radius)
template <class Model, class Kernel_, class FT_, class Point_2_, class Event_time_2_>
class Traits_functors
{
public:
  typedef Kernel_ Kernel;
  typedef FT_ FT;
  typedef Point_2_ Point_2;
  /// A generator: a point, or a segment with the shape on its left.
  typedef Site<Point_2> Site_2;
  /// The position of an event along the separator.
  typedef Event_time_2_ Event_time_2;
  /// The orientation of three points, exact (also for a kernel of doubles).
  typedef Exact_orientation<Kernel> Orientation_2;

  Orientation_2 orientation_2_object() const { return Orientation_2(); }

  /// The time 0 (the source of the separator) and the time of its target.
  struct Compute_start_time_2 {
    Event_time_2 operator()(const Site_2& line) const
    {
      Event_time_2 t;
      Model::time(TIME_ZERO, line, nullptr, t);
      return t;
    }
  };
  struct Compute_end_time_2 {
    Event_time_2 operator()(const Site_2& line) const
    {
      Event_time_2 t;
      Model::time(TIME_END, line, nullptr, t);
      return t;
    }
  };

  /// Time, along the separator `line` (from its source P to its target Q),
  /// of the foot of the disk tangent to `c, a, b` in counter-clockwise
  /// order, where `c` is one side of the separator (`line` or its reverse):
  /// a vertex of the cell of `c`.  False if the disk cannot be built.
  struct Compute_switch_time_2 {
    bool operator()(const Site_2& line, const Site_2& c, const Site_2& a, const Site_2& b,
                    Event_time_2& t) const
    {
      Site_2 s[3] = {c, a, b};
      return Model::time(switch_time_kind<Kernel>(line, c, a, b), line, s, t);
    }
    /// The same, where `hint` may enclose the disk's centre (see
    /// Compute_vanishing_time_2).
    template <class Hint>
    bool operator()(const Site_2& line, const Site_2& c, const Site_2& a, const Site_2& b, Event_time_2& t,
                    const Hint& hint) const
    {
      Site_2 s[3] = {c, a, b};
      const Time_kind kind = switch_time_kind<Kernel>(line, c, a, b);
      if(kind == TIME_SWITCH && hint.valid)
        return Model::switch_time_from_hint(line, s, hint, t);
      return Model::time(kind, line, s, t);
    }
  };

  /// Time, along the separator `line`, of the foot of the point `p`.
  struct Compute_foot_time_2 {
    Event_time_2 operator()(const Site_2& line, const Point_2& p) const { return Model::foot_time(line, p); }
  };

  /// Time at which the tip retracting along `line` meets the disk tangent to
  /// `a, b, d` (in counter-clockwise order): the vanishing of `b`.  False if
  /// there is no such disk, if it does not touch the segments themselves, or
  /// if it does not meet the separator's line.
  struct Compute_vanishing_time_2 {
    bool operator()(const Site_2& line, const Site_2& a, const Site_2& b, const Site_2& d,
                    Event_time_2& t) const
    {
      Site_2 s[3] = {a, b, d};
      return Model::time(TIME_VANISH, line, s, t);
    }
    /// The same, and where the model has a `Disk_hint`, `hint` is then
    /// either invalid or an enclosure of the centre of the disk (in
    /// interval arithmetic): the merge keeps it with the vertex that the
    /// event makes, whose switch times are then computed from it.
    template <class Hint>
    bool operator()(const Site_2& line, const Site_2& a, const Site_2& b, const Site_2& d, Event_time_2& t,
                    Hint& hint) const
    {
      Site_2 s[3] = {a, b, d};
      return Model::time(TIME_VANISH, line, s, t, &hint);
    }
  };

  struct Compare_event_time_2 {
    Comparison_result operator()(const Event_time_2& a, const Event_time_2& b) const
    {
      return Model::compare_times(a, b);
    }
  };

  /// Whether an event computed at time `t` lies before the current time
  /// `now` on the separator `line`, so that it will never happen.
  struct Is_event_in_past_2 {
    bool operator()(const Event_time_2& t, const Event_time_2& now, const Site_2& line) const
    {
      return Model::in_past(t, now, line);
    }
  };

  /// Constructs the disk tangent to three sites in counter-clockwise order
  /// around its centre.  False if there is none.
  struct Construct_medial_disk_2 {
    bool operator()(const Site_2& a, const Site_2& b, const Site_2& c, Point_2& centre, FT& radius) const
    {
      Site_2 s[3] = {a, b, c};
      return Model::disk(s, centre, radius);
    }
  };

  /// Whether the disks tangent to the sites `a0, a1, a2` and to `b0, b1,
  /// b2` (each triple counter-clockwise around its centre) are the same
  /// disk: two vertices of the medial axis at one point.
  struct Equal_medial_disks_2 {
    bool operator()(const Site_2& a0, const Site_2& a1, const Site_2& a2, const Site_2& b0, const Site_2& b1,
                    const Site_2& b2) const
    {
      Site_2 s[3] = {a0, a1, a2}, t[3] = {b0, b1, b2};
      return Model::same_disk(s, t);
    }
  };

  /// Time, along the segment `line` (from its source to its target), of the
  /// foot of the centre of the disk tangent to `a, b, c` in counter-clockwise
  /// order, a disk that need not touch `line`.  False if there is no such
  /// disk.
  struct Compute_disk_foot_time_2 {
    bool operator()(const Site_2& line, const Site_2& a, const Site_2& b, const Site_2& c, Event_time_2& t) const
    {
      Site_2 s[3] = {a, b, c};
      return Model::time(TIME_SWITCH, line, s, t);
    }
  };

  /// Whether the open disk tangent to `a, b, c` (counter-clockwise around
  /// its centre; the disk must exist) meets the closed segment `segment`:
  /// the vertex of the medial axis at its centre is in conflict with a new
  /// boundary edge (the cut of boundary evolution).
  struct Do_intersect_disk_segment_2 {
    bool operator()(const Site_2& a, const Site_2& b, const Site_2& c, const Site_2& segment) const
    {
      Site_2 s[3] = {a, b, c};
      return Model::conflict(segment, s);
    }
  };

  Compute_disk_foot_time_2 compute_disk_foot_time_2_object() const { return Compute_disk_foot_time_2(); }
  Do_intersect_disk_segment_2 do_intersect_disk_segment_2_object() const { return Do_intersect_disk_segment_2(); }
  Equal_medial_disks_2 equal_medial_disks_2_object() const { return Equal_medial_disks_2(); }
  Compute_start_time_2 compute_start_time_2_object() const { return Compute_start_time_2(); }
  Compute_end_time_2 compute_end_time_2_object() const { return Compute_end_time_2(); }
  Compute_switch_time_2 compute_switch_time_2_object() const { return Compute_switch_time_2(); }
  Compute_foot_time_2 compute_foot_time_2_object() const { return Compute_foot_time_2(); }
  Compute_vanishing_time_2 compute_vanishing_time_2_object() const { return Compute_vanishing_time_2(); }
  Compare_event_time_2 compare_event_time_2_object() const { return Compare_event_time_2(); }
  Is_event_in_past_2 is_event_in_past_2_object() const { return Is_event_in_past_2(); }
  Construct_medial_disk_2 construct_medial_disk_2_object() const { return Construct_medial_disk_2(); }
};


/// The model that computes every construction and decision in `K::FT`
/// (see Progressive_medial_axis_traits_2).
/// An event time of the double-precision model: its value, the squared
/// length of its separator (the scale of its rounding errors) and an id
/// shared by its copies (one event compared with itself is not a near tie).
struct Double_time {
  double t = 0, scale = 1;
  double err = 0;   // an estimate of the error of t (Number_model::time_error())
  std::uint64_t id = 0;
  bool exact = false;   // the start of the separator: 0, exactly
  static std::uint64_t next_id()
  {
    static thread_local std::uint64_t n = 0;
    return ++n;
  }
};

/// Two times within this fraction of the squared length of the separator,
/// plus their estimated errors (Double_time::err), are a near tie, which
/// the double-precision model does not decide.
constexpr double near_tie = 1e-10;

template <class FT>
struct Number_time {
  typedef typename std::conditional<std::is_floating_point<FT>::value, Double_time, FT>::type type;
};

template <class CK> class Filtered_model;

template <class K>
class Number_model
  : public Traits_functors<Number_model<K>, K, typename K::FT, typename K::Point_2, typename Number_time<typename K::FT>::type>
{
  typedef Traits_functors<Number_model<K>, K, typename K::FT, typename K::Point_2, typename Number_time<typename K::FT>::type> Base;
  friend Base;

public:
  typedef typename Base::FT FT;
  typedef typename Base::Point_2 Point_2;
  typedef typename Base::Site_2 Site_2;
  typedef typename Base::Event_time_2 Event_time_2;

  /// Whether the event decisions of this model are exact.
  static constexpr bool Has_exact_decisions = !std::is_floating_point<FT>::value;

private:
  static constexpr bool Floating = std::is_floating_point<FT>::value;

  static bool time(Progressive_medial_axes::internal::Time_kind kind, const Site_2& line, const Site_2* s, Event_time_2& t)
  {
    Progressive_medial_axes::internal::Triple_relations rel;
    if(s != nullptr) rel = Progressive_medial_axes::internal::triple_relations<K>(s);
    if constexpr(Floating) {
      t.id = Double_time::next_id();
      t.exact = kind == Progressive_medial_axes::internal::TIME_ZERO;
      const FT dx = line.q.x() - line.p.x(), dy = line.q.y() - line.p.y();
      t.scale = dx * dx + dy * dy;
      namespace I = Progressive_medial_axes::internal;
      t.err = 0;
      if(kind != I::TIME_SWITCH && kind != I::TIME_VANISH)
        return I::evaluate_time<FT>(kind, line, s, rel, I::Identity_convert(), t.t);
      FT rad = 0;
      I::Circle_nt<FT> circle;
      circle.r = -std::numeric_limits<FT>::infinity();   // (set once the disk is built)
      const bool found = I::evaluate_time<FT>(kind, line, s, rel, I::Identity_convert(), t.t, &rad, nullptr, &circle, false);
      if(circle.r == -std::numeric_limits<FT>::infinity()) {
        // no disk: a decision of signs that rounding errors can flip
        if(!found && !no_disk_certain(s, rel))
          throw I::Uncertain_decision();
        return found;
      }
      I::Identity_convert cv;
      const I::Site_nt<FT> sn[3] = {I::site_nt<FT>(s[0], cv), I::site_nt<FT>(s[1], cv), I::site_nt<FT>(s[2], cv)};
      double dc, dr, residual;
      I::disk_error_estimate(sn, rel, circle, dc, dr, &residual);
      // (what plausible_circle() checks: tangent within a relative 1e-9)
      if(!(residual <= 1e-9 * I::plausible_scale(sn, circle)))
        throw I::Uncertain_decision();
      const Chord_error chord(line, circle, dc, dr);
      if(kind == I::TIME_VANISH)
        check_vanishing_decisions(sn, rel, circle, dc, chord);
      if(!found)
        return false;
      t.err = time_error(chord, dc, t.t, rad, kind == I::TIME_VANISH);
      t.t += std::sqrt(rad);
      return true;
    } else {
      return Progressive_medial_axes::internal::evaluate_time<FT>(kind, line, s, rel, Progressive_medial_axes::internal::Identity_convert(), t);
    }
  }

  // Whether the three sites certainly have no medial disk, where the double
  // construction found none.  It decides that on signs that its rounding
  // errors can flip: with a point 2e-17 from the line of a segment, a disk
  // of radius 4e-17 tangent to that line and to the point's segment came
  // out with a negative radius, and a merge went on without its vanishing
  // event (fuzz_engine; test data double_model/point_near_line_2e-17, RESULTS.md,
  // forty-fourth session).  So the same construction is evaluated in
  // interval arithmetic, which certifies its signs or leaves them
  // undecided; only the merges that meet such a case pay for it.
  static bool no_disk_certain(const Site_2* s, const Progressive_medial_axes::internal::Triple_relations& rel)
  {
    namespace I = Progressive_medial_axes::internal;
    typedef Interval_nt<false> Interval;
    // (double coordinates convert to intervals exactly; decide_in_intervals()
    // rounds upward for the construction only, not for the exact predicates
    // of refine_relations(), whose static filters assume rounding to nearest)
    const I::To_nt_convert<Interval> cv;
    const I::Site_nt<Interval> sn[3] = {I::site_nt<Interval>(s[0], cv), I::site_nt<Interval>(s[1], cv),
                                         I::site_nt<Interval>(s[2], cv)};
    I::Circle_nt<Interval> c;
    // (as the filtered model's interval stage: where the intervals leave a
    // branch undecided, again with the relations of exact ties)
    I::Triple_relations r = rel;
    return I::decide_in_intervals<K>(s, static_cast<const Site_2*>(nullptr), r, [&](const I::Triple_relations& x) {
             const int disk = I::medial_circle_decided(sn, x, c);
             return disk < 0 ? -1 : int(disk == 0);
           }) == 1;
  }

  // The separator (P to Q) of a time against its disk, and the estimated
  // error of the radicand r^2 |d|^2 - (d x v)^2 of its chord (d = Q - P,
  // v = centre - P), from the disk's error estimate (dc, dr): what
  // time_error() and check_vanishing_decisions() both need.
  struct Chord_error {
    double vx, vy, d1, d2, h, r2d2, drad;
    Chord_error(const Site_2& line, const Progressive_medial_axes::internal::Circle_nt<FT>& c, double dc, double dr)
    {
      const double u = 2.220446049250313e-16;
      const double dx = line.q.x() - line.p.x(), dy = line.q.y() - line.p.y();
      vx = c.x - line.p.x(); vy = c.y - line.p.y();
      d1 = std::fabs(dx) + std::fabs(dy); d2 = dx * dx + dy * dy;
      h = dx * vy - dy * vx; r2d2 = c.r * c.r * d2;
      drad = 2 * c.r * d2 * dr + 2 * std::fabs(h) * d1 * dc + 8 * u * (r2d2 + h * h);
    }
  };

  // An estimate of the error of a switch or vanishing time computed in
  // double, `alpha + sqrt(rad)` (rad is 0 for a switch time), from the
  // error estimate dc of its disk's centre and that of its chord.
  static double time_error(const Chord_error& chord, double dc, double alpha, double rad, bool vanish)
  {
    const double u = 2.220446049250313e-16;
    // alpha = d.v
    double err = chord.d1 * dc + 4 * u * (std::fabs(alpha) + chord.d1 * (std::fabs(chord.vx) + std::fabs(chord.vy)));
    // |sqrt(a) - sqrt(b)| <= min(sqrt|a - b|, |a - b| / sqrt(a))
    if(vanish)
      err += chord.drad / std::sqrt((std::max)(rad, chord.drad));
    return std::isfinite(err) ? err : std::numeric_limits<double>::infinity();
  }

  // The decisions of a vanishing time in double (evaluate_time()) that its
  // disk's error can flip: does the disk touch each segment site within
  // the segment, does it meet the separator's line.  Throws
  // Uncertain_decision (the merge is redone with exact decisions) where
  // one is within the error.  On a grid moved off its integers by 1e-6, a
  // disk tangent to two consecutive nearly collinear segments was 2e-7 off,
  // its contact a hair beyond the corner between them, and the double model
  // dropped a vanishing event the exact one kept (RESULTS.md, forty-third
  // session).
  static void check_vanishing_decisions(const Progressive_medial_axes::internal::Site_nt<FT> sn[3],
                                        const Progressive_medial_axes::internal::Triple_relations& rel,
                                        const Progressive_medial_axes::internal::Circle_nt<FT>& c, double dc,
                                        const Chord_error& chord)
  {
    namespace I = Progressive_medial_axes::internal;
    const double u = 2.220446049250313e-16;
    // (the tolerance of touches_segments() and chord_far_end_parts() in double)
    const double tolerance = I::floating_contact_tolerance;
    bool uncertain = false;
    for(int i = 0; i < 3; ++i) {
      if(sn[i].is_point || I::segment_contact_known(rel, i)) continue;
      const double dx = sn[i].bx - sn[i].ax, dy = sn[i].by - sn[i].ay, d1 = std::fabs(dx) + std::fabs(dy);
      const double low = -tolerance * (dx * dx + dy * dy);
      const double before = (c.x - sn[i].ax) * dx + (c.y - sn[i].ay) * dy, beyond = (sn[i].bx - c.x) * dx + (sn[i].by - c.y) * dy;
      const double margin = d1 * dc + 4 * u * d1 * (std::fabs(c.x - sn[i].ax) + std::fabs(c.y - sn[i].ay) + d1);
      if(before < low - margin || beyond < low - margin)
        return;   // misses the segment, certainly: no event
      if(!(std::fabs(before - low) > margin) || !(std::fabs(beyond - low) > margin))
        uncertain = true;
    }
    if(uncertain)
      throw I::Uncertain_decision();
    if(rel.separator_on_line)
      return;
    if(!(std::fabs(chord.r2d2 - chord.h * chord.h + tolerance * chord.r2d2) > chord.drad))
      throw I::Uncertain_decision();
  }

  static Event_time_2 foot_time(const Site_2& line, const Point_2& p)
  {
    Event_time_2 t;
    const Site_2 s[3] = {Site_2::point(p), Site_2::point(p), Site_2::point(p)};
    time(Progressive_medial_axes::internal::TIME_FOOT, line, s, t);
    return t;
  }

  // In double precision a near tie (closer than the two estimated errors
  // plus near_tie) is not decided (Uncertain_decision): the merge is redone
  // with exact decisions.
  static Comparison_result compare_times(const Event_time_2& a, const Event_time_2& b)
  {
    if constexpr(Floating) {
      if(a.id == b.id || (a.exact && b.exact)) return EQUAL;
      if(std::fabs(a.t - b.t) <= a.err + b.err + near_tie * (std::max)(a.scale, b.scale)) throw Uncertain_decision();
      return a.t < b.t ? SMALLER : LARGER;
    } else {
      return CGAL::compare(a, b);
    }
  }

  static bool in_past(const Event_time_2& t, const Event_time_2& now, const Site_2&)
  {
    return compare_times(t, now) == SMALLER;
  }

  static bool disk(const Site_2* s, Point_2& centre, FT& radius)
  {
    Progressive_medial_axes::internal::Triple_relations rel = Progressive_medial_axes::internal::triple_relations<K>(s);
    Progressive_medial_axes::internal::Identity_convert cv;
    Progressive_medial_axes::internal::Site_nt<FT> sn[3] = {Progressive_medial_axes::internal::site_nt<FT>(s[0], cv), Progressive_medial_axes::internal::site_nt<FT>(s[1], cv),
                                         Progressive_medial_axes::internal::site_nt<FT>(s[2], cv)};
    Progressive_medial_axes::internal::Circle_nt<FT> circle;
    if constexpr(Floating) {
      // a vertex whose double construction is implausible or ambiguous is
      // built by the exact-decision model
      bool built = false;
      try {
        built = Progressive_medial_axes::internal::medial_circle(sn, rel, circle) &&
                Progressive_medial_axes::internal::plausible_circle(sn, rel, circle, true);
        if(built) {
          // tangent is not enough where the construction is ill-conditioned
          // (disk_error_estimate()): its error must be as small too
          double dc, dr;
          Progressive_medial_axes::internal::disk_error_estimate(sn, rel, circle, dc, dr);
          const FT tolerance = FT(1e-9) * circle.r + FT(32 * 2.220446049250313e-16) * (std::fabs(circle.x) + std::fabs(circle.y) + circle.r);
          built = dc <= tolerance && dr <= tolerance;
        }
      } catch(Progressive_medial_axes::internal::Uncertain_decision&) {
      }
      if(!built)
        return Filtered_model<K>::disk(s, centre, radius);
    } else {
      if(!Progressive_medial_axes::internal::medial_circle(sn, rel, circle))
        return false;
    }
    centre = Point_2(circle.x, circle.y);
    radius = circle.r;
    return true;
  }

  static bool same_disk(const Site_2* s, const Site_2* t)
  {
    Point_2 a, b;
    FT ra, rb;
    return disk(s, a, ra) && disk(t, b, rb) && a == b && ra == rb;
  }

  // In double precision a value within a relative 1e-9 of zero (a tangency,
  // or near one), or within the error its disk's estimate
  // (disk_error_estimate()) carries into it, is not decided: the cut is
  // redone with exact decisions.
  static bool conflict(const Site_2& segment, const Site_2* s)
  {
    namespace I = Progressive_medial_axes::internal;
    const I::Triple_relations rel = I::triple_relations<K>(s);
    I::Identity_convert cv;
    if constexpr(Floating) {
      I::Site_nt<FT> sn[3] = {I::site_nt<FT>(s[0], cv), I::site_nt<FT>(s[1], cv), I::site_nt<FT>(s[2], cv)};
      I::Circle_nt<FT> c;
      if(!I::medial_circle(sn, rel, c) || !I::plausible_circle(sn, rel, c, true))
        throw I::Uncertain_decision();
      const FT v = I::conflict_value(segment.p.x(), segment.p.y(), segment.q.x(), segment.q.y(), c);
      // the centre is off by a few units in the last place of its
      // coordinates: dist^2 by about 2 r times that
      const FT centre_error = FT(64 * 2.220446049250313e-16) * (std::fabs(c.x) + std::fabs(c.y) + c.r);
      // v = dist^2 - r^2: a centre off by dc in each coordinate moves dist
      // by at most 2 dc, a radius off by dr moves r by dr
      double dc, dr;
      I::disk_error_estimate(sn, rel, c, dc, dr);
      const FT dist = std::sqrt((std::max)(v + c.r * c.r, FT(0)));
      const FT disk_error = FT(4) * dist * dc + FT(2) * c.r * dr + FT(4) * dc * dc + dr * dr;
      if(!(std::fabs(v) > FT(1e-9) * (c.r * c.r + std::fabs(v)) + FT(2) * c.r * centre_error + disk_error))
        throw I::Uncertain_decision();
      return v < 0;
    } else {
      FT v;
      if(!I::evaluate_time<FT>(I::TIME_CONFLICT, segment, s, rel, cv, v))
        throw I::Uncertain_decision();   // no such disk
      return CGAL::is_negative(v);
    }
  }
};

/// The span, in bits, of the coordinates of sites: from the highest bit of
/// the largest to the lowest set bit of any.  At most 24 bits (integers of a
/// grid, short binary fractions), the one-root computations fit in
/// Small_rational and the filtered traits try them, then the nested-root
/// numbers, without the MPFR intervals (what the double intervals could not
/// decide is then almost always an exact tie); otherwise Small_rational
/// almost surely overflows, and the MPFR intervals, cheaper than GMP
/// rationals, come first.
struct Coordinate_span {
  int lowest = std::numeric_limits<int>::max(), highest = std::numeric_limits<int>::min();

  void add(double x)
  {
    if(x == 0) return;
    std::uint64_t bits;
    std::memcpy(&bits, &x, sizeof bits);
    const int biased = int((bits >> 52) & 0x7ff);
    if(biased == 0x7ff) {   // (not finite: never short)
      highest = 1 << 20;
      lowest = -(1 << 20);
      return;
    }
    if(biased == 0) {   // subnormal
      int e;
      const double m = std::frexp(x, &e);
      const std::int64_t mi = std::int64_t(std::ldexp(m, 53));
      highest = (std::max)(highest, e);
      lowest = (std::min)(lowest, e - 53 + __builtin_ctzll(std::uint64_t(mi < 0 ? -mi : mi)));
      return;
    }
    // x = (2^52 + mantissa) 2^(biased - 1075), its highest bit 2^(biased - 1023)
    const std::uint64_t significand = (bits & ((std::uint64_t(1) << 52) - 1)) | (std::uint64_t(1) << 52);
    highest = (std::max)(highest, biased - 1022);
    lowest = (std::min)(lowest, biased - 1075 + __builtin_ctzll(significand));
  }
  template <class Site_2>
  void add(const Site_2& x)
  {
    add(CGAL::to_double(x.p.x())); add(CGAL::to_double(x.p.y()));
    add(CGAL::to_double(x.q.x())); add(CGAL::to_double(x.q.y()));
  }
  bool is_short() const { return highest - lowest <= 24; }
};

/// An event time of the filtered traits: an interval that encloses it, and
/// what is needed to evaluate it again more precisely on demand.  Most
/// times are decided by their interval alone, and the merge stores a time
/// in each of its events: the time holds the interval, the kind and the
/// sites (208 bytes with Epick on x86-64), and one pointer to what the more
/// precise stages computed, shared by its copies.  The relations of its
/// sites are computed again by those stages (CK: the kernel of the sites).
template <class Site_2>
class Filtered_event_time
{
public:
  typedef Interval_nt<false> Interval;
  typedef Double_double_interval Dd;
  typedef Mpfr_interval Mpfr;

  Filtered_event_time() : approx_(0) {}
  const Interval& approx() const { return approx_; }
  double to_double() const { return CGAL::to_double(approx_); }

  /// The time as alpha + sqrt(rho) in one-root numbers, with small
  /// rationals when they suffice, else with GMP rationals (Gmp_rational).
  struct One_root_value {
    bool exists = false;           // the event exists (false: the time is not an event)
    bool small = false;            // `small_value` holds it
    Small_one_root_sqrt small_value;
    mutable std::shared_ptr<One_root_sqrt> big_value;   // holds it, or its conversion once asked for

    const One_root_sqrt& big() const
    {
      if(!big_value)
        big_value = std::make_shared<One_root_sqrt>(One_root_sqrt{small_value.alpha.to_big(), small_value.rho.to_big()});
      return *big_value;
    }
    Interval to_interval() const { return small ? small_value.to_interval() : big_value->to_interval(); }
  };

  /// What the stages after the intervals found, computed once.
  struct Exact_values {
    Dd dd;
    signed char dd_state = 2;       // 2 not computed yet, else as returned by dd()
    std::unique_ptr<Mpfr> mpfr;
    signed char mpfr_state = 2;     // 2 not computed yet, else as returned by mpfr()
    std::unique_ptr<One_root_value> one_root;
    signed char one_root_state = 0; // 0 unknown, 1 one_root holds it, -1 not a one-root number
    signed char short_state = 0;    // 0 unknown, else the sign is short_coordinates()
    std::shared_ptr<char> tie;       // shared by times found exactly equal
  };

  /// The time in double-double intervals, computed once: -1 if a branch
  /// of the computation cannot be decided, 0 if the event does not exist,
  /// 1 if `*value` holds the time.
  template <class CK>
  int dd(const Dd** value) const
  {
    Exact_values& x = exact();
    if(x.dd_state == 2)
      x.dd_state = interval_time<CK>(x.dd);
    *value = &x.dd;
    return x.dd_state;
  }

  /// The time in MPFR intervals at the current MPFR precision, computed
  /// once: -1 if a branch of the computation cannot be decided, 0 if the
  /// event does not exist, 1 if `*value` holds the time.
  template <class CK>
  int mpfr(const Mpfr** value) const
  {
    Exact_values& x = exact();
    if(x.mpfr_state == 2) {
      Mpfr t;
      x.mpfr_state = interval_time<CK>(t);
      if(x.mpfr_state == 1)
        x.mpfr.reset(new Mpfr(t));
    }
    *value = x.mpfr.get();
    return x.mpfr_state;
  }

  /// The time in one-root numbers, or null if it does not have that form.
  template <class CK>
  const One_root_value* one_root() const
  {
    Exact_values& x = exact();
    if(x.one_root_state == 0) {
      x.one_root_state = -1;
      std::unique_ptr<One_root_value> v(new One_root_value);
      try {
        const Triple_relations rel = relations<CK>();
        if(short_coordinates()) {
          try {
            To_nt_convert<Small_one_root> cv;
            v->exists = evaluate_time<Small_one_root>(kind_, c_, s_, rel, cv, v->small_value.alpha, &v->small_value.rho);
            v->small = true;
          } catch(Small_rational_overflow&) {
            ++Filtered_model<CK>::filter_statistics().small_rational_overflows;
          }
        }
        if(!v->small) {
          To_nt_convert<One_root_rational> cv;
          One_root_sqrt t;
          v->exists = evaluate_time<One_root_rational>(kind_, c_, s_, rel, cv, t.alpha, &t.rho);
          v->big_value = std::make_shared<One_root_sqrt>(t);
        }
        x.one_root = std::move(v);
        x.one_root_state = 1;
      } catch(Not_one_root&) {
      }
    }
    return x.one_root_state > 0 ? x.one_root.get() : nullptr;
  }

  /// Whether the coordinates of the sites span at most 24 bits (see
  /// Coordinate_span).
  bool short_coordinates() const
  {
    Exact_values& x = exact();
    if(x.short_state == 0) {
      Coordinate_span span;
      span.add(c_);
      if(kind_ > TIME_END)
        for(int i = 0; i < 3; ++i) span.add(s_[i]);
      x.short_state = span.is_short() ? 1 : -1;
    }
    return x.short_state > 0;
  }

  /// The time in nested-root numbers N (Nested_root_number or
  /// Small_nested_root_number), in the current context of N.
  template <class CK, class N>
  bool nested(N& t) const
  {
    To_nt_convert<N> cv;
    return evaluate_time<N>(kind_, c_, s_, relations<CK>(), cv, t);
  }

  /// The time in interval number type NT (a stage of dd() and mpfr()):
  /// -1 if a branch of the computation cannot be decided, 0 if the event
  /// does not exist, 1 if `t` holds the time.
  template <class CK, class NT>
  signed char interval_time(NT& t) const
  {
    try {
      To_nt_convert<NT> cv;
      bool undecided = false;
      if(evaluate_time<NT>(kind_, c_, s_, relations<CK>(), cv, t, nullptr, &undecided))
        return 1;
      if(!undecided)
        return 0;
    } catch(Uncertain_conversion_exception&) {
    }
    return -1;
  }

  /// The relations of the sites (none for the kinds without sites).
  template <class CK>
  Triple_relations relations() const
  {
    return kind_ > TIME_END ? triple_relations<CK>(s_) : Triple_relations();
  }

  /// The stages' values, shared by the copies of this time (created at the
  /// first need).
  Exact_values& exact() const
  {
    if(!exact_)
      exact_ = std::make_shared<Exact_values>();
    return *exact_;
  }

  Interval approx_;
  Time_kind kind_ = TIME_ZERO;
  Site_2 c_, s_[3];
  mutable std::shared_ptr<Exact_values> exact_;
};


/// The model with exact decisions (see Progressive_medial_axis_traits_2).
template <class CK>
class Filtered_model
  : public Traits_functors<Filtered_model<CK>, CK, typename CK::FT, typename CK::Point_2,
                           Filtered_event_time<Site<typename CK::Point_2> > >
{
  typedef Traits_functors<Filtered_model<CK>, CK, typename CK::FT, typename CK::Point_2,
                          Filtered_event_time<Site<typename CK::Point_2> > > Base;
  friend Base;
  template <class> friend class Number_model;   // the double model builds its implausible vertices here

public:
  typedef typename Base::FT FT;
  typedef typename Base::Point_2 Point_2;
  typedef typename Base::Site_2 Site_2;
  typedef typename Base::Event_time_2 Event_time_2;
  typedef Interval_nt<false> Interval;
  typedef Progressive_medial_axes::internal::Double_double_interval Dd;
  typedef Progressive_medial_axes::internal::Mpfr_interval Mpfr;
  typedef Progressive_medial_axes::internal::Nested_root_number Nested;

  static constexpr bool Has_exact_decisions = true;

  /// Counters of the filter stages (shared by all objects of this class in
  /// the thread).
  struct Filter_statistics {
    std::size_t interval_evaluations = 0;      ///< times and disks evaluated in double intervals
    std::size_t double_double_evaluations = 0; ///< disks constructed in double-double arithmetic
    std::size_t dd_interval_evaluations = 0;   ///< times that double intervals left undecided and double-double intervals decided
    std::size_t dd_interval_disks = 0;         ///< disks constructed in double-double intervals (double-double did not settle them)
    std::size_t mpfr_evaluations = 0;          ///< times and disks that neither the double intervals nor double-double settled
    std::size_t rational_evaluations = 0;      ///< ... that were decided in exact one-root numbers
    std::size_t exact_evaluations = 0;         ///< ... that needed the nested-root numbers
    std::size_t dd_interval_comparisons = 0;   ///< comparisons of times decided by double-double intervals
    std::size_t mpfr_comparisons = 0;          ///< ... by MPFR intervals
    std::size_t rational_comparisons = 0;      ///< ... decided in exact one-root numbers
    std::size_t exact_comparisons = 0;         ///< ... decided in nested-root numbers
    std::size_t exact_ties = 0;                ///< comparisons that found two times equal (one-root, nested or mirror)
    std::size_t small_rational_overflows = 0;  ///< computations in 128-bit rationals redone in GMP rationals (a result overflowed)
    std::size_t mirror_ties = 0;               ///< ties found equal by a symmetry, without nested-root numbers (mirror_tie())
    std::size_t hinted_switch_times = 0;       ///< switch times computed from the centre kept with their vertex (Disk_hint)
    std::size_t axis_aligned_disks = 0;        ///< disks with coordinates fixed exactly by axis-parallel sites (axis_aligned_disk())
    std::size_t axis_aligned_ties = 0;         ///< ties of two times whose disks are one by their axis-parallel sites (same_axis_aligned_disk())

    /// Adds the counts of `b - a` (what another thread counted between two readings).
    void add_difference(const Filter_statistics& b, const Filter_statistics& a)
    {
      interval_evaluations += b.interval_evaluations - a.interval_evaluations;
      double_double_evaluations += b.double_double_evaluations - a.double_double_evaluations;
      dd_interval_evaluations += b.dd_interval_evaluations - a.dd_interval_evaluations;
      dd_interval_disks += b.dd_interval_disks - a.dd_interval_disks;
      mpfr_evaluations += b.mpfr_evaluations - a.mpfr_evaluations;
      rational_evaluations += b.rational_evaluations - a.rational_evaluations;
      exact_evaluations += b.exact_evaluations - a.exact_evaluations;
      dd_interval_comparisons += b.dd_interval_comparisons - a.dd_interval_comparisons;
      mpfr_comparisons += b.mpfr_comparisons - a.mpfr_comparisons;
      rational_comparisons += b.rational_comparisons - a.rational_comparisons;
      exact_comparisons += b.exact_comparisons - a.exact_comparisons;
      exact_ties += b.exact_ties - a.exact_ties;
      small_rational_overflows += b.small_rational_overflows - a.small_rational_overflows;
      mirror_ties += b.mirror_ties - a.mirror_ties;
      hinted_switch_times += b.hinted_switch_times - a.hinted_switch_times;
      axis_aligned_disks += b.axis_aligned_disks - a.axis_aligned_disks;
      axis_aligned_ties += b.axis_aligned_ties - a.axis_aligned_ties;
    }
  };
  static Filter_statistics& filter_statistics()
  {
    static thread_local Filter_statistics s;
    return s;
  }

  /// The precision, in bits, of the MPFR stage (see Mpfr_interval::default_precision).
  static constexpr mpfr_prec_t mpfr_precision = Mpfr::default_precision;

  /// An enclosure of the centre of a medial disk, from the interval stage
  /// of the event time that found it.  Kept with a vertex of the axis
  /// (Halfedge_structure::set_centre_hint()) as a centre and an error bound
  /// in doubles: the centre lies within `err` of (x, y) in each coordinate.
  struct Disk_hint {
    bool valid = false;
    Interval x, y;

    /// (x, y) and err as said above; false if they are not finite.
    bool to_doubles(double& cx, double& cy, double& err) const
    {
      cx = x.inf() / 2 + x.sup() / 2;
      cy = y.inf() / 2 + y.sup() / 2;
      // (each difference rounded to nearest is within half a unit of the
      // last place of the exact one: the next double above bounds it)
      const double e = (std::max)((std::max)(x.sup() - cx, cx - x.inf()), (std::max)(y.sup() - cy, cy - y.inf()));
      err = Progressive_medial_axes::internal::next_up(e);
      return std::isfinite(cx) && std::isfinite(cy) && std::isfinite(err);
    }
    static Disk_hint from_doubles(double cx, double cy, double err)
    {
      Disk_hint h;
      h.valid = true;
      Progressive_medial_axes::internal::Upward_rounding protection;
      const Interval e(-err, err);
      h.x = Interval(cx) + e;
      h.y = Interval(cy) + e;
      return h;
    }
  };

private:
  // A switch time from the centre of its disk.
  static bool switch_time_from_hint(const Site_2& line, const Site_2* s, const Disk_hint& hint, Event_time_2& t)
  {
    t.kind_ = Progressive_medial_axes::internal::TIME_SWITCH;
    t.c_ = line;
    for(int i = 0; i < 3; ++i) t.s_[i] = s[i];
    t.exact_.reset();
    ++filter_statistics().hinted_switch_times;
    Progressive_medial_axes::internal::Upward_rounding protection;
    const Interval px(line.p.x()), py(line.p.y()), qx(line.q.x()), qy(line.q.y());
    t.approx_ = Progressive_medial_axes::internal::foot_position(
      px, py, qx, qy, Progressive_medial_axes::internal::Circle_nt<Interval>{hint.x, hint.y, Interval(0)});
    return true;
  }

  // Evaluates a time: double intervals, double-double intervals, MPFR
  // intervals, exactly.  With `hint`, sets it from the interval stage.
  static bool time(Progressive_medial_axes::internal::Time_kind kind, const Site_2& line, const Site_2* s, Event_time_2& t,
                   Disk_hint* hint = nullptr)
  {
    t.kind_ = kind;
    t.c_ = line;
    Progressive_medial_axes::internal::Triple_relations rel;
    if(s != nullptr) {
      for(int i = 0; i < 3; ++i) t.s_[i] = s[i];
      rel = Progressive_medial_axes::internal::triple_relations<CK>(s);
    }
    t.exact_.reset();
    ++filter_statistics().interval_evaluations;
    // in double intervals; where they leave a branch undecided, again with
    // the relations that decide exact ties (refine_relations())
    const int in_intervals = Progressive_medial_axes::internal::decide_in_intervals<CK>(
      s != nullptr ? t.s_ : nullptr, kind == Progressive_medial_axes::internal::TIME_VANISH ? &line : nullptr, rel,
      [&](const Progressive_medial_axes::internal::Triple_relations& r) {
        Interval v;
        Progressive_medial_axes::internal::To_nt_convert<Interval> cv;
        bool undecided = false;
        Progressive_medial_axes::internal::Circle_nt<Interval> circle;
        bool ok = Progressive_medial_axes::internal::evaluate_time<Interval>(kind, line, t.s_, r, cv, v, nullptr,
                                                                               &undecided, hint ? &circle : nullptr);
        if(!ok && !undecided)
          return 0;
        if(ok && CGAL_NTS is_finite(v.inf()) && CGAL_NTS is_finite(v.sup())) {
          t.approx_ = v;
          if(hint != nullptr) {   // (to_doubles() says whether its bounds are finite)
            hint->valid = true;
            hint->x = circle.x;
            hint->y = circle.y;
          }
          return 1;
        }
        return -1;
      });
    if(in_intervals >= 0)
      return in_intervals == 1;
    // (with short coordinates, what the double intervals cannot decide is
    // an exact tie as a rule, which no interval decides: see before_exact())
    if(!t.short_coordinates()) {
      const typename Event_time_2::Dd* v;
      const int state = t.template dd<CK>(&v);
      if(state >= 0) {
        ++filter_statistics().dd_interval_evaluations;
        if(state == 0)
          return false;
        t.approx_ = v->to_interval();
        return true;
      }
    }
    ++filter_statistics().mpfr_evaluations;
    const std::optional<bool> decided = before_exact<bool>(
      [&]() -> std::optional<bool> {
        const Mpfr* v;
        const int state = t.template mpfr<CK>(&v);
        if(state < 0)
          return std::nullopt;
        if(state == 0)
          return false;
        t.approx_ = v->to_interval();
        return true;
      },
      [&]() -> std::optional<bool> {
        const typename Event_time_2::One_root_value* v = t.template one_root<CK>();
        if(v == nullptr)
          return std::nullopt;
        ++filter_statistics().rational_evaluations;
        if(!v->exists)
          return false;
        t.approx_ = v->to_interval();
        return true;
      }, t.short_coordinates());
    if(decided)
      return *decided;
    ++filter_statistics().exact_evaluations;
    return with_nested_numbers(t.short_coordinates(), [&](auto number) {
      decltype(number) v;
      if(!t.template nested<CK>(v))
        return false;
      t.approx_ = v.to_interval();
      return true;
    });
  }

  // The foot of a point on the separator.
  static Event_time_2 foot_time(const Site_2& line, const Point_2& p)
  {
    Event_time_2 t;
    const Site_2 s[3] = {Site_2::point(p), Site_2::point(p), Site_2::point(p)};
    time(Progressive_medial_axes::internal::TIME_FOOT, line, s, t);
    return t;
  }

  // The comparison of two times: their intervals decide nearly all of them
  // (this part is inlined into the merge's event queue), the stages after
  // them are out of line (compare_undecided_times()): inlined whole, the
  // function's entry and exit saved the registers of those stages at every
  // call, about two thirds of its own instructions on c1m_CHN_0.
  static Comparison_result compare_times(const Event_time_2& a, const Event_time_2& b)
  {
    const Uncertain<Comparison_result> r = CGAL::compare(a.approx(), b.approx());
    if(is_certain(r))
      return get_certain(r);
    return compare_undecided_times(a, b);
  }

  // compare_times() where the intervals overlap.
  CGAL_PMA2_NOINLINE static Comparison_result compare_undecided_times(const Event_time_2& a, const Event_time_2& b)
  {
    // the two ends of one separator
    if(a.kind_ == b.kind_ && a.kind_ <= Progressive_medial_axes::internal::TIME_END && a.c_ == b.c_)
      return EQUAL;
    // already found equal
    if(a.exact_ && b.exact_ && a.exact_->tie && a.exact_->tie == b.exact_->tie)
      return EQUAL;
    // Two events of one kind on one separator whose disks are one, as the
    // relations of their axis-parallel sites show (four generators on one
    // circle, where a map's lakes are drawn on a grid): equal without the
    // exact stages, which found every such tie in GMP rationals
    // (RESULTS.md, sixty-fifth session).  A switch or vanishing time is a
    // function of the disk and the separator.
    if constexpr(std::is_same<typename CK::FT, double>::value) {
      if(disk_times_on_one_separator(a, b) && Progressive_medial_axes::internal::same_axis_aligned_disk(a.s_, b.s_)) {
        ++filter_statistics().axis_aligned_ties;
#ifdef CGAL_PMA2_CHECK_AXIS_ALIGNED_DISKS
        // for the tests only (engine.cmake): each such tie confirmed by algebra
        if(nested_sign(a, b) != ZERO)
          throw std::logic_error("compare_times: a tie of one disk from axis-parallel sites that the nested-root numbers deny");
#endif
        return tie(a, b, EQUAL);
      }
    }
    if(!(a.short_coordinates() && b.short_coordinates())) {
      const typename Event_time_2::Dd *va, *vb;
      if(a.template dd<CK>(&va) == 1 && b.template dd<CK>(&vb) == 1) {
        const Uncertain<Comparison_result> m = compare(*va, *vb);
        if(is_certain(m)) {
          ++filter_statistics().dd_interval_comparisons;
          return get_certain(m);
        }
      }
    }
    const std::optional<Comparison_result> decided = before_exact<Comparison_result>(
      [&]() -> std::optional<Comparison_result> {
        const Mpfr *va, *vb;
        if(a.template mpfr<CK>(&va) != 1 || b.template mpfr<CK>(&vb) != 1)
          return std::nullopt;
        Uncertain<Comparison_result> m = compare(*va, *vb);
        if(!is_certain(m))
          return std::nullopt;
        ++filter_statistics().mpfr_comparisons;
        return get_certain(m);
      },
      [&]() -> std::optional<Comparison_result> {
        const typename Event_time_2::One_root_value* ra = a.template one_root<CK>();
        const typename Event_time_2::One_root_value* rb = ra ? b.template one_root<CK>() : nullptr;
        if(rb == nullptr)
          return std::nullopt;
        CGAL_assertion(ra->exists && rb->exists);
        std::optional<Sign> sign;
        if(ra->small && rb->small) {
          try {
            sign = sign_of_difference(ra->small_value, rb->small_value);
          } catch(Progressive_medial_axes::internal::Small_rational_overflow&) {
            ++filter_statistics().small_rational_overflows;
          }
        }
        if(!sign)
          sign = sign_of_difference(ra->big(), rb->big());
        const Comparison_result res = Comparison_result(int(*sign));
        ++filter_statistics().rational_comparisons;
        return tie(a, b, res);
      }, a.short_coordinates() && b.short_coordinates());
    if(decided)
      return *decided;
    // a symmetric pair: equal without algebra
    if(disk_times_on_one_separator(a, b) && Progressive_medial_axes::internal::mirror_tie<CK>(a.c_, a.s_, b.s_)) {
      ++filter_statistics().mirror_ties;
#ifdef CGAL_PMA2_CHECK_MIRROR_TIES
      // for the tests only (engine.cmake): each such tie confirmed by algebra
      if(nested_sign(a, b) != ZERO)
        throw std::logic_error("compare_times: a tie by symmetry (mirror_tie) that the nested-root numbers deny");
#endif
      return tie(a, b, EQUAL);
    }
    ++filter_statistics().exact_comparisons;
    return tie(a, b, Comparison_result(int(nested_sign(a, b))));
  }

  // Whether a and b are switch times, or vanishing times, on one separator:
  // each a function of its triple's disk and the separator, so one disk
  // means one time (the ties found without algebra above).
  static bool disk_times_on_one_separator(const Event_time_2& a, const Event_time_2& b)
  {
    return a.kind_ == b.kind_ &&
           (a.kind_ == Progressive_medial_axes::internal::TIME_SWITCH ||
            a.kind_ == Progressive_medial_axes::internal::TIME_VANISH) &&
           a.c_ == b.c_;
  }

  // The sign of a - b in nested-root numbers.
  static Sign nested_sign(const Event_time_2& a, const Event_time_2& b)
  {
    return with_nested_numbers(a.short_coordinates() && b.short_coordinates(), [&](auto number) {
      decltype(number) ta, tb;
      const bool ok = a.template nested<CK>(ta) && b.template nested<CK>(tb);
      CGAL_assertion(ok);
      CGAL_USE(ok);
      return sign_of_difference(ta, tb);
    });
  }

  // Remembers that a and b are equal, so that comparing them again is immediate.
  static Comparison_result tie(const Event_time_2& a, const Event_time_2& b, Comparison_result r)
  {
    if(r == EQUAL) {
      ++filter_statistics().exact_ties;
      std::shared_ptr<char>& id = a.exact().tie;
      if(!id)
        id = std::make_shared<char>(0);
      b.exact().tie = id;
    }
    return r;
  }

  static bool in_past(const Event_time_2& t, const Event_time_2& now, const Site_2&)
  {
    return compare_times(t, now) == SMALLER;
  }

#ifdef CGAL_PMA2_CHECK_AXIS_ALIGNED_DISKS
  // Throws if a coordinate found by axis_aligned_disk() is not the one that
  // the nested-root numbers round the exact disk to.
  static void check_axis_aligned_disk(const Site_2* s, const Progressive_medial_axes::internal::Triple_relations& rel,
                                      const bool found[3], const double value[3])
  {
    const bool agree = with_nested_numbers(short_coordinates(s, s), [&](auto number) {
      typedef decltype(number) N;
      Progressive_medial_axes::internal::Circle_nt<N> circle;
      if(!disk_nt<N>(s, rel, circle))
        return false;
      const N* c[3] = {&circle.x, &circle.y, &circle.r};
      for(int i = 0; i < 3; ++i)
        if(found[i] && c[i]->to_double() + 0.0 != value[i])
          return false;
      return true;
    });
    if(!agree)
      throw std::logic_error("disk: a coordinate from axis-parallel sites that the nested-root numbers deny");
  }
#endif

  // The centre (x, y), with an exact zero as +0 whichever stage rounded it.
  static Point_2 point_of_doubles(double x, double y) { return Point_2(x + 0.0, y + 0.0); }

  // The disk tangent to three sites: the exact disk correctly rounded to
  // double (ties to even).
  static bool disk(const Site_2* s, Point_2& centre, FT& radius)
  {
    Progressive_medial_axes::internal::Triple_relations rel = Progressive_medial_axes::internal::triple_relations<CK>(s);
    ++filter_statistics().interval_evaluations;
    // Each of x, y and r is settled by the first stage that can round it:
    // a tie in one coordinate (a centre halfway between two input points)
    // sends only that coordinate on to the exact numbers.
    double value[3];
    bool settled[3] = {false, false, false};
    // settles each coordinate i not settled yet that a stage can round
    // (rounds(i)), at rounded(i); once all three are, sets the disk and
    // returns true
    auto settle = [&](const auto& rounds, const auto& rounded) {
      for(int i = 0; i < 3; ++i)
        if(!settled[i] && rounds(i)) {
          value[i] = rounded(i);
          settled[i] = true;
        }
      if(!(settled[0] && settled[1] && settled[2]))
        return false;
      centre = point_of_doubles(value[0], value[1]);
      radius = value[2];
      return true;
    };
    // the coordinates not settled yet, from a circle of an exact number type
    auto round_exactly = [&](const auto& circle) {
      typedef std::decay_t<decltype(circle.x)> N;
      const N* c[3] = {&circle.x, &circle.y, &circle.r};
      return settle([](int) { return true; }, [&](int i) { return c[i]->to_double(); });
    };
    // Once the disk is known to exist: the coordinates that its axis-parallel
    // sites fix as sums and halves of input coordinates, exactly
    // (axis_aligned_disk()).  They lie halfway between two doubles as a
    // rule, which no interval decides: on a map with many axis-parallel
    // edges nearly every disk that double-double left went on to MPFR and
    // GMP rationals for them (RESULTS.md, sixty-fifth session).
    auto by_axis_aligned_sites = [&]() {
      if constexpr(!std::is_same<typename CK::FT, double>::value) {
        return false;
      } else {
        double exact[3];
        bool found[3] = {false, false, false};
        if(!Progressive_medial_axes::internal::axis_aligned_disk(s, found, exact) ||
           !((found[0] && !settled[0]) || (found[1] && !settled[1]) || (found[2] && !settled[2])))
          return false;
        ++filter_statistics().axis_aligned_disks;
#ifdef CGAL_PMA2_CHECK_AXIS_ALIGNED_DISKS
        // for the tests only (engine.cmake): each such coordinate confirmed
        // by the exact stage
        check_axis_aligned_disk(s, rel, found, exact);
#endif
        return settle([&](int i) { return found[i]; }, [&](int i) { return exact[i]; });
      }
    };
    bool branches_decided = false;
    Progressive_medial_axes::internal::Circle_nt<Interval> enclosure;
    const Interval* enclosed[3] = {&enclosure.x, &enclosure.y, &enclosure.r};
    {
      const int found = interval_disk(s, rel, enclosure);
      if(found == 0)
        return false;
      branches_decided = found > 0;
      if(branches_decided &&
         settle([&](int i) { return enclosed[i]->is_point() && std::isfinite(enclosed[i]->inf()); },
                [&](int i) { return enclosed[i]->inf(); }))
        return true;
    }
    if(branches_decided) {
      // The intervals took every branch: the same computation in
      // double-double arithmetic (about 106 bits).  A coordinate is kept
      // only if it rounds to the same double as every value within an error
      // bound of it (rounds_within()); else it goes on to the double-double
      // intervals, then to MPFR, and exact values on a rounding boundary
      // (zeros, midpoints of two doubles: the ties of symmetric and decimal
      // input) to the exact stages, so that the disk is always the exact one
      // correctly rounded.  Coordinates far from 1 (near 1e150 and beyond)
      // overflow its products and go on too.  This plain double-double is
      // cheaper than the intervals and settles nearly every vertex of real
      // outlines: computing every disk in the intervals made them 5% to 16%
      // slower (RESULTS.md, twenty-third session).
      ++filter_statistics().double_double_evaluations;
      Progressive_medial_axes::internal::Circle_nt<Progressive_medial_axes::internal::Double_double> circle;
      try {
        if(disk_nt<Progressive_medial_axes::internal::Double_double>(s, rel, circle)) {
          const Progressive_medial_axes::internal::Double_double* c[3] = {&circle.x, &circle.y, &circle.r};
          if(settle(
               [&](int i) {
                 return Progressive_medial_axes::internal::rounds_within(*c[i], enclosed[i]->inf(), enclosed[i]->sup(),
                                                                         enclosure.root_cancels);
               },
               [&](int i) { return c[i]->to_double(); }))
            return true;
        }
      } catch(Progressive_medial_axes::internal::Inexact_double_double_input&) {
      }
      if(by_axis_aligned_sites())
        return true;
    }
    {
      // The same computation in double-double intervals (about 100 bits,
      // with a rigorous error radius), which also decide the branches that
      // the double intervals could not.  A coordinate is kept if every
      // value of its interval rounds to the same double.
      ++filter_statistics().dd_interval_disks;
      Progressive_medial_axes::internal::Circle_nt<Dd> circle;
      try {
        const int found = disk_nt_decided<Dd>(s, rel, circle);
        if(found == 0)
          return false;
        const Dd* c[3] = {&circle.x, &circle.y, &circle.r};
        // (where the double intervals decided the branches, the relations
        // were applied after double-double already)
        if(found > 0 &&
           (settle([&](int i) { return c[i]->rounds_to_one_double(); }, [&](int i) { return c[i]->to_double(); }) ||
            (!branches_decided && by_axis_aligned_sites())))
          return true;
      } catch(Uncertain_conversion_exception&) {
      }
    }
    ++filter_statistics().mpfr_evaluations;
    const bool short_s = short_coordinates(s, s);
    const std::optional<bool> decided = before_exact<bool>(
      [&]() -> std::optional<bool> {
        Progressive_medial_axes::internal::Circle_nt<Mpfr> circle;
        if(!disk_nt<Mpfr>(s, rel, circle))
          return false;
        const Mpfr* c[3] = {&circle.x, &circle.y, &circle.r};
        if(!settle([&](int i) { return c[i]->rounds_to_one_double(); }, [&](int i) { return c[i]->midpoint(); }))
          return std::nullopt;
        return true;
      },
      [&]() -> std::optional<bool> {
        auto one_root = [&](auto number) {
          typedef decltype(number) N;
          Progressive_medial_axes::internal::Circle_nt<N> circle;
          if(!disk_nt<N>(s, rel, circle))
            return false;
          ++filter_statistics().rational_evaluations;
          return round_exactly(circle);
        };
        return with_one_root_numbers(short_s, one_root);
      }, short_s);
    if(decided)
      return *decided;
    ++filter_statistics().exact_evaluations;
    return with_nested_numbers(short_s, [&](auto number) {
      typedef decltype(number) N;
      Progressive_medial_axes::internal::Circle_nt<N> circle;
      if(!disk_nt<N>(s, rel, circle))
        return false;
      return round_exactly(circle);
    });
  }

  // Whether two triples define the same disk: double intervals, then the
  // stages of before_exact(), then nested-root numbers.
  static bool same_disk(const Site_2* s, const Site_2* t)
  {
    Progressive_medial_axes::internal::Triple_relations rs = Progressive_medial_axes::internal::triple_relations<CK>(s);
    Progressive_medial_axes::internal::Triple_relations rt = Progressive_medial_axes::internal::triple_relations<CK>(t);
    {
      Progressive_medial_axes::internal::Circle_nt<Interval> a, b;
      // (kept, for coordinates of doubles: on integer grids the ends of
      // many edges are compared, and each vertex is the end of two)
      auto kept_interval_disk = [](const Site_2* x, Progressive_medial_axes::internal::Triple_relations& r,
                                   Progressive_medial_axes::internal::Circle_nt<Interval>& c) {
        if constexpr(std::is_same<typename CK::FT, double>::value)
          return kept_disk(x, r, c, [&](Progressive_medial_axes::internal::Triple_relations& q,
                                        Progressive_medial_axes::internal::Circle_nt<Interval>& d) {
            return interval_disk(x, q, d);
          });
        else
          return interval_disk(x, r, c);
      };
      const int found_a = kept_interval_disk(s, rs, a);
      if(found_a == 0)
        return false;
      const int found_b = kept_interval_disk(t, rt, b);
      if(found_b == 0)
        return false;
      if(found_a > 0 && found_b > 0) {
        if(certainly(a.x != b.x) || certainly(a.y != b.y) || certainly(a.r != b.r))
          return false;
        if(Progressive_medial_axes::internal::flat_vertex_swap<CK>(s, t))
          return true;
      }
    }
    auto equal = [&](auto number) {
      typedef decltype(number) N;
      Progressive_medial_axes::internal::Circle_nt<N> a, b;
      if(!disk_nt<N>(s, rs, a) || !disk_nt<N>(t, rt, b))
        return false;
      return bool(a.x == b.x && a.y == b.y && a.r == b.r);
    };
    const bool short_st = short_coordinates(s, t);
    const std::optional<bool> decided = before_exact<bool>(
      [&]() -> std::optional<bool> {   // MPFR intervals decide only that the disks differ
        Progressive_medial_axes::internal::Circle_nt<Mpfr> a, b;
        if(!disk_nt<Mpfr>(s, rs, a) || !disk_nt<Mpfr>(t, rt, b))
          return false;
        if(certainly(a.x != b.x) || certainly(a.y != b.y) || certainly(a.r != b.r))
          return false;
        return std::nullopt;
      },
      [&]() -> std::optional<bool> { return with_one_root_numbers(short_st, equal); }, short_st);
    if(decided)
      return *decided;
    return with_nested_numbers(short_st, equal);
  }

  // The disk of the triple in double intervals: 1, 0 if there is none, -1
  // where a branch of its construction is undecided, after a second try
  // with the relations of exact ties (refine_relations()).  The exact
  // predicates run outside the intervals' rounding mode (Epick's static
  // filters assume rounding to nearest).
  static int interval_disk(const Site_2* s, Progressive_medial_axes::internal::Triple_relations& rel,
                           Progressive_medial_axes::internal::Circle_nt<Interval>& circle)
  {
    return Progressive_medial_axes::internal::decide_in_intervals<CK>(
      s, static_cast<const Site_2*>(nullptr), rel,
      [&](const Progressive_medial_axes::internal::Triple_relations& r) { return disk_nt_decided<Interval>(s, r, circle); });
  }

  // f(number) with the small one-root numbers if the coordinates are short,
  // or with the GMP ones where they overflow.  (Coordinates of more than 24
  // bits, as decimal GIS data has, overflow the small numbers at once: on a
  // polygon of land-10m the tries cost 4,980 exceptions.)
  template <class F>
  static auto with_one_root_numbers(bool short_coordinates, const F& f)
  {
    if(short_coordinates) {
      try {
        return f(Progressive_medial_axes::internal::Small_one_root());
      } catch(Progressive_medial_axes::internal::Small_rational_overflow&) {
        ++filter_statistics().small_rational_overflows;
      }
    }
    return f(Progressive_medial_axes::internal::One_root_rational());
  }

  // f(number) in nested-root numbers, in a context of their own: with
  // Small_rational coefficients first if the coordinates are short, with
  // Gmpq where those overflow (the roots of the first try are dropped).
  template <class F>
  static auto with_nested_numbers(bool short_coordinates, const F& f)
  {
    if(short_coordinates) {
      try {
        Progressive_medial_axes::internal::Small_nested_root_context context;
        return f(Progressive_medial_axes::internal::Small_nested_root_number());
      } catch(Progressive_medial_axes::internal::Small_rational_overflow&) {
        ++filter_statistics().small_rational_overflows;
      }
    }
    Progressive_medial_axes::internal::Nested_root_context context;
    return f(Nested());
  }

  // Whether the sites of two triples have short coordinates (Coordinate_span).
  static bool short_coordinates(const Site_2* s, const Site_2* t)
  {
    Progressive_medial_axes::internal::Coordinate_span span;
    for(int i = 0; i < 3; ++i) {
      span.add(s[i]);
      span.add(t[i]);
    }
    return span.is_short();
  }

  // Whether the open disk of the triple meets the closed segment: the sign
  // of a number evaluated and compared with 0 through the stages of an
  // event time.
  static bool conflict(const Site_2& segment, const Site_2* s)
  {
    Event_time_2 t, zero;
    if(!time(Progressive_medial_axes::internal::TIME_CONFLICT, segment, s, t))
      throw Progressive_medial_axes::internal::Uncertain_decision();   // no such disk
    time(Progressive_medial_axes::internal::TIME_ZERO, segment, nullptr, zero);
    return compare_times(t, zero) == SMALLER;
  }

  // The stages between the double intervals and the nested-root numbers:
  // exact one-root numbers and MPFR intervals.  What the double intervals
  // cannot decide is almost always an exact tie (degenerate input: integer
  // grids, symmetric shapes), which the one-root numbers decide when the
  // computation keeps their form, as it does with axis-parallel edges; MPFR
  // intervals decide the near-ties that are not ties.  With short
  // coordinates (Coordinate_span) the one-root numbers run in
  // Small_rational, and the MPFR stage is skipped: what the one-root
  // numbers cannot take there is a tie of nested roots as a rule, which
  // MPFR cannot decide, and the nested-root numbers, in Small_rational
  // too, decide it at once (FreeMono's percent sign: 14% faster, every
  // other shape of the degenerate benchmark as fast or faster; RESULTS.md,
  // eighth session).  Otherwise the one-root numbers would need GMP
  // rationals, and the MPFR intervals, cheaper, come first (on a Koch
  // snowflake with decimal coordinates most of these decisions are
  // near-ties, not ties).  On non-degenerate input the double intervals
  // decide nearly everything, and a value outside the one-root form is
  // found after a few operations.  A stage returns its result, or nothing
  // when it cannot decide.
  template <class R, class Mpfr_stage, class One_root_stage>
  static std::optional<R> before_exact(const Mpfr_stage& mpfr_stage, const One_root_stage& one_root_stage,
                                       bool short_coordinates)
  {
    auto one_root = [&]() -> std::optional<R> {
      try {
        return one_root_stage();
      } catch(Progressive_medial_axes::internal::Not_one_root&) {
      }
      return std::nullopt;
    };
    if(short_coordinates)
      return one_root();
    {
      Progressive_medial_axes::internal::Mpfr_precision_scope scope(mpfr_precision);
      try {
        if(std::optional<R> r = mpfr_stage())
          return r;
      } catch(Uncertain_conversion_exception&) {
      }
    }
    return one_root();
  }

  template <class NT>
  static bool disk_nt(const Site_2* s, const Progressive_medial_axes::internal::Triple_relations& rel, Progressive_medial_axes::internal::Circle_nt<NT>& circle)
  {
    return Progressive_medial_axes::internal::certain_or_throw(disk_nt_decided<NT>(s, rel, circle),
                                                              "disk_nt: undecided comparison");
  }
  // The same, 1 if the disk exists, 0 if not, -1 where the number type
  // (intervals) cannot decide a branch of the construction.
  template <class NT>
  static int disk_nt_decided(const Site_2* s, const Progressive_medial_axes::internal::Triple_relations& rel, Progressive_medial_axes::internal::Circle_nt<NT>& circle)
  {
    if constexpr(std::is_same<NT, Progressive_medial_axes::internal::Small_one_root>::value &&
                 std::is_same<typename CK::FT, double>::value)
      return small_disk(s, rel, circle);
    else
      return uncached_disk_nt_decided(s, rel, circle);
  }
  template <class NT>
  static int uncached_disk_nt_decided(const Site_2* s, const Progressive_medial_axes::internal::Triple_relations& rel,
                                      Progressive_medial_axes::internal::Circle_nt<NT>& circle)
  {
    Progressive_medial_axes::internal::To_nt_convert<NT> cv;
    Progressive_medial_axes::internal::Site_nt<NT> sn[3] = {Progressive_medial_axes::internal::site_nt<NT>(s[0], cv), Progressive_medial_axes::internal::site_nt<NT>(s[1], cv),
                                         Progressive_medial_axes::internal::site_nt<NT>(s[2], cv)};
    return Progressive_medial_axes::internal::medial_circle_decided(sn, rel, circle);
  }

  // A triple of sites and its relations, as the key of a table of disks.
  struct Triple_key {
    bool used = false;   // (default value: unused)
    bool is_point[3] = {};
    double coordinates[12] = {};
    Progressive_medial_axes::internal::Triple_relations rel;
    std::uint64_t hash = 0;

    Triple_key() {}
    Triple_key(const Site_2* s, const Progressive_medial_axes::internal::Triple_relations& r) : used(true), rel(r)
    {
      hash = 0x9e3779b97f4a7c15ull;
      for(int i = 0; i < 3; ++i) {
        is_point[i] = s[i].is_point;
        const double c[4] = {s[i].p.x(), s[i].p.y(), s[i].q.x(), s[i].q.y()};
        for(int j = 0; j < 4; ++j) {
          coordinates[4 * i + j] = c[j];
          std::uint64_t b;
          std::memcpy(&b, &c[j], sizeof b);
          hash = Progressive_medial_axes::internal::mix_hash(hash, b);
        }
        hash = Progressive_medial_axes::internal::mix_hash(hash, std::uint64_t(s[i].is_point));
      }
    }
    // (the relations compared as bytes: equal bytes are equal relations)
    bool operator==(const Triple_key& k) const
    {
      return used && k.used && std::equal(is_point, is_point + 3, k.is_point) &&
             std::equal(coordinates, coordinates + 12, k.coordinates) && std::memcmp(&rel, &k.rel, sizeof rel) == 0;
    }
  };
  // A disk as disk_nt_decided() returns it (found), with the relations as
  // the construction left them (refined by interval_disk()).
  template <class NT>
  struct Kept_disk {
    int found = 0;
    Progressive_medial_axes::internal::Triple_relations rel;
    Progressive_medial_axes::internal::Circle_nt<NT> circle;
  };
  template <class NT>
  struct Disk_entry {
    static constexpr unsigned max_bits = 8;
    // (a disk in intervals, or exact in one-root numbers: more costly)
    static constexpr std::size_t misses_per_page = std::is_same<NT, Interval_nt<false> >::value ? 16 : 4;
    Triple_key key;
    Kept_disk<NT> disk;
    bool holds(const Triple_key& k) const { return key == k; }
    const Kept_disk<NT>& value() const { return disk; }
    void set(const Triple_key& k, const Kept_disk<NT>& d)
    {
      key = k;
      disk = d;
    }
  };
  // construct(rel, circle) for the triple s, or what it gave before for the
  // same triple and relations in this thread (a table of `Disk_entry<NT>`
  // for each caller: each passes a lambda of its own).
  template <class NT, class Construct>
  static int kept_disk(const Site_2* s, Progressive_medial_axes::internal::Triple_relations& rel,
                       Progressive_medial_axes::internal::Circle_nt<NT>& circle, const Construct& construct)
  {
    const Triple_key key(s, rel);
    static thread_local Progressive_medial_axes::internal::Cache_table<Disk_entry<NT> > table;
    const Kept_disk<NT> d = table.value(key.hash, key, [&] {
      Kept_disk<NT> k;
      k.rel = rel;
      k.found = construct(k.rel, k.circle);
      return k;
    });
    rel = d.rel;
    circle = d.circle;
    return d.found;
  }

  // The disk of a triple in small one-root numbers, kept per thread: on
  // integer grids, the exact ties compare the disks of the same vertices
  // again and again (same_disk() at each end of the chain edges of a merge,
  // then disk() where the vertex is rounded).
  static int small_disk(const Site_2* s, const Progressive_medial_axes::internal::Triple_relations& rel,
                        Progressive_medial_axes::internal::Circle_nt<Progressive_medial_axes::internal::Small_one_root>& circle)
  {
    Progressive_medial_axes::internal::Triple_relations r = rel;
    return kept_disk(
      s, r, circle, [&](Progressive_medial_axes::internal::Triple_relations& q, auto& c) {
        return uncached_disk_nt_decided(s, q, c);
      });
  }
};

/// Kernels for which the traits take every decision exactly, filtered:
/// Epick (double coordinates) and Epeck (exact rational coordinates).
template <class K>
struct Is_filtering_kernel
  : std::integral_constant<bool, std::is_same<K, Exact_predicates_inexact_constructions_kernel>::value ||
                                     std::is_same<K, Exact_predicates_exact_constructions_kernel>::value> {};

} // namespace internal
} // namespace Progressive_medial_axes

/*!
\ingroup PkgProgressiveMedialAxis2Traits

The traits of `Progressive_medial_axis_2` for a kernel `K`, chosen as
\cgal chooses for `Straight_skeleton_builder_traits_2`: a filtering kernel
gets exact decisions, any other kernel its own arithmetic.

<b>Exact decisions</b> (`K` is `Exact_predicates_inexact_constructions_kernel`
or `Exact_predicates_exact_constructions_kernel`):
every decision is exact, and almost all are
taken in floating point.  A decision is evaluated first in double interval
arithmetic (`Interval_nt`).  What the intervals cannot decide is almost
always an exact tie (equal event times, a zero discriminant), and is decided
- in exact numbers alpha + sqrt(rho), where alpha and rho are a + b sqrt(D)
  with rational a, b, D, when the computation keeps that form, as is usual
  with axis-parallel edges (mazes, CAD parts);
- otherwise in double-double intervals (about 100 bits, a value and a
  rigorous error radius), then in MPFR interval arithmetic at 191 bits,
  which decide the near-ties that are not ties;
- and what is left, in nested-root numbers: polynomials with rational coefficients
  in the square roots that the computation takes (segment lengths,
  discriminants, chords), each root possibly of a number holding others,
  whose sign is found by exact squaring.  This stage always decides: the
  model never needs `CORE::Expr` and has no global state.

Constructed vertices: the double intervals decide the branches of the
construction (which of two tangent circles, ...); the disk is then computed
in double-double arithmetic (about 106 bits) and rounded to double, which
gives the exact disk correctly rounded in all but ill-conditioned cases.
The others are computed in double-double intervals, then in MPFR intervals,
until every value of the interval rounds to the same double (the exact
point correctly rounded), or else the exact value is rounded to double.  Points are those of `CK`
(double coordinates).

With `Epeck` the decisions use the exact rational coordinates of the
input; vertices are rounded to double as with `Epick`.

<b>The arithmetic of `K`</b>, for a kernel whose number type has a square
root:

- With `Simple_cartesian<double>`, everything is computed in `double`: the
  fastest model, that of the paper's implementation.  Predicates on input
  points stay exact (those of Epick), and the topology is always valid, but
  a decision on nearly degenerate input may differ from the exact one; see
  the user manual for what this model promises.
- With `Simple_cartesian<CORE::Expr>` every decision and construction is
  made by `CORE::Expr`, with its default (progressive) evaluation: exact and
  slow (two orders of magnitude), a reference.  CGAL 5.5's CORE has been
  seen to misjudge the sign of an expression that is exactly zero in that
  mode; the exact-decision model, which never uses `CORE::Expr`, is the more
  reliable exact choice.

\cgalModels `ProgressiveMedialAxisTraits_2`
*/
template <class K>
class Progressive_medial_axis_traits_2
  : public std::conditional<Progressive_medial_axes::internal::Is_filtering_kernel<K>::value,
                            Progressive_medial_axes::internal::Filtered_model<K>,
                            Progressive_medial_axes::internal::Number_model<K> >::type
{
};

namespace Progressive_medial_axes {
namespace internal {

// The double model redoes with exact decisions a merge that meets an anomaly.
template <class K>
struct Exact_fallback<Progressive_medial_axis_traits_2<K> > {
  typedef typename std::conditional<!Is_filtering_kernel<K>::value && std::is_floating_point<typename K::FT>::value,
                                    Filtered_model<K>, void>::type type;
};

} // namespace internal
} // namespace Progressive_medial_axes

} // namespace CGAL

#endif // CGAL_PROGRESSIVE_MEDIAL_AXIS_TRAITS_2_H
