// SPDX-License-Identifier: GPL-3.0-or-later
// Reading points from every input format, and writing every output format and reading it back.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstring>
#include <filesystem>
#include <regex>
#include <sstream>

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

// Writes v in a PLY scalar type, in the given byte order.
std::string ply_value(const std::string& type, double v, bool big_endian) {
  std::string bytes;
  auto put = [&](auto value) {
    bytes.assign(sizeof value, '\0');
    std::memcpy(bytes.data(), &value, sizeof value);
    if (big_endian) std::reverse(bytes.begin(), bytes.end());
  };
  if (type == "char" || type == "int8") put(std::int8_t(v));
  if (type == "uchar" || type == "uint8") put(std::uint8_t(v));
  if (type == "short" || type == "int16") put(std::int16_t(v));
  if (type == "ushort" || type == "uint16") put(std::uint16_t(v));
  if (type == "int" || type == "int32") put(std::int32_t(v));
  if (type == "uint" || type == "uint32") put(std::uint32_t(v));
  if (type == "float" || type == "float32") put(float(v));
  if (type == "double" || type == "float64") put(double(v));
  return bytes;
}

TEST(Point_reader, PlyCoordinatesOfEveryScalarTypeAndByteOrder) {
  const std::vector<Point<3>> points = {{1, 2, 3}, {4, 5, 6}, {7, 8, 9}, {10, 11, 120}};
  for (const std::string type :
       {"char", "uchar", "short", "ushort", "int", "uint", "float", "double", "int8", "uint8",
        "int16", "uint16", "int32", "uint32", "float32", "float64"}) {
    for (const std::string format : {"ascii", "binary_little_endian", "binary_big_endian"}) {
      SCOPED_TRACE(type + " " + format);
      std::string file = "ply\nformat " + format +
                         " 1.0\ncomment any type\nelement vertex 4\nproperty uchar red\n"
                         "property " +
                         type + " x\nproperty " + type + " y\nproperty " + type +
                         " z\nelement face 2\nproperty list uchar int vertex_indices\n"
                         "end_header\n";
      const bool big = format == "binary_big_endian";
      for (const auto& p : points) {
        if (format == "ascii") {
          file += fmt::format("255 {} {} {}\n", p[0], p[1], p[2]);
        } else {
          file += ply_value("uchar", 255, big);
          for (double x : p) file += ply_value(type, x, big);
        }
      }
      for (const std::array<int, 4> face : {std::array<int, 4>{3, 0, 1, 2}, {3, 0, 2, 3}}) {
        if (format == "ascii") {
          file += fmt::format("{} {} {} {}\n", face[0], face[1], face[2], face[3]);
        } else {
          file += ply_value("uchar", face[0], big);
          for (int k = 1; k < 4; ++k) file += ply_value("int", face[k], big);
        }
      }
      const auto set = io::read_points_from_memory(file, ".ply");
      EXPECT_EQ(set.points, points);
      EXPECT_EQ(set.triangles, (std::vector<std::array<int, 3>>{{0, 1, 2}, {0, 2, 3}}));
    }
  }
}

TEST(Point_reader, ObjPointCloudsAndFaceCornerForms) {
  const auto cloud = io::read_points_from_memory(
      "# scanner export\nv 1 2 3\nv 4 5 6 0.5 0.5 0.5\nv 7 8 9\n", ".obj");
  EXPECT_EQ(cloud.points, (std::vector<Point<3>>{{1, 2, 3}, {4, 5, 6}, {7, 8, 9}}));
  EXPECT_TRUE(cloud.triangles.empty());
  const auto mesh = io::read_points_from_memory(
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nvt 0 0\nvn 0 0 1\ng part\nusemtl m\n"
      "f 1/1/1 2/1/1 3/1/1\nf 1//1 3//1 4//1\nf -4 -2 -1\nl 1 2\n",
      ".obj");
  EXPECT_EQ(mesh.points.size(), 4u);
  EXPECT_EQ(mesh.triangles, (std::vector<std::array<int, 3>>{{0, 1, 2}, {0, 2, 3}, {0, 2, 3}}));
}

TEST(Point_reader, OffVariants) {
  const std::vector<Point<3>> expected = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const std::pair<std::string, std::string> files[] = {
      {"OFF", "OFF\n4 1 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2\n"},
      {"counts on the keyword line", "OFF 4 1 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2 255 0 0\n"},
      {"COFF",
       "COFF\n4 1 0\n0 0 0 255 0 0 255\n1 0 0 0 255 0 255\n0 1 0 0 0 255 255\n"
       "0 0 1 9 9 9 255\n3 0 1 2\n"},
      {"NOFF",
       "NOFF\n# normals\n4 1 0\n0 0 0 0 0 1\n1 0 0 0 0 1\n0 1 0 0 0 1\n0 0 1 1 0 0\n3 0 1 2\n"},
      {"CNOFF",
       "CNOFF\n4 1 0\n0 0 0 0 0 1 1 1 1\n1 0 0 0 0 1 1 1 1\n0 1 0 0 0 1 1 1 1\n"
       "0 0 1 0 0 1 1 1 1\n3 0 1 2\n"},
      {"STOFF", "STOFF\n4 1 0\n0 0 0 0 0\n1 0 0 1 0\n0 1 0 0 1\n0 0 1 1 1\n3 0 1 2\n"},
      {"4OFF", "4OFF\n4 1 0\n0 0 0 2\n2 0 0 2\n0 4 0 4\n0 0 0.5 0.5\n3 0 1 2\n"},
      {"nOFF", "nOFF\n3\n4 1 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2\n"},
      {"CRLF and BOM",
       "\xEF\xBB\xBFOFF\r\n4 1 0\r\n0 0 0\r\n1 0 0\r\n0 1 0\r\n0 0 1\r\n3 0 1 2\r\n"},
  };
  for (const auto& [name, content] : files) {
    SCOPED_TRACE(name);
    const auto set = io::read_points_from_memory(content, ".off");
    EXPECT_EQ(set.points, expected);
    EXPECT_EQ(set.triangles, (std::vector<std::array<int, 3>>{{0, 1, 2}}));
  }
  const auto planar =
      io::read_points_from_memory("nOFF 2\n3 1 0\n0 0\n1 0\n0 1\n3 0 1 2\n", ".off");
  EXPECT_EQ(planar.dimension, 2);
}

TEST(Point_reader, StlAsciiAndBinaryWhoseHeaderSaysSolid) {
  const auto ascii = io::read_points_from_memory(
      "solid part\n  facet normal 0 0 1\n    outer loop\n      vertex 0 0 0\n      vertex 1 0 0\n"
      "      vertex 0 1 0\n    endloop\n  endfacet\n  FACET NORMAL 0 0 1\n    OUTER LOOP\n"
      "      VERTEX 0 0 0\n      VERTEX 0 1 0\n      VERTEX -0 0 1\n    ENDLOOP\n  ENDFACET\n"
      "endsolid part\n",
      ".stl");
  EXPECT_EQ(ascii.points, (std::vector<Point<3>>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}));
  EXPECT_EQ(ascii.triangles, (std::vector<std::array<int, 3>>{{0, 1, 2}, {0, 2, 3}}));
  // Many exporters start the binary header with "solid": the size decides.
  std::string binary = "solid exported by a CAD program";
  binary.resize(80, ' ');
  const std::uint32_t count = 2;
  binary.append(reinterpret_cast<const char*>(&count), 4);
  for (const std::array<float, 9> t : {std::array<float, 9>{0, 0, 0, 1, 0, 0, 0, 1, 0},
                                       std::array<float, 9>{0, 0, 0, 0, 1, 0, 0, 0, 1}}) {
    binary.append(12, '\0');
    binary.append(reinterpret_cast<const char*>(t.data()), 36);
    binary.append(2, '\0');
  }
  const auto set = io::read_points_from_memory(binary, ".stl");
  EXPECT_EQ(set.points, ascii.points);
  EXPECT_EQ(set.triangles, ascii.triangles);
}

TEST(Point_reader, NumbersInEverySpellingAndSeparator) {
  const auto set = io::read_points_from_memory(
      "x,y,z\n+1.5;2e0;-3\n4\t5\t6 # tab separated\n.5 1E+2 7E-1\n", ".csv");
  EXPECT_EQ(set.points, (std::vector<Point<3>>{{1.5, 2, -3}, {4, 5, 6}, {0.5, 100, 0.7}}));
  EXPECT_THROW(io::read_points_from_memory("0x1p3 0 0\n", ".xyz"), io::Error)
      << "a word strtod would half-read is not a number";
}

// A decimal comma, as European spreadsheets write numbers, is named: read as a separator it
// would make two numbers of one and shift every coordinate after it, silently.
TEST(Point_reader, DecimalCommasAreNamedNotMisread) {
  for (const auto& [text, extension] : std::vector<std::pair<std::string, std::string>>{
           {"x;y;z\n1,5;2,25;3,0\n0,5;1,0;2,0\n", ".csv"},
           {"1,5 2,25 3,0\n0,5 1,0 2,0\n", ".xyz"},
           {"1,5\t2\t3\n", ".txt"}}) {
    SCOPED_TRACE(text);
    try {
      io::read_points_from_memory(text, extension);
      ADD_FAILURE() << "accepted";
    } catch (const io::Error& e) {
      EXPECT_NE(std::string(e.what()).find("decimal comma"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("'1,5'"), std::string::npos) << e.what();
    }
  }
  // Commas that part the fields stay separators.
  const std::vector<Point<3>> expected = {{1, 2, 3}, {4, 5, 6}};
  EXPECT_EQ(io::read_points_from_memory("1,2,3\n4,5,6\n", ".csv").points, expected);
  EXPECT_EQ(io::read_points_from_memory("1, 2, 3\n4, 5, 6\n", ".csv").points, expected);
  EXPECT_EQ(io::read_points_from_memory("1,2,3 # a,b c\n4;5;6\n", ".csv").points, expected);
}

TEST(Point_reader, LineEndsByteOrderMarksAndLastLinesWithoutNewline) {
  const std::vector<Point<3>> tetra = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  for (const std::string end : {"\n", "\r\n", "\r"}) {  // Unix, Windows, old Mac
    SCOPED_TRACE(::testing::PrintToString(end));
    std::string text;
    for (const auto& p : tetra) text += fmt::format("{} {} {}", p[0], p[1], p[2]) + end;
    EXPECT_EQ(io::read_points_from_memory(text, ".xyz").points, tetra);
    EXPECT_EQ(io::read_points_from_memory(text, ".xyz", 3).points, tetra);
    EXPECT_EQ(io::read_points_from_memory("OFF" + end + "4 0 0" + end + text, ".off").points,
              tetra);
  }
  // The last line without its newline, where a count announces exactly what follows.
  EXPECT_EQ(io::read_points_from_memory("OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0", ".off").points.size(),
            3u);
  EXPECT_EQ(io::read_points_from_memory("nOFF 2\n3 0 0\n0 0\n1 0\n0 1\n", ".off").points.size(),
            3u);
  EXPECT_EQ(io::read_points_from_memory("3\n0 0\n1 0\n0 1", ".xy").points.size(), 3u);
  // A byte order mark before any format's first word.
  const std::string bom = "\xEF\xBB\xBF";
  EXPECT_EQ(io::read_points_from_memory(
                bom + "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n"
                      "property float y\nproperty float z\nend_header\n1 2 3\n",
                ".ply")
                .points.size(),
            1u);
  EXPECT_EQ(io::read_points_from_memory(
                bom + "solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\n"
                      "vertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\nendsolid s\n",
                ".stl")
                .points.size(),
            3u);
  EXPECT_EQ(io::read_points_from_memory(bom + "1 2 3\n", ".xyz").points.size(), 1u);
}

TEST(Point_reader, CgalPointsWithNormalsAreTheirPoints) {
  // .pwn, as CGAL's data ships it: "x y z nx ny nz"; the normals are not samples.
  const auto set =
      io::read_points(write_file("sphere.pwn", "2.5 0.4 -9.6 0.28 0.04 -0.96\n1 2 3 0 0 1\n"));
  EXPECT_EQ(set.dimension, 3);
  EXPECT_EQ(set.points, (std::vector<Point<3>>{{2.5, 0.4, -9.6}, {1, 2, 3}}));
  EXPECT_THROW(io::read_points_from_memory("1 2\n3 4\n", ".pwn"), io::Error)
      << "a point with two coordinates is no 3D point";
}

TEST(Point_reader, PlyAsciiIntegersWrittenAsDecimalsAndFloatRange) {
  const std::string header =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
  const auto set =
      io::read_points_from_memory(header + "0 0 0\n1 0 0\n0 1 0\n3.0 0 1.0 2\n", ".ply");
  EXPECT_EQ(set.triangles.size(), 1u);
  EXPECT_THROW(io::read_points_from_memory(header + "0 0 0\n1 0 0\n0 1 0\n3.5 0 1 2\n", ".ply"),
               io::Error);
  try {
    io::read_points_from_memory(header + "0 0 0\n1e39 0 0\n0 1 0\n3 0 1 2\n", ".ply");
    FAIL() << "accepted";
  } catch (const io::Error& e) {
    EXPECT_NE(std::string(e.what()).find("beyond the range of a float"), std::string::npos)
        << e.what();
  }
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
  // The text formats hold the triangles, in order (OBJ counts vertices from 1).
  for (const std::string name : {"ascii-s.off", "ascii-s.obj"}) {
    std::istringstream text(read_file(SCULPT_TEST_OUTPUT "/" + name));
    std::vector<Facet<3>> triangles;
    std::string line;
    std::size_t vertex_lines = 0;
    const bool off = io::extension_of(name) == ".off";
    for (int number = 0; std::getline(text, line); ++number) {
      std::istringstream words(line);
      std::string first;
      words >> first;
      if (off && number >= 2 && vertex_lines < points.size()) {
        ++vertex_lines;
        continue;
      }
      if ((off && number >= 2 && first == "3") || (!off && first == "f")) {
        Facet<3> t;
        words >> t[0] >> t[1] >> t[2];
        if (!off) t = {t[0] - 1, t[1] - 1, t[2] - 1};
        triangles.push_back(t);
      }
    }
    EXPECT_EQ(triangles, result.surface) << name;
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

// What other tools write and read past is read too, with a warning that says what was ignored;
// what nothing can read is refused in one line that says why.
TEST(Io, PaddingAndAMissingEndsolidAreReadWithAWarning) {
  std::string ply =
      "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
      "property float y\nproperty float z\nend_header\n";
  for (const float value : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f}) {
    char bytes[4];
    std::memcpy(bytes, &value, 4);
    ply.append(bytes, 4);
  }
  EXPECT_TRUE(io::read_points_from_memory(ply, ".ply").warnings.empty());
  const auto padded = io::read_points_from_memory(ply + "\n" + std::string(509, '\0'), ".ply");
  ASSERT_EQ(padded.points.size(), 3u);
  ASSERT_EQ(padded.warnings.size(), 1u);
  EXPECT_NE(padded.warnings[0].find("510 bytes of padding"), std::string::npos)
      << padded.warnings[0];
  EXPECT_THROW(io::read_points_from_memory(ply + std::string(8, '\0') + "1", ".ply"), io::Error);

  const std::string facet =
      "facet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\n"
      "endloop\nendfacet\n";
  const auto open_ended = io::read_points_from_memory("solid s\n" + facet, ".stl");
  EXPECT_EQ(open_ended.points.size(), 3u);
  ASSERT_EQ(open_ended.warnings.size(), 1u);
  EXPECT_NE(open_ended.warnings[0].find("without 'endsolid'"), std::string::npos);
  EXPECT_TRUE(
      io::read_points_from_memory("solid s\n" + facet + "endsolid s\n", ".stl").warnings.empty());
  try {
    io::read_points_from_memory("solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\n", ".stl");
    ADD_FAILURE() << "a facet cut short was read";
  } catch (const io::Error& e) {
    EXPECT_NE(std::string(e.what()).find("ends inside a facet"), std::string::npos) << e.what();
  }
}

// The bytes with one byte changed.
std::string with_byte(std::string bytes, std::size_t at, char value) {
  bytes[at] = value;
  return bytes;
}

// The bytes are refused in one io::Error whose message says `says`.
void expect_refused(const std::string& bytes, const std::string& extension,
                    const std::string& says) {
  try {
    io::read_points_from_memory(bytes, extension);
    ADD_FAILURE() << "read, though it " << says;
  } catch (const io::Error& e) {
    EXPECT_NE(std::string(e.what()).find(says), std::string::npos) << e.what();
  }
}

// A LAS file of the four corners of a tetrahedron (millimetres, offset by 10, 20, 30 m), in the
// layout of the given version and point data format, with `gap` bytes of variable records.
std::string las_file(int minor, int format, std::size_t gap = 0) {
  const std::size_t fixed = minor == 4 ? 375 : minor == 3 ? 235 : 227;
  const int record = std::vector<int>{20, 28, 26, 34, 57, 63, 30, 36, 38, 59, 67}[format];
  std::string bytes(fixed + gap, '\0');
  const auto put = [&](std::size_t at, const void* value, std::size_t size) {
    std::memcpy(&bytes[at], value, size);  // little endian, as this machine
  };
  bytes.replace(0, 4, "LASF");
  bytes[24] = 1;
  bytes[25] = static_cast<char>(minor);
  const std::uint16_t header = fixed, length = record;
  const std::uint32_t offset = fixed + gap, count = 4;
  const std::uint64_t count64 = 4;
  const double scale = 0.001, origin[3] = {10, 20, 30};
  put(94, &header, 2);
  put(96, &offset, 4);
  bytes[104] = static_cast<char>(format);
  put(105, &length, 2);
  put(107, &count, 4);
  for (int k = 0; k < 3; ++k) {
    put(131 + 8 * k, &scale, 8);
    put(155 + 8 * k, &origin[k], 8);
  }
  if (minor == 4) put(247, &count64, 8);
  for (const std::array<std::int32_t, 3> corner :
       {std::array<std::int32_t, 3>{0, 0, 0}, {1000, 0, 0}, {0, 1000, 0}, {0, 0, -1000}}) {
    std::string point(record, '\0');
    std::memcpy(&point[0], corner.data(), 12);
    bytes += point;
  }
  return bytes;
}

// LAS colours are 16-bit levels; files whose levels stay within a byte hold bytes in them.
TEST(Io, ReadsLasColoursAsLevelsOfSixteenBitsOrOfABytes) {
  for (const auto& [format, at] : {std::pair{2, 20}, {3, 28}, {7, 30}}) {
    for (const std::uint16_t unit : {std::uint16_t{1}, std::uint16_t{257}}) {
      SCOPED_TRACE(fmt::format("format {}, unit {}", format, unit));
      std::string bytes = las_file(4, format);
      const int record = std::vector<int>{20, 28, 26, 34, 57, 63, 30, 36, 38, 59, 67}[format];
      for (int i = 0; i < 4; ++i) {
        for (int c = 0; c < 3; ++c) {
          const std::uint16_t level = static_cast<std::uint16_t>((60 * i + c) * unit);
          std::memcpy(&bytes[375 + record * i + at + 2 * c], &level, 2);
        }
      }
      const auto set = io::read_points_from_memory(bytes, ".las");
      ASSERT_EQ(set.attributes.colors.size(), 4u);
      EXPECT_EQ(set.attributes.colors[3], (std::array<std::uint8_t, 3>{180, 181, 182}));
    }
  }
  EXPECT_TRUE(io::read_points_from_memory(las_file(4, 6), ".las").attributes.colors.empty());
  // A colour format whose colours are all 0 was written without any.
  EXPECT_TRUE(io::read_points_from_memory(las_file(4, 7), ".las").attributes.colors.empty());
}

TEST(Io, ReadsLasOfEveryVersionAndPointFormat) {
  const std::vector<Point<3>> expected = {{10, 20, 30}, {11, 20, 30}, {10, 21, 30}, {10, 20, 29}};
  for (const auto& [minor, format] : {std::pair{0, 0}, {2, 1}, {2, 3}, {3, 5}, {4, 6}, {4, 10}}) {
    SCOPED_TRACE(fmt::format("LAS 1.{} format {}", minor, format));
    const auto set = io::read_points_from_memory(las_file(minor, format, 54), ".las");
    ASSERT_EQ(set.points.size(), 4u);
    for (int i = 0; i < 4; ++i) {
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(set.points[i][k], expected[i][k], 1e-9);
    }
    // Chunked as from a pipe: the same points.
    EXPECT_EQ(io::read_points_from_memory(las_file(minor, format, 54), ".las", 7).points,
              set.points);
  }
  const std::string good = las_file(2, 0);
  const auto padded = io::read_points_from_memory(good + std::string(3, '\0'), ".las");
  EXPECT_EQ(padded.points.size(), 4u);
  ASSERT_EQ(padded.warnings.size(), 1u);
  EXPECT_NE(padded.warnings[0].find("data after the 4 points"), std::string::npos);
  const std::vector<std::pair<std::string, std::string>> refused = {
      {"LASX" + good.substr(4), "not a LAS file"},
      {good.substr(0, 300), "truncated"},
      {with_byte(good, 104, char(0x80)), "compressed (LAZ)"},
      {with_byte(good, 104, 11), "not one of LAS's"},
      {with_byte(good, 105, 19), "too short"},
      {with_byte(good, 25, 9), "LAS version 1.9"},
      {[&] {
         auto b = good;
         std::memset(&b[131], 0, 8);
         return b;
       }(),
       "the scale not 0"},
      {with_byte(good, 108, 1), "announces"},
  };
  for (const auto& [bytes, says] : refused) expect_refused(bytes, ".las", says);
}

TEST(Io, ReadsPcdAsTextAndBinarySkippingUnmeasuredPoints) {
  const std::string header =
      "# .PCD v0.7\nVERSION 0.7\nFIELDS x y z rgb\nSIZE 4 4 4 4\nTYPE F F F U\n"
      "COUNT 1 1 1 1\nWIDTH 5\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS 5\nDATA ";
  const std::vector<std::array<float, 3>> points = {
      {0, 0, 0}, {1, 0, 0}, {NAN, NAN, NAN}, {0, 1, 0}, {0, 0, 1.5f}};
  std::string text = header + "ascii\n", binary = header + "binary\n";
  for (const auto& p : points) {
    text += fmt::format("{} {} {} 4278190080\n", p[0], p[1], p[2]);
    binary.append(reinterpret_cast<const char*>(p.data()), 12);
    const std::uint32_t colour = 0xff000000;
    binary.append(reinterpret_cast<const char*>(&colour), 4);
  }
  for (const std::string& file : {text, binary}) {
    const auto set = io::read_points_from_memory(file, ".pcd");
    ASSERT_EQ(set.points.size(), 4u);
    EXPECT_EQ(set.points[3], (Point<3>{0, 0, 1.5}));
    ASSERT_EQ(set.warnings.size(), 1u);
    EXPECT_NE(set.warnings[0].find("1 points without a measurement (NaN) skipped"),
              std::string::npos);
    EXPECT_EQ(io::read_points_from_memory(file, ".pcd", 5).points, set.points);
  }
  const std::vector<std::pair<std::string, std::string>> refused = {
      {header + "binary_compressed\n", "no Debian package decodes them"},
      {"FIELDS x y\nSIZE 4 4\nTYPE F F\nCOUNT 1 1\nPOINTS 1\nDATA ascii\n1 2\n", "no field z"},
      {text.substr(0, text.size() - 20), "truncated"},
      {text + "1 1 1 0\n", "data after the points"},
      {binary + "x", "data after the 5 points"},
      {"FIELDS x y z\nSIZE 4 4 3\nTYPE F F F\nCOUNT 1 1 1\nPOINTS 1\nDATA ascii\n1 2 3\n",
       "PCD does not define"},
      {"FIELDS x y z\nSIZE 4 4\n", "gives 2 values for 3 fields"},
      {"BANANA 3\n", "not a PCD header line"},
  };
  for (const auto& [bytes, says] : refused) expect_refused(bytes, ".pcd", says);
}

TEST(Io, CompressedFormatsWithoutADebianDecoderAreNamed) {
  for (const char* name : {"scan.laz", "scan.e57"}) {
    try {
      io::read_points(write_file(name, "LASF"));
      ADD_FAILURE() << name;
    } catch (const io::Error& e) {
      EXPECT_NE(std::string(e.what()).find("no Debian package decodes it"), std::string::npos)
          << e.what();
    }
  }
}

}  // namespace
}  // namespace sculpt
