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
#include <CGAL_QD/internal/normal_vsa.h>
#include <CGAL_QD/internal/smooth_face_normals.h>
#include <CGAL_QD/internal/union_find.h>
#include <CGAL_QD/internal/validation.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/tags.h>
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
#include <utility>
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
  /// chart's area; n_f is the face's normal smoothed over `smoothing_radius`
  /// and n_c the chart's area-weighted mean of them. In [0, 4].
  std::vector<double> chart_error;
  std::vector<double> chart_area;
  /// proxies added beyond the first of each connected component (summed)
  std::size_t proxies_added = 0;
  /// whether every chart of at least `min_chart_area` (its component's) was
  /// within the tolerance before `max_number_of_proxies` was reached
  bool tolerance_reached = false;
  /// the radius over which face normals were averaged: 0.03 times the
  /// diagonal of the bounding box of the face centroids of the connected
  /// component of largest area (each component has its own)
  double smoothing_radius = 0;
  /// charts of that component smaller than this area are not split further:
  /// the square of 0.07 times that diagonal
  double min_chart_area = 0;
  /// the cap that applied: the named parameter, else the sum over the components of
  /// ceil(area / the component's `min_chart_area`)
  std::size_t max_number_of_proxies = 0;
  double time_ms = 0;

  explicit operator bool() const { return status == Error_code::OK; }
};

namespace internal {

// Step 1's scale, relative to the diagonal of the bounding box of the face
// centroids: normals are averaged over geodesic discs of radius 0.03 of it,
// and charts narrower than 0.07 of it (by area) are not split further. On
// elephant from 1.4K to 89K faces and on bunny00 from 19K to 75K faces they
// keep the number of charts within 15 %.
inline constexpr double vsa_smoothing_radius = 0.03;
inline constexpr double vsa_min_chart_size = 0.07;
// normals are not averaged across edges whose dihedral angle turns the
// normal by more than 60 degrees (creases such as a cube's edges)
inline constexpr double vsa_crease_cos = 0.5;

// Normalised L2,1 error of every chart, from per-face unit normals and areas:
// the faces taken in `order` (indices into `geo` and `chart`).
inline void chart_errors(const std::vector<Face_geometry>& geo, const std::vector<std::size_t>& order,
                         const std::vector<std::size_t>& chart, std::size_t n_charts, std::vector<double>& error,
                         std::vector<double>& area)
{
  std::vector<std::array<double, 3>> normal_sum(n_charts, {0., 0., 0.});
  area.assign(n_charts, 0.);
  for(std::size_t f : order) {
    const std::size_t k = chart[f];
    const Face_geometry& d = geo[f];
    for(int i = 0; i < 3; ++i) normal_sum[k][i] += d.area * d.normal[i];
    area[k] += d.area;
  }
  error.assign(n_charts, 0.);
  for(std::size_t k = 0; k < n_charts; ++k) {
    const double l = std::sqrt(normal_sum[k][0] * normal_sum[k][0] + normal_sum[k][1] * normal_sum[k][1] +
                               normal_sum[k][2] * normal_sum[k][2]);
    if(l > 0) for(int i = 0; i < 3; ++i) normal_sum[k][i] /= l;
  }
  for(std::size_t f : order) {
    const Face_geometry& d = geo[f];
    const std::size_t k = chart[f];
    const double x = d.normal[0] - normal_sum[k][0], y = d.normal[1] - normal_sum[k][1],
                 z = d.normal[2] - normal_sum[k][2];
    error[k] += d.area * (x * x + y * y + z * z);
  }
  for(std::size_t k = 0; k < n_charts; ++k) error[k] = area[k] > 0 ? error[k] / area[k] : 0.;
}

// The proxies of step 1 on one connected component: its faces' geometry,
// their neighbours (indices into the same arrays) and their order. Proxies are
// added where the error is worst until every chart of at least
// `min_chart_area` is within `tolerance`, or `cap` proxies are reached.
struct Vsa_proxies
{
  std::vector<std::size_t> proxy_of;  // by face
  std::size_t count = 0;
  std::size_t added = 0;  // beyond the first
  bool tolerance_reached = false;
};

inline Vsa_proxies vsa_proxies(const std::vector<Face_geometry>& geo,
                               const std::vector<std::array<std::size_t, 3>>& next_to,
                               const std::vector<std::size_t>& order, double tolerance, double min_chart_area,
                               std::size_t cap, std::size_t relaxations, bool parallel)
{
  Vsa_proxies out;
  Normal_vsa vsa(geo, next_to, order);
  vsa.fit_in_parallel(parallel);
  vsa.bootstrap();
  const std::size_t first = vsa.number_of_proxies();
  vsa.run(relaxations);
  std::vector<double> error, area;
  for(;;) {
    // the charts' errors from the proxies' last fit where it was to them
    // (the same numbers), else measured over the faces
    if(vsa.fitted_to_charts()) {
      vsa.chart_errors(error, area);
    } else {
      out.proxy_of = vsa.proxy_of();
      chart_errors(geo, order, out.proxy_of, vsa.number_of_proxies(), error, area);
    }
    std::size_t violating = 0;
    for(std::size_t k = 0; k < error.size(); ++k) violating += error[k] > tolerance && area[k] >= min_chart_area ? 1 : 0;
    if(violating == 0) {
      out.tolerance_reached = true;
      break;
    }
    if(vsa.number_of_proxies() >= cap) break;
    // one proxy per chart beyond the tolerance, spread over the charts in
    // proportion to their error, then relax once (every round re-partitions
    // the whole component, so the number of rounds sets the time)
    const std::size_t add = (std::min)(cap - vsa.number_of_proxies(), violating);
    const std::size_t added = add == 1 ? vsa.add_to_furthest_proxies(1, 0) : vsa.add_proxies_error_diffusion(add);
    if(added == 0) break;
    vsa.run(relaxations);
  }
  out.proxy_of = vsa.proxy_of();
  out.count = vsa.number_of_proxies();
  out.added = out.count - first;
  return out;
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
template <class TriangleMesh, class FIM>
std::size_t merge_charts_within_tolerance(const TriangleMesh& tm, const std::vector<Face_geometry>& geo,
                                          const FIM& fim, double tolerance, std::size_t n,
                                          std::vector<std::size_t>& chart)
{
  typedef boost::graph_traits<TriangleMesh> GT;
  std::vector<std::array<double, 4>> sum(n, {0., 0., 0., 0.});  // S, A
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
  Union_find sets(n);
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
    if(sets.find(x) != x || sets.find(y) != y) continue;          // merged since
    if(std::get<0>(c) != merged_error(x, y)) continue;  // stale
    if(std::get<0>(c) > tolerance) break;
    sets.unite(x, y);  // x < y: x stays the root
    for(int i = 0; i < 4; ++i) sum[x][i] += sum[y][i];
    for(std::size_t z : adjacent[y]) adjacent[x].insert(z);
    std::set<std::size_t> roots;
    for(std::size_t z : adjacent[x])
      if(sets.find(z) != x) roots.insert(sets.find(z));
    adjacent[x] = roots;
    for(std::size_t z : roots) queue.emplace(merged_error(x, z), (std::min)(x, z), (std::max)(x, z));
  }
  for(std::size_t& k : chart) k = sets.find(k);
  return make_charts_connected(tm, fim, chart);
}

} // namespace internal

/// \ingroup PkgCGAL_QDRef
/// segments `tm` into nearly planar, connected charts by error-controlled
/// Variational Shape Approximation (paper Section 2, step 1): each connected
/// component is segmented on its own, as if it were alone: starting from one
/// proxy, proxies are added where the L2,1 error is worst, each round of
/// additions followed by relaxation, until every chart's normalised L2,1 error
/// is at most the tolerance. Adjacent charts whose union
/// is still within the tolerance are then merged, cheapest first (incremental
/// seeding can split one planar region). Writes a chart id in `[0, n)` per face.
///
/// The error is measured at the scale of the shape, not of its faces, so that
/// the same shape at different resolutions gives about the same charts. With
/// D the diagonal of the bounding box of the face centroids of each connected
/// component (so that a stray triangle or a second object changes nothing in
/// the others):
///   - the normal of each face is the area-weighted mean of the normals of the
///     faces whose centroids are within 0.03 D of its centroid and reached
///     from it across edges without leaving that ball; edges whose dihedral
///     angle turns the normal by more than 60 degrees are not crossed. Faces
///     with no neighbour that close keep their own normal. The L2,1 metric of
///     the relaxation, the chart errors, the stopping test and the merge use
///     these normals;
///   - a chart whose area is below (0.07 D)^2 is not split further, whatever
///     its error: the tolerance is reached when every larger chart is within it;
///   - the default proxy cap is the sum over the components of ceil(area / (0.07 D)^2).
///
/// The mesh may be closed, have borders, several components or handles.
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag`, `CGAL::Parallel_tag` or
///         `CGAL::Parallel_if_available_tag` (the smoothing of the face normals runs in
///         parallel with TBB; the result is the same)
/// \tparam TriangleMesh a model of `FaceListGraph`
/// \tparam FaceChartMap a model of `WritablePropertyMap` with
///         `boost::graph_traits<TriangleMesh>::%face_descriptor` as key and an
///         integral type as value
/// \param tm the triangle mesh
/// \param face_chart the chart id of every face
/// \param np optional named parameters:
///   - `CGAL_QD::parameters::vsa_tolerance`: the largest normalised L2,1 error of a chart of at least
///     (0.07 D)^2 in area (default 0.25, which gives 25 charts on `bunny00` and 12 on `fandisk`)
///   - `max_number_of_proxies`: stop adding proxies beyond this number (default: the sum over the components
///     of ceil(area / (0.07 D)^2)); with several components, each gets a share of it in proportion to its
///     ceil(area / (0.07 D)^2), at least one proxy;
///     `Vsa_result::tolerance_reached` tells whether the tolerance or this cap stopped the addition
///   - `number_of_relaxations`: relaxation iterations after each round of additions (default 3)
///   - `vertex_point_map`, `face_index_map`
/// \returns a `Vsa_result`; `EMPTY_MESH`, `NOT_TRIANGLE_MESH`, `INVALID_COORDINATES`
///          or `DEGENERATE_FACE` on invalid input, `INVALID_ARGUMENT` for a mesh of
///          2^32 faces or more, in which case nothing is written.
template <class ConcurrencyTag = CGAL::Parallel_if_available_tag, class TriangleMesh, class FaceChartMap,
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
  const std::size_t relaxations = choose_parameter(get_parameter(np, CGAL::internal_np::number_of_relaxations), 3);

  result.status = internal::validate_mesh_to_segment(tm, vpm);
  if(result.status != Error_code::OK) return result;
  if(nf > internal::Normal_vsa::max_faces) {
    result.status = Error_code::INVALID_ARGUMENT;
    return result;
  }

  typedef typename std::remove_const<decltype(fim)>::type FIM;
  const std::vector<internal::Face_geometry> raw = internal::face_geometry(tm, vpm, fim);
  const std::vector<std::array<std::size_t, 3>> next_to = internal::face_neighbours(tm, fim);
  const std::vector<std::size_t> order = internal::faces_in_order(tm, fim);
  // the scale of each connected component's shape: the diagonal of the
  // bounding box of its face centroids (a stray triangle far away, or a
  // second object, changes nothing in the others)
  std::vector<std::size_t> component;
  const std::size_t nc = internal::face_components(next_to, component);
  std::vector<double> component_area(nc, 0.), lo(3 * nc, 0.), hi(3 * nc, 0.);
  std::vector<char> seen(nc, 0);
  for(std::size_t i = 0; i < raw.size(); ++i) {
    const std::size_t c = component[i];
    component_area[c] += raw[i].area;
    for(int k = 0; k < 3; ++k) {
      lo[3 * c + k] = !seen[c] ? raw[i].centroid[k] : (std::min)(lo[3 * c + k], raw[i].centroid[k]);
      hi[3 * c + k] = !seen[c] ? raw[i].centroid[k] : (std::max)(hi[3 * c + k], raw[i].centroid[k]);
    }
    seen[c] = 1;
  }
  std::vector<double> smoothing_radius(nc), min_chart_area(nc);
  std::vector<std::size_t> own_cap(nc);  // ceil(area / (0.07 D)^2), at least 1
  std::size_t geometric_cap = 0, largest = 0;
  for(std::size_t c = 0; c < nc; ++c) {
    const double* l = &lo[3 * c];
    const double* h = &hi[3 * c];
    const double diagonal =
        std::sqrt((h[0] - l[0]) * (h[0] - l[0]) + (h[1] - l[1]) * (h[1] - l[1]) + (h[2] - l[2]) * (h[2] - l[2]));
    smoothing_radius[c] = internal::vsa_smoothing_radius * diagonal;
    min_chart_area[c] = internal::vsa_min_chart_size * diagonal * internal::vsa_min_chart_size * diagonal;
    own_cap[c] = min_chart_area[c] > 0 ? (std::max<std::size_t>)(
                                             1, static_cast<std::size_t>(std::ceil(component_area[c] / min_chart_area[c])))
                                       : 1;
    geometric_cap += own_cap[c];
    if(component_area[c] > component_area[largest]) largest = c;
  }
  result.smoothing_radius = smoothing_radius[largest];
  result.min_chart_area = min_chart_area[largest];
  const std::vector<internal::Face_geometry> geo = internal::smooth_face_normals<ConcurrencyTag>(
      tm, fim, raw, component, smoothing_radius, internal::vsa_crease_cos);
  const std::size_t max_proxies = choose_parameter(get_parameter(np, CGAL::internal_np::max_number_of_proxies),
                                                   (std::max<std::size_t>)(1, geometric_cap));
  result.max_number_of_proxies = max_proxies;
  // each component's cap: its own, or its share of the one given, in
  // proportion to their own ones (at least one proxy each)
  std::vector<std::size_t> cap = own_cap;
  if(nc == 1) {
    cap[0] = max_proxies;
  } else if(!CGAL::parameters::is_default_parameter<NamedParameters,
                                                     CGAL::internal_np::max_number_of_proxies_t>::value) {
    double residual = 0.;
    for(std::size_t c = 0; c < nc; ++c) {
      const double x = residual + double(own_cap[c]) * double(max_proxies) / double(geometric_cap),
                   rounded = std::floor(x + 0.5);
      residual = x - rounded;
      cap[c] = static_cast<std::size_t>((std::min)((std::max)(1., rounded), 1e15));  // a cap of 2^64 - 1 stays finite
    }
  }

  // Each component on its own, as if it were alone: the proxies of a round
  // are shared out in proportion to the charts' L2,1 errors, which grow with
  // the square of a component's size, and every round relaxes every chart,
  // so a component segmented beside others would get a share that depends on
  // them (a large object took the proxies a small one beside it needed).
  const bool parallel = internal::number_of_workers<ConcurrencyTag>() > 1;
  std::vector<std::size_t> chart(nf, 0);
  result.tolerance_reached = true;
  if(nc == 1) {
    internal::Vsa_proxies p =
        internal::vsa_proxies(geo, next_to, order, tolerance, min_chart_area[0], cap[0], relaxations, parallel);
    chart.swap(p.proxy_of);
    result.proxies_added = p.added;
    result.tolerance_reached = p.tolerance_reached;
  } else {
    // the faces of each component in the order of `faces(tm)`, and their
    // index in it
    std::size_t proxies = 0;  // of the components before
    std::vector<std::vector<std::size_t>> members(nc);
    std::vector<std::size_t> local(nf);
    for(std::size_t f : order) {
      local[f] = members[component[f]].size();
      members[component[f]].push_back(f);
    }
    for(std::size_t c = 0; c < nc; ++c) {
      const std::vector<std::size_t>& m = members[c];
      std::vector<internal::Face_geometry> g(m.size());
      std::vector<std::array<std::size_t, 3>> next(m.size());
      std::vector<std::size_t> own_order(m.size());
      for(std::size_t i = 0; i < m.size(); ++i) {
        g[i] = geo[m[i]];
        for(int k = 0; k < 3; ++k) {
          const std::size_t across = next_to[m[i]][k];
          next[i][k] = across == internal::Normal_vsa::none ? across : local[across];
        }
        own_order[i] = i;
      }
      const internal::Vsa_proxies p =
          internal::vsa_proxies(g, next, own_order, tolerance, min_chart_area[c], cap[c], relaxations, parallel);
      for(std::size_t i = 0; i < m.size(); ++i) chart[m[i]] = proxies + p.proxy_of[i];
      proxies += p.count;
      result.proxies_added += p.added;
      result.tolerance_reached = result.tolerance_reached && p.tolerance_reached;
    }
  }

  std::size_t n = internal::make_charts_connected(tm, fim, chart);
  n = internal::merge_charts_within_tolerance(tm, geo, fim, tolerance, n, chart);
  internal::chart_errors(geo, order, chart, n, result.chart_error, result.chart_area);
  result.number_of_charts = n;
  result.max_chart_error = *std::max_element(result.chart_error.begin(), result.chart_error.end());
  typedef typename boost::property_traits<FaceChartMap>::value_type Id;
  for(face_descriptor f : faces(tm)) put(face_chart, f, static_cast<Id>(chart[get(fim, f)]));
  result.time_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return result;
}

} // namespace CGAL_QD

#endif // CGAL_QD_VSA_SEGMENTATION_H
