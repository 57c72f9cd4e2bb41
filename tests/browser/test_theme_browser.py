"""The dark projector theme in a real browser: key T turns it on and off, a server started dark opens
every tab dark, and a lesson's caption band follows it.

The canvas is measured, not just the session's flag: on a dark page the ground is black, the rods
show their lightness-flipped colour, and the panel is in viser's dark mode. The tests of one tab
share one, reset before each to where a new tab opens; the tests of a server started dark, with
tabs of their own, come first (the shared tab, opened by the first test that takes it, draws
beside none of them).
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np
import pytest

from rigidrel_app.lessons import builtin_lesson
from rigidrel_app.live.controls import CAPTION_GROUND
from rigidrel_app.live.server import App
from rigidrel_app.view.vocabulary import ROD_COLORS, lightness_flipped, rgb, shaded
from tests.browser.test_app_browser import AppPage
from tests.viser_client import wait_until

pytestmark = pytest.mark.browser


@pytest.fixture
def tab(shared_tab: AppPage) -> AppPage:
    """The file's one tab, back where a new tab opens (:meth:`AppPage.reset`)."""
    shared_tab.reset()
    return shared_tab


PAPER = builtin_lesson("paper")

#: A canvas pixel is the rods' colour when every channel is this close to it (the boxes are lit).
ROD_TOLERANCE = 40
#: At least this share of a default scene's canvas is the rods' fill (measured: about 4 %).
ROD_SHARE = 0.02
#: At least this share of the canvas is the ground (measured: about 83 %).
GROUND_SHARE = 0.6


def share_near(canvas: np.ndarray, color: tuple[int, int, int] | np.ndarray, tolerance: float) -> float:
    """The share of the canvas' pixels within ``tolerance`` of ``color`` in every channel."""
    return float((np.abs(canvas - np.asarray(color, dtype=np.int16)).max(axis=-1) < tolerance).mean())


def assert_dark(canvas: np.ndarray) -> None:
    rod = rgb(ROD_COLORS[0])
    assert share_near(canvas, (0, 0, 0), 20) > GROUND_SHARE
    assert share_near(canvas, lightness_flipped(rod), ROD_TOLERANCE) > ROD_SHARE
    assert share_near(canvas, rod, ROD_TOLERANCE) < 1e-3  # no rod keeps its light-theme blue


def assert_light(canvas: np.ndarray) -> None:
    rod = rgb(ROD_COLORS[0])
    assert share_near(canvas, (255, 255, 255), 20) > GROUND_SHARE
    assert share_near(canvas, rod, ROD_TOLERANCE) > ROD_SHARE


def css_rgb(color: str) -> str:
    """``"#RRGGBB"`` as the browser's computed style writes it."""
    return "rgb({}, {}, {})".format(*rgb(color))


def still(page: Any) -> bool:
    """Whether two screenshots of the page, taken one after the other, are the same."""
    first = page.screenshot(type="png")
    return first == page.screenshot(type="png")


def color_scheme(tab: AppPage) -> str:
    return tab.page.evaluate("() => document.documentElement.getAttribute('data-mantine-color-scheme')")


def test_a_server_started_dark_opens_every_tab_dark(browser: Any, shots: Path) -> None:
    app = App(host="127.0.0.1", port=0, shade="dark")
    tab = None
    try:
        tab = AppPage(browser, app)
        assert_dark(tab.canvas_after(np.full_like(tab.canvas(), 255)))
        assert tab.control("Dark theme").is_checked()
        wait_until(lambda: color_scheme(tab) == "dark")
        tab.page.screenshot(path=str(shots / "opened_dark.png"))
    finally:
        if tab is not None:
            tab.close()
        app.stop()


def test_a_lesson_caption_follows_the_theme(browser: Any, shots: Path) -> None:
    app = App(host="127.0.0.1", port=0, lesson=PAPER, shade="dark")
    page = browser.new_page(viewport={"width": 1280, "height": 720})
    try:
        page.goto(app.url)
        band = page.locator("#rigidrel-caption")
        band.wait_for(state="visible", timeout=60_000)
        wait_until(lambda: PAPER.steps[0].title in band.inner_text(), timeout=30)
        background = page.evaluate(
            "() => getComputedStyle(document.getElementById('rigidrel-caption')).backgroundColor"
        )
        assert background == css_rgb(shaded(CAPTION_GROUND, "dark"))  # the band's colour, lightness flipped
        session = wait_until(lambda: next(iter(app.sessions.values()), None), timeout=30)
        wait_until(lambda: session.painter.layout is not None and session.painter.canvas_size.measured, timeout=30)
        page.evaluate("() => document.activeElement && document.activeElement.blur()")
        if session.state.playback.playing:  # the step plays on arrival: paused, to be photographed still
            page.keyboard.press(" ")
            wait_until(lambda: not session.state.playback.playing)
        wait_until(lambda: still(page), timeout=60, interval=0.5)
        page.screenshot(path=str(shots / "lesson_dark.png"))
        page.evaluate("() => document.activeElement && document.activeElement.blur()")
        page.keyboard.press("t")
        wait_until(lambda: session.state.shade == "light")
        wait_until(
            lambda: (
                page.evaluate("() => getComputedStyle(document.getElementById('rigidrel-caption')).backgroundColor")
                == css_rgb(CAPTION_GROUND)
            ),
            timeout=30,
        )
        page.screenshot(path=str(shots / "lesson_light_again.png"))
    finally:
        page.close()
        app.stop()


def test_t_turns_the_dark_theme_on_and_off(tab: AppPage, shots: Path) -> None:
    tab.page.set_viewport_size({"width": 1280, "height": 720})
    wait_until(lambda: tab.session.painter.layout is not None and tab.session.painter.layout.height == 720)
    light = tab.canvas_after(np.zeros_like(tab.canvas()))
    assert_light(light)
    tab.page.evaluate("() => document.activeElement && document.activeElement.blur()")
    tab.page.keyboard.press("t")
    wait_until(lambda: tab.session.state.shade == "dark")
    dark = tab.canvas_after(light)
    assert_dark(dark)
    wait_until(lambda: color_scheme(tab) == "dark")
    assert tab.control("Dark theme").is_checked()
    assert tab.session.painter.layout is not None and tab.session.painter.layout.theme.shade == "dark"
    tab.page.screenshot(path=str(shots / "dark_1280x720.png"))
    tab.page.keyboard.press("t")
    wait_until(lambda: tab.session.state.shade == "light")
    assert_light(tab.canvas_after(dark))
    wait_until(lambda: color_scheme(tab) == "light")
    assert tab.errors == []


def test_the_checkbox_and_presenter_mode_keep_the_theme(tab: AppPage, shots: Path) -> None:
    tab.page.set_viewport_size({"width": 1280, "height": 720})
    wait_until(lambda: tab.session.painter.layout is not None and tab.session.painter.layout.height == 720)
    before = tab.canvas_after(np.zeros_like(tab.canvas()))
    tab.control("Dark theme").click()
    wait_until(lambda: tab.session.state.shade == "dark")
    assert_dark(tab.canvas_after(before))
    tab.page.evaluate("() => document.activeElement && document.activeElement.blur()")
    tab.page.keyboard.press("f")
    wait_until(lambda: tab.session.state.presenter)
    wait_until(lambda: tab.session.painter.layout is not None and tab.session.painter.layout.width > 1200, timeout=30)
    presenter = tab.canvas_after(np.zeros_like(tab.canvas()))  # a new canvas size: nothing to compare with
    assert_dark(presenter)
    assert tab.session.painter.layout is not None and tab.session.painter.layout.theme.name == "presenter"
    tab.page.screenshot(path=str(shots / "dark_presenter_1280x720.png"))
    assert tab.errors == []
