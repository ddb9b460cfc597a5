// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_OPTIMIZE_FLATTENING_H
#define CGAL_QD_OPTIMIZE_FLATTENING_H

/// \file optimize_flattening.h
/// An as-rigid-as-possible optimisation of a flattening (Liu, Zhang, Xu,
/// Gotsman, Gortler, *A Local/Global Approach to Mesh Parameterization*, SGP
/// 2008), started from a given UV map such as the LPFB+IP of
/// `flatten_patch()`, with the border free, free but pulled to target edge
/// lengths, fixed, or refitted at exact lengths; once the map has no flipped
/// triangle, it never creates one.

#include <CGAL_QD/Error_code.h>
#include <CGAL_QD/Optimization_result.h>
#include <CGAL_QD/flatten_patch.h>
#include <CGAL_QD/length_preserved_free_boundary.h>
#include <CGAL_QD/parameters.h>
#include <CGAL_QD/internal/arap_iteration.h>
#include <CGAL_QD/internal/point_scale.h>
#include <CGAL_QD/internal/validation.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL_QD {

namespace internal {

// the points (u, v, 0) of a map stored by vertex index, as a readable point map
template <class VIM>
struct Planar_point_map
{
  struct Point
  {
    double px, py;
    double x() const { return px; }
    double y() const { return py; }
    double z() const { return 0.; }
  };
  typedef typename boost::property_traits<VIM>::key_type key_type;
  typedef Point value_type;
  typedef Point reference;
  typedef boost::readable_property_map_tag category;
  const std::vector<std::array<double, 2>>* u;
  VIM vim;
  friend Point get(const Planar_point_map& m, const key_type& k)
  {
    const std::array<double, 2>& q = (*m.u)[get(m.vim, k)];
    return Point{q[0], q[1]};
  }
};

// the target length of a border edge: its 3D length (`Edge_length_3`), or a given map's value
template <class Map>
struct Edge_length_from_map
{
  Map map;
  template <class Edge>
  double operator()(const Edge& e) const { return double(get(map, e)); }
};

template <class TriangleMesh, class VPM, class NamedParameters>
Edge_length_3<TriangleMesh, VPM> border_length_functor(const TriangleMesh& tm, const VPM& vpm, const NamedParameters&,
                                                       CGAL::Tag_true /* default */)
{
  return Edge_length_3<TriangleMesh, VPM>{&tm, vpm};
}

template <class TriangleMesh, class VPM, class NamedParameters>
auto border_length_functor(const TriangleMesh&, const VPM&, const NamedParameters& np, CGAL::Tag_false)
{
  auto map = CGAL::parameters::get_parameter(np, internal_np::border_edge_length_map_t());
  return Edge_length_from_map<decltype(map)>{map};
}

} // namespace internal

/// \ingroup PkgCGAL_QDRef
/// improves the flattening `uv` of a triangle patch by the local/global
/// as-rigid-as-possible iteration (Liu et al. 2008): each face takes the
/// rotation that best maps its 3D shape onto its current image, then all
/// vertices move to the positions that best fit the rotated faces (one sparse
/// factorisation, two solves per iteration). Started from LPFB+IP
/// (`flatten_patch()`), it removes most of the area distortion of charts
/// whose LPFB+IP folds or stretches, where the border is far from convex.
///
/// Once the map has no flipped triangle, no step creates one: a step that
/// would flip a face is shortened (halved up to ten times; the iteration stops
/// if no length works). A map that starts with flipped faces may unfold.
///
/// Points and UVs whose largest |coordinate| is beyond [2^-64, 2^64] are
/// optimised scaled by a power of two, which is exact, and the map is scaled
/// back, as in `flatten_patch()`.
///
/// \tparam TriangleMesh a model of `FaceListGraph`
/// \tparam VertexUVMap a model of `ReadWritePropertyMap` from vertices to a 2D
///         point type constructible from two `double`
/// \param tm a connected triangle patch with at least one border loop
/// \param uv the start (read), then the result (written) for every vertex
/// \param np optional named parameters:
///   - `CGAL_QD::parameters::arap_border`: an `Arap_border` (default `LENGTH_PRESERVED`)
///   - `CGAL_QD::parameters::border_edge_length_map`: with `KEEP_LENGTHS` or `LENGTH_PRESERVED`, a
///     readable property map from edges to the target length (a positive `double`) of every border
///     edge; default: the 3D length
///   - `CGAL_QD::parameters::border_length_weight`: with `KEEP_LENGTHS`, the weight of the border
///     edge lengths relative to the cotangent weights of the faces (default 10)
///   - `CGAL_QD::parameters::area_preservation`: a number alpha in [0, 1] (default 0). The local step
///     gives each face the rotation closest to its map J = U diag(s1, s2) V^T, U V^T, with alpha = 0 (ARAP);
///     with alpha > 0 the map U diag(t, 1 / t) V^T of determinant 1, t = (s1 / s2)^(alpha / 2) (at most 2),
///     which keeps a share of the face's anisotropy: the result trades a little shear (L2 stretch) for less
///     area distortion. With alpha = 1 every target is area-preserving with J's own aspect ratio.
///   - `number_of_iterations`: at most this many iterations (default 30); the iteration also stops
///     when one lowers the energy by less than 1e-4 of itself
///   - `CGAL_QD::parameters::number_of_free_iterations`: with `LENGTH_PRESERVED`, at most this many
///     iterations of the free map before its border is fitted (default: `number_of_iterations`); 0 fits the
///     border to the angles of the given map, then `number_of_iterations` fit the interior to it
///   - `CGAL_QD::parameters::anderson_acceleration`: a number m in [0, 100] (default 0). With m > 0, each
///     iteration combines the last m + 1 iterates and their images (Anderson acceleration; Walker and Ni
///     2011, Peng et al. 2018) and takes the combination where it keeps the map flip-free and lowers the
///     energy, the plain step otherwise (the history then starts again): the same fixed point in fewer
///     iterations, each a little dearer (m vectors of the size of the map)
///   - `CGAL_QD::parameters::iteration_callback`: a callable `bool(std::size_t)`, called with the number
///     of iterations done after every iteration (with `LENGTH_PRESERVED`, of the free iteration, before
///     the border is fitted), when `uv` holds the map of that iteration; returning `true` stops the
///     iteration there (`Optimization_result::stopped_by_callback`). It may read `uv`, not write it.
///   - `CGAL_QD::parameters::sparse_solver`: a solver as in `flatten_patch()` (default:
///     `Simplicial_LDLT_solver`, whose two-column solves the iteration repeats; a supernodal
///     factorisation is faster to compute on large patches but slower to solve with)
///   - `vertex_point_map`, `vertex_index_map`
/// \returns an `Optimization_result`: `EMPTY_MESH`, `NOT_TRIANGLE_MESH`,
///          `INVALID_COORDINATES` (a non-finite point or UV), `DEGENERATE_FACE`,
///          `NO_BORDER`, `DEGENERATE_EDGE` (a target length that is not positive and finite),
///          `INVALID_ARGUMENT` (an `area_preservation` outside [0, 1], an `anderson_acceleration` outside
///          [0, 100], a negative or non-finite `number_of_free_iterations`) on invalid input,
///          `SOLVER_FAILED` if the system could not be solved; in those cases nothing is written.
/// \sa `flatten_patch()`
template <class TriangleMesh, class VertexUVMap, class NamedParameters = CGAL::parameters::Default_named_parameters>
Optimization_result optimize_flattening(const TriangleMesh& tm, VertexUVMap uv,
                                        const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename GT::face_descriptor face_descriptor;
  typedef typename boost::property_traits<VertexUVMap>::value_type Point_2;

  Optimization_result result;
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    get_const_property_map(CGAL::vertex_point, tm));
  const auto vim = CGAL::get_initialized_vertex_index_map(tm, np);
  auto solver = internal::unwrap(
      choose_parameter<Simplicial_LDLT_solver>(get_parameter(np, internal_np::sparse_solver_t())));
  internal::Arap_options opt;
  opt.iterations = choose_parameter(get_parameter(np, CGAL::internal_np::number_of_iterations), opt.iterations);
  opt.border = choose_parameter(get_parameter(np, internal_np::arap_border_t()), opt.border);
  opt.border_length_weight =
      choose_parameter(get_parameter(np, internal_np::border_length_weight_t()), opt.border_length_weight);
  opt.area_preservation =
      choose_parameter(get_parameter(np, internal_np::area_preservation_t()), opt.area_preservation);
  const double window = double(choose_parameter(get_parameter(np, internal_np::anderson_acceleration_t()), 0));
  if(!(window >= 0 && window <= 100)) {
    result.status = Error_code::INVALID_ARGUMENT;
    return result;
  }
  opt.anderson_window = static_cast<std::size_t>(window);
  const double free_iterations =
      double(choose_parameter(get_parameter(np, internal_np::number_of_free_iterations_t()), double(opt.iterations)));
  if(!(free_iterations >= 0) || !std::isfinite(free_iterations)) {
    result.status = Error_code::INVALID_ARGUMENT;
    return result;
  }
  if(!(opt.area_preservation >= 0 && opt.area_preservation <= 1)) {
    result.status = Error_code::INVALID_ARGUMENT;
    return result;
  }

  if(faces(tm).empty()) {
    result.status = Error_code::EMPTY_MESH;
    return result;
  }
  const std::size_t nv = num_vertices(tm);
  std::vector<std::array<double, 3>> p(nv);
  std::vector<std::array<double, 2>> u(nv, {0., 0.});
  for(vertex_descriptor v : vertices(tm)) {
    const std::size_t i = get(vim, v);
    p[i] = internal::point_of<TriangleMesh>(v, vpm);
    const Point_2 q = get(uv, v);
    u[i] = {CGAL::to_double(q.x()), CGAL::to_double(q.y())};
    if(!std::isfinite(p[i][0]) || !std::isfinite(p[i][1]) || !std::isfinite(p[i][2]) || !std::isfinite(u[i][0]) ||
       !std::isfinite(u[i][1])) {
      result.status = Error_code::INVALID_COORDINATES;
      return result;
    }
  }
  // points and UVs beyond [2^-64, 2^64] are optimised scaled by a power of two,
  // which is exact (internal/point_scale.h): a chart of a small component of a
  // mesh normalised as a whole can be that small; the map is scaled back
  double scale = 1.;
  {
    double largest = 0;
    for(std::size_t i = 0; i < nv; ++i)
      largest = (std::max)({largest, std::abs(p[i][0]), std::abs(p[i][1]), std::abs(p[i][2]), std::abs(u[i][0]),
                            std::abs(u[i][1])});
    scale = internal::normalizing_scale(largest);
    if(scale != 1.)
      for(std::size_t i = 0; i < nv; ++i) {
        for(int k = 0; k < 3; ++k) p[i][k] *= scale;
        for(int k = 0; k < 2; ++k) u[i][k] *= scale;
      }
  }
  const internal::Scaled_point_map<typename std::remove_const<decltype(vpm)>::type> scaled_vpm{vpm, scale};
  std::vector<std::array<std::size_t, 3>> tri;
  tri.reserve(num_faces(tm));
  for(face_descriptor f : faces(tm)) {
    if(CGAL::halfedges_around_face(halfedge(f, tm), tm).size() != 3) {
      result.status = Error_code::NOT_TRIANGLE_MESH;
      return result;
    }
    const halfedge_descriptor h = halfedge(f, tm);
    tri.push_back({get(vim, source(h, tm)), get(vim, target(h, tm)), get(vim, target(next(h, tm), tm))});
    if(internal::double_area3(p[tri.back()[0]], p[tri.back()[1]], p[tri.back()[2]]) <= 0) {
      result.status = Error_code::DEGENERATE_FACE;
      return result;
    }
  }
  // the 3D lengths of the scaled points (the square of a length of 1e-300
  // is 0), or the lengths given, scaled
  typedef typename CGAL::parameters::is_default_parameter<NamedParameters, internal_np::border_edge_length_map_t>::type
      Lengths_are_3D;
  const auto input_length_of = internal::border_length_functor(tm, scaled_vpm, np, Lengths_are_3D());
  const auto length_of = [&](typename GT::edge_descriptor e) {
    return Lengths_are_3D::value ? input_length_of(e) : scale * input_length_of(e);
  };
  std::vector<std::array<std::size_t, 2>> border_edges;
  std::vector<double> border_length;
  for(halfedge_descriptor h : halfedges(tm))
    if(is_border(opposite(h, tm), tm)) {
      border_edges.push_back({get(vim, source(h, tm)), get(vim, target(h, tm))});
      border_length.push_back(length_of(edge(h, tm)));
      if(!(border_length.back() > 0) || !std::isfinite(border_length.back())) {
        result.status = Error_code::DEGENERATE_EDGE;
        return result;
      }
    }
  if(border_edges.empty()) {
    result.status = Error_code::NO_BORDER;
    return result;
  }
  const Arap_border mode = opt.border;
  internal::Arap_options free_opt = opt;
  if(mode == Arap_border::LENGTH_PRESERVED) {
    free_opt.border = Arap_border::FREE;
    free_opt.iterations = static_cast<std::size_t>((std::min)(free_iterations, 1e9));  // no wrap-around
  }
  const bool no_free_iteration = mode == Arap_border::LENGTH_PRESERVED && free_opt.iterations == 0;
  // with no free iteration, the border is fitted to the given map
  if(!no_free_iteration) {
    if constexpr(CGAL::parameters::is_default_parameter<NamedParameters, internal_np::iteration_callback_t>::value) {
      result = internal::optimize_flattening_impl(nv, tri, p, border_edges, border_length, u, free_opt, solver);
    } else {
      // the map of every iteration written to `uv` for the user's callback
      const auto& user = get_parameter(np, internal_np::iteration_callback_t());
      std::vector<vertex_descriptor> vertex_of(nv);
      for(vertex_descriptor v : vertices(tm)) vertex_of[get(vim, v)] = v;
      const auto callback = [&](std::size_t iterations, const std::vector<std::array<double, 2>>& map) {
        for(std::size_t i = 0; i < nv; ++i) put(uv, vertex_of[i], Point_2(map[i][0] / scale, map[i][1] / scale));
        return bool(user(iterations));
      };
      result = internal::optimize_flattening_impl(nv, tri, p, border_edges, border_length, u, free_opt, solver, callback);
    }
  }
  if(!result) return result;
  if(mode == Arap_border::LENGTH_PRESERVED) {
    // the LPFB whose target angles are the angles of the free map
    std::vector<internal::Uv_pair> border_uv(nv, {0., 0.});
    std::vector<char> on_border(nv, 0);
    typedef typename std::remove_const<decltype(vim)>::type VIM;
    const auto fim = CGAL::get_initialized_face_index_map(tm, np);
    const Free_boundary_result b = internal::length_preserved_free_boundary_impl(
        tm, *faces(tm).begin(), true, GT::null_halfedge(), internal::Indexed_uv_map<VIM>{&border_uv, vim}, scaled_vpm, vim,
        fim, internal::lpfb_options_from(np), [&](vertex_descriptor v) { on_border[get(vim, v)] = 1; },
        internal::Planar_point_map<VIM>{&u, vim}, length_of);
    result.border_status = b.status;
    if(b) {
      // the rigid motion that best puts the new border onto the free map's
      std::vector<std::size_t> ids;
      for(std::size_t i = 0; i < nv; ++i)
        if(on_border[i]) ids.push_back(i);
      double cb[2] = {0., 0.}, cu[2] = {0., 0.};
      for(std::size_t i : ids) {
        cb[0] += border_uv[i].x / ids.size();
        cb[1] += border_uv[i].y / ids.size();
        cu[0] += u[i][0] / ids.size();
        cu[1] += u[i][1] / ids.size();
      }
      double dot = 0, cross = 0;
      for(std::size_t i : ids) {
        const double bx = border_uv[i].x - cb[0], by = border_uv[i].y - cb[1];
        const double ux = u[i][0] - cu[0], uy = u[i][1] - cu[1];
        dot += bx * ux + by * uy;
        cross += bx * uy - by * ux;
      }
      const double n = std::hypot(dot, cross), c = n > 0 ? dot / n : 1., s = n > 0 ? cross / n : 0.;
      for(std::size_t i : ids) {
        const double bx = border_uv[i].x - cb[0], by = border_uv[i].y - cb[1];
        u[i] = {cu[0] + c * bx - s * by, cu[1] + s * bx + c * by};
      }
      opt.border = Arap_border::FIXED;
      const Optimization_result fixed = internal::optimize_flattening_impl(nv, tri, p, border_edges, border_length, u, opt, solver);
      if(!fixed) return fixed;
      if(no_free_iteration) {
        result.energy_before = fixed.energy_before;
        result.input_flipped = fixed.input_flipped;
      }
      result.iterations += fixed.iterations;
      result.shortened_steps += fixed.shortened_steps;
      result.energy_after = fixed.energy_after;
      result.time_ms += fixed.time_ms;
      result.lengths_preserved = true;
    }
  }
  for(vertex_descriptor v : vertices(tm)) put(uv, v, Point_2(u[get(vim, v)][0] / scale, u[get(vim, v)][1] / scale));
  return result;
}

} // namespace CGAL_QD

#endif // CGAL_QD_OPTIMIZE_FLATTENING_H
