r"""Light signals and causal relations (units c = 1), solved in closed form in light-cone coordinates.

With ``u = t - x`` and ``w = t + x`` a light ray moving in ``+x`` keeps its ``u``, one moving in
``-x`` keeps its ``w``, and a boost of rapidity ``psi`` multiplies them, ``u' = e^psi u`` and
``w' = e^-psi w``. A material point's worldline is, piece by piece:

* inertial at rapidity ``theta'`` (frame rapidity) through a switch event ``(u_s, w_s)``:
  ``w - w_s = e^(2 theta') (u - u_s)``;
* on its hyperbola of radius ``rho`` about the centre ``(u_C, w_C)``:
  ``(u - u_C)(w - w_C) = -rho^2`` (paper Sec. 3, Eq. (4), written about the centre event ``C``,
  whose light cone ``u = u_C``, ``w = w_C`` is the Rindler horizon).

A ray meets each piece once at most, at ``w = w_s + e^(2 theta') (u_0 - u_s)`` or
``w = w_C - rho^2 / (u_0 - u_C)`` (and the mirror forms for a ray in ``-x``): no root finding,
and the arrival keeps the ray's own light-cone coordinate exactly, so it lies on the source's
light cone to the last bit. Which piece it meets follows from ``h = u - u_0`` (or ``w - w_0``) at
the two switch events, since ``h`` grows along every worldline slower than light.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING, Literal

import numpy as np
import numpy.typing as npt

from ._exact import relative_rapidity
from ._frame import LAB, Frame
from ._motion import RigidMotion

if TYPE_CHECKING:
    from ._plastic import PlasticMotion
from ._validate import ParameterError, as_real
from ._words import event_in_words

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


def as_event(name: str, value: object) -> Event:
    """``value`` as an event ``(t, x)`` of two finite floats; a :class:`ParameterError` naming ``name``
    otherwise."""
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
    ta, xa = as_event("a", a)
    tb, xb = as_event("b", b)
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


#: A lab light-cone coordinate to double-double: ``(hi, lo)``.
Exact = tuple[float, float]


def _minus(a: Exact, b: Exact) -> float:
    """``a - b`` of two double-double numbers, rounded once: exact however close they are."""
    return (a[0] - b[0]) + (a[1] - b[1])


def signal_arrival_on(
    motion: RigidMotion | PlasticMotion,
    fraction: float,
    frame: Frame,
    source: tuple[Exact, Exact],
    direction: int | None,
) -> Event | None:
    """Where a light ray leaving ``source`` meets material point ``fraction`` of ``motion``, as frame
    ``(t, x)``; ``None`` if it never does.

    ``source`` is given by its *lab* light-cone coordinates ``(u_0, w_0) = (t - x, t + x)`` to
    double-double: exact for the scene's own events, so a source a hair off (or on) a worldline,
    or a ray chasing an ultra-relativistic point, is not blurred by rounding. Every difference of
    light-cone coordinates is taken in the lab to double-double and then scaled by the frame's
    Doppler factor (``u' = e^psi u``, ``w' = e^-psi w``).

    ``direction`` +1 is a ray toward +x (it keeps ``u_0``; it meets the point in the source's future
    iff the meeting's ``w >= w_0``), -1 toward -x (keeps ``w_0``, needs ``u >= u_0``); ``None`` takes
    the one that meets the point in the future (both do, at the source, when it is on the worldline).
    On the hyperbola ``(u - u_C)(w - w_C) = -rho^2`` the ray keeping ``u_0`` meets it at
    ``w = w_s - W_s (u_0 - u_s)/(u_0 - u_C)`` from any point ``s`` of it (``W_s = w_s - w_C``): the
    switch events or the lab vertex, whichever gives the smaller terms.
    """
    u0, w0 = source
    up, down = frame.doppler_factors()
    row = motion.lab_rows(np.array([fraction]), exact=True)[0]
    lo = row.low
    u_start, w_start = (-row.minus_u_start, -lo[1]), (row.w_start, lo[2])
    u_stop, w_stop = (-row.minus_u_stop, -lo[4]), (row.w_stop, lo[5])
    th_i = relative_rapidity(motion.velocity_initial, frame.velocity)
    th_f = relative_rapidity(motion.velocity_final, frame.velocity)
    srho = motion.sign * row.radius
    centre_u, centre_w = (-motion.horizon_x, 0.0), (motion.horizon_x, 0.0)
    # points of the hyperbola (lab u, lab w) with their frame offsets from the centre,
    # U' = -sign rho e^-theta', W' = sign rho e^theta': the switch events and the lab vertex
    anchors = (
        (u_start, w_start, -srho * math.exp(-th_i), srho * math.exp(th_i)),
        (u_stop, w_stop, -srho * math.exp(-th_f), srho * math.exp(th_f)),
        ((-row.x_vertex, 0.0), (row.x_vertex, 0.0), -srho * up, srho * down),
    )

    def on_hyperbola(kept: Exact, centre: Exact, points: list[tuple[Exact, Exact, float]], scale: float) -> float:
        offset = _minus(kept, centre)
        best, best_size = math.nan, math.inf
        for a_s, b_s, big_b in points:
            d = _minus(kept, a_s)
            step = big_b * d / offset if d != 0.0 else 0.0
            b_frame = scale * b_s[0]
            size = abs(b_frame) + abs(step)
            if size < best_size:
                best, best_size = b_frame - step, size
        return best

    def rightward() -> float:  # the ray keeps u0: the meeting's frame w'
        if _minus(u_start, u0) >= 0.0:
            return down * w_start[0] + math.exp(2.0 * th_i) * up * _minus(u0, u_start)
        if _minus(u_stop, u0) >= 0.0 and _minus(u0, centre_u) != 0.0:
            return on_hyperbola(u0, centre_u, [(a[0], a[1], a[3]) for a in anchors], down)
        return down * w_stop[0] + math.exp(2.0 * th_f) * up * _minus(u0, u_stop)

    def leftward() -> float:  # the ray keeps w0: the meeting's frame u'
        if _minus(w_start, w0) >= 0.0:
            return up * u_start[0] + math.exp(-2.0 * th_i) * down * _minus(w0, w_start)
        if _minus(w_stop, w0) >= 0.0 and _minus(w0, centre_w) != 0.0:
            return on_hyperbola(w0, centre_w, [(a[1], a[0], a[2]) for a in anchors], up)
        return up * u_stop[0] + math.exp(-2.0 * th_f) * down * _minus(w0, w_stop)

    u0_frame, w0_frame = up * (u0[0] + u0[1]), down * (w0[0] + w0[1])
    found: list[tuple[float, float]] = []  # light-cone coordinates (u', w') of each meeting
    if direction != -1:
        w = rightward()
        if w >= w0_frame:  # a ray toward +x meets the point in its future
            found.append((u0_frame, w))
    if direction != 1:
        u = leftward()
        if u >= u0_frame:
            found.append((u, w0_frame))
    if not found:
        if direction is None:  # both a hair in the past: the source is on the worldline (to rounding)
            return (0.5 * (u0_frame + w0_frame), 0.5 * (w0_frame - u0_frame))
        return None
    u, w = min(found, key=lambda e: e[0] + e[1])
    return (0.5 * (u + w), 0.5 * (w - u))


@dataclass(frozen=True)
class ChangeVerdict:
    """Where one end's velocity change lies relative to the scene's cause (the kick, the contact, the
    start: :meth:`rigidrel_core.Scene.cause`), in words and in numbers. The kinds (timelike,
    lightlike, spacelike) are invariants, found from the exact lab events; the events and the words
    are those of :attr:`frame`."""

    rod: int
    end: Literal[0, 1]
    start: Event
    """Event of :attr:`frame` where the end starts changing velocity."""
    stop: Event
    """Event of :attr:`frame` where it has its final velocity."""
    relation_start: CausalRelation
    """The start's relation to the cause (the same in every frame)."""
    relation_stop: CausalRelation
    arrival: Event | None
    """Event of :attr:`frame` where the first light signal from the cause reaches the end."""
    text: str
    """The verdict in words; every coordinate pair in it is of :attr:`frame`, labelled
    (:func:`rigidrel_core._words.event_in_words`)."""
    frame: Frame = LAB
    """The frame of the events and of the words."""
    names: tuple[str, str] = ("", "")
    """The start's and the stop's names in the scene (``"T_1"``), ``""`` for one that has none."""
    end_label: str = ""
    """The end in words: ``"the right end of rear ship"``."""

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
    lab: tuple[Event, Event],
    seen: tuple[Event, Event, Event | None],
    frame: Frame,
    origin: str,
    end_label: str,
    cause: Event = (0.0, 0.0),
) -> ChangeVerdict:
    """The verdict on one end's change relative to the lab event ``cause`` (the origin event ``(0, 0)``
    unless an end is kicked elsewhere), which the text calls ``origin`` ("the contact");
    ``end_label`` names the end. ``lab`` holds the change's start and stop
    as exact lab events (their kinds relative to the origin are computed there: invariants);
    ``seen`` the start, the stop and the first light's arrival as events of ``frame``, which the
    words give. ``names`` are the start's and the stop's names (``""``: none; the words then give
    the event's coordinates in ``frame``, labelled)."""
    r_start = causal_relation(cause, lab[0])
    r_stop = causal_relation(cause, lab[1])
    start, stop, arrival = seen
    s, t = (name or event_in_words(event, frame) for name, event in zip(names, (start, stop), strict=True))
    if r_start.kind == "spacelike" and r_stop.kind == "spacelike":
        text = (
            f"{end_label}: its whole change, from {s} to {t}, lies outside the light cone of {origin}: "
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
        text += f" The first light signal from {origin} reaches it at {event_in_words(arrival, frame)}."
    return ChangeVerdict(rod, end, start, stop, r_start, r_stop, arrival, text, frame, names, end_label)
