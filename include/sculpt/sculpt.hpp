// SPDX-License-Identifier: GPL-3.0-or-later
/// \file
/// Sculpt: Delaunay-based curve and surface reconstruction by sculpting
/// (Kuo & Yau, "A Delaunay-based region-growing approach to surface reconstruction from
/// unorganized points", 2003, sections 3 and 4), and methods beyond the paper over the same stages.
///
/// This is the whole public API of the core. It is plain C++ with no CGAL or GL in it, so that
/// the command line, the tests and the viewer compile against it quickly; the algorithm itself is
/// instantiated once per dimension in src/core2d and src/core3d.
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
#include <stdexcept>
#include <string>
#include <vector>

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
