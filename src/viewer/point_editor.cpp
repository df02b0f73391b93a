// SPDX-License-Identifier: GPL-3.0-or-later
#include "point_editor.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <utility>

#include "io/atomic_file.hpp"

namespace sculpt::viewer {
namespace {

// A long lesson keeps its history; a runaway script does not fill the memory.
constexpr std::size_t history_limit = 1000;

}  // namespace

void Point_editor::start(std::vector<Point<2>> points, std::string origin) {
  *this = Point_editor{};
  active_ = true;
  points_ = std::move(points);
  origin_ = std::move(origin);
}

void Point_editor::remember() {
  history_.push_back(points_);
  if (history_.size() > history_limit) history_.erase(history_.begin());
  ++edits_;
}

bool Point_editor::index_ok(int sample) {
  if (sample >= 0 && std::size_t(sample) < points_.size()) return true;
  why_ =
      "no sample " + std::to_string(sample) + " (there are " + std::to_string(points_.size()) + ")";
  return false;
}

int Point_editor::nearest(const Point<2>& p, double radius) const {
  int best = -1;
  double best_distance = radius;
  for (std::size_t i = 0; i < points_.size(); ++i) {
    const double d = std::hypot(points_[i][0] - p[0], points_[i][1] - p[1]);
    if (d <= best_distance) best = int(i), best_distance = d;
  }
  return best;
}

bool Point_editor::add(const Point<2>& p) {
  return add_all({p});
}

bool Point_editor::add_all(const std::vector<Point<2>>& added) {
  // A repeated point would be refused by the triangulation: it is simply not added.
  std::set<std::pair<double, double>> taken;
  for (const auto& p : points_) taken.insert({p[0], p[1]});
  std::vector<Point<2>> fresh;
  for (const auto& p : added) {
    if (std::isfinite(p[0]) && std::isfinite(p[1]) && taken.insert({p[0], p[1]}).second)
      fresh.push_back(p);
  }
  if (fresh.empty()) {
    why_ = "no new sample: each is already there";
    return false;
  }
  remember();
  points_.insert(points_.end(), fresh.begin(), fresh.end());
  return true;
}

bool Point_editor::move(int sample, const Point<2>& to) {
  begin_drag();
  return drag(sample, to);
}

bool Point_editor::drag(int sample, const Point<2>& to) {
  if (!index_ok(sample)) return false;
  if (!std::isfinite(to[0]) || !std::isfinite(to[1])) {
    why_ = "not a finite position";
    return false;
  }
  for (std::size_t i = 0; i < points_.size(); ++i) {
    if (int(i) != sample && points_[i][0] == to[0] && points_[i][1] == to[1]) {
      why_ = "sample " + std::to_string(i) + " is already there";
      return false;
    }
  }
  if (!dragging_) remember(), dragging_ = true;
  points_[sample] = to;
  return true;
}

bool Point_editor::remove(int sample) {
  if (!index_ok(sample)) return false;
  remember();
  points_.erase(points_.begin() + sample);
  return true;
}

bool Point_editor::undo() {
  if (history_.empty()) {
    why_ = "nothing to undo";
    return false;
  }
  points_ = std::move(history_.back());
  history_.pop_back();
  --edits_;
  dragging_ = false;
  return true;
}

void save_points(const std::string& path, const std::vector<Point<2>>& points) {
  io::Atomic_file file(path, false);
  char line[64];
  for (const auto& p : points) {
    std::snprintf(line, sizeof line, "%.17g %.17g\n", p[0], p[1]);
    file.stream() << line;
  }
  file.commit();
}

}  // namespace sculpt::viewer
