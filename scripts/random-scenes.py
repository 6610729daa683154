#!/usr/bin/env python3
"""Drives the real executable with random valid scenes, across commands and algebras.

    scripts/random-scenes.py N [--binary build/quaternia] [--jobs J] [--seed S] [--timeout T]

Each scene is a small job (a few dozen pixels, a coarse mesh, one frame of a film): a random
algebra, a formula from a grammar of polynomials (one- and two-sided coefficients, several
terms) and, for the bicomplex algebra, functions; a random c, z0, slice, camera, look and
limits, given as --set options to one of render (both engines), plane (every kind), mesh,
orbit, cycles and animate. A run is fine when it exits 0, or exits 2 with exactly one line on
standard error (a clean refusal of what the command does not take). Anything else is a
finding: a signal, another exit code, a multi-line error, or a hang past the timeout (20 s).
Findings are printed with the full command line that reproduces them; the exit status is 1
when there is any. The same seed gives the same scenes.
"""

import argparse
import concurrent.futures
import os
import random
import shlex
import subprocess
import sys
import tempfile
import time
from collections import Counter

ALGEBRAS = ["quaternion", "bicomplex", "coquaternion", "biquaternion", "octonion"]
DIMENSION = {"quaternion": 4, "bicomplex": 4, "coquaternion": 4, "biquaternion": 8, "octonion": 8}
FUNCTIONS = ["exp", "log", "sin", "cos", "tan", "sinh", "cosh", "tanh", "asin", "acos", "atan",
             "asinh", "acosh", "atanh", "reciprocal"]
STUDIO_MAP = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "data",
                          "environments", "studio.hdr")
PLANE_KINDS = ["julia", "julia-boundary", "mandelbrot", "basins", "slice"]
PRESETS = ["rabbit", "dendrite", "basilica", "4d-blob", "cubic", "two-sided", "studio", "chrome",
           "glass", "sunset", "hidden-turn", "orbit"]


def real(rng, scale=1.0, digits=3):
    return round(rng.uniform(-scale, scale), digits)


def toml_list(values):
    return "[" + ", ".join(repr(v) for v in values) + "]"


def coefficient(rng):
    """A constant factor: a real, or a quaternion unit or number in parentheses."""
    kind = rng.random()
    if kind < 0.4:
        return f"{abs(real(rng, 1.0)) + 0.05:g}"
    if kind < 0.6:
        return rng.choice(["i", "j", "k"])
    parts = [f"{real(rng, 1.0):g}"] + [f"{real(rng, 0.5):+g}{u}" for u in "ijk" if rng.random() < 0.5]
    return "(" + "".join(parts) + ")"


def polynomial(rng):
    """A quaternion polynomial plus c: terms of degree 1 to 5, one- and two-sided."""
    terms = []
    top = rng.choice([2, 2, 2, 3, 3, 4, 5])
    shape = rng.random()
    if shape < 0.5:
        terms.append(f"z^{top}")
    elif shape < 0.8:
        terms.append(f"{coefficient(rng)}*z^{top}")
    else:  # two-sided: a z b z ... (each z may carry factors on both sides)
        factors = []
        for _ in range(top):
            if rng.random() < 0.5:
                factors.append(coefficient(rng))
            factors.append("z")
        if rng.random() < 0.5:
            factors.append(coefficient(rng))
        terms.append("*".join(factors))
    for _ in range(rng.choice([0, 0, 1, 1, 2])):
        degree = rng.randint(1, max(1, top - 1))
        power = "z" if degree == 1 else f"z^{degree}"
        terms.append(f"{coefficient(rng)}*{power}")
    terms.append("c")
    text = terms[0]
    for term in terms[1:]:
        text += rng.choice([" + ", " - "]) + term
    return text


def formula(rng, algebra):
    if algebra == "bicomplex" and rng.random() < 0.3:
        inner = rng.choice(["z", "z^2", "0.5*z", "z + 0.2"])
        return f"{rng.choice(FUNCTIONS)}({inner}) + c"
    if rng.random() < 0.25:
        return "z^2 + c"
    return polynomial(rng)


def scene_options(rng):
    """The --set options of a random valid scene (the command picks its own extras)."""
    algebra = rng.choice(ALGEBRAS)
    n = DIMENSION[algebra]
    sets = [f"fractal.algebra={algebra}",
            f"fractal.formula=\"{formula(rng, algebra)}\"",
            f"fractal.c={toml_list([real(rng, 1.2) for _ in range(n)])}",
            f"fractal.max_iterations={rng.randint(2, 24)}"]
    if rng.random() < 0.2:
        sets.append(f"fractal.bailout={rng.choice([0, 2, 4, 8, 1.5])}")
    if n == 4:
        if rng.random() < 0.4:
            normal = [real(rng) for _ in range(3)] + [rng.choice([1, -1]) * (0.2 + abs(real(rng)))]
            sets.append(f"slice.normal={toml_list(normal)}")
        if rng.random() < 0.3:
            sets.append(f"slice.distance={real(rng, 0.5)}")
        if rng.random() < 0.3:
            sets.append(f"slice.angles={toml_list([real(rng, 90, 1) for _ in range(6)])}")
    elif rng.random() < 0.5:
        sets.append(f"slice.origin={toml_list([real(rng, 0.3) for _ in range(8)])}")
    z0 = [real(rng, 1.0) for _ in range(4)]  # orbit.z0 is a quaternion in every algebra
    sets.append(f"orbit.z0={toml_list(z0)}")
    return algebra, sets


def render_options(rng):
    engine = rng.choice(['simd', 'simd', 'scalar'])
    sets = [f"render.samples={rng.choice([1, 1, 2, 4])}", f"render.engine={engine}",
            f"render.precision={rng.choice(['single', 'double'])}"]
    if rng.random() < 0.3:
        sets.append("render.method=fixed-step")
        sets.append(f"render.step={rng.choice([0.01, 0.02, 0.05])}")
        engine = "scalar"
    if rng.random() < 0.3:
        sets.append("render.adaptive=true")
    if rng.random() < 0.3:
        position = [real(rng, 5.0) for _ in range(3)]
        if sum(v * v for v in position) > 0.5:
            sets.append(f"camera.position={toml_list(position)}")
    if rng.random() < 0.2:
        sets.append(f"shading.light_kind={rng.choice(['point', 'spot'])}")
    if rng.random() < 0.2:
        sets.append(f"shading.shadows={rng.choice(['hard', 'none'])}")
    if rng.random() < 0.2:
        sets.append(f"shading.fog_density={rng.choice([0.05, 0.3])}")
    if rng.random() < 0.25:  # the environment (issue 39), in both engines
        sets.append("environment.enabled=true")
        sets.append(f"environment.builtin={rng.choice(['sky', 'studio'])}")
        sets.append(f"environment.samples={rng.choice([0, 1, 4])}")
        sets.append(f"environment.rotation={real(rng, 180, 1)}")
        sets.append(f"environment.background={rng.choice(['true', 'false'])}")
        if rng.random() < 0.3:
            sets.append(f"environment.map=\"{rng.choice([STUDIO_MAP, '/no/such/map.hdr'])}\"")
    # The materials, the ground and the glow: both engines draw them (issue 35).
    if rng.random() < 0.2:
        sets.append(f"shading.glow_intensity={rng.choice([0.5, 2])}")
    if rng.random() < 0.25:
        sets.append(f"material.reflectivity={rng.choice([0.3, 1.0])}")
        sets.append(f"material.roughness={rng.choice([0, 0.2])}")
    if rng.random() < 0.2:
        sets.append(f"material.transparency={rng.choice([0.5, 1.0])}")
    if rng.random() < 0.25:
        sets.append("ground.enabled=true")
    if rng.random() < 0.15:
        sets.append(f"camera.aperture={rng.choice([0.02, 0.1])}")
    return sets


def job(rng, work):
    """One command line (a list of arguments, without the binary) and its kind."""
    algebra, sets = scene_options(rng)
    command = rng.choice(["render", "render", "plane", "mesh", "orbit", "orbit", "cycles",
                          "animate"])
    args = [command]
    if rng.random() < 0.1:
        args += ["--preset", rng.choice(PRESETS)]
    if command == "render":
        sets += render_options(rng)
        args += ["--width", str(rng.randint(4, 40)), "--height", str(rng.randint(4, 30)),
                 "-o", os.path.join(work, "out.png")]
        if rng.random() < 0.2:
            args[-1] = os.path.join(work, "out.exr")
    elif command == "plane":
        sets.append(f"plane.kind={rng.choice(PLANE_KINDS)}")
        sets.append(f"plane.max_iterations={rng.randint(8, 200)}")
        if rng.random() < 0.3:
            sets.append(f"plane.width={rng.choice([0.5, 2, 4, 8])}")
        args += ["--width", str(rng.randint(4, 64)), "--height", str(rng.randint(4, 48)),
                 "-o", os.path.join(work, "out.png")]
    elif command == "mesh":
        args += ["--resolution", str(rng.randint(4, 24)),
                 "-o", os.path.join(work, rng.choice(["out.stl", "out.ply", "out.obj"]))]
    elif command == "orbit":
        if rng.random() < 0.5:
            args.append("--json")
    elif command == "cycles":
        sets.append(f"cycles.period={rng.randint(1, 3)}")
        if rng.random() < 0.5:
            args.append("--json")
    elif command == "animate":
        sets += render_options(rng)[:2]
        sets += ["animation.frames=4", f"animation.c_radius={rng.choice([0.05, 0.2])}",
                 f"animation.turn_plane={rng.choice(['none', '1i', 'jk'])}"]
        args += ["--width", str(rng.randint(4, 24)), "--height", str(rng.randint(4, 16)),
                 "--frames", str(rng.randint(1, 4)), "--overwrite", "-o",
                 os.path.join(work, "frames")]
    for assignment in sets:
        args += ["--set", assignment]
    return algebra, command, args


def run_one(binary, args, timeout):
    start = time.monotonic()
    try:
        done = subprocess.run([binary] + args, stdin=subprocess.DEVNULL, capture_output=True,
                              timeout=timeout, env=dict(os.environ, OMP_NUM_THREADS="1"))
    except subprocess.TimeoutExpired:
        return "hang", f"over {timeout} s", time.monotonic() - start
    seconds = time.monotonic() - start
    err = done.stderr.decode(errors="replace").strip()
    if done.returncode == 0:
        return "ok", "", seconds
    if done.returncode == 2 and err and "\n" not in err:
        return "refused", err, seconds
    if done.returncode < 0:
        return "crash", f"signal {-done.returncode}: {err[-400:]}", seconds
    if done.returncode == 2:
        return "multi-line", err[-400:], seconds
    return "exit", f"exit {done.returncode}: {err[-400:]}", seconds


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("count", type=int, help="number of random scenes")
    parser.add_argument("--binary", default=os.path.join(os.path.dirname(__file__), "..",
                                                         "build", "quaternia"))
    parser.add_argument("--jobs", type=int, default=os.cpu_count() or 1)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--timeout", type=float, default=20.0)
    options = parser.parse_args()
    if not os.access(options.binary, os.X_OK):
        sys.exit(f"random-scenes: no executable at {options.binary} (build first)")

    rng = random.Random(options.seed)
    outcomes, findings, slowest = Counter(), [], (0.0, "")
    by_command = Counter()
    with tempfile.TemporaryDirectory(prefix="quaternia-random-") as root:
        def task(index, args):
            work = os.path.join(root, str(index % (options.jobs * 4)))
            os.makedirs(work, exist_ok=True)
            args = [a.replace("@WORK@", work) for a in args]
            # each command threads alone: the jobs run side by side
            return run_one(options.binary, args[:1] + ["--threads", "1"] + args[1:]
                           if args[0] in ("render", "plane", "mesh", "animate") else args,
                           options.timeout)

        with concurrent.futures.ThreadPoolExecutor(options.jobs) as pool:
            pending = {}
            for index in range(options.count):
                algebra, command, args = job(rng, "@WORK@")
                pending[pool.submit(task, index, args)] = (algebra, command, args)
                if len(pending) >= options.jobs * 8 or index == options.count - 1:
                    for future in concurrent.futures.as_completed(list(pending)):
                        algebra, command, args = pending.pop(future)
                        outcome, detail, seconds = future.result()
                        outcomes[outcome] += 1
                        by_command[(command, outcome)] += 1
                        line = "quaternia " + " ".join(shlex.quote(a) for a in args)
                        done = sum(outcomes.values())
                        if done % 1000 == 0:
                            print(f"{done} scenes: " + ", ".join(
                                f"{k} {v}" for k, v in sorted(outcomes.items())), flush=True)
                        if seconds > slowest[0]:
                            slowest = (seconds, line)
                        if outcome not in ("ok", "refused"):
                            findings.append((outcome, detail, line))
                            print(f"{'SLOW' if outcome == 'hang' else 'FINDING'} {outcome}: "
                                  f"{detail}\n  {line}", flush=True)
    # A job over the timeout ran beside others on a shared machine: run it again alone, and count
    # it a hang only if it is over the timeout there too.
    hangs = [f for f in findings if f[0] == "hang"]
    if hangs:
        findings = [f for f in findings if f[0] != "hang"]
        with tempfile.TemporaryDirectory(prefix="quaternia-random-") as work:
            for _, _, line in hangs:
                args = [a.replace("@WORK@", work) for a in shlex.split(line)[1:]]
                outcome, detail, seconds = run_one(options.binary, args, options.timeout)
                print(f"hang rerun alone: {outcome} in {seconds:.1f} s: {line}", flush=True)
                outcomes["hang"] -= 1
                outcomes[outcome] += 1
                if outcome not in ("ok", "refused"):
                    findings.append((outcome, detail, line))
    print(f"{options.count} random scenes (seed {options.seed}): " +
          ", ".join(f"{k} {v}" for k, v in sorted(outcomes.items())))
    for command in sorted({c for c, _ in by_command}):
        print(f"  {command:8s} " + ", ".join(f"{o} {n}" for (c, o), n in sorted(by_command.items())
                                             if c == command))
    print(f"slowest: {slowest[0]:.1f} s: {slowest[1]}")
    print(f"findings: {len(findings)}")
    return 1 if findings else 0


if __name__ == "__main__":
    sys.exit(main())
