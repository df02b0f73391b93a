// SPDX-License-Identifier: GPL-3.0-or-later
#include "ply_writer.hpp"

#include "output_buffer.hpp"

namespace sculpt::io {
void write_ply(std::ostream& out, const std::vector<Point<3>>& vertices,
               const std::vector<Facet<3>>& triangles, const Point_attributes& attributes,
               bool binary) {
  const bool normals = attributes.normals.size() == vertices.size() && !vertices.empty();
  const bool colors = attributes.colors.size() == vertices.size() && !vertices.empty();
  const bool little_endian = __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__;
  Output_buffer ply(out);
  ply.text("ply\nformat {} 1.0\ncomment written by sculpt\n", !binary ? "ascii"
                                                              : little_endian
                                                                  ? "binary_little_endian"
                                                                  : "binary_big_endian");
  ply.text("element vertex {}\n", vertices.size());
  ply.text("property double x\nproperty double y\nproperty double z\n");
  if (normals) ply.text("property double nx\nproperty double ny\nproperty double nz\n");
  if (colors) ply.text("property uchar red\nproperty uchar green\nproperty uchar blue\n");
  ply.text("element face {}\nproperty list uchar int vertex_indices\nend_header\n",
           triangles.size());
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    const auto& p = vertices[i];
    if (binary) {
      for (double x : p) ply.binary(x);
      if (normals) {
        for (double x : attributes.normals[i]) ply.binary(x);
      }
      if (colors) {
        for (std::uint8_t c : attributes.colors[i]) ply.binary(c);
      }
      continue;
    }
    ply.text("{} {} {}", p[0], p[1], p[2]);
    if (normals) {
      const auto& n = attributes.normals[i];
      ply.text(" {} {} {}", n[0], n[1], n[2]);
    }
    if (colors) {
      const auto& c = attributes.colors[i];
      ply.text(" {} {} {}", int{c[0]}, int{c[1]}, int{c[2]});
    }
    ply.text("\n");
  }
  for (const auto& t : triangles) {
    if (binary) {
      ply.binary(std::uint8_t{3});
      for (int v : t) ply.binary(static_cast<std::int32_t>(v));
    } else {
      ply.text("3 {} {} {}\n", t[0], t[1], t[2]);
    }
  }
}

}  // namespace sculpt::io
