// SPDX-License-Identifier: GPL-3.0-or-later
#include "scene/clipping.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sculpt::scene {
namespace {

float dot(const Vec3& a, const Vec3& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

// Keeps the primitives of `count` positions each that pass `kept` (their positions and centre),
// with their normals (one per position) and radii (one per primitive).
template <class Kept>
void keep_primitives(Layer& layer, std::size_t count, const Kept& kept) {
  std::vector<Vec3> positions, normals;
  std::vector<float> radii;
  const std::size_t primitives = layer.positions.size() / count;
  for (std::size_t k = 0; k < primitives; ++k) {
    Vec3 centre{0, 0, 0};
    for (std::size_t j = 0; j < count; ++j) {
      for (int c = 0; c < 3; ++c) centre[c] += layer.positions[k * count + j][c] / float(count);
    }
    if (!kept(&layer.positions[k * count], count, centre)) continue;
    for (std::size_t j = 0; j < count; ++j) {
      positions.push_back(layer.positions[k * count + j]);
      if (!layer.normals.empty()) normals.push_back(layer.normals[k * count + j]);
    }
    if (!layer.radii.empty()) radii.push_back(layer.radii[k]);
  }
  layer.positions = std::move(positions);
  layer.normals = std::move(normals);
  layer.radii = std::move(radii);
}

std::size_t positions_per_primitive(Primitive primitive) {
  switch (primitive) {
    case Primitive::lines:
      return 2;
    case Primitive::triangles:
      return 3;
    default:
      return 1;
  }
}

}  // namespace

Vec3 normal_of(const Clip& clip) {
  const float degrees = float(M_PI) / 180.0f;
  const float az = clip.azimuth * degrees, el = clip.elevation * degrees;
  return {std::cos(el) * std::cos(az), std::cos(el) * std::sin(az), std::sin(el)};
}

Clip facing(const Vec3& direction) {
  const float length = std::sqrt(dot(direction, direction));
  Clip clip;
  clip.position = 0.5f;
  if (!(length > 0)) return clip;
  const float degrees = 180.0f / float(M_PI);
  clip.elevation = std::asin(std::clamp(direction[2] / length, -1.0f, 1.0f)) * degrees;
  clip.azimuth = std::atan2(direction[1], direction[0]) * degrees;
  return clip;
}

Clip_plane plane_of(const Scene& scene, const Clip& clip) {
  Clip_plane plane;
  plane.normal = normal_of(clip);
  // Where the plane crosses the samples' box: its corners' extent along the normal.
  float low = std::numeric_limits<float>::max(), high = std::numeric_limits<float>::lowest();
  for (int corner = 0; corner < 8; ++corner) {
    const Vec3 p{corner & 1 ? scene.upper[0] : scene.lower[0],
                 corner & 2 ? scene.upper[1] : scene.lower[1],
                 corner & 4 ? scene.upper[2] : scene.lower[2]};
    low = std::min(low, dot(plane.normal, p));
    high = std::max(high, dot(plane.normal, p));
  }
  plane.offset = low + clip.position * (high - low);
  plane.extent = high - low;
  return plane;
}

void clip(Scene& scene, const Clip& clip) {
  const Clip_plane plane = plane_of(scene, clip);
  // A section shows the samples' region: what reaches far outside it (edges to the box corners,
  // Voronoi vertices of flat cells) would stand as a wall in front of it.
  const float margin =
      0.05f * std::sqrt(dot(Vec3{scene.upper[0] - scene.lower[0], scene.upper[1] - scene.lower[1],
                                 scene.upper[2] - scene.lower[2]},
                            Vec3{scene.upper[0] - scene.lower[0], scene.upper[1] - scene.lower[1],
                                 scene.upper[2] - scene.lower[2]}));
  const auto near_samples = [&](const Vec3& p) {
    for (int c = 0; c < 3; ++c) {
      if (p[c] < scene.lower[c] - margin || p[c] > scene.upper[c] + margin) return false;
    }
    return true;
  };
  for (auto& layer : scene.layers) {
    if (layer.cut) continue;
    keep_primitives(layer, positions_per_primitive(layer.primitive),
                    [&](const Vec3* positions, std::size_t count, const Vec3& centre) {
                      const float side = plane.side(centre);
                      if (side > 0 || (clip.slab > 0 && side < -clip.slab * plane.extent))
                        return false;
                      return std::all_of(positions, positions + count, near_samples);
                    });
  }
}

void keep_near(Scene& scene, const Vec3& centre, float radius,
               const std::vector<std::string>& whole) {
  for (auto& layer : scene.layers) {
    if (std::find(whole.begin(), whole.end(), layer.id) != whole.end()) continue;
    keep_primitives(layer, positions_per_primitive(layer.primitive),
                    [&](const Vec3* positions, std::size_t count, const Vec3&) {
                      return std::any_of(positions, positions + count, [&](const Vec3& p) {
                        const Vec3 d{p[0] - centre[0], p[1] - centre[1], p[2] - centre[2]};
                        return dot(d, d) <= radius * radius;
                      });
                    });
  }
}

}  // namespace sculpt::scene
