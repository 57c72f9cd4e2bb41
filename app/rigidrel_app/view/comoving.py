"""A frame that rides the rod: at each instant of a material point's clock, its momentarily
comoving inertial frame, the point's event in it, and what the lab diagram shows of it.

Everything is asked of :mod:`rigidrel_core` (:meth:`~rigidrel_core.Scene.comoving_frame`,
:meth:`~rigidrel_core.Scene.point_event`, :meth:`~rigidrel_core.Scene.horizon_event`,
:meth:`~rigidrel_core.Scene.lengths`); this module only arranges it for drawing (c = 1).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

import rigidrel_core as rr

from .vocabulary import FRAME_COLOR, INK, FloatArray, Item, Label, Points, Polyline, Style

#: The legend's names of the ride's items on the diagrams.
RIDE_LINE_NAME = "comoving: now"
#: The event every comoving line of simultaneity passes through while the point accelerates: the centre
#: of its hyperbola, the vertex of the horizon (the horizon is that event's light cone, not the event).
HORIZON_NAME = "pivot event (the horizon's vertex)"
#: Its label on the diagram.
HORIZON_LABEL = "pivot"
#: The pivot event's mark: a square (the named events are dots, the rods now diamonds).
HORIZON_SYMBOL = "square"


@dataclass(frozen=True)
class RidePoint:
    """Which material point the frame rides: ``fraction`` of the rest length of rod ``rod``."""

    rod: int
    fraction: float

    def label(self, scene: rr.Scene) -> str:
        name = scene.rods[self.rod].name
        return f"comoving with {name} at f = {self.fraction:g}"


@dataclass(frozen=True)
class ComovingInstant:
    """One instant of the ride: the point's clock reads ``proper_time``."""

    proper_time: float
    frame: rr.Frame
    """The point's momentarily comoving inertial frame (shares the lab's origin)."""
    event: tuple[float, float]
    """The point's event ``(t', x')`` in ``frame``: the lane shows time ``t'``, centred on ``x'``."""
    event_lab: tuple[float, float]
    horizon_lab: tuple[float, float]
    """The centre of the rod's change: every comoving line of simultaneity passes through it."""
    lengths: tuple[float, ...]
    """Each rod's equal-time length in ``frame`` at ``t'`` (the ridden rod's is its rest length)."""


def ride(scene: rr.Scene, point: RidePoint, proper_time: float) -> ComovingInstant:
    """The instant of ``point``'s clock reading ``proper_time`` (negative before its change)."""
    frame = scene.comoving_frame(point.rod, point.fraction, proper_time=proper_time)
    event = scene.point_event(point.rod, point.fraction, proper_time=proper_time, frame=frame)
    event_lab = scene.point_event(point.rod, point.fraction, proper_time=proper_time)
    horizon = scene.horizon_event(point.rod)
    lengths = scene.lengths(np.array([event[0]]), frame=frame)[:, 0]
    return ComovingInstant(proper_time, frame, event, event_lab, horizon, tuple(float(v) for v in lengths))


def ride_at(scene: rr.Scene, point: RidePoint, t: float) -> ComovingInstant:
    """The instant of the ride where the point's worldline crosses lab time ``t`` (once: its clock
    runs forward with lab time), so the lab lane and the riding lane show the same event of the point."""
    tau = scene.proper_times(np.array([t]), frame=rr.LAB, fractions=np.array([point.fraction]))[point.rod, 0, 0]
    return ride(scene, point, float(tau))


@dataclass(frozen=True)
class RideTrack:
    """The ride sampled over a lab time window: what the length panel and the riding lane's scale need."""

    t: FloatArray
    """Lab times of the point's events, ``(n,)``."""
    lengths: FloatArray
    """Each rod's equal-time length in the point's comoving frame at each instant, ``(rods, n)``
    (the core's :meth:`~rigidrel_core.Scene.lengths`: the ridden rod's is its rest length throughout)."""
    reach: float
    """The farthest any rod's end gets from the point over the window, in the comoving frames."""


def ride_track(scene: rr.Scene, point: RidePoint, window: tuple[float, float], samples: int = 97) -> RideTrack:
    """The ride at ``samples`` lab times evenly over ``window`` (one comoving frame each: c = 1)."""
    t = np.linspace(window[0], window[1], samples)
    lengths = np.empty((scene.n_rods, samples))
    reach = 0.0
    for k, tk in enumerate(t):
        instant = ride_at(scene, point, float(tk))
        here = np.array([instant.event[0]])
        lengths[:, k] = instant.lengths
        ends = scene.positions(here, frame=instant.frame)[:, :, 0]
        reach = max(reach, float(np.max(np.abs(ends - instant.event[1]))))
    return RideTrack(t, lengths, reach)


def proper_time_window(scene: rr.Scene, point: RidePoint, lab_window: tuple[float, float]) -> tuple[float, float]:
    """The point's clock readings over a lab time window (its clock runs forward with lab time)."""
    t = np.array(lab_window, dtype=np.float64)
    tau = scene.proper_times(t, frame=rr.LAB, fractions=np.array([point.fraction]))[point.rod, 0]
    return float(tau[0]), float(tau[1])


def simultaneity_items(instant: ComovingInstant, span: float, seen_from: rr.Frame = rr.LAB) -> tuple[Item, ...]:
    """For a diagram of ``seen_from`` (the lab unless given): the comoving frame's line of simultaneity
    through the point's event (``span`` either side, in the comoving x'), the point's event and the
    pivot event, named (the events boosted by the core: ``seen_from @ comoving⁻¹``)."""
    t_here, x_here = instant.event
    events = np.array([[t_here, x_here - span], [t_here, x_here + span], [t_here, x_here]])
    seen = (seen_from @ instant.frame.inverse()) @ events
    style = Style(FRAME_COLOR, 2.5, "dot", name=RIDE_LINE_NAME, group="comoving")
    horizon = Style(INK, name=HORIZON_NAME, group="comoving")
    th, xh = seen_from @ np.array(instant.horizon_lab)
    te, xe = seen[2]
    return (
        Polyline(seen[:2, 1], seen[:2, 0], style),
        Points(np.array([xe]), np.array([te]), Style(FRAME_COLOR, group="comoving"), size=10, symbol="circle-open"),
        Points(np.array([xh]), np.array([th]), horizon, size=10, symbol=HORIZON_SYMBOL),
        Label(float(xh), float(th), HORIZON_LABEL, Style(INK, group="comoving")),
    )
