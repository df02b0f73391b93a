// SPDX-License-Identifier: GPL-3.0-or-later
// The headless rendering module: an OSMesa OpenGL 3.3 core context (Mesa's llvmpipe) drawing
// into a 4x multisampled offscreen framebuffer (render/framebuffer.hpp), read back as an Image.
// Built as libsculpt_osmesa.so and loaded by headless.cpp when a picture is first asked for.
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

#include "render/framebuffer.hpp"

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
    context_->make_current();
    Image image = draw_offscreen(*renderer_, scene, camera, width, height, options);
    renderer_->set_scene({});
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
