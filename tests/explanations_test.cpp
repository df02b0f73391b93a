// SPDX-License-Identifier: GPL-3.0-or-later
// The Explanation panel: every stage of every method, in each dimension it works in and for
// either kind of surface, has its own paragraph that names what it draws.
#include "frontend/explanations.hpp"

#include <gtest/gtest.h>

#include <set>
#include <string>

#include "frontend/pseudo_code.hpp"
#include "shapes/shapes.hpp"
#include "test_support.hpp"

namespace sculpt {
namespace {

TEST(Explanations, EveryStageOfEveryMethodHasItsOwnParagraph) {
  for (int dimension : {2, 3}) {
    for (Method method : testing::methods_in(dimension)) {
      const std::string name = to_string(method);
      for (Surface_kind kind : {Surface_kind::closed, Surface_kind::bordered}) {
        std::set<std::string> seen;
        for (scene::Stage stage : scene::stages_of(method, dimension)) {
          SCOPED_TRACE(std::string(name) + " " + std::to_string(dimension) + "D " +
                       to_string(kind) + " " + scene::stage_id(stage));
          const std::string text = frontend::explanation(method, kind, dimension, stage);
          EXPECT_GT(text.size(), 120u) << text;  // what, why, what to look for
          EXPECT_LT(text.size(), 700u) << text;  // a paragraph, not a page
          EXPECT_TRUE(seen.insert(text).second) << "the same paragraph as another stage";
          EXPECT_EQ(text.find("  "), std::string::npos) << text;
          // Curves speak of curves and triangles, surfaces of surfaces and tetrahedra.
          if (dimension == 2) {
            EXPECT_EQ(text.find("tetrahedr"), std::string::npos) << text;
          }
        }
      }
    }
  }
}

TEST(Explanations, EachMethodSaysWhatItsOwnSolidAndLabellingAre) {
  using scene::Stage;
  const auto explain = [](Method method, Stage stage) {
    return frontend::explanation(method, Surface_kind::closed, 3, stage);
  };
  EXPECT_NE(explain(Method::alpha_shape, Stage::solid).find("alpha"), std::string::npos);
  EXPECT_NE(explain(Method::tight_cocone, Stage::solid).find("peel"), std::string::npos);
  EXPECT_NE(explain(Method::boissonnat, Stage::solid).find("Boissonnat"), std::string::npos);
  EXPECT_NE(explain(Method::paper, Stage::propagation).find("inscribed"), std::string::npos);
  EXPECT_NE(explain(Method::robust, Stage::propagation).find("confidence"), std::string::npos);
  EXPECT_NE(explain(Method::power_crust, Stage::surface).find("not interpolate"),
            std::string::npos);
  EXPECT_NE(frontend::explanation(Method::paper, Surface_kind::bordered, 3, Stage::seeds)
                .find("only one"),
            std::string::npos);
}

// The pseudo-code follows the kind of surface: bordered, one seed and every labelled pole
// inserted (UP), for the paper method and for the robust one on surfaces; each stage still has
// its line.
TEST(Explanations, TheBorderedPseudoCodeSeedsOnceAndInsertsEveryLabelledPole) {
  for (Method method : {Method::paper, Method::robust}) {
    SCOPED_TRACE(to_string(method));
    const auto& code = frontend::pseudo_code(method, Surface_kind::bordered, 3);
    const auto has = [&](const std::string& text) {
      for (const char* line : code.lines) {
        if (std::string(line).find(text) != std::string::npos) return true;
      }
      return false;
    };
    EXPECT_TRUE(has("one convex pole"));
    EXPECT_TRUE(has("insert(DT, UP)"));
    EXPECT_FALSE(has("OUP"));
    for (scene::Stage stage : scene::stages_of(method, 3)) {
      if (stage == scene::Stage::propagation) continue;
      ASSERT_TRUE(code.lines_of_stage.count(stage)) << scene::stage_id(stage);
      for (int line : code.lines_of_stage.at(stage))
        EXPECT_LT(line, static_cast<int>(code.lines.size()));
    }
    EXPECT_NE(&code, &frontend::pseudo_code(method, Surface_kind::closed, 3));
  }
  // Bordered curves of the robust method join neighbours instead.
  EXPECT_NE(
      std::string(frontend::pseudo_code(Method::robust, Surface_kind::bordered, 2).lines.back())
          .find("2 per sample"),
      std::string::npos);
}

// Every line of every method's pseudo-code is lit at some moment: at a stage, or in the replay
// before the first event, at an event of some reason, or at a conflict; a loop's header is lit
// with its body, a statement with its continuation lines.
TEST(Explanations, EveryLineOfEveryPseudoCodeIsReachableByHighlighting) {
  for (int dimension : {2, 3}) {
    for (Method method : testing::methods_in(dimension)) {
      const std::string name = to_string(method);
      for (Surface_kind kind : {Surface_kind::closed, Surface_kind::bordered}) {
        SCOPED_TRACE(std::string(name) + " " + std::to_string(dimension) + "D " + to_string(kind));
        const auto& code = frontend::pseudo_code(method, kind, dimension);
        const int size = static_cast<int>(code.lines.size());
        std::set<int> lit;
        const auto light = [&](const std::vector<int>& lines) {
          for (int line : lines) {
            ASSERT_GE(line, 0);
            ASSERT_LT(line, size);
            lit.insert(line);
          }
        };
        for (scene::Stage stage : scene::stages_of(method, dimension)) {
          if (stage != scene::Stage::propagation) {
            light(frontend::highlighted_lines(code, stage, nullptr));
            continue;
          }
          light(frontend::highlighted_lines(code, stage, nullptr));  // before any event
          for (const auto& [reason, lines] : code.lines_of_reason) {
            Labelling_event event;
            event.reason = reason;
            light(frontend::highlighted_lines(code, stage, &event));
          }
          light(frontend::highlighted_lines(code, stage, nullptr, /*conflict_now=*/true));
          Labelling_event pairing;
          pairing.reason = Label_reason::pairing;
          light(frontend::highlighted_lines(code, stage, &pairing, false, /*seed_partner=*/true));
        }
        for (int line = 0; line < size; ++line)
          EXPECT_TRUE(lit.count(line)) << "never lit: \"" << code.lines[line] << '"';
      }
    }
  }
}

// A statement is lit with the loops around it and the lines that continue it: the paper's
// pairing lights the while loop, the pop and the pairing's for; Boissonnat's removal lights its
// loop, the continuation of the cell's choice and the comments under it.
TEST(Explanations, AStatementIsLitWithItsLoopsAndItsContinuationLines) {
  const auto& paper = frontend::pseudo_code(Method::paper, Surface_kind::closed, 3);
  Labelling_event pairing;
  pairing.reason = Label_reason::pairing;
  EXPECT_EQ(frontend::highlighted_lines(paper, scene::Stage::propagation, &pairing),
            (std::vector<int>{7, 8, 11, 12}));
  EXPECT_EQ(frontend::current_line(paper, scene::Stage::propagation, &pairing), 12);
  // The pairing of a convex seed is the paper's ISP line; in a real replay, right after the
  // convex seeds.
  EXPECT_EQ(frontend::current_line(paper, scene::Stage::propagation, &pairing, false, true), 5);
  Options options;
  options.method = Method::paper;
  const auto star = reconstruct(shapes::star(200).samples, options);
  bool isp_seen = false;
  for (const auto& event : star.propagation.events)
    isp_seen = isp_seen || frontend::labels_seed_partner(star, &event);
  EXPECT_TRUE(isp_seen);
  const auto& boissonnat = frontend::pseudo_code(Method::boissonnat, Surface_kind::closed, 3);
  EXPECT_EQ(frontend::highlighted_lines(boissonnat, scene::Stage::solid, nullptr),
            (std::vector<int>{2, 3, 4, 5, 6, 7}));
  // A line with a colon inside is not a loop: the robust contradiction lights its own loop.
  const auto& robust = frontend::pseudo_code(Method::robust, Surface_kind::closed, 3);
  EXPECT_EQ(frontend::highlighted_lines(robust, scene::Stage::propagation, nullptr, true),
            (std::vector<int>{5, 11}));
}

// The replay reaches the conflict line: on the spiral (bordered, where poles of neighbouring
// arms are offered both labels) the line is highlighted at the steps where a conflict follows
// the event on screen, and the scene shows conflicts only once they have happened.
TEST(Explanations, TheReplayReachesTheConflictLineWhenAConflictHappens) {
  for (Method method : {Method::paper, Method::robust}) {
    Options options;
    options.method = method;
    options.kind = Surface_kind::bordered;
    const auto r = reconstruct(shapes::spiral().samples, options);
    ASSERT_FALSE(r.propagation.conflicts.empty()) << to_string(method);
    const auto& code = frontend::pseudo_code(method, options.kind, 2);
    ASSERT_GE(code.conflict_line, 0);
    std::set<int> lines;
    std::size_t previously_shown = 0;
    const long events = long(r.propagation.events.size());
    for (long step = 0; step <= events; ++step) {
      const Labelling_event* latest = step > 0 ? &r.propagation.events[step - 1] : nullptr;
      lines.insert(frontend::current_line(code, scene::Stage::propagation, latest,
                                          frontend::conflict_after(r.propagation, step)));
      scene::Request request;
      request.stage = scene::Stage::propagation;
      request.step = step;
      const auto scene = scene::build_scene(r, request);
      std::size_t shown = 0;
      for (const auto& layer : scene.layers)
        if (layer.id == "contradicted-poles") shown = layer.positions.size();
      EXPECT_GE(shown, previously_shown) << "step " << step;
      previously_shown = shown;
    }
    EXPECT_TRUE(lines.count(code.conflict_line)) << to_string(method);
    EXPECT_GT(previously_shown, 0u);
    EXPECT_EQ(
        std::string(code.lines[code.conflict_line]).find("conflict") != std::string::npos ||
            std::string(code.lines[code.conflict_line]).find("contradicted") != std::string::npos,
        true);
  }
}

}  // namespace
}  // namespace sculpt
