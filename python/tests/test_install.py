"""`cmake --install` puts a package that imports and renders, away from the build tree."""

import os
import subprocess
import sys

import pytest

BUILD_DIR = os.environ.get("QUATERNIA_BUILD_DIR")


@pytest.mark.skipif(not BUILD_DIR, reason="run from ctest, which names the build folder")
def test_the_installed_package_imports_and_renders(tmp_path):
    subprocess.run(["cmake", "--install", BUILD_DIR, "--prefix", str(tmp_path)],
                   check=True, capture_output=True)
    packages = list(tmp_path.glob("lib/python3*/dist-packages"))
    assert len(packages) == 1
    for name in ("__init__.py", "_quaternia.pyi", "py.typed"):
        assert (packages[0] / "quaternia" / name).exists()
    code = ("import quaternia; image = quaternia.render(quaternia.Scene(), 16, 10); "
            "print(quaternia.__file__, image.shape)")
    environment = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    environment["PYTHONPATH"] = str(packages[0])
    done = subprocess.run([sys.executable, "-c", code], cwd=tmp_path, env=environment,
                          capture_output=True, text=True, check=True)
    assert done.stdout.startswith(str(packages[0])) and "(10, 16, 4)" in done.stdout
    assert (tmp_path / "bin" / "quaternia").exists()
