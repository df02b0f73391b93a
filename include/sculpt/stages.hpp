// SPDX-License-Identifier: GPL-3.0-or-later
/// \file
/// The stages of a reconstruction as plain data (sculpt/sculpt.hpp lists them): the
/// triangulations, the poles and their labelling, the insertion, the carving and its openings,
/// and the peers' own stages. Reconstruction (sculpt/sculpt.hpp) keeps one of each.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "options.hpp"

namespace sculpt {

// ---------------------------------------------------------------------------------------------
// Stages

enum class Site_kind : std::uint8_t { sample, box_corner, pole };

enum class Label : std::uint8_t { unlabelled, inner, outer };

/// Why a pole received its label.
enum class Label_reason : std::uint8_t {
  convex_seed,     ///< a convex pole, labelled outer at the start
  pairing,         ///< the opposite label of a pole it is paired with (both poles of one sample)
  inscribed_cube,  ///< lies strictly inside the inscribed cube (square) of a labelled polar ball
  ball_overlap,    ///< robust: its polar ball meets the ball of a labelled pole deeply (same side)
};

/// Stage 1 and 6: a Delaunay triangulation, its finite cells as indices into the sites.
template <int D>
struct Delaunay_stage {
  std::size_t cell_count = 0;  ///< finite cells, also when the cells themselves are not kept
  std::vector<Cell<D>> cells;  ///< empty unless Options::keep_triangulations
};

/// A pole is a Delaunay cell of stage 1: its circumcentre and circumradius (the polar ball).
template <int D>
struct Pole {
  Point<D> center{};
  double radius = 0;
  std::size_t cell = 0;  ///< index of the cell among the finite cells of stage 1
  Cell<D> sites{};       ///< that cell's sites: the samples (and box corners) on the polar ball
  bool convex = false;   ///< the cell is incident to a box corner
};

/// Stage 2. One Voronoi vertex can be a pole of several samples, so the pairing of poles is a
/// graph (partners), not a perfect matching.
template <int D>
struct Poles_stage {
  std::vector<Pole<D>> poles;
  std::vector<int> positive_pole;    ///< per sample: p+, the farthest vertex of its Voronoi cell
  std::vector<int> negative_pole;    ///< per sample: p-, farthest on the other side; -1 if none
  std::vector<int> partner_offsets;  ///< partners of pole p: partners[offsets[p] .. offsets[p+1])
  std::vector<int> partners;

  struct Range {
    const int* first;
    const int* last;
    const int* begin() const { return first; }
    const int* end() const { return last; }
    std::size_t size() const { return static_cast<std::size_t>(last - first); }
  };
  Range partners_of(int pole) const {
    return {partners.data() + partner_offsets[pole], partners.data() + partner_offsets[pole + 1]};
  }
};

/// Stage 3.
struct Seeds_stage {
  std::vector<int> convex_poles;  ///< poles whose cell touches a box corner
  std::vector<int> outer_seeds;   ///< closed: every convex pole; bordered: the one chosen seed
};

struct Labelling_event {
  int pole;
  Label label;
  int source;  ///< the pole that gave the label; -1 for a convex seed
  Label_reason reason;
  /// The strength of the evidence, 0..1: 1 for the paper's rules; for the robust labelling the
  /// cosine of the angle at which the two polar balls meet (see confidence_labelling.hpp).
  float weight = 1;
  /// A conflict: how many labelling events had happened when it was offered (the replay shows
  /// it from that step on); -1 for an event.
  long after_events = -1;
};

/// Stage 4: the pole separation, in the order it ran. A conflict is an offer of the opposite
/// label to a pole that already has one; the first label stays (paper). In the robust labelling
/// a conflict is strong evidence (>= 0.5) for the side a pole did not get: present when it was
/// labelled, or arriving later and at least as strong as its own: a "contradicted" pole.
struct Propagation_stage {
  std::vector<Labelling_event> events;
  std::vector<Labelling_event> conflicts;
  std::vector<Label> labels;  ///< final label of every pole
  std::size_t unlabelled = 0;
};

/// Stage 5: the poles inserted into the first triangulation. Closed: OUP, the outer non-convex
/// poles; bordered: UP, every labelled non-convex pole. The paper also counts the box corners in
/// m (or l); they are already in the triangulation.
struct Insertion_stage {
  std::vector<int> inserted_poles;
};

/// Stage 6b (robust method, Boissonnat's): the all-sample cells of DT(S ∪ BBV) removed from the
/// hull, in the order they were removed (cells are numbered as in stage 1), and those that stayed.
enum class Carve_reason : std::uint8_t {
  outer_pole_inside,  ///< its circumball holds an outer pole: inserting OUP would destroy it
  outer_power_cell,   ///< its circumcentre lies in the power cell of an outer polar ball
  exposes_sample,     ///< removed so that a buried sample reaches the surface
  largest_bulge,      ///< (Boissonnat) its circumsphere bulged farthest out of the solid
};

struct Carve_event {
  int cell;
  Carve_reason reason;
};

/// How the robust carving removed several cells at once (methods/robust/solid_openings.hpp).
enum class Opening_kind : std::uint8_t {
  cavity,  ///< a cavity (a group of outer cells enclosed by the solid) opened at one cell
  group,   ///< a group of outer cells touching the outside, removed whole
  punch,   ///< a web of outer cells punched through around the vertex or edge that blocked it
};

/// A removal of several cells at once, the only removals of the robust carving that can change
/// the solid's topology (one cell removed by Boissonnat's condition never does). Its cells are
/// events[first_event, first_event + cells) (with the events kept).
struct Carving_opening {
  std::uint32_t first_event = 0;
  std::uint32_t cells = 0;
  /// The change of the solid's Euler characteristic (vertices - edges + faces - cells of the
  /// cells left): 3D, -1 a handle opened (the surface's genus one more), +1 a cavity or a piece
  /// of its own (one more surface); 2D, -1 a hole (a cavity opened: one more curve); 0 the
  /// topology kept.
  std::int32_t euler_change = 0;
  Opening_kind kind = Opening_kind::group;
  std::uint8_t unused[3] = {0, 0, 0};  ///< written as zeros with the rest (no padding)
};

struct Carving_stage {
  /// Removed cells, in order: largest circumball first, or in the order a flood that stood met
  /// them (Statistics::carved_by_flood). The robust method keeps them with the triangulations'
  /// cells only (Options::keep_triangulations); Statistics::carved_cells counts them always.
  std::vector<Carve_event> events;
  /// Judged outer but kept: removing them breaks the manifold (after a flood, not looked for).
  std::vector<int> kept_outer_cells;
  std::vector<int> buried_samples;  ///< samples left inside the solid, on no surface facet
  /// The removals of several cells at once, in order (after a flood that stood, none: the flood
  /// set the topology at once).
  std::vector<Carving_opening> openings;
  /// Cells of stage 1 where a punch through a web was refused because it would open a handle (a
  /// tunnel one sample wide: methods/robust/solid_openings.hpp); the web stayed around them.
  std::vector<int> refused_handles;
};

/// The crust's own stage (method crust): the Voronoi vertices V of the samples (the circumcentres
/// of the finite cells of stage 1; in 3D only the poles, the Voronoi vertices the crust uses) and
/// DT(S ∪ V), whose cells number a site i < n as sample i and i >= n as V[i - n]. The curve is its
/// edges between two samples.
template <int D>
struct Crust_stage {
  std::vector<Point<D>> voronoi_vertices;
  Delaunay_stage<D> delaunay;
};

/// The candidate triangles of the methods that filter Delaunay triangles and then extract a
/// manifold from them (the crust and the co-cone in 3D): those the method's rule chose, and those
/// the pruning then removed, in order: those on a sharp edge (its triangles all within a wedge
/// narrower than 90 degrees: for two, a fold sharper than 90) and those with an edge of their own;
/// when removing all of these would leave a sample uncovered (a hole in the candidates eats the
/// surface from its rim), only those hanging free (held only where three or more triangles meet):
/// rims_kept. The surface is the outer boundary of the candidates left, walked from the outside
/// (ACDL 2000, sec. 4).
/// The co-cone also marks the samples where the sampling is too sparse for its rule
/// (undersampled: Dey & Giesen 2001); the tight co-cone, those whose triangles in the co-cone's
/// surface do not make one closed fan (no umbrella: Dey & Goswami 2003).
/// The robust method's bordered surfaces (3D) take the paper's bordered surface as candidates,
/// less the triangles spanning an opening (wider than the samples' spacing there): spanning.
template <int D>
struct Candidates_stage {
  std::vector<Facet<D>> chosen;
  std::vector<Facet<D>> spanning;
  std::vector<Facet<D>> pruned;
  bool rims_kept = false;
  std::vector<int> undersampled;
  std::vector<int> without_umbrella;
};

/// CGAL's Advancing Front grows its surface one triangle at a time from a seed, at each step the
/// most plausible triangle on the front's border: the order it added them in (indices into
/// Reconstruction::surface, which is kept in canonical order).
struct Front_stage {
  std::vector<int> order;
};

/// Alpha shapes: every finite cell of the samples' own Delaunay triangulation with the radius of
/// its circumball, smallest first. The solid at a radius alpha is the cells up to it, so the list
/// is the alpha shape at every alpha (the filtration); `chosen` cells make the method's solid.
/// Kept with the triangulations (Options::keep_triangulations).
struct Alpha_stage {
  std::vector<Cell<3>> cells;
  std::vector<double> radii;  ///< in the input's units, ascending
  std::size_t chosen = 0;
};

}  // namespace sculpt
