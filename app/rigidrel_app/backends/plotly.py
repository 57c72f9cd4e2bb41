"""The plotly backend of the drawing vocabulary: charts as plotly figure dicts and JSON.

No go.Figure objects (no validation cost): traces and layouts are plain dicts, numpy arrays
are sent as plotly.js typed arrays (base64 float64: exact and compact).
"""

from __future__ import annotations

import base64
import json
import re
from collections.abc import Sequence
from typing import Any

import numpy as np

from ..view.vocabulary import (
    Area,
    Chart,
    FloatArray,
    Item,
    Label,
    Points,
    Polyline,
    Segments,
    Shade,
    Style,
    lightness_flipped,
    shaded,
)

#: The app's plotly config, sent with every figure: no mode bar, resize with the panel.
APP_CONFIG: dict[str, Any] = {"displayModeBar": False, "responsive": True}
#: Smallest sizes drawn (CSS pixels), for a projected page read from the back of a hall: tick labels
#: and legend, titles and labels, line widths.
TICK_PX = 14.0
TITLE_PX = 16.0
LABEL_PX = 16.0
LINE_PX = 2.5
#: A leader line joining a label moved away from its point (placement found no free spot beside it).
LEADER_PX = 1.5


def _plotly_line(style: Style) -> dict[str, Any]:
    """Plotly line attributes, at least :data:`LINE_PX` wide. ``simplify`` off: plotly would otherwise
    drop vertices it judges collinear (about a pixel), undoing the sampler's chord tolerance and
    leaving visible corners."""
    return {"color": style.color, "width": max(style.width, LINE_PX), "dash": style.dash, "simplify": False}


def item_to_traces(item: Item) -> list[dict[str, Any]]:
    """One vocabulary item as plotly trace dicts (no go.Figure: no validation cost)."""
    s = item.style
    base: dict[str, Any] = {
        "type": "scatter",
        "opacity": s.opacity,
        "showlegend": s.name is not None,
        "hoverinfo": "skip",
    }
    if s.name is not None:
        base["name"] = s.name
    if s.group is not None:
        base["legendgroup"] = s.group
    if isinstance(item, Polyline):
        return [{**base, "x": item.x, "y": item.y, "mode": "lines", "line": _plotly_line(s)}]
    if isinstance(item, Segments):
        n = item.x0.size
        x = np.empty(3 * n)
        y = np.empty(3 * n)
        x[0::3], x[1::3], x[2::3] = item.x0, item.x1, np.nan
        y[0::3], y[1::3], y[2::3] = item.y0, item.y1, np.nan
        return [{**base, "x": x, "y": y, "mode": "lines", "line": _plotly_line(s)}]
    if isinstance(item, Area):
        return [
            {
                **base,
                "x": item.x,
                "y": item.y,
                "mode": "lines",
                "fill": "toself",
                "fillcolor": s.color,
                "line": {"width": 0},
            }
        ]
    if isinstance(item, Points):
        return [
            {
                **base,
                "x": item.x,
                "y": item.y,
                "mode": "markers",
                "marker": {"color": s.color, "size": item.size, "symbol": item.symbol},
            }
        ]
    return []  # labels become annotations


def label_to_annotation(label: Label) -> dict[str, Any]:
    """A label as a plotly annotation, at least :data:`LABEL_PX` high. A placed label (``offset_px``)
    is centred that far from its point, joined to it by a leader line if it has one."""
    ann: dict[str, Any] = {
        "x": label.x,
        "y": label.y,
        "text": label.text,
        "showarrow": False,
        "xanchor": label.anchor,
        "yanchor": "middle",
        "font": {"color": label.style.color, "size": max(label.size, LABEL_PX)},
    }
    if label.offset_px is None:
        ann["xshift"] = 6 if label.anchor == "left" else (-6 if label.anchor == "right" else 0)
        return ann
    dx, dy = label.offset_px
    ann["xanchor"] = "center"
    if label.leader:  # the text's centre at the arrow's tail, (ax, ay) pixels from the point (y down)
        ann.update(
            {
                "showarrow": True,
                "arrowhead": 0,
                "arrowwidth": LEADER_PX,
                "arrowcolor": label.style.color,
                "standoff": 4,
                "ax": dx,
                "ay": -dy,
            }
        )
    else:
        ann.update({"xshift": dx, "yshift": dy})
    return ann


def chart_layout(chart: Chart, height: int | None = None) -> dict[str, Any]:
    layout: dict[str, Any] = {
        "margin": {"l": 60, "r": 10, "t": 34 if chart.title else 8, "b": 96},
        "xaxis": {"title": {"text": chart.x_title}, "range": list(chart.x_range), "zeroline": False},
        "yaxis": {"title": {"text": chart.y_title}, "range": list(chart.y_range), "zeroline": False},
        "showlegend": True,
        "legend": {"orientation": "h", "yanchor": "top", "y": -0.26, "x": 0, "font": {"size": TICK_PX}},
        "plot_bgcolor": "white",
        "paper_bgcolor": "white",
        "font": {"size": TICK_PX},
        "annotations": [label_to_annotation(i) for i in chart.items if isinstance(i, Label)],
    }
    if chart.title:
        layout["title"] = {"text": chart.title, "x": 0.02, "y": 0.98, "font": {"size": TITLE_PX}}
    if chart.equal_aspect:
        layout["yaxis"]["scaleanchor"] = "x"
        layout["yaxis"]["scaleratio"] = 1
    for ax in ("xaxis", "yaxis"):
        layout[ax].update(
            {
                "gridcolor": "#e6e6e6",
                "linecolor": "#999",
                "mirror": True,
                "ticks": "outside",
                "tickfont": {"size": TICK_PX},
                "title": {"text": layout[ax]["title"]["text"], "font": {"size": TITLE_PX}},
            }
        )
    if not chart.x_title and not chart.y_title:  # a hidden panel's note: no axes
        for ax in ("xaxis", "yaxis"):
            layout[ax].update({"visible": False})
    if height is not None:
        layout["height"] = height
    return layout


#: plotly's own colours where a figure leaves them out, made explicit before a figure is shaded
#: (so that a dark figure has no dark-grey text or white slider left of plotly's defaults).
_LAYOUT_DEFAULTS: dict[str, Any] = {"paper_bgcolor": "#FFFFFF", "plot_bgcolor": "#FFFFFF", "font": {"color": "#222222"}}
_AXIS_DEFAULTS = {"gridcolor": "#EEEEEE", "linecolor": "#444444", "zerolinecolor": "#444444", "tickcolor": "#444444"}
_MENU_DEFAULTS = {"bgcolor": "#F4FAFF", "bordercolor": "#BEC8D9", "font": {"color": "#222222"}}
_SLIDER_DEFAULTS = {
    "bgcolor": "#F8FAFC", "activebgcolor": "#DBDDE0", "bordercolor": "#BEC8D9", "tickcolor": "#333333",
    "font": {"color": "#222222"}, "currentvalue": {"font": {"color": "#222222"}},
}  # fmt: skip
_NAMED = {"white": "#FFFFFF", "black": "#000000"}
_RGB = re.compile(r"rgba?\(\s*(\d+)\s*,\s*(\d+)\s*,\s*(\d+)\s*(?:,\s*([\d.]+)\s*)?\)")


def _flipped_color(value: str) -> str:
    """One plotly colour (``#RGB``, ``#RRGGBB``, ``rgb()``, ``rgba()``, white, black) as the dark
    ground shows it (:func:`~rigidrel_app.view.vocabulary.shaded`); any other string is left as it is."""
    v = _NAMED.get(value.strip().lower(), value.strip())
    if re.fullmatch(r"#[0-9A-Fa-f]{3}", v):
        v = "#" + "".join(2 * ch for ch in v[1:])
    if re.fullmatch(r"#[0-9A-Fa-f]{6}", v):
        return shaded(v, "dark")
    m = _RGB.fullmatch(v)
    if m is None:
        return value
    r, g, b = (int(c) for c in lightness_flipped([int(c) for c in m.groups()[:3]]))
    return f"rgba({r},{g},{b},{m.group(4)})" if m.group(4) is not None else f"rgb({r},{g},{b})"


def _with_defaults(target: dict[str, Any], defaults: dict[str, Any]) -> None:
    for key, value in defaults.items():
        if isinstance(value, dict):
            _with_defaults(target.setdefault(key, {}), value)  # pyright: ignore[reportUnknownArgumentType]
        else:
            target.setdefault(key, value)


def _flipped_tree(node: Any) -> Any:
    """A figure's JSON with every value of a key ending in "color" flipped (:func:`_flipped_color`)."""
    if isinstance(node, dict):
        return {
            k: _flipped_color(v) if isinstance(v, str) and k.endswith("color") else _flipped_tree(v)
            for k, v in node.items()  # pyright: ignore[reportUnknownVariableType]
        }
    if isinstance(node, list):
        return [_flipped_tree(v) for v in node]  # pyright: ignore[reportUnknownVariableType]
    return node


def shaded_figure(fig: dict[str, Any], shade: Shade) -> dict[str, Any]:
    """A copy of a plotly figure dict drawn on a ``shade`` ground. Dark: every colour in it (traces,
    annotations, axes, sliders, buttons, frames) lightness-flipped, the same hue with dark and light
    swapped, as the live app's dark theme (:func:`~rigidrel_app.view.vocabulary.lightness_flipped`);
    plotly's defaults are made explicit first. Light: ``fig`` itself."""
    if shade == "light":
        return fig
    fig = json.loads(dumps(fig))
    layout = fig.setdefault("layout", {})
    _with_defaults(layout, _LAYOUT_DEFAULTS)
    for key in list(layout):
        if re.fullmatch(r"[xy]axis\d*", key):
            _with_defaults(layout[key], _AXIS_DEFAULTS)
    for menu in layout.get("updatemenus", []):
        _with_defaults(menu, _MENU_DEFAULTS)
    for slider in layout.get("sliders", []):
        _with_defaults(slider, _SLIDER_DEFAULTS)
    return _flipped_tree(fig)


def _encode(obj: Any) -> Any:
    """numpy arrays as plotly.js typed arrays (base64 float64): exact, compact, fast to encode."""
    if isinstance(obj, np.ndarray):
        data = np.ascontiguousarray(obj, dtype="<f8")
        return {"dtype": "f8", "bdata": base64.b64encode(data.tobytes()).decode("ascii")}
    raise TypeError(type(obj))


def dumps(obj: Any) -> str:
    return json.dumps(obj, default=_encode, separators=(",", ":"), allow_nan=False)


def jsonable(obj: Any) -> Any:
    """``obj`` with its numpy arrays as plotly typed-array dicts: plain JSON values, as plotly.js reads them."""
    return json.loads(dumps(obj))


def decode_array(value: Any) -> FloatArray:
    """Inverse of the typed-array encoding (for tests and exports)."""
    if isinstance(value, dict) and "bdata" in value:
        return np.frombuffer(base64.b64decode(value["bdata"]), dtype=value.get("dtype", "f8")).astype(np.float64)
    return np.asarray(value, dtype=np.float64)


def chart_to_plotly(chart: Chart) -> dict[str, Any]:
    """A plotly figure dict of the chart's items."""
    return {"data": [t for i in chart.items for t in item_to_traces(i)], "layout": chart_layout(chart)}


class SplicedFigure:
    """A figure whose static part is serialised once; ``with_dynamic`` adds the moving items.

    viser's plotly handle re-sends the whole figure JSON on every assignment (the app hands it
    ``with_dynamic``'s string through :func:`rigidrel_app.backends.viser.show_figure_json`), so
    the diagrams follow playback at 10 Hz without rebuilding plotly objects.
    """

    def __init__(self, chart: Chart, config: dict[str, Any] | None = None) -> None:
        self.chart = chart
        layout = chart_layout(chart)
        self._static_traces = [dumps(t) for i in chart.items for t in item_to_traces(i)]
        self._static_annotations = [dumps(a) for a in layout.pop("annotations")]
        self._layout_head = dumps(layout)[:-1]  # without the closing brace
        self._config = "" if config is None else ',"config":' + dumps(config)
        self._json = self._assemble([], [])

    def _assemble(self, traces: list[str], annotations: list[str]) -> str:
        return (
            '{"data":['
            + ",".join([*self._static_traces, *traces])
            + '],"layout":'
            + self._layout_head
            + ',"annotations":['
            + ",".join([*self._static_annotations, *annotations])
            + "]}"
            + self._config
            + "}"
        )

    def with_dynamic(self, items: Sequence[Item]) -> str:
        """The figure JSON with ``items`` drawn on top."""
        traces = [dumps(t) for i in items for t in item_to_traces(i)]
        anns = [dumps(label_to_annotation(i)) for i in items if isinstance(i, Label)]
        return self._assemble(traces, anns)

    def to_json(self) -> str:
        """The static figure alone."""
        return self._json
