// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_VSA_SEGMENTATION_H
#define CGAL_QD_VSA_SEGMENTATION_H

/// \file vsa_segmentation.h
/// Step 1 of the quasi-developable segmentation (paper Section 2): nearly
/// planar charts by error-controlled Variational Shape Approximation (Cohen-
/// Steiner, Alliez, Desbrun, SIGGRAPH 2004), with CGAL's
/// `Variational_shape_approximation` and its L2,1 metric.

#include <CGAL_QD/Error_code.h>
#include <CGAL_QD/parameters.h>
#include <CGAL_QD/internal/charts.h>
#include <CGAL_QD/internal/validation.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/Variational_shape_approximation.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <functional>
#include <queue>
#include <set>
#include <tuple>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL_QD {

/// \ingroup PkgCGAL_QDRef
/// diagnostics of `segment_by_error_controlled_vsa()`.
struct Vsa_result
{
  Error_code status = Error_code::OK;
  std::size_t number_of_charts = 0;
  /// the largest normalised L2,1 error over the charts (see `chart_error`)
  double max_chart_error = 0;
  /// per chart: sum over its faces of area(f) |n_f - n_c|^2, divided by the
  /// chart's area; n_c is the chart's area-weighted mean normal. In [0, 4].
  std::vector<double> chart_error;
  std::vector<double> chart_area;
  /// proxies added beyond the first of each connected component
  std::size_t proxies_added = 0;
  /// whether the tolerance was reached before `max_number_of_proxies`
  bool tolerance_reached = false;
  double time_ms = 0;

  explicit operator bool() const { return status == Error_code::OK; }
};


namespace internal {

// Checks for a mesh to segment: it may be closed, have borders, several
// components or handles, but its faces must be proper triangles.
template <class TriangleMesh, class VPM>
Error_code validate_mesh_to_segment(const TriangleMesh& tm, const VPM& vpm)
{
  typedef boost::graph_traits<TriangleMesh> GT;
  if(faces(tm).empty()) return Error_code::EMPTY_MESH;
  for(typename GT::face_descriptor f : faces(tm))
    if(CGAL::halfedges_around_face(halfedge(f, tm), tm).size() != 3) return Error_code::NOT_TRIANGLE_MESH;
  if(has_non_finite_point<TriangleMesh>(vertices(tm), vpm)) return Error_code::INVALID_COORDINATES;
  if(has_degenerate_face(tm, faces(tm), vpm)) return Error_code::DEGENERATE_FACE;
  return Error_code::OK;
}

// Normalised L2,1 error of every chart, from per-face unit normals and areas.
template <class TriangleMesh, class VPM, class FIM, class ChartOf>
void chart_errors(const TriangleMesh& tm, const VPM& vpm, const FIM& fim, std::size_t n_charts,
                  const ChartOf& chart_of, std::vector<double>& error, std::vector<double>& area)
{
  typedef boost::graph_traits<TriangleMesh> GT;
  std::vector<std::array<double, 3>> normal_sum(n_charts, {0., 0., 0.});
  const std::vector<Face_geometry> geo = face_geometry(tm, vpm, fim);
  area.assign(n_charts, 0.);
  for(typename GT::face_descriptor f : faces(tm)) {
    const std::size_t k = chart_of(f);
    const Face_geometry& d = geo[get(fim, f)];
    for(int i = 0; i < 3; ++i) normal_sum[k][i] += d.area * d.normal[i];
    area[k] += d.area;
  }
  error.assign(n_charts, 0.);
  for(std::size_t k = 0; k < n_charts; ++k) {
    const double l = std::sqrt(normal_sum[k][0] * normal_sum[k][0] + normal_sum[k][1] * normal_sum[k][1] +
                               normal_sum[k][2] * normal_sum[k][2]);
    if(l > 0) for(int i = 0; i < 3; ++i) normal_sum[k][i] /= l;
  }
  for(typename GT::face_descriptor f : faces(tm)) {
    const Face_geometry& d = geo[get(fim, f)];
    const std::size_t k = chart_of(f);
    const double x = d.normal[0] - normal_sum[k][0], y = d.normal[1] - normal_sum[k][1],
                 z = d.normal[2] - normal_sum[k][2];
    error[k] += d.area * (x * x + y * y + z * z);
  }
  for(std::size_t k = 0; k < n_charts; ++k) error[k] = area[k] > 0 ? error[k] / area[k] : 0.;
}

// a property map that stores face values in a vector by face index
template <class Face, class FIM>
struct Indexed_face_writer
{
  typedef Face key_type;
  typedef std::size_t value_type;
  typedef std::size_t reference;
  typedef boost::read_write_property_map_tag category;
  std::vector<std::size_t>* values;
  FIM index;
  friend void put(const Indexed_face_writer& m, const Face& f, std::size_t v) { (*m.values)[get(m.index, f)] = v; }
  friend std::size_t get(const Indexed_face_writer& m, const Face& f) { return (*m.values)[get(m.index, f)]; }
};

// Renumbers chart ids into [0, n) and splits charts that are not connected
// through edges; returns n.
template <class TriangleMesh, class FIM>
std::size_t make_charts_connected(const TriangleMesh& tm, const FIM& fim, std::vector<std::size_t>& chart)
{
  typedef boost::graph_traits<TriangleMesh> GT;
  const std::size_t nf = chart.size();
  std::vector<std::size_t> out(nf, std::size_t(-1));
  std::vector<typename GT::face_descriptor> face_of(nf), queue;
  for(typename GT::face_descriptor f : faces(tm)) face_of[get(fim, f)] = f;
  std::size_t n = 0;
  for(std::size_t s = 0; s < nf; ++s) {
    if(out[s] != std::size_t(-1)) continue;
    out[s] = n;
    queue.assign(1, face_of[s]);
    for(std::size_t q = 0; q < queue.size(); ++q)
      for(typename GT::halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(queue[q], tm), tm)) {
        const typename GT::halfedge_descriptor o = opposite(h, tm);
        if(is_border(o, tm)) continue;
        const std::size_t g = get(fim, face(o, tm));
        if(out[g] == std::size_t(-1) && chart[g] == chart[s]) {
          out[g] = n;
          queue.push_back(face(o, tm));
        }
      }
    ++n;
  }
  chart.swap(out);
  return n;
}

// Merges adjacent charts, cheapest first, while the union stays within the
// tolerance. With S = sum a_f n_f and A = sum a_f over a chart, its normalised
// L2,1 error is 2 - 2|S|/A, so a merge is evaluated in O(1). Incremental
// seeding can put two proxies on one planar region, and VSA never removes one.
// Returns the number of charts; `chart` is renumbered into [0, n).
template <class TriangleMesh, class VPM, class FIM>
std::size_t merge_charts_within_tolerance(const TriangleMesh& tm, const VPM& vpm, const FIM& fim, double tolerance,
                                          std::size_t n, std::vector<std::size_t>& chart)
{
  typedef boost::graph_traits<TriangleMesh> GT;
  std::vector<std::array<double, 4>> sum(n, {0., 0., 0., 0.});  // S, A
  const std::vector<Face_geometry> geo = face_geometry(tm, vpm, fim);
  for(typename GT::face_descriptor f : faces(tm)) {
    const Face_geometry& d = geo[get(fim, f)];
    auto& s = sum[chart[get(fim, f)]];
    for(int i = 0; i < 3; ++i) s[i] += d.area * d.normal[i];
    s[3] += d.area;
  }
  auto merged_error = [&](std::size_t x, std::size_t y) {
    const double sx = sum[x][0] + sum[y][0], sy = sum[x][1] + sum[y][1], sz = sum[x][2] + sum[y][2];
    return 2. - 2. * std::sqrt(sx * sx + sy * sy + sz * sz) / (sum[x][3] + sum[y][3]);
  };
  std::vector<std::size_t> parent(n);
  for(std::size_t i = 0; i < n; ++i) parent[i] = i;
  auto find = [&](std::size_t x) {
    while(parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  std::vector<std::set<std::size_t>> adjacent(n);
  for(typename GT::halfedge_descriptor h : halfedges(tm)) {
    if(is_border_edge(h, tm)) continue;
    const std::size_t x = chart[get(fim, face(h, tm))], y = chart[get(fim, face(opposite(h, tm), tm))];
    if(x != y) adjacent[x].insert(y);
  }
  typedef std::tuple<double, std::size_t, std::size_t> Candidate;
  std::priority_queue<Candidate, std::vector<Candidate>, std::greater<Candidate>> queue;
  for(std::size_t x = 0; x < n; ++x)
    for(std::size_t y : adjacent[x])
      if(x < y) queue.emplace(merged_error(x, y), x, y);
  while(!queue.empty()) {
    const Candidate c = queue.top();
    queue.pop();
    const std::size_t x = std::get<1>(c), y = std::get<2>(c);
    if(find(x) != x || find(y) != y) continue;          // merged since
    if(std::get<0>(c) != merged_error(x, y)) continue;  // stale
    if(std::get<0>(c) > tolerance) break;
    parent[y] = x;
    for(int i = 0; i < 4; ++i) sum[x][i] += sum[y][i];
    for(std::size_t z : adjacent[y]) adjacent[x].insert(z);
    std::set<std::size_t> roots;
    for(std::size_t z : adjacent[x])
      if(find(z) != x) roots.insert(find(z));
    adjacent[x] = roots;
    for(std::size_t z : roots) queue.emplace(merged_error(x, z), (std::min)(x, z), (std::max)(x, z));
  }
  for(std::size_t& k : chart) k = find(k);
  return make_charts_connected(tm, fim, chart);
}

} // namespace internal

/// \ingroup PkgCGAL_QDRef
/// segments `tm` into nearly planar, connected charts by error-controlled
/// Variational Shape Approximation (paper Section 2, step 1): starting from one
/// proxy per connected component, proxies are added where the L2,1 error is
/// worst, each addition followed by relaxation, until every chart's normalised
/// \param tm the triangle mesh
/// \param face_chart the chart id of every face
/// L2,1 error is at most the tolerance. Adjacent charts whose union is still
/// within the tolerance are then merged, cheapest first (incremental seeding
/// can split one planar region). Writes a chart id in `[0, n)` per face.
///
/// The mesh may be closed, have borders, several components or handles.
///
/// \tparam TriangleMesh a model of `FaceListGraph`
/// \tparam FaceChartMap a model of `WritablePropertyMap` with
///         `boost::graph_traits<TriangleMesh>::%face_descriptor` as key and an
///         integral type as value
/// \param np optional named parameters:
///   - `CGAL_QD::parameters::vsa_tolerance`: the largest normalised L2,1 error of a chart (default 0.25,
///     which gives 29 charts on `bunny00` and 13 on `fandisk`)
///   - `max_number_of_proxies`: stop adding proxies beyond this number (default: max(50, faces / 200));
///     `Vsa_result::tolerance_reached` tells whether the tolerance or this cap stopped the addition
///   - `number_of_relaxations`: relaxation iterations after each addition (default 3)
///   - `vertex_point_map`, `face_index_map`
/// \returns a `Vsa_result`; `EMPTY_MESH`, `NOT_TRIANGLE_MESH`, `INVALID_COORDINATES`
///          or `DEGENERATE_FACE` on invalid input, in which case nothing is written.
template <class TriangleMesh, class FaceChartMap,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
Vsa_result segment_by_error_controlled_vsa(const TriangleMesh& tm, FaceChartMap face_chart,
                                           const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::face_descriptor face_descriptor;

  const auto start = std::chrono::steady_clock::now();
  Vsa_result result;
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    get_const_property_map(CGAL::vertex_point, tm));
  const auto fim = CGAL::get_initialized_face_index_map(tm, np);
  const double tolerance = choose_parameter(get_parameter(np, internal_np::vsa_tolerance_t()), 0.25);
  const std::size_t nf = static_cast<std::size_t>(num_faces(tm));
  // the normalised error does not drop below the spread of neighbouring face
  // normals: on a coarse or detailed mesh the tolerance may be out of reach,
  // and the cap keeps the charts at 200 faces on average before the merge-back
  // (at least 50 proxies: small meshes are cheap, and CAD parts have many planes)
  // (every VSA round re-partitions the whole mesh, so the cap bounds the time)
  const std::size_t max_proxies = choose_parameter(get_parameter(np, CGAL::internal_np::max_number_of_proxies),
                                                   (std::max<std::size_t>)(50, nf / 200));
  const std::size_t relaxations = choose_parameter(get_parameter(np, CGAL::internal_np::number_of_relaxations), 3);

  result.status = internal::validate_mesh_to_segment(tm, vpm);
  if(result.status != Error_code::OK) return result;

  typedef typename std::remove_const<decltype(vpm)>::type VPM;
  typedef CGAL::Variational_shape_approximation<TriangleMesh, VPM> VSA;
  typename VSA::Error_metric metric(tm, vpm);
  VSA vsa(tm, vpm, metric);
  vsa.initialize_seeds(CGAL::parameters::seeding_method(CGAL::Surface_mesh_approximation::INCREMENTAL)
                           .max_number_of_proxies(1)
                           .number_of_relaxations(relaxations));
  const std::size_t first_proxies = vsa.number_of_proxies();
  vsa.run(relaxations);

  std::vector<std::size_t> chart(nf);
  auto proxy_of = [&](face_descriptor f) { return chart[get(fim, f)]; };
  const internal::Indexed_face_writer<face_descriptor, typename std::remove_const<decltype(fim)>::type> writer{
      &chart, fim};
  for(;;) {
    vsa.proxy_map(writer);
    internal::chart_errors(tm, vpm, fim, vsa.number_of_proxies(), proxy_of, result.chart_error, result.chart_area);
    const std::size_t violating = static_cast<std::size_t>(
        std::count_if(result.chart_error.begin(), result.chart_error.end(), [&](double e) { return e > tolerance; }));
    if(violating == 0) { result.tolerance_reached = true; break; }
    if(vsa.number_of_proxies() >= max_proxies) break;
    // far from the tolerance, add several proxies per round, spread over the
    // charts in proportion to their error, then relax once
    const std::size_t add = (std::min)(max_proxies - vsa.number_of_proxies(), (std::max<std::size_t>)(1, violating / 2));
    const std::size_t added = add == 1 ? std::size_t(vsa.add_to_furthest_proxies(1, 0))
                                       : vsa.add_proxies_error_diffusion(add);
    if(added == 0) break;
    vsa.run(relaxations);
  }

  std::size_t n = internal::make_charts_connected(tm, fim, chart);
  n = internal::merge_charts_within_tolerance(tm, vpm, fim, tolerance, n, chart);
  internal::chart_errors(tm, vpm, fim, n, proxy_of, result.chart_error, result.chart_area);
  result.number_of_charts = n;
  result.max_chart_error = *std::max_element(result.chart_error.begin(), result.chart_error.end());
  result.proxies_added = vsa.number_of_proxies() - first_proxies;
  typedef typename boost::property_traits<FaceChartMap>::value_type Id;
  for(face_descriptor f : faces(tm)) put(face_chart, f, static_cast<Id>(chart[get(fim, f)]));
  result.time_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return result;
}

} // namespace CGAL_QD

#endif // CGAL_QD_VSA_SEGMENTATION_H
