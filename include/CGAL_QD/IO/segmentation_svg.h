// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_IO_SEGMENTATION_SVG_H
#define CGAL_QD_IO_SEGMENTATION_SVG_H

/// \file IO/segmentation_svg.h
/// A picture of a segmented mesh without a 3D viewer: flat-shaded faces in
/// their chart colours, seams in black, seen from the direction that shows the
/// most charts.

#include <CGAL_QD/Error_code.h>
#include <CGAL_QD/IO/chart_palette.h>
#include <CGAL_QD/IO/internal/closed_components.h>
#include <CGAL_QD/IO/internal/view_choice.h>
#include <CGAL_QD/internal/validation.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <ostream>
#include <set>
#include <vector>

namespace CGAL_QD {
namespace IO {

/// \ingroup PkgCGAL_QDRef
/// options of `write_segmentation_SVG()`.
struct Picture_options
{
  double width = 800, height = 800;  ///< the picture, in pixels
  double azimuth = 0.6;    ///< the view direction: turn about the mesh's y axis, taken as up (radians)
  double elevation = 0.35; ///< and above the horizontal plane (radians)
  /// whether the writer chooses the view instead: of the direction above and 18 others around the mesh
  /// (8 turns about y at 35 degrees above and below the horizontal, straight from above and below), the
  /// one from which the most charts can be seen
  bool choose_view = true;
};

/// \ingroup PkgCGAL_QDRef
/// draws `tm` as seen from the direction of `options`, or the one that shows the
/// most charts (orthographic, y up, fitted to the picture): every face
/// flat-shaded in its chart's colour of `chart_palette()` (charts that share a
/// border differ), by a light from the viewer, back faces darker; the faces are sorted
/// back to front by the depth of their centroid and drawn in that order
/// (painter's algorithm), each followed by its seam edges in black, so nearer
/// faces hide farther seams. Every face is outlined in its own colour, 0.6
/// pixel wide, which closes the gaps that anti-aliasing leaves between
/// neighbouring faces. On a closed connected component (no border edge)
/// the faces turned away from the viewer are left out: the faces turned
/// towards it cover them (about half of the faces, and of the file); which
/// side is outside comes from the sign of the component's volume. A
/// component with a border is drawn whole, its inside showing through the
/// border.
///
/// \param out the stream written to
/// \param tm the triangle mesh
/// \param face_chart the chart id of every face
/// \param options the drawing options
/// \param seam_edges the edges to draw in black (`Segmentation_result::seam_edges`)
/// \param np optional: `vertex_point_map`, `vertex_index_map`, `face_index_map`
/// \returns `OK`; `EMPTY_MESH` without faces, `INVALID_COORDINATES` for a non-finite point
///          or a stream that failed
template <class TriangleMesh, class FaceChartMap, class EdgeRange,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
Error_code write_segmentation_SVG(std::ostream& out, const TriangleMesh& tm, const FaceChartMap& face_chart,
                                  const EdgeRange& seam_edges, const Picture_options& options = Picture_options(),
                                  const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::face_descriptor face_descriptor;
  typedef std::array<double, 3> P;
  const auto input_vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                          get_const_property_map(CGAL::vertex_point, tm));
  // drawn scaled by a power of two beyond [2^-64, 2^64], where the normals'
  // cross products overflow (CGAL_QD/internal/point_scale.h)
  const CGAL_QD::internal::Scaled_point_map<typename std::remove_const<decltype(input_vpm)>::type> vpm{
      input_vpm, CGAL_QD::internal::normalizing_scale(CGAL_QD::internal::largest_coordinate(vertices(tm), input_vpm))};
  const auto vim = CGAL::get_initialized_vertex_index_map(tm, np);
  if(faces(tm).empty()) return Error_code::EMPTY_MESH;
  if(internal::has_non_finite_point<TriangleMesh>(vertices(tm), vpm)) return Error_code::INVALID_COORDINATES;

  // the mesh's y axis is up (as in most scanned models); view frame: x right,
  // y up, z toward the viewer. Turn about y by the azimuth, then tilt about x
  // by the elevation (a positive one looks from above).
  internal::View_angles angles{options.azimuth, options.elevation};
  const std::vector<std::array<unsigned char, 3>> palette = chart_palette(tm, face_chart);
  if(options.choose_view) {
    std::vector<P> points(num_vertices(tm));
    for(auto v : vertices(tm)) points[get(vim, v)] = internal::point_of<TriangleMesh>(v, vpm);
    std::vector<std::array<std::size_t, 3>> triangles;
    std::vector<std::size_t> chart;
    for(face_descriptor f : faces(tm)) {
      std::vector<std::size_t> c;
      for(auto v : CGAL::vertices_around_face(halfedge(f, tm), tm)) c.push_back(get(vim, v));
      for(std::size_t k = 1; k + 1 < c.size(); ++k) {  // a fan over a polygon
        triangles.push_back({{c[0], c[k], c[k + 1]}});
        chart.push_back(static_cast<std::size_t>(get(face_chart, f)));
      }
    }
    angles = internal::view_showing_most_charts(points, triangles, chart, palette.size(), angles);
  }
  auto view = [&](const P& p) { return angles.point(p); };
  std::vector<P> q(num_vertices(tm));
  double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
  for(auto v : vertices(tm)) {
    const P p = view(internal::point_of<TriangleMesh>(v, vpm));
    q[get(vim, v)] = p;
    for(int k = 0; k < 2; ++k) lo[k] = (std::min)(lo[k], p[k]), hi[k] = (std::max)(hi[k], p[k]);
  }
  const double margin = 0.05 * (std::min)(options.width, options.height);
  const double span = (std::max)((std::max)(hi[0] - lo[0], hi[1] - lo[1]), 1e-300);
  const double s = (std::min)(options.width, options.height) - 2 * margin;
  auto px = [&](const P& p) {
    return std::array<double, 2>{{margin + (p[0] - lo[0]) / span * s + (s - (hi[0] - lo[0]) / span * s) / 2,
                                  options.height - margin - (p[1] - lo[1]) / span * s -
                                      (s - (hi[1] - lo[1]) / span * s) / 2}};
  };
  std::set<typename GT::edge_descriptor> seam(seam_edges.begin(), seam_edges.end());
  const auto fim = CGAL::get_initialized_face_index_map(tm, np);
  const std::vector<int> outside = internal::outside_of_closed_components(tm, vpm, fim);

  struct Item { double depth; face_descriptor f; int outside; };
  std::vector<Item> items;
  std::vector<P> c;
  for(face_descriptor f : faces(tm)) {
    c.clear();
    for(auto v : CGAL::vertices_around_face(halfedge(f, tm), tm)) c.push_back(q[get(vim, v)]);
    // a face of a closed component only if it faces the viewer
    const int side = outside[static_cast<std::size_t>(get(fim, f))];
    if(side != 0 && c.size() >= 3 && side * internal::screen_normal_z(c) < 0) continue;
    double d = 0;
    for(const P& p : c) d += p[2];
    items.push_back({d / double(c.size()), f, side});
  }
  std::stable_sort(items.begin(), items.end(), [](const Item& a, const Item& b) { return a.depth < b.depth; });

  char buffer[64];
  auto num = [&](double x) {
    std::snprintf(buffer, sizeof buffer, "%.2f", x);
    return std::string(buffer);
  };
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" width=\""
      << num(options.width) << "\" height=\"" << num(options.height) << "\" viewBox=\"0 0 " << num(options.width) << ' '
      << num(options.height) << "\">\n<desc>CGAL_QD segmentation: " << num_faces(tm)
      << " faces in their chart colours, seams in black</desc>\n<rect width=\"100%\" height=\"100%\" fill=\"#fff\"/>\n"
      << "<g stroke-linejoin=\"round\" stroke-width=\"0.6\">\n";
  for(const Item& it : items) {
    c.clear();
    for(auto v : CGAL::vertices_around_face(halfedge(it.f, tm), tm)) c.push_back(q[get(vim, v)]);
    if(c.size() < 3) continue;
    const P u{{c[1][0] - c[0][0], c[1][1] - c[0][1], c[1][2] - c[0][2]}},
        w{{c[2][0] - c[0][0], c[2][1] - c[0][1], c[2][2] - c[0][2]}};
    const P n{{u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]}};
    const double l = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    // the light comes from the viewer; a closed component turned inside out
    // (negative volume) is lit from its outside too
    const double facing = l > 0 ? (it.outside < 0 ? -n[2] : n[2]) / l : 0;
    const double shade = facing >= 0 ? 0.35 + 0.65 * facing : 0.25 + 0.2 * -facing;
    const std::array<unsigned char, 3> base = palette[static_cast<std::size_t>(get(face_chart, it.f))];
    std::snprintf(buffer, sizeof buffer, "#%02x%02x%02x", int(base[0] * shade), int(base[1] * shade),
                  int(base[2] * shade));
    const std::string color = buffer;
    out << "<polygon fill=\"" << color << "\" stroke=\"" << color << "\" points=\"";
    for(std::size_t k = 0; k < c.size(); ++k) {
      const auto a = px(c[k]);
      out << (k ? " " : "") << num(a[0]) << ',' << num(a[1]);
    }
    out << "\"/>\n";
    for(auto h : CGAL::halfedges_around_face(halfedge(it.f, tm), tm)) {
      if(!seam.count(edge(h, tm))) continue;
      const auto a = px(q[get(vim, source(h, tm))]), b = px(q[get(vim, target(h, tm))]);
      out << "<line stroke=\"#000\" stroke-width=\"1\" x1=\"" << num(a[0]) << "\" y1=\"" << num(a[1]) << "\" x2=\""
          << num(b[0]) << "\" y2=\"" << num(b[1]) << "\"/>\n";
    }
  }
  out << "</g>\n</svg>\n";
  return out ? Error_code::OK : Error_code::INVALID_COORDINATES;
}

} // namespace IO
} // namespace CGAL_QD

#endif // CGAL_QD_IO_SEGMENTATION_SVG_H
