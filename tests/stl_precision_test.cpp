// SPDX-License-Identifier: GPL-3.0-or-later
// STL holds less than the other formats: binary STL 32-bit floats, every STL a normal per facet.
// A surface those cannot carry (a part far from the origin, as survey coordinates are; values
// beyond a float's range) is refused in one line, and nothing is written; the text STL, the other
// formats and parts near the origin are written as before.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "file_support.hpp"
#include "io/writers.hpp"
#include "shapes/shapes.hpp"

namespace sculpt {
namespace {

using testing::output_path;

std::vector<Point<3>> moved(std::vector<Point<3>> points, double offset, double scale = 1) {
  for (auto& p : points) {
    for (double& x : p) x = x * scale + offset;
  }
  return points;
}

TEST(Stl_precision, APartFarFromTheOriginIsRefusedAsBinaryStl) {
  const auto near = shapes::sphere(300);
  const auto surface = reconstruct(near).surface;
  const auto far = moved(near, 1e8);  // floats there are 8 apart: the sphere would collapse
  const auto refused = output_path("far.stl");
  std::filesystem::remove(refused);
  try {
    io::write_surface(refused, far, surface, /*ascii=*/false);
    FAIL() << "a binary STL of a part at 1e8 was written";
  } catch (const io::Error& error) {
    EXPECT_NE(std::string(error.what()).find("32-bit floats"), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find(".off"), std::string::npos) << error.what();
  }
  EXPECT_FALSE(std::filesystem::exists(refused));
  // Text STL keeps doubles; OFF keeps them exactly; near the origin binary STL is fine.
  io::write_surface(output_path("far-ascii.stl"), far, surface, /*ascii=*/true);
  io::write_surface(output_path("far.off"), far, surface, /*ascii=*/false);
  io::write_surface(output_path("near.stl"), near, surface, /*ascii=*/false);
  // A part two millimetres across in metres, ten kilometres out: floats there are 1e-3 apart,
  // more than its triangles' edges (2e-4): they collapse, refused too.
  EXPECT_THROW(io::write_surface(output_path("km.stl"), moved(near, 1e4, 1e-3), surface, false),
               io::Error);
  // A CAD part's small triangles (edges of 2e-3) hundreds of units out: floats move them by
  // under 1%, as STL always has, without turning one over: written.
  io::write_surface(output_path("cad.stl"), moved(near, 384, 1e-2), surface, false);
}

TEST(Stl_precision, NormalsThatOverflowOrVanishAreRefusedInEveryStl) {
  const auto near = shapes::sphere(300);
  const auto surface = reconstruct(near).surface;
  for (double scale : {1e300, 1e-310}) {
    for (bool ascii : {false, true}) {
      SCOPED_TRACE(std::to_string(scale) + (ascii ? " ascii" : " binary"));
      const auto path = output_path("extreme.stl");
      std::filesystem::remove(path);
      EXPECT_THROW(io::write_surface(path, moved(near, 0, scale), surface, ascii), io::Error);
      EXPECT_FALSE(std::filesystem::exists(path));
      // OFF holds them exactly.
      io::write_surface(output_path("extreme.off"), moved(near, 0, scale), surface, ascii);
    }
  }
}

}  // namespace
}  // namespace sculpt
