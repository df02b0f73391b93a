// SPDX-License-Identifier: GPL-3.0-or-later
#include "headless.hpp"

#include <dlfcn.h>

#include <filesystem>
#include <stdexcept>
#include <vector>

#include "render/offscreen.hpp"

namespace sculpt::render {
namespace {

// Where this code was loaded from: the executable, or a shared object such as the Python module.
std::filesystem::path loaded_from() {
  Dl_info info{};
  if (dladdr(reinterpret_cast<void*>(&loaded_from), &info) && info.dli_fname &&
      info.dli_fname[0] == '/') {
    return info.dli_fname;
  }
  std::error_code error;
  const auto executable = std::filesystem::read_symlink("/proc/self/exe", error);
  return error ? std::filesystem::path() : executable;
}

// The module beside the program or library that renders (the build tree), where an installed
// tree keeps it relative to an installed executable or to the installed Python package, and
// where the build put it (the tests run from their own folder).
Make_offscreen_renderer find_module() {
  std::vector<std::filesystem::path> places;
  const auto from = loaded_from();
  if (!from.empty()) {
    const auto folder = from.parent_path();
    places.push_back(folder / offscreen_module_name);
    places.push_back((folder / SCULPT_MODULE_FROM_BIN / offscreen_module_name).lexically_normal());
    places.push_back(
        (folder / SCULPT_MODULE_FROM_PYTHON / offscreen_module_name).lexically_normal());
  }
  places.push_back(std::filesystem::path(SCULPT_MODULE_DIR) / offscreen_module_name);
  std::error_code error;
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
                           (failures.empty() ? " (looked for" + searched +
                                                   "; from Debian's packages, sculpt-render "
                                                   "holds it)"
                                             : ":" + failures));
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
