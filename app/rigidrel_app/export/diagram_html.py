"""A standalone page with the Minkowski diagram and the length plot, explorable without a server.

Two plotly sliders pick precomputed parameter values, generated from the scene's
description: slider A is the scene's first slider parameter (V, V1, ...), slider B its
second one, or the frame's velocity for a scene with one slider. Every combination is a
plotly animation frame computed by the core. A few lines of client-side script combine
the two sliders into a frame name, and the play button sweeps slider A. plotly.js is
inlined: the page works offline.
"""

from __future__ import annotations

import html
import math
from collections.abc import Callable
from dataclasses import dataclass, replace
from typing import Any, Literal

import plotly.io as pio

import rigidrel_core as rr

from ..backends.plotly import (
    LABEL_PX,
    TICK_PX,
    TITLE_PX,
    item_to_traces,
    jsonable,
    label_to_annotation,
    shaded_figure,
)
from ..view.diagrams import LENGTH_TIME_TITLE, frame_title, length_static, minkowski_in_frame
from ..view.state import CUSTOM_BETA, CUSTOM_FRAME, Resolved, Settings, resolve
from ..view.vocabulary import Label, Shade

#: The page's figure (CSS pixels): fits a 1280x720 projector without scrolling.
PAGE_PX = (1240, 700)
#: Margins around the plots (left, right, top, bottom): the title above, the two sliders below.
MARGIN_PX = (70, 30, 60, 140)
#: Horizontal domains (fractions of the plot width) of the diagram and the length plot, and the
#: length plot's vertical domain (the legend sits below it).
DIAGRAM_DOMAIN = (0.0, 0.5)
LENGTH_DOMAIN = (0.6, 1.0)
LENGTH_Y_DOMAIN = (0.45, 1.0)
#: The sliders side by side under the plots (paper fractions: slider A, slider B).
SLIDER_X = ((0.1, 0.38), (0.6, 0.38))
#: Where the two legends start (paper fractions): the diagram's items, the length curves.
LEGEND_X = (0.6, 0.8)
_PLOT_W = PAGE_PX[0] - MARGIN_PX[0] - MARGIN_PX[1]
_PLOT_H = PAGE_PX[1] - MARGIN_PX[2] - MARGIN_PX[3]
#: Pixel size of the page's plot areas (the diagram and the length plot side by side): labels are placed for these.
DIAGRAM_PX = ((DIAGRAM_DOMAIN[1] - DIAGRAM_DOMAIN[0]) * _PLOT_W, float(_PLOT_H))
LENGTH_PX = ((LENGTH_DOMAIN[1] - LENGTH_DOMAIN[0]) * _PLOT_W, (LENGTH_Y_DOMAIN[1] - LENGTH_Y_DOMAIN[0]) * _PLOT_H)
#: Round values per slider (besides the settings' own): every pair is a precomputed frame of the page.
SLIDER_A_STEPS = 9
SLIDER_B_STEPS = 5
#: Values of the frame slider (slider B of a scene with one slider parameter).
FRAME_STEPS = 7
#: The frame velocities of slider B for a scene with a single slider parameter: even steps over the
#: app's β slider.
FRAME_SLIDER = rr.Slider(CUSTOM_BETA[0], CUSTOM_BETA[1], 0.01)


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
        """The settings' value of this slider: the parameter's, or the velocity of the settings' frame."""
        return slider_own(s, self.parameter)

    def index(self, s: Settings) -> int:
        """Where the settings' own value sits among the slider's values."""
        own = self.own(s)
        return self.values.index(own) if own in self.values else 0


def slider_own(s: Settings, parameter: str | None) -> float | None:
    """The settings' value of a page slider (rounded to 4 digits): ``parameter``'s, or for the frame
    slider (``None``) the velocity of the frame the settings resolve to (a preset such as "rod after"
    too), so that the page opens on the settings' own frame."""
    if parameter is not None:
        v = s.value(parameter)
    elif s.frame == CUSTOM_FRAME:
        v = s.beta
    else:
        r = resolve(s)
        v = None if isinstance(r, str) else r.frame.beta
    return None if v is None else round(float(v), 4)


def _even_grid(lo: float, hi: float, step: float, own: float | None, log: bool) -> tuple[float, ...]:
    """Values ``step`` apart (factors of ``10**step`` on a log slider) in ``[lo, hi]``: multiples of
    the step, or, when ``own`` is not one, the grid through ``own``."""
    f = math.log10 if log else float
    a, b = f(lo), f(hi)
    origin = 0.0 if own is None or _on_grid(f(own), step) else f(own)
    first = math.ceil((a - origin) / step - 1e-9)
    last = math.floor((b - origin) / step + 1e-9)
    grid = [origin + k * step for k in range(first, last + 1)]
    return tuple(round(10.0**g if log else g, 6) for g in grid)


def _on_grid(v: float, step: float) -> bool:
    k = round(v / step)
    return abs(v - k * step) <= 1e-9 * max(1.0, abs(v))


def page_values(slider: rr.Slider, most: int, own: float | None = None) -> tuple[float, ...]:
    """At most ``most`` evenly spaced round values across a slider's range, so that the slider's
    ticks step evenly: steps of 1, 2, 2.5, 3, 4 or 5 times a power of ten (linear), or whole decades
    (log). ``own`` (the settings' value) is always among them: the grid is the finest that holds it,
    else the finest one shifted to pass through it."""
    log = slider.scale == "log"
    if log:
        steps: list[float] = [1.0, 2.0, 3.0, 4.0, 5.0]
    else:
        steps = [m * 10.0**k for k in range(-3, 4) for m in (1.0, 2.0, 2.5, 3.0, 4.0, 5.0)]

    def finest(grids: list[tuple[float, ...]]) -> tuple[float, ...] | None:
        fitting = [g for g in grids if 2 <= len(g) <= most]
        return max(fitting, key=len) if fitting else None

    if own is not None:  # the exports take values beyond the app's slider (a frame at β = -0.995)
        slider = replace(slider, lo=min(slider.lo, own), hi=max(slider.hi, own))
    own_g = None if own is None else (math.log10(own) if log else own)
    on_grid = [st for st in steps if own_g is None or _on_grid(own_g, st)]
    chosen = finest([_even_grid(slider.lo, slider.hi, st, None, log) for st in on_grid])
    if chosen is None and own is not None:
        chosen = finest([_even_grid(slider.lo, slider.hi, st, own, log) for st in steps])
    return chosen if chosen is not None else (slider.lo, slider.hi)


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
        own = s.value(p.name)
        axes.append(_axis(p.label, p.name, page_values(p.slider, most, own), s, fmt))
    if len(axes) < 2:
        values = page_values(FRAME_SLIDER, FRAME_STEPS, slider_own(s, None))
        axes.append(_axis("frame β", None, values, s, lambda v: f"{v:+.2f}"))
    return axes[0], axes[1]


def _panels(r: Resolved) -> tuple[list[dict[str, Any]], list[dict[str, Any]], dict[str, Any]]:
    """Traces, annotations and axis ranges of the diagram (in the resolved frame) and the length plot."""
    scene, frame = r.scene, r.frame
    diagram = minkowski_in_frame(scene, frame, DIAGRAM_PX, r.overlay, layers=r.layers)
    lengths = length_static(scene, rr.LAB, frame, scene.time_window(frame=frame), LENGTH_PX)
    traces: list[dict[str, Any]] = []
    annotations: list[dict[str, Any]] = []
    for chart, xa, ya, legend in ((diagram, "x", "y", "legend"), (lengths, "x2", "y2", "legend2")):
        for item in chart.items:
            for t in item_to_traces(item):
                traces.append({**t, "xaxis": xa, "yaxis": ya, "legend": legend})
            if isinstance(item, Label):
                annotations.append({**label_to_annotation(item), "xref": xa, "yref": ya})
    ranges = {
        "x_title": f"{diagram.x_title} (in the scene's length unit, c = 1)",
        "t_title": diagram.y_title,
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
                    "xaxis": {"range": ranges["xaxis.range"], "title": {"text": ranges["x_title"]}},
                    "yaxis": {"range": ranges["yaxis.range"], "title": {"text": ranges["t_title"]}},
                    "xaxis2": {"range": ranges["xaxis2.range"]},
                    "yaxis2": {"range": ranges["yaxis2.range"]},
                    "title": {"text": ranges["title"]},
                },
            }
        )
    first = next(f for f in frames if f["name"] == start)
    i0, j0 = (int(k) for k in start.split("_"))

    left, right, top, bottom = MARGIN_PX
    # the sliders sit below the diagram's x-axis title, in pixels converted to paper fractions
    plot_h = PAGE_PX[1] - top - bottom
    title_font = {"size": TITLE_PX}
    tick_font = {"size": TICK_PX}

    def slider(axis: SliderAxis, active: int, place: tuple[float, float]) -> dict[str, Any]:
        return {
            "active": active,
            "y": slider_y,
            "yanchor": "top",
            "x": place[0],
            "lenmode": "pixels",  # a fraction is measured against a plot width plotly may not have settled yet
            "len": place[1] * _PLOT_W,
            "pad": {"t": 0, "b": 0},
            "font": tick_font,
            "currentvalue": {"prefix": f"{axis.name} = ", "font": {"size": LABEL_PX}},
            "steps": [{"label": axis.fmt(v), "method": "skip", "args": [None]} for v in axis.values],
        }

    def axis(title: str, rng: list[float], **extra: Any) -> dict[str, Any]:
        return {
            "title": {"text": title, "font": title_font},
            "tickfont": tick_font,
            "zeroline": False,
            "range": rng,
            "gridcolor": "#e6e6e6",
            "linecolor": "#999",
            "mirror": True,
            "ticks": "outside",
            **extra,
        }

    fl = first["layout"]

    def legend(x: float) -> dict[str, Any]:
        y = LENGTH_Y_DOMAIN[0] - 74.0 / plot_h
        return {
            "orientation": "v",
            "x": x,
            "xanchor": "left",
            "y": y,
            "yanchor": "top",
            "tracegroupgap": 0,
            "font": tick_font,
        }

    slider_y = -64.0 / plot_h
    layout = {
        "title": {"text": fl["title"]["text"], "x": 0.01, "y": 0.975, "font": {"size": 18}},
        "xaxis": axis(fl["xaxis"]["title"]["text"], fl["xaxis"]["range"], domain=list(DIAGRAM_DOMAIN)),
        "yaxis": axis(fl["yaxis"]["title"]["text"], fl["yaxis"]["range"], scaleanchor="x", scaleratio=1),
        "xaxis2": axis(LENGTH_TIME_TITLE, fl["xaxis2"]["range"], domain=list(LENGTH_DOMAIN), anchor="y2"),
        "yaxis2": axis("equal-time length", fl["yaxis2"]["range"], domain=list(LENGTH_Y_DOMAIN), anchor="x2"),
        "annotations": fl["annotations"],
        "sliders": [slider(a, i0, SLIDER_X[0]), slider(b, j0, SLIDER_X[1])],
        "updatemenus": [
            {
                "type": "buttons",
                "showactive": False,
                "x": 0.0,
                "y": slider_y,
                "xanchor": "left",
                "yanchor": "top",
                "pad": {"t": 22},
                "font": tick_font,
                "buttons": [{"label": f"▶ {a.name}", "method": "skip", "args": [None]}],
            }
        ],
        # two vertical legends under the length plot (the diagram's items, then the length curves):
        # inside the plot area, so that they push no margin (plotly would then place the sliders
        # against a plot width it has not settled)
        "legend": legend(LEGEND_X[0]),
        "legend2": legend(LEGEND_X[1]),
        "font": tick_font,
        "margin": {"l": left, "r": right, "t": top, "b": bottom},
        "plot_bgcolor": "white",
        "width": PAGE_PX[0],
        "height": PAGE_PX[1],
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
    var own = {range: frame.layout[ax].range};
    if (frame.layout[ax].title) {  // the diagram's axes: t, x in the lab, t′, x′ in another frame
      own.title = Object.assign({}, gd.layout[ax].title, {text: frame.layout[ax].title.text});
    }
    layout[ax] = Object.assign({}, gd.layout[ax], own);
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


def diagram_html(settings: Settings, plotly_js: Literal["inline", "beside"] = "inline", shade: Shade = "light") -> str:
    """The standalone page. ``plotly_js``: ``"inline"`` puts plotly.js in the page (no network, one
    file); ``"beside"`` loads ``plotly.min.js`` from the page's folder (a page set shares one copy);
    ``shade``: its ground (dark: every colour lightness-flipped, :func:`shaded_figure`)."""
    fig = shaded_figure(diagram_figure(settings), shade)
    include: Any = True if plotly_js == "inline" else "directory"  # plotly's annotation says bool only
    page = str(
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
    # centred on a wide screen (the figure has a fixed size: its labels are placed for it)
    if shade == "dark":  # the page around the figure black too
        page = page.replace("<head>", "<head><style>html, body { background: #000000; }</style>", 1)
    title = html.escape(f"{settings.description.title}: Minkowski diagrams and the equal-time length")
    page = page.replace("<html>", '<html lang="en">', 1).replace("<head>", f"<head><title>{title}</title>", 1)
    return page.replace("<body>", f'<body style="margin: 8px auto; width: {PAGE_PX[0]}px">', 1)
