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

#ifndef CGAL_DRAW_MEDIAL_AXIS_2_H
#define CGAL_DRAW_MEDIAL_AXIS_2_H

#include <CGAL/license/Progressive_medial_axis_2.h>
#include <CGAL/Progressive_medial_axis_2/Medial_axis_2.h>

#ifdef DOXYGEN_RUNNING
namespace CGAL {

/*!
\ingroup PkgProgressiveMedialAxis2Ref

opens a new window and draws `ma`: the boundary of its shape in black, its
line segments in blue, its parabolic arcs in red and its branch points.  A
call to this function is blocking: the program goes on when the user closes
the window.  This function requires `CGAL_Qt5` (Debian: `libcgal-qt5-dev`),
and is only available if the macro `CGAL_USE_BASIC_VIEWER` is defined;
linking with the cmake target `CGAL::CGAL_Basic_viewer` does both.
*/
template <class K>
void draw(const Medial_axis_2<K>& ma, const char* title = "Medial_axis_2 Basic Viewer");

} // namespace CGAL
#endif

#ifdef CGAL_USE_BASIC_VIEWER

#include <CGAL/version.h>
#include <CGAL/IO/Color.h>

#include <algorithm>
#include <cmath>

#if CGAL_VERSION_NR >= 1060000000
#include <CGAL/Basic_viewer.h>
#include <CGAL/Graphics_scene.h>
#else
#include <CGAL/Qt/Basic_viewer_qt.h>
#include <CGAL/Qt/init_ogl_context.h>
#endif

namespace CGAL {
namespace Progressive_medial_axes {
namespace internal {

// Adds the shape's boundary, the curves (as polylines within a pixel-sized
// tolerance) and the branch points of `ma` to a scene or viewer `s`, which
// has add_segment(p, q, color) and add_point(p, color).
template <class K, class Scene>
void add_medial_axis_to_scene(const Medial_axis_2<K>& ma, Scene& s)
{
  typedef typename K::Point_2 Point;
  typedef Medial_axis_2<K> MA;
  const IO::Color black(0, 0, 0), blue(31, 95, 191), red(192, 57, 43), dark(40, 40, 40);
  double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
  for(const auto& ring : ma.shape_rings()) {
    for(std::size_t i = 0; i < ring.size(); ++i) {
      const Point& p = ma.point(ring[i]);
      const Point& q = ma.point(ring[(i + 1) % ring.size()]);
      s.add_segment(p, q, black);
      const auto xy = MA::to_xy(p);
      x0 = (std::min)(x0, xy.first); x1 = (std::max)(x1, xy.first);
      y0 = (std::min)(y0, xy.second); y1 = (std::max)(y1, xy.second);
    }
  }
  const double tolerance = 1e-3 * std::hypot(x1 - x0, y1 - y0);
  for(const auto& e : ma.edges()) {
    const auto pl = e.polyline(tolerance);
    const IO::Color& c = e.curve_kind() == MA::PARABOLIC_ARC ? red : blue;
    for(std::size_t i = 0; i + 1 < pl.size(); ++i)
      s.add_segment(Point(pl[i].first, pl[i].second), Point(pl[i + 1].first, pl[i + 1].second), c);
  }
  for(const auto& v : ma.vertices())
    if(v.kind() == MA::BRANCH_POINT) s.add_point(v.point(), dark);
}

#if CGAL_VERSION_NR < 1060000000
// The viewer of CGAL 5.x.
template <class K>
class Medial_axis_2_viewer : public Basic_viewer_qt
{
public:
  Medial_axis_2_viewer(QWidget* parent, const Medial_axis_2<K>& ma, const char* title)
    : Basic_viewer_qt(parent, title, true, true, false, false, false), ma_(ma)
  {
    clear();
    add_medial_axis_to_scene(ma_, *this);
  }

private:
  const Medial_axis_2<K>& ma_;
};
#endif

} // namespace internal
} // namespace Progressive_medial_axes

template <class K>
void draw(const Medial_axis_2<K>& ma, const char* title = "Medial_axis_2 Basic Viewer")
{
#if CGAL_VERSION_NR >= 1060000000
  Graphics_scene scene;
  Progressive_medial_axes::internal::add_medial_axis_to_scene(ma, scene);
  draw_graphics_scene(scene, title);
#else
#if defined(CGAL_TEST_SUITE)
  const bool test_suite = true;
#else
  const bool test_suite = qEnvironmentVariableIsSet("CGAL_TEST_SUITE");
#endif
  if(test_suite) return;
  CGAL::Qt::init_ogl_context(4, 3);
  int argc = 1;
  const char* argv[2] = {"medial_axis_2_viewer", nullptr};
  QApplication app(argc, const_cast<char**>(argv));
  Progressive_medial_axes::internal::Medial_axis_2_viewer<K> window(app.activeWindow(), ma, title);
  window.show();
  app.exec();
#endif
}

} // namespace CGAL

#endif // CGAL_USE_BASIC_VIEWER

#endif // CGAL_DRAW_MEDIAL_AXIS_2_H
