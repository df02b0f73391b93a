// SPDX-License-Identifier: GPL-3.0-or-later
// The menu bar: File (open, save what is shown, the link to this view), Examples and View; the
// Paper menu is the tour's (viewer_tour.cpp). In the browser files come from the file picker and
// leave as downloads, so the File menu asks for no paths.
#include <imgui.h>

#include <cmath>
#include <string>
#include <vector>

#include "platform/platform.hpp"
#include "shapes/shapes.hpp"
#include "viewer.hpp"
#include "viewer_internals.hpp"

namespace sculpt::viewer {

using namespace internals;

void Viewer::draw_menu() {
  if (!ImGui::BeginMainMenuBar()) return;
  menu_bar_height_ = int(std::ceil(ImGui::GetWindowHeight()));
  if (ImGui::BeginMenu("File")) {
    if (platform::has_file_picker()) {
      if (ImGui::MenuItem("Open a point file...", nullptr, false, !busy())) platform::choose_file();
      ImGui::TextDisabled("or drop one on the page");
      ImGui::Separator();
      draw_download_items();
    } else {
      draw_file_fields();
    }
    ImGui::Separator();
    if (ImGui::MenuItem(platform::in_browser ? "Copy a link to this view"
                                             : "Copy the command line for this view"))
      copy_link_to_view();
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("What opens this example, method, stage and selection again");
    if (!platform::in_browser) {
      ImGui::Separator();
      if (ImGui::MenuItem("Quit")) quit_ = true;
    }
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("Examples")) {
    for (const auto& e : shapes::examples()) {
      if (ImGui::MenuItem((e.name + " (" + std::to_string(e.dimension) + "D)").c_str(), nullptr,
                          false, !busy())) {
        open_example(e.name);
      }
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", e.description.c_str());
    }
    ImGui::EndMenu();
  }
  draw_paper_menu();
  if (ImGui::BeginMenu("View")) {
    if (ImGui::MenuItem("Fit / reset camera", "R")) reset_camera(), scene_dirty_ = true;
    if (ImGui::MenuItem("Controls", "H", show_help_)) show_help_ = !show_help_;
    if (ImGui::MenuItem("Presentation mode", "F5", presenting_)) presenting_ = !presenting_;
    if (ImGui::IsItemHovered()) {
      ImGui::SetTooltip("The panel hides, the picture takes the window with its legend in it");
    }
    // Side by side: the same points by several methods, one camera (viewer_compare.cpp).
    if (ImGui::BeginMenu("Side by side", reconstruction_ != nullptr)) {
      const bool curve = shown_dimension() == 2;
      const std::vector<std::vector<Method>> sets = {
          {Method::paper, Method::robust},
          curve
              ? std::vector<Method>{Method::paper, Method::robust, Method::crust, Method::nn_crust}
              : std::vector<Method>{Method::paper, Method::robust, Method::cocone,
                                    Method::advancing_front},
          {Method::paper, Method::robust, Method::boissonnat}};
      for (const auto& set : sets) {
        std::string name;
        for (Method m : set) name += (name.empty() ? "" : " | ") + std::string(to_string(m));
        if (ImGui::MenuItem(name.c_str())) start_compare(set);
      }
      if (ImGui::MenuItem("One view", nullptr, false, comparing())) stop_compare();
      ImGui::EndMenu();
    }
    if (ImGui::MenuItem("Colour-blind palette", nullptr, colour_blind_))
      set_colour_blind(!colour_blind_);
    if (ImGui::IsItemHovered()) {
      ImGui::SetTooltip(
          "Colours every pair of layers apart with deuteranopia and protanopia too, in place "
          "of the paper's red and green");
    }
    // Projector mode: text large enough for the back of a room, points and lines to match.
    ImGui::SliderFloat("text size", &ImGui::GetIO().FontGlobalScale, 0.5f, 3.0f, "%.1fx");
    ImGui::SliderFloat("picture scale", &picture_scale_, smallest_picture_scale,
                       largest_picture_scale, "%.1fx");
    ImGui::EndMenu();
  }
  ImGui::EndMainMenuBar();
}

// The desktop: each file at a path typed in the menu.
void Viewer::draw_file_fields() {
  ImGui::InputText("##path", path_field_, sizeof path_field_);
  ImGui::SameLine();
  if (ImGui::Button("Open")) open_file(path_field_);
  ImGui::TextDisabled("or drop a point file on the window");
  ImGui::Separator();
  ImGui::InputText("camera file", camera_field_, sizeof camera_field_);
  if (ImGui::MenuItem("Save camera")) save_camera(camera_field_);
  if (ImGui::MenuItem("Load camera")) load_camera(camera_field_);
  ImGui::Separator();
  ImGui::InputText("picture", picture_field_, sizeof picture_field_);
  ImGui::InputInt2("size", picture_size_);
  if (ImGui::MenuItem("Save picture", "P"))
    export_picture(picture_field_, picture_size_[0], picture_size_[1]);
  ImGui::InputText("animation", animation_field_, sizeof animation_field_);
  // The replay at the propagation stage, else a sweep of the stages.
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("An animated .webp, or a .gif for slide software");
  if (ImGui::MenuItem("Save animation (WebP or GIF)"))
    export_animation(animation_field_, picture_size_[0], picture_size_[1]);
  ImGui::InputText("result", result_field_, sizeof result_field_);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("A surface as .ply .obj .stl .off, a curve as .obj .svg");
  if (ImGui::MenuItem("Save the result", nullptr, false, reconstruction_ != nullptr))
    save_result(result_field_);
}

// The browser: each file a download named after what is shown (torus-paper-poles.png).
void Viewer::draw_download_items() {
  const bool shown = reconstruction_ != nullptr;
  ImGui::InputInt2("picture size", picture_size_);
  if (ImGui::MenuItem("Save a picture (PNG)", "P", false, shown))
    export_picture(platform::output_path(download_name(".png")), picture_size_[0],
                   picture_size_[1]);
  const bool replay = scene::replays(request_.stage);
  // WebP keeps every pixel; slide software plays GIF.
  for (const char* extension : {".webp", ".gif"}) {
    const std::string what =
        std::string(replay ? "Save the replay" : "Save the stages") +
        (extension == std::string(".gif") ? " (animated GIF, for slides)" : " (animated WebP)");
    if (ImGui::MenuItem(what.c_str(), nullptr, false, shown))
      export_animation(platform::output_path(download_name(extension)), picture_size_[0],
                       picture_size_[1]);
  }
  if (shown && shown_dimension() == 3) {
    if (ImGui::BeginMenu("Save the surface")) {
      for (const char* extension : {".ply", ".obj", ".stl", ".off"}) {
        if (ImGui::MenuItem(extension + 1))
          save_result(platform::output_path(download_name(extension)));
      }
      ImGui::EndMenu();
    }
  } else if (shown) {
    if (ImGui::BeginMenu("Save the curve")) {
      for (const char* extension : {".svg", ".obj"}) {
        if (ImGui::MenuItem(extension + 1))
          save_result(platform::output_path(download_name(extension)));
      }
      ImGui::EndMenu();
    }
    if (ImGui::MenuItem("Save the samples (.xy)"))
      save_points(platform::output_path(download_name(".xy")));
  }
  if (ImGui::MenuItem("Save the camera (JSON)", nullptr, false, shown))
    save_camera(platform::output_path(download_name(".camera.json")));
}

}  // namespace sculpt::viewer
