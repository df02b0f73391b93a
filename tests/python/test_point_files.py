# SPDX-License-Identifier: GPL-3.0-or-later
"""sculpt.read_file and write's normals= and colors=: a coloured scan with normals read, merged,
reconstructed and written back with its attributes on the surface's vertices, and the
conversions that hand them to Open3D and trimesh."""
import sys
import types

import numpy as np
import pytest

import sculpt


def coloured_sphere(path, n=500, repeat=3):
    """A binary PLY scan: float coordinates and normals, uchar colours and alpha, with the first
    `repeat` points written twice."""
    i = np.arange(n) + 0.5
    z = 1 - 2 * i / n
    r = np.sqrt(1 - z * z)
    a = np.pi * (3 - np.sqrt(5)) * np.arange(n)
    points = np.column_stack([r * np.cos(a), r * np.sin(a), z]).astype(np.float32)
    colors = np.column_stack([np.arange(n) % 256, 255 - np.arange(n) % 256,
                              np.full(n, 9)]).astype(np.uint8)
    points = np.vstack([points, points[:repeat]])
    colors = np.vstack([colors, colors[:repeat]])
    record = np.dtype([("xyz", "<f4", 3), ("normal", "<f4", 3), ("rgb", "u1", 3), ("a", "u1")])
    rows = np.zeros(len(points), record)
    rows["xyz"], rows["normal"], rows["rgb"], rows["a"] = points, points, colors, 255
    header = ("ply\nformat binary_little_endian 1.0\nelement vertex %d\n" % len(points)
              + "".join("property float %s\n" % p for p in ("x", "y", "z", "nx", "ny", "nz"))
              + "".join("property uchar %s\n" % p for p in ("red", "green", "blue", "alpha"))
              + "end_header\n")
    path.write_bytes(header.encode() + rows.tobytes())
    return points[:n].astype(np.float64), colors[:n]


def test_a_coloured_scan_round_trips_through_ply_and_obj(tmp_path):
    points, colors = coloured_sphere(tmp_path / "scan.ply")
    scan = sculpt.read_file(tmp_path / "scan.ply", merge_duplicates=True)
    assert np.array_equal(scan.points, points)
    assert np.array_equal(scan.normals, points) and scan.normals.dtype == np.float64
    assert np.array_equal(scan.colors, colors) and scan.colors.dtype == np.uint8
    assert scan.triangles is None and "with normals, colors" in repr(scan)
    scan.colors[0] = 0  # the arrays are the caller's own
    scan.colors[0] = colors[0]

    result = sculpt.reconstruct(scan.points)
    for name in ("part.ply", "part.obj"):
        sculpt.write(result, tmp_path / name, normals=scan.normals, colors=scan.colors)
        back = sculpt.read_file(tmp_path / name)
        assert np.array_equal(back.points, points), name
        assert np.array_equal(back.normals, points) and np.array_equal(back.colors, colors), name
        assert np.array_equal(back.triangles, result.surface), name
    # Open3D's fractions are accepted too, and give the same bytes.
    sculpt.write(result, tmp_path / "fractions.ply", colors=scan.colors / 255.0)
    assert np.array_equal(sculpt.read_file(tmp_path / "fractions.ply").colors, colors)


def test_attributes_that_do_not_fit_are_refused_before_writing(tmp_path):
    coloured_sphere(tmp_path / "scan.ply")
    scan = sculpt.read_file(tmp_path / "scan.ply", merge_duplicates=True)
    result = sculpt.reconstruct(scan.points)
    target = tmp_path / "refused.ply"
    for normals, colors, message in [
        (scan.normals[:-1], None, r"shape \(500, 3\)"),
        (None, scan.colors * 2.0, "fractions from 0 to 1"),
        (None, scan.colors.astype(np.int32) + 1, "levels from 0 to 255"),
        (None, scan.colors.astype(complex), "real numbers"),
    ]:
        with pytest.raises(sculpt.InputError, match=message):
            sculpt.write(result, target, normals=normals, colors=colors)
        assert not target.exists()
    with pytest.raises(sculpt.InputError, match="not with 2D curves"):
        sculpt.write(sculpt.reconstruct(sculpt.example("star")), tmp_path / "star.svg",
                     colors=np.zeros((200, 3), np.uint8))


def test_a_file_with_attributes_on_some_points_keeps_none_and_warns(tmp_path):
    path = tmp_path / "partly.pwn"
    path.write_text("0 0 0 0 0 1\n1 0 0\n0 1 0 0 0 1\n0 0 1 1 0 0\n")
    with pytest.warns(UserWarning, match="3 of 4 lines"):
        scan = sculpt.read_file(path)
    assert scan.normals is None and scan.colors is None


def test_the_conversions_take_the_samples_attributes(monkeypatch, tmp_path):
    class Mesh:
        def __init__(self, *arrays, **named):
            self.named = named

        def compute_vertex_normals(self):
            self.computed = True

    o3d = types.ModuleType("open3d")
    o3d.geometry = types.SimpleNamespace(TriangleMesh=Mesh)
    o3d.utility = types.SimpleNamespace(Vector3dVector=np.asarray, Vector3iVector=np.asarray)
    monkeypatch.setitem(sys.modules, "open3d", o3d)
    monkeypatch.setitem(sys.modules, "trimesh", types.SimpleNamespace(Trimesh=Mesh))
    coloured_sphere(tmp_path / "scan.ply", repeat=0)
    scan = sculpt.read_file(tmp_path / "scan.ply")
    result = sculpt.reconstruct(scan.points)
    mesh = sculpt.to_open3d(result, normals=scan.normals, colors=scan.colors)
    assert np.array_equal(mesh.vertex_normals, scan.normals)
    assert np.allclose(mesh.vertex_colors * 255, scan.colors) and not hasattr(mesh, "computed")
    tri = sculpt.to_trimesh(result, colors=scan.colors)
    assert np.array_equal(tri.named["vertex_colors"], scan.colors)
    with pytest.raises(ValueError, match="one row per sample"):
        sculpt.to_open3d(result, colors=scan.colors[:10])
