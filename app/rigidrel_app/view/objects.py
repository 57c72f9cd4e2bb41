"""How scene objects that are not rods look: one style table, by the role the core gives each object.

The core describes every object (:class:`rigidrel_core.SceneObject`: its kind and
:class:`~rigidrel_core.ObjectRole`, its worldlines, a field to colour it by, an event of its own);
:data:`OBJECT_STYLES` says how each role is drawn, in the lanes (:mod:`.lanes`: a bar at a body's
face, a thin bar between a tie's ends), on the diagrams (:mod:`.diagrams`: a body's worldline), in
print (:mod:`rigidrel_app.export.paradox_figures`) and in the recordings' palette
(:mod:`rigidrel_app.backends.raster`). Nothing here, or in what draws from it, names a scene or
an object kind: a new object of a known role is drawn as it comes.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from types import MappingProxyType
from typing import Literal

import rigidrel_core as rr

from .vocabulary import Style

LaneGlyph = Literal["bar", "tie"]
"""A body's bar at its face, on the whole rod band; or a tie's thin bar between its ends, on its row."""

#: A body the rods meet (a wall): grey.
BARRIER_COLOR = "#6E6E6E"
#: A body nothing meets (a barn's door): brown.
MARKER_COLOR = "#8C5A2B"
#: An object's field, faint (0) to strong (its full scale): stops of matplotlib's "magma" map from 0.8
#: down to 0.2 (light peach to dark violet). Its lightness falls monotonically, so the order reads in
#: every kind of colour vision and in grey; none of its stops is a rod's colour. The words for it are
#: "faint → strong", true on a light ground and on a dark one, which shows every colour at the opposite
#: lightness.
FIELD_RAMP = ("#FE9F6D", "#F7705C", "#DE4968", "#B73779", "#8C2981", "#641A80", "#3B0F70")
#: Print figures draw every object in one grey.
PRINT_GREY = "#555555"


@dataclass(frozen=True)
class ObjectStyle:
    """How one role of object is drawn."""

    glyph: LaneGlyph
    color: str
    """A body's bar and worldline; a tie's colour where it has no field (with one: on :attr:`ramp`)."""
    width: float
    """A bar's width (lane units: the largest rest length), or a tie's thickness as a share of its row's."""
    diagram: Style | None
    """Its worldlines on the Minkowski diagrams (``None``: not drawn there, as a tie's ends are the rods')."""
    print_style: Style | None
    """Its worldlines in print figures (``None``: not drawn)."""
    ramp: tuple[str, ...] = ()
    """Its field's colours, faint to strong."""
    loose_end_share: float = 0.0
    """Once parted (a broken string), each loose end is this share of the gap between its ends."""
    length_panel: Style | None = None
    """A tie's equal-time length (its ends' separation) in the length panel, in the lab (the chosen
    frame's dashed, as the rods'); ``None``: not drawn there (a body has no length)."""


#: The style table: every role's look.
OBJECT_STYLES: Mapping[rr.ObjectRole, ObjectStyle] = MappingProxyType(
    {
        rr.ObjectRole.BARRIER: ObjectStyle(
            "bar", BARRIER_COLOR, 0.02, Style(BARRIER_COLOR, 5.0), Style(PRINT_GREY, 5.0)
        ),
        rr.ObjectRole.MARKER: ObjectStyle(
            "bar", MARKER_COLOR, 0.01, Style(MARKER_COLOR, 2.5, "dash"), Style(PRINT_GREY, 2.0, "dash")
        ),
        rr.ObjectRole.TIE: ObjectStyle(
            "tie", FIELD_RAMP[0], 0.35, None, None, FIELD_RAMP, 0.2, Style(FIELD_RAMP[-1], 2.0)
        ),
    }
)


def object_style(obj: rr.SceneObject) -> ObjectStyle:
    """The style of ``obj``'s role."""
    return OBJECT_STYLES[obj.role]


def _amount(field: rr.ObjectField, value: float, spec: str) -> str:
    """A value of ``field`` as a title writes it: ``"22.0 %"`` for a field in per cent."""
    return f"{100.0 * value:{spec}} %" if field.percent else f"{value:{spec}}"


def object_words_at(obj: rr.SceneObject, frame: rr.Frame, now: float) -> str:
    """:func:`object_words` at time ``now`` of ``frame``, its field's value and its event's having
    happened taken from the core (what a lane's title says of ``obj`` then)."""
    value = None if obj.field is None else float(obj.field.values([now], frame=frame)[0])
    return object_words(obj, value, bool(obj.happened([now], frame=frame)[0]))


def object_words(obj: rr.SceneObject, value: float | None, happened: bool) -> str:
    """What a lane's title says of ``obj`` at an instant: its field's ``value``, the frame it is measured
    in, and the colours' key (``"string strain 22.0 % in the rear ship's comoving frame (faint → strong:
    0 → 25 %, breaks)"``), or, once its event has ``happened`` in the lane's frame, the state it
    leaves, with what it did to the rods (``"string broken (at its breaking strain 25 %)"``, ``"door
    closed (Born-rigid pole spans the doorway, signal-limited pole inside)"``), and before it the
    state it ends (``"door open"``); empty for an object with none of these."""
    field, event = obj.field, obj.event
    if happened and event is not None and event.state:
        head = f"{obj.name} {event.state}" + (f" ({event.outcome})" if event.outcome else "")
        if field is None:
            return head
        return f"{head} (at its {field.full_scale_name} {_amount(field, field.full_scale, '.3g')})"
    if event is not None and event.before and not happened:
        return f"{obj.name} {event.before}"
    if field is None or value is None:
        return ""
    now, scale = _amount(field, value, ".1f"), _amount(field, field.full_scale, ".3g")
    measured = f" {field.measured_in}" if field.measured_in else ""
    return f"{obj.name} {field.name} {now}{measured} (faint → strong: 0 → {scale}, {field.full_scale_meaning})"
