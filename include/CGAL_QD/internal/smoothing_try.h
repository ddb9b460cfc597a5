// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_INTERNAL_SMOOTHING_TRY_H
#define CGAL_QD_INTERNAL_SMOOTHING_TRY_H

// One try of smooth_segmentation_seams(): a copy of a mesh with its charts and
// its cut edges in maps that grow with the mesh, and the copy of the try that
// is kept into the caller's mesh, with its flattening carried over.

#include <CGAL_QD/flatten_charts.h>

#include <CGAL/Dynamic_property_map.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <array>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL_QD {
namespace internal {

// room for `faces` more faces (and the vertices and edges that splitting
// faces and edges to add them brings) in the property arrays of a
// `CGAL::Surface_mesh`, so that they do not double when the smoothing adds
// its first face; other meshes grow as they do
template <class TriangleMesh>
void reserve_for_faces(TriangleMesh&, std::size_t)
{}

template <class P>
void reserve_for_faces(CGAL::Surface_mesh<P>& sm, std::size_t faces)
{
  typedef typename CGAL::Surface_mesh<P>::size_type S;
  sm.reserve(static_cast<S>(sm.number_of_vertices() + faces / 2 + 16),
             static_cast<S>(sm.number_of_edges() + 3 * faces / 2 + 16),
             static_cast<S>(sm.number_of_faces() + faces + 16));
}

template <class TriangleMesh>
class Smoothing_try
{
public:
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename GT::edge_descriptor edge_descriptor;
  typedef typename GT::face_descriptor face_descriptor;
  typedef typename boost::property_map<TriangleMesh, CGAL::dynamic_face_property_t<std::size_t>>::type Chart_map;
  typedef typename boost::property_map<TriangleMesh, CGAL::dynamic_edge_property_t<bool>>::type Edge_flag_map;

  TriangleMesh mesh;
  Chart_map chart;    // of every face
  Edge_flag_map cut;  // the cuts inside charts

  Smoothing_try()
    : chart(get(CGAL::dynamic_face_property_t<std::size_t>(), mesh)),
      cut(get(CGAL::dynamic_edge_property_t<bool>(), mesh))
  {}
  Smoothing_try(const Smoothing_try&) = delete;
  Smoothing_try& operator=(const Smoothing_try&) = delete;

  // this (empty) becomes a copy of `source` with its points multiplied by
  // `scale` (a power of two: exact), with the charts `source_chart` and the
  // cuts where `is_cut(edge)` holds
  template <class SourceChartMap, class IsCut>
  void copy(const TriangleMesh& source, const SourceChartMap& source_chart, const IsCut& is_cut, double scale)
  {
    const Images images = copy_mesh(source, mesh);
    scale_points(mesh, scale);
    for(face_descriptor f : faces(source))
      put(chart, images.face_of(f), static_cast<std::size_t>(get(source_chart, f)));
    for(edge_descriptor e : edges(source)) put(cut, edge(images.halfedge_of(halfedge(e, source)), mesh), bool(is_cut(e)));
  }

  // copies this mesh, made with `copy(..., scale)`, into `out` (empty) in the
  // units of the source (its points divided by `scale`), its charts into
  // `out_chart`, and returns `f`, the flattening of this mesh, for `out`: the
  // UVs of the corners and the seam edges carried over, the points by `out`'s
  // vertex index, UVs, lengths and areas in the units of the source
  template <class OutputChartMap>
  Chart_flattening_result<TriangleMesh> copy_into(TriangleMesh& out, OutputChartMap out_chart,
                                                  Chart_flattening_result<TriangleMesh>&& f, double scale) const
  {
    const Images images = copy_mesh(mesh, out);
    scale_points(out, 1. / scale);
    typedef typename boost::property_traits<OutputChartMap>::value_type Id;
    for(face_descriptor f0 : faces(mesh)) put(out_chart, images.face_of(f0), static_cast<Id>(get(chart, f0)));

    Chart_flattening_result<TriangleMesh> r = std::move(f);
    const auto fim = CGAL::get_initialized_face_index_map(mesh);
    const auto out_fim = CGAL::get_initialized_face_index_map(out);
    std::vector<std::array<double, 2>> corner_uv(r.corner_uv.size(), {{0, 0}});
    for(face_descriptor f0 : faces(mesh)) {
      const face_descriptor f1 = images.face_of(f0);
      // corner k is the target of the k-th halfedge from halfedge(face)
      std::array<halfedge_descriptor, 3> corners;
      std::size_t k = 0;
      for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(f1, out), out))
        if(k < 3) corners[k++] = h;
      k = 0;
      for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(f0, mesh), mesh)) {
        if(k == 3) break;
        const halfedge_descriptor g = images.halfedge_of(h);
        const std::size_t j = g == corners[0] ? 0 : g == corners[1] ? 1 : 2;
        corner_uv[3 * get(out_fim, f1) + j] = r.corner_uv[3 * get(fim, f0) + k];
        ++k;
      }
    }
    r.corner_uv.swap(corner_uv);
    for(edge_descriptor& e : r.seam_edges) e = edge(images.halfedge_of(halfedge(e, mesh)), out);
    r.points = points_by_index(out, get(CGAL::vertex_point, out), CGAL::get_initialized_vertex_index_map(out));
    r.number_of_faces = static_cast<std::size_t>(num_faces(out));
    if(scale != 1.) scale_flattening_back(r, scale, false);
    return r;
  }

private:
  // the points of `m` multiplied by `scale`
  static void scale_points(TriangleMesh& m, double scale)
  {
    if(scale == 1.) return;
    const auto vpm = get(CGAL::vertex_point, m);
    typedef typename boost::property_traits<decltype(vpm)>::value_type Point;
    for(const auto v : vertices(m)) {
      const Point p = get(vpm, v);
      put(vpm, v, Point(p.x() * scale, p.y() * scale, p.z() * scale));
    }
  }

  // the image in a copy of every face and halfedge of its source, by index (a
  // few bytes each: on a mesh of a million faces, lists of pairs and a map of
  // the halfedges took a few hundred megabytes)
  struct Images
  {
    decltype(CGAL::get_initialized_face_index_map(std::declval<const TriangleMesh&>())) fim;
    decltype(CGAL::get_initialized_halfedge_index_map(std::declval<const TriangleMesh&>())) him;
    std::vector<face_descriptor> faces;
    std::vector<halfedge_descriptor> halfedges;
    face_descriptor face_of(face_descriptor f) const { return faces[get(fim, f)]; }
    halfedge_descriptor halfedge_of(halfedge_descriptor h) const { return halfedges[get(him, h)]; }
  };

  // `target` (empty) becomes a copy of `source`
  static Images copy_mesh(const TriangleMesh& source, TriangleMesh& target)
  {
    Images i{CGAL::get_initialized_face_index_map(source), CGAL::get_initialized_halfedge_index_map(source),
             std::vector<face_descriptor>(num_faces(source)), std::vector<halfedge_descriptor>(num_halfedges(source))};
    CGAL::copy_face_graph(source, target,
                          CGAL::parameters::face_to_face_map(boost::make_iterator_property_map(i.faces.begin(), i.fim))
                              .halfedge_to_halfedge_map(boost::make_iterator_property_map(i.halfedges.begin(), i.him)));
    return i;
  }
};

} // namespace internal
} // namespace CGAL_QD

#endif // CGAL_QD_INTERNAL_SMOOTHING_TRY_H
