// SPDX-License-Identifier: GPL-3.0-or-later
// What the files of the Python module share: the bind_* functions that PYBIND11_MODULE
// (module.cpp) calls in order, the result object they all take, and the conversions of points
// between numpy and the core. Every file includes the same type casters (stl, functional,
// filesystem): pybind11 needs them alike in each translation unit.
#pragma once

#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <array>
#include <cstring>
#include <sculpt/sculpt.hpp>
#include <utility>
#include <variant>
#include <vector>

#include "frontend/input.hpp"
#include "io/point_reader.hpp"

namespace sculpt::python {

namespace py = pybind11;

using frontend::Any_reconstruction;

// Registered in this order (docstrings and help() follow it).
void bind_catalogue(py::module_& m);       // catalogue.cpp: names, methods, stages, examples
void bind_reading(py::module_& m);         // files.cpp: read_points, _read_file
void bind_points(py::module_& m);          // points.cpp: merge_duplicates
void bind_reconstruction(py::module_& m);  // reconstruction.cpp: Reconstruction, reconstruct
void bind_rendering(py::module_& m);       // rendering.cpp: render
void bind_writing(py::module_& m);         // files.cpp: write

// What `sculpt.reconstruct` returns: the result and the options it was made with.
struct Result {
  Any_reconstruction reconstruction;
  Options options;
  // The main arrays as the caller's own: writable (Open3D's constructors refuse read-only
  // arrays), made on first access and the same object afterwards. Changing them changes nothing
  // of the reconstruction, which render() and write() draw and write.
  py::object samples_array, surface_array;
  int dimension() const { return reconstruction.index() == 0 ? 2 : 3; }
};

template <class Visitor>
decltype(auto) visit(const Result& result, Visitor&& visitor) {
  return std::visit(std::forward<Visitor>(visitor), result.reconstruction);
}

// The method of that name; Input_error naming every method otherwise (catalogue.cpp).
Method method_named(const std::string& name);

// A points array as the core's points: (n, 2) or (n, 3), converted to float64.
template <int D>
std::vector<Point<D>> points_of(const py::array_t<double, py::array::c_style>& array) {
  std::vector<Point<D>> points(static_cast<std::size_t>(array.shape(0)));
  std::memcpy(points.data(), array.data(), points.size() * sizeof(Point<D>));
  return points;
}

template <class T, std::size_t D>
py::array_t<T> array_of(const std::vector<std::array<T, D>>& rows) {
  py::array_t<T> array({static_cast<py::ssize_t>(rows.size()), py::ssize_t(D)});
  std::memcpy(array.mutable_data(), rows.data(), rows.size() * sizeof(rows[0]));
  return array;
}

// An input's points as an (n, 2) or (n, 3) float64 array (points.cpp).
py::object points_array(const frontend::Input& input);

// Any array-like of real numbers as a C-ordered float64 array of shape (n, 2) or (n, 3);
// Input_error otherwise (points.cpp).
py::array_t<double, py::array::c_style> points_from(const py::object& points);

// The points without those that repeat an earlier one (the command line's --merge-duplicates).
template <class Point>
void drop_repeated(std::vector<Point>& points) {
  const std::vector<bool> repeated = io::repeated_points(points);
  std::size_t kept = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!repeated[i]) points[kept++] = points[i];
  }
  points.resize(kept);
}

}  // namespace sculpt::python
