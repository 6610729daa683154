"""orbit, cycles and frame: the CLI's --json fields, and films frame by frame."""

import json

import numpy as np
import pytest

import quaternia
from conftest import cli_file, png_rgba, run_cli


def cli_json(*args):
    return json.loads(run_cli(*args, "--json").stdout)


@pytest.mark.parametrize("preset", [None, "rabbit", "basilica"])
def test_orbit_has_the_fields_of_its_json(preset):
    scene = quaternia.Scene.preset(preset) if preset else quaternia.Scene()
    report = quaternia.orbit(scene)
    expected = cli_json("orbit", *(["--preset", preset] if preset else []))
    assert report == expected
    assert report.fate == expected["fate"] and report.class_ == expected["class"]


def test_orbit_facts():
    scene = quaternia.Scene()
    scene["fractal.c"] = [-1.0, 0.0, 0.0, 0.0]
    report = quaternia.orbit(scene, z0=[0, 0, 0, 0])
    assert report.fate == "periodic" and report.period == 2  # 0 -> -1 -> 0
    assert report.cycle.multiplier == [0.0, 0.0]  # 2z over the cycle: 4 * 0 * (-1)
    assert quaternia.orbit(scene, z0=[3, 0, 0, 0]).fate == "escapes"


def test_cycles_has_the_fields_of_its_json_and_the_known_multipliers():
    scene = quaternia.Scene()
    scene["fractal.c"] = [-1.0, 0.0, 0.0, 0.0]
    report = quaternia.cycles(scene, 1)
    expected = cli_json("cycles", "--set", "fractal.c=[-1.0, 0.0, 0.0, 0.0]", "--period", "1")
    assert report == expected
    # fixed points of z^2 - 1: (1 +- sqrt 5) / 2, multipliers 2z = 1 +- sqrt 5
    found = sorted(complex(*c["multiplier"]).real for c in report.cycles)
    assert np.allclose(found, sorted([1 - 5 ** 0.5, 1 + 5 ** 0.5]), atol=1e-9)


def test_frame_is_the_films_frame():
    scene = quaternia.Scene()
    scene["animation.frames"] = 4
    scene["animation.orbit_turns"] = 1.0
    assert scene.frame_count() == 4
    third = quaternia.frame(scene, 3)
    printed = run_cli("animate", "--set", "animation.frames=4", "--set", "animation.orbit_turns=1.0",
                      "--print-frame", "3").stdout
    assert third == quaternia.Scene.from_toml(printed)
    assert third != quaternia.frame(scene, 1)
    with pytest.raises(ValueError, match="frame"):
        quaternia.frame(scene, 5)
