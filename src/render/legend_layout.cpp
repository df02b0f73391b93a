// SPDX-License-Identifier: GPL-3.0-or-later
#include "render/legend_layout.hpp"

#include <stb/stb_easy_font.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace sculpt::render {
namespace {

// The width of a line of text in stb_easy_font's units (pixels at scale 1).
float text_width(const std::string& text) {
  return float(stb_easy_font_width(const_cast<char*>(text.c_str())));
}

// The text in lines at most `width` wide, broken at spaces (a word wider than that stands alone).
std::vector<std::string> wrapped(const std::string& text, float width) {
  std::vector<std::string> lines;
  if (text.empty()) return lines;
  std::string current;
  std::size_t start = 0;
  while (start <= text.size()) {
    std::size_t end = text.find(' ', start);
    if (end == std::string::npos) end = text.size();
    const std::string word = text.substr(start, end - start);
    const std::string longer = current.empty() ? word : current + " " + word;
    if (!current.empty() && text_width(longer) > width) {
      lines.push_back(current);
      current = word;
    } else {
      current = longer;
    }
    start = end + 1;
  }
  lines.push_back(current);
  return lines;
}

// Whether the segment from a to b crosses the box [x0, x1] x [y0, y1] (Liang and Barsky's
// clipping: the part of the segment inside each of the box's four half-planes).
bool crosses_box(glm::vec2 a, glm::vec2 b, float x0, float y0, float x1, float y1) {
  const glm::vec2 d = b - a;
  const float p[4] = {-d.x, d.x, -d.y, d.y};
  const float q[4] = {a.x - x0, x1 - a.x, a.y - y0, y1 - a.y};
  float enter = 0, leave = 1;
  for (int i = 0; i < 4; ++i) {
    if (p[i] == 0) {
      if (q[i] < 0) return false;  // parallel to that side, and outside it
      continue;
    }
    const float t = q[i] / p[i];
    if (p[i] < 0) {
      enter = std::max(enter, t);
    } else {
      leave = std::min(leave, t);
    }
    if (enter > leave) return false;
  }
  return true;
}

// What a layer is, without its geometry (copying a mesh to clear it would cost as much as the
// mesh); a layer with nothing to draw is left out of the legend.
scene::Layer described(const scene::Layer& layer) {
  scene::Layer info;
  info.id = layer.id;
  info.label = layer.label;
  info.primitive = layer.primitive;
  info.color = layer.color;
  info.size = layer.size;
  info.lit = layer.lit;
  info.translucent = layer.translucent;
  info.in_legend = layer.in_legend && !layer.positions.empty();
  info.cut = layer.cut;
  info.scales = layer.scales;
  info.part_of = layer.part_of;
  return info;
}

}  // namespace

// Where each layer lies, thinned to about 100,000 points in all (the positions themselves live
// on the GPU only): vertices and the middles of triangles, balls' centres with their radii, and
// segments whole (a long Voronoi edge crosses a corner far from its ends and its middle).
Legend_layout::Legend_layout(const scene::Scene& scene)
    : shown_{scene.dimension, scene.title, {}, scene.lower, scene.upper} {
  std::size_t total = 0;
  for (const auto& layer : scene.layers) total += layer.positions.size();
  const std::size_t stride = std::max<std::size_t>(1, total / 100000);
  for (const auto& layer : scene.layers) {
    const std::size_t corners = layer.primitive == scene::Primitive::lines       ? 2
                                : layer.primitive == scene::Primitive::triangles ? 3
                                                                                 : 1;
    std::vector<glm::vec4> marks;
    std::vector<std::pair<glm::vec3, glm::vec3>> segments;
    for (std::size_t i = 0; i + corners <= layer.positions.size(); i += corners * stride) {
      if (corners == 2) {
        const auto &a = layer.positions[i], &b = layer.positions[i + 1];
        segments.push_back({{a[0], a[1], a[2]}, {b[0], b[1], b[2]}});
        continue;
      }
      glm::vec3 middle(0.0f);
      for (std::size_t j = 0; j < corners; ++j) {
        const auto& p = layer.positions[i + j];
        marks.emplace_back(p[0], p[1], p[2], 0.0f);
        middle += glm::vec3(p[0], p[1], p[2]) / float(corners);
      }
      const float radius = i < layer.radii.size() ? layer.radii[i] : 0.0f;
      if (corners > 1 || radius > 0) marks.emplace_back(middle, radius);
    }
    landmarks_.push_back(std::move(marks));
    segments_.push_back(std::move(segments));
    shown_.layers.push_back(described(layer));
  }
}

// The corner for a box of w by h pixels, `inset` from the edges, that the fewest of the drawn
// layers' landmarks fall in (projected by the camera) and segments cross: the top left when none
// does, so that a legend moves only off the data; else the top right or the bottom right (the title
// is at the bottom left, `title_width` long and `title_height` high), whichever covers fewest.
Legend_layout::Corner Legend_layout::emptiest_corner(const Camera& camera, int width, int height,
                                                     float w, float h, float inset,
                                                     float title_width, float title_height,
                                                     const Draw_options& options) const {
  std::vector<std::pair<float, float>> corners = {{inset, inset}};
  if (width - inset - w > inset + w) corners.push_back({width - inset - w, inset});
  if (width - inset - w > title_width && height - inset - h - title_height > inset + h)
    corners.push_back({width - inset - w, height - inset - h - title_height});
  const glm::mat4 view = camera.view();
  const glm::mat4 view_projection = camera.projection(float(width) / float(height)) * view;
  // A ball is seen as a disc: its outline, across the view (the camera's right and up).
  const glm::vec3 right(view[0][0], view[1][0], view[2][0]), up(view[0][1], view[1][1], view[2][1]);
  std::vector<std::size_t> inside(corners.size(), 0);
  // In pixels from the top left; nothing for a point behind the camera.
  const auto on_screen = [&](const glm::vec3& p) -> std::optional<glm::vec2> {
    const glm::vec4 clip = view_projection * glm::vec4(p, 1.0f);
    if (!(clip.w > 0)) return std::nullopt;
    return glm::vec2((clip.x / clip.w + 1) * 0.5f * float(width),
                     (1 - clip.y / clip.w) * 0.5f * float(height));
  };
  const auto count = [&](const glm::vec3& p) {
    const auto at = on_screen(p);
    if (!at) return;
    for (std::size_t k = 0; k < corners.size(); ++k) {
      const auto [cx, cy] = corners[k];
      if (at->x >= cx && at->x <= cx + w && at->y >= cy && at->y <= cy + h) ++inside[k];
    }
  };
  for (std::size_t l = 0; l < shown_.layers.size(); ++l) {
    if (hidden(shown_.layers[l], options)) continue;
    for (const glm::vec4& mark : landmarks_[l]) {
      const glm::vec3 p(mark);
      count(p);
      if (mark.w > 0) {
        for (int a = 0; a < 16; ++a) {
          const float angle = float(a) * 0.3927f;  // a sixteenth of the turn
          count(p + mark.w * (std::cos(angle) * right + std::sin(angle) * up));
        }
      }
    }
    for (const auto& [from, to] : segments_[l]) {
      const auto a = on_screen(from), b = on_screen(to);
      if (!a || !b) {  // running past the eye: its end in front, at least
        count(a ? from : to);
        continue;
      }
      for (std::size_t k = 0; k < corners.size(); ++k) {
        const auto [cx, cy] = corners[k];
        if (crosses_box(*a, *b, cx, cy, cx + w, cy + h)) ++inside[k];
      }
    }
  }
  const std::size_t fewest =
      inside[0] == 0 ? 0
                     : std::size_t(std::min_element(inside.begin(), inside.end()) - inside.begin());
  return {corners[fewest].first, corners[fewest].second, inside[fewest]};
}

// The legend's place and size: its text at the picture's size (half as fast as the points and
// lines grow: it is read, not found), at most two fifths of the picture's width and half its
// height however large that asks (a projector's picture scale), in the corner clearest of data.
Legend_layout::Place Legend_layout::place(const Camera& camera, int width, int height,
                                          const Draw_options& options) const {
  Place place;
  const float scale = text_scale(height, options);
  const float line = 12 * scale, margin = 8 * scale;
  float widest = 0;
  for (const auto& layer : shown_.layers) {
    if (!layer.in_legend || hidden(layer, options)) continue;
    place.listed.push_back(&layer);
    widest = std::max(widest, text_width(layer.label));
  }
  if (place.listed.empty()) return place;
  const float asked_w = 18 * scale + scale * widest,
              asked_h = (12 * float(place.listed.size()) + 6) * scale;
  place.size = std::max(1.0f, std::min({scale, scale * 0.4f * float(width) / asked_w,
                                        scale * 0.5f * float(height) / asked_h}));
  place.pad = 3 * place.size;
  place.w = 12 * place.size + place.size * widest + 2 * place.pad;
  place.h = 12 * place.size * float(place.listed.size()) + 2 * place.pad;
  float title_width = 0;
  const auto title = title_lines(width, height, options);
  for (const auto& part : title)
    title_width = std::max(title_width, scale * text_width(part) + 2 * margin);
  place.corner = emptiest_corner(
      camera, width, height, place.w + 2, place.h + 2, margin - place.pad - 1, title_width,
      line * float(std::max<std::size_t>(title.size(), 1)) + margin, options);
  return place;
}

float Legend_layout::text_scale(int height, const Draw_options& options) {
  return (height >= 600 ? 2.0f : 1.0f) *
         (1.0f + 0.5f * std::max(0.0f, options.picture_scale - 1.0f));
}

// A title wider than the picture is wrapped at spaces, never clipped.
std::vector<std::string> Legend_layout::title_lines(int width, int height,
                                                    const Draw_options& options) const {
  if (!options.title) return {};
  const float scale = text_scale(height, options), margin = 8 * scale;
  return wrapped(shown_.title, (float(width) - 2 * margin) / scale);
}

bool Legend_layout::over_data(const Camera& camera, int width, int height,
                              const Draw_options& options) const {
  return options.legend && place(camera, width, height, options).corner.covered > 0;
}

Camera with_room_for_legend(const Legend_layout& layout, Camera camera, int width, int height,
                            const Draw_options& options, int* steps, int most_steps) {
  Camera stepped = camera;
  int taken = 0;
  while (layout.over_data(stepped, width, height, options)) {
    if (++taken > most_steps) {
      stepped = camera;
      taken = 0;
      break;
    }
    stepped.zoom(legend_step_back);
  }
  if (steps) *steps = taken;
  return stepped;
}

}  // namespace sculpt::render
