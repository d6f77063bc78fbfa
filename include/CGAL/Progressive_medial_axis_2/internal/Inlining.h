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
// Inlining hints for the hot paths of the merge and the traits.

#ifndef CGAL_PROGRESSIVE_MEDIAL_AXIS_2_INTERNAL_INLINING_H
#define CGAL_PROGRESSIVE_MEDIAL_AXIS_2_INTERNAL_INLINING_H

/// Marks a function the compiler must not inline (a rare path of a small,
/// hot function).
#ifndef CGAL_PMA2_NOINLINE
#if defined(__GNUC__)
#define CGAL_PMA2_NOINLINE __attribute__((noinline))
#elif defined(_MSC_VER)
#define CGAL_PMA2_NOINLINE __declspec(noinline)
#else
#define CGAL_PMA2_NOINLINE
#endif
#endif
/// Marks a tiny function the compiler must inline even into the merge's
/// large functions, where its size limits stop inlining.
#ifndef CGAL_PMA2_ALWAYS_INLINE
#if defined(__GNUC__)
#define CGAL_PMA2_ALWAYS_INLINE inline __attribute__((always_inline))
#elif defined(_MSC_VER)
#define CGAL_PMA2_ALWAYS_INLINE __forceinline
#else
#define CGAL_PMA2_ALWAYS_INLINE inline
#endif
#endif

#endif // CGAL_PROGRESSIVE_MEDIAL_AXIS_2_INTERNAL_INLINING_H
