"""The mouse (or a finger) on the canvas does physics, not camera: what a press, a drag and a release
on the diagrams ask for. Pure: page coordinates in, a request out; the live layer carries it out
(:mod:`rigidrel_app.live.gestures`), checked as any control's value is.

On a press, by what lies under it (page px, z up, as :mod:`.canvas` lays the page out):

- an event's dot on a Minkowski diagram (within :data:`EVENT_REACH_PX`): the light cone of that
  event, or none if it is the one drawn (:class:`ChooseCone`);
- elsewhere on the lab's diagram, or on the length panel: the clock jumps to the time under the
  pointer (kept in the playback window by the clock itself), and follows it while dragged
  (:class:`Scrub`; the diagram's vertical axis is t, the panel's horizontal one);
- on the chosen frame's diagram, the now-line (within :data:`NOW_REACH_PX`) scrubs as well; a drag
  anywhere else there changes the frame's velocity β, one unit of β per :data:`BETA_PER_WIDTH` of
  the plot's width, kept to the β slider's range (:class:`DragBeta`);
- anything else (the lanes, the legend, the margins): nothing.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import rigidrel_core as rr

from .canvas import ChartFrame
from .state import CUSTOM_BETA

#: How near an event's dot a press must be to choose its light cone (page px).
EVENT_REACH_PX = 14.0
#: How near the chosen frame's now-line a press must be to scrub rather than drag β (page px).
NOW_REACH_PX = 10.0
#: A drag across the whole plot's width changes β by this much.
BETA_PER_WIDTH = 1.0


@dataclass(frozen=True)
class ChooseCone:
    """Show the light cone of ``event`` (``None``: none)."""

    event: str | None


@dataclass(frozen=True)
class Scrub:
    """The clock to ``time``; a drag goes on reading time from ``chart``'s axis."""

    chart: int
    time: float


@dataclass(frozen=True)
class DragBeta:
    """A drag that sets the chosen frame's β: ``beta`` when it started, on a plot ``width`` px wide,
    from page x ``x0``."""

    beta: float
    width: float
    x0: float


Press = ChooseCone | Scrub | DragBeta | None


@dataclass(frozen=True)
class Diagrams:
    """What a press is read against: the charts on the page (lab diagram, chosen frame's diagram,
    length panel), the frame of each diagram, the events that may have a cone drawn, the one drawn
    and the chosen frame's β now."""

    frames: Sequence[ChartFrame | None]
    diagram_frames: tuple[rr.Frame, rr.Frame]
    scene: rr.Scene
    cone_events: tuple[str, ...]
    cone: str | None
    beta: float


def _shown_at(d: Diagrams, k: int, x: float, z: float) -> ChartFrame | None:
    """Chart ``k``'s frame if that chart is shown and ``(x, z)`` is on its plot, else ``None``."""
    f = d.frames[k] if k < len(d.frames) else None
    if f is None:
        return None
    p = f.plot
    return f if p.x0 <= x <= p.x1 and p.z0 <= z <= p.z1 else None


def press(d: Diagrams, x: float, z: float, now: float) -> Press:
    """What a press at page px ``(x, z)`` asks for, the clock at ``now`` (module docstring)."""
    for k in (0, 1):
        f = _shown_at(d, k, x, z)
        if f is None:
            continue
        near: list[tuple[float, str]] = []
        for name, (te, xe) in d.scene.events_in(frame=d.diagram_frames[k]).items():
            if name in d.cone_events:
                px, pz = f.px_one(xe, te)
                near.append((float((px - x) ** 2 + (pz - z) ** 2) ** 0.5, name))
        hit = min(near, default=None)
        if hit is not None and hit[0] <= EVENT_REACH_PX:
            return ChooseCone(None if hit[1] == d.cone else hit[1])
        if k == 0 or abs(f.px_one(0.0, now)[1] - z) <= NOW_REACH_PX:
            return Scrub(k, f.data_one(x, z)[1])
        return DragBeta(d.beta, f.plot.width, x)
    lengths = _shown_at(d, 2, x, z)
    return None if lengths is None else Scrub(2, lengths.data_one(x, z)[0])


def scrubbed(d: Diagrams, gesture: Scrub, x: float, z: float) -> float | None:
    """The time a scrub that started as ``gesture`` reads, the pointer at page px ``(x, z)``
    (anywhere on the page: a drag may leave its plot; the tab's clock keeps the time in its window
    as it does a typed one); ``None`` if its chart is no longer shown (a lesson's step changed the
    page under the drag)."""
    f = d.frames[gesture.chart] if gesture.chart < len(d.frames) else None
    return None if f is None else f.data_one(x, z)[0 if gesture.chart == 2 else 1]


def dragged_beta(gesture: DragBeta, x: float) -> float:
    """The β a drag that started as ``gesture`` sets, the pointer at page x ``x``."""
    lo, hi = CUSTOM_BETA
    return min(max(gesture.beta + BETA_PER_WIDTH * (x - gesture.x0) / gesture.width, lo), hi)
