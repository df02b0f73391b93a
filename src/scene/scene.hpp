// SPDX-License-Identifier: GPL-3.0-or-later
// A scene is what one picture of the algorithm shows: coloured layers of points, lines,
// triangles and balls, built from any stage of a reconstruction. It knows nothing of GL, so the
// viewer, the headless renderer and the tests all read the same scene.
#pragma once

#include <array>
#include <sculpt/sculpt.hpp>
#include <string>
#include <vector>

namespace sculpt::scene {

using Vec3 = std::array<float, 3>;

struct Color {
  float r = 0, g = 0, b = 0, a = 1;
};

enum class Primitive {
  points,     // one position per point; size = diameter in pixels
  lines,      // two positions per segment; size = width in pixels
  triangles,  // three positions per triangle; optional normals for smooth shading
  balls,      // one position and one radius per ball: circles in 2D, spheres in 3D
};

struct Layer {
  std::string id;     // what --layers names it by
  std::string label;  // what the legend says
  Primitive primitive = Primitive::points;
  Color color;
  std::vector<Vec3> positions;
  std::vector<Vec3> normals;  // triangles only; empty = flat shading
  std::vector<float> radii;   // balls only
  float size = 5;             // pixels
  bool lit = false;           // triangles: shaded by a light that follows the camera
  bool translucent = false;   // balls: filled translucent spheres instead of outlines
  bool in_legend = true;
  bool cut = false;  // already cut at the clip plane through whole cells: clip() leaves it
  // Grows with the picture scale (a projector's): not a wireframe's many edges, which would
  // merge into a dark fill.
  bool scales = true;
  // Drawn as a part of that layer, in its colour (the step's corners, large so they are found).
  std::string part_of;
  // (A field added here is copied where a layer is kept without its geometry:
  // render/legend_layout.cpp, described.)
};

// The stages a picture can show, in the order the algorithm runs.
enum class Stage {
  samples,
  delaunay,           // DT(S ∪ BBV)
  hull,               // its all-sample cells: the convex hull that the sculpting starts from
  voronoi,            // its dual
  poles,              // poles and polar balls
  seeds,              // convex poles (outer seeds) and their partners (inner seeds)
  propagation,        // the labelling after `step` events
  outer_concave,      // inner poles and the outer concave poles OUP (UP when bordered)
  carving,            // the hull's cells leaving it, after `step` steps (carving_replay.hpp)
  sculpted_delaunay,  // DT(S ∪ OUP)
  crust_delaunay,     // the crust's DT(S ∪ V), V the Voronoi vertices (2D) or the poles (3D)
  candidates,         // crust and co-cone (3D): the triangles chosen, and those pruned
  front,              // the Advancing Front's surface after `step` triangles (growth_stages.hpp)
  alpha,              // the alpha shape after `step` cells, smallest circumball first
  solid,              // the all-sample cells
  surface,            // the result: surface (3D) or curve (2D)
};

const std::vector<Stage>& all_stages();  // of every method, in order
// The stages a method has in a dimension, in the order it runs them: the sculpting methods all
// from samples to surface but crust-delaunay and candidates; the crust samples, delaunay,
// voronoi, crust-delaunay, surface, and in 3D also poles and candidates; the co-cone samples,
// delaunay, voronoi, poles, candidates, surface; the NN-crust and the Advancing Front samples,
// delaunay, surface (the Advancing Front with its front between); the alpha shape samples,
// delaunay, alpha, solid, surface.
const std::vector<Stage>& stages_of(Method method, int dimension);
bool has_stage(Method method, int dimension, Stage stage);
// Whether a stage is replayed step by step (Request::step): propagation (the labelling's
// events), carving (the hull's cells leaving it), candidates (the pruning, triangle by triangle),
// front (the Advancing Front's triangles as it adds them), alpha (the cells as alpha grows).
bool replays(Stage stage);
// Throws std::invalid_argument naming the method's stages when it has no such stage.
void require_stage(Method method, int dimension, Stage stage);
const char* stage_id(Stage stage);     // "delaunay", "outer-concave", ...
const char* stage_title(Stage stage);  // "Delaunay triangulation DT(S ∪ BBV)", ...
bool parse_stage(const std::string& id, Stage& stage);

// A cut-away plane for 3D stages (clipping.hpp): where it crosses the samples' box (0 at one
// end, 1 at the other, along its normal) and how it is tilted.
struct Clip {
  float position = 0.5f;  // 0..1 across the samples' box along the normal; 1 keeps everything
  float azimuth = 0;      // the normal's direction about z, in degrees (0: +x)
  float elevation = 0;    // the normal's angle above the xy plane, in degrees (90: +z)
  float slab = 0;         // 0: all before the plane; else only a slab this thick (share of the box)
};

struct Request {
  Stage stage = Stage::surface;
  // A replay (propagation, carving, candidates, front, alpha): how many events or steps have
  // happened; -1: all (at the stage alpha: the method's own alpha).
  long step = -1;
  int focus_sample = -1;   // show this sample's Voronoi cell, poles, polar balls, inscribed cubes
  int focus_pole = -1;     // show this pole's ball and the pole that labelled it
  bool wireframe = false;  // surface: draw its edges too
  bool smooth = false;     // surface: smooth instead of flat shading
  int ball_every = 1;  // polar balls: draw those of every k-th pole only (legible medial circles)
  std::vector<std::string> layers;  // only these layer ids; empty = the stage's own choice
  bool clipped = false;  // 3D: leave out what lies beyond the plane `clip` (clipping.hpp)
  // 3D: instead, a true section at the plane `clip` (section.hpp): the polygons of the cells
  // it cuts, the Voronoi faces and the surface where it crosses them, the samples near it.
  bool sectioned = false;
  Clip clip;
  // With a picked sample: only the cells, edges, faces, poles and balls near it (its few dozen
  // nearest samples), the picked sample's own cell, poles and balls whole.
  bool neighbourhood = false;
  bool colour_blind = false;  // the colour-blind-safe scheme (colours.hpp), not the paper's
  bool polar_balls = false;   // 3D: also the polar balls (every ball_every-th), at any stage
  int ball_limit = 0;         // 3D: at most this many balls of each kind, evenly picked; 0: all
  float ball_opacity = 0.8f;  // 3D: of the translucent spheres
};

struct Scene {
  int dimension = 3;
  std::string title;
  std::vector<Layer> layers;
  Vec3 lower{}, upper{};    // bounds of the samples: what a camera fits by default
  bool seen_along = false;  // best seen looking along `along` (a section: its plane's normal)
  Vec3 along{};
};

// The scene of one stage. Stages 1 and 6 need the triangulations kept in the reconstruction
// (Options::keep_triangulations).
Scene build_scene(const Reconstruction<2>& reconstruction, const Request& request);
Scene build_scene(const Reconstruction<3>& reconstruction, const Request& request);

// Ids of the layers a stage can show, for messages and the viewer's toggles.
std::vector<std::string> layer_ids(const Scene& scene);

}  // namespace sculpt::scene
