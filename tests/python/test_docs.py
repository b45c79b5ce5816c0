"""docs/python.md's examples run as written, and docs/examples/turntable.py renders a
turntable: each from a fresh folder holding the repository's scenes/."""
import os
import pathlib
import re
import subprocess
import sys

import pytest

from conftest import SOURCE

DOC = SOURCE / "docs" / "python.md"
BLOCKS = re.findall(r"```python\n(.*?)```", DOC.read_text(), re.S)


def run_python(args, folder):
    (folder / "scenes").symlink_to(SOURCE / "scenes")
    r = subprocess.run([sys.executable, *args], capture_output=True, text=True, cwd=folder)
    assert r.returncode == 0, r.stdout + r.stderr
    return r.stdout


def test_the_doc_has_examples():
    assert len(BLOCKS) >= 4


@pytest.mark.parametrize("index", range(len(BLOCKS)))
def test_doc_example_runs(index, tmp_path):
    run_python(["-c", BLOCKS[index]], tmp_path)


def test_the_first_example_writes_its_files(tmp_path):
    run_python(["-c", BLOCKS[0]], tmp_path)
    for name in ("cornell.png", "cornell.exr", "cornell-agx.png"):
        assert (tmp_path / name).stat().st_size > 1000, name


def test_turntable_writes_a_folder_of_exrs(tmp_path):
    script = SOURCE / "docs" / "examples" / "turntable.py"
    out = run_python([str(script), "scenes/cornell.gltf", "views", "--views", "3", "--width", "32", "--spp", "4",
                      "--backend", "cpu"], tmp_path)
    views = sorted((tmp_path / "views").iterdir())
    assert [v.name for v in views] == ["view_000.exr", "view_001.exr", "view_002.exr"]
    assert len({v.read_bytes() for v in views}) == 3
    assert "3 views on cpu" in out
