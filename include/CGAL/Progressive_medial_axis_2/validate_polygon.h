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

#ifndef CGAL_PROGRESSIVE_MEDIAL_AXIS_2_VALIDATE_POLYGON_H
#define CGAL_PROGRESSIVE_MEDIAL_AXIS_2_VALIDATE_POLYGON_H

#include <CGAL/license/Progressive_medial_axis_2.h>

/// \file validate_polygon.h
/// Geometric validation of a polygon with holes given as rings.

#include <CGAL/Progressive_medial_axis_2/Input_error.h>
#include <CGAL/Progressive_medial_axis_2/internal/Input_conversion.h>

#include <CGAL/Kernel_traits.h>
#include <CGAL/Polygon_2_algorithms.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>

#include <CGAL/enum.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <cstddef>
#include <iterator>
#include <set>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Progressive_medial_axes {
namespace internal {

/*
  Validation of a polygon with holes given as rings, in O(n log n) time for n vertices,
  with exact predicates only (`Orientation_2` and `Compare_xy_2` of the kernel).

  The checks run in this order; the first problem found is reported:

   1. every ring has at least 3 vertices;
   2. every coordinate is finite;
   3. every ring has at least 3 distinct vertices;
   4. no zero-length edge (two consecutive vertices of a ring are equal);
   5. no repeated vertex (two equal vertices anywhere in the polygon) without
      `allow_touching`; with it (the default of `validate_polygon_rings()`), where
      vertices coincide the sectors between their edges alternate between interior and
      exterior (`check_touching_point()`), after step 6;
   6. no spike (a vertex whose two edges are collinear and fold back, angle 0);
   7. no intersection between two edges other than the common vertex of two
      consecutive edges of a ring (a Shamos-Hoey sweep, see below); with
      `allow_touching`, a vertex may lie inside an edge (an OGC hole touching the outer
      ring inside one of its edges, a "T"): the sweep records it, and after the sweep
      the sectors at that place, the edge counting as two rays, must alternate as in
      step 5 (`has_vertices_on_edges()` says whether there is one);
   8. the rings nest properly: every hole lies directly inside the outer ring.

  Steps 3 and 5 sort all the vertices lexicographically (`Compare_xy_2`, ties broken by
  input order); the sorted order is also the event order of the sweep.

  Where rings touch, the sweep takes the vertices of one place together (first removing
  the edges ending there, then inserting those starting there), orders edges starting at
  one place as if they started at one vertex, and two edges that share an endpoint place
  meet only there unless they overlap.  Without touching vertices:
  after step 5 all vertices are pairwise distinct, so two edges share an endpoint if and
  only if they are consecutive edges of one ring; after step 6 such edges meet only at
  that endpoint. Any other contact between two edges (a proper crossing, a vertex lying
  on another edge, a collinear overlap) is an error.

  Step 7 is the Shamos-Hoey sweep. The sweep line moves in lexicographic (x, then y)
  order, which is equivalent to sweeping with a line rotated by an infinitesimal angle,
  so vertical edges need no special case: an edge goes from its lexicographically
  smaller ("left") endpoint to its larger ("right") one. At each vertex v, the edges
  ending at v are removed from the status first (and their former neighbours, which
  become adjacent, are tested against each other), then the edges starting at v are
  inserted (and tested against their new neighbours). The status is a balanced tree
  (`std::set`) ordered from bottom to top; an edge being inserted at v is compared with
  an edge t of the status by the orientation of v with respect to t, or, when t also
  starts at v, by the orientation of the two right endpoints. A collinear answer there
  means that v lies on t, or that the two edges overlap: an error found by the
  comparison itself. Every pair of edges that becomes adjacent in the status is tested
  with an exact segment-intersection test. The usual argument shows this finds an
  intersection whenever one exists: just before the sweep reaches the lexicographically
  smallest bad contact point p, the order of the status is consistent, and the edges
  through p form a contiguous block in which two of the offending edges are adjacent
  (or, if p is a vertex, the edges inserted at p land next to the edge containing p).

  Step 8 uses the same sweep. For each ring q, the orientation of q is read at its
  lexicographically smallest vertex (a convex vertex). When the smallest vertex v of a
  ring r is reached, the edge t directly below the edges of r starting at v is the first
  edge hit by a ray shot downwards from v. If there is no such edge, r is not enclosed
  by any ring. Otherwise, with q the ring of t: if the interior of q lies above t
  (q counterclockwise and t directed left to right, or q clockwise and t directed right
  to left), r lies directly inside q; otherwise r is a sibling of q and has the same
  parent. The parent of q is known since the smallest vertex of q precedes that of r.
  These parents are only meaningful when no intersection exists, so they are checked
  after the sweep completed: the outer ring must have no parent and every hole must have
  the outer ring as parent.
*/
template <class Kernel>
class Polygon_rings_validator
{
  typedef typename Kernel::Point_2 Point_2;
  typedef typename Kernel::Orientation_2 Orientation_2;
  typedef typename Kernel::Compare_xy_2 Compare_xy_2;
  typedef std::size_t Id; // global vertex index; edge e goes from vertex e to next(e)

  enum Contact { NO_CONTACT, CROSSING, TOUCHING, OVERLAPPING };

  // An edge in the status. Its endpoints are copied into the tree node so that the
  // comparisons made while descending the tree touch no other memory.
  struct Status_edge
  {
    Point_2 left, right; // the smaller and larger endpoint
    Id left_id;          // global index of `left`
    Id id;               // the edge
  };
  struct Status_less
  {
    const Polygon_rings_validator* validator;
    bool operator()(const Status_edge& a, const Status_edge& b) const
    {
      return validator->edge_below(a, b);
    }
  };
  typedef std::set<Status_edge, Status_less> Status;

public:
  /// With `allow_touching`, rings may touch themselves and each other at
  /// vertices (OGC touching holes, pinches, inverted islands; see
  /// `check_touching_vertices()`); otherwise a repeated vertex is an error.
  explicit Polygon_rings_validator(const Rings<Point_2>& rings, bool allow_touching = false,
                                   const Kernel& kernel = Kernel())
    : m_rings(rings),
      m_orientation(kernel.orientation_2_object()),
      m_compare_xy(kernel.compare_xy_2_object()),
      m_allow_touching(allow_touching)
  {}

  /// Runs the checks; without `nesting`, step 8 is left out (see `parents()`).
  void run(bool nesting = true)
  {
    if(m_rings.empty())
      throw Input_error("empty polygon");
    check_ring_sizes();
    build_vertex_arrays();
    check_finite_coordinates();
    sort_vertices();
    check_distinct_vertices_per_ring();
    check_zero_length_edges();
    if(!m_allow_touching)
      check_repeated_vertices();
    check_spikes();
    compute_orientations();
    if(m_allow_touching)
      check_touching_vertices();
    sweep();
    check_vertices_on_edges();
    if(nesting)
      check_nesting();
  }

  /// After `run(false)`: the ring directly enclosing each ring, or -1 (the
  /// outer ring's parent is -1 unless it lies inside a hole; a valid polygon
  /// has 0 as the parent of every hole).
  const std::vector<long>& parents() const { return m_parent; }

  /// After `run()`: whether a vertex lies inside an edge (with `allow_touching`).
  bool has_vertices_on_edges() const { return !m_on_edges.empty(); }
  /// After `run()`: the vertices that lie inside an edge, as (ring, index) pairs.
  std::vector<std::pair<int, int> > vertices_on_edges() const
  {
    std::vector<std::pair<int, int> > r;
    for(const auto& ve : m_on_edges) r.emplace_back(int(ring_of(ve.first)), int(local(ve.first)));
    return r;
  }
  /// After `run()`: the edges that those vertices lie inside, in the same
  /// order, each as the (ring, index) of its first vertex.
  std::vector<std::pair<int, int> > edges_with_vertices() const
  {
    std::vector<std::pair<int, int> > r;
    for(const auto& ve : m_on_edges) r.emplace_back(int(ring_of(ve.second)), int(local(ve.second)));
    return r;
  }

private:
  // ---------------------------------------------------------------- helpers

  const Point_2& point(Id g) const { return *m_points[g]; }
  Id ring_of(Id g) const { return m_ring_of[g]; }
  Id local(Id g) const { return g - m_ring_begin[m_ring_of[g]]; }
  Id next(Id g) const
  {
    Id r = m_ring_of[g];
    return (g + 1 < m_ring_begin[r + 1]) ? g + 1 : m_ring_begin[r];
  }
  Id prev(Id g) const
  {
    Id r = m_ring_of[g];
    return (g > m_ring_begin[r]) ? g - 1 : m_ring_begin[r + 1] - 1;
  }
  bool equal(Id a, Id b) const { return m_compare_xy(point(a), point(b)) == CGAL::EQUAL; }

  std::string ring_name(Id g) const { return "ring " + std::to_string(ring_of(g)); }
  std::string vertex_name(Id g) const
  {
    return ring_name(g) + " vertex " + std::to_string(local(g));
  }
  std::string edge_name(Id e) const
  {
    return ring_name(e) + " edge " + std::to_string(local(e)) + " (vertices " +
           std::to_string(local(e)) + "-" + std::to_string(local(next(e))) + ")";
  }
  std::string point_text(Id g) const
  {
    return format_point(CGAL::to_double(point(g).x()), CGAL::to_double(point(g).y()));
  }
  [[noreturn]] void fail(const std::string& what, Id g) const
  {
    throw Input_error(what, static_cast<int>(ring_of(g)), static_cast<int>(local(g)));
  }

  // ---------------------------------------------------------------- steps 1 to 6

  void check_ring_sizes() const
  {
    for(std::size_t r = 0; r < m_rings.size(); ++r)
      if(m_rings[r].size() < 3)
        throw Input_error("ring " + std::to_string(r) + " has fewer than 3 distinct vertices",
                          static_cast<int>(r));
  }

  void build_vertex_arrays()
  {
    std::size_t n = 0;
    for(const auto& ring : m_rings)
      n += ring.size();
    m_points.reserve(n);
    m_ring_of.reserve(n);
    m_ring_begin.reserve(m_rings.size() + 1);
    for(std::size_t r = 0; r < m_rings.size(); ++r) {
      m_ring_begin.push_back(m_points.size());
      for(const Point_2& p : m_rings[r]) {
        m_points.push_back(&p);
        m_ring_of.push_back(r);
      }
    }
    m_ring_begin.push_back(m_points.size());
  }

  void check_finite_coordinates() const
  {
    for(Id g = 0; g < m_points.size(); ++g)
      if(!CGAL::is_finite(point(g).x()) || !CGAL::is_finite(point(g).y()))
        fail("non-finite coordinate: " + vertex_name(g), g);
  }

  void sort_vertices()
  {
    // Sorting copies of the points (rather than indices) keeps the comparisons local.
    std::vector<std::pair<Point_2, Id> > keyed;
    keyed.reserve(m_points.size());
    for(Id g = 0; g < m_points.size(); ++g)
      keyed.emplace_back(point(g), g);
    std::sort(keyed.begin(), keyed.end(),
              [this](const std::pair<Point_2, Id>& a, const std::pair<Point_2, Id>& b) {
                CGAL::Comparison_result c = m_compare_xy(a.first, b.first);
                return c == CGAL::SMALLER || (c == CGAL::EQUAL && a.second < b.second);
              });
    m_order.resize(keyed.size());
    for(std::size_t k = 0; k < keyed.size(); ++k)
      m_order[k] = keyed[k].second;
  }

  // In the sorted order, equal points are contiguous and sorted by global index, hence
  // by ring: a vertex is the first of its ring at its location if the previous vertex
  // in the order is at another location or in another ring.
  void check_distinct_vertices_per_ring() const
  {
    std::vector<std::size_t> distinct(m_rings.size(), 0);
    for(std::size_t k = 0; k < m_order.size(); ++k) {
      Id g = m_order[k];
      if(k == 0 || ring_of(m_order[k - 1]) != ring_of(g) || !equal(m_order[k - 1], g))
        ++distinct[ring_of(g)];
    }
    for(std::size_t r = 0; r < m_rings.size(); ++r)
      if(distinct[r] < 3)
        throw Input_error("ring " + std::to_string(r) + " has fewer than 3 distinct vertices",
                          static_cast<int>(r));
  }

  void check_zero_length_edges() const
  {
    for(Id g = 0; g < m_points.size(); ++g)
      if(equal(g, next(g)))
        fail("zero-length edge: " + vertex_name(g) + " equals vertex " +
             std::to_string(local(next(g))), g);
  }

  // Reports, among the vertices equal to an earlier vertex (in input order), the
  // earliest one, together with the first vertex at the same location.
  void check_repeated_vertices() const
  {
    bool found = false;
    Id first = 0, repeat = 0;
    std::size_t group_begin = 0;
    for(std::size_t k = 1; k < m_order.size(); ++k) {
      if(!equal(m_order[k - 1], m_order[k])) {
        group_begin = k;
        continue;
      }
      if(k == group_begin + 1 && (!found || m_order[k] < repeat)) {
        found = true;
        first = m_order[group_begin];
        repeat = m_order[k];
      }
    }
    if(found)
      fail("repeated vertex: " + vertex_name(first) + " equals " + vertex_name(repeat) +
           " at " + point_text(first), first);
  }

  // A spike: the previous and next vertices are collinear with the vertex and on the
  // same side of it (the vertices are distinct here).
  bool is_spike(Id g) const
  {
    Id a = prev(g), c = next(g);
    return m_orientation(point(a), point(g), point(c)) == CGAL::COLLINEAR &&
           m_compare_xy(point(a), point(g)) == m_compare_xy(point(c), point(g));
  }

  void check_spikes() const
  {
    for(Id g = 0; g < m_points.size(); ++g)
      if(is_spike(g))
        fail("spike: " + vertex_name(g) + " folds back", g);
  }

  // ---------------------------------------------------------------- touching vertices

  // The orientation of each ring: the side its enclosed region lies on, read at its
  // lexicographically smallest vertex (a convex vertex of the region), or, when that
  // point is a place where the ring touches itself, from the sign of its area,
  // computed exactly.
  void compute_orientations()
  {
    const std::size_t n = m_points.size(), nr = m_rings.size();
    m_smallest.assign(nr, n);
    for(Id g : m_order)
      if(m_smallest[ring_of(g)] == n)
        m_smallest[ring_of(g)] = g;
    m_ccw.assign(nr, false);
    for(std::size_t r = 0; r < nr; ++r) {
      Id m = m_smallest[r];
      bool self_touch = false;
      for(Id g = m_ring_begin[r]; g < m_ring_begin[r + 1] && !self_touch; ++g)
        self_touch = (g != m && equal(g, m));
      if(!self_touch) {
        m_ccw[r] = m_orientation(point(prev(m)), point(m), point(next(m))) == CGAL::LEFT_TURN;
        continue;
      }
      typedef typename CGAL::Exact_predicates_exact_constructions_kernel::FT Exact;
      Exact twice_area = 0;
      const Exact x0 = Exact(CGAL::to_double(point(m).x())), y0 = Exact(CGAL::to_double(point(m).y()));
      for(Id g = m_ring_begin[r]; g < m_ring_begin[r + 1]; ++g) {
        const Exact ax = Exact(CGAL::to_double(point(g).x())) - x0, ay = Exact(CGAL::to_double(point(g).y())) - y0;
        const Exact bx = Exact(CGAL::to_double(point(next(g)).x())) - x0,
                    by = Exact(CGAL::to_double(point(next(g)).y())) - y0;
        twice_area += ax * by - ay * bx;
      }
      m_ccw[r] = CGAL::sign(twice_area) == CGAL::POSITIVE;
    }
  }

  // Is the polygon's interior on the left of the edges of ring r?  (The outer ring
  // encloses it, the holes exclude it.)
  bool interior_on_left(Id r) const { return (r == 0) == static_cast<bool>(m_ccw[r]); }

  // The direction from a touching point P to point q, in counterclockwise order
  // starting from the direction of the positive x axis.
  bool ccw_before(const Point_2& p, const Point_2& a, const Point_2& b) const
  {
    auto upper = [&](const Point_2& q) {   // in [0, pi)
      CGAL::Comparison_result c = CGAL::compare(q.y(), p.y());
      return c == CGAL::LARGER || (c == CGAL::EQUAL && CGAL::compare(q.x(), p.x()) == CGAL::LARGER);
    };
    const bool ua = upper(a), ub = upper(b);
    if(ua != ub)
      return ua;
    return m_orientation(p, a, b) == CGAL::LEFT_TURN;
  }

  /*
    Where rings touch, at a point P where several vertices (occurrences) coincide,
    the 2m edges at P cut a small disc around P into 2m sectors.  Each edge has the
    polygon's interior on a known side (the side of the outer ring's enclosed region,
    the other side of a hole's), so each edge says whether the sector following it
    counterclockwise is interior.  The polygon is valid at P iff no two edges at P
    run in the same direction (an overlap) and, in counterclockwise order, the
    sectors alternate between interior and exterior: each edge's claim agrees with
    its neighbours'.  Otherwise two rings (or a ring and itself) cross at P.  The
    interior near P is then the union of the interior sectors (wedges), pairwise
    disjoint, at most one of them reflex (their angles add up to at most 2 pi).
  */
  void check_touching_vertices()
  {
    std::size_t k = 0;
    while(k < m_order.size()) {
      std::size_t end = k + 1;
      while(end < m_order.size() && equal(m_order[k], m_order[end]))
        ++end;
      if(end - k > 1) {
        try {
          check_touching_point(k, end);
        } catch(const Input_error&) {
          // An edge through the place adds two rays (a T with vertices on both
          // sides of the edge, such as an exterior pocket of the outer ring and
          // a hole touching its edge at one point): valid if the sectors
          // alternate with them.
          const std::vector<Id> through = edges_through(m_order[k]);
          if(through.empty())
            throw;
          check_touching_point(k, end, through);
        }
      }
      k = end;
    }
  }

  // The edges vertex g lies inside (linear: only for a place whose vertices
  // alone fail the check of sectors, before the sweep finds the T's).
  std::vector<Id> edges_through(Id g) const
  {
    std::vector<Id> out;
    for(Id e = 0; e < m_points.size(); ++e) {
      const CGAL::Comparison_result a = m_compare_xy(point(e), point(g)), b = m_compare_xy(point(g), point(next(e)));
      if(a != CGAL::EQUAL && a == b && m_orientation(point(e), point(next(e)), point(g)) == CGAL::COLLINEAR)
        out.push_back(e);
    }
    return out;
  }

  void check_touching_point(std::size_t begin, std::size_t end, const std::vector<Id>& through = {}) const
  {
    const Point_2& p = point(m_order[begin]);
    // `occurrence`: the vertex at p the ray's edge leaves or enters, or for an
    // edge through p (a T), the edge (`through`)
    struct Ray { Id to; Id edge; Id occurrence; bool outgoing; bool through; };
    std::vector<Ray> rays;
    for(std::size_t k = begin; k < end; ++k) {
      Id g = m_order[k];
      rays.push_back(Ray{ next(g), g, g, true, false });
      rays.push_back(Ray{ prev(g), prev(g), g, false, false });
    }
    for(Id t : through) {
      rays.push_back(Ray{ next(t), t, t, true, true });
      rays.push_back(Ray{ t, t, t, false, true });
    }
    std::sort(rays.begin(), rays.end(),
              [&](const Ray& a, const Ray& b) { return ccw_before(p, point(a.to), point(b.to)); });
    const std::size_t n = rays.size();
    for(std::size_t i = 0; i < n; ++i) {
      const Ray& a = rays[i];
      const Ray& b = rays[(i + 1) % n];
      if(!ccw_before(p, point(a.to), point(b.to)) && !ccw_before(p, point(b.to), point(a.to)) &&
         a.occurrence != b.occurrence) {
        Id x = a.edge, y = b.edge;
        if(y < x) std::swap(x, y);
        fail("self-intersection: " + edge_name(x) + " overlaps " + edge_name(y), x);
      }
    }
    // does the sector counterclockwise after the ray lie in the interior?  (An
    // outgoing edge has the interior on the left of its direction from P, an
    // incoming one on the right, when its ring has the interior on its left.)
    auto interior_after = [&](const Ray& ray) { return ray.outgoing == interior_on_left(ring_of(ray.occurrence)); };
    for(std::size_t i = 0; i < n; ++i) {
      const Ray& a = rays[i];
      const Ray& b = rays[(i + 1) % n];
      if(interior_after(a) == interior_after(b)) {
        // (the two rays of one vertex or edge never disagree so)
        if(a.through || b.through) {
          const Ray& v = a.through ? b : a;
          const Ray& t = a.through ? a : b;
          fail("self-intersection: " + vertex_name(v.occurrence) + " crosses " + edge_name(t.edge) + " at " +
               point_text(v.occurrence), v.occurrence);
        }
        Id x = a.occurrence, y = b.occurrence;
        if(y < x) std::swap(x, y);
        fail("self-intersection: " + vertex_name(x) + " and " + vertex_name(y) + " cross at " + point_text(x), x);
      }
    }
  }

  // The places where vertices lie inside edges (the sweep's T's): the sectors
  // there, each such edge counting as two rays, must alternate.
  void check_vertices_on_edges() const
  {
    if(m_on_edges.empty())
      return;
    // by place (the first vertex there in the sorted order), then edge
    std::vector<std::pair<std::size_t, Id> > found;
    for(const auto& ve : m_on_edges) {
      std::size_t k = std::size_t(std::lower_bound(m_order.begin(), m_order.end(), ve.first, [&](Id g, Id v) {
                                    return m_compare_xy(point(g), point(v)) == CGAL::SMALLER;
                                  }) - m_order.begin());
      found.emplace_back(k, ve.second);
    }
    std::sort(found.begin(), found.end());
    found.erase(std::unique(found.begin(), found.end()), found.end());
    for(std::size_t i = 0; i < found.size();) {
      const std::size_t begin = found[i].first;
      std::vector<Id> through;
      for(; i < found.size() && found[i].first == begin; ++i) through.push_back(found[i].second);
      std::size_t end = begin + 1;
      while(end < m_order.size() && equal(m_order[begin], m_order[end]))
        ++end;
      check_touching_point(begin, end, through);
    }
  }

  // ---------------------------------------------------------------- step 7: the sweep

  // The status order: is edge a below edge b at the current position of the sweep?
  // One of the two edges is being inserted, at its left endpoint; the other one is in
  // the status. A degenerate answer is a contact (the left endpoint of the new edge lies
  // in the interior of the other edge, or both start at the same vertex and overlap),
  // recorded here and reported by the caller once the insertion is done.
  bool edge_below(const Status_edge& a, const Status_edge& b) const
  {
    if(a.id == b.id)
      return false;
    if(a.left_id == b.left_id || (m_allow_touching && m_compare_xy(a.left, b.left) == CGAL::EQUAL)) {
      CGAL::Orientation o = m_orientation(a.left, b.right, a.right);
      if(o != CGAL::COLLINEAR)
        return o == CGAL::RIGHT_TURN;
      record_contact(OVERLAPPING, a.id, b.id, a.left_id);
      return a.id < b.id;
    }
    if(m_compare_xy(a.left, b.left) == CGAL::LARGER) {
      // a is being inserted: where is its left endpoint with respect to b?
      CGAL::Orientation o = m_orientation(b.left, b.right, a.left);
      if(o != CGAL::COLLINEAR)
        return o == CGAL::RIGHT_TURN;
      if(m_allow_touching)   // a T: a's left endpoint inside b; a leaves it above or below
        return vertex_on_edge_below(a, b);
      record_contact(TOUCHING, a.id, b.id, a.left_id);
      return a.id < b.id;
    }
    // b is being inserted: where is its left endpoint with respect to a?
    CGAL::Orientation o = m_orientation(a.left, a.right, b.left);
    if(o != CGAL::COLLINEAR)
      return o == CGAL::LEFT_TURN;
    if(m_allow_touching)
      return !vertex_on_edge_below(b, a);
    record_contact(TOUCHING, b.id, a.id, b.left_id);
    return a.id < b.id;
  }

  // Edge a, being inserted, starts inside edge t of the status: is a below t just
  // right of the sweep line?  (Recorded as a vertex on an edge; collinear is an overlap.)
  bool vertex_on_edge_below(const Status_edge& a, const Status_edge& t) const
  {
    m_on_edges.emplace_back(a.left_id, t.id);
    CGAL::Orientation o = m_orientation(t.left, t.right, a.right);
    if(o != CGAL::COLLINEAR)
      return o == CGAL::RIGHT_TURN;
    record_contact(OVERLAPPING, a.id, t.id, a.left_id);
    return a.id < t.id;
  }

  void record_contact(Contact contact, Id a, Id b, Id vertex) const
  {
    if(m_contact != NO_CONTACT)
      return;
    m_contact = contact;
    m_contact_a = a;
    m_contact_b = b;
    m_contact_vertex = vertex;
  }

  // Throws for a contact between edges a and b; for TOUCHING, `vertex` is the vertex
  // (an endpoint of a) lying on edge b.
  [[noreturn]] void report_contact(Contact contact, Id a, Id b, Id vertex) const
  {
    if(contact == TOUCHING) {
      // If an edge of `vertex` runs along b, report the overlap rather than the vertex.
      for(Id e : { prev(vertex), vertex }) {
        Id other = (e == vertex) ? next(vertex) : e;
        if(m_orientation(point(b), point(next(b)), point(other)) == CGAL::COLLINEAR)
          report_contact(OVERLAPPING, e, b, vertex);
      }
      fail("self-intersection: " + vertex_name(vertex) + " lies on " + edge_name(b), vertex);
    }
    if(b < a)
      std::swap(a, b);
    fail("self-intersection: " + edge_name(a) +
         (contact == CROSSING ? " crosses " : " overlaps ") + edge_name(b), a);
  }

  // Exact test of two edges; throws if they touch anywhere except at the common
  // vertex of consecutive edges.
  void check_pair(Id a, Id b) const
  {
    if(a == b)
      return;
    if(ring_of(a) == ring_of(b) && (next(a) == b || next(b) == a)) {
      Id shared = (next(a) == b) ? b : a;
      Id x = (shared == b) ? a : b;             // start of the edge ending at `shared`
      Id y = next(shared);                      // end of the edge starting at `shared`
      if(m_orientation(point(x), point(shared), point(y)) == CGAL::COLLINEAR &&
         m_compare_xy(point(x), point(shared)) == m_compare_xy(point(y), point(shared)))
        report_contact(OVERLAPPING, a, b, shared);
      return;
    }
    Id a0 = a, a1 = next(a), b0 = b, b1 = next(b);
    if(m_allow_touching) {
      // Edges of vertices that touch: they meet at the touching point (where the
      // wedges were checked), and elsewhere only if they overlap.
      for(Id s : { a0, a1 })
        for(Id t : { b0, b1 })
          if(equal(s, t)) {
            Id x = (s == a0) ? a1 : a0, y = (t == b0) ? b1 : b0;
            if(m_orientation(point(s), point(x), point(y)) == CGAL::COLLINEAR &&
               m_compare_xy(point(x), point(s)) == m_compare_xy(point(y), point(s)))
              report_contact(OVERLAPPING, a, b, a);
            return;
          }
    }
    CGAL::Orientation o1 = m_orientation(point(a0), point(a1), point(b0));
    CGAL::Orientation o2 = m_orientation(point(a0), point(a1), point(b1));
    if(o1 == CGAL::COLLINEAR && o2 == CGAL::COLLINEAR) {
      // All four points on a line: the edges meet iff their extents overlap (they
      // cannot share only an endpoint, the vertices being distinct).
      if(m_compare_xy(point(m_right[a]), point(m_left[b])) == CGAL::SMALLER ||
         m_compare_xy(point(m_right[b]), point(m_left[a])) == CGAL::SMALLER)
        return;
      report_contact(OVERLAPPING, a, b, a);
    }
    if(o1 == o2)
      return;
    CGAL::Orientation o3 = m_orientation(point(b0), point(b1), point(a0));
    CGAL::Orientation o4 = m_orientation(point(b0), point(b1), point(a1));
    if(o3 == o4)
      return;
    if(o1 == CGAL::COLLINEAR) return vertex_on_edge(b, a, b0);
    if(o2 == CGAL::COLLINEAR) return vertex_on_edge(b, a, b1);
    if(o3 == CGAL::COLLINEAR) return vertex_on_edge(a, b, a0);
    if(o4 == CGAL::COLLINEAR) return vertex_on_edge(a, b, a1);
    report_contact(CROSSING, a, b, a);
  }

  // `vertex`, an endpoint of edge a, lies inside edge b: an error, or with
  // `allow_touching` a T, checked after the sweep (an edge of `vertex` along b
  // is an overlap).
  void vertex_on_edge(Id a, Id b, Id vertex) const
  {
    if(!m_allow_touching)
      report_contact(TOUCHING, a, b, vertex);
    for(Id other : { prev(vertex), next(vertex) })
      if(m_orientation(point(b), point(next(b)), point(other)) == CGAL::COLLINEAR)
        report_contact(OVERLAPPING, other == next(vertex) ? vertex : other, b, vertex);
    m_on_edges.emplace_back(vertex, b);
  }

  void remove_edge(Id e)
  {
    typename Status::iterator it = m_handles[e];
    typename Status::iterator after = std::next(it);
    bool has_below = (it != m_status->begin());
    typename Status::iterator below = has_below ? std::prev(it) : it;
    m_status->erase(it);
    if(has_below && after != m_status->end())
      check_pair(below->id, after->id);
  }

  void insert_edge(Id e)
  {
    typename Status::iterator it =
      m_status->insert(Status_edge{ point(m_left[e]), point(m_right[e]), m_left[e], e }).first;
    if(m_contact != NO_CONTACT)
      report_contact(m_contact, m_contact_a, m_contact_b, m_contact_vertex);
    m_handles[e] = it;
    if(it != m_status->begin())
      check_pair(std::prev(it)->id, e);
    typename Status::iterator after = std::next(it);
    if(after != m_status->end())
      check_pair(e, after->id);
  }

  void sweep()
  {
    const std::size_t n = m_points.size();
    m_left.resize(n);
    m_right.resize(n);
    for(Id e = 0; e < n; ++e) {
      Id f = next(e);
      bool forward = m_compare_xy(point(e), point(f)) == CGAL::SMALLER;
      m_left[e] = forward ? e : f;
      m_right[e] = forward ? f : e;
    }

    m_parent.assign(m_rings.size(), -1);
    m_parent_known.assign(m_rings.size(), false);

    Status status(Status_less{this});
    m_status = &status;
    m_handles.resize(n);
    m_contact = NO_CONTACT;

    // The vertices at one point (several where rings touch): first the edges ending
    // there leave the status, then the edges starting there enter it.
    std::size_t begin = 0;
    std::vector<Id> pending;
    while(begin < m_order.size()) {
      std::size_t end = begin + 1;
      while(m_allow_touching && end < m_order.size() && equal(m_order[begin], m_order[end]))
        ++end;
      for(std::size_t k = begin; k < end; ++k) {
        const Id v = m_order[k];
        for(Id e : { prev(v), v })
          if(m_right[e] == v)
            remove_edge(e);
      }
      for(std::size_t k = begin; k < end; ++k) {
        const Id v = m_order[k];
        for(Id e : { prev(v), v })
          if(m_left[e] == v)
            insert_edge(e);
      }
      // the parents of the rings whose smallest vertex is here, lowest first (a ring
      // may need the parent of a ring touching it here, below it)
      pending.clear();
      for(std::size_t k = begin; k < end; ++k)
        if(m_order[k] == m_smallest[ring_of(m_order[k])])
          pending.push_back(m_order[k]);
      while(!pending.empty()) {
        const std::size_t before = pending.size();
        pending.erase(std::remove_if(pending.begin(), pending.end(), [&](Id v) { return find_parent(v); }),
                      pending.end());
        if(pending.size() == before)
          break;
      }
      begin = end;
    }
    m_status = nullptr;
  }

  // At the smallest vertex v of its ring r: the ring directly enclosing r, from the
  // first edge of another ring directly below the edges of v.  Returns false if that
  // needs the parent of a ring not known yet (one touching r at v, whose smallest
  // vertex is also there).
  bool find_parent(Id v)
  {
    const Id r = ring_of(v);
    // both edges of v start at v; the lower one
    const Id e1 = prev(v), e2 = v;
    const Id lower = (m_orientation(point(v), point(m_right[e1]), point(m_right[e2])) == CGAL::LEFT_TURN) ? e1 : e2;
    typename Status::iterator it = m_handles[lower];
    while(it != m_status->begin() && ring_of(std::prev(it)->id) == r)   // r touching itself here
      --it;
    if(it != m_status->begin()) {
      const Id t = std::prev(it)->id;
      const Id q = ring_of(t);
      const bool interior_above = (m_ccw[q] == (m_left[t] == t));
      if(interior_above) {
        m_parent[r] = static_cast<long>(q);
      } else {
        if(!m_parent_known[q])
          return false;
        m_parent[r] = m_parent[q];
      }
    }
    m_parent_known[r] = true;
    return true;
  }

  // ---------------------------------------------------------------- step 8

  void check_nesting() const
  {
    // The outer ring inside a hole implies a hole with no parent, reported below.
    for(std::size_t r = 1; r < m_rings.size(); ++r) {
      if(m_parent[r] == 0)
        continue;
      std::string hole = "hole " + std::to_string(r) + " (ring " + std::to_string(r) + ")";
      if(m_parent[r] < 0)
        throw Input_error(hole + " is not inside the outer ring", static_cast<int>(r));
      std::string p = std::to_string(m_parent[r]);
      throw Input_error(hole + " lies inside hole " + p + " (ring " + p + ")",
                        static_cast<int>(r));
    }
  }

  // ---------------------------------------------------------------- data

  const Rings<Point_2>& m_rings;
  Orientation_2 m_orientation;
  Compare_xy_2 m_compare_xy;

  std::vector<const Point_2*> m_points; // by global index, ring after ring
  std::vector<Id> m_ring_of;            // global index -> ring
  std::vector<Id> m_ring_begin;         // ring -> first global index (one past the end at the end)
  std::vector<Id> m_order;              // global indices sorted lexicographically

  std::vector<Id> m_left, m_right;      // edge -> its smaller / larger endpoint
  std::vector<bool> m_ccw;              // ring -> counterclockwise?
  std::vector<Id> m_smallest;           // ring -> its lexicographically smallest vertex (first in input order)
  std::vector<long> m_parent;           // ring -> directly enclosing ring, or -1
  std::vector<bool> m_parent_known;     // ring -> m_parent computed?
  Status* m_status = nullptr;
  std::vector<typename Status::iterator> m_handles; // edge -> its place in the status

  bool m_allow_touching;
  mutable Contact m_contact = NO_CONTACT;
  mutable std::vector<std::pair<Id, Id> > m_on_edges;   // (vertex, edge) found by the sweep
  static constexpr Id NO_VERTEX = Id(-1);
  mutable Id m_contact_a = 0, m_contact_b = 0, m_contact_vertex = 0;
};

} // namespace internal

/*!
\ingroup PkgProgressiveMedialAxis2IO

Checks that `rings` describe a valid polygon with holes: ring 0 is the outer boundary,
the other rings are the holes (either orientation is accepted for any ring, and a vertex
with an angle of exactly \f$\pi\f$, collinear with its neighbours, is valid).

Throws `Input_error` naming the ring(s) and vertex or edge indices of the first problem
found (edge `i` of a ring goes from vertex `i` to vertex `(i+1) mod` ring size), for:
- a ring with fewer than 3 (distinct) vertices;
- a non-finite coordinate;
- a zero-length edge (two consecutive equal vertices);
- rings that cross where they touch: rings may touch themselves and each other at
  vertices (holes touching the outer ring or each other, pinches, inverted islands), and
  a vertex may lie inside an edge (a "T", such as a hole touching the outer ring inside
  one of its edges, valid in OGC Simple Features), but there the edges, in angular order
  (an edge through the place counting twice), must bound interior and exterior sectors
  alternately;
- a spike (two consecutive edges collinear and folding back, angle 0);
- any other intersection or contact between two edges that are not consecutive in the
  same ring (a proper crossing, a collinear overlap), whether they belong to the same
  ring or not;
- a hole not inside the outer ring, or a hole inside another hole.

Runs in \f$O(n \log n)\f$ time for \f$n\f$ vertices in total, using only the exact
predicates `Kernel::Orientation_2` and `Kernel::Compare_xy_2` (exact with
`CGAL::Exact_predicates_inexact_constructions_kernel`); there is no tolerance.

\tparam Kernel a \cgal kernel; `Kernel::Point_2` is the point type of `rings`.
*/
template <class Kernel>
void validate_polygon_rings(const Rings<typename Kernel::Point_2>& rings)
{
  internal::Polygon_rings_validator<Kernel>(rings, true).run();
}

namespace internal {

/// Whether `rings` is a valid polygon whose rings are simple and pairwise
/// disjoint (no ring touches itself or another, no vertex lies on another
/// edge), for a polygon of at most `max_vertices` vertices, by testing every
/// pair of edges (the brute force of the validator's tests), with the exact
/// predicates of `Kernel`.  False says nothing: the validator then runs, and
/// names the problem or finds the places where rings touch.  On a glyph of a
/// few vertices, the validator's first call in a process (its search tree
/// and sorts, code run nowhere else) was a quarter of the one-shot's time,
/// page faults mostly (RESULTS.md, "The first call on tiny polygons",
/// sixty-sixth session).
template <class Kernel>
bool simple_small_polygon(const Rings<typename Kernel::Point_2>& rings, std::size_t max_vertices = 64)
{
  typedef typename Kernel::Point_2 Point_2;
  if(rings.empty()) return false;
  std::size_t n = 0;
  for(const auto& ring : rings) {
    if(ring.size() < 3) return false;
    n += ring.size();
  }
  if(n > max_vertices) return false;
  const Kernel k;
  const auto orientation = k.orientation_2_object();
  const auto compare_xy = k.compare_xy_2_object();
  for(const auto& ring : rings)
    for(const Point_2& p : ring)
      if(!CGAL::is_finite(p.x()) || !CGAL::is_finite(p.y())) return false;
  // p on the segment ab, given that the three are collinear
  auto between = [&](const Point_2& a, const Point_2& b, const Point_2& p) {
    const Comparison_result ap = compare_xy(a, p), pb = compare_xy(p, b);
    return ap == EQUAL || pb == EQUAL || ap == pb;
  };
  auto meet = [&](const Point_2& a, const Point_2& b, const Point_2& c, const Point_2& d) {
    if(!do_overlap(a.bbox() + b.bbox(), c.bbox() + d.bbox())) return false;
    const Orientation o1 = orientation(a, b, c), o2 = orientation(a, b, d);
    const Orientation o3 = orientation(c, d, a), o4 = orientation(c, d, b);
    if(o1 != COLLINEAR && o2 != COLLINEAR && o3 != COLLINEAR && o4 != COLLINEAR)
      return o1 != o2 && o3 != o4;
    return (o1 == COLLINEAR && between(a, b, c)) || (o2 == COLLINEAR && between(a, b, d)) ||
           (o3 == COLLINEAR && between(c, d, a)) || (o4 == COLLINEAR && between(c, d, b));
  };
  for(std::size_t r = 0; r < rings.size(); ++r) {
    const std::size_t m = rings[r].size();
    for(std::size_t i = 0; i < m; ++i) {
      const Point_2 &a = rings[r][(i + m - 1) % m], &g = rings[r][i], &c = rings[r][(i + 1) % m];
      if(compare_xy(g, c) == EQUAL) return false;   // a zero-length edge
      if(orientation(a, g, c) == COLLINEAR && compare_xy(a, g) == compare_xy(c, g)) return false;   // a spike
      // every later edge that does not share a vertex with edge (g, c)
      for(std::size_t s = r; s < rings.size(); ++s) {
        const std::size_t ms = rings[s].size();
        for(std::size_t j = (s == r ? i + 1 : 0); j < ms; ++j) {
          if(s == r && (j == i + 1 || (j + 1) % m == i)) continue;
          if(meet(g, c, rings[s][j], rings[s][(j + 1) % ms])) return false;
        }
      }
    }
  }
  // disjoint simple rings: each hole inside the outer ring and in no other hole
  for(std::size_t h = 1; h < rings.size(); ++h) {
    const Point_2& p = rings[h][0];
    if(bounded_side_2(rings[0].begin(), rings[0].end(), p, k) != ON_BOUNDED_SIDE) return false;
    for(std::size_t o = 1; o < rings.size(); ++o)
      if(o != h && bounded_side_2(rings[o].begin(), rings[o].end(), p, k) != ON_UNBOUNDED_SIDE) return false;
  }
  return true;
}

// validate_polygon(), returning whether a vertex lies inside an edge (a T),
// with `on_edges`, which ones (as (ring, index) pairs; a vertex may be listed
// more than once), and with `edges`, the edges they lie inside (in the same
// order, by the (ring, index) of the edge's first vertex).
template <class Point_2>
bool validate_and_find_vertices_on_edges(const Rings<Point_2>& rings,
                                         std::vector<std::pair<int, int> >* on_edges = nullptr,
                                         std::vector<std::pair<int, int> >* edges = nullptr)
{
  typedef typename Kernel_traits<Point_2>::Kernel K;
  typedef Exact_predicates_kernel_for<K> EK;
  auto finish = [&](const auto& validator) {
    if(on_edges) *on_edges = validator.vertices_on_edges();
    if(edges) *edges = validator.edges_with_vertices();
    return validator.has_vertices_on_edges();
  };
  auto simple = [&]() {   // (no vertex inside an edge)
    if(on_edges) on_edges->clear();
    if(edges) edges->clear();
    return false;
  };
  if constexpr(std::is_same<typename EK::type, K>::value) {
    if(simple_small_polygon<K>(rings)) return simple();
    Polygon_rings_validator<K> validator(rings, true);
    validator.run();
    return finish(validator);
  } else {
    Rings<typename EK::type::Point_2> converted;
    for(const auto& r : rings) {
      converted.emplace_back();
      for(const auto& p : r) converted.back().push_back(EK::point(p));
    }
    if(simple_small_polygon<typename EK::type>(converted)) return simple();
    Polygon_rings_validator<typename EK::type> validator(converted, true);
    validator.run();
    return finish(validator);
  }
}

} // namespace internal

/*!
\ingroup PkgProgressiveMedialAxis2Ref

Checks that `rings` (the outer ring, then the holes, each a vector of points
of a \cgal kernel) describe a valid polygon with holes, as
`validate_polygon_rings()` does, with exact predicates (those of `Epick` for
a kernel of doubles).  Throws `Input_error` naming the problem, its ring and
vertex.  This is the check the constructors of `Progressive_medial_axis_2`
run unless told `TRUST_INPUT`.
*/
template <class Point_2>
void validate_polygon(const Rings<Point_2>& rings)
{
  internal::validate_and_find_vertices_on_edges(rings);
}

} // namespace Progressive_medial_axes
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_MEDIAL_AXIS_2_VALIDATE_POLYGON_H
