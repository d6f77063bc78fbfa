// Copyright (c) 2026 The Progressive_medial_axis_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_PROGRESSIVE_MEDIAL_AXIS_TRAITS_2_H
#define CGAL_PROGRESSIVE_MEDIAL_AXIS_TRAITS_2_H

#include <CGAL/Progressive_medial_axis_2/internal/Medial_constructions.h>
#include <CGAL/Progressive_medial_axis_2/internal/Mpfr_interval.h>
#include <CGAL/Progressive_medial_axis_2/internal/Double_double.h>
#include <CGAL/Progressive_medial_axis_2/internal/One_root_rational.h>
#include <CGAL/Progressive_medial_axis_2/internal/Nested_root_number.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/CORE_Expr.h>
#include <CGAL/Interval_nt.h>
#include <CGAL/enum.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <type_traits>

namespace CGAL {

namespace PMA2 {
namespace internal {

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
    return a.is_point ? a.p == b.p : (a.p == b.p && a.q == b.q);
  }
};

/// Exact symbolic relations of a triple, from exact predicates of `K`.
template <class K, class Site_>
Triple_relations triple_relations(const Site_ s[3], const K& k = K())
{
  typename K::Orientation_2 orientation = k.orientation_2_object();
  Triple_relations rel;
  for(int i = 0; i < 3; ++i)
    for(int j = 0; j < 3; ++j) {
      if(i == j) continue;
      rel.same[i][j] = (s[i] == s[j]);
      if(s[i].is_point && !s[j].is_point) {
        rel.point_is_source[i][j] = (s[i].p == s[j].p);
        rel.point_is_target[i][j] = (s[i].p == s[j].q);
      }
      if(!s[i].is_point && !s[j].is_point)
        rel.flat_join[i][j] = (s[i].q == s[j].p) &&
                              orientation(s[i].p, s[i].q, s[j].q) == COLLINEAR;
    }
  if(s[0].is_point && s[1].is_point && s[2].is_point)
    rel.ppp_orientation = int(orientation(s[0].p, s[1].p, s[2].p));
  return rel;
}

template <class NT, class Site_, class Convert>
Site_nt<NT> site_nt(const Site_& s, const Convert& cv)
{
  Site_nt<NT> r;
  r.is_point = s.is_point;
  r.ax = cv(s.p.x()); r.ay = cv(s.p.y());
  r.bx = cv(s.q.x()); r.by = cv(s.q.y());
  r.axis_parallel = !s.is_point && (s.p.x() == s.q.x() || s.p.y() == s.q.y());
  return r;
}

/// TIME_FOOT: the foot on the separator of the point of site s[0].
enum Time_kind : unsigned char { TIME_ZERO, TIME_END, TIME_SWITCH, TIME_VANISH, TIME_FOOT };

/// A vertex of the separator's cell whose disk passes through an endpoint of
/// the separator (a reflex vertex there) lies on the normal at that endpoint:
/// its switch time is known exactly.
template <class Site_>
Time_kind switch_time_kind(const Site_& line, const Site_& a, const Site_& b)
{
  if((a.is_point && a.p == line.p) || (b.is_point && b.p == line.p)) return TIME_ZERO;
  if((a.is_point && a.p == line.q) || (b.is_point && b.p == line.q)) return TIME_END;
  return TIME_SWITCH;
}

/// Evaluates an event time in number type NT.  Returns false when a
/// vanishing event does not exist (for a switch time, when the disk cannot
/// be built: the caller then falls back on the stored vertex).  With `rad`,
/// the time is `t + sqrt(*rad)` (the square root of a vanishing time is not
/// taken; *rad = 0 for the other kinds).
template <class NT, class Site_, class Convert>
bool evaluate_time(Time_kind kind, const Site_& c, const Site_* s, const Triple_relations& rel,
                   const Convert& cv, NT& t, NT* rad = nullptr)
{
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
  if(!medial_circle(sn, rel, circle))
    return false;
  if(kind == TIME_SWITCH) {
    t = foot_position(px, py, qx, qy, circle);
    return true;
  }
  // a vanishing point needs a disk that touches the segments themselves
  const double tolerance = std::is_floating_point<NT>::value ? 1e-12 : 0.0;
  if(!touches_segments(sn, rel, circle, tolerance))
    return false;
  if(rad != nullptr)
    return chord_far_end_parts(px, py, qx, qy, circle, t, *rad);
  return chord_far_end(px, py, qx, qy, circle, t);
}

struct Identity_convert {
  template <class T> const T& operator()(const T& x) const { return x; }
};

template <class NT>
struct To_nt_convert {
  template <class T> NT operator()(const T& x) const { return NT(x); }
};

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
  typedef typename Kernel::Orientation_2 Orientation_2;

  Orientation_2 orientation_2_object() const { return Kernel().orientation_2_object(); }

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
      return Model::time(switch_time_kind(line, a, b), line, s, t);
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

  Compute_start_time_2 compute_start_time_2_object() const { return Compute_start_time_2(); }
  Compute_end_time_2 compute_end_time_2_object() const { return Compute_end_time_2(); }
  Compute_switch_time_2 compute_switch_time_2_object() const { return Compute_switch_time_2(); }
  Compute_foot_time_2 compute_foot_time_2_object() const { return Compute_foot_time_2(); }
  Compute_vanishing_time_2 compute_vanishing_time_2_object() const { return Compute_vanishing_time_2(); }
  Compare_event_time_2 compare_event_time_2_object() const { return Compare_event_time_2(); }
  Is_event_in_past_2 is_event_in_past_2_object() const { return Is_event_in_past_2(); }
  Construct_medial_disk_2 construct_medial_disk_2_object() const { return Construct_medial_disk_2(); }
};

} // namespace internal
} // namespace PMA2

/*!
\ingroup PkgProgressiveMedialAxis2Traits

The traits model for a kernel `K` whose number type has a square root: every
construction and every decision of the merge is computed in `K::FT`.

- With `Exact_predicates_inexact_constructions_kernel` (`FT` is `double`) the
  decisions are made in floating point; predicates on input points are exact.
  This is the fastest model and the one of the paper's implementation.
- With `Exact_predicates_exact_constructions_kernel_with_sqrt`
  (`Simple_cartesian<CORE::Expr>`) every decision and construction is made
  by `CORE::Expr`, with its default (progressive) evaluation.  CGAL 5.5's
  CORE has been seen to misjudge the sign of an expression that is exactly
  zero in that mode; the filtered model, which never uses `CORE::Expr`, is
  the more reliable exact choice.

\cgalModels `ProgressiveMedialAxisTraits_2`
*/
template <class K>
class Progressive_medial_axis_traits_2
  : public PMA2::internal::Traits_functors<Progressive_medial_axis_traits_2<K>, K, typename K::FT,
                                           typename K::Point_2, typename K::FT>
{
  typedef PMA2::internal::Traits_functors<Progressive_medial_axis_traits_2<K>, K, typename K::FT,
                                          typename K::Point_2, typename K::FT> Base;
  friend Base;

public:
  typedef typename Base::FT FT;
  typedef typename Base::Point_2 Point_2;
  typedef typename Base::Site_2 Site_2;
  typedef typename Base::Event_time_2 Event_time_2;

  /// Whether the event decisions of this model are exact.
  static constexpr bool Has_exact_decisions = !std::is_floating_point<FT>::value;

private:
  static bool time(PMA2::internal::Time_kind kind, const Site_2& line, const Site_2* s, Event_time_2& t)
  {
    PMA2::internal::Triple_relations rel;
    if(s != nullptr) rel = PMA2::internal::triple_relations<K>(s);
    return PMA2::internal::evaluate_time<FT>(kind, line, s, rel, PMA2::internal::Identity_convert(), t);
  }

  static Event_time_2 foot_time(const Site_2& line, const Point_2& p)
  {
    return (line.q.x() - line.p.x()) * (p.x() - line.p.x()) + (line.q.y() - line.p.y()) * (p.y() - line.p.y());
  }

  static Comparison_result compare_times(const Event_time_2& a, const Event_time_2& b) { return CGAL::compare(a, b); }

  // With floating-point decisions, times within a few ulps of `now` count as now.
  static bool in_past(const Event_time_2& t, const Event_time_2& now, const Site_2& line)
  {
    if constexpr(Has_exact_decisions) {
      return CGAL::compare(t, now) == SMALLER;
    } else {
      FT scale;
      time(PMA2::internal::TIME_END, line, nullptr, scale);
      return t < now - FT(1e-12) * scale;
    }
  }

  static bool disk(const Site_2* s, Point_2& centre, FT& radius)
  {
    PMA2::internal::Triple_relations rel = PMA2::internal::triple_relations<K>(s);
    PMA2::internal::Identity_convert cv;
    PMA2::internal::Site_nt<FT> sn[3] = {PMA2::internal::site_nt<FT>(s[0], cv), PMA2::internal::site_nt<FT>(s[1], cv),
                                         PMA2::internal::site_nt<FT>(s[2], cv)};
    PMA2::internal::Circle_nt<FT> circle;
    if(!PMA2::internal::medial_circle(sn, rel, circle))
      return false;
    centre = Point_2(circle.x, circle.y);
    radius = circle.r;
    return true;
  }
};

namespace PMA2 {
namespace internal {

/// An event time of the filtered traits: an interval that encloses it, and
/// what is needed to evaluate it again more precisely on demand.
template <class Site_2>
class Filtered_event_time
{
public:
  typedef Interval_nt<false> Interval;
  typedef Mpfr_interval Mpfr;

  Filtered_event_time() : approx_(0) {}
  const Interval& approx() const { return approx_; }
  double to_double() const { return CGAL::to_double(approx_); }

  /// The time in MPFR intervals at the current MPFR precision, computed
  /// once: -1 if a branch of the computation cannot be decided, 0 if the
  /// event does not exist, 1 if `*value` holds the time.
  int mpfr(const Mpfr** value) const
  {
    if(mpfr_state_ == 2) {
      mpfr_state_ = -1;
      try {
        To_nt_convert<Mpfr> cv;
        Mpfr t;
        if(evaluate_time<Mpfr>(kind_, c_, s_, rel_, cv, t)) {
          mpfr_ = std::make_shared<Mpfr>(t);
          mpfr_state_ = 1;
        } else {
          mpfr_state_ = 0;
        }
      } catch(Uncertain_conversion_exception&) {
      }
    }
    *value = mpfr_.get();
    return mpfr_state_;
  }

  /// The time as alpha + sqrt(rho) in one-root numbers, with small
  /// rationals when they suffice, else with Gmpq.
  struct One_root_value {
    bool exists = false;           // the event exists (false: the time is not an event)
    bool small = false;            // `small_value` holds it
    Small_one_root_sqrt small_value;
    mutable std::shared_ptr<One_root_sqrt> big_value;   // holds it, or its conversion once asked for

    const One_root_sqrt& big() const
    {
      if(!big_value)
        big_value = std::make_shared<One_root_sqrt>(One_root_sqrt{small_value.alpha.to_gmpq(), small_value.rho.to_gmpq()});
      return *big_value;
    }
    Interval to_interval() const { return small ? small_value.to_interval() : big_value->to_interval(); }
  };

  /// The time in one-root numbers, or null if it does not have that form.
  const One_root_value* one_root() const
  {
    if(one_root_state_ == 0) {
      one_root_state_ = -1;
      auto v = std::make_shared<One_root_value>();
      try {
        try {
          if(!short_coordinates())
            throw Small_rational_overflow();
          To_nt_convert<Small_one_root> cv;
          v->exists = evaluate_time<Small_one_root>(kind_, c_, s_, rel_, cv, v->small_value.alpha, &v->small_value.rho);
          v->small = true;
        } catch(Small_rational_overflow&) {
          To_nt_convert<One_root_rational> cv;
          One_root_sqrt t;
          v->exists = evaluate_time<One_root_rational>(kind_, c_, s_, rel_, cv, t.alpha, &t.rho);
          v->big_value = std::make_shared<One_root_sqrt>(t);
        }
        one_root_ = v;
        one_root_state_ = 1;
      } catch(Not_one_root&) {
      }
    }
    return one_root_state_ > 0 ? one_root_.get() : nullptr;
  }

  /// Whether the coordinates of the sites span at most 24 bits (integers
  /// of a grid, short binary fractions): the computation then fits in
  /// Small_rational, and otherwise almost surely overflows it.
  bool short_coordinates() const
  {
    int lowest = std::numeric_limits<int>::max(), highest = std::numeric_limits<int>::min();
    auto add = [&](double x) {
      if(x == 0) return;
      int e;
      const double m = std::frexp(x, &e);
      const std::int64_t mi = std::int64_t(std::ldexp(m, 53));
      highest = (std::max)(highest, e);
      lowest = (std::min)(lowest, e - 53 + __builtin_ctzll(std::uint64_t(mi < 0 ? -mi : mi)));
    };
    auto add_site = [&](const Site_2& x) {
      add(CGAL::to_double(x.p.x())); add(CGAL::to_double(x.p.y()));
      add(CGAL::to_double(x.q.x())); add(CGAL::to_double(x.q.y()));
    };
    add_site(c_);
    if(kind_ > TIME_END)
      for(int i = 0; i < 3; ++i) add_site(s_[i]);
    return highest - lowest <= 24;
  }

  /// The time in nested-root numbers, in the current Nested_root_context.
  bool nested(Nested_root_number& t) const
  {
    To_nt_convert<Nested_root_number> cv;
    return evaluate_time<Nested_root_number>(kind_, c_, s_, rel_, cv, t);
  }

  Time_kind kind_ = TIME_ZERO;
  Interval approx_;
  Site_2 c_, s_[3];
  Triple_relations rel_;
  mutable std::shared_ptr<Mpfr> mpfr_;
  mutable signed char mpfr_state_ = 2;     // 2 not computed yet, else as returned by mpfr()
  mutable std::shared_ptr<One_root_value> one_root_;
  mutable signed char one_root_state_ = 0; // 0 unknown, 1 one_root_ holds it, -1 not a one-root number
  mutable std::shared_ptr<char> tie_;       // shared by times found exactly equal
};

} // namespace internal
} // namespace PMA2

/*!
\ingroup PkgProgressiveMedialAxis2Traits

The filtered traits model: every decision is exact, and almost all are
taken in floating point.  A decision is evaluated first in double interval
arithmetic (`Interval_nt`).  What the intervals cannot decide is almost
always an exact tie (equal event times, a zero discriminant), and is decided
- in exact numbers alpha + sqrt(rho), where alpha and rho are a + b sqrt(D)
  with rational a, b, D, when the computation keeps that form, as is usual
  with axis-parallel edges (mazes, CAD parts);
- otherwise in MPFR interval arithmetic at 256 bits, which decides the
  near-ties that are not ties;
- and what is left, in nested-root numbers: polynomials with rational coefficients
  in the square roots that the computation takes (segment lengths,
  discriminants, chords), each root possibly of a number holding others,
  whose sign is found by exact squaring.  This stage always decides: the
  model never needs `CORE::Expr` and has no global state.

Constructed vertices: the double intervals decide the branches of the
construction (which of two tangent circles, ...); the disk is then computed
in double-double arithmetic (about 106 bits) and rounded to double, which
gives the exact disk correctly rounded in all but ill-conditioned cases.
When the intervals cannot decide a branch, MPFR intervals are used until
both ends round to the same double (the exact point correctly rounded), or
else the exact value is rounded to double.  Points are those of `CK`
(double coordinates).

\cgalModels `ProgressiveMedialAxisTraits_2`
*/
template <class CK = Exact_predicates_inexact_constructions_kernel>
class Progressive_medial_axis_filtered_traits_2
  : public PMA2::internal::Traits_functors<
      Progressive_medial_axis_filtered_traits_2<CK>, CK, typename CK::FT, typename CK::Point_2,
      PMA2::internal::Filtered_event_time<PMA2::internal::Site<typename CK::Point_2> > >
{
  typedef PMA2::internal::Traits_functors<
    Progressive_medial_axis_filtered_traits_2<CK>, CK, typename CK::FT, typename CK::Point_2,
    PMA2::internal::Filtered_event_time<PMA2::internal::Site<typename CK::Point_2> > > Base;
  friend Base;

public:
  typedef typename Base::FT FT;
  typedef typename Base::Point_2 Point_2;
  typedef typename Base::Site_2 Site_2;
  typedef typename Base::Event_time_2 Event_time_2;
  typedef Interval_nt<false> Interval;
  typedef PMA2::internal::Mpfr_interval Mpfr;
  typedef PMA2::internal::Nested_root_number Nested;

  static constexpr bool Has_exact_decisions = true;

  /// Counters of the filter stages (shared by all objects of this class in
  /// the thread).
  struct Filter_statistics {
    std::size_t interval_evaluations = 0;      ///< times and disks evaluated in double intervals
    std::size_t double_double_evaluations = 0; ///< disks constructed in double-double arithmetic
    std::size_t mpfr_evaluations = 0;          ///< ... that the double intervals could not decide
    std::size_t rational_evaluations = 0;      ///< ... that were decided in exact one-root numbers
    std::size_t exact_evaluations = 0;         ///< ... that needed the nested-root numbers
    std::size_t mpfr_comparisons = 0;          ///< comparisons of times decided by MPFR intervals
    std::size_t rational_comparisons = 0;      ///< ... decided in exact one-root numbers
    std::size_t exact_comparisons = 0;         ///< ... decided in nested-root numbers
    std::size_t exact_ties = 0;                ///< comparisons that found two times equal (one-root or nested)
  };
  static Filter_statistics& filter_statistics()
  {
    static thread_local Filter_statistics s;
    return s;
  }

  /// The precision, in bits, of the MPFR stage.
  static constexpr mpfr_prec_t mpfr_precision = 256;

private:
  // Evaluates a time: double intervals, MPFR intervals, exactly.
  static bool time(PMA2::internal::Time_kind kind, const Site_2& line, const Site_2* s, Event_time_2& t)
  {
    t.kind_ = kind;
    t.c_ = line;
    if(s != nullptr) {
      for(int i = 0; i < 3; ++i) t.s_[i] = s[i];
      t.rel_ = PMA2::internal::triple_relations<CK>(s);
    }
    t.one_root_.reset();
    t.one_root_state_ = 0;
    t.mpfr_.reset();
    t.mpfr_state_ = 2;
    t.tie_.reset();
    ++filter_statistics().interval_evaluations;
    {
      Protect_FPU_rounding<true> protection;
      try {
        Interval v;
        PMA2::internal::To_nt_convert<Interval> cv;
        bool ok = PMA2::internal::evaluate_time<Interval>(kind, line, t.s_, t.rel_, cv, v);
        if(!ok)
          return false;
        if(CGAL_NTS is_finite(v.inf()) && CGAL_NTS is_finite(v.sup())) {
          t.approx_ = v;
          return true;
        }
      } catch(Uncertain_conversion_exception&) {
      }
    }
    ++filter_statistics().mpfr_evaluations;
    const std::optional<bool> decided = before_exact<bool>(
      [&]() -> std::optional<bool> {
        const Mpfr* v;
        const int state = t.mpfr(&v);
        if(state < 0)
          return std::nullopt;
        if(state == 0)
          return false;
        t.approx_ = v->to_interval();
        return true;
      },
      [&]() -> std::optional<bool> {
        const typename Event_time_2::One_root_value* v = t.one_root();
        if(v == nullptr)
          return std::nullopt;
        ++filter_statistics().rational_evaluations;
        if(!v->exists)
          return false;
        t.approx_ = v->to_interval();
        return true;
      });
    if(decided)
      return *decided;
    ++filter_statistics().exact_evaluations;
    PMA2::internal::Nested_root_context context;
    Nested v;
    if(!t.nested(v))
      return false;
    t.approx_ = v.to_interval();
    return true;
  }

  // The foot of a point on the separator.
  static Event_time_2 foot_time(const Site_2& line, const Point_2& p)
  {
    Event_time_2 t;
    const Site_2 s[3] = {Site_2::point(p), Site_2::point(p), Site_2::point(p)};
    time(PMA2::internal::TIME_FOOT, line, s, t);
    return t;
  }

  static Comparison_result compare_times(const Event_time_2& a, const Event_time_2& b)
  {
    Uncertain<Comparison_result> r = CGAL::compare(a.approx(), b.approx());
    if(is_certain(r))
      return get_certain(r);
    // the two ends of one separator
    if(a.kind_ == b.kind_ && a.kind_ <= PMA2::internal::TIME_END && a.c_ == b.c_)
      return EQUAL;
    // already found equal
    if(a.tie_ && a.tie_ == b.tie_)
      return EQUAL;
    const std::optional<Comparison_result> decided = before_exact<Comparison_result>(
      [&]() -> std::optional<Comparison_result> {
        const Mpfr *va, *vb;
        if(a.mpfr(&va) != 1 || b.mpfr(&vb) != 1)
          return std::nullopt;
        Uncertain<Comparison_result> m = compare(*va, *vb);
        if(!is_certain(m))
          return std::nullopt;
        ++filter_statistics().mpfr_comparisons;
        return get_certain(m);
      },
      [&]() -> std::optional<Comparison_result> {
        const typename Event_time_2::One_root_value* ra = a.one_root();
        const typename Event_time_2::One_root_value* rb = ra ? b.one_root() : nullptr;
        if(rb == nullptr)
          return std::nullopt;
        CGAL_assertion(ra->exists && rb->exists);
        std::optional<Sign> sign;
        if(ra->small && rb->small) {
          try {
            sign = sign_of_difference(ra->small_value, rb->small_value);
          } catch(PMA2::internal::Small_rational_overflow&) {
          }
        }
        if(!sign)
          sign = sign_of_difference(ra->big(), rb->big());
        const Comparison_result res = Comparison_result(int(*sign));
        ++filter_statistics().rational_comparisons;
        return tie(a, b, res);
      });
    if(decided)
      return *decided;
    ++filter_statistics().exact_comparisons;
    PMA2::internal::Nested_root_context context;
    Nested ta, tb;
    const bool ok = a.nested(ta) && b.nested(tb);
    CGAL_assertion(ok);
    CGAL_USE(ok);
    return tie(a, b, Comparison_result(int(sign_of_difference(ta, tb))));
  }

  // Remembers that a and b are equal, so that comparing them again is immediate.
  static Comparison_result tie(const Event_time_2& a, const Event_time_2& b, Comparison_result r)
  {
    if(r == EQUAL) {
      ++filter_statistics().exact_ties;
      if(!a.tie_)
        a.tie_ = std::make_shared<char>(0);
      b.tie_ = a.tie_;
    }
    return r;
  }

  static bool in_past(const Event_time_2& t, const Event_time_2& now, const Site_2&)
  {
    return compare_times(t, now) == SMALLER;
  }

  // The disk tangent to three sites, rounded to double.
  static bool disk(const Site_2* s, Point_2& centre, FT& radius)
  {
    PMA2::internal::Triple_relations rel = PMA2::internal::triple_relations<CK>(s);
    ++filter_statistics().interval_evaluations;
    bool branches_decided = false;
    {
      Protect_FPU_rounding<true> protection;
      try {
        PMA2::internal::Circle_nt<Interval> circle;
        if(!disk_nt<Interval>(s, rel, circle))
          return false;
        branches_decided = true;
        if(circle.x.is_point() && circle.y.is_point() && circle.r.is_point()) {
          centre = Point_2(circle.x.inf(), circle.y.inf());
          radius = circle.r.inf();
          return true;
        }
      } catch(Uncertain_conversion_exception&) {
      }
    }
    if(branches_decided) {
      // The intervals took every branch: the same computation in
      // double-double arithmetic (about 106 bits), rounded to double, gives
      // the exact disk correctly rounded in all but ill-conditioned cases.
      ++filter_statistics().double_double_evaluations;
      PMA2::internal::Circle_nt<PMA2::internal::Double_double> circle;
      if(disk_nt<PMA2::internal::Double_double>(s, rel, circle)) {
        centre = Point_2(circle.x.to_double(), circle.y.to_double());
        radius = circle.r.to_double();
        return true;
      }
    }
    ++filter_statistics().mpfr_evaluations;
    const std::optional<bool> decided = before_exact<bool>(
      [&]() -> std::optional<bool> {
        PMA2::internal::Circle_nt<Mpfr> circle;
        if(!disk_nt<Mpfr>(s, rel, circle))
          return false;
        if(!circle.x.rounds_to_one_double() || !circle.y.rounds_to_one_double() || !circle.r.rounds_to_one_double())
          return std::nullopt;
        centre = Point_2(circle.x.midpoint(), circle.y.midpoint());
        radius = circle.r.midpoint();
        return true;
      },
      [&]() -> std::optional<bool> {
        auto one_root = [&](auto number) {
          typedef decltype(number) N;
          PMA2::internal::Circle_nt<N> circle;
          if(!disk_nt<N>(s, rel, circle))
            return false;
          ++filter_statistics().rational_evaluations;
          centre = Point_2(circle.x.to_double(), circle.y.to_double());
          radius = circle.r.to_double();
          return true;
        };
        try {
          return one_root(PMA2::internal::Small_one_root());
        } catch(PMA2::internal::Small_rational_overflow&) {
          return one_root(PMA2::internal::One_root_rational());
        }
      });
    if(decided)
      return *decided;
    ++filter_statistics().exact_evaluations;
    PMA2::internal::Nested_root_context context;
    PMA2::internal::Circle_nt<Nested> circle;
    if(!disk_nt<Nested>(s, rel, circle))
      return false;
    centre = Point_2(circle.x.to_double(), circle.y.to_double());
    radius = circle.r.to_double();
    return true;
  }

  // The stages between the double intervals and the nested-root numbers, in
  // order: exact one-root numbers, then MPFR intervals.  What the double
  // intervals cannot decide is almost always an exact tie (degenerate input:
  // integer grids, symmetric shapes), which the one-root numbers decide
  // when the computation keeps their form, as it does with axis-parallel
  // edges; MPFR intervals then decide the near-ties that are not ties.  On
  // non-degenerate input the double intervals decide nearly everything, and
  // a value outside the one-root form is found after a few operations.  A
  // stage returns its result, or nothing when it cannot decide.
  template <class R, class Mpfr_stage, class One_root_stage>
  static std::optional<R> before_exact(const Mpfr_stage& mpfr_stage, const One_root_stage& one_root_stage)
  {
    try {
      if(std::optional<R> r = one_root_stage())
        return r;
    } catch(PMA2::internal::Not_one_root&) {
    }
    PMA2::internal::Mpfr_precision_scope scope(mpfr_precision);
    try {
      return mpfr_stage();
    } catch(Uncertain_conversion_exception&) {
    }
    return std::nullopt;
  }

  template <class NT>
  static bool disk_nt(const Site_2* s, const PMA2::internal::Triple_relations& rel, PMA2::internal::Circle_nt<NT>& circle)
  {
    PMA2::internal::To_nt_convert<NT> cv;
    PMA2::internal::Site_nt<NT> sn[3] = {PMA2::internal::site_nt<NT>(s[0], cv), PMA2::internal::site_nt<NT>(s[1], cv),
                                         PMA2::internal::site_nt<NT>(s[2], cv)};
    return PMA2::internal::medial_circle(sn, rel, circle);
  }
};

} // namespace CGAL

#endif // CGAL_PROGRESSIVE_MEDIAL_AXIS_TRAITS_2_H
