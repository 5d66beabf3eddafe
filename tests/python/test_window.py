# SPDX-License-Identifier: MIT
# lamina.vis.run: Lamina's window on a simulation Python drives, in an Xvfb server of the test's
# own, with the real `s` key pressed through xdotool. Skipped when Xvfb or xdotool is missing
# (cmake/setup-deps.sh installs both).
import threading
import time

import numpy
import pytest
from PIL import Image

import lamina
from lamina import vis
from conftest import blocks_world, needs_x, press_key

CAMERA = "target=0,0,0.3;yaw=-90;pitch=10;dist=1.5"


def two_blocks(tmp_path):
    world = lamina.WorldModel(blocks_world(tmp_path / "drop.xml", [(0, 0, 0.5), (0.05, 0, 0.8)]))
    return lamina.Simulator(world)


@needs_x
def test_idle_drives_the_simulation_and_the_window_shows_it(tmp_path, display):
    sim = two_blocks(tmp_path)
    times = []

    def idle():
        times.append(sim.getTime())
        sim.simulate(0.01)

    shot = tmp_path / "window.png"
    vis.run(sim, idle, size="640x480", camera=CAMERA, running=True, frames=30, screenshot=shot)
    assert len(times) == 30 and sim.getTime() == pytest.approx(0.3, abs=1e-9)
    # the window's 3D view is the off-screen picture of the same state (the status line covers
    # the bottom 40 rows; the window's software-GL shadow map is coarser: a few edge pixels)
    window = numpy.asarray(Image.open(shot).convert("RGB")).astype(int)
    offscreen = vis.OffscreenRenderer("640x480", CAMERA, samples=1).pixels(sim).astype(int)
    differing = numpy.abs(window - offscreen).max(axis=2)[:440] > 8
    assert differing.mean() < 0.005


@needs_x
def test_the_s_key_starts_it_and_idle_returning_false_closes_it(tmp_path, display):
    sim = two_blocks(tmp_path)
    calls = []

    def idle():
        calls.append(sim.getTime())
        sim.simulate(0.01)
        return len(calls) < 5

    paused_calls = []

    def press_s():
        time.sleep(1.0)  # the window is up and paused: no idle calls yet
        paused_calls.append(len(calls))
        press_key("Lamina", "s", until=lambda: calls)

    presser = threading.Thread(target=press_s)
    presser.start()
    vis.run(sim, idle, size="320x240", frames=100000)  # returns when idle says False
    presser.join()
    assert paused_calls == [0]
    assert len(calls) == 5 and sim.getTime() == pytest.approx(0.05, abs=1e-9)


@needs_x
def test_real_time_without_idle_and_errors_from_idle_propagate(tmp_path, display):
    sim = two_blocks(tmp_path)
    start = time.monotonic()
    vis.run(sim, size="320x240", running=True, frames=20)
    # the simulation advanced by the frames' wall-clock time (each frame's share at most 0.1 s)
    assert 0.0 < sim.getTime() <= min(2.0, time.monotonic() - start + 1e-6)

    def broken():
        raise ZeroDivisionError("from idle")

    with pytest.raises(ZeroDivisionError, match="from idle"):
        vis.run(sim, broken, size="320x240", running=True, frames=5)


def test_bad_arguments_raise_before_any_window_opens():
    with pytest.raises(ValueError, match="size expects WIDTHxHEIGHT"):
        vis.run(lamina.Simulator(lamina.WorldModel()), size="wide")
    with pytest.raises(TypeError, match="Simulator"):
        vis.run(42)
    with pytest.raises(ValueError, match="frames must be >= 0"):
        vis.run(lamina.Simulator(lamina.WorldModel()), frames=-1)
