// SPDX-License-Identifier: GPL-3.0-or-later
// include/sculpt/io.hpp over the project's own readers and writers (src/io): their io::Error
// becomes the public File_error, so that a program sees only the public header's types.
#include <sculpt/io.hpp>

#include "io/destinations.hpp"
#include "io/output_set.hpp"
#include "io/point_reader.hpp"
#include "io/writers.hpp"

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
void write_result(const Reconstruction<D>& result, const std::string& path,
                  const std::string& solid_path, bool ascii) {
  as_file_error([&] {
    const std::string extension = io::extension_of(path);
    if (D == 3 ? !io::writes_surface(extension) : !io::writes_curve(extension)) {
      throw io::Error(std::string("cannot write a ") + (D == 3 ? "surface" : "curve") + " as '" +
                      path + "' (known: " + (D == 3 ? io::surface_formats : io::curve_formats) +
                      ")");
    }
    if (ascii && extension != ".stl" && extension != ".ply") {
      throw io::Error("ascii writes .stl and .ply as text; '" + path + "' is text already");
    }
    if (!solid_path.empty() && !io::writes_solid(io::extension_of(solid_path))) {
      throw io::Error("cannot write a solid as '" + solid_path + "' (known: " +
                      io::solid_formats + ")");
    }
    if (!solid_path.empty() && result.solid.empty()) {
      throw io::Error(std::string("the method ") + to_string(result.options.method) +
                      " built no solid to write as '" + solid_path + "'");
    }
    io::check_destinations(io::with_companions({path, solid_path}));
    const std::vector<Point<D>> samples(result.sites.begin(),
                                        result.sites.begin() + result.sample_count());
    const std::vector<Point<D>>& vertices =
        result.interpolates() ? samples : result.surface_vertices;
    io::Output_set outputs;  // all or none
    if constexpr (D == 3) {
      io::write_surface(outputs.stage(path), vertices, result.surface, ascii);
    } else {
      io::write_curve(outputs.stage(path), vertices, result.surface);
    }
    if (!solid_path.empty()) io::write_solid<D>(outputs.stage(solid_path), samples, result.solid);
    outputs.commit();
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
    file.warnings = std::move(set.warnings);
    return file;
  });
}

void write(const Reconstruction<3>& result, const std::string& path,
           const std::string& solid_path, bool ascii) {
  write_result<3>(result, path, solid_path, ascii);
}

void write(const Reconstruction<2>& result, const std::string& path,
           const std::string& solid_path) {
  write_result<2>(result, path, solid_path, false);
}

}  // namespace sculpt
