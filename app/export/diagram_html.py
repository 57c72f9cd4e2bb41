"""A standalone page with the Minkowski diagram and the length plot, explorable without a server.

Two plotly sliders pick precomputed parameter values (slider A: V or V1; slider B: the
frame's velocity, epsilon, or the mass ratio, by scene); every combination is a plotly
animation frame computed by the core. A few lines of client-side script combine the two
sliders into a frame name, and the play button sweeps slider A. plotly.js is inlined:
the page works offline.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, replace
from typing import Any

import numpy as np
import plotly.io as pio

import rigidrel_core as rr
from rigidrel_core import SceneKind

from ..diagrams import View, frame_title, length_static, minkowski_static, window_x_range
from ..draw import Chart, Label, dumps, item_to_traces, label_to_annotation
from ..drawing import equal_scale_ranges
from ..settings import CUSTOM_FRAME, SCENE_LABELS, Resolved, Settings, resolve

#: Pixel size of the page's plot areas (the diagram and the length plot side by side).
DIAGRAM_PX = (560.0, 520.0)
LENGTH_PX = (420.0, 300.0)


@dataclass(frozen=True)
class SliderAxis:
    name: str
    values: tuple[float, ...]
    apply: Callable[[Settings, float], Settings]
    fmt: Callable[[float], str]


def _with_value(values: np.ndarray, value: float) -> tuple[float, ...]:
    out = sorted({round(float(v), 4) for v in values} | {round(value, 4)})
    return tuple(out)


def slider_axes(s: Settings) -> tuple[SliderAxis, SliderAxis]:
    """What the two sliders vary for this scene, around the settings' own values."""
    if s.scene is SceneKind.ROD_COLLISION:
        lo = max(0.05, s.v2 + 0.05)
        a = SliderAxis(
            "V1", _with_value(np.linspace(lo, 0.95, 9), s.v), lambda st, v: replace(st, v=v), "{:.2f}".format
        )
        ratios = np.log10([0.25, 0.5, 1.0, 2.0, 4.0])
        b = SliderAxis(
            "M2/M1",
            _with_value(ratios, s.log_mass_ratio),
            lambda st, v: replace(st, log_mass_ratio=v),
            lambda v: f"{10**v:.3g}",
        )
        return a, b
    a = SliderAxis("V", _with_value(np.linspace(0.1, 0.9, 9), s.v), lambda st, v: replace(st, v=v), "{:.2f}".format)
    if s.scene is SceneKind.WALL_COLLISION:
        b = SliderAxis(
            "ε", _with_value(np.linspace(0.0, 1.0, 5), s.eps), lambda st, v: replace(st, eps=v), "{:.2f}".format
        )
    else:
        b = SliderAxis(
            "frame β",
            _with_value(np.array([-0.8, -0.5, 0.0, 0.5, 0.8]), s.beta),
            lambda st, v: replace(st, frame=CUSTOM_FRAME, beta=v),
            "{:+.2f}".format,
        )
    return a, b


def _panels(r: Resolved) -> tuple[list[dict[str, Any]], list[dict[str, Any]], dict[str, Any]]:
    """Traces, annotations and axis ranges of the diagram (in the resolved frame) and the length plot."""
    scene, frame = r.scene, r.frame
    lab = rr.Frame.lab()
    window = scene.time_window(frame)
    x_range, t_range = equal_scale_ranges(window_x_range(scene, (frame,), window), window, DIAGRAM_PX)
    other = lab if frame.key() != lab.key() else frame
    view = View(frame, other, frame.name, "'" if frame.name != "lab" else "", "")
    diagram: Chart = minkowski_static(scene, view, t_range, x_range, DIAGRAM_PX[0], r.overlay)
    lengths: Chart = length_static(scene, lab, frame, window, LENGTH_PX)
    traces: list[dict[str, Any]] = []
    annotations: list[dict[str, Any]] = []
    for chart, xa, ya in ((diagram, "x", "y"), (lengths, "x2", "y2")):
        for item in chart.items:
            for t in item_to_traces(item):
                traces.append({**t, "xaxis": xa, "yaxis": ya})
            if isinstance(item, Label):
                annotations.append({**label_to_annotation(item), "xref": xa, "yref": ya})
    ranges = {
        "xaxis.range": list(diagram.x_range),
        "yaxis.range": list(diagram.y_range),
        "xaxis2.range": list(lengths.x_range),
        "yaxis2.range": list(lengths.y_range),
        "title": f"{SCENE_LABELS[scene.kind]} — Minkowski diagram in the {frame_title(frame)} frame",
    }
    return traces, annotations, ranges


def diagram_figure(settings: Settings) -> dict[str, Any]:
    """The plotly figure (dict) with its frames, sliders and play button."""
    a, b = slider_axes(settings)
    frames: list[dict[str, Any]] = []
    max_traces = 0
    built: dict[str, tuple[list[dict[str, Any]], list[dict[str, Any]], dict[str, Any]]] = {}
    for i, va in enumerate(a.values):
        for j, vb in enumerate(b.values):
            r = resolve(b.apply(a.apply(settings, va), vb))
            if isinstance(r, str):
                continue
            built[f"{i}_{j}"] = _panels(r)
            max_traces = max(max_traces, len(built[f"{i}_{j}"][0]))
    if not built:
        raise rr.ParameterError("parameters", "such that at least one slider combination is a valid scene", settings)
    # start where the settings are (both sliders' value lists contain them)
    start = f"{a.values.index(round(settings.v, 4))}_{b.values.index(_b_value(settings, b))}"
    if start not in built:
        start = next(iter(built))
    empty = {"type": "scatter", "x": [], "y": [], "mode": "lines", "showlegend": False, "hoverinfo": "skip"}
    for name, (traces, anns, ranges) in built.items():
        padded = traces + [empty] * (max_traces - len(traces))
        frames.append(
            {
                "name": name,
                "data": padded,
                "layout": {
                    "annotations": anns,
                    "xaxis": {"range": ranges["xaxis.range"]},
                    "yaxis": {"range": ranges["yaxis.range"]},
                    "xaxis2": {"range": ranges["xaxis2.range"]},
                    "yaxis2": {"range": ranges["yaxis2.range"]},
                    "title": {"text": ranges["title"]},
                },
            }
        )
    first = next(f for f in frames if f["name"] == start)
    i0, j0 = (int(k) for k in start.split("_"))

    def slider(axis: SliderAxis, active: int, y: float) -> dict[str, Any]:
        return {
            "active": active,
            "y": y,
            "x": 0.08,
            "len": 0.86,
            "pad": {"t": 10, "b": 0},
            "currentvalue": {"prefix": f"{axis.name} = ", "font": {"size": 13}},
            "steps": [{"label": axis.fmt(v), "method": "skip", "args": [None]} for v in axis.values],
        }

    layout = {
        "title": {"text": first["layout"]["title"]["text"], "x": 0.01, "font": {"size": 15}},
        "xaxis": {
            "domain": [0.0, 0.56],
            "title": {"text": "x (rest lengths of rod 1, c = 1)"},
            "zeroline": False,
            "range": first["layout"]["xaxis"]["range"],
        },
        "yaxis": {
            "title": {"text": "t"},
            "scaleanchor": "x",
            "scaleratio": 1,
            "zeroline": False,
            "range": first["layout"]["yaxis"]["range"],
        },
        "xaxis2": {
            "domain": [0.64, 1.0],
            "title": {"text": "time in its own frame"},
            "anchor": "y2",
            "range": first["layout"]["xaxis2"]["range"],
        },
        "yaxis2": {
            "title": {"text": "equal-time length"},
            "anchor": "x2",
            "domain": [0.35, 1.0],
            "range": first["layout"]["yaxis2"]["range"],
        },
        "annotations": first["layout"]["annotations"],
        "sliders": [slider(a, i0, -0.12), slider(b, j0, -0.3)],
        "updatemenus": [
            {
                "type": "buttons",
                "showactive": False,
                "x": 0.0,
                "y": -0.12,
                "xanchor": "right",
                "yanchor": "top",
                "buttons": [{"label": f"▶ {a.name}", "method": "skip", "args": [None]}],
            }
        ],
        "legend": {"orientation": "h", "y": 1.08, "x": 0.0, "font": {"size": 10}},
        "margin": {"l": 60, "r": 20, "t": 90, "b": 190},
        "plot_bgcolor": "white",
        "width": 1100,
        "height": 820,
        "meta": {"slider_a_count": len(a.values), "slider_b_count": len(b.values)},
    }
    return {"data": first["data"], "layout": layout, "frames": frames}


def _b_value(s: Settings, b: SliderAxis) -> float:
    probe = b.apply(s, 0.123456)
    for name in ("beta", "eps", "log_mass_ratio"):
        if getattr(probe, name) == 0.123456:
            return round(float(getattr(s, name)), 4)
    return 0.0


_SCRIPT = """
var gd = document.getElementById('{plot_id}');
var NA = gd.layout.meta.slider_a_count;
// Each slider combination is a precomputed frame; show it with Plotly.react (no tweening:
// Plotly.animate leaves an unhandled rejection on its first call).
function show(i, j) {
  var frame = gd._transitionData._frameHash[i + '_' + j];
  if (!frame) { return; }
  var layout = Object.assign({}, gd.layout, {annotations: frame.layout.annotations,
    title: Object.assign({}, gd.layout.title, frame.layout.title)});
  ['xaxis', 'yaxis', 'xaxis2', 'yaxis2'].forEach(function (ax) {
    layout[ax] = Object.assign({}, gd.layout[ax], {range: frame.layout[ax].range});
  });
  layout.sliders = gd.layout.sliders.map(function (s, k) { return Object.assign({}, s, {active: k ? j : i}); });
  Plotly.react(gd, frame.data, layout);
}
gd.on('plotly_sliderchange', function () {
  show(gd.layout.sliders[0].active, gd.layout.sliders[1].active);
});
gd.on('plotly_buttonclicked', function () {
  var j = gd.layout.sliders[1].active, i = 0;
  (function step() {
    if (i >= NA) { return; }
    show(i, j);
    i += 1;
    setTimeout(step, 600);
  })();
});
"""


def diagram_html(settings: Settings) -> str:
    """The standalone page (plotly.js inlined: no network needed)."""
    fig = diagram_figure(settings)
    return str(
        pio.to_html(
            dumps_free(fig),
            include_plotlyjs=True,
            full_html=True,
            post_script=_SCRIPT,
            auto_play=False,
            config={"displaylogo": False, "responsive": False},
            validate=False,
        )
    )


def dumps_free(fig: dict[str, Any]) -> dict[str, Any]:
    """The figure with numpy arrays as plotly typed-array dicts (what ``pio.to_html`` serialises)."""
    import json

    return json.loads(dumps(fig))
