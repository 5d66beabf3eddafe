# SPDX-License-Identifier: MIT
"""What calling the simulator from Python costs: sim.simulate(0.01) in a Python loop against the
same calls in a C++ loop (Simulator._simulateLoop) on the same simulator, ATHLETE on fractal
terrain with the exact solver. Each round runs a block of CALLS calls both ways from the same
saved state (getState/setState), so both do exactly the same physics, in alternating order; the
medians of the per-call times over ROUNDS rounds and their ratio are printed (docs/python.md
quotes them).

    PYTHONPATH=build/python /usr/bin/python3 tests/bench/python_overhead.py [--rounds 15]"""
import argparse
import statistics
import time

import lamina
from lamina.model.access import set_item

parser = argparse.ArgumentParser(description=__doc__)
parser.add_argument("--rounds", type=int, default=15)
parser.add_argument("--calls", type=int, default=20, help="simulate(0.01) calls per block")
parser.add_argument("--world", default=str(lamina.WORLDS / "klampt" / "athlete_fractal_1.xml"))
parser.add_argument("--quickstep", action="store_true",
                    help="QuickStep instead of the exact solver (cheaper steps: a larger share "
                         "for the call itself)")
options = parser.parse_args()

world = lamina.WorldModel(options.world)
if options.quickstep:
    set_item(world, "settings.solver", 1)
sim = lamina.Simulator(world)
sim.simulate(1.0)  # standing on the terrain: the steady cost, not the landing
python_ms, cpp_ms = [], []
same_physics = True


def from_python():
    start = time.perf_counter()
    for _ in range(options.calls):
        sim.simulate(0.01)
    python_ms.append((time.perf_counter() - start) * 1e3 / options.calls)


def from_cpp():
    start = time.perf_counter()
    sim._simulateLoop(0.01, options.calls)
    cpp_ms.append((time.perf_counter() - start) * 1e3 / options.calls)


for k in range(options.rounds):
    state = sim.getState()
    first, second = (from_python, from_cpp) if k % 2 == 0 else (from_cpp, from_python)
    first()
    end = sim.getActualConfig(0)
    sim.setState(state)
    second()
    same_physics &= sim.getActualConfig(0) == end
python_median, cpp_median = statistics.median(python_ms), statistics.median(cpp_ms)
ratios = [p / c for p, c in zip(python_ms, cpp_ms)]
solver = "QuickStep" if options.quickstep else "exact solver"
print(f"simulate(0.01), {solver}, {options.rounds} rounds of {options.calls} calls, "
      f"t = {sim.getTime():.2f} s")
print(f"  from C++:    median {cpp_median:.3f} ms per call "
      f"(min {min(cpp_ms):.3f}, max {max(cpp_ms):.3f})")
print(f"  from Python: median {python_median:.3f} ms per call "
      f"(min {min(python_ms):.3f}, max {max(python_ms):.3f})")
print(f"  Python / C++: {python_median / cpp_median:.4f} (ratio of the medians), "
      f"{statistics.median(ratios):.4f} (median of the rounds' ratios)")
print(f"  the same end configuration both ways in every round: {same_physics}")
