// SPDX-License-Identifier: GPL-3.0-or-later
#include "scene/growth_stages.hpp"

#include <algorithm>
#include <array>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/facet_orientation.hpp"
#include "scene/clipping.hpp"
#include "scene/cut_cells.hpp"
#include "scene/layer_helpers.hpp"
#include "scene/palette.hpp"

namespace sculpt::scene {
namespace {

// A radius in titles and labels: four significant digits.
std::string radius_text(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.4g", value);
  return buffer;
}

std::size_t shown_of(long step, std::size_t all) {
  return step < 0 ? all : std::min<std::size_t>(std::size_t(step), all);
}

// The step's simplex is small among thousands: its corners are drawn large, so the eye finds it.
template <std::size_t K>
void mark_corners(std::deque<Layer>& layers, const Reconstruction<3>& r,
                  const std::array<int, K>& simplex) {
  Layer& corners = add_layer(layers, "just-added-corners", "its corners", Primitive::points,
                             palette::just_removed, 10);
  corners.in_legend = false;
  corners.part_of = "just-added";
  corners.cut = true;
  for (int v : simplex) corners.positions.push_back(vec(r.sites[v]));
}

// The samples no shown simplex has reached yet: where the shape is still to grow.
template <std::size_t K>
void samples_not_reached(std::deque<Layer>& layers, const Reconstruction<3>& r,
                         const std::vector<std::array<int, K>>& simplices, const char* label) {
  const std::size_t n = r.sample_count();
  std::vector<bool> reached(n, false);
  for (const auto& simplex : simplices) {
    for (int v : simplex) reached[v] = true;
  }
  Layer& layer = add_layer(layers, "samples", label, Primitive::points, palette::sample, 4);
  for (std::size_t s = 0; s < n; ++s) {
    if (!reached[s]) layer.positions.push_back(vec(r.sites[s]));
  }
}

}  // namespace

std::string describe_growth(const Reconstruction<3>& r, Stage stage, long shown) {
  if (stage == Stage::front) {
    return shown <= 0 ? "before the seed triangle"
                      : "triangle " + std::to_string(shown) + " of " +
                            std::to_string(r.front.order.size()) + " added on the front";
  }
  const Alpha_stage& alpha = r.alpha;
  const std::string own = alpha.chosen == 0
                              ? ""
                              : " (the method's: " + radius_text(alpha.radii[alpha.chosen - 1]) +
                                    ", cell " + std::to_string(alpha.chosen) + ")";
  if (shown <= 0 || alpha.cells.empty()) return "alpha 0: the samples alone" + own;
  const std::size_t k = std::min<std::size_t>(std::size_t(shown), alpha.cells.size());
  return "alpha " + radius_text(alpha.radii[k - 1]) + ": cell " + std::to_string(k) + " of " +
         std::to_string(alpha.cells.size()) + own;
}

long front_length(const Reconstruction<3>& r) {
  return long(r.front.order.size());
}
long alpha_length(const Reconstruction<3>& r) {
  return long(r.alpha.cells.size());
}

void front_growth(std::deque<Layer>& layers, Scene& scene, const Reconstruction<3>& r, long step) {
  const auto& order = r.front.order;
  if (order.size() != r.surface.size())
    throw std::invalid_argument("this reconstruction did not keep the Advancing Front's order");
  const std::size_t shown = shown_of(step, order.size());
  std::vector<Facet<3>> grown;
  grown.reserve(shown);
  for (std::size_t k = 0; k < shown; ++k) grown.push_back(r.surface[order[k]]);
  scene.title = shown == 0 ? "Advancing Front: before its seed triangle (" +
                                 std::to_string(order.size()) + " to add)"
                           : "Advancing Front, triangle " + std::to_string(shown) + " of " +
                                 std::to_string(order.size()) +
                                 ": the most plausible triangle on the front's border";
  if (shown > 1) {
    Layer& before =
        add_layer(layers, "surface", "grown (" + std::to_string(shown - 1) + " triangles)",
                  Primitive::triangles, palette::surface, 1.0f);
    before.lit = true;
    for (std::size_t k = 0; k + 1 < shown; ++k) {
      for (int v : grown[k]) before.positions.push_back(vec(r.sites[v]));
    }
  }
  if (shown > 0) {
    Layer& now = add_layer(layers, "just-added", "added at this step", Primitive::triangles,
                           palette::just_removed, 1.0f);
    now.lit = true;
    for (int v : grown.back()) now.positions.push_back(vec(r.sites[v]));
    mark_corners(layers, r, grown.back());
  }
  // The front: the edges of one grown triangle only (the surface's border so far).
  std::vector<std::array<int, 2>> edges;
  for (const auto& t : grown) {
    for (int j = 0; j < 3; ++j)
      edges.push_back({std::min(t[j], t[(j + 1) % 3]), std::max(t[j], t[(j + 1) % 3])});
  }
  std::sort(edges.begin(), edges.end());
  Layer& front = add_layer(layers, "front", "the front: the border of what has grown",
                           Primitive::lines, palette::border, 2.0f);
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i;
    while (j < edges.size() && edges[j] == edges[i]) ++j;
    if (j - i == 1) {
      front.positions.push_back(vec(r.sites[edges[i][0]]));
      front.positions.push_back(vec(r.sites[edges[i][1]]));
    }
    i = j;
  }
  samples_not_reached(layers, r, grown, "samples the front has not reached");
}

void alpha_growth(std::deque<Layer>& layers, Scene& scene, const Reconstruction<3>& r,
                  const Request& request) {
  const Alpha_stage& alpha = r.alpha;
  if (alpha.cells.empty())
    throw std::invalid_argument(r.surface.empty() ? "no alpha gives one solid holding every sample"
                                                  : "this reconstruction did not keep its "
                                                    "triangulations");
  const std::size_t shown =
      request.step < 0 ? alpha.chosen : shown_of(request.step, alpha.cells.size());
  const std::vector<Cell<3>> in(alpha.cells.begin(), alpha.cells.begin() + long(shown));
  const std::string chosen = alpha.chosen == 0 ? ""
                                               : "; the method's alpha " +
                                                     radius_text(alpha.radii[alpha.chosen - 1]) +
                                                     " at cell " + std::to_string(alpha.chosen);
  scene.title = shown == 0 ? "Alpha shape, alpha 0: the samples alone (" +
                                 std::to_string(alpha.cells.size()) + " cells to join)" + chosen
                : shown == alpha.chosen
                    ? "Alpha shape at the method's alpha " + radius_text(alpha.radii[shown - 1]) +
                          ": the " + std::to_string(shown) + " cells of circumradius up to it"
                    : "Alpha shape, alpha " + radius_text(alpha.radii[shown - 1]) + " (cell " +
                          std::to_string(shown) + " of " + std::to_string(alpha.cells.size()) +
                          "): the cells of circumradius up to it" + chosen;
  const std::vector<Cell<3>> none;
  const std::string label = "alpha solid (" + std::to_string(shown) + " tetrahedra)";
  if (request.clipped) {
    whole_cells_cut(layers, r.sites, plane_of(scene, request.clip), request.clip.slab,
                    {"solid", label, palette::solid, &in},
                    {"sculpted-away", "not yet joined", palette::sculpted_away, &none},
                    std::find(request.layers.begin(), request.layers.end(), "cut-cells") !=
                        request.layers.end());
    scene.title += "; cut at the clip plane";
  } else {
    Clip everything;
    everything.position = 1;
    whole_cells_cut(layers, r.sites, plane_of(scene, everything), 0,
                    {"solid", label, palette::solid, &in},
                    {"sculpted-away", "not yet joined", palette::sculpted_away, &none}, false);
  }
  if (shown > 0 && (request.step >= 0 || shown != alpha.chosen)) {
    Layer& now = add_layer(layers, "just-added", "joined at this step", Primitive::triangles,
                           palette::just_removed, 1.0f);
    now.lit = true;
    now.cut = true;
    for (const auto& f : Facet_orientation<3>::vertex) {
      for (int i : f) now.positions.push_back(vec(r.sites[in.back()[i]]));
    }
    mark_corners(layers, r, in.back());
  }
  samples_not_reached(layers, r, in, "samples on no cell yet");
}

}  // namespace sculpt::scene
