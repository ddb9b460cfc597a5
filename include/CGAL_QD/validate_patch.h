// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_VALIDATE_PATCH_H
#define CGAL_QD_VALIDATE_PATCH_H

/// \file validate_patch.h
/// The input checks of CGAL_QD's flattening functions, on their own.

#include <CGAL_QD/Error_code.h>
#include <CGAL_QD/internal/validation.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>

namespace CGAL_QD {

/// \ingroup PkgCGAL_QDRef
/// checks that `tm` is a patch that `compute_length_preserved_free_boundary()`
/// and `flatten_patch()` accept: a connected, manifold triangle mesh of genus 0
/// with at least one border loop, finite coordinates, no zero-length border edge
/// and no degenerate face.
/// \param tm the triangle mesh
/// \param np optional: `vertex_point_map`, `vertex_index_map`, `face_index_map`
/// \returns `Error_code::OK` or the first problem found (see `Error_code`).
template <class TriangleMesh, class NamedParameters = CGAL::parameters::Default_named_parameters>
Error_code validate_patch(const TriangleMesh& tm, const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  if(faces(tm).empty()) return Error_code::EMPTY_MESH;
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    get_const_property_map(CGAL::vertex_point, tm));
  const auto vim = CGAL::get_initialized_vertex_index_map(tm, np);
  const auto fim = CGAL::get_initialized_face_index_map(tm, np);
  internal::Patch<TriangleMesh> patch;
  return internal::collect_and_validate_patch(tm, *faces(tm).begin(), true, vpm, vim, fim, patch);
}

} // namespace CGAL_QD

#endif // CGAL_QD_VALIDATE_PATCH_H
