# SPDX-License-Identifier: MIT
# Playing God, contact feedback and kinematic bodies through the Python API, checked against
# Newton's laws (tolerances stated per assertion).
import pytest

import lamina
from conftest import DATA, blocks_world


def lifted_block(world):
    """The block of `world` 1 m up and at rest, in a simulation without gravity."""
    block = world.rigidObject(0)
    block.setTransform([1, 0, 0, 0, 1, 0, 0, 0, 1], [0, 0, 1])
    block.setVelocity([0, 0, 0], [0, 0, 0])
    sim = lamina.Simulator(world)
    sim.setGravity([0, 0, 0])
    return block, sim, sim.body(block)


def test_force_through_com_accelerates_by_f_over_m(resting_block):
    block, sim, body = lifted_block(resting_block)
    m, com = block.getMass(), block.getCom()
    force = [2.0, 0.0, 0.0]
    for _ in range(100):  # 1 s; a force applied once lasts for the next simulate call
        _, t = body.getTransform()
        body.applyForceAtPoint(force, [t[k] + com[k] for k in range(3)])
        sim.simulate(0.01)
    w, v = body.getVelocity()
    assert v[0] == pytest.approx(force[0] / m * 1.0, rel=0.01)
    assert abs(v[1]) + abs(v[2]) + sum(map(abs, w)) < 1e-9
    _, t = body.getTransform()
    assert t[0] == pytest.approx(0.5 * force[0] / m, rel=0.01)


def test_wrench_torque_spins_by_tau_over_i(resting_block):
    block, sim, body = lifted_block(resting_block)
    izz = block.getInertia()[8]
    # automass of the box mesh: a thin shell (Klamp't's default), 5/18 m a^2
    assert izz == pytest.approx(5 / 18 * block.getMass() * 0.1**2, rel=1e-6)
    torque = [0.0, 0.0, 0.005]
    for _ in range(100):
        body.applyWrench([0, 0, 0], torque)
        sim.simulate(0.01)
    w, v = body.getVelocity()
    assert w[2] == pytest.approx(torque[2] / izz * 1.0, rel=0.01)
    assert max(map(abs, v)) < 1e-9


def test_contact_feedback_finds_pairs_and_weight(resting_block):
    sim = lamina.Simulator(resting_block)
    block, floor = resting_block.rigidObject(0), resting_block.terrain(0)
    sim.body(block).setVelocity([0, 0, 0], [0, 0, 0])
    sim.enableContactFeedbackAll()
    sim.simulate(0.5)  # settles into the layer
    sim.simulate(0.5)
    n = resting_block.numIDs()
    touching = [(a, b) for a in range(n) for b in range(a + 1, n) if sim.inContact(a, b)]
    assert touching == [(floor.getID(), block.getID())]
    assert sim.hadContact(block) and not sim.hadSeparation(block, floor)
    weight = block.getMass() * -sim.getGravity()[2]
    f = sim.contactForce(block.getID(), floor.getID())  # on the block, from the floor
    assert f[2] == pytest.approx(weight, rel=0.01)
    assert abs(f[0]) + abs(f[1]) < 1e-3 * weight
    assert sim.contactForce(floor, block)[2] == pytest.approx(-f[2], rel=1e-12)
    assert sim.meanContactForce(block, floor)[2] == pytest.approx(weight, rel=0.01)
    forces = sim.getContactForces(block, floor)
    assert sum(fc[2] for fc in forces) == pytest.approx(f[2], rel=1e-9)


def test_get_contacts_rows_carry_the_blended_friction(resting_block):
    sim = lamina.Simulator(resting_block)
    block, floor = resting_block.rigidObject(0), resting_block.terrain(0)
    body = sim.body(block)
    body.setVelocity([0, 0, 0], [0, 0, 0])
    surface = body.getSurface()
    surface.kFriction = 0.1
    body.setSurface(surface)
    assert sim.body(block).getSurface().kFriction == 0.1
    sim.enableContactFeedback(block, floor)
    sim.simulate(0.5)
    rows = sim.getContacts(block, floor)
    assert len(rows) >= 3
    for row in rows:
        assert len(row) == 7
        assert row[5] == pytest.approx(1.0, abs=1e-9)  # the normal points into the block
        assert row[6] == pytest.approx(2 * 0.5 * 0.1 / (0.5 + 0.1), rel=1e-12)  # harmonic mean
    assert all(r[5] == pytest.approx(-1.0, abs=1e-9) for r in sim.getContacts(floor, block))


def test_surface_parameters_are_the_tables_rows():
    surface = lamina.SurfaceParameters()
    for name in ("kRestitution", "kFriction", "kStiffness", "kDamping"):
        assert getattr(lamina.SurfaceParameters, name).__doc__  # the table's help
    surface.kRestitution = 0.5
    assert surface.kRestitution == 0.5
    with pytest.raises(ValueError, match="kRestitution: "):
        surface.kRestitution = 1.5  # the table's range is [0, 1]
    with pytest.raises(ValueError, match="kStiffness: "):
        surface.kStiffness = 0.0  # stiffness must be > 0
    assert surface.kRestitution == 0.5  # a refused value changes nothing
    surface.kStiffness = float("inf")
    assert surface.kStiffness == float("inf")


def test_rolling_and_spinning_friction_are_surface_parameters(resting_block):
    surface = lamina.SurfaceParameters()
    assert (surface.kRollingFriction, surface.kSpinningFriction) == (0.0, 0.0)  # off by default
    surface.kRollingFriction = 0.005  # m
    surface.kSpinningFriction = 0.002
    with pytest.raises(ValueError, match="kRollingFriction: "):
        surface.kRollingFriction = float("inf")  # finite only
    with pytest.raises(ValueError, match="kSpinningFriction: "):
        surface.kSpinningFriction = -0.001
    sim = lamina.Simulator(resting_block)
    body = sim.body(resting_block.rigidObject(0))
    body.setSurface(surface)
    assert body.getSurface().kRollingFriction == 0.005
    assert body.getSurface().kSpinningFriction == 0.002


def test_kinematic_body_moves_at_its_velocity_and_pushes(tmp_path):
    world = lamina.WorldModel(
        blocks_world(tmp_path / "two.xml", [(0, 0, 0.0525), (0.3, 0, 0.0525)]))
    sim = lamina.Simulator(world)
    pusher, pushed = sim.body(world.rigidObject(0)), sim.body(world.rigidObject(1))
    pusher.enableDynamics(False)
    assert not pusher.isDynamicsEnabled()
    pusher.setVelocity([0, 0, 0], [0.5, 0, 0])
    for _ in range(100):
        sim.simulate(0.01)
    _, t = pusher.getTransform()
    assert t[0] == pytest.approx(0.5, abs=1e-6)
    assert t[2] == pytest.approx(0.0525, abs=1e-9)
    assert pusher.getVelocity()[1] == pytest.approx([0.5, 0, 0], abs=1e-9)
    _, tb = pushed.getTransform()
    # pushed from t = 0.4 s on: ahead of the pusher by a block and the two paddings, at most
    assert tb[0] > 0.55
    assert tb[0] - t[0] == pytest.approx(0.105, abs=0.01)


def test_get_state_set_state_replays_exactly():
    world = lamina.WorldModel(str(DATA / "sliding_block.xml"))
    sim = lamina.Simulator(world)
    sim.simulate(0.05)
    state = sim.getState()
    sim.simulate(0.1)
    first = sim.body(world.rigidObject(0)).getTransform()
    sim.setState(state)
    assert sim.getTime() == pytest.approx(0.05)
    sim.simulate(0.1)
    assert sim.body(world.rigidObject(0)).getTransform() == first  # bit for bit
    sim.reset()
    assert sim.getTime() == 0.0
    assert sim.body(world.rigidObject(0)).getTransform() == world.rigidObject(0).getTransform()


def test_settings_by_name_as_klampt_text(resting_block):
    sim = lamina.Simulator(resting_block)
    sim.setSetting("gravity", "0 0 -1.62")
    assert sim.getGravity() == [0, 0, -1.62]
    sim.setSetting("timestep", "0.002")
    assert sim.getSimStep() == 0.002 and float(sim.getSetting("timestep")) == 0.002
    sim.setSetting("gravity", "0,0,-9.8")  # the access paths' text works too
    assert sim.getSetting("gravity").replace(" ", "") == "0,0,-9.8"
    with pytest.raises(ValueError, match="timestep"):
        sim.setSetting("timestep", "-1")
