# SPDX-License-Identifier: GPL-3.0-or-later
"""Sculpt: Delaunay-based curve and surface reconstruction (Kuo & Yau 2003, and its peers).

    import sculpt
    points = sculpt.example("bumpy")              # or sculpt.read_points("scan.ply"), any (n, 3) array
    print(sculpt.methods(dimension=3))            # the surface methods, the default first
    result = sculpt.reconstruct(points)           # method="robust" (sculpt.methods() lists them all)
    print(result.verdict)                         # "closed 2-manifold of genus 0: 1 component, ..."
    result.surface                                # (f, 3) triangles, indices into result.samples
    result.stages["poles"].radius                 # every stage as read-only numpy arrays
    image = sculpt.render(result, stage="poles")  # (height, width, 4) RGBA, as `sculpt render` draws
    sculpt.write(result, "bumpy.stl")
    scan = sculpt.read_file("scan.ply")           # points, normals, colors, triangles
    sculpt.write(sculpt.reconstruct(scan.points), "part.ply", normals=scan.normals, colors=scan.colors)

The same core, methods, stage names, statistics and error messages as the `sculpt` command.
Reconstruction runs without the GIL; progress(stage, fraction) may return False to cancel.
"""

from ._sculpt import (
    CARVE_REASONS,
    OPENING_KINDS,
    DEFAULT_METHOD,
    LABEL_REASONS,
    LABELS,
    Cancelled,
    DuplicatePoints,
    InputError,
    Reconstruction,
    example,
    examples,
    merge_duplicates,
    methods,
    read_points,
    reconstruct,
    render,
    stages,
    version,
    write,
)

from .conversions import to_open3d, to_trimesh
from .files import PointFile, read_file

__version__ = version()


__all__ = [
    "CARVE_REASONS",
    "OPENING_KINDS",
    "DEFAULT_METHOD",
    "LABEL_REASONS",
    "LABELS",
    "Cancelled",
    "DuplicatePoints",
    "InputError",
    "PointFile",
    "Reconstruction",
    "example",
    "examples",
    "merge_duplicates",
    "methods",
    "read_file",
    "read_points",
    "reconstruct",
    "render",
    "stages",
    "to_open3d",
    "to_trimesh",
    "version",
    "write",
]
