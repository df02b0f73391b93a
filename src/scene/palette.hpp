// SPDX-License-Identifier: GPL-3.0-or-later
// The colours of the paper's figures: samples green, inner poles red, outer concave poles blue
// in 2D and orange in 3D, Delaunay edges blue, Voronoi edges green, polar circles dark. Shades
// are set apart where the paper's would be mistaken for one another (dark green samples on
// light green Voronoi edges, deep blue poles on light blue edges), and every layer a stage can
// show has a colour of its own: tests/palette_test.cpp checks every stage of every method.
#pragma once

#include "scene.hpp"

namespace sculpt::scene::palette {

inline constexpr Color sample{0.05f, 0.55f, 0.10f};
inline constexpr Color given_sample{0.55f, 0.55f, 0.60f};     // before the cleaning: grey
inline constexpr Color smoothing_move{0.85f, 0.35f, 0.75f};   // from given to smoothed: magenta
inline constexpr Color removed_outlier{0.95f, 0.15f, 0.15f};  // removed by the cleaning: red
inline constexpr Color delaunay_edge{0.40f, 0.55f, 0.95f};
// Lighter than the samples: the same hue as the paper's, apart at a glance (palette_test.cpp).
inline constexpr Color voronoi_edge{0.50f, 0.82f, 0.40f};
inline constexpr Color pole{0.85f, 0.10f, 0.10f};
inline constexpr Color inner_pole{0.85f, 0.10f, 0.10f};
inline constexpr Color outer_pole_2d{0.10f, 0.25f, 0.95f};
inline constexpr Color outer_pole_3d{1.00f, 0.55f, 0.00f};
inline constexpr Color convex_pole{0.55f, 0.20f, 0.70f};
inline constexpr Color unlabelled_pole{0.60f, 0.60f, 0.60f};
inline constexpr Color box_corner{0.10f, 0.10f, 0.10f};
inline constexpr Color polar_ball{0.30f, 0.30f, 0.30f, 0.55f};
// Translucent spheres in 3D, legible a few at a time (a stride, or a picked sample).
inline constexpr Color polar_ball_3d{0.00f, 0.45f, 0.70f, 0.8f};
// Inner and outer balls apart, near their poles' hues but lighter, so that a pole shows on
// its ball (the opacity is the request's).
inline constexpr Color inner_ball{0.85f, 0.40f, 0.25f};
inline constexpr Color outer_ball{1.00f, 0.90f, 0.45f};
// What is picked: the sample's Voronoi cell, its polar balls and their inscribed cubes, and the
// poles (the sample's two, or the pole clicked).
inline constexpr Color focus_cell{0.45f, 0.30f, 0.00f};
inline constexpr Color focus_ball{0.95f, 0.35f, 0.55f, 0.9f};
inline constexpr Color inscribed_cube{0.45f, 0.20f, 0.40f};
inline constexpr Color picked_pole{0.95f, 0.60f, 0.95f};
inline constexpr Color picked_sample{0.05f, 0.25f, 0.00f};  // a darker sample
// The replay: the pole just labelled, the ball that labelled it and that ball's cube.
inline constexpr Color current_pole{1.00f, 0.85f, 0.00f};
inline constexpr Color source_ball{0.70f, 0.55f, 0.00f, 0.9f};
inline constexpr Color source_cube{0.50f, 0.05f, 0.10f};
inline constexpr Color contradicted_pole{0.00f, 0.80f, 0.85f};  // cyan: apart from every label
inline constexpr Color solid{0.55f, 0.70f, 0.90f};
// In a section, the cells with a box corner: outside the samples' hull, quiet.
inline constexpr Color section_outside{0.86f, 0.86f, 0.80f};
// The cells' sides in a section: mid grey, as thin slivers crowd them together.
inline constexpr Color section_edge{0.45f, 0.45f, 0.50f};
inline constexpr Color cut_cell_edge{0.15f, 0.15f, 0.20f};  // the cells' edges on a section
// What sculpting removed from the hull, beside what it kept (Kuo & Yau, Figs. 1 and 2).
inline constexpr Color sculpted_away{0.95f, 0.60f, 0.55f};
// The cells the step shown of the carving replay takes away: strong, where the eye must go.
inline constexpr Color just_removed{0.95f, 0.00f, 0.80f};
inline constexpr Color carving_circle{0.65f, 0.50f, 0.00f};  // and their circumcircles (2D)
inline constexpr Color surface{0.78f, 0.80f, 0.86f};
inline constexpr Color wireframe{0.15f, 0.15f, 0.20f};
inline constexpr Color curve{0.05f, 0.05f, 0.05f};
// Where a result ends (border edges, curve ends) and where it is not a manifold.
inline constexpr Color border{1.00f, 0.45f, 0.00f};
inline constexpr Color non_manifold{0.90f, 0.00f, 0.00f};
// The triangles a bordered rule removed over an opening: where the samples end.
inline constexpr Color opening{0.55f, 0.30f, 0.85f};
// A handle thinner than the samples' spacing: a loop the sampling cannot vouch for.
inline constexpr Color thin_handle{0.00f, 0.75f, 0.80f};
// Where the carving refused to punch a handle through a web one sample thin: wine, apart from
// the borders' orange and the defects' red.
inline constexpr Color refused_handle{0.55f, 0.00f, 0.30f};
// Samples an interpolating result leaves off.
inline constexpr Color unused_sample{0.10f, 0.10f, 0.55f};
// The curve a built-in 2D example was sampled from (the viewer's ground truth), light under all.
inline constexpr Color true_curve{0.88f, 0.80f, 0.60f};
inline constexpr Color background{1.0f, 1.0f, 1.0f};
// The co-cones' marks on samples: undersampled (Dey & Giesen), no umbrella (tight co-cone).
inline constexpr Color undersampled{0.80f, 0.10f, 0.80f};
inline constexpr Color without_umbrella{0.00f, 0.60f, 0.60f};

inline Color outer_pole(int dimension) {
  return dimension == 2 ? outer_pole_2d : outer_pole_3d;
}

}  // namespace sculpt::scene::palette
