// SPDX-License-Identifier: GPL-3.0-or-later
// Each method's pseudo-code, in the order our implementation runs it (the paper method: its
// Fig. 5), and which lines a moment of the algorithm is at: every line is reached by some stage
// or some event of the replay (tests/explanations_test.cpp).
#pragma once

#include <algorithm>
#include <map>
#include <string>
#include <vector>

#include "scene/scene.hpp"

namespace sculpt::frontend {

// The statements a moment runs, by their first lines, the main one first. The viewer also
// lights each statement's continuation lines and the loop headers around it (statement_block).
using Line_list = std::vector<int>;

struct Pseudo_code {
  std::vector<const char*> lines;
  std::map<scene::Stage, Line_list> lines_of_stage;
  std::map<Label_reason, Line_list> lines_of_reason;  // in the propagation: the latest event's
  Line_list before_any_event = {0};                   // in the propagation, before any event
  // In the propagation: a convex seed's partner labelled by the pairing (the paper's ISP);
  // empty where the method has no line of its own for it.
  Line_list seed_partner;
  // In the propagation: the line of a conflict (a label offered against the one a pole has),
  // shown when one follows the event on screen; -1 for a method without conflicts.
  int conflict_line = -1;
};

// The stages before the labelling show the first line or the poles' lines in every method.
inline std::map<scene::Stage, Line_list> common_stage_lines(Line_list poles_lines) {
  using scene::Stage;
  return {{Stage::samples, {0}},
          {Stage::delaunay, {0}},
          {Stage::hull, {0}},
          {Stage::voronoi, {0}},
          {Stage::poles, poles_lines}};
}

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

// The confidence labelling the robust method and the power crust share
// (src/methods/robust/confidence_labelling.hpp), after the poles: its lines and their places.
inline void add_confidence_labelling_lines(Pseudo_code& code) {
  code.lines = {
      "DT <- Delaunay(S + BBV)   # BB: 5x box",     "for each sample s:",
      "    p+(s), p-(s) <- poles of Vor(s)",        "OSP <- convex poles: outer, weight 1",
      "heap <- OSP  # largest |outer-inner| first", "while heap not empty:",
      "    p <- most confident pole; label it",     "    for q whose ball meets B(p) at s:",
      "        ev(q, label p) max= cos(p s q)",     "    for q paired with p (antipodal):",
      "        ev(q, other side) max= -cos(p s q)", "    ev >= .5 against q's label: contradicted",
  };
  code.lines_of_stage = common_stage_lines({2});
  code.lines_of_stage.insert({scene::Stage::seeds, {3}});
  code.lines_of_reason = {{Label_reason::convex_seed, {6, 3}},
                          {Label_reason::ball_overlap, {8, 6}},
                          {Label_reason::pairing, {10, 6}},
                          {Label_reason::inscribed_cube, {8, 6}}};
  code.before_any_event = {4};
  code.conflict_line = 11;
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

// The crust of Amenta, Bern and Kamvysselis (src/methods/crust/crust_method.hpp).
inline Pseudo_code crust_pseudo_code() {
  using scene::Stage;
  Pseudo_code code;
  code.lines = {
      "DT <- Delaunay(S + BBV)   # BB: 5x box",
      "V <- Voronoi vertices: circumcentres of DT",
      "DT' <- Delaunay(S + V)",
      "crust <- edges of DT' between two samples",
  };
  code.lines_of_stage = {{Stage::samples, {0}},
                         {Stage::delaunay, {0}},
                         {Stage::voronoi, {1}},
                         {Stage::crust_delaunay, {2}},
                         {Stage::surface, {3}}};
  return code;
}

// The nearest-neighbour crust of Dey and Kumar (src/methods/crust/nn_crust.hpp).
inline Pseudo_code nn_crust_pseudo_code() {
  using scene::Stage;
  Pseudo_code code;
  code.lines = {
      "DT <- Delaunay(S + BBV)   # BB: 5x box",
      "for each sample s:",
      "    q <- nearest Delaunay neighbour of s",
      "    r <- nearest at > 90 degrees from q",
      "    keep sq, sr",
  };
  code.lines_of_stage = {
      {Stage::samples, {0}}, {Stage::delaunay, {0}}, {Stage::surface, {4, 2, 3}}};
  return code;
}

// The manifold extraction the crust and the co-cone share (extract_manifold in
// src/methods/extraction/manifold_extraction.hpp), appended; returns its first line. Its last
// line makes the surface.
inline int add_manifold_extraction_lines(Pseudo_code& code) {
  const int first = int(code.lines.size());
  code.lines.insert(code.lines.end(), {
                                          "prune t on an edge whose triangles fit in",
                                          "    90 deg (a sharp fold) or",
                                          "    with an edge of its own (only fins if",
                                          "    that leaves a sample bare), repeatedly",
                                          "surface <- outer boundary of T, walked",
                                      });
  return first;
}

// The crust for surfaces (src/methods/crust/surface_crust.hpp).
inline Pseudo_code surface_crust_pseudo_code() {
  using scene::Stage;
  Pseudo_code code;
  // clang-format off
  code.lines = {
      "DT <- Delaunay(S + BBV)   # BB: 5x box",
      "for each sample s:",
      "    p+(s), p-(s) <- poles of Vor(s)",
      "DT' <- Delaunay(S + P)   # P: the poles",
      "T <- triangles of DT' between samples",
      "drop t if its normal leans from p+(s)-s",
      "    > 45 deg at its widest angle, 67.5 else",
  };
  // clang-format on
  const int pruning = add_manifold_extraction_lines(code);
  code.lines_of_stage = common_stage_lines({2});
  code.lines_of_stage.insert({{Stage::crust_delaunay, {3}},
                              {Stage::candidates, {pruning, 4, 5}},
                              {Stage::surface, {int(code.lines.size()) - 1}}});
  return code;
}

// The co-cone of Amenta, Choi, Dey and Leekha (src/methods/cocone/cocone_method.hpp).
inline Pseudo_code cocone_pseudo_code() {
  using scene::Stage;
  Pseudo_code code;
  code.lines = {
      "DT <- Delaunay(S + BBV)   # BB: 5x box",
      "for each sample s:",
      "    v(s) <- p+(s) - s   # pole vector",
      "    cocone(s) <- directions within 22.5 deg",
      "                 of the plane normal to v(s)",
      "U <- undersampled s: Vor(s) not long and",
      "    thin, or normals of neighbours disagree",
      "T <- triangles t of DT between samples whose",
      "    Voronoi edge meets cocone(s), s in t - U",
  };
  const int pruning = add_manifold_extraction_lines(code);
  code.lines_of_stage = common_stage_lines({2, 3});
  code.lines_of_stage.insert(
      {{Stage::candidates, {7, 5}}, {Stage::surface, {int(code.lines.size()) - 1, pruning}}});
  return code;
}

// The tight co-cone of Dey and Goswami (src/methods/cocone/tight_cocone_method.hpp): the
// co-cone's lines, then the peeling.
inline Pseudo_code tight_cocone_pseudo_code() {
  using scene::Stage;
  Pseudo_code code = cocone_pseudo_code();
  code.lines.back() = "S0 <- outer boundary of T, walked";
  const int first = int(code.lines.size());
  code.lines.insert(code.lines.end(), {
                                          "good <- samples with one closed fan in S0",
                                          "out <- cells touching the box; peel from out",
                                          "    across f not in S0 into cell d if a good",
                                          "    s of d is on f, or d's are all bad and f",
                                          "    is not d's smallest facet",
                                          "solid <- cells not peeled",
                                          "surface <- facets solid | out",
                                      });
  // The co-cone's surface is the tight co-cone's first guess S0: shown with the candidates.
  Line_list& candidates = code.lines_of_stage[Stage::candidates];
  const Line_list& s0 = code.lines_of_stage[Stage::surface];
  candidates.insert(candidates.end(), s0.begin(), s0.end());
  code.lines_of_stage[Stage::solid] = {first + 5, first, first + 1};
  code.lines_of_stage[Stage::surface] = {first + 6};
  return code;
}

// CGAL's Advancing Front (src/methods/cgal/advancing_front_method.hpp).
inline Pseudo_code advancing_front_pseudo_code() {
  using scene::Stage;
  Pseudo_code code;
  code.lines = {
      "DT <- Delaunay(S)   # CGAL's own, no box",   "surface <- the triangle of smallest radius",
      "while the front (border) has an edge e:",    "    t <- DT triangle on e, smallest radius,",
      "         that keeps an oriented 2-manifold", "    add t to the surface; the front moves",
  };
  code.lines_of_stage = {{Stage::samples, {0}},
                         {Stage::delaunay, {0}},
                         {Stage::front, {5, 3, 4}},
                         {Stage::surface, {2, 1, 3, 5}}};
  return code;
}

// CGAL's alpha shapes (src/methods/cgal/alpha_shape_method.hpp).
inline Pseudo_code alpha_shape_pseudo_code() {
  using scene::Stage;
  Pseudo_code code;
  code.lines = {
      "DT <- Delaunay(S)",
      "alpha <- the smallest radius such that the",
      "    cells of DT with circumradius < alpha",
      "    make one solid holding every sample",
      "solid <- those cells",
      "surface <- facets between solid and rest",
  };
  code.lines_of_stage = {{Stage::samples, {0}},
                         {Stage::delaunay, {0}},
                         {Stage::alpha, {2, 4}},
                         {Stage::solid, {4, 1}},
                         {Stage::surface, {5}}};
  return code;
}

// The power crust of Amenta, Choi and Kolluri (src/methods/power_crust/power_crust_method.hpp).
inline Pseudo_code power_crust_pseudo_code() {
  using scene::Stage;
  Pseudo_code code;
  add_confidence_labelling_lines(code);
  const int crust = int(code.lines.size());
  code.lines.insert(code.lines.end(), {
                                          "PD <- power diagram of poles, weight r(p)^2",
                                          "crust <- faces of PD between the cells of",
                                          "    an inner and an outer pole",
                                      });
  code.lines_of_stage.insert({Stage::surface, {crust + 1, crust}});
  return code;
}

// Boissonnat's sculpting (src/methods/boissonnat/boissonnat_method.hpp).
inline Pseudo_code boissonnat_pseudo_code() {
  using scene::Stage;
  Pseudo_code code;
  code.lines = {
      "DT <- Delaunay(S + BBV)   # BB: 5x box",
      "solid <- cells of DT whose vertices are in S",
      "while a sample is off the boundary:",
      "    c <- removable cell whose circumsphere",
      "         bulges farthest beyond its boundary",
      "    # removable: 1 facet out, apex off the",
      "    # boundary; 2 out, edge off it (3D)",
      "    solid <- solid - c",
      "surface <- facets solid | rest",
  };
  code.lines_of_stage = {{Stage::samples, {0}},    {Stage::delaunay, {0}}, {Stage::hull, {1}},
                         {Stage::carving, {7, 3}}, {Stage::solid, {7, 3}}, {Stage::surface, {8}}};
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
