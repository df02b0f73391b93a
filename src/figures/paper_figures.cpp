// SPDX-License-Identifier: GPL-3.0-or-later
#include "paper_figures.hpp"

#include <algorithm>
#include <cctype>
#include <string>

#include "figure_writing.hpp"

namespace sculpt::figures {

const std::vector<Figure>& paper_figures() {
  static const std::vector<Figure> figures = [] {
    std::vector<Figure> f;
    writing::add_method_figures(f);
    writing::add_result_figures(f);
    return f;
  }();
  return figures;
}

const Figure* find_figure(const std::string& id) {
  const std::string digits = id.rfind("fig", 0) == 0 ? id.substr(3) : id;
  const bool number = !digits.empty() && digits.size() <= 2 &&
                      std::all_of(digits.begin(), digits.end(), [](char c) {
                        return std::isdigit(static_cast<unsigned char>(c));
                      });
  if (!number) return nullptr;
  const std::string wanted = "fig" + std::string(digits.size() == 1 ? "0" : "") + digits;
  for (const auto& figure : paper_figures()) {
    if (figure.id == wanted) return &figure;
  }
  return nullptr;
}

std::string panel_name(const Figure& figure, std::size_t panel) {
  std::string name = "Fig. " + std::to_string(std::stoi(figure.id.substr(3)));
  const std::string& suffix = figure.images.at(panel).suffix;
  return suffix.empty() ? name : name + " (" + suffix + ")";
}

}  // namespace sculpt::figures
