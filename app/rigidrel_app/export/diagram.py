"""The Minkowski diagram of one scene in one frame as a plotly figure dict: for notebooks and slides."""

from __future__ import annotations

from typing import Any

import rigidrel_core as rr

from ..backends.plotly import TITLE_PX, chart_to_plotly, jsonable
from ..view.diagrams import frame_title, minkowski_in_frame


def diagram_figure(
    scene: rr.Scene, frame: rr.Frame, size: tuple[int, int] = (640, 560), density: float = 2.0
) -> dict[str, Any]:
    """The scene's Minkowski diagram in ``frame``, exact, as a plain plotly figure dict (JSON values).

    Curves are sampled to half a pixel at ``density`` device pixels per CSS pixel (2 covers
    high-density screens and 2x PNG exports).
    """
    area = (size[0] - 100.0, size[1] - 180.0)
    chart = minkowski_in_frame(scene, frame, area, density=density)
    fig = jsonable(chart_to_plotly(chart))
    fig["layout"].update({"width": size[0], "height": size[1]})
    fig["layout"]["legend"].update({"y": -0.13})
    return fig


def slide_diagram(scene: rr.Scene, frame: rr.Frame) -> dict[str, Any]:
    """The Minkowski diagram in ``frame`` with a title, for slides (PNG/SVG)."""
    fig = diagram_figure(scene, frame, size=(760, 640))
    layout = fig["layout"]
    layout["title"] = {
        "text": f"{scene.kind}: Minkowski diagram, {frame_title(frame)} frame",
        "x": 0.02,
        "y": 0.985,
        "yanchor": "top",
        "font": {"size": TITLE_PX + 2},
    }
    layout["margin"]["t"] = 48
    return fig
