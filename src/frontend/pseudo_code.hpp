// SPDX-License-Identifier: GPL-3.0-or-later
// The sculpting methods' pseudo-code, in the order our implementation runs it (the paper method:
// its Fig. 5; the robust method), each method's by name (the peers' in peer_pseudo_code.hpp),
// and which lines a moment of the algorithm is at: every line is reached by some stage or some
// event of the replay (tests/explanations_test.cpp).
#pragma once

#include <algorithm>
#include <map>
#include <string>
#include <vector>

#include "peer_pseudo_code.hpp"
#include "pseudo_code_listing.hpp"
#include "scene/scene.hpp"

namespace sculpt::frontend {

inline Pseudo_code paper_pseudo_code() {
  using scene::Stage;
  Pseudo_code code;
  code.lines = {
      "DT <- Delaunay(S + BBV)   # BB: 5x box",
      "for each sample s:",
      "    p+(s) <- farthest vertex of Vor(s)",
      "    p-(s) <- farthest v, (v-s).(p+ -s) < 0",
      "OSP <- convex poles: outer",
      "ISP <- poles paired with OSP: inner",
      "queue <- OSP, ISP",
      "while queue not empty:",
      "    p <- pop(queue)",
      "    for q in kd-range(cube in B(p)):",
      "        label q like p",
      "    for q paired with p:",
      "        label q opposite p",
      "    q labelled before: conflict, label kept",
      "OUP <- outer poles that are not convex",
      "DT <- insert(DT, OUP)",
      "solid <- cells whose vertices are all in S",
      "surface <- facets solid | rest",
  };
  code.lines_of_stage = common_stage_lines({2, 3});
  code.lines_of_stage.insert({{Stage::seeds, {4, 5}},
                              {Stage::outer_concave, {14}},
                              {Stage::carving, {15}},
                              {Stage::sculpted_delaunay, {15}},
                              {Stage::solid, {16}},
                              {Stage::surface, {17}}});
  // An event pops p and labels one q: the loop's lines around the labelling are lit too.
  code.lines_of_reason = {{Label_reason::convex_seed, {4}},
                          {Label_reason::inscribed_cube, {10, 8}},
                          {Label_reason::pairing, {12, 8}},
                          {Label_reason::ball_overlap, {10, 8}}};
  code.before_any_event = {6};
  code.seed_partner = {5};
  code.conflict_line = 13;
  return code;
}

// A bordered surface (section 4): one convex seed, every labelled pole inserted (UP), and the
// facets between samples with an outer apex: the paper's lines, or the robust labelling's.
inline Pseudo_code bordered_surface_pseudo_code(Pseudo_code code, int first_seed_line) {
  using scene::Stage;
  code.lines[first_seed_line] = "OSP <- one convex pole: outer   # bordered";
  // The labelling stays (its conflict line too); what follows it changes.
  code.lines.resize(
      std::max(code.lines_of_reason.at(Label_reason::pairing)[0], code.conflict_line) + 1);
  const int up = int(code.lines.size());
  code.lines.insert(code.lines.end(), {
                                          "UP <- labelled poles that are not convex",
                                          "DT <- insert(DT, UP)",
                                          "solid <- cells whose vertices are all in S",
                                          "surface <- facets of S with an outer apex",
                                      });
  code.lines_of_stage[Stage::outer_concave] = {up};
  code.lines_of_stage[Stage::carving] = {up + 1};
  code.lines_of_stage[Stage::sculpted_delaunay] = {up + 1};
  code.lines_of_stage[Stage::solid] = {up + 2};
  code.lines_of_stage[Stage::surface] = {up + 3};
  return code;
}

// The robust method's bordered surfaces (src/methods/robust/bordered_surface.hpp): the paper's
// bordered surface is the candidates, less the triangles spanning an opening; loops that are gaps
// are filled.
inline Pseudo_code robust_bordered_pseudo_code(Pseudo_code code) {
  using scene::Stage;
  const int candidates = code.lines_of_stage.at(Stage::surface).front();
  code.lines[candidates] = "cands <- facets of S with an outer apex";
  code.lines.insert(code.lines.end(),
                    {
                        "# R: circumradius, h: median 6th-neighbour gap",
                        "drop f: R(f) > 3 h, no sample near its centre;",
                        "  next to those, > 2 h",
                        "surface <- prune, walk the rest",
                        "set in, attach left-off samples; join pinches; fill gaps",
                        "drop fans still pinched; fill gaps",
                    });
  code.lines_of_stage[Stage::surface] = {candidates + 2, candidates,     candidates + 1,
                                         candidates + 3, candidates + 4, candidates + 5,
                                         candidates + 6};
  return code;
}

inline Pseudo_code robust_pseudo_code() {
  using scene::Stage;
  Pseudo_code code;
  add_confidence_labelling_lines(code);
  const int carving = int(code.lines.size());
  code.lines.insert(code.lines.end(),
                    {
                        "outer(c) <- power(c) outer or OUP p in ball(c), r_p >= 0.3 r_c",
                        "carve outer c from outside, if manifold",
                        "open cavities, handles; expose samples",
                        "solid <- cells left",
                        "surface <- facets solid | outside",
                    });
  code.lines_of_stage.insert({{Stage::outer_concave, {carving}},
                              {Stage::carving, {carving + 1, carving + 2}},
                              {Stage::sculpted_delaunay, {carving + 1, carving + 2}},
                              {Stage::solid, {carving + 3}},
                              {Stage::surface, {carving + 4}}});
  return code;
}

// The robust method's bordered curves (src/methods/robust/open_curves.hpp): the poles are
// labelled as for a closed curve, for the stages to show, but the curve joins neighbours.
inline Pseudo_code open_curves_pseudo_code() {
  using scene::Stage;
  Pseudo_code code;
  code.lines = {
      "DT <- Delaunay(S + BBV)   # BB: 5x box",      "for each sample s:",
      "    p+(s), p-(s) <- poles of Vor(s)",         "OSP <- convex poles: outer, weight 1",
      "label poles as closed; contradicted",         "for each sample s:   # NN-crust, with ends",
      "    q <- nearest Delaunay neighbour of s",    "    r <- nearest at > 90 degrees from q",
      "    offer sq; sr too if |sr| <= 2.5 spacing", "curve <- offers shortest first, 2 per sample",
  };
  code.lines_of_stage = common_stage_lines({2});
  code.lines_of_stage.insert({{Stage::seeds, {3}},
                              {Stage::outer_concave, {4}},
                              {Stage::carving, {8, 6, 7}},  // the offers, no carving
                              {Stage::sculpted_delaunay, {8, 6, 7}},
                              {Stage::solid, {9}},
                              {Stage::surface, {9}}});
  code.lines_of_reason = {{Label_reason::convex_seed, {4}},
                          {Label_reason::ball_overlap, {4}},
                          {Label_reason::pairing, {4}},
                          {Label_reason::inscribed_cube, {4}}};
  code.before_any_event = {4};
  code.conflict_line = 4;  // the labelling, in one line
  return code;
}

inline const Pseudo_code& pseudo_code(Method method, Surface_kind kind = Surface_kind::closed,
                                      int dimension = 3) {
  static const Pseudo_code paper_bordered = bordered_surface_pseudo_code(paper_pseudo_code(), 4),
                           robust_bordered = robust_bordered_pseudo_code(
                               bordered_surface_pseudo_code(robust_pseudo_code(), 3));
  static const Pseudo_code paper = paper_pseudo_code(), robust = robust_pseudo_code(),
                           open_curves = open_curves_pseudo_code(), crust = crust_pseudo_code(),
                           nn_crust = nn_crust_pseudo_code(),
                           surface_crust = surface_crust_pseudo_code(),
                           cocone = cocone_pseudo_code(),
                           advancing_front = advancing_front_pseudo_code(),
                           alpha_shape = alpha_shape_pseudo_code(),
                           power_crust = power_crust_pseudo_code(),
                           tight_cocone = tight_cocone_pseudo_code(),
                           boissonnat = boissonnat_pseudo_code();
  switch (method) {
    case Method::paper:
      return kind == Surface_kind::bordered ? paper_bordered : paper;
    case Method::crust:
      return dimension == 2 ? crust : surface_crust;
    case Method::cocone:
      return cocone;
    case Method::advancing_front:
      return advancing_front;
    case Method::alpha_shape:
      return alpha_shape;
    case Method::nn_crust:
      return nn_crust;
    case Method::power_crust:
      return power_crust;
    case Method::tight_cocone:
      return tight_cocone;
    case Method::boissonnat:
      return boissonnat;
    case Method::robust:
      break;
  }
  if (joins_neighbours(method, kind, dimension)) return open_curves;
  return inserts_poles(method, kind, dimension) ? robust_bordered : robust;
}

// Whether a conflict was offered right after the first `shown` events (before the next one).
inline bool conflict_after(const Propagation_stage& propagation, long shown) {
  return std::any_of(propagation.conflicts.begin(), propagation.conflicts.end(),
                     [&](const Labelling_event& c) { return c.after_events == shown; });
}

// The statements a moment runs, the main one first. `conflict_now`: a conflict was offered
// right after the latest event on screen; `seed_partner`: that event labelled the partner of a
// convex seed.
inline Line_list current_lines(const Pseudo_code& code, scene::Stage stage,
                               const Labelling_event* latest, bool conflict_now = false,
                               bool seed_partner = false) {
  if (stage != scene::Stage::propagation) return code.lines_of_stage.at(stage);
  if (conflict_now && code.conflict_line >= 0) return {code.conflict_line};
  if (seed_partner && !code.seed_partner.empty()) return code.seed_partner;
  return latest ? code.lines_of_reason.at(latest->reason) : code.before_any_event;
}

// The main line of a moment: the one the viewer marks with an arrow.
inline int current_line(const Pseudo_code& code, scene::Stage stage, const Labelling_event* latest,
                        bool conflict_now = false, bool seed_partner = false) {
  return current_lines(code, stage, latest, conflict_now, seed_partner).front();
}

// Whether an event labels the partner of an outer seed (by pairing from one of the seeds; when
// bordered, the one seed chosen, not any convex pole).
template <int D>
bool labels_seed_partner(const Reconstruction<D>& r, const Labelling_event* event) {
  const auto& seeds = r.seeds.outer_seeds;
  return event && event->reason == Label_reason::pairing && event->source >= 0 &&
         std::find(seeds.begin(), seeds.end(), event->source) != seeds.end();
}

namespace pseudo_code_layout {
inline int indent(const char* line) {
  int spaces = 0;
  while (line[spaces] == ' ') ++spaces;
  return spaces;
}
// The text before a comment, without the spaces that end it.
inline std::string code_part(const char* line) {
  std::string text(line);
  text = text.substr(0, text.find('#'));
  while (!text.empty() && text.back() == ' ') text.pop_back();
  return text;
}
inline bool is_comment(const char* line) {
  return line[indent(line)] == '#';
}
// A loop or branch: its body is the lines indented under it.
inline bool is_header(const char* line) {
  const std::string text = code_part(line);
  return !text.empty() && text.back() == ':';
}
}  // namespace pseudo_code_layout

// The lines lit for a statement starting at `line`: itself, its continuation lines (indented
// deeper, under a line that is not a header) and the comments right under it, and the headers
// of the loops it is in. A teacher sees where in the loop the replay is, not one line alone.
inline std::vector<int> statement_block(const Pseudo_code& code, int line) {
  using namespace pseudo_code_layout;
  const auto& lines = code.lines;
  std::vector<int> block = {line};
  const int own = indent(lines[line]);
  if (!is_header(lines[line])) {
    for (int next = line + 1; next < int(lines.size()); ++next) {
      const bool continues = indent(lines[next]) > own && !is_comment(lines[next]);
      const bool explains = indent(lines[next]) >= own && is_comment(lines[next]);
      if (!continues && !explains) break;
      block.push_back(next);
    }
  }
  int enclosing = own;
  for (int above = line - 1; above >= 0 && enclosing > 0; --above) {
    if (is_header(lines[above]) && indent(lines[above]) < enclosing) {
      block.push_back(above);
      enclosing = indent(lines[above]);
    }
  }
  return block;
}

// Every line lit at a moment, in order.
inline std::vector<int> highlighted_lines(const Pseudo_code& code, scene::Stage stage,
                                          const Labelling_event* latest, bool conflict_now = false,
                                          bool seed_partner = false) {
  std::vector<int> lit;
  for (int line : current_lines(code, stage, latest, conflict_now, seed_partner)) {
    const auto block = statement_block(code, line);
    lit.insert(lit.end(), block.begin(), block.end());
  }
  std::sort(lit.begin(), lit.end());
  lit.erase(std::unique(lit.begin(), lit.end()), lit.end());
  return lit;
}

}  // namespace sculpt::frontend
