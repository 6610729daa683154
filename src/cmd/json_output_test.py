"""Every command's --json, and the explorer's JSON answers, read by an independent parser
(Python's json, with NaN and Infinity refused): c reads back exactly as given, and a few values
have the right type.
Usage: python3 json_output_test.py path/to/quaternia"""
import json
import os
import re
import subprocess
import sys
import tempfile
import threading
import time
import urllib.error
import urllib.request

# Digits that 6 or 9 significant digits would lose.
C = [-0.12256116687665, 0.74486176661974, 0.0123456789012345, -0.3]
C_TEXT = "-0.12256116687665+0.74486176661974i+0.0123456789012345j-0.3k"
C_COMPLEX_TEXT = "-0.12256116687665+0.74486176661974i"
C_SET = "fractal.c=[%s]" % ", ".join(repr(v) for v in C)


def refuse(name):
    raise ValueError("not JSON: " + name)


def parse(text, what):
    try:
        return json.loads(text, parse_constant=refuse)
    except ValueError as error:
        raise AssertionError("%s: %s in:\n%s" % (what, error, text))


def check(condition, message):
    if not condition:
        raise AssertionError(message)


def check_types(report, what, **types):
    for key, kind in types.items():
        check(key in report, "%s: no %r in %s" % (what, key, report))
        value = report[key]
        # bool is an int in Python: a count must not come out as true/false, nor a flag as 0/1.
        ok = isinstance(value, kind) and (kind is bool or not isinstance(value, bool))
        check(ok, "%s: %r is %r, not %s" % (what, key, value, kind))


def run(binary, *arguments):
    result = subprocess.run([binary, *arguments], capture_output=True, text=True, timeout=120)
    what = " ".join(arguments)
    check(result.returncode == 0, "%s: exit %d: %s" % (what, result.returncode, result.stderr))
    return parse(result.stdout, what), what


def check_commands(binary, work):
    report, what = run(binary, "render", "--json", "-o", os.path.join(work, "r.png"), "--width",
                       "8", "--height", "6", "--set", "render.samples=1", "--set", C_SET)
    check(report["c"] == C, "%s: c = %r" % (what, report["c"]))
    check_types(report, what, command=str, width=int, rays=int, seconds=float, engine=str,
                lane_utilisation=(int, float))
    check(report["depth_output"] is None, what + ": depth_output is null without --depth")

    report, what = run(binary, "animate", "--json", "-o", os.path.join(work, "frames"),
                       "--preset", "hidden-turn", "--set", "animation.duration=0.1", "--width",
                       "8", "--height", "6", "--set", "render.samples=1", "--set", C_SET)
    check_types(report, what, command=str, output=str, film_frames=int, first_frame=int,
                last_frame=int, frames_rendered=int, frames_skipped=int, seconds=float,
                frames_per_second=float, render_seconds=float, fps=float, width=int, threads=int)
    check(report["frames_rendered"] == 3, "%s: %r frames" % (what, report["frames_rendered"]))
    check(report["video"] is None, what + ": video is null without --video")

    report, what = run(binary, "plane", "--json", "-o", os.path.join(work, "p.png"), "--width",
                       "8", "--height", "6", "--set", C_SET)
    check(report["c"] == C, "%s: c = %r" % (what, report["c"]))
    check_types(report, what, kind=str, width=int, seconds=float, threads=int)

    report, what = run(binary, "mesh", "--json", "-o", os.path.join(work, "m.stl"),
                       "--resolution", "8", "--set", C_SET)
    check(report["c"] == C, "%s: c = %r" % (what, report["c"]))
    check_types(report, what, resolution=int, iso=(int, float), cell_size=float, grid=list,
                triangles=int, volume=(int, float), watertight=bool, seconds=float)

    report, what = run(binary, "orbit", "--json", "--c", C_TEXT)
    check(report["c"] == C, "%s: c = %r" % (what, report["c"]))
    check_types(report, what, z0=list, fate=str, preperiod=int, unsure=bool, iterations=int,
                escape_radius=float)

    # Complex c: the quaternion written back has j = k = 0.
    report, what = run(binary, "cycles", "--json", "--c", C_COMPLEX_TEXT, "--period", "3")
    check(report["c"] == C[:2] + [0, 0], "%s: c = %r" % (what, report["c"]))
    check_types(report, what, period=int, points=int, cycles=list)
    check(len(report["cycles"]) > 0, what + ": no cycles")
    check_types(report["cycles"][0], what + " cycles[0]", multiplier=list, complete=bool,
                residual=float)


class Explorer:
    """`binary explore SCENE --port 0`; url is what it prints once it listens."""

    def __init__(self, binary, scene):
        self.process = subprocess.Popen([binary, "explore", scene, "--port", "0"],
                                        stdout=subprocess.PIPE, text=True)
        found = []

        def read():
            for line in self.process.stdout:
                match = re.search(r"(http://\S+)", line)
                if match:
                    found.append(match.group(1))

        threading.Thread(target=read, daemon=True).start()
        deadline = time.monotonic() + 20
        while not found:
            check(self.process.poll() is None, "explore exited")
            check(time.monotonic() < deadline, "explore did not start")
            time.sleep(0.02)
        self.url = found[0].rstrip("/")

    def get(self, path):
        try:
            with urllib.request.urlopen(self.url + path, timeout=60) as response:
                return response.status, response.read().decode()
        except urllib.error.HTTPError as error:
            return error.code, error.read().decode()

    def stop(self):
        self.process.terminate()
        self.process.wait(10)


def check_explorer(binary, work):
    scene = os.path.join(work, "scene.toml")
    with open(scene, "w") as file:
        file.write("[fractal]\nc = [%s]\n" % ", ".join(repr(v) for v in C))
    explorer = Explorer(binary, scene)
    try:
        status, text = explorer.get("/api/parameters")
        table = parse(text, "/api/parameters")
        check(status == 200 and isinstance(table, list), "/api/parameters: a list")
        c = next(p for p in table if p["name"] == "fractal.c")
        check(c["value"] == C, "/api/parameters: fractal.c = %r" % c["value"])
        check_types(c, "/api/parameters fractal.c", default=list, minimum=(int, float),
                    choices=list, help=str)
        status, text = explorer.get("/api/render?fractal.max_iterations=0")
        error = parse(text, "/api/render error")
        check(status == 400 and error["key"] == "fractal.max_iterations",
              "/api/render error: %d %r" % (status, error))
        check_types(error, "/api/render error", error=str)
    finally:
        explorer.stop()


def main():
    binary = sys.argv[1]
    with tempfile.TemporaryDirectory(prefix="quaternia-json-") as work:
        check_commands(binary, work)
        check_explorer(binary, work)
    print("json output test: render, animate, plane, mesh, orbit, cycles and explore read back")


if __name__ == "__main__":
    main()
