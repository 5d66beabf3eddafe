# SPDX-License-Identifier: MIT
"""Looking at a simulation from Python: off screen (render, OffscreenRenderer) or in Lamina's
window (run).

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


def run(sim, idle=None, size="1280x720", camera="bodies", overlay="", running=False, frames=0,
        screenshot=""):
    """Opens Lamina's window on `sim` (a Simulator this script drives) and returns when it is
    closed. Press s to run and stop the simulation (as in Klamp't's simulation template), Escape
    to close; drag to orbit, scroll to zoom. While it runs, `idle()` is called once per frame
    to move the simulation on (e.g. set controller commands, then sim.simulate(dt)); returning
    False from it closes the window. Without `idle` the window simulates in real time.

    The camera starts framing the bodies that move (camera='bodies'; 'world' frames everything,
    terrains included; or a camera description as lamina-headless --camera takes).
    running=True starts it running; frames=N closes after N frames and screenshot='f.png'
    writes the last one (for scripts and tests). The window needs a display (X11 or Xvfb); an
    exception raised in `idle` closes the window and propagates."""
    from . import _window  # loaded on first use: it links GLFW and OpenGL
    _window.run(sim, idle, size, camera, overlay, running, frames, str(screenshot))
