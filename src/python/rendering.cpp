// SPDX-License-Identifier: GPL-3.0-or-later
// Pictures from Python: sculpt.render draws a stage as `sculpt render` and the viewer do, with
// one headless renderer for the process, the GIL released while it draws.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "frontend/option_use.hpp"
#include "frontend/shots.hpp"
#include "python/bindings.hpp"
#include "render/headless.hpp"
#include "scene/scene.hpp"

namespace sculpt::python {
namespace {

// One headless renderer for the process, drawing for one caller at a time.
struct Shared_renderer {
  std::mutex mutex;
  std::unique_ptr<render::Headless_renderer> renderer;
};
Shared_renderer& shared_renderer() {
  static Shared_renderer* shared = new Shared_renderer;  // lives as long as the loaded module
  return *shared;
}

py::array render_stage(const Result& result, const frontend::Shot& shot) {
  frontend::Picture picture;
  {
    py::gil_scoped_release released;
    Shared_renderer& shared = shared_renderer();
    std::lock_guard<std::mutex> lock(shared.mutex);
    scene::Scene scene = frontend::scene_of(shot, result.reconstruction);
    if (const std::string problem =
            frontend::unused_drawing_option(shot, scene, frontend::Spelling::python);
        !problem.empty())
      throw Input_error(problem);
    if (!shared.renderer) shared.renderer = std::make_unique<render::Headless_renderer>();
    picture = frontend::draw_scene(*shared.renderer, shot, std::move(scene));
  }
  const auto& image = picture.image;
  py::array_t<std::uint8_t> pixels(
      {py::ssize_t(image.height), py::ssize_t(image.width), py::ssize_t(4)});
  std::memcpy(pixels.mutable_data(), image.rgba.data(), image.rgba.size());
  return pixels;
}

// A picture size: one number (a square) or (width, height), in pixels.
std::string size_of(const py::object& size) {
  const std::string rule =
      "the size is (width, height) or one number for a square, each from 1 to " +
      std::to_string(render::max_image_side) + " pixels";
  std::vector<long> sides;
  try {
    if (py::isinstance<py::int_>(size)) {
      sides = {size.cast<long>(), size.cast<long>()};
    } else {
      for (auto side : size) {
        if (!py::isinstance<py::int_>(side)) throw Input_error(rule);
        sides.push_back(side.cast<long>());
      }
    }
  } catch (py::error_already_set&) {
    throw Input_error(rule);
  } catch (py::cast_error&) {
    throw Input_error(rule);
  }
  if (sides.size() != 2) throw Input_error(rule);
  for (long side : sides) {
    if (side < 1 || side > render::max_image_side) throw Input_error(rule);
  }
  return std::to_string(sides[0]) + "x" + std::to_string(sides[1]);
}

}  // namespace

void bind_rendering(py::module_& m) {
  const frontend::Shot shot_defaults;
  m.def(
      "render",
      [](const Result& result, const std::string& stage, const py::object& size, long step,
         int focus_sample, int focus_pole, std::vector<std::string> layers, bool wireframe,
         bool smooth, bool legend, double zoom, int ball_every, double yaw, double pitch,
         std::optional<std::vector<double>> clip, std::optional<std::vector<double>> section,
         bool polar_balls, int ball_limit, double ball_opacity, const std::string& palette) {
        frontend::Shot shot;
        shot.stage = stage;
        shot.size = size_of(size);
        shot.step = step;
        shot.focus_sample = focus_sample;
        shot.focus_pole = focus_pole;
        shot.layers = std::move(layers);
        shot.wireframe = wireframe;
        shot.smooth = smooth;
        shot.no_legend = !legend;
        shot.zoom = zoom;
        shot.ball_every = ball_every;
        shot.yaw = yaw;
        shot.pitch = pitch;
        if (clip) {
          if (clip->size() != 3 && clip->size() != 4)
            throw Input_error("clip is (position, azimuth, elevation) or with a slab, 4 numbers");
          shot.clip = fmt::format("{}", fmt::join(*clip, ","));
        }
        if (section) {
          if (section->size() != 3)
            throw Input_error("section is (position, azimuth, elevation), 3 numbers");
          shot.section = fmt::format("{}", fmt::join(*section, ","));
        }
        shot.polar_balls = polar_balls;
        if (ball_limit < 0) throw Input_error("ball_limit is a count of balls, 0 for all");
        shot.ball_limit = ball_limit;
        shot.ball_opacity = ball_opacity;
        shot.palette = palette;
        return render_stage(result, shot);
      },
      py::arg("result"), py::arg("stage") = shot_defaults.stage,
      py::arg("size") = py::make_tuple(800, 800), py::arg("step") = shot_defaults.step,
      py::arg("focus_sample") = shot_defaults.focus_sample,
      py::arg("focus_pole") = shot_defaults.focus_pole,
      py::arg("layers") = std::vector<std::string>{},
      py::arg("wireframe") = shot_defaults.wireframe, py::arg("smooth") = shot_defaults.smooth,
      py::arg("legend") = !shot_defaults.no_legend, py::arg("zoom") = shot_defaults.zoom,
      py::arg("ball_every") = shot_defaults.ball_every, py::arg("yaw") = shot_defaults.yaw,
      py::arg("pitch") = shot_defaults.pitch, py::arg("clip") = py::none(),
      py::arg("section") = py::none(), py::arg("polar_balls") = shot_defaults.polar_balls,
      py::arg("ball_limit") = shot_defaults.ball_limit,
      py::arg("ball_opacity") = shot_defaults.ball_opacity,
      py::arg("palette") = shot_defaults.palette,
      R"(A picture of a stage, as `sculpt render` and the viewer draw it: an (height, width, 4)
uint8 RGBA array (matplotlib's imshow shows it).

stage         a name of sculpt.stages(result.method, result.dimension): 'samples', 'delaunay',
              'voronoi', 'poles', 'propagation', 'surface', ...
size          (width, height) in pixels, or one number for a square
step          a replay (propagation, carving, candidates, front, alpha): its first `step`
              events or steps; -1: all (alpha: the method's own)
focus_sample  a sample whose Voronoi cell, poles, polar balls and inscribed cubes are drawn
focus_pole    a pole whose polar ball, and the pole that labelled it, are drawn
layers        only these layers (their names are in the error message of a wrong one)
wireframe, smooth   surfaces: draw the edges; smooth shading
legend        the legend and the title
zoom          of the fitted camera: below 1 zooms in
ball_every    draw the polar balls of every k-th pole only
yaw, pitch    3D: the direction the camera looks from, in radians
clip          3D: (position, azimuth, elevation[, slab]) cuts away what lies beyond a plane:
              position 0 to 1 across the samples' box along its normal, the normal's angles in
              degrees, and a slab (a share of the box) keeps only that thickness before it;
              (0.5, 0, 90) shows the lower half of the Delaunay cells, whole
section       3D: (position, azimuth, elevation) draws the stage in that plane instead: the
              cells it cuts as polygons filled by what they are, the Voronoi faces and the
              surface where it crosses them, the samples near it; seen along the plane
polar_balls   3D: the polar balls at any stage, inner and outer apart
ball_limit    3D: at most this many inner and this many outer balls (0: all)
ball_opacity  3D: the balls' opacity, above 0 and at most 1 (the outer ones fainter)
palette       'paper' (the paper's colours) or 'colour-blind' (every pair of layers apart with
              deuteranopia and protanopia too))");
}

}  // namespace sculpt::python
