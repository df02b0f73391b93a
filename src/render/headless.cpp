#include "headless.hpp"

#include <dlfcn.h>

#include <filesystem>
#include <stdexcept>
#include <vector>

#include "render/offscreen.hpp"

namespace sculpt::render {
namespace {

// The module beside the executable (build tree, or an installed bin/), in ../lib/sculpt (an
// installed tree), or where the build put it (the tests run from their own folder).
Make_offscreen_renderer find_module() {
  std::vector<std::filesystem::path> places;
  std::error_code error;
  const auto executable = std::filesystem::read_symlink("/proc/self/exe", error);
  if (!error) {
    places.push_back(executable.parent_path() / offscreen_module_name);
    places.push_back(executable.parent_path() / "../lib/sculpt" / offscreen_module_name);
  }
  places.push_back(std::filesystem::path(SCULPT_MODULE_DIR) / offscreen_module_name);
  std::string failures;
  for (const auto& place : places) {
    if (!std::filesystem::exists(place, error)) continue;
    void* module = dlopen(place.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!module) {
      failures += std::string(" ") + dlerror();
      continue;
    }
    const auto make =
        reinterpret_cast<Make_offscreen_renderer>(dlsym(module, make_offscreen_renderer_symbol));
    if (make) return make;  // the module stays loaded for the life of the process
    failures += " " + place.string() + " has no " + make_offscreen_renderer_symbol;
    dlclose(module);
  }
  std::string searched;
  for (const auto& place : places) searched += " " + place.string();
  throw std::runtime_error(std::string("cannot load the headless renderer ") +
                           offscreen_module_name +
                           (failures.empty() ? " (looked for" + searched + ")" : ":" + failures));
}

// Loaded once per process, whichever thread asks first.
Make_offscreen_renderer load_module() {
  static const Make_offscreen_renderer make = find_module();
  return make;
}

}  // namespace

Headless_renderer::Headless_renderer() {
  std::string error;
  offscreen_.reset(load_module()(offscreen_interface_version, &error));
  if (!offscreen_) throw std::runtime_error(error);
}

Headless_renderer::~Headless_renderer() = default;

const char* Headless_renderer::gl_renderer() const {
  return offscreen_->gl_renderer();
}

Image Headless_renderer::render(const scene::Scene& scene, const Camera& camera, int width,
                                int height, const Draw_options& options) {
  return offscreen_->render(scene, camera, width, height, options);
}

}  // namespace sculpt::render
