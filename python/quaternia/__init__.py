"""Quaternia from Python: hypercomplex Julia sets as NumPy arrays.

    import quaternia
    scene = quaternia.Scene.preset("rabbit")
    scene["fractal.c"] = [-0.2, 0.6, 0.2, 0.2]
    image = quaternia.render(scene, 640, 360)      # (360, 640, 4) uint8, shows itself in Jupyter
    inside = quaternia.contains(scene, points)     # (N,) bool, points (N, 4)
    mesh = quaternia.mesh(scene, 128)               # vertices, faces = mesh; mesh.save("k.stl")

Everything is computed by the same library as the `quaternia` command: render gives the
samples of the PNG that `quaternia render` writes, contains decides membership as the
renderer does, orbit and cycles give the fields of `--json`. Long calls release the GIL, use
every core, and stop on Ctrl-C. docs/python.md is the guide.
"""

from __future__ import annotations

import keyword
from typing import Any, Callable, Iterator, NamedTuple, Optional, Sequence

import numpy as np

from . import _quaternia
from ._quaternia import (
    Scene,
    UnknownKeyError,
    contains,
    distance,
    encode_png,
    frame,
    lane_target,
    limit_isa,
    presets,
    read_png,
)

__all__ = [
    "Scene",
    "UnknownKeyError",
    "Image",
    "Plane",
    "Mesh",
    "Report",
    "render",
    "render_passes",
    "certify",
    "plane",
    "contains",
    "distance",
    "mesh",
    "save_mesh",
    "orbit",
    "cycles",
    "frame",
    "presets",
    "encode_png",
    "show",
    "lane_target",
    "limit_isa",
    "read_png",
]

Progress = Optional[Callable[[float], Any]]


class Image(np.ndarray):
    """An array (height, width, 4) of uint8 or uint16 samples that shows itself in a notebook
    (`_repr_png_`) and saves as PNG. Slicing and arithmetic give plain arrays' behaviour."""

    def __new__(cls, array: np.ndarray) -> "Image":
        return np.asarray(array).view(cls)

    def _repr_png_(self) -> Optional[bytes]:
        if self.ndim != 3 or self.shape[2] != 4 or self.dtype not in (np.uint8, np.uint16):
            return None
        return encode_png(np.asarray(self))

    def png(self) -> bytes:
        """The PNG file's bytes (RGB where every pixel is opaque, as `quaternia render`)."""
        return encode_png(np.asarray(self))

    def save(self, path: str) -> None:
        """Writes the PNG to `path` (whole or not at all)."""
        import os
        import tempfile

        data = self.png()
        directory = os.path.dirname(os.path.abspath(path))
        handle, temporary = tempfile.mkstemp(dir=directory, prefix=".quaternia-", suffix=".png")
        try:
            with os.fdopen(handle, "wb") as out:
                out.write(data)
            os.replace(temporary, path)
        except BaseException:
            if os.path.exists(temporary):
                os.unlink(temporary)
            raise


def render(
    scene: Scene,
    width: Optional[int] = None,
    height: Optional[int] = None,
    samples: Optional[int] = None,
    threads: Optional[int] = None,
    *,
    bit_depth: Optional[int] = None,
    linear: bool = False,
    progress: Progress = None,
    memory_budget: Optional[str] = None,
) -> np.ndarray:
    """Renders the scene: an Image (height, width, 4) of uint8 (uint16 where bit_depth or
    render.bit_depth is 16), the samples of the PNG `quaternia render` writes for it.

    width, height and samples override render.width, render.height and render.samples.
    linear=True gives float32 linear colour (before exposure and gamma), a plain array.
    threads: None or 0 for every core. progress(fraction) is called as the render goes.
    memory_budget: "512M", "8G" or "unlimited" (default: the memory available); a render that
    does not fit raises MemoryError before any work. Ctrl-C stops it (KeyboardInterrupt).
    """
    array = _quaternia.render(
        scene, width, height, samples, threads,
        bit_depth=bit_depth, linear=linear, progress=progress, memory_budget=memory_budget,
    )
    return array if linear else Image(array)


def render_passes(
    scene: Scene,
    width: Optional[int] = None,
    height: Optional[int] = None,
    samples: Optional[int] = None,
    threads: Optional[int] = None,
    *,
    progress: Progress = None,
    memory_budget: Optional[str] = None,
) -> dict:
    """Renders with the passes of the EXR writer: a dict of arrays, "image" (as render),
    "linear" (h, w, 4) float32, "depth" (h, w) float32 (distance along the ray, 1e10 where
    nothing was hit), "normal" (h, w, 3) float32, "trap" (h, w) float32, "id" (h, w) uint32
    (0 nothing, 1 the set, 2 the ground)."""
    passes = _quaternia.render_passes(
        scene, width, height, samples, threads, progress=progress, memory_budget=memory_budget
    )
    passes["image"] = Image(passes["image"])
    return passes


def certify(
    scene: Scene,
    width: Optional[int] = None,
    height: Optional[int] = None,
    threads: Optional[int] = None,
    *,
    progress: Progress = None,
    memory_budget: Optional[str] = None,
) -> dict:
    """What is proven about the scene's picture, as `quaternia render --certify` writes it
    (docs/certificates.md): "classes" (h, w) uint8 (0 the pixel's footprint certainly misses
    K_N, 255 its central ray certainly meets it, 128 undecided), "nearest" and "farthest"
    (h, w) float32 (for certain hits, the distances between which the central ray first meets
    K_N; 1e10 elsewhere), and the counts "missed", "hit", "undecided", "undecided_fraction",
    "proofs" and "seconds". A formula part with no interval extension, or a thin lens, raises
    ValueError naming the key."""
    return _quaternia.certify(
        scene, width, height, threads, progress=progress, memory_budget=memory_budget
    )


class Plane(NamedTuple):
    """plane()'s result: the image, and an int32 label per pixel (the escape iteration, -1
    where the orbit stayed; for basins the attracting cycle's index, -1 escaping, -2
    undecided)."""

    image: np.ndarray
    labels: np.ndarray


def plane(
    scene: Scene,
    kind: Optional[str] = None,
    width: Optional[int] = None,
    height: Optional[int] = None,
    samples: Optional[int] = None,
    threads: Optional[int] = None,
    *,
    progress: Progress = None,
    memory_budget: Optional[str] = None,
) -> Plane:
    """The 2D image of `quaternia plane` (kind: plane.kind, "julia", "julia-boundary",
    "mandelbrot", "basins" or "slice") with its labels; see Plane."""
    image, labels = _quaternia.plane(
        scene, kind, width, height, samples, threads, progress=progress, memory_budget=memory_budget
    )
    return Plane(Image(image), labels)


class Mesh(tuple):
    """mesh()'s result: unpacks as (vertices, faces), float32 (V, 3) and uint32 (F, 3), and
    keeps the renderer's normals (V, 3) and orbit colours (V, 3) uint8 for saving."""

    normals: np.ndarray
    colors: np.ndarray

    def __new__(cls, vertices: np.ndarray, faces: np.ndarray, normals: Optional[np.ndarray] = None,
                colors: Optional[np.ndarray] = None) -> "Mesh":
        mesh = super().__new__(cls, (vertices, faces))
        mesh.normals = normals if normals is not None else np.zeros((0, 3), np.float32)
        mesh.colors = colors if colors is not None else np.zeros((0, 3), np.uint8)
        return mesh

    @property
    def vertices(self) -> np.ndarray:
        return self[0]

    @property
    def faces(self) -> np.ndarray:
        return self[1]

    def volume(self) -> float:
        """The enclosed volume (the mesh is closed and outward-oriented), in world units."""
        v = self.vertices.astype(np.float64)
        a, b, c = v[self.faces[:, 0]], v[self.faces[:, 1]], v[self.faces[:, 2]]
        return float(np.einsum("ij,ij->i", a, np.cross(b, c)).sum() / 6.0)

    def area(self) -> float:
        """The surface area, in world units squared."""
        v = self.vertices.astype(np.float64)
        a, b, c = v[self.faces[:, 0]], v[self.faces[:, 1]], v[self.faces[:, 2]]
        return float(np.linalg.norm(np.cross(b - a, c - a), axis=1).sum() / 2.0)

    def save(self, path: str) -> None:
        """Writes the mesh as `quaternia mesh` does: STL, PLY or OBJ by the extension."""
        save_mesh(self, path)


def mesh(
    scene: Scene,
    resolution: Optional[int] = None,
    threads: Optional[int] = None,
    *,
    progress: Progress = None,
    memory_budget: Optional[str] = None,
) -> Mesh:
    """Meshes the scene's set as `quaternia mesh` does (resolution overrides
    mesh.resolution): a closed, outward-oriented surface. Returns a Mesh, which unpacks as
    (vertices, faces)."""
    arrays = _quaternia._mesh(
        scene, resolution, threads, progress=progress, memory_budget=memory_budget
    )
    return Mesh(arrays["vertices"], arrays["faces"], arrays["normals"], arrays["colors"])


def save_mesh(mesh: Sequence[np.ndarray], path: str) -> None:
    """Writes (vertices, faces), with a Mesh's normals and colours, as STL, PLY or OBJ (by the
    extension of `path`), whole or not at all. OSError if it cannot be written."""
    vertices, faces = mesh[0], mesh[1]
    normals = getattr(mesh, "normals", None)
    colors = getattr(mesh, "colors", None)
    _quaternia._save_mesh(path, vertices, faces, normals, colors)


class Report(dict):
    """A report as `--json` gives it: a dict whose keys also read as attributes (a key that is
    a Python keyword, such as "class", with a trailing underscore: report.class_)."""

    def __getattr__(self, name: str) -> Any:
        key = name[:-1] if name.endswith("_") and keyword.iskeyword(name[:-1]) else name
        try:
            return self[key]
        except KeyError:
            raise AttributeError(name) from None

    def __dir__(self) -> Iterator[str]:
        names = [k + "_" if keyword.iskeyword(k) else k for k in self]
        return iter(sorted(set(list(super().__dir__()) + names)))


def _report(value: Any) -> Any:
    if isinstance(value, dict):
        return Report({k: _report(v) for k, v in value.items()})
    if isinstance(value, list):
        return [_report(v) for v in value]
    return value


def orbit(scene: Scene, z0: Optional[Sequence[float]] = None,
          max_iterations: Optional[int] = None) -> Report:
    """The fate of the orbit of z0 (orbit.z0 by default) under the scene's map, with the
    fields of `quaternia orbit --json`: fate, escape_iteration, preperiod, period, class,
    cycle (points, multiplier, eigenvalues, ...), connectedness, ..."""
    s = scene.copy()
    if z0 is not None:
        s["orbit.z0"] = list(np.asarray(z0, dtype=np.float64).ravel())
    if max_iterations is not None:
        s["orbit.max_iterations"] = max_iterations
    return _report(_quaternia._orbit(s))


def cycles(scene: Scene, period: Optional[int] = None) -> Report:
    """Every periodic point of the period (cycles.period by default) of the scene's complex
    map, grouped into cycles with multipliers and classes: the fields of
    `quaternia cycles --json`."""
    s = scene.copy()
    if period is not None:
        s["cycles.period"] = period
    return _report(_quaternia._cycles(s))


def show(image: np.ndarray) -> None:
    """Shows an image: inline in a notebook (IPython), else in a matplotlib window."""
    try:
        from IPython import get_ipython
        from IPython.display import display

        if get_ipython() is not None:
            display(Image(image))
            return
    except ImportError:
        pass
    import matplotlib.pyplot as plt

    array = np.asarray(image)
    if array.dtype == np.uint16:
        array = (array / 65535.0).astype(np.float32)
    plt.imshow(array)
    plt.axis("off")
    plt.show()
