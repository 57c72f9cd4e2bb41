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
import numpy.typing as npt
import plotly.io as pio

import rigidrel_core as rr
from rigidrel_core import SceneKind

from ..diagrams import frame_title, length_static, minkowski_in_frame
from ..draw import Label, item_to_traces, jsonable, label_to_annotation
from ..settings import CUSTOM_FRAME, SCENE_LABELS, Resolved, Settings, resolve

#: Pixel size of the page's plot areas (the diagram and the length plot side by side).
DIAGRAM_PX = (560.0, 520.0)
LENGTH_PX = (420.0, 300.0)


@dataclass(frozen=True)
class SliderAxis:
    """One page slider: which field of :class:`Settings` it sets, to which values."""

    name: str
    field: str
    values: tuple[float, ...]
    fmt: Callable[[float], str]

    def apply(self, s: Settings, value: float) -> Settings:
        """``s`` with this slider at ``value`` (the frame slider also selects the custom frame)."""
        extra = {"frame": CUSTOM_FRAME} if self.field == "beta" else {}
        return replace(s, **{self.field: value}, **extra)

    def index(self, s: Settings) -> int:
        """Where the settings' own value sits among the slider's values."""
        return self.values.index(round(float(getattr(s, self.field)), 4))


def _axis(name: str, field: str, values: npt.ArrayLike, s: Settings, fmt: Callable[[float], str]) -> SliderAxis:
    """A slider over ``values`` and the settings' own value of ``field`` (rounded to 4 digits)."""
    own = round(float(getattr(s, field)), 4)
    steps = {round(v, 4) for v in np.asarray(values, dtype=np.float64).ravel().tolist()}
    return SliderAxis(name, field, tuple(sorted(steps | {own})), fmt)


def slider_axes(s: Settings) -> tuple[SliderAxis, SliderAxis]:
    """What the two sliders vary for this scene, around the settings' own values."""
    if s.scene is SceneKind.ROD_COLLISION:
        a = _axis("V1", "v", np.linspace(max(0.05, s.v2 + 0.05), 0.95, 9), s, "{:.2f}".format)
        ratios = np.log10([0.25, 0.5, 1.0, 2.0, 4.0])
        return a, _axis("M2/M1", "log_mass_ratio", ratios, s, lambda v: f"{10**v:.3g}")
    a = _axis("V", "v", np.linspace(0.1, 0.9, 9), s, "{:.2f}".format)
    if s.scene is SceneKind.WALL_COLLISION:
        return a, _axis("ε", "eps", np.linspace(0.0, 1.0, 5), s, "{:.2f}".format)
    return a, _axis("frame β", "beta", (-0.8, -0.5, 0.0, 0.5, 0.8), s, "{:+.2f}".format)


def _panels(r: Resolved) -> tuple[list[dict[str, Any]], list[dict[str, Any]], dict[str, Any]]:
    """Traces, annotations and axis ranges of the diagram (in the resolved frame) and the length plot."""
    scene, frame = r.scene, r.frame
    diagram = minkowski_in_frame(scene, frame, DIAGRAM_PX, r.overlay)
    lengths = length_static(scene, rr.Frame.lab(), frame, scene.time_window(frame), LENGTH_PX)
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
    start = f"{a.index(settings)}_{b.index(settings)}"
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
            jsonable(fig),
            include_plotlyjs=True,
            full_html=True,
            post_script=_SCRIPT,
            auto_play=False,
            config={"displaylogo": False, "responsive": False},
            validate=False,
        )
    )
