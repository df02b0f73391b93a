// SPDX-License-Identifier: GPL-3.0-or-later
// What the viewer's own files (viewer*.cpp) share and nobody else needs: small questions about
// the shown reconstruction and the options chosen in the panel.
#pragma once

#include <imgui.h>

#include <string>

#include "viewer.hpp"

namespace sculpt::viewer::internals {

// The methods in the order of method_names() (the default first).
inline Method method_at(int index) {
  Method method = Options{}.method;
  parse_method(method_names()[index], method);
  return method;
}

inline const char* const rule_names[] = {"auto", "skin", "extraction"};
// In the order of cleaning_choices().
inline const char* const cleaning_names[] = {"auto", "none", "outliers", "jet", "outliers+jet"};

// What makes two reconstructions the same: their input and options.
inline std::string request_key(const Job_request& r) {
  return r.path + "|" + r.example + "|" + std::to_string(r.dimension) + "|" +
         to_string(r.options.method) + "|" + to_string(r.options.kind) + "|" +
         std::to_string(r.options.box_factor) + "|" + to_string(r.options.rule) + "|" +
         std::to_string(r.options.alpha) + "|" + to_string(r.options.cleaning) + "|" +
         std::to_string(r.merge_duplicates) + "|" +
         // Edited points are never the same twice: each edit makes a new set.
         std::to_string(reinterpret_cast<std::uintptr_t>(r.edited_points.get()));
}

// A stage as it shows by default: no selection, every layer.
inline scene::Request default_view(scene::Stage stage) {
  scene::Request request;
  request.stage = stage;
  return request;
}

// The samples and poles of the shown reconstruction, to refuse a pick of one that is not there.
inline std::size_t sample_count(const Any_reconstruction& r) {
  return std::visit([](const auto& x) { return x.stats.samples; }, r);
}
inline std::size_t pole_count(const Any_reconstruction& r) {
  return std::visit([](const auto& x) { return x.poles.poles.size(); }, r);
}
inline int dimension_of(const Any_reconstruction& r) {
  return std::visit([](const auto& x) { return x.stats.dimension; }, r);
}
inline const Options& options_of(const Any_reconstruction& r) {
  return std::visit([](const auto& x) -> const Options& { return x.options; }, r);
}
inline const Statistics& statistics_of(const Any_reconstruction& r) {
  return std::visit([](const auto& x) -> const Statistics& { return x.stats; }, r);
}

// Why a pole was labelled, in words; the paper's cube is a square in the plane.
inline const char* reason_name(Label_reason reason, int dimension) {
  return dimension == 2 && reason == Label_reason::inscribed_cube ? "inscribed square"
                                                                  : to_string(reason);
}

inline ImVec4 imgui_color(const scene::Color& c) {
  return ImVec4(c.r, c.g, c.b, 1.0f);
}

}  // namespace sculpt::viewer::internals
