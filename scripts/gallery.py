#!/usr/bin/env python3
"""Runs the commands of docs/gallery.md: small, to check them, or as written, to remake it.

Every picture of docs/gallery.md sits above the `quaternia ...` command that made it, in a
```sh block of its own. Options get renamed, ranges tightened and defaults changed, and a
command on a documentation page breaks without anyone noticing; so ctest's
Docs.GalleryCommandsRun runs them all (--check): each writes into a temporary folder instead of
docs/gallery, at 64x36 (mesh: resolution 16) with one sample per pixel, and the test fails if
any exits non-zero. --make runs them as written, from the repository root, to remake the
pictures (commands whose output is not under docs/gallery, such as the mesh's STL, are skipped).

Usage: scripts/gallery.py --check|--make QUATERNIA_BINARY
"""
import os
import pathlib
import re
import shlex
import subprocess
import sys
import tempfile
import time

ROOT = pathlib.Path(__file__).resolve().parent.parent
PAGE = ROOT / "docs" / "gallery.md"
BLOCK = re.compile(r"^```sh\n(.*?)^```", re.S | re.M)


def commands():
    """The argument lists of the page's commands, in order, each without the leading
    'quaternia'."""
    found = []
    for block in BLOCK.findall(PAGE.read_text(encoding="utf-8")):
        text = block.replace("\\\n", " ").strip()
        words = shlex.split(text, comments=True)
        if not words or words[0] != "quaternia" or "\n" in text:
            sys.exit("docs/gallery.md: a ```sh block must hold one `quaternia ...` command, "
                     "not %r" % text)
        found.append(words[1:])
    return found


def set_option(words, name, value):
    """`words` with option `name` taking `value`: replaced where given, else appended (CLI11
    refuses an option given twice)."""
    words = list(words)
    if name in words:
        words[words.index(name) + 1] = value
    else:
        words += [name, value]
    return words


def small(words, folder):
    """The command made cheap: outputs into `folder`, a tiny image, one sample per pixel."""
    command = next(w for w in words if not w.startswith("-"))
    for option in ("-o", "--output", "--video", "--depth"):
        if option in words:
            i = words.index(option) + 1
            words = words[:i] + [str(folder / os.path.basename(words[i]))] + words[i + 1:]
    if command in ("render", "plane", "animate"):
        words = set_option(set_option(words, "--width", "64"), "--height", "36")
        words = words + ["--set", "render.samples=1"]
    if command == "mesh":
        words = set_option(words, "--resolution", "16")
    return words


def output_of(words):
    for option in ("-o", "--output"):
        if option in words:
            return words[words.index(option) + 1]
    return None


def main() -> int:
    if len(sys.argv) != 3 or sys.argv[1] not in ("--check", "--make"):
        print(__doc__.strip().splitlines()[-1], file=sys.stderr)
        return 2
    mode, binary = sys.argv[1], str(pathlib.Path(sys.argv[2]).resolve())
    failures = 0
    with tempfile.TemporaryDirectory(prefix="quaternia-gallery-") as temporary:
        for words in commands():
            if mode == "--check":
                run = small(words, pathlib.Path(temporary))
            else:
                output = output_of(words)
                if output is None or not output.startswith("docs/gallery/"):
                    print("skipped (not a picture of the page): quaternia " + shlex.join(words))
                    continue
                run = words
            start = time.monotonic()
            result = subprocess.run([binary] + run, cwd=ROOT, stdout=subprocess.DEVNULL,
                                    stderr=subprocess.PIPE, text=True)
            seconds = time.monotonic() - start
            shown = "quaternia " + shlex.join(run)
            if result.returncode != 0:
                failures += 1
                print("FAILED (exit %d, %.1f s): %s\n%s" % (result.returncode, seconds, shown,
                                                             result.stderr.strip()))
            else:
                print("ok (%.1f s): %s" % (seconds, shown))
    if failures:
        print("%d command%s of docs/gallery.md failed: fix the command on the page, or the "
              "change that broke it" % (failures, "" if failures == 1 else "s"))
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
