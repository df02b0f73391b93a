// SPDX-License-Identifier: GPL-3.0-or-later
#include "paper_figures.hpp"

#include <algorithm>
#include <cctype>
#include <stdexcept>

namespace sculpt::figures {
namespace {

using frontend::Shot;

// A shot of `input` ("example:NAME" or "cgal:FILE.off") at `stage`.
Shot shot(const std::string& input, const char* stage) {
  Shot s;
  s.method = to_string(Method::paper);  // the paper's figures show the paper's algorithm
  if (input.rfind("example:", 0) == 0) {
    s.example = input.substr(8);
  } else {
    s.input = input;  // resolved when the CGAL meshes are unpacked
  }
  s.stage = stage;
  return s;
}

Shot bordered(Shot s, double box_factor = sculpt::Options{}.box_factor) {
  s.bordered = true;
  s.box_factor = box_factor;
  return s;
}

// A bordered example reconstructed as if closed: what the closed algorithm does to a sheet.
Shot closed(Shot s) {
  s.closed = true;
  return s;
}

Shot with_layers(Shot s, std::vector<std::string> layers) {
  s.layers = std::move(layers);
  return s;
}

Shot zoomed(Shot s, float zoom) {
  s.zoom = zoom;
  s.wireframe = true;
  return s;
}

// Looking into a hemisphere's opening (its rim lies in the plane z = 0, the dome towards +z).
Shot from_below(Shot s) {
  s.yaw = 3.14159265f;
  s.pitch = 0.45f;
  return s;
}

Shot wire(Shot s) {
  s.wireframe = true;
  return s;
}

// The same input by one of the peers the paper compares with.
Shot with_method(Shot s, Method method) {
  s.method = to_string(method);
  return s;
}

}  // namespace

// A panel's claim, asserted by tests/figures_test.cpp.
Claim closed_manifold_claim(long components, long samples_left_off_at_most) {
  Claim claim;
  claim.asserted = true;
  claim.closed_manifold = true;
  claim.components = components;
  claim.samples_left_off = {0, samples_left_off_at_most};
  return claim;
}

// Exactly the counts the text gives: a text whose numbers drift from the result fails its test.
Claim defects_claim(long non_manifold_edges, long samples_left_off, long components) {
  Claim claim;
  claim.asserted = true;
  claim.non_manifold_edges = {non_manifold_edges, non_manifold_edges};
  claim.samples_left_off = {samples_left_off, samples_left_off};
  claim.components = components;
  return claim;
}

Claim border_claim(long loops, long edges_at_least, long edges_at_most) {
  Claim claim;
  claim.asserted = true;
  claim.border_loops = loops;
  claim.border_edges = {edges_at_least, edges_at_most};
  return claim;
}

void claim(Figure& figure, const std::string& suffix, Claim claim) {
  for (auto& image : figure.images) {
    if (image.suffix == suffix) {
      image.claim = claim;
      return;
    }
  }
  throw std::logic_error(figure.id + " has no panel " + suffix);
}

const std::vector<Figure>& paper_figures() {
  static const std::vector<Figure> figures = [] {
    std::vector<Figure> f;
    f.push_back(
        {"fig01",
         "Fig. 1 The illustration of the sculpting idea in 3D space.",
         "Figure 1(a) shows the convex object from straight Delaunay triangulation. Figure 1(b) "
         "shows the concave regions being sculpted out.",
         "the built-in `bumpy` (6000 samples on a sphere with dents and bumps)",
         "The paper's model is not available; a bumpy sphere shows the concavities well.",
         {{"a", "the convex hull: all-sample tetrahedra of DT(S + BBV)",
           "The Delaunay tetrahedra whose four corners are all samples fill the convex hull: every "
           "dent is bridged over. Sculpting starts from this solid.",
           shot("example:bumpy", "hull")},
          {"b", "the concavities sculpted out",
           "The tetrahedra bridging the dents are gone, broken by the outer concave poles inserted "
           "above them; the skin of what is left passes through every sample.",
           shot("example:bumpy", "surface")}}});
    f.push_back(
        {"fig02",
         "Fig. 2 The illustration of the sculpting idea in 2D plane.",
         "In Fig. 2(a), the green points are the input sample set and the blue lines are from "
         "their Delaunay triangulation. In Fig. 2(b), the outside triangles of the actual shape "
         "are removed. Finally, the skin is extracted as a set of segments that represent the "
         "reconstructed boundaries shown in Fig. 2(c).",
         "the built-in `blob` (150 samples on a smooth closed curve)",
         "Our DT also has the box corners BBV, so (a) shows edges leaving the frame; (b) is "
         "the sculpted solid, the triangles left when the outer concave poles are in, filled "
         "without its edges.",
         {{"a", "samples and their Delaunay triangulation",
           "Every Delaunay triangle of the samples and the box corners, inside the curve or out: "
           "the material the sculpting cuts from.",
           shot("example:blob", "delaunay")},
          {"b", "the outside triangles removed",
           "Only triangles with three sample corners are kept, so those reaching a box corner "
           "go at once; of the rest, the outer concave poles, once inserted, break those that "
           "span a concavity. What remains is the solid, drawn as one fill (the solid stage "
           "also draws the removed triangles, layer sculpted-away, left out here as in the "
           "paper).",
           with_layers(shot("example:blob", "solid"), {"solid", "samples"})},
          {"c", "the boundary",
           "The curve is the solid's skin: the edges with solid on one side only, joining each "
           "sample to its two neighbours.",
           shot("example:blob", "surface")}}});
    {
      Shot medial = with_layers(shot("example:blob-dense", "propagation"),
                                {"polar-balls", "inner-poles", "outer-poles", "samples"});
      medial.ball_every = 16;
      f.push_back(
          {"fig03",
           "Fig. 3 The internal and external medial axis and the medial circles of a closed "
           "curve in two dimensions.",
           "Figure 3 shows a two-dimensional example. The medial axis transformation (MAT) is the "
           "set of medial balls.",
           "the built-in `blob-dense` (600 samples)",
           "The medial axis is approximated by the poles of a dense sample (inner red, outer "
           "blue); one polar circle in 16 is drawn.",
           {{"", "inner and outer poles with polar circles",
             "With a dense sample the poles crowd along the medial axis, inner poles inside and "
             "outer poles outside, and polar circles approach medial circles. The separation "
             "rests on this: an inner polar circle holds no outer pole.",
             medial}}});
    }
    {
      Shot pair = with_layers(shot("example:star", "poles"),
                              {"poles", "samples", "focus-balls", "focus-cubes", "focus-poles"});
      pair.focus_sample = 37;
      f.push_back(
          {"fig04",
           "Fig. 4 (a) The distribution of all the polar circles (black circles) centered at the "
           "poles (red points shown in (b)) in 2D plane. (b) The illustration of a pair of polar "
           "circles and its pair of corresponding inscribed squares.",
           "From the observation of the distribution, each inner polar circle contains no outer "
           "poles. On the contrary, each outer polar circle also contains no inner poles. [...] "
           "Fig. 4(b) highlights a pair of polar circles (in the 2D case) which are colored as red "
           "and pink respectively. A pair of corresponding inscribed squares is also shown in the "
           "figure.",
           "the built-in `star` (200 samples)",
           "(a) draws the poles' circles without the Delaunay and Voronoi lines the paper has "
           "beneath them. (b) shows one sample's two polar circles and squares in one colour: "
           "the inner circle is the small one inside the star, the outer one is so large that "
           "most of it lies beyond the frame.",
           {{"a", "all polar circles",
             "Each sample has two poles, the far ends of its Voronoi cell on either side of the "
             "curve, each the centre of a polar circle through samples and empty of them.",
             shot("example:star", "poles")},
            {"b", "a sample's two polar circles and their inscribed squares",
             "One sample's pair. Any pole inside a labelled pole's inscribed square gets the same "
             "label: the square lies inside the circle, and a k-d tree finds its poles fast.",
             pair}}});
    }
    {
      Shot midway = shot("example:star", "propagation");
      midway.step = 160;
      f.push_back(
          {"fig05",
           "Fig. 5 The detailed pseudo-code for the pole-separation procedure.",
           "Figure 5 shows the detailed pseudo-code for a complete description of the "
           "pole-separation procedure.",
           "the built-in `star`; the pseudo-code below is the one our implementation runs",
           "The paper's pseudo-code is missing from its text; ours is written out in the "
           "gallery with the counts of one run. The picture is the separation after 160 "
           "labelling events: the pole just labelled and the ball and square that labelled it.",
           {{"", "the pole separation after 160 events",
             "The labelling spreads from the convex seeds: a labelled pole labels the poles in "
             "its inscribed square alike, and its partner the opposite way. Here 160 events have "
             "happened; the panel's pseudo-code marks the line that ran last.",
             midway}}});
    }
    f.push_back(
        {"fig06",
         "Fig. 6 An example of a two-dimensional closed curve reconstruction.",
         "Figure 6(a) shows a set of input sample points S. Figure 6(b) is the Voronoi diagram of "
         "the sample points. Figure 6(c) demonstrates the separation of poles. [...] Figure 6(d) "
         "is the Delaunay triangulation of S + OUP. Figure 6(e) shows the resulting line "
         "segments after the extraction process.",
         "the built-in `star` (200 samples)",
         "",
         {{"a", "the samples S",
           "The input: 200 points on a closed curve, nothing more (no order, no normals).",
           shot("example:star", "samples")},
          {"b", "the Voronoi diagram",
           "Each sample's Voronoi cell is long and thin across the curve; its far corners on "
           "either side are the sample's poles.",
           shot("example:star", "voronoi")},
          {"c", "separated poles: inner (red) and outer concave (blue)",
           "The poles are separated. Inner poles trace the inner medial axis; of the outer "
           "poles, only the concave ones between the arms are kept for insertion (the convex "
           "ones lie far outside the picture).",
           shot("example:star", "outer-concave")},
          {"d", "DT(S + OUP)",
           "The outer concave poles are inserted: every triangle that spanned a valley between "
           "two arms had one in its circumcircle and is gone.",
           shot("example:star", "sculpted-delaunay")},
          {"e", "the extracted curve",
           "What remains of the all-sample triangles is the star's inside; its boundary edges "
           "are the curve, through every sample in order.",
           shot("example:star", "surface")}}});
    f.push_back(
        {"fig07",
         "Fig. 7 An example of a three-dimensional closed surface reconstruction (a torso model).",
         "Figure 7(a) shows the set of input sample points S. In Fig. 7(b), the red points "
         "represent the set of the inner poles IP and the orange represent a part of the set of "
         "the outer concave poles OUP. Figure 7(c) illustrates the resulting triangulated "
         "surface and its shading. Figure 7(d) is a zoom-in of Fig. 7(c).",
         "the built-in `torso`",
         "A generated torso-like blob stands in for the paper's scan.",
         {{"a", "the samples",
           "The same steps in 3D: the samples of a closed surface, with no normals.",
           shot("example:torso", "samples")},
          {"b", "inner poles (red) and outer concave poles (orange)",
           "Inner poles fill the inside along the medial axis; outer concave poles hover over "
           "the concave regions, where tetrahedra of the hull bridge the surface.",
           shot("example:torso", "outer-concave")},
          {"c", "the shaded surface",
           "Inserting the outer concave poles removed the bridging tetrahedra; the skin of the "
           "all-sample tetrahedra left is a closed surface through every sample.",
           shot("example:torso", "surface")},
          {"d", "a zoom",
           "Closer, with the edges: the triangles join neighbouring samples, the surface "
           "interpolates them.",
           zoomed(shot("example:torso", "surface"), 0.4f)}}});
    f.push_back(
        {"fig08",
         "Fig. 8 An example of the effect of all the concave poles on the creation of the "
         "boundary (a foot).",
         "In Fig. 8(a), the blue points are the sample data and the red points represent all the "
         "inner poles IP. [...] Notice that some inner poles associated with the boundary sample "
         "points are located in the outer region. Using such characteristics with our proposed "
         "extraction rule, the boundary is created and a bordered surface is reconstructed as "
         "shown in the bottom of Fig. 8(b).",
         "the built-in `saddle` (z = x^2 - y^2, 40 x 40 jittered samples)",
         "The saddle stands in for the foot. A hemisphere shows the rule's limit: its border cuts "
         "across the rim in 13 long chords, the slivers between them and the rim kept (Fig. 13a "
         "and Table 1), because facets there have an outer apex and no inserted pole breaks "
         "them. Panel (d) is not the paper's: the robust method's bordered rule removes them.",
         {{"a", "all concave poles UP inserted: inner (red) and outer (orange)",
           "For a bordered surface all concave poles UP are inserted, inner ones too: near the "
           "border, inner poles of border samples fall outside the sheet and cut it there.",
           bordered(shot("example:saddle", "outer-concave"))},
          {"b", "closed: the sheet breaks into the skins of thin slivers, with no border anywhere",
           "The closed method on the same sheet, for comparison: a sheet has no inside, so only "
           "thin slivers survive and their skins double the sheet, with no border.",
           wire(closed(shot("example:saddle", "surface")))},
          {"c", "bordered: the border is created",
           "Bordered again, by the paper's extraction rule: the facets kept are those with an "
           "outer pole for an apex, and the sheet ends where the samples end.",
           wire(bordered(shot("example:saddle", "surface")))},
          {"d", "robust rule: the hemisphere's opening found",
           "Not the paper's: the robust method's bordered rule on a hemisphere, seen into its "
           "opening. The paper's rule cuts across the rim (Fig. 13a); here the triangles across "
           "the opening, far wider than the gaps between samples (violet), are removed and the "
           "border (orange) follows the rim.",
           from_below(
               bordered(with_method(shot("example:hemisphere", "surface"), Method::robust)))}}});
    f.back().contradiction =
        "Our (b) is the closed rule on the sheet, for comparison: 428 non-manifold edges and no "
        "border; the paper's bordered result is our (c). On a hemisphere the paper's rule cuts "
        "across the rim in 13 chords; (d) is the robust rule, following the rim.";
    claim(f.back(), "b", [] {
      Claim c = defects_claim(428, 292, 31);
      c.border_edges = {0, 0};
      return c;
    }());
    claim(f.back(), "c", border_claim(1, 1, -1));
    claim(f.back(), "d", border_claim(1, 40, -1));
    f.push_back(
        {"fig09",
         "Fig. 9 An example of a three-dimensional bordered surface reconstruction (a hyper "
         "sheet).",
         "Figure 9(a) shows the set of input sample points S. In Fig. 9(b), the red points "
         "represent a part of the set of inner poles IP and the orange represent a part of the "
         "set of outer poles OP. Figure 9(c) illustrates the resulting triangulated surface and "
         "its shading. Fig. 9(d) is a zoom-in from Fig. 9(c).",
         "the built-in `saddle` (z = x^2 - y^2, 40 x 40 jittered samples)",
         "",
         {{"a", "the samples", "A sheet's samples: a saddle, bordered all round.",
           bordered(shot("example:saddle", "samples"))},
          {"b", "poles of both sides (red, orange)",
           "Poles on both sides of the sheet. Which side is called inner is arbitrary for a "
           "sheet; the bordered rule inserts both.",
           bordered(shot("example:saddle", "outer-concave"))},
          {"c", "the shaded surface",
           "The bordered surface through every sample, left open: the paper's extraction rule "
           "drew it, its border in orange.",
           bordered(shot("example:saddle", "surface"))},
          {"d", "a zoom", "Closer, with the edges.",
           bordered(zoomed(shot("example:saddle", "surface"), 0.4f))}}});
    f.push_back(
        {"fig10",
         "Fig. 10 The reconstruction from the sample points with uneven distribution (a rocker "
         "arm).",
         "Figure 10(a) is the reconstruction of a uniform distribution case. In contrast, Fig. "
         "10(b) shows the result of a non-uniform distribution case. It is obvious that our "
         "proposed algorithm is stable and is insensitive to the data non-uniformity.",
         "the built-in `bumpy` (6000 samples) and `bumpy-nonuniform` (its +x side thinned 3:1)",
         "A bumpy sphere stands in for the rocker arm.",
         {{"a", "uniform sampling", "A uniform sample of a bumpy sphere: the reference.",
           wire(shot("example:bumpy", "surface"))},
          {"b", "non-uniform sampling",
           "One side thinned three to one. Poles follow the local spacing, so the sculpting "
           "needs no global density and the surface stays whole.",
           wire(shot("example:bumpy-nonuniform", "surface"))},
          {"c", "a zoom on the thinned side",
           "On the thinned side the triangles are larger but still join neighbouring samples.",
           zoomed(shot("example:bumpy-nonuniform", "surface"), 0.5f)}}});
    f.push_back(
        {"fig11",
         "Fig. 11 An example of the effect of poles on the reconstruction of the geometric sharp "
         "features (a shoe model).",
         "Figure 11 demonstrates the resulting triangulated surface of a shoe model using the "
         "proposed sculpting algorithm, which highlights the clean and clear sharp edges and "
         "corners located in the convex regions.",
         "CGAL's `fandisk.off` (6475 vertices)",
         "fandisk stands in for the shoe. Its CAD sampling gives conflicts and non-manifold "
         "edges at sharp edges (Table 1).",
         {{"", "sharp edges and corners",
           "Convex sharp edges come out clean: no pole is inserted over them, so the hull's "
           "tetrahedra stay. At concave creases the regular CAD sampling confuses the pole "
           "labels, the paper's method's weak point (see Table 1): 386 non-manifold edges, 765 "
           "samples off the surface.",
           wire(shot("cgal:fandisk.off", "surface"))},
          {"robust", "the robust method on the same samples",
           "Not the paper's: the robust default on the same points, one closed manifold through "
           "every sample, its sharp edges kept as the samples give them.",
           wire(with_method(shot("cgal:fandisk.off", "surface"), Method::robust))}}});
    f.back().contradiction =
        "The paper shows clean sharp edges; on fandisk (a regularly sampled CAD part) the paper "
        "method leaves 386 non-manifold edges and 765 samples off. The robust method's result "
        "is the panel (robust).";
    claim(f.back(), "", defects_claim(386, 765, 7));
    claim(f.back(), "robust", closed_manifold_claim(1, 0));
    f.push_back(
        {"fig12",
         "Fig. 12 Several examples of closed surface reconstruction. (a) A three-hole model. (b) "
         "An oil pump model. (c) A hand model. (d) A baby dragon model.",
         "Figure 12(a) shows a three-hole model. Figure 12(b) displays an oil pump model, which "
         "is complicated with many more features. Then, Fig. 12(c) shows that the output is a "
         "closed hand model although there obviously exists a boundary in the set of the input "
         "sample points.",
         "the built-in `three-holes` and `torus-knot`, CGAL's `hand.off` and "
         "`ChineseDragon-10kv.off`",
         "A tube around a torus knot stands in for the oil pump; CGAL's Chinese dragon for "
         "the baby dragon.",
         {{"a", "three holes",
           "Genus three: the holes are concavities too, opened by the outer concave poles that "
           "the separation labels through them.",
           shot("example:three-holes", "surface")},
          {"b", "torus-knot tube",
           "A thin knotted tube: concave all along, and close to itself where it crosses.",
           shot("example:torus-knot", "surface")},
          {"c", "hand",
           "A scanned hand, open at the wrist. The paper's rule closes it, as the paper says, "
           "but not cleanly: the verdict reports 249 non-manifold edges and a stray second "
           "component. The robust method closes it as one manifold (next panel).",
           shot("cgal:hand.off", "surface")},
          {"c-robust", "hand, robust method",
           "Not the paper's: the robust default on the same hand, one closed manifold through "
           "every sample, as the paper's caption says of its own.",
           with_method(shot("cgal:hand.off", "surface"), Method::robust)},
          {"d", "dragon", "A scanned dragon: fine detail and uneven sampling.",
           shot("cgal:ChineseDragon-10kv.off", "surface")}}});
    f.back().contradiction =
        "The paper says the hand comes out closed; on CGAL's hand the paper method leaves 249 "
        "non-manifold edges and a second piece (denser, subdivided hands too). The robust "
        "method's hand is panel c-robust.";
    claim(f.back(), "c", defects_claim(249, 28, 2));
    claim(f.back(), "c-robust", closed_manifold_claim(1, 0));
    f.push_back(
        {"fig13",
         "Fig. 13 Several examples of bordered surfaces reconstruction. (a) A hand model. (b) A "
         "shampoo bottle model. (c) A monkey bar. (d) A golf club model. (e) An automobile "
         "exterior surface.",
         "Figure 13(b) is a shampoo bottle model. Figure 13(c) displays a monkey bar. Figure "
         "13(d) displays a golf club model. Figure 13(e) reveals a good surface reconstruction "
         "of an automobile exterior surface.",
         "the built-in `hemisphere`, `saddle` and `monkey-saddle` (default box factor 5, and "
         "1.5)",
         "The paper's scans are not available; generated sheets stand in. Panels (a), (c) and "
         "(d) are the paper's extraction rule: the hemisphere's border, seen from below, cuts "
         "across its rim in 13 long chords, and the monkey saddle needs a box factor "
         "of 1.5 (with 5, its flat centre has both poles near the box, and 860 non-manifold "
         "edges appear). Panels (b) and (e) are not the paper's: the robust method's bordered "
         "rule, at the default box, finds both borders whole.",
         {{"a", "hemisphere, paper's rule",
           "A hemisphere, bordered, seen into its opening: the paper's rule keeps slivers across "
           "the rim, its border 13 long chords, since facets there have an outer apex and no "
           "inserted pole breaks them.",
           from_below(bordered(shot("example:hemisphere", "surface")))},
          {"b", "hemisphere, robust rule",
           "The robust method's bordered rule on the same samples: the slivers across the rim are "
           "far wider than the gaps between samples (violet) and go; the border (orange) follows "
           "the rim.",
           from_below(
               bordered(with_method(shot("example:hemisphere", "surface"), Method::robust)))},
          {"c", "saddle, paper's rule", "A saddle: here the paper's rule finds the whole border.",
           bordered(shot("example:saddle", "surface"))},
          {"d", "monkey saddle, paper's rule, box 1.5",
           "A monkey saddle by the paper's rule, with a box 1.5 times the samples' bounds: with "
           "the default 5, its flat centre gets poles near the box and non-manifold edges.",
           bordered(wire(shot("example:monkey-saddle", "surface")), 1.5)},
          {"e", "monkey saddle, robust rule, box 5",
           "The robust method's bordered rule at the default box: one border loop, no "
           "non-manifold edge, every sample on it.",
           bordered(
               wire(with_method(shot("example:monkey-saddle", "surface"), Method::robust)))}}});
    f.back().contradiction =
        "The paper's (a) is a hand left open; on our hemisphere the paper's rule closes most of "
        "the opening, its border 13 chords across the rim. Panel (b) is the robust rule, whose "
        "border follows the rim.";
    claim(f.back(), "a", border_claim(1, 13, 13));
    claim(f.back(), "b", border_claim(1, 40, -1));
    f.push_back(
        {"fig14",
         "Fig. 14 The comparison of our proposed algorithm with the power crust algorithm. "
         "(a) The reconstruction from the proposed algorithm. The number of output points is "
         "1748. (b) The reconstruction from the power crust without a decimated post process. "
         "The number of output points is 14927.",
         "Figure 14 demonstrates the different reconstructed results between our proposed "
         "algorithm and the power crust algorithm. [...] Notice that the output number of points "
         "of the power crust without a decimated post process is 8 times larger than the initial "
         "sample points.",
         "CGAL's `knot1.off` (3200 vertices), for both methods",
         "The paper's 1,748 points are the power crust distribution's `hotdogs` sample, which is "
         "GPL-2 data; Sculpt ships no third-party data, so CGAL's knot1 (installed with "
         "libcgal-demo) stands in. We measure 14.2 power crust vertices per sample on it (45,291 "
         "for 3,200; 11.3 on CGAL's bunny00), more than the paper's 8.5 (14,927 for 1,748): the "
         "power crust here is "
         "our own (src/methods/power_crust), and its vertices are those of the power diagram, "
         "one per regular cell, none merged.",
         {{"a", "our reconstruction",
           "Sculpting interpolates: the surface's vertices are exactly the 3200 samples.",
           wire(shot("cgal:knot1.off", "surface"))},
          {"b", "the power crust",
           "The power crust's faces lie between the power cells of inner and outer poles: a "
           "closed surface of genus 1 too, but through vertices of the power diagram, about 14 "
           "per sample, none of them a sample.",
           wire(with_method(shot("cgal:knot1.off", "surface"), Method::power_crust))}}});
    f.push_back(
        {"fig15",
         "Fig. 15 Top row is a knot and bottom row is a femur. (a) The reconstruction from "
         "the proposed algorithm. (b) The reconstruction from the modified co-cone. (c) The "
         "reconstruction from the tight co-cone.",
         "Figure 15(a) shows the reconstructed result from our sculpting algorithm. Figure 15(b) "
         "shows the reconstructed result from the modified co-cone without a hole-filling "
         "process. Figure 15(c) shows the reconstructed result from the tight co-cone.",
         "CGAL's `knot1.off` and `femur.off`",
         "The co-cones are our own (src/methods/cocone), from the papers and the constants of "
         "the authors' Tight Cocone program. On the knot every column is closed (the paper "
         "method but for 2 non-manifold edges). On the femur none is right: the paper method "
         "has hundreds of non-manifold edges, the modified co-cone about 90 holes, the tight "
         "co-cone a watertight skin with a few dozen non-manifold edges that leaves about 550 "
         "samples "
         "inside it; the paper reports its own method best there, and our robust default is "
         "(10 samples off the surface, no defect).",
         {{"a-knot", "the knot by sculpting (top row, column a)",
           "Shaded, it looks closed and smooth, but the verdict finds a few non-manifold "
           "edges; the robust method closes it as one manifold.",
           shot("cgal:knot1.off", "surface")},
          {"b-knot", "the knot by the modified co-cone (top row, column b)",
           "Well sampled everywhere: no sample is undersampled and the co-cone is closed.",
           with_method(shot("cgal:knot1.off", "surface"), Method::cocone)},
          {"c-knot", "the knot by the tight co-cone (top row, column c)",
           "Every sample has an umbrella, so peeling stops at the co-cone's surface: the same "
           "triangles, now bounding a solid.",
           with_method(shot("cgal:knot1.off", "surface"), Method::tight_cocone)},
          {"a-femur", "the femur by sculpting (bottom row, column a)",
           "A femur: thin and unevenly sampled, where the paper's method leaves 697 "
           "non-manifold edges (Table 1); the robust method closes it (last panel).",
           shot("cgal:femur.off", "surface")},
          {"b-femur", "the femur by the modified co-cone (bottom row, column b)",
           "Its ends are undersampled: the samples there impose no co-cone and the surface has "
           "holes (orange) instead of wrong triangles, as in the paper.",
           with_method(shot("cgal:femur.off", "surface"), Method::cocone)},
          {"c-femur", "the femur by the tight co-cone (bottom row, column c)",
           "The holes are closed by the peeled cells' skin, watertight; where the co-cone "
           "gave no umbrella the cells decide, and a few edges are non-manifold (red).",
           with_method(shot("cgal:femur.off", "surface"), Method::tight_cocone)},
          {"robust-femur", "the femur by the robust method (not in the paper)",
           "Not the paper's: the robust default on the same femur, closed with no non-manifold "
           "edge and a handful of samples off the surface.",
           with_method(shot("cgal:femur.off", "surface"), Method::robust)}}});
    f.back().contradiction =
        "The paper reports its method best on the femur; on CGAL's femur it leaves 697 "
        "non-manifold edges and 70 samples off, so the robust method's femur is shown last.";
    claim(f.back(), "a-knot", defects_claim(2, 0, 1));
    claim(f.back(), "b-knot", closed_manifold_claim(1, 0));
    claim(f.back(), "a-femur", defects_claim(697, 70, 1));
    claim(f.back(), "robust-femur", closed_manifold_claim(1, 10));
    return f;
  }();
  return figures;
}

const Figure* find_figure(const std::string& id) {
  const std::string digits = id.rfind("fig", 0) == 0 ? id.substr(3) : id;
  const bool number = !digits.empty() && digits.size() <= 2 &&
                      std::all_of(digits.begin(), digits.end(), [](char c) {
                        return std::isdigit(static_cast<unsigned char>(c));
                      });
  if (!number) return nullptr;
  const std::string wanted = "fig" + std::string(digits.size() == 1 ? "0" : "") + digits;
  for (const auto& figure : paper_figures()) {
    if (figure.id == wanted) return &figure;
  }
  return nullptr;
}

std::string panel_name(const Figure& figure, std::size_t panel) {
  std::string name = "Fig. " + std::to_string(std::stoi(figure.id.substr(3)));
  const std::string& suffix = figure.images.at(panel).suffix;
  return suffix.empty() ? name : name + " (" + suffix + ")";
}

}  // namespace sculpt::figures
