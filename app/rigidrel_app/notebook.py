"""Scenes in a Jupyter notebook: the diagram as a plotly figure, the 3-D lanes as a playing recording.

    import rigidrel_core as rr
    from app.notebook import diagram, recording
    scene = rr.rod_collision(v1=0.6, v2=0.0, m1=1.0, m2=2.0, l1=1.0, l2=1.0, eps=1.0)
    diagram(scene, frame="barycentric")      # interactive plotly figure
    recording(scene, frame="barycentric")    # the lanes playing, offline (an iframe)

Outside a notebook both return ordinary objects (a plotly ``Figure``; a :class:`Recording`
with ``html`` and ``save``).
"""

from __future__ import annotations

import html as html_lib
from dataclasses import dataclass
from pathlib import Path

import plotly.graph_objects as go

import rigidrel_core as rr

from .diagrams import minkowski_in_frame
from .draw import chart_to_plotly, jsonable
from .drawing import build_drawing
from .settings import Resolved, choose_frame

FrameLike = rr.Frame | str | float


def diagram(
    scene: rr.Scene, frame: FrameLike = "lab", size: tuple[int, int] = (640, 560), density: float = 2.0
) -> go.Figure:
    """The scene's Minkowski diagram in ``frame``, exact, as an interactive plotly figure.

    ``frame``: a preset name of the scene, a velocity in (-1, 1) or a :class:`~rigidrel_core.Frame`.
    Curves are sampled to half a pixel at ``density`` device pixels per CSS pixel (2 covers
    high-density screens and 2x PNG exports).
    """
    area = (size[0] - 100.0, size[1] - 180.0)
    chart = minkowski_in_frame(scene, choose_frame(scene, frame), area, density=density)
    fig = jsonable(chart_to_plotly(chart))
    fig["layout"].update({"width": size[0], "height": size[1]})
    fig["layout"]["legend"].update({"y": -0.13})
    return go.Figure(fig)


@dataclass(frozen=True)
class Recording:
    """A standalone HTML page of the lanes playing; shows itself in a notebook."""

    html: str

    def save(self, path: str | Path) -> Path:
        p = Path(path)
        p.write_text(self.html, encoding="utf-8")
        return p

    def _repr_html_(self) -> str:
        return (
            f'<iframe srcdoc="{html_lib.escape(self.html, quote=True)}" style="width:100%;height:520px;'
            'border:1px solid #ddd" sandbox="allow-scripts"></iframe>'
        )


def recording(scene: rr.Scene, frame: FrameLike = "lab", seconds: float = 10.0, fps: float = 30.0) -> Recording:
    """Both lanes (the lab and ``frame``) playing through the scene's window, as offline HTML."""
    from .export.recording import record_lanes_html

    drawn = build_drawing(Resolved(scene, choose_frame(scene, frame), None))
    return Recording(record_lanes_html(drawn, seconds, fps))
