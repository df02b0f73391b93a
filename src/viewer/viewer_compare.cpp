// SPDX-License-Identifier: GPL-3.0-or-later
// Side by side: two to four methods on the points shown, each in a view of its own with its
// verdict, all seen by one camera (turn one, all turn). The methods are reconstructed one after
// another by a job of their own, so the window stays live and the main view is left as it was.
#include <imgui.h>

#include <algorithm>
#include <string>
#include <vector>

#include "readable_style.hpp"
#include "render/picture_cache.hpp"
#include "render/renderer.hpp"
#include "viewer.hpp"
#include "viewer_internals.hpp"

namespace sculpt::viewer {

using namespace internals;

struct Viewer::Compared {
  Method method = Method::robust;
  std::shared_ptr<const Any_reconstruction> reconstruction;
  std::string error;  // why it has none
  std::unique_ptr<render::Renderer> renderer;
  render::Picture_cache cache;
  bool drawn_scene = false;  // the renderer holds this stage's scene
};

Viewer::Compare_state::Compare_state() = default;
Viewer::Compare_state::~Compare_state() = default;

bool Viewer::start_compare(const std::vector<Method>& methods) {
  if (methods.size() < 2 || methods.size() > 4) {
    message_ = "compare shows two to four methods side by side";
    return false;
  }
  if (!reconstruction_) {
    message_ = "nothing shown to compare: open an example or a file first";
    return false;
  }
  stop_compare();
  for (Method method : methods) {
    auto view = std::make_unique<Compared>();
    view->method = method;
    compare_.views.push_back(std::move(view));
  }
  compare_.next = 0;
  refit_for_views();
  message_ = "comparing " + std::to_string(methods.size()) + " methods on " + description_;
  return true;
}

void Viewer::stop_compare() {
  if (compare_.job) compare_.job->abandon();
  const bool was_comparing = comparing();
  compare_.views.clear();
  compare_.next = 0;
  if (was_comparing) refit_for_views();
}

// The camera framed for the views' shape: a half or a quarter of the picture's.
void Viewer::refit_for_views() {
  if (!reconstruction_ || frame_height_ <= 0) return;
  const std::size_t count = compare_.views.size();
  const float columns = count == 0 ? 1.0f : 2.0f, rows = count > 2 ? 2.0f : 1.0f;
  // The verdicts' band above each picture (draw_compare) is left out: about two lines.
  const float band = 2.5f * ImGui::GetTextLineHeightWithSpacing();
  const float aspect = (float(view_width(frame_width_)) / columns) /
                       std::max(1.0f, float(view_height(frame_height_)) / rows - band);
  camera_move_.reset();
  camera_ = render::fit(renderer_->scene(), aspect);
  camera_fitted_ = true;
}

bool Viewer::comparing() const {
  return !compare_.views.empty();
}

void Viewer::compare_scenes_stale() {
  for (auto& view : compare_.views) view->drawn_scene = false;
}

bool Viewer::compare_busy() const {
  return comparing() &&
         (compare_.next < compare_.views.size() ||
          (compare_.job && (compare_.job->running() || compare_.job->outcome_waiting())));
}

// One reconstruction at a time: its outcome taken, the next started.
void Viewer::advance_compare() {
  if (!comparing()) return;
  if (!compare_.job) compare_.job = make_reconstruction_job();
  if (auto outcome = compare_.job->take_outcome()) {
    Compared& view = *compare_.views[compare_.next];
    if (outcome->error.empty()) {
      view.reconstruction =
          std::make_shared<const Any_reconstruction>(std::move(*outcome->reconstruction));
    } else {
      view.error = outcome->error;
    }
    ++compare_.next;
  }
  if (compare_.job->running() || compare_.next >= compare_.views.size()) return;
  Compared& view = *compare_.views[compare_.next];
  // The method shown already is not computed again.
  if (reconstruction_ && options_of(*reconstruction_).method == view.method) {
    view.reconstruction = reconstruction_;
    ++compare_.next;
    return;
  }
  Job_request request = shown_request_;
  request.options.method = view.method;
  // The automatic kind is the robust method's own choice; the others reconstruct the kind the
  // shown result has.
  if (view.method != Method::robust && request.options.kind == Surface_kind::automatic)
    request.options.kind = options_of(*reconstruction_).kind;
  compare_.job->start(std::move(request));
}

// The views in a row (two) or two rows of two, right of the panel, above the caption.
void Viewer::draw_compare(int width, int height) {
  const std::size_t count = compare_.views.size();
  const int columns = 2, rows = count == 2 ? 1 : 2;
  const int view_w = std::max(1, view_width(width) / columns);
  const int view_h = std::max(1, view_height(height) / rows);
  ImDrawList* draw = ImGui::GetForegroundDrawList();
  // Each view's picture starts below a band as high as the tallest verdict, so that the verdicts
  // are read above the pictures, never over them.
  // Where a whole verdict would take more than three lines (narrow views, large text), its
  // head alone: "paper: NOT a closed 2-manifold".
  const float wrap = float(view_w) - 12;
  const auto fitted = [&](const std::string& label) {
    if (ImGui::CalcTextSize(label.c_str(), nullptr, false, wrap).y <=
        3.5f * ImGui::GetTextLineHeight())
      return label;
    const auto head = label.find(':', label.find(": ") + 2);
    return head == std::string::npos ? label : label.substr(0, head);
  };
  // Each view's scene, built when the stage or the options changed; a stage the method has not
  // shows its result.
  for (auto& view : compare_.views) {
    if (!view->reconstruction || view->drawn_scene) continue;
    if (!view->renderer) view->renderer = std::make_unique<render::Renderer>();
    scene::Request request = request_;
    request.colour_blind = colour_blind_;
    request.focus_sample = request.focus_pole = -1;
    request.neighbourhood = false;
    const Options& options = options_of(*view->reconstruction);
    if (!scene::has_stage(options.method, dimension_of(*view->reconstruction), request.stage))
      request.stage = scene::Stage::surface, request.step = -1;
    try {
      view->renderer->set_scene(std::visit(
          [&](const auto& r) { return scene::build_scene(r, request); }, *view->reconstruction));
      view->error.clear();
    } catch (const std::exception& e) {
      view->error = e.what();
      view->renderer->set_scene(scene::Scene{});
    }
    view->drawn_scene = true;
  }
  // Each view's name and verdict (or the error drawing it), and the band as high as the tallest.
  std::vector<std::string> labels;
  std::vector<bool> good;
  float band = 0;
  for (const auto& view : compare_.views) {
    std::string label = std::string(to_string(view->method)) + ": ";
    bool closed = false;
    if (!view->error.empty()) {
      label += view->error;
    } else if (view->reconstruction) {
      const Verdict verdict_of = verdict(statistics_of(*view->reconstruction));
      label += verdict_of.line;
      closed = verdict_of.manifold;
    } else {
      label += "reconstructing...";
    }
    good.push_back(closed);
    labels.push_back(fitted(label));
    band = std::max(band, ImGui::CalcTextSize(labels.back().c_str(), nullptr, false, wrap).y);
  }
  const int picture_h = std::max(1, view_h - std::min(int(band) + 8, view_h / 3));
  for (std::size_t i = 0; i < count; ++i) {
    Compared& view = *compare_.views[i];
    const int column = int(i) % columns, row = int(i) / columns;
    const int x = int(panel_width()) + column * view_w;
    // GL counts rows from the bottom; the first row is the top one.
    const int y = caption_height_ + reserved_height_ + (rows - 1 - row) * view_h;
    const float top = float(height - y - view_h);
    if (view.reconstruction) {
      render::Draw_options options;
      options.legend = false;
      options.title = false;
      options.picture_scale = picture_scale_;
      options.hidden_layers = hidden_layers_;
      options.viewport_x = x;
      options.viewport_y = y;
      view.cache.draw(*view.renderer, camera_, view_w, picture_h, options);
    }
    // Its name and verdict over its top edge, on a band that reads over any picture.
    const std::string& label = labels[i];
    const ImVec2 at(float(x) + 6, top + 4);
    const ImVec2 size = ImGui::CalcTextSize(label.c_str(), nullptr, false, wrap);
    draw->AddRectFilled(ImVec2(at.x - 4, at.y - 2), ImVec2(at.x + size.x + 4, at.y + size.y + 2),
                        IM_COL32(20, 20, 24, 220));
    draw->AddText(nullptr, 0, at,
                  ImGui::ColorConvertFloat4ToU32(
                      imgui_colour(good[i] ? panel_colours::success : panel_colours::failure)),
                  label.c_str(), nullptr, wrap);
    // A thin line between the views.
    if (column > 0)
      draw->AddLine(ImVec2(float(x), top), ImVec2(float(x), top + float(view_h)),
                    IM_COL32(120, 120, 120, 255));
    if (row > 0)
      draw->AddLine(ImVec2(float(x), top), ImVec2(float(x + view_w), top),
                    IM_COL32(120, 120, 120, 255));
  }
}

}  // namespace sculpt::viewer
