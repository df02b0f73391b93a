// SPDX-License-Identifier: GPL-3.0-or-later
// A reconstruction made into bytes and back (how the browser's worker hands it to the page) is
// the same reconstruction: every stage of every method draws the same scene from it, with a
// sample and a pole picked, and its statistics and verdict are the same; bytes that are not a
// reconstruction, or are cut short, are refused in one line.
#include "io/reconstruction_bytes.hpp"

#include <gtest/gtest.h>

#include <cstring>

#include "frontend/statistics_json.hpp"
#include "io/io_error.hpp"
#include "scene/scene.hpp"
#include "shapes/shapes.hpp"

namespace sculpt {
namespace {

template <class T>
bool same_values(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() &&
         (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

void expect_same_scene(const scene::Scene& a, const scene::Scene& b) {
  EXPECT_EQ(a.title, b.title);
  ASSERT_EQ(a.layers.size(), b.layers.size());
  for (std::size_t i = 0; i < a.layers.size(); ++i) {
    SCOPED_TRACE(a.layers[i].id);
    EXPECT_EQ(a.layers[i].id, b.layers[i].id);
    EXPECT_TRUE(same_values(a.layers[i].positions, b.layers[i].positions));
    EXPECT_TRUE(same_values(a.layers[i].normals, b.layers[i].normals));
    EXPECT_TRUE(same_values(a.layers[i].radii, b.layers[i].radii));
  }
}

template <int D>
void expect_round_trip(const std::vector<Point<D>>& points, Method method) {
  SCOPED_TRACE(to_string(method));
  Options options;
  options.method = method;
  const Reconstruction<D> original = reconstruct(points, options);
  const std::vector<std::uint8_t> bytes = io::to_bytes(original);
  ASSERT_EQ(io::dimension_of_bytes(bytes.data(), bytes.size()), D);
  const Reconstruction<D> copy = io::reconstruction_from_bytes<D>(bytes.data(), bytes.size());

  EXPECT_EQ(frontend::statistics_json(copy.stats), frontend::statistics_json(original.stats));
  EXPECT_EQ(verdict(copy.stats).line, verdict(original.stats).line);
  EXPECT_EQ(copy.options.method, original.options.method);
  EXPECT_EQ(copy.options.kind, original.options.kind);
  // Every stage, field by field (a field the bytes forgot would come back empty).
  EXPECT_TRUE(same_values(copy.sites, original.sites));
  EXPECT_EQ(copy.delaunay.cell_count, original.delaunay.cell_count);
  EXPECT_TRUE(same_values(copy.delaunay.cells, original.delaunay.cells));
  EXPECT_TRUE(same_values(copy.poles.poles, original.poles.poles));
  EXPECT_TRUE(same_values(copy.poles.positive_pole, original.poles.positive_pole));
  EXPECT_TRUE(same_values(copy.poles.negative_pole, original.poles.negative_pole));
  EXPECT_TRUE(same_values(copy.poles.partner_offsets, original.poles.partner_offsets));
  EXPECT_TRUE(same_values(copy.poles.partners, original.poles.partners));
  EXPECT_TRUE(same_values(copy.seeds.convex_poles, original.seeds.convex_poles));
  EXPECT_TRUE(same_values(copy.seeds.outer_seeds, original.seeds.outer_seeds));
  EXPECT_TRUE(same_values(copy.propagation.events, original.propagation.events));
  EXPECT_TRUE(same_values(copy.propagation.conflicts, original.propagation.conflicts));
  EXPECT_TRUE(same_values(copy.propagation.labels, original.propagation.labels));
  EXPECT_EQ(copy.propagation.unlabelled, original.propagation.unlabelled);
  EXPECT_TRUE(same_values(copy.insertion.inserted_poles, original.insertion.inserted_poles));
  EXPECT_TRUE(same_values(copy.sculpted_delaunay.cells, original.sculpted_delaunay.cells));
  EXPECT_TRUE(same_values(copy.carving.events, original.carving.events));
  EXPECT_TRUE(same_values(copy.carving.kept_outer_cells, original.carving.kept_outer_cells));
  EXPECT_TRUE(same_values(copy.carving.buried_samples, original.carving.buried_samples));
  EXPECT_TRUE(same_values(copy.carving.openings, original.carving.openings));
  EXPECT_TRUE(same_values(copy.carving.refused_handles, original.carving.refused_handles));
  EXPECT_TRUE(same_values(copy.crust.voronoi_vertices, original.crust.voronoi_vertices));
  EXPECT_TRUE(same_values(copy.crust.delaunay.cells, original.crust.delaunay.cells));
  EXPECT_TRUE(same_values(copy.candidates.chosen, original.candidates.chosen));
  EXPECT_TRUE(same_values(copy.candidates.spanning, original.candidates.spanning));
  EXPECT_TRUE(same_values(copy.candidates.pruned, original.candidates.pruned));
  EXPECT_EQ(copy.candidates.rims_kept, original.candidates.rims_kept);
  EXPECT_TRUE(same_values(copy.candidates.undersampled, original.candidates.undersampled));
  EXPECT_TRUE(same_values(copy.candidates.without_umbrella, original.candidates.without_umbrella));
  EXPECT_TRUE(same_values(copy.solid, original.solid));
  EXPECT_TRUE(same_values(copy.surface, original.surface));
  EXPECT_TRUE(same_values(copy.surface_vertices, original.surface_vertices));
  EXPECT_EQ(copy.stats.unused_samples, original.stats.unused_samples);
  EXPECT_EQ(copy.stats.stages.size(), original.stats.stages.size());
  EXPECT_EQ(io::to_bytes(copy), bytes);
  for (scene::Stage stage : scene::stages_of(method, D)) {
    SCOPED_TRACE(scene::stage_id(stage));
    scene::Request request;
    request.stage = stage;
    expect_same_scene(scene::build_scene(copy, request), scene::build_scene(original, request));
    request.focus_sample = 3;  // its Voronoi cell, poles and balls
    expect_same_scene(scene::build_scene(copy, request), scene::build_scene(original, request));
    if (!original.poles.poles.empty()) {
      request.focus_sample = -1;
      request.focus_pole = 0;
      expect_same_scene(scene::build_scene(copy, request), scene::build_scene(original, request));
    }
  }
}

TEST(ReconstructionBytes, EveryMethodComesBackTheSameIn2d) {
  const auto star = shapes::example_points_2("star");
  for (Method method : {Method::robust, Method::paper, Method::crust, Method::nn_crust,
                        Method::power_crust, Method::boissonnat})
    expect_round_trip<2>(star, method);
}

TEST(ReconstructionBytes, EveryMethodComesBackTheSameIn3d) {
  const auto torus = shapes::torus(600);
  for (const char* name : method_names()) {
    Method method;
    ASSERT_TRUE(parse_method(name, method));
    if (reconstructs_in(method, 3)) expect_round_trip<3>(torus, method);
  }
}

// Noise gives the paper's labelling conflicts and the robust method's contradicted poles, and a
// bordered sheet the robust method's spanning and filled triangles: stages that are empty on
// clean closed shapes come back too.
TEST(ReconstructionBytes, StagesOnlyNoiseAndBordersFillComeBackToo) {
  const auto noisy = shapes::noisy_sphere(800, 0.1);
  expect_round_trip<3>(noisy, Method::paper);
  expect_round_trip<3>(noisy, Method::robust);
  expect_round_trip<3>(shapes::saddle(20), Method::robust);
  Options paper;
  paper.method = Method::paper;
  EXPECT_FALSE(reconstruct(noisy, paper).propagation.conflicts.empty());
  EXPECT_FALSE(reconstruct(noisy).propagation.conflicts.empty());
  // The carving's openings and refused handles: the drilled block has both.
  const auto block = shapes::example_points_3("drilled-block");
  expect_round_trip<3>(block, Method::robust);
  const auto carved = reconstruct(block);
  EXPECT_FALSE(carved.carving.openings.empty());
  EXPECT_FALSE(carved.carving.refused_handles.empty());
}

TEST(ReconstructionBytes, RefusesWhatIsNotAReconstruction) {
  const auto bytes = io::to_bytes(reconstruct(shapes::example_points_2("star")));
  // Another dimension, other bytes, and lengths short of the whole: none, the header alone, a
  // few stages, half, all but the last byte.
  EXPECT_THROW(io::reconstruction_from_bytes<3>(bytes.data(), bytes.size()), io::Error);
  const std::vector<std::uint8_t> text = {'h', 'e', 'l', 'l', 'o', ' ',
                                          'w', 'o', 'r', 'l', 'd', '!'};
  EXPECT_EQ(io::dimension_of_bytes(text.data(), text.size()), 0);
  EXPECT_THROW(io::reconstruction_from_bytes<2>(text.data(), text.size()), io::Error);
  for (std::size_t size :
       {std::size_t(0), std::size_t(11), std::size_t(200), bytes.size() / 2, bytes.size() - 1}) {
    SCOPED_TRACE(size);
    EXPECT_THROW(io::reconstruction_from_bytes<2>(bytes.data(), size), io::Error);
  }
  std::vector<std::uint8_t> longer = bytes;
  longer.push_back(0);
  EXPECT_THROW(io::reconstruction_from_bytes<2>(longer.data(), longer.size()), io::Error);
}

}  // namespace
}  // namespace sculpt
