// SPDX-License-Identifier: GPL-3.0-or-later
/// \file
/// The basic vocabulary of the public API (sculpt/sculpt.hpp): points, cells and facets as
/// indices, the methods, kinds, rules and cleanings by name, the options of a run, and the
/// errors it throws.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>

namespace sculpt {

template <int D>
using Point = std::array<double, D>;

/// A triangle (D = 3) or tetrahedron, or an edge (D = 2) or triangle: indices into the sites.
template <int D>
using Cell = std::array<int, D + 1>;

/// A facet of a cell: a triangle in 3D, an edge in 2D. Indices into the samples.
template <int D>
using Facet = std::array<int, D>;

// ---------------------------------------------------------------------------------------------
// Options

/// Closed (the shape bounds a solid), bordered (it ends somewhere: a sheet, a part scanned from
/// one side), or automatic: the robust method reconstructs closed first and, when the result
/// spans openings, bordered too, and keeps the one with fewer defects (driver/automatic_kind.hpp);
/// the other methods take automatic as closed. A result's kind is never automatic: its options
/// and statistics say which was kept, and Statistics::kind_chosen_automatically that the robust
/// method chose it.
enum class Surface_kind { closed, bordered, automatic };

/// The reconstruction method: siblings over the shared stages 1-3. The names are what the command
/// line, the viewer and the statistics use (method_names(), parse_method()).
enum class Method {
  paper,   ///< Kuo & Yau's algorithm exactly as published (the figures and lessons use it)
  robust,  ///< confidence labelling and a manifold carve: the default, for real scans
  crust,   ///< Amenta, Bern & Kamvysselis 1998: Delaunay edges of S and its Voronoi vertices
           ///< (2D), or the triangles of DT(S ∪ poles) between samples, filtered and walked (3D)
  nn_crust,  ///< Dey & Kumar 1999: each sample's nearest neighbour and nearest on the far side
  cocone,    ///< Amenta, Choi, Dey & Leekha 2000: the triangles whose Voronoi edges cross the
             ///< co-cones of their three samples, pruned and walked (surfaces)
  advancing_front,  ///< CGAL's Advancing Front Surface Reconstruction (Cohen-Steiner & Da 2004)
  alpha_shape,      ///< CGAL's alpha shapes: the smallest alpha giving one solid with every sample
  power_crust,      ///< Amenta, Choi & Kolluri 2001: the power diagram faces between the cells of
                    ///< inner and outer poles (does not interpolate: vertices of its own)
  tight_cocone,     ///< Dey & Goswami 2003: the co-cone's surface, then the Delaunay cells peeled
                    ///< from the outside up to it; the rest is a solid, its skin watertight
  boissonnat,       ///< Boissonnat 1984: the hull's cells removed greedily, farthest-bulging
                    ///< first, while the boundary stays a polyhedron, until every sample is on it
};

/// Which facets of DT(S ∪ OUP) make the surface.
///  skin:       facets with an outer apex (outer pole, box corner) on one side and an inner apex
///              (a sample, i.e. an all-sample cell, or an inner pole) on the other. For a closed
///              surface this is exactly the boundary of the sculpted solid.
///  extraction: the paper's literal extraction rule: all-sample facets with at least one outer
///              apex. It contains the skin and adds "dangling" facets where labels are wrong.
///  automatic:  the rule that measured better for the kind of surface: skin when closed (it
///              leaves out dangling facets), extraction when bordered (box corners stand on both
///              sides of a sheet, so a facet between two of them belongs to it; the skin rule
///              loses such facets, e.g. 17 of 79 edges of a sampled sine curve).
enum class Surface_rule { automatic, skin, extraction };

/// Cleaning the samples before any method (driver/cleaning.hpp). `outliers` removes the samples
/// that no surface through their neighbours passes near (core/outlying_samples.hpp): a scanner's
/// stray returns, which an interpolating surface would pass through as spikes. `jet` moves each
/// sample onto the quadric fitted to its 24 nearest samples (CGAL's jet smoothing, Cazals &
/// Pouget 2005): noise of a third of the samples' spacing crumples an interpolating surface into
/// invented handles. `outliers_and_jet` does both, in that order; `automatic` does both where the
/// robust method reconstructs a surface from samples whose measured noise (Statistics::noise) is
/// at least noise_worth_cleaning; `none` never. Surfaces only. The surface then passes through
/// the cleaned samples, and not through the outliers removed.
enum class Cleaning { none, automatic, jet, outliers, outliers_and_jet };

/// The noise (of the spacing) from which the automatic cleaning smooths: a sphere of 20,000
/// samples with noise of 0.2 of its spacing comes back of genus 0, with 0.3 of genus 2.
inline constexpr double noise_worth_cleaning = 0.3;

/// What the core reports while it runs; returning false from the callback cancels the run.
struct Progress {
  const char* stage;  ///< name of the stage being computed
  double fraction;    ///< 0..1 within that stage, where known
  ///< 0..1 across the whole reconstruction: the stages done and this one's fraction, each stage
  ///< weighted by its usual share of the time (a progress bar that fills once, never back).
  double overall = 0;
};

/// The one place the defaults live: front ends initialise their own settings from Options{}.
struct Options {
  Method method = Method::robust;
  Surface_kind kind = Surface_kind::automatic;
  Surface_rule rule = Surface_rule::automatic;
  /// Side lengths of the bounding box BB relative to those of the samples' bounding box.
  double box_factor = 5.0;
  /// The alpha shape's radius, in the input's units; 0 chooses the smallest alpha whose solid is
  /// one piece holding every sample.
  double alpha = 0;
  /// Bordered surfaces start from one convex pole. -1 chooses p+ of the lowest-index sample whose
  /// p+ is convex, a choice that does not depend on CGAL's internal order; otherwise the convex
  /// pole (p+ or p-) of the given sample.
  int bordered_seed_sample = -1;
  /// Keep the cells of both triangulations in the result (the viewer and the tests read them);
  /// the command line switches this off to save memory on large inputs. Without it, the methods
  /// through CGAL (advancing-front, alpha-shape), which read neither, build no DT(S ∪ BBV) and no
  /// poles: their stages 1-2 are empty and counted 0.
  bool keep_triangulations = true;
  /// Keep the solid's cells (stage 7; the statistics count them either way): the command line
  /// keeps them only to write them (--solid).
  bool keep_solid = true;
  /// The robust method's carving (stage 6b) first floods the outer cells from the outside and
  /// keeps the flood when it is a closed 2-manifold through every sample, with no sample left off,
  /// no cavity left to open and no small piece cut off (methods/robust/manifold_carving.hpp):
  /// where carving cell by cell ends too, unless it stalls short of it with outer cells it cannot
  /// remove one group at a time (the flood's surface is then the more complete). On the inputs
  /// measured (CGAL's knot1 and bunny00, random tori, the built-in closed shapes) the same
  /// triangles, in 60-70% of the carving's time. false carves cell by cell from the start,
  /// largest circumball first.
  bool carve_by_flood = true;
  Cleaning cleaning = Cleaning::automatic;
  std::function<bool(const Progress&)> progress;
};

/// Input the algorithm cannot work on: too few points, NaN, duplicates, degenerate sets.
class Input_error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Two samples at the same place (scans often repeat a few points).
class Duplicate_points : public Input_error {
 public:
  using Input_error::Input_error;
};

/// Thrown when Options::progress returned false.
class Cancelled : public std::runtime_error {
 public:
  Cancelled() : std::runtime_error("reconstruction cancelled") {}
};

}  // namespace sculpt
