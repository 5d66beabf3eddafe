# SPDX-License-Identifier: MIT
"""Lamina: Klamp't's simulation API (WorldModel, Simulator, SimBody, SimRobotController) on
Lamina's core. `lamina.model.access` and `lamina.sim.batch` follow klampt.model.access and
klampt.sim.batch. See docs/python.md."""
from ._lamina import (  # noqa: F401
    RigidObjectModel,
    RobotModel,
    RobotModelLink,
    SimBody,
    SimRobotController,
    SimState,
    Simulator,
    SurfaceParameters,
    TerrainModel,
    WorldModel,
)
from . import model, sim, vis  # noqa: F401,E402
from .vis import render  # noqa: F401,E402
