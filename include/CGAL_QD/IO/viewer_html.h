// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_IO_VIEWER_HTML_H
#define CGAL_QD_IO_VIEWER_HTML_H

/// \file IO/viewer_html.h
/// A segmentation to look at before cutting: one HTML file that opens offline
/// in a browser, with the mesh in its chart colours on the left and the
/// flattened pieces at true scale on the right, drawn with three.js.

#include <CGAL_QD/Error_code.h>
#include <CGAL_QD/IO/chart_palette.h>
#include <CGAL_QD/IO/internal/assembly_order.h>
#include <CGAL_QD/IO/internal/seam_labels.h>
#include <CGAL_QD/IO/internal/view_choice.h>
#include <CGAL_QD/IO/internal/viewer_page.h>
#include <CGAL_QD/flatten_charts.h>
#include <CGAL_QD/internal/validation.h>
#include <CGAL_QD/pack_charts.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <ostream>
#include <set>
#include <string>
#include <vector>

namespace CGAL_QD {
namespace internal {

inline void write_base64(std::ostream& out, const void* bytes, std::size_t size)
{
  static const char table[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  const unsigned char* b = static_cast<const unsigned char*>(bytes);
  std::string chunk;
  chunk.reserve(4096);
  for(std::size_t i = 0; i < size; i += 3) {
    const unsigned v = (unsigned(b[i]) << 16) | (i + 1 < size ? unsigned(b[i + 1]) << 8 : 0u) |
                       (i + 2 < size ? unsigned(b[i + 2]) : 0u);
    chunk += table[(v >> 18) & 63];
    chunk += table[(v >> 12) & 63];
    chunk += i + 1 < size ? table[(v >> 6) & 63] : '=';
    chunk += i + 2 < size ? table[v & 63] : '=';
    if(chunk.size() >= 4000) {
      out << chunk;
      chunk.clear();
    }
  }
  out << chunk;
}

// the values as little-endian bytes, as the browser's typed arrays read them
template <class T>
void write_base64(std::ostream& out, const std::vector<T>& values)
{
  const std::uint16_t one = 1;
  unsigned char first;
  std::memcpy(&first, &one, 1);
  if(first == 1) {
    write_base64(out, values.data(), values.size() * sizeof(T));
    return;
  }
  std::vector<unsigned char> bytes(values.size() * sizeof(T));
  for(std::size_t i = 0; i < values.size(); ++i) {
    std::memcpy(&bytes[i * sizeof(T)], &values[i], sizeof(T));
    std::reverse(bytes.begin() + i * sizeof(T), bytes.begin() + (i + 1) * sizeof(T));
  }
  write_base64(out, bytes.data(), bytes.size());
}

inline std::string escape_html(const std::string& s)
{
  std::string r;
  for(char c : s) {
    switch(c) {
    case '<': r += "&lt;"; break;
    case '>': r += "&gt;"; break;
    case '&': r += "&amp;"; break;
    case '"': r += "&quot;"; break;
    default: r += c;
    }
  }
  return r;
}

// a string as a JSON string (the page's data sits in a script element, so
// "</" is written "<\/")
inline std::string json_string(const std::string& s)
{
  std::string r = "\"";
  for(std::size_t i = 0; i < s.size(); ++i) {
    const char c = s[i];
    if(c == '"' || c == '\\') r += '\\', r += c;
    else if(c == '/' && i > 0 && s[i - 1] == '<') r += "\\/";
    else if(static_cast<unsigned char>(c) < 0x20) {
      char buffer[8];
      std::snprintf(buffer, sizeof buffer, "\\u%04x", unsigned(c));
      r += buffer;
    } else r += c;
  }
  return r + "\"";
}

inline std::string json_number(double x)
{
  if(!std::isfinite(x)) return "null";
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.9g", x);
  return buffer;
}

} // namespace internal

namespace IO {

/// \ingroup PkgCGAL_QDRef
/// options of `write_viewer_HTML()`.
struct Viewer_options
{
  /// the text of three.js's UMD build (`build/three.min.js` of the npm package `three`, release 159 or
  /// earlier), inlined into the page; required
  std::string three_js;
  /// three.js's licence notice, written next to it in a comment (its MIT licence asks for it)
  std::string three_js_license;
  std::string title = "CGAL_QD segmentation";  ///< the page's title and heading (HTML is escaped)
  /// the printed pattern's units per mesh unit (`Pattern_result::scale`) and their name, to give lengths
  /// and areas on the pattern as well; 0 for none
  double pattern_scale = 0;
  std::string pattern_units = "mm";
};


/// \ingroup PkgCGAL_QDRef
/// writes one HTML file that shows a segmentation in a browser, offline: on
/// the left the mesh in the colours of `chart_palette()` (charts that share a
/// border differ) with its seams drawn, seen first from the direction that
/// shows the most charts and turned by dragging, zoomed with the wheel; on the
/// right the flattened pieces at true scale (packed as by `pack_charts()`,
/// each turned to its smallest enclosing rectangle) with a scale bar, panned
/// by dragging and zoomed with the wheel. Hovering over a piece or a seam on
/// either side highlights it on both, with the piece's id, area, A(Omega), L2
/// stretch and A_loc, or the seam's label (as on the printed pattern, see
/// `write_patterns_SVG()`), its 3D length and the 2D lengths of its two sides;
/// a click keeps the highlight until the next click. The data are typed
/// arrays in base64 and the page draws on demand, so meshes of a few hundred
/// thousand faces stay responsive. three.js is inlined with its licence
/// notice: the file needs nothing else.
///
/// \tparam TriangleMesh a model of `FaceListGraph` whose faces are triangles
/// \tparam FaceChartMap a model of `ReadablePropertyMap` from faces to a chart id in `[0, n)`
/// \param out the stream written to
/// \param tm the triangle mesh
/// \param face_chart the chart id of every face
/// \param flattening the flattening of the charts (a `Segmentation_result`, or the result of
///        `flatten_charts()` or `smooth_segmentation_seams()` for this mesh): its `corner_uv`,
///        `seam_edges` and `charts`
/// \param options the page's options; `options.three_js` is required
/// \param np optional: `vertex_point_map`, `vertex_index_map`, `face_index_map`, `halfedge_index_map`
/// \returns `OK`; `EMPTY_MESH`, `NOT_TRIANGLE_MESH`, `INVALID_COORDINATES` (a non-finite point or UV, or
///          a flattening of another mesh), `INVALID_ARGUMENT` without three.js (or with a text that would
///          close its script element, or a licence with "-->", which would close its comment), or `CANNOT_WRITE`
///          when the stream fails; nothing is written unless the input is valid
template <class TriangleMesh, class FaceChartMap, class NamedParameters = CGAL::parameters::Default_named_parameters>
Error_code write_viewer_HTML(std::ostream& out, const TriangleMesh& tm, const FaceChartMap& face_chart,
                             const Chart_flattening_result<TriangleMesh>& flattening,
                             const Viewer_options& options,
                             const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::face_descriptor face_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef std::array<double, 3> P;
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    get_const_property_map(CGAL::vertex_point, tm));
  const auto vim = CGAL::get_initialized_vertex_index_map(tm, np);
  const auto fim = CGAL::get_initialized_face_index_map(tm, np);
  const auto him = CGAL::get_initialized_halfedge_index_map(tm, np);
  const std::size_t nf = static_cast<std::size_t>(num_faces(tm)), nv = static_cast<std::size_t>(num_vertices(tm));
  if(nf == 0) return Error_code::EMPTY_MESH;
  for(face_descriptor f : faces(tm))
    if(CGAL::halfedges_around_face(halfedge(f, tm), tm).size() != 3) return Error_code::NOT_TRIANGLE_MESH;
  // three.js and its licence go into a script element and a comment, which they must not close
  if(options.three_js.empty() || options.three_js.find("</script") != std::string::npos ||
     options.three_js.find("</SCRIPT") != std::string::npos || options.three_js_license.find("-->") != std::string::npos ||
     options.three_js_license.find("--!>") != std::string::npos)
    return Error_code::INVALID_ARGUMENT;
  if(internal::has_non_finite_point<TriangleMesh>(vertices(tm), vpm) || flattening.corner_uv.size() != 3 * nf)
    return Error_code::INVALID_COORDINATES;
  for(const auto& uv : flattening.corner_uv)
    if(!std::isfinite(uv[0]) || !std::isfinite(uv[1])) return Error_code::INVALID_COORDINATES;

  // the charts, renumbered only if needed: ids in [0, n)
  std::vector<std::size_t> chart(nf);
  std::size_t n = 0;
  for(face_descriptor f : faces(tm)) {
    chart[get(fim, f)] = static_cast<std::size_t>(get(face_chart, f));
    n = (std::max)(n, chart[get(fim, f)] + 1);
  }
  std::vector<std::size_t> faces_of_chart(n, 0);
  for(std::size_t c : chart) ++faces_of_chart[c];

  // the points centred and divided by the largest dimension (float-safe for any finite input)
  std::vector<P> points(nv);
  P low, high;
  low.fill(std::numeric_limits<double>::infinity());
  high.fill(-std::numeric_limits<double>::infinity());
  for(auto v : vertices(tm)) {
    points[get(vim, v)] = internal::point_of<TriangleMesh>(v, vpm);
    for(int c = 0; c < 3; ++c)
      low[c] = (std::min)(low[c], points[get(vim, v)][c]), high[c] = (std::max)(high[c], points[get(vim, v)][c]);
  }
  double extent = 0;
  for(int c = 0; c < 3; ++c) extent = (std::max)(extent, high[c] / 2 - low[c] / 2);
  extent *= 2;  // halves first: high - low may overflow
  if(!(extent > 0) || !std::isfinite(extent)) return Error_code::INVALID_COORDINATES;
  auto unit = [&](const P& p) {
    P r;
    for(int c = 0; c < 3; ++c) r[c] = (p[c] / 2 - (low[c] / 4 + high[c] / 4)) / extent * 2;
    return r;
  };
  std::vector<P> unit_points(nv);
  std::vector<float> positions(3 * nv);
  for(std::size_t i = 0; i < nv; ++i) {
    unit_points[i] = unit(points[i]);
    for(int c = 0; c < 3; ++c) positions[3 * i + c] = static_cast<float>(unit_points[i][c]);
  }
  std::vector<std::uint32_t> triangles(3 * nf), face_chart_ids(nf);
  std::vector<std::array<std::size_t, 3>> tri(nf);
  for(face_descriptor f : faces(tm)) {
    const std::size_t i = get(fim, f);
    int k = 0;
    // corner k: the target of the k-th halfedge from halfedge(f), as in corner_uv
    for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(f, tm), tm)) {
      tri[i][k] = get(vim, target(h, tm));
      triangles[3 * i + k] = static_cast<std::uint32_t>(tri[i][k]);
      ++k;
    }
    face_chart_ids[i] = static_cast<std::uint32_t>(chart[i]);
  }

  // the pieces packed at one scale; back to mesh units, then to the page's unit box
  const Atlas_result atlas = pack_charts(tm, face_chart, flattening.corner_uv, CGAL::parameters::face_index_map(fim));
  if(!atlas) return atlas.status;
  std::vector<float> flat(6 * nf);
  for(std::size_t c = 0; c < 3 * nf; ++c)
    for(int k = 0; k < 2; ++k)
      flat[2 * c + k] = static_cast<float>(atlas.corner_uv[c][k] / atlas.scale / extent);

  // the seam curves with their labels, their sides and lengths
  const std::set<typename GT::edge_descriptor> seam(flattening.seam_edges.begin(), flattening.seam_edges.end());
  const auto curves = internal::labelled_seam_curves(tm, chart, seam, fim, vim, him);
  std::vector<float> seams3, seams2;
  std::vector<std::int32_t> ids3, ids2;
  std::string seam_json = "[";
  auto corner_of = [&](halfedge_descriptor h) {  // the corner of h's target in h's face
    const face_descriptor f = face(h, tm);
    const halfedge_descriptor h0 = halfedge(f, tm);
    return 3 * get(fim, f) + (h == h0 ? 0 : (h == next(h0, tm) ? 1 : 2));
  };
  auto flat_of = [&](std::size_t c) { return std::array<double, 2>{{atlas.corner_uv[c][0] / atlas.scale, atlas.corner_uv[c][1] / atlas.scale}}; };
  for(std::size_t id = 0; id < curves.size(); ++id) {
    double length = 0, sides[2] = {0, 0};
    for(halfedge_descriptor h : curves[id]) {
      const std::size_t vs = get(vim, source(h, tm)), vt = get(vim, target(h, tm));
      length += internal::distance3(points[vs], points[vt]);
      const P &ua = unit_points[vs], &ub = unit_points[vt];
      for(int c = 0; c < 3; ++c) seams3.push_back(static_cast<float>(ua[c]));
      for(int c = 0; c < 3; ++c) seams3.push_back(static_cast<float>(ub[c]));
      ids3.push_back(static_cast<std::int32_t>(id));
      int s = 0;
      for(halfedge_descriptor g : {h, opposite(h, tm)}) {
        const std::size_t to = corner_of(g), from = corner_of(prev(g, tm));
        const std::array<double, 2> p = flat_of(from), q = flat_of(to);
        sides[s++] += std::hypot(q[0] - p[0], q[1] - p[1]);
        for(double x : {p[0], p[1], q[0], q[1]}) seams2.push_back(static_cast<float>(x / extent));
        ids2.push_back(static_cast<std::int32_t>(id));
      }
    }
    const std::size_t a = chart[get(fim, face(curves[id].front(), tm))],
                      b = chart[get(fim, face(opposite(curves[id].front(), tm), tm))];
    seam_json += std::string(id ? "," : "") + "{\"label\":" + internal::json_string(internal::seam_label(id)) +
                 ",\"charts\":[" + std::to_string((std::min)(a, b)) + "," + std::to_string((std::max)(a, b)) +
                 "],\"length\":" + internal::json_number(length) + ",\"sides\":[" + internal::json_number(sides[0]) +
                 "," + internal::json_number(sides[1]) + "]}";
  }
  seam_json += "]";
  // the mesh's own border on the flat side, in black with no seam id
  for(halfedge_descriptor h : halfedges(tm)) {
    if(!is_border(opposite(h, tm), tm) || is_border(h, tm)) continue;
    const std::array<double, 2> p = flat_of(corner_of(prev(h, tm))), q = flat_of(corner_of(h));
    for(double x : {p[0], p[1], q[0], q[1]}) seams2.push_back(static_cast<float>(x / extent));
    ids2.push_back(-1);
  }

  // the view that shows the most charts, as in segmentation.svg
  const internal::View_angles view = internal::view_showing_most_charts(unit_points, tri, chart, n, internal::View_angles());
  const std::vector<std::array<unsigned char, 3>> palette = chart_palette(tm, face_chart);

  std::string chart_json = "[";
  for(std::size_t k = 0; k < n; ++k) {
    const Chart_report r = k < flattening.charts.size() ? flattening.charts[k] : Chart_report();
    chart_json += std::string(k ? "," : "") + "{\"faces\":" + std::to_string(faces_of_chart[k]) +
                  ",\"area\":" + internal::json_number(r.area) +
                  ",\"area_distortion_pct\":" + internal::json_number(r.area_distortion) +
                  ",\"l2_stretch\":" + internal::json_number(r.l2_stretch) +
                  ",\"local_area_distortion_pct\":" + internal::json_number(r.local_area_distortion) +
                  ",\"accepted\":" + (r.accepted ? "true" : "false") + "}";
  }
  chart_json += "]";
  std::string palette_json = "[";
  for(std::size_t k = 0; k < palette.size(); ++k) {
    char buffer[16];
    std::snprintf(buffer, sizeof buffer, "\"#%02x%02x%02x\"", palette[k][0], palette[k][1], palette[k][2]);
    palette_json += std::string(k ? "," : "") + buffer;
  }
  palette_json += "]";

  const std::string title = internal::escape_html(options.title);
  out << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" << title
      << "</title>\n<style>" << internal::viewer_style() << "</style>\n</head>\n<body data-status=\"loading\">\n"
      << "<div id=\"bar\"><b>" << title << "</b><span>" << n << (n == 1 ? " piece, " : " pieces, ") << curves.size()
      << (curves.size() == 1 ? " seam" : " seams")
      << "</span><span>drag to turn or move, wheel to zoom, point at a piece or a seam, click to keep it</span></div>\n"
      << "<div id=\"views\"><div id=\"left\"><div class=\"caption\">the mesh</div></div>"
      << "<div id=\"right\"><div class=\"caption\">the pieces, flat, at true scale</div><div id=\"scale\"></div></div></div>\n"
      << "<div id=\"info\"></div>\n"
      // errors are counted for tests and shown to the reader
      << "<script>\n(function () {\n  var errors = 0;\n  function seen(text) {\n    errors += 1;\n"
      << "    document.body.dataset.errors = String(errors);\n    var info = document.getElementById('info');\n"
      << "    if (info) info.textContent = 'The viewer failed: ' + text;\n  }\n  document.body.dataset.errors = '0';\n"
      << "  window.addEventListener('error', function (e) { seen(e.message); });\n"
      << "  var error = console.error;\n  console.error = function () { seen(Array.prototype.join.call(arguments, ' ')); "
      << "error.apply(console, arguments); };\n"
      // three.js r159 warns on loading that its UMD build is deprecated: not the reader's concern
      << "  window.qdWarn = console.warn;\n  console.warn = function () {};\n})();\n</script>\n"
      << "<!-- three.js, inlined below, is published under this licence:\n" << options.three_js_license << "\n-->\n"
      << "<script>\n" << options.three_js << "\n</script>\n<script>console.warn = window.qdWarn;</script>\n"
      << "<script type=\"application/json\" id=\"qd-data\">{\"extent\":" << internal::json_number(extent)
      << ",\"pattern_scale\":" << internal::json_number(options.pattern_scale)
      << ",\"pattern_units\":" << internal::json_string(options.pattern_units)
      << ",\"view\":{\"azimuth\":" << internal::json_number(view.azimuth)
      << ",\"elevation\":" << internal::json_number(view.elevation) << "},\"charts\":" << chart_json
      << ",\"palette\":" << palette_json << ",\"seams\":" << seam_json;
  // the typed arrays, in base64
  auto field = [&](const char* name, const auto& values) {
    out << ",\"" << name << "\":\"";
    internal::write_base64(out, values);
    out << '"';
  };
  field("positions", positions);
  field("triangles", triangles);
  field("face_chart", face_chart_ids);
  field("flat", flat);
  field("seam_edges_3d", seams3);
  field("seam_ids_3d", ids3);
  field("seam_edges_2d", seams2);
  field("seam_ids_2d", ids2);
  out << "}</script>\n<script>" << internal::viewer_script() << "</script>\n</body>\n</html>\n";
  return out ? Error_code::OK : Error_code::CANNOT_WRITE;
}

} // namespace IO
} // namespace CGAL_QD

#endif // CGAL_QD_IO_VIEWER_HTML_H
