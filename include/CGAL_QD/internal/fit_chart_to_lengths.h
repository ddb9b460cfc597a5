// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_INTERNAL_FIT_CHART_TO_LENGTHS_H
#define CGAL_QD_INTERNAL_FIT_CHART_TO_LENGTHS_H

// A chart's flattening fitted to target lengths of its border edges, so that
// the two sides of every seam match: exactly where the thresholds allow it,
// else pulled towards the targets as far as the chart's rigidity lets it.

#include <CGAL_QD/chart_criterion.h>
#include <CGAL_QD/optimize_flattening.h>
#include <CGAL_QD/parameters.h>
#include <CGAL_QD/sparse_solvers.h>
#include <CGAL_QD/internal/chart_mesh.h>

#include <array>
#include <cstddef>
#include <vector>

namespace CGAL_QD {
namespace internal {

// The history of the Anderson acceleration of a pull of a chart's border
// towards target lengths (`Arap_border::KEEP_LENGTHS`, below).
// Plain, two thirds of the pulls stop at their 30 iterations; accelerated,
// they come closer to the targets within them. Measured on CGAL's seven
// meshes of doc/segmentation_results.md: 545 instead of 543 of 551 seams
// matched (`elephant` 79 of 79, its worst seam 0.0 % instead of 12.6 %
// apart), one to two seam-smoothing tries fewer on `armadillo` and
// `mannequin-devil` (10 and 15 % less time), the same pieces. A history of 5
// left one `armadillo` seam unmatched; 2 gave `elephant` more zigzag (1.242
// against 1.232).
inline constexpr int seam_pull_anderson_window = 10;

// Fits the flattening `uv` of the chart `sm` (face i on the wedges of
// corners 3i to 3i + 2 of `wedge_of_corner`), which holds its start, to the
// target lengths `border_target` (per corner, of the edge that ends at it;
// read for the border edges): with `exact`, every border edge at exactly its
// target length (the border angles kept as closely as the closure allows,
// the interior fitted again) where the thresholds accept that; otherwise,
// or where they do not, the border pulled towards the targets with
// `pull_weight` (`Arap_border::KEEP_LENGTHS`). `rep` (holding the chart's
// area) receives the measures of the map left in `uv`, or `accepted` false
// where no map could be made or measured (the caller keeps its earlier
// flattening); `write_uv()` is called whenever `uv` holds a map to give.
// The vertices of `sm` must come in a fill-reducing order: the systems are
// factorised in the order of their rows (`Simplicial_LDLT_natural_solver`).
template <class UVMap, class WriteUV>
void fit_chart_to_lengths(Chart_mesh& sm, UVMap uv, const std::vector<std::size_t>& wedge_of_corner,
                          const std::vector<double>& border_target, double pull_weight, bool exact,
                          const Merge_thresholds& thresholds, Chart_report& rep, const WriteUV& write_uv)
{
  typedef Chart_mesh::Vertex_index V;
  typedef Chart_mesh::size_type S;
  const std::size_t n_faces = wedge_of_corner.size() / 3;
  auto goal = sm.template add_property_map<Chart_mesh::Edge_index, double>("e:goal", 0.).first;
  for(std::size_t i = 0; i < n_faces; ++i)
    for(auto h : CGAL::halfedges_around_face(halfedge(Chart_mesh::Face_index(static_cast<S>(i)), sm), sm)) {
      int k = 0;
      while(k < 2 && wedge_of_corner[3 * i + k] != std::size_t(target(h, sm))) ++k;
      put(goal, edge(h, sm), border_target[3 * i + k]);
    }
  rep.number_of_border_loops = number_of_border_loops(sm);
  // the border pulled towards the targets with `weight`
  auto pull = [&](double weight) {
    const Optimization_result o = optimize_flattening(
        sm, uv,
        parameters::sparse_solver(
            Simplicial_LDLT_natural_solver(),
            parameters::arap_border(
                Arap_border::KEEP_LENGTHS,
                parameters::border_edge_length_map(
                    goal, parameters::border_length_weight(
                              weight, parameters::area_preservation(
                                          thresholds.area_preservation,
                                          parameters::anderson_acceleration(seam_pull_anderson_window)))))));
    if(o && measure_chart_flattening(sm, uv, thresholds, rep)) {
      rep.optimized = true;
      write_uv();
    } else {
      rep.accepted = false;
    }
  };
  if(!exact) {
    pull(pull_weight);
    return;
  }
  // first every border edge at exactly its target length; where that leaves
  // the thresholds, the border pulled towards the targets
  auto exact_uv = sm.template add_property_map<V, Chart_kernel::Point_2>("v:exact", Chart_kernel::Point_2(0, 0)).first;
  for(auto v : vertices(sm)) put(exact_uv, v, get(uv, v));
  const Optimization_result e = optimize_flattening(
      sm, exact_uv,
      parameters::sparse_solver(
          Simplicial_LDLT_natural_solver(),
          parameters::arap_border(Arap_border::LENGTH_PRESERVED,
                                  parameters::number_of_free_iterations(
                                      0, parameters::border_edge_length_map(
                                             goal, parameters::area_preservation(thresholds.area_preservation))))));
  Chart_report exact_rep = rep;
  if(e && e.lengths_preserved && measure_chart_flattening(sm, exact_uv, thresholds, exact_rep) &&
     exact_rep.accepted) {
    exact_rep.optimized = exact_rep.lengths_matched = true;
    for(auto v : vertices(sm)) put(uv, v, get(exact_uv, v));
    rep = exact_rep;
    write_uv();
    return;
  }
  pull(pull_weight);
}

} // namespace internal
} // namespace CGAL_QD

#endif // CGAL_QD_INTERNAL_FIT_CHART_TO_LENGTHS_H
