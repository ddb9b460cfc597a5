// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#define BOOST_TEST_MODULE flatten_patch
#include <boost/test/unit_test.hpp>
#include <boost/mpl/list.hpp>

#include "mesh_generators.h"
#include "test_utils.h"

#include <CGAL_QD/LPFB_border_parameterizer_3.h>
#include <CGAL_QD/distortion.h>
#include <CGAL_QD/flatten_patch.h>
#include <CGAL_QD/optimize_flattening.h>
#include <CGAL_QD/internal/amd_order_of_triangles.h>
#include <CGAL_QD/internal/arap_optimizer.h>
#include <CGAL_QD/internal/lower_triangle.h>

#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_conformal_map_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <memory>
#include <random>

namespace QD = CGAL_QD;
namespace SMP = CGAL::Surface_mesh_parameterization;
using namespace qd_test;

typedef boost::mpl::list<Surface_mesh, Polyhedron, Cartesian_surface_mesh> Mesh_types;

namespace {

template <class Mesh>
struct Flattened
{
  QD::Flattening_result result;
  QD::Distortion_report<Mesh> report;
  Uv_store<Mesh> uv;
};

template <class Mesh, class NP = CGAL::parameters::Default_named_parameters>
Flattened<Mesh> flatten(const Mesh& tm, const NP& np = CGAL::parameters::default_values())
{
  Flattened<Mesh> f;
  f.result = QD::flatten_patch(tm, f.uv.pmap(), np);
  BOOST_REQUIRE_MESSAGE(f.result, QD::error_message(f.result.status));
  BOOST_REQUIRE(f.uv.map.size() == f.result.number_of_vertices);
  f.report = QD::compute_distortion(tm, f.uv.pmap_const());
  BOOST_REQUIRE(f.report);
  return f;
}

// z = 0.3 sin(x): rulings along y, the grid's cells are planar rectangles
Soup sine_sheet() { return grid(30, 10, [](double u, double v) { return P3{4 * u, 2 * v, 0.3 * std::sin(4 * u)}; }); }

} // namespace

BOOST_AUTO_TEST_CASE_TEMPLATE(developable_patches_flatten_exactly, Mesh, Mesh_types)
{
  const std::vector<Soup> soups = {grid(24, 8, cylinder(1.0, 1.5 * pi, 2.0)), grid(24, 8, cone(0.5, 1.5, 1.6 * pi, 1.0)),
                                   grid(12, 12, [](double u, double v) { return P3{u + 0.2 * v * v, v, 0}; }),
                                   sine_sheet()};
  for(const Soup& s : soups) {
    const Mesh tm = make<Mesh>(s);
    const auto f = flatten(tm);
    BOOST_TEST(f.result.border.iterations <= 1u);
    BOOST_TEST(f.report.area_distortion < 1e-6);
    BOOST_TEST(std::abs(f.report.l2_stretch - 1) < 1e-6);
    BOOST_TEST(f.report.boundary_length_error < 1e-12);
    BOOST_TEST(f.report.flipped_faces == 0u);
    BOOST_TEST(!f.report.overlap);
  }
}

BOOST_AUTO_TEST_CASE(hemisphere_area_distortion_is_half)
{
  // the equator (length 2 pi) becomes a circle of radius 1: area pi against 2 pi
  double previous = 100;
  for(std::size_t n : {24, 48, 96}) {
    const Surface_mesh tm = make<Surface_mesh>(polar(n / 2, n, sphere_cap(0.5 * pi)));
    const auto f = flatten(tm);
    BOOST_TEST_MESSAGE("hemisphere " << num_faces(tm) << " faces: A = " << f.report.area_distortion << " %");
    BOOST_TEST(std::abs(f.report.area_distortion - 50) < 3);
    BOOST_TEST(std::abs(f.report.area_distortion - 50) <= previous + 1e-9);  // converges with refinement
    previous = std::abs(f.report.area_distortion - 50);
    BOOST_TEST(!f.report.overlap);
  }
}

BOOST_AUTO_TEST_CASE(cube_versus_noisy_cylinder)
{
  // the paper's Fig. 1: LPFB+IP amplifies the distortion of a non-developable
  // patch and keeps a quasi-developable one almost isometric
  const Surface_mesh cube = make<Surface_mesh>(cube_opened_by_five_cuts(12));
  const auto fc = flatten(cube);
  BOOST_TEST_MESSAGE("cube: A = " << fc.report.area_distortion << " %, L2 = " << fc.report.l2_stretch
                                  << ", flips " << fc.report.flipped_faces << ", iterations "
                                  << fc.result.border.iterations);
  BOOST_TEST(fc.result.border.number_of_loops == 1u);
  BOOST_TEST(fc.report.area_distortion > 30);
  BOOST_TEST(fc.report.l2_stretch > 1.5);  // 1.509 for this cut, at every resolution from 192 to 6,912 faces

  Soup noisy = grid(40, 20, cylinder(1.0, 1.5 * pi, 2.0));
  for(std::size_t k : {5 * 41 + 7, 9 * 41 + 20, 14 * 41 + 31, 11 * 41 + 12, 6 * 41 + 28}) {
    P3& p = noisy.points[k];  // small radial spikes at interior vertices
    const double r = std::hypot(p[0], p[1]);
    p[0] *= (r + 0.05) / r;
    p[1] *= (r + 0.05) / r;
  }
  const Surface_mesh cyl = make<Surface_mesh>(noisy);
  const auto fn = flatten(cyl);
  BOOST_TEST_MESSAGE("noisy cylinder: A = " << fn.report.area_distortion << " %, L2 = " << fn.report.l2_stretch);
  BOOST_TEST(fn.report.area_distortion < 2);
  BOOST_TEST(fn.report.l2_stretch < 1.05);
  BOOST_TEST(!fn.report.overlap);
}

BOOST_AUTO_TEST_CASE_TEMPLATE(patch_with_two_holes, Mesh, Mesh_types)
{
  const Mesh tm = make<Mesh>(grid(24, 24, bump(0.3), holes({{4, 8, 5, 9}, {14, 19, 12, 16}})));
  const auto f = flatten(tm);
  BOOST_TEST(f.result.border.number_of_loops == 3u);
  BOOST_TEST(f.result.border.coincidence_error < 1e-10);  // every hole closes up
  BOOST_TEST(f.report.boundary_length_error < 1e-10);     // on every loop
  BOOST_TEST(std::isfinite(f.report.area_distortion));
  BOOST_TEST(std::isfinite(f.report.l2_stretch));
  BOOST_TEST(!f.report.overlap);
  BOOST_TEST(f.result.number_of_interior_vertices + f.result.number_of_border_vertices ==
             f.result.number_of_vertices);
}

BOOST_AUTO_TEST_CASE(same_uvs_as_cgal_parameterize_with_the_lpfb_border)
{
  Surface_mesh tm = make<Surface_mesh>(grid(20, 20, bump(0.35)));
  const auto f = flatten(tm);
  Uv_store<Surface_mesh> cgal;
  SMP::Discrete_conformal_map_parameterizer_3<Surface_mesh, QD::LPFB_border_parameterizer_3<Surface_mesh>> p;
  BOOST_REQUIRE(SMP::parameterize(tm, p, CGAL::Polygon_mesh_processing::longest_border(tm).first, cgal.pmap()) ==
                SMP::OK);
  double worst = 0;
  for(auto v : vertices(tm))
    worst = (std::max)(worst, std::hypot(f.uv.at(v)[0] - cgal.at(v)[0], f.uv.at(v)[1] - cgal.at(v)[1]));
  BOOST_TEST(worst < 1e-6);  // CGAL solves iteratively (BiCGSTAB)
}

BOOST_AUTO_TEST_CASE(stage_times_and_sizes)
{
  const Surface_mesh tm = make<Surface_mesh>(grid(30, 30, bump(0.3)));
  const auto f = flatten(tm);
  BOOST_TEST(f.result.number_of_faces == num_faces(tm));
  BOOST_TEST(f.result.number_of_border_vertices == 120u);
  BOOST_TEST(f.result.number_of_interior_vertices == 29u * 29u);
  // lower triangle: diagonal plus one entry per interior edge
  BOOST_TEST(f.result.number_of_nonzeros > f.result.number_of_interior_vertices);
  BOOST_TEST(f.result.time_border_ms >= 0);
  BOOST_TEST(f.result.time_total_ms >= f.result.time_border_ms);
  BOOST_TEST(f.result.time_total_ms >= f.result.time_factorization_ms + f.result.time_solve_ms);
  BOOST_TEST(!f.result.used_fallback);
  BOOST_TEST(!f.result.solver.empty());
}

namespace {
// a solver that always fails to factorise
struct Failing_solver
{
  bool factorize(const Eigen::SparseMatrix<double>&) { return false; }
  bool solve(const Eigen::MatrixXd&, Eigen::MatrixXd&) { return false; }
  const char* name() const { return "failing"; }
};
} // namespace

BOOST_AUTO_TEST_CASE(solver_choice_and_fallback)
{
  const Surface_mesh tm = make<Surface_mesh>(grid(16, 16, bump(0.3), holes({{5, 9, 5, 9}})));
  const auto reference = flatten(tm);
  const auto ldlt = flatten(tm, QD::parameters::sparse_solver(QD::Simplicial_LDLT_solver()));
  BOOST_TEST(ldlt.result.solver == "SimplicialLDLT");
#ifdef CGAL_QD_USE_CHOLMOD
  const auto cholmod = flatten(tm, QD::parameters::sparse_solver(QD::Cholmod_solver()));
  BOOST_TEST(cholmod.result.solver == "CHOLMOD");
  for(auto v : vertices(tm))
    BOOST_TEST(std::hypot(cholmod.uv.at(v)[0] - reference.uv.at(v)[0], cholmod.uv.at(v)[1] - reference.uv.at(v)[1]) <
               1e-9);
#endif
  const auto fallback = flatten(tm, QD::parameters::sparse_solver(Failing_solver()));
  BOOST_TEST(fallback.result.used_fallback);
  BOOST_TEST(fallback.result.solver == "SparseLU");
  for(auto v : vertices(tm)) {
    BOOST_TEST(std::hypot(ldlt.uv.at(v)[0] - reference.uv.at(v)[0], ldlt.uv.at(v)[1] - reference.uv.at(v)[1]) < 1e-9);
    BOOST_TEST(std::hypot(fallback.uv.at(v)[0] - reference.uv.at(v)[0], fallback.uv.at(v)[1] - reference.uv.at(v)[1]) <
               1e-9);
  }
}

// Size_adaptive_solver, the default: SimplicialLDLT below its threshold, the
// supernodal CHOLMOD factorisation from it (where CMake found CHOLMOD), with
// the same UVs to 1e-9, and SimplicialLDLT again where CHOLMOD cannot
// factorise (an indefinite matrix)
BOOST_AUTO_TEST_CASE(size_adaptive_solver_switches_and_falls_back)
{
  BOOST_TEST(QD::Default_flattening_solver().supernodal_threshold() == 100000u);
  const Surface_mesh tm = make<Surface_mesh>(grid(24, 24, bump(0.3), holes({{5, 9, 5, 12}})));
  const auto ldlt = flatten(tm, QD::parameters::sparse_solver(QD::Simplicial_LDLT_solver()));
  const auto below = flatten(tm);
  BOOST_TEST(below.result.solver == "SimplicialLDLT");
  const auto above = flatten(tm, QD::parameters::sparse_solver(QD::Size_adaptive_solver(1)));
#ifdef CGAL_QD_USE_CHOLMOD
  BOOST_TEST(above.result.solver == "CHOLMOD supernodal");
#else
  BOOST_TEST(above.result.solver == "SimplicialLDLT");
#endif
  BOOST_TEST(!above.result.used_fallback);
#ifdef CGAL_QD_USE_CHOLMOD
  // the symbolic analysis ran ahead, on the pattern found from the mesh
  BOOST_TEST(above.result.time_analysis_ms > 0);
#endif
  BOOST_TEST(below.result.time_analysis_ms == 0);
  for(auto v : vertices(tm)) {
    BOOST_TEST((below.uv.at(v)[0] == ldlt.uv.at(v)[0] && below.uv.at(v)[1] == ldlt.uv.at(v)[1]));
    BOOST_TEST(std::hypot(above.uv.at(v)[0] - ldlt.uv.at(v)[0], above.uv.at(v)[1] - ldlt.uv.at(v)[1]) < 1e-9);
  }

  // symmetric and indefinite (eigenvalues of both signs), lower triangle
  Eigen::SparseMatrix<double> A(3, 3);
  std::vector<Eigen::Triplet<double>> t = {{0, 0, 2.}, {1, 0, 1.}, {1, 1, -3.}, {2, 1, 0.5}, {2, 2, 4.}};
  A.setFromTriplets(t.begin(), t.end());
  Eigen::MatrixXd B(3, 2), X;
  B << 1., 0., 2., -1., 0.5, 3.;
  QD::Size_adaptive_solver solver(1);
  BOOST_REQUIRE(solver.factorize(A));
  BOOST_TEST(std::string(solver.name()) == "SimplicialLDLT");
  BOOST_REQUIRE(solver.solve(B, X));
  const Eigen::MatrixXd residual = A.selfadjointView<Eigen::Lower>() * X - B;
  BOOST_TEST(residual.norm() < 1e-12);
#ifdef CGAL_QD_USE_CHOLMOD
  {
    // an analysis ahead is used for a matrix of its pattern, and a matrix of
    // another pattern is analysed anew: the same solutions either way
    Eigen::SparseMatrix<double> spd(3, 3), other(3, 3);
    std::vector<Eigen::Triplet<double>> a = {{0, 0, 4.}, {1, 0, 1.}, {1, 1, 3.}, {2, 1, 0.5}, {2, 2, 2.}};
    spd.setFromTriplets(a.begin(), a.end());
    a.push_back({2, 0, 0.25});
    other.setFromTriplets(a.begin(), a.end());
    for(const Eigen::SparseMatrix<double>* M : {&spd, &other}) {
      QD::Cholmod_supernodal_solver cholmod;
      BOOST_REQUIRE(cholmod.analyze(spd));
      BOOST_REQUIRE(cholmod.factorize(*M));
      BOOST_REQUIRE(cholmod.solve(B, X));
      BOOST_TEST((M->selfadjointView<Eigen::Lower>() * X - B).norm() < 1e-12);
    }
  }
#endif
  // a copy has no factorisation
  QD::Size_adaptive_solver copy(solver);
  BOOST_TEST(!copy.solve(B, X));
  BOOST_TEST(copy.supernodal_threshold() == 1u);
}

// Simplicial_LDLT_solver solves all the columns of a right-hand side in one
// pass over the factor: the same numbers, to the last bit, as Eigen's solve()
// column by column, with the AMD and the natural ordering, for 1 to 3 columns
// (rows of zeros, and rows with a zero in one column only, which Eigen skips
// in that column alone)
BOOST_AUTO_TEST_CASE(simplicial_ldlt_solves_columns_as_eigen_does)
{
  // a symmetric positive definite matrix on a 20 x 20 grid (lower triangle),
  // and right-hand sides with a few zero entries
  const int k = 20, n = k * k;
  std::vector<Eigen::Triplet<double>> t;
  for(int i = 0; i < k; ++i)
    for(int j = 0; j < k; ++j) {
      const int r = i * k + j;
      double d = 0.1 + 0.01 * ((r * 7) % 5);
      for(const auto& o : {std::make_pair(0, 1), std::make_pair(1, 0), std::make_pair(1, 1)}) {
        const int i2 = i + o.first, j2 = j + o.second;
        if(i2 >= k || j2 >= k) continue;
        const double w = 0.3 + 0.1 * ((r + 3 * i2 + j2) % 7);
        t.emplace_back(i2 * k + j2, r, -w);
        d += w;
      }
      // diagonally dominant: d holds the weights to the next vertices, and the
      // at most three weights from the previous ones are below 0.9 each
      t.emplace_back(r, r, d + 3.);
    }
  Eigen::SparseMatrix<double> A(n, n);
  A.setFromTriplets(t.begin(), t.end());
  for(int cols = 1; cols <= 3; ++cols) {
    Eigen::MatrixXd B(n, cols);
    for(int r = 0; r < n; ++r)
      for(int c = 0; c < cols; ++c)
        B(r, c) = r % 11 == 0 || (r % 13 == 0 && c == 1) ? 0. : std::sin(0.37 * r + c);
    QD::Simplicial_LDLT_solver ours;
    BOOST_REQUIRE(ours.factorize(A));
    Eigen::MatrixXd X;
    BOOST_REQUIRE(ours.solve(B, X));
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower, Eigen::AMDOrdering<int>> amd(A);
    const Eigen::MatrixXd Y = amd.solve(B);
    BOOST_TEST((X.array() == Y.array()).all());
    QD::Eigen_symmetric_solver<Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower, Eigen::NaturalOrdering<int>>>
        natural("natural");
    BOOST_REQUIRE(natural.factorize(A));
    BOOST_REQUIRE(natural.solve(B, X));
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower, Eigen::NaturalOrdering<int>> plain(A);
    BOOST_TEST((X.array() == plain.solve(B).array()).all());
    BOOST_TEST((A.selfadjointView<Eigen::Lower>() * X - B).norm() < 1e-10 * B.norm());
  }
}

// Simplicial_LDLT_solver::solve_in_order() solves two columns held row by
// row in the factor's order: the same numbers, to the last bit, as solve();
// and the ARAP iteration, which gathers its right-hand side in that order with
// this solver, gives the same map to the last bit as with a solver that
// permutes the columns (Eigen_symmetric_solver of the same SimplicialLDLT)
BOOST_AUTO_TEST_CASE(arap_global_step_in_the_factor_order_gives_the_same_map)
{
  const int k = 12, n = k * k;
  std::vector<Eigen::Triplet<double>> t;
  std::vector<double> d(n, 0.05);
  for(int i = 0; i < k; ++i)
    for(int j = 0; j < k; ++j)
      for(const int other : {j + 1 < k ? i * k + j + 1 : -1, i + 1 < k ? (i + 1) * k + j : -1}) {
        if(other < 0) continue;
        const double w = 0.4 + 0.1 * ((i * 5 + j * 3 + other) % 6);
        t.emplace_back(other, i * k + j, -w);
        d[i * k + j] += w;
        d[other] += w;
      }
  for(int r = 0; r < n; ++r) t.emplace_back(r, r, d[r]);
  Eigen::SparseMatrix<double> A(n, n);
  A.setFromTriplets(t.begin(), t.end());
  Eigen::MatrixXd B(n, 2);
  for(int r = 0; r < n; ++r)
    for(int c = 0; c < 2; ++c) B(r, c) = r % 7 == 0 || (r % 5 == 0 && c == 0) ? 0. : std::cos(0.29 * r + 2 * c);
  QD::Simplicial_LDLT_solver solver;
  BOOST_REQUIRE(solver.factorize(A));
  const int* order = solver.order_of_rows();
  BOOST_REQUIRE(order != nullptr);  // AMD reorders a grid
  std::vector<double> y(2 * n);
  for(int r = 0; r < n; ++r)
    for(int c = 0; c < 2; ++c) y[2 * order[r] + c] = B(r, c);
  BOOST_REQUIRE(solver.solve_in_order(y.data(), n));
  Eigen::MatrixXd X;
  BOOST_REQUIRE(solver.solve(B, X));
  bool same = true;
  for(int r = 0; r < n; ++r)
    for(int c = 0; c < 2; ++c) same = same && y[2 * order[r] + c] == X(r, c);
  BOOST_TEST(same);
  BOOST_TEST(!solver.solve_in_order(y.data(), n + 1));  // not the size of the factor
  BOOST_TEST(!QD::Simplicial_LDLT_solver().solve_in_order(y.data(), n));  // no factorisation

  // a cap of 70 degrees, free border and a fixed border, plain and area-preserving targets
  typedef Surface_mesh Mesh;
  const Mesh tm = make<Mesh>(polar(10, 40, sphere_cap(70 * pi / 180)));
  const auto f = flatten(tm);
  typedef QD::Eigen_symmetric_solver<
      Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower, Eigen::AMDOrdering<int>>>
      Permuting_solver;
  for(const QD::Arap_border border : {QD::Arap_border::FREE, QD::Arap_border::FIXED})
    for(const double alpha : {0., 0.5}) {
      Uv_store<Mesh> in_order = f.uv, permuting = f.uv;
      const auto np = QD::parameters::area_preservation(
          alpha, QD::parameters::arap_border(border, CGAL::parameters::number_of_iterations(20)));
      const QD::Optimization_result a = QD::optimize_flattening(tm, in_order.pmap(), np);
      const QD::Optimization_result b = QD::optimize_flattening(
          tm, permuting.pmap(), QD::parameters::sparse_solver(Permuting_solver("permuting"), np));
      BOOST_REQUIRE_MESSAGE(a, QD::error_message(a.status));
      BOOST_REQUIRE_MESSAGE(b, QD::error_message(b.status));
      BOOST_TEST(a.iterations == b.iterations);
      BOOST_TEST(a.iterations > 1u);
      BOOST_TEST((in_order.map == permuting.map));
      BOOST_TEST(a.energy_after < a.energy_before);
    }
}

// Simplicial_LDLT_solvers sharing an Ordering_cache: a pattern met again
// takes its ordering from the cache, and the solution is the same to the last
// bit as without it; another pattern is ordered again; beyond its budget the
// cache drops the ordering used least recently
BOOST_AUTO_TEST_CASE(ordering_cache_gives_the_same_factorisation)
{
  // a grid Laplacian plus a diagonal, with values that depend on `seed`, and
  // optionally one more coupling (another pattern)
  const int k = 15, n = k * k;
  auto matrix = [&](int seed, bool extra) {
    std::vector<Eigen::Triplet<double>> t;
    std::vector<double> d(n, 1. + 0.1 * seed);
    auto couple = [&](int a, int b, double w) {
      t.emplace_back((std::max)(a, b), (std::min)(a, b), -w);
      d[a] += w;
      d[b] += w;
    };
    for(int i = 0; i < k; ++i)
      for(int j = 0; j < k; ++j) {
        if(j + 1 < k) couple(i * k + j, i * k + j + 1, 0.5 + 0.1 * ((i + j + seed) % 4));
        if(i + 1 < k) couple(i * k + j, (i + 1) * k + j, 0.7 + 0.1 * ((i * j + seed) % 3));
      }
    if(extra) couple(0, n - 1, 0.4);
    for(int r = 0; r < n; ++r) t.emplace_back(r, r, d[r]);
    Eigen::SparseMatrix<double> A(n, n);
    A.setFromTriplets(t.begin(), t.end());
    return A;
  };
  Eigen::MatrixXd B(n, 2);
  for(int r = 0; r < n; ++r) B.row(r) << std::sin(0.3 * r), std::cos(0.2 * r);
  auto solve = [&](QD::Simplicial_LDLT_solver& s, const Eigen::SparseMatrix<double>& A) {
    Eigen::MatrixXd X;
    BOOST_REQUIRE(s.factorize(A));
    BOOST_REQUIRE(s.solve(B, X));
    return X;
  };
  const auto cache = std::make_shared<QD::Ordering_cache>();
  QD::Simplicial_LDLT_solver plain, cached(cache);
  const QD::Simplicial_LDLT_solver copy = cached;  // shares the cache
  for(int seed = 0; seed < 3; ++seed) {
    const Eigen::SparseMatrix<double> A = matrix(seed, false);
    const Eigen::MatrixXd X = solve(plain, A);
    QD::Simplicial_LDLT_solver other = seed == 2 ? copy : cached;
    BOOST_TEST((solve(other, A).array() == X.array()).all());
    BOOST_TEST((A.selfadjointView<Eigen::Lower>() * X - B).norm() < 1e-10 * B.norm());
  }
  BOOST_TEST(cache->misses() == 1u);
  BOOST_TEST(cache->hits() == 2u);
  const Eigen::SparseMatrix<double> E = matrix(1, true);
  BOOST_TEST((solve(cached, E).array() == solve(plain, E).array()).all());
  BOOST_TEST(cache->misses() == 2u);
  // room for one permutation only: the second pattern pushed the first out
  const auto small = std::make_shared<QD::Ordering_cache>(sizeof(int) * std::size_t(n));
  QD::Simplicial_LDLT_solver one(small);
  solve(one, matrix(0, false));
  solve(one, E);
  solve(one, E);
  BOOST_TEST(small->hits() == 1u);
  solve(one, matrix(0, false));
  BOOST_TEST(small->misses() == 3u);
}

// The ordering of Simplicial_LDLT_solver (Cached_AMD_ordering) calls Eigen's
// AMD routine on the symmetric pattern it is given, without the transpose and
// sum of Eigen::AMDOrdering: the permutation must be Eigen's, entry for entry,
// on patterns as SimplicialLDLT gives them (a grid, random couplings, a
// dense row, empty columns)
BOOST_AUTO_TEST_CASE(amd_ordering_on_the_pattern_is_eigens)
{
  typedef Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> Permutation;
  std::mt19937 rng(11);
  for(int shape = 0; shape < 4; ++shape) {
    const int n = shape == 0 ? 400 : 300;
    std::vector<Eigen::Triplet<double>> t;
    for(int r = 0; r < n; ++r)
      if(!(shape == 3 && r % 17 == 0)) t.emplace_back(r, r, 4.);  // shape 3: a few empty columns
    auto couple = [&](int a, int b) {
      if(a != b) t.emplace_back((std::max)(a, b), (std::min)(a, b), -1.);
    };
    if(shape == 0) {  // a 20 x 20 grid
      for(int i = 0; i < 20; ++i)
        for(int j = 0; j < 20; ++j) {
          if(j + 1 < 20) couple(i * 20 + j, i * 20 + j + 1);
          if(i + 1 < 20) couple(i * 20 + j, (i + 1) * 20 + j);
        }
    } else {
      for(int e = 0; e < 4 * n; ++e) couple(int(rng() % unsigned(n)), int(rng() % unsigned(n)));
      if(shape == 2)  // a row dense enough for AMD to set it aside
        for(int r = 1; r < n; ++r) couple(0, r);
    }
    Eigen::SparseMatrix<double> A(n, n);
    A.setFromTriplets(t.begin(), t.end());
    Eigen::SparseMatrix<double> C;
    C = A.selfadjointView<Eigen::Lower>();  // as SimplicialLDLT orders it
    Permutation ours, eigen;
    QD::internal::Cached_AMD_ordering<int>()(C, ours);
    Eigen::AMDOrdering<int>()(C, eigen);
    BOOST_REQUIRE_EQUAL(ours.size(), eigen.size());
    BOOST_TEST((ours.indices().array() == eigen.indices().array()).all(), "shape " << shape);
    if(shape == 1) {
      // the routine's answer depends on the order of the entries in a column
      // (so that the comparison above sees a pattern handed over in another
      // order): every column reversed gives another permutation
      Eigen::SparseMatrix<double> R = C;
      for(Eigen::Index j = 0; j < n; ++j)
        std::reverse(R.innerIndexPtr() + R.outerIndexPtr()[j], R.innerIndexPtr() + R.outerIndexPtr()[j + 1]);
      Permutation reversed;
      Eigen::internal::minimum_degree_ordering(R, reversed);
      BOOST_TEST(!(reversed.indices().array() == eigen.indices().array()).all());
    }
  }
}

// Lower_triangle_assembly makes, from entries given in any order with
// repeats, the matrix Eigen's setFromTriplets() makes of the same triplets,
// to the last bit (repeats summed in the order given), its columns sorted
BOOST_AUTO_TEST_CASE(lower_triangle_assembly_is_set_from_triplets)
{
  std::mt19937 rng(5);
  for(const long n : {1L, 7L, 60L, 500L}) {
    std::uniform_int_distribution<long> index(0, n - 1);
    std::uniform_real_distribution<double> value(-1., 1.);
    std::vector<Eigen::Triplet<double>> t;
    QD::internal::Lower_triangle_assembly ours(n, 0);
    for(long e = 0; e < 8 * n; ++e) {
      long i = index(rng), j = e % 3 == 0 ? i : index(rng);  // every third on the diagonal
      if(i < j) std::swap(i, j);
      // values of different magnitudes, so that the order of a sum shows
      const double v = value(rng) * std::pow(10., double(e % 5) - 2.) + 1. / 3.;
      for(int again = 0; again < (e % 4 == 0 ? 3 : 1); ++again) {  // repeats, some in a row
        t.emplace_back(i, j, v * (again + 1));
        ours.add(i, j, v * (again + 1));
      }
    }
    Eigen::SparseMatrix<double> expected(n, n), A;
    expected.setFromTriplets(t.begin(), t.end());
    ours.assemble(A);
    BOOST_REQUIRE(A.isCompressed());
    BOOST_REQUIRE_EQUAL(A.rows(), n);
    BOOST_REQUIRE_EQUAL(A.cols(), n);
    BOOST_REQUIRE_EQUAL(A.nonZeros(), expected.nonZeros());
    bool same = true;
    for(long j = 0; j <= n; ++j) same = same && A.outerIndexPtr()[j] == expected.outerIndexPtr()[j];
    for(Eigen::Index k = 0; k < A.nonZeros(); ++k)
      same = same && A.innerIndexPtr()[k] == expected.innerIndexPtr()[k] && A.valuePtr()[k] == expected.valuePtr()[k];
    BOOST_TEST(same, "n = " << n);
  }
  // nothing added: an empty matrix of the size asked
  Eigen::SparseMatrix<double> E;
  QD::internal::Lower_triangle_assembly(4, 0).assemble(E);
  BOOST_TEST(E.rows() == 4);
  BOOST_TEST(E.nonZeros() == 0);
}

// amd_order_of_triangles() orders the graph of a mesh once (through the
// cache), and the systems on a part of its vertices numbered in that order
// (the interior, as LPFB+IP solves it) have no more fill than the whole;
// Simplicial_LDLT_natural_solver factorises them in that order and solves as
// Eigen's SimplicialLDLT with the natural ordering does, to the last bit
BOOST_AUTO_TEST_CASE(one_amd_ordering_of_a_mesh_serves_the_systems_on_its_parts)
{
  const std::size_t rings = 20, sectors = 60;
  const Soup soup = polar(rings, sectors, sphere_cap(1.));
  const std::size_t n = soup.points.size();
  std::vector<std::size_t> corner;
  for(const Tri& t : soup.triangles) corner.insert(corner.end(), t.begin(), t.end());
  const auto cache = std::make_shared<QD::Ordering_cache>();
  const std::vector<int> order = QD::internal::amd_order_of_triangles(n, corner, cache.get());
  BOOST_REQUIRE_EQUAL(order.size(), n);
  std::vector<int> sorted = order;
  std::sort(sorted.begin(), sorted.end());
  bool permutation = true;
  for(std::size_t i = 0; i < n; ++i) permutation = permutation && sorted[i] == int(i);
  BOOST_REQUIRE(permutation);
  BOOST_TEST(cache->misses() == 1u);
  BOOST_TEST((QD::internal::amd_order_of_triangles(n, corner, cache.get()) == order));
  BOOST_TEST(cache->hits() == 1u);
  std::vector<std::size_t> position(n);
  for(std::size_t k = 0; k < n; ++k) position[std::size_t(order[k])] = k;

  // a graph Laplacian plus a diagonal on the vertices kept (all, or all but
  // the outer ring), numbered in increasing `rank`
  typedef Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower, Eigen::NaturalOrdering<int>> Natural;
  auto system = [&](bool interior, const std::function<std::size_t(std::size_t)>& rank) {
    std::vector<std::pair<std::size_t, std::size_t>> kept;
    for(std::size_t v = 0; v < n; ++v)
      if(!interior || v + sectors < n) kept.push_back({rank(v), v});
    std::sort(kept.begin(), kept.end());
    std::vector<long> row(n, -1);
    for(std::size_t r = 0; r < kept.size(); ++r) row[kept[r].second] = long(r);
    std::vector<Eigen::Triplet<double>> t;
    std::vector<double> d(kept.size(), 0.1);
    for(std::size_t c = 0; c < corner.size(); ++c) {
      const long a = row[corner[c]], b = row[corner[c % 3 == 2 ? c - 2 : c + 1]];
      if(a < 0 || b < 0) continue;
      const double w = 0.5 + 0.01 * double(c % 7);
      t.emplace_back((std::max)(a, b), (std::min)(a, b), -w);
      d[std::size_t(a)] += w;
      d[std::size_t(b)] += w;
    }
    for(std::size_t r = 0; r < kept.size(); ++r) t.emplace_back(long(r), long(r), d[r]);
    Eigen::SparseMatrix<double> A(long(kept.size()), long(kept.size()));
    A.setFromTriplets(t.begin(), t.end());
    return A;
  };
  auto in_order = [&](std::size_t v) { return position[v]; };
  auto by_index = [](std::size_t v) { return v; };
  auto factor_size = [](const Eigen::SparseMatrix<double>& A) {
    Natural ldlt(A);
    BOOST_REQUIRE(ldlt.info() == Eigen::Success);
    return ldlt.matrixL().nestedExpression().nonZeros();
  };
  const Eigen::SparseMatrix<double> whole = system(false, in_order), inside = system(true, in_order);
  BOOST_REQUIRE_EQUAL(inside.rows(), Eigen::Index(n - sectors));
  BOOST_TEST(factor_size(inside) <= factor_size(whole));
  // the rings' own numbering has the bandwidth of a ring
  BOOST_TEST(2 * factor_size(whole) < factor_size(system(false, by_index)));

  Eigen::MatrixXd B(inside.rows(), 2);
  for(Eigen::Index r = 0; r < B.rows(); ++r) B.row(r) << std::sin(0.3 * double(r)), r % 9 == 0 ? 0. : std::cos(0.2 * double(r));
  QD::Simplicial_LDLT_natural_solver solver;
  BOOST_REQUIRE(solver.factorize(inside));
  BOOST_TEST(solver.order_of_rows() == nullptr);
  Eigen::MatrixXd X;
  BOOST_REQUIRE(solver.solve(B, X));
  const Natural plain(inside);
  BOOST_TEST((X.array() == plain.solve(B).array()).all());
  BOOST_TEST((inside.selfadjointView<Eigen::Lower>() * X - B).norm() < 1e-10 * B.norm());
  std::vector<double> y(std::size_t(2 * B.rows()));
  for(Eigen::Index r = 0; r < B.rows(); ++r)
    for(int c = 0; c < 2; ++c) y[std::size_t(2 * r + c)] = B(r, c);
  BOOST_REQUIRE(solver.solve_in_order(y.data(), std::size_t(B.rows())));
  bool same = true;
  for(Eigen::Index r = 0; r < B.rows(); ++r)
    for(int c = 0; c < 2; ++c) same = same && y[std::size_t(2 * r + c)] == X(r, c);
  BOOST_TEST(same);
}

// with the default solver, and with one that analyses every system ahead on a
// second thread (which then runs on the bad mesh too)
BOOST_AUTO_TEST_CASE_TEMPLATE(bad_input_writes_nothing, Mesh, Mesh_types)
{
  for(std::size_t threshold : {QD::Size_adaptive_solver::default_supernodal_threshold, std::size_t(1)}) {
    const auto np = QD::parameters::sparse_solver(QD::Size_adaptive_solver(threshold));
    {
      Soup s;  // a closed octahedron
      s.points = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
      s.triangles = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
      const Mesh tm = make<Mesh>(s);
      Uv_store<Mesh> uv;
      const auto r = QD::flatten_patch(tm, uv.pmap(), np);
      BOOST_TEST((r.status == QD::Error_code::NO_BORDER));
      BOOST_TEST(uv.map.empty());
    }
    {
      Mesh empty;
      Uv_store<Mesh> uv;
      BOOST_TEST((QD::flatten_patch(empty, uv.pmap(), np).status == QD::Error_code::EMPTY_MESH));
    }
    {
      Soup s = grid(4, 4, bump(0.2));
      s.points[7][2] = std::numeric_limits<double>::quiet_NaN();
      const Mesh tm = make<Mesh>(s);
      Uv_store<Mesh> uv;
      BOOST_TEST((QD::flatten_patch(tm, uv.pmap(), np).status == QD::Error_code::INVALID_COORDINATES));
      BOOST_TEST(uv.map.empty());
    }
  }
}

// ===================================================================== optimize_flattening()

namespace {

// the largest |l_2D - target| / target over the border edges
template <class Mesh, class Goal>
double border_length_error(const Mesh& tm, const Uv_store<Mesh>& uv, const Goal& goal)
{
  double worst = 0;
  for(auto h : halfedges(tm)) {
    if(!is_border(h, tm)) continue;
    const auto a = uv.at(source(h, tm)), b = uv.at(target(h, tm));
    const double l = goal(h);
    worst = (std::max)(worst, std::abs(std::hypot(a[0] - b[0], a[1] - b[1]) - l) / l);
  }
  return worst;
}

template <class Mesh>
double length3(const Mesh& tm, typename boost::graph_traits<Mesh>::halfedge_descriptor h)
{
  const auto p = p3(tm, source(h, tm)), q = p3(tm, target(h, tm));
  return std::sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) + (p[2] - q[2]) * (p[2] - q[2]));
}

} // namespace

BOOST_AUTO_TEST_CASE_TEMPLATE(arap_keeps_an_isometry, Mesh, Mesh_types)
{
  // LPFB+IP of a developable patch is an isometry: ARAP has nothing to do
  const Mesh tm = make<Mesh>(grid(24, 8, cylinder(1.0, 1.5 * pi, 2.0)));
  auto f = flatten(tm);
  for(QD::Arap_border mode : {QD::Arap_border::FREE, QD::Arap_border::KEEP_LENGTHS, QD::Arap_border::FIXED,
                              QD::Arap_border::LENGTH_PRESERVED}) {
    Uv_store<Mesh> uv = f.uv;
    const QD::Optimization_result o = QD::optimize_flattening(tm, uv.pmap(), QD::parameters::arap_border(mode));
    BOOST_REQUIRE_MESSAGE(o, QD::error_message(o.status));
    BOOST_TEST(o.energy_before < 1e-12);
    BOOST_TEST(o.energy_after < 1e-12);
    BOOST_TEST(!o.input_flipped);
    const auto d = QD::compute_distortion(tm, uv.pmap_const());
    BOOST_TEST(d.area_distortion < 1e-6);
    BOOST_TEST(d.local_area_distortion < 1e-5);
    BOOST_TEST(d.flipped_faces == 0u);
  }
}

BOOST_AUTO_TEST_CASE(arap_local_step_two_faces_at_once_is_bit_for_bit_the_same)
{
  // random triangles and random maps, with faces collapsed to a point, to a
  // segment, flipped and stretched far beyond the bound on the anisotropy:
  // the targets and the energy of the local step found in lanes (four faces
  // at a time, then a pair, then one alone) must be those of the one-face
  // code, bit for bit
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> coord(-1., 1.);
  // a face alone after the groups of four; then a pair and a face
  for(const std::size_t nf : {std::size_t(101), std::size_t(103)}) {
    const std::size_t nv = 40;
    std::vector<std::array<double, 3>> p(nv);
    for(auto& x : p) x = {coord(rng), coord(rng), coord(rng)};
    std::vector<std::array<std::size_t, 3>> tri(nf);
    for(auto& t : tri) {
      do {
        t = {rng() % nv, rng() % nv, rng() % nv};
      } while(t[0] == t[1] || t[1] == t[2] || t[0] == t[2]);
    }
    const std::vector<std::array<std::size_t, 2>> no_border;
    const std::vector<double> no_length;
    for(int round = 0; round < 6; ++round) {
      std::vector<std::array<double, 2>> u(nv);
      for(auto& x : u) x = {coord(rng), coord(rng)};
      if(round == 1) u.assign(nv, {0.25, -0.5});  // every face a point: q = 0
      if(round == 2)
        for(auto& x : u) x = {x[0], 3 * x[0]};  // every face a segment: s2 = 0
      if(round == 3)
        for(auto& x : u) x = {1e-9 * x[0], 1e3 * x[1]};  // t far beyond 2
      if(round == 4)
        for(std::size_t i = 0; i < nv; i += 2) u[i] = {0., 0.};  // some faces collapsed
      for(double alpha : {0., 0.5, 1., 0.3}) {
        QD::internal::Arap_optimizer<QD::Simplicial_LDLT_solver> two(nv, tri, p, no_border, no_length, 0.,
                                                                    QD::Simplicial_LDLT_solver(), alpha);
        QD::internal::Arap_optimizer<QD::Simplicial_LDLT_solver> one(nv, tri, p, no_border, no_length, 0.,
                                                                    QD::Simplicial_LDLT_solver(), alpha);
        one.set_two_lanes(false);
        const double e2 = two.local_step(u), e1 = one.local_step(u);
        BOOST_TEST(std::memcmp(&e1, &e2, sizeof(double)) == 0, "round " << round << " alpha " << alpha);
        BOOST_REQUIRE_EQUAL(two.targets().size(), nf);
        for(std::size_t f = 0; f < nf; ++f)
          BOOST_TEST(std::memcmp(two.targets()[f].data(), one.targets()[f].data(), 4 * sizeof(double)) == 0,
                     "round " << round << " alpha " << alpha << " face " << f);
      }
    }
  }
}

BOOST_AUTO_TEST_CASE_TEMPLATE(arap_lowers_the_stretch_of_a_cap, Mesh, Mesh_types)
{
  // a spherical cap of 70 degrees: LPFB keeps its border at full length, so
  // the interior stretches; the free border lets it shrink
  const Mesh tm = make<Mesh>(polar(12, 48, sphere_cap(70 * pi / 180)));
  const auto f = flatten(tm);
  Uv_store<Mesh> free_uv = f.uv;
  const QD::Optimization_result o =
      QD::optimize_flattening(tm, free_uv.pmap(), QD::parameters::arap_border(QD::Arap_border::FREE));
  BOOST_REQUIRE_MESSAGE(o, QD::error_message(o.status));
  BOOST_TEST(o.iterations >= 1u);
  BOOST_TEST(o.energy_after < o.energy_before);
  const auto d = QD::compute_distortion(tm, free_uv.pmap_const());
  BOOST_TEST_MESSAGE("cap: A_loc " << f.report.local_area_distortion << " % with LPFB+IP, "
                                   << d.local_area_distortion << " % with free ARAP, " << o.iterations
                                   << " iterations (" << o.shortened_steps << " shortened), energy "
                                   << o.energy_before << " -> " << o.energy_after);
  BOOST_TEST(d.local_area_distortion < 0.5 * f.report.local_area_distortion);
  BOOST_TEST(d.flipped_faces == 0u);
  BOOST_TEST(!d.overlap);

  // LENGTH_PRESERVED: every border edge at its 3D length again
  Uv_store<Mesh> kept = f.uv;
  const QD::Optimization_result k = QD::optimize_flattening(tm, kept.pmap());
  BOOST_REQUIRE_MESSAGE(k, QD::error_message(k.status));
  BOOST_TEST(k.lengths_preserved);
  BOOST_TEST(border_length_error(tm, kept, [&](auto h) { return length3(tm, h); }) < 1e-6);
  BOOST_TEST(QD::compute_distortion(tm, kept.pmap_const()).flipped_faces == 0u);

  // KEEP_LENGTHS with given lengths, 1 % shorter than in 3D, and a large weight
  std::map<typename boost::graph_traits<Mesh>::edge_descriptor, double> shorter;
  for(auto e : edges(tm)) shorter[e] = 0.99 * length3(tm, halfedge(e, tm));
  Uv_store<Mesh> pulled = free_uv;
  const QD::Optimization_result p = QD::optimize_flattening(
      tm, pulled.pmap(),
      QD::parameters::arap_border(
          QD::Arap_border::KEEP_LENGTHS,
          QD::parameters::border_edge_length_map(boost::make_assoc_property_map(shorter),
                                                 QD::parameters::border_length_weight(1000.))));
  BOOST_REQUIRE_MESSAGE(p, QD::error_message(p.status));
  BOOST_TEST(border_length_error(tm, pulled, [&](auto h) { return shorter.at(edge(h, tm)); }) < 0.005);
  BOOST_TEST(QD::compute_distortion(tm, pulled.pmap_const()).flipped_faces == 0u);
}

BOOST_AUTO_TEST_CASE_TEMPLATE(no_free_iteration_fits_the_border_to_the_given_map, Mesh, Mesh_types)
{
  // the cap of 70 degrees, its border fitted at the 3D lengths (30 free
  // iterations, then the border fitted): fitting it again without free
  // iterations finds the same border (the given map's angles, at lengths it
  // already has), where 30 free iterations first let it shrink and move
  const Mesh tm = make<Mesh>(polar(12, 48, sphere_cap(70 * pi / 180)));
  const auto f = flatten(tm);
  Uv_store<Mesh> fitted = f.uv;
  const QD::Optimization_result k = QD::optimize_flattening(tm, fitted.pmap());
  BOOST_REQUIRE_MESSAGE(k, QD::error_message(k.status));
  BOOST_REQUIRE(k.lengths_preserved);

  auto largest_border_move = [&](const Uv_store<Mesh>& a, const Uv_store<Mesh>& b) {
    double move = 0;
    for(auto v : vertices(tm))
      if(is_border(v, tm)) {
        const auto p = a.at(v), q = b.at(v);
        move = (std::max)(move, std::hypot(p[0] - q[0], p[1] - q[1]));
      }
    return move;
  };
  Uv_store<Mesh> again = fitted, with_free = fitted;
  std::size_t calls = 0;
  const QD::Optimization_result a = QD::optimize_flattening(
      tm, again.pmap(), QD::parameters::number_of_free_iterations(0, QD::parameters::iteration_callback([&](std::size_t) {
        ++calls;
        return false;
      })));
  BOOST_REQUIRE_MESSAGE(a, QD::error_message(a.status));
  BOOST_TEST(a.lengths_preserved);
  BOOST_TEST(calls == 0u);  // no free iteration
  BOOST_TEST(a.iterations <= 30u);
  BOOST_TEST(border_length_error(tm, again, [&](auto h) { return length3(tm, h); }) < 1e-6);
  const QD::Optimization_result w = QD::optimize_flattening(tm, with_free.pmap());
  BOOST_REQUIRE_MESSAGE(w, QD::error_message(w.status));
  const double kept = largest_border_move(fitted, again), moved = largest_border_move(fitted, with_free);
  BOOST_TEST_MESSAGE("cap: the border moves by " << kept << " without free iterations, " << moved
                                                 << " with 30 (radius about 1)");
  BOOST_TEST(kept < 1e-6);
  BOOST_TEST(moved > 1e-3);
  BOOST_TEST(QD::compute_distortion(tm, again.pmap_const()).flipped_faces == 0u);

  // a huge count runs the free iteration until it converges
  Uv_store<Mesh> huge = f.uv;
  const QD::Optimization_result h =
      QD::optimize_flattening(tm, huge.pmap(), QD::parameters::number_of_free_iterations(1e30));
  BOOST_REQUIRE_MESSAGE(h, QD::error_message(h.status));
  BOOST_TEST(h.lengths_preserved);

  // a negative or non-finite count is refused, and nothing is written
  for(const double bad : {-1., std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
    Uv_store<Mesh> uv = f.uv;
    BOOST_TEST((QD::optimize_flattening(tm, uv.pmap(), QD::parameters::number_of_free_iterations(bad)).status ==
                QD::Error_code::INVALID_ARGUMENT));
    BOOST_TEST((uv.map == f.uv.map));
  }
}

BOOST_AUTO_TEST_CASE_TEMPLATE(iteration_callback_sees_every_map_and_can_stop, Mesh, Mesh_types)
{
  // the cap of 70 degrees, free border, half of the anisotropy kept: the
  // callback is called after every iteration with that iteration's map in
  // `uv`; a callback that never stops changes nothing, one that stops at
  // iteration 5 leaves the map of 5 iterations
  const Mesh tm = make<Mesh>(polar(12, 48, sphere_cap(70 * pi / 180)));
  const auto f = flatten(tm);
  const auto np = QD::parameters::arap_border(QD::Arap_border::FREE, QD::parameters::area_preservation(0.5));
  Uv_store<Mesh> plain = f.uv, five = f.uv;
  const QD::Optimization_result p = QD::optimize_flattening(tm, plain.pmap(), np);
  BOOST_REQUIRE_MESSAGE(p, QD::error_message(p.status));
  BOOST_TEST_MESSAGE("cap: " << p.iterations << " iterations");
  BOOST_REQUIRE(p.iterations > 5u);
  BOOST_REQUIRE(QD::optimize_flattening(tm, five.pmap(), np.number_of_iterations(5)));

  Uv_store<Mesh> watched = f.uv;
  std::vector<std::size_t> seen;
  std::vector<double> a_loc;
  const QD::Optimization_result w =
      QD::optimize_flattening(tm, watched.pmap(), QD::parameters::iteration_callback([&](std::size_t it) {
        seen.push_back(it);
        a_loc.push_back(QD::compute_distortion(tm, watched.pmap_const()).local_area_distortion);
        return false;
      }, np));
  BOOST_REQUIRE_MESSAGE(w, QD::error_message(w.status));
  BOOST_TEST(!w.stopped_by_callback);
  BOOST_TEST(w.iterations == p.iterations);
  BOOST_TEST((watched.map == plain.map));
  BOOST_REQUIRE(seen.size() == p.iterations);
  for(std::size_t k = 0; k < seen.size(); ++k) BOOST_TEST(seen[k] == k + 1);
  // the map seen last is the result
  BOOST_TEST(a_loc.back() == QD::compute_distortion(tm, plain.pmap_const()).local_area_distortion);

  Uv_store<Mesh> stopped = f.uv;
  const QD::Optimization_result s = QD::optimize_flattening(
      tm, stopped.pmap(), QD::parameters::iteration_callback([](std::size_t it) { return it == 5; }, np));
  BOOST_REQUIRE_MESSAGE(s, QD::error_message(s.status));
  BOOST_TEST(s.stopped_by_callback);
  BOOST_TEST(s.iterations == 5u);
  BOOST_TEST((stopped.map == five.map));
  BOOST_TEST(QD::compute_distortion(tm, stopped.pmap_const()).local_area_distortion == a_loc[4]);
}

BOOST_AUTO_TEST_CASE_TEMPLATE(area_preservation_trades_shear_for_area, Mesh, Mesh_types)
{
  // the cap of 70 degrees, free border: the more of its anisotropy every face
  // keeps in its target, the less area distortion and the more shear (mean
  // angle distortion; Sander's L2 counts the area change and falls as well);
  // alpha = 0 is plain ARAP, to the last bit
  const Mesh tm = make<Mesh>(polar(12, 48, sphere_cap(70 * pi / 180)));
  const auto f = flatten(tm);
  auto run = [&](const double* alpha) {
    Uv_store<Mesh> uv = f.uv;
    const auto np = QD::parameters::arap_border(QD::Arap_border::FREE).number_of_iterations(300);
    const QD::Optimization_result o = alpha ? QD::optimize_flattening(tm, uv.pmap(), QD::parameters::area_preservation(*alpha, np))
                                            : QD::optimize_flattening(tm, uv.pmap(), np);
    BOOST_REQUIRE_MESSAGE(o, QD::error_message(o.status));
    return uv;
  };
  const double zero = 0, half = 0.5, three_quarters = 0.75, one = 1;
  const Uv_store<Mesh> arap = run(nullptr);
  BOOST_TEST((run(&zero).map == arap.map));
  double last_a_loc = std::numeric_limits<double>::infinity(), last_angle = 0;
  for(const double* alpha : {&zero, &half, &three_quarters, &one}) {
    const Uv_store<Mesh> uv = run(alpha);
    const auto d = QD::compute_distortion(tm, uv.pmap_const());
    BOOST_TEST_MESSAGE("cap, area preservation " << *alpha << ": A_loc " << d.local_area_distortion << " %, A "
                                                 << d.area_distortion << " %, L2 " << d.l2_stretch << ", angles "
                                                 << d.angle_distortion << " rad");
    BOOST_TEST(d.local_area_distortion < last_a_loc);
    BOOST_TEST(d.angle_distortion > last_angle);
    BOOST_TEST(d.flipped_faces == 0u);
    BOOST_TEST(!d.overlap);
    last_a_loc = d.local_area_distortion;
    last_angle = d.angle_distortion;
  }
  // area-preserving targets: almost no area distortion left
  BOOST_TEST(last_a_loc < 0.25 * QD::compute_distortion(tm, arap.pmap_const()).local_area_distortion);

  // outside [0, 1]: INVALID_ARGUMENT, nothing written
  for(const double bad : {-0.1, 1.5, std::numeric_limits<double>::quiet_NaN()}) {
    Uv_store<Mesh> uv = f.uv;
    const auto before = uv.map;
    BOOST_TEST((QD::optimize_flattening(tm, uv.pmap(), QD::parameters::area_preservation(bad)).status ==
                QD::Error_code::INVALID_ARGUMENT));
    BOOST_TEST((uv.map == before));
  }
}

BOOST_AUTO_TEST_CASE_TEMPLATE(anderson_acceleration_reaches_the_fixed_point_sooner, Mesh, Mesh_types)
{
  // a bumped strip with plain ARAP and with the segmentation's
  // area-preserving targets, a cap of 100 degrees with those targets (plain
  // ARAP flattens the symmetric cap in two iterations); free border, run
  // until the energy stalls: the accelerated iteration stops in fewer
  // iterations at an energy no higher (to 1e-3), flip-free and without overlap
  const Mesh cap = make<Mesh>(polar(12, 48, sphere_cap(100 * pi / 180)));
  const Mesh wavy = make<Mesh>(grid(24, 8, bump(0.6)));
  const std::pair<const Mesh*, double> cases[] = {{&wavy, 0.}, {&wavy, 0.5}, {&cap, 0.5}};
  for(const auto& c : cases) {
    const Mesh* tm = c.first;
    const double alpha = c.second;
    const auto f = flatten(*tm);
    auto run = [&](std::size_t window, Uv_store<Mesh>& uv) {
      uv = f.uv;
      const QD::Optimization_result o = QD::optimize_flattening(
          *tm, uv.pmap(),
          QD::parameters::anderson_acceleration(
              window, QD::parameters::area_preservation(alpha, QD::parameters::arap_border(QD::Arap_border::FREE)))
              .number_of_iterations(2000));
      BOOST_REQUIRE_MESSAGE(o, QD::error_message(o.status));
      return o;
    };
    Uv_store<Mesh> plain_uv, fast_uv;
    const QD::Optimization_result plain = run(0, plain_uv), fast = run(5, fast_uv);
    const auto dp = QD::compute_distortion(*tm, plain_uv.pmap_const()),
               df = QD::compute_distortion(*tm, fast_uv.pmap_const());
    BOOST_TEST_MESSAGE((tm == &cap ? "cap" : "wavy strip")
                       << ", area preservation " << alpha << ": plain " << plain.iterations << " iterations, energy "
                       << plain.energy_after << ", A_loc " << dp.local_area_distortion << " %; accelerated "
                       << fast.iterations << " iterations, energy " << fast.energy_after << ", A_loc "
                       << df.local_area_distortion << " %");
    BOOST_TEST(plain.iterations < 2000u);
    BOOST_TEST(fast.iterations < plain.iterations);
    BOOST_TEST(fast.energy_after <= plain.energy_after * (1 + 1e-3));
    BOOST_TEST(df.flipped_faces == 0u);
    BOOST_TEST(!df.overlap);
  }

  // a window outside [0, 100]: INVALID_ARGUMENT, nothing written
  const auto f = flatten(cap);
  for(const double bad : {-1., 101., std::numeric_limits<double>::quiet_NaN()}) {
    Uv_store<Mesh> uv = f.uv;
    const auto before = uv.map;
    BOOST_TEST((QD::optimize_flattening(cap, uv.pmap(), QD::parameters::anderson_acceleration(bad)).status ==
                QD::Error_code::INVALID_ARGUMENT));
    BOOST_TEST((uv.map == before));
  }
}

BOOST_AUTO_TEST_CASE_TEMPLATE(arap_rejects_bad_input, Mesh, Mesh_types)
{
  {
    Mesh empty;
    Uv_store<Mesh> uv;
    BOOST_TEST((QD::optimize_flattening(empty, uv.pmap()).status == QD::Error_code::EMPTY_MESH));
  }
  {
    Soup s;  // a closed octahedron
    s.points = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    s.triangles = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
    const Mesh tm = make<Mesh>(s);
    Uv_store<Mesh> uv;
    for(auto v : vertices(tm)) uv.map[v] = typename Uv_store<Mesh>::Point_2(0, 0);
    BOOST_TEST((QD::optimize_flattening(tm, uv.pmap()).status == QD::Error_code::NO_BORDER));
  }
  {
    const Mesh tm = make<Mesh>(grid(4, 4, bump(0.2)));
    auto f = flatten(tm);
    f.uv.map.begin()->second = typename Uv_store<Mesh>::Point_2(std::numeric_limits<double>::infinity(), 0);
    const auto before = f.uv.map;
    BOOST_TEST((QD::optimize_flattening(tm, f.uv.pmap()).status == QD::Error_code::INVALID_COORDINATES));
    BOOST_TEST((f.uv.map == before));  // nothing written
  }
}
