// The names of the stages, as the command line, the viewer's stepper and the figures use them.
#include "scene.hpp"

namespace sculpt::scene {

const std::vector<Stage>& all_stages() {
  static const std::vector<Stage> stages = {
      Stage::samples, Stage::delaunay,    Stage::voronoi,       Stage::poles,
      Stage::seeds,   Stage::propagation, Stage::outer_concave, Stage::sculpted_delaunay,
      Stage::solid,   Stage::surface};
  return stages;
}

const char* stage_id(Stage stage) {
  switch (stage) {
    case Stage::samples:
      return "samples";
    case Stage::delaunay:
      return "delaunay";
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
      return "1. Samples S";
    case Stage::delaunay:
      return "2. Delaunay triangulation DT(S + BBV)";
    case Stage::voronoi:
      return "3. Voronoi diagram";
    case Stage::poles:
      return "4. Poles and polar balls";
    case Stage::seeds:
      return "5. Seeds: convex poles and their partners";
    case Stage::propagation:
      return "6. Pole separation";
    case Stage::outer_concave:
      return "7. Inner poles and outer concave poles";
    case Stage::sculpted_delaunay:
      return "8. DT(S + OUP)";
    case Stage::solid:
      return "9. Sculpted solid";
    case Stage::surface:
      return "10. Reconstruction";
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
