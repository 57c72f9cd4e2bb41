"""What one scene in one frame looks like: everything the app, the recordings and the exports draw.

Pure functions over :mod:`rigidrel_core` and the drawing vocabulary; no viser or plotly
here, so the exporters use exactly what the app shows.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, replace

import numpy as np

import rigidrel_core as rr

from . import camera as cam
from .canvas import LegendEntry, legend_entries
from .diagrams import (
    View,
    equal_scale_ranges,
    frame_title,
    length_now,
    length_static,
    minkowski_now,
    minkowski_static,
    overlay_label,
    window_x_range,
)
from .lanes import (
    LaneGeometry,
    LanePicture,
    LaneState,
    lane_geometry,
    lane_picture,
    lane_state,
    lane_static,
    pulse_segments,
    steady_width,
)
from .layers import Layer
from .layout import CanvasLayout
from .sampling import ADAPTIVE, Sampler
from .signals import Signals, signals_in, verdict_lines
from .state import Resolved, format_value
from .vocabulary import INK, ROD_COLORS, Chart, FloatArray, Item, Label, Points, Polyline, Segments, Style, signed

#: Lane heights (z, in lane units): the lab on top, the chosen frame below.
LAB_Z = 0.55
FRAME_Z = -0.55
LANE_Z = (LAB_Z, FRAME_Z)
#: Each lane's ruler is named by its frame's coordinate: the lab's x, the chosen frame's x′.
RULER_NAMES = ("x", "x′")
#: The clock rule, in the readout (docs/conventions.md says the same).
CLOCK_RULE = "every clock reads 0 where its point starts changing velocity"
#: The window plays in this many seconds at speed 1.
PLAY_SECONDS = 8.0
#: The playback clock's box in the control panel follows playback at this rate (the canvas, lanes
#: and diagrams alike, at the animation rate); the recordings relabel their lanes at this rate.
PLOT_HZ = 10.0
#: The rods' current places on the diagrams: a diamond in the rod's colour (the black dots are the
#: named events).
NOW_MARKER = "diamond"
NOW_MARKER_NAME = "rods now"
#: Widths of the docked panels (CSS pixels) and the plots' height/width.
CONTROL_PX = 340
PLOT_PANEL_PX = 440
PLOT_ASPECT = 0.8
LENGTH_ASPECT = 0.75
#: The plot area inside a Minkowski diagram (pixels): the panel minus plotly's margins.
PLOT_AREA_PX = (PLOT_PANEL_PX - 40 - 58, PLOT_PANEL_PX * PLOT_ASPECT - 40 - 114)
LENGTH_AREA_PX = (PLOT_PANEL_PX - 40 - 58, PLOT_PANEL_PX * LENGTH_ASPECT - 40 - 114)
_LAB = rr.LAB


@dataclass(frozen=True)
class Drawn:
    """What a rebuild made for one resolved scene: reused by every playback frame."""

    resolved: Resolved
    window: tuple[float, float]
    geometry: LaneGeometry
    lane_ranges: tuple[tuple[float, float], tuple[float, float]]
    """Each lane's own x extent (lab, chosen frame): rulers and titles depend only on their frame."""
    lab_chart: Chart
    frame_chart: Chart
    length_chart: Chart
    views: tuple[View, View]
    """The lab diagram's view and the chosen frame's (their relative frames composed once)."""
    steady_widths: tuple[float, float] = (1.0, 1.0)
    """Each lane's x width (the frame's units) while no rod is too contracted to see (:func:`lanes.steady_width`)."""
    signals: tuple[Signals, Signals] | None = None
    """The light signals in the lab and in the chosen frame (:func:`.signals.signals_in`), if the
    :attr:`~.layers.Layer.SIGNALS` layer is shown: the lanes' pulses, at no cost to the core per frame."""

    @property
    def x_range(self) -> tuple[float, float]:
        """Both lanes together (the camera fits this)."""
        return min(r[0] for r in self.lane_ranges), max(r[1] for r in self.lane_ranges)

    @property
    def lane_x_range(self) -> tuple[float, float]:
        """``x_range`` in lane units (the camera and the raster frames fit this)."""
        return self.x_range[0] / self.geometry.unit, self.x_range[1] / self.geometry.unit

    @property
    def span(self) -> float:
        """A half-length beyond anything on screen: the diagrams' 'now' lines run this far."""
        return 4.0 * max(abs(v) for v in (*self.window, *self.x_range))

    def lane_statics(self) -> list[tuple[Segments, tuple[Label, ...]]]:
        """Each lane's ruler (x in the lab, x′ in the chosen frame) and origin mark: drawn once per scene."""
        origin = self.resolved.scene.origin_event
        return [lane_static(self.geometry, r, origin, axis) for r, axis in zip(self.lane_ranges, RULER_NAMES)]

    @property
    def charts(self) -> tuple[Chart, Chart, Chart]:
        """The lab diagram, the chosen frame's diagram, the equal-time lengths."""
        return (self.lab_chart, self.frame_chart, self.length_chart)

    def moving_items(self, now: float, ends: Sequence[FloatArray]) -> tuple[tuple[Item, ...], ...]:
        """What moves on each of :attr:`charts` at playback time ``now``: the now-lines and markers.

        ``ends`` are the rods' end positions at ``now`` in the lab and in the chosen frame (each
        ``(rods, 2)``, from the core, as the lanes drew them): they mark the rods on the diagrams,
        as diamonds in the rods' colours. The length plot's markers are the core's equal-time
        lengths in both frames. The now-lines' legend names carry no number (the lanes show it).
        """
        r = self.resolved
        lab_view, frame_view = self.views
        now_lines = Layer.SIMULTANEITY in r.layers
        lab = minkowski_now(lab_view, now, self.span, ends[0])
        frame = minkowski_now(frame_view, now, self.span, ends[1])
        if Layer.LENGTH_PANEL in r.layers:
            lengths = np.stack([r.scene.lengths(now, f) for f in (_LAB, r.frame)])  # (2, rods)
            length = _now_items(length_now(now, self.length_chart.y_range[1], lengths), *_at(now, lengths.T))
        else:
            length = ()
        return (
            _now_items(lab, ends[0], np.full(ends[0].shape, now), now_lines),
            _now_items(frame, ends[1], np.full(ends[1].shape, now), now_lines),
            length,
        )

    def legend(self) -> list[LegendEntry]:
        """Every named item of the three charts, static or moving, each name once."""
        moving = self.moving_items(self.window[0], [np.zeros((self.resolved.scene.n_rods, 2))] * 2)
        items = [it for chart in self.charts for it in chart.items] + [it for m in moving for it in m]
        return legend_entries(items)

    def lane_pictures(self, now: float, layout: CanvasLayout) -> list[LanePicture]:
        """Both lanes at playback time ``now`` on the canvas: the lab at t = now, the chosen frame at t' = now."""
        r = self.resolved
        titles = lane_titles(r, now)
        frames = (_LAB, r.frame)
        lanes = [
            lane_picture(r.scene, f, now, w, place, title)
            for f, w, place, title in zip(frames, self.steady_widths, layout.lanes, titles, strict=True)
        ]
        if self.signals is None:
            return lanes
        out = []
        for lane, place, sig in zip(lanes, layout.lanes, self.signals, strict=True):
            light = pulse_segments(sig.pulses_at(now), sig.far_arrivals, lane, place)
            out.append(replace(lane, segments=(*lane.segments, light)))
        return out


def _at(now: float, values: FloatArray) -> tuple[FloatArray, FloatArray]:
    """The length chart's markers: ``(rods, frames)`` lengths at time ``now`` as ``(x, y)``."""
    return np.full(values.shape, now), values


def _now_items(items: tuple[Item, ...], x: FloatArray, y: FloatArray, now_lines: bool = True) -> tuple[Item, ...]:
    """A diagram's moving items with the rods' current places as diamonds in each rod's colour
    (``x``, ``y``: ``(rods, k)`` data coordinates) instead of dots, and now-lines named without
    their number (left out unless ``now_lines``: the simultaneity layer hidden)."""
    out: list[Item] = []
    for it in items:
        if isinstance(it, Points):
            continue
        if not now_lines and isinstance(it, Polyline):
            continue
        if isinstance(it, Polyline | Segments) and it.style.name is not None:
            it = replace(it, style=replace(it.style, name=it.style.name.split(" = ")[0]))
        out.append(it)
    for r in range(x.shape[0]):
        name = NOW_MARKER_NAME if r == 0 else None
        style = Style(ROD_COLORS[r % len(ROD_COLORS)], name=name, group=NOW_MARKER_NAME)
        out.append(Points(np.ravel(x[r]), np.ravel(y[r]), style, size=9, symbol=NOW_MARKER))
    return tuple(out)


def lane_titles(r: Resolved, now: float) -> tuple[str, str]:
    """The lanes' first lines: the frame and its time."""
    return f"lab frame:   t = {signed(now)}", f"{frame_title(r.frame)} frame:   t' = {signed(now)}"


def _views(frame: rr.Frame) -> tuple[View, View]:
    """The lab diagram (compared with ``frame``) and the chosen frame's (compared with the lab)."""
    return View(_LAB, frame, "", "'"), View(frame, _LAB, "'", "")


def build_drawing(
    resolved: Resolved,
    sampler: Sampler = ADAPTIVE,
    areas: tuple[tuple[float, float], tuple[float, float]] = (PLOT_AREA_PX, LENGTH_AREA_PX),
) -> Drawn:
    """Everything that depends only on the scene and frame (not on playback time).

    ``sampler`` samples the diagrams' curves (the app's adaptive one unless a benchmark swaps it);
    ``areas`` are the plot areas (px) of the Minkowski diagrams and of the lengths chart.
    """
    plot_area, length_area = areas
    scene, frame = resolved.scene, resolved.frame
    lab = _LAB
    a0, a1 = scene.time_window(lab)
    b0, b1 = scene.time_window(frame)
    signals = (signals_in(scene, lab), signals_in(scene, frame)) if Layer.SIGNALS in resolved.layers else None
    window = _round_outward(min(a0, b0), _signals_end(max(a1, b1), min(a0, b0), signals))
    geometry = lane_geometry(scene)

    def lane_range(f: rr.Frame) -> tuple[float, float]:
        lo, hi = window_x_range(scene, (f,), _round_outward(*scene.time_window(f)))
        pad = 0.08 * (hi - lo) + 0.1 * geometry.unit
        return (lo - pad, hi + pad)

    lab_view, frame_view = _views(frame)
    lab_x, lab_t = equal_scale_ranges(window_x_range(scene, (lab,), window), window, plot_area)
    fr_x, fr_t = equal_scale_ranges(window_x_range(scene, (frame,), window), window, plot_area)
    label = overlay_label(scene)
    layers = resolved.layers
    lab_signals, frame_signals = signals if signals is not None else (None, None)
    lab_chart = minkowski_static(
        scene, lab_view, lab_t, lab_x, plot_area[0], resolved.overlay, sampler, label, plot_area, layers, lab_signals
    )
    frame_chart = minkowski_static(
        scene, frame_view, fr_t, fr_x, plot_area[0], resolved.overlay, sampler, label, plot_area, layers, frame_signals
    )
    if Layer.LENGTH_PANEL in layers:
        length_chart = length_static(scene, lab, frame, window, length_area, sampler)
    else:
        length_chart = hidden_chart(LENGTH_HIDDEN_TITLE, LENGTH_HIDDEN_NOTE)
    return Drawn(
        resolved=resolved,
        window=window,
        geometry=geometry,
        lane_ranges=(lane_range(lab), lane_range(frame)),
        lab_chart=lab_chart,
        frame_chart=frame_chart,
        length_chart=length_chart,
        views=(lab_view, frame_view),
        # each lane's scale from its own frame's window: the lab lane does not change with the frame
        steady_widths=(
            steady_width(scene, lab, _round_outward(a0, a1)),
            steady_width(scene, frame, _round_outward(b0, b1)),
        ),
        signals=signals,
    )


#: The length panel's place when its layer is hidden: a title and a note say so and how to bring it
#: back (the panel keeps its place, so the diagrams do not jump while a lecturer toggles it).
LENGTH_HIDDEN_TITLE = "Equal-time length (hidden)"
LENGTH_HIDDEN_NOTE = "The length panel is hidden:\nturn on its layer to show it."


def hidden_chart(title: str, note: str) -> Chart:
    """A panel that shows only ``title`` and ``note`` (no axes: its chart has no axis names)."""
    text = Label(0.5, 0.5, note, Style(INK), anchor="center", size=15.0)
    return Chart(items=(text,), x_title="", y_title="", x_range=(0.0, 1.0), y_range=(0.0, 1.0), title=title)


#: The window grows to show the light reach the far ends only if that adds at most this many windows.
SIGNAL_REACH = 1.5


def _signals_end(end: float, start: float, signals: tuple[Signals, Signals] | None) -> float:
    """The window's end, late enough for the light from the key event to reach every far end
    (the arrivals ``S`` in both frames), unless that would squeeze the diagrams: then the rays run
    off the top and the readout gives the arrival in numbers."""
    if signals is None:
        return end
    arrivals = [leg.arrival[0] for sig in signals for leg in sig.legs if leg.name.startswith("S")]
    late = max(arrivals, default=end)
    if late <= end or late - end > SIGNAL_REACH * (end - start):
        return end
    return late + 0.05 * (late - start)


def _round_outward(t0: float, t1: float) -> tuple[float, float]:
    """The window widened to round numbers (about 1/20 of its length), for a tidy time slider."""
    step = nice_step(t1 - t0) * 50.0
    return (math.floor(t0 / step) * step, math.ceil(t1 / step) * step)


def camera_pose(lane_x_range: tuple[float, float], aspect: float) -> cam.CameraPose:
    """Both lanes (rods, clocks, rulers, titles) in view, looking straight at them."""
    return cam.fit_lanes(lane_x_range, (FRAME_Z - 0.35, LAB_Z + 0.5), aspect)


def nice_step(span: float) -> float:
    raw = span / 1000.0
    if raw <= 0 or not math.isfinite(raw):
        return 0.001
    return float(10 ** math.floor(math.log10(raw)))


def lane_states(d: Drawn, now: float, labels: bool = True) -> list[LaneState]:
    """Both lanes at playback time ``now``: the lab at t = now, the chosen frame at t' = now."""
    r = d.resolved
    lab_x, frame_x = (rng[0] / d.geometry.unit for rng in d.lane_ranges)
    lab_title, frame_title_ = lane_titles(r, now)
    return [
        lane_state(r.scene, _LAB, now, d.geometry, lab_title, lab_x, labels),
        lane_state(r.scene, r.frame, now, d.geometry, frame_title_, frame_x, labels),
    ]


def signals_readout(resolved: Resolved) -> str:
    """The causal verdicts in words (:func:`.signals.verdict_lines`, from the core's
    :meth:`~rigidrel_core.Scene.causal_verdicts`) as readout Markdown, or ``""`` while the
    :attr:`~.layers.Layer.SIGNALS` layer is hidden."""
    if Layer.SIGNALS not in resolved.layers:
        return ""
    return "".join(f"  \n**Light** {line}" for line in verdict_lines(resolved.scene))


def readout_markdown(resolved: Resolved) -> str:
    """Parameters, final velocities and events in plain numbers, for the control panel."""
    scene, frame = resolved.scene, resolved.frame
    d = rr.describe(scene)
    params = [f"{d.parameter(k).symbol} = {format_value(v)}" for k, v in scene.parameters.items()]
    v = ", ".join(f"{r.name}: {signed(v, 4)}" for r, v in zip(scene.rods, scene.final_velocities, strict=True))
    ev = " · ".join(f"{k} ({_fixed(t)}, {_fixed(x)})" for k, (t, x) in scene.events.items())
    notes = "".join(f"  \n**Note** {n}" for n in scene.notes(frame))  # a paradox's verdicts, in words
    return (
        f"**Scene** {', '.join(params)}  \n**Final velocities** {v}  \n**Events (lab t, x)** {ev}  \n"
        f"**Frame** {frame_title(frame)}  \n**Clocks** {CLOCK_RULE}{notes}{signals_readout(resolved)}"
    )


def _fixed(x: float, digits: int = 3) -> str:
    """``x`` with ``digits`` decimals, and rounding noise such as -1e-17 shown as 0.000, not -0.000."""
    return f"{round(x, digits) + 0.0:.{digits}f}"
