// SPDX-License-Identifier: GPL-3.0-or-later
// The viewer's point editor on its own: every edit is undone exactly, a drag is one edit, and
// what the triangulation would refuse (a repeated point, a missing index) is refused here first.
#include "viewer/point_editor.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "file_support.hpp"
#include "frontend/input.hpp"

namespace sculpt {
namespace {

using viewer::Point_editor;

TEST(Point_editor, EveryEditIsUndoneExactlyAndADragIsOneEdit) {
  const std::vector<Point<2>> start = {{0, 0}, {1, 0}, {0, 1}};
  Point_editor editor;
  editor.start(start, "three points");
  EXPECT_TRUE(editor.add({1, 1}));
  EXPECT_TRUE(editor.remove(0));
  editor.begin_drag();
  for (double x = 0.1; x < 1; x += 0.1) EXPECT_TRUE(editor.drag(2, {x, 2}));
  EXPECT_EQ(editor.edits(), 3);
  EXPECT_EQ(editor.points().size(), 3u);
  EXPECT_EQ(editor.nearest({0.95, 2.01}, 0.1), 2);
  EXPECT_EQ(editor.nearest({5, 5}, 0.1), -1);
  EXPECT_TRUE(editor.undo());  // the whole drag
  EXPECT_EQ(editor.points()[2], (Point<2>{1, 1}));
  EXPECT_TRUE(editor.undo());
  EXPECT_TRUE(editor.undo());
  EXPECT_EQ(editor.points(), start);
  EXPECT_FALSE(editor.undo());
  EXPECT_EQ(editor.why(), "nothing to undo");
}

TEST(Point_editor, RefusesWhatTheTriangulationWouldRefuse) {
  Point_editor editor;
  editor.start({{0, 0}, {1, 0}, {0, 1}}, "three points");
  EXPECT_FALSE(editor.add({1, 0}));  // already there
  EXPECT_FALSE(editor.move(0, {0, 1}));
  EXPECT_FALSE(editor.remove(3));
  EXPECT_FALSE(editor.remove(-1));
  EXPECT_FALSE(editor.move(1, {std::nan(""), 0}));
  EXPECT_EQ(editor.edits(), 0);
  // A stroke's samples: the repeated ones are dropped, the rest added as one edit.
  EXPECT_TRUE(editor.add_all({{0, 0}, {2, 2}, {2, 2}, {3, 3}}));
  EXPECT_EQ(editor.points().size(), 5u);
  EXPECT_EQ(editor.edits(), 1);
}

TEST(Point_editor, SavedPointsReadBackTheSame) {
  const std::vector<Point<2>> points = {{0.1, 1e-17}, {1.0 / 3, -2.5}, {12345.678, 0.2}};
  const std::string path = testing::output_path("editor-points.xy");
  viewer::save_points(path, points);
  const auto input = frontend::load_input(path, "", 0);
  ASSERT_EQ(input.dimension(), 2);
  EXPECT_EQ(std::get<0>(input.points), points);  // full precision
}

}  // namespace
}  // namespace sculpt
