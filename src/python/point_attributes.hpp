// SPDX-License-Identifier: GPL-3.0-or-later
// The samples' normals and colours between numpy and the core: (n, 3) float64 normals and
// (n, 3) uint8 colours out; in, normals of any real type and colours as levels 0-255 (integers)
// or fractions 0-1 (floats, as Open3D keeps them), each checked against the samples' count.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cmath>
#include <cstring>
#include <sculpt/point_attributes.hpp>
#include <sculpt/sculpt.hpp>
#include <string>

namespace sculpt::python {

namespace py = pybind11;

inline py::object normals_array(const Point_attributes& attributes) {
  if (attributes.normals.empty()) return py::none();
  py::array_t<double> array({static_cast<py::ssize_t>(attributes.normals.size()), py::ssize_t(3)});
  std::memcpy(array.mutable_data(), attributes.normals.data(),
              attributes.normals.size() * sizeof(attributes.normals[0]));
  return std::move(array);
}

inline py::object colors_array(const Point_attributes& attributes) {
  if (attributes.colors.empty()) return py::none();
  py::array_t<std::uint8_t> array(
      {static_cast<py::ssize_t>(attributes.colors.size()), py::ssize_t(3)});
  std::memcpy(array.mutable_data(), attributes.colors.data(), attributes.colors.size() * 3);
  return std::move(array);
}

// An (n, 3) array of real numbers named `what`, as float64; Input_error otherwise.
// `given_kind`, when given, receives the dtype's kind of the array as given ('f', 'i', 'u').
inline py::array_t<double, py::array::c_style> triples_from(const py::object& given,
                                                            std::size_t samples, const char* what,
                                                            char* given_kind = nullptr) {
  py::array array;
  try {
    array = py::module_::import("numpy").attr("asarray")(given);
  } catch (py::error_already_set&) {
    throw Input_error(std::string(what) + " must be an array of shape (n, 3)");
  }
  const char kind = array.dtype().kind();
  if (given_kind) *given_kind = kind;
  if (kind != 'f' && kind != 'i' && kind != 'u') {
    throw Input_error(std::string(what) + " must be real numbers, an array of shape (n, 3)");
  }
  if (array.ndim() != 2 || array.shape(1) != 3 ||
      static_cast<std::size_t>(array.shape(0)) != samples) {
    throw Input_error(std::string(what) + " must be an array of shape (" + std::to_string(samples) +
                      ", 3): one row per sample, in their order");
  }
  return py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(array);
}

inline Point_attributes attributes_from(const py::object& normals, const py::object& colors,
                                        std::size_t samples) {
  Point_attributes attributes;
  if (!normals.is_none()) {
    const auto values = triples_from(normals, samples, "normals");
    attributes.normals.resize(samples);
    std::memcpy(attributes.normals.data(), values.data(), samples * sizeof(double) * 3);
  }
  if (!colors.is_none()) {
    char kind = 0;
    const auto values = triples_from(colors, samples, "colors", &kind);
    const double full = kind == 'f' ? 1.0 : 255.0;  // fractions or levels
    attributes.colors.resize(samples);
    const double* value = values.data();
    for (auto& color : attributes.colors) {
      for (auto& channel : color) {
        const double v = *value++;
        if (!(v >= 0 && v <= full)) {
          throw Input_error(kind == 'f' ? "colors given as floats are fractions from 0 to 1"
                                        : "colors given as integers are levels from 0 to 255");
        }
        channel = static_cast<std::uint8_t>(std::lround(v / full * 255));
      }
    }
  }
  return attributes;
}

}  // namespace sculpt::python
