"""quaternia-mpi against quaternia: the same files byte for byte, whatever the ranks and threads;
a rank killed in the middle of a film, then the command again: the same frames as an
uninterrupted run; a bad scene: one line from rank 0, exit code 2, no file; rank 0's memory
stays far below the image's size (the PNG is streamed band by band).

Usage: mpi_test.py MPIRUN QUATERNIA QUATERNIA_MPI [TEST...]
As root, OpenMPI needs OMPI_ALLOW_RUN_AS_ROOT=1 and OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 (set here).
"""
import json
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import time
from pathlib import Path

MPIRUN, QUATERNIA, QUATERNIA_MPI = sys.argv[1:4]
ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
           OMPI_MCA_rmaps_base_oversubscribe="1")

TURN = ["--preset", "hidden-turn", "--set", "animation.fps=3"]


def mpi(ranks, *args, check=True):
    command = [MPIRUN, "-q", "--oversubscribe", "-np", str(ranks), QUATERNIA_MPI, *args]
    done = subprocess.run(command, env=ENV, capture_output=True, text=True, timeout=600)
    if check and done.returncode != 0:
        raise AssertionError(f"{' '.join(command)} exited {done.returncode}: {done.stderr}")
    return done


def single(*args):
    done = subprocess.run([QUATERNIA, *args], capture_output=True, text=True, timeout=600)
    if done.returncode != 0:
        raise AssertionError(f"quaternia {' '.join(args)}: {done.stderr}")
    return done


def same_files(a, b):
    names_a = sorted(p.name for p in Path(a).iterdir())
    names_b = sorted(p.name for p in Path(b).iterdir())
    assert names_a == names_b, f"{a}: {names_a} but {b}: {names_b}"
    for name in names_a:
        assert (Path(a) / name).read_bytes() == (Path(b) / name).read_bytes(), f"{name} differs"


def test_render_is_byte_identical(tmp):
    # Two units across, three bands, 16-bit RGBA with coverage and a depth pass; then opaque RGB.
    cases = [
        ["--width", "1100", "--height", "150", "--set", "render.alpha=\"coverage\"",
         "--set", "render.bit_depth=16", "--set", "render.samples=2"],
        ["--width", "1100", "--height", "150", "--set", "render.alpha=\"opaque\""],
    ]
    for n, case in enumerate(cases):
        expected, depth = tmp / f"single{n}.png", tmp / f"single{n}_depth.png"
        single("render", *case, "-o", str(expected), "--depth", str(depth))
        for ranks, threads in [(1, 2), (3, 1), (2, 2)]:
            out, out_depth = tmp / f"mpi{n}.png", tmp / f"mpi{n}_depth.png"
            done = mpi(ranks, "render", *case, "--threads", str(threads), "-o", str(out),
                       "--depth", str(out_depth), "--json")
            assert out.read_bytes() == expected.read_bytes(), f"case {n}, {ranks} ranks"
            assert out_depth.read_bytes() == depth.read_bytes(), f"depth {n}, {ranks} ranks"
            summary = json.loads(done.stdout)
            assert summary["ranks"] == ranks and len(summary["per_rank"]) == ranks
            assert sum(r["pixels"] for r in summary["per_rank"]) == 1100 * 150
            assert sum(r["units"] for r in summary["per_rank"]) == 6
            assert summary["rays"] == 1100 * 150 * summary["samples"]


def test_animate_is_byte_identical(tmp):
    film = ["--width", "64", "--height", "36", *TURN, "--set", "animation.duration=2"]
    single("animate", *film, "-o", str(tmp / "single"))
    done = mpi(3, "animate", *film, "--threads", "1", "-o", str(tmp / "mpi"),
               "--video", str(tmp / "film.mp4"), "--json")
    same_files(tmp / "single", tmp / "mpi")
    summary = json.loads(done.stdout)
    assert summary["frames_rendered"] == 6 and summary["ranks"] == 3
    assert sum(r["frames"] for r in summary["per_rank"]) == 6
    assert (tmp / "film.mp4").stat().st_size > 0
    # --print-frame prints frame 3's scene once, as quaternia does.
    printed = mpi(3, "animate", *film, "--print-frame", "3").stdout
    assert printed == single("animate", *film, "--print-frame", "3").stdout
    # Run again: every frame exists, none is rendered.
    again = json.loads(mpi(2, "animate", *film, "-o", str(tmp / "mpi"), "--json").stdout)
    assert again["frames_rendered"] == 0 and again["frames_skipped"] == 6


def rank_pids(rank):
    pids = []
    for entry in Path("/proc").iterdir():
        if not entry.name.isdigit():
            continue
        try:
            environ = (entry / "environ").read_bytes().split(b"\0")
            cmdline = (entry / "cmdline").read_bytes()
        except OSError:
            continue
        if QUATERNIA_MPI.encode() in cmdline and f"OMPI_COMM_WORLD_RANK={rank}".encode() in environ:
            pids.append(int(entry.name))
    return pids


def test_killed_rank_then_restart(tmp):
    # Frames slow enough (about 0.3 s each on one core) that the film is far from done when
    # mpirun, a second or two after the kill, ends the job. Under the sanitizers (CMakeLists.txt
    # sets QUATERNIA_SANITIZED) each sample costs about ten times as much, so a tenth of them do.
    samples = 10 if os.environ.get("QUATERNIA_SANITIZED") else 100
    film = ["--width", "192", "--height", "108", "--set", f"render.samples={samples}", *TURN,
            "--set", "animation.duration=6", "--threads", "1"]
    single("animate", *film, "-o", str(tmp / "whole"))
    assert len(list((tmp / "whole").iterdir())) == 18
    killed = tmp / "killed"
    command = [MPIRUN, "-q", "--oversubscribe", "-np", "3", QUATERNIA_MPI, "animate", *film,
               "-o", str(killed)]
    job = subprocess.Popen(command, env=ENV, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    deadline = time.time() + 60
    victims = []
    while time.time() < deadline and not victims and job.poll() is None:
        victims = rank_pids(1)
    assert victims, f"rank 1 not found; mpirun exited {job.poll()}"
    while time.time() < deadline and not list(killed.glob("frame_*.png")):
        time.sleep(0.002)
    for pid in victims:
        os.kill(pid, signal.SIGKILL)
    assert job.wait(timeout=120) != 0, "the job went on without rank 1"
    written = len(list(killed.glob("frame_*.png")))
    assert 1 <= written < 18, f"{written} frames at the kill"
    mpi(3, "animate", *film, "-o", str(killed))
    assert not list(killed.glob("*.tmp-*")), "a temporary was left"
    same_files(tmp / "whole", killed)


def test_killed_rank_leaves_no_png(tmp):
    out = tmp / "poster.png"
    command = [MPIRUN, "-q", "--oversubscribe", "-np", "3", QUATERNIA_MPI, "render", "--width",
               "2048", "--height", "2048", "--set", "render.samples=4", "--threads", "1",
               "-o", str(out)]
    job = subprocess.Popen(command, env=ENV, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    deadline = time.time() + 60
    # The PNG's first pieces are in its temporary: the render is under way.
    while time.time() < deadline and job.poll() is None and not any(
            p.stat().st_size > 1000 for p in tmp.glob("poster.png.tmp-*")):
        time.sleep(0.005)
    victims = rank_pids(1)
    assert victims, f"rank 1 not found; mpirun exited {job.poll()}"
    for pid in victims:
        os.kill(pid, signal.SIGKILL)
    assert job.wait(timeout=120) != 0, "the job went on without rank 1"
    assert not out.exists(), "a PNG was written"
    assert not list(tmp.iterdir()), f"left behind: {list(tmp.iterdir())}"


def test_bad_scene_is_one_line_from_rank_zero(tmp):
    out = tmp / "bad.png"
    done = mpi(3, "render", "--set", "fractal.bailout=-1", "-o", str(out), check=False)
    assert done.returncode == 2, done.returncode
    lines = done.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("quaternia: error: ") and "fractal.bailout" in lines[0], done.stderr
    assert not out.exists() and not list(tmp.iterdir())
    done = mpi(3, "render", "--no-such-option", check=False)
    assert done.returncode == 2 and len(done.stderr.strip().splitlines()) == 1, done.stderr
    # A request beyond --memory-budget: refused before any work, naming the size key.
    for command in (["render", "-o", str(out)], ["animate", "--preset", "hidden-turn", "-o", str(tmp / "frames")]):
        done = mpi(2, *command, "--width", "16384", "--height", "16384", "--memory-budget", "4M",
                   check=False)
        lines = done.stderr.strip().splitlines()
        assert done.returncode == 2 and len(lines) == 1 and "render.width" in lines[0], done.stderr
        assert "of memory, more than the 4.00 MiB available" in lines[0], done.stderr
        assert not list(tmp.iterdir()), list(tmp.iterdir())


def test_rank_zero_streams_the_png(tmp):
    # A 6144 x 6144 RGB image is 108 MiB; rank 0 holds a window of bands.
    out = tmp / "big.png"
    size = 6144
    done = mpi(2, "render", "--width", str(size), "--height", str(size), "--set",
               "render.alpha=\"opaque\"", "--set", "render.samples=1", "--set",
               "camera.fov=150", "-o", str(out), "--json")
    summary = json.loads(done.stdout)
    image_kib = size * size * 3 // 1024
    rss = summary["per_rank"][0]["peak_rss_kib"]
    print(f"rank 0 peak RSS {rss / 1024:.0f} MiB for an image of {image_kib / 1024:.0f} MiB")
    assert rss < image_kib / 2, f"rank 0 peak {rss} KiB, image {image_kib} KiB"
    assert out.stat().st_size > 0


TESTS = {name[5:]: f for name, f in globals().items() if name.startswith("test_")}

if __name__ == "__main__":
    names = sys.argv[4:] or list(TESTS)
    failed = 0
    for name in names:
        tmp = Path(tempfile.mkdtemp(prefix="quaternia_mpi_"))
        start = time.time()
        try:
            TESTS[name](tmp)
            print(f"ok   {name} ({time.time() - start:.1f} s)")
        except Exception as e:  # report every test, then fail
            failed += 1
            print(f"FAIL {name}: {e}")
        finally:
            shutil.rmtree(tmp, ignore_errors=True)
    sys.exit(1 if failed else 0)
