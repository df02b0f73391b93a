// SPDX-License-Identifier: GPL-3.0-or-later
// include/sculpt/io.hpp over the project's own readers and writers (src/io): their io::Error
// becomes the public File_error, so that a program sees only the public header's types.
#include <sculpt/io.hpp>

#include "io/destinations.hpp"
#include "io/point_reader.hpp"
#include "io/result_files.hpp"

namespace sculpt {
namespace {

template <class Action>
auto as_file_error(Action&& action) -> decltype(action()) {
  try {
    return action();
  } catch (const io::Error& e) {
    throw File_error(e.what());
  }
}

template <int D>
void write_checked(const Reconstruction<D>& result, const std::string& path,
                   const std::string& solid_path, bool ascii, const Point_attributes& attributes) {
  as_file_error([&] {
    io::check_result_formats<D>(path, solid_path);
    const std::string extension = io::extension_of(path);
    if (ascii && extension != ".stl" && extension != ".ply") {
      throw io::Error("ascii writes .stl and .ply as text; '" + path + "' is text already");
    }
    if (!solid_path.empty() && result.solid.empty()) {
      throw io::Error(std::string("the method ") + to_string(result.options.method) +
                      " built no solid to write as '" + solid_path + "'");
    }
    io::write_result(result, path, solid_path, ascii, attributes);
  });
}

}  // namespace

std::vector<Point<2>> Point_file::planar() const {
  return as_file_error([&] {
    io::Point_set set;
    set.points = points;
    set.dimension = dimension;
    return io::planar_points(set);
  });
}

Point_file read_points(const std::string& path, bool merge_duplicates) {
  return as_file_error([&] {
    io::Point_set set = io::read_points(path);
    io::remember_input(path);  // no write() may replace it
    if (merge_duplicates) io::merge_duplicates(set);
    Point_file file;
    file.dimension = set.dimension;
    file.points = std::move(set.points);
    file.triangles.assign(set.triangles.begin(), set.triangles.end());
    file.attributes = std::move(set.attributes);
    file.warnings = std::move(set.warnings);
    return file;
  });
}

void write(const Reconstruction<3>& result, const std::string& path, const std::string& solid_path,
           bool ascii, const Point_attributes& attributes) {
  write_checked<3>(result, path, solid_path, ascii, attributes);
}

void write(const Reconstruction<2>& result, const std::string& path,
           const std::string& solid_path) {
  write_checked<2>(result, path, solid_path, false, {});
}

}  // namespace sculpt
