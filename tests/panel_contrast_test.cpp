// SPDX-License-Identifier: GPL-3.0-or-later
// Every text of the viewer's panel is readable on every background it is drawn on: a WCAG 2.1
// contrast ratio of at least 4.5 to 1 (level AA for normal text), hovered and pressed controls
// included. The projector in a lit room is where low contrast fails first.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "viewer/panel_colours.hpp"

namespace sculpt {
namespace {

using viewer::panel_colours::Rgb;

// WCAG 2.1's relative luminance of an sRGB colour.
double luminance(const Rgb& c) {
  const auto linear = [](double u) {
    return u <= 0.04045 ? u / 12.92 : std::pow((u + 0.055) / 1.055, 2.4);
  };
  return 0.2126 * linear(c.r) + 0.7152 * linear(c.g) + 0.0722 * linear(c.b);
}

double contrast(const Rgb& a, const Rgb& b) {
  const double la = luminance(a), lb = luminance(b);
  return (std::max(la, lb) + 0.05) / (std::min(la, lb) + 0.05);
}

TEST(PanelContrast, TheRatioIsWcags) {
  EXPECT_NEAR(contrast({1, 1, 1}, {0, 0, 0}), 21.0, 1e-9);
  EXPECT_NEAR(contrast({0.5f, 0.5f, 0.5f}, {0.5f, 0.5f, 0.5f}), 1.0, 1e-9);
  // ImGui's own dark style: its grey disabled text passes, its hovered button does not.
  EXPECT_LT(contrast({1, 1, 1}, {0.26f, 0.59f, 0.98f}), 4.5);
}

TEST(PanelContrast, EveryTextMeetsLevelAaOnItsBackgrounds) {
  const auto pairs = viewer::panel_colours::text_on_background();
  ASSERT_GT(pairs.size(), 20u);
  for (const auto& [text, background] : pairs) {
    EXPECT_GE(contrast(text, background), 4.5)
        << "text (" << text.r << ", " << text.g << ", " << text.b << ") on (" << background.r
        << ", " << background.g << ", " << background.b << ")";
  }
}

}  // namespace
}  // namespace sculpt
