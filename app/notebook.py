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

from .diagrams import View, minkowski_static, window_x_range
from .draw import chart_to_plotly, dumps
from .drawing import Drawn, build_drawing, equal_scale_ranges
from .settings import Resolved


def _frame(scene: rr.Scene, frame: str | float | rr.Frame) -> rr.Frame:
    if isinstance(frame, rr.Frame):
        return frame
    if isinstance(frame, str):
        if frame not in scene.frames:
            raise rr.ParameterError("frame", f"one of {', '.join(scene.frames)} or a velocity in (-1, 1)", frame)
        return scene.frames[frame]
    return rr.Frame.from_velocity(frame)


def diagram(
    scene: rr.Scene, frame: str | float | rr.Frame = "lab", size: tuple[int, int] = (640, 560), density: float = 2.0
) -> go.Figure:
    """The scene's Minkowski diagram in ``frame``, exact, as an interactive plotly figure.

    Curves are sampled to half a pixel at ``density`` device pixels per CSS pixel (2 covers
    high-density screens and 2x PNG exports).
    """
    import json

    f = _frame(scene, frame)
    lab = rr.Frame.lab()
    window = scene.time_window(f)
    area = (size[0] - 100.0, size[1] - 180.0)
    x_range, t_range = equal_scale_ranges(window_x_range(scene, (f,), window), window, area)
    other = lab if f.key() != lab.key() else f
    chart = minkowski_static(
        scene, View(f, other, f.name, "'" if f.name != "lab" else "", ""), t_range, x_range, area[0]
    )
    fig = json.loads(dumps(chart_to_plotly(chart)))
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


def recording(
    scene: rr.Scene, frame: str | float | rr.Frame = "lab", seconds: float = 10.0, fps: float = 30.0
) -> Recording:
    """Both lanes (the lab and ``frame``) playing through the scene's window, as offline HTML."""
    from .export.recording import record_lanes_html

    drawn: Drawn = build_drawing(Resolved(scene, _frame(scene, frame), None))
    return Recording(record_lanes_html(drawn, seconds, fps))
