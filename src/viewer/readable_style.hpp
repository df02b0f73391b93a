// SPDX-License-Identifier: GPL-3.0-or-later
// The panel's colours (panel_colours.hpp) given to Dear ImGui: its dark style with every
// background a text sits on made opaque and dark enough for WCAG AA.
#pragma once

#include <imgui.h>

#include "panel_colours.hpp"

namespace sculpt::viewer {

inline ImVec4 imgui_colour(panel_colours::Rgb c) {
  return ImVec4(c.r, c.g, c.b, 1.0f);
}

inline void use_readable_colours(ImGuiStyle& style) {
  namespace c = panel_colours;
  ImVec4* colours = style.Colors;
  colours[ImGuiCol_Text] = imgui_colour(c::text);
  colours[ImGuiCol_TextDisabled] = imgui_colour(c::quiet_text);
  colours[ImGuiCol_WindowBg] = imgui_colour(c::window);
  colours[ImGuiCol_ChildBg] = imgui_colour(c::window);
  colours[ImGuiCol_PopupBg] = imgui_colour(c::popup);
  colours[ImGuiCol_MenuBarBg] = imgui_colour(c::menu_bar);
  colours[ImGuiCol_TitleBg] = imgui_colour(c::title);
  colours[ImGuiCol_TitleBgActive] = imgui_colour(c::title);
  colours[ImGuiCol_TitleBgCollapsed] = imgui_colour(c::title);
  colours[ImGuiCol_FrameBg] = imgui_colour(c::frame);
  colours[ImGuiCol_FrameBgHovered] = imgui_colour(c::frame_hovered);
  colours[ImGuiCol_FrameBgActive] = imgui_colour(c::frame_active);
  colours[ImGuiCol_Button] = imgui_colour(c::button);
  colours[ImGuiCol_ButtonHovered] = imgui_colour(c::button_hovered);
  colours[ImGuiCol_ButtonActive] = imgui_colour(c::button_active);
  colours[ImGuiCol_Header] = imgui_colour(c::header);
  colours[ImGuiCol_HeaderHovered] = imgui_colour(c::header_hovered);
  colours[ImGuiCol_HeaderActive] = imgui_colour(c::header_active);
}

}  // namespace sculpt::viewer
