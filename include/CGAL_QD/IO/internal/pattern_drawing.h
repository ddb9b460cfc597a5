// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_IO_INTERNAL_PATTERN_DRAWING_H
#define CGAL_QD_IO_INTERNAL_PATTERN_DRAWING_H

// Computes what a printed pattern shows (pattern_pieces.h): the scale, the
// pages, and for every piece its glue tabs, cut and fold lines, notches
// (seam_notches.h), seam labels and id; a piece larger than a page in parts
// (pattern_tiles.h). IO/patterns_svg.h and IO/patterns_pdf.h write it.

#include <CGAL_QD/Error_code.h>
#include <CGAL_QD/IO/internal/assembly_order.h>
#include <CGAL_QD/IO/internal/assembly_page.h>
#include <CGAL_QD/IO/internal/fold_lines.h>
#include <CGAL_QD/IO/internal/label_placement.h>
#include <CGAL_QD/IO/internal/pattern_layout.h>
#include <CGAL_QD/IO/internal/pattern_pieces.h>
#include <CGAL_QD/IO/internal/pattern_scale.h>
#include <CGAL_QD/IO/internal/pattern_tiles.h>
#include <CGAL_QD/IO/internal/scale_check.h>
#include <CGAL_QD/IO/internal/seam_labels.h>
#include <CGAL_QD/IO/internal/seam_notches.h>
#include <CGAL_QD/IO/pattern_options.h>
#ifdef CGAL_QD_HAS_CLIPPER
#include <CGAL_QD/IO/internal/seam_allowance.h>
#endif
#include <CGAL_QD/internal/charts.h>
#include <CGAL_QD/internal/constants.h>
#include <CGAL_QD/internal/validation.h>
#include <CGAL_QD/pack_charts.h>
#include <CGAL_QD/segmentation_measures.h>

#include <CGAL/Bbox_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace CGAL_QD {
namespace internal {

// computes the drawing of `write_patterns_SVG()` and `write_patterns_PDF()`
// (see there); nothing is drawn unless the result's status is OK
template <class TriangleMesh, class FaceChartMap, class EdgeRange, class NamedParameters>
IO::Pattern_result draw_pattern(const TriangleMesh& tm, const FaceChartMap& face_chart,
                                const std::vector<std::array<double, 2>>& input_corner_uv, const EdgeRange& seam_edges,
                                const IO::Pattern_options& input_options, const NamedParameters& np,
                                Pattern_drawing& drawing)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename GT::face_descriptor face_descriptor;
  typedef typename GT::edge_descriptor edge_descriptor;
  typedef std::array<double, 2> P2;
  typedef CGAL::Exact_predicates_inexact_constructions_kernel K;

  IO::Pattern_result result;
  const auto input_vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                          get_const_property_map(CGAL::vertex_point, tm));
  // a mesh beyond [2^-64, 2^64] (at 1e200, its areas overflow) is drawn scaled
  // by a power of two, which is exact; `options.scale` (drawing units per mesh
  // unit) and the result's scale are converted (CGAL_QD/internal/point_scale.h)
  double largest = CGAL_QD::internal::largest_coordinate(vertices(tm), input_vpm);
  for(const auto& p : input_corner_uv) largest = (std::max)({largest, std::abs(p[0]), std::abs(p[1])});
  const double unit_scale = CGAL_QD::internal::normalizing_scale(largest);
  const CGAL_QD::internal::Scaled_point_map<typename std::remove_const<decltype(input_vpm)>::type> vpm{input_vpm,
                                                                                                     unit_scale};
  std::vector<std::array<double, 2>> scaled_uv;
  if(unit_scale != 1.) {
    scaled_uv = input_corner_uv;
    for(auto& p : scaled_uv) p = {{p[0] * unit_scale, p[1] * unit_scale}};
  }
  const std::vector<std::array<double, 2>>& corner_uv = unit_scale != 1. ? scaled_uv : input_corner_uv;
  IO::Pattern_options options = input_options;
  options.scale /= unit_scale;
  const auto vim = CGAL::get_initialized_vertex_index_map(tm, np);
  const auto fim = CGAL::get_initialized_face_index_map(tm, np);
  const auto him = CGAL::get_initialized_halfedge_index_map(tm, np);
  const std::size_t nf = static_cast<std::size_t>(num_faces(tm));
  if(nf == 0) {
    result.status = Error_code::EMPTY_MESH;
    return result;
  }
  const double mm_per_unit = IO::millimetres_per_unit(options.units);
  auto finite_at_least = [](double x, double low) { return std::isfinite(x) && x >= low; };
  bool valid = corner_uv.size() == 3 * nf && mm_per_unit > 0 && finite_at_least(options.scale, 0) &&
               finite_at_least(options.model_size, 0) && finite_at_least(options.spacing, 0) &&
               finite_at_least(options.tab_width, 0) && finite_at_least(options.page_margin, 0) &&
               finite_at_least(options.font_size, 0) && finite_at_least(options.notch_spacing, 0) &&
               finite_at_least(options.seam_allowance, 0) &&
               std::isfinite(options.fold_angle) && finite_at_least(options.min_fold_length, 0) &&
               finite_at_least(options.min_fold_share, 0) && finite_at_least(options.min_loose_piece_size, 0) &&
               std::isfinite(options.page_width) && std::isfinite(options.page_height) &&
               options.page_width > 2 * options.page_margin && options.page_height > 2 * options.page_margin;
  // notches a millimetre apart at least (closer ones could not be cut)
  valid = valid && (options.notch_spacing == 0 || options.notch_spacing * mm_per_unit >= 1 - 1e-9);
  // the spacing, tabs and seam allowance around a piece leave it room on a page
  const double pad = options.space_around_piece();
  valid = valid && 2 * pad < (std::min)(options.page_width, options.page_height) - 2 * options.page_margin;
  for(std::size_t i = 0; valid && i < corner_uv.size(); ++i)
    valid = std::isfinite(corner_uv[i][0]) && std::isfinite(corner_uv[i][1]);
  // the box of a vertex's point, as doubles (not `Point_3::bbox()`, an
  // interval for exact kernels)
  auto box_of = [&](typename GT::vertex_descriptor v) {
    const std::array<double, 3> p = CGAL_QD::internal::point_of<TriangleMesh>(v, vpm);
    return CGAL::Bbox_3(p[0], p[1], p[2], p[0], p[1], p[2]);
  };
  // the model's largest dimension
  if(valid) {
    CGAL::Bbox_3 all;  // empty
    for(auto v : vertices(tm)) all += box_of(v);
    const double extent = (std::max)({0., all.x_span(), all.y_span(), all.z_span()});
    valid = std::isfinite(extent) && extent > 0;
  }
  if(!valid) {
    result.status = Error_code::INVALID_COORDINATES;
    return result;
  }
#ifndef CGAL_QD_HAS_CLIPPER
  if(options.seam_allowance > 0) {  // the offset needs Clipper
    result.status = Error_code::INVALID_ARGUMENT;
    return result;
  }
#endif
  const double mm = 1 / mm_per_unit;  // drawing units per millimetre
  const double font = options.font_size > 0 ? options.font_size : std::min(options.page_width, options.page_height) / 60;

  std::vector<face_descriptor> face_of(nf);
  std::vector<std::size_t> chart(nf);
  std::size_t n = 0;
  for(face_descriptor f : faces(tm)) {
    face_of[get(fim, f)] = f;
    chart[get(fim, f)] = static_cast<std::size_t>(get(face_chart, f));
    n = (std::max)(n, chart[get(fim, f)] + 1);
  }
  std::vector<std::vector<std::size_t>> faces_of_chart(n);
  for(std::size_t i = 0; i < nf; ++i) faces_of_chart[chart[i]].push_back(i);
  std::vector<std::size_t> vertex_number(num_vertices(tm));
  {
    std::size_t k = 0;
    for(auto v : vertices(tm)) vertex_number[get(vim, v)] = k++;
  }
  // corner of halfedge h in its face: the target of the k-th halfedge from halfedge(f)
  auto corner = [&](halfedge_descriptor h) {
    const face_descriptor f = face(h, tm);
    const halfedge_descriptor h0 = halfedge(f, tm);
    return 3 * get(fim, f) + (h == h0 ? 0 : (h == next(h0, tm) ? 1 : 2));
  };
  std::set<edge_descriptor> seam(seam_edges.begin(), seam_edges.end());
  auto is_cut = [&](halfedge_descriptor h) {  // h is a halfedge of a face
    return is_border(opposite(h, tm), tm) || seam.count(edge(h, tm)) > 0;
  };

  // ---- the scale, and every chart in its rectangle packed on pages
  std::vector<internal::Rectangle> boxes(n);
  std::vector<bool> used(n, false);
  for(std::size_t k = 0; k < n; ++k) {
    if(faces_of_chart[k].empty()) continue;
    std::vector<K::Point_2> points;
    for(std::size_t i : faces_of_chart[k])
      for(int c = 0; c < 3; ++c) points.emplace_back(corner_uv[3 * i + c][0], corner_uv[3 * i + c][1]);
    boxes[k] = internal::min_area_rectangle(points);
    used[k] = true;
  }
  // the scale, from the 3D bounding box of the pieces drawn, and the loose
  // pieces left out (each a whole connected component of the mesh)
  std::vector<CGAL::Bbox_3> box_3d(n);  // empty
  std::vector<bool> loose(n, true);
  for(std::size_t i = 0; i < nf; ++i)
    for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(face_of[i], tm), tm)) {
      box_3d[chart[i]] += box_of(target(h, tm));
      if(!is_border(opposite(h, tm), tm) && chart[get(fim, face(opposite(h, tm), tm))] != chart[i])
        loose[chart[i]] = false;
    }
  internal::Pattern_scale scale = internal::choose_pattern_scale(boxes, box_3d, used, loose, options, mm_per_unit, pad);
  result.scale = scale.scale;
  result.reduced_to_fit = scale.reduced_to_fit;
  if(!(std::isfinite(result.scale) && result.scale > 0)) {
    result.status = Error_code::INVALID_COORDINATES;
    return result;
  }
  result.model_size = result.scale * scale.extent;
  if(!(result.model_size >= mm * (1 - 1e-9))) {
    result.status = Error_code::INVALID_ARGUMENT;  // under a millimetre: no line would show a piece
    return result;
  }
  result.left_out_pieces.swap(scale.left_out);
  used.swap(scale.drawn);
  const double min_fold_length = result.min_fold_length =
      options.min_fold_length > 0 ? options.min_fold_length : options.min_fold_share * result.model_size;
  const internal::Page_layout layout =
      internal::lay_out_pieces(boxes, used, result.scale, options.page_width, options.page_height,
                               options.page_margin, pad);
  const std::vector<internal::Piece_placement>& place = layout.pieces;
  result.number_of_pages = layout.number_of_pages;
  if(layout.number_of_pages + (options.assembly_page ? 1 : 0) > options.max_pages) {
    result.status = Error_code::INVALID_ARGUMENT;  // a scale far beyond the pages
    return result;
  }
  result.number_of_charts = layout.order.size();
  result.oversized_charts = layout.oversized;
  // the drawing position of a corner: scaled, rotated, y pointing down (so the
  // chart is seen from its outer side), placed on its page
  auto to_page = [&](std::size_t c, const P2& uv) {
    const internal::Piece_placement& p = place[chart[c / 3]];
    const double co = std::cos(p.angle), si = std::sin(p.angle);
    const double rx = co * uv[0] - si * uv[1] - p.low[0], ry = si * uv[0] + co * uv[1] - p.low[1];
    const double h = p.size[1] - 2 * pad;
    return P2{{p.at[0] + pad + result.scale * rx,
               p.page * options.page_height + p.at[1] + pad + h - result.scale * ry}};
  };
  auto point_at = [&](std::size_t c) { return to_page(c, corner_uv[c]); };
  // sizes that follow the pieces: a piece's smaller side, the lines' width
  auto smaller_side = [&](std::size_t k) {
    return (std::max)(0., (std::min)(place[k].size[0], place[k].size[1]) - 2 * pad);
  };
  // 0.25 mm, thinner on a piece less than 10 mm across, so that its lines
  // leave it room; a piece without area keeps 0.25 mm
  const double line = 0.25 * mm;
  auto line_of = [&](std::size_t k) {
    const double l = smaller_side(k) / 40;
    return l > 0 ? (std::min)(line, l) : line;
  };

  // ---- seam curves: connected seam edges with the same pair of charts, in order along the curve
  auto pair_of = [&](halfedge_descriptor h) {
    const std::size_t a = chart[get(fim, face(h, tm))], b = chart[get(fim, face(opposite(h, tm), tm))];
    return std::make_pair((std::min)(a, b), (std::max)(a, b));
  };
  const std::vector<std::vector<halfedge_descriptor>> curves = internal::labelled_seam_curves(tm, chart, seam, fim, vim, him);
  // the sides of every curve to label, each in the chart whose faces its halfedges are in:
  // the curve's halfedges (side 0) or their opposites (side 1)
  std::vector<std::vector<std::pair<std::size_t, int>>> labels_of_chart(n);
  std::vector<std::pair<std::size_t, std::size_t>> curve_charts(curves.size());
  std::vector<double> curve_length(curves.size(), 0.);
  for(std::size_t id = 0; id < curves.size(); ++id) {
    curve_charts[id] = pair_of(curves[id].front());
    double total = 0;
    std::vector<double> lengths;
    for(halfedge_descriptor h : curves[id]) {
      lengths.push_back(CGAL_QD::internal::distance3(CGAL_QD::internal::point_of<TriangleMesh>(source(h, tm), vpm),
                                                     CGAL_QD::internal::point_of<TriangleMesh>(target(h, tm), vpm)));
      total += lengths.back();
    }
    for(int side = 0; side < 2; ++side) {
      const halfedge_descriptor h = side == 0 ? curves[id].front() : opposite(curves[id].front(), tm);
      labels_of_chart[chart[get(fim, face(h, tm))]].emplace_back(id, side);
    }
    curve_length[id] = total;
  }
  // the curves drawn: all but the cuts inside pieces left out (a loose piece has no other)
  std::vector<char> drawn_curve(curves.size());
  for(std::size_t id = 0; id < curves.size(); ++id) {
    drawn_curve[id] = used[curve_charts[id].first] && used[curve_charts[id].second];
    result.seam_labels += drawn_curve[id];
  }
  // the two sides of every curve as drawn
  for(std::size_t id = 0; id < curves.size(); ++id) {
    if(!drawn_curve[id]) continue;
    IO::Pattern_seam ps;
    ps.label = seam_label(id);
    for(int side = 0; side < 2; ++side) {
      auto on_side = [&](halfedge_descriptor h) { return side == 0 ? h : opposite(h, tm); };
      ps.pieces[side] = chart[get(fim, face(on_side(curves[id].front()), tm))];
      for(halfedge_descriptor h : curves[id]) {
        const halfedge_descriptor g = on_side(h);
        const P2 a = point_at(corner(prev(g, tm))), b = point_at(corner(g));
        ps.sides[side] += std::hypot(b[0] - a[0], b[1] - a[1]);
      }
    }
    ps.matched = std::abs(ps.sides[0] - ps.sides[1]) <=
                 CGAL_QD::internal::matched_seam_tolerance * (std::max)(ps.sides[0], ps.sides[1]);
    result.seams.push_back(ps);
  }
  std::vector<std::vector<std::pair<Pattern_drawing::Line, Pattern_drawing::Text>>> notches_of_chart(n);
  auto notch_length = [&](std::size_t k) { return (std::min)(3 * mm, smaller_side(k) / 8); };
  if(options.notch_spacing > 0)
    notches_of_chart = seam_notches(tm, curves, drawn_curve, chart, fim, n, options.notch_spacing, font, corner,
                                    point_at, notch_length, result.notches);
  const std::vector<internal::Face_geometry> geo = internal::face_geometry(tm, vpm, fim);
  {
    std::vector<double> area(n, 0.);
    for(std::size_t i = 0; i < nf; ++i) area[chart[i]] += geo[i].area;
    result.assembly = assembly_order(area, used, curve_charts, curve_length);
  }
  std::vector<std::vector<halfedge_descriptor>> tabs_of_chart(n);
  if(options.tabs)  // on the side of the halfedges stored in the curve
    for(const auto& c : curves)
      for(halfedge_descriptor h : c) tabs_of_chart[chart[get(fim, face(h, tm))]].push_back(h);
  // ---- what is drawn, piece by piece
  drawing.units = options.units;
  drawing.page_width = options.page_width;
  drawing.page_height = options.page_height;
  drawing.page_margin = options.page_margin;
  drawing.number_of_pages = result.number_of_pages;
  drawing.line_width = line;
  drawing.seam_allowance = options.seam_allowance;
  drawing.font_size = font;
  result.font_size = font;
  drawing.millimetre = mm;
  drawing.pieces.clear();
  drawing.assembly.clear();
  drawing.captions.clear();
  drawing.check_lines.clear();
  drawing.check_length = 0;
  for(std::size_t k : layout.order) {
    const internal::Piece_placement& p = place[k];
    const double side = smaller_side(k);
    drawing.pieces.emplace_back();
    Pattern_drawing::Piece& piece = drawing.pieces.back();
    piece.chart = k;
    piece.page = p.page;
    piece.line_width = line_of(k);
    // tabs first, under the piece
    for(halfedge_descriptor h : tabs_of_chart[k]) {
      const P2 a = point_at(corner(prev(h, tm))), b = point_at(corner(h));  // h runs from a to b
      const double dx = b[0] - a[0], dy = b[1] - a[1], l = std::hypot(dx, dy);
      if(!(l > 0)) continue;
      // the page shows the chart as in UV (y is flipped into the page's downward axis), so the
      // face stays on the visual left of a -> b; (nx, ny) points there, and the tab goes the other way
      const double nx = dy / l, ny = -dx / l, tw = (std::min)(options.tab_width, 0.45 * l);
      const P2 c1{{a[0] + 0.25 * dx - nx * tw, a[1] + 0.25 * dy - ny * tw}},
          c2{{a[0] + 0.75 * dx - nx * tw, a[1] + 0.75 * dy - ny * tw}};
      piece.tabs.push_back({{a, c1, c2, b}});
      ++result.tabs;
    }
    // cut lines, and the edges that bend more than the fold angle, of which
    // those on fold lines long enough are drawn (fold_lines.h)
    std::vector<internal::Fold_edge> folds;
    std::vector<std::size_t> border;  // the vertices of the cut line
    for(std::size_t i : faces_of_chart[k]) {
      halfedge_descriptor h = halfedge(face_of[i], tm);
      for(int c = 0; c < 3; ++c, h = next(h, tm)) {
        // the edge of next(h) runs from corner c to corner c + 1
        const halfedge_descriptor g = next(h, tm);
        const P2 a = point_at(3 * i + c), b = point_at(3 * i + (c + 1) % 3);
        const std::size_t from = static_cast<std::size_t>(get(vim, source(g, tm))),
                          to = static_cast<std::size_t>(get(vim, target(g, tm)));
        if(is_cut(g)) {
          piece.lines.push_back({Pattern_drawing::CUT, a, b, {{vertex_number[from], vertex_number[to]}}});
          ++result.cut_edges;
          border.push_back(from);
          border.push_back(to);
          continue;
        }
        // an interior edge: draw it once, from the face with the smaller index
        const std::size_t j = get(fim, face(opposite(g, tm), tm));
        if(j < i) continue;
        const internal::Face_geometry &fa = geo[i], &fb = geo[j];
        const double cosine = fa.normal[0] * fb.normal[0] + fa.normal[1] * fb.normal[1] + fa.normal[2] * fb.normal[2];
        if(std::acos((std::max)(-1., (std::min)(1., cosine))) <= options.fold_angle) continue;
        const double above = (fb.centroid[0] - fa.centroid[0]) * fa.normal[0] +
                             (fb.centroid[1] - fa.centroid[1]) * fa.normal[1] +
                             (fb.centroid[2] - fa.centroid[2]) * fa.normal[2];
        folds.push_back({{{from, to}}, a, b, above > 0 ? Pattern_drawing::VALLEY : Pattern_drawing::MOUNTAIN});
      }
    }
    std::sort(border.begin(), border.end());
    const std::vector<char> on_line = internal::edges_on_fold_lines(folds, min_fold_length, border);
    for(std::size_t q = 0; q < folds.size(); ++q)
      if(on_line[q]) {
        piece.lines.push_back({Pattern_drawing::Line_kind(folds[q].kind), folds[q].a, folds[q].b, {{0, 0}}});
        ++result.fold_lines;
      }
    for(const auto& nt : notches_of_chart[k]) {
      piece.notches.push_back(nt.first);
      piece.notch_labels.push_back(nt.second);
    }
    std::vector<std::array<P2, 2>> cut_segments;
    for(const Pattern_drawing::Line& l : piece.lines)
      if(l.kind == Pattern_drawing::CUT) cut_segments.push_back({{l.a, l.b}});
    // the chart id where the piece is widest (the point inside it farthest
    // from its cut lines), smaller where it would reach them, down to half
    {
      const std::string text = std::to_string(k);
      const std::pair<P2, double> widest = internal::farthest_inside(cut_segments);
      const double largest = (std::min)(1.5 * font, side / 3);
      // the half diagonal of the text's box (label_placement.h) per unit of height
      const double reach = std::hypot(0.375, 0.35 * double(text.size()));
      const double size = widest.second > 0 ? (std::min)(largest, (std::max)(largest / 2, widest.second / reach))
                                            : largest;
      piece.id = {widest.first, size, 0., text};
    }
    // a piece too small for labels and a number that can be read gets them
    // outside, within the room the layout keeps around it (on a tab or off
    // the tabs; not with a seam allowance, whose cut line is there)
    internal::Label_room room;
    room.readable = 0.5 * font;
    room.outside = !(options.seam_allowance > 0);
    room.room = {{p.at[0], p.page * options.page_height + p.at[1], p.at[0] + p.size[0],
                  p.page * options.page_height + p.at[1] + p.size[1]}};
    // the outlines of the tabs are cut too: a text outside is on a tab or off them
    for(const auto& t : piece.tabs)
      for(int c = 0; c < 3; ++c) cut_segments.push_back({{t[c], t[c + 1]}});
    std::size_t crowded = 0;
    // a number too small to be read goes outside after the labels, where they left room
    const bool number_out = room.outside && room.unreadable(piece.id.size);
    // seam labels inside the piece beside their curve, apart from one another
    // and from the texts already there, off the cut lines (label_placement.h)
    {
      const double label = (std::min)(font, side / 4);
      const internal::Segment_grid cuts(std::move(cut_segments), label);
      std::vector<Pattern_drawing::Text> fixed = piece.notch_labels;
      if(!number_out) fixed.push_back(piece.id);
      // beyond the notches and their numbers if there are
      const double beyond = options.notch_spacing > 0 ? notch_length(k) + 1.2 * font : 0.;
      std::vector<internal::Seam_label_request> requests;
      for(const auto& label_side : labels_of_chart[k]) {
        internal::Seam_label_request q;
        q.text = seam_label(label_side.first);
        q.beyond = beyond;
        for(halfedge_descriptor h0 : curves[label_side.first]) {
          const halfedge_descriptor h = label_side.second == 0 ? h0 : opposite(h0, tm);
          q.curve.push_back({{point_at(corner(prev(h, tm))), point_at(corner(h))}});  // h runs from [0] to [1]
        }
        requests.push_back(std::move(q));
      }
      for(Pattern_drawing::Text& t : internal::place_seam_labels(requests, label, cuts, fixed, &crowded, room)) {
        if(room.unreadable(t.size)) ++crowded;
        piece.labels.push_back(std::move(t));
      }
      if(number_out) {
        std::vector<Pattern_drawing::Text> taken = piece.labels;
        taken.insert(taken.end(), piece.notch_labels.begin(), piece.notch_labels.end());
        bool free = false;
        if(!internal::number_outside(
               piece.id, {{room.room[0] + pad, room.room[1] + pad, room.room[2] - pad, room.room[3] - pad}}, room,
               taken, cuts, free) ||
           !free)
          ++crowded;
      } else if(room.unreadable(piece.id.size)) {
        ++crowded;
      }
    }
    if(crowded > 0) result.crowded_pieces.push_back(k);
#ifdef CGAL_QD_HAS_CLIPPER
    if(options.seam_allowance > 0) {
      std::vector<std::array<P2, 3>> triangles;
      for(std::size_t i : faces_of_chart[k]) triangles.push_back({{point_at(3 * i), point_at(3 * i + 1), point_at(3 * i + 2)}});
      piece.allowance = seam_allowance_outline(triangles, options.seam_allowance, 1e-4 * mm);
    }
#endif
  }
  std::sort(result.crowded_pieces.begin(), result.crowded_pieces.end());
  // the pieces larger than a page in parts, on the pages after the others;
  // then the assembly page
  std::size_t pages = layout.first_part_page;
  pages += cut_into_parts(drawing, place, pages,
                          {{options.page_width - 2 * options.page_margin, options.page_height - 2 * options.page_margin}},
                          (std::min)(3 * mm, (std::min)(options.page_width, options.page_height) / 60));
  for(const Pattern_drawing::Piece& piece : drawing.pieces) result.part_pages += piece.parts.size();
  result.number_of_pages = drawing.number_of_pages = pages;
  if(options.assembly_page && !result.assembly.empty()) {
    result.assembly_pages =
        lay_out_assembly_pages(result.assembly, result.seams, options.units, result.number_of_pages, drawing);
    drawing.number_of_pages = result.number_of_pages += result.assembly_pages;
    if(result.number_of_pages > options.max_pages) {
      result.status = Error_code::INVALID_ARGUMENT;  // a list of many thousand pieces
      return result;
    }
  }
  if(options.scale_check) lay_out_scale_check(drawing, options.units == "in");
  result.scale_check = drawing.check_length;
  result.scale *= unit_scale;  // drawing units per unit of the input mesh
  return result;
}

} // namespace internal
} // namespace CGAL_QD

#endif // CGAL_QD_IO_INTERNAL_PATTERN_DRAWING_H
