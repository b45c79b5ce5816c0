"""Scene.begin: a render taken in steps whose result equals Scene.render's at the same
spp, bit for bit; its end when the scene moves on; Ctrl-C and progress's False ending a
step, not the render."""
import _thread
import threading

import numpy as np
import pytest

import vkpt
from conftest import CORNELL, SMALL


@pytest.mark.parametrize("backend", ["cpu", "vulkan"])
def test_steps_equal_a_render_at_the_same_spp(backend):
    scene = vkpt.Scene(CORNELL, backend=backend)
    options = dict(SMALL, spp=12, aovs=["depth"])
    whole = scene.render(**dict(options, spp=7))
    full = scene.render(**options)
    steps = scene.begin(**options)
    assert isinstance(steps, vkpt.ProgressiveRender) and steps.max_spp == 12 and steps.spp == 0
    assert steps.advance() == 1 and steps.advance(6) == 7
    r = steps.result()
    assert r.spp == 7 and r.stopped_by == ""
    assert np.array_equal(r.image, whole.image) and np.array_equal(r.aovs["depth"], whole.aovs["depth"])
    assert steps.advance(1000) == 12
    last = steps.result()
    assert last.stopped_by == "spp" and np.array_equal(last.image, full.image)
    assert steps.camera.index == 0


def test_a_progressive_render_ends_when_its_scene_moves_on():
    scene = vkpt.Scene(CORNELL, backend="cpu")
    steps = scene.begin(**SMALL)
    steps.advance()
    scene.render(**SMALL)
    with pytest.raises(vkpt.Error, match="this progressive render has ended"):
        steps.advance()
    steps = scene.begin(**SMALL)
    scene.update({"materials/0/roughness": 0.5})
    with pytest.raises(vkpt.Error, match="has ended"):
        steps.result()
    steps = scene.begin(**SMALL)
    scene.close()
    with pytest.raises(vkpt.Error, match="has ended"):
        steps.spp


def test_the_progressive_render_keeps_its_scene_alive():
    steps = vkpt.Scene(CORNELL, backend="cpu").begin(**SMALL)
    assert steps.advance(4) == 4 and steps.result().spp == 4


def test_renders_budgets_are_refused():
    scene = vkpt.Scene(CORNELL, backend="cpu")
    for budget in (dict(seconds=1.0), dict(noise_target=0.01), dict(adaptive=True)):
        with pytest.raises(vkpt.SettingError, match="are Render's"):
            scene.begin(**SMALL, **budget)


def test_progress_false_ends_one_step_and_the_next_goes_on():
    scene = vkpt.Scene(CORNELL, backend="cpu")
    fractions = []
    answer = [None]

    def progress(f):
        fractions.append(f)
        return answer[0]

    steps = scene.begin(**dict(SMALL, spp=64), progress=progress)
    assert steps.advance(8) == 8 and fractions[-1] == pytest.approx(8 / 64)
    answer[0] = False
    taken = steps.advance(32)
    assert 8 < taken < 40 and steps.result().stopped_by == "cancelled"
    answer[0] = None
    assert steps.advance(4) == taken + 4


def test_ctrl_c_ends_a_step_and_is_raised():
    scene = vkpt.Scene(CORNELL, backend="cpu")
    steps = scene.begin(width=64, height=64, spp=65536)
    steps.advance()
    timer = threading.Timer(0.3, _thread.interrupt_main)
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            while True:
                steps.advance(64)
    finally:
        timer.cancel()
    assert 1 <= steps.spp < 65536
