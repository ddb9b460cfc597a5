// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_INTERNAL_ARAP_OPTIMIZER_H
#define CGAL_QD_INTERNAL_ARAP_OPTIMIZER_H

// The local/global as-rigid-as-possible iteration of `optimize_flattening()`
// on a patch given by index arrays: the fixed part (per-face isometric edge
// vectors and cotangents, the factorised global matrix) and the two steps.
//
// The local step gives every face a target linear map. With
// `area_preservation` alpha = 0 it is the rotation closest to the face's
// current map J = U diag(s1, s2) V^T, U V^T (ARAP, Liu et al. 2008); with
// alpha > 0 it is U diag(t, 1 / t) V^T, t = (s1 / s2)^(alpha / 2) (at most
// 2): a map of determinant 1 that keeps a share of J's anisotropy. With
// alpha = 1 the target is area-preserving with J's own aspect ratio; in
// between, the iteration trades a little shear for less area distortion.

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <CGAL_QD/internal/arap_lanes.h>
#include <CGAL_QD/internal/lower_triangle.h>
#include <CGAL_QD/internal/sse2.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL_QD {
namespace internal {

// whether a solver offers `order_of_rows()` and `solve_in_order(y, rows)`
// (see `Simplicial_LDLT_solver`)
template <class Solver, class = void>
struct Solves_in_order : std::false_type
{};
template <class Solver>
struct Solves_in_order<Solver, std::void_t<decltype(std::declval<const Solver&>().order_of_rows()),
                                           decltype(std::declval<const Solver&>().solve_in_order(
                                               std::declval<double*>(), std::size_t()))>> : std::true_type
{};

template <class Solver>
class Arap_optimizer
{
public:
  typedef std::array<double, 2> Vector_2;

  // `tri`: 3 vertex indices per face in [0, nv); `p`: 3D points by vertex;
  // `border_edges`: pairs (i, j) of border edges, with the surface on the left
  // of i -> j, pulled to `border_length` with weight `border_weight` (with
  // KEEP_LENGTHS; 0 otherwise); `area_preservation` in [0, 1]: see above.
  Arap_optimizer(std::size_t nv, const std::vector<std::array<std::size_t, 3>>& tri,
                 const std::vector<std::array<double, 3>>& p, const std::vector<std::array<std::size_t, 2>>& border_edges,
                 const std::vector<double>& border_length, double border_weight, const Solver& solver,
                 double area_preservation = 0.)
      : m_nv(nv), m_tri(tri), m_border(border_edges), m_lambda(border_weight), m_length(border_length),
        m_solver(solver), m_alpha(area_preservation)
  {
    const std::size_t nf = tri.size();
    m_dx.resize(nf);
    m_cot.resize(nf);
    m_kappa.resize(nf);
    m_area = 0;
    for(std::size_t f = 0; f < nf; ++f) {
      const std::array<double, 3>&a = p[tri[f][0]], &b = p[tri[f][1]], &c = p[tri[f][2]];
      const double e1[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, e2[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
      const double l1 = std::sqrt(e1[0] * e1[0] + e1[1] * e1[1] + e1[2] * e1[2]);
      const double d = (e1[0] * e2[0] + e1[1] * e2[1] + e1[2] * e2[2]) / l1;
      const double cx = e1[1] * e2[2] - e1[2] * e2[1], cy = e1[2] * e2[0] - e1[0] * e2[2],
                   cz = e1[0] * e2[1] - e1[1] * e2[0];
      const double h = std::sqrt(cx * cx + cy * cy + cz * cz) / l1;
      // the face laid flat, isometrically
      const std::array<Vector_2, 3> x = {{{0., 0.}, {l1, 0.}, {d, h}}};
      m_area += 0.5 * l1 * h;
      for(int k = 0; k < 3; ++k) {
        const Vector_2&o = x[k], &q = x[(k + 1) % 3], &r = x[(k + 2) % 3];
        const double u[2] = {q[0] - o[0], q[1] - o[1]}, w[2] = {r[0] - o[0], r[1] - o[1]};
        m_cot[f][k] = (u[0] * w[0] + u[1] * w[1]) / std::abs(u[0] * w[1] - u[1] * w[0]);
        m_dx[f][k] = {q[0] - r[0], q[1] - r[1]};
      }
      m_kappa[f] = {l1 * h, l1 * h > 0 ? 1 / (l1 * h) : 0.};  // twice the area
    }
  }

  // Factorises the global matrix; `fixed[i]` marks the vertices that keep
  // their position (the border with FIXED, else one pinned vertex).
  bool factorize(const std::vector<char>& fixed)
  {
    std::vector<long> row(m_nv, -1);  // the row of every vertex that moves
    m_unknowns = 0;
    for(std::size_t i = 0; i < m_nv; ++i)
      if(!fixed[i]) row[i] = static_cast<long>(m_unknowns++);
    if(m_unknowns == 0) return true;
    {
      // freed before the factorisation: 48 bytes a face
      Lower_triangle_assembly t(static_cast<long>(m_unknowns), 3 * m_tri.size() + m_border.size());
      auto add_edge = [&](std::size_t i, std::size_t j, double w) {
        const long ri = row[i], rj = row[j];
        if(ri >= 0) t.add(ri, ri, w);
        if(rj >= 0) t.add(rj, rj, w);
        if(ri >= 0 && rj >= 0) t.add((std::max)(ri, rj), (std::min)(ri, rj), -w);
      };
      for(std::size_t f = 0; f < m_tri.size(); ++f)
        for(int k = 0; k < 3; ++k) add_edge(m_tri[f][(k + 1) % 3], m_tri[f][(k + 2) % 3], m_cot[f][k]);
      if(m_lambda > 0)
        for(const auto& e : m_border) add_edge(e[0], e[1], m_lambda);
      t.assemble(m_matrix);
    }
    const bool ok = m_solver.factorize(m_matrix);
    m_matrix = Eigen::SparseMatrix<double>();  // the solves need only the factor
    // the slot of every vertex's row in the right-hand side of the global
    // step: the factor's own order where the solver solves in it
    const int* order = nullptr;
    if constexpr(Solves_in_order<Solver>::value) {
      if(ok) order = m_solver.order_of_rows();
    }
    m_slot.assign(m_nv, -1);
    for(std::size_t i = 0; i < m_nv; ++i)
      if(row[i] >= 0) m_slot[i] = order ? order[row[i]] : static_cast<int>(row[i]);
    m_face_slot.resize(m_tri.size());
    for(std::size_t f = 0; f < m_tri.size(); ++f)
      for(int k = 0; k < 3; ++k) m_face_slot[f][k] = m_slot[m_tri[f][k]];
    return ok;
  }

  // The target map of every face for `u`, and the energy of `u` with them.
  //
  // For a face with isometric edge vectors dx_k (opposite corner k) and
  // cotangent weights w_k, sum_k w_k dx_k dx_k^T = kappa I with kappa = 2
  // area. The image edges are du_k = J dx_k for the face's linear map J, so
  // M = sum_k w_k du_k dx_k^T = kappa J and the face's energy for a target T
  // is sum_k w_k |du_k - T dx_k|^2 = kappa |J - T|_F^2 = |M - kappa T|_F^2 /
  // kappa: a sum of squares formed from M alone. The first pass gathers `u`
  // into M (kept in the target array); the second finds the targets and the
  // energy without touching `u`, so that the square roots and divisions of
  // neighbouring faces overlap.
  double local_step(const std::vector<Vector_2>& u)
  {
    const std::size_t nf = m_tri.size();
    m_target.resize(nf);
    for(std::size_t f = 0; f < nf; ++f) {
      const std::array<std::size_t, 3>& t = m_tri[f];
      const std::array<Vector_2, 3>& dx = m_dx[f];
      const std::array<double, 3>& w = m_cot[f];
      double a = 0, b = 0, c = 0, d = 0;
      for(int k = 0; k < 3; ++k) {
        const Vector_2 &ui = u[t[(k + 1) % 3]], &uj = u[t[(k + 2) % 3]];
        const double dux = ui[0] - uj[0], duy = ui[1] - uj[1];
        a += w[k] * dux * dx[k][0];
        b += w[k] * dux * dx[k][1];
        c += w[k] * duy * dx[k][0];
        d += w[k] * duy * dx[k][1];
      }
      m_target[f] = {a, b, c, d};
    }
    double energy = 0;
    std::size_t f = 0;
#ifdef CGAL_QD_SSE2
    if(m_two_lanes && (m_alpha == 0 || m_alpha == 0.5 || m_alpha == 1.)) {
      for(; f + 3 < nf; f += 4) energy = arap_targets_in_lanes<2>(m_target, m_kappa, m_alpha, f, energy);
      for(; f + 1 < nf; f += 2) energy = arap_targets_in_lanes<1>(m_target, m_kappa, m_alpha, f, energy);
    }
#endif
    for(; f < nf; ++f) energy += target_and_energy(f);
    return (energy + spring_energy(u)) / m_area;
  }

  // every face's target map from the last `local_step()`, row by row
  const std::vector<std::array<double, 4>>& targets() const { return m_target; }

  // whether `local_step()` may find the targets of two faces at once (where
  // SSE2 is available; the same result, bit for bit)
  void set_two_lanes(bool on) { m_two_lanes = on; }

  // The positions that minimise the energy for the current rotations: the
  // right-hand side is gathered in the slots of `factorize()`, its two
  // columns side by side. A solver that solves in its own order does so in
  // place (no permutation of the right-hand side and of the solution); any
  // other gets the two columns. Each entry receives the same terms in the
  // same order either way, so the positions are the same to the last bit.
  bool global_step(const std::vector<Vector_2>& u, std::vector<Vector_2>& out)
  {
    out.resize(m_nv);
    if(m_unknowns == 0) {
      out = u;
      return true;
    }
    gather_right_hand_side(u);
    typedef Eigen::Matrix<double, Eigen::Dynamic, 2, Eigen::RowMajor> Rows;
    Eigen::Map<Rows> y(m_y.data(), static_cast<Eigen::Index>(m_unknowns), 2);
    if constexpr(Solves_in_order<Solver>::value) {
      if(!m_solver.solve_in_order(m_y.data(), m_unknowns)) return false;
    } else {
      m_rhs = y;  // kept between iterations: no allocation per step
      if(!m_solver.solve(m_rhs, m_solution) || !m_solution.allFinite()) return false;
      y = m_solution;
    }
    for(std::size_t i = 0; i < m_nv; ++i) {
      const int s = m_slot[i];
      out[i] = s >= 0 ? Vector_2{m_y[2 * s], m_y[2 * s + 1]} : u[i];
    }
    return true;
  }

  // whether the face has a positive orientation
  bool positive(std::size_t f, const std::vector<Vector_2>& u) const
  {
    const Vector_2&a = u[m_tri[f][0]], &b = u[m_tri[f][1]], &c = u[m_tri[f][2]];
    return (b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]) > 0;
  }

  bool has_flip(const std::vector<Vector_2>& u) const
  {
    for(std::size_t f = 0; f < m_tri.size(); ++f)
      if(!positive(f, u)) return true;
    return false;
  }

private:
  typedef std::array<double, 4> Matrix_2;  // row by row

  // the right-hand side of the global step for `u` into `m_y`, row by row in the slots
  void gather_right_hand_side(const std::vector<Vector_2>& u)
  {
    m_y.assign(2 * m_unknowns, 0.);
    double* Y = m_y.data();
    // w |(u_i - u_j) - t|^2, with the slots si and sj of i and j (-1 where fixed)
    auto add_edge = [&](int si, int sj, std::size_t i, std::size_t j, double w, double tx, double ty) {
      if(si >= 0) {
        double* y = Y + 2 * si;
        y[0] += w * tx;
        y[1] += w * ty;
        if(sj < 0) {
          y[0] += w * u[j][0];
          y[1] += w * u[j][1];
        }
      }
      if(sj >= 0) {
        double* y = Y + 2 * sj;
        y[0] -= w * tx;
        y[1] -= w * ty;
        if(si < 0) {
          y[0] += w * u[i][0];
          y[1] += w * u[i][1];
        }
      }
    };
    for(std::size_t f = 0; f < m_tri.size(); ++f) {
      const Matrix_2& T = m_target[f];
      const std::array<int, 3>& slot = m_face_slot[f];
      for(int k = 0; k < 3; ++k) {
        const Vector_2& dx = m_dx[f][k];
        const int a = (k + 1) % 3, b = (k + 2) % 3;
        add_edge(slot[a], slot[b], m_tri[f][a], m_tri[f][b], m_cot[f][k], T[0] * dx[0] + T[1] * dx[1],
                 T[2] * dx[0] + T[3] * dx[1]);
      }
    }
    if(m_lambda > 0)
      for(std::size_t e = 0; e < m_border.size(); ++e) {
        const std::size_t i = m_border[e][0], j = m_border[e][1];
        const double dx = u[i][0] - u[j][0], dy = u[i][1] - u[j][1], n = std::sqrt(dx * dx + dy * dy);
        if(n > 0) add_edge(m_slot[i], m_slot[j], i, j, m_lambda, m_length[e] * dx / n, m_length[e] * dy / n);
      }
  }

  // The target of face f from M (held in its target) and the face's energy term.
  double target_and_energy(std::size_t f)
  {
    Matrix_2& T = m_target[f];
    const double a = T[0], b = T[1], c = T[2], d = T[3];
    // M = [[a, b], [c, d]] = q Rot + r Ref (see `target_of_determinant_one`):
    // the closest rotation is Rot
    const double E = (a + d) / 2, F = (a - d) / 2, G = (c + b) / 2, H = (c - b) / 2;
    const double q = std::sqrt(E * E + H * H);
    if(!(m_alpha > 0) || !target_of_determinant_one(E, F, G, H, q, T))
      T = q > 0 ? Matrix_2{E / q, -H / q, H / q, E / q} : Matrix_2{1., 0., 0., 1.};
    const double k = m_kappa[f][0];
    const double ea = a - k * T[0], eb = b - k * T[1], ec = c - k * T[2], ed = d - k * T[3];
    return (ea * ea + eb * eb + ec * ec + ed * ed) * m_kappa[f][1];
  }

  // Sets `T` to the target U diag(t, 1 / t) V^T for the map M = [[a, b],
  // [c, d]] = U diag(s1, s2) V^T, s1 >= |s2|; returns false, leaving `T`
  // alone, where M is flipped or degenerate (s2 <= 0) or a similarity (the
  // target is then the rotation). M is the sum of a similarity and an
  // anti-similarity, q Rot(a2) + r Ref(a1) (Ref(x) = [[cos x, sin x], [sin x,
  // -cos x]]), with s1 = q + r and s2 = q - r; U diag(t, 1 / t) V^T is then
  // (t + 1 / t) / 2 Rot(a2) + (t - 1 / t) / 2 Ref(a1): no angle is formed.
  // Here E = (a + d) / 2, F = (a - d) / 2, G = (c + b) / 2, H = (c - b) / 2
  // and q = |(E, H)|. The factors (t + 1 / t) / (2 q) and (t - 1 / t) / (2 r)
  // share one division: this runs for every face in every iteration, and
  // divisions and square roots are most of its cost.
  bool target_of_determinant_one(double E, double F, double G, double H, double q, Matrix_2& T) const
  {
    const double r = std::sqrt(F * F + G * G);
    const double s1 = q + r, s2 = q - r;
    if(!(s2 > 1e-12 * s1) || !(r > 0)) return false;
    const double t = (std::min)(ratio_power(s1 / s2), 2.);
    const double k = 0.5 / (t * q * r);
    const double p = (t * t + 1) * r * k, m = (t * t - 1) * q * k;
    T = {p * E + m * F, m * G - p * H, p * H + m * G, p * E - m * F};
    return true;
  }

  // x^(alpha / 2): the fourth root for the segmentation's 0.5 and the square
  // root for 1 take a fifth of the time of std::pow
  double ratio_power(double x) const
  {
    if(m_alpha == 0.5) return std::sqrt(std::sqrt(x));
    if(m_alpha == 1.) return std::sqrt(x);
    return std::pow(x, m_alpha / 2);
  }

  // lambda sum (|u_i - u_j| - l)^2 over the border edges pulled to their lengths
  double spring_energy(const std::vector<Vector_2>& u) const
  {
    double e = 0;
    if(m_lambda > 0)
      for(std::size_t k = 0; k < m_border.size(); ++k) {
        const std::size_t i = m_border[k][0], j = m_border[k][1];
        const double d = std::hypot(u[i][0] - u[j][0], u[i][1] - u[j][1]) - m_length[k];
        e += m_lambda * d * d;
      }
    return e;
  }

  std::size_t m_nv;
  const std::vector<std::array<std::size_t, 3>>& m_tri;
  const std::vector<std::array<std::size_t, 2>>& m_border;
  double m_lambda;
  const std::vector<double>& m_length;  // target length of every border edge
  Solver m_solver;
  // per face and corner k: the isometric image of the edge opposite the
  // corner, from corner k + 1 to corner k + 2, and the cotangent of the corner
  std::vector<std::array<Vector_2, 3>> m_dx;
  std::vector<std::array<double, 3>> m_cot;
  // per face: kappa with sum_k cot_k dx_k dx_k^T = kappa I (twice the area), and 1 / kappa
  std::vector<std::array<double, 2>> m_kappa;
  double m_alpha;                  // area preservation
  std::vector<Matrix_2> m_target;  // every face's target map
  bool m_two_lanes = true;
  Eigen::MatrixXd m_rhs, m_solution;  // of the global step, for a solver that takes columns
  // the slot of every vertex's row in the global step's right-hand side (-1
  // where fixed), by vertex and, read once per face in every iteration, by
  // face corner; and that right-hand side, row by row
  std::vector<int> m_slot;
  std::vector<std::array<int, 3>> m_face_slot;
  std::vector<double> m_y;
  std::size_t m_unknowns = 0;
  double m_area = 0;
  Eigen::SparseMatrix<double> m_matrix;
};

} // namespace internal
} // namespace CGAL_QD

#endif // CGAL_QD_INTERNAL_ARAP_OPTIMIZER_H
