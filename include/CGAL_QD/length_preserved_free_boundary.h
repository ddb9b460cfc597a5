// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_LENGTH_PRESERVED_FREE_BOUNDARY_H
#define CGAL_QD_LENGTH_PRESERVED_FREE_BOUNDARY_H

/// \file length_preserved_free_boundary.h
/// The length-preserved free boundary (LPFB) of a triangle patch: planar
/// positions of its border vertices that keep every border edge at its 3D
/// length and the border angles as close as possible to the surface angles
/// (C. C. L. Wang, "Computing Length-Preserved Free Boundary for
/// Quasi-Developable Mesh Segmentation", IEEE TVCG 14(1), 2008, Sections 3.1-3.3).

#include <CGAL_QD/Error_code.h>
#include <CGAL_QD/parameters.h>
#include <CGAL_QD/internal/lpfb_solver.h>
#include <CGAL_QD/internal/point_scale.h>
#include <CGAL_QD/internal/validation.h>
#include <CGAL_QD/internal/virtual_cut.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/property_map.h>

#include <boost/graph/graph_traits.hpp>

#include <cmath>
#include <cstddef>
#include <type_traits>
#include <vector>

namespace CGAL_QD {

/// \ingroup PkgCGAL_QDRef
/// diagnostics of `compute_length_preserved_free_boundary()`.
struct Free_boundary_result
{
  Error_code status = Error_code::OK;
  /// solver steps taken (0 for a developable patch, whose surface angles are already feasible)
  std::size_t iterations = 0;
  /// largest constraint residual at the end (closure divided by the loop length, and turning, in radians)
  double constraint_residual = 0;
  /// largest distance between two copies of a vertex on the cut border, divided by the outer loop length
  double coincidence_error = 0;
  /// final objective 1/2 sum (theta_i - a_i)^2 over the corners of the cut border
  double objective = 0;
  /// Pi_L: mean |l_2D - l_3D| over the edges of every border loop
  double boundary_length_error = 0;
  /// Pi_theta: mean |a_v - theta_v| over the vertices of every border loop, in radians
  double boundary_angle_error = 0;
  std::size_t number_of_loops = 0;
  /// vertices on the border loops of the patch (each counted once)
  std::size_t number_of_border_vertices = 0;
  /// 3D length of the virtual cut paths joining the inner loops to the outer loop
  double cut_length = 0;

  explicit operator bool() const { return status == Error_code::OK; }
};

namespace internal {

// Computes the LPFB of the patch of `start_face` and writes the border UVs.
// Shared by the free function and the border parameterizer.
struct No_vertex_visitor
{
  template <class V> void operator()(const V&) const {}
};

// `on_write(v)` is called for every border vertex written to `uv`. The
// target angles are the corner angles measured with `angle_vpm`, the border
// edge lengths `border_length(e)`.
template <class TriangleMesh, class VertexUVMap, class VPM, class VIM, class FIM, class OnWrite, class AngleVPM,
          class BorderLength>
Free_boundary_result length_preserved_free_boundary_impl(
    const TriangleMesh& tm, typename boost::graph_traits<TriangleMesh>::face_descriptor start_face,
    bool require_single_component, typename boost::graph_traits<TriangleMesh>::halfedge_descriptor border,
    VertexUVMap uv, const VPM& vpm, const VIM& vim, const FIM& fim, const Lpfb_options& options,
    OnWrite on_write, const AngleVPM& angle_vpm, const BorderLength& border_length)
{
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename boost::property_traits<VertexUVMap>::value_type Point_2;

  Free_boundary_result result;
  Patch<TriangleMesh> patch;
  result.status = collect_and_validate_patch(tm, start_face, require_single_component, vpm, vim, fim, patch);
  if(result.status != Error_code::OK) return result;

  // the outer loop: the caller's, or the longest
  std::size_t outer = 0;
  if(border == GT::null_halfedge()) {
    for(std::size_t l = 1; l < patch.loops.size(); ++l)
      if(patch.loop_length[l] > patch.loop_length[outer]) outer = l;
  } else {
    if(!is_border(border, tm)) { result.status = Error_code::INVALID_BORDER_HALFEDGE; return result; }
    std::vector<char> in_patch_loop(num_vertices(tm), 0);
    bool found = false;
    halfedge_descriptor h = border;
    std::size_t guard = 0;
    do {
      for(std::size_t l = 0; l < patch.loops.size() && !found; ++l)
        if(patch.loops[l] == h) { outer = l; found = true; }
      h = next(h, tm);
    } while(h != border && !found && ++guard <= 2 * patch.number_of_edges);
    if(!found) { result.status = Error_code::INVALID_BORDER_HALFEDGE; return result; }
  }

  Virtual_cut_border<TriangleMesh> cut;
  if(!build_virtual_cut_border(tm, patch, outer, vpm, vim, cut, angle_vpm, border_length)) {
    result.status = Error_code::NOT_A_DISK;
    return result;
  }
  Lpfb_solver solver(cut.problem);
  const Lpfb_solution sol = solver.solve(options);
  result.iterations = sol.iterations;
  result.constraint_residual = sol.constraint_residual;
  result.objective = sol.objective;
  result.number_of_loops = patch.loops.size();
  result.cut_length = cut.cut_length;
  if(sol.status == Lpfb_status::FAILED) { result.status = Error_code::SOLVER_FAILED; return result; }
  if(sol.status == Lpfb_status::NOT_CONVERGED) { result.status = Error_code::NOT_CONVERGED; return result; }

  // copies of one vertex coincide: average them, and measure how well they do
  const std::size_t n = cut.corner_vertex.size();
  struct Acc { double x = 0, y = 0, theta = 0, a = 0; std::size_t count = 0; double fx = 0, fy = 0; };
  std::vector<Acc> acc(num_vertices(tm));
  for(std::size_t i = 0; i < n; ++i) {
    Acc& a = acc[get(vim, cut.corner_vertex[i])];
    if(a.count == 0) { a.fx = sol.position[i][0]; a.fy = sol.position[i][1]; }
    result.coincidence_error = (std::max)(result.coincidence_error,
                                          std::hypot(sol.position[i][0] - a.fx, sol.position[i][1] - a.fy));
    a.x += sol.position[i][0];
    a.y += sol.position[i][1];
    a.theta += sol.theta[i];
    a.a += cut.problem.target_angle[i];
    ++a.count;
  }
  result.coincidence_error /= cut.loop_length[0];

  double length_error = 0, angle_error = 0;
  std::size_t count = 0;
  for(const auto& loop : cut.loop_halfedges) {
    for(halfedge_descriptor h : loop) {
      const Acc& s = acc[get(vim, source(h, tm))];
      const Acc& t = acc[get(vim, target(h, tm))];
      const double l2 = std::hypot(t.x / t.count - s.x / s.count, t.y / t.count - s.y / s.count);
      length_error += std::abs(l2 - double(border_length(edge(h, tm))));
      angle_error += std::abs(s.a - s.theta);
      ++count;
    }
  }
  result.boundary_length_error = length_error / count;
  result.boundary_angle_error = angle_error / count;
  result.number_of_border_vertices = count;

  for(const auto& loop : cut.loop_halfedges)
    for(halfedge_descriptor h : loop) {
      const vertex_descriptor v = source(h, tm);
      const Acc& a = acc[get(vim, v)];
      put(uv, v, Point_2(a.x / a.count, a.y / a.count));
      on_write(v);
    }
  return result;
}

template <class TriangleMesh, class VertexUVMap, class VPM, class VIM, class FIM,
          class OnWrite = No_vertex_visitor>
Free_boundary_result length_preserved_free_boundary_impl(
    const TriangleMesh& tm, typename boost::graph_traits<TriangleMesh>::face_descriptor start_face,
    bool require_single_component, typename boost::graph_traits<TriangleMesh>::halfedge_descriptor border,
    VertexUVMap uv, const VPM& vpm, const VIM& vim, const FIM& fim, const Lpfb_options& options,
    OnWrite on_write = OnWrite())
{
  return length_preserved_free_boundary_impl(tm, start_face, require_single_component, border, uv, vpm, vim, fim,
                                             options, on_write, vpm, Edge_length_3<TriangleMesh, VPM>{&tm, vpm});
}

template <class NamedParameters>
Lpfb_options lpfb_options_from(const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  Lpfb_options o;
  o.max_iterations = choose_parameter(get_parameter(np, CGAL::internal_np::number_of_iterations),
                                      o.max_iterations);
  o.constraint_tolerance = choose_parameter(get_parameter(np, internal_np::constraint_tolerance_t()),
                                            o.constraint_tolerance);
  o.angle_tolerance = choose_parameter(get_parameter(np, internal_np::angle_tolerance_t()), o.angle_tolerance);
  o.line_search = choose_parameter(get_parameter(np, internal_np::use_line_search_t()), o.line_search);
  return o;
}

// reads the maps from the named parameters; a null `border` means the longest loop
template <class TriangleMesh, class VertexUVMap, class NamedParameters>
Free_boundary_result compute_length_preserved_free_boundary_np(
    const TriangleMesh& tm, typename boost::graph_traits<TriangleMesh>::halfedge_descriptor border,
    VertexUVMap uv, const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const auto input_vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                          get_const_property_map(CGAL::vertex_point, tm));
  const auto vim = CGAL::get_initialized_vertex_index_map(tm, np);
  const auto fim = CGAL::get_initialized_face_index_map(tm, np);
  if(faces(tm).empty()) {
    Free_boundary_result r;
    r.status = Error_code::EMPTY_MESH;
    return r;
  }
  // coordinates beyond [2^-64, 2^64] are solved scaled by a power of two,
  // which is exact (internal/point_scale.h); the UVs and lengths scaled back
  const double scale = normalizing_scale(largest_coordinate(vertices(tm), input_vpm));
  const Scaled_point_map<typename std::remove_const<decltype(input_vpm)>::type> vpm{input_vpm, scale};
  Free_boundary_result r = length_preserved_free_boundary_impl(
      tm, *faces(tm).begin(), true, border, Scaled_uv_map<VertexUVMap>{uv, 1. / scale}, vpm, vim, fim,
      lpfb_options_from(np));
  r.boundary_length_error /= scale;
  r.cut_length /= scale;
  return r;
}

} // namespace internal

/// \ingroup PkgCGAL_QDRef
/// computes the length-preserved free boundary of a triangle patch and writes
/// the planar position of every border vertex, of every border loop, to `uv`.
///
/// The unknowns are the planar inner angles at the border vertices; the solver
/// minimises 1/2 sum (theta_i - a_i)^2 (a_i the surface angle) subject to the
/// closed-path theorem and closure, so every border edge keeps its 3D length
/// exactly. Inner loops are handled by virtual cutting: shortest paths join them
/// to the outer loop and every copy of a vertex on the cut border is kept at one
/// position. The layout is oriented like the mesh: the outer loop runs
/// counter-clockwise when the faces are oriented counter-clockwise.
///
/// Coordinates whose largest |value| is beyond [2^-64, 2^64] are solved scaled
/// by a power of two, which is exact; the UVs, `boundary_length_error` and
/// `cut_length` are in the units of the mesh.
///
/// \tparam TriangleMesh a model of `FaceListGraph`
/// \tparam VertexUVMap a model of `WritablePropertyMap` with
///         `boost::graph_traits<TriangleMesh>::vertex_descriptor` as key type and a
///         `Point_2` (constructible from two `double`) as value type
///
/// \param tm a connected triangle patch of genus 0 with at least one border loop
/// \param border a border halfedge (`is_border(border, tm)`) of the outer loop;
///        the overload without it takes the longest loop (by 3D length)
/// \param uv receives the positions of the border vertices; nothing else is written
/// \param np optional named parameters:
///   - `vertex_point_map` (default: the internal point map of `tm`)
///   - `vertex_index_map`, `face_index_map` (default: initialised internal or dynamic maps)
///   - `number_of_iterations`: most solver steps (default: 200)
///   - `CGAL_QD::parameters::constraint_tolerance`: on closure residual / loop length (default: 1e-11)
///   - `CGAL_QD::parameters::angle_tolerance`: on the angle update, in radians (default: 1e-9)
///   - `CGAL_QD::parameters::use_line_search`: globalise the steps (default: true)
///
/// \returns a `Free_boundary_result` whose `status` is `Error_code::OK` on success;
/// otherwise `EMPTY_MESH`, `NOT_TRIANGLE_MESH`, `INVALID_COORDINATES`, `NON_MANIFOLD`, `NOT_CONNECTED`,
/// `NO_BORDER`, `NOT_A_DISK`, `INVALID_BORDER_HALFEDGE`, `DEGENERATE_EDGE`, `DEGENERATE_FACE`, `NOT_CONVERGED`
/// or `SOLVER_FAILED`, and `uv` is untouched.
///
/// \sa `LPFB_border_parameterizer_3`
template <class TriangleMesh, class VertexUVMap,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
Free_boundary_result compute_length_preserved_free_boundary(
    const TriangleMesh& tm, typename boost::graph_traits<TriangleMesh>::halfedge_descriptor border,
    VertexUVMap uv, const NamedParameters& np = CGAL::parameters::default_values())
{
  if(border == boost::graph_traits<TriangleMesh>::null_halfedge() && !faces(tm).empty()) {
    Free_boundary_result r;
    r.status = Error_code::INVALID_BORDER_HALFEDGE;
    return r;
  }
  return internal::compute_length_preserved_free_boundary_np(tm, border, uv, np);
}

/// \ingroup PkgCGAL_QDRef
/// same as above, with the longest border loop (by 3D length) as outer loop.
template <class TriangleMesh, class VertexUVMap, class T, class Tag, class Base>
Free_boundary_result compute_length_preserved_free_boundary(
    const TriangleMesh& tm, VertexUVMap uv, const CGAL::Named_function_parameters<T, Tag, Base>& np)
{
  return internal::compute_length_preserved_free_boundary_np(
      tm, boost::graph_traits<TriangleMesh>::null_halfedge(), uv, np);
}

/// \ingroup PkgCGAL_QDRef
/// same as above, with default named parameters.
template <class TriangleMesh, class VertexUVMap>
Free_boundary_result compute_length_preserved_free_boundary(const TriangleMesh& tm, VertexUVMap uv)
{
  return compute_length_preserved_free_boundary(tm, uv, CGAL::parameters::default_values());
}

} // namespace CGAL_QD

#endif // CGAL_QD_LENGTH_PRESERVED_FREE_BOUNDARY_H
