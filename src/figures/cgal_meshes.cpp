// SPDX-License-Identifier: GPL-3.0-or-later
#include "cgal_meshes.hpp"

#include <unistd.h>

#include <cstdlib>
#include <filesystem>

#include "io/io_error.hpp"

namespace sculpt::figures {

Cgal_meshes::~Cgal_meshes() {
  std::error_code ignored;
  if (!folder_.empty()) std::filesystem::remove_all(folder_, ignored);
}

void Cgal_meshes::unpack(const std::set<std::string>& meshes) {
  std::string missing;
  for (const auto& mesh : meshes) {
    if (!unpacked_.count(mesh)) missing += " 'data/meshes/" + mesh + "'";
  }
  if (missing.empty()) return;
  if (!std::filesystem::exists(archive_)) {
    throw io::Error(archive_ +
                    " is missing: install Debian's libcgal-demo (scripts/install-dependencies)");
  }
  if (folder_.empty()) {
    folder_ = (std::filesystem::temp_directory_path() /
               ("sculpt-cgal-meshes-" + std::to_string(getpid())))
                  .string();
    std::filesystem::create_directories(folder_);
  }
  const std::string command =
      "tar -xzf '" + archive_ + "' -C '" + folder_ + "'" + missing + " 2>/dev/null";
  if (std::system(command.c_str()) != 0)
    throw io::Error("cannot unpack" + missing + " from " + archive_);
  unpacked_.insert(meshes.begin(), meshes.end());
}

frontend::Shot Cgal_meshes::resolve(frontend::Shot shot) {
  if (shot.input.rfind("cgal:", 0) != 0) return shot;
  const std::string mesh = shot.input.substr(5);
#ifdef __EMSCRIPTEN__
  // In the browser the site holds the meshes: the page fetches /cgal/NAME from its meshes/
  // folder when a reconstruction reads it (web/sculpt-page.js).
  shot.input = "/cgal/" + mesh;
  return shot;
#endif
  unpack({mesh});
  shot.input = (std::filesystem::path(folder_) / "data" / "meshes" / mesh).string();
  return shot;
}

}  // namespace sculpt::figures
