// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

// Helpers shared by the tests: a UV store for every mesh type, point access.

#ifndef CGAL_QD_TEST_UTILS_H
#define CGAL_QD_TEST_UTILS_H

#include "mesh_generators.h"

#include <boost/property_map/property_map.hpp>
#include <boost/test/unit_test.hpp>

#include <array>
#include <unordered_map>

namespace qd_test {

// a UV store keyed by vertex, usable with every mesh type
template <class Mesh>
struct Uv_store
{
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
  typedef typename CGAL::Kernel_traits<typename boost::property_traits<
      typename boost::property_map<Mesh, CGAL::vertex_point_t>::type>::value_type>::Kernel::Point_2 Point_2;
  std::unordered_map<vertex_descriptor, Point_2> map;
  boost::associative_property_map<std::unordered_map<vertex_descriptor, Point_2>> pmap() { return {map}; }
  boost::const_associative_property_map<std::unordered_map<vertex_descriptor, Point_2>> pmap_const() const
  {
    return {map};
  }
  std::array<double, 2> at(vertex_descriptor v) const
  {
    const Point_2& p = map.at(v);
    return {CGAL::to_double(p.x()), CGAL::to_double(p.y())};
  }
};

template <class Mesh>
std::array<double, 3> p3(const Mesh& tm, typename boost::graph_traits<Mesh>::vertex_descriptor v)
{
  const auto& p = get(CGAL::vertex_point, tm, v);
  return {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
}

template <class Mesh>
Mesh make(const Soup& s)
{
  Mesh tm;
  BOOST_REQUIRE(build(s, tm));
  return tm;
}

} // namespace qd_test

#endif // CGAL_QD_TEST_UTILS_H
