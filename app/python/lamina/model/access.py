# SPDX-License-Identifier: MIT
"""klampt.model.access's get_item/set_item on access paths (docs/access-paths.md).

get_item(obj, path) and set_item(obj, path, value) take a WorldModel (rows and initial
conditions) or a Simulator (rows, live, and the current state). Paths are parsed, never
evaluated; a bad path or a refused value raises ValueError naming the path."""
from .._lamina import get_item, set_item  # noqa: F401
