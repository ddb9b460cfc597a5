// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_EXTRACT_CHART_H
#define CGAL_QD_EXTRACT_CHART_H

/// \file extract_chart.h
/// One chart of a segmentation as a standalone mesh, cut open along the seams
/// with the other charts and along the cut edges inside the chart.

#include <CGAL_QD/Error_code.h>
#include <CGAL_QD/internal/union_find.h>
#include <CGAL_QD/internal/validation.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Default.h>

#include <boost/graph/graph_traits.hpp>

#include <array>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL_QD {
namespace internal {

// The corners of a set of faces grouped into wedges: two corners at the same
// vertex are in one wedge when they are linked through edges interior to the
// set that are not cut. Every wedge becomes one vertex of the cut-open mesh,
// which is then manifold at every vertex whatever the chart looks like (a
// chart touching itself at a vertex, a dangling cut, a chart around a hole).
// Corner 3 i + k is the target of the k-th halfedge of `faces[i]`, starting at
// `halfedge(faces[i], tm)`.
template <class TriangleMesh>
struct Wedges
{
  typedef boost::graph_traits<TriangleMesh> GT;
  std::vector<std::size_t> wedge_of_corner;                        // 3 per face
  std::vector<typename GT::vertex_descriptor> vertex_of_wedge;     // in the input mesh
  std::size_t size() const { return vertex_of_wedge.size(); }
};

// The wedges of `out` numbered in the order of their first corners, from the
// groups of corners `sets`; `vertex_of_corner(c)` is the vertex of corner c.
template <class TriangleMesh, class VertexOfCorner>
void number_wedges(Union_find& sets, Wedges<TriangleMesh>& out, const VertexOfCorner& vertex_of_corner)
{
  const std::size_t nc = sets.size();
  out.wedge_of_corner.assign(nc, 0);
  out.vertex_of_wedge.clear();
  std::vector<std::size_t> id(nc, std::size_t(-1));
  for(std::size_t c = 0; c < nc; ++c) {
    const std::size_t r = sets.find(c);
    if(id[r] == std::size_t(-1)) {
      id[r] = out.vertex_of_wedge.size();
      out.vertex_of_wedge.push_back(vertex_of_corner(c));
    }
    out.wedge_of_corner[c] = id[r];
  }
}

// `local[fim(f)]` is the position of f in `faces`, or -1 for a face that is
// not in the set; `is_cut(h)` tells whether the edge of halfedge h is cut.
template <class TriangleMesh, class FIM, class IsCut>
void compute_wedges(const TriangleMesh& tm, const FIM& fim,
                    const std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor>& faces,
                    const std::vector<long>& local, const IsCut& is_cut, Wedges<TriangleMesh>& out)
{
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  const std::size_t nc = 3 * faces.size();
  Union_find sets(nc);
  // the corner of halfedge h, whose face is in the set
  auto corner = [&](halfedge_descriptor h) {
    const auto f = face(h, tm);
    const halfedge_descriptor h0 = halfedge(f, tm);
    const std::size_t k = h == h0 ? 0 : (h == next(h0, tm) ? 1 : 2);
    return 3 * static_cast<std::size_t>(local[get(fim, f)]) + k;
  };
  for(std::size_t i = 0; i < faces.size(); ++i)
    for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(faces[i], tm), tm)) {
      const halfedge_descriptor o = opposite(h, tm);
      if(is_border(o, tm) || local[get(fim, face(o, tm))] < 0 || is_cut(h)) continue;
      sets.unite(corner(h), corner(prev(o, tm)));  // at target(h)
      sets.unite(corner(prev(h, tm)), corner(o));  // at source(h)
    }
  number_wedges(sets, out, [&](std::size_t c) {
    halfedge_descriptor h = halfedge(faces[c / 3], tm);
    for(std::size_t k = 0; k < c % 3; ++k) h = next(h, tm);
    return target(h, tm);
  });
}

// The corners of every face of a mesh by face index, for `compute_wedges()`
// on many sets of faces of the same mesh: corner 3 i + k (the target of the
// k-th halfedge of face i, starting at `halfedge(face, tm)`) with its
// halfedge and the corner of the opposite halfedge in its face (`none` on the
// mesh border), so that grouping the corners reads arrays instead of walking
// the mesh.
template <class TriangleMesh>
struct Corner_table
{
  typedef boost::graph_traits<TriangleMesh> GT;
  static constexpr std::size_t none = std::size_t(-1);
  std::vector<typename GT::halfedge_descriptor> halfedge_of_corner;
  std::vector<std::size_t> opposite_corner;

  template <class FIM>
  Corner_table(const TriangleMesh& tm, const FIM& fim)
  {
    const std::size_t nf = static_cast<std::size_t>(num_faces(tm));
    halfedge_of_corner.resize(3 * nf);
    opposite_corner.assign(3 * nf, none);
    for(typename GT::face_descriptor f : faces(tm)) {
      int k = 0;
      for(typename GT::halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(f, tm), tm)) {
        if(k == 3) break;  // triangles only
        halfedge_of_corner[3 * static_cast<std::size_t>(get(fim, f)) + std::size_t(k++)] = h;
      }
    }
    for(std::size_t c = 0; c < 3 * nf; ++c) {
      const typename GT::halfedge_descriptor o = opposite(halfedge_of_corner[c], tm);
      if(is_border(o, tm)) continue;
      const auto g = face(o, tm);
      const typename GT::halfedge_descriptor g0 = halfedge(g, tm);
      opposite_corner[c] = 3 * static_cast<std::size_t>(get(fim, g)) + (o == g0 ? 0 : (o == next(g0, tm) ? 1 : 2));
    }
  }
};

// `compute_wedges()` with the corners read from `table` (of `tm` and `fim`):
// the same wedges, numbered the same
template <class TriangleMesh, class FIM, class IsCut>
void compute_wedges(const Corner_table<TriangleMesh>& table, const TriangleMesh& tm, const FIM& fim,
                    const std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor>& faces,
                    const std::vector<long>& local, const IsCut& is_cut, Wedges<TriangleMesh>& out)
{
  const std::size_t nc = 3 * faces.size();
  Union_find sets(nc);
  for(std::size_t i = 0; i < faces.size(); ++i) {
    const std::size_t first = 3 * static_cast<std::size_t>(get(fim, faces[i]));
    for(std::size_t k = 0; k < 3; ++k) {
      const std::size_t o = table.opposite_corner[first + k];
      if(o == Corner_table<TriangleMesh>::none) continue;
      const long j = local[o / 3];
      if(j < 0 || is_cut(table.halfedge_of_corner[first + k])) continue;
      // corner k of face i is the target of its halfedge, the source of the
      // opposite one: the corner before it in its face; and the other way round
      const std::size_t kk = o % 3, base = 3 * static_cast<std::size_t>(j);
      sets.unite(3 * i + k, base + (kk + 2) % 3);
      sets.unite(3 * i + (k + 2) % 3, base + kk);
    }
  }
  number_wedges(sets, out, [&](std::size_t c) {
    return target(table.halfedge_of_corner[3 * static_cast<std::size_t>(get(fim, faces[c / 3])) + c % 3], tm);
  });
}

// faces of chart `chart` in the order of `faces(tm)`, and the local index map
template <class TriangleMesh, class FaceChartMap, class FIM>
void faces_of_chart(const TriangleMesh& tm, const FaceChartMap& face_chart, std::size_t chart, const FIM& fim,
                    std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor>& out,
                    std::vector<long>& local)
{
  out.clear();
  local.assign(num_faces(tm), -1);
  for(auto f : faces(tm))
    if(static_cast<std::size_t>(get(face_chart, f)) == chart) {
      local[get(fim, f)] = static_cast<long>(out.size());
      out.push_back(f);
    }
}

struct Null_output
{
  template <class T> Null_output& operator=(const T&) { return *this; }
  Null_output& operator*() { return *this; }
  Null_output& operator++() { return *this; }
  Null_output& operator++(int) { return *this; }
};

} // namespace internal

/// \ingroup PkgCGAL_QDRef
/// copies the faces of one chart of `tm` into `out`, cut open along the
/// chart's border with the other charts and along the edges marked as cut
/// inside it (the remaining boundary curves of a boundary-based merging, see
/// \param tm the triangle mesh
/// \param face_chart the chart id of every face
/// `Segmentation_result::seam_edges`). A vertex of `tm` gives one vertex of
/// `out` per wedge: per group of its corners in the chart linked by edges that
/// are interior to the chart and not cut. `out` is manifold, even where the
/// chart touches itself at a vertex; it is a disk with holes when the cuts
/// open every handle of the chart, and is then ready for `flatten_patch()`.
///
/// \tparam TriangleMesh a model of `FaceListGraph`
/// \tparam FaceChartMap a model of `ReadablePropertyMap` from faces to an integral chart id
/// \tparam OutputMesh a model of `MutableFaceGraph`, whose points are constructible from three `double`
/// \param chart the id of the chart to copy
/// \param out receives the chart; it is cleared first
/// \param np optional named parameters:
///   - `edge_is_constrained_map`: a readable map from edges of `tm` to `bool`, the cut edges (default: none)
///   - `vertex_to_vertex_output_iterator`: receives a `std::pair` (vertex of `tm`, vertex of `out`) per vertex of `out`
///   - `face_to_face_output_iterator`: receives a `std::pair` (face of `tm`, face of `out`) per face of `out`
///   - `vertex_point_map`, `face_index_map` of `tm`
/// \returns `EMPTY_MESH` when no face has that id, `NON_MANIFOLD` when `out`
///          rejected a face, `OK` otherwise.
template <class TriangleMesh, class FaceChartMap, class OutputMesh,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
Error_code extract_chart(const TriangleMesh& tm, const FaceChartMap& face_chart, std::size_t chart, OutputMesh& out,
                         const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef boost::graph_traits<OutputMesh> OGT;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename GT::face_descriptor face_descriptor;
  typedef typename OGT::vertex_descriptor out_vertex;
  typedef typename OGT::face_descriptor out_face;

  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    get_const_property_map(CGAL::vertex_point, tm));
  const auto fim = CGAL::get_initialized_face_index_map(tm, np);
  const auto cut = choose_parameter(get_parameter(np, CGAL::internal_np::edge_is_constrained),
                                    CGAL::Constant_property_map<typename GT::edge_descriptor, bool>(false));
  auto v2v = choose_parameter<internal::Null_output>(get_parameter(np, CGAL::internal_np::vertex_to_vertex_output_iterator));
  auto f2f = choose_parameter<internal::Null_output>(get_parameter(np, CGAL::internal_np::face_to_face_output_iterator));

  clear(out);
  std::vector<face_descriptor> chart_faces;
  std::vector<long> local;
  internal::faces_of_chart(tm, face_chart, chart, fim, chart_faces, local);
  if(chart_faces.empty()) return Error_code::EMPTY_MESH;
  internal::Wedges<TriangleMesh> wedges;
  internal::compute_wedges(tm, fim, chart_faces, local,
                           [&](halfedge_descriptor h) { return bool(get(cut, edge(h, tm))); }, wedges);

  auto out_vpm = get(CGAL::vertex_point, out);
  typedef typename boost::property_traits<decltype(out_vpm)>::value_type Out_point;
  std::vector<out_vertex> vertex_of_wedge(wedges.size());
  for(std::size_t w = 0; w < wedges.size(); ++w) {
    const std::array<double, 3> p = internal::point_of<TriangleMesh>(wedges.vertex_of_wedge[w], vpm);
    vertex_of_wedge[w] = add_vertex(out);
    put(out_vpm, vertex_of_wedge[w], Out_point(p[0], p[1], p[2]));
    *v2v++ = std::make_pair(wedges.vertex_of_wedge[w], vertex_of_wedge[w]);
  }
  for(std::size_t i = 0; i < chart_faces.size(); ++i) {
    const std::array<out_vertex, 3> tri = {vertex_of_wedge[wedges.wedge_of_corner[3 * i]],
                                           vertex_of_wedge[wedges.wedge_of_corner[3 * i + 1]],
                                           vertex_of_wedge[wedges.wedge_of_corner[3 * i + 2]]};
    const out_face f = CGAL::Euler::add_face(tri, out);
    if(f == OGT::null_face()) {
      clear(out);
      return Error_code::NON_MANIFOLD;
    }
    *f2f++ = std::make_pair(chart_faces[i], f);
  }
  return Error_code::OK;
}

} // namespace CGAL_QD

#endif // CGAL_QD_EXTRACT_CHART_H
