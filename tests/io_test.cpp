// Reading points from every input format, and writing every output format and reading it back.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <regex>

#include "file_support.hpp"
#include "io/output_set.hpp"
#include "io/point_reader.hpp"
#include "io/writers.hpp"
#include "shapes/shapes.hpp"

namespace sculpt {
namespace {

using testing::output_path;
using testing::read_file;
using testing::write_file;

TEST(Point_reader, TextWithPrefixesCommentsAndExtraColumns) {
  const auto path = write_file("prefixed.pts",
                               "# a scan\n"
                               "p 1 2 3 0.5 0.5\n"
                               "\n"
                               "p 4, 5, 6  # trailing comment\n"
                               "p 7 8 9\n");
  const auto set = io::read_points(path);
  EXPECT_EQ(set.dimension, 3);
  ASSERT_EQ(set.points.size(), 3u);
  EXPECT_EQ(set.points[1], (Point<3>{4, 5, 6}));
}

TEST(Point_reader, OnlyPointRecordsArePoints) {
  // Hoppe's scans carry scanner records (d, s, g) among the `p` points; OBJ-like files `vn`.
  const auto set = io::read_points(write_file("records.pts",
                                              "# scan\nd 0 0 0\ns 0 0 0\ng 1 0 0\n"
                                              "p 1 2 3\nvn 0 0 1\nv 4 5 6\np 7 8 9\n"));
  ASSERT_EQ(set.points.size(), 3u);
  EXPECT_EQ(set.points[0], (Point<3>{1, 2, 3}));
  EXPECT_EQ(set.points[1], (Point<3>{4, 5, 6}));
}

TEST(Point_reader, MergeDuplicatesKeepsFirstOccurrences) {
  auto set =
      io::read_points(write_file("repeated.xyz", "0 0 0\n1 0 0\n0 0 0\n0 1 0\n1 0 0\n0 0 1\n"));
  EXPECT_EQ(io::merge_duplicates(set), 2u);
  EXPECT_EQ(set.points, (std::vector<Point<3>>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}));
}

TEST(Point_reader, CountHeaderAndTwoColumns) {
  const auto set = io::read_points(write_file("counted.xy", "3\n0 0\n1 0\n0 1\n"));
  EXPECT_EQ(set.dimension, 2);
  ASSERT_EQ(set.points.size(), 3u);
  EXPECT_EQ(set.points[2], (Point<3>{0, 1, 0}));
}

TEST(Point_reader, PlyPointCloudsAsciiAndBinary) {
  // Scans often come as PLY vertices without faces, with extra properties.
  const std::string header =
      "element vertex 2\nproperty double x\nproperty double y\nproperty double z\n"
      "property uchar intensity\nend_header\n";
  const auto ascii = io::read_points(
      write_file("cloud-ascii.ply", "ply\nformat ascii 1.0\n" + header + "1 2 3 9\n4 5 6 9\n"));
  ASSERT_EQ(ascii.points.size(), 2u);
  EXPECT_EQ(ascii.points[1], (Point<3>{4, 5, 6}));

  std::string binary = "ply\nformat binary_little_endian 1.0\n" + header;
  for (double x : {1.5, 2.5, 3.5, 4.5, 5.5, 6.5}) {
    binary.append(reinterpret_cast<const char*>(&x), sizeof x);
    if (x == 3.5 || x == 6.5) binary.push_back('\x09');
  }
  const auto set = io::read_points(write_file("cloud-binary.ply", binary));
  ASSERT_EQ(set.points.size(), 2u);
  EXPECT_EQ(set.points[1], (Point<3>{4.5, 5.5, 6.5}));
}

TEST(Point_reader, PlanarPointsDropTheirConstantCoordinate) {
  const auto set = io::read_points(write_file("plane.pts", "p 0 1 2\np 0 3 4\np 0 5 7\n"));
  std::string dropped;
  const auto points = io::planar_points(set, &dropped);
  EXPECT_EQ(dropped, "x");
  EXPECT_EQ(points[2], (Point<2>{5, 7}));
  EXPECT_THROW(io::planar_points(io::read_points(write_file("space.xyz", "0 0 0\n1 2 3\n"))),
               io::Error);
}

TEST(Point_reader, RefusesBadFilesWithOneLine) {
  const std::pair<std::string, std::string> bad[] = {
      {"words.xyz", "1 2 3\n4 five 6\n"},
      {"short.xyz", "1 2 3\n4 5\n"},
      {"truncated.xyz", "4\n1 2 3\n4 5 6\n"},
      {"nan.xyz", "1 2 3\nnan 5 6\n"},
      {"inf.xy", "1 2\n3 inf\n"},
      {"garbage.xyz", std::string("\x7f\x45\x4c\x46\x02\x01\x00\x00 binary", 16)},
      {"empty.xyz", "# nothing\n"},
      {"points.unknown", "1 2 3\n"},
      {"truncated.off", "OFF\n4 1 0\n0 0 0\n1 0 0\n"},
      {"bad-face.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n"},
      {"truncated.ply",
       "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
       "property float y\nproperty float z\nend_header\n0 0 0\n1 0 0\n"},
  };
  for (const auto& [name, content] : bad) {
    try {
      io::read_points(write_file(name, content));
      ADD_FAILURE() << name << " was accepted";
    } catch (const io::Error& e) {
      const std::string message = e.what();
      EXPECT_EQ(message.find('\n'), std::string::npos) << message;
      EXPECT_NE(message.find(name), std::string::npos) << "the message names the file: " << message;
    }
  }
  EXPECT_THROW(io::read_points(output_path("missing.xyz")), io::Error);
}

std::vector<Point<3>> sorted(std::vector<Point<3>> points) {
  std::sort(points.begin(), points.end());
  return points;
}

TEST(Surface_writer, EveryFormatRoundTripsItsVertices) {
  const auto points = shapes::sphere(200);
  const auto result = reconstruct(points);
  for (const std::string name : {"s.stl", "s.ply", "s.off", "s.obj"}) {
    for (bool ascii : {false, true}) {
      const auto path = output_path((ascii ? "ascii-" : "binary-") + name);
      io::write_surface(path, points, result.surface, ascii);
      const auto back = io::read_points(path).points;
      ASSERT_EQ(back.size(), points.size()) << path;
      if (io::extension_of(path) == ".stl") {
        // STL stores floats and no vertex list: compare as sets, to float precision.
        const auto a = sorted(points), b = sorted(back);
        for (std::size_t i = 0; i < a.size(); ++i) {
          for (int k = 0; k < 3; ++k) EXPECT_NEAR(a[i][k], b[i][k], 1e-6) << path;
        }
      } else {
        EXPECT_EQ(back, points) << path << ": vertices are the samples, in order, exactly";
      }
    }
  }
  // The binary STL holds exactly one record per triangle.
  io::write_surface(output_path("count.stl"), points, result.surface, false);
  EXPECT_EQ(read_file(SCULPT_TEST_OUTPUT "/count.stl").size(), 84 + 50 * result.surface.size());
  EXPECT_NE(read_file(SCULPT_TEST_OUTPUT "/ascii-s.stl").find("facet normal"), std::string::npos);
}

TEST(Curve_writer, ObjPolylinesAndSvg) {
  const auto truth = shapes::nested_circles(40, 20);
  const auto result = reconstruct(truth.samples);
  const auto obj = output_path("curve.obj");
  io::write_curve(obj, truth.samples, result.surface);
  const std::string text = read_file(obj);
  // Two closed polylines, each repeating its first sample at the end.
  const std::regex line_element("\nl( \\d+)+");
  EXPECT_EQ(std::distance(std::sregex_iterator(text.begin(), text.end(), line_element),
                          std::sregex_iterator()),
            2);
  const std::regex vertex("(^|\n)v ");
  EXPECT_EQ(
      std::distance(std::sregex_iterator(text.begin(), text.end(), vertex), std::sregex_iterator()),
      60);
  const auto svg = output_path("curve.svg");
  io::write_curve(svg, truth.samples, result.surface);
  const std::string picture = read_file(svg);
  EXPECT_EQ(picture.rfind("<svg", 0), 0u);
  EXPECT_NE(picture.find("</svg>"), std::string::npos);
  EXPECT_EQ(std::count(picture.begin(), picture.end(), 'M'), 2);
}

TEST(Solid_writer, MeditVtuAndTetgen) {
  const auto points = shapes::bumpy_sphere(500);
  const auto result = reconstruct(points);
  const std::size_t cells = result.solid.size();
  ASSERT_GT(cells, 0u);

  io::write_solid<3>(output_path("solid.mesh"), points, result.solid);
  const auto medit = read_file(SCULPT_TEST_OUTPUT "/solid.mesh");
  EXPECT_NE(medit.find("Tetrahedra\n" + std::to_string(cells) + "\n"), std::string::npos);
  EXPECT_NE(medit.find("Vertices\n" + std::to_string(points.size()) + "\n"), std::string::npos);

  io::write_solid<3>(output_path("solid.vtu"), points, result.solid);
  const auto vtu = read_file(SCULPT_TEST_OUTPUT "/solid.vtu");
  EXPECT_NE(vtu.find("NumberOfCells=\"" + std::to_string(cells) + "\""), std::string::npos);

  io::write_solid<3>(output_path("solid.ele"), points, result.solid);
  std::istringstream node(read_file(SCULPT_TEST_OUTPUT "/solid.node"));
  std::istringstream ele(read_file(SCULPT_TEST_OUTPUT "/solid.ele"));
  std::size_t node_count = 0, ele_count = 0, per_cell = 0;
  node >> node_count;
  ele >> ele_count >> per_cell;
  EXPECT_EQ(node_count, points.size());
  EXPECT_EQ(ele_count, cells);
  EXPECT_EQ(per_cell, 4u);

  const auto curve = shapes::star(60);
  const auto flat = reconstruct(curve.samples);
  io::write_solid<2>(output_path("flat.mesh"), curve.samples, flat.solid);
  EXPECT_NE(read_file(SCULPT_TEST_OUTPUT "/flat.mesh").find("Dimension 2\n"), std::string::npos);
}

TEST(Writers, AFailedWriteLeavesNoFile) {
  // A folder of its own: other tests write (and briefly hold .partial files) in parallel.
  const std::filesystem::path folder = std::string(SCULPT_TEST_OUTPUT) + "/atomic-writes";
  std::filesystem::remove_all(folder);
  std::filesystem::create_directories(folder);
  const auto points = shapes::sphere(100);
  const auto result = reconstruct(points);
  EXPECT_THROW(io::write_surface("/nonexistent-folder/out.stl", points, result.surface, false),
               io::Error);
  EXPECT_THROW(io::write_surface((folder / "out.xyz").string(), points, result.surface, false),
               io::Error);
  EXPECT_THROW(io::write_solid<3>((folder / "out.txt").string(), points, result.solid), io::Error);
  io::write_surface((folder / "fine.off").string(), points, result.surface, false);
  std::vector<std::string> left;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    left.push_back(entry.path().filename().string());
  }
  EXPECT_EQ(left, std::vector<std::string>{"fine.off"})
      << "only the file written completely remains";
}

// A run's outputs appear together or not at all.
std::vector<std::string> files_in(const std::filesystem::path& folder) {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    names.push_back(entry.path().filename().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

TEST(Output_set, CommitsAllOrLeavesNothing) {
  const auto folder = std::filesystem::path(SCULPT_TEST_OUTPUT) / "output-set";
  std::filesystem::remove_all(folder);
  std::filesystem::create_directories(folder);
  {
    io::Output_set outputs;
    std::ofstream(outputs.stage((folder / "a.stl").string())) << "a";
    const auto node = outputs.stage((folder / "b.node").string());
    std::ofstream(node) << "n";
    std::ofstream(node.substr(0, node.size() - 5) + ".ele") << "e";  // its companion
    EXPECT_EQ(files_in(folder).size(), 3u);
    for (const auto& name : files_in(folder))
      EXPECT_EQ(name[0], '.') << "staged under a temporary name";
    // Leaving without commit (as an error would) removes everything staged.
  }
  EXPECT_TRUE(files_in(folder).empty());
  {
    io::Output_set outputs;
    std::ofstream(outputs.stage((folder / "a.stl").string())) << "a";
    const auto node = outputs.stage((folder / "b.node").string());
    std::ofstream(node) << "n";
    std::ofstream(node.substr(0, node.size() - 5) + ".ele") << "e";
    outputs.commit();
  }
  EXPECT_EQ(files_in(folder), (std::vector<std::string>{"a.stl", "b.ele", "b.node"}));
}

}  // namespace
}  // namespace sculpt
