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
// The shape decomposition of the region-growing driver: a constrained
// Delaunay triangulation of the polygon and the adjacency of its triangles.

#ifndef CGAL_PROGRESSIVE_MEDIAL_AXIS_2_INTERNAL_TRIANGULATE_H
#define CGAL_PROGRESSIVE_MEDIAL_AXIS_2_INTERNAL_TRIANGULATE_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/number_utils.h>
#include <CGAL/Progressive_medial_axis_2/Input_error.h>
#include <CGAL/Progressive_medial_axis_2/internal/Input_conversion.h>
#include <CGAL/Progressive_medial_axis_2/internal/Medial_axis_engine.h>

#include <deque>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Progressive_medial_axes {
namespace internal {

/// A triangle of the decomposition: its vertices (indices of input points,
/// counter-clockwise) and, across edge i (opposite vertex i), the index of
/// the neighbouring triangle inside the polygon, or -1 across the boundary.
struct Triangle {
  int v[3];
  int nbr[3];
};

/// The side of triangle u shared with its neighbour t.
inline int side_towards(const std::vector<Triangle>& triangles, int u, int t)
{
  int e = 0;
  while(triangles[std::size_t(u)].nbr[e] != t) ++e;
  return e;
}

/// Triangulates the polygon whose rings are the point ranges
/// [ring_start[r], ring_start[r+1]) of `points`, consecutive along each ring,
/// in the kernel of the points (with exact predicates): distinct input
/// points stay distinct.
template <class Kernel>
std::vector<Triangle> triangulate_rings(const std::vector<typename Kernel::Point_2>& points,
                                        const std::vector<int>& ring_start, const std::vector<Point_info>& info)
{
  typedef Exact_predicates_kernel_for<Kernel> TK;
  typedef typename TK::type K;
  typedef Triangulation_vertex_base_with_info_2<int, K> Vb;
  typedef Triangulation_face_base_with_info_2<int, K> Fbi;
  typedef Constrained_triangulation_face_base_2<K, Fbi> Fb;
  typedef Triangulation_data_structure_2<Vb, Fb> Tds;
  typedef Constrained_Delaunay_triangulation_2<K, Tds, Exact_predicates_tag> CDT;

  std::vector<std::pair<typename K::Point_2, int> > pts;
  pts.reserve(points.size());
  for(std::size_t i = 0; i < points.size(); ++i)
    pts.emplace_back(TK::point(points[i]), int(i));
  CDT cdt;
  cdt.insert(pts.begin(), pts.end());
  std::vector<typename CDT::Vertex_handle> handle(points.size());
  for(auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v)
    handle[v->info()] = v;
  // input points at one place (where rings touch): the triangulation keeps
  // one of them; the triangles get the corner of their sector below
  std::map<typename CDT::Vertex_handle, std::vector<int> > touching;
  for(std::size_t i = 0; i < points.size(); ++i)
    if(handle[i] == typename CDT::Vertex_handle()) {
      handle[i] = cdt.insert(pts[i].first);
      std::vector<int>& at = touching[handle[i]];
      if(at.empty()) at.push_back(handle[i]->info());
      at.push_back(int(i));
    }
  for(std::size_t r = 0; r + 1 < ring_start.size(); ++r) {
    int b = ring_start[r], e = ring_start[r + 1];
    for(int i = b; i < e; ++i)
      cdt.insert_constraint(handle[i], handle[i + 1 < e ? i + 1 : b]);
  }

  // Nesting level of every face: 0 outside, 1 inside the outer ring, 2 in a hole...
  for(auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f) f->info() = -1;
  std::deque<typename CDT::Face_handle> border;
  auto flood = [&](typename CDT::Face_handle start, int level) {
    if(start->info() != -1) return;
    std::deque<typename CDT::Face_handle> queue;
    queue.push_back(start);
    start->info() = level;
    while(!queue.empty()) {
      auto f = queue.front();
      queue.pop_front();
      for(int i = 0; i < 3; ++i) {
        auto n = f->neighbor(i);
        if(n->info() != -1) continue;
        if(cdt.is_constrained(std::make_pair(f, i))) {
          border.push_back(n);
        } else {
          n->info() = level;
          queue.push_back(n);
        }
      }
    }
  };
  border.push_back(cdt.infinite_face());
  int level = 0;
  while(!border.empty()) {
    std::deque<typename CDT::Face_handle> current;
    current.swap(border);
    for(auto f : current) flood(f, level);
    ++level;
  }

  std::vector<Triangle> tris;
  int count = 0;
  for(auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if(f->info() % 2 == 1) {
      f->info() = -2 - count;   // remember the triangle's index
      ++count;
    }
  }
  tris.resize(count);
  // The corner of the sector of face f at its vertex i, a place where rings
  // touch: turning clockwise about it, the first constrained edge leads to the
  // successor of that corner (see link_touching_corners()).
  auto corner = [&](typename CDT::Face_handle f, int i) {
    const typename CDT::Vertex_handle v = f->vertex(i);
    const std::vector<int>& at = touching.at(v);
    while(!cdt.is_constrained(std::make_pair(f, CDT::cw(i)))) {
      f = f->neighbor(CDT::cw(i));
      i = f->index(v);
    }
    const typename CDT::Vertex_handle w = f->vertex(CDT::ccw(i));
    for(int c : at)
      if(handle[std::size_t(info[std::size_t(c)].next)] == w) return c;
    CGAL_assertion_msg(false, "no corner for the sector");
    return at.front();
  };
  for(auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if(f->info() > -2) continue;
    Triangle& t = tris[-2 - f->info()];
    for(int i = 0; i < 3; ++i) {
      t.v[i] = touching.empty() || !touching.count(f->vertex(i)) ? f->vertex(i)->info() : corner(f, i);
      auto n = f->neighbor(i);
      bool inside = !cdt.is_infinite(n) && n->info() <= -2;
      t.nbr[i] = (inside && !cdt.is_constrained(std::make_pair(f, i))) ? -2 - n->info() : -1;
    }
  }
  return tris;
}

} // namespace internal
} // namespace Progressive_medial_axes
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_MEDIAL_AXIS_2_INTERNAL_TRIANGULATE_H
