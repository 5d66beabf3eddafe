# SPDX-License-Identifier: MIT
# lamina.render / lamina.vis.OffscreenRenderer: a Python-driven simulation drawn off screen is the
# picture `lamina-headless shot` draws of the same state (same renderer, OSMesa), pixel for pixel.
import subprocess

import numpy
import pytest
from PIL import Image

import lamina
from lamina import vis
from conftest import BIN, blocks_world


def png(path):
    return numpy.asarray(Image.open(path).convert("RGB"))


def test_render_of_a_python_simulation_is_the_shot_of_the_same_state(tmp_path):
    world_file = blocks_world(tmp_path / "drop.xml", [(0, 0, 0.5), (0.05, 0.0, 0.8)])
    sim = lamina.Simulator(lamina.WorldModel(world_file))
    sim.simulate(0.4)  # the first block has landed, the second is falling
    lamina.render(sim, tmp_path / "python.png", size="320x240", camera="world")
    subprocess.run([str(BIN / "lamina-headless"), "shot", world_file, "-o",
                    str(tmp_path / "shot.png"), "--time", "0.4", "--size", "320x240",
                    "--camera", "world"], check=True, capture_output=True)
    ours, theirs = png(tmp_path / "python.png"), png(tmp_path / "shot.png")
    assert ours.shape == (240, 320, 3)
    assert numpy.array_equal(ours, theirs)


def test_pixels_follow_the_simulation_and_match_the_png(tmp_path):
    world = lamina.WorldModel(blocks_world(tmp_path / "drop.xml", [(0, 0, 0.5)]))
    sim = lamina.Simulator(world)
    view = vis.OffscreenRenderer(size="160x120", camera="target=0,0,0.3;yaw=-90;pitch=10;dist=1.5")
    start = view.pixels(sim)
    assert start.shape == (120, 160, 3) and start.dtype == numpy.uint8
    # the world at its initial conditions is the simulation at t = 0
    assert numpy.array_equal(view.pixels(world), start)
    camera = view.camera()
    sim.simulate(0.3)  # the block falls 0.44 m: the picture changes, the camera stays
    moved = view.pixels(sim)
    assert numpy.count_nonzero(numpy.any(moved != start, axis=2)) > 100
    assert view.camera() == camera
    view.save(sim, str(tmp_path / "moved.png"))
    assert numpy.array_equal(png(tmp_path / "moved.png"), moved)


def test_bad_options_raise_with_the_shot_messages(tmp_path):
    with pytest.raises(ValueError, match="size expects WIDTHxHEIGHT"):
        vis.OffscreenRenderer(size="big")
    with pytest.raises(ValueError, match="overlay"):
        vis.OffscreenRenderer(overlay="sparkles")
    with pytest.raises(TypeError, match="Simulator or a WorldModel"):
        vis.OffscreenRenderer(size="16x16").pixels(42)
