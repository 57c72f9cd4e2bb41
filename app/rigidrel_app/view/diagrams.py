"""Minkowski diagrams and equal-time-length charts, as drawing-vocabulary charts.

Pure functions of a scene, a frame, a time window and a panel size; every coordinate
comes from :mod:`rigidrel_core` (positions, events, boosts). Axes: x horizontal, time up,
one unit of each equally long, so light moves at 45 degrees.
"""

from __future__ import annotations

import functools
from collections.abc import Sequence
from dataclasses import dataclass, replace

import numpy as np

import rigidrel_core as rr

from .layers import DEFAULT_LAYERS, Layer
from .layout import MIN_TEXT_PX
from .objects import object_style
from .placement import place_labels
from .sampling import ADAPTIVE, Sampled, Sampler
from .signals import Signals, signal_items, signals_in, signals_window_end
from .vocabulary import (
    FRAME_COLOR,
    INK,
    LIGHT_COLOR,
    ROD_COLORS,
    Area,
    Chart,
    Dash,
    FloatArray,
    Item,
    Label,
    Points,
    Polyline,
    Segments,
    Style,
    event_label,
    rgba,
)

#: Material points drawn in the diagrams (fractions of the rest length).
DIAGRAM_FRACTIONS = np.array([0.0, 0.25, 0.5, 0.75, 1.0])
#: Font size of event labels (CSS pixels): legible from the back of a hall.
EVENT_LABEL_PX = 16.0
#: Legend name and marker of the rods' ends at the current instant (not the events' black dots).
ENDS_NOW_NAME = "rod ends now"
ENDS_NOW_SYMBOL = "diamond-open"
#: A tie's event on its curve in the length panel (the string's break), named in the legend.
TIE_EVENT_SYMBOL = "square"
LENGTH_NOW_NAME = "lengths now"
#: The length plot's top, per the largest length: room above the rest length for event labels.
LENGTH_HEADROOM = 1.3
#: The length panel's time axis: each curve is drawn against its own frame's time (its legend says
#: which, "(t)" or "(t′)").
LENGTH_TIME_TITLE = "lab t, or t′ of the frame chosen"


@dataclass(frozen=True)
class View:
    """Which frame a diagram is drawn in, and which other frame it shows for comparison."""

    frame: rr.Frame
    other: rr.Frame
    prime: str
    """Axis names of this frame: "" for the lab (t, x), "'" for the chosen frame (t', x')."""
    other_prime: str

    @functools.cached_property
    def from_other(self) -> rr.Frame:
        """This frame seen from the other one (composed once, exactly: the now-lines use it every update)."""
        return self.frame @ self.other.inverse()

    @staticmethod
    def alone(frame: rr.Frame) -> View:
        """A diagram of ``frame`` compared with the lab (or with nothing, if it is the lab)."""
        if frame.same_velocity(rr.LAB):
            return View(frame, frame, "", "")
        return View(frame, rr.LAB, "'", "")

    @property
    def compares(self) -> bool:
        """Whether the other frame differs from this one (else no second axes or now-line)."""
        return not self.frame.same_velocity(self.other)


def typeset_prime(prime: str) -> str:
    """A :class:`View`'s ASCII prime as printed on axes and labels: ``"'"`` -> ``"′"``."""
    return prime.replace("'", "′")


def frame_title(frame: rr.Frame) -> str:
    """``"lab"``, or the frame's name (``"custom"`` for an unnamed one) and its velocity; one at rest
    in the lab says it is the lab: ``"custom (β = 0: the lab)"``."""
    if frame.same_velocity(rr.LAB):
        return "lab" if frame.name in (None, "lab") else f"{frame.name} (β = 0: the lab)"
    return f"{frame.name or 'custom'} (β = {frame.beta:.4g})"


def _to_view(view: View, events_other: FloatArray) -> FloatArray:
    """Events of the other frame ``(..., 2)`` into this view's frame: one boost by the exactly
    composed relative frame (no round trip through the lab)."""
    return view.from_other @ events_other


def window_x_range(scene: rr.Scene, frames: tuple[rr.Frame, ...], t_range: tuple[float, float]) -> tuple[float, float]:
    """The x interval the rods and the scene's objects sweep over the window in any of the frames (for
    shared scales)."""
    t = np.linspace(t_range[0], t_range[1], 97)
    xs = [scene.positions(t, frame=f) for f in frames]
    xs += [o.positions(t, frame=f) for o in scene.objects for f in frames]
    lo = min(float(x.min()) for x in xs)
    hi = max(float(x.max()) for x in xs)
    return lo, hi


def equal_scale_ranges(
    x: tuple[float, float], t: tuple[float, float], area: tuple[float, float]
) -> tuple[tuple[float, float], tuple[float, float]]:
    """Axis ranges holding ``x`` and ``t`` (padded) with one unit as long on both axes of a plot
    area of ``area`` pixels (width, height): light at 45 degrees."""
    xc, tc = 0.5 * (x[0] + x[1]), 0.5 * (t[0] + t[1])
    half_x = 0.55 * (x[1] - x[0]) + 0.05
    half_t = 0.5 * (t[1] - t[0])
    ratio = area[0] / area[1]  # pixels wide per pixel high
    if not half_t > 0.0 or half_x / half_t > ratio:  # a window of no width (a degenerate scene): from x
        half_t = half_x / ratio
    else:
        half_x = half_t * ratio
    return (xc - half_x, xc + half_x), (tc - half_t, tc + half_t)


def minkowski_in_frame(
    scene: rr.Scene,
    frame: rr.Frame,
    area_px: tuple[float, float],
    overlay: rr.Scene | None = None,
    density: float = 1.0,
    layers: frozenset[Layer] = DEFAULT_LAYERS,
) -> Chart:
    """The diagram of one frame on its own (notebooks, exports): the frame's event window at equal
    scales in a plot area of ``area_px`` CSS pixels, compared with the lab; curves sampled to half
    a pixel at ``density`` device pixels per CSS pixel. With the light-signal layer in ``layers``, the
    signals are drawn and the window reaches their arrivals, as the app's (so an arrival a caption
    names is on the page)."""
    window = scene.time_window(frame=frame)
    signals = signals_in(scene, frame) if Layer.SIGNALS in layers else None
    if signals is not None:
        window = (window[0], signals_window_end(window[1], window[0], (signals,)))
    x_range, t_range = equal_scale_ranges(window_x_range(scene, (frame,), window), window, area_px)
    label = overlay_label(scene)
    return minkowski_static(
        scene, View.alone(frame), t_range, x_range, density * area_px[0], overlay, ADAPTIVE, label, area_px,
        layers, signals,
    )  # fmt: skip


def overlay_label(scene: rr.Scene) -> str:
    """The legend name of the scene's comparison overlay (its description's)."""
    overlay = rr.describe(scene).overlay
    return overlay.label if overlay is not None else "comparison"


def minkowski_static(
    scene: rr.Scene,
    view: View,
    t_range: tuple[float, float],
    x_range: tuple[float, float],
    panel_px: float,
    overlay: rr.Scene | None = None,
    sampler: Sampler = ADAPTIVE,
    overlay_label: str = "comparison",
    area_px: tuple[float, float] | None = None,
    layers: frozenset[Layer] = DEFAULT_LAYERS,
    signals: Signals | None = None,
    label_px: float = EVENT_LABEL_PX,
) -> Chart:
    """Everything in a Minkowski diagram that does not move with playback.

    ``overlay`` is a second scene drawn dashed (Fig. 1's impulsive curve), named ``overlay_label``.
    The event labels are placed (:func:`~rigidrel_app.view.placement.place_labels`) for a plot
    area of ``area_px`` CSS pixels; ``None``: ``panel_px`` wide at equal scales. ``layers`` says
    what is drawn (:class:`~.layers.Layer`): the origin's light cone, the other frame's axes, the
    world tubes and end worldlines, the interior worldlines. ``signals``: the light signals of
    :mod:`.signals` in this diagram's frame, drawn if given (their arrivals named and placed with
    the events' labels, so none overprints). ``label_px``: the size the labels are drawn at (CSS px),
    which their placement reserves.
    """
    frame = view.frame
    px_per_x = panel_px / max(x_range[1] - x_range[0], 1e-300)
    items: list[Item] = []
    t0, t1 = t_range
    # light cone of the origin event (start / kick / contact): x = +-t
    span = max(abs(t0), abs(t1), abs(x_range[0]), abs(x_range[1])) * 2.0
    signal_layer: tuple[Item, ...] = ()
    if signals is not None:  # the key event's future, shaded under everything else
        signal_layer = signal_items(signals, x_range, t_range)
        items.extend(i for i in signal_layer if isinstance(i, Area))
    if Layer.LIGHT_CONE in layers:
        cone = Style(LIGHT_COLOR, 1.5, "dash", name="light cone of the origin", group="cone")
        items.append(Polyline(np.array([-span, span]), np.array([-span, span]), cone))
        items.append(
            Polyline(np.array([-span, span]), np.array([span, -span]), Style(LIGHT_COLOR, 1.5, "dash", group="cone"))
        )
    # the other frame's time and space axes (x_o = 0 and t_o = 0), through the origin
    other = typeset_prime(view.other_prime)
    if view.compares and Layer.OTHER_AXES in layers:
        ax = Style(
            FRAME_COLOR,
            1.5,
            "dashdot",
            name=f"t{other}, x{other} axes of {frame_title(view.other)}",
            group="axes",
        )
        e = np.array([[[-span, 0.0], [span, 0.0]], [[0.0, -span], [0.0, span]]])
        both = _to_view(view, e)
        items.append(Polyline(both[0, :, 1], both[0, :, 0], ax))
        items.append(Polyline(both[1, :, 1], both[1, :, 0], Style(FRAME_COLOR, 1.5, "dashdot", group="axes")))
        # name the other frame's time axis where it leaves the top of the window
        t_label = t0 + 0.92 * (t1 - t0)
        x_label = float(np.interp(t_label, both[0, :, 0], both[0, :, 1]))
        items.append(Label(x_label, t_label, f"t{other}", Style(FRAME_COLOR), size=label_px, movable=True))
    # the scene's objects that are not rods, by their roles' styles (a wall, a door: straight worldlines)
    items.extend(object_worldlines(scene, frame, (t0, t1), px_per_x, sampler))
    # world tubes and worldlines
    tube, interior = Layer.WORLD_TUBE in layers, Layer.INTERIOR_LINES in layers
    fractions = DIAGRAM_FRACTIONS if interior else DIAGRAM_FRACTIONS[[0, -1]]
    lines = sampler.worldlines(scene, frame, fractions, t_range, px_per_x) if tube or interior else []
    for r, rod in enumerate(scene.rods if lines else ()):
        color = ROD_COLORS[r % len(ROD_COLORS)]
        items += world_tube(
            lines[r],
            fill=Style(rgba(color, 0.16), 0.0, group=rod.name) if tube else None,
            edge=Style(color, 2.5, name=rod.name, group=rod.name) if tube else None,
            # the legend names the rod by what is drawn
            interior=Style(color, 1.0, opacity=0.7, name=None if tube else rod.name, group=rod.name),
        )
    if overlay is not None:  # e.g. Fig. 1's dashed curve: the impulsive start to the same V
        for r, (left, right) in enumerate(sampler.worldlines(overlay, frame, np.array([0.0, 1.0]), t_range, px_per_x)):
            items.append(Polyline(left.x, left.t, Style(INK, 1.5, "dash", group="overlay")))
            name = overlay_label if r == 0 else None
            items.append(Polyline(right.x, right.t, Style(INK, 1.5, "dash", name=name, group="overlay")))
    # named events, in the paper's notation
    events = scene.events_in(frame=frame)
    if events:
        et = np.array([e[0] for e in events.values()])
        ex = np.array([e[1] for e in events.values()])
        items.append(Points(ex, et, Style(INK, name="events", group="events"), size=7))
        for name, (t, x) in events.items():
            items.append(Label(x, t, event_label(name), Style(INK), size=label_px, movable=True))
    for it in signal_layer:  # the rays and arrivals over the worldlines; their names placed with the events'
        if isinstance(it, Label):
            items.append(replace(it, size=label_px, movable=True))
        elif not isinstance(it, Area):
            items.append(it)
    chart = Chart(
        items=tuple(items),
        x_title=f"x{typeset_prime(view.prime)}",
        y_title=f"t{typeset_prime(view.prime)}",
        x_range=x_range,
        y_range=t_range,
        title=f"Minkowski diagram, {frame_title(frame)} frame",
        equal_aspect=True,
    )
    if area_px is None:
        area_px = (panel_px, panel_px * (t1 - t0) / max(x_range[1] - x_range[0], 1e-300))
    return place_labels(chart, area_px, MIN_TEXT_PX)


def object_worldlines(
    scene: rr.Scene,
    frame: rr.Frame,
    t_range: tuple[float, float],
    px_per_x: float,
    sampler: Sampler = ADAPTIVE,
    print_style: bool = False,
) -> list[Item]:
    """The worldlines of ``scene``'s objects over ``t_range`` of ``frame``, each in its role's style
    (:data:`.objects.OBJECT_STYLES`): on the diagrams, named by the object, or with ``print_style`` in
    print, unnamed. Those of a role drawn on no diagram (a tie, whose ends are the rods') are left out.
    An inertial worldline is its two ends; one that follows a rod is sampled as that rod's worldline
    is (``sampler``, to its tolerance at ``px_per_x`` px per unit of x)."""
    items: list[Item] = []
    tt = np.array(t_range)
    for obj in scene.objects:
        style = object_style(obj).print_style if print_style else object_style(obj).diagram
        if style is None:
            continue
        for k, w in enumerate(obj.worldlines):
            name = obj.name if k == 0 and not print_style else None
            if isinstance(w, rr.MaterialWorldline):
                line = sampler.worldlines(scene, frame, np.array([w.fraction]), t_range, px_per_x)[w.rod][0]
                items.append(Polyline(line.x, line.t, replace(style, name=name)))
            else:
                items.append(Polyline(w.positions(tt, frame=frame), tt, replace(style, name=name)))
    return items


def world_tube(
    worldlines: Sequence[Sampled], *, fill: Style | None, edge: Style | None, interior: Style | None = None
) -> list[Item]:
    """One rod's world tube from its sampled worldlines (left end first, right end last): the region
    between its ends filled in ``fill``, its interior worldlines in ``interior`` (the first of them
    named by its style, the others not), then its two ends in ``edge`` (the left one named, the right
    one not); each part left out where its style is ``None``. The diagrams, the paper's figures and
    the paradoxes' draw every tube with it."""
    left, right = worldlines[0], worldlines[-1]
    items: list[Item] = []
    if fill is not None:
        items.append(Area(np.concatenate([left.x, right.x[::-1]]), np.concatenate([left.t, right.t[::-1]]), fill))
    if interior is not None:
        for k, w in enumerate(worldlines[1:-1]):
            items.append(Polyline(w.x, w.t, interior if k == 0 else replace(interior, name=None)))
    if edge is not None:
        items.append(Polyline(left.x, left.t, edge))
        items.append(Polyline(right.x, right.t, replace(edge, name=None)))
    return items


def minkowski_now(view: View, now: float, span: float, ends: FloatArray) -> tuple[Item, ...]:
    """The moving parts: this frame's 'now' line, the other frame's, the rods' current places.

    ``ends``: the rods' end positions at ``now`` in this view's frame (from the core), any shape.
    They are open diamonds named ``rod ends now`` in the legend: the black dots are the named events.
    """
    items: list[Item] = [
        Polyline(
            np.array([-span, span]),
            np.array([now, now]),
            Style(INK, 1.2, name=f"now: t{typeset_prime(view.prime)} = {now:.3g}"),
        ),
    ]
    if view.compares:
        # the other frame's line of simultaneity t_o = now, drawn in this frame
        e = _to_view(view, np.array([[now, -span], [now, span]]))
        items.append(
            Polyline(
                e[:, 1],
                e[:, 0],
                Style(FRAME_COLOR, 1.2, "dot", name=f"now: t{typeset_prime(view.other_prime)} = {now:.3g}"),
            )
        )
    now_style = Style(INK, name=ENDS_NOW_NAME, group="ends-now")
    items.append(Points(ends.ravel(), np.full(ends.size, now), now_style, size=11, symbol=ENDS_NOW_SYMBOL))
    return tuple(items)


def length_static(
    scene: rr.Scene,
    lab: rr.Frame,
    chosen: rr.Frame,
    t_range: tuple[float, float],
    panel_px: tuple[float, float],
    sampler: Sampler = ADAPTIVE,
    comoving: tuple[FloatArray, FloatArray, str] | None = None,
    label_px: float = EVENT_LABEL_PX,
) -> Chart:
    """Equal-time length of each rod against time, in the lab and in the chosen frame (Fig. 2), and
    of each tie (Bell's string: its ends' separation, the gap between the ships), with its event
    (the string's break) marked on it.

    ``panel_px`` is the plot area (width, height) in pixels; curves are sampled to half a pixel.
    ``comoving``: ``(t, lengths, name)``, the lengths ``(rods, n)`` in a riding point's comoving
    frames at lab times ``t`` (:class:`.comoving.RideTrack`, from the core), drawn dashed instead of
    the chosen frame's.
    """
    items: list[Item] = []
    frames: list[tuple[rr.Frame, str, Dash]] = [(lab, "", "solid")]
    if not chosen.same_velocity(lab) and comoving is None:
        frames.append((chosen, "'", "dash"))
    # the largest length over the window: the rest lengths and the contracted ones at the ends
    probe = np.array([t_range[0], t_range[1]])
    top = max(
        max(r.motion.length for r in scene.rods), *(float(scene.lengths(probe, frame=f).max()) for f, _, _ in frames)
    )
    ties = [o for o in scene.objects if object_style(o).length_panel is not None]
    grid = np.linspace(t_range[0], t_range[1], 17)  # a tie's gap may peak inside the window
    for tie in ties:
        top = max(top, *(float(np.max(np.diff(tie.positions(grid, frame=f), axis=0))) for f, _, _ in frames))
    if comoving is not None:
        top = max(top, float(np.max(comoving[1])))
        for r, rod in enumerate(scene.rods):
            color = ROD_COLORS[r % len(ROD_COLORS)]
            style = Style(color, 2.0, "dash", name=f"{rod.name}, {comoving[2]}")
            items.append(Polyline(comoving[0], comoving[1][r], style))
    px_per_length = panel_px[1] / (LENGTH_HEADROOM * top)
    half_px_t, half_px_length = 0.5 * (t_range[1] - t_range[0]) / panel_px[0], 0.5 / px_per_length
    for frame, prime, dash in frames:
        short = "lab" if not prime else (frame.name or "custom")  # the chart's title gives β
        curves = sampler.lengths(scene, frame, t_range, px_per_length)
        for r, rod in enumerate(scene.rods):
            color = ROD_COLORS[r % len(ROD_COLORS)]
            name = f"{rod.name}, {short} (t{typeset_prime(prime)})"
            items.append(Polyline(curves[r].t, curves[r].x, Style(color, 2.5 if not prime else 2.0, dash, name=name)))
        # the named events on the curves; events on one spot (within half a pixel: Bell's two ships
        # have one length curve in the lab) share one dot and one label
        marks: list[tuple[float, float, list[str]]] = []
        breaks: list[tuple[float, float, str]] = []  # a tie's event on its curve
        for tie in ties:
            look = object_style(tie).length_panel
            assert look is not None
            gap = sampler.tie_span(scene, tie, frame, t_range, px_per_length)
            top = max(top, float(np.max(gap.x)))
            name = f"{tie.name}, {short} (t{typeset_prime(prime)})"
            items.append(Polyline(gap.t, gap.x, replace(look, dash=dash, name=name)))
            event = tie.event_in(frame=frame)
            if tie.event is not None and event is not None and t_range[0] <= event[0] <= t_range[1]:
                at = tie.positions([event[0]], frame=frame)[:, 0]
                breaks.append((event[0], float(at[1] - at[0]), f"{tie.name}: {tie.event.name}"))
        for name, (te, _) in scene.events_in(frame=frame).items():
            if t_range[0] <= te <= t_range[1]:
                le = float(scene.lengths(np.array([te]), frame=frame)[scene.event_rod(name), 0])
                same = [m for m in marks if abs(m[0] - te) <= half_px_t and abs(m[1] - le) <= half_px_length]
                if same:
                    same[0][2].append(name)
                else:
                    marks.append((te, le, [name]))
        for te, le, names in marks:
            items.append(Points(np.array([te]), np.array([le]), Style(INK), size=7))
            text = ", ".join(event_label(name) for name in names) + (" (t′)" if prime else "")
            items.append(Label(te, le, text, Style(INK), size=label_px, movable=True))
        for te, le, name in breaks:  # named in the legend, not by a label: the panel is crowded
            items.append(Points(np.array([te]), np.array([le]), Style(INK, name=name), size=9, symbol=TIE_EVENT_SYMBOL))
    chart = Chart(
        items=tuple(items),
        x_title=LENGTH_TIME_TITLE,
        y_title="equal-time length",
        x_range=t_range,
        y_range=(0.0, top * LENGTH_HEADROOM if top > 0 else 1.0),
        title="Equal-time length (Fig. 2)",
    )
    return place_labels(chart, panel_px, MIN_TEXT_PX)


def length_now(now: float, y_top: float, lengths: FloatArray) -> tuple[Item, ...]:
    """The current time on the length plot, and each rod's length there in each frame.

    ``lengths``: the rods' equal-time lengths at ``now`` (from the core), any shape. Open diamonds,
    as the rods' current places on the Minkowski diagrams: the black dots are the named events.
    """
    return (
        Segments(np.array([now]), np.array([0.0]), np.array([now]), np.array([y_top]), Style(INK, 1.2)),
        Points(
            np.full(lengths.size, now),
            lengths.ravel(),
            Style(INK, name=LENGTH_NOW_NAME, group="ends-now"),
            size=11,
            symbol=ENDS_NOW_SYMBOL,
        ),
    )
