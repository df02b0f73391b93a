// SPDX-License-Identifier: GPL-3.0-or-later
// The panel's colours, text and what it sits on, chosen so that every text is readable at
// WCAG 2.1 level AA (a contrast ratio of at least 4.5 to 1) on every background it appears on,
// hovered and pressed ones included; tests/panel_contrast_test.cpp checks each pair. Opaque on
// purpose: a translucent background's contrast depends on what lies behind it.
#pragma once

#include <utility>
#include <vector>

namespace sculpt::viewer::panel_colours {

struct Rgb {
  float r, g, b;
};

// Backgrounds.
inline constexpr Rgb window{0.06f, 0.06f, 0.07f};
inline constexpr Rgb popup{0.09f, 0.09f, 0.10f};
inline constexpr Rgb menu_bar{0.14f, 0.14f, 0.14f};
inline constexpr Rgb title{0.16f, 0.29f, 0.48f};
inline constexpr Rgb frame{0.12f, 0.19f, 0.29f};  // an input, a slider
inline constexpr Rgb frame_hovered{0.15f, 0.27f, 0.43f};
inline constexpr Rgb frame_active{0.18f, 0.35f, 0.58f};
inline constexpr Rgb button{0.14f, 0.27f, 0.43f};
inline constexpr Rgb button_hovered{0.18f, 0.38f, 0.64f};
inline constexpr Rgb button_active{0.16f, 0.33f, 0.56f};
inline constexpr Rgb header{0.12f, 0.22f, 0.35f};  // a collapsing header, a selected item
inline constexpr Rgb header_hovered{0.18f, 0.38f, 0.64f};
inline constexpr Rgb header_active{0.16f, 0.33f, 0.56f};
inline constexpr Rgb failure_notice{0.70f, 0.08f, 0.06f};

// Texts.
inline constexpr Rgb text{1.00f, 1.00f, 1.00f};
// The pseudo-code's lines not running, and disabled items: quieter than the text, still AA.
inline constexpr Rgb quiet_text{0.68f, 0.68f, 0.70f};
inline constexpr Rgb current_line{1.00f, 0.80f, 0.20f};   // the statement running; lesson titles
inline constexpr Rgb lit_line{0.95f, 0.85f, 0.60f};       // its loops and continuation lines
inline constexpr Rgb success{0.50f, 0.90f, 0.50f};        // a verdict of a closed manifold
inline constexpr Rgb failure{1.00f, 0.45f, 0.40f};        // a verdict with defects, a failed run
inline constexpr Rgb caption{0.70f, 0.75f, 0.85f};        // the tour's figure caption
inline constexpr Rgb contradiction{1.00f, 0.70f, 0.35f};  // where our figure differs from it

// Every text with every background it is drawn on.
inline std::vector<std::pair<Rgb, Rgb>> text_on_background() {
  std::vector<std::pair<Rgb, Rgb>> pairs;
  for (Rgb background : {window, popup, menu_bar, title, frame, frame_hovered, frame_active, button,
                         button_hovered, button_active, header, header_hovered, header_active})
    pairs.push_back({text, background});
  for (Rgb coloured :
       {quiet_text, current_line, lit_line, success, failure, caption, contradiction}) {
    pairs.push_back({coloured, window});
    pairs.push_back({coloured, popup});
  }
  pairs.push_back({quiet_text, frame});  // a disabled control
  pairs.push_back({text, failure_notice});
  return pairs;
}

}  // namespace sculpt::viewer::panel_colours
