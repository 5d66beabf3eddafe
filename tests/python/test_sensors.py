# SPDX-License-Identifier: MIT
# SimRobotSensor: Klamp't's sensor objects on a simulated robot — the defaults q and dq, every
# type of worlds/examples/sensors.xml by index and by name, readings against the simulation,
# settings read and changed live, bad names and values raising.
import math

import pytest

import lamina
from conftest import WORLDS


def one_r():
    world = lamina.WorldModel(str(WORLDS / "klampt" / "control" / "world1.xml"))
    return lamina.Simulator(world)


def tx90():
    world = lamina.WorldModel(str(WORLDS / "examples" / "sensors.xml"))
    return lamina.Simulator(world)


def test_a_robot_without_sensors_has_q_and_dq_that_read_its_state():
    sim = one_r()
    c = sim.controller(0)
    assert c.numSensors() == 2
    q, dq = c.sensor(0), c.sensor("dq")
    assert (q.name(), q.type()) == ("q", "JointPositionSensor")
    assert dq.measurementNames() == ["dq[0]"]
    c.setTorque([2.0])
    sim.simulate(0.5)
    # sampled at the start of the last control period (0.49 s): within a period's motion
    assert q.getMeasurements()[0] == pytest.approx(sim.getActualConfig(0)[0], abs=0.05)
    assert q.getMeasurements()[0] != 0.0


def test_every_type_reads_and_its_settings_change_live():
    sim = tx90()
    c = sim.controller(0)
    types = {c.sensor(i).type() for i in range(c.numSensors())}
    assert len(types) == 15
    accel = c.sensor("accelerometer")
    assert accel.measurementNames() == ["accel_x", "accel_y", "accel_z"]
    assert accel.getLink() == 6
    sim.simulate(0.05)
    # at rest at first, the wrist's z along the world's up: specific force +9.8 along its z
    ax, ay, az = accel.getMeasurements()
    assert math.sqrt(ax * ax + ay * ay + az * az) == pytest.approx(9.8, abs=0.1)
    assert accel.getSetting("hasAxis") == "1 1 1"
    accel.setSetting("hasAxis", "0 0 1")
    sim.simulate(0.02)
    assert accel.getMeasurements()[:2] == [0.0, 0.0]
    lidar = c.sensor("lidar")
    assert len(lidar.getMeasurements()) == 61
    assert "depthMaximum" in lidar.settings()
    # disabled, a sensor keeps its last measurements
    enc = c.sensor("encoders")
    enc.setEnabled(False)
    held = enc.getMeasurements()
    sim.simulate(0.1)
    assert enc.getMeasurements() == held and not enc.getEnabled()


def test_bad_sensor_names_settings_and_values_raise():
    sim = tx90()
    c = sim.controller(0)
    with pytest.raises(KeyError):
        c.sensor("nothing")
    with pytest.raises(IndexError):
        c.sensor(99)
    assert c.sensor(-1).name() == "late_encoders"
    accel = c.sensor("accelerometer")
    with pytest.raises(KeyError):
        accel.getSetting("hasAxes")
    with pytest.raises(ValueError, match="expected 3 booleans"):
        accel.setSetting("hasAxis", "1 1")
    with pytest.raises(ValueError, match="unknown setting"):
        accel.setSetting("colour", "red")
    assert accel.getSetting("hasAxis") == "1 1 1"
