// SPDX-License-Identifier: GPL-3.0-or-later
// What the library knows by name, as Python sees it: the codes of labels, reasons and openings,
// the version, the methods and their stages, the built-in examples.
#include <string>
#include <vector>

#include "python/bindings.hpp"
#include "scene/scene.hpp"
#include "shapes/shapes.hpp"

namespace sculpt::python {
namespace {

template <class Enum>
py::tuple names_of(int count) {
  py::tuple names(count);
  for (int code = 0; code < count; ++code) names[code] = to_string(static_cast<Enum>(code));
  return names;
}

}  // namespace

Method method_named(const std::string& name) {
  Method method;
  if (!parse_method(name, method)) {
    std::string names;
    for (const char* known : method_names())
      names += std::string(names.empty() ? "" : ", ") + known;
    throw Input_error("no method '" + name + "' (methods: " + names + ")");
  }
  return method;
}

void bind_catalogue(py::module_& m) {
  m.attr("LABELS") = names_of<Label>(3);
  m.attr("LABEL_REASONS") = names_of<Label_reason>(4);
  m.attr("CARVE_REASONS") = names_of<Carve_reason>(4);
  m.attr("OPENING_KINDS") = names_of<Opening_kind>(3);
  m.attr("DEFAULT_METHOD") = to_string(Options{}.method);

  m.def("version", &sculpt::version, "Sculpt's version, e.g. '0.1.0'.");
  m.def(
      "methods",
      [](int dimension) {
        if (dimension != 0 && dimension != 2 && dimension != 3)
          throw Input_error("the dimension is 0 (every method), 2 or 3");
        py::dict methods;  // in order, the default first
        for (const char* name : method_names()) {
          const Method method = method_named(name);
          if (dimension == 0 || reconstructs_in(method, dimension))
            methods[name] = describe(method);
        }
        return methods;
      },
      py::arg("dimension") = 0,
      "The methods by name with a few words on each, the default first: all of them, or those that "
      "reconstruct curves (dimension=2) or surfaces (dimension=3).");
  m.def(
      "stages",
      [](const std::string& name, int dimension) {
        const Method method = method_named(name);
        if (dimension != 2 && dimension != 3) throw Input_error("the dimension is 2 or 3");
        if (!reconstructs_in(method, dimension)) {
          throw Input_error("the method " + name + " does not reconstruct in " +
                            std::to_string(dimension) + "D");
        }
        std::vector<std::string> ids;
        for (auto stage : scene::stages_of(method, dimension))
          ids.push_back(scene::stage_id(stage));
        return ids;
      },
      py::arg("method"), py::arg("dimension"),
      "The stages a method shows in this dimension, in order: the names sculpt.render takes.");
  m.def(
      "examples",
      [] {
        py::list examples;
        for (const auto& e : shapes::examples()) {
          examples.append(py::dict(py::arg("name") = e.name, py::arg("dimension") = e.dimension,
                                   py::arg("description") = e.description,
                                   py::arg("bordered") = e.bordered));
        }
        return examples;
      },
      "The built-in examples: dicts of name, dimension, description and bordered (reconstruct "
      "those with kind='bordered').");
  m.def(
      "example",
      [](const std::string& name) {
        if (!shapes::find_example(name)) {
          throw Input_error("no built-in example named '" + name +
                            "' (sculpt.examples() lists them)");
        }
        return points_array(frontend::load_input("", name, 0));
      },
      py::arg("name"), "The points of a built-in example, as an (n, 2) or (n, 3) float64 array.");
}

}  // namespace sculpt::python
