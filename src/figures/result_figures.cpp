// SPDX-License-Identifier: GPL-3.0-or-later
// The paper's figures of its results (section 4 on): bordered surfaces, uneven sampling, sharp
// features, closed and bordered models, the power crust beside it, the knot and the femur. Figs.
// 9-15.
#include <vector>

#include "figure_writing.hpp"

namespace sculpt::figures::writing {

void add_result_figures(std::vector<Figure>& f) {
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
         from_below(bordered(with_method(shot("example:hemisphere", "surface"), Method::robust)))},
        {"c", "saddle, paper's rule", "A saddle: here the paper's rule finds the whole border.",
         bordered(shot("example:saddle", "surface"))},
        {"d", "monkey saddle, paper's rule, box 1.5",
         "A monkey saddle by the paper's rule, with a box 1.5 times the samples' bounds: with "
         "the default 5, its flat centre gets poles near the box and non-manifold edges.",
         bordered(wire(shot("example:monkey-saddle", "surface")), 1.5)},
        {"e", "monkey saddle, robust rule, box 5",
         "The robust method's bordered rule at the default box: one border loop, no "
         "non-manifold edge, every sample on it.",
         bordered(wire(with_method(shot("example:monkey-saddle", "surface"), Method::robust)))}}});
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
}

}  // namespace sculpt::figures::writing
