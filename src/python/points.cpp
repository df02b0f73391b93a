// SPDX-License-Identifier: GPL-3.0-or-later
// The points between numpy and the core: what reconstruct and merge_duplicates accept, checked
// before any copy, and the arrays the readers give back.
#include <fmt/format.h>

#include <cstdint>
#include <string>

#include "io/input_limits.hpp"
#include "python/bindings.hpp"

namespace sculpt::python {

py::object points_array(const frontend::Input& input) {
  return std::visit([](const auto& points) -> py::object { return array_of(points); },
                    input.points);
}

// Any array-like of real numbers (an array, a list of points) as a C-ordered float64 array of
// shape (n, 2) or (n, 3); Input_error otherwise. The shape and the point budget are checked
// before any copy: a broadcast view of 10^9 rows costs nothing until it is copied.
py::array_t<double, py::array::c_style> points_from(const py::object& points) {
  const py::module_ numpy = py::module_::import("numpy");
  py::array array;
  try {
    array = numpy.attr("asarray")(points);  // an array stays itself: no copy yet
    const char kind = array.dtype().kind();
    if (kind == 'c') throw Input_error("points must be real numbers, not complex");
    if (kind != 'f' && kind != 'i' && kind != 'u' && kind != 'b') {
      array = numpy.attr("asarray")(points, "float64");  // objects that are numbers (Decimal)
    }
  } catch (py::error_already_set&) {
    throw Input_error("points must be numbers: an array of shape (n, 2) or (n, 3)");
  }
  if (array.ndim() != 2 || (array.shape(1) != 2 && array.shape(1) != 3)) {
    std::string shape;
    for (py::ssize_t axis = 0; axis < array.ndim(); ++axis)
      shape += (axis ? ", " : "") + std::to_string(array.shape(axis));
    throw Input_error("points must be an array of shape (n, 2) or (n, 3), not (" + shape +
                      (array.ndim() == 1 ? ",)" : ")"));
  }
  const std::uint64_t rows = static_cast<std::uint64_t>(array.shape(0));
  const std::uint64_t limit = io::input_limits().points;
  if (rows > limit) {
    throw Input_error(
        fmt::format("points: an array of {} points ({:.1f} GB as float64) is more than {}", rows,
                    double(rows) * double(array.shape(1)) * 8 / 1e9, io::points_limit_text(limit)));
  }
  return py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(array);
}

void bind_points(py::module_& m) {
  m.def(
      "merge_duplicates",
      [](const py::object& points) {
        const auto samples = points_from(points);
        py::object merged;
        if (samples.shape(1) == 2) {
          auto kept = points_of<2>(samples);
          drop_repeated(kept);
          merged = array_of(kept);
        } else {
          auto kept = points_of<3>(samples);
          drop_repeated(kept);
          merged = array_of(kept);
        }
        return merged;
      },
      py::arg("points"),
      "The points without those that repeat an earlier one exactly, in order: what `sculpt "
      "reconstruct --merge-duplicates` does to a file.");
}

}  // namespace sculpt::python
