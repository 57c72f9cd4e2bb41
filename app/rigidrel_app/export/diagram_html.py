"""A standalone page with the Minkowski diagram and the length plot, explorable without a server.

Two plotly sliders pick precomputed parameter values, generated from the scene's
description: slider A is the scene's first slider parameter (V, V1, ...), slider B its
second one, or the frame's velocity for a scene with one slider. Every combination is a
plotly animation frame computed by the core. A few lines of client-side script combine
the two sliders into a frame name, and the play button sweeps slider A. plotly.js is
inlined: the page works offline.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, replace
from typing import Any, Literal

import plotly.io as pio

import rigidrel_core as rr

from ..backends.plotly import item_to_traces, jsonable, label_to_annotation
from ..view.diagrams import frame_title, length_static, minkowski_in_frame
from ..view.state import CUSTOM_FRAME, Resolved, Settings, resolve
from ..view.vocabulary import Label

#: Pixel size of the page's plot areas (the diagram and the length plot side by side).
DIAGRAM_PX = (560.0, 520.0)
LENGTH_PX = (420.0, 300.0)
#: Round values per slider (besides the settings' own): every pair is a precomputed frame of the page.
SLIDER_A_STEPS = 9
SLIDER_B_STEPS = 5
#: The frame velocities of slider B for a scene with a single slider parameter.
FRAME_BETAS = (-0.8, -0.5, 0.0, 0.5, 0.8)


@dataclass(frozen=True)
class SliderAxis:
    """One page slider: the scene parameter it sets (``None``: the custom frame's velocity), and its values."""

    name: str
    parameter: str | None
    values: tuple[float, ...]
    fmt: Callable[[float], str]

    def apply(self, s: Settings, value: float) -> Settings:
        """``s`` with this slider at ``value`` (the frame slider also selects the custom frame)."""
        if self.parameter is None:
            return replace(s, frame=CUSTOM_FRAME, beta=value)
        return s.with_value(self.parameter, value)

    def own(self, s: Settings) -> float | None:
        v = s.beta if self.parameter is None else s.value(self.parameter)
        return None if v is None else round(float(v), 4)

    def index(self, s: Settings) -> int:
        """Where the settings' own value sits among the slider's values."""
        own = self.own(s)
        return self.values.index(own) if own in self.values else 0


def page_values(slider: rr.Slider, most: int) -> tuple[float, ...]:
    """At most ``most`` round values across a slider's range: steps of 1, 2, 2.5 or 5 times a power of
    ten (linear), or powers of ten, thinned evenly (log)."""
    if slider.scale == "log":
        lo, hi = math.ceil(math.log10(slider.lo) - 1e-9), math.floor(math.log10(slider.hi) + 1e-9)
        decades = list(range(lo, hi + 1))
        stride = max(1, math.ceil((len(decades) - 1) / max(most - 1, 1)))
        return tuple(10.0**k for k in decades[::stride])
    for step in (m * 10.0**k for k in range(-3, 4) for m in (1.0, 2.0, 2.5, 5.0)):
        first = math.ceil(slider.lo / step - 1e-9)
        last = math.floor(slider.hi / step + 1e-9)
        if last - first + 1 <= most:
            return tuple(round(k * step, 6) for k in range(first, last + 1))
    return (slider.lo, slider.hi)


def _axis(
    name: str, parameter: str | None, values: tuple[float, ...], s: Settings, fmt: Callable[[float], str]
) -> SliderAxis:
    axis = SliderAxis(name, parameter, (), fmt)
    own = axis.own(s)
    steps = {round(v, 4) for v in values} | ({own} if own is not None else set())
    return SliderAxis(name, parameter, tuple(sorted(steps)), fmt)


def slider_axes(s: Settings) -> tuple[SliderAxis, SliderAxis]:
    """What the two sliders vary for this scene (its first two slider parameters, or the first and the
    frame's velocity), around the settings' own values."""
    params = [p for p in s.description.parameters if p.slider is not None and s.value(p.name) is not None]
    axes: list[SliderAxis] = []
    for p, most in zip(params[:2], (SLIDER_A_STEPS, SLIDER_B_STEPS), strict=False):
        assert p.slider is not None
        fmt = (lambda v: f"{v:.3g}") if p.slider.scale == "log" else (lambda v: f"{v:.2f}")
        axes.append(_axis(p.label, p.name, page_values(p.slider, most), s, fmt))
    if len(axes) < 2:
        axes.append(_axis("frame β", None, FRAME_BETAS, s, lambda v: f"{v:+.2f}"))
    return axes[0], axes[1]


def _panels(r: Resolved) -> tuple[list[dict[str, Any]], list[dict[str, Any]], dict[str, Any]]:
    """Traces, annotations and axis ranges of the diagram (in the resolved frame) and the length plot."""
    scene, frame = r.scene, r.frame
    diagram = minkowski_in_frame(scene, frame, DIAGRAM_PX, r.overlay)
    lengths = length_static(scene, rr.LAB, frame, scene.time_window(frame), LENGTH_PX)
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
        "title": f"{rr.describe(scene).title} — Minkowski diagram in the {frame_title(frame)} frame",
    }
    return traces, annotations, ranges


def diagram_figure(settings: Settings) -> dict[str, Any]:
    """The plotly figure (dict) with its frames, sliders and play button."""
    a, b = slider_axes(settings)
    valid = {
        (va, vb): r
        for va in a.values
        for vb in b.values
        if not isinstance(r := resolve(b.apply(a.apply(settings, va), vb)), str)
    }
    if not valid:
        raise rr.ParameterError("parameters", "such that at least one slider combination is a valid scene", settings)
    # a slider step that shows no valid scene for any value of the other slider is left out
    a = replace(a, values=tuple(va for va in a.values if any(k[0] == va for k in valid)))
    b = replace(b, values=tuple(vb for vb in b.values if any(k[1] == vb for k in valid)))
    frames: list[dict[str, Any]] = []
    built: dict[str, tuple[list[dict[str, Any]], list[dict[str, Any]], dict[str, Any]]] = {}
    for (va, vb), r in valid.items():
        built[f"{a.values.index(va)}_{b.values.index(vb)}"] = _panels(r)
    max_traces = max(len(p[0]) for p in built.values())
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


def diagram_html(settings: Settings, plotly_js: Literal["inline", "beside"] = "inline") -> str:
    """The standalone page. ``plotly_js``: ``"inline"`` puts plotly.js in the page (no network, one
    file); ``"beside"`` loads ``plotly.min.js`` from the page's folder (a page set shares one copy)."""
    fig = diagram_figure(settings)
    include: Any = True if plotly_js == "inline" else "directory"  # plotly's annotation says bool only
    return str(
        pio.to_html(
            jsonable(fig),
            include_plotlyjs=include,
            full_html=True,
            post_script=_SCRIPT,
            auto_play=False,
            config={"displaylogo": False, "responsive": False},
            validate=False,
        )
    )
