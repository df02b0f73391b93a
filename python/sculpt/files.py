# SPDX-License-Identifier: GPL-3.0-or-later
"""A point or mesh file with what a scan carries beside its points: normals and colours."""
from dataclasses import dataclass
from typing import Optional

import numpy as np

from ._sculpt import _read_file


@dataclass
class PointFile:
    """What read_file found. Every array is your own (writable); None where the file has none.

    points     (n, 2) or (n, 3) float64, in the file's order (a mesh's vertices)
    normals    (n, 3) float64 as the file gives them (not normalised, not oriented), or None
    colors     (n, 3) uint8 levels 0-255, or None
    triangles  (f, 3) int32, a mesh file's faces as triangles, or None
    """

    points: np.ndarray
    normals: Optional[np.ndarray]
    colors: Optional[np.ndarray]
    triangles: Optional[np.ndarray]

    def __repr__(self):
        kept = [name for name in ("normals", "colors", "triangles") if getattr(self, name) is not None]
        return (f"<sculpt.PointFile {len(self.points)} points of {self.points.shape[1]}D"
                + (" with " + ", ".join(kept) if kept else "") + ">")


def read_file(path, dimension=0, merge_duplicates=False):
    """The points of a file with their normals and colours (PLY nx/red..., OBJ vn and
    `v x y z r g b`, .pwn/.xyzn/.xyz normals, .pts/.xyzrgb colours) and a mesh's triangles, as a
    PointFile. dimension and merge_duplicates as in read_points (a merged point's normal and
    colour are its first occurrence's). Hand normals= and colors= to write() to keep them on a
    .ply or .obj surface:

        scan = sculpt.read_file("scan.ply", merge_duplicates=True)
        result = sculpt.reconstruct(scan.points)
        sculpt.write(result, "part.ply", normals=scan.normals, colors=scan.colors)
    """
    points, normals, colors, triangles = _read_file(path, dimension, merge_duplicates)
    return PointFile(points, normals, colors, triangles)
