// The names of the stages, as the command line, the viewer's stepper and the figures use them.
#include "scene.hpp"

namespace sculpt::scene {

const std::vector<Stage>& all_stages() {
  static const std::vector<Stage> stages = {
      Stage::samples,     Stage::delaunay,      Stage::hull,
      Stage::voronoi,     Stage::poles,         Stage::seeds,
      Stage::propagation, Stage::outer_concave, Stage::sculpted_delaunay,
      Stage::solid,       Stage::surface};
  return stages;
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
    case Stage::sculpted_delaunay:
      return "sculpted-delaunay";
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
    case Stage::sculpted_delaunay:
      return "DT(S + OUP)";
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

}  // namespace sculpt::scene
