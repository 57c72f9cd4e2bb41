"""Captions whose numbers come from the core when the lesson loads, never typed in.

A caption is Markdown with ``str.format`` fields over a small, read-only vocabulary of the step's
scene in the step's frame (c = 1):

==========================  ===========================================================
``{event[T_1].t}``          a named event's time in the step's frame (``.x`` its place)
``{lab[T_1].t}``            the same event in the lab
``{preset[rod before][T_1].t}``  the same event in one of the scene's frame presets
``{signal[S].t}``           where the light from the key event arrives (``S``, ``R``, ``S_1``...)
``{rod[1].v_after}``        rod 1's lab velocity after (``v_before``, ``gamma_before``,
                            ``gamma_after``, ``rest_length``, ``mass_before``, ``mass_after``,
                            ``length_before``, ``length_after``)
``{param[v]}``              a parameter's value
``{frame.beta}``            the step's frame velocity (``frame.name``)
``{heat}``                  rest energy created (the budget's heat; of the scene's first
                            physical system where its rods are alternatives)
``{heat_where}``            which body that heat is in, in words (``"all in the wall (the rod
                            keeps its rest mass)"``)
``{verdict[1]}``            the core's first causal verdict in words, its events in the step's
                            frame, each labelled (``(lab t, x) = ...`` in the lab)
``{note[1]}``               the scene's first note in words (the string's strain, the barn's
                            verdicts), its events in the step's frame, labelled
==========================  ===========================================================

A format spec follows a colon as usual: ``{event[T_1].t:.3g}``. Write ``{{`` and ``}}`` for braces.
A negative number is printed with the minus sign, −0.75, as the prose writes −V (in code spans,
a command line, it stays as typed).
"""

from __future__ import annotations

import re
import string
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

import rigidrel_core as rr

from ..view.signals import signals_in, verdict_lines


class CaptionError(ValueError):
    """A caption field the vocabulary does not have, or a bad format spec."""


@dataclass(frozen=True)
class EventValue:
    t: float
    x: float


@dataclass(frozen=True)
class RodValues:
    v_before: float
    v_after: float
    gamma_before: float
    gamma_after: float
    rest_length: float
    mass_before: float
    mass_after: float
    length_before: float
    """Equal-time length in the step's frame at the start of the scene's time window."""
    length_after: float
    """Equal-time length in the step's frame at the end of the window (``L0/gamma`` when it moves there)."""


@dataclass(frozen=True)
class FrameValues:
    beta: float
    name: str


class _Table(Mapping[Any, Any]):
    """A named table that says what it has when asked for what it has not."""

    def __init__(self, what: str, items: Mapping[str, Any], renamed: Mapping[str, str] | None = None) -> None:
        self._what, self._items, self._renamed = what, dict(items), dict(renamed or {})

    def __getitem__(self, key: str | int) -> Any:
        key = str(key)  # str.format reads rod[1] with the integer 1
        if key in self._renamed:  # a caption written before the parameter was renamed
            raise CaptionError(f"{self._what}[{key}] is now {self._what}[{self._renamed[key]}]")
        if key not in self._items:
            have = ", ".join(self._items) or "none in this scene"
            raise CaptionError(f"{self._what}[{key}] does not exist; {self._what} has {have}")
        return self._items[key]

    def __iter__(self):  # pyright: ignore[reportImplicitOverride]
        return iter(self._items)

    def __len__(self) -> int:
        return len(self._items)


def vocabulary(scene: rr.Scene, frame: rr.Frame) -> dict[str, Any]:
    """The values a caption may name, all asked of the core."""
    signals = signals_in(scene, frame)
    lengths = scene.lengths(np.array(scene.time_window(frame=frame)), frame=frame)
    rods = {
        str(k + 1): RodValues(
            rod.motion.velocity_initial.value,
            rod.motion.velocity_final.value,
            rod.motion.velocity_initial.lorentz_factor(),
            rod.motion.velocity_final.lorentz_factor(),
            rod.motion.length,
            rod.mass_before,
            rod.mass_after,
            float(lengths[k, 0]),
            float(lengths[k, 1]),
        )
        for k, rod in enumerate(scene.rods)
    }
    verdicts: Sequence[str] = verdict_lines(scene, frame)
    return {
        "event": _Table("event", {k: EventValue(*v) for k, v in scene.events_in(frame=frame).items()}),
        "lab": _Table("lab", {k: EventValue(*v) for k, v in scene.events.items()}),
        "preset": _Table(
            "preset",
            {
                name: _Table(f"preset[{name}]", {k: EventValue(*v) for k, v in scene.events_in(frame=f).items()})
                for name, f in scene.frames.items()
            },
        ),
        "signal": _Table("signal", {leg.name: EventValue(*leg.arrival) for leg in signals.legs}),
        "rod": _Table("rod", rods),
        "param": _Table("param", {k: v for k, v in scene.parameters.items()}, rr.describe(scene).renamed),
        "frame": FrameValues(frame.beta, frame.label()),
        "heat": scene.budget(frame=frame).systems[0].heat,
        "heat_where": scene.budget(frame=frame).systems[0].heat_where,
        "verdict": _Table("verdict", {str(k + 1): v for k, v in enumerate(verdicts)}),
        "note": _Table("note", {str(k + 1): n[:1].upper() + n[1:] for k, n in enumerate(scene.notes(frame=frame))}),
    }


class _Formatter(string.Formatter):
    def get_value(self, key: int | str, args: Sequence[Any], kwargs: Mapping[str, Any]) -> Any:
        if isinstance(key, int):
            raise CaptionError("a caption field needs a name, e.g. {event[T_1].t}; write {{ and }} for braces")
        if key not in kwargs:
            raise CaptionError(f"{{{key}}} is not a caption value; the values are {', '.join(kwargs)}")
        return kwargs[key]

    def get_field(self, field_name: str, args: Sequence[Any], kwargs: Mapping[str, Any]) -> Any:
        if "._" in field_name or field_name.startswith("_"):
            raise CaptionError(f"{{{field_name}}}: no private names in captions")
        try:
            return super().get_field(field_name, args, kwargs)
        except AttributeError as exc:
            raise CaptionError(f"{{{field_name}}}: {exc.name!r} is not a value there") from None


#: A hyphen-minus that is the sign of a number (not a hyphen, nor an exponent's sign).
_SIGN = re.compile(r"(?<![\w′'.\])-])-(?=\.?\d)")


def with_minus_signs(text: str) -> str:
    """``text`` with each number's sign the minus sign, ``−0.75``, outside code spans (a command line
    is left as typed)."""
    parts = text.split("`")
    return "`".join(part if k % 2 else _SIGN.sub("−", part) for k, part in enumerate(parts))


def render_caption(template: str, scene: rr.Scene, frame: rr.Frame) -> str:
    """The caption with every field filled in from the core, each negative number with its minus sign."""
    try:
        return with_minus_signs(_Formatter().vformat(template, (), vocabulary(scene, frame)))
    except CaptionError:
        raise
    except (ValueError, KeyError, IndexError, TypeError) as exc:
        raise CaptionError(f"cannot fill in the caption ({exc})") from None
