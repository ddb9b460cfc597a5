// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_INTERNAL_SSE2_H
#define CGAL_QD_INTERNAL_SSE2_H

// `CGAL_QD_SSE2` is defined where the compiler targets SSE2 (every x86-64
// compiler): the two-lane paths of the ARAP local step and of the two-column
// solves, which give the same bits as their scalar code, are used there.

#if defined(__SSE2__) || defined(_M_X64) || (defined(_M_IX86_FP) && _M_IX86_FP >= 2)
#include <emmintrin.h>
#define CGAL_QD_SSE2
#endif

#endif // CGAL_QD_INTERNAL_SSE2_H
