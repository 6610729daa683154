"""plane: the CLI's images, with escape counts and basin labels."""

import numpy as np
import pytest

import quaternia
from conftest import cli_file, png_rgba


@pytest.mark.parametrize("kind", ["julia", "mandelbrot", "basins"])
def test_plane_equals_the_cli(kind):
    scene = quaternia.Scene.preset("rabbit")
    image, labels = quaternia.plane(scene, kind, 72, 48)
    png = cli_file("plane", "--preset", "rabbit", "--set", f"plane.kind={kind}", "--width", "72",
                   "--height", "48")
    assert np.array_equal(np.asarray(image), png_rgba(png))
    assert labels.shape == (48, 72) and labels.dtype == np.int32


def test_escape_labels_are_the_escape_iterations():
    scene = quaternia.Scene.preset("rabbit")
    scene["render.samples"] = 1
    image, labels = quaternia.plane(scene, "julia", 64, 64)
    inside = labels == -1
    assert 0 < inside.sum() < inside.size
    assert labels[~inside].min() >= 0
    assert labels[~inside].max() <= scene["plane.max_iterations"]
    # the points that stayed take the one interior colour
    pixels = np.asarray(image)[inside]
    assert np.all(pixels == pixels[0])


def test_basin_labels_name_the_attracting_cycles():
    scene = quaternia.Scene.preset("rabbit")
    _, labels = quaternia.plane(scene, "basins", 64, 64)
    found = set(np.unique(labels).tolist())
    assert 0 in found and -1 in found  # the rabbit's 3-cycle, and infinity
    assert found <= {-2, -1, 0}
