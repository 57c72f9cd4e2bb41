"""Scenes in a Jupyter notebook: the diagram as a plotly figure, the 3-D lanes as a playing recording.

    import rigidrel_core as rr
    from rigidrel_app.notebook import diagram, recording
    scene = rr.rod_collision(v1=0.6, v2=0.0, m1=1.0, m2=2.0, l1=1.0, l2=1.0, eps=1.0)
    diagram(scene, scene.frame("barycentric"))      # interactive plotly figure
    recording(scene, scene.frame("barycentric"))    # the lanes playing, offline (an iframe)

Outside a notebook both return ordinary objects (a plotly ``Figure``; a :class:`Recording`
with ``html`` and ``save``).
"""

from __future__ import annotations

import html as html_lib
from dataclasses import dataclass
from pathlib import Path

import plotly.graph_objects as go

import rigidrel_core as rr

from .export.diagram import diagram_figure
from .export.recording import record_lanes_html
from .view.scene_view import build_drawing
from .view.state import Resolved


def diagram(
    scene: rr.Scene, frame: rr.Frame = rr.LAB, size: tuple[int, int] = (640, 560), density: float = 2.0
) -> go.Figure:
    """The scene's Minkowski diagram in ``frame`` (a :class:`~rigidrel_core.Frame`, e.g.
    ``scene.frame("barycentric")``), exact, as an interactive plotly figure.

    Curves are sampled to half a pixel at ``density`` device pixels per CSS pixel (2 covers
    high-density screens and 2x PNG exports).
    """
    return go.Figure(diagram_figure(scene, frame, size, density))


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


def recording(scene: rr.Scene, frame: rr.Frame | None = None, seconds: float = 10.0, fps: float = 30.0) -> Recording:
    """Both lanes (the lab and ``frame``, by default the scene's default frame) playing through the
    scene's window, as offline HTML."""
    chosen = rr.default_frame(scene) if frame is None else frame
    drawn = build_drawing(Resolved(scene, chosen, None))
    return Recording(record_lanes_html(drawn, seconds, fps))
