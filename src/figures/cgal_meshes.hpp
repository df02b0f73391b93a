// SPDX-License-Identifier: GPL-3.0-or-later
// The CGAL meshes some figures are drawn from, unpacked on demand from Debian's libcgal-demo
// archive into a temporary folder of their own that lives as long as this object (in the
// browser, fetched from the site).
#pragma once

#include <set>
#include <string>

#include "frontend/shot.hpp"

namespace sculpt::figures {

class Cgal_meshes {
 public:
  explicit Cgal_meshes(std::string archive = "/usr/share/doc/libcgal-demo/data.tar.gz")
      : archive_(std::move(archive)) {}
  ~Cgal_meshes();
  Cgal_meshes(const Cgal_meshes&) = delete;
  Cgal_meshes& operator=(const Cgal_meshes&) = delete;

  // Replaces a shot's input "cgal:NAME.off" by the path of the unpacked mesh, unpacking it
  // first if needed; other shots are returned as they are. Throws io::Error with a one-line
  // message when the archive is missing or does not hold the mesh.
  frontend::Shot resolve(frontend::Shot shot);
  // Unpacks these meshes ("NAME.off") in one go.
  void unpack(const std::set<std::string>& meshes);

 private:
  std::string archive_, folder_;
  std::set<std::string> unpacked_;
};

}  // namespace sculpt::figures
