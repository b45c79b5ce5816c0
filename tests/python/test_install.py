"""`pip install build/python` into a virtual environment (offline, NumPy from Debian through
--system-site-packages) gives a working `import vkpt` there, with no PYTHONPATH."""
import os
import pathlib
import shutil
import subprocess
import sys

from conftest import CORNELL


def test_pip_installs_the_package_into_a_venv(tmp_path):
    built = pathlib.Path(os.environ["PYTHONPATH"].split(os.pathsep)[0])
    source = tmp_path / "package"
    shutil.copytree(built, source)  # pip builds in the folder it is given
    venv = tmp_path / "venv"
    subprocess.run([sys.executable, "-m", "venv", "--system-site-packages", str(venv)], check=True)
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    pip = subprocess.run(
        [str(venv / "bin" / "pip"), "install", "--no-index", "--no-build-isolation", str(source)],
        capture_output=True, text=True, env=env)
    assert pip.returncode == 0, pip.stdout + pip.stderr
    check = ("import vkpt, numpy\n"
             f"r = vkpt.Scene({CORNELL!r}, backend='cpu').render(width=8, height=6, spp=1)\n"
             "print(vkpt.__file__, vkpt.__version__, r.image.shape, r.image.dtype)\n")
    run = subprocess.run([str(venv / "bin" / "python"), "-c", check], capture_output=True, text=True, env=env,
                         cwd=tmp_path)
    assert run.returncode == 0, run.stderr
    where, version, *shape = run.stdout.split()
    assert where.startswith(str(venv)), where
    assert " ".join(shape) == "(6, 8, 3) float32"
