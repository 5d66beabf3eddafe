# SPDX-License-Identifier: MIT
"""Lamina: Klamp't's simulation API (WorldModel, Simulator, SimBody, SimRobotController) on
Lamina's core. `lamina.model.access`, `lamina.model.trajectory` and `lamina.sim.batch` follow
klampt.model.access, klampt.model.trajectory and klampt.sim.batch; `lamina.vis` draws
simulations off screen (render) or in Lamina's window (run). See docs/python.md."""
import pathlib as _pathlib

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
from ._paths import WORLDS as _WORLDS
from .vis import render  # noqa: F401,E402

#: Lamina's worlds folder: the checkout's worlds/, or <prefix>/share/lamina/worlds once installed
WORLDS = _pathlib.Path(_WORLDS)
