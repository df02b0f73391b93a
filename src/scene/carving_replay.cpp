// SPDX-License-Identifier: GPL-3.0-or-later
#include "carving_replay.hpp"

#include <algorithm>
#include <climits>
#include <cstdint>
#include <deque>
#include <mutex>
#include <stdexcept>
#include <tuple>
#include <utility>

#include "core/point_tree.hpp"
#include "growth_stages.hpp"
#include "scene.hpp"
#include "simplex_geometry.hpp"

namespace sculpt::scene {
namespace {

template <int D>
Cell<D> sorted(Cell<D> cell) {
  std::sort(cell.begin(), cell.end());
  return cell;
}

template <int D>
std::vector<Cell<D>> sorted_cells(const std::vector<Cell<D>>& cells) {
  std::vector<Cell<D>> result;
  result.reserve(cells.size());
  for (const auto& cell : cells) result.push_back(sorted<D>(cell));
  std::sort(result.begin(), result.end());
  return result;
}

// Paper, sec. 3.3: inserting a pole destroys the cells whose circumballs hold it. A hull cell
// leaves at the first pole of the list inside its circumball.
template <int D>
void steps_by_poles(const Reconstruction<D>& r, const std::vector<int>& leaving,
                    Carving_replay& replay) {
  const auto& inserted = r.insertion.inserted_poles;
  replay.inserted_poles = inserted.size();
  std::vector<Point<D>> centres;
  centres.reserve(inserted.size());
  for (int pole : inserted) centres.push_back(r.poles.poles[pole].center);
  const Point_tree<D> tree(centres.data(), centres.data() + centres.size());
  std::vector<std::vector<int>> destroyed(inserted.size() + 1);  // the last: no pole found
  for (int c : leaving) {
    std::array<Point<D>, D + 1> corners;
    for (int i = 0; i <= D; ++i) corners[i] = r.sites[r.delaunay.cells[c][i]];
    const Point<D> centre = circumcenter<D>(corners);
    double radius2 = 0;
    for (int k = 0; k < D; ++k)
      radius2 += (centre[k] - corners[0][k]) * (centre[k] - corners[0][k]);
    int first = INT_MAX;
    tree.any_within_indexed(centre, radius2, [&](const Point<D>&, int i) {
      first = std::min(first, i);
      return false;  // look at every pole inside: the first in the list is wanted
    });
    destroyed[first == INT_MAX ? inserted.size() : std::size_t(first)].push_back(c);
  }
  for (std::size_t i = 0; i < destroyed.size(); ++i) {
    if (destroyed[i].empty()) continue;
    Carving_step step;
    step.cells = std::move(destroyed[i]);
    step.pole = i < inserted.size() ? inserted[i] : -1;
    replay.steps.push_back(std::move(step));
  }
}

// The robust method's carving and Boissonnat's removal: their own order, one cell a step, or one
// opening (several cells removed at once) a step.
void steps_by_carving(const Carving_stage& carving, std::vector<int> leaving,
                      Carving_replay& replay) {
  std::sort(leaving.begin(), leaving.end());
  std::vector<bool> taken(leaving.size(), false);
  std::size_t next_opening = 0;
  for (std::size_t e = 0; e < carving.events.size(); ++e) {
    const Carve_event& event = carving.events[e];
    const auto at = std::lower_bound(leaving.begin(), leaving.end(), event.cell);
    if (at == leaving.end() || *at != event.cell || taken[at - leaving.begin()]) continue;
    taken[at - leaving.begin()] = true;
    while (next_opening < carving.openings.size() &&
           carving.openings[next_opening].first_event + carving.openings[next_opening].cells <= e)
      ++next_opening;
    const bool in_opening =
        next_opening < carving.openings.size() && carving.openings[next_opening].first_event <= e;
    if (in_opening && !replay.steps.empty() &&
        replay.steps.back().opening == static_cast<int>(next_opening)) {
      replay.steps.back().cells.push_back(event.cell);
      continue;
    }
    Carving_step step;
    step.cells = {event.cell};
    step.reason = event.reason;
    if (in_opening) step.opening = static_cast<int>(next_opening);
    replay.steps.push_back(std::move(step));
  }
  Carving_step rest;  // not in the record (none is expected): they leave last, together
  for (std::size_t i = 0; i < leaving.size(); ++i) {
    if (!taken[i]) rest.cells.push_back(leaving[i]);
  }
  if (!rest.cells.empty()) replay.steps.push_back(std::move(rest));
}

}  // namespace

bool carves_cells(Method method, Surface_kind kind, int dimension) {
  if (method == Method::boissonnat || method == Method::paper) return true;
  return method == Method::robust && !joins_neighbours(method, kind, dimension);
}

template <int D>
Carving_replay carving_replay(const Reconstruction<D>& r) {
  Carving_replay replay;
  const Method method = r.options.method;
  if (!carves_cells(method, r.options.kind, D)) return replay;
  if (r.delaunay.cells.size() != r.delaunay.cell_count)
    throw std::invalid_argument(
        "the carving replay needs the triangulations, which the reconstruction did not keep "
        "(keep_triangulations)");
  const int n = static_cast<int>(r.sample_count());
  const auto kept = sorted_cells<D>(r.solid);
  std::vector<int> leaving;
  for (std::size_t c = 0; c < r.delaunay.cells.size(); ++c) {
    const auto& cell = r.delaunay.cells[c];
    if (!std::all_of(cell.begin(), cell.end(), [&](int v) { return v < n; })) continue;
    replay.hull.push_back(int(c));
    if (!std::binary_search(kept.begin(), kept.end(), sorted<D>(cell))) leaving.push_back(int(c));
  }
  replay.by_poles = inserts_poles(method, r.options.kind, D);
  if (replay.by_poles)
    steps_by_poles(r, leaving, replay);
  else
    steps_by_carving(r.carving, std::move(leaving), replay);
  return replay;
}

template Carving_replay carving_replay(const Reconstruction<2>&);
template Carving_replay carving_replay(const Reconstruction<3>&);

namespace {
// What tells one reconstruction's replay from another's: where it lives, its counts, and a
// checksum of its cells and solid (a reconstruction freed and another made at its address has
// other cells, unless it is the same input by the same method: the same replay).
struct Replay_key {
  const void* address = nullptr;
  std::size_t cells = 0, solid = 0, carved = 0, inserted = 0, poles = 0, sites = 0;
  std::uint64_t checksum = 0;
  Method method = Method::robust;
  Surface_kind kind = Surface_kind::closed;
  auto tied() const {
    return std::tie(address, cells, solid, carved, inserted, poles, sites, checksum, method, kind);
  }
  bool operator==(const Replay_key& other) const { return tied() == other.tied(); }
};

template <int D>
Replay_key key_of(const Reconstruction<D>& r) {
  std::uint64_t sum = 1469598103934665603ull;  // FNV-1a over the cells' and solid's indices
  const auto add = [&](const std::vector<Cell<D>>& cells) {
    for (const auto& cell : cells) {
      for (int v : cell) sum = (sum ^ std::uint64_t(std::uint32_t(v))) * 1099511628211ull;
    }
  };
  add(r.delaunay.cells);
  add(r.solid);
  for (const auto& event : r.carving.events)
    sum = (sum ^ std::uint64_t(std::uint32_t(event.cell))) * 1099511628211ull;
  return {&r,
          r.delaunay.cells.size(),
          r.solid.size(),
          r.carving.events.size(),
          r.insertion.inserted_poles.size(),
          r.poles.poles.size(),
          r.sites.size(),
          sum,
          r.options.method,
          r.options.kind};
}
}  // namespace

// The last few asked about are kept: the views of a comparison each replay their own.
template <int D>
std::shared_ptr<const Carving_replay> shared_carving_replay(const Reconstruction<D>& r) {
  constexpr std::size_t kept_at_most = 4;
  static std::mutex mutex;
  static std::deque<std::pair<Replay_key, std::shared_ptr<const Carving_replay>>> kept;
  const Replay_key key = key_of(r);
  {
    const std::lock_guard<std::mutex> lock(mutex);
    for (const auto& [k, replay] : kept) {
      if (k == key) return replay;
    }
  }
  auto replay = std::make_shared<const Carving_replay>(carving_replay(r));
  const std::lock_guard<std::mutex> lock(mutex);
  kept.emplace_front(key, replay);
  if (kept.size() > kept_at_most) kept.pop_back();
  return replay;
}

template std::shared_ptr<const Carving_replay> shared_carving_replay(const Reconstruction<2>&);
template std::shared_ptr<const Carving_replay> shared_carving_replay(const Reconstruction<3>&);

namespace {
template <int D>
long length_of(const Reconstruction<D>& r, Stage stage) {
  if (!has_stage(r.options.method, D, stage)) return 0;
  if (stage == Stage::propagation) return long(r.propagation.events.size());
  if (stage == Stage::carving) return long(shared_carving_replay(r)->steps.size());
  if (stage == Stage::candidates) return long(r.candidates.pruned.size());
  if constexpr (D == 3) {
    if (stage == Stage::front) return front_length(r);
    if (stage == Stage::alpha) return alpha_length(r);
  }
  return 0;
}
}  // namespace

long replay_length(const Reconstruction<2>& r, Stage stage) {
  return length_of(r, stage);
}
long replay_length(const Reconstruction<3>& r, Stage stage) {
  return length_of(r, stage);
}

Carving_moment moment_of(const Carving_replay& replay, std::size_t cell_count, long step) {
  Carving_moment moment;
  moment.shown = step < 0 ? replay.steps.size() : std::min<std::size_t>(step, replay.steps.size());
  moment.states.assign(cell_count, Cell_state::outside_hull);
  for (int c : replay.hull) moment.states[c] = Cell_state::kept;
  for (std::size_t i = 0; i < moment.shown; ++i) {
    for (int c : replay.steps[i].cells)
      moment.states[c] = i + 1 == moment.shown ? Cell_state::taken_now : Cell_state::taken_before;
  }
  return moment;
}

namespace {
// An opening's change of the solid's Euler characteristic, in words.
std::string what_it_did(int change, int dimension) {
  if (change == 0) return "the topology stays";
  if (change > 0)
    return dimension == 3 ? "a cavity or a piece of its own opens" : "a piece of its own opens";
  if (dimension == 2) return "a hole opens";
  return change == -1 ? "a handle opens" : std::to_string(-change) + " handles open";
}
}  // namespace

std::string describe_step(const Carving_replay& replay, std::size_t step, int dimension,
                          const Carving_stage& carving) {
  const Carving_step& s = replay.steps.at(step);
  const std::string cells = dimension == 2 ? "triangle" : "tetrahedron";
  const std::string plural = dimension == 2 ? "triangles" : "tetrahedra";
  const std::string count =
      std::to_string(s.cells.size()) + " " + (s.cells.size() == 1 ? cells : plural);
  const std::string of = " of " + std::to_string(replay.steps.size());
  const std::string at = "step " + std::to_string(step + 1) + of + ": ";
  if (replay.by_poles)
    return at + (s.pole < 0 ? count + " on a circumsphere's edge, taken last"
                            : "a pole destroys " + count);
  if (s.opening >= 0) {
    const Carving_opening& opening = carving.openings.at(std::size_t(s.opening));
    return at + to_string(opening.kind) + ", " + count + (s.cells.size() == 1 ? "" : " at once") +
           ": " + what_it_did(opening.euler_change, dimension);
  }
  if (s.cells.size() != 1) return at + count + " not in the record, taken last";
  return at + to_string(s.reason);
}

}  // namespace sculpt::scene
