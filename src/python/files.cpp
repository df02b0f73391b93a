// SPDX-License-Identifier: GPL-3.0-or-later
// Files from Python: points (and their normals, colours and reference triangles) read as the
// command line reads them, and a result written as it writes it.
#include <filesystem>
#include <optional>
#include <string>
#include <type_traits>

#include "frontend/command_line.hpp"
#include "frontend/option_use.hpp"
#include "io/destinations.hpp"
#include "io/result_files.hpp"
#include "python/bindings.hpp"
#include "python/point_attributes.hpp"

namespace sculpt::python {
namespace {

// Writes the surface (3D) or curve (2D), and the solid if asked: all files or none.
void write_result(const Result& result, const std::filesystem::path& path_name,
                  const std::optional<std::filesystem::path>& solid_name, bool ascii,
                  const py::object& normals, const py::object& colors) {
  const std::string path = path_name.string(), solid = solid_name ? solid_name->string() : "";
  if (!solid.empty() && !builds_solid(result.options.method)) {
    throw Input_error(frontend::no_solid_message(result.options.method));
  }
  visit(result, [&](const auto& r) {
    io::check_result_formats<std::decay_t<decltype(r)>::dimension>(path, solid);
    if (ascii) {
      if (const std::string problem = frontend::unused_ascii(path, frontend::Spelling::python);
          !problem.empty())
        throw Input_error(problem);
    }
    const Point_attributes attributes =
        attributes_from(normals, colors, static_cast<std::size_t>(r.sample_count()));
    // Before any work: both can be written, and neither replaces a file read_points read.
    io::write_result(r, path, solid, ascii, attributes);
  });
}

// A file's points as read_points and read_file read them: the dimension checked, the file
// remembered as an input (no write() may replace it), and what the reader read past warned of
// as Python warns (once per place, catchable, filterable); `stack_level` names the frame.
frontend::Input input_of_file(const std::filesystem::path& path, int dimension,
                              bool merge_duplicates, int stack_level) {
  if (dimension != 0 && dimension != 2 && dimension != 3)
    throw Input_error("the dimension is 0 (the file's), 2 or 3");
  frontend::Input input = frontend::load_input(path.string(), "", dimension, merge_duplicates);
  io::remember_input(path.string());
  for (const std::string& warning : input.warnings) {
    if (PyErr_WarnEx(PyExc_UserWarning, warning.c_str(), stack_level) != 0)
      throw py::error_already_set();
  }
  return input;
}

}  // namespace

void bind_reading(py::module_& m) {
  m.def(
      "read_points",
      [](const std::filesystem::path& path, int dimension, bool merge_duplicates) {
        return points_array(input_of_file(path, dimension, merge_duplicates, 1));
      },
      py::arg("path"), py::arg("dimension") = 0, py::arg("merge_duplicates") = false,
      ("The points of a file (" + std::string(io::point_formats) +
       "; a mesh gives its vertices) as an (n, 2) or (n, 3) float64 array. dimension=2 or 3 "
       "forces it (a flat 3D file becomes 2D points); merge_duplicates drops points that repeat "
       "an earlier one. read_file gives their normals and colours too.")
          .c_str());
  m.def(
      "_read_file",
      [](const std::filesystem::path& path, int dimension, bool merge_duplicates) {
        // Called by sculpt.read_file: the warnings name the frame that called that.
        const frontend::Input input = input_of_file(path, dimension, merge_duplicates, 2);
        py::object triangles = py::none();
        if (!input.reference_triangles.empty()) triangles = array_of(input.reference_triangles);
        return py::make_tuple(points_array(input), normals_array(input.attributes),
                              colors_array(input.attributes), triangles);
      },
      py::arg("path"), py::arg("dimension") = 0, py::arg("merge_duplicates") = false,
      "read_file's reader: (points, normals, colors, triangles), None where the file has none.");
}

void bind_writing(py::module_& m) {
  m.def("write", &write_result, py::arg("result"), py::arg("path"), py::arg("solid") = py::none(),
        py::arg("ascii") = false, py::arg("normals") = py::none(), py::arg("colors") = py::none(),
        "Writes the surface (.stl .ply .off .obj) or curve (.obj .svg), and the solid if a path "
        "is given (.mesh .vtu .node/.ele): every file or none. STL and PLY are binary unless "
        "ascii=True. Paths are strings or pathlib paths. normals and colors, (n, 3) arrays with "
        "a row per sample (read_file gives them), go on the vertices of a .ply or .obj surface; "
        "colors are levels 0-255 (integers) or fractions 0-1 (floats).");
}

}  // namespace sculpt::python
