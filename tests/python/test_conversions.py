# SPDX-License-Identifier: GPL-3.0-or-later
"""sculpt.to_open3d and sculpt.to_trimesh: the arrays they hand over (through stand-ins that
record them, so the contract is checked on every machine), the real Open3D where Debian's
python3-open3d is installed, and a message naming what to install where it is not."""
import importlib.util
import sys
import types

import numpy as np
import pytest

import sculpt


class Recorder:
    def __init__(self, *arrays, **named):
        self.arrays = [np.asarray(a) for a in arrays]
        self.named = {k: np.asarray(v) for k, v in named.items()}
        self.normals = False

    def compute_vertex_normals(self):
        self.normals = True


def stand_in_open3d():
    module = types.ModuleType("open3d")
    module.geometry = types.SimpleNamespace(TriangleMesh=Recorder, LineSet=Recorder)
    module.utility = types.SimpleNamespace(Vector3dVector=np.asarray, Vector3iVector=np.asarray,
                                           Vector2iVector=np.asarray)
    return module


def test_the_arrays_handed_over(monkeypatch):
    monkeypatch.setitem(sys.modules, "open3d", stand_in_open3d())
    monkeypatch.setitem(sys.modules, "trimesh", types.SimpleNamespace(Trimesh=Recorder))
    surface = sculpt.reconstruct(sculpt.example("bumpy"))
    mesh = sculpt.to_open3d(surface)
    assert np.array_equal(mesh.arrays[0], surface.samples)
    assert np.array_equal(mesh.arrays[1], surface.surface) and mesh.normals
    curve = sculpt.to_open3d(sculpt.reconstruct(sculpt.example("star")))
    assert curve.arrays[0].shape == (200, 3) and not curve.arrays[0][:, 2].any()
    assert curve.arrays[1].shape == (200, 2)
    tri = sculpt.to_trimesh(surface)
    assert np.array_equal(tri.named["faces"], surface.surface) and not tri.named["process"]
    # The power crust's surface is on vertices of its own.
    power = sculpt.reconstruct(sculpt.example("sphere"), method="power-crust")
    assert not power.interpolates
    assert np.array_equal(sculpt.to_open3d(power).arrays[0], power.surface_vertices)
    with pytest.raises(ValueError, match="2D curve"):
        sculpt.to_trimesh(sculpt.reconstruct(sculpt.example("star")))


def test_open3d_itself_or_what_to_install(monkeypatch):
    result = sculpt.reconstruct(sculpt.example("bumpy"))
    if importlib.util.find_spec("open3d") is None:
        with pytest.raises(ImportError, match="apt install python3-open3d"):
            sculpt.to_open3d(result)
        return
    mesh = sculpt.to_open3d(result)
    assert len(mesh.triangles) == len(result.surface)
    assert mesh.is_watertight() and mesh.is_edge_manifold()
    monkeypatch.setitem(sys.modules, "trimesh", None)  # import fails
    with pytest.raises(ImportError, match="pip install trimesh"):
        sculpt.to_trimesh(result)
