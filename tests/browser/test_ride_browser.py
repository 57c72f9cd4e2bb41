"""The riding frame and the light cone of a chosen event, in a real browser, measured in pixels.

Measured on the canvas's pixels: in the lab lane a rod that has reached V is drawn shorter than at
rest (Lorentz contraction), while in the lane that rides its back end it spans the same pixels at
every instant, with the ridden end still at the lane's centre. The tests share one tab, reset
before each to where a new tab opens.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from rigidrel_app.view.comoving import RidePoint
from rigidrel_app.view.state import RIDE_FRAME, Settings
from rigidrel_app.view.vocabulary import LIGHT_COLOR
from tests.browser.test_app_browser import PIXEL_TOLERANCE, AppPage, rods_drawn, show
from tests.viser_client import wait_until

pytestmark = pytest.mark.browser


@pytest.fixture
def tab(shared_tab: AppPage) -> AppPage:
    """The file's one tab, back where a new tab opens (:meth:`AppPage.reset`)."""
    shared_tab.reset()
    return shared_tab


def test_the_riding_lane_keeps_the_rod_at_rest_length(tab: AppPage, shots: Path) -> None:
    before = tab.canvas()
    tab.choose("Frame", RIDE_FRAME)  # as a person would: the menu, then the point's box
    wait_until(
        lambda: tab.session.painter.drawn is not None and tab.session.painter.drawn.resolved.ride is not None,
        timeout=60,
    )
    img = tab.canvas_after(before)
    tab.type_into_slider("Ride: point f", 0.0)
    wait_until(lambda: tab.session.painter.drawn.resolved.ride == RidePoint(0, 0.0), timeout=60)  # type: ignore[union-attr]
    img = tab.canvas_after(img)
    assert "riding: comoving with rod at f = 0" in tab.session.painter.renderer_lanes[1].title
    layout = tab.session.painter.layout
    assert layout is not None
    place = layout.lanes[1]
    centre = 0.5 * (place.track.x0 + place.track.x1)
    lab_px, ride_px = [], []
    for now in (-0.5, 1.5):  # at rest, then at V = 0.6 (lab length 0.8 L0)
        tab.type_into_slider("t, t'", now)
        wait_until(lambda now=now: abs(tab.session.state.playback.now - now) < 1e-9, timeout=60)
        img = tab.canvas_after(img)
        lab, riding = rods_drawn(tab)
        tab.page.screenshot(path=str(shots / f"riding_back_end_t_{now}.png"))
        lane = tab.session.painter.renderer_lanes[1]
        expected = 1.0 * lane.scale  # the rest length, L0 = 1, in this lane's pixels
        (a, b) = riding[0]
        assert abs((b - a) - expected) <= 2 * PIXEL_TOLERANCE, (now, b - a, expected)
        assert abs(a - centre) <= PIXEL_TOLERANCE, (now, a, centre)  # the ridden end stays put
        lab_px.append(lab[0][1] - lab[0][0])
        ride_px.append(b - a)
    assert abs(ride_px[0] - ride_px[1]) <= 2 * PIXEL_TOLERANCE, ride_px
    assert lab_px[0] - lab_px[1] > 10 * PIXEL_TOLERANCE, lab_px  # the lab sees it contracted: the test can fail
    # both lanes at one scale: at V = 0.6 the lab's rod (0.8 L0) is drawn 0.8 of the riding one (L0),
    # at 1280x720 and again at 1920x1080
    assert lab_px[1] / ride_px[1] == pytest.approx(0.8, abs=3 * PIXEL_TOLERANCE / ride_px[1]), (lab_px, ride_px)
    tab.page.set_viewport_size({"width": 1920, "height": 1080})
    wait_until(lambda: (lay := tab.session.painter.layout) is not None and lay.height > 900, timeout=60)
    tab.canvas_after(np.zeros_like(tab.canvas()))  # at its new size (rods_drawn waits for the rods)
    lab, riding = rods_drawn(tab)
    tab.page.screenshot(path=str(shots / "riding_back_end_1920x1080.png"))
    big_lab, big_ride = lab[0][1] - lab[0][0], riding[0][1] - riding[0][0]
    assert big_ride > ride_px[1] and big_lab / big_ride == pytest.approx(0.8, abs=3 * PIXEL_TOLERANCE / big_ride)
    assert tab.errors == []


def _light_pixels(img: np.ndarray, color: str) -> int:
    """Pixels within a small distance of the light rays' colour."""
    rgb = np.array([int(color[k : k + 2], 16) for k in (1, 3, 5)])
    return int((np.abs(img - rgb).sum(axis=-1) < 60).sum())


def test_an_event_chosen_from_the_list_gets_its_light_cone_on_both_diagrams(tab: AppPage, shots: Path) -> None:
    default_scene = tab.canvas()
    show(tab, Settings.of("wall-collision", v=0.6, eps=0.0), 0.5)
    img = tab.canvas_after(default_scene)
    layout = tab.session.painter.layout
    assert layout is not None
    top = round(layout.height - layout.diagram.outer.z1)  # the diagrams' part of the canvas
    before = [
        _light_pixels(img[top:, round(c.outer.x0) : round(c.outer.x1)], LIGHT_COLOR) for c in layout.shown_charts[:2]
    ]
    tab.choose("Light cone of", "T_1")
    wait_until(lambda: tab.session.painter.drawn.resolved.cone == "T_1", timeout=60)  # type: ignore[union-attr]
    img = tab.canvas_after(img)
    tab.page.screenshot(path=str(shots / "light_cone_of_T1.png"))
    after = [
        _light_pixels(img[top:, round(c.outer.x0) : round(c.outer.x1)], LIGHT_COLOR) for c in layout.shown_charts[:2]
    ]
    for b, a in zip(before, after, strict=True):  # the cone's dashed rays, in both diagrams
        assert a > b + 150, (before, after)
    assert "--cone T_1" in tab.session.controls.scenario_shown.content
    assert tab.errors == []
