"""The scenes' own print figures (the paradoxes': Bell's spaceships, the pole in the barn), drawn from
their descriptions: one for every preset with a :class:`~rigidrel_core.PresetFigure`, of every
registered scene.

Each is the lab Minkowski diagram of the preset's scene in the paper's print style, sampled exactly
from the core: the scene's objects in their roles' print styles (:data:`..view.objects.OBJECT_STYLES`),
each rod's world tube (the first rod group's solid and shaded, the other groups' dashed: alternatives
and comparisons), and the figure's marked events; its caption is the description's, every number in
it the core's.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

import rigidrel_core as rr

from ..view.diagrams import object_worldlines, world_tube
from ..view.sampling import Sampler
from ..view.vocabulary import Chart, Item, Label, Points, Style, event_label
from .figures import (
    _BLACK,
    _GREY,
    _PLOT_AREA,
    _PNG_SCALE,
    FIGURE_TOLERANCE_PX,
    PRINT_SHADE,
    PaperFigure,
    _ranges,
    write_figures,
)

#: The figures' sampler: a tenth of the app's half pixel (:data:`.figures.FIGURE_TOLERANCE_PX`).
_SAMPLER = Sampler(FIGURE_TOLERANCE_PX)


def _mark(t: float, x: float, name: str, side: str) -> list[Item]:
    """An event: a black dot, named beside it (on the ``side`` its figure asks)."""
    return [
        Points(np.array([x]), np.array([t]), Style(_BLACK), size=7),
        Label(x, t, name, Style(_BLACK), anchor="right" if side == "right" else "left", size=15),
    ]


def _marked(scene: rr.Scene, name: str) -> tuple[tuple[float, float], str]:
    """The lab event a figure marks as ``name`` and its label: a named event of the scene (in the
    paper's notation) or an event of one of its objects (by its own name)."""
    if name in scene.events:
        return scene.events[name], event_label(name)
    for obj in scene.objects:
        if obj.event is not None and obj.event.name == name:
            return obj.event.lab, name
    raise ValueError(
        f"{scene.kind}: the figure marks {name!r}, which is neither an event of the scene nor of its objects"
    )


def preset_figure(description: rr.SceneDescription, preset: rr.ScenePreset) -> PaperFigure:
    """The print figure of ``preset`` (which must have one) of the scene ``description`` describes."""
    spec = preset.figure
    if spec is None:
        raise ValueError(f"{description.kind}: the preset {preset.label!r} has no figure")
    scene = description.build(**preset.values)
    x_range, t_range = _ranges(scene, spec.t_range)
    px_per_x = _PNG_SCALE * _PLOT_AREA[0] / (x_range[1] - x_range[0])
    items: list[Item] = object_worldlines(scene, rr.LAB, t_range, px_per_x, _SAMPLER, print_style=True)
    lines = _SAMPLER.worldlines(scene, rr.LAB, np.array([0.0, 1.0]), t_range, px_per_x)
    first = scene.rod_groups[0] if scene.n_rods else 0
    for r, group in enumerate(scene.rod_groups):
        if group == first:
            items += world_tube(lines[r], fill=PRINT_SHADE, edge=Style(_BLACK, 2.0))
        else:
            items += world_tube(lines[r], fill=None, edge=Style(_GREY, 2.0, "dash"))
    for name, side in spec.marks:
        (t, x), label = _marked(scene, name)
        items += _mark(t, x, label, side)
    chart = Chart(tuple(items), "x", "t", x_range, t_range, equal_aspect=True)
    return PaperFigure(spec.name, spec.caption(scene), chart)


def paradox_figures() -> list[PaperFigure]:
    """Every registered scene's preset figures, in teaching order."""
    return [preset_figure(d, p) for d in rr.scene_descriptions().values() for p in d.presets if p.figure is not None]


def write_paradox_figures(out: Path) -> list[Path]:
    """The figures as SVG and PNG in ``out``, and their captions as ``<name>.txt``."""
    return write_figures(out, paradox_figures(), captions=True)
