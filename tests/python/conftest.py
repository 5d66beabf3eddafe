# SPDX-License-Identifier: MIT
# Shared paths and worlds of the Python tests (run with /usr/bin/python3 -m pytest tests/python and
# PYTHONPATH=build/python; CTest sets both).
import os
import pathlib

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
