# SPDX-License-Identifier: GPL-3.0-or-later
"""A reconstruction handed to the libraries the field works in, when they are installed:
Open3D (Debian: python3-open3d) and trimesh. Neither is needed by sculpt itself."""
import numpy as np


def _vertices(result):
    # An interpolating method's surface is on the samples; the power crust has vertices of its own.
    return result.samples if result.interpolates else np.array(result.surface_vertices)


def _need(module, what, install):
    try:
        return __import__(module)
    except ImportError as error:
        raise ImportError(f"sculpt.{what} needs {module} ({install})") from error


def to_open3d(result):
    """The result as an Open3D geometry: a TriangleMesh of a surface (vertex normals computed),
    a LineSet of a curve (its points at z = 0)."""
    o3d = _need("open3d", "to_open3d", "Debian: apt install python3-open3d; or pip install open3d")
    vertices = np.asarray(_vertices(result), dtype=np.float64)
    if result.dimension == 3:
        mesh = o3d.geometry.TriangleMesh(o3d.utility.Vector3dVector(vertices),
                                         o3d.utility.Vector3iVector(np.asarray(result.surface)))
        mesh.compute_vertex_normals()
        return mesh
    points = np.column_stack([vertices, np.zeros(len(vertices))])
    return o3d.geometry.LineSet(o3d.utility.Vector3dVector(points),
                                o3d.utility.Vector2iVector(np.asarray(result.surface)))


def to_trimesh(result):
    """The surface as a trimesh.Trimesh (3D results only), its faces as the reconstruction's,
    without trimesh's merging or reordering."""
    trimesh = _need("trimesh", "to_trimesh", "pip install trimesh")
    if result.dimension != 3:
        raise ValueError("to_trimesh takes a surface; this reconstruction is a 2D curve")
    # Copies: a mesh edited later leaves the result as it was.
    return trimesh.Trimesh(vertices=np.array(_vertices(result), dtype=np.float64),
                           faces=np.array(result.surface, dtype=np.int64), process=False)
