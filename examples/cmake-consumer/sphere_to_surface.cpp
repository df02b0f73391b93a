// SPDX-License-Identifier: GPL-3.0-or-later
// Samples a sphere, reconstructs it through the installed libsculpt, and prints the verdict:
// what a program outside the project needs is include/sculpt/sculpt.hpp and Sculpt::sculpt.
// Exits 0 when the result is a closed 2-manifold and bad input is reported as the API says.
#include <cmath>
#include <cstdint>
#include <iostream>
#include <sculpt/io.hpp>
#include <sculpt/sculpt.hpp>
#include <vector>

int main() {
  // A Fibonacci sphere: n points spread evenly by the golden angle.
  const int n = 2000;
  const double golden_angle = M_PI * (3.0 - std::sqrt(5.0));
  std::vector<sculpt::Point<3>> points;
  for (int k = 0; k < n; ++k) {
    const double z = 1.0 - 2.0 * (k + 0.5) / n, r = std::sqrt(1.0 - z * z);
    points.push_back({r * std::cos(golden_angle * k), r * std::sin(golden_angle * k), z});
  }
  sculpt::Options options;
  sculpt::parse_method("robust", options.method);
  const auto result = sculpt::reconstruct(points, options);
  const sculpt::Verdict verdict = sculpt::verdict(result.stats);
  std::cout << "sculpt " << sculpt::version() << ", method " << sculpt::to_string(options.method)
            << ": " << result.surface.size() << " triangles\nverdict: " << verdict.line << '\n';

  // Written and read back through the library's files: the same triangles, and no write
  // over a file that was read.
  sculpt::write(result, "sphere.off");
  const sculpt::Point_file file = sculpt::read_points("sphere.off");
  std::cout << "read back: " << file.points.size() << " points, " << file.triangles.size()
            << " triangles\n";
  if (file.points.size() != points.size() || file.triangles.size() != result.surface.size())
    return 1;
  // A scan's normals and colours go onto the surface's vertices (the samples) in PLY and OBJ.
  sculpt::Point_attributes attributes;
  for (const auto& p : points) {
    attributes.normals.push_back(p);  // a unit sphere's normal is its point
    attributes.colors.push_back(
        {std::uint8_t(128 + 127 * p[0]), 64, std::uint8_t(128 + 127 * p[2])});
  }
  sculpt::write(result, "coloured.ply", "", false, attributes);
  const sculpt::Point_file coloured = sculpt::read_points("coloured.ply");
  std::cout << "attributes back: " << coloured.attributes.normals.size() << " normals, "
            << coloured.attributes.colors.size() << " colours\n";
  if (coloured.attributes.normals != attributes.normals ||
      coloured.attributes.colors != attributes.colors)
    return 1;
  try {
    sculpt::write(result, "sphere.off");
    std::cout << "a file read was replaced\n";
    return 1;
  } catch (const sculpt::File_error& e) {
    std::cout << "written over: " << e.what() << '\n';
  }

  // Exceptions cross the library boundary as the types the header declares.
  try {
    sculpt::reconstruct(std::vector<sculpt::Point<3>>(points.begin(), points.begin() + 3));
    std::cout << "three points were not refused\n";
    return 1;
  } catch (const sculpt::Input_error& e) {
    std::cout << "three points: " << e.what() << '\n';
  }
  return verdict.manifold ? 0 : 1;
}
