// SPDX-License-Identifier: GPL-3.0-or-later
// The paper's figures of its method (sections 2-3): the sculpting idea, the medial axis and
// the poles, the pseudo-code, a curve and a torso, the concave poles. Figs. 1-8.
#include <vector>

#include "figure_writing.hpp"

namespace sculpt::figures::writing {

void add_method_figures(std::vector<Figure>& f) {
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
}

}  // namespace sculpt::figures::writing
