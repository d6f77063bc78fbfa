// Copyright (c) 2026 The Progressive_medial_axis_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_PROGRESSIVE_MEDIAL_AXIS_2_MEDIAL_AXIS_2_H
#define CGAL_PROGRESSIVE_MEDIAL_AXIS_2_MEDIAL_AXIS_2_H

#include <CGAL/Progressive_medial_axis_2/internal/Halfedge_structure.h>
#include <CGAL/number_utils.h>
#include <CGAL/enum.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <string>
#include <vector>

namespace CGAL {

template <class Traits> class Progressive_medial_axis_2;

/*!
\ingroup PkgProgressiveMedialAxis2Ref

The medial axis of a polygon (possibly with holes), stored as a half-edge
structure whose faces are the generator cells.  This class is the read-only
view: vertices (branch points with the radius of their maximal disk,
terminal points at convex polygon vertices, junctions), medial curves
(line segments and parabolic arcs, each between two generators) and the
generators themselves (polygon edges and reflex vertices).

It is filled by `Progressive_medial_axis_2` (at every step of a progressive
computation) or returned by `medial_axis_2()`.

\tparam Traits a model of `ProgressiveMedialAxisTraits_2`.
*/
template <class Traits_>
class Medial_axis_2
{
public:
  typedef Traits_ Traits;
  typedef typename Traits::Point_2 Point_2;
  typedef typename Traits::FT FT;
  typedef PMA2::internal::Halfedge_structure<Point_2, FT> Hds;

  /// Kind of a vertex of the medial axis.
  enum Vertex_kind {
    BRANCH_POINT,   ///< three or more medial curves meet
    TERMINAL_POINT, ///< a convex vertex of the polygon, radius 0
    JUNCTION_POINT  ///< two curves meet where the generator changes (e.g. line to parabola)
  };
  /// Kind of a medial curve.
  enum Curve_kind {
    LINE_SEGMENT,   ///< bisector of two segments or of two points
    PARABOLIC_ARC   ///< bisector of a point and a segment
  };

  /// A polygon vertex, named by its ring (0 = outer ring, k = k-th hole)
  /// and its index in that ring in input order.
  struct Input_vertex {
    int ring = -1;
    int index = -1;
  };

  /// A generator: a polygon edge or a reflex vertex.  During a progressive
  /// computation a segment generator can also be a diagonal of the
  /// triangulation that bounds the current shape.
  class Generator
  {
  public:
    Generator() {}
    /// true for a reflex vertex, false for a segment
    bool is_point() const { return is_point_; }
    /// true for a segment that is an edge of the input polygon
    bool is_input_edge() const { return input_edge_ring_ >= 0; }
    /// the ring and index of an input edge (edge i goes from vertex i to vertex i+1)
    int ring() const { return is_point_ ? first_.ring : input_edge_ring_; }
    int index() const { return is_point_ ? first_.index : input_edge_index_; }
    /// the point of a reflex vertex; the source of a segment (the shape is on its left)
    const Point_2& source() const { return *source_; }
    /// the target of a segment (equal to source() for a point)
    const Point_2& target() const { return *target_; }
    /// the input vertices of the source and target
    Input_vertex source_vertex() const { return first_; }
    Input_vertex target_vertex() const { return second_; }
    /// the internal index of the generator's cell (stable while the cell lives)
    int face_index() const { return face_; }
    /// canonical id as in the package documentation: `e<r>.<i>` or `v<r>.<i>`
    /// (for a diagonal, `d<r>.<i>-<s>.<j>`)
    std::string id() const
    {
      if(is_point_)
        return "v" + std::to_string(first_.ring) + "." + std::to_string(first_.index);
      if(is_input_edge())
        return "e" + std::to_string(input_edge_ring_) + "." + std::to_string(input_edge_index_);
      return "d" + std::to_string(first_.ring) + "." + std::to_string(first_.index) + "-" +
             std::to_string(second_.ring) + "." + std::to_string(second_.index);
    }

  private:
    template <class> friend class Medial_axis_2;
    bool is_point_ = false;
    int face_ = -1;
    int input_edge_ring_ = -1, input_edge_index_ = -1;
    Input_vertex first_, second_;
    const Point_2* source_ = nullptr;
    const Point_2* target_ = nullptr;
  };

  /// A vertex of the medial axis.
  class Vertex
  {
  public:
    Vertex() {}
    const Point_2& point() const { return ma_->vertex_point(v_); }
    /// radius of the maximal disk centred here (0 at terminal points)
    const FT& radius() const { return ma_->vertex_radius(v_); }
    Vertex_kind kind() const
    {
      int m = ma_->medial_degree(v_);
      return m >= 3 ? BRANCH_POINT : (m == 1 ? TERMINAL_POINT : JUNCTION_POINT);
    }
    /// number of medial curves at this vertex
    int degree() const { return ma_->medial_degree(v_); }
    /// the generators whose cells meet here, in counter-clockwise order
    std::vector<Generator> generators() const
    {
      std::vector<Generator> g;
      int h0 = ma_->hds_.vertex(v_).halfedge, h = h0;
      do {
        int f = ma_->hds_.face_of(h);
        if(f >= 0) g.push_back(ma_->generator(f));
        h = Hds::twin(ma_->hds_.next(h));
      } while(h != h0);
      return g;
    }
    /// the polygon vertex, for a terminal point
    Input_vertex input_vertex() const { return ma_->input_vertex(ma_->hds_.vertex(v_).input_point); }
    int index() const { return v_; }
    bool operator==(const Vertex& o) const { return v_ == o.v_; }
    bool operator!=(const Vertex& o) const { return v_ != o.v_; }

  private:
    template <class> friend class Medial_axis_2;
    Vertex(const Medial_axis_2* ma, int v) : ma_(ma), v_(v) {}
    const Medial_axis_2* ma_ = nullptr;
    int v_ = -1;
  };

  /// A medial curve: the trimmed bisector of two generators.
  class Edge
  {
  public:
    Edge() {}
    Generator first_generator() const { return ma_->generator(ma_->hds_.face_of(h_)); }
    Generator second_generator() const { return ma_->generator(ma_->hds_.face_of(Hds::twin(h_))); }
    Vertex source() const { return Vertex(ma_, ma_->hds_.source(h_)); }
    Vertex target() const { return Vertex(ma_, ma_->hds_.target(h_)); }
    Curve_kind kind() const
    {
      return ma_->hds_.face(ma_->hds_.face_of(h_)).is_point ==
                 ma_->hds_.face(ma_->hds_.face_of(Hds::twin(h_))).is_point
               ? LINE_SEGMENT : PARABOLIC_ARC;
    }
    /// length of the curve (computed in double)
    double length() const { return ma_->curve_length(h_); }
    /// points along the curve from source() to target(), such that the
    /// polyline is within `tolerance` of the curve
    std::vector<std::pair<double, double> > polyline(double tolerance) const
    {
      return ma_->curve_polyline(h_, tolerance);
    }
    int index() const { return h_; }

  private:
    template <class> friend class Medial_axis_2;
    Edge(const Medial_axis_2* ma, int h) : ma_(ma), h_(h) {}
    const Medial_axis_2* ma_ = nullptr;
    int h_ = -1;
  };

  // Iterators over the live vertices and medial curves.
  template <class Value, int Step>
  class Index_iterator
  {
  public:
    typedef std::forward_iterator_tag iterator_category;
    typedef Value value_type;
    typedef std::ptrdiff_t difference_type;
    typedef const Value* pointer;
    typedef Value reference;
    Index_iterator() {}
    Index_iterator(const Medial_axis_2* ma, int i, int end) : ma_(ma), i_(i), end_(end) { skip(); }
    Value operator*() const { return Value(ma_, i_); }
    Index_iterator& operator++() { i_ += Step; skip(); return *this; }
    Index_iterator operator++(int) { Index_iterator t = *this; ++*this; return t; }
    bool operator==(const Index_iterator& o) const { return i_ == o.i_; }
    bool operator!=(const Index_iterator& o) const { return i_ != o.i_; }

  private:
    void skip() { while(i_ < end_ && !ma_->keep_index(i_, Step == 2)) i_ += Step; }
    const Medial_axis_2* ma_ = nullptr;
    int i_ = 0, end_ = 0;
  };
  typedef Index_iterator<Vertex, 1> Vertex_iterator;
  typedef Index_iterator<Edge, 2> Edge_iterator;

  template <class It>
  struct Range {
    It b, e;
    It begin() const { return b; }
    It end() const { return e; }
  };

  Vertex_iterator vertices_begin() const { return Vertex_iterator(this, 0, int(hds_.vertex_capacity())); }
  Vertex_iterator vertices_end() const { return Vertex_iterator(this, int(hds_.vertex_capacity()), int(hds_.vertex_capacity())); }
  Edge_iterator edges_begin() const { return Edge_iterator(this, 0, int(hds_.halfedge_capacity())); }
  Edge_iterator edges_end() const { return Edge_iterator(this, int(hds_.halfedge_capacity()), int(hds_.halfedge_capacity())); }
  /// All vertices of the medial axis (branch, terminal and junction points).
  Range<Vertex_iterator> vertices() const { return {vertices_begin(), vertices_end()}; }
  /// All medial curves.
  Range<Edge_iterator> edges() const { return {edges_begin(), edges_end()}; }

  std::size_t number_of_vertices() const { return std::size_t(std::distance(vertices_begin(), vertices_end())); }
  std::size_t number_of_edges() const { return std::size_t(std::distance(edges_begin(), edges_end())); }

  /// All generators (live cells).
  std::vector<Generator> generators() const
  {
    std::vector<Generator> g;
    for(int f = 0; f < int(hds_.face_capacity()); ++f)
      if(hds_.face(f).alive) g.push_back(generator(f));
    return g;
  }

  Generator generator(int f) const
  {
    const PMA2::internal::Hds_face& x = hds_.face(f);
    Generator g;
    g.is_point_ = x.is_point;
    g.face_ = f;
    g.first_ = input_vertex(x.p0);
    g.second_ = input_vertex(x.p1);
    g.source_ = &points_[x.p0];
    g.target_ = &points_[x.p1];
    if(!x.is_point) {
      const Point_info& a = info_[x.p0];
      if(a.next == x.p1) {
        g.input_edge_ring_ = a.ring;
        g.input_edge_index_ = a.reversed ? info_[x.p1].index : a.index;
      }
    }
    return g;
  }

  /// The polygon vertex with internal index `i`.
  Input_vertex input_vertex(int i) const
  {
    Input_vertex r;
    if(i >= 0) {
      r.ring = info_[i].ring;
      r.index = info_[i].index;
    }
    return r;
  }

  /// The boundary of the shape whose medial axis this is: one ring per
  /// boundary cycle, as internal point indices, the outer ring
  /// counter-clockwise and holes clockwise.
  std::vector<std::vector<int> > boundary_cycles() const
  {
    std::vector<std::vector<int> > cycles;
    std::vector<char> seen(hds_.halfedge_capacity(), 0);
    for(int h = 0; h < int(hds_.halfedge_capacity()); ++h) {
      if(seen[h] || hds_.face_of(h) != PMA2::internal::OUTSIDE) continue;
      // the outer side runs clockwise around the shape: reverse it
      std::vector<int> c;
      int g = h;
      do {
        seen[g] = 1;
        c.push_back(hds_.vertex(hds_.target(g)).input_point);
        g = hds_.next(g);
      } while(g != h);
      std::reverse(c.begin(), c.end());
      cycles.push_back(c);
    }
    return cycles;
  }

  const std::vector<Point_2>& points() const { return points_; }

  /// The rings of the input polygon, as internal point indices in input order.
  std::vector<std::vector<int> > input_rings() const
  {
    std::vector<std::vector<int> > rings;
    for(int i = 0; i < int(info_.size()); ++i) {
      if(info_[i].index == 0) rings.emplace_back();
      rings.back().push_back(i);
    }
    return rings;
  }

  /// The point and radius of vertex `v` of the half-edge structure
  /// (computed on first use; not thread-safe).
  const Point_2& vertex_point(int v) const
  {
    resolve(v);
    return hds_.vertex(v).point;
  }
  const FT& vertex_radius(int v) const
  {
    resolve(v);
    return hds_.vertex(v).radius;
  }
  const Hds& halfedge_structure() const { return hds_; }

  /// Whether the half-edge's edge is a medial curve (not a boundary edge and
  /// not the normal that separates a reflex vertex from its own edges).
  bool is_medial_edge(int h) const
  {
    if(h & 1) return false;
    int f = hds_.face_of(h), g = hds_.face_of(Hds::twin(h));
    if(f < 0 || g < 0) return false;
    return !is_normal_pair(f, g);
  }

  bool keep_index(int i, bool edge) const { return edge ? is_medial_edge(i) : is_medial_vertex(i); }

  bool is_medial_vertex(int v) const
  {
    if(!hds_.vertex(v).alive) return false;
    return medial_degree(v) > 0;
  }

  int medial_degree(int v) const
  {
    int h0 = hds_.vertex(v).halfedge, h = h0, m = 0;
    do {
      if(is_medial_edge(h & ~1)) ++m;
      h = Hds::twin(hds_.next(h));
    } while(h != h0);
    return m;
  }

  double curve_length(int h) const
  {
    std::pair<double, double> a = to_xy(vertex_point(hds_.source(h)));
    std::pair<double, double> b = to_xy(vertex_point(hds_.target(h)));
    Parabola par;
    if(!parabola(h, par))
      return std::hypot(b.first - a.first, b.second - a.second);
    return std::fabs(par.arc(par.abscissa(b)) - par.arc(par.abscissa(a)));
  }

  std::vector<std::pair<double, double> > curve_polyline(int h, double tol) const
  {
    std::pair<double, double> a = to_xy(vertex_point(hds_.source(h)));
    std::pair<double, double> b = to_xy(vertex_point(hds_.target(h)));
    std::vector<std::pair<double, double> > out;
    Parabola par;
    if(!parabola(h, par)) {
      out.push_back(a);
      out.push_back(b);
      return out;
    }
    double x1 = par.abscissa(a), x2 = par.abscissa(b);
    // the sagitta of a parabola piece of width w is w^2 / (8 * 2h): choose steps
    double w = std::fabs(x2 - x1);
    int n = 1;
    if(tol > 0 && par.h > 0) {
      double step = std::sqrt(16.0 * par.h * tol);
      n = (std::max)(1, (std::min)(10000, int(std::ceil(w / step))));
    }
    out.push_back(a);
    for(int i = 1; i < n; ++i)
      out.push_back(par.point(x1 + (x2 - x1) * double(i) / double(n)));
    out.push_back(b);
    return out;
  }

  static std::pair<double, double> to_xy(const Point_2& p)
  {
    return std::make_pair(CGAL::to_double(p.x()), CGAL::to_double(p.y()));
  }

private:
  template <class> friend class Progressive_medial_axis_2;

  struct Point_info {
    int ring = -1, index = -1;
    int next = -1;          // next point along the ring with the interior on the left
    bool reversed = false;  // the ring was given clockwise (for the outer ring)
  };

  // Bisector of a focus and a line, in a frame along the line:
  // foot of the focus at abscissa 0, height h of the focus.
  struct Parabola {
    double fx, fy;   // foot of the focus on the line
    double tx, ty;   // unit direction of the line
    double nx, ny;   // unit normal towards the focus
    double h;
    double abscissa(const std::pair<double, double>& p) const { return (p.first - fx) * tx + (p.second - fy) * ty; }
    std::pair<double, double> point(double x) const
    {
      double y = (x * x + h * h) / (2.0 * h);
      return std::make_pair(fx + x * tx + y * nx, fy + x * ty + y * ny);
    }
    double arc(double x) const
    {
      double s = std::sqrt(x * x + h * h);
      return (x * s + h * h * std::asinh(x / h)) / (2.0 * h);
    }
  };

  bool parabola(int h, Parabola& par) const
  {
    int f = hds_.face_of(h), g = hds_.face_of(Hds::twin(h));
    if(f < 0 || g < 0) return false;
    const PMA2::internal::Hds_face& F = hds_.face(f);
    const PMA2::internal::Hds_face& G = hds_.face(g);
    if(F.is_point == G.is_point) return false;
    const PMA2::internal::Hds_face& P = F.is_point ? F : G;
    const PMA2::internal::Hds_face& S = F.is_point ? G : F;
    std::pair<double, double> p = to_xy(points_[P.p0]);
    std::pair<double, double> a = to_xy(points_[S.p0]), b = to_xy(points_[S.p1]);
    double dx = b.first - a.first, dy = b.second - a.second;
    double len = std::hypot(dx, dy);
    par.tx = dx / len;
    par.ty = dy / len;
    par.nx = -par.ty;
    par.ny = par.tx;
    double s = (p.first - a.first) * par.tx + (p.second - a.second) * par.ty;
    par.fx = a.first + s * par.tx;
    par.fy = a.second + s * par.ty;
    par.h = (p.first - a.first) * par.nx + (p.second - a.second) * par.ny;
    return par.h > 0;
  }

  // A point and one of its own edges, or two collinear edges that share an
  // endpoint (a flat vertex), are separated by a normal line, not a medial curve.
  bool is_normal_pair(int f, int g) const
  {
    const PMA2::internal::Hds_face& F = hds_.face(f);
    const PMA2::internal::Hds_face& G = hds_.face(g);
    if(F.is_point && G.is_point) return false;
    if(F.is_point) return F.p0 == G.p0 || F.p0 == G.p1;
    if(G.is_point) return G.p0 == F.p0 || G.p0 == F.p1;
    if(F.p1 == G.p0) return is_collinear(F.p0, F.p1, G.p1);
    if(G.p1 == F.p0) return is_collinear(G.p0, G.p1, F.p1);
    return false;
  }

  void resolve(int v) const
  {
    auto point_site = [this](int p0, int p1) {
      return p0 == p1 ? Traits::Site_2::point(points_[p0]) : Traits::Site_2::segment(points_[p0], points_[p1]);
    };
    PMA2::internal::resolve_vertex(hds_, v, Traits(), [this, &point_site](int f) {
      const PMA2::internal::Hds_face& x = hds_.face(f);
      return point_site(x.p0, x.p1);
    }, point_site);
  }

  bool is_collinear(int a, int b, int c) const
  {
    return Traits().orientation_2_object()(points_[a], points_[b], points_[c]) == COLLINEAR;
  }

  Hds hds_;
  std::vector<Point_2> points_;
  std::vector<Point_info> info_;
};

} // namespace CGAL

#endif // CGAL_PROGRESSIVE_MEDIAL_AXIS_2_MEDIAL_AXIS_2_H
