// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_INTERNAL_POINT_SCALE_H
#define CGAL_QD_INTERNAL_POINT_SCALE_H

// Coordinates in any finite double range. The algorithms square lengths
// (areas, cotangents, Gram matrices) and square areas, which overflows for
// coordinates beyond about 1e75 and underflows below about 1e-75. Inputs whose
// largest |coordinate| is outside [2^-64, 2^64] are therefore either refused
// (`Error_code::COORDINATES_OUT_OF_RANGE`) or, by `segment_quasi_developable()`,
// `smooth_segmentation_seams()`, `shorten_chart_cuts()` and `flatten_patch()`
// (and the measures), scaled internally by a power of two, which is exact:
// every result is then the one of the scaled mesh, scaled back.

#include <CGAL/number_utils.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <cmath>

namespace CGAL_QD {
namespace internal {

constexpr int coordinate_exponent_bound = 64;

// the largest |coordinate| over the vertices (NaN if one is not finite)
template <class VertexRange, class VPM>
double largest_coordinate(const VertexRange& vs, const VPM& vpm)
{
  double m = 0;
  for(const auto& v : vs) {
    const auto& p = get(vpm, v);
    for(const double x : {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())}) {
      if(!std::isfinite(x)) return std::nan("");
      m = (std::max)(m, std::abs(x));
    }
  }
  return m;
}

// whether the largest |coordinate| is in [2^-64, 2^64] (or 0: a degenerate
// mesh, refused by the face checks)
inline bool coordinates_in_range(double largest)
{
  return largest == 0 ||
         (largest >= std::ldexp(1., -coordinate_exponent_bound) && largest <= std::ldexp(1., coordinate_exponent_bound));
}

// 1 for coordinates in range; otherwise the power of two that brings the
// largest |coordinate| into [0.5, 1)
inline double normalizing_scale(double largest)
{
  if(!std::isfinite(largest) || coordinates_in_range(largest)) return 1.;
  int e = 0;
  std::frexp(largest, &e);  // largest = f 2^e, f in [0.5, 1)
  return std::ldexp(1., -e);
}

// A readable point map that multiplies the points of another by `scale` (a
// power of two).
template <class VPM>
struct Scaled_point_map
{
  typedef typename boost::property_traits<VPM>::key_type key_type;
  typedef typename boost::property_traits<VPM>::value_type value_type;
  typedef value_type reference;
  typedef boost::readable_property_map_tag category;

  VPM vpm;
  double scale = 1.;

  friend value_type get(const Scaled_point_map& m, const key_type& k)
  {
    const auto& p = get(m.vpm, k);
    if(m.scale == 1.) return p;
    return value_type(p.x() * m.scale, p.y() * m.scale, p.z() * m.scale);
  }
};

// A read-write UV map that stores in another what it is given times `scale`
// (a power of two), and reads it back divided.
template <class UVMap>
struct Scaled_uv_map
{
  typedef typename boost::property_traits<UVMap>::key_type key_type;
  typedef typename boost::property_traits<UVMap>::value_type value_type;
  typedef value_type reference;
  typedef boost::read_write_property_map_tag category;

  UVMap uv;
  double scale = 1.;

  friend void put(const Scaled_uv_map& m, const key_type& k, const value_type& p)
  {
    if(m.scale == 1.) put(m.uv, k, p);
    else put(m.uv, k, value_type(p.x() * m.scale, p.y() * m.scale));
  }
  friend value_type get(const Scaled_uv_map& m, const key_type& k)
  {
    const value_type p = get(m.uv, k);
    if(m.scale == 1.) return p;
    return value_type(p.x() / m.scale, p.y() / m.scale);
  }
};

} // namespace internal
} // namespace CGAL_QD

#endif // CGAL_QD_INTERNAL_POINT_SCALE_H
