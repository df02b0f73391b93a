"""Sculpt: Delaunay-based curve and surface reconstruction (Kuo & Yau 2003, and its peers).

    import sculpt
    points = sculpt.example("bumpy")              # or sculpt.read_points("scan.ply"), any (n, 3) array
    result = sculpt.reconstruct(points)           # method="robust" (sculpt.methods() lists them all)
    print(result.verdict)                         # "closed 2-manifold, 1 component, genus 0"
    result.surface                                # (f, 3) triangles, indices into result.samples
    result.stages["poles"].radius                 # every stage as read-only numpy arrays
    image = sculpt.render(result, stage="poles")  # (height, width, 4) RGBA, as `sculpt render` draws
    sculpt.write(result, "bumpy.stl")

The same core, methods, stage names, statistics and error messages as the `sculpt` command.
Reconstruction runs without the GIL; progress(stage, fraction) may return False to cancel.
"""

import numpy as _numpy

from ._sculpt import (
    CARVE_REASONS,
    DEFAULT_METHOD,
    LABEL_REASONS,
    LABELS,
    Cancelled,
    DuplicatePoints,
    InputError,
    Reconstruction,
    example,
    examples,
    methods,
    read_points,
    reconstruct,
    render,
    stages,
    version,
    write,
)

__version__ = version()


def merge_duplicates(points):
    """The points without repeated rows (exact copies), first occurrences kept, in order: what
    `sculpt reconstruct --merge-duplicates` does to a file."""
    points = _numpy.asarray(points, dtype=float)
    _, first = _numpy.unique(points, axis=0, return_index=True)
    return points[_numpy.sort(first)]


__all__ = [
    "CARVE_REASONS",
    "DEFAULT_METHOD",
    "LABEL_REASONS",
    "LABELS",
    "Cancelled",
    "DuplicatePoints",
    "InputError",
    "Reconstruction",
    "example",
    "examples",
    "merge_duplicates",
    "methods",
    "read_points",
    "reconstruct",
    "render",
    "stages",
    "version",
    "write",
]
