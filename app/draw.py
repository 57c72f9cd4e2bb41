"""The drawing vocabulary shared by the 3-D lanes (viser) and the diagrams (plotly).

Pure data: sampled coordinates plus a :class:`Style`. Builders (``diagrams``, ``lanes``)
produce these; backends (:func:`chart_to_plotly` here, ``viser_scene`` for 3-D) only
translate them. Nothing here knows any physics.
"""

from __future__ import annotations

import base64
import json
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any, Literal

import numpy as np
import numpy.typing as npt

FloatArray = npt.NDArray[np.float64]
Dash = Literal["solid", "dash", "dot", "dashdot"]
Anchor = Literal["left", "right", "center"]

# palette (colour-blind safe: blue / orange / purple, Okabe-Ito)
ROD_COLORS = ("#0072B2", "#E8710A")
FRAME_COLOR = "#7B3FA0"
LIGHT_COLOR = "#C9A400"
WALL_COLOR = "#6E6E6E"
INK = "#222222"


def rgb(color: str) -> tuple[int, int, int]:
    """``"#RRGGBB"`` -> ``(r, g, b)``."""
    c = color.lstrip("#")
    return int(c[0:2], 16), int(c[2:4], 16), int(c[4:6], 16)


def rgba(color: str, alpha: float) -> str:
    r, g, b = rgb(color)
    return f"rgba({r},{g},{b},{alpha:g})"


@dataclass(frozen=True)
class Style:
    color: str = INK
    width: float = 2.0
    dash: Dash = "solid"
    opacity: float = 1.0
    name: str | None = None
    """Legend entry; ``None`` keeps the item out of the legend."""
    group: str | None = None
    """Items of one group toggle together in the legend."""


@dataclass(frozen=True)
class Polyline:
    """A curve through ``(x[i], y[i])``."""

    x: FloatArray
    y: FloatArray
    style: Style = Style()


@dataclass(frozen=True)
class Segments:
    """Separate straight segments ``(x0, y0) -> (x1, y1)``; arrays of shape ``(n,)``."""

    x0: FloatArray
    y0: FloatArray
    x1: FloatArray
    y1: FloatArray
    style: Style = Style()


@dataclass(frozen=True)
class Area:
    """A filled polygon (closed automatically)."""

    x: FloatArray
    y: FloatArray
    style: Style = Style()


@dataclass(frozen=True)
class Points:
    x: FloatArray
    y: FloatArray
    style: Style = Style()
    size: float = 8.0
    symbol: str = "circle"


@dataclass(frozen=True)
class Label:
    x: float
    y: float
    text: str
    """May use ``<sub>``/``<b>`` (plotly) and is rendered as plain text in 3-D."""
    style: Style = Style()
    anchor: Anchor = "left"
    size: float = 13.0


Item = Polyline | Segments | Area | Points | Label


@dataclass(frozen=True)
class Chart:
    """A 2-D chart: items, axis titles and ranges."""

    items: tuple[Item, ...]
    x_title: str
    y_title: str
    x_range: tuple[float, float]
    y_range: tuple[float, float]
    title: str = ""
    equal_aspect: bool = False
    """Minkowski diagrams: one unit of x as long as one unit of t (light at 45 degrees)."""


def event_label(name: str) -> str:
    """The paper's notation: ``T_1'`` -> ``T'<sub>1</sub>``, ``-T_F`` -> ``−T<sub>F</sub>``."""
    sign = "−" if name.startswith("-") else ""
    core = name.lstrip("-")
    prime = "'" if core.endswith("'") else ""
    core = core.rstrip("'")
    if "_" in core:
        head, sub = core.split("_", 1)
        return f"<b>{sign}{head}{prime}<sub>{sub}</sub></b>"
    return f"<b>{sign}{core}{prime}</b>"


def plain_text(text: str) -> str:
    """Strip the small HTML subset for text drawn in 3-D."""
    for tag in ("<b>", "</b>", "<sub>", "</sub>"):
        text = text.replace(tag, "")
    return text


# ------------------------------------------------------------------- plotly backend
def _plotly_line(style: Style) -> dict[str, Any]:
    """Plotly line attributes. ``simplify`` off: plotly would otherwise drop vertices it judges
    collinear (about a pixel), undoing the sampler's chord tolerance and leaving visible corners."""
    return {"color": style.color, "width": style.width, "dash": style.dash, "simplify": False}


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
    return {
        "x": label.x,
        "y": label.y,
        "text": label.text,
        "showarrow": False,
        "xanchor": label.anchor,
        "yanchor": "middle",
        "font": {"color": label.style.color, "size": label.size},
        "xshift": 6 if label.anchor == "left" else (-6 if label.anchor == "right" else 0),
    }


def chart_layout(chart: Chart, height: int | None = None) -> dict[str, Any]:
    layout: dict[str, Any] = {
        "margin": {"l": 48, "r": 10, "t": 30 if chart.title else 8, "b": 84},
        "xaxis": {"title": {"text": chart.x_title}, "range": list(chart.x_range), "zeroline": False},
        "yaxis": {"title": {"text": chart.y_title}, "range": list(chart.y_range), "zeroline": False},
        "showlegend": True,
        "legend": {"orientation": "h", "yanchor": "top", "y": -0.26, "x": 0, "font": {"size": 10}},
        "plot_bgcolor": "white",
        "paper_bgcolor": "white",
        "font": {"size": 11},
        "annotations": [label_to_annotation(i) for i in chart.items if isinstance(i, Label)],
    }
    if chart.title:
        layout["title"] = {"text": chart.title, "x": 0.02, "y": 0.98, "font": {"size": 13}}
    if chart.equal_aspect:
        layout["yaxis"]["scaleanchor"] = "x"
        layout["yaxis"]["scaleratio"] = 1
    for ax in ("xaxis", "yaxis"):
        layout[ax].update({"gridcolor": "#e6e6e6", "linecolor": "#999", "mirror": True, "ticks": "outside"})
    if height is not None:
        layout["height"] = height
    return layout


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

    viser's plotly handle re-sends the whole figure JSON on every assignment (it calls
    ``figure.to_json()``: the app hands it a :class:`JsonFigure` of ``with_dynamic``'s
    string), so the diagrams follow playback at 10 Hz without rebuilding plotly objects.
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


class JsonFigure:
    """A ready JSON string with the one method viser's plotly handle calls."""

    def __init__(self, text: str) -> None:
        self._text = text

    def to_json(self) -> str:
        return self._text
