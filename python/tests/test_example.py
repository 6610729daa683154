"""examples/c_sweep.py runs (small) and its two volumes agree."""

import os
import re
import subprocess
import sys

from conftest import SOURCE_DIR


def test_the_c_sweep_example_measures_and_plots(tmp_path):
    script = os.path.join(SOURCE_DIR, "examples", "c_sweep.py")
    output = tmp_path / "sweep.png"
    done = subprocess.run(
        [sys.executable, script, "--steps", "2", "--grid", "40", "--resolution", "40",
         "--output", str(output)],
        capture_output=True, text=True, check=True, env=dict(os.environ, MPLBACKEND="Agg"))
    assert output.read_bytes().startswith(b"\x89PNG")
    rows = re.findall(r"grid ([0-9.]+)\s+mesh ([0-9.]+)", done.stdout)
    assert len(rows) == 2
    solid = [(float(g), float(m)) for g, m in rows if float(m) > 0.1]
    assert solid  # the path passes a set of some volume, where the two measures agree
    for grid, mesh in solid:
        assert abs(grid / mesh - 1) < 0.1
