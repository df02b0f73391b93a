#include "viewer.hpp"

// Our GL header before GLFW's keys: it must be the first to include GL/gl.h.
#include "render/gl.hpp"
// clang-format off
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
// clang-format on
#include <imgui.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>

#include "frontend/pseudo_code.hpp"
#include "io/atomic_file.hpp"
#include "picking.hpp"
#include "shapes/shapes.hpp"

namespace sculpt::viewer {
namespace {

constexpr float panel_width = 360.0f;

const char* rule_names[] = {"auto", "skin", "extraction"};
// The methods in the order of method_names() (the default first).
Method method_at(int index) {
  Method method = Options{}.method;
  parse_method(method_names()[index], method);
  return method;
}

ImVec4 imgui_color(const scene::Color& c) {
  return ImVec4(c.r, c.g, c.b, 1.0f);
}

int view_width(int window_width) {
  return std::max(1, window_width - int(panel_width));
}

}  // namespace

Viewer::Viewer() : renderer_(std::make_unique<render::Renderer>()) {}

// ---------------------------------------------------------------------------------------------
// Reconstructions

void Viewer::open_example(const std::string& name) {
  Job_request request;
  request.example = name;
  if (const auto* example = shapes::find_example(name)) bordered_ = example->bordered;
  start_job(request);
}

void Viewer::open_file(const std::string& path) {
  Job_request request;
  request.path = path;
  std::snprintf(path_field_, sizeof path_field_, "%s", path.c_str());
  start_job(request);
}

void Viewer::rerun() {
  start_job(last_request_);
}

void Viewer::start_job(Job_request request) {
  request.options.method = method_at(method_);
  request.options.kind = bordered_ ? Surface_kind::bordered : Surface_kind::closed;
  request.options.box_factor = box_factor_;
  request.options.rule = rule_ == 1   ? Surface_rule::skin
                         : rule_ == 2 ? Surface_rule::extraction
                                      : Surface_rule::automatic;
  last_request_ = request;
  message_ =
      "reconstructing " + (request.example.empty() ? request.path : "example " + request.example);
  job_.start(std::move(request));
}

void Viewer::take_finished_job() {
  auto outcome = job_.take_outcome();
  if (!outcome) return;
  if (!outcome->error.empty()) {
    message_ = outcome->error == "cancelled" ? "cancelled" : "error: " + outcome->error;
    return;
  }
  const bool same_dimension =
      reconstruction_ && reconstruction_->index() == outcome->reconstruction->index();
  reconstruction_ = std::move(outcome->reconstruction);
  description_ = outcome->description;
  message_ = "showing " + description_;
  request_.focus_sample = request_.focus_pole = -1;
  request_.step = -1;
  playing_ = false;
  if (!same_dimension) camera_fitted_ = false;
  scene_dirty_ = true;
}

// ---------------------------------------------------------------------------------------------
// What is shown

void Viewer::set_stage(scene::Stage stage) {
  request_.stage = stage;
  scene_dirty_ = true;
}

void Viewer::step_stage(int delta) {
  const auto& stages = scene::all_stages();
  int index =
      static_cast<int>(std::find(stages.begin(), stages.end(), request_.stage) - stages.begin());
  index = std::clamp(index + delta, 0, static_cast<int>(stages.size()) - 1);
  set_stage(stages[index]);
}

void Viewer::set_step(long events) {
  request_.step = events < 0 ? -1 : std::min(events, event_count());
  scene_dirty_ = true;
}

void Viewer::pick_sample(int sample) {
  request_.focus_sample = sample;
  request_.focus_pole = -1;
  scene_dirty_ = true;
}

void Viewer::pick_pole(int pole) {
  request_.focus_pole = pole;
  request_.focus_sample = -1;
  scene_dirty_ = true;
}

void Viewer::reset_camera() {
  camera_fitted_ = false;
}

long Viewer::event_count() const {
  if (!reconstruction_) return 0;
  return std::visit([](const auto& r) { return long(r.propagation.events.size()); },
                    *reconstruction_);
}

const Labelling_event* Viewer::latest_event() const {
  if (!reconstruction_ || request_.stage != scene::Stage::propagation) return nullptr;
  return std::visit(
      [&](const auto& r) -> const Labelling_event* {
        const long shown = request_.step < 0 ? long(r.propagation.events.size()) : request_.step;
        return shown > 0 ? &r.propagation.events[shown - 1] : nullptr;
      },
      *reconstruction_);
}

void Viewer::rebuild_scene() {
  if (!scene_dirty_ || !reconstruction_) return;
  scene_dirty_ = false;
  try {
    scene::Scene scene = std::visit([&](const auto& r) { return scene::build_scene(r, request_); },
                                    *reconstruction_);
    renderer_->set_scene(scene);
    if (!camera_fitted_) {
      camera_ = render::fit(
          scene, frame_height_ > 0 ? float(view_width(frame_width_)) / frame_height_ : 1.0f);
      camera_fitted_ = true;
    }
  } catch (const std::exception& e) {
    message_ = std::string("error: ") + e.what();
  }
}

// ---------------------------------------------------------------------------------------------
// The frame

void Viewer::frame(int width, int height, double seconds) {
  frame_width_ = width;
  frame_height_ = height;
  take_finished_job();
  advance_playback(seconds);
  handle_input(width, height);
  draw_menu();
  draw_panel(height);
  if (show_help_) draw_help();
  rebuild_scene();

  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  if (reconstruction_) {
    render::Draw_options options;
    options.legend = options.title = false;  // the panel shows both
    options.hidden_layers = hidden_layers_;
    options.viewport_x = int(panel_width);  // the picture takes the window right of the panel
    renderer_->draw(camera_, view_width(width), height, options);
  } else {
    glViewport(0, 0, width, height);
    glClearColor(1, 1, 1, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  }
}

void Viewer::advance_playback(double seconds) {
  if (!playing_ || request_.stage != scene::Stage::propagation) return;
  playback_clock_ += seconds * events_per_second_;
  const long steps = long(playback_clock_);
  if (steps == 0) return;
  playback_clock_ -= double(steps);
  const long current = request_.step < 0 ? event_count() : request_.step;
  if (current >= event_count()) {
    playing_ = false;
    return;
  }
  set_step(current + steps);
}

void Viewer::handle_input(int width, int height) {
  ImGuiIO& io = ImGui::GetIO();
  if (!io.WantCaptureKeyboard) {
    if (ImGui::IsKeyPressed(GLFW_KEY_R) || ImGui::IsKeyPressed(GLFW_KEY_F))
      reset_camera(), scene_dirty_ = true;
    if (ImGui::IsKeyPressed(GLFW_KEY_H)) show_help_ = !show_help_;
    if (ImGui::IsKeyPressed(GLFW_KEY_RIGHT)) step_stage(+1);
    if (ImGui::IsKeyPressed(GLFW_KEY_LEFT)) step_stage(-1);
    if (ImGui::IsKeyPressed(GLFW_KEY_SPACE) && request_.stage == scene::Stage::propagation)
      playing_ = !playing_;
    if (ImGui::IsKeyPressed(GLFW_KEY_PERIOD))
      set_step((request_.step < 0 ? event_count() : request_.step) + 1);
    if (ImGui::IsKeyPressed(GLFW_KEY_COMMA))
      set_step(std::max(0L, (request_.step < 0 ? event_count() : request_.step) - 1));
    if (ImGui::IsKeyPressed(GLFW_KEY_P))
      export_picture(picture_field_, picture_size_[0], picture_size_[1]);
  }
  if (io.WantCaptureMouse || !reconstruction_) return;

  const glm::vec2 delta(io.MouseDelta.x, io.MouseDelta.y);
  const float scale = 2.0f / float(std::max(height, 1));
  const bool three = camera_.dimension == 3;
  if (ImGui::IsMouseDragging(ImGuiMouseButton_Left)) {
    if (three) {
      camera_.orbit(-delta.x * 0.01f, delta.y * 0.01f);
    } else {
      camera_.pan(-delta.x * scale, delta.y * scale);
    }
  }
  if (ImGui::IsMouseDragging(ImGuiMouseButton_Right) ||
      ImGui::IsMouseDragging(ImGuiMouseButton_Middle)) {
    camera_.pan(-delta.x * scale, delta.y * scale);
  }
  if (io.MouseWheel != 0) camera_.zoom(std::pow(0.88f, io.MouseWheel));
  if (ImGui::IsMouseReleased(ImGuiMouseButton_Left)) {
    const ImVec2 drag = ImGui::GetMouseDragDelta(ImGuiMouseButton_Left, 0.0f);
    if (drag.x * drag.x + drag.y * drag.y < 9.0f) {
      click({io.MousePos.x - panel_width, io.MousePos.y}, view_width(width), height);
    }
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

// ---------------------------------------------------------------------------------------------
// Files

bool Viewer::export_picture(const std::string& path, int width, int height) {
  // The figures' own renderer: `sculpt render`, next to this program, with this view's shot.
  const auto self = std::filesystem::read_symlink("/proc/self/exe");
  const auto sculpt = self.parent_path() / "sculpt";
  nlohmann::json shot = {{"stage", scene::stage_id(request_.stage)},
                         {"step", request_.step},
                         {"focus_sample", request_.focus_sample},
                         {"focus_pole", request_.focus_pole},
                         {"bordered", bordered_},
                         {"box_factor", last_request_.options.box_factor},
                         {"rule", rule_names[rule_]},
                         {"method", method_names()[method_]},
                         {"camera", render::to_json(camera_)},
                         {"size", std::to_string(width) + "x" + std::to_string(height)},
                         {"output", std::filesystem::absolute(path).string()}};
  if (!last_request_.example.empty()) shot["example"] = last_request_.example;
  if (!last_request_.path.empty())
    shot["input"] = std::filesystem::absolute(last_request_.path).string();
  std::vector<std::string> visible;
  for (const auto& layer : renderer_->scene().layers) {
    if (std::find(hidden_layers_.begin(), hidden_layers_.end(), layer.id) == hidden_layers_.end()) {
      visible.push_back(layer.id);
    }
  }
  shot["layers"] = visible;
  const auto shots = std::filesystem::temp_directory_path() /
                     ("sculpt-view-" + std::to_string(getpid()) + ".json");
  std::ofstream(shots) << nlohmann::json{{"shots", {shot}}}.dump();
  const std::string command = sculpt.string() + " render --shots " + shots.string() + " 2>&1";
  const int status = std::system(command.c_str());
  std::filesystem::remove(shots);
  message_ = status == 0 ? "saved " + path : "the picture could not be made (sculpt render failed)";
  return status == 0;
}

bool Viewer::save_camera(const std::string& path) {
  try {
    io::Atomic_file file(path, false);
    file.stream() << render::to_json(camera_).dump(2) << '\n';
    file.commit();
    message_ = "camera saved to " + path;
    return true;
  } catch (const std::exception& e) {
    message_ = std::string("error: ") + e.what();
    return false;
  }
}

bool Viewer::load_camera(const std::string& path) {
  try {
    std::ifstream in(path);
    if (!in) throw std::runtime_error("cannot open " + path);
    const auto camera = render::camera_from_json(nlohmann::json::parse(in));
    if (camera.dimension != camera_.dimension)
      throw std::runtime_error("that camera is for another dimension");
    camera_ = camera;
    camera_fitted_ = true;
    message_ = "camera loaded from " + path;
    return true;
  } catch (const std::exception& e) {
    message_ = std::string("error: ") + e.what();
    return false;
  }
}

// ---------------------------------------------------------------------------------------------
// Panels

void Viewer::draw_menu() {
  if (!ImGui::BeginMainMenuBar()) return;
  if (ImGui::BeginMenu("File")) {
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
    ImGui::Separator();
    if (ImGui::MenuItem("Quit")) quit_ = true;
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
  if (ImGui::BeginMenu("View")) {
    if (ImGui::MenuItem("Fit / reset camera", "R")) reset_camera(), scene_dirty_ = true;
    if (ImGui::MenuItem("Controls", "H", show_help_)) show_help_ = !show_help_;
    ImGui::EndMenu();
  }
  ImGui::EndMainMenuBar();
}

void Viewer::draw_panel(int height) {
  const float top = ImGui::GetFrameHeight();
  ImGui::SetNextWindowPos(ImVec2(0, top), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(panel_width, float(height) - top), ImGuiCond_Always);
  ImGui::Begin("Sculpt", nullptr,
               ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse);
  ImGui::TextWrapped("%s", message_.c_str());
  if (busy()) {
    const auto status = job_.status();
    ImGui::ProgressBar(float(status.fraction), ImVec2(-70, 0), status.stage.c_str());
    ImGui::SameLine();
    if (ImGui::Button("Cancel")) cancel();
  }
  if (ImGui::CollapsingHeader("Reconstruction options")) {
    ImGui::Combo("method", &method_, method_names().data(),
                 static_cast<int>(method_names().size()));
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", describe(method_at(method_)));
    ImGui::Checkbox("bordered surface", &bordered_);
    ImGui::SliderFloat("box factor", &box_factor_, 1.1f, 10.0f, "%.1f");
    ImGui::Combo("surface rule", &rule_, rule_names, 3);
    if (ImGui::Button("Reconstruct again") && !busy() &&
        (!last_request_.path.empty() || !last_request_.example.empty()))
      rerun();
  }
  if (reconstruction_) {
    draw_stepper();
    if (request_.stage == scene::Stage::propagation) draw_propagation_controls();
    draw_pseudo_code();
    draw_layers();
    draw_selection();
    draw_statistics();
  }
  ImGui::End();
}

void Viewer::draw_stepper() {
  ImGui::Separator();
  ImGui::TextUnformatted(scene::stage_title(request_.stage));
  const auto& stages = scene::all_stages();
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

void Viewer::draw_propagation_controls() {
  const long total = event_count();
  int shown = int(request_.step < 0 ? total : request_.step);
  if (ImGui::Button(playing_ ? "Pause" : "Play")) {
    if (!playing_ && shown >= total) set_step(0);
    playing_ = !playing_;
  }
  ImGui::SameLine();
  if (ImGui::Button("<")) set_step(std::max(0, shown - 1));
  ImGui::SameLine();
  if (ImGui::Button(">")) set_step(shown + 1);
  ImGui::SameLine();
  ImGui::SetNextItemWidth(150);
  ImGui::SliderFloat("events/s", &events_per_second_, 1.0f, 2000.0f, "%.0f",
                     ImGuiSliderFlags_Logarithmic);
  if (ImGui::SliderInt("event", &shown, 0, int(total))) set_step(shown);
  if (const Labelling_event* e = latest_event()) {
    ImGui::Text("pole %d <- %s (%s", e->pole, to_string(e->label), to_string(e->reason));
    ImGui::SameLine(0, 0);
    if (e->source >= 0) {
      ImGui::Text(" of pole %d)", e->source);
    } else {
      ImGui::TextUnformatted(")");
    }
  }
}

void Viewer::draw_pseudo_code() {
  if (!ImGui::CollapsingHeader("Algorithm", ImGuiTreeNodeFlags_DefaultOpen)) return;
  const Method method =
      std::visit([](const auto& r) { return r.options.method; }, *reconstruction_);
  const frontend::Pseudo_code& code = frontend::pseudo_code(method);
  const int current = frontend::current_line(code, request_.stage, latest_event());
  const auto& lines = code.lines;
  for (int i = 0; i < static_cast<int>(lines.size()); ++i) {
    if (i == current) {
      ImGui::TextColored(ImVec4(1.0f, 0.8f, 0.2f, 1.0f), "> %s", lines[i]);
    } else {
      ImGui::TextDisabled("  %s", lines[i]);
    }
  }
}

void Viewer::draw_layers() {
  if (!ImGui::CollapsingHeader("Layers", ImGuiTreeNodeFlags_DefaultOpen)) return;
  for (const auto& layer : renderer_->scene().layers) {
    ImGui::ColorButton(("##" + layer.id).c_str(), imgui_color(layer.color),
                       ImGuiColorEditFlags_NoTooltip, ImVec2(12, 12));
    ImGui::SameLine();
    bool visible =
        std::find(hidden_layers_.begin(), hidden_layers_.end(), layer.id) == hidden_layers_.end();
    if (ImGui::Checkbox(layer.label.c_str(), &visible)) {
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
                          to_string(e.reason));
            } else {
              ImGui::Text("  labelled at event %zu: %s", i + 1, to_string(e.reason));
            }
          }
        };
        if (request_.focus_sample >= 0) {
          const int s = request_.focus_sample;
          ImGui::Text("sample %d", s);
          ImGui::TextDisabled("its Voronoi cell, poles, polar balls and inscribed cubes are shown");
          ImGui::TextUnformatted("p+:");
          describe_pole(r.poles.positive_pole[s]);
          ImGui::TextUnformatted("p-:");
          describe_pole(r.poles.negative_pole[s]);
        } else {
          describe_pole(request_.focus_pole);
        }
      },
      *reconstruction_);
  if (ImGui::Button("Clear selection")) pick_sample(-1);
}

void Viewer::draw_statistics() {
  if (!ImGui::CollapsingHeader("Statistics", ImGuiTreeNodeFlags_DefaultOpen)) return;
  const Statistics& s =
      std::visit([](const auto& r) -> const Statistics& { return r.stats; }, *reconstruction_);
  const bool three = s.dimension == 3;
  ImGui::Text("%s", description_.c_str());
  const Verdict v = verdict(s);
  ImGui::PushStyleColor(ImGuiCol_Text,
                        v.manifold ? ImVec4(0.5f, 0.9f, 0.5f, 1) : ImVec4(1, 0.45f, 0.4f, 1));
  ImGui::TextWrapped("method %s: %s", to_string(s.method), v.line.c_str());
  ImGui::PopStyleColor();
  ImGui::Text("n %zu   poles %zu   m %zu", s.samples, s.poles, s.inserted_poles);
  ImGui::Text("%s %zu   unlabelled %zu", s.method == Method::paper ? "conflicts" : "contradicted",
              s.conflicts, s.unlabelled_poles);
  if (inserts_poles(s.method, s.kind)) {
    ImGui::Text("cells %zu -> %zu   solid %zu", s.delaunay_cells, s.sculpted_cells, s.solid_cells);
  } else {
    ImGui::Text("cells %zu, carved %zu, outer kept %zu", s.delaunay_cells, s.carved_cells,
                s.kept_outer_cells);
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

void Viewer::draw_help() {
  ImGui::SetNextWindowPos(ImVec2(panel_width + 20, 40), ImGuiCond_FirstUseEver);
  ImGui::Begin("Controls", &show_help_, ImGuiWindowFlags_AlwaysAutoResize);
  ImGui::TextUnformatted(
      "left / right arrow   previous / next stage\n"
      "space                play / pause the pole separation\n"
      ", and .              one labelling event back / forward\n"
      "left drag            orbit (3D), pan (2D)\n"
      "right or middle drag pan\n"
      "wheel                zoom\n"
      "click                pick a sample or a pole\n"
      "R or F               fit and reset the camera\n"
      "P                    save a picture (File menu: path and size)\n"
      "H                    this help");
  ImGui::End();
}

}  // namespace sculpt::viewer
