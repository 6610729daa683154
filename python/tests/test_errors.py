"""Every bad key, value and file raises the right exception, with the key in its message."""

import pytest

import quaternia


@pytest.mark.parametrize(
    "call, exception, key",
    [
        (lambda s: quaternia.render(s, width=0), ValueError, "render.width"),
        (lambda s: quaternia.render(s, height=99999), ValueError, "render.height"),
        (lambda s: quaternia.render(s, samples=-1), ValueError, "render.samples"),
        (lambda s: quaternia.render(s, 8, 8, threads=-2), ValueError, "threads"),
        (lambda s: quaternia.render(s, 8, 8, bit_depth=12), ValueError, "bit_depth"),
        (lambda s: quaternia.render(s, 8, 8, memory_budget="lots"), ValueError, "memory_budget"),
        (lambda s: quaternia.plane(s, "spiral", 8, 8), ValueError, "plane.kind"),
        (lambda s: quaternia.mesh(s, -1), ValueError, "mesh.resolution"),
        (lambda s: quaternia.contains(s, [[0.0] * 5]), ValueError, "fractal.algebra"),
        (lambda s: quaternia.frame(s, 1), ValueError, "animation"),
        (lambda s: quaternia.cycles(s, 0), ValueError, "cycles.period"),
        (lambda s: quaternia.orbit(s, max_iterations=0), ValueError, "orbit.max_iterations"),
    ],
)
def test_bad_values_raise_value_errors_naming_the_key(call, exception, key):
    with pytest.raises(exception) as raised:
        call(quaternia.Scene())
    assert key in str(raised.value)
    assert "\n" not in str(raised.value)


def test_a_bad_formula_names_the_formula():
    scene = quaternia.Scene()
    scene["fractal.formula"] = "z^ + c"
    with pytest.raises(ValueError, match="fractal.formula"):
        quaternia.render(scene, 8, 8)
    with pytest.raises(ValueError, match="fractal.formula"):
        quaternia.contains(scene, [[0.0, 0.0, 0.0, 0.0]])


def test_what_does_not_fit_the_memory_budget_is_a_memory_error_before_work():
    with pytest.raises(MemoryError, match="render.width"):
        quaternia.render(quaternia.Scene(), 16000, 16000, memory_budget="64M")
    with pytest.raises(MemoryError, match="render.width"):
        quaternia.plane(quaternia.Scene(), "julia", 16000, 16000, memory_budget="64M")
    scene = quaternia.Scene()
    with pytest.raises(MemoryError, match="mesh.resolution"):
        quaternia.mesh(scene, 2000, memory_budget="16M")


def test_files(tmp_path):
    with pytest.raises(OSError):
        quaternia.Scene.from_file(str(tmp_path / "absent.toml"))
    with pytest.raises(OSError):
        quaternia.save_mesh(([[0, 0, 0]] * 3, [[0, 1, 2]]), str(tmp_path / "no" / "such.stl"))
    with pytest.raises(ValueError, match="stl"):
        quaternia.save_mesh(([[0, 0, 0]] * 3, [[0, 1, 2]]), str(tmp_path / "mesh.xyz"))
    with pytest.raises(OSError):
        quaternia.read_png(str(tmp_path / "absent.png"))
    assert list(tmp_path.iterdir()) == []  # nothing half-written


def test_a_bad_environment_map_names_the_key_and_the_file(tmp_path):
    scene = quaternia.Scene()
    scene["environment.enabled"] = True
    scene["environment.map"] = str(tmp_path / "absent.hdr")
    with pytest.raises(ValueError, match="environment.map: .*absent.hdr.*no such file"):
        quaternia.render(scene, 8, 8)
    picture = tmp_path / "picture.png"
    quaternia.render(quaternia.Scene(), 8, 8).save(str(picture))
    scene["environment.map"] = str(picture)
    with pytest.raises(ValueError, match="not an HDR image"):
        quaternia.render_passes(scene, 8, 8)
