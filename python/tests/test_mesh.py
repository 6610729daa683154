"""mesh: the unit ball's volume, and saving as the CLI does."""

import math
import os

import numpy as np
import pytest

import quaternia
from conftest import cli_file


def ball():
    scene = quaternia.Scene()
    scene["fractal.c"] = [0.0, 0.0, 0.0, 0.0]  # K of z^2 is the closed unit ball
    return scene


def test_the_unit_ball_meshes_to_its_volume():
    mesh = quaternia.mesh(ball(), 96)
    vertices, faces = mesh
    assert vertices.dtype == np.float32 and vertices.shape[1] == 3
    assert faces.dtype == np.uint32 and faces.shape[1] == 3
    assert faces.max() < len(vertices)
    assert abs(mesh.volume() / (4 * math.pi / 3) - 1) < 0.005
    radii = np.linalg.norm(vertices, axis=1)
    assert np.all(np.abs(radii - 1) < 0.03)
    assert mesh.normals.shape == vertices.shape and mesh.colors.shape == vertices.shape


@pytest.mark.parametrize("suffix", [".stl", ".ply", ".obj"])
def test_saving_writes_the_clis_file(tmp_path, suffix):
    scene = quaternia.Scene()
    mesh = quaternia.mesh(scene, 40)
    path = tmp_path / ("mesh" + suffix)
    mesh.save(str(path))
    assert path.read_bytes() == cli_file("mesh", "--resolution", "40", suffix=suffix)
