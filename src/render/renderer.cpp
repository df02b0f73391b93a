// SPDX-License-Identifier: GPL-3.0-or-later
#include "renderer.hpp"

#include <stb/stb_easy_font.h>

#include <algorithm>
#include <cmath>
#include <glm/gtc/type_ptr.hpp>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "render/gl.hpp"
#include "render/shader_sources.hpp"

namespace sculpt::render {
namespace {

GLuint compile(GLenum kind, const char* source) {
  const GLuint shader = glCreateShader(kind);
  const char* parts[] = {shader_header, source};
  glShaderSource(shader, 2, parts, nullptr);
  glCompileShader(shader);
  GLint ok = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char log[4096];
    glGetShaderInfoLog(shader, sizeof log, nullptr, log);
    throw std::runtime_error(std::string("a shader does not compile: ") + log);
  }
  return shader;
}

GLuint link(const char* vertex, const char* fragment) {
  const GLuint program = glCreateProgram();
  const GLuint shaders[2] = {compile(GL_VERTEX_SHADER, vertex),
                             compile(GL_FRAGMENT_SHADER, fragment)};
  for (GLuint s : shaders) glAttachShader(program, s);
  glLinkProgram(program);
  for (GLuint s : shaders) glDeleteShader(s);
  GLint ok = 0;
  glGetProgramiv(program, GL_LINK_STATUS, &ok);
  if (!ok) {
    char log[4096];
    glGetProgramInfoLog(program, sizeof log, nullptr, log);
    throw std::runtime_error(std::string("a shader program does not link: ") + log);
  }
  return program;
}

GLint uniform(GLuint program, const char* name) {
  return glGetUniformLocation(program, name);
}

void set_color(GLuint program, const scene::Color& c) {
  glUniform4f(uniform(program, "color"), c.r, c.g, c.b, c.a);
}

}  // namespace

struct Renderer::Programs {
  GLuint points = link(shaders::points_vert, shaders::points_frag);
  GLuint lines = link(shaders::lines_vert, shaders::flat_frag);
  GLuint mesh = link(shaders::mesh_vert, shaders::mesh_frag);
  GLuint balls = link(shaders::balls_vert, shaders::balls_frag);
  GLuint screen = link(shaders::screen_vert, shaders::flat_frag);
  ~Programs() {
    for (GLuint p : {points, lines, mesh, balls, screen}) glDeleteProgram(p);
  }
};

// A layer's vertex array: positions (location 0), normals (1) and radii (2) as it needs them.
// Lines and balls are drawn as instances of a four-vertex strip, the shaders widening each into
// a quad (WebGL has no geometry shaders): their attributes advance once per instance, a line's
// two ends read from consecutive positions (locations 0 and 3).
struct Renderer::Gpu_layer {
  GLuint array = 0;
  GLuint buffers[3] = {0, 0, 0};
  GLsizei count = 0;
  bool has_normals = false;
};

Renderer::Renderer() : programs_(std::make_unique<Programs>()) {
  glGenVertexArrays(1, &overlay_array_);
  glGenBuffers(1, &overlay_buffer_);
}

Renderer::~Renderer() {
  set_scene({});
  glDeleteBuffers(1, &overlay_buffer_);
  glDeleteVertexArrays(1, &overlay_array_);
}

void Renderer::set_scene(const scene::Scene& scene) {
  ++generation_;
  for (auto& layer : layers_) {
    glDeleteBuffers(3, layer.buffers);
    glDeleteVertexArrays(1, &layer.array);
  }
  layers_.clear();
  legend_ = Legend_layout(scene);
  for (const auto& layer : scene.layers) {
    Gpu_layer gpu;
    gpu.count = static_cast<GLsizei>(layer.positions.size());
    gpu.has_normals = !layer.normals.empty();
    glGenVertexArrays(1, &gpu.array);
    glBindVertexArray(gpu.array);
    glGenBuffers(3, gpu.buffers);
    const bool instanced =
        layer.primitive == scene::Primitive::lines || layer.primitive == scene::Primitive::balls;
    const auto pointer = [&](int location, int components, int stride, std::size_t offset) {
      glEnableVertexAttribArray(location);
      glVertexAttribPointer(location, components, GL_FLOAT, GL_FALSE, stride,
                            reinterpret_cast<const void*>(offset));
      glVertexAttribDivisor(location, instanced ? 1 : 0);
    };
    const auto attribute = [&](int location, GLuint buffer, const void* data, std::size_t bytes,
                               int components) {
      glBindBuffer(GL_ARRAY_BUFFER, buffer);
      glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(bytes), data, GL_STATIC_DRAW);
      pointer(location, components, 0, 0);
    };
    attribute(0, gpu.buffers[0], layer.positions.data(),
              layer.positions.size() * sizeof(scene::Vec3), 3);
    if (layer.primitive == scene::Primitive::lines) {
      // A segment's start and end: every other position, from the first and from the second.
      constexpr int segment = 2 * sizeof(scene::Vec3);
      pointer(0, 3, segment, 0);
      pointer(3, 3, segment, sizeof(scene::Vec3));
    }
    if (gpu.has_normals) {
      attribute(1, gpu.buffers[1], layer.normals.data(), layer.normals.size() * sizeof(scene::Vec3),
                3);
    } else {
      glVertexAttrib3f(1, 0, 0, 1);
    }
    if (!layer.radii.empty()) {
      attribute(2, gpu.buffers[2], layer.radii.data(), layer.radii.size() * sizeof(float), 1);
    }
    glBindVertexArray(0);
    layers_.push_back(gpu);
  }
}

void Renderer::draw(const Camera& camera, int width, int height, const Draw_options& options) {
  glViewport(options.viewport_x, options.viewport_y, width, height);
  const auto& bg = options.background;
  glClearColor(bg.r, bg.g, bg.b, bg.a);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
#ifndef __EMSCRIPTEN__
  glEnable(GL_PROGRAM_POINT_SIZE);  // always on in OpenGL ES
#endif

  const scene::Scene& shown = legend_.scene();
  const bool three = shown.dimension == 3;
  if (three) {
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
  } else {
    glDisable(GL_DEPTH_TEST);
  }
  // 3D: opaque triangles first (pushed back so edges on them show), then lines and points,
  // translucent balls last without writing depth. 2D: layer order is drawing order.
  const scene::Primitive order_3d[] = {scene::Primitive::triangles, scene::Primitive::lines,
                                       scene::Primitive::points, scene::Primitive::balls};
  if (three) {
    for (auto primitive : order_3d) {
      for (std::size_t i = 0; i < layers_.size(); ++i) {
        if (shown.layers[i].primitive == primitive && !hidden(shown.layers[i], options)) {
          draw_layer(layers_[i], shown.layers[i], camera, width, height, options.picture_scale);
        }
      }
    }
  } else {
    for (std::size_t i = 0; i < layers_.size(); ++i) {
      if (!hidden(shown.layers[i], options))
        draw_layer(layers_[i], shown.layers[i], camera, width, height, options.picture_scale);
    }
  }
  draw_overlay(camera, width, height, options);
}

Image read_pixels(int width, int height) {
  Image image;
  image.width = width;
  image.height = height;
  image.rgba.resize(std::size_t(width) * height * 4);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, image.rgba.data());
  // GL's rows start at the bottom; images start at the top.
  const std::size_t row = std::size_t(width) * 4;
  for (int y = 0; y < height / 2; ++y) {
    std::swap_ranges(image.rgba.begin() + y * row, image.rgba.begin() + (y + 1) * row,
                     image.rgba.begin() + (height - 1 - y) * row);
  }
  return image;
}

void Renderer::draw_layer(const Gpu_layer& layer, const scene::Layer& info, const Camera& camera,
                          int width, int height, float picture_scale) {
  if (layer.count == 0) return;
  // A point's diameter, a line's width (pixels).
  const float size = info.size * (info.scales ? picture_scale : 1.0f);
  const float aspect = float(width) / float(height);
  const glm::mat4 view = camera.view();
  const glm::mat4 projection = camera.projection(aspect);
  const glm::mat4 view_projection = projection * view;
  glBindVertexArray(layer.array);
  switch (info.primitive) {
    case scene::Primitive::points: {
      const GLuint p = programs_->points;
      glUseProgram(p);
      glUniformMatrix4fv(uniform(p, "view_projection"), 1, GL_FALSE,
                         glm::value_ptr(view_projection));
      glUniform1f(uniform(p, "point_size"), size);
      glUniform1i(uniform(p, "shaded"), camera.dimension == 3 ? 1 : 0);
      // A few millionths of the depth range: enough for a nearer point to round over a
      // farther one, too little to lift a point through the surface it lies on.
      glUniform1f(uniform(p, "depth_radius"), camera.dimension == 3 ? 2e-6f * size : 0.0f);
      set_color(p, info.color);
      glDrawArrays(GL_POINTS, 0, layer.count);
      break;
    }
    case scene::Primitive::lines: {
      const GLuint p = programs_->lines;
      glUseProgram(p);
      glUniformMatrix4fv(uniform(p, "view_projection"), 1, GL_FALSE,
                         glm::value_ptr(view_projection));
      glUniform2f(uniform(p, "viewport"), float(width), float(height));
      glUniform1f(uniform(p, "line_width"), size);
      set_color(p, info.color);
      glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, layer.count / 2);
      break;
    }
    case scene::Primitive::triangles: {
      const GLuint p = programs_->mesh;
      glUseProgram(p);
      glUniformMatrix4fv(uniform(p, "view"), 1, GL_FALSE, glm::value_ptr(view));
      glUniformMatrix4fv(uniform(p, "view_projection"), 1, GL_FALSE,
                         glm::value_ptr(view_projection));
      glUniform1i(uniform(p, "lit"), info.lit);
      glUniform1i(uniform(p, "smooth_normals"), layer.has_normals);
      set_color(p, info.color);
      glEnable(GL_POLYGON_OFFSET_FILL);
      glPolygonOffset(1.0f, 1.0f);
      glDrawArrays(GL_TRIANGLES, 0, layer.count);
      glDisable(GL_POLYGON_OFFSET_FILL);
      break;
    }
    case scene::Primitive::balls: {
      const GLuint p = programs_->balls;
      glUseProgram(p);
      glUniformMatrix4fv(uniform(p, "view"), 1, GL_FALSE, glm::value_ptr(view));
      glUniformMatrix4fv(uniform(p, "projection"), 1, GL_FALSE, glm::value_ptr(projection));
      glUniform1i(uniform(p, "translucent"), info.translucent);
      glUniform1f(uniform(p, "line_width"), size);
      set_color(p, info.color);
      glDepthMask(GL_FALSE);
      glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, layer.count);
      glDepthMask(GL_TRUE);
      break;
    }
  }
  glBindVertexArray(0);
}

// The legend and title: coloured swatches and text (stb_easy_font quads) in pixel coordinates.

void Renderer::draw_overlay(const Camera& camera, int width, int height,
                            const Draw_options& options) {
  struct Piece {
    scene::Color color;
    std::vector<float> triangles;  // x, y, z per vertex
  };
  std::vector<Piece> pieces;
  const float scale = Legend_layout::text_scale(height, options);
  const auto text = [&](float x, float y, const std::string& words, scene::Color color,
                        float size) {
    std::vector<char> quads(words.size() * 270 + 1000);
    const int count = stb_easy_font_print(0, 0, const_cast<char*>(words.c_str()), nullptr,
                                          quads.data(), static_cast<int>(quads.size()));
    Piece piece{color, {}};
    const auto* vertices = reinterpret_cast<const float*>(quads.data());  // x y z + 4 bytes colour
    for (int q = 0; q < count; ++q) {
      for (int corner : {0, 1, 2, 0, 2, 3}) {
        const float* v = vertices + (4 * q + corner) * 4;
        piece.triangles.insert(piece.triangles.end(), {x + size * v[0], y + size * v[1], 0.0f});
      }
    }
    pieces.push_back(std::move(piece));
  };
  const auto box = [&](float x, float y, float w, float h, scene::Color color) {
    pieces.push_back(
        {color, {x, y, 0, x + w, y, 0, x + w, y + h, 0, x, y, 0, x + w, y + h, 0, x, y + h, 0}});
  };
  const float line = 12 * scale, margin = 8 * scale;
  const std::vector<std::string> title = legend_.title_lines(width, height, options);
  if (options.legend) {
    // On a box of its own, so that the legend reads over the data in a small picture.
    const Legend_layout::Place place = legend_.place(camera, width, height, options);
    const std::vector<const scene::Layer*>& listed = place.listed;
    const float size = place.size, legend_line = 12 * size;
    const float left = place.corner.x + place.pad + 1, top = place.corner.y + place.pad + 1;
    if (!listed.empty()) {
      box(place.corner.x, place.corner.y, place.w + 2, place.h + 2, {0.55f, 0.55f, 0.55f, 1});
      box(place.corner.x + 1, place.corner.y + 1, place.w, place.h, {0.98f, 0.98f, 0.98f, 1});
    }
    float y = top;
    for (const scene::Layer* layer : listed) {
      scene::Color swatch = layer->color;
      swatch.a = 1;
      // An outline, so a light swatch shows on the light box.
      box(left - 1, y + 1 * size - 1, 8 * size + 2, 8 * size + 2, {0.3f, 0.3f, 0.3f, 1});
      box(left, y + 1 * size, 8 * size, 8 * size, swatch);
      text(left + 12 * size, y + 1 * size, layer->label, {0.1f, 0.1f, 0.1f, 1}, size);
      y += legend_line;
    }
  }
  for (std::size_t i = 0; i < title.size(); ++i) {
    const float from_bottom = float(title.size() - 1 - i) * line;
    text(margin, height - margin - 8 * scale - from_bottom, title[i], {0.1f, 0.1f, 0.1f, 1}, scale);
  }

  glDisable(GL_DEPTH_TEST);
  const GLuint p = programs_->screen;
  glUseProgram(p);
  glUniform2f(uniform(p, "viewport"), float(width), float(height));
  glBindVertexArray(overlay_array_);
  glBindBuffer(GL_ARRAY_BUFFER, overlay_buffer_);
  glEnableVertexAttribArray(0);
  for (const auto& piece : pieces) {
    if (piece.triangles.empty()) continue;
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(piece.triangles.size() * sizeof(float)),
                 piece.triangles.data(), GL_STREAM_DRAW);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
    set_color(p, piece.color);
    glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(piece.triangles.size() / 3));
  }
  glBindVertexArray(0);
}

}  // namespace sculpt::render
