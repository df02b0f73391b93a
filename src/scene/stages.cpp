// SPDX-License-Identifier: GPL-3.0-or-later
// The names of the stages, as the command line, the viewer's stepper and the figures use them.
#include <algorithm>
#include <stdexcept>

#include "scene.hpp"

namespace sculpt::scene {

const std::vector<Stage>& all_stages() {
  static const std::vector<Stage> stages = {Stage::samples,        Stage::delaunay,
                                            Stage::hull,           Stage::voronoi,
                                            Stage::poles,          Stage::seeds,
                                            Stage::propagation,    Stage::outer_concave,
                                            Stage::carving,        Stage::sculpted_delaunay,
                                            Stage::crust_delaunay, Stage::candidates,
                                            Stage::front,          Stage::alpha,
                                            Stage::solid,          Stage::surface};
  return stages;
}

const std::vector<Stage>& stages_of(Method method, int dimension) {
  static const std::vector<Stage> sculpting = {
      Stage::samples,           Stage::delaunay,      Stage::hull,
      Stage::voronoi,           Stage::poles,         Stage::seeds,
      Stage::propagation,       Stage::outer_concave, Stage::carving,
      Stage::sculpted_delaunay, Stage::solid,         Stage::surface};
  static const std::vector<Stage> curve_crust = {Stage::samples, Stage::delaunay, Stage::voronoi,
                                                 Stage::crust_delaunay, Stage::surface};
  static const std::vector<Stage> surface_crust = {
      Stage::samples,        Stage::delaunay,   Stage::voronoi, Stage::poles,
      Stage::crust_delaunay, Stage::candidates, Stage::surface};
  static const std::vector<Stage> cocone = {Stage::samples, Stage::delaunay,   Stage::voronoi,
                                            Stage::poles,   Stage::candidates, Stage::surface};
  static const std::vector<Stage> nn_crust = {Stage::samples, Stage::delaunay, Stage::surface};
  static const std::vector<Stage> advancing_front = {Stage::samples, Stage::delaunay, Stage::front,
                                                     Stage::surface};
  static const std::vector<Stage> alpha_shape = {Stage::samples, Stage::delaunay, Stage::alpha,
                                                 Stage::solid, Stage::surface};
  static const std::vector<Stage> power_crust = {
      Stage::samples, Stage::delaunay,    Stage::voronoi, Stage::poles,
      Stage::seeds,   Stage::propagation, Stage::surface};
  static const std::vector<Stage> tight_cocone = {Stage::samples, Stage::delaunay,   Stage::voronoi,
                                                  Stage::poles,   Stage::candidates, Stage::solid,
                                                  Stage::surface};
  static const std::vector<Stage> boissonnat = {Stage::samples, Stage::delaunay, Stage::hull,
                                                Stage::carving, Stage::solid,    Stage::surface};
  switch (method) {
    case Method::boissonnat:
      return boissonnat;
    case Method::tight_cocone:
      return tight_cocone;
    case Method::power_crust:
      return power_crust;
    case Method::crust:
      return dimension == 2 ? curve_crust : surface_crust;
    case Method::cocone:
      return cocone;
    case Method::advancing_front:
      return advancing_front;
    case Method::alpha_shape:
      return alpha_shape;
    case Method::nn_crust:
      return nn_crust;
    default:
      return sculpting;
  }
}

bool has_stage(Method method, int dimension, Stage stage) {
  const auto& stages = stages_of(method, dimension);
  return std::find(stages.begin(), stages.end(), stage) != stages.end();
}

bool replays(Stage stage) {
  return stage == Stage::propagation || stage == Stage::carving || stage == Stage::candidates ||
         stage == Stage::front || stage == Stage::alpha;
}

const char* stage_id(Stage stage) {
  switch (stage) {
    case Stage::samples:
      return "samples";
    case Stage::delaunay:
      return "delaunay";
    case Stage::hull:
      return "hull";
    case Stage::voronoi:
      return "voronoi";
    case Stage::poles:
      return "poles";
    case Stage::seeds:
      return "seeds";
    case Stage::propagation:
      return "propagation";
    case Stage::outer_concave:
      return "outer-concave";
    case Stage::carving:
      return "carving";
    case Stage::sculpted_delaunay:
      return "sculpted-delaunay";
    case Stage::crust_delaunay:
      return "crust-delaunay";
    case Stage::candidates:
      return "candidates";
    case Stage::front:
      return "front";
    case Stage::alpha:
      return "alpha";
    case Stage::solid:
      return "solid";
    case Stage::surface:
      return "surface";
  }
  return "?";
}

const char* stage_title(Stage stage) {
  switch (stage) {
    case Stage::samples:
      return "Samples S";
    case Stage::delaunay:
      return "Delaunay triangulation DT(S + BBV)";
    case Stage::hull:
      return "Convex hull: all-sample cells of DT(S + BBV)";
    case Stage::voronoi:
      return "Voronoi diagram";
    case Stage::poles:
      return "Poles and polar balls";
    case Stage::seeds:
      return "Seeds: convex poles and their partners";
    case Stage::propagation:
      return "Pole separation";
    case Stage::outer_concave:
      return "Inner poles and outer concave poles";
    case Stage::carving:
      return "Sculpting: the hull's cells leaving it";
    case Stage::sculpted_delaunay:
      return "DT(S + OUP)";
    case Stage::crust_delaunay:
      return "DT(S + V): the samples and their Voronoi vertices";
    case Stage::candidates:
      return "Candidate triangles, and the pruned ones";
    case Stage::front:
      return "Advancing Front: the triangles in the order it adds them";
    case Stage::alpha:
      return "Alpha shape as alpha grows";
    case Stage::solid:
      return "Sculpted solid";
    case Stage::surface:
      return "Reconstruction";
  }
  return "?";
}

bool parse_stage(const std::string& id, Stage& stage) {
  for (Stage candidate : all_stages()) {
    if (id == stage_id(candidate)) {
      stage = candidate;
      return true;
    }
  }
  return false;
}

void require_stage(Method method, int dimension, Stage stage) {
  if (has_stage(method, dimension, stage)) return;
  std::string stages;
  for (Stage s : stages_of(method, dimension))
    stages += (stages.empty() ? "" : ", ") + std::string(stage_id(s));
  throw std::invalid_argument(std::string("the method ") + to_string(method) + " has no stage '" +
                              stage_id(stage) + "' (its stages: " + stages + ")");
}

}  // namespace sculpt::scene
