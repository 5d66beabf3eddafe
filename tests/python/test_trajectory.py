# SPDX-License-Identifier: MIT
# lamina.model.trajectory: Klamp't's Trajectory and RobotTrajectory (linear milestones, .path
# files through the core). The seed's streaming example (ATHLETE following athlete_flex.path
# through setPIDCommand from t = 2 s) is docs/examples/python/stream_path.py, run by
# test_examples.py.
import pytest

import lamina
from lamina.model.trajectory import RobotTrajectory, Trajectory
from conftest import WORLDS

FLEX = WORLDS / "klampt" / "motions" / "athlete_flex.path"


def test_eval_and_deriv_are_linear_between_milestones():
    traj = Trajectory([1.0, 2.0, 4.0], [[0.0, 1.0], [1.0, 1.0], [3.0, -1.0]])
    assert traj.startTime() == 1.0 and traj.endTime() == 4.0 and traj.duration() == 3.0
    assert traj.eval(1.5) == pytest.approx([0.5, 1.0], abs=1e-15)
    assert traj.eval(3.0) == pytest.approx([2.0, 0.0], abs=1e-15)
    assert traj.deriv(1.5) == pytest.approx([1.0, 0.0], abs=1e-15)
    assert traj.deriv(3.0) == pytest.approx([1.0, -1.0], abs=1e-15)
    assert traj.getSegment(2.5) == (1, pytest.approx(0.25, abs=1e-15))
    # halt: held at the ends with zero velocity
    assert traj.eval(0.0) == [0.0, 1.0] and traj.eval(9.0) == [3.0, -1.0]
    assert traj.deriv(0.0) == [0.0, 0.0] and traj.deriv(9.0) == [0.0, 0.0]
    # loop: 5.5 s is 1 + (4.5 mod 3) = 2.5 s
    assert traj.eval(5.5, "loop") == pytest.approx(traj.eval(2.5), abs=1e-15)
    with pytest.raises(ValueError, match="endBehavior"):
        traj.eval(1.0, "bounce")
    with pytest.raises(ValueError, match="2 times for 1 milestones"):
        Trajectory([0.0, 1.0], [[0.0]])


def test_milestones_edited_in_place_take_effect():
    traj = Trajectory([0.0, 1.0], [[0.0], [1.0]])
    traj.times.append(3.0)
    traj.milestones.append([5.0])
    assert traj.eval(2.0) == pytest.approx([3.0], abs=1e-15)


def test_path_files_round_trip_and_bad_lines_name_file_and_line(tmp_path):
    traj = Trajectory()
    traj.load(FLEX)
    assert len(traj.milestones[0]) == 42 and traj.times[0] == 0.0
    copy = tmp_path / "copy.path"
    traj.save(copy)
    again = Trajectory()
    again.load(str(copy))
    assert again.times == traj.times and again.milestones == traj.milestones
    bad = tmp_path / "bad.path"
    bad.write_text("0 2 0 0\n1 2 0 x\n")
    with pytest.raises(RuntimeError, match=r"bad\.path:2"):
        Trajectory().load(bad)
    with pytest.raises(RuntimeError, match="cannot open"):
        Trajectory().load(tmp_path / "missing.path")


def test_robot_trajectory_interpolates_by_the_robots_joints():
    world = lamina.WorldModel(str(WORLDS / "klampt" / "athlete_fractal_1.xml"))
    robot = world.robot(0)
    a, b = robot.getConfig(), robot.getConfig()
    b[7] += 0.4
    traj = RobotTrajectory(robot, [0.0, 2.0], [a, b])
    assert traj.eval(0.5)[7] == pytest.approx(a[7] + 0.1, abs=1e-12)
    assert traj.deriv(0.5)[7] == pytest.approx(0.2, abs=1e-12)
    assert robot.interpolateDeriv(a, b)[7] == pytest.approx(0.4, abs=1e-12)
    with pytest.raises(ValueError, match="42 numbers"):
        robot.interpolate(a, [0.0], 0.5)
