# SPDX-License-Identifier: MIT
"""The seed's batch: a 1R arm hanging in gravity starts at a random angle and is sent to 0 by
its PID controller (kP 20, kI 8, kD 5) in 100 runs of 5 s on every core (Klamp't's
klampt.sim.batch.monteCarloSim). With --args the target is sampled too, as a named argument the
set-up's milestone uses. The same runs as `lamina-headless batch worlds/batch/spin_to_zero.json`
(or spin_to_target.json), value for value.

    PYTHONPATH=build/python /usr/bin/python3 docs/examples/python/batch_monte_carlo.py [--args]"""
import argparse
import math

import lamina
from lamina.model.access import set_item
from lamina.sim import batch

parser = argparse.ArgumentParser(description=__doc__)
parser.add_argument("--args", action="store_true", help="sample the target in [-0.5, 0.5] too")
parser.add_argument("--runs", type=int, default=100)
options = parser.parse_args()

world = lamina.WorldModel(str(lamina.WORLDS / "klampt" / "control" / "world1.xml"))
for gain, value in (("kP", 20), ("kI", 8), ("kD", 5)):
    set_item(world, f"robots[0].drivers[0].{gain}", value)
samplers = {"robots[0].config[0]": batch.uniform(-math.pi, math.pi)}
target = [0.0]
if options.args:
    samplers["args"] = {"target": batch.uniform(-0.5, 0.5)}
    target = "args.target"
items = ["robots[0].actualConfig[0]", "robots[0].actualVelocity[0]",
         "controllers[0].commandedConfig[0]"]
runs = batch.monteCarloSim(world, 5.0, samplers, options.runs, items,
                           setup=[{"robot": 0, "milestones": [target]}],
                           seed=2 if options.args else 1)
errors = [r[items[0]] - r[items[2]] for _, r in runs]
print(f"{len(runs)} runs, statuses {sorted({r['status'] for _, r in runs})}")
print(f"final angle minus command: min {min(errors):.4f}, max {max(errors):.4f} rad")
