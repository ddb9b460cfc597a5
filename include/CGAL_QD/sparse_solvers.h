// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_SPARSE_SOLVERS_H
#define CGAL_QD_SPARSE_SOLVERS_H

/// \file sparse_solvers.h
/// The sparse direct solvers of `flatten_patch()` and `optimize_flattening()`:
/// models of their solver concept, `factorize(A)` for the lower triangle of a
/// symmetric matrix, then `solve(B, X)` for a right-hand side of several
/// columns, both returning whether they succeeded, and `name()`.

#include <Eigen/Sparse>
#include <Eigen/OrderingMethods>
#include <Eigen/SparseCholesky>
#ifdef CGAL_QD_USE_CHOLMOD
#include <Eigen/CholmodSupport>
#endif

#include <CGAL_QD/internal/sse2.h>
#include <CGAL_QD/ordering_cache.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <memory>
#include <type_traits>
#include <utility>

namespace CGAL_QD {
namespace internal {

// whether a solver offers `analyzes_ahead(n)` and `analyze(P)` (see
// `Size_adaptive_solver`)
template <class Solver, class = void>
struct Analyzes_ahead : std::false_type
{};
template <class Solver>
struct Analyzes_ahead<Solver, std::void_t<decltype(std::declval<const Solver&>().analyzes_ahead(std::size_t())),
                                          decltype(std::declval<Solver&>().analyze(
                                              std::declval<const Eigen::SparseMatrix<double>&>()))>>
    : std::true_type
{};

template <class EigenSolver>
struct Is_simplicial_LDLT : std::false_type
{};
template <class Matrix, int UpLo, class Ordering>
struct Is_simplicial_LDLT<Eigen::SimplicialLDLT<Matrix, UpLo, Ordering>> : std::true_type
{};

// y = (L D L^T)^-1 y with the factorisation P A P^T = L D L^T of `ldlt`, for
// the two columns of y held row by row (Y[2 i], Y[2 i + 1]) in the order of
// the factorisation (P applied). Every column goes through the same
// operations in the same order as in Eigen's SimplicialLDLT::solve(), so the
// result is the same to the last bit. L must be in compressed storage. With
// SSE2 the two columns share the lanes of one register (a product and a
// difference each, rounded as alone): a sixth to a quarter less time than
// one after the other, measured on grid Laplacians of 5K and 22K unknowns.
template <class Solver>
void solve_ldlt_interleaved(const Solver& ldlt, double* Y)
{
  const auto& L = ldlt.matrixL().nestedExpression();  // strictly lower part, by columns
  const Eigen::Index n = L.cols();
  const auto* outer = L.outerIndexPtr();
  const auto* inner = L.innerIndexPtr();
  const double* value = L.valuePtr();
  const auto& d = ldlt.vectorD();
  // L y = y (Eigen skips a column's updates where its entry is 0; so do we)
  for(Eigen::Index j = 0; j < n; ++j) {
    const double a = Y[2 * j], b = Y[2 * j + 1];
    if(a == 0 && b == 0) continue;
#ifdef CGAL_QD_SSE2
    if(a != 0 && b != 0) {
      // both columns in the two lanes: the same product and difference each
      const __m128d ab = _mm_loadu_pd(Y + 2 * j);
      for(auto p = outer[j], e = outer[j + 1]; p < e; ++p) {
        double* yi = Y + 2 * inner[p];
        _mm_storeu_pd(yi, _mm_sub_pd(_mm_loadu_pd(yi), _mm_mul_pd(ab, _mm_set1_pd(value[p]))));
      }
      continue;
    }
#endif
    for(auto p = outer[j], e = outer[j + 1]; p < e; ++p) {
      double* yi = Y + 2 * inner[p];
      if(a != 0) yi[0] -= a * value[p];
      if(b != 0) yi[1] -= b * value[p];
    }
  }
  // D y = y
  for(Eigen::Index i = 0; i < n; ++i) {
    const double inverse = 1. / d[i];
    Y[2 * i] = inverse * Y[2 * i];
    Y[2 * i + 1] = inverse * Y[2 * i + 1];
  }
  // L^T y = y
  for(Eigen::Index j = n - 1; j >= 0; --j) {
#ifdef CGAL_QD_SSE2
    __m128d ab = _mm_loadu_pd(Y + 2 * j);
    for(auto p = outer[j], e = outer[j + 1]; p < e; ++p)
      ab = _mm_sub_pd(ab, _mm_mul_pd(_mm_set1_pd(value[p]), _mm_loadu_pd(Y + 2 * inner[p])));
    _mm_storeu_pd(Y + 2 * j, ab);
#else
    double a = Y[2 * j], b = Y[2 * j + 1];
    for(auto p = outer[j], e = outer[j + 1]; p < e; ++p) {
      const double* yi = Y + 2 * inner[p];
      a -= value[p] * yi[0];
      b -= value[p] * yi[1];
    }
    Y[2 * j] = a;
    Y[2 * j + 1] = b;
#endif
  }
}

// X = A^-1 B with the factorisation of `ldlt`. A B of two columns (the u and
// v of a flattening) is solved in one pass over L for each triangular solve
// (`solve_ldlt_interleaved()`), where Eigen makes one per column; X is the
// same to the last bit. Any other B, or an L not in compressed storage, goes
// to Eigen's solve().
template <class Solver>
void solve_ldlt_columns(const Solver& ldlt, const Eigen::MatrixXd& B, Eigen::MatrixXd& X)
{
  if(B.cols() != 2 || ldlt.matrixL().nestedExpression().innerNonZeroPtr()) {
    X = ldlt.solve(B);
    return;
  }
  // the two columns of a row side by side
  Eigen::Matrix<double, Eigen::Dynamic, 2, Eigen::RowMajor> y;
  if(ldlt.permutationP().size() > 0) y = ldlt.permutationP() * B;
  else y = B;  // natural ordering
  solve_ldlt_interleaved(ldlt, y.data());
  if(ldlt.permutationPinv().size() > 0) X = ldlt.permutationPinv() * y;
  else X = y;
}

} // namespace internal

/// \ingroup PkgCGAL_QDRef
/// A sparse direct solver of symmetric systems for `flatten_patch()`, wrapping
/// an Eigen solver that reads the lower triangle (`SimplicialLDLT`,
/// `SimplicialLLT`, `CholmodSupernodalLLT`, `CholmodDecomposition`, ...).
/// A model of the solver concept of `flatten_patch()`: `factorize(A)` then
/// `solve(B, X)` for a matrix `B` with several columns, both returning whether
/// they succeeded, and `name()`.
template <class EigenSolver>
class Eigen_symmetric_solver
{
public:
  typedef Eigen::SparseMatrix<double> Matrix;
  explicit Eigen_symmetric_solver(const char* name) : m_name(name) {}
  /// copies the configuration, not a factorisation (Eigen's solvers are not all copyable)
  Eigen_symmetric_solver(const Eigen_symmetric_solver& other) : m_name(other.m_name) {}
  Eigen_symmetric_solver& operator=(const Eigen_symmetric_solver& other)
  {
    m_solver.reset();
    m_name = other.m_name;
    return *this;
  }
  bool factorize(const Matrix& lower)
  {
    m_solver.reset(new EigenSolver);
    m_solver->compute(lower);
    return m_solver->info() == Eigen::Success;
  }
  bool solve(const Eigen::MatrixXd& B, Eigen::MatrixXd& X)
  {
    if(!m_solver) return false;
    if constexpr(internal::Is_simplicial_LDLT<EigenSolver>::value) {
      if(m_solver->info() != Eigen::Success || m_solver->rows() != B.rows()) return false;
      internal::solve_ldlt_columns(*m_solver, B, X);
    } else {
      X = m_solver->solve(B);
    }
    return m_solver->info() == Eigen::Success && X.allFinite();
  }
  const char* name() const { return m_name; }

protected:
  const EigenSolver* eigen_solver() const { return m_solver.get(); }

private:
  std::unique_ptr<EigenSolver> m_solver;
  const char* m_name;
};

namespace internal {

// Eigen's `SimplicialLDLT` with the fill-reducing ordering `Ordering`, and
// its two-column solves in the order of the factorisation
template <class Ordering>
class Simplicial_LDLT_base
    : public Eigen_symmetric_solver<Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower, Ordering>>
{
  typedef Eigen_symmetric_solver<Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower, Ordering>> Base;

public:
  explicit Simplicial_LDLT_base(const char* name) : Base(name) {}

  /// after a successful `factorize()`: the position in the factorisation's
  /// order of every row of the matrix (its fill-reducing permutation), or
  /// `nullptr` where that order is the matrix's own
  const int* order_of_rows() const
  {
    const auto* s = this->eigen_solver();
    return s && s->permutationP().size() > 0 ? s->permutationP().indices().data() : nullptr;
  }

  /// solves for two right-hand sides at once, in place: `y` holds them row
  /// by row (y[2 k] and y[2 k + 1] for the row at position k of the order of
  /// `order_of_rows()`), and receives the solutions in the same layout. The
  /// same numbers, to the last bit, as `solve()` of the two columns, without
  /// permuting them; returns false without a factorisation of that size
  /// or where a solution is not finite.
  bool solve_in_order(double* y, std::size_t rows) const
  {
    const auto* s = this->eigen_solver();
    if(!s || s->info() != Eigen::Success || static_cast<std::size_t>(s->rows()) != rows ||
       s->matrixL().nestedExpression().innerNonZeroPtr())
      return false;
    solve_ldlt_interleaved(*s, y);
    for(std::size_t k = 0; k < 2 * rows; ++k)
      if(!std::isfinite(y[k])) return false;
    return true;
  }
};

} // namespace internal

/// \ingroup PkgCGAL_QDRef
/// Eigen's `SimplicialLDLT` with AMD ordering. Given an `Ordering_cache`
/// (shared by its copies), a pattern already ordered through that cache takes
/// its ordering from it: the same factorisation, without computing the
/// ordering again. Its two-column solves can run in the order of the
/// factorisation (`order_of_rows()`, `solve_in_order()`).
struct Simplicial_LDLT_solver : internal::Simplicial_LDLT_base<internal::Cached_AMD_ordering<int>>
{
  Simplicial_LDLT_solver() : Simplicial_LDLT_base("SimplicialLDLT") {}
  explicit Simplicial_LDLT_solver(std::shared_ptr<Ordering_cache> orderings)
      : Simplicial_LDLT_base("SimplicialLDLT"), m_orderings(std::move(orderings))
  {}
  bool factorize(const Matrix& lower)
  {
    const internal::Ordering_cache_scope scope(m_orderings.get());
    return Simplicial_LDLT_base::factorize(lower);
  }

private:
  std::shared_ptr<Ordering_cache> m_orderings;
};

/// \ingroup PkgCGAL_QDRef
/// Eigen's `SimplicialLDLT` factorising the rows in the matrix's own order,
/// for systems whose unknowns already come in a fill-reducing order: the
/// segmentation numbers the vertices of a chart in the AMD order of the
/// chart's graph, and the systems of its flattening
/// (the interior vertices) and of its optimisation (all vertices but one)
/// then both take their order from that one ordering.
struct Simplicial_LDLT_natural_solver : internal::Simplicial_LDLT_base<Eigen::NaturalOrdering<int>>
{
  Simplicial_LDLT_natural_solver() : Simplicial_LDLT_base("SimplicialLDLT, rows in their order") {}
};

#ifdef CGAL_QD_USE_CHOLMOD
/// \ingroup PkgCGAL_QDRef
/// SuiteSparse's CHOLMOD (it chooses simplicial or supernodal), available when
/// CMake found it (`CGAL_QD_USE_CHOLMOD` is then defined).
struct Cholmod_solver
    : Eigen_symmetric_solver<Eigen::CholmodDecomposition<Eigen::SparseMatrix<double>, Eigen::Lower>>
{
  Cholmod_solver() : Eigen_symmetric_solver("CHOLMOD") {}
};

/// \ingroup PkgCGAL_QDRef
/// SuiteSparse's supernodal Cholesky factorisation with the AMD ordering alone
/// (CHOLMOD's default would also weigh other orderings), available when CMake
/// found CHOLMOD. Its dense blocks go to BLAS, which may run them on several
/// threads (OpenBLAS: `OPENBLAS_NUM_THREADS`). The matrix must be positive
/// definite: `factorize()` returns false, and prints nothing, where it is not.
///
/// Besides the solver concept of `flatten_patch()` it offers
/// `analyzes_ahead(n)` (true) and `analyze(P)`: the
/// symbolic analysis (the ordering and the structure of the factor) of a
/// matrix with the pattern of `P`, which `factorize(A)` then uses if `A` has
/// exactly that pattern (and otherwise analyses `A` itself). `flatten_patch()`
/// runs it on a second thread while it computes the border and the weights.
class Cholmod_supernodal_solver
{
public:
  typedef Eigen::SparseMatrix<double> Matrix;
  Cholmod_supernodal_solver() {}
  /// copies nothing: a copy has no analysis and no factorisation
  Cholmod_supernodal_solver(const Cholmod_supernodal_solver&) {}
  Cholmod_supernodal_solver& operator=(const Cholmod_supernodal_solver&)
  {
    m_solver.reset();
    m_pattern = Matrix();
    return *this;
  }
  /// `flatten_patch()` runs `analyze()` ahead for every size
  bool analyzes_ahead(std::size_t) const { return true; }
  bool analyze(const Matrix& lower_pattern)
  {
    make();
    m_solver->analyzePattern(lower_pattern);
    if(m_solver->info() != Eigen::Success) {
      m_solver.reset();
      return false;
    }
    m_pattern = lower_pattern;
    m_pattern.makeCompressed();
    return true;
  }
  bool factorize(const Matrix& lower)
  {
    if(m_solver && same_pattern(lower)) {
      m_solver->factorize(lower);
    } else {
      make();
      m_solver->compute(lower);
    }
    m_pattern = Matrix();
    return m_solver->info() == Eigen::Success;
  }
  bool solve(const Eigen::MatrixXd& B, Eigen::MatrixXd& X)
  {
    if(!m_solver || m_solver->info() != Eigen::Success || m_solver->rows() != B.rows()) return false;
    X = m_solver->solve(B);
    return m_solver->info() == Eigen::Success && X.allFinite();
  }
  const char* name() const { return "CHOLMOD supernodal"; }

private:
  typedef Eigen::CholmodSupernodalLLT<Matrix, Eigen::Lower> Factorization;

  void make()
  {
    m_solver.reset(new Factorization);
    cholmod_common& c = m_solver->cholmod();
    c.nmethods = 1;
    c.method[0].ordering = CHOLMOD_AMD;
    c.supernodal = CHOLMOD_SUPERNODAL;
    c.quick_return_if_not_posdef = 1;
    c.print = 0;  // a failure is reported by the return value, not on standard output
  }

  // whether `A` has the pattern of the last `analyze()`
  bool same_pattern(const Matrix& A) const
  {
    if(A.rows() != m_pattern.rows() || A.cols() != m_pattern.cols() || A.nonZeros() != m_pattern.nonZeros() ||
       !A.isCompressed() || m_pattern.nonZeros() == 0)
      return false;
    const auto cols = static_cast<std::size_t>(A.cols()), nnz = static_cast<std::size_t>(A.nonZeros());
    return std::equal(A.outerIndexPtr(), A.outerIndexPtr() + cols + 1, m_pattern.outerIndexPtr()) &&
           std::equal(A.innerIndexPtr(), A.innerIndexPtr() + nnz, m_pattern.innerIndexPtr());
  }

  std::unique_ptr<Factorization> m_solver;
  Matrix m_pattern;  // of the last analysis, until the next factorisation
};
#endif

/// \ingroup PkgCGAL_QDRef
/// The default solver of `flatten_patch()`: `Simplicial_LDLT_solver` below
/// `supernodal_threshold` unknowns, and above it `Cholmod_supernodal_solver`
/// where CMake found CHOLMOD, with `Simplicial_LDLT_solver` again if that
/// factorisation fails (a matrix that is not positive definite). On a
/// 442K-face patch (220K unknowns) the supernodal factorisation takes about
/// 0.55 s on two cores against 0.93 s for SimplicialLDLT; at 80K unknowns the
/// two are even, and below, the simplicial factorisation is faster
/// (`doc/performance.md`). The default threshold is 100,000 unknowns.
/// `name()` names the solver of the last factorisation.
///
/// `analyzes_ahead(n)` tells whether `analyze(P)` does anything for a system
/// of up to `n` unknowns: the symbolic analysis of the supernodal
/// factorisation, for a pattern of at least `supernodal_threshold` rows.
class Size_adaptive_solver
{
public:
  typedef Eigen::SparseMatrix<double> Matrix;
  static constexpr std::size_t default_supernodal_threshold = 100000;
  explicit Size_adaptive_solver(std::size_t supernodal_threshold = default_supernodal_threshold)
      : m_threshold(supernodal_threshold)
  {}
  /// copies the threshold, not an analysis or a factorisation
  Size_adaptive_solver(const Size_adaptive_solver& other) : m_threshold(other.m_threshold) {}
  Size_adaptive_solver& operator=(const Size_adaptive_solver& other)
  {
    m_threshold = other.m_threshold;
    m_supernodal = false;
    m_ldlt = Simplicial_LDLT_solver();
#ifdef CGAL_QD_USE_CHOLMOD
    m_cholmod = Cholmod_supernodal_solver();
#endif
    return *this;
  }
  bool analyzes_ahead(std::size_t unknowns) const
  {
#ifdef CGAL_QD_USE_CHOLMOD
    return unknowns >= m_threshold;
#else
    (void)unknowns;
    return false;
#endif
  }
  bool analyze(const Matrix& lower_pattern)
  {
#ifdef CGAL_QD_USE_CHOLMOD
    if(static_cast<std::size_t>(lower_pattern.rows()) >= m_threshold) return m_cholmod.analyze(lower_pattern);
#else
    (void)lower_pattern;
#endif
    return false;
  }
  bool factorize(const Matrix& lower)
  {
    m_supernodal = false;
#ifdef CGAL_QD_USE_CHOLMOD
    if(static_cast<std::size_t>(lower.rows()) >= m_threshold) {
      m_supernodal = m_cholmod.factorize(lower);
      if(m_supernodal) return true;
      m_cholmod = Cholmod_supernodal_solver();  // its memory freed before the next try
    }
#endif
    return m_ldlt.factorize(lower);
  }
  bool solve(const Eigen::MatrixXd& B, Eigen::MatrixXd& X)
  {
#ifdef CGAL_QD_USE_CHOLMOD
    if(m_supernodal) return m_cholmod.solve(B, X);
#endif
    return m_ldlt.solve(B, X);
  }
  const char* name() const
  {
#ifdef CGAL_QD_USE_CHOLMOD
    if(m_supernodal) return m_cholmod.name();
#endif
    return m_ldlt.name();
  }
  std::size_t supernodal_threshold() const { return m_threshold; }

private:
  std::size_t m_threshold;
  bool m_supernodal = false;
  Simplicial_LDLT_solver m_ldlt;
#ifdef CGAL_QD_USE_CHOLMOD
  Cholmod_supernodal_solver m_cholmod;
#endif
};

/// \ingroup PkgCGAL_QDRef
/// the default solver of `flatten_patch()`: `Size_adaptive_solver` with its
/// default threshold.
typedef Size_adaptive_solver Default_flattening_solver;

} // namespace CGAL_QD

#endif // CGAL_QD_SPARSE_SOLVERS_H
