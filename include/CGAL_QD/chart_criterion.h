// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_CHART_CRITERION_H
#define CGAL_QD_CHART_CRITERION_H

/// \file chart_criterion.h
/// How the segmentation flattens one chart and decides whether it is within
/// the thresholds: `Chart_criterion` and the `Chart_report` of a chart (the
/// evaluator that applies them is in internal/chart_evaluator.h).

#include <CGAL_QD/Error_code.h>
#include <CGAL_QD/optimize_flattening.h>
#include <CGAL_QD/parameters.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <cstddef>

namespace CGAL_QD {

/// \ingroup PkgCGAL_QDRef
/// how the segmentation flattens a chart and decides whether it is within the thresholds.
enum class Chart_criterion
{
  /// the paper's (Section 4.2): the LPFB+IP flattening, accepted when A(Omega) <= `max_area_distortion`,
  /// L2 <= `max_l2_stretch` and there is no overlap
  LPFB_IP,
  /// LPFB+IP, then the free-boundary ARAP of `optimize_flattening()` started from it, with every face's
  /// target keeping the share `area_preservation` (default 0.5) of its anisotropy; a flattening is
  /// accepted when A(Omega) <= `max_area_distortion`, L2 <= `max_l2_stretch`, A_loc <=
  /// `max_local_area_distortion` and there is no overlap. LPFB+IP is the first screen: the optimisation
  /// runs only when LPFB+IP is not accepted (at most 30 iterations in a trial, which gives up where A_loc
  /// after k iterations is above (30 / k)^0.6 times the bound; until it converges, at most 100, in
  /// the final flattening, continued up to 300 and started again from LSCM for at most 300 where that is
  /// still not accepted). The final flattening of every chart then gives the two sides of every seam
  /// curve a common length (the mean of their lengths) and gives every border edge its share of it
  /// exactly (`Arap_border::LENGTH_PRESERVED`) where the chart stays within the thresholds, or else
  /// pulls the border towards those lengths (`Arap_border::KEEP_LENGTHS`); where the sides of curves
  /// still differ, up to 6 rounds pull the borders of their charts towards the mean with a weight of
  /// 30, each chart as far as its rigidity allows, and those charts are fitted again. The splitting and the
  /// merging of `segment_quasi_developable()` accept a chart only 5 % below `max_local_area_distortion`,
  /// which leaves room for this fit and for the seam smoothing; the final charts are measured against the
  /// bound itself.
  LPFB_IP_THEN_ARAP
};

/// \ingroup PkgCGAL_QDRef
/// how one chart flattens, cut open along its seams and cuts.
struct Chart_report
{
  /// `OK`, or why the chart could not be flattened (`NOT_A_DISK` for a chart with a handle, ...)
  Error_code status = Error_code::OK;
  std::size_t number_of_faces = 0;
  std::size_t number_of_border_loops = 0;  ///< of the chart cut open
  double area = 0;                         ///< 3D area
  double area_distortion = 0;              ///< A(Omega), in percent
  double l2_stretch = 0;                   ///< Sander's L2 stretch (not normalised: LPFB keeps the border lengths)
  double local_area_distortion = 0;        ///< A_loc, in percent
  /// the largest |l_2D - l_3D| / l_3D over the border edges of the flattening (with matched lengths, the
  /// seams' common lengths differ from the 3D ones)
  double max_border_length_error = 0;
  bool overlap = false;                    ///< S(Omega): a flipped face, a branch vertex or a border crossing
  /// whether the flattening is the optimised one (`Chart_criterion::LPFB_IP_THEN_ARAP`), not LPFB+IP; in
  /// a rejected merging trial, whether the measures are those of its optimised map, the last it judged; in
  /// a rejected final flattening, whether the flattening nearest the thresholds is an optimised one
  bool optimized = false;
  /// a merging trial that gave its optimisation up, its A_loc too far above the bound to come below it
  /// within the trial's iterations: after how many iterations (0: it did not). `area_distortion` and
  /// `local_area_distortion` are then those of its map at that point; `l2_stretch` (0) and `overlap`
  /// (false) are not measured
  std::size_t given_up_after = 0;
  /// whether every border edge has exactly (up to the border solver's tolerance) its share of the
  /// length common to the two sides of its seam (the final flattening with
  /// `Chart_criterion::LPFB_IP_THEN_ARAP`); LPFB+IP gives them their 3D lengths
  bool lengths_matched = false;
  /// whether the chart is within the thresholds: status `OK`, A(Omega) and L2 at most the thresholds, no overlap
  bool accepted = false;
  /// whether every seam curve along the chart has its two sides within 0.5 % of each other in the
  /// final flattening (`Chart_flattening_result::seam_curves_matched`); true for a chart without seams
  bool seams_matched = true;
  /// the compactness `4 pi A / P^2` of the piece (`chart_compactness()`: 3D area, perimeter along its
  /// border with its cuts counted twice), set by the final flattening; 0 in the trials
  double compactness = 0;
};

namespace internal {

struct Merge_thresholds
{
  double max_area_distortion = 0.10;  // fraction
  double max_l2_stretch = 2.0;
  double max_local_area_distortion = 0.025;  // fraction
  Chart_criterion criterion = Chart_criterion::LPFB_IP_THEN_ARAP;
  // the border of the optimised flattening of a trial: FREE or KEEP_LENGTHS
  Arap_border arap_border = Arap_border::FREE;
  double border_length_weight = 10.;
  // the share of anisotropy kept in the targets of the optimisation (see
  // `CGAL_QD::parameters::area_preservation`)
  double area_preservation = 0.5;
  // the two sides of a cut inside a developable chart develop onto each other:
  // they touch, which is not an overlap
  double overlap_tolerance = 1e-9;
  // the merging tries a curve only where the merged chart keeps this share of
  // the compactness of the less compact of its two charts (see
  // `CGAL_QD::parameters::compactness_ratio`)
  double compactness_ratio = 0.6;
};

template <class TriangleMesh, class NamedParameters>
Merge_thresholds merge_thresholds_from(const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  Merge_thresholds t;
  t.max_area_distortion = choose_parameter(get_parameter(np, internal_np::max_area_distortion_t()), t.max_area_distortion);
  t.max_l2_stretch = choose_parameter(get_parameter(np, internal_np::max_l2_stretch_t()), t.max_l2_stretch);
  t.overlap_tolerance = choose_parameter(get_parameter(np, internal_np::overlap_tolerance_t()), t.overlap_tolerance);
  t.max_local_area_distortion = choose_parameter(get_parameter(np, internal_np::max_local_area_distortion_t()),
                                                 t.max_local_area_distortion);
  t.criterion = choose_parameter(get_parameter(np, internal_np::chart_criterion_t()), t.criterion);
  t.arap_border = choose_parameter(get_parameter(np, internal_np::arap_border_t()), t.arap_border);
  t.border_length_weight =
      choose_parameter(get_parameter(np, internal_np::border_length_weight_t()), t.border_length_weight);
  t.area_preservation = choose_parameter(get_parameter(np, internal_np::area_preservation_t()), t.area_preservation);
  t.compactness_ratio = choose_parameter(get_parameter(np, internal_np::compactness_ratio_t()), t.compactness_ratio);
  return t;
}

// whether the parameters that the library does not clamp are in their ranges
// (the bounds of the criterion: not negative and not NaN; infinity is no bound)
inline bool thresholds_valid(const Merge_thresholds& t)
{
  return t.area_preservation >= 0 && t.area_preservation <= 1 && t.compactness_ratio >= 0 &&
         t.compactness_ratio <= 1 && t.max_area_distortion >= 0 && t.max_l2_stretch >= 0 &&
         t.max_local_area_distortion >= 0;
}

} // namespace internal
} // namespace CGAL_QD

#endif // CGAL_QD_CHART_CRITERION_H
