# SPDX-License-Identifier: MIT
# WorldModel: loading, ids, names, configurations and transforms as Klamp't's.
import math

import numpy as np
import pytest

import lamina
from conftest import DATA, WORLDS


def test_read_file_counts_ids_and_names():
    w = lamina.WorldModel()
    w.readFile(str(WORLDS / "klampt" / "athlete_fractal_1.xml"))
    assert (w.numRobots(), w.numTerrains(), w.numRigidObjects()) == (1, 1, 0)
    robot = w.robot(0)
    # ids: terrains, objects, then the robot and its links
    assert robot.getID() == 1
    assert w.numIDs() == 1 + 1 + robot.numLinks()
    assert w.robot(robot.getName()).getIndex() == 0
    link = robot.link(7)
    assert link.getID() == robot.getID() + 1 + 7
    assert w.getName(link.getID()) == link.getName()
    assert robot.link(link.getName()).getIndex() == 7
    assert w.robotlink(0, 7).getID() == link.getID()


def test_read_file_error_carries_file_and_line(tmp_path):
    bad = tmp_path / "bad.xml"
    bad.write_text('<world>\n  <rigidObject file="missing.obj"/>\n</world>\n')
    with pytest.raises(RuntimeError, match=r"bad\.xml:2"):
        lamina.WorldModel().readFile(str(bad))


def test_config_and_transforms_accept_numpy():
    w = lamina.WorldModel(str(WORLDS / "klampt" / "control" / "world1.xml"))
    robot = w.robot(0)
    q = np.array(robot.getConfig())
    q[0] = 0.25
    robot.setConfig(q)
    assert robot.getConfig()[0] == 0.25
    R, t = robot.link(0).getTransform()
    assert len(R) == 9 and len(t) == 3
    with pytest.raises(ValueError, match="one per link"):
        robot.setConfig([0.0] * (robot.numLinks() + 1))


def test_object_transform_is_klampt_se3():
    w = lamina.WorldModel(str(DATA / "sliding_block.xml"))
    block = w.rigidObject("block")
    R, t = block.getTransform()
    assert R == [1, 0, 0, 0, 1, 0, 0, 0, 1]
    assert t == pytest.approx([0, 0, 0.0525])
    c, s = math.cos(0.3), math.sin(0.3)
    block.setTransform([c, s, 0, -s, c, 0, 0, 0, 1], [1, 2, 3])  # column-major
    R2, t2 = block.getTransform()
    assert R2 == pytest.approx([c, s, 0, -s, c, 0, 0, 0, 1]) and t2 == [1, 2, 3]
