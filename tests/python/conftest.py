# SPDX-License-Identifier: MIT
# Shared paths and worlds of the Python tests (run with /usr/bin/python3 -m pytest tests/python and
# PYTHONPATH=build/python; CTest sets both).
import os
import pathlib
import shutil
import subprocess
import time

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
BIN = pathlib.Path(os.environ.get("LAMINA_BIN_DIR", ROOT / "build" / "bin"))
DATA = ROOT / "tests" / "data" / "worlds"
WORLDS = ROOT / "worlds"


def blocks_world(path, positions):
    """A rigid floor and 1 kg, 10 cm blocks (tests/data/worlds/block.geom) at `positions`,
    friction 0.5, no restitution, 2.5 mm padding; written to `path`."""
    objects = "".join(
        f'<rigidObject name="block{i}" position="{x} {y} {z}">'
        f'<geometry mesh="{DATA}/block.geom"/><physics mass="1" automass="1"/></rigidObject>\n'
        for i, (x, y, z) in enumerate(positions))
    sims = "".join(
        f'<object index="{i}"><geometry kRestitution="0" kFriction="0.5" padding="0.0025"/>'
        f'</object>\n' for i in range(len(positions)))
    path.write_text(
        f'<world>\n<terrain name="floor" file="{DATA}/floor.geom"/>\n{objects}<simulation>\n'
        f'<terrain index="0"><geometry kRestitution="0" kFriction="0.5" padding="0"/></terrain>\n'
        f'{sims}</simulation>\n</world>\n')
    return str(path)


@pytest.fixture
def resting_block(tmp_path):
    """The floor and one block resting on it (on the top of its padding)."""
    import lamina
    return lamina.WorldModel(blocks_world(tmp_path / "block.xml", [(0, 0, 0.0525)]))


needs_x = pytest.mark.skipif(not (shutil.which("Xvfb") and shutil.which("xdotool")),
                             reason="needs Xvfb and xdotool")


@pytest.fixture
def display(monkeypatch):
    """An Xvfb server of this test's own; DISPLAY points at it."""
    read, write = os.pipe()
    # -noreset: the server would otherwise reset when its last client leaves, refusing the
    # next window that opens meanwhile (a test opening two windows in a row)
    server = subprocess.Popen(["Xvfb", "-displayfd", str(write), "-noreset", "-screen", "0",
                               "1024x768x24"],
                              pass_fds=(write,), stderr=subprocess.DEVNULL)
    os.close(write)
    with os.fdopen(read) as numbers:
        number = numbers.readline().strip()
    assert number, "Xvfb did not start"
    monkeypatch.setenv("DISPLAY", ":" + number)
    yield ":" + number
    server.terminate()
    server.wait()


def press_key(window_name, key, until=None, timeout=10.0):
    """Presses `key` in the window named `window_name` through xdotool (real X input), held
    across frames as a hand would (ImGui 1.86 samples keys once per frame, so a press shorter
    than a frame is lost): 0.5 s, or until `until()` is true (at most `timeout` s)."""
    window = subprocess.run(["xdotool", "search", "--sync", "--name", window_name],
                            capture_output=True, text=True, timeout=10).stdout.split()[0]
    subprocess.run(["xdotool", "windowfocus", "--sync", window, "keydown", key], timeout=10)
    held = time.monotonic()
    while time.monotonic() - held < (timeout if until else 0.5):
        if until is not None and until():
            break
        time.sleep(0.02)
    subprocess.run(["xdotool", "keyup", key], timeout=10)
