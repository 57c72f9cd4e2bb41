"""An exported lesson, opened from disk in headless Chromium with the network cut: it makes no
request, moves between steps by keyboard, its canvas plays and its diagram's sliders respond; a
step's caption and canvas fit one screen, at the live app's text sizes."""

from __future__ import annotations

import re
from pathlib import Path
from typing import Any

import pytest

from rigidrel_app.export.lesson_site import CANVAS_HEIGHT, CANVAS_WIDTH, export_lesson
from rigidrel_app.lessons import parse_lesson
from tests.viser_client import wait_until

pytestmark = pytest.mark.browser

LESSON = """title = "Crash and bounce"
subtitle = "two steps"

[[step]]
title = "The crash"
scene = "wall-collision --v 0.6 --eps 0 --frame lab"
caption = "The back end starts braking at t = {event[T_1].t:.3g}, **before** the contact."

[[step]]
title = "The bounce"
scene = "wall-collision --v 0.6 --eps 1"
caption = "It leaves at V′ = {rod[1].v_after:.3g}."
"""
LOCAL = ("file://", "data:", "blob:", "about:")


@pytest.fixture(scope="module")
def site(tmp_path_factory: pytest.TempPathFactory) -> Path:
    out = tmp_path_factory.mktemp("lesson")
    export_lesson(parse_lesson(LESSON, "crash.toml"), out, seconds=4.0, fps=15.0)
    return out


def test_the_folder(site: Path) -> None:
    names = sorted(p.name for p in site.iterdir())
    assert names == sorted(
        ["index.html", "plotly.min.js"]
        + [f"step-0{k}{suffix}.html" for k in (1, 2) for suffix in ("", "-canvas", "-diagram")]
    )
    page = (site / "step-01.html").read_text(encoding="utf-8")
    assert "The back end starts braking at t = −0.75, <strong>before</strong> the contact." in page
    assert "src='plotly.min.js'" not in page  # the step page itself loads no plotly
    assert 'src="plotly.min.js"' in (site / "step-01-diagram.html").read_text(encoding="utf-8")
    assert not re.search(r"(src|href)=['\"]https?:", page)


def test_offline_by_keyboard(browser: Any, site: Path, shots: Path) -> None:
    context = browser.new_context(viewport={"width": 1280, "height": 720})
    requests: list[str] = []
    errors: list[str] = []
    context.on("request", lambda r: None if r.url.startswith(LOCAL) else requests.append(r.url))
    context.route(re.compile(r"^(https?|wss?|ftp)://"), lambda route: route.abort())
    try:
        page = context.new_page()

        def arrive(name: str) -> None:  # the page is there and its keys are listened to
            page.wait_for_url(f"**/{name}", wait_until="commit")
            page.wait_for_function("() => typeof NEXT !== 'undefined'")

        page.on("pageerror", lambda e: errors.append(str(e)))
        page.goto((site / "index.html").as_uri())
        arrive("index.html")
        assert page.locator("ol.index li").count() == 2
        page.keyboard.press("ArrowRight")
        arrive("step-01.html")
        page.wait_for_selector("h1:has-text('The crash')")
        lanes = page.frame_locator("iframe.canvas")
        canvas = lanes.locator("canvas[data-engine]")
        canvas.wait_for(timeout=60_000)

        # the recording plays: its playback slider moves on (its pixels are checked in test_export_browser)
        progress = lanes.locator("[role=slider]").first

        def now() -> float:
            return float(progress.get_attribute("aria-valuenow") or "nan")

        first = wait_until(lambda: (v := now()) == v and v, timeout=60)  # a number, not NaN
        wait_until(lambda: now() != first, timeout=30)
        # the diagram's sliders respond (plotly from the folder's one copy)
        diagram = page.frame_locator("iframe.diagram")
        diagram.locator(".js-plotly-plot .main-svg").first.wait_for(timeout=60_000)
        frame = next(f for f in page.frames if f.url.endswith("step-01-diagram.html"))
        curves = "() => JSON.stringify(document.querySelector('.js-plotly-plot')._fullData.map(d => d.x))"
        before = frame.evaluate(curves)
        diagram.locator("text=▶ V").first.click(force=True)  # sweeps V: every curve is redrawn
        wait_until(lambda: frame.evaluate(curves) != before, timeout=30)
        page.screenshot(path=str(shots / "step_1.png"), timeout=120_000)
        # the clicker's key with the focus still inside the diagram's frame (its slider's play
        # button was clicked last): the step page around it moves on
        assert page.evaluate("() => document.activeElement && document.activeElement.tagName") == "IFRAME"
        page.keyboard.press("PageDown")
        arrive("step-02.html")
        page.wait_for_selector("text=It leaves at V′ = 0.6.")
        # a click into the canvas' frame, then ←: back
        lanes = page.frame_locator("iframe.canvas")
        lanes.locator("canvas[data-engine]").click(timeout=60_000)
        assert page.evaluate("() => document.activeElement && document.activeElement.tagName") == "IFRAME"
        page.keyboard.press("ArrowLeft")
        arrive("step-01.html")
        page.locator("h1").click()
        page.keyboard.press("Home")
        arrive("index.html")
        assert requests == [], requests
        assert errors == [], errors
    finally:
        context.close()


@pytest.mark.parametrize(("width", "height"), [(1280, 720), (1920, 1080)])
def test_a_step_fits_one_screen_at_the_app_s_text_sizes(
    browser: Any, site: Path, shots: Path, width: int, height: int
) -> None:
    """The caption band over the app's canvas, both within the screen's height: at 1280x720 the
    canvas at one page px per CSS px (the live app's text sizes), at 1920x1080 zoomed whole."""
    page = browser.new_page(viewport={"width": width, "height": height})
    try:
        page.goto((site / "step-01.html").as_uri())
        page.frame_locator("iframe.canvas").locator("canvas[data-engine]").wait_for(timeout=60_000)
        band, canvas = page.locator(".band").bounding_box(), page.locator("iframe.canvas").bounding_box()
        assert band is not None and canvas is not None
        assert band["y"] == 0 and canvas["y"] >= band["y"] + band["height"] - 1
        assert canvas["y"] + canvas["height"] <= height + 1, (band, canvas)  # nothing of it below the fold
        zoom = float(page.evaluate("() => getComputedStyle(document.querySelector('iframe.canvas')).zoom"))
        recorded = (CANVAS_WIDTH, CANVAS_HEIGHT)
        assert canvas["width"] == pytest.approx(zoom * recorded[0], abs=1) and canvas["height"] == pytest.approx(
            zoom * recorded[1], abs=1
        )
        if width == 1280:
            assert zoom == pytest.approx(1.0, abs=0.01) and height - canvas["height"] == pytest.approx(band["height"])
        else:
            assert zoom > 1.4  # a hall's screen shows it larger, text and all
        page.screenshot(path=str(shots / f"exported-step-{width}x{height}.png"))
    finally:
        page.close()
