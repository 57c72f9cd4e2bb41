r"""Scene objects that are not rods: what they are, where they are, what a picture colours them by.

A wall, a barn's door, Bell's string: a scene does not solve for them, but every front end draws
them, from this description alone (units c = 1). A :class:`SceneObject` has

- a kind (:class:`~rigidrel_core.ObjectKind`), whose :class:`~rigidrel_core.ObjectRole` says how it
  is drawn: a body's bar and worldline, or a tie between two rods;
- its worldlines, exact functions of any frame's time like the rods': an inertial body's face
  ``x = x_0 + v t`` (:class:`InertialWorldline`), or a material point of a rod
  (:class:`MaterialWorldline`: a tie's end, a piston's face on the rod it pushes);
- optionally a scalar field along it that a picture colours it by (:class:`ObjectField`: a string's
  strain) and an event of its own (:class:`ObjectEvent`: the door closes, the string breaks).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Literal, Protocol

import numpy as np
import numpy.typing as npt

from ._exact import ExactVelocity, relative_rapidity
from ._frame import LAB, Frame, check_frame
from ._kinds import ObjectKind, ObjectRole
from ._motion import PIECEWISE_MIN, MotionPlan
from ._plastic import Motion, plan_rods
from ._validate import ParameterError, check_times, check_times_ordered

FloatArray = npt.NDArray[np.float64]
_MAX_CACHED_PLANS = 8


@dataclass(frozen=True)
class InertialWorldline:
    """An inertial lab worldline ``x = x0 + v t`` (a wall at rest at the origin: ``x0 = 0``, ``v = 0``)."""

    x0: float
    """Lab x at lab time 0."""
    velocity: ExactVelocity

    def positions(self, t: npt.ArrayLike, *, frame: Frame = LAB) -> FloatArray:
        """x' at times ``t'`` of ``frame``: ``x' = x'_0 + w (t' - t'_0)``, with ``w`` the velocity in
        the frame and ``(t'_0, x'_0)`` the lab event ``(0, x0)`` seen there (``x' = -beta t'`` for a wall
        at rest at the origin). Shape of ``t``."""
        frame = check_frame(frame)
        tt = check_times("t", t)
        w = float(np.tanh(relative_rapidity(self.velocity, frame.velocity)))
        t0, x0 = (frame @ np.array([0.0, self.x0])).tolist()
        return x0 + w * (tt - t0)


@dataclass(frozen=True)
class MaterialWorldline:
    """Material point ``fraction`` (of the rest length, from the left end) of rod ``rod``, whose motion
    is ``motion``: the rod's own worldline there, to the rods' accuracy."""

    rod: int
    """The rod's index in its scene (a picture draws a tie on that rod's row)."""
    fraction: float
    motion: Motion
    _plans: dict[tuple[float, float], MotionPlan] = field(
        default_factory=dict[tuple[float, float], MotionPlan], init=False, repr=False, compare=False
    )

    def _plan(self, frame: Frame) -> MotionPlan:
        """The point's constants in ``frame``, kept for the last few frames (a lane asks every frame)."""
        key = frame.key()
        plan = self._plans.get(key)
        if plan is None:
            plan = plan_rods([self.motion], frame, np.array([self.fraction]))
            if len(self._plans) >= _MAX_CACHED_PLANS:
                self._plans.clear()
            self._plans[key] = plan
        return plan

    def positions(self, t: npt.ArrayLike, *, frame: Frame = LAB) -> FloatArray:
        """x' at times ``t'`` of ``frame`` (closed form, :mod:`rigidrel_core._motion`). Shape of ``t``."""
        frame = check_frame(frame)
        tt, ordered = check_times_ordered("t", t, PIECEWISE_MIN)
        return self._plan(frame).positions(tt.ravel(), ordered=ordered).reshape(tt.shape)

    def proper_times(self, t: npt.ArrayLike, *, frame: Frame = LAB) -> FloatArray:
        """The point's clock at times ``t'`` of ``frame`` (0 where its change starts). Shape of ``t``."""
        frame = check_frame(frame)
        tt = check_times("t", t)
        return self._plan(frame).proper_times(tt.ravel()).reshape(tt.shape)


ObjectWorldline = InertialWorldline | MaterialWorldline


class FieldValues(Protocol):
    """A scalar field sampled as every sampler is: times ``t'`` of a frame given by name."""

    def __call__(self, t: npt.ArrayLike, *, frame: Frame = ...) -> FloatArray: ...


@dataclass(frozen=True)
class ObjectField:
    """A scalar along an object's history that a picture colours it by, from ``0`` (faint) to
    :attr:`full_scale` (strong): Bell's string's strain."""

    name: str
    """What it is, as a title names it: ``"strain"``."""
    values: FieldValues
    """The field at times ``t'`` of a frame, ``values(t, frame=f)`` (exact; shape of ``t``). A pure
    function of the scene's numbers, holding no scene."""
    full_scale: float
    """The value drawn strongest: the breaking strain, or without one the strain the string ends at."""
    full_scale_name: str
    """What the full scale is, in words: ``"breaking strain"``."""
    full_scale_meaning: str
    """What reaching it means, in a colour key's words: ``"breaks"``, ``"its final"``."""
    percent: bool = False
    """Shown in per cent (a strain)."""
    measured_in: str = ""
    """The convention the value depends on, as a title says it: ``"in the rear ship's comoving frame"``
    (``""``: none)."""


@dataclass(frozen=True)
class ObjectEvent:
    """An event of an object's own (the door closes, the string breaks), exact in the lab."""

    name: str
    """As a figure labels it: ``"door closes"``, ``"break"``."""
    lab: tuple[float, float]
    """Lab ``(t, x)``."""
    parts: bool = False
    """Whether the object is in two parts from this event on (a broken string's loose ends)."""
    state: str = ""
    """What the object is from then on, as a title says it: ``"broken"``."""
    meaning: str = ""
    """What the event is, in words, as an events table gives it: ``"the barn's door closes"``."""
    closes: bool = False
    """Whether a body is open until this event and closed from it on (a door): drawn as a stub at
    its top, then whole."""
    before: str = ""
    """What the object is until this event, as a title says it: ``"open"`` (``""``: nothing said)."""
    outcome: str = ""
    """What the event does to the rods, the same in every frame, as a title says it from the event
    on: ``"Born-rigid pole spans the doorway, signal-limited pole inside"`` (``""``: nothing said)."""

    def in_frame(self, *, frame: Frame = LAB) -> tuple[float, float]:
        """The event as ``(t', x')`` of ``frame`` (one boost)."""
        t, x = (check_frame(frame) @ np.array(self.lab)).tolist()
        return (t, x)


@dataclass(frozen=True)
class SceneObject:
    """A thing in a scene that is not a rod, with what a front end needs to draw it (module docstring)."""

    name: str
    kind: ObjectKind
    worldlines: tuple[ObjectWorldline, ...]
    """One for a body (its face toward the rods), two for a tie (its ends); checked."""
    side: Literal[-1, 1] = -1
    """Which side of its face a body's matter lies on: ``-1`` toward -x (a wall the rods meet from
    the right), ``+1`` toward +x."""
    field: ObjectField | None = None
    event: ObjectEvent | None = None

    def __post_init__(self) -> None:
        wanted = 2 if self.kind.role is ObjectRole.TIE else 1
        if len(self.worldlines) != wanted:
            allowed = f"{wanted} worldline{'s' if wanted > 1 else ''} for an object of role {self.kind.role.value!r}"
            raise ParameterError("worldlines", allowed, self.worldlines)
        if self.side not in (-1, 1):
            raise ParameterError("side", "-1 or 1", self.side)

    @classmethod
    def inertial(
        cls,
        name: str,
        kind: ObjectKind,
        x0: float,
        velocity: ExactVelocity,
        side: Literal[-1, 1] = -1,
        event: ObjectEvent | None = None,
    ) -> SceneObject:
        """A body whose face has the inertial lab worldline ``x = x0 + v t``."""
        return cls(name, kind, (InertialWorldline(x0, velocity),), side, None, event)

    @property
    def role(self) -> ObjectRole:
        return self.kind.role

    def positions(self, t: npt.ArrayLike, *, frame: Frame = LAB) -> FloatArray:
        """x' of each worldline at times ``t'`` of ``frame``. Shape ``(len(worldlines), *t.shape)``."""
        return np.stack([w.positions(t, frame=frame) for w in self.worldlines])

    def event_in(self, *, frame: Frame = LAB) -> tuple[float, float] | None:
        """The object's event as ``(t', x')`` of ``frame``, or ``None`` (it has none)."""
        return None if self.event is None else self.event.in_frame(frame=frame)

    def happened(self, t: npt.ArrayLike, *, frame: Frame = LAB) -> npt.NDArray[np.bool_]:
        """Whether the object's event has happened by times ``t'`` of ``frame`` (``t' >= t'_event``,
        the event's time in that frame, so the answer depends on the frame: the pole in the barn's
        door closes at another instant of the pole's frame); all ``False`` without an event. Shape
        of ``t``."""
        frame = check_frame(frame)
        tt = check_times("t", t)
        event = self.event
        if event is None:
            return np.zeros(tt.shape, dtype=np.bool_)
        return tt >= event.in_frame(frame=frame)[0]

    def parted(self, t: npt.ArrayLike, *, frame: Frame = LAB) -> npt.NDArray[np.bool_]:
        """Whether the object is in two parts at times ``t'`` of ``frame``: from its event on, if that
        parts it (:meth:`happened`); all ``False`` otherwise. Shape of ``t``."""
        happened = self.happened(t, frame=frame)
        return happened if self.event is not None and self.event.parts else np.zeros_like(happened)

    def closed(self, t: npt.ArrayLike, *, frame: Frame = LAB) -> npt.NDArray[np.bool_]:
        """Whether the object is closed at times ``t'`` of ``frame``: a body whose event closes it
        (a door), from that event on; any other object is never open, so always ``True``. Shape
        of ``t``."""
        happened = self.happened(t, frame=frame)
        return happened if self.event is not None and self.event.closes else np.ones_like(happened)
