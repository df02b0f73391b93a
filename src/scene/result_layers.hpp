// SPDX-License-Identifier: GPL-3.0-or-later
// The result, drawn on the surface stage: the curve or surface (its edges when asked for), its
// border and non-manifold ridges, the samples it leaves out, the triangles removed over openings,
// and the handles on thin evidence (handle_layers.hpp). Its own file: what the method made, apart
// from the stages that lead to it.
#pragma once

#include <algorithm>
#include <array>
#include <map>
#include <sculpt/sculpt.hpp>
#include <string>
#include <vector>

#include "builder_context.hpp"
#include "handle_layers.hpp"
#include "layer_helpers.hpp"
#include "palette.hpp"
#include "scene.hpp"
#include "simplex_geometry.hpp"

namespace sculpt::scene {

// The samples the result leaves out: an interpolating reconstruction should pass through
// every one, so each left off marks a place it went wrong (a valley cut across, a cavity).
template <int D>
void unused_samples(const Builder_context<D>& ctx) {
  if (!ctx.r.interpolates()) return;  // vertices of its own: no sample is on it
  std::vector<bool> used(ctx.n, false);
  for (const auto& facet : ctx.r.surface) {
    for (int v : facet) {
      if (v < ctx.n) used[v] = true;
    }
  }
  const auto unused = static_cast<std::size_t>(std::count(used.begin(), used.end(), false));
  if (unused == 0) return;
  Layer& layer = ctx.add("unused-samples", "samples left off (" + std::to_string(unused) + ")",
                         Primitive::points, palette::unused_sample, D == 2 ? 10.0f : 7.0f);
  for (int i = 0; i < ctx.n; ++i) {
    if (!used[i]) layer.positions.push_back(vec(ctx.r.sites[i]));
  }
}

// The result's border (curve ends in 2D, border edges in 3D) and its non-manifold ridges
// (branching samples, edges on more than two triangles), each a layer when there are any.
template <int D>
void borders_and_defects(const Builder_context<D>& ctx) {
  std::map<std::array<int, D - 1>, int> facets_on;
  for (const auto& facet : ctx.r.surface) {
    for (int skip = 0; skip < D; ++skip) {
      std::array<int, D - 1> ridge;
      for (int j = 0, k = 0; j < D; ++j) {
        if (j != skip) ridge[k++] = facet[j];
      }
      std::sort(ridge.begin(), ridge.end());
      ++facets_on[ridge];
    }
  }
  const auto layer_of = [&](bool border) -> Layer* {
    std::size_t count = 0;
    for (const auto& [ridge, facets] : facets_on) count += border ? facets == 1 : facets > 2;
    if (count == 0) return nullptr;
    const std::size_t loops = ctx.r.stats.boundary_loops;
    // Loops noise tore in the sheet and loops too short to be an opening's rim: not openings
    // (robust bordered rule).
    std::string not_openings;
    if (ctx.r.stats.torn_loops > 0) not_openings = std::to_string(ctx.r.stats.torn_loops) + " torn";
    if (ctx.r.stats.short_loops > 0) {
      not_openings +=
          (not_openings.empty() ? "" : ", ") + std::to_string(ctx.r.stats.short_loops) + " short";
    }
    const std::string torn = not_openings.empty() ? "" : " (" + not_openings + ")";
    const std::string what =
        D == 2 ? (border ? "curve ends (" + std::to_string(count) + ")"
                         : "branching samples (" + std::to_string(count) + ")")
               : (border ? "border: " + std::to_string(loops) + (loops == 1 ? " loop" : " loops") +
                               torn + ", " + std::to_string(count) + " edges"
                         : "non-manifold edges (" + std::to_string(count) + ")");
    return &ctx.add(border ? "border" : "non-manifold", what,
                    D == 2 ? Primitive::points : Primitive::lines,
                    border ? palette::border : palette::non_manifold, D == 2 ? 11.0f : 3.0f);
  };
  for (const bool border : {true, false}) {
    Layer* layer = layer_of(border);
    if (!layer) continue;
    for (const auto& [ridge, facets] : facets_on) {
      if (border ? facets != 1 : facets <= 2) continue;
      for (int v : ridge) layer->positions.push_back(vec(ctx.r.surface_points()[v]));
    }
  }
  unused_samples(ctx);
  add_handle_layers(ctx.layers, ctx.r);
}

// The triangles the robust bordered rule removed as spanning an opening, as edges: the caps
// the closed rules would have put over the openings (methods/robust/bordered_surface.hpp).
template <int D>
void openings(const Builder_context<D>& ctx) {
  const auto& spanning = ctx.r.candidates.spanning;
  if (spanning.empty()) return;
  Layer& layer =
      ctx.add("openings", "removed over openings (" + std::to_string(spanning.size()) + ")",
              Primitive::lines, palette::opening, 1.0f);
  for (const auto& facet : spanning) {
    for (int j = 0; j < D; ++j) {
      layer.positions.push_back(vec(ctx.r.sites[facet[j]]));
      layer.positions.push_back(vec(ctx.r.sites[facet[(j + 1) % D]]));
    }
  }
}

template <int D>
void surface(const Builder_context<D>& ctx) {
  // The samples, or the vertices of a result that does not interpolate (the power crust).
  const auto& points = ctx.r.surface_points();
  if constexpr (D == 2) {
    Layer& layer = ctx.add("curve", "reconstructed curve", Primitive::lines, palette::curve, 3.0f);
    for (const auto& edge : ctx.r.surface) {
      layer.positions.push_back(vec(points[edge[0]]));
      layer.positions.push_back(vec(points[edge[1]]));
    }
    borders_and_defects(ctx);
  } else {
    Layer& layer =
        ctx.add("surface", "reconstructed surface", Primitive::triangles, palette::surface, 1.0f);
    layer.lit = true;
    for (const auto& t : ctx.r.surface) {
      for (int v : t) layer.positions.push_back(vec(points[v]));
    }
    if (ctx.request.smooth)
      layer.normals = vertex_normals(points, ctx.r.surface, static_cast<int>(points.size()));
    borders_and_defects(ctx);
    openings(ctx);
    if (ctx.request.wireframe) {
      Layer& wire = ctx.add("wireframe", "edges", Primitive::lines, palette::wireframe, 1.0f);
      wire.in_legend = false;
      wire.scales = false;
      for (const auto& t : ctx.r.surface) {
        for (int j = 0; j < 3; ++j) {
          wire.positions.push_back(vec(points[t[j]]));
          wire.positions.push_back(vec(points[t[(j + 1) % 3]]));
        }
      }
    }
  }
}

}  // namespace sculpt::scene
