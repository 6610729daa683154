#!/usr/bin/env python3
"""The Python module's benchmark rows (issue 37), written to bench/results/python-DATE-ISA.md:

- render from Python against the CLI at 1920x1080, interleaved runs, medians: Python's
  render() call, and the CLI's whole command and its own render time (--json "seconds");
- contains: points per second for z^2 + c (fractal.max_iterations 12) on every core, points
  uniform in the bounding ball's cube, so that both fates are common.

    PYTHONPATH=build/python python3 bench/python_bench.py [--isa avx2] [--runs 7]
"""

import argparse
import datetime
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time

import numpy as np

import quaternia

HERE = os.path.dirname(os.path.abspath(__file__))


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--isa", default="best")
    parser.add_argument("--runs", type=int, default=7)
    parser.add_argument("--binary", default=os.path.join(HERE, "..", "build", "quaternia"))
    parser.add_argument("--points", type=int, default=4_000_000)
    args = parser.parse_args()
    quaternia.limit_isa(args.isa)
    scene = quaternia.Scene()
    quaternia.render(scene, 64, 36)  # warm up
    target = quaternia.lane_target()
    python_times, cli_wall, cli_render = [], [], []
    with tempfile.TemporaryDirectory() as directory:
        out = os.path.join(directory, "out.png")
        for _ in range(args.runs):
            start = time.perf_counter()
            quaternia.render(scene, 1920, 1080)
            python_times.append(time.perf_counter() - start)
            start = time.perf_counter()
            done = subprocess.run([args.binary, "--isa", args.isa, "render", "--width", "1920",
                                   "--height", "1080", "-o", out, "--json"],
                                  capture_output=True, text=True, check=True)
            cli_wall.append(time.perf_counter() - start)
            cli_render.append(json.loads(done.stdout)["seconds"])
    scene["fractal.max_iterations"] = 12
    rng = np.random.default_rng(1)

    def contains_rate(scene, points):
        """Points per second (median), and the fraction inside."""
        rates, inside = [], None
        for _ in range(args.runs):
            start = time.perf_counter()
            inside = quaternia.contains(scene, points)
            rates.append(len(points) / (time.perf_counter() - start))
        return statistics.median(rates), inside.mean()

    # The default c (a dust: most points escape early), points in its bounding cube; and the
    # rabbit's c (K connected, with interior), points in [-1, 1]^4, where many run all 12.
    rate, fraction = contains_rate(scene, rng.uniform(-1.5, 1.5, size=(args.points, 4)))
    rabbit = quaternia.Scene()
    rabbit["fractal.c"] = [-0.123, 0.745, 0.0, 0.0]
    rabbit["fractal.max_iterations"] = 12
    rabbit_rate, rabbit_fraction = contains_rate(
        rabbit, rng.uniform(-1.0, 1.0, size=(args.points, 4)))
    median = statistics.median
    stamp = datetime.datetime.now().strftime("%Y-%m-%d-%H%M")
    lines = [
        f"# The Python module against the CLI, {stamp}",
        "",
        f"Machine: {os.cpu_count()} cores; lanes: {target} (`--isa {args.isa}`); "
        f"{args.runs} interleaved runs, medians. `bench/python_bench.py`.",
        "",
        "| row | ISA | median | note |",
        "|---|---|---|---|",
        f"| render 1920x1080, Python `quaternia.render` | {target} | {median(python_times):.3f} s | "
        "the array, no PNG |",
        f"| render 1920x1080, CLI whole command | {target} | {median(cli_wall):.3f} s | "
        "process, render, PNG file |",
        f"| render 1920x1080, CLI's own render time | {target} | {median(cli_render):.3f} s | "
        "`--json` seconds |",
        f"| Python / CLI render time | {target} | {median(python_times) / median(cli_render):.3f} | "
        "goal: within 1.05 |",
        f"| contains, z^2 + c, N = 12, default c, points in [-1.5, 1.5]^4 | {target} | "
        f"{rate / 1e6:.1f} M points/s | {args.points} points, {fraction:.1%} inside; "
        "goal 20 M/s on 2 cores |",
        f"| contains, z^2 + c, N = 12, c = -0.123 + 0.745i, points in [-1, 1]^4 | {target} | "
        f"{rabbit_rate / 1e6:.1f} M points/s | {args.points} points, {rabbit_fraction:.1%} "
        "inside; goal 20 M/s on 2 cores |",
        "",
    ]
    text = "\n".join(lines)
    print(text)
    path = os.path.join(HERE, "results", f"python-{stamp}-{args.isa}.md")
    with open(path, "w") as f:
        f.write(text)
    print("wrote", path, file=sys.stderr)


if __name__ == "__main__":
    main()
