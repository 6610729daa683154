"""contains and distance: membership as the renderer decides it, against orbits and rays."""

import math

import numpy as np
import pytest

import quaternia


def rabbit(precision="single"):
    scene = quaternia.Scene()
    scene["fractal.c"] = [-0.123, 0.745, 0.0, 0.0]
    scene["render.precision"] = precision
    return scene


def test_contains_agrees_with_orbit_on_random_points():
    scene = rabbit("double")
    n = scene["fractal.max_iterations"]
    rng = np.random.default_rng(7)
    points = rng.uniform(-1.2, 1.2, size=(300, 4))
    inside = quaternia.contains(scene, points)
    assert inside.dtype == np.bool_ and inside.shape == (300,)
    assert 10 < inside.sum() < 290  # both fates are met
    checked = 0
    for point, member in zip(points, inside):
        report = quaternia.orbit(scene, z0=point, max_iterations=n + 1)
        escape = report.escape_iteration
        if escape is not None and escape in (n, n + 1):
            continue  # escapes right at the limit: N's convention decides, not the arithmetic
        assert member == (escape is None or escape > n), (point, escape, member)
        checked += 1
    assert checked > 250


def test_single_precision_decides_almost_every_point_alike():
    rng = np.random.default_rng(8)
    points = rng.uniform(-1.2, 1.2, size=(20000, 4))
    single = quaternia.contains(rabbit("single"), points)
    double = quaternia.contains(rabbit("double"), points)
    assert (single != double).mean() < 0.002


def test_distance_is_zero_inside_and_bounds_the_distance_to_members():
    scene = rabbit("double")
    rng = np.random.default_rng(9)
    points = rng.uniform(-1.2, 1.2, size=(4000, 4))
    d = quaternia.distance(scene, points)
    inside = quaternia.contains(scene, points)
    assert np.all(d[inside] == 0) and np.all(d[~inside] > 0)
    members = points[inside]
    # no member lies closer to an outside point than its estimate (the estimate's promise,
    # up to its own slack near the set)
    for p, estimate in zip(points[~inside][:400], d[~inside][:400]):
        nearest = np.min(np.linalg.norm(members - p, axis=1))
        assert estimate <= nearest * 1.05 + 1e-9


def test_the_vectorised_query_equals_one_point_at_a_time():
    scene = rabbit()
    rng = np.random.default_rng(10)
    points = rng.uniform(-1.2, 1.2, size=(50, 4))
    together = quaternia.distance(scene, points)
    alone = np.array([quaternia.distance(scene, p[None, :])[0] for p in points])
    assert np.array_equal(together, alone)
    assert quaternia.contains(scene, points[0]).shape == ()


def test_points_of_the_slice_agree_with_the_renderers_hits():
    """Along rays through the image centre, every point before the render's hit (less half a
    pixel's footprint: the march ends within a quarter of one of the surface, either side) is
    outside K_N, and points of K_N lie just past it."""
    for look_at in ([0.0, 0.0, 0.0], [0.2, 0.1, 0.0], [-0.3, 0.0, 0.1]):
        scene = quaternia.Scene()
        scene["camera.look_at"] = look_at
        scene["render.samples"] = 1
        passes = quaternia.render_passes(scene, 33, 33)
        assert passes["id"][16, 16] == 1
        t_hit = float(passes["depth"][16, 16])
        origin = np.array(scene["camera.position"])
        direction = np.array(look_at) - origin
        direction /= np.linalg.norm(direction)
        footprint = t_hit * 2 * math.tan(math.radians(scene["camera.fov"]) / 2) / 33
        before = origin + np.outer(np.linspace(0.0, t_hit - footprint / 2, 4000), direction)
        assert not quaternia.contains(scene, before).any()
        after = origin + np.outer(np.linspace(t_hit - footprint / 2, t_hit + 0.05, 2000),
                                  direction)
        assert quaternia.contains(scene, after).any()


def test_eight_component_and_scalar_algebras():
    scene = quaternia.Scene()
    scene["fractal.algebra"] = "octonion"
    scene["fractal.c"] = [-0.2, 0.6, 0.2, 0.2, 0.0, 0.0, 0.0, 0.0]
    origin = np.zeros((1, 8))
    far = np.full((1, 8), 3.0)
    assert quaternia.contains(scene, np.vstack([origin, far])).tolist() == [True, False]
    scene = quaternia.Scene()
    scene["fractal.algebra"] = "coquaternion"
    d = quaternia.distance(scene, [[0.0, 0.0, 0.0, 0.0], [5.0, 0.0, 0.0, 0.0]])
    assert d[1] > 0
