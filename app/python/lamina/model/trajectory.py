# SPDX-License-Identifier: MIT
"""klampt.model.trajectory's Trajectory and RobotTrajectory: milestones at times, evaluated
piecewise linearly, with Klamp't's attributes (`times`, `milestones`, both plain lists that may be
edited in place) and methods (`eval`, `deriv`, `getSegment`, `load`, `save`, `startTime`,
`endTime`, `duration`).

`load`/`save` read and write Klamp't's `.path` text through Lamina's core (a bad line raises
RuntimeError with its file:line). A RobotTrajectory interpolates with
`RobotModel.interpolate`, so spin joints turn the short way round (docs/python.md lists the
differences from Klamp't)."""
import bisect

from .._lamina import _read_path, _write_path


class Trajectory:
    """Milestones (lists of numbers) at nondecreasing times (s), linear in between."""

    def __init__(self, times=None, milestones=None):
        self.times = [] if times is None else [float(t) for t in times]
        self.milestones = [] if milestones is None else [list(m) for m in milestones]
        if len(self.times) != len(self.milestones):
            raise ValueError(f"{len(self.times)} times for {len(self.milestones)} milestones")

    def load(self, fn):
        """Reads a Klamp't .path file ("t  N q1 ... qN" per line)."""
        self.times, self.milestones = _read_path(str(fn))

    def save(self, fn):
        """Writes a Klamp't .path file."""
        _write_path(str(fn), self.times, self.milestones)

    def startTime(self):
        return self.times[0] if self.times else 0.0

    def endTime(self):
        return self.times[-1] if self.times else 0.0

    def duration(self):
        return self.endTime() - self.startTime()

    def getSegment(self, t, endBehavior="halt"):
        """(i, u): t lies a fraction u along the segment from milestone i to i + 1; i = -1
        before the start and the last index after the end. endBehavior 'loop' wraps t into
        the trajectory's time span."""
        if not self.times:
            raise ValueError("empty trajectory")
        if len(self.times) == 1:
            return (-1, 0.0)
        if endBehavior == "loop" and self.duration() > 0:
            t = self.startTime() + (t - self.startTime()) % self.duration()
        elif endBehavior != "halt":
            raise ValueError(f"endBehavior must be 'halt' or 'loop', got {endBehavior!r}")
        if t >= self.times[-1]:
            return (len(self.times) - 1, 0.0)
        if t <= self.times[0]:
            return (-1, 0.0)
        i = bisect.bisect_right(self.times, t) - 1
        return (i, (t - self.times[i]) / (self.times[i + 1] - self.times[i]))

    def eval(self, t, endBehavior="halt"):
        """The configuration at time t: the first milestone before the start, the last after
        the end (or wrapped, with 'loop')."""
        i, u = self.getSegment(t, endBehavior)
        if i < 0:
            return list(self.milestones[0])
        if i + 1 >= len(self.milestones):
            return list(self.milestones[-1])
        return self.interpolate_state(self.milestones[i], self.milestones[i + 1], u,
                                      self.times[i + 1] - self.times[i])

    def deriv(self, t, endBehavior="halt"):
        """The velocity at time t: the segment's slope, zero before the start and after the
        end."""
        i, u = self.getSegment(t, endBehavior)
        if i < 0 or i + 1 >= len(self.milestones):
            return [0.0] * len(self.milestones[0 if i < 0 else -1])
        return self.difference_state(self.milestones[i + 1], self.milestones[i], u,
                                     self.times[i + 1] - self.times[i])

    def interpolate_state(self, a, b, u, dt):
        return [x + u * (y - x) for x, y in zip(a, b)]

    def difference_state(self, a, b, u, dt):
        """(a - b) / dt: the velocity of the segment from b to a lasting dt."""
        return [(x - y) / dt for x, y in zip(a, b)]


class RobotTrajectory(Trajectory):
    """A Trajectory of a robot's configurations (robot: a RobotModel), interpolated by the
    robot's joints."""

    def __init__(self, robot, times=None, milestones=None):
        super().__init__(times, milestones)
        self.robot = robot

    def interpolate_state(self, a, b, u, dt):
        return self.robot.interpolate(a, b, u)

    def difference_state(self, a, b, u, dt):
        return [d / dt for d in self.robot.interpolateDeriv(b, a)]
