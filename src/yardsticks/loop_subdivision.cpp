// SPDX-License-Identifier: GPL-3.0-or-later
// A denser mesh on the same surface for the benchmark (the "bunny00 Loop-subdivided"):
// one step of Loop subdivision by CGAL's Subdivision_method_3.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Subdivision_method_3/subdivision_methods_3.h>
#include <CGAL/Surface_mesh.h>

#include <sculpt/sculpt.hpp>
#include <vector>

namespace sculpt {

Triangle_mesh loop_subdivided(const Triangle_mesh& coarse) {
  using Point_3 = CGAL::Exact_predicates_inexact_constructions_kernel::Point_3;
  using Mesh = CGAL::Surface_mesh<Point_3>;
  Mesh mesh;
  std::vector<Mesh::Vertex_index> vertices;
  for (const auto& p : coarse.points) vertices.push_back(mesh.add_vertex(Point_3(p[0], p[1], p[2])));
  const int n = static_cast<int>(vertices.size());
  for (const auto& t : coarse.triangles) {
    const bool indices_valid = t[0] >= 0 && t[0] < n && t[1] >= 0 && t[1] < n && t[2] >= 0 && t[2] < n;
    if (!indices_valid || mesh.add_face(vertices[t[0]], vertices[t[1]], vertices[t[2]]) == Mesh::null_face())
      throw Input_error("not a manifold triangle mesh, so it cannot be Loop-subdivided");
  }
  CGAL::Subdivision_method_3::Loop_subdivision(mesh, CGAL::parameters::number_of_iterations(1));

  Triangle_mesh dense;
  for (auto v : mesh.vertices()) {
    const Point_3& p = mesh.point(v);
    dense.points.push_back({p.x(), p.y(), p.z()});
  }
  for (auto f : mesh.faces()) {
    Facet<3> triangle;
    int k = 0;
    for (auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) triangle[k++] = int(v);
    dense.triangles.push_back(triangle);
  }
  return dense;
}

}  // namespace sculpt
