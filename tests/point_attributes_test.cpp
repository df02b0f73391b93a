// SPDX-License-Identifier: GPL-3.0-or-later
// A scan's normals and colours: read from each format that has them, dropped with a warning when
// some points lack them, kept by --merge-duplicates, and written back onto the surface's
// vertices (PLY and OBJ) exactly, through the writers and the command line.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <cstring>

#include "file_support.hpp"
#include "io/point_reader.hpp"
#include "io/result_files.hpp"
#include "sculpt_process.hpp"

namespace sculpt {
namespace {

using testing::write_file;

template <class T>
void append(std::string& bytes, T value) {
  char raw[sizeof(T)];
  std::memcpy(raw, &value, sizeof(T));
  bytes.append(raw, sizeof(T));
}

// A small binary PLY: float coordinates and normals, then colours of `color_type` (a PLY type
// name: uchar, ushort or float) holding `level(i, channel)`.
std::string binary_ply(int n, const std::string& color_type, double (*level)(int, int)) {
  std::string ply = "ply\nformat binary_little_endian 1.0\nelement vertex " + std::to_string(n) +
                    "\nproperty float x\nproperty float y\nproperty float z\n"
                    "property float nx\nproperty float ny\nproperty float nz\n"
                    "property " +
                    color_type + " red\nproperty " + color_type +
                    " green\n"
                    "property " +
                    color_type + " blue\nproperty uchar alpha\nend_header\n";
  for (int i = 0; i < n; ++i) {
    for (float v : {float(i), float(i * i), 1.0f, 0.0f, 0.6f, 0.8f}) append(ply, v);
    for (int c = 0; c < 3; ++c) {
      const double value = level(i, c);
      if (color_type == "uchar") append(ply, static_cast<std::uint8_t>(value));
      if (color_type == "ushort") append(ply, static_cast<std::uint16_t>(value));
      if (color_type == "float") append(ply, static_cast<float>(value));
    }
    append(ply, std::uint8_t{255});
  }
  return ply;
}

TEST(Point_attributes, PlyNormalsAndColoursOfEveryScalarType) {
  const auto bytes = binary_ply(4, "uchar", [](int i, int c) { return 60.0 * i + c; });
  const io::Point_set set = io::read_points_from_memory(bytes, ".ply");
  ASSERT_EQ(set.attributes.normals.size(), 4u);
  ASSERT_EQ(set.attributes.colors.size(), 4u);
  EXPECT_EQ(set.attributes.normals[2], (std::array<double, 3>{0.0, double(0.6f), double(0.8f)}));
  EXPECT_EQ(set.attributes.colors[3], (std::array<std::uint8_t, 3>{180, 181, 182}));
  EXPECT_TRUE(set.warnings.empty());

  // 16-bit levels and 0-1 fractions come out as the same bytes.
  const auto wide = io::read_points_from_memory(
      binary_ply(2, "ushort", [](int i, int c) { return 257.0 * (100 + i + c); }), ".ply");
  EXPECT_EQ(wide.attributes.colors[1], (std::array<std::uint8_t, 3>{101, 102, 103}));
  const auto fractions = io::read_points_from_memory(
      binary_ply(2, "float", [](int, int c) { return c / 2.0; }), ".ply");
  EXPECT_EQ(fractions.attributes.colors[0], (std::array<std::uint8_t, 3>{0, 128, 255}));
  // Float colours written as levels 0-255 (some writers do) are read as levels.
  const auto float_levels = io::read_points_from_memory(
      binary_ply(2, "float", [](int, int c) { return 100.0 * c; }), ".ply");
  EXPECT_EQ(float_levels.attributes.colors[0], (std::array<std::uint8_t, 3>{0, 100, 200}));

  // An ASCII PLY with normals only, under the names MeshLab also writes.
  const auto text = io::read_points_from_memory(
      "ply\nformat ascii 1.0\nelement vertex 2\nproperty double x\nproperty double y\n"
      "property double z\nproperty double nx\nproperty double ny\nproperty double nz\n"
      "end_header\n0 0 0 0 0 1\n1 0 0 nan 0 1\n",
      ".ply");
  ASSERT_EQ(text.attributes.normals.size(), 2u);
  EXPECT_TRUE(text.attributes.colors.empty());
  EXPECT_EQ(text.attributes.normals[1], (std::array<double, 3>{0, 0, 0}));  // NaN: no direction
  ASSERT_EQ(text.warnings.size(), 1u);
  EXPECT_NE(text.warnings[0].find("not finite"), std::string::npos);
}

TEST(Point_attributes, ObjNormalsOnePerVertexAndVertexColours) {
  const auto set = io::read_points_from_memory(
      "v 0 0 0 1 0 0\nv 1 0 0 0 1 0\nv 0 1 0 0 0 1\nvn 0 0 1\nvn 0 0.5 0.5\nvn 1 0 0\n"
      "f 1//1 2//2 3//3\n",
      ".obj");
  ASSERT_EQ(set.attributes.normals.size(), 3u);
  EXPECT_EQ(set.attributes.normals[1], (std::array<double, 3>{0, 0.5, 0.5}));
  ASSERT_EQ(set.attributes.colors.size(), 3u);
  EXPECT_EQ(set.attributes.colors[2], (std::array<std::uint8_t, 3>{0, 0, 255}));
  EXPECT_EQ(set.triangles.size(), 1u);

  // Normals that are not one per vertex are not the vertices': none kept, and said. Fewer:
  const auto fewer = io::read_points_from_memory("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\n", ".obj");
  EXPECT_TRUE(fewer.attributes.normals.empty());
  ASSERT_EQ(fewer.warnings.size(), 1u);
  EXPECT_NE(fewer.warnings[0].find("1 normals for 3 vertices"), std::string::npos);
  // As many, but the faces' corners name others than their vertices' own:
  const auto corners = io::read_points_from_memory(
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nvn 0 1 0\nvn 1 0 0\nf 1//3 2//1 3//2\n", ".obj");
  EXPECT_TRUE(corners.attributes.normals.empty());
  ASSERT_EQ(corners.warnings.size(), 1u);
  EXPECT_NE(corners.warnings[0].find("per corner"), std::string::npos);
}

TEST(Point_attributes, TextColumnsByTheFormat) {
  const auto pwn = io::read_points_from_memory("0 0 0 0 0 1\n1 0 0 0 1 0\n", ".pwn");
  EXPECT_EQ(pwn.attributes.normals.size(), 2u);
  EXPECT_TRUE(pwn.attributes.colors.empty());
  // .xyz: six columns of fractions are a normal, of whole levels up to 255 a colour.
  const auto normals = io::read_points_from_memory("0 0 0 0 0.6 0.8\n1 0 0 1 0 0\n", ".xyz");
  EXPECT_EQ(normals.attributes.normals.size(), 2u);
  const auto levels = io::read_points_from_memory("0 0 0 255 0 10\n1 0 0 0 1 0\n", ".xyz");
  EXPECT_TRUE(levels.attributes.normals.empty());
  ASSERT_EQ(levels.attributes.colors.size(), 2u);
  EXPECT_EQ(levels.attributes.colors[0], (std::array<std::uint8_t, 3>{255, 0, 10}));
  // Leica's .pts: a count, then x y z intensity r g b.
  const auto pts = io::read_points_from_memory("2\n0 0 0 -1200 10 20 30\n1 0 0 5 1 1 1\n", ".pts");
  ASSERT_EQ(pts.attributes.colors.size(), 2u);
  EXPECT_EQ(pts.attributes.colors[0], (std::array<std::uint8_t, 3>{10, 20, 30}));
  EXPECT_EQ(pts.attributes.colors[1], (std::array<std::uint8_t, 3>{1, 1, 1}));
  // Six columns of a .pts are read as an .xyz's: fractions are a normal.
  const auto pts_normals = io::read_points_from_memory("0 0 0 0 0.6 0.8\n1 0 0 1 0 0\n", ".pts");
  EXPECT_EQ(pts_normals.attributes.normals.size(), 2u);
  EXPECT_TRUE(pts_normals.attributes.colors.empty());
  // Open3D's .xyzrgb: fractions.
  const auto xyzrgb = io::read_points_from_memory("0 0 0 1 0.5 0\n1 0 0 0 0 0\n", ".xyzrgb");
  EXPECT_EQ(xyzrgb.attributes.colors[0], (std::array<std::uint8_t, 3>{255, 128, 0}));
  // Plain text keeps its extra columns to itself.
  EXPECT_TRUE(io::read_points_from_memory("0 0 0 0 0 1\n1 0 0 0 1 0\n", ".txt").attributes.empty());
  // Some lines without: none kept, with a warning.
  const auto partly = io::read_points_from_memory("0 0 0 0 0 1\n1 0 0\n", ".pwn");
  EXPECT_TRUE(partly.attributes.empty());
  ASSERT_EQ(partly.warnings.size(), 1u);
  EXPECT_NE(partly.warnings[0].find("1 of 2 lines"), std::string::npos);
}

TEST(Point_attributes, PointsWithoutThemInPlyAndObjDropThemAll) {
  const auto obj = io::read_points_from_memory("v 0 0 0 1 0 0\nv 1 0 0\nv 0 1 0 0 0 1\n", ".obj");
  EXPECT_TRUE(obj.attributes.colors.empty());
  ASSERT_EQ(obj.warnings.size(), 1u);
  EXPECT_NE(obj.warnings[0].find("2 of 3 points have colours"), std::string::npos);
}

TEST(Point_attributes, MergingDuplicatesKeepsTheFirstOccurrences) {
  io::Point_set set = io::read_points_from_memory(
      "v 0 0 0 1 0 0\nv 1 0 0 0 1 0\nv 0 0 0 0 0 1\nv 0 1 0 1 1 1\n", ".obj");
  ASSERT_EQ(io::merge_duplicates(set), 1u);
  ASSERT_EQ(set.attributes.colors.size(), 3u);
  EXPECT_EQ(set.attributes.colors[0], (std::array<std::uint8_t, 3>{255, 0, 0}));
  EXPECT_EQ(set.attributes.colors[1], (std::array<std::uint8_t, 3>{0, 255, 0}));
  EXPECT_EQ(set.attributes.colors[2], (std::array<std::uint8_t, 3>{255, 255, 255}));
}

// A coloured sphere with normals, reconstructed, written and read back: the same points,
// normals and colours on the same vertices, and the surface's triangles.
TEST(Point_attributes, ARoundTripThroughEveryFormatThatCarriesThem) {
  const int n = 400;
  std::string text;
  std::vector<Point<3>> points;
  Point_attributes given;
  for (int i = 0; i < n; ++i) {
    const double z = 1 - (2 * i + 1.0) / n, r = std::sqrt(1 - z * z), a = 2.399963229728653 * i;
    points.push_back({r * std::cos(a), r * std::sin(a), z});
    given.normals.push_back(points.back());
    given.colors.push_back({std::uint8_t(i % 256), std::uint8_t(255 - i % 256), std::uint8_t(7)});
  }
  const Reconstruction<3> result = reconstruct(points, Options{});
  ASSERT_FALSE(result.surface.empty());
  for (const char* name : {"round.ply", "round.obj"}) {
    for (bool ascii : {false, true}) {
      if (ascii && std::string(name) == "round.obj") continue;
      SCOPED_TRACE(std::string(name) + (ascii ? " ascii" : ""));
      const std::string path = testing::output_path(name);
      io::write_result(result, path, "", ascii, given);
      const io::Point_set back = io::read_points(path);
      EXPECT_EQ(back.points, points);
      EXPECT_EQ(back.attributes.normals, given.normals);
      EXPECT_EQ(back.attributes.colors, given.colors);
      EXPECT_EQ(back.triangles, result.surface);
    }
  }
  // A format without a place for them writes the surface alone; a list of the wrong length is
  // refused before anything is written.
  const std::string stl = testing::output_path("round.stl");
  io::write_result(result, stl, "", false, given);
  EXPECT_TRUE(io::read_points(stl).attributes.empty());
  Point_attributes short_list = given;
  short_list.colors.pop_back();
  const std::string refused = testing::output_path("refused.ply");
  EXPECT_THROW(io::write_result(result, refused, "", false, short_list), io::Error);
  EXPECT_FALSE(std::filesystem::exists(refused));
}

TEST(Point_attributes, TheCommandLineCarriesThemFromTheInputToTheSurface) {
  const auto folder = testing::fresh_folder("attributes_cli");
  // A coloured sphere with one repeated point, read with --merge-duplicates.
  std::string body;
  const int n = 300;
  std::vector<std::array<float, 3>> sphere;
  for (int i = 0; i < n; ++i) {
    const double z = 1 - (2 * i + 1.0) / n, r = std::sqrt(1 - z * z), a = 2.399963229728653 * i;
    sphere.push_back({float(r * std::cos(a)), float(r * std::sin(a)), float(z)});
  }
  sphere.push_back(sphere[5]);
  std::string scan = "ply\nformat binary_little_endian 1.0\nelement vertex " +
                     std::to_string(sphere.size()) +
                     "\nproperty float x\nproperty float y\nproperty float z\nproperty float nx\n"
                     "property float ny\nproperty float nz\nproperty uchar red\nproperty uchar "
                     "green\nproperty uchar blue\nend_header\n";
  for (std::size_t i = 0; i < sphere.size(); ++i) {
    for (float v : sphere[i]) append(scan, v);
    for (float v : sphere[i]) append(scan, v);
    for (int c = 0; c < 3; ++c) append(scan, std::uint8_t((i * 7 + c * 50) % 256));
  }
  std::ofstream(folder / "scan.ply", std::ios::binary) << scan;
  const auto run = testing::run_sculpt(
      folder, {"reconstruct", "scan.ply", "-o", "part.ply", "--merge-duplicates", "-q"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const io::Point_set back = io::read_points((folder / "part.ply").string());
  ASSERT_EQ(back.points.size(), sphere.size() - 1);
  ASSERT_EQ(back.attributes.colors.size(), back.points.size());
  ASSERT_EQ(back.attributes.normals.size(), back.points.size());
  for (std::size_t i = 0; i < back.points.size(); ++i) {
    EXPECT_EQ(back.attributes.colors[i][1], std::uint8_t((i * 7 + 50) % 256));
    EXPECT_EQ(back.attributes.normals[i][2], double(sphere[i][2]));
  }
}

// The outliers the cleaning removes take their normals and colours with them: each vertex of
// the surface keeps its own sample's.
TEST(Point_attributes, OutliersRemovedTakeTheirsWithThem) {
  const auto folder = testing::fresh_folder("attributes_outliers");
  const int n = 600;
  std::vector<std::array<double, 3>> points;
  for (int i = 0; i < n; ++i) {
    const double z = 1 - (2 * i + 1.0) / n, r = std::sqrt(1 - z * z), a = 2.399963229728653 * i;
    points.push_back({r * std::cos(a), r * std::sin(a), z});
  }
  const std::vector<int> strays = {100, 101, 350};  // far outside, among the samples
  for (int at : strays) {
    const auto p = points[std::size_t(at)];
    const double out = 1.6 + 0.001 * at;
    points.insert(points.begin() + at, {out * p[0], out * p[1], out * p[2]});
  }
  std::string text;  // x y z r g b, a colour of its own per point
  for (std::size_t i = 0; i < points.size(); ++i) {
    text += fmt::format("{:.17g} {:.17g} {:.17g} {} {} {}\n", points[i][0], points[i][1],
                        points[i][2], i % 256, (i / 256) % 256, 7);
  }
  std::ofstream(folder / "scan.xyzrgb") << text;
  const auto run = testing::run_sculpt(
      folder, {"reconstruct", "scan.xyzrgb", "-o", "part.ply", "--clean", "outliers"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const io::Point_set back = io::read_points((folder / "part.ply").string());
  ASSERT_EQ(back.points.size(), std::size_t(n));
  ASSERT_EQ(back.attributes.colors.size(), back.points.size());
  std::size_t given = 0;
  for (std::size_t i = 0; i < back.points.size(); ++i, ++given) {
    while (std::find(strays.begin(), strays.end(), int(given)) != strays.end()) ++given;
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(back.points[i][k], points[given][k], 1e-6);
    EXPECT_EQ(back.attributes.colors[i][0], std::uint8_t(given % 256));
    EXPECT_EQ(back.attributes.colors[i][1], std::uint8_t((given / 256) % 256));
  }
}

}  // namespace
}  // namespace sculpt
