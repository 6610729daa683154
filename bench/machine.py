#!/usr/bin/env python3
"""The head of a results file under bench/results/: where and when it was measured.

A table of timings means nothing without the machine that made it, the instruction set its
lanes ran on, the date and the commit (docs/benchmarks.md: the machines are shared and differ).
bench/run.sh and bench/compare write their tables to bench/results/ with this head, so that a
result file says it all by itself.

As a program (for bench/run.sh): bench/machine.py QUATERNIA_BINARY KIND TITLE COMMAND prints the
path of a new results file, bench/results/KIND-DATE-ISA.md, on the first line, then its head.
"""
import datetime
import json
import os
import pathlib
import subprocess
import sys
import tempfile

ROOT = pathlib.Path(__file__).resolve().parent.parent
RESULTS = ROOT / "bench" / "results"


def cpu_model():
    """The CPU's model name and its logical processors, from /proc/cpuinfo."""
    model, processors = "unknown CPU", 0
    try:
        with open("/proc/cpuinfo") as cpuinfo:
            for line in cpuinfo:
                key, _, value = line.partition(":")
                if key.strip() == "model name" and model == "unknown CPU":
                    model = value.strip()
                elif key.strip() == "processor":
                    processors += 1
    except OSError:
        pass
    return model, processors


def lane_isa(binary, isa="best"):
    """The instruction set `quaternia --isa ISA` runs its lanes on here, as its --json's
    engine names it (AVX3, AVX2, ...): what a tiny render reports."""
    with tempfile.TemporaryDirectory() as folder:
        result = subprocess.run([binary, "--isa", isa, "render", "--width", "8", "--height", "8",
                                 "--json", "-o", os.path.join(folder, "probe.png")],
                                capture_output=True, text=True)
    if result.returncode != 0:
        return isa
    return json.loads(result.stdout).get("engine", isa)


def commit():
    """The commit of the tree, marked when the tree has changes that are not committed."""
    def git(*args):
        return subprocess.run(["git", "-C", str(ROOT)] + list(args), capture_output=True,
                              text=True)
    head = git("rev-parse", "--short=12", "HEAD")
    if head.returncode != 0:
        return "unknown (not a git checkout)"
    dirty = git("status", "--porcelain", "--untracked-files=no").stdout.strip()
    return head.stdout.strip() + (" with uncommitted changes" if dirty else "")


def results_file(kind, isa, now):
    """bench/results/KIND-YYYY-MM-DD-HHMM-ISA.md (UTC), made unique if it exists."""
    RESULTS.mkdir(parents=True, exist_ok=True)
    stem = "%s-%s-%s" % (kind, now.strftime("%Y-%m-%d-%H%M"), isa.lower())
    path, n = RESULTS / (stem + ".md"), 2
    while path.exists():
        path, n = RESULTS / ("%s-%d.md" % (stem, n)), n + 1
    return path


def head(title, command, isa, now, lanes_note=""):
    """The file's title and a list: date, machine, lanes, commit, command, load."""
    model, processors = cpu_model()
    return "\n".join([
        "# %s" % title,
        "",
        "- date: %s UTC" % now.strftime("%Y-%m-%d %H:%M"),
        "- machine: %s, %d logical processors, %d available to the process" % (
            model, processors, len(os.sched_getaffinity(0))),
        "- lanes: %s%s" % (isa, lanes_note),
        "- commit: %s" % commit(),
        "- command: `%s`" % command,
        "- load average at the start: %.2f" % os.getloadavg()[0],
        "",
    ]) + "\n"


def main():
    if len(sys.argv) != 5:
        sys.exit("usage: bench/machine.py QUATERNIA_BINARY KIND TITLE COMMAND")
    binary, kind, title, command = sys.argv[1:]
    now = datetime.datetime.now(datetime.timezone.utc)
    isa = lane_isa(binary)
    print(results_file(kind, isa, now).relative_to(ROOT))
    print(head(title, command, isa, now, " (the best this CPU has; rows named `-avx2` are capped "
               "with `quaternia --isa avx2`)"), end="")


if __name__ == "__main__":
    main()
