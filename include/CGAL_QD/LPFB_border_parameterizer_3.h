// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_LPFB_BORDER_PARAMETERIZER_3_H
#define CGAL_QD_LPFB_BORDER_PARAMETERIZER_3_H

/// \file LPFB_border_parameterizer_3.h
/// A border parameterizer for CGAL's Surface_mesh_parameterization package
/// that places the border at its length-preserved free boundary.

#include <CGAL_QD/length_preserved_free_boundary.h>

#include <CGAL/Surface_mesh_parameterization/Error_code.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <boost/graph/graph_traits.hpp>

namespace CGAL_QD {

/// \ingroup PkgCGAL_QDRef
/// places the border vertices of a patch at their length-preserved free
/// boundary (see `compute_length_preserved_free_boundary()`): every border
/// edge keeps its 3D length and the border angles stay as close as possible to
/// the surface angles. A model of CGAL's border parameterizer concept, to be
/// used as `BorderParameterizer` of
/// `CGAL::Surface_mesh_parameterization::Fixed_border_parameterizer_3` and its
/// subclasses, for instance
/// `Discrete_conformal_map_parameterizer_3<TM, CGAL_QD::LPFB_border_parameterizer_3<TM>>`
/// (which is LPFB+IP, the paper's flattening).
///
/// The patch is the connected component of the border halfedge `bhd`; `bhd`
/// names the outer loop. Every border loop of the component is placed and
/// marked as parameterized. Note that CGAL 5.5's `Fixed_border_parameterizer_3`
/// keeps only the loop of `bhd` fixed in its linear system and solves the
/// vertices of the other loops as inner vertices; use `CGAL_QD::flatten_patch()`
/// to keep every loop fixed.
///
/// The border is not convex in general: `is_border_convex()` returns `false`,
/// so the map is not guaranteed to be one-to-one by Tutte's theorem; the
/// distortion measures of CGAL_QD detect flipped triangles and overlaps.
///
/// \tparam TriangleMesh_ a model of `FaceListGraph` with an internal vertex point map
template <class TriangleMesh_>
class LPFB_border_parameterizer_3
{
public:
  typedef TriangleMesh_ Triangle_mesh;
  typedef TriangleMesh_ TriangleMesh;
  typedef typename boost::graph_traits<Triangle_mesh>::vertex_descriptor vertex_descriptor;
  typedef typename boost::graph_traits<Triangle_mesh>::halfedge_descriptor halfedge_descriptor;

  /// \param max_iterations most solver steps
  /// \param constraint_tolerance tolerance on the closure residual divided by the loop length
  /// \param angle_tolerance tolerance on the angle update, in radians
  explicit LPFB_border_parameterizer_3(std::size_t max_iterations = 200, double constraint_tolerance = 1e-11,
                                       double angle_tolerance = 1e-9)
  {
    m_options.max_iterations = max_iterations;
    m_options.constraint_tolerance = constraint_tolerance;
    m_options.angle_tolerance = angle_tolerance;
  }

  /// assigns to every border vertex of the component of `bhd` its position on
  /// the length-preserved free boundary and marks it as parameterized.
  /// \returns `OK`, or the SMP error code closest to the failure; `last_result()`
  /// tells the precise `CGAL_QD::Error_code`.
  template <class VertexUVMap, class VertexIndexMap, class VertexParameterizedMap>
  CGAL::Surface_mesh_parameterization::Error_code parameterize(const Triangle_mesh& mesh,
                                                               halfedge_descriptor bhd, VertexUVMap uvmap,
                                                               VertexIndexMap vimap, VertexParameterizedMap vpmap)
  {
    namespace SMP = CGAL::Surface_mesh_parameterization;
    typedef boost::graph_traits<Triangle_mesh> GT;
    if(bhd == GT::null_halfedge() || !is_border(bhd, mesh)) {
      m_result = Free_boundary_result();
      m_result.status = Error_code::INVALID_BORDER_HALFEDGE;
      return SMP::ERROR_WRONG_PARAMETER;
    }
    typedef typename boost::property_traits<VertexParameterizedMap>::value_type Flag;
    const auto fim = CGAL::get_initialized_face_index_map(mesh);
    m_result = internal::length_preserved_free_boundary_impl(
        mesh, face(opposite(bhd, mesh), mesh), false, bhd, uvmap, get_const_property_map(CGAL::vertex_point, mesh),
        vimap, fim, m_options, [&vpmap](vertex_descriptor v) { put(vpmap, v, Flag(true)); });
    switch(m_result.status) {
      case Error_code::OK: return SMP::OK;
      case Error_code::EMPTY_MESH: return SMP::ERROR_EMPTY_MESH;
      case Error_code::NOT_TRIANGLE_MESH: return SMP::ERROR_NON_TRIANGULAR_MESH;
      case Error_code::NON_MANIFOLD:
      case Error_code::NO_BORDER:
      case Error_code::NOT_A_DISK: return SMP::ERROR_NO_TOPOLOGICAL_DISC;
      case Error_code::SOLVER_FAILED:
      case Error_code::NOT_CONVERGED: return SMP::ERROR_CANNOT_SOLVE_LINEAR_SYSTEM;
      default: return SMP::ERROR_WRONG_PARAMETER;
    }
  }

  /// returns `false`: a length-preserved free boundary is not convex in general.
  bool is_border_convex() const { return false; }

  /// diagnostics of the last call to `parameterize()`
  const Free_boundary_result& last_result() const { return m_result; }

private:
  internal::Lpfb_options m_options;
  Free_boundary_result m_result;
};

} // namespace CGAL_QD

#endif // CGAL_QD_LPFB_BORDER_PARAMETERIZER_3_H
