// SPDX-License-Identifier: GPL-3.0-or-later
#include "render/picture_cache.hpp"

#include "render/gl.hpp"

namespace sculpt::render {

Picture_cache::~Picture_cache() {
  release();
}

bool Picture_cache::same(const Key& a, const Key& b) {
  const Camera &p = a.camera, &q = b.camera;
  return a.scene == b.scene && a.width == b.width && a.height == b.height && a.legend == b.legend &&
         a.title == b.title && a.background.r == b.background.r &&
         a.background.g == b.background.g && a.background.b == b.background.b &&
         a.background.a == b.background.a && a.hidden_layers == b.hidden_layers &&
         a.picture_scale == b.picture_scale && p.dimension == q.dimension && p.target == q.target &&
         p.distance == q.distance && p.yaw == q.yaw && p.pitch == q.pitch &&
         p.fov_degrees == q.fov_degrees && p.center == q.center && p.half_height == q.half_height;
}

void Picture_cache::release() {
  if (multisampled_) glDeleteFramebuffers(1, &multisampled_);
  if (resolved_) glDeleteFramebuffers(1, &resolved_);
  glDeleteRenderbuffers(3, renderbuffers_);
  multisampled_ = resolved_ = 0;
  renderbuffers_[0] = renderbuffers_[1] = renderbuffers_[2] = 0;
  width_ = height_ = 0;
  cached_.reset();
}

void Picture_cache::make_framebuffers(int width, int height) {
  release();
  glGenRenderbuffers(3, renderbuffers_);
  glGenFramebuffers(1, &multisampled_);
  glBindFramebuffer(GL_FRAMEBUFFER, multisampled_);
  glBindRenderbuffer(GL_RENDERBUFFER, renderbuffers_[0]);
  glRenderbufferStorageMultisample(GL_RENDERBUFFER, 4, GL_RGBA8, width, height);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER,
                            renderbuffers_[0]);
  glBindRenderbuffer(GL_RENDERBUFFER, renderbuffers_[1]);
  glRenderbufferStorageMultisample(GL_RENDERBUFFER, 4, GL_DEPTH_COMPONENT24, width, height);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER,
                            renderbuffers_[1]);
  glGenFramebuffers(1, &resolved_);
  glBindFramebuffer(GL_FRAMEBUFFER, resolved_);
  glBindRenderbuffer(GL_RENDERBUFFER, renderbuffers_[2]);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER,
                            renderbuffers_[2]);
  width_ = width;
  height_ = height;
}

void Picture_cache::draw(Renderer& renderer, const Camera& camera, int width, int height,
                         const Draw_options& options) {
  GLint target = 0;  // the framebuffer to draw into (the window's)
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &target);
  Key key{renderer.scene_generation(),
          camera,
          width,
          height,
          options.legend,
          options.title,
          options.background,
          options.hidden_layers,
          options.picture_scale};
  if (width != width_ || height != height_) make_framebuffers(width, height);
  if (!cached_ || !same(*cached_, key)) {
    Draw_options at_origin = options;
    at_origin.viewport_x = at_origin.viewport_y = 0;
    glBindFramebuffer(GL_FRAMEBUFFER, multisampled_);
    renderer.draw(camera, width, height, at_origin);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, multisampled_);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, resolved_);
    glBlitFramebuffer(0, 0, width, height, 0, 0, width, height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    cached_ = std::move(key);
    ++scenes_drawn_;
  }
  glBindFramebuffer(GL_READ_FRAMEBUFFER, resolved_);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, GLuint(target));
  const int x = options.viewport_x, y = options.viewport_y;
  glBlitFramebuffer(0, 0, width, height, x, y, x + width, y + height, GL_COLOR_BUFFER_BIT,
                    GL_NEAREST);
  glBindFramebuffer(GL_FRAMEBUFFER, GLuint(target));
}

}  // namespace sculpt::render
