// SPDX-License-Identifier: GPL-3.0-or-later
/// \file
/// Sculpt: Delaunay-based curve and surface reconstruction by sculpting
/// (Kuo & Yau, "A Delaunay-based region-growing approach to surface reconstruction from
/// unorganized points", 2003, sections 3 and 4), and methods beyond the paper over the same stages.
///
/// This is the whole public API of the core, with the two headers it includes: sculpt/options.hpp
/// (points, methods, options, errors) and sculpt/stages.hpp (each stage's data). It is plain C++
/// with no CGAL or GL in it, so that the command line, the tests and the viewer compile against it
/// quickly; the algorithm itself is instantiated once per dimension in src/core2d and src/core3d.
///
/// Methods (Options::method) share stages 1-3 and differ after them:
/// paper   the paper's algorithm, literally: breadth-first pole separation, insertion of the
/// outer concave poles, the all-sample cells of DT(S ∪ OUP) (stages 4-8 below);
/// robust  the default, right on real scans: poles labelled by confidence (a priority queue of
/// evidence, as in the power crust), then the hull's all-sample cells carved from the
/// outside in an order that keeps the surface a 2-manifold (stages 4, 6b, 7, 8).
///
/// Every stage of the algorithm is kept in the returned Reconstruction as plain data:
/// 1. delaunay           DT(S ∪ BBV): the samples plus the corners of an enlarged bounding box
/// 2. poles              Amenta's poles (p+ farthest Voronoi vertex, p- farthest on the other
/// side)
/// 3. seeds              convex poles (cells incident to a box corner) and the seed labels
/// 4. propagation        the ordered labelling events of the pole separation
/// 5. insertion          the poles inserted: OUP (closed) or UP (bordered)
/// 6. sculpted_delaunay  DT(S ∪ OUP), made by inserting those poles into the first DT (the
/// robust method builds DT(S ∪ BBV ∪ UP) anew from every site: the same
/// triangulation, numbered otherwise); for a closed surface with the skin
/// rule and without keep_triangulations, the solid is read off the first DT
/// by circumball queries instead, and this stays empty
/// 6b. carving           (robust) the all-sample cells removed, in order, with the reason
/// (kept with keep_triangulations; counted in the statistics always)
/// 7. solid              the cells whose vertices are all samples
/// 8. surface            the triangles (3D) or edges (2D) of the reconstruction
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "options.hpp"
#include "stages.hpp"

namespace sculpt {

struct Stage_measure {
  std::string name;
  double seconds = 0;
  double peak_memory_mib = 0;  ///< peak resident memory of the process at the end of the stage
};

struct Statistics {
  Method method = Method::robust;
  Surface_kind kind = Surface_kind::closed;
  /// Automatic kind: the kind was chosen, and how many facets of the closed attempt spanned an
  /// opening (core/spanning_openings.hpp; 0: closed was kept at once).
  bool kind_chosen_automatically = false;
  std::size_t closed_spanning_facets = 0;
  int dimension = 0;
  std::size_t samples = 0;  ///< n
  ///< The stages ran on (sample - translation) * 2^scale_exponent, both exact (any finite
  ///< scale, any distance from the origin); every result is in the input's coordinates.
  std::array<double, 3> translation{};  ///< the unused coordinate of 2D is 0
  int scale_exponent = 0;
  std::size_t poles = 0;  ///< distinct poles
  std::size_t convex_poles = 0;
  std::size_t inner_poles = 0;
  std::size_t outer_poles = 0;
  std::size_t unlabelled_poles = 0;
  std::size_t conflicts = 0;         ///< poles offered both labels
  std::size_t conflict_offers = 0;   ///< offers of the other label (several per pole)
  std::size_t carved_cells = 0;      ///< robust: all-sample cells removed from the hull
  std::size_t kept_outer_cells = 0;  ///< robust: judged outer, kept so the surface stays manifold
  std::size_t carved_handles = 0;    ///< robust: handles (2D: holes) opened (not after a flood)
  std::size_t refused_handles = 0;   ///< robust, 3D: webs kept where a punch would open a handle
  bool carved_by_flood = false;      ///< robust: the outer cells went in one flood (the shortcut);
                                     ///< kept_outer_cells, carved_handles are then not counted (0)
  std::size_t inserted_poles = 0;    ///< m (closed) or l (bordered), without the box corners
  std::size_t delaunay_cells = 0;    ///< cells of DT(S ∪ BBV)
  std::size_t sculpted_cells = 0;    ///< cells of DT(S ∪ OUP); 0 when it was not built
  std::size_t solid_cells = 0;
  std::size_t candidate_facets = 0;  ///< crust, co-cone (3D): triangles the filter chose
  std::size_t spanning_facets = 0;   ///< robust bordered (3D): removed as spanning an opening
  std::size_t filled_gaps = 0;       ///< robust bordered (3D): border loops filled as gaps
  std::size_t torn_loops = 0;        ///< robust bordered (3D): border loops torn in the sheet
                                     ///< (by noise), not openings: of at most 64 samples, their
                                     ///< least folded fill covers no empty disc but folds back
  std::size_t short_loops = 0;       ///< robust bordered (3D): border loops, not torn, through
                                     ///< fewer samples than the rim of the smallest opening the
                                     ///< kind choice finds (19): holes the rule cut, not openings
  std::size_t set_in_samples = 0;    ///< robust bordered (3D): left-off samples set into a
                                     ///< triangle over them
  std::size_t attached_samples = 0;  ///< robust bordered (3D): left-off samples put back
  std::size_t closed_notches = 0;    ///< robust bordered (3D): sharp border notches closed
  std::size_t joined_pinches = 0;    ///< robust bordered (3D): triangles joining pinched fans
  std::size_t dropped_fans = 0;      ///< robust bordered (3D): smaller pinched fans removed
  std::size_t pruned_facets = 0;     ///< of those, removed at a sharp edge
  bool rims_kept = false;            ///< the pruning kept the rims of holes (Candidates_stage)
  std::size_t undersampled_samples = 0;      ///< co-cones: samples judged undersampled
  std::size_t samples_without_umbrella = 0;  ///< tight co-cone: no closed fan in the co-cone's
  double alpha = 0;  ///< alpha-shape: the radius chosen, in the input's units
  ///< A method that does not interpolate (the power crust): the vertices of its result, which are
  ///< not samples; 0 when the result's vertices are the samples.
  std::size_t surface_vertices = 0;
  std::size_t unbounded_power_faces = 0;  ///< power crust: inner-outer faces reaching infinity
  std::size_t facets = 0;                 ///< triangles (3D) or edges (2D) of the result
  ///< Of the result's ridges (edges of the surface in 3D, vertices of the curve in 2D):
  std::size_t boundary_ridges = 0;        ///< on one facet only: border edges, or curve end points
  std::size_t non_manifold_ridges = 0;    ///< on more than two facets
  std::size_t non_manifold_vertices = 0;  ///< 3D: vertices whose triangles do not form one fan
  std::size_t boundary_loops = 0;         ///< 3D: closed loops of border edges; 2D: open curves
  std::size_t components = 0;             ///< connected pieces of the result
  long euler_characteristic = 0;          ///< V - E + F (3D) or V - E (2D) of the result
  std::size_t unused_samples = 0;         ///< samples on no facet of the result
  /// 3D, a closed 2-manifold: how many of its handles are thinner than the samples' spacing, a
  /// neck of three or four samples that the sampling cannot tell from a gap (at least this many:
  /// Reconstruction::thin_handles).
  std::size_t thin_handles = 0;
  /// The samples' noise over their spacing (core/sample_noise.hpp), as given; -1 when not
  /// measured (fewer than 100 samples).
  double noise = -1;
  bool cleaned = false;          ///< the samples were cleaned (Options::cleaning) before the method
  bool smoothed = false;         ///< cleaned: by jet smoothing
  bool outliers_sought = false;  ///< cleaned: outliers were looked for
  std::size_t outliers_removed = 0;  ///< cleaned: outliers removed (not on the surface)
  double noise_after = -1;           ///< cleaned: the noise of the cleaned samples
  double cleaning_shift = 0;  ///< cleaned: how far the samples moved, on average, over the spacing
  std::vector<Stage_measure> stages;
  double total_seconds = 0;
};

/// A handle of a closed surface that its samples cannot vouch for: the loop of three samples
/// (the fourth -1) or four around its neck, or through it, bounding no piece of the surface, with
/// no sample around it (core/thin_handles.hpp).
struct Thin_handle {
  std::array<int, 4> loop{-1, -1, -1, -1};
  double width_over_spacing = 0;  ///< the loop's longest edge over the samples' spacing there
};

/// Index ranges of the sites: samples first, then the 2^D box corners, then inserted poles.
template <int D>
struct Reconstruction {
  static constexpr int dimension = D;
  static constexpr int box_corner_count = 1 << D;

  Options options;
  std::vector<Point<D>> sites;

  Delaunay_stage<D> delaunay;           ///< 1
  Poles_stage<D> poles;                 ///< 2
  Seeds_stage seeds;                    ///< 3
  Propagation_stage propagation;        ///< 4
  Insertion_stage insertion;            ///< 5 (paper)
  Delaunay_stage<D> sculpted_delaunay;  ///< 6 (paper)
  Carving_stage carving;                ///< 6b (robust)
  Crust_stage<D> crust;                 ///< 6c (crust)
  Candidates_stage<D> candidates;       ///< 6d (crust and co-cone in 3D)
  Front_stage front;                    ///< the Advancing Front (3D)
  Alpha_stage alpha;                    ///< alpha shapes (3D)
  std::vector<Cell<D>> solid;           ///< 7: cells of stage 6 whose vertices are all samples
  std::vector<Facet<D>> surface;        ///< 8: oriented facets; closed: normals point outward
  /// 3D, a closed surface of genus > 0: its thin handles, the evidence for Statistics::thin_handles
  std::vector<Thin_handle> thin_handles;
  /// 0 (when Statistics::cleaned): the samples as they were given, before cleaning; the sites'
  /// first points are the cleaned samples, which the surface passes through: those given, but
  /// the outliers removed, in their order, smoothed where Statistics::smoothed.
  std::vector<Point<D>> given_samples;
  /// 0 (when Statistics::cleaned, whether or not the triangulations are kept): the outliers
  /// removed, as indices of the samples as given, increasing; the k-th sample is the k-th given
  /// of those not listed.
  std::vector<int> removed_outliers;
  ///< A method that does not interpolate (the power crust) makes vertices of its own: then the
  ///< surface's facets index these instead of the samples.
  std::vector<Point<D>> surface_vertices;
  Statistics stats;

  bool interpolates() const { return surface_vertices.empty(); }
  /// The points the surface's facets index: the samples (the first sites), or its own vertices.
  const std::vector<Point<D>>& surface_points() const {
    return interpolates() ? sites : surface_vertices;
  }

  std::size_t sample_count() const {
    return sites.size() - box_corner_count - insertion.inserted_poles.size();
  }
  Site_kind kind_of_site(int site) const {
    const auto n = static_cast<int>(sample_count());
    if (site < n) return Site_kind::sample;
    if (site < n + box_corner_count) return Site_kind::box_corner;
    return Site_kind::pole;
  }
  /// The pole a site of kind Site_kind::pole stands for.
  int pole_of_site(int site) const {
    return insertion.inserted_poles[site - static_cast<int>(sample_count()) - box_corner_count];
  }
};

/// The rule `automatic` stands for with this kind of surface.
Surface_rule resolved_rule(const Options& options);

/// Whether the surface comes from inserting poles (stages 5-6, then a surface rule): the paper
/// method, and bordered surfaces in 3D. Otherwise the robust method carves (stage 6b, closed) or
/// joins nearest neighbours (bordered curves: joins_neighbours).
bool inserts_poles(Method method, Surface_kind kind, int dimension);
bool joins_neighbours(Method method, Surface_kind kind, int dimension);
/// Whether the automatic kind chooses between closed and bordered for this method: the robust
/// method's. The paper's, as published, is told its kind (automatic is closed); the others have
/// no bordered rule.
bool chooses_kind(Method method);

/// The verdict on a result, from its statistics: a closed 2-manifold (closed curve in 2D), a
/// bordered one (open curves), or what is wrong with it.
struct Verdict {
  bool manifold = false;  ///< closed or properly bordered, every sample on it, no defect
  std::string line;       ///< one line for people, e.g. "closed 2-manifold, 1 component, genus 0"
};
Verdict verdict(const Statistics& stats);

/// The topology fields of Statistics (facets ... unused_samples) for any facets on n samples: a
/// reference mesh's own, for comparison.
Statistics facet_topology(std::size_t sample_count, const std::vector<Facet<2>>& facets);
Statistics facet_topology(std::size_t sample_count, const std::vector<Facet<3>>& facets);

/// The share (0..1) of a reference's triangles that a result has, whatever their orientation:
/// how close a reconstruction of a mesh's vertices comes to the mesh.
double triangles_reproduced(const std::vector<Facet<3>>& reference,
                            const std::vector<Facet<3>>& result);

/// Names of the methods (the default first) and rules, and the reverse (false for an unknown name).
const std::vector<const char*>& method_names();
const char* describe(Method method);  ///< a few words for menus and help
///< Whether a method works in this dimension (the NN-crust reconstructs curves only, the co-cone
///< surfaces only).
///< Whether a method's result passes through the samples (all but the power crust).
bool interpolates(Method method);
bool reconstructs_in(Method method, int dimension);
/// Whether a method labels poles and sculpts a solid (paper, robust), or only reads the
/// triangulation and the poles (the crusts, the co-cone).
bool sculpts(Method method);
/// Whether a method's result has a solid (stage 7): the sculpting methods and the alpha shape.
bool builds_solid(Method method);
bool parse_method(const std::string& name, Method& method);
bool parse_rule(const std::string& name, Surface_rule& rule);  ///< auto, skin, extraction

/// Reconstructs a curve from 2D samples or a surface from 3D samples.
/// Throws Input_error for input it cannot work on, Cancelled when the progress callback says so.
Reconstruction<2> reconstruct(const std::vector<Point<2>>& samples, const Options& options = {});
Reconstruction<3> reconstruct(const std::vector<Point<3>>& samples, const Options& options = {});

/// The yardsticks of the benchmark (src/yardsticks), on the same points:
/// CGAL's plain Delaunay triangulation (range insertion, spatially sorted), in seconds; every
/// timing is given as a ratio to it.
double delaunay_seconds(const std::vector<Point<2>>& points);
double delaunay_seconds(const std::vector<Point<3>>& points);
/// CGAL's Advancing Front Surface Reconstruction, default parameters: its triangles.
std::vector<Facet<3>> cgal_advancing_front(const std::vector<Point<3>>& points);
/// A triangle mesh: its points and its triangles on their indices.
struct Triangle_mesh {
  std::vector<Point<3>> points;
  std::vector<Facet<3>> triangles;
};
/// A denser mesh on the same surface: one step of Loop subdivision (CGAL), a new vertex on every
/// edge, so V + E vertices and 4 times the triangles (bunny00: 37,706 -> 150,818 vertices).
/// Throws Input_error when the triangles are not a manifold mesh.
Triangle_mesh loop_subdivided(const Triangle_mesh& coarse);
/// The two-sided Hausdorff distance between two triangle meshes (each its points and triangles),
/// from samples of each measured exactly to the other (CGAL's AABB tree): a lower bound within a
/// 400th of the meshes' diagonal. Infinite when either has no triangle of positive area.
double hausdorff_distance(const std::vector<Point<3>>& a_points, const std::vector<Facet<3>>& a,
                          const std::vector<Point<3>>& b_points, const std::vector<Facet<3>>& b);

const char* to_string(Method method);
const char* to_string(Carve_reason reason);
const char* to_string(Opening_kind kind);
const char* to_string(Label label);
const char* to_string(Label_reason reason);
const char* to_string(Surface_rule rule);
const char* to_string(Surface_kind kind);
const char* to_string(Cleaning cleaning);
bool parse_cleaning(const std::string& name, Cleaning& cleaning);  ///< cleaning_choices
/// The cleanings by name, as the command line, the viewer and Python take them: "auto, none, ..."
const char* cleaning_choices();
bool parse_kind(const std::string& name, Surface_kind& kind);  ///< closed, bordered, automatic
const char* version();

}  // namespace sculpt
