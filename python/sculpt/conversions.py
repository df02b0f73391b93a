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


def _fractions(colors):
    # Open3D and trimesh take colours as 0-1 fractions and 0-255 levels; read_file gives levels.
    colors = np.asarray(colors)
    return colors / 255.0 if colors.dtype.kind in "iu" else colors.astype(np.float64)


def _on_samples(result, values, what):
    if values is None:
        return None
    if not result.interpolates:
        raise ValueError(f"{what} belong to the samples; this surface's vertices are its own")
    values = np.asarray(values)
    if values.shape != (len(result.samples), 3):
        raise ValueError(f"{what} must have shape ({len(result.samples)}, 3): one row per sample")
    return values


def to_open3d(result, normals=None, colors=None):
    """The result as an Open3D geometry: a TriangleMesh of a surface (vertex normals computed,
    or the samples' normals if given), a LineSet of a curve (its points at z = 0). normals and
    colors, a row per sample as read_file gives them, become the mesh's vertex attributes."""
    o3d = _need("open3d", "to_open3d", "Debian: apt install python3-open3d; or pip install open3d")
    vertices = np.asarray(_vertices(result), dtype=np.float64)
    if result.dimension == 3:
        mesh = o3d.geometry.TriangleMesh(o3d.utility.Vector3dVector(vertices),
                                         o3d.utility.Vector3iVector(np.asarray(result.surface)))
        normals = _on_samples(result, normals, "normals")
        colors = _on_samples(result, colors, "colors")
        if normals is None:
            mesh.compute_vertex_normals()
        else:
            mesh.vertex_normals = o3d.utility.Vector3dVector(normals.astype(np.float64))
        if colors is not None:
            mesh.vertex_colors = o3d.utility.Vector3dVector(_fractions(colors))
        return mesh
    points = np.column_stack([vertices, np.zeros(len(vertices))])
    return o3d.geometry.LineSet(o3d.utility.Vector3dVector(points),
                                o3d.utility.Vector2iVector(np.asarray(result.surface)))


def to_trimesh(result, normals=None, colors=None):
    """The surface as a trimesh.Trimesh (3D results only), its faces as the reconstruction's,
    without trimesh's merging or reordering; normals and colors (a row per sample) as its vertex
    normals and colours."""
    trimesh = _need("trimesh", "to_trimesh", "pip install trimesh")
    if result.dimension != 3:
        raise ValueError("to_trimesh takes a surface; this reconstruction is a 2D curve")
    # Copies: a mesh edited later leaves the result as it was.
    normals = _on_samples(result, normals, "normals")
    colors = _on_samples(result, colors, "colors")
    return trimesh.Trimesh(vertices=np.array(_vertices(result), dtype=np.float64),
                           faces=np.array(result.surface, dtype=np.int64),
                           vertex_normals=None if normals is None else np.array(normals, dtype=np.float64),
                           vertex_colors=None if colors is None else np.round(_fractions(colors) * 255).astype(np.uint8),
                           process=False)
