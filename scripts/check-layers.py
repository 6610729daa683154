#!/usr/bin/env python3
"""Fails when a source file includes from a layer above its own.

Each folder of the library is a layer and may include only from itself and the folders named
for it below (docs/architecture.md, "The layers", and the README draw the same map). Tests
count as part of the folder they sit in. Prints each offending include as FILE:LINE: FOLDER may not include TARGET.
"""
import pathlib
import re
import sys

# What each folder may include besides itself. A folder not listed here is an error, so that a
# new folder gets its place in the map when it is made.
LIBRARY = "quaternia/"
MAY_USE = {
    "quaternia/util": [],
    "quaternia/algebra": ["util"],
    "quaternia/image": ["util", "algebra"],
    "quaternia/interval": ["util", "algebra"],
    "quaternia/fractal": ["util", "algebra", "interval"],
    "quaternia/scene": ["util", "algebra", "interval", "fractal"],
    "quaternia/cellmap": ["util", "algebra", "interval", "fractal", "scene"],
    "quaternia/distribute": ["util", "scene"],
    "quaternia/dynamics": ["util", "algebra", "image", "scene", "interval", "fractal"],
    "quaternia/render/lanes": ["util", "algebra", "scene", "interval", "fractal"],
    "quaternia/render": ["util", "algebra", "image", "scene", "interval", "fractal", "cellmap",
                         "render/lanes"],
    "quaternia/plane": ["util", "algebra", "image", "scene", "interval", "fractal", "cellmap", "dynamics", "render",
                        "render/lanes"],
    "quaternia/mesh": ["util", "algebra", "image", "scene", "interval", "fractal", "render", "render/lanes"],
    "quaternia/film": ["util", "algebra", "image", "scene", "interval", "fractal", "render"],
    "server": ["quaternia/*"],
    "python": ["quaternia/*"],
    "cmd": ["quaternia/*", "server"],
}

INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"')


def folder_of(path: str) -> str:
    return path.rsplit("/", 1)[0] if "/" in path else ""


def allowed(own: str, target_folder: str) -> bool:
    if target_folder == own:
        return True
    for use in MAY_USE[own]:
        full = use if use.startswith(("quaternia", "server", "cmd")) else LIBRARY + use
        if full.endswith("/*"):
            if target_folder.startswith(full[:-1]):
                return True
        elif target_folder == full:
            return True
    return False


def main() -> int:
    # The tree to check: the project's src/, or the folder given (the test of this script).
    src = (pathlib.Path(sys.argv[1]) if len(sys.argv) > 1
           else pathlib.Path(__file__).resolve().parent.parent / "src")
    problems = []
    for path in sorted(src.rglob("*")):
        if path.suffix not in (".h", ".cpp"):
            continue
        relative = path.relative_to(src).as_posix()
        own = folder_of(relative)
        if own not in MAY_USE:
            problems.append(f"{relative}: folder {own} has no place in the layer map "
                            f"(scripts/check-layers.py)")
            continue
        for number, line in enumerate(path.read_text().splitlines(), 1):
            match = INCLUDE.match(line)
            if not match:
                continue
            target = match.group(1)
            if "/" not in target:
                problems.append(f"{relative}:{number}: include \"{target}\" does not name "
                                f"its folder")
                continue
            target_folder = folder_of(target)
            if target_folder not in MAY_USE:
                continue  # a generated or system header found through the include path
            if not allowed(own, target_folder):
                problems.append(f"{relative}:{number}: {own} may not include {target} "
                                f"(layer {target_folder} is not below it)")
    for problem in problems:
        print(problem)
    if problems:
        print(f"{len(problems)} include(s) break the layering", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
