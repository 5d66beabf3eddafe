# SPDX-License-Identifier: MIT
"""Contact feedback: a stack of ten 1 kg boxes settles, then the loop over every pair of ids
(Klamp't's simulation tutorial) finds the touching pairs and the force each box takes from the
one below it: the weight of the boxes it carries, itself included.

    PYTHONPATH=build/python /usr/bin/python3 docs/examples/python/contact_feedback.py"""
import lamina
from example import drive, parse

args = parse(__doc__, duration=1.0)
world = lamina.WorldModel(
    str(lamina.WORLDS / "klampt" / "simulation_test_worlds" / "stacktest.xml"))
sim = lamina.Simulator(world)
sim.enableContactFeedbackAll()


def idle():
    sim.simulate(0.01)


drive(sim, idle, args)
for i in range(world.numIDs()):
    for j in range(i + 1, world.numIDs()):
        if sim.inContact(i, j):
            fz = sim.contactForce(j, i)[2]  # on j (the upper one) from i
            print(f"{world.getName(i)} - {world.getName(j)}: {fz:7.2f} N up on "
                  f"{world.getName(j)}")
