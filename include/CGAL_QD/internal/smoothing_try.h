// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_INTERNAL_SMOOTHING_TRY_H
#define CGAL_QD_INTERNAL_SMOOTHING_TRY_H

// One try of smooth_segmentation_seams(): a copy of a mesh with its charts and
// its cut edges in maps that grow with the mesh, and the copy of the try that
// is kept into the caller's mesh, with its flattening carried over.

#include <CGAL_QD/flatten_charts.h>

#include <CGAL/Dynamic_property_map.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <boost/graph/graph_traits.hpp>

#include <array>
#include <cstddef>
#include <iterator>
#include <map>
#include <utility>
#include <vector>

namespace CGAL_QD {
namespace internal {

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
    std::vector<std::pair<face_descriptor, face_descriptor>> f2f;
    std::vector<std::pair<halfedge_descriptor, halfedge_descriptor>> h2h;
    CGAL::copy_face_graph(source, mesh,
                          CGAL::parameters::face_to_face_output_iterator(std::back_inserter(f2f))
                              .halfedge_to_halfedge_output_iterator(std::back_inserter(h2h)));
    for(const auto& p : f2f) put(chart, p.second, static_cast<std::size_t>(get(source_chart, p.first)));
    for(const auto& p : h2h) put(cut, edge(p.second, mesh), bool(is_cut(edge(p.first, source))));
  }

  // copies this mesh into `out` (empty), its charts into `out_chart`, and
  // returns `f`, the flattening of this mesh, for `out`: the UVs of the
  // corners and the seam edges carried over, the points by `out`'s vertex index
  template <class OutputChartMap>
  Chart_flattening_result<TriangleMesh> copy_into(TriangleMesh& out, OutputChartMap out_chart,
                                                  const Chart_flattening_result<TriangleMesh>& f) const
  {
    std::vector<std::pair<face_descriptor, face_descriptor>> f2f;
    std::vector<std::pair<halfedge_descriptor, halfedge_descriptor>> h2h;
    CGAL::copy_face_graph(mesh, out,
                          CGAL::parameters::face_to_face_output_iterator(std::back_inserter(f2f))
                              .halfedge_to_halfedge_output_iterator(std::back_inserter(h2h)));
    const std::map<halfedge_descriptor, halfedge_descriptor> image(h2h.begin(), h2h.end());
    typedef typename boost::property_traits<OutputChartMap>::value_type Id;
    for(const auto& p : f2f) put(out_chart, p.second, static_cast<Id>(get(chart, p.first)));

    Chart_flattening_result<TriangleMesh> r = f;
    const auto fim = CGAL::get_initialized_face_index_map(mesh);
    const auto out_fim = CGAL::get_initialized_face_index_map(out);
    r.corner_uv.assign(f.corner_uv.size(), {{0, 0}});
    for(const auto& p : f2f) {
      // corner k is the target of the k-th halfedge from halfedge(face)
      std::array<halfedge_descriptor, 3> corners;
      std::size_t k = 0;
      for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(p.second, out), out))
        if(k < 3) corners[k++] = h;
      k = 0;
      for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(p.first, mesh), mesh)) {
        if(k == 3) break;
        const halfedge_descriptor g = image.at(h);
        const std::size_t j = g == corners[0] ? 0 : g == corners[1] ? 1 : 2;
        r.corner_uv[3 * get(out_fim, p.second) + j] = f.corner_uv[3 * get(fim, p.first) + k];
        ++k;
      }
    }
    for(edge_descriptor& e : r.seam_edges) e = edge(image.at(halfedge(e, mesh)), out);
    r.points = points_by_index(out, get(CGAL::vertex_point, out), CGAL::get_initialized_vertex_index_map(out));
    r.number_of_faces = static_cast<std::size_t>(num_faces(out));
    return r;
  }
};

} // namespace internal
} // namespace CGAL_QD

#endif // CGAL_QD_INTERNAL_SMOOTHING_TRY_H
