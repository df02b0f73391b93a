// SPDX-License-Identifier: GPL-3.0-or-later
// The stages of a reconstruction as numpy arrays for the Python module. Every array is a
// read-only view of the result's own vectors (no copy: a 150k-point result costs nothing to
// look at), and keeps the Python object that owns the result alive.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstddef>
#include <sculpt/sculpt.hpp>
#include <string>
#include <type_traits>
#include <vector>

namespace sculpt::python {

namespace py = pybind11;

// A read-only array over `count` records of `dtype` at `data`, owned by `owner`; `shape_tail`
// gives the dimensions of one record beyond the first axis (e.g. {3} for points of 3D).
inline py::array read_only_view(py::handle owner, const void* data, std::size_t count,
                                const py::dtype& dtype, std::vector<py::ssize_t> shape_tail = {}) {
  std::vector<py::ssize_t> shape{static_cast<py::ssize_t>(count)};
  shape.insert(shape.end(), shape_tail.begin(), shape_tail.end());
  py::array array = count == 0 ? py::array(dtype, shape)  // numpy refuses a null view
                               : py::array(dtype, shape, data, owner);
  array.attr("setflags")(py::arg("write") = false);
  return array;
}

// Points and index tuples: std::array rows are contiguous, so a vector of them is a 2D array.
template <class Scalar, std::size_t N>
py::array rows_view(py::handle owner, const std::vector<std::array<Scalar, N>>& rows) {
  return read_only_view(owner, rows.data(), rows.size(), py::dtype::of<Scalar>(),
                        {static_cast<py::ssize_t>(N)});
}

template <class T>
py::array values_view(py::handle owner, const std::vector<T>& values) {
  if constexpr (std::is_enum_v<T>) {  // labels: their codes (names in sculpt.LABELS, ...)
    return read_only_view(owner, values.data(), values.size(),
                          py::dtype::of<std::underlying_type_t<T>>());
  } else {
    return read_only_view(owner, values.data(), values.size(), py::dtype::of<T>());
  }
}

// A numpy record type laid over a C++ struct: field names, numpy formats, byte offsets.
struct Field {
  const char* name;
  std::string format;
  std::size_t offset;
};
inline py::dtype record_type(const std::vector<Field>& fields, std::size_t size) {
  py::list names, formats, offsets;
  for (const auto& field : fields) {
    names.append(field.name);
    formats.append(field.format);
    offsets.append(field.offset);
  }
  return py::dtype(names, formats, offsets, static_cast<py::ssize_t>(size));
}

// Labelling events and conflicts (stage 4): pole, label, source, reason, weight, after_events.
inline py::dtype labelling_event_type() {
  using E = Labelling_event;
  static_assert(sizeof(Label) == 1 && sizeof(Label_reason) == 1);
  return record_type({{"pole", "i4", offsetof(E, pole)},
                      {"label", "u1", offsetof(E, label)},
                      {"source", "i4", offsetof(E, source)},
                      {"reason", "u1", offsetof(E, reason)},
                      {"weight", "f4", offsetof(E, weight)},
                      {"after_events", "i8", offsetof(E, after_events)}},
                     sizeof(E));
}

// Carving events (stage 6b): cell, reason.
inline py::dtype carve_event_type() {
  static_assert(sizeof(Carve_reason) == 1);
  return record_type({{"cell", "i4", offsetof(Carve_event, cell)},
                      {"reason", "u1", offsetof(Carve_event, reason)}},
                     sizeof(Carve_event));
}

// The carving's openings (methods/robust/solid_openings.hpp): first_event, cells, kind,
// euler_change.
inline py::dtype carving_opening_type() {
  static_assert(sizeof(Opening_kind) == 1);
  static_assert(std::has_unique_object_representations_v<Carving_opening>);  // no padding
  return record_type({{"first_event", "u4", offsetof(Carving_opening, first_event)},
                      {"cells", "u4", offsetof(Carving_opening, cells)},
                      {"kind", "u1", offsetof(Carving_opening, kind)},
                      {"euler_change", "i4", offsetof(Carving_opening, euler_change)}},
                     sizeof(Carving_opening));
}

// Thin handles (core/thin_handles.hpp): the loop of 3 samples (then -1) or 4, width over spacing.
inline py::dtype thin_handle_type() {
  return record_type({{"loop", "(4,)i4", offsetof(Thin_handle, loop)},
                      {"width_over_spacing", "f8", offsetof(Thin_handle, width_over_spacing)}},
                     sizeof(Thin_handle));
}

// Poles (stage 2): center, radius, the cell of stage 1, its sites, convex.
template <int D>
py::dtype pole_type() {
  using P = Pole<D>;
  static_assert(sizeof(std::size_t) == 8 && sizeof(bool) == 1);
  return record_type({{"center", "(" + std::to_string(D) + ",)f8", offsetof(P, center)},
                      {"radius", "f8", offsetof(P, radius)},
                      {"cell", "i8", offsetof(P, cell)},
                      {"sites", "(" + std::to_string(D + 1) + ",)i4", offsetof(P, sites)},
                      {"convex", "?", offsetof(P, convex)}},
                     sizeof(P));
}

// A stage as an object with one attribute per array (types.SimpleNamespace).
inline py::object stage_object(const py::dict& fields) {
  return py::module_::import("types").attr("SimpleNamespace")(**fields);
}

// Each field of a record array as an array of its own (views, strided).
inline void add_fields(py::dict& fields, const py::array& records) {
  for (auto name : records.dtype().attr("names")) {
    fields[name] = records[name];
  }
}

template <int D>
py::dict delaunay_fields(py::handle owner, const Delaunay_stage<D>& stage) {
  py::dict fields;
  fields["cells"] = rows_view(owner, stage.cells);
  fields["cell_count"] = stage.cell_count;
  return fields;
}

// Every stage of a reconstruction, by the names of Reconstruction's members.
template <int D>
py::dict stage_objects(py::handle owner, const Reconstruction<D>& r) {
  py::dict stages;
  stages["delaunay"] = stage_object(delaunay_fields(owner, r.delaunay));
  {
    py::dict poles;
    const py::array records =
        read_only_view(owner, r.poles.poles.data(), r.poles.poles.size(), pole_type<D>());
    poles["records"] = records;
    add_fields(poles, records);
    poles["positive_pole"] = values_view(owner, r.poles.positive_pole);
    poles["negative_pole"] = values_view(owner, r.poles.negative_pole);
    poles["partner_offsets"] = values_view(owner, r.poles.partner_offsets);
    poles["partners"] = values_view(owner, r.poles.partners);
    stages["poles"] = stage_object(poles);
  }
  {
    py::dict seeds;
    seeds["convex_poles"] = values_view(owner, r.seeds.convex_poles);
    seeds["outer_seeds"] = values_view(owner, r.seeds.outer_seeds);
    stages["seeds"] = stage_object(seeds);
  }
  {
    const auto& p = r.propagation;
    py::dict propagation;
    propagation["events"] =
        read_only_view(owner, p.events.data(), p.events.size(), labelling_event_type());
    propagation["conflicts"] =
        read_only_view(owner, p.conflicts.data(), p.conflicts.size(), labelling_event_type());
    propagation["labels"] = values_view(owner, p.labels);
    propagation["unlabelled"] = p.unlabelled;
    stages["propagation"] = stage_object(propagation);
  }
  {
    py::dict insertion;
    insertion["inserted_poles"] = values_view(owner, r.insertion.inserted_poles);
    stages["insertion"] = stage_object(insertion);
  }
  stages["sculpted_delaunay"] = stage_object(delaunay_fields(owner, r.sculpted_delaunay));
  {
    const auto& c = r.carving;
    py::dict carving;
    carving["events"] = read_only_view(owner, c.events.data(), c.events.size(), carve_event_type());
    carving["kept_outer_cells"] = values_view(owner, c.kept_outer_cells);
    carving["buried_samples"] = values_view(owner, c.buried_samples);
    carving["openings"] =
        read_only_view(owner, c.openings.data(), c.openings.size(), carving_opening_type());
    carving["refused_handles"] = values_view(owner, c.refused_handles);
    stages["carving"] = stage_object(carving);
  }
  {
    py::dict crust = delaunay_fields(owner, r.crust.delaunay);
    crust["voronoi_vertices"] = rows_view(owner, r.crust.voronoi_vertices);
    stages["crust"] = stage_object(crust);
  }
  {
    py::dict candidates;
    candidates["chosen"] = rows_view(owner, r.candidates.chosen);
    candidates["pruned"] = rows_view(owner, r.candidates.pruned);
    candidates["spanning"] = rows_view(owner, r.candidates.spanning);
    candidates["rims_kept"] = r.candidates.rims_kept;
    stages["candidates"] = stage_object(candidates);
  }
  {
    py::dict front;
    front["order"] = values_view(owner, r.front.order);
    stages["front"] = stage_object(front);
    py::dict alpha;
    alpha["cells"] = rows_view(owner, r.alpha.cells);
    alpha["radii"] = values_view(owner, r.alpha.radii);
    alpha["chosen"] = r.alpha.chosen;
    stages["alpha"] = stage_object(alpha);
  }
  {
    py::dict handles;
    handles["thin"] =
        read_only_view(owner, r.thin_handles.data(), r.thin_handles.size(), thin_handle_type());
    stages["handles"] = stage_object(handles);
  }
  return stages;
}

}  // namespace sculpt::python
