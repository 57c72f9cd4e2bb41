"""A tab's playback runtime, seen from the server: the script it runs, and what it reports.

The runtime (``assets/runtime.js``) is sent to each tab when its session starts. It says it is
ready, and later where it paused or ended, and where the pointer pressed, dragged or let go on
the canvas, by setting a hidden text control of the tab's (the viser way a page tells the server
anything): a :class:`Report` in JSON. Until it is ready, the
server draws the tab's frames itself, as for a client without a browser.
"""

from __future__ import annotations

import functools
import json
import string
from dataclasses import dataclass
from importlib import resources
from typing import Literal

import viser

from ..backends._viser import handle_uuid
from ..backends.viser import SHARED_ROOT
from .playback import FRAME_RATE

#: The hidden control's label (it is never shown).
REPORT_LABEL = "rigidrel playback"

Event = Literal["ready", "paused", "ended", "pointer"]
EVENTS: tuple[Event, ...] = ("ready", "paused", "ended", "pointer")
Phase = Literal["down", "move", "up"]
PHASES: tuple[Phase, ...] = ("down", "move", "up")
#: The largest canvas coordinate a pointer report may carry (CSS px).
POINTER_LIMIT_PX = 100_000.0
#: The pointer events one report carries at most (the runtime's latest).
POINTER_EVENTS = 16


@dataclass(frozen=True)
class Report:
    """What a runtime says: it is ``ready``, or it ``paused`` or ``ended`` at ``frame`` of ``timeline``."""

    event: Event
    timeline: str | None = None
    frame: int | None = None
    lead: str | None = None
    """With ``ready``: the lead token the tab's address carried (``?lead=...``), if any."""
    still: bool = False
    """With ``ready``: the browser asks for reduced motion (``prefers-reduced-motion: reduce``)."""
    pointer: tuple[PointerEvent, ...] = ()
    """With ``pointer``: the runtime's latest pointer events, oldest first (the server takes those
    it has not seen: a callback reads the report control's newest value, which may already be a
    later report than the one that called it)."""
    run: str = ""
    """With ``pointer``: which runtime numbered them (its sequence starts again in a new one)."""


@dataclass(frozen=True)
class PointerEvent:
    """The pointer went down on the canvas, moved while down, or went up, at ``(x, y)`` in the
    canvas' CSS px from its top left corner; ``seq`` numbers the runtime's events from 1."""

    seq: int
    phase: Phase
    x: float
    y: float


#: The longest lead token a report may carry (the server's are 22 characters).
LEAD_CHARS = 64


def _pointer_event(raw: object) -> PointerEvent | None:
    """One pointer event of a report, or None if it is not one (any field missing or out of range)."""
    if not isinstance(raw, dict):
        return None
    seq, phase, x, y = raw.get("seq"), raw.get("phase"), raw.get("x"), raw.get("y")
    numbers = [v for v in (x, y) if isinstance(v, int | float) and not isinstance(v, bool)]
    in_range = all(-POINTER_LIMIT_PX <= v <= POINTER_LIMIT_PX for v in numbers)  # NaN and inf fail it
    if not isinstance(seq, int) or isinstance(seq, bool) or seq < 1 or phase not in PHASES:
        return None
    if len(numbers) != 2 or not in_range:
        return None
    return PointerEvent(seq, phase, float(numbers[0]), float(numbers[1]))


def parse_report(text: str) -> Report | None:
    """A report as the runtime writes it, or None for anything else (a client may send anything)."""
    try:
        raw = json.loads(text)
    except (ValueError, TypeError):
        return None
    if not isinstance(raw, dict):
        return None
    event, timeline, frame = raw.get("event"), raw.get("timeline"), raw.get("frame")
    if event not in EVENTS:
        return None
    if event == "ready":
        lead = raw.get("lead")
        lead = lead if isinstance(lead, str) and 0 < len(lead) <= LEAD_CHARS else None
        return Report("ready", lead=lead, still=raw.get("still") is True)
    if event == "pointer":
        run, events = raw.get("run"), raw.get("events")
        if not isinstance(run, str) or not 0 < len(run) <= LEAD_CHARS or not isinstance(events, list):
            return None
        if not 0 < len(events) <= POINTER_EVENTS:
            return None
        read = [_pointer_event(e) for e in events]
        if any(e is None for e in read):
            return None
        return Report("pointer", pointer=tuple(e for e in read if e is not None), run=run)
    if not isinstance(timeline, str) or not isinstance(frame, int) or isinstance(frame, bool) or frame < 0:
        return None
    return Report(event, timeline, frame)


def add_playback_report(gui: viser.GuiApi) -> viser.GuiTextHandle:
    """The hidden text control the runtime reports through."""
    return gui.add_text(REPORT_LABEL, "", visible=False)


@dataclass(frozen=True)
class RuntimeConfig:
    """What the runtime is told when it is sent: the owner id its scene messages carry, the report
    control, and the time controls it keeps up to date while it plays (each a number or a text)."""

    owner: str
    report: str
    clock: tuple[tuple[str, Literal["number", "text"]], ...]


@functools.cache
def _asset_source(name: str) -> str:
    return resources.files("rigidrel_app.live").joinpath("assets", name).read_text(encoding="utf-8")


def page_asset(name: str, **values: object) -> str:
    """A file of the page's JavaScript or CSS (``live/assets/NAME``, package data) with its
    ``$placeholders`` filled in from ``values`` (every one must be given)."""
    source = _asset_source(name)
    return string.Template(source).substitute({k: str(v) for k, v in values.items()}) if values else source


def runtime_script(config: RuntimeConfig) -> str:
    """The runtime's source with its configuration filled in."""
    source = _asset_source("runtime.js")
    values = {
        "owner": config.owner,
        "report": config.report,
        "clock": config.clock,
        "frameRate": FRAME_RATE,
        "sharedRoot": SHARED_ROOT,
    }
    return source.replace("__CONFIG__", json.dumps(values))


def clock_controls(
    handles: tuple[viser.GuiInputHandle[float] | viser.GuiTextHandle, ...],
) -> tuple[tuple[str, Literal["number", "text"]], ...]:
    """The time controls as the runtime writes them: a text box gets the time as text."""
    return tuple((handle_uuid(h), "text" if isinstance(h, viser.GuiTextHandle) else "number") for h in handles)
