// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_IO_INTERNAL_LABEL_PLACEMENT_H
#define CGAL_QD_IO_INTERNAL_LABEL_PLACEMENT_H

// Where the texts of a printed piece go. Its number: where the piece is
// widest (`farthest_inside()`). Its seam labels: beside their curve, inside
// the piece, apart from one another, from the piece's number and from the
// notch numbers, and off the cut lines. Each label tries places along its
// curve from the curve's middle outwards, at its full height and then
// smaller, as long as it stays readable; then, on a piece too small for
// readable labels, outside the piece beside its curve, within the room the
// layout keeps around the piece; then smaller inside. Where no place is
// free, it takes the place that meets the fewest others. A number too small
// to be read inside goes beside the piece (`number_outside()`).

#include <CGAL_QD/IO/internal/pattern_pieces.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL_QD {
namespace internal {

// the text drawn as a rectangle: its corners, counter-clockwise in a y-up
// frame; a character is taken 0.7 of the height wide and a capital 0.75 high
// (sans-serif capitals and digits, as the labels are), with `margin` around
inline std::array<Pattern_drawing::P2, 4> text_box(const Pattern_drawing::Text& t, double margin = 0)
{
  const double w = 0.7 * t.size * double(t.text.size()) / 2 + margin, h = 0.75 * t.size / 2 + margin;
  const double a = t.angle * 3.14159265358979323846 / 180, c = std::cos(a), s = std::sin(a);
  std::array<Pattern_drawing::P2, 4> box;
  const double dx[4] = {-w, w, w, -w}, dy[4] = {-h, -h, h, h};
  for(int k = 0; k < 4; ++k) box[k] = {{t.at[0] + c * dx[k] - s * dy[k], t.at[1] + s * dx[k] + c * dy[k]}};
  return box;
}

// whether two convex polygons (2 to 4 corners in order; 2: a segment) overlap,
// by separating axes: the normals of their edges
template <std::size_t N, std::size_t M>
bool convex_overlap(const std::array<Pattern_drawing::P2, N>& p, const std::array<Pattern_drawing::P2, M>& q)
{
  auto separated_along = [&](double ax, double ay) {
    if(ax == 0 && ay == 0) return false;
    double p0 = HUGE_VAL, p1 = -HUGE_VAL, q0 = HUGE_VAL, q1 = -HUGE_VAL;
    for(const auto& v : p) {
      const double d = v[0] * ax + v[1] * ay;
      p0 = (std::min)(p0, d);
      p1 = (std::max)(p1, d);
    }
    for(const auto& v : q) {
      const double d = v[0] * ax + v[1] * ay;
      q0 = (std::min)(q0, d);
      q1 = (std::max)(q1, d);
    }
    return p1 < q0 || q1 < p0;
  };
  for(std::size_t k = 0; k < N; ++k) {
    const auto &a = p[k], &b = p[(k + 1) % N];
    if(separated_along(a[1] - b[1], b[0] - a[0])) return false;
  }
  for(std::size_t k = 0; k < M; ++k) {
    const auto &a = q[k], &b = q[(k + 1) % M];
    if(separated_along(a[1] - b[1], b[0] - a[0])) return false;
  }
  return true;
}

// The segments of a piece's cut lines, bucketed in square cells (a segment
// whose box spans many cells is kept aside and looked at by every query)
class Segment_grid
{
public:
  typedef Pattern_drawing::P2 P2;
  typedef std::array<P2, 2> Segment;

  Segment_grid(std::vector<Segment> segments, double cell) : m_segments(std::move(segments)), m_cell(cell)
  {
    for(std::size_t i = 0; i < m_segments.size(); ++i) {
      const Segment& s = m_segments[i];
      if(!for_cells(s[0][0], s[0][1], s[1][0], s[1][1], [&](std::uint64_t key) { m_cells[key].push_back(i); }))
        m_long.push_back(i);
    }
  }

  // whether a segment crosses the convex polygon `p`
  template <std::size_t N>
  bool crosses(const std::array<P2, N>& p) const
  {
    double x0 = HUGE_VAL, y0 = HUGE_VAL, x1 = -HUGE_VAL, y1 = -HUGE_VAL;
    for(const P2& v : p) {
      x0 = (std::min)(x0, v[0]);
      y0 = (std::min)(y0, v[1]);
      x1 = (std::max)(x1, v[0]);
      y1 = (std::max)(y1, v[1]);
    }
    for(std::size_t i : m_long)
      if(convex_overlap(p, m_segments[i])) return true;
    bool hit = false;
    const bool few = for_cells(x0, y0, x1, y1, [&](std::uint64_t key) {
      if(hit) return;
      const auto it = m_cells.find(key);
      if(it == m_cells.end()) return;
      for(std::size_t i : it->second)
        if(convex_overlap(p, m_segments[i])) {
          hit = true;
          return;
        }
    });
    if(!few)  // a query far larger than the cells: every segment
      for(const Segment& s : m_segments)
        if(convex_overlap(p, s)) return true;
    return hit;
  }

private:
  // calls f with the key of every cell the box spans, unless it spans more
  // than 64 (or the cell size is not a positive number): then returns false
  template <class F>
  bool for_cells(double ax, double ay, double bx, double by, F&& f) const
  {
    if(!(m_cell > 0)) return false;
    const double i0 = std::floor((std::min)(ax, bx) / m_cell), i1 = std::floor((std::max)(ax, bx) / m_cell);
    const double j0 = std::floor((std::min)(ay, by) / m_cell), j1 = std::floor((std::max)(ay, by) / m_cell);
    if(!((i1 - i0 + 1) * (j1 - j0 + 1) <= 64)) return false;
    for(double i = i0; i <= i1; ++i)
      for(double j = j0; j <= j1; ++j)
        f((std::uint64_t(std::uint32_t(std::int64_t(i))) << 32) | std::uint64_t(std::uint32_t(std::int64_t(j))));
    return true;
  }

  std::vector<Segment> m_segments;
  double m_cell;
  std::unordered_map<std::uint64_t, std::vector<std::size_t>> m_cells;
  std::vector<std::size_t> m_long;  // spanning many cells
};

// The point inside the region that `segments` bound (closed loops: a point is
// inside where a ray from it crosses them an odd number of times) farthest
// from them, and that distance: the best of a 40 x 40 grid over their box,
// then twice the best of a 9 x 9 grid around the point found, each a quarter
// of the spacing before. Where no point of the first grid is inside (a
// sliver), the centre of the box and a distance of 0.
inline std::pair<Pattern_drawing::P2, double>
farthest_inside(const std::vector<std::array<Pattern_drawing::P2, 2>>& segments)
{
  typedef Pattern_drawing::P2 P2;
  double x0 = HUGE_VAL, y0 = HUGE_VAL, x1 = -HUGE_VAL, y1 = -HUGE_VAL;
  for(const auto& s : segments)
    for(const P2& v : s) {
      x0 = (std::min)(x0, v[0]);
      y0 = (std::min)(y0, v[1]);
      x1 = (std::max)(x1, v[0]);
      y1 = (std::max)(y1, v[1]);
    }
  if(segments.empty()) return {P2{{0., 0.}}, 0.};
  auto inside = [&](const P2& p) {
    bool odd = false;
    for(const auto& s : segments)
      if((s[0][1] > p[1]) != (s[1][1] > p[1]) &&
         s[0][0] + (p[1] - s[0][1]) * (s[1][0] - s[0][0]) / (s[1][1] - s[0][1]) > p[0])
        odd = !odd;
    return odd;
  };
  // the distance from p to the segments, or a number no larger than `beaten`
  // once it is clear that the distance is no larger
  auto distance = [&](const P2& p, double beaten) {
    double d2 = HUGE_VAL;
    const double stop = beaten > 0 ? beaten * beaten : -1.;
    for(const auto& s : segments) {
      const double dx = s[1][0] - s[0][0], dy = s[1][1] - s[0][1], l2 = dx * dx + dy * dy;
      const double t =
          l2 > 0 ? (std::max)(0., (std::min)(1., ((p[0] - s[0][0]) * dx + (p[1] - s[0][1]) * dy) / l2)) : 0.;
      const double ex = s[0][0] + t * dx - p[0], ey = s[0][1] + t * dy - p[1];
      d2 = (std::min)(d2, ex * ex + ey * ey);
      if(d2 <= stop) break;
    }
    return std::sqrt(d2);
  };
  P2 best{{(x0 + x1) / 2, (y0 + y1) / 2}};
  double farthest = -1;
  auto look = [&](const P2& p, bool known_inside) {
    if(!known_inside && !inside(p)) return;
    const double d = distance(p, farthest);
    if(d > farthest) {
      farthest = d;
      best = p;
    }
  };
  const int n = 40;
  double sx = (x1 - x0) / n, sy = (y1 - y0) / n;
  std::vector<double> crossings;
  for(int j = 0; j < n; ++j) {
    // the row's points inside: between the 1st and 2nd crossing of the row, the 3rd and 4th, ...
    const double y = y0 + (j + 0.5) * sy;
    crossings.clear();
    for(const auto& s : segments)
      if((s[0][1] > y) != (s[1][1] > y))
        crossings.push_back(s[0][0] + (y - s[0][1]) * (s[1][0] - s[0][0]) / (s[1][1] - s[0][1]));
    std::sort(crossings.begin(), crossings.end());
    for(int i = 0; i < n; ++i) {
      const double x = x0 + (i + 0.5) * sx;
      const std::size_t beyond = std::size_t(crossings.end() - std::upper_bound(crossings.begin(), crossings.end(), x));
      if(beyond % 2 == 1) look(P2{{x, y}}, true);
    }
  }
  if(farthest < 0) return {best, 0.};
  for(int round = 0; round < 2; ++round) {
    sx /= 4;
    sy /= 4;
    const P2 centre = best;
    for(int i = -4; i <= 4; ++i)
      for(int j = -4; j <= 4; ++j)
        if(i != 0 || j != 0) look(P2{{centre[0] + i * sx, centre[1] + j * sy}}, false);
  }
  return {best, farthest};
}

// A seam label to place: its text, and the side of its curve in the piece as
// segments on the page in order along the curve, each with the piece on the
// side of (dy, -dx) (a segment may run against the curve)
struct Seam_label_request
{
  std::string text;
  std::vector<std::array<Pattern_drawing::P2, 2>> curve;
  double beyond = 0;  // how much further into the piece than the label's own offset (notches)
};

// the polyline of a request's segments in their order along the curve, and
// for each of its segments whether the piece lies on the side of (dy, -dx)
inline void curve_polyline(const Seam_label_request& q, std::vector<Pattern_drawing::P2>& points,
                           std::vector<char>& left)
{
  typedef Pattern_drawing::P2 P2;
  points.clear();
  left.clear();
  auto d2 = [](const P2& a, const P2& b) { return (a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]); };
  for(std::size_t i = 0; i < q.curve.size(); ++i) {
    const auto& s = q.curve[i];
    bool forward = true;  // travelled from s[0] to s[1]
    if(i == 0) {
      if(q.curve.size() > 1) {
        const auto& n = q.curve[1];
        forward = (std::min)(d2(s[1], n[0]), d2(s[1], n[1])) <= (std::min)(d2(s[0], n[0]), d2(s[0], n[1]));
      }
      points.push_back(forward ? s[0] : s[1]);
    } else {
      forward = d2(s[0], points.back()) <= d2(s[1], points.back());
    }
    points.push_back(forward ? s[1] : s[0]);
    left.push_back(forward ? 1 : 0);
  }
}

// How small the texts of a piece may be and where they may go: `readable`
// the smallest height they can be read at; outside the piece, if `outside`,
// within `room` (x0, y0, x1, y1), the box the layout keeps for the piece
struct Label_room
{
  double readable = 0;
  bool outside = false;
  std::array<double, 4> room{{0, 0, 0, 0}};

  // whether a text `height` high is too small to be read
  bool unreadable(double height) const { return height < readable * (1 - 1e-9); }
  // whether every corner of `box` is within the room
  bool holds(const std::array<Pattern_drawing::P2, 4>& box) const
  {
    for(const Pattern_drawing::P2& c : box)
      if(!(c[0] >= room[0] && c[0] <= room[2] && c[1] >= room[1] && c[1] <= room[3])) return false;
    return true;
  }
};

// The number of a piece too small for it to be read inside (`id` smaller than
// `room.readable`): that high, beside the piece's box `box` (x0, y0, x1,
// y1), below or above it, right or left of it or at a corner, next to the
// box and then at the room's edge: the first of those within the room that
// overlaps none of the texts `taken` and crosses none of the lines `cuts`
// (the tabs' outlines), or else the first within the room (and `free` false);
// false, and `id` as it was, where none is within the room.
inline bool number_outside(Pattern_drawing::Text& id, const std::array<double, 4>& box, const Label_room& room,
                           const std::vector<Pattern_drawing::Text>& taken, const Segment_grid& cuts, bool& free)
{
  typedef Pattern_drawing::P2 P2;
  const double h = room.readable, gap = 0.3 * h, half_w = 0.35 * h * double(id.text.size()),
               half_h = 0.375 * h;
  // below and above the box at its middle, a quarter, three quarters and its
  // ends, then right and left of it at its middle, a quarter and three
  // quarters, then the corners: next to the box, then at the room's edge
  // (beyond the tabs)
  std::vector<P2> spots;
  for(int far = 0; far < 2; ++far) {
    const double dy = far ? (std::min)(box[1] - room.room[1], room.room[3] - box[3]) - half_h - gap / 2
                          : gap + half_h,
                 dx = far ? (std::min)(box[0] - room.room[0], room.room[2] - box[2]) - half_w - gap / 2
                          : gap + half_w;
    if(far && !(dy > gap + half_h || dx > gap + half_w)) break;
    for(double f : {0.5, 0.25, 0.75, 0., 1.}) {
      const double x = box[0] + f * (box[2] - box[0]);
      spots.push_back(P2{{x, box[3] + dy}});
      spots.push_back(P2{{x, box[1] - dy}});
    }
    for(double f : {0.5, 0.25, 0.75}) {
      const double y = box[1] + f * (box[3] - box[1]);
      spots.push_back(P2{{box[2] + dx, y}});
      spots.push_back(P2{{box[0] - dx, y}});
    }
    for(double x : {box[2] + dx, box[0] - dx})
      for(double y : {box[3] + dy, box[1] - dy}) spots.push_back(P2{{x, y}});
  }
  bool found = false;
  Pattern_drawing::Text first = id;
  for(const P2& at : spots) {
    Pattern_drawing::Text t = id;
    t.at = at;
    t.size = h;
    t.angle = 0;
    const std::array<P2, 4> b = text_box(t, 0.1 * h);
    if(!room.holds(b)) continue;
    bool apart = !cuts.crosses(text_box(t));
    for(const Pattern_drawing::Text& o : taken) apart = apart && !convex_overlap(b, text_box(o));
    if(apart) {
      id = t;
      free = true;
      return true;
    }
    if(!found) first = t;
    found = true;
  }
  if(found) id = first;
  free = false;
  return found;
}

// The labels of one piece at most `size` high, each `0.9 size + beyond` into
// the piece from its curve and turned along it; `cuts` are the piece's cut
// lines, `fixed` the texts already on the piece (its number, notch numbers).
// Heights of `room.readable` and more are tried first, then, if texts may go
// outside, that height outside the piece (0.9 of it from the curve) within
// `room.room`, then the smaller heights inside.
// The shorter curves are placed first: they have the fewer places. `crowded`,
// when given, counts the labels that found no free place.
inline std::vector<Pattern_drawing::Text> place_seam_labels(const std::vector<Seam_label_request>& requests,
                                                            double size, const Segment_grid& cuts,
                                                            const std::vector<Pattern_drawing::Text>& fixed,
                                                            std::size_t* crowded = nullptr,
                                                            const Label_room& room = Label_room())
{
  typedef Pattern_drawing::P2 P2;
  typedef Pattern_drawing::Text Text;
  typedef std::array<P2, 4> Box;
  const std::size_t places = 33;  // along each curve
  // the heights tried in turn, and whether outside the piece: of `size` down
  // to half of it, the readable ones first
  std::vector<std::pair<double, bool>> tries;
  const std::array<double, 3> heights = {{1., 0.75, 0.5}};
  for(double h : heights)
    if(!room.unreadable(h * size)) tries.push_back({h * size, false});
  if(room.outside) tries.push_back({room.readable, true});
  for(double h : heights)
    if(room.unreadable(h * size)) tries.push_back({h * size, false});
  const double margin = 0.1 * size;

  std::vector<Box> taken;
  for(const Text& t : fixed) taken.push_back(text_box(t, margin));
  std::vector<double> length(requests.size(), 0.);
  for(std::size_t r = 0; r < requests.size(); ++r)
    for(const auto& s : requests[r].curve) length[r] += std::hypot(s[1][0] - s[0][0], s[1][1] - s[0][1]);
  std::vector<std::size_t> order(requests.size());
  for(std::size_t r = 0; r < order.size(); ++r) order[r] = r;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return length[a] < length[b]; });

  std::vector<Text> out(requests.size());
  for(std::size_t r : order) {
    const Seam_label_request& q = requests[r];
    std::vector<P2> points;
    std::vector<char> left;
    curve_polyline(q, points, left);
    const double total = length[r];
    // the point at arc length s along the curve, and its segment
    auto at = [&](double s, std::size_t* segment = nullptr) {
      s = (std::max)(0., (std::min)(total, s));
      for(std::size_t i = 0; i + 1 < points.size(); ++i) {
        const P2 &a = points[i], &b = points[i + 1];
        const double l = std::hypot(b[0] - a[0], b[1] - a[1]);
        if(s <= l || i + 2 == points.size()) {
          if(segment) *segment = i;
          const double t = l > 0 ? (std::min)(1., s / l) : 0.;
          return P2{{a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])}};
        }
        s -= l;
      }
      if(segment) *segment = 0;
      return points.empty() ? P2{{0., 0.}} : points.back();
    };
    // the label at arc length s, `height` high: along the chord of the curve
    // over the label's width, into the piece, or out of it
    auto label_at = [&](double s, double height, bool out, P2& foot) {
      Text t;
      t.size = height;
      t.text = q.text;
      const double half = 0.35 * height * double(q.text.size());
      std::size_t segment = 0;
      foot = at(s, &segment);
      P2 a = at(s - half), b = at(s + half);
      if(a == b && points.size() > 1) {  // a curve of no length: its first segment's direction
        a = points[0];
        b = points[1];
      }
      const double sign = (left.empty() || left[segment] ? 1. : -1.) * (out ? -1. : 1.);
      const double dx = b[0] - a[0], dy = b[1] - a[1], l = std::hypot(dx, dy);
      const double d = 0.9 * height + (out ? 0. : q.beyond);
      t.at = l > 0 ? P2{{foot[0] + sign * d * dy / l, foot[1] - sign * d * dx / l}} : foot;
      const double angle = std::atan2(dy, dx) * 180 / 3.141592653589793;
      t.angle = angle > 90 || angle < -90 ? angle + 180 : angle;
      return t;
    };
    // how many things a label meets: other labels and texts, or the room of
    // another piece, count more than a cut line
    auto conflicts = [&](const Text& t, const P2& foot, bool out) {
      const Box box = text_box(t, margin);
      std::size_t c = 0;
      for(const Box& o : taken) c += convex_overlap(box, o) ? 2 : 0;
      if(out && !room.holds(text_box(t))) c += 2;
      // off the cut lines, and not behind another one seen from its curve
      const double l = std::hypot(t.at[0] - foot[0], t.at[1] - foot[1]);
      const double from = l > 0 ? (std::min)(1., 0.3 * t.size / l) : 0.;
      const std::array<P2, 2> sight = {
          {P2{{foot[0] + from * (t.at[0] - foot[0]), foot[1] + from * (t.at[1] - foot[1])}}, t.at}};
      if(cuts.crosses(text_box(t)) || (from < 1 && cuts.crosses(sight))) ++c;
      return c;
    };
    bool placed = false;
    std::size_t least = 0;
    Text best;
    for(std::size_t k = 0; k < tries.size() && !placed; ++k) {
      for(std::size_t j = 0; j < places && !placed; ++j) {
        // the middle, then alternately either side of it
        const double step = total / double(places - 1);
        const double s = total / 2 + (j % 2 == 1 ? 1. : -1.) * double((j + 1) / 2) * step;
        P2 foot;
        const Text t = label_at(s, tries[k].first, tries[k].second, foot);
        const std::size_t c = conflicts(t, foot, tries[k].second);
        if(c == 0) {
          best = t;
          placed = true;
        } else if((k == 0 && j == 0) || c < least) {
          best = t;
          least = c;
        }
      }
    }
    if(!placed && crowded) ++*crowded;
    out[r] = best;
    taken.push_back(text_box(best, margin));
  }
  return out;
}

} // namespace internal
} // namespace CGAL_QD

#endif // CGAL_QD_IO_INTERNAL_LABEL_PLACEMENT_H
