// SPDX-License-Identifier: GPL-3.0-or-later
// The reconstruction from Python: sculpt.reconstruct, with the command line's options and
// messages, and the Reconstruction it returns (arrays, stages, statistics, verdict). The core
// runs without the GIL; the progress callback takes it back briefly.
#include <memory>
#include <optional>
#include <string>
#include <type_traits>

#include "frontend/option_use.hpp"
#include "frontend/statistics_json.hpp"
#include "python/bindings.hpp"
#include "python/stage_views.hpp"

namespace sculpt::python {
namespace {

// A read-only property: the rows of what `member` takes of the result, as rows_view gives them
// (a view that keeps the result alive).
template <class Member>
auto rows_property(Member member) {
  return [member](py::object self) {
    return visit(self.cast<const Result&>(),
                 [&](const auto& r) { return rows_view(self, member(r)); });
  };
}

const Statistics& statistics_of(const Result& result) {
  return visit(result, [](const auto& r) -> const Statistics& { return r.stats; });
}

py::object json_to_python(const nlohmann::json& json) {
  return py::module_::import("json").attr("loads")(json.dump());
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
  options.method = method_named(method);
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
    throw Input_error("no cleaning '" + clean + "' (cleanings: " + cleaning_choices() + ")");
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

void bind_reconstruction(py::module_& m) {
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
          "When stats['cleaned'], the cleaned samples: those given but the outliers removed, "
          "smoothed where stats['smoothed'] (the surface passes through these).")
      .def_property_readonly(
          "given_samples",
          [](py::object self) -> py::object {
            return visit(self.cast<const Result&>(), [&](const auto& r) -> py::object {
              if (r.given_samples.empty()) return py::none();
              return rows_view(self, r.given_samples);
            });
          },
          "When the samples were cleaned (clean=...) and the triangulations kept (the "
          "default), the points as given, (n, d), read-only; None otherwise.")
      .def_property_readonly(
          "removed_outliers",
          [](const Result& result) -> py::object {
            return visit(result, [&](const auto& r) -> py::object {
              if (!r.stats.cleaned) return py::none();
              return py::array_t<int>(static_cast<py::ssize_t>(r.removed_outliers.size()),
                                      r.removed_outliers.data());
            });
          },
          "When stats['cleaned']: the indices (among the points given) of the outliers the "
          "cleaning removed, which the surface does not pass through, increasing, int array "
          "(result.samples are the others, in their order); None otherwise.")
      .def_property_readonly(
          "sites", rows_property([](const auto& r) -> const auto& { return r.sites; }),
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
          rows_property([](const auto& r) -> const auto& { return r.surface_points(); }),
          "The points the surface's indices refer to, (v, d): the sites (whose first rows are "
          "the samples) for an interpolating method, the power crust's own vertices otherwise.")
      .def_property_readonly(
          "solid", rows_property([](const auto& r) -> const auto& { return r.solid; }),
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
clean                clean the samples first (3D): 'outliers' (remove samples far off their
                     neighbours' surface), 'jet' (CGAL's jet smoothing), 'outliers+jet', 'none',
                     or 'auto' (both, for robust, where stats['noise'], the noise over the
                     samples' spacing, is at least 0.3: noise that crumples an interpolating
                     surface); the surface then passes through the cleaned samples
                     (result.samples, stats['cleaned'], result.given_samples the points as
                     given, result.removed_outliers those it does not pass through)
progress             progress(stage, fraction) is called as each stage starts and ends (and
                     within the long ones); progress(stage, fraction, overall), if it takes
                     three arguments, also gets the whole run's fraction, which only grows
                     (a bar that fills once); returning False cancels (sculpt.Cancelled)

Returns a sculpt.Reconstruction. Bad input raises sculpt.InputError, whose message is the line
`sculpt reconstruct` prints. The GIL is released while the core runs; Ctrl-C stops it at its
next progress report.)");
}
}  // namespace sculpt::python
