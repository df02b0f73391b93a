// SPDX-License-Identifier: GPL-3.0-or-later
// The mouse and the keys: the camera moved by hand, a click picking a sample or a pole, the
// keys of the stepper, the replay, the tour and editing. ImGui's panels take them first.
// clang-format off
#define GLFW_INCLUDE_NONE  // only the key names: no GL header
#include <GLFW/glfw3.h>
// clang-format on
#include <imgui.h>

#include <algorithm>
#include <cmath>

#include "picking.hpp"
#include "platform/platform.hpp"
#include "viewer.hpp"
#include "viewer_internals.hpp"

namespace sculpt::viewer {

using namespace internals;

void Viewer::handle_input(int width, int height) {
  ImGuiIO& io = ImGui::GetIO();
  if (!io.WantCaptureKeyboard) {
    for (int key : {GLFW_KEY_R,
                    GLFW_KEY_F,
                    GLFW_KEY_H,
                    GLFW_KEY_RIGHT,
                    GLFW_KEY_LEFT,
                    GLFW_KEY_SPACE,
                    GLFW_KEY_PERIOD,
                    GLFW_KEY_COMMA,
                    GLFW_KEY_P,
                    GLFW_KEY_PAGE_DOWN,
                    GLFW_KEY_PAGE_UP,
                    GLFW_KEY_RIGHT_BRACKET,
                    GLFW_KEY_LEFT_BRACKET,
                    GLFW_KEY_T,
                    GLFW_KEY_ESCAPE,
                    GLFW_KEY_E,
                    GLFW_KEY_U,
                    GLFW_KEY_Z,
                    GLFW_KEY_DELETE,
                    GLFW_KEY_BACKSPACE,
                    GLFW_KEY_F5}) {
      // A lesson running takes the page keys (App): it goes on with Page Down.
      const bool lesson_key = key == GLFW_KEY_PAGE_DOWN || key == GLFW_KEY_PAGE_UP;
      const int presses =
          static_cast<int>(std::count(key_presses_.begin(), key_presses_.end(), key));
      for (int i = 0; i < presses && !(lesson_running_ && lesson_key); ++i) on_key(key);
    }
  }
  if (io.WantCaptureMouse || !reconstruction_) return;
  if (editing_ && handle_editing_input(width, height)) return;

  const glm::vec2 delta(io.MouseDelta.x, io.MouseDelta.y);
  const float scale = 2.0f / float(view_height(height));
  const bool three = camera_.dimension == 3;
  const auto moved_by_hand = [&] {
    camera_move_.reset();
    camera_is_panel_camera_ = false;
  };
  if (ImGui::IsMouseDragging(ImGuiMouseButton_Left)) {
    moved_by_hand();
    if (three) {
      camera_.orbit(-delta.x * 0.01f, delta.y * 0.01f);
    } else {
      camera_.pan(-delta.x * scale, delta.y * scale);
    }
  }
  if (ImGui::IsMouseDragging(ImGuiMouseButton_Right) ||
      ImGui::IsMouseDragging(ImGuiMouseButton_Middle)) {
    moved_by_hand();
    camera_.pan(-delta.x * scale, delta.y * scale);
  }
  if (io.MouseWheel != 0) {
    moved_by_hand();
    camera_.zoom(std::pow(0.88f, io.MouseWheel));
  }
  if (ImGui::IsMouseReleased(ImGuiMouseButton_Left)) {
    const ImVec2 drag = ImGui::GetMouseDragDelta(ImGuiMouseButton_Left, 0.0f);
    if (drag.x * drag.x + drag.y * drag.y < 9.0f) {
      click({io.MousePos.x - panel_width(), io.MousePos.y - float(menu_bar_height_)},
            view_width(width), view_height(height));
    }
  }
}

void Viewer::press_key(int key) {
  on_key(key);
}

void Viewer::on_key(int key) {
  const long shown = shown_step();
  switch (key) {
    case GLFW_KEY_R:
    case GLFW_KEY_F:
      reset_camera(), scene_dirty_ = true;
      break;
    case GLFW_KEY_H:
      show_help_ = !show_help_;
      break;
    case GLFW_KEY_RIGHT:
      step_stage(+1);
      break;
    case GLFW_KEY_LEFT:
      step_stage(-1);
      break;
    case GLFW_KEY_SPACE:
      if (scene::replays(request_.stage)) explore(), playing_ = !playing_;
      break;
    case GLFW_KEY_PERIOD:
      set_step(shown + 1);
      break;
    case GLFW_KEY_COMMA:
      set_step(std::max(0L, shown - 1));
      break;
    case GLFW_KEY_P:
      // The desktop: the path typed in the File menu; the browser: a download named for the view.
      export_picture(platform::has_file_picker() ? platform::output_path(download_name(".png"))
                                                 : std::string(picture_field_),
                     picture_size_[0], picture_size_[1]);
      break;
    // The tour; page keys are what presentation remotes send.
    case GLFW_KEY_PAGE_DOWN:
      go_to_panel("next");
      break;
    case GLFW_KEY_PAGE_UP:
      go_to_panel("previous");
      break;
    case GLFW_KEY_RIGHT_BRACKET:
      next_figure();
      break;
    case GLFW_KEY_LEFT_BRACKET:
      previous_figure();
      break;
    case GLFW_KEY_T:
      return_to_panel();
      break;
    case GLFW_KEY_ESCAPE:
      close_tour();
      break;
    case GLFW_KEY_E:
      editing_ = !editing_;
      if (editing_ && !begin_editing()) editing_ = false;
      break;
    case GLFW_KEY_U:
      undo_edit();
      break;
    case GLFW_KEY_F5:  // as slide software starts and ends a presentation
      presenting_ = !presenting_;
      break;
    case GLFW_KEY_Z:  // Ctrl+Z
      if (ImGui::GetIO().KeyCtrl) undo_edit();
      break;
    case GLFW_KEY_DELETE:
    case GLFW_KEY_BACKSPACE:
      if (editing_ && request_.focus_sample >= 0) delete_point(request_.focus_sample);
      break;
    default:
      break;
  }
}

// A click picks the nearest pole where poles are shown, else the nearest sample; elsewhere it
// clears the selection.
void Viewer::click(glm::vec2 mouse, int width, int height) {
  const glm::mat4 view_projection = camera_.projection(float(width) / height) * camera_.view();
  const glm::vec2 viewport(width, height);
  const bool poles_shown =
      request_.stage >= scene::Stage::poles && request_.stage <= scene::Stage::sculpted_delaunay;
  std::visit(
      [&](const auto& r) {
        constexpr int D = std::decay_t<decltype(r)>::dimension;
        int pole = -1;
        if (poles_shown) {
          std::vector<Point<D>> centers;
          for (const auto& p : r.poles.poles) centers.push_back(p.center);
          pole = pick_nearest<D>(centers, centers.size(), view_projection, mouse, viewport);
        }
        const int sample =
            pick_nearest<D>(r.sites, r.sample_count(), view_projection, mouse, viewport);
        if (sample >= 0) {
          pick_sample(sample);
        } else if (pole >= 0) {
          pick_pole(pole);
        } else {
          pick_sample(-1);
        }
      },
      *reconstruction_);
}

}  // namespace sculpt::viewer
