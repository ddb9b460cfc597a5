// Uses the installed headers: the free boundary of a small curved strip.
#include <CGAL_QD/length_preserved_free_boundary.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <cmath>
#include <iostream>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;

int main()
{
  Mesh m;
  std::vector<Mesh::Vertex_index> v;
  for(int j = 0; j < 2; ++j)
    for(int i = 0; i < 5; ++i)
      v.push_back(m.add_vertex(K::Point_3(std::cos(0.4 * i), std::sin(0.4 * i), j)));
  for(int i = 0; i < 4; ++i) {
    m.add_face(v[i], v[i + 1], v[i + 6]);
    m.add_face(v[i], v[i + 6], v[i + 5]);
  }
  auto uv = m.add_property_map<Mesh::Vertex_index, K::Point_2>("v:uv").first;
  const auto r = CGAL_QD::compute_length_preserved_free_boundary(m, uv, CGAL::parameters::default_values());
  std::cout << CGAL_QD::error_message(r.status) << ", " << r.iterations << " iterations\n";
  return r && r.number_of_border_vertices == 10 ? 0 : 1;
}
