"""Every axis of the app's Minkowski diagrams carries at least three numbered ticks.

Pure view layer (no browser): the diagrams' axes as the canvas draws them
(:func:`~rigidrel_app.view.canvas.chart_picture`), for every preset in each of its frames and every
scene at its defaults, on a desk's canvas and a projector's.
"""

from __future__ import annotations

import re
from dataclasses import replace

import numpy as np
import pytest

import rigidrel_core as rr
from rigidrel_app.view.canvas import MIN_AXIS_TICKS, chart_picture, nice_ticks
from rigidrel_app.view.layout import NORMAL, PRESENTER, CanvasLayout, Theme, canvas_layout
from rigidrel_app.view.scene_view import Drawn, build_drawing
from rigidrel_app.view.state import Settings, build, presets
from tests.viser_client import shown

#: A desk's canvas (the panel docked at 1280x720) and a projector's.
CANVASES: tuple[tuple[float, float, Theme], ...] = ((936, 720, NORMAL), (1280, 720, PRESENTER))
#: A ride, and contracted rods that make the lanes zoom (v = 0.99).
EXTRA = [
    Settings.of("wall-collision", v=0.6, eps=0.0).riding(0, 1.0),
    Settings.of("constant-acceleration", v=0.99),
    Settings.of("wall-collision", v=0.99),
]


def _drawn(settings: Settings, layout: CanvasLayout) -> Drawn:
    return build_drawing(build(settings), areas=layout.chart_areas, label_px=layout.theme.text_px)


def _axis_numbers(chart_index: int, d: Drawn, layout: CanvasLayout) -> tuple[list[float], list[float]]:
    """The numbers a diagram's x axis (below the plot) and t axis (left of it) carry on the canvas."""
    _, picture = chart_picture(d.charts[chart_index], shown(layout.charts[chart_index]), layout.theme)
    plot = shown(layout.charts[chart_index]).plot
    xs, ts = [], []
    for t in picture.texts:
        if not re.fullmatch(r"-?\d+(\.\d+)?", t.text):
            continue
        if t.anchor == "top-center" and t.z < plot.z0:
            xs.append(float(t.text))
        elif t.anchor == "center-right" and t.x < plot.x0:
            ts.append(float(t.text))
    return xs, ts


def _every_frame(settings: Settings) -> list[Settings]:
    """``settings`` in each frame its scene names (the lab, the rods' frames before and after, ...)."""
    return [replace(settings, frame=name) for name in build(settings).scene.frames]


AXIS_CASES = [
    *(s for p in presets().values() for s in _every_frame(p)),
    *(Settings(kind) for kind in sorted(rr.scene_descriptions())),
    *EXTRA,
]


@pytest.mark.parametrize("w, h, theme", CANVASES, ids=["desk", "projector"])
def test_every_diagram_axis_carries_three_numbered_ticks(w: float, h: float, theme: Theme) -> None:
    """Both Minkowski diagrams' x and t axes, for every preset in each of its frames and every scene
    at its defaults: at least :data:`MIN_AXIS_TICKS` numbers, evenly spaced (Fig. 3's barycentric
    frame had a lone "0" under its x axis)."""
    layout = canvas_layout(w, h, theme)
    for settings in AXIS_CASES:
        d = _drawn(settings, layout)
        for k in (0, 1):
            for numbers in _axis_numbers(k, d, layout):
                assert len(numbers) >= MIN_AXIS_TICKS, (settings, k, numbers)
                steps = np.diff(numbers)
                np.testing.assert_allclose(steps, steps[0], rtol=1e-6)


@pytest.mark.parametrize(
    "lo, hi, count", [(-0.4, 0.45, 1.0), (-1.3, 0.2, 2.5), (0.0, 1e-3, 1.0), (-7.0, 9.0, 0.5), (0.1, 0.25, 2.0)]
)
def test_nice_ticks_gives_at_least_three(lo: float, hi: float, count: float) -> None:
    ticks = nice_ticks(lo, hi, count)
    assert ticks.size >= MIN_AXIS_TICKS and ticks.min() >= lo - 1e-12 and ticks.max() <= hi + 1e-12
