#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Lesson 1: the Voronoi diagram of samples on a curve, and its poles (Amenta's; Kuo & Yau sec. 3).

Reconstructs the built-in star, then draws with matplotlib what the first stages hold:
the Delaunay triangles of the samples, the Voronoi diagram (the triangles' circumcentres, joined
across shared edges), the poles coloured by the label the separation gave them, the two polar
balls of one sample, and the curve. Writes voronoi_and_poles.png (or the path given).

    python3 voronoi_and_poles.py [OUTPUT.png]
"""
import sys

import matplotlib

matplotlib.use("Agg")  # headless: write a file, open no window
import matplotlib.pyplot as plt
import numpy as np

import sculpt


def circumcentres(points, triangles):
    """The circumcentre of each triangle: the Voronoi vertices of a 2D Delaunay triangulation."""
    a, b, c = (points[triangles[:, k]] for k in range(3))
    ab, ac = b - a, c - a
    d = 2 * (ab[:, 0] * ac[:, 1] - ab[:, 1] * ac[:, 0])
    ab2, ac2 = (ab**2).sum(1), (ac**2).sum(1)
    x = (ac[:, 1] * ab2 - ab[:, 1] * ac2) / d
    y = (ab[:, 0] * ac2 - ac[:, 0] * ab2) / d
    return a + np.column_stack([x, y])


def voronoi_edges(triangles, centres):
    """Segments between the circumcentres of triangles that share an edge (a Voronoi edge each)."""
    edges = np.sort(triangles[:, [0, 1, 1, 2, 2, 0]].reshape(-1, 2), axis=1)
    owner = np.repeat(np.arange(len(triangles)), 3)
    order = np.lexsort((edges[:, 1], edges[:, 0]))
    edges, owner = edges[order], owner[order]
    shared = np.all(edges[1:] == edges[:-1], axis=1)
    return np.stack([centres[owner[:-1][shared]], centres[owner[1:][shared]]], axis=1)


def main():
    output = sys.argv[1] if len(sys.argv) > 1 else "voronoi_and_poles.png"
    result = sculpt.reconstruct(sculpt.example("star"), method="paper")
    print(result.verdict)
    samples, sites = result.samples, result.sites
    cells = result.stages["delaunay"].cells
    poles = result.stages["poles"]
    labels = result.stages["propagation"].labels

    fig, ax = plt.subplots(figsize=(8, 8))
    # Only the cells between samples: the box corners' cells reach far outside the picture.
    inner = cells[np.all(cells < len(samples), axis=1)]
    ax.triplot(sites[:, 0], sites[:, 1], inner, color="0.85", linewidth=0.5)
    segments = voronoi_edges(cells, circumcentres(sites, cells))
    for a, b in segments:
        ax.plot([a[0], b[0]], [a[1], b[1]], color="tab:cyan", linewidth=0.6)
    for code, colour in ((1, "tab:red"), (2, "tab:blue"), (0, "0.5")):
        chosen = labels == code
        ax.scatter(*poles.center[chosen].T, s=8, color=colour, label=f"{sculpt.LABELS[code]} poles")
    sample = 40  # its two polar balls: centred on its poles p+ and p-, through the sample
    for pole in (poles.positive_pole[sample], poles.negative_pole[sample]):
        if pole >= 0:
            ax.add_patch(plt.Circle(poles.center[pole], poles.radius[pole], fill=False,
                                    color="tab:purple"))
    for a, b in result.surface:
        ax.plot(*samples[[a, b]].T, color="black", linewidth=1.2)
    ax.scatter(*samples.T, s=6, color="tab:green", zorder=3, label="samples")
    ax.scatter(*samples[sample], s=40, color="tab:purple", zorder=4, label=f"sample {sample}")
    low, high = samples.min(0), samples.max(0)
    margin = 0.6 * (high - low)
    ax.set_xlim(low[0] - margin[0], high[0] + margin[0])
    ax.set_ylim(low[1] - margin[1], high[1] + margin[1])
    ax.set_aspect("equal")
    ax.legend(loc="upper right", fontsize=8)
    ax.set_title(f"Voronoi diagram and poles of the star ({len(samples)} samples)")
    fig.savefig(output, dpi=100)
    print(f"wrote {output}: {len(segments)} Voronoi edges, {len(poles.radius)} poles")


if __name__ == "__main__":
    main()
