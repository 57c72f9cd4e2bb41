"""Static notebook output: the diagram as a plotly figure, the 3-D lanes as a playing recording,
a lesson's steps inline. All of it works with no network: plotly.js comes from the installed
plotly package, never from a CDN.

    import rigidrel_core as rr
    from rigidrel_app.notebook import diagram, lesson, recording
    scene = rr.rod_collision(v1=0.6, v2=0.0, mass1=1.0, mass2=2.0, length1=1.0, length2=1.0, eps=1.0)
    diagram(scene, scene.frame("barycentric"))      # interactive plotly figure
    recording(scene, scene.frame("barycentric"))    # the lanes playing, offline (an iframe)
    lesson("paper")                                 # the built-in lesson's steps, captions and diagrams

Outside a notebook they return ordinary objects (a plotly ``Figure``; a :class:`Recording`
with ``html`` and ``save``; a :class:`LessonView` with ``html``). Each takes ``theme="dark"``: the
app's dark projector theme, as ``rigidrel export --theme dark``.
"""

from __future__ import annotations

import html as html_lib
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import plotly.graph_objects as go
import plotly.io as pio
from markdown_it import MarkdownIt

import rigidrel_core as rr

from ..backends.plotly import shaded_figure
from ..export.diagram import diagram_figure
from ..export.recording import record_lanes_html
from ..lessons import Lesson, lesson_from
from ..view.scene_view import build_drawing
from ..view.state import Resolved
from ..view.vocabulary import Shade
from .live_state import checked_theme


class _PlotlyInPage:
    """Whether this kernel has already put plotly.js into the notebook page (the first figure does)."""

    sent = False


def offline_html(fig: go.Figure) -> str:
    """A figure as notebook HTML that needs no network: the first one of a kernel carries
    plotly.js from the installed package; later ones use it (as plotly's own offline notebook mode)."""
    include = not _PlotlyInPage.sent
    _PlotlyInPage.sent = True
    return str(pio.to_html(fig, include_plotlyjs=include, full_html=False, config={"displaylogo": False}))


class OfflineFigure(go.Figure):
    """A plotly ``Figure`` that shows itself in a notebook without a CDN."""

    def _repr_mimebundle_(
        self, include: Any = None, exclude: Any = None, validate: bool = True, **kwargs: Any
    ) -> dict[str, str]:
        del include, exclude, validate, kwargs
        return {"text/html": offline_html(self)}

    def _repr_html_(self) -> str:
        return offline_html(self)

    def _ipython_display_(self) -> None:
        """IPython asks this first; plotly's own would choose a renderer that may need a CDN."""
        from IPython.display import display  # only ever called inside IPython

        display({"text/html": offline_html(self)}, raw=True)


def diagram(
    scene: rr.Scene,
    frame: rr.Frame = rr.LAB,
    size: tuple[int, int] = (640, 560),
    density: float = 2.0,
    *,
    theme: Shade = "light",
) -> go.Figure:
    """The scene's Minkowski diagram in ``frame`` (a :class:`~rigidrel_core.Frame`, e.g.
    ``scene.frame("barycentric")``), exact, as an interactive plotly figure that shows offline.

    Curves are sampled to half a pixel at ``density`` device pixels per CSS pixel (2 covers
    high-density screens and 2x PNG exports). ``theme``: ``"light"``, or ``"dark"`` for the app's
    dark projector theme (light on black, every colour lightness-flipped, :func:`shaded_figure`);
    anything else raises :class:`~rigidrel_core.ParameterError`.
    """
    shade = checked_theme(theme)
    return OfflineFigure(shaded_figure(diagram_figure(scene, frame, size, density), shade))


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
    scene: rr.Scene, frame: rr.Frame | None = None, seconds: float = 10.0, fps: float = 30.0, *, theme: Shade = "light"
) -> Recording:
    """Both lanes (the lab and ``frame``, by default the scene's default frame) playing through the
    scene's window, as offline HTML. ``theme``: ``"light"``, or ``"dark"`` for the app's dark
    projector theme (as ``rigidrel export --theme dark``); anything else raises
    :class:`~rigidrel_core.ParameterError`."""
    shade = checked_theme(theme)
    chosen = rr.default_frame(scene) if frame is None else frame
    drawn = build_drawing(Resolved(scene, chosen, None))
    return Recording(record_lanes_html(drawn, seconds, fps, shade=shade))


_MARKDOWN = MarkdownIt("commonmark", {"html": False})


@dataclass(frozen=True)
class LessonView:
    """A lesson's steps as one HTML block: each step's title, caption and diagram (offline)."""

    lesson: Lesson
    html: str

    def _repr_html_(self) -> str:
        return self.html


def lesson(name_or_path: str, size: tuple[int, int] = (560, 460), *, theme: Shade = "light") -> LessonView:
    """A lesson file (or a built-in lesson's name, such as ``"paper"``) shown inline: every step's
    title, its caption with the core's numbers, and its Minkowski diagram in the step's frame.
    A mistake in the file raises :class:`~rigidrel_app.lessons.LessonError` naming its line.
    ``theme``: ``"light"``, or ``"dark"`` for the diagrams in the app's dark projector theme (the
    titles and captions keep the notebook's colours); anything else raises
    :class:`~rigidrel_core.ParameterError`."""
    shade = checked_theme(theme)
    chosen = lesson_from(name_or_path)
    parts = [f"<h2>{html_lib.escape(chosen.title)}</h2>"]
    if chosen.subtitle:
        parts.append(f"<p><em>{html_lib.escape(chosen.subtitle)}</em></p>")
    for k, step in enumerate(chosen.steps, start=1):
        scene, frame = step.resolved.scene, step.resolved.frame
        parts.append(f"<h3>{k}. {html_lib.escape(step.title)}</h3>{_MARKDOWN.render(step.caption)}")
        parts.append(offline_html(OfflineFigure(shaded_figure(diagram_figure(scene, frame, size, 1.0), shade))))
    return LessonView(chosen, "\n".join(parts))
