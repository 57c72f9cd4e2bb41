r"""Light signals and causal relations (units c = 1), solved in closed form in light-cone coordinates.

With ``u = t - x`` and ``w = t + x`` a light ray moving in ``+x`` keeps its ``u``, one moving in
``-x`` keeps its ``w``, and a boost of rapidity ``psi`` multiplies them, ``u' = e^psi u`` and
``w' = e^-psi w``. A material point's worldline is, piece by piece:

* inertial at rapidity ``theta'`` (frame rapidity) through a switch event ``(u_s, w_s)``:
  ``w - w_s = e^(2 theta') (u - u_s)``;
* on its hyperbola of radius ``rho`` about the centre ``(u_C, w_C)``:
  ``(u - u_C)(w - w_C) = -rho^2`` (paper Sec. 3, Eq. (4), written about the Rindler horizon).

A ray meets each piece once at most, at ``w = w_s + e^(2 theta') (u_0 - u_s)`` or
``w = w_C - rho^2 / (u_0 - u_C)`` (and the mirror forms for a ray in ``-x``): no root finding,
and the arrival keeps the ray's own light-cone coordinate exactly, so it lies on the source's
light cone to the last bit. Which piece it meets follows from ``h = u - u_0`` (or ``w - w_0``) at
the two switch events, since ``h`` grows along every worldline slower than light.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Literal

import numpy as np
import numpy.typing as npt

from ._exact import relative_rapidity
from ._frame import Frame
from ._motion import RigidMotion
from ._validate import ParameterError, as_real

CausalKind = Literal["timelike", "lightlike", "spacelike"]
Event = tuple[float, float]


@dataclass(frozen=True)
class CausalRelation:
    """How event ``b`` is related to event ``a`` (c = 1); the same in every frame.

    ``interval`` is ``s^2 = dt^2 - dx^2``, formed as ``(dt - dx)(dt + dx)`` (a product of light-cone
    differences, so a lightlike pair gives exactly 0 when its events are exact). ``order`` is
    ``+1`` when ``b`` lies in ``a``'s future light cone (timelike or lightlike), ``-1`` in its past,
    and ``0`` for a spacelike pair (whose time order depends on the frame) or the same event.
    """

    kind: CausalKind
    interval: float
    order: Literal[-1, 0, 1]

    @property
    def can_signal(self) -> bool:
        """Whether a signal no faster than light can go from ``a`` to ``b``."""
        return self.order == 1

    @property
    def proper_time(self) -> float:
        """``sqrt(s^2)`` for a timelike pair (0 otherwise): the time between them in the frame where
        they happen at one place."""
        return math.sqrt(self.interval) if self.interval > 0.0 else 0.0

    @property
    def proper_distance(self) -> float:
        """``sqrt(-s^2)`` for a spacelike pair (0 otherwise): their distance in the frame where they
        happen at once."""
        return math.sqrt(-self.interval) if self.interval < 0.0 else 0.0


def _event(name: str, value: object) -> Event:
    allowed = "an event (t, x): two finite real numbers"
    try:
        arr = np.asarray(value)
    except (TypeError, ValueError):
        raise ParameterError(name, allowed, value) from None
    if arr.shape != (2,) or arr.dtype.kind not in "biuf":
        raise ParameterError(name, allowed, value)
    t, x = (as_real(name, float(v), allowed) for v in arr)
    return t, x


def causal_relation(a: npt.ArrayLike, b: npt.ArrayLike) -> CausalRelation:
    """The causal relation of events ``a`` and ``b`` given as ``(t, x)`` in one frame (any frame).

    ``s^2 = (dt - dx)(dt + dx)``: positive is timelike, zero lightlike, negative spacelike.
    """
    ta, xa = _event("a", a)
    tb, xb = _event("b", b)
    du = (tb - ta) - (xb - xa)
    dw = (tb - ta) + (xb - xa)
    interval = du * dw
    if interval > 0.0:
        return CausalRelation("timelike", interval, 1 if du > 0.0 else -1)
    if interval < 0.0:
        return CausalRelation("spacelike", interval, 0)
    if du == 0.0 and dw == 0.0:
        return CausalRelation("lightlike", 0.0, 0)
    return CausalRelation("lightlike", 0.0, 1 if du + dw > 0.0 else -1)


def signal_arrival_on(
    motion: RigidMotion, fraction: float, frame: Frame, source: Event, x_now: float, direction: int | None
) -> Event | None:
    """Where a light ray leaving ``source`` (frame ``(t, x)``) meets material point ``fraction`` of
    ``motion``, as frame ``(t, x)``; ``None`` if it never does. ``x_now`` is the point's frame x at the
    source's time; ``direction`` is +1 (ray toward +x), -1, or ``None`` (toward the point)."""
    t0, x0 = source
    ahead = x_now - x0
    if direction is None:
        if ahead == 0.0:
            return (t0, x0)
        direction = 1 if ahead > 0.0 else -1
    if direction * ahead < 0.0:
        return None  # the ray leaves the point behind: it never meets it
    up, down = frame.doppler_factors()
    row = motion.lab_rows(np.array([fraction]))[0]
    u_start, w_start = -row.minus_u_start * up, row.w_start * down
    u_stop, w_stop = -row.minus_u_stop * up, row.w_stop * down
    th_i = relative_rapidity(motion.velocity_initial, frame.velocity)
    th_f = relative_rapidity(motion.velocity_final, frame.velocity)
    u_centre, w_centre = -motion.horizon_x * up, motion.horizon_x * down
    rho2 = row.radius * row.radius
    if direction == 1:  # the ray keeps u = u0; solve for w
        u0 = t0 - x0
        if u_start >= u0:
            u, w = u0, w_start + math.exp(2.0 * th_i) * (u0 - u_start)
        elif u_stop >= u0 and u0 != u_centre:
            u, w = u0, w_centre - rho2 / (u0 - u_centre)
        else:
            u, w = u0, w_stop + math.exp(2.0 * th_f) * (u0 - u_stop)
    else:  # the ray keeps w = w0; solve for u
        w0 = t0 + x0
        if w_start >= w0:
            u, w = u_start + math.exp(-2.0 * th_i) * (w0 - w_start), w0
        elif w_stop >= w0 and w0 != w_centre:
            u, w = u_centre - rho2 / (w0 - w_centre), w0
        else:
            u, w = u_stop + math.exp(-2.0 * th_f) * (w0 - w_stop), w0
    return (0.5 * (u + w), 0.5 * (w - u))


@dataclass(frozen=True)
class ChangeVerdict:
    """Where one end's velocity change lies relative to the scene's origin event (the kick, the
    contact, the start), in words and in numbers; frame-independent (computed from invariants)."""

    rod: int
    end: Literal[0, 1]
    start: Event
    """Lab event where the end starts changing velocity."""
    stop: Event
    """Lab event where it has its final velocity."""
    relation_start: CausalRelation
    """The start's relation to the origin event."""
    relation_stop: CausalRelation
    arrival: Event | None
    """Lab event where the first light signal from the origin event reaches the end."""
    text: str

    @property
    def caused_by_a_signal(self) -> bool:
        """Whether a signal from the origin event could have started the change."""
        return self.relation_start.can_signal


def _where(relation: CausalRelation, origin: str) -> str:
    if relation.kind == "spacelike":
        return f"outside the light cone of {origin}"
    cone = "future" if relation.order == 1 else "past"
    if relation.kind == "lightlike":
        return f"on the {cone} light cone of {origin}"
    return f"inside the {cone} light cone of {origin}"


def change_verdict(
    rod: int,
    end: Literal[0, 1],
    names: tuple[str, str],
    start: Event,
    stop: Event,
    arrival: Event | None,
    origin: str,
    end_label: str,
) -> ChangeVerdict:
    """The verdict on one end's change ``start -> stop`` (lab events named ``names``) relative to the
    origin event ``(0, 0)``, which the text calls ``origin`` ("the contact"); ``end_label`` names the end."""
    r_start = causal_relation((0.0, 0.0), start)
    r_stop = causal_relation((0.0, 0.0), stop)
    s, t = names
    if r_start.kind == "spacelike" and r_stop.kind == "spacelike":
        text = (
            f"{end_label}: its whole change, {s} to {t}, lies outside the light cone of {origin}: "
            f"no signal from {origin} can have caused it, in any frame."
        )
    elif r_start.kind == "spacelike":
        text = (
            f"{end_label}: its change starts at {s}, outside the light cone of {origin} (no signal "
            f"from {origin} can have started it), and ends at {t}, {_where(r_stop, origin)}."
        )
    elif r_start.order == -1:
        text = (
            f"{end_label}: its change starts at {s}, {_where(r_start, origin)}: before {origin} in every "
            f"frame, and ends at {t}, {_where(r_stop, origin)}."
        )
    else:
        text = (
            f"{end_label}: its change starts at {s}, {_where(r_start, origin)}: a signal from {origin} "
            f"could have started it."
        )
    if arrival is not None:
        text += f" The first light signal from {origin} reaches it at (t, x) = ({arrival[0]:.4g}, {arrival[1]:.4g})."
    return ChangeVerdict(rod, end, start, stop, r_start, r_stop, arrival, text)
