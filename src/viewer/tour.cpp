// SPDX-License-Identifier: GPL-3.0-or-later
#include "tour.hpp"

#include <algorithm>
#include <cctype>

namespace sculpt::viewer {

std::string Tour::panel_id() const {
  return active() ? figure_->id + image().suffix : "";
}

std::size_t Tour::figure_index() const {
  return static_cast<std::size_t>(figure_ - figures::paper_figures().data());
}

bool Tour::open(const figures::Figure& figure, std::size_t panel) {
  if (panel >= figure.images.size()) return false;
  figure_ = &figure;
  panel_ = panel;
  exploring_ = false;
  return true;
}

bool Tour::next() {
  if (!active()) return open(figures::paper_figures().front());
  if (panel_ + 1 < figure_->images.size()) return open(*figure_, panel_ + 1);
  return next_figure();
}

bool Tour::previous() {
  if (!active()) return false;
  if (panel_ > 0) return open(*figure_, panel_ - 1);
  if (figure_index() == 0) return false;
  const auto& before = figures::paper_figures()[figure_index() - 1];
  return open(before, before.images.size() - 1);
}

bool Tour::next_figure() {
  const auto& all = figures::paper_figures();
  if (!active()) return open(all.front());
  return figure_index() + 1 < all.size() && open(all[figure_index() + 1]);
}

bool Tour::previous_figure() {
  if (!active() || figure_index() == 0) return false;
  return open(figures::paper_figures()[figure_index() - 1]);
}

bool Tour::go_to(const std::string& panel) {
  if (panel == "next") return next();
  if (panel == "previous") return previous();
  if (!active() || panel.empty()) return false;
  if (std::all_of(panel.begin(), panel.end(),
                  [](unsigned char c) { return std::isdigit(c) != 0; })) {
    if (panel.size() > 3) return false;
    const std::size_t number = std::stoul(panel);
    return number >= 1 && open(*figure_, number - 1);
  }
  for (std::size_t i = 0; i < figure_->images.size(); ++i) {
    if (figure_->images[i].suffix == panel) return open(*figure_, i);
  }
  return false;
}

}  // namespace sculpt::viewer
