"""`cmake --build build --target wheel` writes build/dist/vkpt-*.whl without touching
build/python; `pip install` of it into a virtual environment (offline, NumPy from Debian
through --system-site-packages) gives a working, typed `import vkpt` there, with no
PYTHONPATH."""
import os
import pathlib
import subprocess
import sys

from conftest import CORNELL


def test_the_wheel_installs_into_a_venv(tmp_path):
    package = pathlib.Path(os.environ["PYTHONPATH"].split(os.pathsep)[0])
    build = package.parent
    before = sorted(p.name for p in package.iterdir())
    made = subprocess.run(["cmake", "--build", str(build), "--target", "wheel"], capture_output=True, text=True)
    assert made.returncode == 0, made.stdout + made.stderr
    assert sorted(p.name for p in package.iterdir()) == before, "the wheel's build wrote into build/python"
    wheels = sorted((build / "dist").glob("vkpt-*.whl"))
    assert len(wheels) == 1, wheels
    venv = tmp_path / "venv"
    subprocess.run([sys.executable, "-m", "venv", "--system-site-packages", str(venv)], check=True)
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    pip = subprocess.run([str(venv / "bin" / "pip"), "install", "--no-index", str(wheels[0])],
                         capture_output=True, text=True, env=env)
    assert pip.returncode == 0, pip.stdout + pip.stderr
    check = ("import pathlib, vkpt, numpy\n"
             f"r = vkpt.Scene({CORNELL!r}, backend='cpu').render(width=8, height=6, spp=1)\n"
             "here = pathlib.Path(vkpt.__file__).parent\n"
             "typed = all((here / f).exists() for f in ('py.typed', '__init__.pyi', '_vkpt.pyi'))\n"
             "print(vkpt.__file__, vkpt.__version__, typed, r.image.shape, r.image.dtype)\n")
    run = subprocess.run([str(venv / "bin" / "python"), "-c", check], capture_output=True, text=True, env=env,
                         cwd=tmp_path)
    assert run.returncode == 0, run.stderr
    where, version, typed, *shape = run.stdout.split()
    assert where.startswith(str(venv)), where
    assert typed == "True"
    assert " ".join(shape) == "(6, 8, 3) float32"
