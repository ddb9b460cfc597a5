// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_INTERNAL_DISTORTION_PASS_H
#define CGAL_QD_INTERNAL_DISTORTION_PASS_H

// The one pass over the faces of `compute_distortion()` (distortion.h), with
// options: without the border crossings, without the corner angles (the
// measures that decide whether a chart is accepted), with an overlap
// tolerance.

#include <CGAL_QD/Error_code.h>
#include <CGAL_QD/distortion_report.h>
#include <CGAL_QD/parameters.h>
#include <CGAL_QD/internal/uv_overlap.h>
#include <CGAL_QD/internal/validation.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/box_intersection_d.h>
#include <CGAL/number_utils.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL_QD {
namespace internal {

struct Distortion_options
{
  bool border_crossings = true;
  // false: no corner angles (`angle_distortion`, `boundary_angle_error` stay
  // 0), and branch vertices counted only where no face is flipped (the map
  // overlaps anyway otherwise); the other measures and `overlap` are the same
  bool angle_measures = true;
  // border edges that come closer than this, relative to the diagonal of the
  // UV bounding box of the border, touch rather than cross (0: exact tests)
  double overlap_tolerance = 0;
};

inline double angle_between(const double* u, const double* w, int dim)
{
  double dot = 0, c = 0;
  if(dim == 2) {
    dot = u[0] * w[0] + u[1] * w[1];
    c = std::abs(u[0] * w[1] - u[1] * w[0]);
  } else {
    dot = u[0] * w[0] + u[1] * w[1] + u[2] * w[2];
    const double x = u[1] * w[2] - u[2] * w[1], y = u[2] * w[0] - u[0] * w[2], z = u[0] * w[1] - u[1] * w[0];
    c = std::sqrt(x * x + y * y + z * z);
  }
  return std::atan2(c, dot);
}

template <class TriangleMesh, class VertexUVMap, class VPM, class VIM>
Distortion_report<TriangleMesh> compute_distortion_impl(const TriangleMesh& tm, const VertexUVMap& uv,
                                                        const VPM& vpm, const VIM& vim,
                                                        const Distortion_options& opt)
{
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename GT::face_descriptor face_descriptor;
  typedef CGAL::Exact_predicates_inexact_constructions_kernel EK;

  Distortion_report<TriangleMesh> rep;
  if(faces(tm).empty()) { rep.status = Error_code::EMPTY_MESH; return rep; }
  for(face_descriptor f : faces(tm))
    if(CGAL::halfedges_around_face(halfedge(f, tm), tm).size() != 3) {
      rep.status = Error_code::NOT_TRIANGLE_MESH;
      return rep;
    }
  for(vertex_descriptor v : vertices(tm)) {
    if(halfedge(v, tm) == GT::null_halfedge()) continue;
    const auto p = point_of<TriangleMesh>(v, vpm);
    const auto q = uv_of(uv, v);
    if(!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]) || !std::isfinite(q[0]) ||
       !std::isfinite(q[1])) {
      rep.status = Error_code::INVALID_COORDINATES;
      return rep;
    }
  }

  const std::size_t nv = num_vertices(tm);
  std::vector<double> angle_sum_2d(opt.angle_measures ? nv : 0, 0.), angle_sum_3d(opt.angle_measures ? nv : 0, 0.);
  double stretch2 = 0, angle_error = 0, local_area_error = 0;
  std::size_t corners = 0;
  bool infinite_stretch = false;
  for(face_descriptor f : faces(tm)) {
    ++rep.number_of_faces;
    const halfedge_descriptor h = halfedge(f, tm);
    const vertex_descriptor v[3] = {source(h, tm), target(h, tm), target(next(h, tm), tm)};
    std::array<double, 3> q[3];
    std::array<double, 2> s[3];
    for(int k = 0; k < 3; ++k) { q[k] = point_of<TriangleMesh>(v[k], vpm); s[k] = uv_of(uv, v[k]); }
    const double a3 = 0.5 * double_area3(q[0], q[1], q[2]);
    const double a2s = 0.5 * ((s[1][0] - s[0][0]) * (s[2][1] - s[0][1]) - (s[2][0] - s[0][0]) * (s[1][1] - s[0][1]));
    rep.area_3d += a3;
    rep.area_2d += std::abs(a2s);
    local_area_error += std::abs(std::abs(a2s) - a3);
    if(CGAL::orientation(EK::Point_2(s[0][0], s[0][1]), EK::Point_2(s[1][0], s[1][1]),
                         EK::Point_2(s[2][0], s[2][1])) != CGAL::LEFT_TURN)
      ++rep.flipped_faces;

    // Sander et al. 2001: S_s, S_t are the partial derivatives of the 2D -> 3D map
    if(a2s == 0) {
      infinite_stretch = true;
    } else {
      const double d = 2 * a2s;
      double Ss[3], St[3];
      for(int c = 0; c < 3; ++c) {
        Ss[c] = (q[0][c] * (s[1][1] - s[2][1]) + q[1][c] * (s[2][1] - s[0][1]) + q[2][c] * (s[0][1] - s[1][1])) / d;
        St[c] = (q[0][c] * (s[2][0] - s[1][0]) + q[1][c] * (s[0][0] - s[2][0]) + q[2][c] * (s[1][0] - s[0][0])) / d;
      }
      const double a = Ss[0] * Ss[0] + Ss[1] * Ss[1] + Ss[2] * Ss[2];
      const double b = Ss[0] * St[0] + Ss[1] * St[1] + Ss[2] * St[2];
      const double c = St[0] * St[0] + St[1] * St[1] + St[2] * St[2];
      const double big = std::sqrt(0.5 * ((a + c) + std::sqrt((a - c) * (a - c) + 4 * b * b)));
      stretch2 += 0.5 * (a + c) * a3;
      rep.linf_stretch = (std::max)(rep.linf_stretch, big);
    }

    for(int k = 0; k < 3 && opt.angle_measures; ++k) {
      const int i = (k + 1) % 3, j = (k + 2) % 3;
      const double u3[3] = {q[i][0] - q[k][0], q[i][1] - q[k][1], q[i][2] - q[k][2]};
      const double w3[3] = {q[j][0] - q[k][0], q[j][1] - q[k][1], q[j][2] - q[k][2]};
      const double u2[2] = {s[i][0] - s[k][0], s[i][1] - s[k][1]};
      const double w2[2] = {s[j][0] - s[k][0], s[j][1] - s[k][1]};
      const double al3 = angle_between(u3, w3, 3), al2 = angle_between(u2, w2, 2);
      angle_error += std::abs(al2 - al3);
      ++corners;
      angle_sum_2d[get(vim, v[k])] += al2;
      angle_sum_3d[get(vim, v[k])] += al3;
    }
  }
  rep.area_distortion = rep.area_3d > 0 ? std::abs(rep.area_2d - rep.area_3d) / rep.area_3d * 100. : 0.;
  rep.local_area_distortion = rep.area_3d > 0 ? local_area_error / rep.area_3d * 100. : 0.;
  if(infinite_stretch) {
    rep.l2_stretch = rep.l2_stretch_normalized = rep.linf_stretch = std::numeric_limits<double>::infinity();
  } else {
    rep.l2_stretch = std::sqrt(stretch2 / rep.area_3d);
    rep.l2_stretch_normalized = rep.l2_stretch * std::sqrt(rep.area_2d / rep.area_3d);
  }
  if(corners > 0) rep.angle_distortion = angle_error / corners;

  // border loops: Pi_L, Pi_theta; interior vertices: branch points
  std::vector<halfedge_descriptor> border;
  std::vector<char> on_border(nv, 0);
  for(halfedge_descriptor h : halfedges(tm))
    if(is_border(h, tm)) {
      border.push_back(h);
      on_border[get(vim, target(h, tm))] = 1;
    }
  if(opt.angle_measures) {
    for(vertex_descriptor v : vertices(tm)) {
      const std::size_t i = get(vim, v);
      if(halfedge(v, tm) != GT::null_halfedge() && !on_border[i] && angle_sum_2d[i] > 3 * pi)
        ++rep.branch_vertices;
    }
  } else if(rep.flipped_faces == 0) {
    // every face is positively oriented (exactly): the 1-ring of an interior
    // vertex v turns around it counterclockwise, each face by less than a
    // half-turn, so it crosses the ray from v towards +x only upwards, and the
    // crossings count the turns (the angle sum above is 2 pi per turn)
    for(vertex_descriptor v : vertices(tm)) {
      if(halfedge(v, tm) == GT::null_halfedge() || on_border[get(vim, v)]) continue;
      const double y = uv_of(uv, v)[1];
      std::size_t turns = 0;
      for(halfedge_descriptor h : CGAL::halfedges_around_target(halfedge(v, tm), tm)) {
        // the face of h is (a, v, c): its side of the 1-ring runs from c to a
        const double ya = uv_of(uv, source(h, tm))[1], yc = uv_of(uv, target(next(h, tm), tm))[1];
        if(yc <= y && y < ya) ++turns;
      }
      if(turns > 1) ++rep.branch_vertices;
    }
  }
  // the 2D angle sum at a vertex: from the corner loop, or summed over its
  // faces where the loop was skipped
  auto angle_sum_2d_at = [&](vertex_descriptor v) {
    if(opt.angle_measures) return angle_sum_2d[get(vim, v)];
    double sum = 0;
    for(halfedge_descriptor h : CGAL::halfedges_around_target(halfedge(v, tm), tm)) {
      if(is_border(h, tm)) continue;
      const auto s0 = uv_of(uv, v), s1 = uv_of(uv, target(next(h, tm), tm)), s2 = uv_of(uv, source(h, tm));
      const double u2[2] = {s1[0] - s0[0], s1[1] - s0[1]}, w2[2] = {s2[0] - s0[0], s2[1] - s0[1]};
      sum += angle_between(u2, w2, 2);
    }
    return sum;
  };
  double length_error = 0, theta_error = 0;
  for(halfedge_descriptor b : border) {
    // b runs with the outside on its left; the surface-side order is reversed
    const auto s0 = uv_of(uv, source(b, tm)), s1 = uv_of(uv, target(b, tm)),
               s2 = uv_of(uv, target(next(b, tm), tm));
    length_error += std::abs(std::hypot(s1[0] - s0[0], s1[1] - s0[1]) -
                             distance3(point_of<TriangleMesh>(source(b, tm), vpm),
                                       point_of<TriangleMesh>(target(b, tm), vpm)));
    if(!opt.angle_measures) continue;
    // inner angle at target(b) on the surface side, walking s2 -> s1 -> s0
    const double ux = s2[0] - s1[0], uy = s2[1] - s1[1], wx = s0[0] - s1[0], wy = s0[1] - s1[1];
    double theta = std::atan2(wx * uy - wy * ux, wx * ux + wy * uy);
    if(theta <= 0) theta += 2 * pi;
    theta_error += std::abs(angle_sum_3d[get(vim, target(b, tm))] - theta);
  }
  if(!border.empty()) {
    rep.boundary_length_error = length_error / border.size();
    rep.boundary_angle_error = theta_error / border.size();
  }

  // border crossings: boxes of the border segments, exact segment tests
  if(opt.border_crossings && border.size() > 1) {
    typedef CGAL::Box_intersection_d::Box_with_info_d<double, 2, std::size_t> Box;
    std::vector<Box> boxes;
    boxes.reserve(border.size());
    std::vector<EK::Segment_2> seg;
    seg.reserve(border.size());
    for(std::size_t k = 0; k < border.size(); ++k) {
      const auto a = uv_of(uv, source(border[k], tm)), b = uv_of(uv, target(border[k], tm));
      seg.emplace_back(EK::Point_2(a[0], a[1]), EK::Point_2(b[0], b[1]));
      boxes.emplace_back(seg.back().bbox(), k);
    }
    double delta = 0;
    if(opt.overlap_tolerance > 0) {
      CGAL::Bbox_2 box;
      for(const EK::Segment_2& sg : seg) box += sg.bbox();
      delta = opt.overlap_tolerance * std::hypot(box.xmax() - box.xmin(), box.ymax() - box.ymin());
    }
    auto report = [&](const Box& x, const Box& y) {
      const std::size_t i = x.info(), j = y.info();
      const halfedge_descriptor hi = border[i], hj = border[j];
      const vertex_descriptor si = source(hi, tm), ti = target(hi, tm), sj = source(hj, tm), tj = target(hj, tm);
      bool crossing = false;
      if(si == sj || si == tj || ti == sj || ti == tj) {
        // consecutive edges: they only cross by folding back onto each other
        const vertex_descriptor shared = (si == sj || si == tj) ? si : ti;
        const EK::Point_2& c = (shared == si) ? seg[i].source() : seg[i].target();
        const EK::Point_2& p = (shared == si) ? seg[i].target() : seg[i].source();
        const EK::Point_2& q = (shared == sj) ? seg[j].target() : seg[j].source();
        if(delta > 0) {
          // folded back: q on the ray from c through p, within delta of it, and apart from p; unless the
          // faces at c fill less than a half-turn between the two edges: then it is the sharp tip of a
          // needle, whose faces lie between the edges without overlapping
          const std::array<double, 2> cc = {c.x(), c.y()}, pp = {p.x(), p.y()}, qq = {q.x(), q.y()};
          const double along = (pp[0] - cc[0]) * (qq[0] - cc[0]) + (pp[1] - cc[1]) * (qq[1] - cc[1]);
          crossing = along > 0 && std::abs(signed_distance(cc, pp, qq)) <= delta &&
                     std::hypot(pp[0] - qq[0], pp[1] - qq[1]) > delta && angle_sum_2d_at(shared) > pi;
        } else {
          crossing = CGAL::collinear(c, p, q) && !CGAL::collinear_are_ordered_along_line(p, c, q);
        }
      } else if(delta > 0) {
        const auto pt = [](const EK::Point_2& p) { return std::array<double, 2>{p.x(), p.y()}; };
        crossing = cross_beyond(pt(seg[i].source()), pt(seg[i].target()), pt(seg[j].source()), pt(seg[j].target()),
                                delta);
        // touching within delta: an overlap only if the faces on either side overlap there
        if(!crossing && CGAL::do_intersect(seg[i], seg[j]))
          crossing = fans_overlap(tm, uv, {si, ti}, {sj, tj});
      } else {
        crossing = CGAL::do_intersect(seg[i], seg[j]);
      }
      if(crossing) rep.border_crossings.emplace_back(hi, hj);
    };
    CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), report);
  }
  rep.overlap = rep.flipped_faces > 0 || rep.branch_vertices > 0 || !rep.border_crossings.empty();
  return rep;
}

// `compute_distortion()` with the options `opt` (its overlap tolerance taken
// from `np`)
template <class TriangleMesh, class VertexUVMap, class NamedParameters>
Distortion_report<TriangleMesh> compute_distortion_with(const TriangleMesh& tm, const VertexUVMap& uv,
                                                        const NamedParameters& np, Distortion_options opt)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const auto input_vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                          get_const_property_map(CGAL::vertex_point, tm));
  const auto vim = CGAL::get_initialized_vertex_index_map(tm, np);
  opt.overlap_tolerance = choose_parameter(get_parameter(np, internal_np::overlap_tolerance_t()), 0.);
  // coordinates beyond [2^-64, 2^64] (3D or UV) are measured scaled by a power
  // of two, which is exact (internal/point_scale.h)
  double largest = largest_coordinate(vertices(tm), input_vpm);
  for(const auto v : vertices(tm)) {
    const auto q = uv_of(uv, v);
    largest = (std::max)(largest, (std::max)(std::abs(q[0]), std::abs(q[1])));
  }
  const double scale = normalizing_scale(largest);
  const Scaled_point_map<typename std::remove_const<decltype(input_vpm)>::type> vpm{input_vpm, scale};
  const Scaled_uv_map<VertexUVMap> scaled_uv{uv, 1. / scale};  // reads uv * scale
  Distortion_report<TriangleMesh> rep = compute_distortion_impl(tm, scaled_uv, vpm, vim, opt);
  rep.area_3d /= scale * scale;
  rep.area_2d /= scale * scale;
  rep.boundary_length_error /= scale;
  return rep;
}

// The measures that decide whether a chart's flattening is accepted: A(Omega),
// L2, A_loc, the flipped faces and `overlap`, the same as `compute_distortion()`
// gives, without the corner angles (`angle_distortion` and
// `boundary_angle_error` are 0; `branch_vertices` is 0 where a face is flipped).
template <class TriangleMesh, class VertexUVMap, class NamedParameters>
Distortion_report<TriangleMesh> acceptance_measures(const TriangleMesh& tm, const VertexUVMap& uv,
                                                    const NamedParameters& np)
{
  Distortion_options opt;
  opt.angle_measures = false;
  return compute_distortion_with(tm, uv, np, opt);
}

// the measures of the faces alone, without the border crossings
template <class TriangleMesh, class VertexUVMap, class NamedParameters>
Distortion_report<TriangleMesh> face_measures(const TriangleMesh& tm, const VertexUVMap& uv,
                                              const NamedParameters& np)
{
  Distortion_options opt;
  opt.border_crossings = false;
  return compute_distortion_with(tm, uv, np, opt);
}

} // namespace internal
} // namespace CGAL_QD

#endif // CGAL_QD_INTERNAL_DISTORTION_PASS_H
