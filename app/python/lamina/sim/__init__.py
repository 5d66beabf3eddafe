# SPDX-License-Identifier: MIT
"""lamina.sim: batch simulation (lamina.sim.batch)."""
from . import batch  # noqa: F401
