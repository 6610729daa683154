"""quaternia.Scene: the parameter table as a mapping, with its validation."""

import copy
import os

import pytest

import quaternia


def test_default_scene_is_the_tables_defaults():
    scene = quaternia.Scene()
    assert scene == quaternia.Scene.from_toml("")
    assert scene["fractal.formula"] == "z^2 + c"
    assert scene["fractal.c"] == [-0.2, 0.6, 0.2, 0.2]
    assert isinstance(scene["render.width"], int) and isinstance(scene["camera.fov"], float)
    assert isinstance(scene["render.adaptive"], bool)


def test_keys_cover_the_table_in_order():
    scene = quaternia.Scene()
    keys = scene.keys()
    assert keys[0].startswith("fractal.")
    assert "render.width" in keys and "camera.fov" in keys and "light1.kind" in keys
    assert len(keys) == len(scene) == len(set(keys))
    assert list(iter(scene)) == keys
    assert "render.width" in scene and "render.widht" not in scene


def test_set_reads_back_and_validates():
    scene = quaternia.Scene()
    scene["fractal.c"] = [0.1, 0.2, 0.3, 0.4]
    assert scene["fractal.c"] == [0.1, 0.2, 0.3, 0.4]
    scene["render.width"] = 320
    assert scene["render.width"] == 320
    scene["fractal.formula"] = "z^3 + c"
    assert scene["fractal.formula"] == "z^3 + c"
    with pytest.raises(ValueError, match="render.width"):
        scene["render.width"] = 0
    with pytest.raises(ValueError, match="fractal.c"):
        scene["fractal.c"] = [1, 2, 3]
    with pytest.raises(ValueError, match="render.width"):
        scene["render.width"] = "wide"
    with pytest.raises(ValueError, match="render.method"):
        scene["render.method"] = "teleport"
    assert scene["render.width"] == 320  # a refused value leaves the scene as it was


def test_numpy_values_are_taken():
    import numpy as np

    scene = quaternia.Scene()
    scene["fractal.c"] = np.array([0.0, 0.5, 0.0, 0.0])
    scene["render.width"] = np.int64(100)
    assert scene["fractal.c"] == [0.0, 0.5, 0.0, 0.0]
    assert scene["render.width"] == 100


def test_unknown_keys_suggest_the_nearest():
    scene = quaternia.Scene()
    for action in (lambda: scene["render.widht"], lambda: scene.__setitem__("render.widht", 3)):
        with pytest.raises(quaternia.UnknownKeyError) as raised:
            action()
        assert isinstance(raised.value, KeyError) and isinstance(raised.value, ValueError)
        assert "render.widht" in str(raised.value) and "render.width" in str(raised.value)
        assert not str(raised.value).startswith("'")


def test_copies_are_independent():
    scene = quaternia.Scene()
    other = scene.copy()
    other["fractal.c"] = [0, 0, 0, 0]
    assert scene["fractal.c"] == [-0.2, 0.6, 0.2, 0.2]
    for duplicate in (copy.copy(scene), copy.deepcopy(scene)):
        duplicate["render.width"] = 17
        assert scene["render.width"] != 17


def test_toml_round_trip_and_files(tmp_path):
    scene = quaternia.Scene.preset("rabbit")
    scene["camera.fov"] = 33.25
    again = quaternia.Scene.from_toml(scene.to_toml())
    assert again == scene and again.to_toml() == scene.to_toml()
    path = tmp_path / "scene.toml"
    path.write_text(scene.to_toml())
    assert quaternia.Scene.from_file(str(path)) == scene
    with pytest.raises(ValueError, match="render.width"):
        quaternia.Scene.from_toml("[render]\nwidth = -3\n")
    with pytest.raises(ValueError, match="did you mean"):
        quaternia.Scene.from_toml("[render]\nwidht = 3\n")
    with pytest.raises(OSError, match="missing.toml"):
        quaternia.Scene.from_file(str(tmp_path / "missing.toml"))


def test_equality_is_by_value():
    assert quaternia.Scene() == quaternia.Scene()
    assert quaternia.Scene() != quaternia.Scene.preset("rabbit")
    assert quaternia.Scene() != 3


def test_presets():
    names = [name for name, _ in quaternia.presets()]
    assert "rabbit" in names and "glass" in names
    rabbit = quaternia.Scene.preset("rabbit")
    assert rabbit != quaternia.Scene()
    with pytest.raises(ValueError, match="rabit.*rabbit"):
        quaternia.Scene.preset("rabit")


def test_help_is_one_line():
    text = quaternia.Scene().help("render.width")
    assert "\n" not in text and "[1, 16384]" in text
