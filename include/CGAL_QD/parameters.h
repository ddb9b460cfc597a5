// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_PARAMETERS_H
#define CGAL_QD_PARAMETERS_H

/// \file parameters.h
/// Named parameters of CGAL_QD. They build genuine CGAL named-parameter packs,
/// so they chain with CGAL's own parameters:
/// `CGAL_QD::parameters::constraint_tolerance(1e-12).number_of_iterations(50)`,
/// or, with CGAL's first, `CGAL_QD::parameters::constraint_tolerance(1e-12,
/// CGAL::parameters::number_of_iterations(50))`.

#include <CGAL/Named_function_parameters.h>

namespace CGAL_QD {
namespace internal_np {

struct constraint_tolerance_t {};
struct angle_tolerance_t {};
struct use_line_search_t {};
struct sparse_solver_t {};
struct vsa_tolerance_t {};
struct refine_boundaries_t {};
struct refinement_band_width_t {};
struct denoise_boundaries_t {};
struct denoising_iterations_t {};
struct merge_charts_t {};
struct share_out_small_charts_t {};
struct denoised_point_map_t {};
struct overlap_tolerance_t {};
struct merge_order_t {};
struct atlas_margin_t {};
struct max_area_distortion_t {};
struct max_l2_stretch_t {};
struct needle_threshold_t {};
struct max_local_area_distortion_t {};
struct chart_criterion_t {};
struct arap_border_t {};
struct border_edge_length_map_t {};
struct border_length_weight_t {};
struct area_preservation_t {};
struct iteration_callback_t {};
struct anderson_acceleration_t {};
struct number_of_free_iterations_t {};
struct compactness_ratio_t {};
struct final_flattening_t {};

} // namespace internal_np

namespace parameters {

#define CGAL_QD_ADD_NAMED_PARAMETER(NAME)                                              \
  template <class T>                                                                  \
  CGAL::Named_function_parameters<T, internal_np::NAME##_t> NAME(const T& value)      \
  {                                                                                   \
    return CGAL::Named_function_parameters<T, internal_np::NAME##_t>(value);          \
  }                                                                                   \
  template <class T, class A, class B, class C>                                       \
  CGAL::Named_function_parameters<T, internal_np::NAME##_t,                           \
                                  CGAL::Named_function_parameters<A, B, C>>           \
  NAME(const T& value, const CGAL::Named_function_parameters<A, B, C>& rest)          \
  {                                                                                   \
    return CGAL::Named_function_parameters<T, internal_np::NAME##_t,                  \
                                           CGAL::Named_function_parameters<A, B, C>>( \
        value, rest);                                                                 \
  }

/// relative tolerance on the closure constraints of the length-preserved free
/// boundary (closure residual divided by the loop length). Default: `1e-11`.
CGAL_QD_ADD_NAMED_PARAMETER(constraint_tolerance)
/// tolerance, in radians, on the optimality of the border angles. Default: `1e-9`.
CGAL_QD_ADD_NAMED_PARAMETER(angle_tolerance)
/// whether the border solver globalises its steps by a merit-function line
/// search. Default: `true`. Switching it off gives the plain full-step
/// iteration of the paper, which can oscillate on strongly curved patches.
CGAL_QD_ADD_NAMED_PARAMETER(use_line_search)
/// the solver of `flatten_patch()`'s interior system, a model of its solver
/// concept (default: `Default_flattening_solver`), or of the global step of
/// `optimize_flattening()` (default: `Simplicial_LDLT_solver`).
CGAL_QD_ADD_NAMED_PARAMETER(sparse_solver)
/// the largest normalised L2,1 error of a chart after error-controlled VSA
/// (see `Vsa_result::chart_error`). Default: 0.25.
CGAL_QD_ADD_NAMED_PARAMETER(vsa_tolerance)
/// whether `segment_quasi_developable()` runs the minimum-cut boundary
/// refinement (step 2). Default: `true`.
CGAL_QD_ADD_NAMED_PARAMETER(refine_boundaries)
/// the half-width of the fuzzy band of `refine_chart_boundaries()`, relative to
/// the square root of the smaller chart's area. Default: 0.15.
CGAL_QD_ADD_NAMED_PARAMETER(refinement_band_width)
/// whether `segment_quasi_developable()` runs the least-squares boundary
/// denoising (step 3) on its copy of the points. Default: `false`.
CGAL_QD_ADD_NAMED_PARAMETER(denoise_boundaries)
/// the number of updates of `denoise_chart_boundaries()`. Default: 10.
CGAL_QD_ADD_NAMED_PARAMETER(denoising_iterations)
/// a writable vertex point map that receives the denoised positions in
/// `segment_quasi_developable()` (it may be the mesh's own map, which then
/// changes). Default: none; the denoised positions stay in the result.
CGAL_QD_ADD_NAMED_PARAMETER(denoised_point_map)
/// whether `segment_quasi_developable()` runs the boundary-based merging
/// (step 4). Default: `true`.
CGAL_QD_ADD_NAMED_PARAMETER(merge_charts)
/// whether `segment_quasi_developable()`, after the merging, shares out every
/// small chart (at most 5 % of the mesh's area) that can be shared among two
/// or more of its neighbours: each neighbour takes the faces nearer to its
/// side, and the sharing is kept only where every neighbour so enlarged passes
/// the merging's trial and keeps 0.9 of its compactness. Default: `true`,
/// except with `Chart_criterion::LPFB_IP`, which reproduces the paper's
/// merging alone.
CGAL_QD_ADD_NAMED_PARAMETER(share_out_small_charts)
/// whether `segment_quasi_developable()` flattens the final charts (step 5).
/// Default: `true`. With `false` the result holds the charts and the seams but
/// no flattening (`Chart_flattening_result::flattened` is `false`):
/// `smooth_segmentation_seams()` takes such a result and flattens the charts
/// as they are only where it needs them, which saves a flattening of the whole
/// mesh when the smoothed seams are kept.
CGAL_QD_ADD_NAMED_PARAMETER(final_flattening)
/// the largest area distortion A(Omega) of an accepted chart, as a fraction
/// (0.10 is 10 %). Default: 0.10, the paper's threshold.
CGAL_QD_ADD_NAMED_PARAMETER(max_area_distortion)
/// the largest L2 stretch of an accepted chart. Default: 2.0, the paper's threshold.
CGAL_QD_ADD_NAMED_PARAMETER(max_l2_stretch)
/// the largest local area distortion A_loc of an accepted chart, as a
/// fraction (0.025 is 2.5 %; see `Distortion_report::local_area_distortion`).
/// Default: 0.025. Not used by the paper's criterion (`Chart_criterion::LPFB_IP`).
CGAL_QD_ADD_NAMED_PARAMETER(max_local_area_distortion)
/// how the segmentation flattens and judges a chart, a `CGAL_QD::Chart_criterion`.
/// Default: `Chart_criterion::LPFB_IP_THEN_ARAP`.
CGAL_QD_ADD_NAMED_PARAMETER(chart_criterion)
/// how `optimize_flattening()` treats the border, a `CGAL_QD::Arap_border`.
/// Default: `Arap_border::LENGTH_PRESERVED`. In `segment_quasi_developable()`
/// and `merge_charts_by_boundaries()`, the border of the optimised flattening
/// of a merging trial: `FREE` (the default) or `KEEP_LENGTHS`.
CGAL_QD_ADD_NAMED_PARAMETER(arap_border)
/// the target length of every border edge in `optimize_flattening()` with
/// `Arap_border::KEEP_LENGTHS` or `LENGTH_PRESERVED`: a readable property map
/// from edges to positive `double`s. Default: the 3D lengths.
CGAL_QD_ADD_NAMED_PARAMETER(border_edge_length_map)
/// the weight of the border edge lengths in `optimize_flattening()` with
/// `Arap_border::KEEP_LENGTHS`, relative to the cotangent weights. Default: 10.
/// Larger weights give seams whose two sides differ less in length, and more pieces.
CGAL_QD_ADD_NAMED_PARAMETER(border_length_weight)
/// how much of its anisotropy every face keeps in the targets of the
/// local/global iteration of `optimize_flattening()`, a number in [0, 1]: 0 is
/// ARAP (rotations), 1 area-preserving targets (see `optimize_flattening()`).
/// Default: 0 in `optimize_flattening()`, 0.5 in the segmentation
/// (`Chart_criterion::LPFB_IP_THEN_ARAP`).
CGAL_QD_ADD_NAMED_PARAMETER(area_preservation)
/// a callable `bool(std::size_t iterations)` that `optimize_flattening()`
/// calls after every iteration, with the map of that iteration in its `uv`;
/// returning `true` stops the iteration. Default: none.
CGAL_QD_ADD_NAMED_PARAMETER(iteration_callback)
/// the number of earlier iterates that the Anderson acceleration of
/// `optimize_flattening()` combines (a `std::size_t`; 0: the plain local/global
/// iteration). Default: 0. The segmentation does not use it: its trials stop
/// after at most 30 iterations, and the fixed point that the acceleration
/// reaches sooner can overlap itself where the map of the 30th plain iteration
/// does not.
CGAL_QD_ADD_NAMED_PARAMETER(anderson_acceleration)
/// with `Arap_border::LENGTH_PRESERVED`, the largest number of iterations of
/// the free map in `optimize_flattening()` before its border is fitted at the
/// target lengths (a number >= 0; 0 fits the border to the angles of the given
/// map itself). Default: `number_of_iterations`.
CGAL_QD_ADD_NAMED_PARAMETER(number_of_free_iterations)
/// the ratio of the longest to the shortest edge above which `inspect_mesh()`
/// counts a triangle as a needle. Default: 1000.
CGAL_QD_ADD_NAMED_PARAMETER(needle_threshold)

/// border edges of a UV map closer than this fraction of the diagonal of the
/// border's UV bounding box touch rather than cross (see `compute_distortion()`).
/// Default: 0 in `compute_distortion()`, 1e-9 in the segmentation.
CGAL_QD_ADD_NAMED_PARAMETER(overlap_tolerance)
/// the order of the merging trials, a `CGAL_QD::Merge_order`. Default:
/// `Merge_order::SMALLEST_AREA_FIRST`; `LARGEST_AREA_FIRST` is the paper's.
CGAL_QD_ADD_NAMED_PARAMETER(merge_order)
/// a number rho in [0, 1]: the merging of `merge_charts_by_boundaries()` and
/// `segment_quasi_developable()` tries to remove a curve between two charts
/// only when the merged chart is at least rho times as compact (4 pi area /
/// perimeter^2) as the less compact of the two, so that fewer pieces do not
/// come as sprawling shapes. Default: 0.6; 0 tries every curve (the paper's
/// merging).
CGAL_QD_ADD_NAMED_PARAMETER(compactness_ratio)
/// the free space around each chart in `pack_charts()`, about a fraction of
/// the atlas side. Default: 0.005.
CGAL_QD_ADD_NAMED_PARAMETER(atlas_margin)

#undef CGAL_QD_ADD_NAMED_PARAMETER

} // namespace parameters
} // namespace CGAL_QD

#endif // CGAL_QD_PARAMETERS_H
