# SPDX-License-Identifier: MIT
# SimRobotController: Klamp't's commands on the 1R robot of worlds/klampt/control/world1.xml and
# ATHLETE's leg lift on fractal terrain; a step's status in Klamp't's numbers.
import pytest

import lamina
from lamina.model.access import get_item, set_item
from conftest import WORLDS


def one_r():
    world = lamina.WorldModel(str(WORLDS / "klampt" / "control" / "world1.xml"))
    return world, lamina.Simulator(world)


def test_milestone_reaches_its_target():
    world, sim = one_r()
    c = sim.controller(0)
    assert sim.controller(world.robot(0)).getPIDGains() == c.getPIDGains()
    c.setPIDGains([20], [8], [5])
    assert c.getPIDGains() == ([20.0], [8.0], [5.0])
    c.setMilestone([0.5])
    assert c.remainingTime() > 0
    # the link hangs in gravity: PD leaves a sag of 4.9 N·m / kP = 0.245 rad that the integral
    # removes with a time constant of kP / kI = 2.5 s (docs/batch.md); 10 s: 0.0045 rad left
    sim.simulate(c.remainingTime() + 10.0)
    assert c.remainingTime() <= 1e-9
    assert c.getCommandedConfig() == pytest.approx([0.5], abs=1e-9)
    assert sim.getActualConfig(0)[0] == pytest.approx(0.5, abs=0.01)
    assert c.getSensedConfig()[0] == pytest.approx(sim.getActualConfig(0)[0], abs=0.01)


def test_bad_commands_raise_with_the_controllers_message():
    _, sim = one_r()
    c = sim.controller(0)
    with pytest.raises(ValueError):
        c.setMilestone([0.1, 0.2, 0.3])
    c.setTorque([0.0])
    with pytest.raises(RuntimeError, match="PID"):
        c.getCommandedConfig()
    c.setPIDCommand([0.2], [0.0])
    assert c.getCommandedConfig() == [0.2]


def test_athlete_leg_lift_on_fractal_terrain():
    world = lamina.WorldModel(str(WORLDS / "klampt" / "athlete_fractal_1.xml"))
    set_item(world, "settings.solver", 1)  # quick step: the exact solver is slow for a test
    sim = lamina.Simulator(world)
    assert get_item(sim, "settings.solver") == 1
    c = sim.controller(0)
    foot = sim.body(world.robotlink(0, 11))  # "ankle roll 1", the foot of leg 1
    sim.simulate(2.0)
    base0 = sim.getActualConfig(0)[:3]
    foot0 = foot.getTransform()[1][2]
    q = c.getCommandedConfig()
    q[7] -= 1.0  # hip pitch 1: lift the leg
    c.setMilestone(q)
    q[7] += 1.5
    c.addMilestone(q)
    samples, t_end = [], sim.getTime() + c.remainingTime() + 1.0
    while sim.getTime() < t_end:
        sim.simulate(0.05)
        samples.append((foot.getTransform()[1][2], sim.getActualConfig(0)[:3]))
        assert sim.getStatus() < 3, sim.getStatusString()  # neither unstable nor stopped
    heights = [z for z, _ in samples]
    peak = heights.index(max(heights))
    assert heights[peak] > foot0 + 0.2  # the foot rose (by 0.21 m)
    # and came down to where it started: the first sample after the peak back within 3 cm
    back = next(i for i in range(peak, len(samples)) if heights[i] < foot0 + 0.03)
    assert heights[back] == pytest.approx(foot0, abs=0.03)
    # the base stayed while the leg was up (the last 0.5 rad then presses the foot into the
    # ground and pushes the base back)
    for _, base in samples[:back + 1]:
        assert max(abs(base[k] - base0[k]) for k in range(3)) < 0.005


def test_a_joint_the_solver_does_not_hold_is_klampts_unreliable_status():
    # the taut bridge under QuickStep at 10 ms opens its hinges by up to 0.44 m (docs/stress.md):
    # Lamina's "joint open", which Klamp't's numbers give as 2 (STATUS_CONTACT_UNRELIABLE)
    world = lamina.WorldModel(str(WORLDS / "accuracy" / "bridge_160.xml"))
    sim = lamina.Simulator(world)
    sim.setSetting("solver", "quick")
    sim.setSimStep(0.01)
    codes, names = set(), set()
    for _ in range(200):
        sim.simulate(0.01)
        codes.add(sim.getStatus())
        names.add(sim.getStatusString())
    assert "joint open" in names
    assert max(codes) == 2
    assert sim.getStatusString(2) == "contact unreliable"
    assert sim.getStatusString(3) == "unstable"
    assert sim.getStatusString(4) == "error"
