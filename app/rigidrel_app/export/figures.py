"""The paper's missing Figs. 1-4, regenerated from the core with the paper's labels.

Franklin (2012) prints captions but no images. Each figure here is exact (every sample
a core evaluation, sampled to half a pixel at the export size) and drawn in print style:
black curves, the rods' world tubes lightly shaded, events named as in the paper.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

import rigidrel_core as rr
from rigidrel_core import examples

from ..backends.plotly import chart_to_plotly
from ..view.diagrams import equal_scale_ranges, window_x_range, world_tube
from ..view.placement import place_labels
from ..view.sampling import sample_lengths, sample_worldlines
from ..view.vocabulary import Anchor, Chart, Dash, Item, Label, Points, Polyline, Style, event_label

#: Export size of every figure (CSS pixels; PNGs are written at twice this).
FIGURE_SIZE = (640, 560)
_PLOT_AREA = (FIGURE_SIZE[0] - 110.0, FIGURE_SIZE[1] - 110.0)
#: PNGs are written at this scale; curves are sampled for it.
_PNG_SCALE = 2.0
#: Chord tolerance of the figures, in PNG pixels: a tenth of the app's half pixel, so that the
#: polylines show no corners in print or in the SVG enlarged tenfold (each chord of a curve of
#: radius R pixels turns by sqrt(8 tol / R): 1.5 degrees at R = 600, about one rest length).
FIGURE_TOLERANCE_PX = 0.05
_BLACK = "#000000"
_GREY = "#555555"
#: A world tube's shade in print.
PRINT_SHADE = Style("rgba(0,0,0,0.07)", 0.0)
_FONT = "DejaVu Serif, Liberation Serif, Times New Roman, serif"


@dataclass(frozen=True)
class PaperFigure:
    name: str
    caption: str
    """The paper's caption, verbatim apart from typesetting."""
    chart: Chart


CAPTIONS = {
    "fig1": "Fig. 1: Constant acceleration of a rigid body. The solid curve is the trajectory for continuous "
    "acceleration. The dashed curve is for impulsive acceleration. The time T_B on the solid curve represents the "
    "end of acceleration for the back end of the rod, and T_F for the front end.",
    "fig2": "Fig. 2: Equal time length of an accelerating rigid rod. The length decreases from L0 to L0/γ. The time "
    "T_B on the solid curve represents the end of acceleration for the back end of the rod, and T_F for the front end.",
    "fig3": "Fig. 3: Trajectories for a collision between rigid rods for case I: M2 = 2M1. The times T1 and T2 "
    "represent the start of acceleration, and T'1 and T'2 the end of acceleration for the outer ends of the rods.",
    "fig4": "Fig. 4: Trajectories for a collision between rigid rods for case II: M1 = 2M2. The times T1 and T2 "
    "represent the start of acceleration, and T'1 and T'2 the end of acceleration for the outer ends of the rods.",
}


def _tube(
    scene: rr.Scene,
    t_range: tuple[float, float],
    x_range: tuple[float, float],
    dash: Dash = "solid",
    shade: bool = True,
    colors: tuple[str, ...] = (_BLACK, _GREY),
) -> list[Item]:
    """Every rod's world tube in print (:func:`~rigidrel_app.view.diagrams.world_tube`): its ends in
    ``colors`` by rod, ``dash``ed, the tube shaded if ``shade``."""
    px_per_x = _PNG_SCALE * _PLOT_AREA[0] / (x_range[1] - x_range[0])
    lines = sample_worldlines(scene, rr.LAB, np.array([0.0, 1.0]), t_range, px_per_x, FIGURE_TOLERANCE_PX)
    items: list[Item] = []
    for r in range(scene.n_rods):
        edge = Style(colors[r % len(colors)], 2.0, dash)
        items += world_tube(lines[r], fill=PRINT_SHADE if shade else None, edge=edge)
    return items


def _events(scene: rr.Scene, names: tuple[str, ...], side: dict[str, Anchor] | None = None) -> list[Item]:
    ev = scene.events
    items: list[Item] = [
        Points(np.array([ev[n][1] for n in names]), np.array([ev[n][0] for n in names]), Style(_BLACK), size=7)
    ]
    for n in names:
        t, x = ev[n]
        anchor = (side or {}).get(n, "left")
        items.append(Label(x, t, event_label(n), Style(_BLACK), anchor=anchor, size=16, movable=True))
    return items


def _ranges(scene: rr.Scene, t_range: tuple[float, float]) -> tuple[tuple[float, float], tuple[float, float]]:
    return equal_scale_ranges(window_x_range(scene, (rr.LAB,), t_range), t_range, _PLOT_AREA)


def figure1() -> PaperFigure:
    solid = examples.fig1_constant_acceleration()
    dashed = examples.fig1_impulsive_start()
    t_range = (0.0, 2.2)
    x_range, t_range = _ranges(solid, t_range)
    items = [
        *_tube(solid, t_range, x_range),
        *_tube(dashed, t_range, x_range, "dash", shade=False),
        *_events(solid, ("T_B", "T_F"), {"T_B": "right"}),
    ]
    return PaperFigure(
        "fig1",
        CAPTIONS["fig1"],
        _placed(Chart(tuple(items), "x / L<sub>0</sub>", "t / L<sub>0</sub>", x_range, t_range, equal_aspect=True)),
    )


def _placed(chart: Chart) -> Chart:
    """The chart with its event labels placed clear of each other and of the curves (both the solid
    and the dashed ones) in the figure's plot area."""
    return place_labels(chart, _PLOT_AREA)


def figure2() -> PaperFigure:
    scene = examples.fig1_constant_acceleration()
    t_range = (0.0, 2.2)
    y_range = (0.75, 1.02)
    px_per_length = _PNG_SCALE * _PLOT_AREA[1] / (y_range[1] - y_range[0])
    curve = sample_lengths(scene, rr.LAB, t_range, px_per_length, FIGURE_TOLERANCE_PX)[0]
    items: list[Item] = [Polyline(curve.t, curve.x, Style(_BLACK, 2.0))]
    for n in ("T_B", "T_F"):
        t = scene.events[n][0]
        length = float(scene.lengths(np.array([t]))[0, 0])
        items.append(Points(np.array([t]), np.array([length]), Style(_BLACK), size=7))
        items.append(Label(t, length, event_label(n), Style(_BLACK), anchor="left", size=16, movable=True))
    contracted = float(scene.lengths(np.array([t_range[1]]))[0, 0])  # L0/γ once both ends coast
    items.append(Label(2.15, contracted - 0.012, "L<sub>0</sub>/γ", Style(_GREY), anchor="right", size=16))
    items.append(Label(0.05, 0.99, "L<sub>0</sub>", Style(_GREY), anchor="left", size=16))
    return PaperFigure(
        "fig2",
        CAPTIONS["fig2"],
        _placed(Chart(tuple(items), "t / L<sub>0</sub>", "L / L<sub>0</sub>", t_range, y_range)),
    )


def _collision(scene: rr.Scene, name: str, t_range: tuple[float, float]) -> PaperFigure:
    x_range, t_range = _ranges(scene, t_range)
    side: dict[str, Anchor] = {"T_1": "right", "T_1'": "right", "T_2": "left", "T_2'": "left"}
    items = [
        *_tube(scene, t_range, x_range),
        *_events(scene, ("T_1", "T_1'", "T_2", "T_2'"), side),
        Label(-0.5, t_range[0] + 0.08, "rod 1", Style(_BLACK), anchor="center", size=16),
        Label(0.5, t_range[0] + 0.08, "rod 2", Style(_GREY), anchor="center", size=16),
    ]
    return PaperFigure(
        name,
        CAPTIONS[name],
        _placed(Chart(tuple(items), "x / L<sub>0</sub>", "t / L<sub>0</sub>", x_range, t_range, equal_aspect=True)),
    )


def paper_figures() -> list[PaperFigure]:
    return [
        figure1(),
        figure2(),
        _collision(examples.fig3_case_one(), "fig3", (-1.0, 1.3)),
        _collision(examples.fig4_case_two(), "fig4", (-1.0, 1.4)),
    ]


def print_style(chart: Chart) -> dict[str, Any]:
    """The chart as a plotly figure in print style: serif, black axes, no legend, no grid."""
    fig = chart_to_plotly(chart)
    layout = fig["layout"]
    layout.update(
        {
            "showlegend": False,
            "margin": {"l": 70, "r": 30, "t": 20, "b": 60},
            "font": {"family": _FONT, "size": 16, "color": _BLACK},
        }
    )
    layout.pop("title", None)
    for ax in ("xaxis", "yaxis"):
        layout[ax].update(
            {
                "showgrid": False,
                "linecolor": _BLACK,
                "mirror": True,
                "ticks": "outside",
                "tickcolor": _BLACK,
                "zeroline": False,
            }
        )
    return fig


def write_figures(out: Path, figures: Sequence[PaperFigure] | None = None, captions: bool = False) -> list[Path]:
    """Figures (default: the paper's) as SVG and PNG in ``out`` (one Chromium for all, through
    kaleido); with ``captions``, each caption too as ``<name>.txt``."""
    from .images import image_writer

    out.mkdir(parents=True, exist_ok=True)
    written: list[Path] = []
    with image_writer() as writer:
        for fig in paper_figures() if figures is None else figures:
            plotly_fig = print_style(fig.chart)
            for ext in ("svg", "png"):
                scale = _PNG_SCALE if ext == "png" else 1.0
                written.append(writer.write(plotly_fig, out / f"{fig.name}.{ext}", *FIGURE_SIZE, scale=scale))
            if captions:
                caption = out / f"{fig.name}.txt"
                caption.write_text(fig.caption + "\n")
                written.append(caption)
    return written
