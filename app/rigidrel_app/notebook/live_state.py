"""What the notebook's live view shows, as values: the state behind its sliders and the figure they draw.

Pure: no widgets here. A :class:`LiveState` holds the last valid scene (its :class:`Settings`,
the :class:`~rigidrel_app.view.scene_view.Drawn` the app's own builders made of it), the playback
time, and the notice of the last refused change. Each ``with_*`` function returns the state one
control's change leads to: a value the core refuses leaves the scene as it was and says why in
:attr:`LiveState.notice`. :func:`live_figure` lays the app's three charts (the lab's Minkowski
diagram, the chosen frame's, the equal-time lengths, Fig. 2) side by side as one plotly figure
dict; :func:`moving_traces` are the parts that follow the time slider. Every number on them
comes from :mod:`rigidrel_core` through the view layer (the app computes no physics). On a dark
:attr:`LiveState.shade` both are drawn in the app's dark theme (:func:`shaded_figure`).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, replace
from typing import Any

import numpy as np
from markdown_it import MarkdownIt

import rigidrel_core as rr

from ..backends.plotly import TITLE_PX, chart_layout, item_to_traces, label_to_annotation, shaded_figure
from ..view.entry import NumberEntry, control_value, significant
from ..view.scene_view import Drawn, build_drawing, nice_step, readout_markdown
from ..view.state import CUSTOM_BETA, CUSTOM_FRAME, Settings, build, frame_choice, frame_choices, resolve
from ..view.vocabulary import SHADES, Chart, Item, Label, Shade

#: The live figure (CSS pixels): the two Minkowski diagrams side by side, the equal-time lengths
#: under the lab's, the legends beside it. Fits the output area of JupyterLab or VS Code in a
#: 1280-px-wide window (about 850 px).
FIGURE_PX = (840, 940)
#: Margins around the panels (left, right, top, bottom): two-line panel titles above.
MARGIN_PX = (60, 10, 60, 60)
#: Each panel's domain (x, y: fractions of the plot area): the lab diagram, the chosen frame's, the lengths.
PANEL_DOMAINS = (((0.0, 0.45), (0.5, 1.0)), ((0.55, 1.0), (0.5, 1.0)), ((0.0, 0.45), (0.0, 0.3)))
#: Where the one legend starts (paper fractions, its top left corner): beside the lengths.
LEGEND_AT = (0.55, 0.41)
#: The β slider of a custom frame: the app's range and step.
BETA_ENTRY = NumberEntry("β (custom frame)", *CUSTOM_BETA, 0.01)
_PLOT_W = FIGURE_PX[0] - MARGIN_PX[0] - MARGIN_PX[1]
_PLOT_H = FIGURE_PX[1] - MARGIN_PX[2] - MARGIN_PX[3]
#: Each panel's plot area (px): the diagrams' curves are sampled and their labels placed for it.
PANEL_PX = tuple(((x1 - x0) * _PLOT_W, (y1 - y0) * _PLOT_H) for (x0, x1), (y0, y1) in PANEL_DOMAINS)
_MARKDOWN = MarkdownIt("commonmark", {"html": False})
#: The material points whose places the time slider marks: each rod's two ends.
_ENDS = np.array([0.0, 1.0])


def slider_parameters(kind: str) -> tuple[tuple[rr.Parameter, NumberEntry], ...]:
    """The scene's parameters that have a slider in the registry, each with the entry (label, range,
    step, linear or log scale) the app's own slider uses."""
    return tuple((p, NumberEntry.of(p)) for p in rr.describe(kind).parameters if p.slider is not None)


def time_entry(drawn: Drawn) -> NumberEntry:
    """The time slider: over the scene's window (lab t and the chosen frame's t′ together), in steps
    of about 1/1000 of it."""
    t0, t1 = (slider_time(t) for t in drawn.window)
    return NumberEntry("t, t′", t0, t1, nice_step(t1 - t0), noun="a time")


def slider_time(t: float) -> float:
    """A time as the time slider holds it: to 12 significant digits. A browser's slider computes its
    value as ``min + k * step`` in floating point, which leaves noise in the last digits (0.3 comes
    back as 0.29999999999999977); the same time must give the same picture, not a redraw."""
    return significant(t, 12)


@dataclass(frozen=True)
class LiveState:
    """The live view's state: the last valid scene, the playback time, the last refusal."""

    settings: Settings
    """The settings of the scene on screen (a refused change never gets here)."""
    drawn: Drawn
    """What the app's builders made of :attr:`settings` (:func:`build_drawing`)."""
    now: float
    """Playback time: the lab diagram's t and the chosen frame's t′ (c = 1, units of rod 1's rest length)."""
    notice: str = ""
    """Why the last change was refused, naming the parameter and its allowed range ("" if it was not)."""
    shade: Shade = "light"
    """The figure's ground: light, or dark (the app's projector theme, every colour lightness-flipped);
    every change of scene, frame or time keeps it."""

    @property
    def frame_options(self) -> tuple[str, ...]:
        """The frame menu: the scene's frame presets, then the custom frame set by the β slider."""
        return frame_choices(self.drawn.resolved.scene)

    @property
    def frame_value(self) -> str:
        r = self.drawn.resolved
        return frame_choice(r.scene, r.frame)

    @property
    def beta(self) -> float:
        """The velocity of the frame on screen (a preset's or the custom one's), c = 1."""
        return float(self.drawn.resolved.frame.beta)

    @property
    def time(self) -> NumberEntry:
        return time_entry(self.drawn)

    def readout_html(self) -> str:
        """The app's readout (parameters, final velocities, events, the frame, the clock rule) as HTML."""
        return _MARKDOWN.render(readout_markdown(self.drawn.resolved))


def _draw(settings: Settings) -> Drawn | str:
    resolved = resolve(settings)
    if isinstance(resolved, str):
        return resolved
    return build_drawing(resolved, areas=(PANEL_PX[0], PANEL_PX[2]))


def checked_theme(theme: object) -> Shade:
    """``theme`` as a :data:`~rigidrel_app.view.vocabulary.Shade`; anything but ``"light"`` or ``"dark"``
    raises :class:`~rigidrel_core.ParameterError` naming ``theme``."""
    for shade in SHADES:
        if isinstance(theme, str) and theme == shade:
            return shade
    raise rr.ParameterError("theme", " or ".join(repr(s) for s in SHADES), theme)


def start(
    kind: str,
    frame: str | float | None = None,
    t: float | None = None,
    *,
    theme: Shade = "light",
    **values: float | None,
) -> LiveState:
    """The state the view opens on: scene ``kind`` (a registry name, e.g. ``"rod-collision"``) with
    ``values`` (the rest at their defaults), in ``frame`` (a preset name of the scene, a velocity
    β in (-1, 1) for a custom frame, or ``None`` for the scene's default frame), at time ``t``
    (default: the start of the window), drawn in ``theme`` (``"dark"``: the app's dark projector
    theme). Values the core refuses raise its :class:`~rigidrel_core.ParameterError`, which names
    the parameter and its allowed range."""
    shade = checked_theme(theme)
    if isinstance(frame, str) or frame is None:
        settings = Settings.of(kind, **values)
        settings = replace(settings, frame=frame)
    else:
        settings = replace(Settings.of(kind, **values), frame=CUSTOM_FRAME, beta=float(frame))
    drawn = build_drawing(build(settings), areas=(PANEL_PX[0], PANEL_PX[2]))  # a refusal raises, naming it
    now = drawn.window[0] if t is None else t
    state = LiveState(settings, drawn, slider_time(drawn.window[0]), shade=shade)
    moved = at_time(state, now)
    if moved.notice:
        raise rr.ParameterError("t", state.time.allowed(), t)
    return moved


def change(state: LiveState, settings: Settings) -> LiveState:
    """The state with ``settings``, or, if the core refuses them, the old scene with the notice.
    The time stays where it was if the new scene's window holds it, else it moves to the nearer end;
    the shade stays."""
    drawn = _draw(settings)
    if isinstance(drawn, str):
        return replace(state, notice=drawn)
    t0, t1 = (slider_time(t) for t in drawn.window)
    return LiveState(settings, drawn, min(max(state.now, t0), t1), shade=state.shade)


def with_parameter(state: LiveState, name: str, value: float | None) -> LiveState:
    """The state after a parameter's slider (or :meth:`LiveView.set`) moved to ``value``."""
    if name not in state.settings.description.parameter_map:
        names = ", ".join(state.settings.description.parameter_map)
        return replace(state, notice=f"{name} is not a parameter of {state.settings.scene} (it has {names}).")
    return change(state, state.settings.with_value(name, value))


def with_frame(state: LiveState, choice: str) -> LiveState:
    """The state after the frame menu chose ``choice`` (a preset name, or the custom frame: the
    velocity on screen is kept, so that the picture does not jump)."""
    if choice == CUSTOM_FRAME:
        return change(state, replace(state.settings, frame=CUSTOM_FRAME, beta=state.beta))
    if choice not in state.frame_options:
        allowed = ", ".join(repr(c) for c in state.frame_options)
        return replace(state, notice=f"frame = {choice!r} refused: it must be one of {allowed}.")
    return change(state, replace(state.settings, frame=choice))


def with_beta(state: LiveState, beta: float) -> LiveState:
    """The state after the β slider moved: the custom frame at velocity ``beta`` (c = 1)."""
    if not BETA_ENTRY.lo <= beta <= BETA_ENTRY.hi:
        return replace(state, notice=BETA_ENTRY.refuse(f"{beta:.6g}").notice)
    return change(state, replace(state.settings, frame=CUSTOM_FRAME, beta=float(beta)))


def at_time(state: LiveState, now: float) -> LiveState:
    """The state at playback time ``now`` (lab t on the lab diagram, t′ on the chosen frame's); a
    time outside the scene's window is refused, naming the window."""
    entry = state.time
    t = slider_time(now)
    if not entry.lo <= t <= entry.hi:
        return replace(state, notice=entry.refuse(f"{now:.6g}").notice)
    return replace(state, now=t, notice="")


# ---------------------------------------------------------------------------------- the figure
def _axis_names(k: int) -> tuple[str, str]:
    """Plotly's names of panel ``k``'s axes, as a trace refers to them (``x``, ``x2``, ``x3``)."""
    return ("x", "y") if k == 0 else (f"x{k + 1}", f"y{k + 1}")


def _panel_traces(items: tuple[Item, ...], k: int) -> list[dict[str, Any]]:
    """Panel ``k``'s traces. The panels share one legend: an entry of the chosen frame's
    diagram named as one of the lab's (rod 1, light cone, events...) is grouped with it under that
    name (a click on it shows or hides both), and listed once."""
    xa, ya = _axis_names(k)
    out = []
    for t in (t for i in items for t in item_to_traces(i)):
        shared = {"legendgroup": t.get("legendgroup", f"name: {t['name']}")} if k < 2 and t["showlegend"] else {}
        out.append({**t, **shared, "xaxis": xa, "yaxis": ya})
    return out


def _list_once(data: list[dict[str, Any]]) -> list[dict[str, Any]]:
    """``data`` with each legend entry listed once (the first trace of its name)."""
    seen: set[str] = set()
    out = []
    for t in data:
        if t["showlegend"] and t["name"] in seen:
            t = {**t, "showlegend": False}
        if t["showlegend"]:
            seen.add(t["name"])
        out.append(t)
    return out


def _moving_items(state: LiveState) -> tuple[tuple[Item, ...], ...]:
    """What the time slider moves on each panel: the core's rod ends at ``now`` in the lab and in the
    chosen frame, and the now-lines and length markers the app draws from them."""
    d = state.drawn
    r = d.resolved
    instant = d.ride_instant(state.now)  # riding a point: its comoving frame at its event at lab time now
    lower = (state.now, r.frame) if instant is None else (instant.event[0], instant.frame)
    ends = [r.scene.snapshot(t, frame=f, fractions=_ENDS)[0] for t, f in ((state.now, rr.LAB), lower)]
    return d.moving_items(state.now, ends, instant)


def _light_moving_traces(state: LiveState) -> list[dict[str, Any]]:
    return [t for k, items in enumerate(_moving_items(state)) for t in _panel_traces(items, k)]


def _shaded(fig: dict[str, Any], shade: Shade) -> dict[str, Any]:
    """:func:`shaded_figure` of ``fig``, with its traces' ``x`` and ``y`` still the numpy arrays they
    were (not plotly's typed-array dicts): the widget updates them, :func:`figure_arrays` reads them."""
    if shade == "light":
        return fig
    out = shaded_figure(fig, shade)
    out["data"] = [{**t, "x": old["x"], "y": old["y"]} for t, old in zip(out["data"], fig["data"], strict=True)]
    return out


def moving_traces(state: LiveState) -> list[dict[str, Any]]:
    """The traces that follow the time slider, in the order :func:`live_figure` puts them last, in
    the state's shade (their colours those of the same traces of :func:`live_figure`)."""
    return _shaded({"data": _light_moving_traces(state)}, state.shade)["data"]


def static_trace_count(drawn: Drawn) -> int:
    """How many traces of :func:`live_figure` stay put while the time slider moves (they come first)."""
    return sum(len(_panel_traces(chart.items, k)) for k, chart in enumerate(drawn.charts))


def _panel_layout(chart: Chart, k: int) -> dict[str, Any]:
    """Panel ``k``'s axes, labels, title and legend, from the app's own chart layout."""
    own = chart_layout(chart)
    xa, ya = _axis_names(k)
    x_name, y_name = ("xaxis", "yaxis") if k == 0 else (f"xaxis{k + 1}", f"yaxis{k + 1}")
    (x0, x1), (y0, y1) = PANEL_DOMAINS[k]
    xaxis = {**own["xaxis"], "domain": [x0, x1], "anchor": ya}
    yaxis = {**own["yaxis"], "domain": [y0, y1], "anchor": xa}
    if chart.equal_aspect:
        yaxis["scaleanchor"] = xa
    annotations = [{**label_to_annotation(i), "xref": xa, "yref": ya} for i in chart.items if isinstance(i, Label)]
    annotations.append(
        {
            "text": chart.title.replace(", ", ",<br>", 1),  # two lines: a frame's name with its β is long
            "x": x0,
            "y": y1,
            "xref": "paper",
            "yref": "paper",
            "xanchor": "left",
            "align": "left",
            "yanchor": "bottom",
            "yshift": 6,
            "showarrow": False,
            "font": {"size": TITLE_PX},
        }
    )
    panel = {x_name: xaxis, y_name: yaxis, "annotations": annotations}
    return panel


def live_figure(state: LiveState) -> dict[str, Any]:
    """The three panels as one plotly figure dict (numpy arrays in the traces): the static traces of
    each chart first (:func:`static_trace_count`), then :func:`moving_traces`; on a dark
    :attr:`~LiveState.shade`, every colour lightness-flipped as in the app's dark theme."""
    d = state.drawn
    data = [t for k, chart in enumerate(d.charts) for t in _panel_traces(chart.items, k)]
    data = _list_once(data + _light_moving_traces(state))
    left, right, top, bottom = MARGIN_PX
    layout: dict[str, Any] = {
        "width": FIGURE_PX[0],
        "height": FIGURE_PX[1],
        "margin": {"l": left, "r": right, "t": top, "b": bottom},
        "plot_bgcolor": "white",
        "paper_bgcolor": "white",
        "font": chart_layout(d.length_chart)["font"],
        "showlegend": True,
        "legend": {
            **chart_layout(d.length_chart)["legend"],
            "orientation": "v",
            "x": LEGEND_AT[0],
            "y": LEGEND_AT[1],
            "xanchor": "left",
            "yanchor": "top",
            "tracegroupgap": 0,
        },
        "annotations": [],
    }
    for k, chart in enumerate(d.charts):
        panel = _panel_layout(chart, k)
        layout["annotations"] += panel.pop("annotations")
        layout.update(panel)
    return _shaded({"data": data, "layout": layout}, state.shade)


def parameter_values(state: LiveState) -> Mapping[str, float]:
    """Each slider parameter's slider value in the state (what the sliders should show)."""
    s = state.settings
    return {p.name: control_value(p, s.value(p.name)) for p, _ in slider_parameters(s.scene)}


def figure_arrays(fig: dict[str, Any]) -> list[tuple[np.ndarray, np.ndarray]]:
    """Every trace's ``(x, y)`` as float arrays (for comparing two figures, or a figure with the core)."""
    return [(np.asarray(t["x"], dtype=float), np.asarray(t["y"], dtype=float)) for t in fig["data"]]
