# SPDX-License-Identifier: MIT
"""lamina.model: access paths (lamina.model.access) and trajectories (lamina.model.trajectory)."""
from . import access, trajectory  # noqa: F401
