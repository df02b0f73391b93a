// Real data: the vertices of CGAL's meshes (Debian's libcgal-demo, unpacked by the
// unpack_cgal_meshes fixture). Assert what holds; record the rest as test properties.
#include <gtest/gtest.h>

#include <filesystem>

#include "io/point_reader.hpp"
#include "test_support.hpp"

namespace sculpt {
namespace {

Reconstruction<3> reconstruct_mesh(const std::string& name) {
  const std::string path = std::string(SCULPT_TEST_DATA) + "/data/meshes/" + name;
  if (!std::filesystem::exists(path)) {
    throw std::runtime_error(path + " is missing: the unpack_cgal_meshes fixture did not run");
  }
  Options options;
  options.keep_triangulations = false;
  auto result = reconstruct(io::read_points(path).points, options);
  const auto& s = result.stats;
  ::testing::Test::RecordProperty("samples", std::to_string(s.samples));
  ::testing::Test::RecordProperty("conflicts", std::to_string(s.conflicts));
  ::testing::Test::RecordProperty("non_manifold_edges", std::to_string(s.non_manifold_ridges));
  ::testing::Test::RecordProperty("unused_samples", std::to_string(s.unused_samples));
  std::cout << name << ": n " << s.samples << ", conflicts " << s.conflicts << ", unlabelled "
            << s.unlabelled_poles << ", triangles " << s.facets << ", boundary edges "
            << s.boundary_ridges << ", non-manifold edges " << s.non_manifold_ridges << ", unused "
            << s.unused_samples << ", components " << s.components << "\n";
  return result;
}

TEST(Cgal_meshes, BunnyIsAClosedManifold) {
  const auto result = reconstruct_mesh("bunny00.off");
  EXPECT_EQ(result.stats.samples, 37706u);
  EXPECT_EQ(result.stats.conflicts, 0u);
  testing::expect_closed_manifold(result, 2);
}

TEST(Cgal_meshes, KnotIsOneClosedPieceOfGenusOne) {
  const auto result = reconstruct_mesh("knot1.off");
  EXPECT_EQ(result.stats.conflicts, 0u);
  EXPECT_EQ(result.stats.boundary_ridges, 0u);
  EXPECT_EQ(result.stats.components, 1u);
  EXPECT_EQ(result.stats.unused_samples, 0u);
}

}  // namespace
}  // namespace sculpt
