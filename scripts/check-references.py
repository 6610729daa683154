#!/usr/bin/env python3
"""Fails when docs/parameters.md or docs/cli.md differs from what the code generates.

The two pages are printed by `quaternia reference parameters` and `quaternia reference cli`
from the parameter table, the presets and the CLI11 declarations, and committed so that they
can be read on GitHub. A change to a key, a default, a range or a help string then has to be
followed by regenerating the page; this check (ctest's Docs.ParameterReferenceIsCurrent and
Docs.CliReferenceIsCurrent) says so, with the command line that does it, instead of letting the
page go stale.

Usage: scripts/check-references.py QUATERNIA_BINARY parameters|cli
"""
import difflib
import os
import pathlib
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent


def main() -> int:
    if len(sys.argv) != 3 or sys.argv[2] not in ("parameters", "cli"):
        print(__doc__.strip().splitlines()[-1], file=sys.stderr)
        return 2
    binary, page = pathlib.Path(sys.argv[1]).resolve(), sys.argv[2]
    committed_path = ROOT / "docs" / (page + ".md")
    result = subprocess.run([str(binary), "reference", page], capture_output=True, text=True)
    if result.returncode != 0:
        print("%s reference %s failed (exit %d): %s"
              % (binary, page, result.returncode, result.stderr.strip()))
        return 1
    generated = result.stdout
    committed = committed_path.read_text() if committed_path.exists() else ""
    if generated == committed:
        return 0
    # The command line to paste, from the repository root when the binary is inside it.
    shown = os.path.relpath(binary, ROOT) if binary.is_relative_to(ROOT) else str(binary)
    diff = list(difflib.unified_diff(committed.splitlines(), generated.splitlines(),
                                     "docs/%s.md (committed)" % page,
                                     "%s reference %s (generated)" % (shown, page), lineterm="",
                                     n=1))
    print("docs/%s.md is not what the code generates%s:" % (
        page, "" if committed_path.exists() else " (the file is missing)"))
    print("\n".join(diff[:60]) + ("\n... (%d more lines of diff)" % (len(diff) - 60)
                                   if len(diff) > 60 else ""))
    print("\nRegenerate it, from the repository root:\n    %s reference %s > docs/%s.md"
          % (shown, page, page))
    return 1


if __name__ == "__main__":
    sys.exit(main())
