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

  // this (empty) becomes a copy of `source`, with the charts `source_chart` and
  // the cuts where `is_cut(edge)` holds
  template <class SourceChartMap, class IsCut>
  void copy(const TriangleMesh& source, const SourceChartMap& source_chart, const IsCut& is_cut)
  {
    // the image of every face and halfedge, by index (a few bytes each: on a
    // mesh of a million faces, lists of pairs took a hundred megabytes)
    const auto fim = CGAL::get_initialized_face_index_map(source);
    const auto him = CGAL::get_initialized_halfedge_index_map(source);
    std::vector<face_descriptor> face_image(num_faces(source));
    std::vector<halfedge_descriptor> halfedge_image(num_halfedges(source));
    CGAL::copy_face_graph(source, mesh,
                          CGAL::parameters::face_to_face_map(boost::make_iterator_property_map(face_image.begin(), fim))
                              .halfedge_to_halfedge_map(
                                  boost::make_iterator_property_map(halfedge_image.begin(), him)));
    for(face_descriptor f : faces(source))
      put(chart, face_image[get(fim, f)], static_cast<std::size_t>(get(source_chart, f)));
    for(edge_descriptor e : edges(source))
      put(cut, edge(halfedge_image[get(him, halfedge(e, source))], mesh), bool(is_cut(e)));
  }

  // moves this mesh into `out` (empty) by a copy, its charts into
  // `out_chart`, and returns `f`, the flattening of this mesh, for `out`: the
  // UVs of the corners and the seam edges carried over, the points by `out`'s
  // vertex index
  template <class OutputChartMap>
  Chart_flattening_result<TriangleMesh> copy_into(TriangleMesh& out, OutputChartMap out_chart,
                                                  Chart_flattening_result<TriangleMesh>&& f) const
  {
    const auto fim = CGAL::get_initialized_face_index_map(mesh);
    const auto him = CGAL::get_initialized_halfedge_index_map(mesh);
    std::vector<face_descriptor> face_image(num_faces(mesh));
    std::vector<halfedge_descriptor> halfedge_image(num_halfedges(mesh));
    CGAL::copy_face_graph(mesh, out,
                          CGAL::parameters::face_to_face_map(boost::make_iterator_property_map(face_image.begin(), fim))
                              .halfedge_to_halfedge_map(
                                  boost::make_iterator_property_map(halfedge_image.begin(), him)));
    typedef boost::property_traits<OutputChartMap> Id_traits;
    typedef typename Id_traits::value_type Id;
    for(face_descriptor f0 : faces(mesh)) put(out_chart, face_image[get(fim, f0)], static_cast<Id>(get(chart, f0)));

    Chart_flattening_result<TriangleMesh> r = std::move(f);
    const auto out_fim = CGAL::get_initialized_face_index_map(out);
    std::vector<std::array<double, 2>> corner_uv(r.corner_uv.size(), {{0, 0}});
    for(face_descriptor f0 : faces(mesh)) {
      const face_descriptor f1 = face_image[get(fim, f0)];
      // corner k is the target of the k-th halfedge from halfedge(face)
      std::array<halfedge_descriptor, 3> corners;
      std::size_t k = 0;
      for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(f1, out), out))
        if(k < 3) corners[k++] = h;
      k = 0;
      for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(f0, mesh), mesh)) {
        if(k == 3) break;
        const halfedge_descriptor g = halfedge_image[get(him, h)];
        const std::size_t j = g == corners[0] ? 0 : g == corners[1] ? 1 : 2;
        corner_uv[3 * get(out_fim, f1) + j] = r.corner_uv[3 * get(fim, f0) + k];
        ++k;
      }
    }
    r.corner_uv.swap(corner_uv);
    for(edge_descriptor& e : r.seam_edges) e = edge(halfedge_image[get(him, halfedge(e, mesh))], out);
    r.points = points_by_index(out, get(CGAL::vertex_point, out), CGAL::get_initialized_vertex_index_map(out));
    r.number_of_faces = static_cast<std::size_t>(num_faces(out));
    return r;
  }
};

} // namespace internal
} // namespace CGAL_QD

#endif // CGAL_QD_INTERNAL_SMOOTHING_TRY_H
