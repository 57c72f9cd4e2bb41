"""The layers on the canvas, looked at in pixels: the light signals appear in the diagrams' plot
areas and in the lanes (the pulse moving with time) when asked for and never otherwise; hiding the
world tubes or the length panel empties exactly those regions.

The settings are set on the server, as a preset would (``show``); every picture is awaited until
it has changed and settled, never after a fixed sleep. The tests share one tab, reset before each
to where a new tab opens.
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from PIL import Image

from rigidrel_app.view.canvas import color_rgb
from rigidrel_app.view.layers import DEFAULT_LAYERS, Layer
from rigidrel_app.view.layout import Rect
from rigidrel_app.view.state import Settings, presets
from rigidrel_app.view.vocabulary import LIGHT_COLOR, ROD_COLORS, rgba
from tests.browser.test_app_browser import AppPage, show
from tests.viser_client import shown, wait_until

pytestmark = pytest.mark.browser


@pytest.fixture
def tab(shared_tab: AppPage) -> AppPage:
    """The file's one tab, back where a new tab opens (:meth:`AppPage.reset`)."""
    shared_tab.reset()
    return shared_tab


CRASH = presets()["Sec. 5: crash into a wall, V = 0.6"]
#: The origin's light cone is drawn in the light's colour too: hidden here, so any of that colour is a signal.
BASE = DEFAULT_LAYERS - {Layer.LIGHT_CONE}


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
    """Pixels of the light's colour (a deep gold with no blue, unlike the rods, the wall and the frames' wine)."""
    return near(img, color_rgb(LIGHT_COLOR), 36)


def cone_shade(img: np.ndarray) -> np.ndarray:
    """Pixels of the key event's shaded future (the light's colour at 13 % over white)."""
    return near(img, color_rgb(rgba(LIGHT_COLOR, 0.13)), 6)


def rod_blue(img: np.ndarray) -> np.ndarray:
    """Pixels of the rod's colour, solid or as the world tube's pale shade."""
    return near(img, color_rgb(ROD_COLORS[0]), 40) | near(img, color_rgb(rgba(ROD_COLORS[0], 0.16)), 8)


def save(img: np.ndarray, path: Path) -> None:
    Image.fromarray(img.astype(np.uint8)).save(path)


Check = Callable[[np.ndarray], list[str]]


def canvas_showing(tab: AppPage, before: np.ndarray, check: Check, timeout: float = 60.0) -> np.ndarray:
    """The canvas once it has changed from ``before``, settled, and passes ``check`` (no problems
    listed): the server's whole update drawn, however slowly the browser draws it. On a timeout the
    problems of the last canvas are the failure's message."""
    shots = [tab.canvas_after(before)]

    def ok() -> bool:
        if not check(shots[-1]):
            return True
        shots.append(tab.canvas())
        return False

    try:
        wait_until(ok, timeout=timeout, interval=0.25)
    except AssertionError:
        pytest.fail("; ".join(check(shots[-1])))
    return shots[-1]


def pulse_problems(tab: AppPage, img: np.ndarray, now: float) -> list[str]:
    """Each lane's pulse: a bar of the light's colour at the page x where the core's signal is at ``now``."""
    s = tab.session
    layout, d = s.painter.layout, s.painter.drawn
    assert layout is not None and d is not None and d.signals is not None
    problems = []
    for k, (place, lane, sig) in enumerate(zip(layout.lanes, s.painter.renderer_lanes, d.signals, strict=True)):
        cols = np.flatnonzero(light(region(img, tab, place.band, inset=0.0)).any(axis=0))
        x = sig.pulse_positions(now)
        if x.size != 1:
            problems.append(f"lane {k}: {x.size} pulses in flight at {now}")
            continue
        expected = lane.origin_px + float(x[0]) * lane.scale - place.band.x0
        if cols.size == 0 or np.min(np.abs(cols - expected)) >= 3.0:
            problems.append(f"lane {k}: no pulse at column {expected:.1f} (light at {cols.tolist()[:12]})")
    return problems


def test_signals_are_drawn_in_the_diagrams_and_lanes_only_when_asked_for(tab: AppPage, shots: Path) -> None:
    s = tab.session
    first = tab.canvas()
    show(tab, crash(BASE), 0.5)
    layout = s.painter.layout
    assert layout is not None
    regions = [shown(layout.charts[0]).plot, shown(layout.charts[1]).plot, *(lane.band for lane in layout.lanes)]

    def no_light(img: np.ndarray) -> list[str]:
        counts = [(light(region(img, tab, r)).sum(), cone_shade(region(img, tab, r)).sum()) for r in regions]
        return [f"region {k}: {a} px of light, {b} of its cone" for k, (a, b) in enumerate(counts) if a > 0 or b >= 20]

    off = canvas_showing(tab, first, no_light)
    save(off, shots / "signals_off.png")

    def diagrams_lit(img: np.ndarray) -> list[str]:
        assert layout is not None
        problems = []
        for k in (0, 1):
            plot = region(img, tab, shown(layout.charts[k]).plot)
            if light(plot).sum() <= 150:
                problems.append(f"no light ray in diagram {k}")
            if cone_shade(plot).mean() <= 0.05:
                problems.append(f"no shaded future in diagram {k}")
        return problems

    show(tab, crash(BASE | {Layer.SIGNALS}), 0.5)
    layout = s.painter.layout  # the legend may take another row
    assert layout is not None
    on = canvas_showing(tab, off, lambda img: diagrams_lit(img) + pulse_problems(tab, img, 0.5))
    save(on, shots / "signals_on.png")

    # later, the pulse has moved on with the light (one unit of x per unit of t) in each lane
    with s.lock:
        s.asks.seek(0.8)
    later = canvas_showing(tab, on, lambda img: pulse_problems(tab, img, 0.8))
    save(later, shots / "signals_later.png")
    for k, place in enumerate(layout.lanes):  # and on the screen: the bar has moved right
        was = np.flatnonzero(light(region(on, tab, place.band)).any(axis=0)).mean()
        now = np.flatnonzero(light(region(later, tab, place.band)).any(axis=0)).mean()
        assert now - was > 10.0, f"lane {k}: the light moved from column {was:.0f} to {now:.0f}"


def test_hiding_the_world_tubes_and_the_length_panel_empties_their_regions(tab: AppPage, shots: Path) -> None:
    s = tab.session
    first = tab.canvas()
    show(tab, crash(DEFAULT_LAYERS), 0.5)
    layout = s.painter.layout
    assert layout is not None

    def lengths_ink(img: np.ndarray) -> int:
        """Dark pixels of the length panel's plot area (as the page is laid out now), its middle
        rows (the hidden panel's note) left out."""
        now = s.painter.layout
        assert now is not None
        plot = shown(now.charts[2]).plot
        middle = slice(round(0.35 * plot.height), round(0.65 * plot.height))
        return int((np.delete(region(img, tab, plot), middle, axis=0).sum(axis=-1) < 600).sum())

    def drawn(img: np.ndarray) -> list[str]:
        problems = [
            f"diagram {k}: no rod"
            for k in (0, 1)
            if rod_blue(region(img, tab, shown(layout.charts[k]).plot)).sum() < 2000
        ]
        return problems + (["no length curves"] if lengths_ink(img) < 1500 else [])

    full = canvas_showing(tab, first, drawn)
    save(full, shots / "all_layers.png")
    tubes = [rod_blue(region(full, tab, shown(layout.charts[k]).plot)).sum() for k in (0, 1)]
    lanes = [rod_blue(region(full, tab, lane.band)).sum() for lane in layout.lanes]
    ink = lengths_ink(full)

    def hidden(img: np.ndarray) -> list[str]:
        problems = []
        now = s.painter.layout  # fewer legend entries may take fewer rows: the diagrams grow
        assert now is not None
        for k in (0, 1):
            left = rod_blue(region(img, tab, shown(now.charts[k]).plot)).sum()
            if left >= 0.05 * tubes[k]:
                problems.append(f"diagram {k}: the rod's colour is left ({left} of {tubes[k]} px)")
        if now.charts[2] is not None:
            problems.append("the length panel is still laid out")
        for k, lane in enumerate(layout.lanes):  # the lanes still draw the rod (edges blur when the
            blue = rod_blue(region(img, tab, lane.band)).sum()  # client renders below full resolution)
            if abs(blue - lanes[k]) >= 0.2 * lanes[k]:
                problems.append(f"lane {k}: the rod changed ({blue} of {lanes[k]} px)")
        return problems

    assert ink > 0
    show(tab, crash(DEFAULT_LAYERS - {Layer.WORLD_TUBE, Layer.INTERIOR_LINES, Layer.LENGTH_PANEL}), 0.5)
    bare = canvas_showing(tab, full, hidden)
    save(bare, shots / "no_tubes_no_lengths.png")
    # the lanes keep their places; the hidden panel gives its room to the two diagrams, and a legend
    # of fewer rows gives its own
    new = s.painter.layout
    assert new is not None and new.lanes == layout.lanes and new.theme == layout.theme
    assert new.charts[2] is None and new.legend.z1 <= layout.legend.z1
    (a, b), (c, d) = ((shown(x.charts[0]).outer, shown(x.charts[1]).outer) for x in (layout, new))
    assert c.x0 == a.x0 and d.x1 == pytest.approx(shown(layout.charts[2]).outer.x1)
    assert c.width > 1.4 * a.width and d.width > 1.4 * b.width
    assert c.z1 == a.z1 and c.z0 - a.z0 == pytest.approx(new.legend.z1 - layout.legend.z1)
    assert not [t for t in tab.texts() if t.startswith("Equal-time length")]


def test_layers_reach_the_session(tab: AppPage) -> None:
    """The drawing the session keeps is built with the layers asked for (the pixel tests' premise)."""
    show(tab, crash(frozenset(Layer)), 0.2)
    d: Any = tab.session.painter.drawn
    assert d.resolved.layers == frozenset(Layer)
    assert d.signals is not None
