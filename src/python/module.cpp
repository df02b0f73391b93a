// SPDX-License-Identifier: GPL-3.0-or-later
// The compiled part of the Python module `sculpt` (sculpt._sculpt; python/sculpt/__init__.py is
// what users import). It calls the same core as the command line: methods and stages by the same
// names, the same one-line messages for bad input, the same statistics (statistics_json).
// Reconstruction and rendering release the GIL; the progress callback takes it back briefly.
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <array>
#include <cstring>
#include <memory>
#include <mutex>
#include <optional>
#include <sculpt/sculpt.hpp>

#include "frontend/command_line.hpp"
#include "frontend/input.hpp"
#include "frontend/option_use.hpp"
#include "frontend/shots.hpp"
#include "frontend/statistics_json.hpp"
#include "io/destinations.hpp"
#include "io/io_error.hpp"
#include "io/output_set.hpp"
#include "io/point_reader.hpp"
#include "io/result_files.hpp"
#include "io/temporary_files.hpp"
#include "io/writers.hpp"
#include "python/point_attributes.hpp"
#include "python/stage_views.hpp"
#include "render/headless.hpp"
#include "scene/scene.hpp"
#include "shapes/shapes.hpp"

namespace sculpt::python {
namespace {

using frontend::Any_reconstruction;

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

template <class T, std::size_t D>
py::array_t<T> array_of(const std::vector<std::array<T, D>>& rows) {
  py::array_t<T> array({static_cast<py::ssize_t>(rows.size()), py::ssize_t(D)});
  std::memcpy(array.mutable_data(), rows.data(), rows.size() * sizeof(rows[0]));
  return array;
}

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

// The progress callback seen from the core's side, on the thread that reconstructs: it takes the
// GIL to call the Python callable (stage, fraction[, overall]) -> falsy-but-not-None to cancel,
// and checks for Ctrl-C. An exception in the callable cancels the run and is raised again
// afterwards.
struct Progress_bridge {
  py::object callback;        // None for no callable
  bool with_overall = false;  // the callable takes a third argument: the whole run's fraction
  std::optional<py::error_already_set> error;

  explicit Progress_bridge(py::object callable) : callback(std::move(callable)) {
    if (callback.is_none()) return;
    try {  // a callable of three arguments gets the overall fraction too (a tqdm bar)
      py::module_::import("inspect").attr("signature")(callback).attr("bind")(0, 0, 0);
      with_overall = true;
    } catch (py::error_already_set&) {
    }
  }

  bool operator()(const Progress& progress) {
    py::gil_scoped_acquire gil;
    try {
      if (PyErr_CheckSignals() != 0) throw py::error_already_set();
      if (callback.is_none()) return true;
      const py::object answer = with_overall
                                    ? callback(progress.stage, progress.fraction, progress.overall)
                                    : callback(progress.stage, progress.fraction);
      return answer.is_none() || PyObject_IsTrue(answer.ptr()) == 1;
    } catch (py::error_already_set& e) {
      error = std::move(e);
      return false;
    }
  }
};

// The options as the keywords give them; a keyword that the method or kind would never read is
// refused (frontend/option_use.hpp). kind=None is the method's default: chosen automatically
// where the method chooses, else closed.
Options options_from(const std::string& method, const std::optional<std::string>& kind,
                     const std::string& rule, double box_factor, double alpha,
                     int bordered_seed_sample, bool keep_triangulations) {
  Options options;
  if (!parse_method(method, options.method)) {
    std::string names;
    for (const char* name : method_names()) names += std::string(names.empty() ? "" : ", ") + name;
    throw Input_error("no method '" + method + "' (methods: " + names + ")");
  }
  if (kind && !parse_kind(*kind, options.kind)) {
    throw Input_error("no kind of surface '" + *kind + "' (kinds: closed, bordered, automatic)");
  }
  const auto python = frontend::Spelling::python;
  if (kind && options.kind == Surface_kind::automatic) {
    if (const std::string problem = frontend::unused_automatic_kind(options.method, python);
        !problem.empty())
      throw Input_error(problem);
  }
  if (!parse_rule(rule, options.rule)) {
    throw Input_error("no surface rule '" + rule + "' (rules: auto, skin, extraction)");
  }
  options.box_factor = box_factor;
  options.alpha = alpha;
  options.bordered_seed_sample = bordered_seed_sample;
  options.keep_triangulations = keep_triangulations;
  if (const std::string problem = frontend::unused_reconstruction_option(options, python);
      !problem.empty())
    throw Input_error(problem);
  return options;
}

Result reconstruct_points(const py::object& points, const std::string& method,
                          const std::optional<std::string>& kind, const std::string& rule,
                          double box_factor, double alpha, int bordered_seed_sample,
                          bool keep_triangulations, bool merge_duplicates, const std::string& clean,
                          const py::object& progress) {
  const auto samples = points_from(points);
  Result result;
  result.options = options_from(method, kind, rule, box_factor, alpha, bordered_seed_sample,
                                keep_triangulations);
  if (!parse_cleaning(clean, result.options.cleaning)) {
    throw Input_error("no cleaning '" + clean + "' (cleanings: auto, jet, none)");
  }
  auto bridge = std::make_shared<Progress_bridge>(progress);
  Options options = result.options;
  options.progress = [bridge](const Progress& p) { return (*bridge)(p); };
  try {
    if (samples.shape(1) == 2) {
      auto input = points_of<2>(samples);
      py::gil_scoped_release released;
      if (merge_duplicates) drop_repeated(input);
      result.reconstruction = reconstruct(input, options);
    } else {
      auto input = points_of<3>(samples);
      py::gil_scoped_release released;
      if (merge_duplicates) drop_repeated(input);
      result.reconstruction = reconstruct(input, options);
    }
  } catch (const Cancelled&) {
    if (bridge->error) throw std::move(*bridge->error);  // the callable's own exception
    throw;
  }
  // The result keeps its options but not the callback (nor the Python objects it holds).
  // An automatic kind is resolved: the result says which kind it is.
  std::visit([&](auto& r) { result.options.kind = r.options.kind; }, result.reconstruction);
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
    scene::Scene scene = frontend::scene_of(shot, result.reconstruction);
    if (const std::string problem =
            frontend::unused_drawing_option(shot, scene, frontend::Spelling::python);
        !problem.empty())
      throw Input_error(problem);
    if (!shared.renderer) shared.renderer = std::make_unique<render::Headless_renderer>();
    picture = frontend::draw_scene(*shared.renderer, shot, std::move(scene));
  }
  const auto& image = picture.image;
  py::array_t<std::uint8_t> pixels(
      {py::ssize_t(image.height), py::ssize_t(image.width), py::ssize_t(4)});
  std::memcpy(pixels.mutable_data(), image.rgba.data(), image.rgba.size());
  return pixels;
}

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

template <class Enum>
py::tuple names_of(int count) {
  py::tuple names(count);
  for (int code = 0; code < count; ++code) names[code] = to_string(static_cast<Enum>(code));
  return names;
}

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

// A picture size: one number (a square) or (width, height), in pixels.
std::string size_of(const py::object& size) {
  const std::string rule =
      "the size is (width, height) or one number for a square, each from 1 to " +
      std::to_string(render::max_image_side) + " pixels";
  std::vector<long> sides;
  try {
    if (py::isinstance<py::int_>(size)) {
      sides = {size.cast<long>(), size.cast<long>()};
    } else {
      for (auto side : size) {
        if (!py::isinstance<py::int_>(side)) throw Input_error(rule);
        sides.push_back(side.cast<long>());
      }
    }
  } catch (py::error_already_set&) {
    throw Input_error(rule);
  } catch (py::cast_error&) {
    throw Input_error(rule);
  }
  if (sides.size() != 2) throw Input_error(rule);
  for (long side : sides) {
    if (side < 1 || side > render::max_image_side) throw Input_error(rule);
  }
  return std::to_string(sides[0]) + "x" + std::to_string(sides[1]);
}

const char* stages_doc =
    R"(Every stage of the reconstruction by name, each an object whose attributes are
read-only numpy arrays (views of the result: no copy). Indices of samples are rows of `samples`;
indices of sites are rows of `sites` (the samples, then the 2^d box corners, then the poles
inserted); indices of poles are rows of poles' arrays.

delaunay           cells (m, d+1) int32: sites of the finite cells of DT(S + box corners);
                   cell_count
poles              center (p, d), radius (p,): the polar balls; cell (p,) int64: the cell of
                   delaunay whose circumcentre the pole is; sites (p, d+1); convex (p,) bool: the
                   cell touches a box corner; positive_pole, negative_pole (n,): the poles p+ and
                   p- of each sample (-1: none); partners of pole k:
                   partners[partner_offsets[k]:partner_offsets[k+1]]; records: all as one record
                   array
seeds              convex_poles, outer_seeds: poles
propagation        events: records (pole, label, source, reason, weight, after_events) in the
                   order the labelling ran (label codes: sculpt.LABELS; reason codes:
                   LABEL_REASONS; source -1: a convex seed); conflicts: offers of the other
                   label, same records, after_events the events before each (-1 for events);
                   labels (p,) uint8: the final label of each pole; unlabelled: a count
insertion          inserted_poles: the poles inserted into DT (paper method: OUP, or UP bordered)
sculpted_delaunay  cells, cell_count: DT(S + OUP) (paper method)
carving            events: records (cell, reason) of the cells of delaunay removed (robust
                   method, with keep_triangulations; reason codes: CARVE_REASONS);
                   kept_outer_cells (not counted after a flood); buried_samples; openings:
                   records (first_event, cells, kind, euler_change), the removals of several
                   cells at once, the only ones that can change the solid's topology (kind
                   codes: OPENING_KINDS; euler_change of the solid: 3D -1 a handle opened, +1 a
                   cavity; 2D -1 a hole); stats['carved_handles'] sums the handles (holes);
                   refused_handles: cells of delaunay where a punch through a web was refused
                   as it would open a handle one sample wide (stats['refused_handles'])
crust              voronoi_vertices (v, d), cells, cell_count: DT(S + V) of the crust, whose
                   sites are the samples then the Voronoi vertices
candidates         chosen, pruned (k, d): the facets the crust or co-cone chose, those pruned;
                   rims_kept; spanning (k, d): robust bordered surfaces, the facets removed as
                   spanning an opening (the paper's bordered surface is chosen + spanning)
front              order (t,) int32: the Advancing Front's surface triangles, as indices into
                   surface, in the order it added them
alpha              cells (c, 4), radii (c,): alpha shapes, every cell of the samples' own
                   Delaunay triangulation with its circumradius, smallest first; chosen: how
                   many make the method's solid (with keep_triangulations)
handles            thin: records (loop (4,) int32, width_over_spacing) of a closed surface's
                   handles thinner than the samples' spacing, the loop of 3 samples (then -1)
                   or 4 around or through each (any method, 3D; stats['thin_handles'] counts)

The pictures of sculpt.render name stages as the viewer does (sculpt.stages(method, d)):
'sculpted-delaunay' draws sculpted_delaunay, 'propagation' the events, and so on.)";

}  // namespace
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

}  // namespace sculpt::python

PYBIND11_MODULE(_sculpt, m) {
  using namespace sculpt;
  using namespace sculpt::python;
  m.doc() = "Sculpt's compiled core: see the package sculpt";
  // A write() ended by a signal (SIGTERM, ...) leaves no hidden temporary; Python's own handlers
  // (SIGINT) stay as they are.
  io::remove_temporaries_on_signals();

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
  input_error.doc() = "Input Sculpt cannot work on: the message is the line `sculpt` prints.";
  duplicates.doc() = "Two points at the same place: merge_duplicates=True drops the copies.";
  cancelled.doc() = "The progress callback returned False.";

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

  py::class_<Result>(m, "Reconstruction",
                     "A reconstruction: the samples and the surface (or curve) as writable arrays "
                     "of your own, the solid and every stage as read-only numpy views, the "
                     "statistics and the verdict.")
      .def_property_readonly("dimension", &Result::dimension, "2 (a curve) or 3 (a surface).")
      .def_property_readonly(
          "method", [](const Result& r) { return to_string(r.options.method); }, "Its name.")
      .def_property_readonly(
          "kind", [](const Result& r) { return to_string(r.options.kind); },
          "'closed' or 'bordered'.")
      .def_property_readonly(
          "interpolates",
          [](const Result& r) { return visit(r, [](const auto& x) { return x.interpolates(); }); },
          "True when the surface's vertices are the samples (every method but the power crust, "
          "whose surface_vertices are its own).")
      .def_property_readonly(
          "samples",
          [](Result& result) {
            if (!result.samples_array) {
              result.samples_array = visit(result, [](const auto& r) -> py::object {
                using Point = typename std::decay_t<decltype(r.sites)>::value_type;
                return array_of(
                    std::vector<Point>(r.sites.begin(), r.sites.begin() + r.sample_count()));
              });
            }
            return result.samples_array;
          },
          "The samples, (n, d) float64, in the order given: a writable array of your own. "
          "Smoothed when stats['cleaned'] (the surface passes through these).")
      .def_property_readonly(
          "given_samples",
          [](py::object self) -> py::object {
            return visit(self.cast<const Result&>(), [&](const auto& r) -> py::object {
              if (r.given_samples.empty()) return py::none();
              return rows_view(self, r.given_samples);
            });
          },
          "When the samples were smoothed (clean=...) and the triangulations kept (the "
          "default), the points as given, (n, d), read-only; None otherwise.")
      .def_property_readonly(
          "sites",
          [](py::object self) {
            return visit(self.cast<const Result&>(),
                         [&](const auto& r) { return rows_view(self, r.sites); });
          },
          "The triangulations' sites, (s, d): the samples, the 2^d box corners, then the poles "
          "inserted (paper method).")
      .def_property_readonly(
          "surface",
          [](py::object self) {
            Result& result = self.cast<Result&>();
            if (!result.surface_array) {
              const py::array view =
                  visit(result, [&](const auto& r) { return rows_view(self, r.surface); });
              result.surface_array = view.attr("copy")();  // writable, of its own
            }
            return result.surface_array;
          },
          "A writable array of your own: triangles (f, 3) of a surface or edges (f, 2) of a curve, "
          "as int32 indices "
          "of samples (of surface_vertices for the power crust, which does not interpolate); "
          "closed surfaces face outward, closed curves run counterclockwise.")
      .def_property_readonly(
          "surface_vertices",
          [](py::object self) {
            return visit(self.cast<const Result&>(),
                         [&](const auto& r) { return rows_view(self, r.surface_points()); });
          },
          "The points the surface's indices refer to, (v, d): the sites (whose first rows are "
          "the samples) for an interpolating method, the power crust's own vertices otherwise.")
      .def_property_readonly(
          "solid",
          [](py::object self) {
            return visit(self.cast<const Result&>(),
                         [&](const auto& r) { return rows_view(self, r.solid); });
          },
          "The solid's tetrahedra (k, 4), or triangles (k, 3) in 2D, as indices of samples: the "
          "sculpted cells (paper, robust) or the alpha solid; empty for the other methods.")
      .def_property_readonly(
          "stages",
          [](py::object self) {
            return visit(self.cast<const Result&>(),
                         [&](const auto& r) { return stage_objects(self, r); });
          },
          stages_doc)
      .def_property_readonly(
          "verdict", [](const Result& r) { return verdict(statistics_of(r)).line; },
          "One line: a closed (or bordered) 2-manifold through every sample, or what is wrong.")
      .def_property_readonly(
          "manifold", [](const Result& r) { return verdict(statistics_of(r)).manifold; },
          "Whether the verdict is good: closed or properly bordered, every sample on it.")
      .def_property_readonly(
          "stats",
          [](const Result& r) {
            auto json = frontend::statistics_json(statistics_of(r));
            json["rule"] = frontend::surface_rule_name(r.options, r.dimension());
            json["box_factor"] = r.options.box_factor;
            return json_to_python(json);
          },
          "The statistics as a dict, named as `sculpt reconstruct --stats` names them; the stages' "
          "names and seconds under 'stages'. The command line keeps no triangulation "
          "(keep_triangulations=False gives its numbers exactly: without it DT(S + OUP) is not "
          "built and sculpted_cells is 0).")
      .def("__repr__", [](const Result& r) {
        const auto& stats = statistics_of(r);
        return "<sculpt.Reconstruction " + std::to_string(r.dimension()) + "D, " +
               std::to_string(stats.samples) + " samples, method " + to_string(r.options.method) +
               ": " + verdict(stats).line + ">";
      });

  const Options defaults;
  m.def("reconstruct", &reconstruct_points, py::arg("points"),
        py::arg("method") = to_string(defaults.method), py::arg("kind") = py::none(),
        py::arg("rule") = "auto", py::arg("box_factor") = defaults.box_factor,
        py::arg("alpha") = defaults.alpha,
        py::arg("bordered_seed_sample") = defaults.bordered_seed_sample,
        py::arg("keep_triangulations") = defaults.keep_triangulations,
        py::arg("merge_duplicates") = false, py::arg("clean") = to_string(defaults.cleaning),
        py::arg("progress") = py::none(),
        R"(Reconstructs a curve from 2D points or a surface from 3D points.

points               an (n, 2) or (n, 3) array, or anything numpy.asarray makes one of
method               a name of sculpt.methods(): 'robust' (the default, for real scans),
                     'paper' (Kuo & Yau as published), and the peers 'crust', 'nn-crust',
                     'cocone', 'tight-cocone', 'power-crust', 'boissonnat', 'advancing-front',
                     'alpha-shape'
kind                 'closed', 'bordered' for samples of a surface (curve) with a border, or
                     'automatic' (robust only): closed, unless the closed result spans openings
                     and the bordered one has fewer defects (the result's kind and
                     stats['kind_chosen_automatically'] say what was kept). None (the
                     default): automatic for robust, closed for the others
rule                 paper method: which facets make the surface, 'auto', 'skin' or
                     'extraction' (the paper's rule)
box_factor           the bounding box's size relative to the samples' box (the paper: 5)
alpha                alpha-shape: the radius, in the points' units; 0 chooses the smallest
                     whose solid is one piece holding every sample (stats['alpha'] says which)
bordered_seed_sample bordered: the sample whose convex pole seeds the labelling (-1: chosen)
keep_triangulations  keep the cells of the triangulations (the stages' pictures need them);
                     False computes as the command line does, with less memory (and for
                     advancing-front and alpha-shape, without DT(S + BBV) and the poles)
merge_duplicates     drop points that repeat an earlier one (else sculpt.DuplicatePoints)
clean                smooth the samples first (3D): 'jet' (CGAL's jet smoothing), 'none', or
                     'auto' (robust, where stats['noise'], the noise over the samples' spacing,
                     is at least 0.3: noise that crumples an interpolating surface); the surface
                     then passes through the smoothed samples (result.samples, stats['cleaned'],
                     result.given_samples the points as given)
progress             progress(stage, fraction) is called as each stage starts and ends (and
                     within the long ones); progress(stage, fraction, overall), if it takes
                     three arguments, also gets the whole run's fraction, which only grows
                     (a bar that fills once); returning False cancels (sculpt.Cancelled)

Returns a sculpt.Reconstruction. Bad input raises sculpt.InputError, whose message is the line
`sculpt reconstruct` prints. The GIL is released while the core runs; Ctrl-C stops it at its
next progress report.)");

  const frontend::Shot shot_defaults;
  m.def(
      "render",
      [](const Result& result, const std::string& stage, const py::object& size, long step,
         int focus_sample, int focus_pole, std::vector<std::string> layers, bool wireframe,
         bool smooth, bool legend, double zoom, int ball_every, double yaw, double pitch,
         std::optional<std::vector<double>> clip, std::optional<std::vector<double>> section,
         bool polar_balls, int ball_limit, double ball_opacity, const std::string& palette) {
        frontend::Shot shot;
        shot.stage = stage;
        shot.size = size_of(size);
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
        if (clip) {
          if (clip->size() != 3 && clip->size() != 4)
            throw Input_error("clip is (position, azimuth, elevation) or with a slab, 4 numbers");
          shot.clip = fmt::format("{}", fmt::join(*clip, ","));
        }
        if (section) {
          if (section->size() != 3)
            throw Input_error("section is (position, azimuth, elevation), 3 numbers");
          shot.section = fmt::format("{}", fmt::join(*section, ","));
        }
        shot.polar_balls = polar_balls;
        if (ball_limit < 0) throw Input_error("ball_limit is a count of balls, 0 for all");
        shot.ball_limit = ball_limit;
        shot.ball_opacity = ball_opacity;
        shot.palette = palette;
        return render_stage(result, shot);
      },
      py::arg("result"), py::arg("stage") = shot_defaults.stage,
      py::arg("size") = py::make_tuple(800, 800), py::arg("step") = shot_defaults.step,
      py::arg("focus_sample") = shot_defaults.focus_sample,
      py::arg("focus_pole") = shot_defaults.focus_pole,
      py::arg("layers") = std::vector<std::string>{},
      py::arg("wireframe") = shot_defaults.wireframe, py::arg("smooth") = shot_defaults.smooth,
      py::arg("legend") = !shot_defaults.no_legend, py::arg("zoom") = shot_defaults.zoom,
      py::arg("ball_every") = shot_defaults.ball_every, py::arg("yaw") = shot_defaults.yaw,
      py::arg("pitch") = shot_defaults.pitch, py::arg("clip") = py::none(),
      py::arg("section") = py::none(), py::arg("polar_balls") = shot_defaults.polar_balls,
      py::arg("ball_limit") = shot_defaults.ball_limit,
      py::arg("ball_opacity") = shot_defaults.ball_opacity,
      py::arg("palette") = shot_defaults.palette,
      R"(A picture of a stage, as `sculpt render` and the viewer draw it: an (height, width, 4)
uint8 RGBA array (matplotlib's imshow shows it).

stage         a name of sculpt.stages(result.method, result.dimension): 'samples', 'delaunay',
              'voronoi', 'poles', 'propagation', 'surface', ...
size          (width, height) in pixels, or one number for a square
step          a replay (propagation, carving, candidates, front, alpha): its first `step`
              events or steps; -1: all (alpha: the method's own)
focus_sample  a sample whose Voronoi cell, poles, polar balls and inscribed cubes are drawn
focus_pole    a pole whose polar ball, and the pole that labelled it, are drawn
layers        only these layers (their names are in the error message of a wrong one)
wireframe, smooth   surfaces: draw the edges; smooth shading
legend        the legend and the title
zoom          of the fitted camera: below 1 zooms in
ball_every    draw the polar balls of every k-th pole only
yaw, pitch    3D: the direction the camera looks from, in radians
clip          3D: (position, azimuth, elevation[, slab]) cuts away what lies beyond a plane:
              position 0 to 1 across the samples' box along its normal, the normal's angles in
              degrees, and a slab (a share of the box) keeps only that thickness before it;
              (0.5, 0, 90) shows the lower half of the Delaunay cells, whole
section       3D: (position, azimuth, elevation) draws the stage in that plane instead: the
              cells it cuts as polygons filled by what they are, the Voronoi faces and the
              surface where it crosses them, the samples near it; seen along the plane
polar_balls   3D: the polar balls at any stage, inner and outer apart
ball_limit    3D: at most this many inner and this many outer balls (0: all)
ball_opacity  3D: the balls' opacity, above 0 and at most 1 (the outer ones fainter)
palette       'paper' (the paper's colours) or 'colour-blind' (every pair of layers apart with
              deuteranopia and protanopia too))");

  m.def("write", &write_result, py::arg("result"), py::arg("path"), py::arg("solid") = py::none(),
        py::arg("ascii") = false, py::arg("normals") = py::none(), py::arg("colors") = py::none(),
        "Writes the surface (.stl .ply .off .obj) or curve (.obj .svg), and the solid if a path "
        "is given (.mesh .vtu .node/.ele): every file or none. STL and PLY are binary unless "
        "ascii=True. Paths are strings or pathlib paths. normals and colors, (n, 3) arrays with "
        "a row per sample (read_file gives them), go on the vertices of a .ply or .obj surface; "
        "colors are levels 0-255 (integers) or fractions 0-1 (floats).");
}
