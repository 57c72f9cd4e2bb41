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

from .vocabulary import FRAME_COLOR, INK, Item, Label, Points, Polyline, Style


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
    lengths = scene.lengths(np.array([event[0]]), frame)[:, 0]
    return ComovingInstant(proper_time, frame, event, event_lab, horizon, tuple(float(v) for v in lengths))


def proper_time_window(scene: rr.Scene, point: RidePoint, lab_window: tuple[float, float]) -> tuple[float, float]:
    """The point's clock readings over a lab time window (its clock runs forward with lab time)."""
    t = np.array(lab_window, dtype=np.float64)
    tau = scene.proper_times(t, rr.LAB, fractions=np.array([point.fraction]))[point.rod, 0]
    return float(tau[0]), float(tau[1])


def simultaneity_items(instant: ComovingInstant, span: float) -> tuple[Item, ...]:
    """For the lab diagram: the comoving frame's line of simultaneity through the point's event
    (``span`` either side, in the frame's x'), the point's event and the horizon event, named."""
    t_here, x_here = instant.event
    line = np.array([[t_here, x_here - span], [t_here, x_here + span]])
    lab = instant.frame.inverse() @ line
    style = Style(FRAME_COLOR, 2.5, "dot", name="comoving: now", group="comoving")
    th, xh = instant.horizon_lab
    te, xe = instant.event_lab
    return (
        Polyline(lab[:, 1], lab[:, 0], style),
        Points(np.array([xe]), np.array([te]), Style(FRAME_COLOR, group="comoving"), size=10, symbol="circle-open"),
        Points(np.array([xh]), np.array([th]), Style(INK, name="horizon event", group="comoving"), size=10, symbol="x"),
        Label(xh, th, "horizon", Style(INK, group="comoving")),
    )
