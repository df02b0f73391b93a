// The headless rendering module: an OSMesa OpenGL 3.3 core context (Mesa's llvmpipe) drawing
// into a 4x multisampled offscreen framebuffer, read back as an Image. Built as
// libsculpt_osmesa.so and loaded by headless.cpp when a picture is first asked for.
#include "render/offscreen.hpp"

// gl.hpp first: osmesa.h includes GL/gl.h, which must see GL_GLEXT_PROTOTYPES.
#include "render/gl.hpp"
// clang-format off
#include <GL/osmesa.h>
// clang-format on

#include <cstdlib>
#include <memory>
#include <stdexcept>
#include <vector>

namespace sculpt::render {

namespace {

struct Osmesa_context {
  OSMesaContext context = nullptr;
  std::vector<unsigned char> dummy =
      std::vector<unsigned char>(16 * 16 * 4);  // OSMesa's own buffer; we draw to FBOs

  Osmesa_context() {
    // llvmpipe, whatever else Mesa finds: pictures must not depend on the machine.
    setenv("GALLIUM_DRIVER", "llvmpipe", 0);
    const int attributes[] = {OSMESA_FORMAT,
                              OSMESA_RGBA,
                              OSMESA_DEPTH_BITS,
                              24,
                              OSMESA_PROFILE,
                              OSMESA_CORE_PROFILE,
                              OSMESA_CONTEXT_MAJOR_VERSION,
                              3,
                              OSMESA_CONTEXT_MINOR_VERSION,
                              3,
                              0};
    context = OSMesaCreateContextAttribs(attributes, nullptr);
    if (!context) throw std::runtime_error("OSMesa cannot create an OpenGL 3.3 core context");
    if (!OSMesaMakeCurrent(context, dummy.data(), GL_UNSIGNED_BYTE, 16, 16)) {
      OSMesaDestroyContext(context);
      throw std::runtime_error("OSMesa cannot make its context current");
    }
  }
  ~Osmesa_context() { OSMesaDestroyContext(context); }

  // A context is current per thread: a caller that renders from several threads (one at a time,
  // e.g. a Python program's) makes it current on each.
  void make_current() {
    if (OSMesaGetCurrentContext() == context) return;
    if (!OSMesaMakeCurrent(context, dummy.data(), GL_UNSIGNED_BYTE, 16, 16)) {
      throw std::runtime_error("OSMesa cannot make its context current");
    }
  }
};

// A framebuffer of one or several samples with colour and depth renderbuffers.
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
      throw std::runtime_error("cannot make a " + std::to_string(width) + "x" +
                               std::to_string(height) + " offscreen framebuffer");
    }
  }
  ~Framebuffer() {
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteRenderbuffers(2, renderbuffers_);
    glDeleteFramebuffers(1, &framebuffer_);
  }
  GLuint id() const { return framebuffer_; }

 private:
  GLuint framebuffer_ = 0;
  GLuint renderbuffers_[2] = {0, 0};
};

class Osmesa_offscreen : public Offscreen_renderer {
 public:
  Osmesa_offscreen()
      : context_(std::make_unique<Osmesa_context>()), renderer_(std::make_unique<Renderer>()) {}
  ~Osmesa_offscreen() override {
    context_->make_current();
    renderer_.reset();  // its GL objects go while the context still exists
  }

  const char* gl_renderer() const override {
    return reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  }

  Image render(const scene::Scene& scene, const Camera& camera, int width, int height,
               const Draw_options& options) override {
    if (width <= 0 || height <= 0 || width > max_image_side || height > max_image_side) {
      throw std::runtime_error("image size out of range: " + std::to_string(width) + "x" +
                               std::to_string(height));
    }
    context_->make_current();
    const Framebuffer multisampled(width, height, 4);
    const Framebuffer resolved(width, height, 0);
    glBindFramebuffer(GL_FRAMEBUFFER, multisampled.id());
    renderer_->set_scene(scene);
    renderer_->draw(camera, width, height, options);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, multisampled.id());
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, resolved.id());
    glBlitFramebuffer(0, 0, width, height, 0, 0, width, height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, resolved.id());

    Image image = read_pixels(width, height);
    renderer_->set_scene({});
    if (glGetError() != GL_NO_ERROR)
      throw std::runtime_error("OpenGL reported an error while rendering");
    return image;
  }

 private:
  std::unique_ptr<Osmesa_context> context_;
  std::unique_ptr<Renderer> renderer_;
};

}  // namespace

}  // namespace sculpt::render

extern "C" __attribute__((visibility("default"))) sculpt::render::Offscreen_renderer*
sculpt_make_offscreen_renderer(int interface_version, std::string* error) {
  if (interface_version != sculpt::render::offscreen_interface_version) {
    *error = "the headless renderer module was built from other sources than this program";
    return nullptr;
  }
  try {
    return new sculpt::render::Osmesa_offscreen();
  } catch (const std::exception& e) {
    *error = e.what();
    return nullptr;
  }
}
