// SPDX-License-Identifier: GPL-3.0-or-later
// The paragraphs of the Explanation panel. Each says what is drawn, why it matters and what to
// look for; where a method reads a stage differently (the labelling of the paper against the
// confidence labelling, the solid of sculpting against the alpha shape's), it says so.
#include "explanations.hpp"

namespace sculpt::frontend {
namespace {

std::string cells(int dimension) {
  return dimension == 2 ? "triangles" : "tetrahedra";
}
std::string cell(int dimension) {
  return dimension == 2 ? "triangle" : "tetrahedron";
}
std::string facets(int dimension) {
  return dimension == 2 ? "edges" : "triangles";
}

std::string labelling(Method method, Surface_kind kind) {
  if (method == Method::paper) {
    return std::string(
               "Pole separation (Kuo & Yau, sec. 3.1.1): the convex poles, Voronoi vertices "
               "made with a box corner, are outer for sure") +
           (kind == Surface_kind::bordered
                ? "; a bordered surface starts from one of them only, since its two sides meet "
                  "around the border. "
                : ". ") +
           "Breadth first, each labelled pole gives its label to every pole inside the cube "
           "inscribed in its polar ball (same side: the balls overlap deeply) and the opposite "
           "label to the other pole of each of its samples. The first label offered stays. Look "
           "for conflicts: a pole offered both labels is where the rules disagree, at sharp "
           "edges and thin parts; one wrong early offer spreads.";
  }
  return "The poles labelled by confidence, as in the power crust (Amenta, Choi & Kolluri, "
         "sec. 5): the convex poles are outer; then the pole whose evidence is most one-sided "
         "is labelled next, and offers its label to the poles whose balls meet its own deeply at "
         "a sample (weight: the cosine of the angle between the balls) and the opposite label "
         "to its sample's other pole when the two are antipodal. Watch the confident poles go "
         "first, far from the surface's trouble spots; cyan poles were labelled against strong "
         "evidence.";
}

std::string solid(Method method, int dimension) {
  switch (method) {
    case Method::alpha_shape:
      return "The alpha solid: the Delaunay " + cells(dimension) +
             " whose circumball is smaller than alpha. One radius for the whole shape: where "
             "the samples are sparser than alpha it has holes, where a gap is narrower it is "
             "filled. Look at thin parts and concavities, then change alpha.";
    case Method::tight_cocone:
      return "The cells the peeling did not reach: the outside was peeled from the box inward, "
             "around each sample with an umbrella only on the side first reached, and never "
             "across the umbrella. What is left bounds a watertight surface, even where the "
             "co-cone had holes. Look for cells hanging on by an edge: non-manifold edges.";
    case Method::boissonnat:
      return "Boissonnat's solid: the hull's " + cells(dimension) +
             " left when every sample reached the boundary, removed one at a time, the one "
             "whose circumsphere bulges farthest out first, only where the boundary stays a "
             "polyhedron through the same samples. It can never open a hole: a torus keeps a "
             "membrane, an annulus stays a disc.";
    default:
      return "The sculpted solid (Kuo & Yau, sec. 3.3): the " + cells(dimension) +
             " whose vertices are all samples and that survived the outer concave poles; the "
             "hull's cells sculpted away (their circumball held an outer pole) are drawn beside "
             "them in salmon. The surface is this solid's skin; look for cells left in a "
             "concavity or missing in a thin part.";
  }
}

// The carving replay (scene/carving_replay.hpp): what one step is, by method.
std::string carving(Method method, Surface_kind kind, int dimension) {
  if (joins_neighbours(method, kind, dimension))
    return "No cells are carved here: a bordered curve bounds no region, so the robust method "
           "joins each sample to its nearest neighbours instead (the NN-crust's rule, keeping "
           "the curve's ends), and there is no hull to carve.";
  const std::string ball = dimension == 2 ? "circumcircle" : "circumball";
  if (method == Method::boissonnat)
    return "Boissonnat's sculpting step by step: at each step the removable " + cell(dimension) +
           " whose circumsphere bulges farthest beyond the boundary leaves, while the boundary "
           "stays a polyhedron, until every sample is on it. Watch the concavities open from "
           "the outside in.";
  if (inserts_poles(method, kind, dimension))
    return "The sculpting as the paper does it (sec. 3.3): the poles are inserted one by one, "
           "and a pole inserted into a Delaunay triangulation destroys every " +
           cell(dimension) + " whose " + ball +
           " holds it. Each step is a pole whose insertion destroys some of the hull's " +
           cells(dimension) + ", highlighted" +
           (dimension == 2 ? ", with their " + ball + "s" : "") +
           " (a pole that destroys none of them is no step). What is left when the last pole is "
           "in is the solid. The poles go in the order "
           "listed; any order ends at the same triangulation.";
  return "The robust method's carving step by step: from the outside in, one " + cell(dimension) +
         " at a time, each cell judged outer (an outer pole in its " + ball +
         ", or its centre in an outer ball's power cell) leaves when its removal keeps the "
         "boundary a manifold, which never changes the topology. " +
         std::string(dimension == 2
                         ? "A hole opens as a cavity: outer cells enclosed by the solid, opened "
                           "at one cell in one step. "
                         : "A handle opens only where a whole group of outer cells leaves in one "
                           "step; a web one sample thin is never punched through into one. ") +
         "Some cells leave last to expose a sample buried in the solid.";
}

std::string surface(Method method, Surface_kind kind, int dimension) {
  std::string what = "The reconstruction: " + facets(dimension) +
                     (interpolates(method) ? " through the samples" : " near the samples");
  switch (method) {
    case Method::power_crust:
      what +=
          ", the faces of the power diagram between inner and outer poles' cells: it does "
          "not interpolate, and has many more vertices than samples.";
      break;
    case Method::crust:
    case Method::cocone:
      what +=
          dimension == 2 ? "." : ", the candidates left after pruning, walked from the outside.";
      break;
    case Method::robust:
      what +=
          dimension == 3 && kind == Surface_kind::bordered
              ? ": the paper's bordered surface less the triangles spanning an opening "
                "(violet), those whose circumscribed circle is wider than 3 times the "
                "samples' spacing there (around each vertex, the median distance to the 6th "
                "nearest sample) with no sample near its centre, and, next to them, 2 times; "
                "the rest is pruned and walked as the co-cone's is, then mended: samples left off "
                "set in or attached, fans pinched at a vertex joined (or the smaller "
                "dropped), small loops filled by their least folded triangulation unless it "
                "covers an opening or folds back (a hole torn by noise)."
              : ".";
      break;
    default:
      what += ".";
  }
  what += kind == Surface_kind::bordered
              ? " A bordered result: its border loops (orange) should be where the samples end."
              : " The verdict says whether it is a closed manifold: holes are drawn in orange, "
                "non-manifold edges in red, and it counts samples left off.";
  return what;
}

}  // namespace

std::string explanation(Method method, Surface_kind kind, int dimension, scene::Stage stage) {
  using scene::Stage;
  switch (stage) {
    case Stage::samples:
      return "The input: points sampled on an unknown " +
             std::string(dimension == 2 ? "curve" : "surface") +
             ". Nothing joins them yet. Look at the density: every method needs the samples "
             "closer than the features they are to show, and sparse places are where they fail.";
    case Stage::delaunay:
      return "The Delaunay triangulation of the samples and the corners of a box 5 times their "
             "size: every " +
             cell(dimension) + " has an empty " +
             std::string(dimension == 2 ? "circumcircle" : "circumball") + ". The " +
             facets(dimension) + " of the " +
             std::string(dimension == 2 ? "curve are among its edges"
                                        : "surface are among its faces") +
             " when the sampling is dense; every method here chooses among them (the power "
             "crust builds its own).";
    case Stage::hull:
      return "The convex hull: the Delaunay " + cells(dimension) +
             " whose vertices are all samples. Sculpting starts from it and carves the outside "
             "away (Kuo & Yau, Fig. 1); for a convex shape there is nothing to carve.";
    case Stage::voronoi:
      return "The Voronoi diagram, dual of the Delaunay triangulation: each sample's cell holds "
             "the points nearer to it than to any other. Near a densely sampled " +
             std::string(dimension == 2 ? "curve" : "surface") +
             " the cells are long and thin, along the normal: that is what the poles" +
             std::string(dimension == 2 ? " read." : " and the co-cones read.");
    case Stage::poles:
      return "The poles (Amenta): p+, the farthest vertex of a sample's Voronoi cell, and p-, "
             "the farthest on the other side. They lie near the medial axis, inside and "
             "outside; their balls touch the samples and hold none. Look at a sample: one pole "
             "on each side of the " +
             std::string(dimension == 2 ? "curve." : "surface.");
    case Stage::seeds:
      return "The seeds: the convex poles, the Voronoi vertices made with a box corner (their "
             "samples' cells reach the box). They lie "
             "outside any surface of the samples, so they are outer for sure, and the labelling "
             "starts from them" +
             std::string(kind == Surface_kind::bordered && inserts_poles(method, kind, dimension)
                             ? "; bordered, only one of them does."
                             : ".");
    case Stage::propagation:
      return labelling(method, kind);
    case Stage::outer_concave:
      return kind == Surface_kind::bordered && inserts_poles(method, kind, dimension)
                 ? "The poles to insert, bordered: every labelled pole that is not convex (UP). "
                   "Inserted among the samples, they break the Delaunay cells on both sides of "
                   "the sheet."
                 : "The outer concave poles (OUP): outer, but not convex, so they sit in the "
                   "concavities. The cells whose circumball holds one are outside the shape; "
                   "inserting them breaks those cells (sec. 3.2).";
    case Stage::carving:
      return carving(method, kind, dimension);
    case Stage::sculpted_delaunay:
      if (kind == Surface_kind::bordered && inserts_poles(method, kind, dimension)) {
        return "DT(S + UP): the samples triangulated with every labelled pole that is not "
               "convex. The facets between samples with an outer pole for an apex are the "
               "candidates of the surface.";
      }
      return "DT(S + OUP): the samples triangulated with the outer concave poles. The cells "
             "whose vertices are all samples are the solid; the concavities are now cut off. "
             "The command line reads the same solid off the first triangulation by circumball "
             "queries, without building this one.";
    case Stage::crust_delaunay:
      return dimension == 2
                 ? "The crust's triangulation of the samples and the Voronoi vertices: a "
                   "Voronoi vertex sits near the medial axis, so the circle of an edge across "
                   "the shape holds one and the edge is broken; edges between neighbours on "
                   "the curve survive."
                 : "The crust's triangulation of the samples and their poles: a triangle "
                   "across the shape has a pole in its circumball and is broken; triangles on "
                   "the surface survive, with some extra ones the normal filter removes.";
    case Stage::candidates:
      return method == Method::crust
                 ? "The crust's candidate triangles: those of DT(S + P) between samples whose "
                   "normal agrees with the pole vectors. Pruned ones (red) sit on sharp edges "
                   "or hang free; the surface is the outer boundary of the rest."
                 : "The co-cone's candidates: the Delaunay triangles whose Voronoi edge crosses "
                   "the co-cone (a slab about the tangent plane) of each of their well-sampled "
                   "samples. Magenta samples were judged undersampled (Dey & Giesen) and impose "
                   "nothing; teal ones have no umbrella for the tight co-cone.";
    case Stage::front:
      return "The Advancing Front grows its surface from one seed triangle (the smallest), "
             "adding at each step a Delaunay triangle on an edge of the front, the border of "
             "what it has grown: the one most plausible (small, and little bent from its "
             "neighbour) among those that keep an oriented 2-manifold. Watch it stop where no "
             "triangle is plausible: that is where it leaves holes.";
    case Stage::alpha:
      return "The alpha shape at every alpha: the Delaunay cells join the solid in the order "
             "of their circumball's radius, smallest first. Small alphas leave the samples "
             "apart; large ones fill the hull. The method stops at the smallest alpha whose "
             "solid is one piece holding every sample, so one radius serves the whole shape: "
             "step past it and see cavities fill, step before it and see holes open.";
    case Stage::solid:
      return solid(method, dimension);
    case Stage::surface:
      return surface(method, kind, dimension);
  }
  return "";
}

}  // namespace sculpt::frontend
