# SPDX-License-Identifier: MIT
"""Looking at a simulation from Python.

render(sim, fn) draws a Simulator's current state (or a WorldModel's initial one) to a PNG off
screen, through OSMesa and the renderer of `lamina-headless shot`: the same pixels as
`lamina-headless shot WORLD --time T` for the same state, size and camera. OffscreenRenderer
keeps one camera over many pictures (a video's frames) and gives numpy arrays."""


def OffscreenRenderer(size="1280x720", camera="", overlay="", samples=4):
    """A reusable off-screen view: save(sim, fn), pixels(sim) (height x width x 3 uint8),
    camera(). size 'WxH'; camera and overlay as lamina-headless shot's --camera and
    --overlay ('' = the whole world, no overlays)."""
    from . import _render  # loaded on first use: it links OSMesa
    return _render.OffscreenRenderer(size, camera, overlay, samples)


def render(sim, fn, size="1280x720", camera="", overlay="", samples=4):
    """Writes a PNG of `sim` (a Simulator, or a WorldModel at its initial conditions)."""
    OffscreenRenderer(size, camera, overlay, samples).save(sim, str(fn))
