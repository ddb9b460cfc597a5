// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_INTERNAL_ARAP_LANES_H
#define CGAL_QD_INTERNAL_ARAP_LANES_H

// The SSE2 path of the ARAP iteration's local step (arap_optimizer.h): the
// targets of two faces at a time in the lanes of a register. Each lane forms
// the same products and sums as the scalar code, in the same order, so the
// results are the same to the last bit (a test compares both codes). Only
// where `CGAL_QD_SSE2` is defined (internal/sse2.h).

#include <CGAL_QD/internal/sse2.h>

#ifdef CGAL_QD_SSE2

#include <array>
#include <cstddef>
#include <vector>

namespace CGAL_QD {
namespace internal {

// mask ? x : y, lane by lane
inline __m128d arap_blend(__m128d mask, __m128d x, __m128d y)
{
  return _mm_or_pd(_mm_and_pd(mask, x), _mm_andnot_pd(mask, y));
}

// `Arap_optimizer::target_and_energy()` for the 2 P faces from f on
// (`target` holds their M on entry, their targets on return; `kappa_of` their
// kappa and 1 / kappa), two at a time in SSE2 lanes: the same operations in
// the same order, so the same bits (the square roots and divisions, most of
// the cost, run two at a time); the energy terms are added to `energy` face
// after face. With P = 2 the two pairs go through each stage side by side,
// so that the processor works on one pair's chain of square roots and
// divisions while the other's waits. The rotation, the target where a face is
// flipped, degenerate or a similarity, is formed only where a face of the
// group needs it. For alpha 0, 0.5 or 1.
template <int P>
inline double arap_targets_in_lanes(std::vector<std::array<double, 4>>& target,
                                    const std::vector<std::array<double, 2>>& kappa_of, double alpha, std::size_t f,
                                    double energy)
{
  __m128d a[P], b[P], c[P], d[P], E[P], F[P], G[P], H[P], q[P], t0[P], t1[P], t2[P], t3[P], ok[P];
  const __m128d half = _mm_set1_pd(0.5), one = _mm_set1_pd(1.), zero = _mm_setzero_pd();
  for(int j = 0; j < P; ++j) {
    const double* T0 = target[f + 2 * j].data();
    const double* T1 = target[f + 2 * j + 1].data();
    const __m128d ab0 = _mm_loadu_pd(T0), ab1 = _mm_loadu_pd(T1);
    const __m128d cd0 = _mm_loadu_pd(T0 + 2), cd1 = _mm_loadu_pd(T1 + 2);
    a[j] = _mm_unpacklo_pd(ab0, ab1);
    b[j] = _mm_unpackhi_pd(ab0, ab1);
    c[j] = _mm_unpacklo_pd(cd0, cd1);
    d[j] = _mm_unpackhi_pd(cd0, cd1);
    // x / 2 and x * 0.5 are the same number
    E[j] = _mm_mul_pd(_mm_add_pd(a[j], d[j]), half);
    F[j] = _mm_mul_pd(_mm_sub_pd(a[j], d[j]), half);
    G[j] = _mm_mul_pd(_mm_add_pd(c[j], b[j]), half);
    H[j] = _mm_mul_pd(_mm_sub_pd(c[j], b[j]), half);
    q[j] = _mm_sqrt_pd(_mm_add_pd(_mm_mul_pd(E[j], E[j]), _mm_mul_pd(H[j], H[j])));
    ok[j] = t0[j] = t1[j] = t2[j] = t3[j] = zero;
  }
  int all_ok = 0;  // a bit per lane of every pair where the target is of determinant one
  if(alpha > 0) {
    __m128d r[P], s1[P], s2[P], t[P];
    for(int j = 0; j < P; ++j) {
      r[j] = _mm_sqrt_pd(_mm_add_pd(_mm_mul_pd(F[j], F[j]), _mm_mul_pd(G[j], G[j])));
      s1[j] = _mm_add_pd(q[j], r[j]);
      s2[j] = _mm_sub_pd(q[j], r[j]);
      ok[j] = _mm_and_pd(_mm_cmpgt_pd(s2[j], _mm_mul_pd(_mm_set1_pd(1e-12), s1[j])), _mm_cmpgt_pd(r[j], zero));
      all_ok |= _mm_movemask_pd(ok[j]) << (2 * j);
    }
    if(all_ok != 0) {
      for(int j = 0; j < P; ++j) t[j] = _mm_div_pd(s1[j], s2[j]);
      for(int j = 0; j < P; ++j) t[j] = _mm_sqrt_pd(t[j]);
      if(alpha != 1.)
        for(int j = 0; j < P; ++j) t[j] = _mm_sqrt_pd(t[j]);
      for(int j = 0; j < P; ++j) {
        t[j] = _mm_min_pd(t[j], _mm_set1_pd(2.));
        const __m128d k = _mm_div_pd(half, _mm_mul_pd(_mm_mul_pd(t[j], q[j]), r[j]));
        const __m128d tt = _mm_mul_pd(t[j], t[j]);
        const __m128d p = _mm_mul_pd(_mm_mul_pd(_mm_add_pd(tt, one), r[j]), k);
        const __m128d m = _mm_mul_pd(_mm_mul_pd(_mm_sub_pd(tt, one), q[j]), k);
        t0[j] = _mm_add_pd(_mm_mul_pd(p, E[j]), _mm_mul_pd(m, F[j]));
        t1[j] = _mm_sub_pd(_mm_mul_pd(m, G[j]), _mm_mul_pd(p, H[j]));
        t2[j] = _mm_add_pd(_mm_mul_pd(p, H[j]), _mm_mul_pd(m, G[j]));
        t3[j] = _mm_sub_pd(_mm_mul_pd(p, E[j]), _mm_mul_pd(m, F[j]));
      }
    }
  }
  if(all_ok != (1 << (2 * P)) - 1)
    for(int j = 0; j < P; ++j) {
      // the rotation, or the identity where q is 0; kept where the target
      // of determinant one is not
      const __m128d q_positive = _mm_cmpgt_pd(q[j], zero);
      const __m128d Eq = _mm_div_pd(E[j], q[j]), Hq = _mm_div_pd(H[j], q[j]);
      const __m128d minus_Hq = _mm_xor_pd(Hq, _mm_set1_pd(-0.));
      const __m128d r0 = arap_blend(q_positive, Eq, one), r1 = arap_blend(q_positive, minus_Hq, zero);
      const __m128d r2 = arap_blend(q_positive, Hq, zero);
      t0[j] = arap_blend(ok[j], t0[j], r0);
      t1[j] = arap_blend(ok[j], t1[j], r1);
      t2[j] = arap_blend(ok[j], t2[j], r2);
      t3[j] = arap_blend(ok[j], t3[j], r0);
    }
  for(int j = 0; j < P; ++j) {
    double* T0 = target[f + 2 * j].data();
    double* T1 = target[f + 2 * j + 1].data();
    _mm_storeu_pd(T0, _mm_unpacklo_pd(t0[j], t1[j]));
    _mm_storeu_pd(T1, _mm_unpackhi_pd(t0[j], t1[j]));
    _mm_storeu_pd(T0 + 2, _mm_unpacklo_pd(t2[j], t3[j]));
    _mm_storeu_pd(T1 + 2, _mm_unpackhi_pd(t2[j], t3[j]));
    // the energy terms
    const __m128d kk0 = _mm_loadu_pd(kappa_of[f + 2 * j].data());
    const __m128d kk1 = _mm_loadu_pd(kappa_of[f + 2 * j + 1].data());
    const __m128d kappa = _mm_unpacklo_pd(kk0, kk1), inverse = _mm_unpackhi_pd(kk0, kk1);
    const __m128d ea = _mm_sub_pd(a[j], _mm_mul_pd(kappa, t0[j])), eb = _mm_sub_pd(b[j], _mm_mul_pd(kappa, t1[j]));
    const __m128d ec = _mm_sub_pd(c[j], _mm_mul_pd(kappa, t2[j])), ed = _mm_sub_pd(d[j], _mm_mul_pd(kappa, t3[j]));
    const __m128d sum = _mm_add_pd(
        _mm_add_pd(_mm_add_pd(_mm_mul_pd(ea, ea), _mm_mul_pd(eb, eb)), _mm_mul_pd(ec, ec)), _mm_mul_pd(ed, ed));
    const __m128d e = _mm_mul_pd(sum, inverse);
    energy += _mm_cvtsd_f64(e);
    energy += _mm_cvtsd_f64(_mm_unpackhi_pd(e, e));
  }
  return energy;
}

} // namespace internal
} // namespace CGAL_QD

#endif // CGAL_QD_SSE2

#endif // CGAL_QD_INTERNAL_ARAP_LANES_H
