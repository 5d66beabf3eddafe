# SPDX-License-Identifier: MIT
"""klampt.sim.batch's doSim, batchSim and monteCarloSim on Lamina's C++ batch (docs/batch.md).

Without Python callbacks (simInit, simStep, simTerm) and with data samplers (uniform, normal,
choice, fixed, list below) the runs go to the C++ batch on every core with the GIL released;
run i of monteCarloSim draws from its own generator (seed, i), so results do not depend on the
threads and equal `lamina-headless batch` for the same spec and seed. Python callables as
samplers or callbacks run the batch serially, holding the GIL.

Lamina's keyword-only additions: setup=[{"robot": 0, "milestones": [q, ...]}] or
[{"robot": 0, "pid": q}] (commands sent before simInit), seed= and threads=."""
from .._lamina import Sampler, batchSim, doSim, monteCarloSim, runSpec  # noqa: F401

uniform = Sampler.uniform
normal = Sampler.normal
choice = Sampler.choice
fixed = Sampler.fixed
values = Sampler.list
