// SPDX-License-Identifier: GPL-3.0-or-later
#include "render/framebuffer.hpp"

#include <stdexcept>
#include <string>

#include "render/gl.hpp"

namespace sculpt::render {

namespace {

// A framebuffer of one or several samples with colour and depth renderbuffers; when it goes,
// the window's (0) is bound.
class Framebuffer {
 public:
  Framebuffer(int width, int height, int samples) {
    glGenFramebuffers(1, &framebuffer_);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
    glGenRenderbuffers(2, renderbuffers_);
    glBindRenderbuffer(GL_RENDERBUFFER, renderbuffers_[0]);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_RGBA8, width, height);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER,
                              renderbuffers_[0]);
    glBindRenderbuffer(GL_RENDERBUFFER, renderbuffers_[1]);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_DEPTH_COMPONENT24, width, height);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER,
                              renderbuffers_[1]);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
      release();
      throw std::runtime_error("cannot make a " + std::to_string(width) + "x" +
                               std::to_string(height) + " offscreen framebuffer");
    }
  }
  ~Framebuffer() { release(); }
  Framebuffer(const Framebuffer&) = delete;
  Framebuffer& operator=(const Framebuffer&) = delete;
  GLuint id() const { return framebuffer_; }

 private:
  void release() {
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteRenderbuffers(2, renderbuffers_);
    glDeleteFramebuffers(1, &framebuffer_);
  }
  GLuint framebuffer_ = 0;
  GLuint renderbuffers_[2] = {0, 0};
};

}  // namespace

Image draw_offscreen(Renderer& renderer, const scene::Scene& scene, const Camera& camera, int width,
                     int height, const Draw_options& options) {
  if (width <= 0 || height <= 0 || width > max_image_side || height > max_image_side) {
    throw std::runtime_error("image size out of range: " + std::to_string(width) + "x" +
                             std::to_string(height));
  }
  while (glGetError() != GL_NO_ERROR) {
  }  // an error left by someone else is not this picture's
  const Framebuffer multisampled(width, height, 4);
  const Framebuffer resolved(width, height, 0);
  glBindFramebuffer(GL_FRAMEBUFFER, multisampled.id());
  renderer.set_scene(scene);
  renderer.draw(camera, width, height, options);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, multisampled.id());
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, resolved.id());
  glBlitFramebuffer(0, 0, width, height, 0, 0, width, height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, resolved.id());
  Image image = read_pixels(width, height);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  if (glGetError() != GL_NO_ERROR)
    throw std::runtime_error("OpenGL reported an error while rendering");
  return image;
}

Context_picture_renderer::Context_picture_renderer() : renderer_(std::make_unique<Renderer>()) {}

Context_picture_renderer::~Context_picture_renderer() = default;

Image Context_picture_renderer::render(const scene::Scene& scene, const Camera& camera, int width,
                                       int height, const Draw_options& options) {
  Image image = draw_offscreen(*renderer_, scene, camera, width, height, options);
  renderer_->set_scene({});  // its geometry is not kept on the GPU between pictures
  return image;
}

}  // namespace sculpt::render
