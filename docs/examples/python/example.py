# SPDX-License-Identifier: MIT
"""What the examples share: their command line and the choice between running headless and
watching in Lamina's window (press s to run, as in Klamp't's simulation template)."""
import argparse

import lamina
from lamina import vis


def parse(description, duration):
    """--window, --duration and --png, with the example's own default duration (s)."""
    parser = argparse.ArgumentParser(description=description)
    parser.add_argument("--window", action="store_true",
                        help="watch in Lamina's window (press s to run, Escape to close)")
    parser.add_argument("--duration", type=float, default=duration,
                        help=f"simulated seconds (default {duration})")
    parser.add_argument("--png", help="write a picture of the last state to this file")
    return parser.parse_args()


def drive(sim, idle, args):
    """Calls idle() (one control step: commands, then sim.simulate) until the duration is
    simulated: in a loop, or once per frame of Lamina's window with --window."""
    def step():
        return sim.getTime() < args.duration - 1e-9 and idle() is not False

    if args.window:
        vis.run(sim, step)
    else:
        while step():
            pass
    if args.png:
        lamina.render(sim, args.png)
