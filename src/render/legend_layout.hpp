// SPDX-License-Identifier: GPL-3.0-or-later
// Where the legend and the title go in a picture. The legend takes the corner clearest of the
// data, judged from where each layer lies (points and segments, about 100,000 in all), so
// that it hides as little as it can of what it explains; a freshly fitted camera steps back a
// little where that clears a corner. No OpenGL here: the renderer draws by this layout, and the
// exports (`sculpt render`, the gallery, Python) step their fitted cameras back by it before
// drawing, as the viewer does.
#pragma once

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "render/camera.hpp"
#include "render/draw_options.hpp"
#include "scene/scene.hpp"

namespace sculpt::render {

class Legend_layout {
 public:
  Legend_layout() = default;
  explicit Legend_layout(const scene::Scene& scene);

  struct Corner {
    float x = 0, y = 0;       // the legend box's top left, in pixels from the top left
    std::size_t covered = 0;  // the data's points under it and segments across it
  };
  struct Place {
    std::vector<const scene::Layer*> listed;  // the layers the legend names, in order
    float size = 1, pad = 0, w = 0, h = 0;    // text scale; the box inside its border
    Corner corner;
  };

  // The scene without its geometry: kinds, colours, labels (a layer with nothing to draw is
  // left out of the legend).
  const scene::Scene& scene() const { return shown_; }
  // The legend's size and corner in a width x height picture seen by `camera`.
  Place place(const Camera& camera, int width, int height, const Draw_options& options) const;
  // Whether the legend (Draw_options::legend) lies over drawn data wherever it goes.
  bool over_data(const Camera& camera, int width, int height, const Draw_options& options) const;
  // The title wrapped at spaces to the picture's width, never clipped.
  std::vector<std::string> title_lines(int width, int height, const Draw_options& options) const;
  // Text grows with the picture's height and half as fast as points and lines with the picture
  // scale: it is read, not found.
  static float text_scale(int height, const Draw_options& options);

 private:
  scene::Scene shown_;
  std::vector<std::vector<glm::vec4>> landmarks_;  // per layer: points, with a ball's radius in w
  std::vector<std::vector<std::pair<glm::vec3, glm::vec3>>> segments_;  // per layer: its lines

  Corner emptiest_corner(const Camera& camera, int width, int height, float w, float h, float inset,
                         float title_width, float title_height, const Draw_options& options) const;
};

// A camera just fitted, stepped back a little at a time until a corner of the picture is clear
// of data for the legend: at most `most_steps` steps of 12% (three by default, so that the shape
// keeps at least 70% of its fitted size). Where they do not clear a corner (Delaunay edges
// running to the box, poles strewn to every corner) the camera stays as given, the legend in the
// corner with the least data: shrinking the shape further would cost more than the legend hides.
// A camera chosen by hand is not passed here: it stays where it was put. `steps`, if given,
// learns how many steps were taken.
inline constexpr int legend_steps_at_most = 3;
Camera with_room_for_legend(const Legend_layout& layout, Camera camera, int width, int height,
                            const Draw_options& options, int* steps = nullptr,
                            int most_steps = legend_steps_at_most);
// What one step back zooms by.
inline constexpr float legend_step_back = 1.12f;

}  // namespace sculpt::render
