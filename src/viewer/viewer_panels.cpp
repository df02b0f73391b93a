// SPDX-License-Identifier: GPL-3.0-or-later
// The panel left of the picture: the message and progress, the reconstruction options, the
// verdict, the stage stepper, the explanation, the method's pseudo-code with the statement
// running, the layers, the selection, the statistics, the 3D cut-away; and the controls window.
#include <imgui.h>

#include <algorithm>

#include "frontend/explanations.hpp"
#include "frontend/pseudo_code.hpp"
#include "readable_style.hpp"
#include "viewer.hpp"
#include "viewer_internals.hpp"

namespace sculpt::viewer {

using namespace internals;

void Viewer::draw_panel(int height) {
  const float top = ImGui::GetFrameHeight();
  ImGui::SetNextWindowPos(ImVec2(0, top), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(panel_width(), float(height) - top), ImGuiCond_Always);
  ImGui::Begin("Sculpt", nullptr,
               ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse);
  if (last_job_failed_) ImGui::PushStyleColor(ImGuiCol_Text, imgui_colour(panel_colours::failure));
  ImGui::TextWrapped("%s", message_.c_str());
  if (last_job_failed_) ImGui::PopStyleColor();
  if (job_->running()) {  // not while the view merely moves to a tour panel
    // Across the whole reconstruction, naming the stage it is in.
    const auto status = job_->status();
    const std::string label =
        status.stage + " (" + std::to_string(int(100 * status.overall)) + "%)";
    ImGui::ProgressBar(float(status.overall), ImVec2(-70, 0), label.c_str());
    ImGui::SameLine();
    if (ImGui::Button("Cancel")) cancel();
  }
  if (ImGui::CollapsingHeader("Reconstruction options")) {
    // Choosing another method reconstructs the same input at once, the camera kept, so a class
    // can flip between methods on the same points.
    if (ImGui::Combo("method", &method_, method_names().data(),
                     static_cast<int>(method_names().size())) &&
        !job_->running() &&
        (!last_request_.path.empty() || !last_request_.example.empty() || editor_.active())) {
      rerun();
    }
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", describe(method_at(method_)));
    // Automatic: closed, unless the closed result spans openings and the bordered one has fewer
    // defects (the verdict line says which was kept).
    static const char* kinds[] = {"automatic", "closed", "bordered"};
    int kind = kind_ == Surface_kind::closed ? 1 : kind_ == Surface_kind::bordered ? 2 : 0;
    if (ImGui::Combo("kind", &kind, kinds, 3)) {
      kind_ = kind == 1   ? Surface_kind::closed
              : kind == 2 ? Surface_kind::bordered
                          : Surface_kind::automatic;
    }
    if (ImGui::IsItemHovered()) {
      ImGui::SetTooltip(
          "automatic: closed, unless the closed result spans openings and the bordered one is "
          "cleaner");
    }
    ImGui::Checkbox("merge repeated points", &merge_duplicates_);
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip(
          "Scans often repeat a few points: drop the copies instead of refusing the file");
    ImGui::SliderFloat("box factor", &box_factor_, 1.1f, 10.0f, "%.1f");
    if (method_at(method_) == Method::alpha_shape) {
      // One radius for the whole shape: the lesson of what it fills and what it leaves open.
      if (ImGui::InputFloat("alpha (0: chosen)", &alpha_, 0, 0, "%g"))
        alpha_ = std::max(alpha_, 0.0f);
      if (ImGui::IsItemHovered())
        ImGui::SetTooltip(
            "The radius of the alpha shape, in the input's units; 0 takes the smallest "
            "whose solid is one piece holding every sample");
    }
    ImGui::Combo("surface rule", &rule_, rule_names, 3);
    ImGui::Combo("clean samples", &cleaning_, cleaning_names, IM_ARRAYSIZE(cleaning_names));
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip(
          "Clean the samples first (3D): outliers removes samples far off the surface of their "
          "nearest (a scanner's stray returns, spikes on an interpolating surface); jet fits a "
          "quadric to each sample's 24 nearest and moves it onto it; auto does both for the "
          "robust method when the noise is a third of the spacing or more, which crumples an "
          "interpolating surface; none never");
    if (ImGui::Button("Reconstruct again") && !busy() &&
        (!last_request_.path.empty() || !last_request_.example.empty() || editor_.active()))
      rerun();
  }
  if (reconstruction_) {
    draw_verdict();
    draw_stepper();
    if (dimension_of(*reconstruction_) == 3) draw_clip_controls();
    if (dimension_of(*reconstruction_) == 2) draw_editing_controls();
    if (scene::replays(request_.stage)) draw_propagation_controls();
    draw_explanation();
    draw_pseudo_code();
    draw_layers();
    draw_selection();
    draw_statistics();
  }
  ImGui::End();
}

void Viewer::draw_failure_notice(int width, int height) {
  // In the middle of an empty picture; over the top of the old one, which stays on screen.
  const float left = panel_width(), picture_width = float(width) - left;
  const float box_width = std::min(picture_width - 40.0f, 40.0f * ImGui::GetFontSize());
  const float top = ImGui::GetFrameHeight() + 20.0f;
  const float y = reconstruction_ ? top : std::max(top, 0.4f * float(height));
  ImGui::SetNextWindowPos(ImVec2(left + 0.5f * (picture_width - box_width), y), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(box_width, 0), ImGuiCond_Always);
  ImGui::PushStyleColor(ImGuiCol_WindowBg, imgui_colour(panel_colours::failure_notice));
  ImGui::PushStyleColor(ImGuiCol_Text, imgui_colour(panel_colours::text));
  ImGui::Begin("##failure", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing);
  ImGui::TextUnformatted(reconstruction_ ? "Failed: the picture is the last one that worked"
                                         : "Nothing to show: it failed");
  ImGui::Separator();
  ImGui::TextWrapped("%s", message_.c_str());
  ImGui::Spacing();
  ImGui::TextWrapped("Open another file (File > Open) or an example (Examples).");
  ImGui::End();
  ImGui::PopStyleColor(2);
}

void Viewer::draw_stepper() {
  ImGui::Separator();
  ImGui::TextUnformatted(scene::stage_title(request_.stage));
  const auto& stages = shown_stages();
  int index =
      static_cast<int>(std::find(stages.begin(), stages.end(), request_.stage) - stages.begin());
  if (ImGui::ArrowButton("##previous", ImGuiDir_Left)) step_stage(-1);
  ImGui::SameLine();
  ImGui::SetNextItemWidth(220);
  if (ImGui::SliderInt("##stage", &index, 0, static_cast<int>(stages.size()) - 1,
                       scene::stage_id(stages[index]))) {
    set_stage(stages[index]);
  }
  ImGui::SameLine();
  if (ImGui::ArrowButton("##next", ImGuiDir_Right)) step_stage(+1);
}

std::string Viewer::explanation() const {
  if (!reconstruction_) return "";
  const Options& options = options_of(*reconstruction_);
  return frontend::explanation(options.method, options.kind, dimension_of(*reconstruction_),
                               request_.stage);
}

// What the stage on screen shows, why it matters and what to look for: open by default, so a
// class reads it with the picture.
void Viewer::draw_explanation() {
  if (!ImGui::CollapsingHeader("Explanation", ImGuiTreeNodeFlags_DefaultOpen)) return;
  ImGui::PushTextWrapPos(0.0f);  // wrap at the panel's edge
  ImGui::TextUnformatted(explanation().c_str());
  ImGui::PopTextWrapPos();
}

void Viewer::draw_pseudo_code() {
  if (!ImGui::CollapsingHeader("Algorithm", ImGuiTreeNodeFlags_DefaultOpen)) return;
  const Options& options = options_of(*reconstruction_);
  const frontend::Pseudo_code& code =
      frontend::pseudo_code(options.method, options.kind, dimension_of(*reconstruction_));
  // A conflict offered right after the event on screen: its line, so the replay reaches it.
  const long shown = shown_step();
  const bool conflict_now =
      std::visit([&](const auto& r) { return frontend::conflict_after(r.propagation, shown); },
                 *reconstruction_);
  const Labelling_event* latest = latest_event();
  const bool seed_partner = std::visit(
      [&](const auto& r) { return frontend::labels_seed_partner(r, latest); }, *reconstruction_);
  const int current =
      frontend::current_line(code, request_.stage, latest, conflict_now, seed_partner);
  // The statement's loops and continuation lines in a softer colour, the statement itself marked.
  const std::vector<int> lit =
      frontend::highlighted_lines(code, request_.stage, latest, conflict_now, seed_partner);
  const auto& lines = code.lines;
  // The code scrolls in a box of its own, at most 45% of the panel high (a projector's large
  // font): the running statement is scrolled into sight there, never the verdict and controls.
  const float all_lines = ImGui::GetTextLineHeightWithSpacing() * float(lines.size()) +
                          ImGui::GetStyle().WindowPadding.y;
  ImGui::BeginChild("pseudo-code",
                    ImVec2(0, std::min(all_lines, 0.45f * ImGui::GetWindowHeight())));
  for (int i = 0; i < static_cast<int>(lines.size()); ++i) {
    if (i == current) {
      ImGui::TextColored(imgui_colour(panel_colours::current_line), "> %s", lines[i]);
      if (current != shown_code_line_ && !ImGui::IsItemVisible()) ImGui::SetScrollHereY(0.5f);
      shown_code_line_ = current;
    } else if (std::binary_search(lit.begin(), lit.end(), i)) {
      ImGui::TextColored(imgui_colour(panel_colours::lit_line), "  %s", lines[i]);
    } else {
      ImGui::TextDisabled("  %s", lines[i]);
    }
  }
  ImGui::EndChild();
}

void Viewer::draw_layers() {
  if (!ImGui::CollapsingHeader("Layers", ImGuiTreeNodeFlags_DefaultOpen)) return;
  for (const auto& layer : renderer_->scene().layers) {
    ImGui::ColorButton(("##" + layer.id).c_str(), imgui_color(layer.color),
                       ImGuiColorEditFlags_NoTooltip, ImVec2(12, 12));
    // A light outline: dark swatches (the curve, the polar circles) show on the dark panel.
    ImGui::GetWindowDrawList()->AddRect(ImGui::GetItemRectMin(), ImGui::GetItemRectMax(),
                                        IM_COL32(220, 220, 220, 255));
    ImGui::SameLine();
    bool visible =
        std::find(hidden_layers_.begin(), hidden_layers_.end(), layer.id) == hidden_layers_.end();
    if (ImGui::Checkbox(layer.label.c_str(), &visible)) {
      explore();
      if (visible) {
        hidden_layers_.erase(std::remove(hidden_layers_.begin(), hidden_layers_.end(), layer.id),
                             hidden_layers_.end());
      } else {
        hidden_layers_.push_back(layer.id);
      }
    }
  }
}

void Viewer::draw_selection() {
  if (request_.focus_sample < 0 && request_.focus_pole < 0) return;
  if (!ImGui::CollapsingHeader("Selection", ImGuiTreeNodeFlags_DefaultOpen)) return;
  ImGui::PushTextWrapPos(0.0f);  // long lines wrap at the panel's edge instead of being cut
  std::visit(
      [&](const auto& r) {
        const auto describe_pole = [&](int pole) {
          if (pole < 0) return;
          const auto& p = r.poles.poles[pole];
          ImGui::Text("pole %d: %s%s, radius %.4g", pole, to_string(r.propagation.labels[pole]),
                      p.convex ? ", convex" : "", p.radius);
          for (std::size_t i = 0; i < r.propagation.events.size(); ++i) {
            const auto& e = r.propagation.events[i];
            if (e.pole != pole) continue;
            if (e.source >= 0) {
              ImGui::Text("  labelled at event %zu by pole %d (%s)", i + 1, e.source,
                          reason_name(e.reason, r.stats.dimension));
            } else {
              ImGui::Text("  labelled at event %zu: %s", i + 1,
                          reason_name(e.reason, r.stats.dimension));
            }
          }
        };
        if (request_.focus_sample >= 0) {
          const int s = request_.focus_sample;
          ImGui::Text("sample %d", s);
          ImGui::TextDisabled("its Voronoi cell, poles, polar balls and inscribed %s are shown",
                              r.stats.dimension == 2 ? "squares" : "cubes");
          ImGui::TextUnformatted("p+:");
          describe_pole(r.poles.positive_pole[s]);
          ImGui::TextUnformatted("p-:");
          describe_pole(r.poles.negative_pole[s]);
        } else {
          describe_pole(request_.focus_pole);
        }
      },
      *reconstruction_);
  ImGui::PopTextWrapPos();
  if (ImGui::Button("Clear selection")) pick_sample(-1);
}

// The truth about the result, green or red, at the top of the panel where it is always seen.
void Viewer::draw_verdict() {
  const Statistics& s = statistics_of(*reconstruction_);
  const Verdict v = verdict(s);
  ImGui::PushStyleColor(ImGuiCol_Text,
                        imgui_colour(v.manifold ? panel_colours::success : panel_colours::failure));
  ImGui::TextWrapped("%s: %s", to_string(s.method), v.line.c_str());
  ImGui::PopStyleColor();
}

void Viewer::draw_statistics() {
  if (!ImGui::CollapsingHeader("Statistics", ImGuiTreeNodeFlags_DefaultOpen)) return;
  const Statistics& s = statistics_of(*reconstruction_);
  const bool three = s.dimension == 3;
  ImGui::Text("%s", description_.c_str());
  if (s.kind_chosen_automatically) {
    if (s.closed_spanning_facets > 0) {
      ImGui::TextWrapped("kind: %s, chosen (closed spanned openings with %zu %s)",
                         to_string(s.kind), s.closed_spanning_facets,
                         three ? "triangles" : "edges");
    } else {
      ImGui::Text("kind: %s, chosen (no opening)", to_string(s.kind));
    }
  } else {
    ImGui::Text("kind: %s", to_string(s.kind));
  }
  if (sculpts(s.method)) {
    ImGui::Text("n %zu   poles %zu   m %zu", s.samples, s.poles, s.inserted_poles);
    ImGui::Text("%s %zu   unlabelled %zu", s.method == Method::paper ? "conflicts" : "contradicted",
                s.conflicts, s.unlabelled_poles);
  } else {
    ImGui::Text("n %zu   poles %zu", s.samples, s.poles);
  }
  if (s.method == Method::alpha_shape) ImGui::Text("alpha %g", s.alpha);
  if (s.spanning_facets > 0) ImGui::Text("triangles spanning openings %zu", s.spanning_facets);
  if (s.set_in_samples > 0) ImGui::Text("left-off samples set in %zu", s.set_in_samples);
  if (s.attached_samples > 0) ImGui::Text("left-off samples attached %zu", s.attached_samples);
  if (s.joined_pinches > 0) ImGui::Text("pinched fans joined %zu", s.joined_pinches);
  if (s.dropped_fans > 0) ImGui::Text("pinched fans dropped %zu", s.dropped_fans);
  if (s.closed_notches > 0) ImGui::Text("sharp border notches closed %zu", s.closed_notches);
  if (s.filled_gaps > 0) ImGui::Text("gaps in the sampling filled %zu", s.filled_gaps);
  if (s.torn_loops > 0) ImGui::Text("torn loops (not openings) %zu", s.torn_loops);
  if (s.short_loops > 0) ImGui::Text("short loops (not openings) %zu", s.short_loops);
  if (s.candidate_facets > 0) {
    ImGui::Text("cells %zu   candidates %zu, pruned %zu%s", s.delaunay_cells, s.candidate_facets,
                s.pruned_facets, s.rims_kept ? " (rims kept)" : "");
  } else if (!sculpts(s.method)) {
    ImGui::Text("cells %zu", s.delaunay_cells);
  } else if (joins_neighbours(s.method, s.kind, s.dimension)) {
    ImGui::Text("cells %zu; the curves join nearest neighbours", s.delaunay_cells);
  } else if (inserts_poles(s.method, s.kind, s.dimension)) {
    ImGui::Text("cells %zu -> %zu   solid %zu", s.delaunay_cells, s.sculpted_cells, s.solid_cells);
  } else {
    if (s.carved_by_flood) {
      ImGui::Text("cells %zu, carved %zu in one flood", s.delaunay_cells, s.carved_cells);
    } else {
      ImGui::Text("cells %zu, carved %zu, outer kept %zu", s.delaunay_cells, s.carved_cells,
                  s.kept_outer_cells);
    }
    ImGui::Text("solid %zu", s.solid_cells);
  }
  ImGui::Text("%s %zu   %s %zu", three ? "triangles" : "edges", s.facets,
              three ? "border edges" : "end points", s.boundary_ridges);
  ImGui::Text("non-manifold %zu   unused %zu   pieces %zu", s.non_manifold_ridges, s.unused_samples,
              s.components);
  if (ImGui::TreeNode("time per stage")) {
    for (const auto& stage : s.stages)
      ImGui::Text("%-12s %8.3f s", stage.name.c_str(), stage.seconds);
    ImGui::Text("%-12s %8.3f s", "total", s.total_seconds);
    ImGui::TreePop();
  }
}

// A cut-away plane for the 3D stages that fill space: the cells in front of it go, so those
// behind are seen whole, in section.
void Viewer::draw_clip_controls() {
  if (!ImGui::CollapsingHeader("Look inside (3D)")) return;
  bool changed = false;
  if (ImGui::Checkbox("only near the picked sample", &request_.neighbourhood))
    set_neighbourhood(request_.neighbourhood);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip(
        "With a sample picked (click one): only the cells, edges, faces, poles and balls "
        "near it, its own Voronoi cell, poles and balls whole");
  if (ImGui::Checkbox("polar balls", &request_.polar_balls)) {
    changed = true;
    // A sample's inner ball is as large as the part it lies in: a score of them at first.
    if (request_.polar_balls && request_.ball_every == 1)
      request_.ball_every = std::max<int>(1, int(pole_count(*reconstruction_) / 20));
  }
  if (request_.polar_balls) {
    ImGui::SameLine();
    ImGui::SetNextItemWidth(120);
    changed |= ImGui::SliderInt("every", &request_.ball_every, 1, 500, "%d-th",
                                ImGuiSliderFlags_Logarithmic);
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("Thousands of balls hide one another: draw every k-th pole's");
    ImGui::SetNextItemWidth(120);
    changed |=
        ImGui::SliderInt("at most", &request_.ball_limit, 0, 2000,
                         request_.ball_limit > 0 ? "%d" : "all", ImGuiSliderFlags_Logarithmic);
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("At most this many inner and this many outer balls, evenly picked");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(120);
    changed |= ImGui::SliderFloat("opacity", &request_.ball_opacity, 0.1f, 1.0f, "%.2f");
  }
  changed |= ImGui::Checkbox("cut at a plane", &request_.clipped);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip(
        "Leave out every cell, edge, face and ball whose centre lies beyond the "
        "plane, to see inside the Delaunay triangulation, the Voronoi diagram or "
        "the solid");
  ImGui::SameLine();
  if (ImGui::Checkbox("section", &request_.sectioned)) {
    changed = true;
    if (request_.sectioned) look_along_the_section();
  }
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip(
        "Draw the stage in the plane: each cell it cuts as the polygon of the cut, filled by "
        "what the cell is (inside or outside the hull, kept or sculpted away), the Voronoi "
        "faces and the surface where it crosses them, the samples near it");
  if (request_.clipped || request_.sectioned) {
    auto& clip = request_.clip;
    bool turned = false;
    changed |= ImGui::SliderFloat("position", &clip.position, 0.0f, 1.0f, "%.2f");
    turned |= ImGui::SliderFloat("azimuth", &clip.azimuth, -180.0f, 180.0f, "%.0f deg");
    turned |= ImGui::SliderFloat("elevation", &clip.elevation, -90.0f, 90.0f, "%.0f deg");
    if (turned && request_.sectioned) look_along_the_section();
    changed |= turned;
    if (request_.clipped && !request_.sectioned) {
      changed |= ImGui::SliderFloat("slab", &clip.slab, 0.0f, 0.5f, clip.slab > 0 ? "%.2f" : "off");
      if (ImGui::IsItemHovered())
        ImGui::SetTooltip(
            "Keep only a slab this thick before the plane (a share of the box): the cells "
            "near the plane instead of a half");
    }
  }
  if (changed) scene_dirty_ = true;
}

void Viewer::draw_help() {
  ImGui::SetNextWindowPos(ImVec2(panel_width() + 20, 40), ImGuiCond_FirstUseEver);
  ImGui::Begin("Controls", &show_help_, ImGuiWindowFlags_AlwaysAutoResize);
  ImGui::TextUnformatted(
      "left / right arrow   previous / next stage\n"
      "space                play / pause the pole separation\n"
      ", and .              one labelling event back / forward\n"
      "left drag            orbit (3D), pan (2D)\n"
      "right or middle drag pan\n"
      "wheel                zoom\n"
      "click                pick a sample or a pole\n"
      "E                    edit samples (2D): click adds, drag moves,\n"
      "                     right click or Delete removes, Shift+drag draws\n"
      "U or Ctrl+Z          undo the last edit\n"
      "R or F               fit and reset the camera\n"
      "Page Down / Page Up  paper tour: next / previous panel\n"
      "] and [              paper tour: next / previous figure\n"
      "T                    paper tour: back to the panel after exploring\n"
      "Esc                  close the paper tour\n"
      "P                    save a picture (File menu: path and size)\n"
      "F5                   presentation mode: no panel, the legend in the picture\n"
      "H                    this help");
  ImGui::End();
}

}  // namespace sculpt::viewer
