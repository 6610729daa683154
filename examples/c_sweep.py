#!/usr/bin/env python3
"""Walks c along a path and measures the volume of the 3D slice of K_N at each step, two ways:
by counting the points of a grid that `contains` places in the set, and by the mesh's volume.
Plots both against the path's parameter (matplotlib) into c_sweep.png.

    PYTHONPATH=build/python python3 examples/c_sweep.py [--steps 24] [--grid 64]
"""

import argparse
import math
import time

import numpy as np

import quaternia


def grid_volume(scene, grid):
    """The volume of K_N in the slice from membership on a grid of cells over [-1.5, 1.5]^3."""
    side = 3.0
    axis = (np.arange(grid) + 0.5) / grid * side - side / 2
    x, y, z = np.meshgrid(axis, axis, axis, indexing="ij")
    points = np.stack([x.ravel(), y.ravel(), z.ravel()], axis=1)
    inside = quaternia.contains(scene, points)  # points of the 3D slice
    return inside.sum() * (side / grid) ** 3


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--steps", type=int, default=24)
    parser.add_argument("--grid", type=int, default=64)
    parser.add_argument("--resolution", type=int, default=64)
    parser.add_argument("--output", default="c_sweep.png")
    args = parser.parse_args()

    scene = quaternia.Scene()
    scene["fractal.max_iterations"] = 12
    # c on a circle of radius 0.7 in the (1, i) plane, lifted a little into j
    ts = np.linspace(0, 1, args.steps, endpoint=False)
    grid_volumes, mesh_volumes = [], []
    start = time.perf_counter()
    for t in ts:
        angle = 2 * math.pi * t
        scene["fractal.c"] = [0.7 * math.cos(angle) - 0.1, 0.7 * math.sin(angle), 0.15, 0.0]
        grid_volumes.append(grid_volume(scene, args.grid))
        mesh_volumes.append(quaternia.mesh(scene, args.resolution).volume())
        print(f"t = {t:.3f}  c = {scene['fractal.c']}  grid {grid_volumes[-1]:.4f}  "
              f"mesh {mesh_volumes[-1]:.4f}")
    print(f"{args.steps} steps in {time.perf_counter() - start:.1f} s "
          f"({quaternia.lane_target()} lanes)")

    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    figure, axes = plt.subplots(figsize=(7, 4))
    axes.plot(ts, grid_volumes, "o-", label=f"contains on a {args.grid}^3 grid")
    axes.plot(ts, mesh_volumes, "s--", label=f"mesh at resolution {args.resolution}")
    axes.set_xlabel("t  (c = 0.7 e^{2 pi i t} - 0.1 + 0.15 j)")
    axes.set_ylabel("volume of the slice of K_12")
    axes.legend()
    figure.tight_layout()
    figure.savefig(args.output, dpi=100)
    print("wrote", args.output)


if __name__ == "__main__":
    main()
