"""Exported pages in headless Chromium with the network cut: they make no request, animate, respond."""

from __future__ import annotations

import io
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from PIL import Image

import rigidrel_core as rr
from rigidrel_app.export.diagram_html import diagram_html
from rigidrel_app.export.recording import record_lanes_html
from rigidrel_app.view.scene_view import build_drawing
from rigidrel_app.view.state import Resolved, Settings
from tests.viser_client import wait_until

pytestmark = pytest.mark.browser

ALLOWED = ("file://", "data:", "blob:", "about:")


class OfflinePage:
    """A page whose every non-local request is aborted and recorded."""

    def __init__(self, browser: Any, path: Path) -> None:
        self.context = browser.new_context(viewport={"width": 1280, "height": 860})
        self.requests: list[str] = []
        self.errors: list[str] = []

        def route(r: Any) -> None:
            url = r.request.url
            if url.startswith(ALLOWED):
                r.continue_()
            else:
                self.requests.append(url)
                r.abort()

        self.context.route("**/*", route)
        self.page = self.context.new_page()
        self.page.on("pageerror", lambda e: self.errors.append(str(e)))
        self.page.goto(path.as_uri())

    def png(self, selector: str | None = None) -> np.ndarray:
        shot = self.page.locator(selector).screenshot() if selector else self.page.screenshot()
        return np.asarray(Image.open(io.BytesIO(shot)).convert("RGB")).astype(int)

    def close(self) -> None:
        self.context.close()


@pytest.fixture(scope="module")
def exported(tmp_path_factory: pytest.TempPathFactory) -> dict[str, Path]:
    out = tmp_path_factory.mktemp("offline")
    scene = rr.rod_collision(0.6, 0.0, 1.0, 2.0, 1.0, 1.0, 1.0)
    drawn = build_drawing(Resolved(scene, scene.frame("barycentric"), None))
    lanes = out / "lanes.html"
    lanes.write_text(record_lanes_html(drawn, seconds=6.0, fps=20.0), encoding="utf-8")
    slider = out / "diagram.html"
    slider.write_text(diagram_html(Settings("rod-collision")), encoding="utf-8")
    return {"lanes": lanes, "diagram": slider}


def test_3d_recording_plays_offline(browser: Any, exported: dict[str, Path], shots: Path) -> None:
    page = OfflinePage(browser, exported["lanes"])
    try:
        page.page.wait_for_selector("canvas[data-engine]", timeout=60_000)

        def rods(img: np.ndarray) -> np.ndarray:
            return ((img[..., 2] - img[..., 0]) > 80) | ((img[..., 0] - img[..., 2]) > 120)

        # the rods are drawn, and where they are differs between two moments of playback
        def drawn() -> bool:
            return rods(page.png("canvas[data-engine]")).mean() > 0.005

        wait_until(drawn, timeout=60)
        a = page.png("canvas[data-engine]")
        page.page.screenshot(path=str(shots / "playing_a.png"))

        def moved_on() -> bool:
            b = page.png("canvas[data-engine]")
            moved = np.abs(a - b).sum(axis=-1) > 60
            return bool(moved[rods(a) | rods(b)].mean() > 0.02)

        wait_until(moved_on, timeout=30, interval=0.25)
        page.page.screenshot(path=str(shots / "playing_b.png"))
        assert page.requests == []
        assert page.errors == []
    finally:
        page.close()


def test_diagram_page_responds_to_its_slider_offline(browser: Any, exported: dict[str, Path], shots: Path) -> None:
    page = OfflinePage(browser, exported["diagram"])
    try:
        page.page.wait_for_selector(".js-plotly-plot", timeout=60_000)
        title = "() => document.querySelector('.js-plotly-plot').layout.title.text"
        traces = "() => Array.from(document.querySelector('.js-plotly-plot')._fullData[5].x)"
        before_title = wait_until(lambda: page.page.evaluate(title))
        before = page.page.evaluate(traces)
        assert "β = 0.2308" in before_title  # case I's barycentric frame: V1 = 0.6, M2/M1 = 2
        # as a user: click the first step of the mass-ratio slider (the page's second slider)
        group = page.page.locator("g.slider-group").nth(1)
        label = group.locator("g.slider-label-group").nth(0).bounding_box()
        rail = group.locator("rect.slider-rail-touch-rect").bounding_box()
        assert label is not None and rail is not None
        page.page.mouse.click(label["x"] + label["width"] / 2, rail["y"] + rail["height"] / 2)
        after_title = wait_until(lambda: (t := page.page.evaluate(title)) != before_title and t)
        after = page.page.evaluate(traces)
        page.page.screenshot(path=str(shots / "mass_ratio_0.01.png"))
        assert "β = 0.5952)" in after_title  # M2/M1 = 0.01: u = M1 γ V / (M1 γ + M2) = 0.75/1.26
        assert after != before
        # the play button sweeps V1
        page.page.click("text=▶ V1")
        wait_until(lambda: page.page.evaluate(title) != after_title)
        assert page.requests == [] and page.errors == []
    finally:
        page.close()
