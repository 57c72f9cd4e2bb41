"""Exported pages in headless Chromium with the network cut: they make no request, animate, respond."""

from __future__ import annotations

import io
from dataclasses import replace
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
from tests.browser.conftest import element_png
from tests.browser.test_app_browser import SOFTWARE_NOTE
from tests.sweeps import cases
from tests.viser_client import wait_until

pytestmark = pytest.mark.browser

ALLOWED = ("file://", "data:", "blob:", "about:")


class OfflinePage:
    """A page whose every non-local request is aborted and recorded."""

    def __init__(self, browser: Any, path: Path, viewport: tuple[int, int] = (1280, 860)) -> None:
        self.context = browser.new_context(viewport={"width": viewport[0], "height": viewport[1]})
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

    def png(self, selector: str | None = None, timeout_ms: float = 30_000) -> np.ndarray:
        if selector:
            return element_png(self.page, selector, timeout_ms).astype(int)
        return np.asarray(Image.open(io.BytesIO(self.page.screenshot())).convert("RGB")).astype(int)

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
    pages = {"lanes": lanes, "diagram": slider}
    for name, settings in EXTREME_PAGES.items():
        pages[name] = out / f"{name}.html"
        pages[name].write_text(diagram_html(settings), encoding="utf-8")
    return pages


#: Diagram pages at the settings where a lecturer found labels printed over each other.
EXTREME_PAGES = {
    "v-0.99": Settings.of("constant-acceleration", v=0.99),
    "fig1": replace(Settings("constant-acceleration"), overlay=True),
    "m2-0.01": Settings.of("rod-collision", mass2=0.01),
    "m2-100": Settings.of("rod-collision", mass2=100.0),
    "l2-0.1": Settings.of("rod-collision", length2=0.1),
    "frame-slider": Settings("impulsive-start"),
}

_DOM = """() => {
  const gd = document.querySelector('.js-plotly-plot');
  const box = e => { const r = e.getBoundingClientRect(); return [r.left, r.top, r.right, r.bottom]; };
  const px = e => parseFloat(getComputedStyle(e).fontSize);
  return {
    labels: Array.from(gd.querySelectorAll('text.annotation-text')).map(e => ({text: e.textContent, box: box(e),
      size: px(e)})),
    ytitles: Array.from(gd.querySelectorAll('.g-ytitle text')).map(e => e.textContent),
    xtitles: Array.from(gd.querySelectorAll('.g-xtitle text')).map(e => e.textContent),
    titleSizes: Array.from(gd.querySelectorAll('.g-xtitle text, .g-ytitle text, .gtitle')).map(px),
    tickSizes: Array.from(gd.querySelectorAll('.xtick text, .ytick text, .slider-label, .legendtext')).map(px),
    lineWidths: Array.from(gd.querySelectorAll('.scatterlayer path.js-line')).map(
      e => parseFloat(getComputedStyle(e).strokeWidth)),
    page: box(gd.querySelector('.main-svg')),
  };
}"""


def overprinted(labels: list[dict[str, Any]]) -> list[tuple[str, str]]:
    """Pairs of annotation texts whose drawn boxes overlap by more than half a pixel."""
    pairs = []
    for i, a in enumerate(labels):
        for b in labels[i + 1 :]:
            (l1, t1, r1, b1), (l2, t2, r2, b2) = a["box"], b["box"]
            if min(r1, r2) - max(l1, l2) > 0.5 and min(b1, b2) - max(t1, t2) > 0.5:
                pairs.append((a["text"], b["text"]))
    return pairs


def wait_for_plot(page: OfflinePage) -> dict[str, Any]:
    page.page.wait_for_selector(".js-plotly-plot", timeout=60_000)
    return wait_until(lambda: (dom := page.page.evaluate(_DOM))["labels"] and dom)


def test_3d_recording_plays_offline(browser: Any, exported: dict[str, Path], shots: Path) -> None:
    # The recording draws every animation frame in software WebGL. At 960x540 (a third fewer
    # pixels than 1280x720) and with a minute for each screenshot, it is read on a loaded machine:
    # in a full run on two cores one screenshot of it at 1280x860 waited past 30 s.
    page = OfflinePage(browser, exported["lanes"], viewport=(960, 540))

    def canvas() -> np.ndarray:
        return page.png("canvas[data-engine]", timeout_ms=60_000)

    try:
        page.page.wait_for_selector("canvas[data-engine]", timeout=60_000)

        def rods(img: np.ndarray) -> np.ndarray:
            return ((img[..., 2] - img[..., 0]) > 80) | ((img[..., 0] - img[..., 2]) > 120)

        # the rods are drawn, and where they are differs between two moments of playback
        def drawn() -> bool:
            return rods(canvas()).mean() > 0.005

        wait_until(drawn, timeout=60)
        wait_until(lambda: page.page.locator(SOFTWARE_NOTE).count() == 0)  # viser's note, closed by the page
        a = canvas()
        page.page.screenshot(path=str(shots / "playing_a.png"))

        def moved_on() -> bool:
            b = canvas()
            moved = np.abs(a - b).sum(axis=-1) > 60
            return bool(moved[rods(a) | rods(b)].mean() > 0.02)

        wait_until(moved_on, timeout=60, interval=0.25)
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
        assert "β = 0.5906)" in after_title  # M2/M1 = 0.02: u = M1 γ V / (M1 γ + M2) = 0.75/1.27
        assert after != before
        # the play button sweeps V1
        page.page.click("text=▶ V1")
        wait_until(lambda: page.page.evaluate(title) != after_title)
        assert page.requests == [] and page.errors == []
    finally:
        page.close()


SCREENS = {"720p": (1280, 720), "1080p": (1920, 1080)}
#: Every page on the smaller screen, where labels are most crowded, and the scene's own page on the
#: larger one; ``python -m tests.sweeps.export_pages`` checks every page on both.
OVERPRINT = cases(
    [*((name, "720p") for name in ["diagram", *EXTREME_PAGES]), ("diagram", "1080p")],
    [(name, screen) for name in ["diagram", *EXTREME_PAGES] for screen in SCREENS],
)


@pytest.mark.parametrize(("name", "screen"), OVERPRINT, ids=[f"{n}-{s}" for n, s in OVERPRINT])
def test_diagram_page_labels_do_not_overprint(
    browser: Any, exported: dict[str, Path], shots: Path, name: str, screen: str
) -> None:
    """As drawn by plotly in the browser: no two annotation texts overlap, text and lines are sized
    for a projector, and the page fits a 1280x720 screen."""
    viewport = SCREENS[screen]
    page = OfflinePage(browser, exported[name], viewport)
    try:
        dom = wait_for_plot(page)
        page.page.screenshot(path=str(shots / f"{name}_{viewport[0]}.png"))
        assert overprinted(dom["labels"]) == []
        assert min(label["size"] for label in dom["labels"]) >= 16
        assert min(dom["titleSizes"]) >= 16 and min(dom["tickSizes"]) >= 14
        assert min(w for w in dom["lineWidths"] if w > 0) >= 2.5  # (a world tube's fill has no outline)
        left, top, right, bottom = dom["page"]
        assert right - left <= 1280 and bottom - top <= 720  # fits a projector
        assert page.errors == []
    finally:
        page.close()


def test_diagram_page_names_the_frames_axes(browser: Any, exported: dict[str, Path], shots: Path) -> None:
    """The boosted diagram's axes are t′ and x′; moving the frame slider to β = 0 (the lab) names them
    t and x; the labels stay clear of each other after the change."""
    page = OfflinePage(browser, exported["frame-slider"], (1280, 720))
    try:
        dom = wait_for_plot(page)
        assert dom["ytitles"][0] == "t′" and dom["xtitles"][0].startswith("x′ ")
        group = page.page.locator("g.slider-group").nth(1)
        labels = group.locator("g.slider-label-group")
        steps = [labels.nth(k).text_content() for k in range(labels.count())]
        assert steps == ["-0.90", "-0.60", "-0.30", "+0.00", "+0.30", "+0.60", "+0.90"]  # even, with the rod's 0.6
        lab = labels.nth(steps.index("+0.00")).bounding_box()
        rail = group.locator("rect.slider-rail-touch-rect").bounding_box()
        assert lab is not None and rail is not None
        page.page.mouse.click(lab["x"] + lab["width"] / 2, rail["y"] + rail["height"] / 2)
        dom = wait_until(lambda: (d := page.page.evaluate(_DOM))["ytitles"][0] == "t" and d)
        page.page.screenshot(path=str(shots / "frame_slider_lab.png"))
        assert dom["xtitles"][0].startswith("x ")
        assert overprinted(dom["labels"]) == []
        assert page.errors == []
    finally:
        page.close()
