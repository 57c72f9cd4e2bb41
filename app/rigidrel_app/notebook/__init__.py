"""Scenes in a Jupyter notebook (JupyterLab, Notebook 7, VS Code), all of it with no network.

    import rigidrel_core as rr
    from rigidrel_app.notebook import diagram, explore, lesson, recording
    scene = rr.rod_collision(v1=0.6, v2=0.0, mass1=1.0, mass2=2.0, length1=1.0, length2=1.0, eps=1.0)
    diagram(scene, scene.frame("barycentric"))      # interactive plotly figure
    recording(scene, scene.frame("barycentric"))    # the lanes playing, offline (an iframe)
    lesson("paper")                                 # the built-in lesson's steps, captions and diagrams
    explore("rod-collision", v1=0.6, frame="barycentric")   # live: sliders, the core runs in the kernel

Each takes ``theme="dark"``: its figures in the app's dark projector theme (as ``--theme dark``).

``diagram``, ``recording`` and ``lesson`` are static HTML (:mod:`.inline`): plotly.js comes from
the installed plotly package, never from a CDN. ``explore`` (:mod:`.widget`, needs the
``notebook`` extra: ``pip install 'rigidrel[notebook]'``) is a live widget: its sliders are the
scene registry's parameters, each change is computed by the core in the kernel and redraws a
plotly ``FigureWidget`` (its script also ships with plotly). Its logic, without widgets, is
:mod:`.live_state`. Outside a notebook they return ordinary objects (a plotly ``Figure``; a
:class:`Recording` with ``html`` and ``save``; a :class:`LessonView` with ``html``; an ipywidgets box).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from .inline import LessonView, OfflineFigure, Recording, diagram, lesson, offline_html, recording

if TYPE_CHECKING:
    from ..view.vocabulary import Shade
    from .widget import LiveView


def explore(
    kind: str,
    frame: str | float | None = None,
    t: float | None = None,
    continuous: bool = False,
    *,
    theme: Shade = "light",
    **values: float | None,
) -> LiveView:
    """The live view of scene ``kind`` with sliders (see :func:`.widget.explore`), e.g.
    ``explore("rod-collision", v1=0.6, frame="barycentric")``; ``theme="dark"`` draws it in the
    app's dark projector theme. Needs the ``notebook`` extra."""
    try:
        from .widget import explore as live
    except ImportError as exc:  # ipywidgets or anywidget missing: say how to get them
        raise ImportError(
            f"explore() needs the notebook extra ({exc.name} is missing): pip install 'rigidrel[notebook]'"
        ) from exc
    return live(kind, frame, t, continuous, theme=theme, **values)


__all__ = ["LessonView", "OfflineFigure", "Recording", "diagram", "explore", "lesson", "offline_html", "recording"]
