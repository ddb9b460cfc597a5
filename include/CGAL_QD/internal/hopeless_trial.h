// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_INTERNAL_HOPELESS_TRIAL_H
#define CGAL_QD_INTERNAL_HOPELESS_TRIAL_H

#include <CGAL_QD/internal/uv_overlap.h>
#include <CGAL_QD/internal/validation.h>

#include <CGAL/Bbox_2.h>
#include <CGAL/box_intersection_d.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL_QD {
namespace internal {

// Whether a trial's optimisation of the chart `sm` has no hope of acceptance,
// looked at every 5 iterations:
// - A_loc (summed as `compute_distortion()` sums it) falls as the iteration
//   goes on, more slowly as it converges; a map whose A_loc is above (cap /
//   iterations)^0.6 times the bound after `iterations` of at most `cap`
//   iterations is hopeless. Measured on 6170 trials of six of CGAL's meshes
//   (30 iterations, A_loc looked at every 5): this factor (2.93, 1.93, 1.52,
//   1.28, 1.12 at 5 to 25 iterations) stops 2077 trials early, none of which
//   would have been accepted at iteration 30.
// - A map whose border crosses itself widely (a chart that winds around in
//   the plane) does not come apart again: measured on the 7,396 trials of the
//   seven meshes of doc/segmentation_results.md, run to iteration 30 (4,634
//   of them rejected for an overlap), the trials accepted at iteration 30
//   had at most 8, 7, 6, 6 and 2 pairs of border edges crossing at iterations
//   5, 10, 15, 20 and 25. Twice those counts (`crossing_limit()`) stop 2,341
//   trials early, a fifth of the trials' face-iterations, and none of them
//   would have been accepted.
// `Mesh` is a `CGAL::Surface_mesh`; `sm` must outlive the test.
template <class Mesh>
class Hopeless_trial
{
public:
  // `max_local_area_distortion` as a fraction (0.025 for 2.5 %);
  // `overlap_tolerance` as in `compute_distortion()`: border edges cross when
  // each has its ends on either side of the other further than this fraction
  // of the diagonal of the border's box
  Hopeless_trial(const Mesh& sm, double max_local_area_distortion, std::size_t cap, double overlap_tolerance = 0)
      : m_sm(sm), m_cap(cap), m_max_local(100. * max_local_area_distortion), m_tolerance(overlap_tolerance)
  {
    for(auto h : halfedges(sm))
      if(is_border(h, sm)) m_border.push_back({source(h, sm), target(h, sm)});
    m_area.reserve(sm.number_of_faces());
    for(auto f : faces(sm)) {
      const auto h = halfedge(f, sm);
      m_area.push_back(0.5 * double_area3(point(source(h, sm)), point(target(h, sm)), point(target(next(h, sm), sm))));
      m_total += m_area.back();
    }
  }

  // whether the map `uv` after `iterations` iterations is hopeless
  template <class UVMap>
  bool operator()(const UVMap& uv, std::size_t iterations) const
  {
    if(iterations % 5 != 0 || iterations >= m_cap || !(m_total > 0)) return false;
    double local = 0, area2 = 0;
    std::size_t i = 0;
    for(auto f : faces(m_sm)) {
      const auto h = halfedge(f, m_sm);
      const auto &a = get(uv, source(h, m_sm)), &b = get(uv, target(h, m_sm)),
                 &c = get(uv, target(next(h, m_sm), m_sm));
      const double a2 = std::abs(0.5 * ((b.x() - a.x()) * (c.y() - a.y()) - (c.x() - a.x()) * (b.y() - a.y())));
      local += std::abs(a2 - m_area[i++]);
      area2 += a2;
    }
    m_local_area_distortion = local / m_total * 100.;
    m_area_distortion = std::abs(area2 - m_total) / m_total * 100.;
    m_crossed = false;
    if(m_local_area_distortion > m_max_local * std::pow(double(m_cap) / double(iterations), 0.6)) return true;
    const std::size_t limit = m_cap == 30 ? crossing_limit(iterations) : 0;
    m_crossed = limit > 0 && border_crossings(uv, limit) >= limit;
    return m_crossed;
  }

  // the pairs of border edges, sharing no vertex, that cross in the map `uv`
  // (each with its ends on either side of the other, beyond the tolerance),
  // counted up to `enough`
  template <class UVMap>
  std::size_t border_crossings(const UVMap& uv, std::size_t enough = std::size_t(-1)) const
  {
    typedef CGAL::Box_intersection_d::Box_with_info_d<double, 2, std::size_t> Box;
    if(m_border.size() < 4) return 0;
    m_segments.resize(m_border.size());
    std::vector<Box> boxes;
    boxes.reserve(m_border.size());
    CGAL::Bbox_2 all;
    for(std::size_t k = 0; k < m_border.size(); ++k) {
      const auto &a = get(uv, m_border[k].first), &b = get(uv, m_border[k].second);
      m_segments[k] = {{{{a.x(), a.y()}}, {{b.x(), b.y()}}}};
      const CGAL::Bbox_2 box((std::min)(a.x(), b.x()), (std::min)(a.y(), b.y()), (std::max)(a.x(), b.x()),
                             (std::max)(a.y(), b.y()));
      boxes.emplace_back(box, k);
      all += box;
    }
    const double delta = m_tolerance * std::hypot(all.xmax() - all.xmin(), all.ymax() - all.ymin());
    std::size_t count = 0;
    CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), [&](const Box& x, const Box& y) {
      if(count >= enough) return;
      const auto &e = m_border[x.info()], &f = m_border[y.info()];
      if(e.first == f.first || e.first == f.second || e.second == f.first || e.second == f.second) return;
      const auto &s = m_segments[x.info()], &t = m_segments[y.info()];
      if(cross_beyond(s[0], s[1], t[0], t[1], delta)) ++count;
    });
    return count;
  }

  // the number of crossing border-edge pairs that makes a map hopeless after
  // `iterations` of a trial of 30 (0: none)
  static std::size_t crossing_limit(std::size_t iterations)
  {
    switch(iterations) {
    case 5: return 16;
    case 10: return 14;
    case 15:
    case 20: return 12;
    case 25: return 4;
    default: return 0;
    }
  }

  // whether the map last found hopeless was found so by its border crossings
  bool crossed() const { return m_crossed; }

  // A_loc and A(Omega), in percent, of the map last looked at
  double local_area_distortion() const { return m_local_area_distortion; }
  double area_distortion() const { return m_area_distortion; }

private:
  std::array<double, 3> point(typename Mesh::Vertex_index v) const
  {
    const auto& p = m_sm.point(v);
    return {p.x(), p.y(), p.z()};
  }

  const Mesh& m_sm;
  std::size_t m_cap;
  double m_max_local;          // in percent
  double m_tolerance;
  std::vector<std::pair<typename Mesh::Vertex_index, typename Mesh::Vertex_index>> m_border;  // border edges
  mutable std::vector<std::array<std::array<double, 2>, 2>> m_segments;  // their 2D segments
  mutable bool m_crossed = false;
  std::vector<double> m_area;  // 3D area by face
  double m_total = 0;
  mutable double m_local_area_distortion = 0, m_area_distortion = 0;
};

} // namespace internal
} // namespace CGAL_QD

#endif // CGAL_QD_INTERNAL_HOPELESS_TRIAL_H
