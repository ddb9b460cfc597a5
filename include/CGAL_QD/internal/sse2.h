// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_INTERNAL_SSE2_H
#define CGAL_QD_INTERNAL_SSE2_H

// `CGAL_QD_SSE2` is defined where the compiler targets SSE2 (every x86-64
// compiler) but not FMA: the two-lane paths of the ARAP local step and of the
// two-column solves, which give the same bits as their scalar code, are used
// there. Where the compiler may fuse a product and a sum into one rounding
// (`-mfma`, `-march=native` on a processor with FMA: GCC and Clang then
// contract by default), it does not fuse the same operations in the scalar
// code and in the lanes, and the two would part in their last bits; the
// scalar code alone runs there.

#if (defined(__SSE2__) || defined(_M_X64) || (defined(_M_IX86_FP) && _M_IX86_FP >= 2)) && !defined(__FMA__)
#include <emmintrin.h>
#define CGAL_QD_SSE2
#endif

#endif // CGAL_QD_INTERNAL_SSE2_H
