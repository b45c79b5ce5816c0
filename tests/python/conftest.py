"""Shared fixtures of the Python module's tests, run by ctest (tests/CMakeLists.txt) with
PYTHONPATH at build/python, VKPT_BINARY naming the vkpt command and VKPT_SOURCE_DIR the
checkout."""
import os
import pathlib
import subprocess

import numpy as np
import pytest

SOURCE = pathlib.Path(os.environ.get("VKPT_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
CORNELL = str(SOURCE / "scenes" / "cornell.gltf")
SMALL = dict(width=24, height=16, spp=4, chunk_spp=4, seed=5)


def run_vkpt(*args):
    """Runs the vkpt command with the small render's options; fails the test if it fails."""
    small = ["--width", "24", "--height", "16", "--spp", "4", "--chunk", "4", "--seed", "5"]
    r = subprocess.run([os.environ["VKPT_BINARY"], "--scene", CORNELL, *small, *args], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    return r


def read_pfm(path):
    """A PFM file as an H x W x 3 float32 array, row 0 at the top."""
    with open(path, "rb") as f:
        assert f.readline().strip() == b"PF"
        width, height = map(int, f.readline().split())
        scale = float(f.readline())
        data = np.frombuffer(f.read(), dtype="<f4" if scale < 0 else ">f4")
    return data.reshape(height, width, 3)[::-1].astype(np.float32)


@pytest.fixture(scope="module")
def cpu_scene():
    import vkpt

    return vkpt.Scene(CORNELL, backend="cpu")
