# SPDX-License-Identifier: MIT
# lamina.model.access and lamina.sim.batch: paths named in errors, and the seed batch
# (worlds/batch/spin_to_zero.json) set up through the Python API reproducing the C++ batch.
import math

import pytest

import lamina
from lamina.model.access import get_item, set_item
from lamina.sim import batch
from conftest import DATA, WORLDS

ITEMS = ["robots[0].actualConfig[0]", "robots[0].actualVelocity[0]",
         "controllers[0].commandedConfig[0]", "robots[0].actualTorques[0]"]


def test_get_and_set_items_on_world_and_simulator():
    world = lamina.WorldModel(str(DATA / "sliding_block.xml"))
    assert get_item(world, "objects[block].kFriction") == 0.5
    set_item(world, "objects[block].kFriction", 0.1)
    assert get_item(world, "objects[0].kFriction") == pytest.approx(0.1)
    assert get_item(world, "settings.gravity") == pytest.approx([0, 0, -9.8])
    sim = lamina.Simulator(world)
    sim.simulate(2.0)
    # the block slides v^2 / (2 mu g) with the pair's friction 1/6 (tests/data/worlds)
    R, t = get_item(sim, "objects[block].transform")
    assert t[0] == pytest.approx(1.0 / (2 * (1 / 6) * 9.8), rel=0.03)
    assert get_item(sim, "time") == pytest.approx(2.0)
    with pytest.raises(ValueError, match=r"objects\[blok\]"):
        get_item(world, "objects[blok].kFriction")
    with pytest.raises(ValueError, match="kFriction"):
        set_item(sim, "objects[block].kFriction", -1)


def spin_world():
    world = lamina.WorldModel(str(WORLDS / "klampt" / "control" / "world1.xml"))
    for gain, value in (("kP", 20), ("kI", 8), ("kD", 5)):
        set_item(world, f"robots[0].drivers[0].{gain}", value)
    return world


def test_seed_batch_matches_the_cpp_batch():
    world = spin_world()
    runs = batch.monteCarloSim(world, 5.0, {"robots[0].config[0]": batch.uniform(-math.pi, math.pi)},
                               100, ITEMS, simDt=0.01, setup=[{"robot": 0, "milestones": [[0]]}],
                               seed=1)
    spec = batch.runSpec(str(WORLDS / "batch" / "spin_to_zero.json"))
    assert len(runs) == len(spec) == 100
    for (condition, result), expected in zip(runs, spec):
        assert condition["robots[0].config[0]"] == expected["sampled"][0][0]
        assert result["status"] == expected["status"]
        assert [result[item] for item in ITEMS] == [v[0] for v in expected["items"]]  # exactly
    # docs/batch.md: every commanded angle is 0 at 5 s; the hanging link still sags toward +q
    # by 0.245 rad e^(-t/2.5) after it arrived: (0.03, 0.16) rad in every run
    for _, r in runs:
        assert r["controllers[0].commandedConfig[0]"] == 0.0
        assert 0.03 < r["robots[0].actualConfig[0]"] < 0.16


def test_batch_with_sampled_args_matches_the_cpp_batch_threaded_and_serial():
    # worlds/batch/spin_to_target.json: the start and the target both sampled (seed 2), the
    # target a named argument used by the set-up's milestone
    world = spin_world()
    items = ITEMS[:3]
    samplers = {"robots[0].config[0]": batch.uniform(-math.pi, math.pi),
                "args": {"target": batch.uniform(-0.5, 0.5)}}
    setup = [{"robot": 0, "milestones": ["args.target"]}]
    threaded = batch.monteCarloSim(world, 5.0, samplers, 100, items, setup=setup, seed=2)
    targets = []
    serial = batch.monteCarloSim(world, 5.0, samplers, 100, items, setup=setup, seed=2,
                                 simInit=lambda sim, target: targets.append(target))
    spec = batch.runSpec(str(WORLDS / "batch" / "spin_to_target.json"))
    assert len(threaded) == len(serial) == len(spec) == 100
    for (condition, result), (condition2, result2), expected in zip(threaded, serial, spec):
        start, target = expected["sampled"][0][0], expected["sampled"][1][0]
        assert condition == condition2 == {"robots[0].config[0]": start, "args": {"target": target}}
        assert [result[i] for i in items] == [v[0] for v in expected["items"]]  # exactly
        assert [result2[i] for i in items] == [result[i] for i in items]
        # docs/batch.md: a negative target is clamped to qMin = 0 plus the ramp planner's margin of
        # 1e-7 of the joint range (2 pi): 6.3e-7 rad
        assert result["controllers[0].commandedConfig[0]"] == pytest.approx(max(target, 6.28319e-7),
                                                                           abs=1e-12)
    assert targets == [c["args"]["target"] for c, _ in threaded]  # callbacks get the args


def test_klampt_args_reach_the_callbacks_and_unknown_args_are_refused():
    world = spin_world()
    seen = []

    def init(sim, target, label):
        seen.append(label)
        sim.controller(0).setMilestone([target])

    runs = batch.monteCarloSim(world, 5.0, {"args": lambda: (0.3, "klampt")}, 2,
                               ["controllers[0].commandedConfig[0]"], simInit=init)
    assert seen == ["klampt", "klampt"]
    assert [c["args"] for c, _ in runs] == [(0.3, "klampt")] * 2
    assert runs[0][1]["controllers[0].commandedConfig[0]"] == pytest.approx(0.3, abs=1e-12)
    named = batch.doSim(world, 5.0, {"args": {"target": 0.2}},
                        ["controllers[0].commandedConfig[0]"],
                        setup=[{"robot": 0, "milestones": ["args.target"]}])
    assert named["controllers[0].commandedConfig[0]"] == pytest.approx(0.2, abs=1e-12)
    with pytest.raises(ValueError, match="args.goal: no such argument"):
        batch.doSim(world, 1.0, {"args": {"target": 0.2}}, None,
                    setup=[{"robot": 0, "pid": "args.goal"}])
    with pytest.raises(ValueError, match="args.goal: no such argument"):
        batch.monteCarloSim(world, 1.0, {"args": {"target": batch.uniform(0, 1)}}, 2,
                            setup=[{"robot": 0, "milestones": ["args.goal"]}])


def test_python_callbacks_run_serially_with_the_same_physics():
    world = spin_world()
    seen = []
    items = ITEMS[:1]
    plain = batch.doSim(world, 1.0, {"robots[0].config[0]": 1.0}, items,
                        setup=[{"robot": 0, "milestones": [[0]]}])
    hooked = batch.doSim(world, 1.0, {"robots[0].config[0]": 1.0}, items,
                         setup=[{"robot": 0, "milestones": [[0]]}],
                         simStep=lambda sim: seen.append(sim.getTime()))
    assert hooked[items[0]] == plain[items[0]]
    assert len(seen) == 100 and seen[0] == 0.0
    stopped = batch.doSim(world, 1.0, {"robots[0].config[0]": 1.0}, items,
                          simTerm=lambda sim: sim.getTime() >= 0.5)
    assert stopped["time"] == pytest.approx(0.5)
    runs = batch.monteCarloSim(world, 0.1, {"robots[0].config[0]": lambda: 0.25}, 3, items)
    assert [c["robots[0].config[0]"] for c, _ in runs] == [0.25] * 3
    failed = batch.doSim(world, 0.1, {}, items, simInit=lambda sim: 1 / 0)
    assert failed["status"] == "error" and "division" in failed["error"]
    kept = []
    batch.doSim(world, 0.1, {}, items, simInit=kept.append)
    with pytest.raises(RuntimeError, match="has ended"):
        kept[0].getTime()  # a run's simulator does not outlive its run


def test_batch_sim_keeps_the_order_of_its_initial_conditions():
    world = spin_world()
    starts = [0.5, -0.5, 1.0]
    results = batch.batchSim(world, 0.2, [{"robots[0].config[0]": q} for q in starts],
                             ["robots[0].actualConfig[0]"], threads=2)
    for q, result in zip(starts, results):
        single = batch.doSim(world, 0.2, {"robots[0].config[0]": q}, ["robots[0].actualConfig[0]"])
        assert result["robots[0].actualConfig[0]"] == single["robots[0].actualConfig[0]"]
    assert results[0]["robots[0].actualConfig[0]"] != results[1]["robots[0].actualConfig[0]"]
