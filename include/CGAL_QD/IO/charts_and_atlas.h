// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_IO_CHARTS_AND_ATLAS_H
#define CGAL_QD_IO_CHARTS_AND_ATLAS_H

/// \file IO/charts_and_atlas.h
/// Writers of a segmentation: the mesh with a colour and a chart id per face
/// (PLY), and the mesh with one UV per face corner (OBJ with `vt`).

#include <CGAL_QD/internal/validation.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <boost/graph/graph_traits.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <map>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace CGAL_QD {
namespace IO {

/// \ingroup PkgCGAL_QDRef
/// a colour per chart id, well spread: hues step by the golden angle, and
/// saturation and value alternate, so neighbouring ids differ clearly.
inline std::array<unsigned char, 3> chart_color(std::size_t chart)
{
  const double h = std::fmod(chart * 0.6180339887498949, 1.0) * 6;
  const double s = chart % 2 ? 0.55 : 0.75, v = chart % 3 == 1 ? 0.8 : 0.95;
  const int i = static_cast<int>(h) % 6;
  const double f = h - std::floor(h), p = v * (1 - s), q = v * (1 - s * f), t = v * (1 - s * (1 - f));
  double r = v, g = t, b = p;
  switch(i) {
  case 1: r = q, g = v, b = p; break;
  case 2: r = p, g = v, b = t; break;
  case 3: r = p, g = q, b = v; break;
  case 4: r = t, g = p, b = v; break;
  case 5: r = v, g = p, b = q; break;
  default: break;
  }
  return {{static_cast<unsigned char>(std::lround(255 * r)), static_cast<unsigned char>(std::lround(255 * g)),
           static_cast<unsigned char>(std::lround(255 * b))}};
}

/// \ingroup PkgCGAL_QDRef
/// writes `tm` as an ASCII PLY file with, per face, `red`, `green`, `blue`
/// \param out the stream written to
/// \param tm the triangle mesh
/// \param face_chart the chart id of every face
/// (`uchar`, from `chart_color()`) and `chart` (`int`). CGAL's PLY reader loads
/// them back into a `Surface_mesh` as the face maps `"f:color"` and `"f:chart"`.
///
/// \tparam TriangleMesh a model of `FaceListGraph`
/// \tparam FaceChartMap a model of `ReadablePropertyMap` from faces to an integral chart id
/// \param np optional: `vertex_point_map`, `vertex_index_map`, `stream_precision` (default 17)
/// \returns whether the stream is good after writing
template <class TriangleMesh, class FaceChartMap, class NamedParameters = CGAL::parameters::Default_named_parameters>
bool write_PLY_with_charts(std::ostream& out, const TriangleMesh& tm, const FaceChartMap& face_chart,
                           const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    get_const_property_map(CGAL::vertex_point, tm));
  const auto vim = CGAL::get_initialized_vertex_index_map(tm, np);
  const int precision = choose_parameter(get_parameter(np, CGAL::internal_np::stream_precision), 17);
  out.precision(precision);
  std::vector<std::size_t> index(num_vertices(tm), 0);
  std::size_t nv = 0;
  for(auto v : vertices(tm)) index[get(vim, v)] = nv++;
  out << "ply\nformat ascii 1.0\ncomment written by CGAL_QD: one chart id and colour per face\n"
      << "element vertex " << nv << "\nproperty double x\nproperty double y\nproperty double z\n"
      << "element face " << num_faces(tm) << "\nproperty list uchar int vertex_indices\n"
      << "property uchar red\nproperty uchar green\nproperty uchar blue\nproperty int chart\nend_header\n";
  for(auto v : vertices(tm)) {
    const std::array<double, 3> p = internal::point_of<TriangleMesh>(v, vpm);
    out << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
  }
  for(auto f : faces(tm)) {
    const auto vs = CGAL::vertices_around_face(halfedge(f, tm), tm);
    out << vs.size();
    for(auto v : vs) out << ' ' << index[get(vim, v)];
    const std::size_t chart = static_cast<std::size_t>(get(face_chart, f));
    const std::array<unsigned char, 3> c = chart_color(chart);
    out << ' ' << int(c[0]) << ' ' << int(c[1]) << ' ' << int(c[2]) << ' ' << chart << '\n';
  }
  return bool(out);
}

/// \ingroup PkgCGAL_QDRef
/// writes `tm` as an OBJ file with one `vt` per distinct (vertex, UV) pair, so
/// a vertex on a seam gets one texture coordinate per chart that meets there.
/// \param out the stream written to
/// \param tm the triangle mesh
/// \param corner_uv 3 UVs per face by face index
/// \param material_library the `.mtl` file named by `mtllib` (used only with a material)
/// \param material the material named by `usemtl`, or empty for none
/// `corner_uv` holds 3 UVs per face by face index (`Segmentation_result::corner_uv`
/// or `Atlas_result::corner_uv`): the k-th is that of the target of the k-th
/// halfedge of the face, from `halfedge(f, tm)`. With a non-empty `material`,
/// the file refers to `material_library` and uses that material.
///
/// \param np optional: `vertex_point_map`, `vertex_index_map`, `face_index_map`,
///        `stream_precision` (default 17)
/// \returns whether the stream is good after writing; `false` without writing if
///          a face is not a triangle or `corner_uv` does not have 3 entries per face
template <class TriangleMesh, class NamedParameters = CGAL::parameters::Default_named_parameters>
bool write_OBJ_with_uv(std::ostream& out, const TriangleMesh& tm, const std::vector<std::array<double, 2>>& corner_uv,
                       const std::string& material_library = std::string(),
                       const std::string& material = std::string(),
                       const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    get_const_property_map(CGAL::vertex_point, tm));
  const auto vim = CGAL::get_initialized_vertex_index_map(tm, np);
  const auto fim = CGAL::get_initialized_face_index_map(tm, np);
  const int precision = choose_parameter(get_parameter(np, CGAL::internal_np::stream_precision), 17);
  if(corner_uv.size() != 3 * static_cast<std::size_t>(num_faces(tm))) return false;
  for(auto f : faces(tm))
    if(CGAL::halfedges_around_face(halfedge(f, tm), tm).size() != 3) return false;
  out.precision(precision);
  out << "# written by CGAL_QD: one texture coordinate per vertex and chart\n";
  if(!material.empty()) out << "mtllib " << material_library << '\n';
  std::vector<std::size_t> index(num_vertices(tm), 0);
  std::size_t nv = 0;
  for(auto v : vertices(tm)) {
    index[get(vim, v)] = ++nv;
    const std::array<double, 3> p = internal::point_of<TriangleMesh>(v, vpm);
    out << "v " << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
  }
  std::map<std::pair<std::size_t, std::array<double, 2>>, std::size_t> vt;
  std::vector<std::size_t> corner_vt(corner_uv.size());
  for(auto f : faces(tm)) {
    std::size_t k = 0;
    for(auto h : CGAL::halfedges_around_face(halfedge(f, tm), tm)) {
      const std::size_t c = 3 * get(fim, f) + k++;
      const auto key = std::make_pair(index[get(vim, target(h, tm))], corner_uv[c]);
      auto it = vt.find(key);
      if(it == vt.end()) {
        it = vt.emplace(key, vt.size() + 1).first;
        out << "vt " << corner_uv[c][0] << ' ' << corner_uv[c][1] << '\n';
      }
      corner_vt[c] = it->second;
    }
  }
  if(!material.empty()) out << "usemtl " << material << '\n';
  for(auto f : faces(tm)) {
    out << 'f';
    std::size_t k = 0;
    for(auto h : CGAL::halfedges_around_face(halfedge(f, tm), tm))
      out << ' ' << index[get(vim, target(h, tm))] << '/' << corner_vt[3 * get(fim, f) + k++];
    out << '\n';
  }
  return bool(out);
}

} // namespace IO
} // namespace CGAL_QD

#endif // CGAL_QD_IO_CHARTS_AND_ATLAS_H
