# SPDX-License-Identifier: MIT
"""lamina.model: access paths (lamina.model.access)."""
from . import access  # noqa: F401
