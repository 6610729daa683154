"""Shared by the Python module's tests: the CLI to compare with, and small scenes."""

import os
import subprocess
import tempfile

import numpy as np
import pytest

import quaternia

BINARY = os.environ.get("QUATERNIA_BINARY", "quaternia")
SOURCE_DIR = os.environ.get(
    "QUATERNIA_SOURCE_DIR", os.path.dirname(os.path.dirname(os.path.dirname(__file__)))
)


def run_cli(*args, check=True):
    """Runs the quaternia command; returns the completed process (text output)."""
    return subprocess.run([BINARY, *args], capture_output=True, text=True, check=check)


def cli_file(command, *args, suffix=".png"):
    """Runs `quaternia COMMAND ... -o FILE` and returns the file's bytes."""
    with tempfile.TemporaryDirectory() as directory:
        path = os.path.join(directory, "out" + suffix)
        run_cli(command, *args, "-o", path)
        with open(path, "rb") as f:
            return f.read()


def png_rgba(data):
    """A PNG's samples (as bytes) as an array (h, w, 4), alpha the largest sample where the
    file has none (an opaque RGB file)."""
    with tempfile.TemporaryDirectory() as directory:
        path = os.path.join(directory, "in.png")
        with open(path, "wb") as f:
            f.write(data)
        samples = quaternia.read_png(path)
    if samples.shape[2] == 4:
        return samples
    alpha = np.full(samples.shape[:2] + (1,), np.iinfo(samples.dtype).max, samples.dtype)
    return np.concatenate([samples, alpha], axis=2)


@pytest.fixture
def small_scene():
    scene = quaternia.Scene()
    scene["render.width"] = 64
    scene["render.height"] = 40
    scene["render.samples"] = 1
    return scene
