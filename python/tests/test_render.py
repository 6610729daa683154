"""render: the CLI's pixels, the passes, memory ownership, the GIL and Ctrl-C."""

import _thread
import gc
import os
import threading
import time

import numpy as np
import pytest

import quaternia
from conftest import cli_file, png_rgba


def test_render_equals_the_cli_png_for_the_default_scene():
    image = quaternia.render(quaternia.Scene(), 96, 64)
    assert image.shape == (64, 96, 4) and image.dtype == np.uint8
    png = cli_file("render", "--width", "96", "--height", "64")
    assert np.array_equal(np.asarray(image), png_rgba(png))
    assert image.png() == png  # and Image's PNG is the CLI's very file


@pytest.mark.parametrize("preset", ["glass", "studio"])
def test_render_equals_the_cli_png_for_a_look(preset):
    scene = quaternia.Scene.preset(preset)
    scene["render.samples"] = 2
    image = quaternia.render(scene, 80, 48)
    png = cli_file("render", "--preset", preset, "--set", "render.samples=2", "--width", "80",
                   "--height", "48")
    assert np.array_equal(np.asarray(image), png_rgba(png))


def test_sixteen_bits_and_coverage_alpha_equal_the_cli():
    scene = quaternia.Scene()
    scene["render.alpha"] = "coverage"
    scene["render.bit_depth"] = 16
    image = quaternia.render(scene, 64, 40, samples=2)
    assert image.dtype == np.uint16
    png = cli_file("render", "--set", "render.alpha=coverage", "--set", "render.bit_depth=16",
                   "--set", "render.samples=2", "--width", "64", "--height", "40")
    assert np.array_equal(np.asarray(image), png_rgba(png))
    assert 0 < (image[:, :, 3] == 0).sum() < image.shape[0] * image.shape[1]
    eight = quaternia.render(scene, 64, 40, samples=2, bit_depth=8)
    assert eight.dtype == np.uint8


def test_linear_and_passes(small_scene):
    linear = quaternia.render(small_scene, linear=True)
    assert linear.dtype == np.float32 and linear.shape == (40, 64, 4)
    passes = quaternia.render_passes(small_scene)
    assert np.array_equal(passes["linear"], linear)
    assert np.array_equal(np.asarray(passes["image"]), np.asarray(quaternia.render(small_scene)))
    hit = passes["id"] == 1
    assert 0 < hit.sum() < hit.size
    assert np.all(passes["depth"][~hit] == np.float32(1e10))
    assert np.all(passes["depth"][hit] > 0) and np.all(passes["depth"][hit] < 1e3)
    lengths = np.linalg.norm(passes["normal"][hit], axis=1)
    assert np.allclose(lengths, 1, atol=1e-3)
    assert np.all(passes["trap"][hit] >= 0)


def test_arrays_own_their_memory(small_scene):
    image = quaternia.render(small_scene)
    passes = quaternia.render_passes(small_scene)
    expected = np.array(image, copy=True)
    depth = passes["depth"]
    depth_copy = depth.copy()
    del small_scene, passes
    gc.collect()
    for _ in range(3):  # churn the allocator
        quaternia.render(quaternia.Scene(), 32, 20)
    assert np.array_equal(image, expected) and np.array_equal(depth, depth_copy)
    assert depth.base is not None  # the library's buffer, handed over without a copy


def test_progress_is_reported():
    fractions = []
    quaternia.render(quaternia.Scene(), 160, 100, progress=fractions.append)
    assert fractions and fractions[-1] == 1.0
    assert all(0 <= f <= 1 for f in fractions) and fractions == sorted(fractions)


def test_a_python_thread_runs_during_a_render():
    counter = [0]
    stop = threading.Event()

    def count():
        while not stop.is_set():
            counter[0] += 1

    worker = threading.Thread(target=count)
    worker.start()
    time.sleep(0.05)
    before = counter[0]
    start = time.perf_counter()
    quaternia.render(quaternia.Scene(), 960, 540, samples=4)
    elapsed = time.perf_counter() - start
    during = counter[0] - before
    stop.set()
    worker.join()
    assert elapsed > 0.1  # long enough to tell
    assert during > 1000  # the GIL was free while it rendered


def test_an_interrupted_render_stops_within_a_fifth_of_a_second(tmp_path):
    scene = quaternia.Scene()
    scene["render.samples"] = 16
    interrupted = []

    def interrupt():
        interrupted.append(time.perf_counter())
        _thread.interrupt_main()

    timer = threading.Timer(0.3, interrupt)
    timer.start()
    with pytest.raises(KeyboardInterrupt):
        quaternia.render(scene, 1920, 1080)
    stopped = time.perf_counter()
    timer.join()
    assert stopped - interrupted[0] < 0.2
    # and nothing is left behind: the next render is whole and equal to a fresh one
    a = quaternia.render(quaternia.Scene(), 48, 32)
    b = quaternia.render(quaternia.Scene(), 48, 32)
    assert np.array_equal(a, b)
    assert list(tmp_path.iterdir()) == []


def test_a_failing_progress_callback_stops_the_render():
    def fail(fraction):
        raise RuntimeError("stop here")

    with pytest.raises(RuntimeError, match="stop here"):
        quaternia.render(quaternia.Scene(), 640, 360, progress=fail)


def test_image_shows_itself_and_saves(tmp_path, small_scene):
    image = quaternia.render(small_scene)
    data = image._repr_png_()
    assert data.startswith(b"\x89PNG")
    path = tmp_path / "out.png"
    image.save(str(path))
    assert path.read_bytes() == data
    assert [p.name for p in tmp_path.iterdir()] == ["out.png"]


def test_certify_agrees_with_the_render_and_refuses_what_it_cannot_prove():
    scene = quaternia.Scene()
    scene["render.samples"] = 1
    certificate = quaternia.certify(scene, 64, 36)
    classes = np.asarray(certificate["classes"])
    assert classes.shape == (36, 64) and classes.dtype == np.uint8
    assert set(np.unique(classes)) <= {0, 128, 255}
    assert certificate["missed"] + certificate["hit"] + certificate["undecided"] == 64 * 36
    assert certificate["hit"] == int(np.sum(classes == 255)) > 0
    # No pixel the renderer draws as the set is certainly missed.
    drawn = np.asarray(quaternia.render_passes(scene, 64, 36)["id"]) == 1
    assert not np.any(drawn & (classes == 0))
    hits = classes == 255
    assert np.all(np.asarray(certificate["nearest"])[hits] <= np.asarray(certificate["farthest"])[hits])
    scene["fractal.algebra"] = "bicomplex"
    scene["fractal.formula"] = "log(z) + c"
    with pytest.raises(ValueError, match="fractal.formula: the function log"):
        quaternia.certify(scene, 16, 9)
