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

#ifndef CGAL_PROGRESSIVE_MEDIAL_AXIS_2_MEDIAL_AXIS_2_H
#define CGAL_PROGRESSIVE_MEDIAL_AXIS_2_MEDIAL_AXIS_2_H

#include <CGAL/license/Progressive_medial_axis_2.h>

#include <CGAL/Progressive_medial_axis_2/internal/Medial_axis_engine.h>
#include <CGAL/Progressive_medial_axis_2/internal/Curves.h>
#include <CGAL/Progressive_medial_axis_2/internal/Input_conversion.h>
#include <CGAL/Exact_rational.h>
#include <CGAL/number_utils.h>
#include <CGAL/enum.h>

#include <boost/container/vector.hpp>

#if defined(CGAL_LINKED_WITH_TBB) && !defined(CGAL_PMA2_NO_TBB)
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#endif

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstddef>
#include <functional>
#include <iostream>
#include <iterator>
#include <limits>
#include <memory>
#include <new>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {

template <class K> class Medial_axis_2;
template <class Traits_> class Progressive_medial_axis_2;
namespace Progressive_medial_axes {
namespace internal {
// Calls f(begin, end) on blocks that cover [0, n), in parallel where TBB is
// linked and `parallel` is true (f must only write what its block owns).
// Work that reads numbers of an exact kernel must pass false: a lazy exact
// number refines itself when it is read, which is not thread-safe.
template <class F>
void parallel_blocks(std::size_t n, const F& f, bool parallel = true)
{
#if defined(CGAL_LINKED_WITH_TBB) && !defined(CGAL_PMA2_NO_TBB)
  if(parallel && n > 16384) {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 8192),
                      [&](const tbb::blocked_range<std::size_t>& r) { f(r.begin(), r.end()); });
    return;
  }
#else
  (void)parallel;
#endif
  f(std::size_t(0), n);
}

// Calls f(part, begin, end) on `parts` contiguous parts of [0, n) of about
// the same size, in parallel where TBB is linked (f must only write what its
// part owns).  For work that each part does in the order of [0, n), so that
// the result does not depend on the number of parts.
template <class F>
void parallel_parts(std::size_t n, std::size_t parts, const F& f)
{
#if defined(CGAL_LINKED_WITH_TBB) && !defined(CGAL_PMA2_NO_TBB)
  if(parts > 1) {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, parts, 1), [&](const tbb::blocked_range<std::size_t>& r) {
      for(std::size_t p = r.begin(); p < r.end(); ++p) f(p, n * p / parts, n * (p + 1) / parts);
    });
    return;
  }
#endif
  for(std::size_t p = 0; p < parts; ++p) f(p, n * p / parts, n * (p + 1) / parts);
}

// The number of parts for parallel_parts(): the threads of the current
// arena where TBB is linked, 1 otherwise, and 1 for less than `least` items.
inline std::size_t number_of_parts(std::size_t n, std::size_t least = 65536)
{
#if defined(CGAL_LINKED_WITH_TBB) && !defined(CGAL_PMA2_NO_TBB)
  if(n >= least) return std::size_t((std::max)(1, tbb::this_task_arena::max_concurrency()));
#endif
  (void)n;
  (void)least;
  return 1;
}

// Writes the indices i of [0, n) with keep(i), in their order, after `first`
// entries of an array: resize(total) sizes the array to `first` plus their
// number, then write(i, k) writes i at position k.  The indices are counted,
// then written, in parallel parts (see number_of_parts()).
template <class Keep, class Resize, class Write>
void parallel_compact(std::size_t n, std::size_t first, const Keep& keep, const Resize& resize, const Write& write)
{
  const std::size_t parts = number_of_parts(n);
  std::vector<std::size_t> part_first(parts + 1, 0);
  parallel_parts(n, parts, [&](std::size_t part, std::size_t b, std::size_t e) {
    std::size_t c = 0;
    for(std::size_t i = b; i < e; ++i) c += std::size_t(bool(keep(i)));
    part_first[part + 1] = c;
  });
  part_first[0] = first;
  for(std::size_t p = 0; p < parts; ++p) part_first[p + 1] += part_first[p];
  resize(part_first[parts]);
  parallel_parts(n, parts, [&](std::size_t part, std::size_t b, std::size_t e) {
    std::size_t k = part_first[part];
    for(std::size_t i = b; i < e; ++i)
      if(keep(i)) write(i, k++);
  });
}

// A vector of n copies of `value`, written in parallel blocks: the pages of
// a large fresh array are then faulted in by all the threads rather than by
// one (for the large arrays of the analysis).
template <class T>
boost::container::vector<T> parallel_filled(std::size_t n, const T& value)
{
  boost::container::vector<T> v(n, boost::container::default_init);
  parallel_blocks(n, [&](std::size_t b, std::size_t e) {
    std::fill(v.begin() + std::ptrdiff_t(b), v.begin() + std::ptrdiff_t(e), value);
  });
  return v;
}

// A read-only array of n records, each written once, in parallel, by
// write(), and never constructed before: the analysis of a plate of 100,000
// holes makes arrays of over a million records, and a container that
// constructs its elements (std::vector, or boost::container::vector for a
// class with a constructor of its own, such as a handle) would first write
// them all on one thread.  Copies share the records (they are not written
// once the array is handed out).  For trivially copyable, trivially
// destructible records.
template <class T>
class Written_once_array
{
  static_assert(std::is_trivially_destructible<T>::value && std::is_trivially_copyable<T>::value,
                "the array neither copies nor destroys its records one by one");

public:
  typedef T value_type;
  typedef const T* const_iterator;
  typedef const_iterator iterator;
  Written_once_array() {}
  explicit Written_once_array(std::size_t n)
    : p_(n == 0 ? nullptr : static_cast<T*>(::operator new(n * sizeof(T))), [](T* q) { ::operator delete(q); }), n_(n)
  {
  }
  void write(std::size_t i, const T& x) { new(p_.get() + i) T(x); }
  const_iterator begin() const { return p_.get(); }
  const_iterator end() const { return p_.get() + n_; }
  std::size_t size() const { return n_; }
  bool empty() const { return n_ == 0; }
  const T& operator[](std::size_t i) const { return p_.get()[i]; }
  const T& front() const { return p_.get()[0]; }
  const T& back() const { return p_.get()[n_ - 1]; }

private:
  std::shared_ptr<T> p_;
  std::size_t n_ = 0;
};

// A hint that the record at p is read soon: for the passes of the analysis
// over a tree, whose reads jump around memory in an order known ahead.
inline void prefetch(const void* p)
{
#if defined(__GNUC__) || defined(__clang__)
  __builtin_prefetch(p);
#else
  (void)p;
#endif
}

// Builds a Medial_axis_2 from the data that a driver filled.
struct Medial_axis_access {
  template <class K, class Data>
  static Medial_axis_2<K> make(std::shared_ptr<const Data> d)
  {
    return Medial_axis_2<K>(std::move(d));
  }
  // The data of an axis (for a driver that builds on finished axes).
  template <class K>
  static const auto& data(const Medial_axis_2<K>& m)
  {
    return m.d_;
  }
};

// Where an outer boundary is pinched (it touches itself at a place), the
// interior has several parts, each with a counter-clockwise boundary cycle
// (a lobe).  A lobe that shares a place with the outer cycle (cycles[0]) is
// spliced into it there, so that the outer ring passes that place twice, as
// a pinched input ring does: the ring enters the place from the outer
// cycle's previous vertex and leaves along the lobe, so that each edge starts
// at the corner that is its source.  A lobe that touches no outer cycle is
// an island in a hole that touches the hole's ring (the "inverted island"
// of a hole ring that touches itself, which region growing can reach before
// it fills the hole's surroundings): it is spliced into the first hole it
// touches, the same way.  Written as a hole of its own, it was a hole inside
// a hole (forty-eighth session).  `same_place(u, v)` tells whether two cycle
// vertices are one place, `counterclockwise(c)` a cycle's orientation.
template <class Same_place, class Counterclockwise>
void splice_lobes(std::vector<std::vector<int> >& cycles, const Same_place& same_place,
                  const Counterclockwise& counterclockwise)
{
  // (each cycle's orientation once: splicing a lobe into a cycle leaves it
  // the outer cycle or a hole)
  std::vector<char> lobe(cycles.size(), 0);
  for(std::size_t i = 1; i < cycles.size(); ++i) lobe[i] = counterclockwise(cycles[i]);
  bool spliced = true;
  while(spliced && cycles.size() > 1) {
    spliced = false;
    for(std::size_t i = 1; i < cycles.size() && !spliced; ++i) {
      if(!lobe[i]) continue;
      // into the outer cycle, else into the first hole it touches
      for(std::size_t j = 0; j < cycles.size() && !spliced; ++j) {
        if(j == i || lobe[j]) continue;
        std::vector<int>& o = cycles[j];
        const std::vector<int>& l = cycles[i];
        // (!spliced first: after the erase below, o and l may refer past the end)
        for(std::size_t a = 0; !spliced && a < o.size(); ++a)
          for(std::size_t b = 0; !spliced && b < l.size(); ++b) {
            if(!same_place(o[a], l[b])) continue;
            // o[0..a-1], the lobe from l[b] round to l[b-1], then o[a..]
            std::vector<int> joined(o.begin(), o.begin() + std::ptrdiff_t(a));
            for(std::size_t k = 0; k < l.size(); ++k) joined.push_back(l[(b + k) % l.size()]);
            joined.insert(joined.end(), o.begin() + std::ptrdiff_t(a), o.end());
            o.swap(joined);
            cycles.erase(cycles.begin() + std::ptrdiff_t(i));
            lobe.erase(lobe.begin() + std::ptrdiff_t(i));
            spliced = true;
          }
      }
    }
  }
}
} // namespace internal
} // namespace Progressive_medial_axes

/*!
\ingroup PkgProgressiveMedialAxis2Ref

The medial axis of a polygon (possibly with holes), as the subdivision of the
shape into the cells of its generators.

- A *generator* is a polygon edge or a reflex vertex; its *cell* (a face,
  `Face_handle`) is the part of the shape closer to it than to any other.
- The cells are bounded by half-edges (`Halfedge_handle`) of three kinds:
  *medial curves* (a line segment or a parabolic arc, the trimmed bisector
  of two generators), *boundary edges* (the generator segment itself, whose
  opposite half-edge is on the border, outside the shape) and *normals*
  (the segment that separates the cell of a reflex vertex from the cells of
  its two edges).
- Vertices (`Vertex_handle`) are branch points (three or more medial
  curves, with the radius of their maximal disk), junctions (two curves,
  where a curve changes generator), terminal points (one curve: a convex
  polygon vertex, radius 0) and the contour vertices where no curve ends
  (reflex and flat polygon vertices).  A point where four or more generators
  meet is one vertex.

Handles are light values that stay valid while the axis is not refined
further (moving the `Medial_axis_2` object keeps them valid); all its const
member functions may be called from several threads at once.  Navigation
follows CGAL's half-edge data structures: `h.opposite()`, `h.next()` and
`h.prev()` walk the cell on the left of `h` counter-clockwise,
`v.incident_halfedges()` circulates counter-clockwise around a vertex, and
`f.ccb()` around a cell.

The axis is returned by `CGAL::medial_axis_2()` or read at every step of a
`Progressive_medial_axis_2`.

\tparam K the kernel of the points (the kernel of the traits that computed it).
*/
template <class K>
class Medial_axis_2
{
public:
  typedef K Kernel;
  typedef typename K::Point_2 Point_2;
  typedef typename K::FT FT;

  /// Kind of a vertex.
  enum Vertex_kind {
    BRANCH_POINT,   ///< three or more medial curves meet
    TERMINAL_POINT, ///< one medial curve ends: a convex vertex of the polygon, radius 0
    JUNCTION_POINT, ///< two curves meet where the generator changes (e.g. line to parabola)
    CONTOUR_POINT   ///< a polygon vertex where no medial curve ends (reflex or flat)
  };
  /// Kind of a medial curve.
  enum Curve_kind {
    LINE_SEGMENT,   ///< bisector of two segments or of two points
    PARABOLIC_ARC   ///< bisector of a point and a segment
  };
  /// Kind of a half-edge.
  enum Halfedge_kind {
    MEDIAL_CURVE,   ///< a medial curve, between the cells of two generators
    BOUNDARY_EDGE,  ///< a generator segment, or the opposite half-edge on the border
    NORMAL_SEGMENT  ///< the segment between a reflex vertex's cell and one of its edges' cells
  };

  /// A polygon vertex, named by its ring (0 = outer ring, k = k-th hole)
  /// and its index in that ring in input order.
  struct Input_vertex {
    int ring = -1;
    int index = -1;
    friend bool operator==(const Input_vertex& a, const Input_vertex& b) { return a.ring == b.ring && a.index == b.index; }
    friend bool operator!=(const Input_vertex& a, const Input_vertex& b) { return !(a == b); }
    friend bool operator<(const Input_vertex& a, const Input_vertex& b)
    {
      return a.ring < b.ring || (a.ring == b.ring && a.index < b.index);
    }
  };

private:
  typedef Progressive_medial_axes::internal::Medial_axis_data<Point_2, FT> Data;
  typedef typename Data::Hds Hds;
  static constexpr int NONE = Progressive_medial_axes::internal::NO_INDEX;

public:
  class Vertex_handle;
  class Halfedge_handle;
  class Face_handle;

  /// The cell of a generator: a polygon edge or a reflex vertex.  During a
  /// progressive computation a segment generator can also be a diagonal of
  /// the triangulation that bounds the current shape.
  class Face_handle
  {
  public:
    Face_handle() {}
    const Face_handle* operator->() const { return this; }
    const Face_handle& operator*() const { return *this; }
    /// false for a default-constructed handle, and for the outside of the shape
    explicit operator bool() const { return d_ != nullptr && f_ >= 0; }
    /// true for a reflex vertex, false for a segment
    bool is_point() const { return face().is_point; }
    /// true for a segment that is an edge of the input polygon
    bool is_input_edge() const { return input_edge(nullptr, nullptr); }
    /// the ring and index of an input edge (edge i goes from vertex i to vertex i+1),
    /// or of the reflex vertex
    int ring() const
    {
      int r = -1, i = -1;
      if(is_point()) return source_vertex().ring;
      input_edge(&r, &i);
      return r;
    }
    int index() const
    {
      int r = -1, i = -1;
      if(is_point()) return source_vertex().index;
      input_edge(&r, &i);
      return i;
    }
    /// the point of a reflex vertex; the source of a segment (the shape is on its left)
    const Point_2& source() const { return d_->points[face().p0]; }
    /// the target of a segment (equal to source() for a point)
    const Point_2& target() const { return d_->points[face().p1]; }
    /// the input vertices of the source and target
    Input_vertex source_vertex() const { return input_vertex_of(d_, face().p0); }
    Input_vertex target_vertex() const { return input_vertex_of(d_, face().p1); }
    /// canonical id as in the package documentation: `e<r>.<i>` or `v<r>.<i>`
    /// (for a diagonal, `d<r>.<i>-<s>.<j>`)
    std::string id() const
    {
      const Input_vertex a = source_vertex(), b = target_vertex();
      if(is_point()) return "v" + std::to_string(a.ring) + "." + std::to_string(a.index);
      int r, i;
      if(input_edge(&r, &i)) return "e" + std::to_string(r) + "." + std::to_string(i);
      return "d" + std::to_string(a.ring) + "." + std::to_string(a.index) + "-" + std::to_string(b.ring) + "." +
             std::to_string(b.index);
    }
    /// a half-edge of the cell's boundary (counter-clockwise)
    Halfedge_handle halfedge() const { return Halfedge_handle(d_, first_nonzero(d_, face().halfedge)); }
    /// the half-edges of the cell's boundary, counter-clockwise
    std::vector<Halfedge_handle> ccb() const
    {
      std::vector<Halfedge_handle> out;
      const Halfedge_handle h0 = halfedge();
      Halfedge_handle h = h0;
      do {
        out.push_back(h);
        h = h.next();
      } while(h != h0);
      return out;
    }
    /// a number that identifies the cell while it lives
    std::size_t id_number() const { return std::size_t(f_); }
    friend bool operator==(const Face_handle& a, const Face_handle& b) { return a.d_ == b.d_ && a.f_ == b.f_; }
    friend bool operator!=(const Face_handle& a, const Face_handle& b) { return !(a == b); }
    friend bool operator<(const Face_handle& a, const Face_handle& b) { return a.f_ < b.f_; }

  private:
    friend class Medial_axis_2;
    Face_handle(const Data* d, int f) : d_(d), f_(f) {}
    const Progressive_medial_axes::internal::Hds_face& face() const { return d_->hds.face(f_); }
    bool input_edge(int* ring, int* index) const
    {
      const auto& x = face();
      if(x.is_point) return false;
      const auto& a = d_->info[x.p0];
      if(a.next != x.p1) return false;
      if(ring) *ring = a.edge_ring;
      if(index) *index = a.edge_index;
      return true;
    }
    const Data* d_ = nullptr;
    int f_ = -1;
  };

  /// A generator is designated by its cell.
  typedef Face_handle Generator;

  /// A vertex of the subdivision.
  class Vertex_handle
  {
  public:
    Vertex_handle() {}
    const Vertex_handle* operator->() const { return this; }
    const Vertex_handle& operator*() const { return *this; }
    explicit operator bool() const { return d_ != nullptr; }
    const Point_2& point() const { return d_->hds.point(v_, d_->points); }
    /// radius of the maximal disk centred here (0 at polygon vertices)
    FT radius() const { return d_->hds.radius(v_); }
    Vertex_kind kind() const
    {
      const int m = degree();
      return m >= 3 ? BRANCH_POINT : (m == 2 ? JUNCTION_POINT : (m == 1 ? TERMINAL_POINT : CONTOUR_POINT));
    }
    /// number of medial curves at this vertex
    int degree() const
    {
      int m = 0;
      for_each_incoming(d_, v_, [&](int h) { if(is_medial(d_, h)) ++m; });
      return m;
    }
    /// an incoming half-edge
    Halfedge_handle halfedge() const { return Halfedge_handle(d_, incoming(d_, v_)); }
    /// the incoming half-edges, counter-clockwise around the vertex
    std::vector<Halfedge_handle> incident_halfedges() const
    {
      std::vector<Halfedge_handle> out;
      for_each_incoming(d_, v_, [&](int h) { out.push_back(Halfedge_handle(d_, h)); });
      return out;
    }
    /// the generators whose cells meet here, counter-clockwise
    std::vector<Face_handle> generators() const
    {
      std::vector<Face_handle> out;
      for_each_incoming(d_, v_, [&](int h) {
        const int f = d_->hds.face_of(h);
        if(f >= 0) out.push_back(Face_handle(d_, f));
      });
      return out;
    }
    /// whether this is a vertex of the polygon (the shape's boundary)
    bool is_polygon_vertex() const { return d_->hds.vertex(v_).input_point() != NONE; }
    /// the polygon vertex, for a terminal or contour point
    Input_vertex input_vertex() const { return input_vertex_of(d_, d_->hds.vertex(v_).input_point()); }
    /// a number that identifies the vertex while it lives
    std::size_t id_number() const { return std::size_t(v_); }
    friend bool operator==(const Vertex_handle& a, const Vertex_handle& b) { return a.d_ == b.d_ && a.v_ == b.v_; }
    friend bool operator!=(const Vertex_handle& a, const Vertex_handle& b) { return !(a == b); }
    friend bool operator<(const Vertex_handle& a, const Vertex_handle& b) { return a.v_ < b.v_; }

  private:
    friend class Medial_axis_2;
    Vertex_handle(const Data* d, int v) : d_(d), v_(representative(d, v)) {}
    Vertex_handle(const Data* d, int v, int /* v is a representative */) : d_(d), v_(v) {}
    const Data* d_ = nullptr;
    int v_ = -1;
  };

  /// A half-edge: a medial curve, a boundary edge or a normal, with the cell
  /// of `face()` on its left.
  class Halfedge_handle
  {
  public:
    Halfedge_handle() {}
    const Halfedge_handle* operator->() const { return this; }
    const Halfedge_handle& operator*() const { return *this; }
    explicit operator bool() const { return d_ != nullptr; }
    Halfedge_handle opposite() const { return Halfedge_handle(d_, h_ ^ 1); }
    Halfedge_handle twin() const { return opposite(); }
    /// the next half-edge of the cell on the left (counter-clockwise)
    Halfedge_handle next() const { return Halfedge_handle(d_, next_nonzero(d_, h_)); }
    Halfedge_handle prev() const { return Halfedge_handle(d_, prev_nonzero(d_, h_)); }
    Vertex_handle source() const { return Vertex_handle(d_, d_->hds.source(h_)); }
    Vertex_handle target() const { return Vertex_handle(d_, d_->hds.target(h_)); }
    /// the cell on the left; a null handle on the border (outside the shape)
    Face_handle face() const { return Face_handle(d_, d_->hds.face_of(h_)); }
    bool is_border() const { return d_->hds.face_of(h_) < 0; }
    Halfedge_kind kind() const
    {
      const int f = d_->hds.face_of(h_), g = d_->hds.face_of(h_ ^ 1);
      if(f < 0 || g < 0) return BOUNDARY_EDGE;
      return is_normal_pair(d_, f, g) ? NORMAL_SEGMENT : MEDIAL_CURVE;
    }
    bool is_medial_curve() const { return kind() == MEDIAL_CURVE; }
    /// the generators on both sides (a medial curve)
    Face_handle first_generator() const { return face(); }
    Face_handle second_generator() const { return opposite().face(); }
    /// line segment or parabolic arc (for a medial curve)
    Curve_kind curve_kind() const
    {
      const int f = d_->hds.face_of(h_), g = d_->hds.face_of(h_ ^ 1);
      if(f < 0 || g < 0) return LINE_SEGMENT;
      return d_->hds.face(f).is_point == d_->hds.face(g).is_point ? LINE_SEGMENT : PARABOLIC_ARC;
    }
    /// length of the curve (computed in double)
    double length() const { return curve(d_, h_).length(); }
    /// points along the curve from source() to target(), such that the
    /// polyline is within `tolerance` > 0 of the curve
    std::vector<std::pair<double, double> > polyline(double tolerance) const
    {
      return curve(d_, h_).polyline(tolerance);
    }
    /// the point at arc length `s` from source() (0 <= s <= length(); in double)
    std::pair<double, double> point_at(double s) const { return curve(d_, h_).point_at_length(s); }
    /// the unit tangent at arc length `s` from source(), pointing towards target()
    std::pair<double, double> tangent_at(double s) const { return curve(d_, h_).tangent_at_length(s); }
    /// the point of source(): `source().point()` without building the vertex
    /// handle (the vertices that edges of length zero join are at one point)
    const Point_2& source_point() const { return d_->hds.point(d_->hds.source(h_), d_->points); }
    /// the point of target(), as source_point()
    const Point_2& target_point() const { return d_->hds.point(d_->hds.target(h_), d_->points); }
    /// the radius of the maximal disk centred at source(): `source().radius()`
    /// without building the vertex handle (which looks for the vertices that
    /// edges of length zero join to the source, to name their point by one
    /// of them); with exact decisions the same number (the disks of one
    /// point are one disk, its radius correctly rounded)
    FT source_radius() const { return d_->hds.radius(d_->hds.source(h_)); }
    /// the radius of the maximal disk centred at target(), as source_radius()
    FT target_radius() const { return d_->hds.radius(d_->hds.target(h_)); }
    /// the radius of the maximal disk centred at arc length `s` from source()
    /// (the distance to the generator of face(); in double)
    double radius_at(double s) const { return distance_to_point(point_at(s)); }
    /// the distance from a point to the generator of face() (in double)
    double distance_to_point(const std::pair<double, double>& q) const
    {
      return distance_to_generator(d_, d_->hds.face_of(h_), q);
    }
    /// \cond
    // the curve in double precision (for the functions of the package that
    // walk along curves: significance and centerlines)
    Progressive_medial_axes::internal::Curve geometry() const { return curve(d_, h_); }
    /// \endcond
    /// the part of the curve between arc lengths `s0` < `s1` from source(),
    /// as a polyline within `tolerance` of the curve; an end at 0 or at
    /// length() is the vertex itself
    std::vector<std::pair<double, double> > polyline(double tolerance, double s0, double s1) const
    {
      const auto c = curve(d_, h_);
      return (s0 > 0 || s1 < c.length() ? c.part(s0, s1) : c).polyline(tolerance);
    }
    /// the part of the curve between arc lengths `s0` < `s1` from source() as
    /// a quadratic Bezier curve {start, control point, end}: exactly the
    /// curve for a parabolic arc and for a line segment (whose control point
    /// is the middle)
    std::array<std::pair<double, double>, 3> quadratic_bezier(double s0, double s1) const
    {
      auto c = curve(d_, h_);
      if(s0 > 0 || s1 < c.length()) c = c.part(s0, s1);
      return {{c.a, c.bezier_control_point(), c.b}};
    }
    /// a number that identifies the half-edge while it lives
    std::size_t id_number() const { return std::size_t(h_); }
    friend bool operator==(const Halfedge_handle& a, const Halfedge_handle& b) { return a.d_ == b.d_ && a.h_ == b.h_; }
    friend bool operator!=(const Halfedge_handle& a, const Halfedge_handle& b) { return !(a == b); }
    friend bool operator<(const Halfedge_handle& a, const Halfedge_handle& b) { return a.h_ < b.h_; }

  private:
    friend class Medial_axis_2;
    Halfedge_handle(const Data* d, int h) : d_(d), h_(h) {}
    const Data* d_ = nullptr;
    int h_ = -1;
  };

  /// A medial curve is designated by one of its half-edges.
  typedef Halfedge_handle Edge;
  typedef Vertex_handle Vertex;

  // ---- iteration ----

  /// Iterator over the items of one kind (vertices, medial curves, cells).
  template <class Handle>
  class Item_iterator
  {
  public:
    typedef std::forward_iterator_tag iterator_category;
    typedef Handle value_type;
    typedef std::ptrdiff_t difference_type;
    typedef const Handle* pointer;
    typedef Handle reference;
    Item_iterator() {}
    Handle operator*() const { return Handle(d_, i_); }
    Item_iterator& operator++()
    {
      ++i_;
      skip();
      return *this;
    }
    Item_iterator operator++(int)
    {
      Item_iterator t = *this;
      ++*this;
      return t;
    }
    bool operator==(const Item_iterator& o) const { return i_ == o.i_; }
    bool operator!=(const Item_iterator& o) const { return i_ != o.i_; }

  private:
    friend class Medial_axis_2;
    Item_iterator(const Data* d, int i, int end, bool (*keep)(const Data*, int)) : d_(d), i_(i), end_(end), keep_(keep)
    {
      skip();
    }
    void skip()
    {
      while(i_ < end_ && !keep_(d_, i_)) ++i_;
    }
    const Data* d_ = nullptr;
    int i_ = 0, end_ = 0;
    bool (*keep_)(const Data*, int) = nullptr;
  };

  template <class It>
  struct Range {
    It b, e;
    It begin() const { return b; }
    It end() const { return e; }
  };

  typedef Item_iterator<Vertex_handle> Vertex_iterator;
  typedef Item_iterator<Halfedge_handle> Edge_iterator;
  typedef Item_iterator<Face_handle> Face_iterator;

  Medial_axis_2() {}

  /// The vertices on the medial axis (branch, junction and terminal points).
  Range<Vertex_iterator> vertices() const { return range<Vertex_handle>(d_ ? int(hds().vertex_capacity()) : 0, &keep_vertex); }
  /// The medial curves, one half-edge each.
  Range<Edge_iterator> edges() const { return range<Halfedge_handle>(d_ ? int(hds().halfedge_capacity()) : 0, &keep_edge); }
  /// The generator cells.
  Range<Face_iterator> faces() const { return range<Face_handle>(d_ ? int(hds().face_capacity()) : 0, &keep_face); }
  Range<Face_iterator> generators() const { return faces(); }

  /// \cond
  // Bounds of the id numbers of vertices and half-edges (for arrays indexed
  // by them).
  std::size_t vertex_id_bound() const { return d_ ? hds().vertex_capacity() : 0; }
  std::size_t halfedge_id_bound() const { return d_ ? hds().halfedge_capacity() : 0; }

  // The handles of id numbers: `v` is the id_number() of a Vertex_handle of
  // this axis, `h` that of a Halfedge_handle.
  Vertex_handle vertex_of_id(std::size_t v) const { return Vertex_handle(d_.get(), int(v), 0); }
  Halfedge_handle halfedge_of_id(std::size_t h) const { return Halfedge_handle(d_.get(), int(h)); }

  // The medial curves as a graph, for the analysis functions (significance,
  // pruning), read from the arrays instead of through handles: `curves`
  // gets the id number of a half-edge of every medial curve, in the order
  // of edges(), the one from the curve's end of smaller (x, y) (so that the
  // lengths, and the times summed from them, do not depend on which
  // half-edge the structure lists: on how the axis was computed), `ends`
  // the id numbers of its source and target vertices,
  // `lengths` its length(), `radii` (if given) the radii at its ends in
  // double (read with the points).  The passes run in parallel where TBB is
  // linked and the kernel's numbers are doubles.  (The arrays are not
  // initialised before they are written: they are large, and their pages
  // are then first touched by the passes, in parallel.)
  void medial_curve_graph(boost::container::vector<int>& curves, boost::container::vector<std::array<int, 2> >& ends,
                          boost::container::vector<double>& lengths,
                          boost::container::vector<std::array<double, 2> >* radii = nullptr) const
  {
    using Progressive_medial_axes::internal::parallel_blocks;
    using Progressive_medial_axes::internal::parallel_compact;
    const auto no_init = boost::container::default_init;
    curves.clear();
    ends.clear();
    lengths.clear();
    if(radii) radii->clear();
    if(!d_) return;
    const Data* d = d_.get();
    const std::size_t pairs = hds().halfedge_capacity() / 2;
    // (the passes read the points and radii: in parallel only for doubles)
    const bool plain_numbers = std::is_floating_point<FT>::value;
    // 1: a medial curve, 2: an edge of length zero (its ends are one point)
    boost::container::vector<char> kind(pairs, no_init);
    std::atomic<bool> any_zero(false);
    parallel_blocks(pairs, [&](std::size_t b, std::size_t e) {
      bool zero = false;
      for(std::size_t i = b; i < e; ++i) {
        const int h = int(2 * i);
        kind[i] = keep_edge(d, h) ? 1 : (!d->hds.is_deleted(h) && d->hds.is_zero_length(h) ? 2 : 0);
        zero = zero || kind[i] == 2;
      }
      if(zero) any_zero.store(true, std::memory_order_relaxed);
    }, plain_numbers);
    // the curves, and the ends of the edges of length zero (rare), in the
    // order of the pairs: counted, then written, in parallel parts
    parallel_compact(pairs, 0, [&](std::size_t i) { return kind[i] == 1; },
                     [&](std::size_t total) { curves.resize(total, no_init); },
                     [&](std::size_t i, std::size_t k) { curves[k] = int(2 * i); });
    std::vector<int> zero_length_ends;
    if(any_zero.load())
      parallel_compact(pairs, 0, [&](std::size_t i) { return kind[i] == 2; },
                       [&](std::size_t total) { zero_length_ends.resize(2 * total); },
                       [&](std::size_t i, std::size_t k) {
                         zero_length_ends[2 * k] = d->hds.source(int(2 * i));
                         zero_length_ends[2 * k + 1] = d->hds.target(int(2 * i));
                       });
    const std::size_t m = curves.size();
    // the representatives of the vertices at edges of length zero (rare);
    // every other vertex stands for itself
    std::vector<std::pair<int, int> > rep;
    for(int v : zero_length_ends) rep.emplace_back(v, representative(d, v));
    std::sort(rep.begin(), rep.end());
    auto representative_of = [&](int v) {
      if(rep.empty()) return v;
      const auto it = std::lower_bound(rep.begin(), rep.end(), std::make_pair(v, (std::numeric_limits<int>::min)()));
      return it != rep.end() && it->first == v ? it->second : v;
    };
    ends.resize(m, no_init);
    lengths.resize(m, no_init);
    if(radii) radii->resize(m, no_init);
    parallel_blocks(m, [&](std::size_t b, std::size_t e) {
      for(std::size_t k = b; k < e; ++k) {
        int h = curves[k];
        if(k + 16 < e) {   // the vertices and cells of a curve further on, read in no order
          const int g = curves[k + 16];
          Progressive_medial_axes::internal::prefetch(&d->hds.vertex(d->hds.source(g)));
          Progressive_medial_axes::internal::prefetch(&d->hds.vertex(d->hds.target(g)));
          const int f0 = d->hds.face_of(g), f1 = d->hds.face_of(g ^ 1);
          if(f0 >= 0) Progressive_medial_axes::internal::prefetch(&d->hds.face(f0));
          if(f1 >= 0) Progressive_medial_axes::internal::prefetch(&d->hds.face(f1));
        }
        if(k + 8 < e) {   // and the points of their generators, once their cells are read
          const int g = curves[k + 8];
          const int f0 = d->hds.face_of(g), f1 = d->hds.face_of(g ^ 1);
          if(f0 >= 0) Progressive_medial_axes::internal::prefetch(&d->points[std::size_t(d->hds.face(f0).p0)]);
          if(f1 >= 0) Progressive_medial_axes::internal::prefetch(&d->points[std::size_t(d->hds.face(f1).p0)]);
        }
        ends[k] = {{representative_of(d->hds.source(h)), representative_of(d->hds.target(h))}};
        if(d->hds.point(d->hds.target(h), d->points) < d->hds.point(d->hds.source(h), d->points)) {
          h ^= 1;
          curves[k] = h;
          std::swap(ends[k][0], ends[k][1]);
        }
        lengths[k] = curve(d, h).length();
        if(radii)
          (*radii)[k] = {{CGAL::to_double(d->hds.radius(ends[k][0])), CGAL::to_double(d->hds.radius(ends[k][1]))}};
      }
    }, plain_numbers);
  }
  /// \endcond

  std::size_t number_of_vertices() const { return count(vertices()); }
  std::size_t number_of_edges() const { return count(edges()); }
  std::size_t number_of_faces() const { return count(faces()); }

  /// Whether the half-edge structure under the axis is combinatorially
  /// valid, as `Triangulation_2::is_valid()` checks a triangulation: the
  /// boundary of every cell is one cycle of half-edges, the half-edges
  /// around every vertex are one fan, `next()` and `prev()` are each
  /// other's inverse, deleted elements are all on their free lists, and
  /// cells and polygon vertices name points of the input polygon.  With
  /// `verbose`, the first problem found is written to `std::cerr` in one
  /// line.  Linear in the size of the axis; for tests and debugging (no
  /// computation calls it).
  bool is_valid(bool verbose = false) const
  {
    if(!d_) return true;
    std::string why;
    bool ok = hds().is_valid(&why);
    const long n = long(d_->points.size());
    for(std::size_t v = 0; ok && v < hds().vertex_capacity(); ++v) {
      const auto& x = hds().vertex(int(v));
      if(x.alive && x.is_corner() && x.input_point() >= n) {
        ok = false;
        why = "vertex " + std::to_string(v) + " is at input point " + std::to_string(x.input_point()) + " of " +
              std::to_string(n);
      }
    }
    for(std::size_t f = 0; ok && f < hds().face_capacity(); ++f) {
      const auto& x = hds().face(int(f));
      if(x.alive && (x.p0 < 0 || x.p0 >= n || x.p1 < 0 || x.p1 >= n)) {
        ok = false;
        why = "cell " + std::to_string(f) + " has input points " + std::to_string(x.p0) + " and " +
              std::to_string(x.p1) + " of " + std::to_string(n);
      }
    }
    if(!ok && verbose) std::cerr << "Medial_axis_2::is_valid(): " << why << "\n";
    return ok;
  }

  // ---- the shape and its polygon ----

  /// The point of a polygon vertex.
  const Point_2& point(const Input_vertex& v) const { return d_->points[d_->ring_start[v.ring] + v.index]; }
  /// Number of rings of the input polygon (the outer ring and the holes).
  std::size_t number_of_input_rings() const { return d_ ? d_->ring_start.size() - 1 : 0; }
  /// Number of vertices of ring r of the input polygon.
  std::size_t input_ring_size(std::size_t r) const { return std::size_t(d_->ring_start[r + 1] - d_->ring_start[r]); }
  /// The rings of the input polygon, their points in the order and the
  /// orientation of the input: ring r's vertex i is `point({r, i})`.
  std::vector<std::vector<Point_2> > input_rings() const
  {
    return d_ ? Progressive_medial_axes::internal::input_rings(*d_) : std::vector<std::vector<Point_2> >();
  }

  /// The boundary of the shape whose medial axis this is (at a step of a
  /// progressive computation, the current shape), as polygon vertices: its
  /// outer boundary counter-clockwise first, then its holes clockwise; each
  /// ring starts at its vertex of smallest (ring, index), and the holes
  /// come in the order of that vertex.
  std::vector<std::vector<Input_vertex> > shape_rings() const
  {
    if(!d_) return {};
    const Hds& h = hds();
    std::vector<std::vector<int> > cycles;
    std::vector<char> seen(h.halfedge_capacity(), 0);
    for(int e = 0; e < int(h.halfedge_capacity()); ++e) {
      if(seen[e] || h.face_of(e) != Progressive_medial_axes::internal::OUTSIDE) continue;
      // the border runs clockwise around the shape: reverse it
      std::vector<int> c;
      int g = e;
      do {
        seen[g] = 1;
        c.push_back(h.vertex(h.target(g)).input_point());
        g = h.next(g);
      } while(g != e);
      std::reverse(c.begin(), c.end());
      std::rotate(c.begin(), std::min_element(c.begin(), c.end()), c.end());
      cycles.push_back(c);
    }
    // The outer boundary holds the smallest point (x, then y): every hole
    // lies strictly inside it.  This is exact and needs no area.
    // (Where a hole touches it there, the counter-clockwise cycle is the outer one.)
    // (The candidate's smallest point is kept, and its orientation once a
    // tie needs it, -1 before: found again for each cycle, they made this
    // quadratic, 58 s of a GeoJSON output of a polygon of 191,274 holes;
    // RESULTS.md, seventy-first session.)
    std::size_t outer = 0;
    int outer_min = cycles.empty() ? 0 : min_point(cycles[0]);
    int outer_ccw = -1;
    for(std::size_t i = 1; i < cycles.size(); ++i) {
      const int a = min_point(cycles[i]);
      if(lexicographically_smaller(a, outer_min)) {
        outer = i;
        outer_min = a;
        outer_ccw = -1;
      } else if(!lexicographically_smaller(outer_min, a)) {
        if(outer_ccw < 0) outer_ccw = counterclockwise(cycles[outer]) ? 1 : 0;
        if(outer_ccw == 0 && counterclockwise(cycles[i])) {
          outer = i;
          outer_ccw = 1;
        }
      }
    }
    if(!cycles.empty()) std::swap(cycles[0], cycles[outer]);
    splice_lobes(cycles);
    std::sort(cycles.begin() + (cycles.empty() ? 0 : 1), cycles.end(),
              [](const std::vector<int>& x, const std::vector<int>& y) { return x.front() < y.front(); });
    std::vector<std::vector<Input_vertex> > out;
    for(const std::vector<int>& c : cycles) {
      out.emplace_back();
      for(int i : c) out.back().push_back(input_vertex_of(d_.get(), i));
    }
    return out;
  }

  /// Approximation of a point as doubles.
  static std::pair<double, double> to_xy(const Point_2& p)
  {
    return std::make_pair(CGAL::to_double(p.x()), CGAL::to_double(p.y()));
  }

private:
  template <class> friend class Progressive_medial_axis_2;
  friend struct Progressive_medial_axes::internal::Medial_axis_access;

  explicit Medial_axis_2(std::shared_ptr<const Data> d) : d_(std::move(d)) {}

  const Hds& hds() const { return d_->hds; }

  template <class Handle>
  Range<Item_iterator<Handle> > range(int end, bool (*keep)(const Data*, int)) const
  {
    if(!d_) return {Item_iterator<Handle>(), Item_iterator<Handle>()};
    return {Item_iterator<Handle>(d_.get(), 0, end, keep), Item_iterator<Handle>(d_.get(), end, end, keep)};
  }

  template <class R>
  static std::size_t count(const R& r)
  {
    return std::size_t(std::distance(r.begin(), r.end()));
  }

  // Lobes of a pinched outer ring spliced into it (see internal::splice_lobes()).
  void splice_lobes(std::vector<std::vector<int> >& cycles) const
  {
    Progressive_medial_axes::internal::splice_lobes(
      cycles, [this](int u, int v) { return d_->points[u] == d_->points[v]; },
      [this](const std::vector<int>& c) { return counterclockwise(c); });
  }
  // The sign of the area of a cycle (exact for points of doubles).
  bool counterclockwise(const std::vector<int>& c) const
  {
    CGAL::Exact_rational twice_area = 0;
    for(std::size_t k = 0; k < c.size(); ++k) {
      const auto p = to_xy(d_->points[c[k]]), q = to_xy(d_->points[c[(k + 1) % c.size()]]);
      twice_area += CGAL::Exact_rational(p.first) * CGAL::Exact_rational(q.second) -
                    CGAL::Exact_rational(p.second) * CGAL::Exact_rational(q.first);
    }
    return CGAL::sign(twice_area) == CGAL::POSITIVE;
  }

  bool lexicographically_smaller(int a, int b) const
  {
    const Point_2 &p = d_->points[a], &q = d_->points[b];
    return p.x() < q.x() || (p.x() == q.x() && p.y() < q.y());
  }
  int min_point(const std::vector<int>& c) const
  {
    int m = c[0];
    for(int i : c)
      if(lexicographically_smaller(i, m)) m = i;
    return m;
  }

  // ---- the rules of the view, on the internal structure ----

  static Input_vertex input_vertex_of(const Data* d, int i)
  {
    Input_vertex r;
    if(i >= 0) {
      r.ring = d->info[i].ring;
      r.index = d->info[i].index;
    }
    return r;
  }

  // A point and one of its own edges, or two collinear edges that share an
  // endpoint (a flat vertex), are separated by a normal, not a medial curve.
  static bool is_normal_pair(const Data* d, int f, int g)
  {
    const auto& F = d->hds.face(f);
    const auto& G = d->hds.face(g);
    if(F.is_point && G.is_point) return false;
    if(F.is_point) return F.p0 == G.p0 || F.p0 == G.p1;
    if(G.is_point) return G.p0 == F.p0 || G.p0 == F.p1;
    if(F.p1 == G.p0) return collinear(d, F.p0, F.p1, G.p1);
    if(G.p1 == F.p0) return collinear(d, G.p0, G.p1, F.p1);
    return false;
  }
  // (with exact predicates: the points of the double model are doubles,
  // whose orientation evaluated in double called a fold of 2e-17 flat and
  // dropped the curve along it; data/double_model/fold_2e-17 of the tests)
  static bool collinear(const Data* d, int a, int b, int c)
  {
    return Progressive_medial_axes::internal::Exact_orientation<K>()(d->points[a], d->points[b], d->points[c]) == COLLINEAR;
  }

  static bool is_medial(const Data* d, int h)
  {
    const int f = d->hds.face_of(h), g = d->hds.face_of(h ^ 1);
    return f >= 0 && g >= 0 && !d->hds.is_zero_length(h) && !is_normal_pair(d, f, g);
  }

  // next and prev in a cell, over edges of length zero
  static int next_nonzero(const Data* d, int h)
  {
    int n = d->hds.next(h);
    while(d->hds.is_zero_length(n) && n != h) n = d->hds.next(n);
    return n;
  }
  static int prev_nonzero(const Data* d, int h)
  {
    int p = d->hds.prev(h);
    while(d->hds.is_zero_length(p) && p != h) p = d->hds.prev(p);
    return p;
  }
  static int first_nonzero(const Data* d, int h) { return d->hds.is_zero_length(h) ? next_nonzero(d, h) : h; }

  // An incoming half-edge, not of length zero, of the point of v (v and
  // the vertices joined to it by edges of length zero: where six or more
  // generators meet, a vertex of the point can have only such edges).
  static int incoming(const Data* d, int v)
  {
    if(!touches_zero_length(d, v)) return d->hds.vertex(v).halfedge;
    int found = d->hds.vertex(v).halfedge;
    visit_point(d, v, [&](int u) {
      const int h0 = d->hds.vertex(u).halfedge;
      int h = h0;
      do {
        if(!d->hds.is_zero_length(h)) {
          found = h;
          return true;
        }
        h = Hds::twin(d->hds.next(h));
      } while(h != h0);
      return false;
    });
    return found;
  }

  // Whether an edge of length zero ends at v (rare: where four or more
  // generators meet).
  static bool touches_zero_length(const Data* d, int v)
  {
    const int h0 = d->hds.vertex(v).halfedge;
    int h = h0;
    do {
      if(d->hds.is_zero_length(h)) return true;
      h = Hds::twin(d->hds.next(h));
    } while(h != h0);
    return false;
  }

  // Calls f(u) for v and the vertices joined to it by edges of length zero,
  // until f returns true.
  template <class F>
  static void visit_point(const Data* d, int v, const F& f)
  {
    std::vector<int> stack(1, v), seen(1, v);
    while(!stack.empty()) {
      const int u = stack.back();
      stack.pop_back();
      if(f(u)) return;
      const int h0 = d->hds.vertex(u).halfedge;
      int h = h0;
      do {
        if(d->hds.is_zero_length(h)) {
          const int w = d->hds.source(h);
          if(std::find(seen.begin(), seen.end(), w) == seen.end()) {
            seen.push_back(w);
            stack.push_back(w);
          }
        }
        h = Hds::twin(d->hds.next(h));
      } while(h != h0);
    }
  }

  // Calls f(h) for the incoming half-edges of the point of v (v and the
  // vertices joined to it by edges of length zero), counter-clockwise.
  template <class F>
  static void for_each_incoming(const Data* d, int v, const F& f)
  {
    const int h0 = incoming(d, v);
    int h = h0;
    do {
      f(h);
      h = prev_nonzero(d, Hds::twin(h));
    } while(h != h0);
  }

  // The vertex that stands for the point of v: the smallest index among the
  // vertices joined to v by edges of length zero.
  static int representative(const Data* d, int v)
  {
    if(!touches_zero_length(d, v)) return v;
    int best = v;
    visit_point(d, v, [&](int u) {
      best = (std::min)(best, u);
      return false;
    });
    return best;
  }

  static bool keep_vertex(const Data* d, int v)
  {
    const auto& x = d->hds.vertex(v);
    if(!x.alive || x.halfedge == NONE || representative(d, v) != v) return false;
    bool medial = false;
    for_each_incoming(d, v, [&](int h) { medial = medial || is_medial(d, h); });
    return medial;
  }
  static bool keep_edge(const Data* d, int h) { return (h & 1) == 0 && !d->hds.is_deleted(h) && is_medial(d, h); }
  static bool keep_face(const Data* d, int f) { return d->hds.face(f).alive; }

  static Progressive_medial_axes::internal::Curve curve(const Data* d, int h)
  {
    const auto& hds = d->hds;
    Progressive_medial_axes::internal::Curve c;
    c.a = to_xy(hds.point(hds.source(h), d->points));
    c.b = to_xy(hds.point(hds.target(h), d->points));
    const int f = hds.face_of(h), g = hds.face_of(h ^ 1);
    if(f >= 0 && g >= 0 && hds.face(f).is_point != hds.face(g).is_point) {
      const auto& P = hds.face(f).is_point ? hds.face(f) : hds.face(g);
      const auto& S = hds.face(f).is_point ? hds.face(g) : hds.face(f);
      c.set_parabola(to_xy(d->points[P.p0]), to_xy(d->points[S.p0]), to_xy(d->points[S.p1]));
    }
    return c;
  }

  // Distance from q to the generator of cell f, in double.
  static double distance_to_generator(const Data* d, int f, const std::pair<double, double>& q)
  {
    if(f < 0) return 0;
    const auto& F = d->hds.face(f);
    return Progressive_medial_axes::internal::distance_to_segment(q, to_xy(d->points[F.p0]), to_xy(d->points[F.p1]));
  }

  std::shared_ptr<const Data> d_;
};

} // namespace CGAL

#endif // CGAL_PROGRESSIVE_MEDIAL_AXIS_2_MEDIAL_AXIS_2_H
