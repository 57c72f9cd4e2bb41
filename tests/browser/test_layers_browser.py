"""The layers on the canvas, looked at in pixels: the light signals appear in the diagrams' plot
areas and in the lanes (the pulse moving with time) when asked for and never otherwise; hiding the
world tubes or the length panel empties exactly those regions.

The settings are set on the server, as a preset would (``show``); every picture is awaited until
it has changed and settled, never after a fixed sleep.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np
import pytest
from PIL import Image

from rigidrel_app.live.server import App
from rigidrel_app.view.canvas import color_rgb
from rigidrel_app.view.layers import DEFAULT_LAYERS, Layer
from rigidrel_app.view.layout import Rect
from rigidrel_app.view.scene_view import LENGTH_HIDDEN_NOTE, LENGTH_HIDDEN_TITLE
from rigidrel_app.view.state import Settings, presets
from rigidrel_app.view.vocabulary import LIGHT_COLOR, ROD_COLORS, rgba
from tests.browser.test_app_browser import AppPage, show

pytestmark = pytest.mark.browser

CRASH = presets()["Sec. 5: crash into a wall, V = 0.6"]
#: The origin's light cone is drawn in the light's colour too: hidden here, so any of that colour is a signal.
BASE = DEFAULT_LAYERS - {Layer.LIGHT_CONE}


@pytest.fixture
def tab(browser: Any, app_server: App) -> Any:
    page = AppPage(browser, app_server)
    try:
        yield page
    finally:
        page.close()


def crash(layers: frozenset[Layer]) -> Settings:
    return CRASH.with_layers(layers)


def region(img: np.ndarray, tab: AppPage, r: Rect, inset: float = 3.0) -> np.ndarray:
    """The pixels of a page rectangle (less ``inset`` px all round)."""
    c0, r0 = tab.page_to_pixel(r.x0 + inset, r.z1 - inset)
    c1, r1 = tab.page_to_pixel(r.x1 - inset, r.z0 + inset)
    return img[round(r0) : round(r1), round(c0) : round(c1)]


def near(img: np.ndarray, color: np.ndarray, tol: float) -> np.ndarray:
    """Which pixels are within ``tol`` of ``color`` in every channel."""
    return np.asarray((np.abs(img - color.astype(np.int16)) <= tol).all(axis=-1))


def light(img: np.ndarray) -> np.ndarray:
    """Pixels of the light's colour (#C9A400: a strong yellow, unlike the rods, the wall and the frames' purple)."""
    r, g, b = img[..., 0], img[..., 1], img[..., 2]
    return np.asarray((r > 150) & (g > 110) & (b < 90) & (r - b > 110) & (np.abs(r - g) < 70))


def cone_shade(img: np.ndarray) -> np.ndarray:
    """Pixels of the key event's shaded future (the light's colour at 13 % over white)."""
    return near(img, color_rgb(rgba(LIGHT_COLOR, 0.13)), 6)


def rod_blue(img: np.ndarray) -> np.ndarray:
    """Pixels of the rod's colour, solid or as the world tube's pale shade."""
    return near(img, color_rgb(ROD_COLORS[0]), 40) | near(img, color_rgb(rgba(ROD_COLORS[0], 0.16)), 8)


def save(img: np.ndarray, path: Path) -> None:
    Image.fromarray(img.astype(np.uint8)).save(path)


def test_signals_are_drawn_in_the_diagrams_and_lanes_only_when_asked_for(tab: AppPage, shots: Path) -> None:
    s = tab.session
    first = tab.canvas()
    show(tab, crash(BASE), 0.5)
    off = tab.canvas_after(first)
    save(off, shots / "signals_off.png")
    layout = s.layout
    assert layout is not None
    plots = [layout.charts[0].plot, layout.charts[1].plot]
    lanes = [lane.band for lane in layout.lanes]
    for r in plots + lanes:
        assert light(region(off, tab, r)).sum() == 0
        assert cone_shade(region(off, tab, r)).sum() < 20

    show(tab, crash(BASE | {Layer.SIGNALS}), 0.5)
    on = tab.canvas_after(off)
    save(on, shots / "signals_on.png")
    layout = s.layout
    assert layout is not None
    for k in (0, 1):
        plot = region(on, tab, layout.charts[k].plot)
        assert light(plot).sum() > 150, f"no light ray in diagram {k}"
        assert cone_shade(plot).mean() > 0.05, f"no shaded future in diagram {k}"
    # the pulse: a bright bar in each lane, where the core's signal is at the lane's time
    d = s.drawn
    assert d is not None and d.signals is not None
    columns = []
    for lane_place, lane, sig in zip(layout.lanes, s.renderer_lanes, d.signals, strict=True):
        band = region(on, tab, lane_place.band, inset=0.0)
        cols = np.flatnonzero(light(band).any(axis=0))
        pulse_x = sig.pulse_positions(0.5)
        assert pulse_x.size == 1
        expected = lane.origin_px + float(pulse_x[0]) * lane.scale - (lane_place.band.x0 + 0.0)
        assert cols.size > 0, "no pulse in the lane"
        assert np.min(np.abs(cols - expected)) < 3.0, (cols, expected)
        columns.append(expected)

    # later, the pulse has moved on with the light (one unit of x per unit of t) in each lane
    with s.lock:
        s.seek(0.8)
    later = tab.canvas_after(on)
    save(later, shots / "signals_later.png")
    for lane_place, lane, sig, before in zip(layout.lanes, s.renderer_lanes, d.signals, columns, strict=True):
        band = region(later, tab, lane_place.band, inset=0.0)
        cols = np.flatnonzero(light(band).any(axis=0))
        pulse_x = sig.pulse_positions(0.8)
        expected = lane.origin_px + float(pulse_x[0]) * lane.scale - lane_place.band.x0
        assert np.min(np.abs(cols - expected)) < 3.0
        assert expected - before > 10.0, "the pulse did not move to the right"


def test_hiding_the_world_tubes_and_the_length_panel_empties_their_regions(tab: AppPage, shots: Path) -> None:
    s = tab.session
    first = tab.canvas()
    show(tab, crash(DEFAULT_LAYERS), 0.5)
    full = tab.canvas_after(first)
    save(full, shots / "all_layers.png")
    layout = s.layout
    assert layout is not None
    show(tab, crash(DEFAULT_LAYERS - {Layer.WORLD_TUBE, Layer.INTERIOR_LINES, Layer.LENGTH_PANEL}), 0.5)
    bare = tab.canvas_after(full)
    save(bare, shots / "no_tubes_no_lengths.png")
    assert s.layout == layout  # the panels keep their places
    for k in (0, 1):
        before = rod_blue(region(full, tab, layout.charts[k].plot)).sum()
        after = rod_blue(region(bare, tab, layout.charts[k].plot)).sum()
        assert before > 2000
        assert after < 0.05 * before, f"diagram {k}: the rod's colour is left ({after} of {before} px)"
    for lane in layout.lanes:  # the lanes still draw the rod
        before = rod_blue(region(full, tab, lane.band)).sum()
        after = rod_blue(region(bare, tab, lane.band)).sum()
        assert abs(after - before) < 0.05 * before
    lengths_full = region(full, tab, layout.charts[2].plot)
    lengths_bare = region(bare, tab, layout.charts[2].plot)
    ink_full = int((lengths_full.sum(axis=-1) < 600).sum())
    ink_bare = int((lengths_bare.sum(axis=-1) < 600).sum())
    assert ink_full > 1500
    assert ink_bare < 0.25 * ink_full, (ink_bare, ink_full)
    texts = tab.texts()
    assert LENGTH_HIDDEN_TITLE in texts
    assert LENGTH_HIDDEN_NOTE in texts


def test_layers_reach_the_session(tab: AppPage) -> None:
    """The drawing the session keeps is built with the layers asked for (the pixel tests' premise)."""
    show(tab, crash(frozenset(Layer)), 0.2)
    d: Any = tab.session.drawn
    assert d.resolved.layers == frozenset(Layer)
    assert d.signals is not None
