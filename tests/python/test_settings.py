"""The settings schema (host/vkpt/settings_schema.h) walked for Python: every value out of a
setting's range raises vkpt.SettingError, a ValueError and a vkpt.Error, naming the keyword
and the range the command line names (tests/test_settings.cpp tries the command line and
C++); the keywords' defaults are the library's; settings at odds are refused."""
import math
import re

import pytest

import vkpt
from conftest import CORNELL, SOURCE
from vkpt import _vkpt

SETTINGS = _vkpt._settings()
RANGED = [s for s in SETTINGS if "range" in s]
VIEW = dict(width=8, height=8, spp=1)


def outside(setting):
    """The values just outside the setting's range and the non-finite ones that Python can
    pass as its type (a count takes no NaN and no negative number)."""
    lo, hi, lo_open, _ = setting["range"]
    step = lambda x: max(1.0, abs(x) * 1e-3)  # a step a float still tells apart
    values = [lo if lo_open else lo - step(lo), math.nan, math.inf, -math.inf]
    values += [] if math.isinf(hi) else [hi + step(hi)]
    for v in values:
        if setting["type"] == "count":
            if math.isfinite(v) and v >= 0 and v == int(v) and v < 2**64:
                yield int(v)
        elif setting["type"] == "triple":
            yield (v, v, v)
        else:
            yield v


def attempt(setting, value):
    """Loads (and for a view's setting renders) with the setting at `value`."""
    if setting["where"] == "scene":
        vkpt.Scene(CORNELL, backend="cpu", **{setting["key"]: value})
        return
    scene = vkpt.Scene(CORNELL, backend="cpu")
    if setting["where"] == "camera":
        scene.render(vkpt.Camera(**{setting["key"]: value}), **VIEW)
    else:
        scene.render(**{**VIEW, setting["key"]: value})


@pytest.mark.parametrize("setting", RANGED, ids=[s["key"] for s in RANGED])
def test_every_value_out_of_range_is_refused_naming_the_keyword_and_range(setting):
    values = list(outside(setting))
    for value in values:
        pattern = "^" + re.escape(setting["python"]) + " must be .*" + re.escape(setting["range"][3])
        with pytest.raises(vkpt.SettingError, match=pattern):
            attempt(setting, value)


def test_setting_errors_are_value_errors_and_vkpt_errors():
    assert issubclass(vkpt.SettingError, ValueError) and issubclass(vkpt.SettingError, vkpt.Error)
    with pytest.raises(ValueError, match=r"^spp must be in \[1, 1073741824\], got 0$"):
        attempt({"where": "render", "key": "spp"}, 0)


def test_the_keywords_defaults_are_the_librarys():
    docs = {"scene": vkpt.Scene.__init__.__doc__, "render": vkpt.Scene.render.__doc__,
            "camera": vkpt.Camera.__init__.__doc__}
    compared = 0
    for s in SETTINGS:
        if not s["default"] or s["type"] == "triple":
            continue
        shown = re.search(r"\b" + s["key"] + r": [^=,]+ = ([^,)]+)", docs[s["where"]])
        assert shown, f"{s['key']} has no default in the signature"
        assert float(shown.group(1).replace("True", "1").replace("False", "0")) == s["default"][0], s["key"]
        compared += 1
    assert compared >= 8


def docstrings():
    return {"scene": vkpt.Scene.__doc__, "render": vkpt.Scene.render.__doc__, "camera": vkpt.Camera.__doc__}


def test_every_keyword_is_documented_by_its_settings_doc():
    docs = docstrings()
    for s in SETTINGS:
        line = f"\n{s['key']}: {s['doc'].replace('`', '')}"
        assert line in docs[s["where"]], f"{s['key']}: no line {line!r} in the docstring"
        assert "--" not in s["doc"] or "--" in line, s["key"]  # no flag left untranslated
    assert all("--" not in d for d in docs.values()), "a command-line option in a docstring"


def keyword_defaults(text, start):
    """keyword → default (as written) of the signature that starts at text[start:] ("name(")."""
    args, depth, current = [], 0, ""
    for c in text[text.index("(", start) + 1:]:
        if c in "([" or (c == ")" and depth) or c == "]":
            depth += 1 if c in "([" else -1
        elif c == ")":
            break
        if c == "," and depth == 0:
            args.append(current)
            current = ""
        else:
            current += c
    defaults = {}
    for arg in args + [current]:
        name, _, default = arg.partition("=")
        if default:
            defaults[name.split(":")[0].strip()] = default.strip().replace("'", '"')
    return defaults


def test_the_python_docs_signatures_are_the_bindings():
    """docs/python.md writes the signatures of Scene() and render() out; their defaults must
    be the binding's, which are the library's (a second default written there fails)."""
    doc = (SOURCE / "docs" / "python.md").read_text()
    for written, bound in [("vkpt.Scene(path, *", vkpt.Scene.__init__.__doc__),
                           ("scene.render(camera=", vkpt.Scene.render.__doc__)]:
        assert written in doc, written
        have, want = keyword_defaults(doc, doc.index(written)), keyword_defaults(bound, 0)
        assert have == want, written


def test_settings_at_odds_are_refused():
    with pytest.raises(vkpt.SettingError, match="^time needs animation: it is a time in that animation$"):
        vkpt.Scene(CORNELL, backend="cpu").render(time=1.0, **VIEW)
    with pytest.raises(vkpt.SettingError, match="^environment_rotation and environment_intensity need environment"):
        vkpt.Scene(CORNELL, backend="cpu", environment_intensity=2.0)
