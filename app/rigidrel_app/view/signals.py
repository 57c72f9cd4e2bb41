"""The light-signal layer: rays from the scene's key event to each rod's far end and back, the key
event's future light cone, the pulse in the lanes, and the causal verdicts in words.

Every event comes from :mod:`rigidrel_core` (:meth:`rigidrel_core.Scene.signal_arrival`, solved in
closed form in the frame asked for, and :meth:`rigidrel_core.Scene.causal_verdicts`). This module
only chooses what to show and lays it out (c = 1: light moves one unit of x per unit of t).

The key event is the scene's cause (:meth:`rigidrel_core.Scene.cause`): its origin event, ``(0, 0)``
in every frame (the start, the kick, the contact or the left end's stop), or a kick elsewhere. A
general velocity change has no cause (nothing happens at its origin, the vertex of its left end's
hyperbola); its key event is where an end starts to change velocity first in the lab. Whether that
is first in another frame depends on the frame (the two starts are spacelike apart): the words say
which, from the events of the frame shown.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, replace

import numpy as np

import rigidrel_core as rr

from .vocabulary import (
    LIGHT_COLOR,
    Area,
    Chart,
    FloatArray,
    Item,
    Label,
    Points,
    Segments,
    Style,
    event_label,
    rgba,
)

#: The legend group of every item of this layer (toggled together).
GROUP = "signals"


@dataclass(frozen=True)
class SignalLeg:
    """A straight light ray from ``source`` to ``arrival``, events ``(t, x)`` of one frame."""

    source: tuple[float, float]
    arrival: tuple[float, float]
    name: str
    """The arrival's name in the paper's style: ``"S_1"`` (rod 1's far end), ``"R_1"`` (back at its near end)."""
    meaning: str = ""
    """The arrival in words: ``"light from the contact reaches the right end of the Born-rigid pole"``."""

    def position(self, t: float) -> float | None:
        """Where the pulse is at time ``t`` of the frame, or ``None`` before it leaves or after it arrives."""
        (t0, x0), (t1, x1) = self.source, self.arrival
        if not t0 <= t <= t1:
            return None
        return x0 + (t - t0) * (1.0 if x1 >= x0 else -1.0)


@dataclass(frozen=True)
class Signals:
    """The signal layer of one scene in one frame."""

    key_event: tuple[float, float]
    key_phrase: str
    """How a sentence names the key event: "the contact", "the start of the change", ..."""
    legs: tuple[SignalLeg, ...]
    key_definition: str = ""
    """What the key event is, in words: ``"the start: the event at the origin of every frame, where the
    rear ship's left end starts accelerating"``."""

    def pulse_positions(self, t: float) -> FloatArray:
        """The x of every pulse in flight at time ``t`` (shape ``(n,)``, possibly empty)."""
        return np.array(self.pulses_at(t), dtype=np.float64)

    def pulses_at(self, t: float) -> list[float]:
        """:meth:`pulse_positions` as plain floats (every playback frame: no numpy per call)."""
        return [x for leg in self.legs if (x := leg.position(t)) is not None]

    def seen_from(self, frame: rr.Frame) -> Signals:
        """These signals, given as events of the lab, as ``frame`` sees them: every event boosted by
        the core (``frame @ events``, exact on the light cone), so each ray stays at 45 degrees."""

        def boost(event: tuple[float, float]) -> tuple[float, float]:
            t, x = frame @ np.array(event)
            return float(t), float(x)

        legs = tuple(replace(leg, source=boost(leg.source), arrival=boost(leg.arrival)) for leg in self.legs)
        return replace(self, key_event=boost(self.key_event), legs=legs)

    @property
    def far_arrivals(self) -> tuple[float, ...]:
        """The x of each event ``S``: where the first light from the key event reaches a far end."""
        return tuple(leg.arrival[1] for leg in self.legs if leg.name.startswith("S"))


def _key_event(scene: rr.Scene) -> tuple[str, str, tuple[float, float]]:
    """The key event as a source name for the core, its phrase, and its lab ``(t, x)``."""
    cause = scene.cause()
    if cause is not None:
        return cause
    events = scene.events_in(frame=rr.LAB)
    starts = [s.name for s in scene.event_specs if s.phase == "start"]
    first = min(starts, key=lambda name: events[name][0])
    return first, "the start of the change", events[first]


def _the(name: str) -> str:
    return name if name.startswith("rod ") else f"the {name}"


def end_words(scene: rr.Scene, rod: int, fraction: float) -> str:
    """``"the right end"`` of a one-rod scene, ``"the right end of the rear ship"`` of any other: the
    words the core's causal verdicts name an end with."""
    side = "left" if fraction == 0.0 else "right"
    return f"the {side} end" + (f" of {_the(scene.rods[rod].name)}" if scene.n_rods > 1 else "")


def _spec(scene: rr.Scene, name: str) -> rr.EventSpec:
    return next(s for s in scene.event_specs if s.name == name)


def _side(end: int) -> str:
    return "left" if end == 0 else "right"


def _letter(scene: rr.Scene, end: int) -> str:
    """The paper's name of a one-rod change's end: B is behind, seen along the push (it changes harder)."""
    return "B" if (end == 0) == (scene.rods[0].motion.sign == 1) else "F"


def time_order(a: tuple[float, float], b: tuple[float, float], frame: rr.Frame) -> int:
    """The sign of ``t'_b - t'_a`` in ``frame`` for two lab events: 1 when ``a`` comes first there,
    0 when they are simultaneous there (to rounding of the terms), -1 when ``b`` comes first."""
    dt, dx = b[0] - a[0], b[1] - a[1]
    d = rr.shown(dt - frame.beta * dx, abs(dt) + abs(frame.beta * dx))
    return (d > 0.0) - (d < 0.0)


def _first_start_words(scene: rr.Scene, first: str, frame: rr.Frame) -> str:
    """Which end of a general velocity change starts first: in the lab (where ``first`` does), in the
    rod's frame before (together) and in ``frame``, from the events of each."""
    lab = scene.events_in(frame=rr.LAB)
    other = next(s.name for s in scene.event_specs if s.phase == "start" and s.name != first)
    other_side = _side(_spec(scene, other).end)
    words = "in the lab it is the first thing that happens to the rod"
    before = scene.frames.get("rod before")
    if before is not None and time_order(lab[first], lab[other], before) == 0:
        words += "; in the frame 'rod before' both ends start together"
    if not frame.same_velocity(rr.LAB) and (before is None or not frame.same_velocity(before)):
        order = time_order(lab[first], lab[other], frame)
        here = rr.frame_in_words(frame)
        if order > 0:
            words += f"; in {here} it is first too"
        elif order == 0:
            words += f"; in {here} both ends start together"
        else:
            words += f"; in {here} the {other_side} end starts first"
    return words


def key_definition(scene: rr.Scene, frame: rr.Frame = rr.LAB) -> str:
    """What the key event is (:func:`_key_event`), in words, for the reader of "light from the start";
    an order of events it names is the lab's and says so, or that of ``frame``, found from its events."""
    source, phrase, _ = _key_event(scene)
    first = _the(scene.rods[0].name)
    walls = [o.name for o in scene.objects if o.role is rr.ObjectRole.BARRIER]
    origin = "the event at the origin of every frame"
    if scene.kick:
        spec = _spec(scene, scene.kick)
        stop = next(s.name for s in scene.event_specs if (s.rod, s.end, s.phase) == (spec.rod, spec.end, "stop"))
        side, letter = _side(spec.end), _letter(scene, spec.end)
        return (
            f"{phrase}: the event {scene.kick} (= {stop}), where {first}'s {side} end ({letter}) is kicked: it "
            "jumps to its final velocity at once"
        )
    if scene.cause() is None:
        spec = _spec(scene, source)
        side, letter = _side(spec.end), _letter(scene, spec.end)
        where = f"the event {source}, where {first}'s {side} end ({letter}) starts changing velocity"
        return f"{phrase}: {where}; {_first_start_words(scene, source, frame)}"
    if scene.origin_event is rr.OriginEvent.START:
        what = f"where {first}'s left end starts accelerating"
    elif scene.origin_event is rr.OriginEvent.KICK:
        what = f"where {first}'s left end is kicked: it jumps to its final velocity at once"
    elif scene.origin_event is rr.OriginEvent.REST:
        lead = "leading" if scene.rods[0].motion.velocity_initial.value < 0.0 else "trailing"
        what = f"where {first}'s left end ({_letter(scene, 0)}, {lead} in the lab) comes to rest in the lab"
    elif walls:
        noun = "pole" if all(r.name.endswith("pole") for r in scene.rods) else "rod"
        ends = f"the left end of each {noun}" if scene.n_rods > 1 else f"{first}'s left end"
        what = f"where {ends} hits the {walls[0]}"
    else:
        what = "where the rods' facing ends touch"
    return f"{phrase}: {origin}, {what}"


def far_fractions(scene: rr.Scene, key_lab: tuple[float, float]) -> tuple[tuple[float, float], ...]:
    """Per rod, ``(far, near)`` fractions: the end farther from the key event at its lab time, and the other."""
    x = scene.positions(np.array([key_lab[0]]))[:, :, 0]  # (rods, ends)
    out = []
    for left, right in x:
        far_is_right = abs(right - key_lab[1]) >= abs(left - key_lab[1])
        out.append((1.0, 0.0) if far_is_right else (0.0, 1.0))
    return tuple(out)


def signals_in(scene: rr.Scene, frame: rr.Frame) -> Signals:
    """The key event's light signal to each rod's far end, and from there back to its near end, in ``frame``.

    A leg the light never completes (the point outruns it for ever) is left out.
    """
    source, phrase, key_lab = _key_event(scene)
    key_here = scene.source_event(source, frame=frame)
    legs: list[SignalLeg] = []
    for rod, (far, near) in enumerate(far_fractions(scene, key_lab)):
        suffix = f"_{rod + 1}" if scene.n_rods > 1 else ""
        arrival = scene.signal_arrival(source, rod, far, frame=frame)
        if arrival is None:
            continue
        legs.append(
            SignalLeg(key_here, arrival, f"S{suffix}", f"light from {phrase} reaches {end_words(scene, rod, far)}")
        )
        back = scene.signal_arrival(arrival, rod, near, frame=frame)
        if back is not None:
            legs.append(SignalLeg(arrival, back, f"R{suffix}", f"its echo is back at {end_words(scene, rod, near)}"))
    return Signals(key_here, phrase, tuple(legs), key_definition(scene, frame))


#: The window grows to show the light reach the far ends only if that adds at most this many windows.
SIGNAL_REACH = 1.5


def signals_window_end(end: float, start: float, signals: Sequence[Signals] | None) -> float:
    """The window's end, late enough for the light from the key event to reach every far end (the
    arrivals ``S`` in each frame of ``signals``), unless that would squeeze the diagrams: then the
    rays run off the top and the readout gives the arrival in numbers."""
    if signals is None:
        return end
    arrivals = [leg.arrival[0] for sig in signals for leg in sig.legs if leg.name.startswith("S")]
    late = max(arrivals, default=end)
    if late <= end or late - end > SIGNAL_REACH * (end - start):
        return end
    return late + 0.05 * (late - start)


def _clip(poly: FloatArray, x_range: tuple[float, float], y_range: tuple[float, float]) -> FloatArray:
    """A convex polygon ``(n, 2)`` clipped to a rectangle (Sutherland-Hodgman); ``(0, 2)`` if nothing is left."""
    for axis, bound, keep_above in (
        (0, x_range[0], True),
        (0, x_range[1], False),
        (1, y_range[0], True),
        (1, y_range[1], False),
    ):
        if poly.shape[0] == 0:
            break
        inside = poly[:, axis] >= bound if keep_above else poly[:, axis] <= bound
        out: list[FloatArray] = []
        for i in range(poly.shape[0]):
            a, b = poly[i - 1], poly[i]
            ina, inb = bool(inside[i - 1]), bool(inside[i])
            if ina != inb:
                s = (bound - a[axis]) / (b[axis] - a[axis])
                out.append(a + s * (b - a))
            if inb:
                out.append(b)
        poly = np.array(out, dtype=np.float64).reshape(-1, 2)
    return poly


def future_cone(key: tuple[float, float], x_range: tuple[float, float], t_range: tuple[float, float]) -> FloatArray:
    """The key event's future light cone ``t - t_k >= |x - x_k|`` inside the chart, as a polygon of ``(x, t)``."""
    tk, xk = key
    reach = (x_range[1] - x_range[0]) + (t_range[1] - t_range[0]) + abs(tk) + abs(xk)
    tri = np.array([[xk, tk], [xk + reach, tk + reach], [xk - reach, tk + reach]])
    return _clip(tri, x_range, t_range)


def signal_items(signals: Signals, x_range: tuple[float, float], t_range: tuple[float, float]) -> tuple[Item, ...]:
    """Diagram items: the shaded future cone of the key event, the 45-degree rays, the arrivals named."""
    items: list[Item] = []
    cone = future_cone(signals.key_event, x_range, t_range)
    if cone.shape[0] >= 3:
        items.append(
            Area(
                cone[:, 0],
                cone[:, 1],
                Style(rgba(LIGHT_COLOR, 0.13), 0.0, name=f"future of {signals.key_phrase}", group=GROUP),
            )
        )
    if signals.legs:
        src = np.array([leg.source for leg in signals.legs])
        arr = np.array([leg.arrival for leg in signals.legs])
        ray = Style(LIGHT_COLOR, 3.0, name=f"light from {signals.key_phrase}, and back", group=GROUP)
        items.append(Segments(src[:, 1], src[:, 0], arr[:, 1], arr[:, 0], ray))
        items.append(Points(arr[:, 1], arr[:, 0], Style(LIGHT_COLOR, group=GROUP), size=9, symbol="diamond"))
        for leg in signals.legs:
            items.append(Label(leg.arrival[1], leg.arrival[0], event_label(leg.name), Style(LIGHT_COLOR, group=GROUP)))
    return tuple(items)


def verdict_lines(scene: rr.Scene, frame: rr.Frame = rr.LAB) -> tuple[str, ...]:
    """The core's causal verdicts in words, one per rod end that changes away from the key event, each
    event named or given as ``(t, x)`` of ``frame`` and labelled so (``"(lab t, x) = ..."`` in the lab);
    for a change without a cause (a general velocity change), why it has none."""
    verdicts = scene.causal_verdicts(frame=frame)
    if verdicts:
        return tuple(v.text[:1].upper() + v.text[1:] for v in verdicts)
    if scene.cause() is not None:
        return ()
    motion = scene.rods[0].motion
    key = _spec(scene, _key_event(scene)[0])
    if motion.velocity_initial.value * motion.velocity_final.value < 0.0:
        origin = (
            "The scene's origin is where the left end, midway through its change, is momentarily at rest in "
            "the lab (the vertex of its hyperbola): nothing happens there that could cause the change."
        )
    else:
        origin = (
            "Nothing happens at the scene's origin: it is where the left end would be at rest in the lab if "
            "its hyperbola were continued (its vertex), and the rod never passes through it."
        )
    return (
        f"{origin} A general velocity change has no single cause: its ends start changing velocity at "
        f"spacelike-separated events. The light shown leaves where the {_side(key.end)} end starts.",
    )


def with_signals(chart: Chart, scene: rr.Scene, frame: rr.Frame) -> Chart:
    """A Minkowski diagram of ``scene`` in ``frame`` with the signal layer drawn over it (within its ranges)."""
    layer = signal_items(signals_in(scene, frame), chart.x_range, chart.y_range)
    return replace(chart, items=(*chart.items, *layer))


def event_cone_items(
    scene: rr.Scene, name: str, frame: rr.Frame, x_range: tuple[float, float], t_range: tuple[float, float]
) -> tuple[Item, ...]:
    """The light cone of one named event (or the origin event's name) in ``frame``: its future and past
    shaded, its four light rays, clipped to the chart. The event comes from the core (exact). Its
    rays are dotted, and name it in the legend ("light cone of T₁"): the origin's cone is dashed,
    the signals from the key event solid, and its future a fill of the same gold, whose swatch
    this cone's fill would match."""
    tk, xk = scene.source_event(name, frame=frame)
    reach = (x_range[1] - x_range[0]) + (t_range[1] - t_range[0]) + abs(tk) + abs(xk)
    items: list[Item] = []
    label = event_label(name) if name != scene.origin_event.value else scene.origin_event.phrase
    for sign in (1.0, -1.0):  # future, past
        tri = np.array([[xk, tk], [xk + reach, tk + sign * reach], [xk - reach, tk + sign * reach]])
        poly = _clip(tri, x_range, t_range)
        if poly.shape[0] >= 3:
            style = Style(rgba(LIGHT_COLOR, 0.10 if sign > 0 else 0.06), 0.0, group="event cone")
            items.append(Area(poly[:, 0], poly[:, 1], style))
    rays = Style(LIGHT_COLOR, 2.5, dash="dot", name=f"light cone of {label}", group="event cone")
    items.append(
        Segments(
            np.array([xk - reach, xk + reach]),
            np.array([tk - reach, tk - reach]),
            np.array([xk + reach, xk - reach]),
            np.array([tk + reach, tk + reach]),
            rays,
        )
    )
    return tuple(items)
