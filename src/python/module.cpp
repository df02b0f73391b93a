// The compiled part of the Python module `sculpt` (sculpt._sculpt; python/sculpt/__init__.py is
// what users import). It calls the same core as the command line: methods and stages by the same
// names, the same one-line messages for bad input, the same statistics (statistics_json).
// Reconstruction and rendering release the GIL; the progress callback takes it back briefly.
#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cstring>
#include <memory>
#include <mutex>
#include <optional>
#include <sculpt/sculpt.hpp>

#include "frontend/input.hpp"
#include "frontend/shots.hpp"
#include "frontend/statistics_json.hpp"
#include "io/io_error.hpp"
#include "io/output_set.hpp"
#include "io/point_reader.hpp"
#include "io/writers.hpp"
#include "python/stage_views.hpp"
#include "scene/scene.hpp"
#include "shapes/shapes.hpp"

namespace sculpt::python {
namespace {

using frontend::Any_reconstruction;

// What `sculpt.reconstruct` returns: the result and the options it was made with.
struct Result {
  Any_reconstruction reconstruction;
  Options options;
  int dimension() const { return reconstruction.index() == 0 ? 2 : 3; }
};

template <class Visitor>
decltype(auto) visit(const Result& result, Visitor&& visitor) {
  return std::visit(std::forward<Visitor>(visitor), result.reconstruction);
}

const Statistics& statistics_of(const Result& result) {
  return visit(result, [](const auto& r) -> const Statistics& { return r.stats; });
}

py::object json_to_python(const nlohmann::json& json) {
  return py::module_::import("json").attr("loads")(json.dump());
}

// A points array as the core's points: (n, 2) or (n, 3), converted to float64.
template <int D>
std::vector<Point<D>> points_of(const py::array_t<double, py::array::c_style>& array) {
  std::vector<Point<D>> points(static_cast<std::size_t>(array.shape(0)));
  std::memcpy(points.data(), array.data(), points.size() * sizeof(Point<D>));
  return points;
}

template <std::size_t D>
py::array_t<double> array_of(const std::vector<std::array<double, D>>& points) {
  py::array_t<double> array({static_cast<py::ssize_t>(points.size()), py::ssize_t(D)});
  std::memcpy(array.mutable_data(), points.data(), points.size() * sizeof(Point<D>));
  return array;
}

py::object points_array(const frontend::Input& input) {
  return std::visit([](const auto& points) -> py::object { return array_of(points); },
                    input.points);
}

// The progress callback seen from the core's side, on the thread that reconstructs: it takes the
// GIL to call the Python callable (stage, fraction) -> falsy-but-not-None to cancel, and checks
// for Ctrl-C. An exception in the callable cancels the run and is raised again afterwards.
struct Progress_bridge {
  py::object callback;  // None for no callable
  std::optional<py::error_already_set> error;

  bool operator()(const Progress& progress) {
    py::gil_scoped_acquire gil;
    try {
      if (PyErr_CheckSignals() != 0) throw py::error_already_set();
      if (callback.is_none()) return true;
      const py::object answer = callback(progress.stage, progress.fraction);
      return answer.is_none() || PyObject_IsTrue(answer.ptr()) == 1;
    } catch (py::error_already_set& e) {
      error = std::move(e);
      return false;
    }
  }
};

Options options_from(const std::string& method, const std::string& kind, const std::string& rule,
                     double box_factor, int bordered_seed_sample, bool keep_triangulations) {
  Options options;
  if (!parse_method(method, options.method)) {
    std::string names;
    for (const char* name : method_names()) names += std::string(names.empty() ? "" : ", ") + name;
    throw py::value_error("no method '" + method + "' (methods: " + names + ")");
  }
  if (kind != "closed" && kind != "bordered") {
    throw py::value_error("no kind of surface '" + kind + "' (kinds: closed, bordered)");
  }
  options.kind = kind == "closed" ? Surface_kind::closed : Surface_kind::bordered;
  if (!parse_rule(rule, options.rule)) {
    throw py::value_error("no surface rule '" + rule + "' (rules: auto, skin, extraction)");
  }
  options.box_factor = box_factor;
  options.bordered_seed_sample = bordered_seed_sample;
  options.keep_triangulations = keep_triangulations;
  return options;
}

Result reconstruct_points(const py::array& points, const std::string& method,
                          const std::string& kind, const std::string& rule, double box_factor,
                          int bordered_seed_sample, bool keep_triangulations,
                          const py::object& progress) {
  if (points.ndim() != 2 || (points.shape(1) != 2 && points.shape(1) != 3)) {
    std::string shape;
    for (py::ssize_t axis = 0; axis < points.ndim(); ++axis)
      shape += (axis ? ", " : "") + std::to_string(points.shape(axis));
    throw py::value_error("points must be an array of shape (n, 2) or (n, 3), not (" + shape + ")");
  }
  const auto samples =
      py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(points);
  if (!samples) throw py::value_error("points must be numbers");
  Result result;
  result.options =
      options_from(method, kind, rule, box_factor, bordered_seed_sample, keep_triangulations);
  auto bridge = std::make_shared<Progress_bridge>();
  bridge->callback = progress;
  Options options = result.options;
  options.progress = [bridge](const Progress& p) { return (*bridge)(p); };
  try {
    if (samples.shape(1) == 2) {
      auto input = points_of<2>(samples);
      py::gil_scoped_release released;
      result.reconstruction = reconstruct(input, options);
    } else {
      auto input = points_of<3>(samples);
      py::gil_scoped_release released;
      result.reconstruction = reconstruct(input, options);
    }
  } catch (const Cancelled&) {
    if (bridge->error) throw std::move(*bridge->error);  // the callable's own exception
    throw;
  }
  // The result keeps its options but not the callback (nor the Python objects it holds).
  std::visit([](auto& r) { r.options.progress = nullptr; }, result.reconstruction);
  return result;
}

// One headless renderer for the process, drawing for one caller at a time.
struct Shared_renderer {
  std::mutex mutex;
  std::unique_ptr<render::Headless_renderer> renderer;
};
Shared_renderer& shared_renderer() {
  static Shared_renderer* shared = new Shared_renderer;  // lives as long as the loaded module
  return *shared;
}

py::array render_stage(const Result& result, const frontend::Shot& shot) {
  frontend::Picture picture;
  {
    py::gil_scoped_release released;
    Shared_renderer& shared = shared_renderer();
    std::lock_guard<std::mutex> lock(shared.mutex);
    if (!shared.renderer) shared.renderer = std::make_unique<render::Headless_renderer>();
    picture = frontend::draw_shot(*shared.renderer, shot, result.reconstruction);
  }
  const auto& image = picture.image;
  py::array_t<std::uint8_t> pixels(
      {py::ssize_t(image.height), py::ssize_t(image.width), py::ssize_t(4)});
  std::memcpy(pixels.mutable_data(), image.rgba.data(), image.rgba.size());
  return pixels;
}

// Writes the surface (3D) or curve (2D), and the solid if asked: all files or none.
void write_result(const Result& result, const std::string& path, const std::string& solid,
                  bool ascii) {
  visit(result, [&](const auto& r) {
    constexpr int D = std::decay_t<decltype(r)>::dimension;
    const std::vector<Point<D>> samples(r.sites.begin(), r.sites.begin() + r.sample_count());
    const std::string extension = io::extension_of(path);
    if (D == 3 ? !io::writes_surface(extension) : !io::writes_curve(extension)) {
      throw io::Error(std::string("cannot write a ") + (D == 3 ? "surface" : "curve") + " as '" +
                      path + "' (known: " + (D == 3 ? io::surface_formats : io::curve_formats) +
                      ")");
    }
    if (!solid.empty() && !io::writes_solid(io::extension_of(solid))) {
      throw io::Error("cannot write a solid as '" + solid + "' (known: " + io::solid_formats + ")");
    }
    io::check_output_folder(path);
    io::check_output_folder(solid);
    io::Output_set outputs;
    if constexpr (D == 3) {
      io::write_surface(outputs.stage(path), samples, r.surface, ascii);
    } else {
      io::write_curve(outputs.stage(path), samples, r.surface);
    }
    if (!solid.empty()) io::write_solid<D>(outputs.stage(solid), samples, r.solid);
    outputs.commit();
  });
}

template <class Enum>
py::tuple names_of(int count) {
  py::tuple names(count);
  for (int code = 0; code < count; ++code) names[code] = to_string(static_cast<Enum>(code));
  return names;
}

}  // namespace
}  // namespace sculpt::python

PYBIND11_MODULE(_sculpt, m) {
  using namespace sculpt;
  using namespace sculpt::python;
  m.doc() = "Sculpt's compiled core: see the package sculpt";

  // Bad input raises one of these with the line the command line prints after "sculpt: error: ".
  static py::exception<Input_error> input_error(m, "InputError", PyExc_ValueError);
  static py::exception<Duplicate_points> duplicates(m, "DuplicatePoints", input_error.ptr());
  static py::exception<Cancelled> cancelled(m, "Cancelled", PyExc_RuntimeError);
  py::register_exception_translator([](std::exception_ptr raised) {
    try {
      if (raised) std::rethrow_exception(raised);
    } catch (const Duplicate_points& e) {
      duplicates(
          (std::string(e.what()) + " (merge_duplicates=True removes repeated points)").c_str());
    } catch (const Input_error& e) {
      input_error(e.what());
    } catch (const io::Error& e) {
      input_error(e.what());
    } catch (const Cancelled& e) {
      cancelled(e.what());
    }
  });

  m.attr("LABELS") = names_of<Label>(3);
  m.attr("LABEL_REASONS") = names_of<Label_reason>(4);
  m.attr("CARVE_REASONS") = names_of<Carve_reason>(3);
  m.attr("DEFAULT_METHOD") = to_string(Options{}.method);

  m.def("version", &sculpt::version);
  m.def(
      "methods",
      [] {
        py::dict methods;  // in order, the default first
        for (const char* name : method_names()) {
          Method method;
          parse_method(name, method);
          methods[name] = describe(method);
        }
        return methods;
      },
      "The methods by name, with a few words on each; the default first.");
  m.def(
      "stages",
      [](const std::string& method_name, int dimension) {
        Method method;
        if (!parse_method(method_name, method))
          throw py::value_error("no method '" + method_name + "'");
        if (dimension != 2 && dimension != 3) throw py::value_error("the dimension is 2 or 3");
        std::vector<std::string> ids;
        for (auto stage : scene::stages_of(method, dimension))
          ids.push_back(scene::stage_id(stage));
        return ids;
      },
      py::arg("method"), py::arg("dimension"),
      "The stages a method shows in this dimension, in order (names for render()).");
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
      "The built-in examples: name, dimension, description, bordered.");
  m.def(
      "example",
      [](const std::string& name) { return points_array(frontend::load_input("", name, 0)); },
      py::arg("name"), "The points of a built-in example, as an (n, 2) or (n, 3) array.");
  m.def(
      "read_points",
      [](const std::string& path, int dimension, bool merge_duplicates) {
        if (dimension != 0 && dimension != 2 && dimension != 3)
          throw py::value_error("the dimension is 0 (the file's), 2 or 3");
        return points_array(frontend::load_input(path, "", dimension, merge_duplicates));
      },
      py::arg("path"), py::arg("dimension") = 0, py::arg("merge_duplicates") = false,
      "Points of a file (.xyz .pts .txt .csv .xy .p2d .ply .off .obj .stl): an (n, 2) or (n, 3) "
      "array. dimension 2 or 3 forces it; merge_duplicates drops repeated points.");

  py::class_<Result>(m, "Reconstruction",
                     "A reconstruction: every stage as read-only numpy arrays, the statistics "
                     "and the verdict.")
      .def_property_readonly("dimension", &Result::dimension)
      .def_property_readonly("method", [](const Result& r) { return to_string(r.options.method); })
      .def_property_readonly("kind", [](const Result& r) { return to_string(r.options.kind); })
      .def_property_readonly(
          "samples",
          [](py::object self) {
            const Result& result = self.cast<const Result&>();
            return visit(result, [&](const auto& r) {
              return read_only_view(self, r.sites.data(), r.sample_count(), py::dtype::of<double>(),
                                    {r.dimension});
            });
          },
          "The samples, (n, d).")
      .def_property_readonly(
          "sites",
          [](py::object self) {
            return visit(self.cast<const Result&>(),
                         [&](const auto& r) { return rows_view(self, r.sites); });
          },
          "The triangulation's sites: the samples, the 2^d box corners, then the poles inserted.")
      .def_property_readonly(
          "surface",
          [](py::object self) {
            return visit(self.cast<const Result&>(),
                         [&](const auto& r) { return rows_view(self, r.surface); });
          },
          "Triangles (3D) or edges (2D) as sample indices; closed surfaces face outward.")
      .def_property_readonly(
          "solid",
          [](py::object self) {
            return visit(self.cast<const Result&>(),
                         [&](const auto& r) { return rows_view(self, r.solid); });
          },
          "The sculpted solid's tetrahedra (triangles in 2D) as sample indices.")
      .def_property_readonly(
          "stages",
          [](py::object self) {
            return visit(self.cast<const Result&>(),
                         [&](const auto& r) { return stage_objects(self, r); });
          },
          "Every stage by name (delaunay, poles, seeds, propagation, insertion, "
          "sculpted_delaunay, carving, crust, candidates), each with its arrays as attributes.")
      .def_property_readonly(
          "verdict", [](const Result& r) { return verdict(statistics_of(r)).line; },
          "One line: a closed (or bordered) 2-manifold, or what is wrong with the result.")
      .def_property_readonly("manifold",
                             [](const Result& r) { return verdict(statistics_of(r)).manifold; })
      .def_property_readonly(
          "stats",
          [](const Result& r) {
            auto json = frontend::statistics_json(statistics_of(r));
            json["kind"] = to_string(r.options.kind);
            json["rule"] = frontend::surface_rule_name(r.options, r.dimension());
            json["box_factor"] = r.options.box_factor;
            return json_to_python(json);
          },
          "The statistics, named as in `sculpt reconstruct --stats`.")
      .def("__repr__", [](const Result& r) {
        const auto& stats = statistics_of(r);
        return "<sculpt.Reconstruction " + std::to_string(r.dimension()) + "D, " +
               std::to_string(stats.samples) + " samples, method " + to_string(r.options.method) +
               ": " + verdict(stats).line + ">";
      });

  const Options defaults;
  m.def("reconstruct", &reconstruct_points, py::arg("points"),
        py::arg("method") = to_string(defaults.method), py::arg("kind") = to_string(defaults.kind),
        py::arg("rule") = to_string(defaults.rule), py::arg("box_factor") = defaults.box_factor,
        py::arg("bordered_seed_sample") = defaults.bordered_seed_sample,
        py::arg("keep_triangulations") = defaults.keep_triangulations,
        py::arg("progress") = py::none(),
        "Reconstructs a curve from (n, 2) points or a surface from (n, 3) points.\n"
        "method: a name of sculpt.methods(); kind: 'closed' or 'bordered'; rule: 'auto', 'skin' "
        "or 'extraction' (paper method). progress(stage, fraction) is called as the stages run; "
        "returning False cancels (sculpt.Cancelled). Bad input raises sculpt.InputError.");

  const frontend::Shot shot_defaults;
  m.def(
      "render",
      [](const Result& result, const std::string& stage, std::pair<int, int> size, long step,
         int focus_sample, int focus_pole, std::vector<std::string> layers, bool wireframe,
         bool smooth, bool legend, float zoom, int ball_every, float yaw, float pitch) {
        frontend::Shot shot;
        shot.stage = stage;
        shot.size = std::to_string(size.first) + "x" + std::to_string(size.second);
        shot.step = step;
        shot.focus_sample = focus_sample;
        shot.focus_pole = focus_pole;
        shot.layers = std::move(layers);
        shot.wireframe = wireframe;
        shot.smooth = smooth;
        shot.no_legend = !legend;
        shot.zoom = zoom;
        shot.ball_every = ball_every;
        shot.yaw = yaw;
        shot.pitch = pitch;
        return render_stage(result, shot);
      },
      py::arg("result"), py::arg("stage") = shot_defaults.stage,
      py::arg("size") = std::pair<int, int>(800, 800), py::arg("step") = shot_defaults.step,
      py::arg("focus_sample") = shot_defaults.focus_sample,
      py::arg("focus_pole") = shot_defaults.focus_pole,
      py::arg("layers") = std::vector<std::string>{},
      py::arg("wireframe") = shot_defaults.wireframe, py::arg("smooth") = shot_defaults.smooth,
      py::arg("legend") = !shot_defaults.no_legend, py::arg("zoom") = shot_defaults.zoom,
      py::arg("ball_every") = shot_defaults.ball_every, py::arg("yaw") = shot_defaults.yaw,
      py::arg("pitch") = shot_defaults.pitch,
      "A picture of a stage (a name of sculpt.stages()) as an (height, width, 4) uint8 RGBA "
      "array, drawn by the headless renderer as `sculpt render` draws it. size is (width, "
      "height); step replays the separation or the carving up to that event.");

  m.def("write", &write_result, py::arg("result"), py::arg("path"), py::arg("solid") = "",
        py::arg("ascii") = false,
        "Writes the surface (.stl .ply .off .obj) or curve (.obj .svg), and the solid if a path "
        "is given (.mesh .vtu .node/.ele): every file or none.");
}
