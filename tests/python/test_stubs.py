"""The type stubs built beside the module (host/python/make_stubs.py) against the module
itself: mypy's stubtest for every name, and pybind11's own signatures for every
function's parameters, keywords and defaults (stubtest cannot read a compiled function's
signature); a stub edited by hand is caught; and a user's script type-checks, its
mistakes found, as an IDE finds them."""
import ast
import os
import re
import pathlib
import shutil
import subprocess
import sys

import pytest

import vkpt._vkpt

PACKAGE = pathlib.Path(os.environ["PYTHONPATH"].split(os.pathsep)[0])
# pybind11's classes have its own metaclass, which no stub can name: only that, by class.
ALLOWLIST = r"vkpt(\._vkpt)?\.[A-Z]\w*" + "\n"


def stubtest(package_dir, tmp_path):
    allow = tmp_path / "allowlist.txt"
    allow.write_text(ALLOWLIST)
    code = ("import sys\nfrom mypy.stubtest import main\n"
            f"sys.argv = ['stubtest', 'vkpt', '--concise', '--allowlist', {str(allow)!r}]\nsys.exit(main())\n")
    env = dict(os.environ, PYTHONPATH=str(package_dir), MYPYPATH=str(package_dir))
    return subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env, cwd=tmp_path)


def test_the_stubs_match_the_module(tmp_path):
    for f in ("_vkpt.pyi", "__init__.pyi", "py.typed"):
        assert (PACKAGE / "vkpt" / f).exists(), f
    r = stubtest(PACKAGE, tmp_path)
    assert r.returncode == 0, r.stdout + r.stderr


def runtime_signatures():
    """Every function of the module as pybind11 declares it: (owner, name) -> parameters,
    each (name, kind, has a default), kind "*" after a bare * (keyword-only)."""
    found = {}
    owners = [("", vkpt._vkpt)] + [(n, c) for n, c in vars(vkpt._vkpt).items() if isinstance(c, type)]
    for owner, holder in owners:
        for name, f in vars(holder).items():
            line = (getattr(f, "__doc__", None) or "").split("\n")[0]
            m = re.match(rf"{re.escape(name)}\((.*)\) ->", line)
            if not callable(f) or not m:
                continue
            params, keyword = [], False
            for p in re.split(r", (?![^\[]*\])", m.group(1)) if m.group(1) else []:
                if p == "*":
                    keyword = True
                    continue
                params.append((p.split(":")[0].lstrip("*"), "*" if keyword else "", " = " in p))
            found[(owner, name)] = params
    return found


def stub_signatures(text):
    found = {}
    for node in ast.walk(ast.parse(text)):
        for f in getattr(node, "body", []):
            if isinstance(f, ast.FunctionDef) and not any(getattr(d, "id", "") == "property" for d in f.decorator_list):
                a = f.args
                plain = a.posonlyargs + a.args
                params = [(x.arg, "", i >= len(plain) - len(a.defaults)) for i, x in enumerate(plain)]
                params += [(x.arg, "*", d is not None) for x, d in zip(a.kwonlyargs, a.kw_defaults)]
                if a.vararg:
                    params.append((a.vararg.arg, "", False))
                found[(getattr(node, "name", ""), f.name)] = params
    return found


def mismatches(text):
    stub = stub_signatures(text)
    return [(key, params, stub.get(key)) for key, params in runtime_signatures().items() if stub.get(key) != params]


def test_every_signature_is_pybind11s():
    runtime = runtime_signatures()
    assert ("Scene", "render") in runtime and len(runtime) > 10
    assert mismatches((PACKAGE / "vkpt" / "_vkpt.pyi").read_text()) == []


@pytest.mark.parametrize("edit", [("seed: int = ..., ", "seeds: int = ..., "),
                                  ("seed: int = ..., ", "seed: int, "),
                                  ("*, width", "width")])
def test_a_stub_that_differs_from_the_module_is_caught(edit):
    text = (PACKAGE / "vkpt" / "_vkpt.pyi").read_text()
    render = next(line for line in text.splitlines() if line.lstrip().startswith("def render("))
    assert edit[0] in render
    mutated = text.replace(render, render.replace(edit[0], edit[1], 1))
    assert [key for key, _, _ in mismatches(mutated)] == [("Scene", "render")]


def test_a_missing_name_is_caught(tmp_path):
    copy = tmp_path / "package"
    shutil.copytree(PACKAGE / "vkpt", copy / "vkpt")
    stub = copy / "vkpt" / "_vkpt.pyi"
    stub.write_text(stub.read_text().replace("    def cancel(self)", "    def cancelled(self)"))
    r = stubtest(copy, tmp_path)
    assert r.returncode != 0 and "Scene.cancel" in r.stdout, r.stdout + r.stderr


@pytest.mark.parametrize("script, error", [
    ("scene = vkpt.Scene('a.glb')\nimage: NDArray[numpy.float32] = scene.render(spp=4).image\n"
     "colour: tuple[float, float, float] = scene.materials[0].base_color\n"
     "p = scene.parameters()\np['nodes/0/translation'] = (1.0, 2.0, 3.0)\nscene.update(p)\n", None),
    ("vkpt.Scene('a.glb').render(spp=4).imag\n", '"Render" has no attribute "imag"'),
    ("vkpt.Scene('a.glb').render(sp=4)\n", 'Unexpected keyword argument "sp"'),
    ("vkpt.Scene('a.glb').render(spp='4')\n", 'incompatible type "str"'),
])
def test_a_users_script_type_checks(tmp_path, script, error):
    user = tmp_path / "user.py"
    user.write_text("import numpy\nfrom numpy.typing import NDArray\nimport vkpt\n" + script)
    env = dict(os.environ, MYPYPATH=str(PACKAGE))
    code = f"import sys\nfrom mypy import api\nout, err, status = api.run(['--strict', {str(user)!r}])\nprint(out)\n"
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env, cwd=tmp_path)
    if error is None:
        assert "Success" in r.stdout, r.stdout + r.stderr
    else:
        assert error in r.stdout, r.stdout + r.stderr
