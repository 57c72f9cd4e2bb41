"""What one scene in one frame looks like: everything the app, the recordings and the exports draw.

Pure functions over :mod:`rigidrel_core` and the drawing vocabulary; no viser or plotly
here, so the exporters use exactly what the app shows.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, replace
from typing import NamedTuple

import numpy as np

import rigidrel_core as rr

from . import camera as cam
from .canvas import LegendEntry, legend_entries
from .comoving import HORIZON_NAME, HORIZON_SYMBOL, ComovingInstant, RideTrack, ride_at, ride_track, simultaneity_items
from .diagrams import (
    EVENT_LABEL_PX,
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
    FIT_SHARE,
    TICK_FRACTIONS,
    LaneFit,
    LaneGeometry,
    LanePicture,
    LaneScale,
    LaneScales,
    LaneState,
    lane_fit,
    lane_geometry,
    lane_picture,
    lane_scales,
    lane_state,
    lane_static,
    pulse_segments,
    steady_width,
    title_text,
    zoomed_title,
)
from .layers import Layer
from .layout import CanvasLayout, Panels
from .objects import object_words_at
from .sampling import ADAPTIVE, Sampler
from .signals import Signals, event_cone_items, key_definition, signals_in, signals_window_end, verdict_lines
from .state import Resolved, format_value
from .vocabulary import (
    INK,
    ROD_COLORS,
    Chart,
    FloatArray,
    Item,
    Label,
    Points,
    Polyline,
    Segments,
    Style,
    names_html,
    signed,
)

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
    lane_scale: LaneScale = LaneScale.SHARED
    """One scale for both lanes (the default: a rod's lengths in the two frames compare by eye), or
    each lane its own (:func:`.lanes.lane_scales`)."""
    signals: tuple[Signals, Signals] | None = None
    """The light signals in the lab and in the chosen frame (:func:`.signals.signals_in`), if the
    :attr:`~.layers.Layer.SIGNALS` layer is shown: the lanes' pulses, at no cost to the core per frame."""
    ride: RideTrack | None = None
    """The ride over the window while the lower lane rides a point (:attr:`.state.Resolved.ride`)."""

    def ride_instant(self, now: float) -> ComovingInstant | None:
        """The riding lane's instant at playback time ``now``: the point's event at lab time ``now``
        (:func:`.comoving.ride_at`), or ``None`` when the lane does not ride."""
        point = self.resolved.ride
        return None if point is None else ride_at(self.resolved.scene, point, now)

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

    @property
    def ruler_names(self) -> tuple[str, str]:
        """The lanes' rulers' names: x in the lab, x′ in the chosen frame (x again where it is the lab)."""
        return ruler_names(self.resolved)

    def lane_statics(self) -> list[tuple[Segments, tuple[Label, ...]]]:
        """Each lane's ruler (x in the lab, x′ in the chosen frame) and origin mark: drawn once per scene."""
        origin = self.resolved.scene.origin_event
        return [lane_static(self.geometry, r, origin, axis) for r, axis in zip(self.lane_ranges, self.ruler_names)]

    @property
    def charts(self) -> tuple[Chart, Chart, Chart]:
        """The lab diagram, the chosen frame's diagram, the equal-time lengths."""
        return (self.lab_chart, self.frame_chart, self.length_chart)

    def moving_items(
        self, now: float, ends: Sequence[FloatArray], instant: ComovingInstant | None = None
    ) -> tuple[tuple[Item, ...], ...]:
        """What moves on each of :attr:`charts` at playback time ``now``: the now-lines and markers.

        ``ends`` are the rods' end positions at ``now`` in the lab and in the chosen frame (each
        ``(rods, 2)``, from the core, as the lanes drew them): they mark the rods on the diagrams,
        as diamonds in the rods' colours. The length plot's markers are the core's equal-time
        lengths in both frames. The now-lines' legend names carry no number (the lanes show it).
        While the lower lane rides a point, its ends are in the point's comoving frame at the ride's
        ``instant`` (:meth:`ride_instant`, found here if not given), and :meth:`_riding_items` draws them.
        With fewer lanes shown (:func:`panels`), ``ends`` are :meth:`rod_ends`'.
        """
        r = self.resolved
        if len(ends) < 2:
            ends = [*ends, *self.rod_ends(now, instant, first=len(ends))]
        if r.ride is not None:
            return self._riding_items(now, ends, instant or self.ride_instant(now))
        lab_view, frame_view = self.views
        now_lines = Layer.SIMULTANEITY in r.layers
        lab = minkowski_now(lab_view, now, self.span, ends[0])
        frame = minkowski_now(frame_view, now, self.span, ends[1])
        if Layer.LENGTH_PANEL in r.layers:
            lengths = np.stack([r.scene.lengths(now, frame=f) for f in (_LAB, r.frame)])  # (2, rods)
            length = _now_items(length_now(now, self.length_chart.y_range[1], lengths), *_at(now, lengths.T))
        else:
            length = ()
        return (
            _now_items(lab, ends[0], np.full(ends[0].shape, now), now_lines),
            _now_items(frame, ends[1], np.full(ends[1].shape, now), now_lines),
            length,
        )

    def _riding_items(
        self, now: float, ends: Sequence[FloatArray], instant: ComovingInstant | None
    ) -> tuple[tuple[Item, ...], ...]:
        """The moving parts while the lower lane rides a point: on the lab diagram its now-line and the
        comoving frame's line of simultaneity through the point's event (sweeping as the point
        accelerates, always through the pivot event); on the second diagram (the scene's default
        frame) the same comoving line and the riding lane's rod ends, boosted there by the core; on
        the length panel the lab's lengths and the comoving frame's (the ridden rod's: its rest length)."""
        assert instant is not None
        r = self.resolved
        frame_view = self.views[1]
        now_lines = Layer.SIMULTANEITY in r.layers
        lab = _now_items(
            minkowski_now(View.alone(_LAB), now, self.span, ends[0]), ends[0], np.full(ends[0].shape, now), now_lines
        )
        t_ride = np.full(ends[1].shape, instant.event[0])
        seen = (frame_view.frame @ instant.frame.inverse()) @ np.stack([t_ride, ends[1]], axis=-1)  # (rods, 2, 2)
        frame = _now_items((), seen[..., 1], seen[..., 0])
        lab += simultaneity_items(instant, self.span)[:2]
        frame += simultaneity_items(instant, self.span, frame_view.frame)[:2]
        if Layer.LENGTH_PANEL in r.layers:
            lengths = np.stack([r.scene.lengths(now, frame=_LAB), np.array(instant.lengths)])  # (2, rods)
            length = _now_items(length_now(now, self.length_chart.y_range[1], lengths), *_at(now, lengths.T))
        else:
            length = ()
        return lab, frame, length

    def rod_ends(self, now: float, instant: ComovingInstant | None = None, first: int = 0) -> list[FloatArray]:
        """The rods' ends ``(rods, 2)`` at playback time ``now`` in each lane's frame from lane
        ``first`` on, as :meth:`lane_pictures` draws them: the lab at t = now, the chosen frame at
        t′ = now or, riding, the comoving frame at the ride's ``instant`` (found here if not given).
        A lane not drawn (:func:`panels`) still marks its rods on its diagram."""
        r = self.resolved
        if r.ride is not None:
            instant = instant or self.ride_instant(now)
        lanes = [(_LAB, now), (r.frame, now) if instant is None else (instant.frame, instant.event[0])]
        return [r.scene.snapshot(t, frame=f, fractions=TICK_FRACTIONS)[0][:, [0, -1]] for f, t in lanes[first:]]

    def lane_titles_at(self, now: float, layout: CanvasLayout) -> list[str]:
        """The lanes' titles at ``now`` as :meth:`lane_pictures` writes them (their frame and clock,
        zoom, objects' words and end clocks), without drawing the lanes."""
        if not layout.lanes:
            return []
        r = self.resolved
        instant = self.ride_instant(now) if r.ride is not None else None
        shown, snaps, _, scales = self._lanes_at(now, layout, instant)
        out: list[str] = []
        titles = lane_titles(r, now, instant)[: len(shown)]
        for (frame, t, _), title, (_, tau), zoom in zip(shown, titles, snaps, scales.zooms, strict=True):
            words = [object_words_at(obj, frame, t) for obj in r.scene.objects]
            out.append(title_text(r.scene, zoomed_title(title, zoom), words, tau))
        return out

    def _lanes_at(self, now: float, layout: CanvasLayout, instant: ComovingInstant | None) -> _LanesAt:
        """What the lanes of ``layout`` show at ``now`` (``instant``: the ride's, riding): each lane's
        frame, time and the point it keeps still (a riding lane: the ridden point), the rods'
        snapshot in it, its fit and the lanes' scales."""
        r = self.resolved
        n = len(layout.lanes)
        shown: list[tuple[rr.Frame, float, float | None]] = [(_LAB, now, None)]
        if instant is None:
            shown.append((r.frame, now, None))
        else:
            t_ride, x_point = instant.event
            shown.append((instant.frame, t_ride, x_point))
        shown = shown[:n]
        rest = np.array([rod.motion.length for rod in r.scene.rods])
        snaps = [r.scene.snapshot(t, frame=f, fractions=TICK_FRACTIONS) for f, t, _ in shown]
        fits = [lane_fit(x[:, [0, -1]], rest, c) for (x, _), (_, _, c) in zip(snaps, shown, strict=True)]
        tracks = [place.track.width for place in layout.lanes]
        return _LanesAt(shown, snaps, fits, lane_scales(fits, tracks, self.steady_widths[:n], self.lane_scale))

    def legend(self, shown: tuple[bool, bool, bool] | None = None) -> list[LegendEntry]:
        """Every named item of the charts ``shown`` (default: as :func:`panels` has them, unzoomed),
        static or moving, each name once."""
        moving = self.moving_items(self.window[0], [np.zeros((self.resolved.scene.n_rods, 2))] * 2)
        shown = panels(self.resolved).charts if shown is None else shown
        items = [it for chart, on in zip(self.charts, shown, strict=True) if on for it in chart.items]
        items += [it for m, on in zip(moving, shown, strict=True) if on for it in m]
        return legend_entries(items)

    def lane_pictures(
        self, now: float, layout: CanvasLayout, instant: ComovingInstant | None = None
    ) -> list[LanePicture]:
        """The lanes ``layout`` has at playback time ``now``: the lab at t = now, then (if shown: not
        where the chosen frame is the lab, :func:`panels`) the chosen frame at t' = now; or, riding
        a point, its comoving frame at the ride's ``instant`` (:meth:`ride_instant`, found here if
        not given), centred on the point, which stays still on screen."""
        r = self.resolved
        if r.ride is not None:
            instant = instant or self.ride_instant(now)
        n = len(layout.lanes)
        if n == 0:  # one diagram zoomed to the whole canvas
            return []
        shown, snaps, fits, scales = self._lanes_at(now, layout, instant)
        titles = lane_titles(r, now, instant)[: len(shown)]
        lanes = [
            lane_picture(r.scene, f, t, scale, place, title, fit, snap, zoom)
            for (f, t, _), scale, place, title, fit, snap, zoom in zip(
                shown, scales.scales, layout.lanes, titles, fits, snaps, scales.zooms, strict=True
            )
        ]
        if self.signals is None:
            return lanes
        signals = self.signals
        if instant is not None:  # the lab's rays, boosted into the comoving frame of this instant
            signals = (signals[0], signals[0].seen_from(instant.frame))
        times = (now, now if instant is None else instant.event[0])
        out = []
        for lane, place, sig, t in zip(lanes, layout.lanes, signals[:n], times[:n], strict=True):
            light = pulse_segments(sig.pulses_at(t), sig.far_arrivals, lane, place)
            out.append(replace(lane, segments=(*lane.segments, light)))
        return out


class _LanesAt(NamedTuple):
    """What the lanes show at one instant (:meth:`Drawn._lanes_at`)."""

    shown: list[tuple[rr.Frame, float, float | None]]
    """Each lane's frame, its time and the point it keeps still (a riding lane: the ridden point)."""
    snaps: list[tuple[FloatArray, FloatArray]]
    """The rods in each lane's frame at its time (:meth:`rigidrel_core.Scene.snapshot`)."""
    fits: list[LaneFit]
    scales: LaneScales


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


def _is_lab(r: Resolved) -> bool:
    """Whether the chosen frame is the lab's (a lab step, or a preset at rest in the lab), unridden."""
    return r.ride is None and r.frame.same_velocity(_LAB)


def panels(r: Resolved, zoomed: bool = False, portrait: bool = False) -> Panels:
    """The lanes and charts the canvas shows for ``r``: the chosen frame's lane and diagram unless
    that frame is the lab's own (:attr:`~.state.Resolved.lab_only`), the lengths chart while its
    layer is shown. ``zoomed`` (key Z): one diagram, the chosen frame's (the lab's in a lab step),
    over the whole canvas, drawn larger (a diagram keeps one scale for x and t, so its height bounds
    it: the lanes give theirs). ``portrait``: a phone held upright
    (:func:`~.layout.is_portrait`), whose height holds the lanes and one diagram under them, as
    wide as the phone: the same one (turned sideways, or with Z, the phone shows the rest)."""
    one_lab = r.lab_only
    if zoomed:
        return Panels(lanes=0, charts=(one_lab, not one_lab, False))
    if portrait:
        return Panels(lanes=1 if one_lab else 2, charts=(one_lab, not one_lab, False))
    return Panels(lanes=1 if one_lab else 2, charts=(True, not one_lab, Layer.LENGTH_PANEL in r.layers))


def ruler_names(r: Resolved) -> tuple[str, str]:
    """The lanes' rulers' names: x in the lab, x′ in the chosen frame, x where that is the lab too."""
    return ("x", "x") if _is_lab(r) else RULER_NAMES


def lane_titles(r: Resolved, now: float, instant: ComovingInstant | None = None) -> tuple[str, str]:
    """The lanes' first lines: the frame and its time; riding, the point and its clock's reading
    (``instant``: the ride at ``now``). The chosen frame's time is t′, and t where it is the lab."""
    lab = f"lab frame:   t = {signed(now)}"
    if r.ride is not None and instant is not None:
        return lab, f"riding: {r.ride.label(r.scene)}:   its clock τ = {signed(instant.proper_time)}"
    if _is_lab(r):
        return lab, f"{frame_title(r.frame)} frame (chosen):   t = {signed(now)}"
    return lab, f"{frame_title(r.frame)} frame:   t′ = {signed(now)}"


def _views(frame: rr.Frame) -> tuple[View, View]:
    """The lab diagram (compared with ``frame``) and the chosen frame's (compared with the lab)."""
    return View(_LAB, frame, "", "'"), View(frame, _LAB, "'", "")


def build_drawing(
    resolved: Resolved,
    sampler: Sampler = ADAPTIVE,
    areas: tuple[tuple[float, float], tuple[float, float]] = (PLOT_AREA_PX, LENGTH_AREA_PX),
    label_px: float = EVENT_LABEL_PX,
    lane_scale: LaneScale = LaneScale.SHARED,
) -> Drawn:
    """Everything that depends only on the scene and frame (not on playback time).

    ``sampler`` samples the diagrams' curves (the app's adaptive one unless a benchmark swaps it);
    ``areas`` are the plot areas (px) of the Minkowski diagrams and of the lengths chart;
    ``label_px`` the size (CSS px) the diagrams' labels are drawn at, which their placement reserves;
    ``lane_scale`` whether the canvas' lanes share one scale (the default) or each fits its own rods.
    """
    plot_area, length_area = areas
    scene, frame = resolved.scene, resolved.frame
    lab = _LAB
    a0, a1 = scene.time_window(frame=lab)
    b0, b1 = scene.time_window(frame=frame)
    signals = (signals_in(scene, lab), signals_in(scene, frame)) if Layer.SIGNALS in resolved.layers else None
    window = _round_outward(min(a0, b0), signals_window_end(max(a1, b1), min(a0, b0), signals))
    geometry = lane_geometry(scene)

    def lane_range(f: rr.Frame) -> tuple[float, float]:
        lo, hi = window_x_range(scene, (f,), _round_outward(*scene.time_window(frame=f)))
        pad = 0.08 * (hi - lo) + 0.1 * geometry.unit
        return (lo - pad, hi + pad)

    lab_view, frame_view = _views(frame)
    lab_sweep, frame_sweep = window_x_range(scene, (lab,), window), window_x_range(scene, (frame,), window)
    if resolved.ride is not None:  # the riding lane's lines of simultaneity meet at the pivot event: show it
        lab_sweep = _reaching(lab_sweep, scene.horizon_event(resolved.ride.rod)[1])
        frame_sweep = _reaching(frame_sweep, scene.horizon_event(resolved.ride.rod, frame=frame)[1])
    lab_x, lab_t = equal_scale_ranges(lab_sweep, window, plot_area)
    fr_x, fr_t = equal_scale_ranges(frame_sweep, window, plot_area)
    label = overlay_label(scene)
    layers = resolved.layers
    lab_signals, frame_signals = signals if signals is not None else (None, None)
    lab_chart = minkowski_static(
        scene, lab_view, lab_t, lab_x, plot_area[0], resolved.overlay, sampler, label, plot_area, layers, lab_signals,
        label_px,
    )  # fmt: skip
    frame_chart = minkowski_static(
        scene, frame_view, fr_t, fr_x, plot_area[0], resolved.overlay, sampler, label, plot_area, layers,
        frame_signals, label_px,
    )  # fmt: skip
    if resolved.cone is not None:  # the chosen event's light cone, in both diagrams
        lab_chart = _with_cone(lab_chart, scene, resolved.cone, lab)
        frame_chart = _with_cone(frame_chart, scene, resolved.cone, frame)
    track = None
    frame_width = steady_width(scene, frame, _round_outward(b0, b1))
    if resolved.ride is not None:
        track = ride_track(scene, resolved.ride, window)
        frame_width = 2.0 * track.reach / FIT_SHARE  # about the point, which the riding lane keeps still
        lab_chart = _with_horizon(lab_chart, scene.horizon_event(resolved.ride.rod))
        frame_chart = _with_horizon(frame_chart, scene.horizon_event(resolved.ride.rod, frame=frame))
    if Layer.LENGTH_PANEL in layers:
        comoving = None if track is None else (track.t, track.lengths, RIDE_LENGTH_NAME)
        length_chart = length_static(scene, lab, frame, window, length_area, sampler, comoving, label_px)
    else:
        length_chart = NO_CHART  # not shown: the diagrams take its room (:func:`panels`)
    return Drawn(
        resolved=resolved,
        window=window,
        geometry=geometry,
        lane_ranges=(lane_range(lab), lane_range(frame)),
        lab_chart=lab_chart,
        frame_chart=frame_chart,
        length_chart=length_chart,
        views=(lab_view, frame_view),
        # each lane's steady width from its own frame's window; the lanes then share the scale at
        # which both fit (LaneScale.SHARED), or each keeps its own (LaneScale.OWN)
        steady_widths=(steady_width(scene, lab, _round_outward(a0, a1)), frame_width),
        lane_scale=lane_scale,
        signals=signals,
        ride=track,
    )


#: The length panel's name for the riding point's comoving frames (the legend shows it per rod).
RIDE_LENGTH_NAME = "comoving (ride)"


def _with_cone(chart: Chart, scene: rr.Scene, event: str, frame: rr.Frame) -> Chart:
    """``chart`` (a Minkowski diagram in ``frame``) with the light cone of ``event`` drawn under its
    curves: its future and past shaded, its light rays dashed (:func:`.signals.event_cone_items`)."""
    cone = event_cone_items(scene, event, frame, chart.x_range, chart.y_range)
    return replace(chart, items=(*cone, *chart.items))


#: A diagram widens to show the pivot event if that at most triples its x range.
HORIZON_REACH = 1.0


def _reaching(x_range: tuple[float, float], x: float) -> tuple[float, float]:
    """``x_range`` widened to hold ``x``, unless ``x`` lies farther than :data:`HORIZON_REACH` ranges
    beyond it (a weakly accelerated rod's horizon is far away: the lines then run off the plot)."""
    lo, hi = x_range
    reach = HORIZON_REACH * (hi - lo)
    return (min(lo, x), max(hi, x)) if lo - reach <= x <= hi + reach else x_range


def _with_horizon(chart: Chart, event: tuple[float, float]) -> Chart:
    """``chart`` with the ridden rod's pivot event (the centre of its change, where every comoving
    line of simultaneity meets) marked and named in the legend, if it lies on the chart."""
    t, x = event
    if not (chart.x_range[0] <= x <= chart.x_range[1] and chart.y_range[0] <= t <= chart.y_range[1]):
        return chart
    style = Style(INK, name=HORIZON_NAME, group="comoving")
    mark = Points(np.array([x]), np.array([t]), style, size=9, symbol=HORIZON_SYMBOL)
    return replace(chart, items=(*chart.items, mark))


#: A chart the canvas does not show (:class:`~.layout.Panels`): nothing to draw.
NO_CHART = Chart(items=(), x_title="", y_title="", x_range=(0.0, 1.0), y_range=(0.0, 1.0), title="")


def _round_outward(t0: float, t1: float) -> tuple[float, float]:
    """The window widened to round numbers (about 1/20 of its length), for a tidy time slider."""
    step = nice_step(t1 - t0) * 50.0
    lo, hi = (t0 / step, t1 / step) if step > 0.0 else (math.inf, math.inf)
    if not (math.isfinite(lo) and math.isfinite(hi)):  # a window of subnormal width: kept as it is
        return (t0, t1)
    return (math.floor(lo) * step, math.ceil(hi) * step)


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
    :meth:`~rigidrel_core.Scene.causal_verdicts`, their events the lab's and labelled so, as the
    readout's) as readout Markdown, or ``""`` while the :attr:`~.layers.Layer.SIGNALS` layer is hidden."""
    if Layer.SIGNALS not in resolved.layers:
        return ""
    definition = key_definition(resolved.scene)
    lines = (definition[:1].upper() + definition[1:] + ".", *verdict_lines(resolved.scene))
    return "".join(f"  \n**Light** {line}" for line in lines)


def readout_markdown(resolved: Resolved) -> str:
    """Parameters, final velocities and events in plain numbers, for the control panel: every event,
    in the numbers and in the words (notes, verdicts), the lab's, and labelled "(lab t, x)"; its
    name written as the canvas draws it (``T<sub>B</sub>``: viser's Markdown shows raw HTML)."""
    scene, frame = resolved.scene, resolved.frame
    d = rr.describe(scene)
    params = [f"{d.parameter(k).symbol} = {format_value(v)}" for k, v in scene.parameters.items()]
    v = ", ".join(f"{r.name}: {signed(v, 4)}" for r, v in zip(scene.rods, scene.final_velocities, strict=True))
    ev = " · ".join(f"{k} ({_fixed(t)}, {_fixed(x)})" for k, (t, x) in scene.events.items())
    # a paradox's verdicts in words, their events the lab's (labelled "(lab t, x)"), as the events above
    notes = "".join(f"  \n**Note** {n}" for n in scene.notes(frame=_LAB))
    shown = frame_title(frame)
    if resolved.ride is not None:
        shown = f"the lower lane rides: {resolved.ride.label(scene)} ({RIDE_RULE}); the second diagram: {shown}"
    return names_html(
        f"**Scene** {', '.join(params)}  \n**Final velocities** {v}  \n**Events (lab t, x)** {ev}  \n"
        f"**Frame** {shown}  \n**Clocks** {CLOCK_RULE}{notes}{signals_readout(resolved)}"
    )


#: What a riding lane shows, in the readout's words.
RIDE_RULE = "at each instant the inertial frame moving with that point, at the point's event at lab time t"


def _fixed(x: float, digits: int = 3) -> str:
    """``x`` with ``digits`` decimals, and rounding noise such as -1e-17 shown as 0.000, not -0.000."""
    return f"{round(x, digits) + 0.0:.{digits}f}"
