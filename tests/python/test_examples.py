# SPDX-License-Identifier: MIT
# docs/examples/python: the seed's snippets as scripts, each run as a user runs it, with the
# physics each promises checked on what it prints; one of them also through its --window in an
# Xvfb of the test's own, started with the real s key.
import os
import re
import subprocess
import sys
import threading

import pytest

from conftest import ROOT, needs_x, press_key

EXAMPLES = ROOT / "docs" / "examples" / "python"


def run(script, *args, env=None):
    result = subprocess.run([sys.executable, str(EXAMPLES / script), *args], env=env,
                            capture_output=True, text=True, timeout=240)
    assert result.returncode == 0, result.stderr
    return result.stdout


def numbers(pattern, text):
    match = re.search(pattern, text)
    assert match, f"{pattern!r} not in:\n{text}"
    return [float(x) for x in match.groups()]


def test_leg_lift_raises_the_foot_and_the_base_stays():
    out = run("leg_lift.py")
    assert "status normal" in out
    rise, back = numbers(r"foot rise: ([\d.]+) m, back to ([-+\d.]+) m", out)
    assert rise > 0.2 and abs(back) < 0.03
    assert numbers(r"base moved at most ([\d.]+) m", out)[0] < 0.005


def test_streamed_path_is_tracked_within_the_bars_of_the_cpp_test():
    # the bars of tests/physics/robot_worlds_test.cpp (there streamed from t = 0)
    out = run("stream_path.py")
    assert "status normal" in out
    mean, worst = numbers(r"while moving: mean ([\d.]+) rad, worst ([\d.]+) rad", out)
    assert mean < 0.15 and worst < 0.75
    end_mean, end_worst = numbers(r"at the end: mean ([\d.]+) rad, worst ([\d.]+) rad", out)
    assert end_mean < 0.05 and end_worst < 0.25


def test_playing_god_accelerates_by_the_net_force_over_the_mass():
    out = run("playing_god.py")
    mu, speed, expected = numbers(r"friction ([\d.]+); speed after the push: ([\d.]+) m/s "
                                  r"\(expected .* = ([\d.]+)\)", out)
    assert mu == pytest.approx(0.5, abs=1e-9)
    assert speed == pytest.approx(expected, rel=0.01)
    assert numbers(r"spin at the end: ([-\d.]+) rad/s", out)[0] > 1.0


def test_kinematic_block_moves_at_its_velocity_and_pushes_the_other():
    out = run("kinematic_push.py")
    assert numbers(r"pusher x: ([\d.]+) m", out)[0] == pytest.approx(0.6, abs=1e-4)
    # shoved ahead: touching, one block width and the two paddings in front
    assert numbers(r"pushed x: ([\d.]+) m", out)[0] == pytest.approx(0.6 + 0.1 + 0.004, abs=2e-3)


def test_contact_feedback_loop_finds_each_box_carrying_the_boxes_above():
    out = run("contact_feedback.py")
    lines = [line for line in out.splitlines() if " N up on " in line]
    assert len(lines) == 10  # the ground and nine box-on-box pairs
    for k, line in enumerate(lines):  # pair k carries boxes k+1..10, 1 kg each
        assert numbers(r": +([\d.]+) N up", line)[0] == pytest.approx(9.8 * (10 - k), rel=0.01)


@pytest.mark.parametrize("extra", [[], ["--args"]])
def test_batch_example_runs_on_every_core(extra):
    out = run("batch_monte_carlo.py", *extra)
    assert "100 runs, statuses ['normal']" in out
    low, high = numbers(r"min ([\d.]+), max ([\d.]+) rad", out)
    assert 0.03 < low <= high < 0.16  # the sag the integral term is still removing (batch.md)


@needs_x
def test_an_example_in_the_window_starts_with_s_and_closes_at_its_end(display, tmp_path):
    shot = tmp_path / "last.png"
    presser = threading.Thread(target=press_key, args=("Lamina", "s"))
    presser.start()
    out = run("kinematic_push.py", "--window", "--duration", "0.5", "--png", str(shot),
              env=dict(os.environ))
    presser.join()
    assert "t = 0.50 s" in out and shot.is_file()
