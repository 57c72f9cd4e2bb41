"""Regenerate the pictures in assets/ from the code as it is today (keep the README true).

    python -m tests.make_assets

Writes assets/app.png and assets/app-presenter.png (the app in headless Chromium at 1280x720,
with its control panel and in presenter mode: Fig. 3's collision seen from the barycentric
frame, paused mid-collision), assets/scenes/<scene>{,-presenter}.png (every registered scene at
its defaults, halfway through its events, in both modes), assets/figures/fig1-4.{svg,png} (the
paper's figures), assets/figures/{bell-spaceships,pole-barn}.{svg,png,txt} (the paradoxes),
assets/rod-collision-lanes.gif (the lanes of that collision), assets/wall-crash-signals.png
(Sec. 5's crash into a wall with the light-signal layer, in the lab and the rod's frame before)
and assets/lesson-step.png (a step of the built-in lesson given live, in presenter mode).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import replace
from pathlib import Path
from typing import Any

import rigidrel_core as rr
from rigidrel_app.backends.raster import write_gif
from rigidrel_app.export.figures import write_figures
from rigidrel_app.export.paradox_figures import write_paradox_figures
from rigidrel_app.export.recording import playback_times
from rigidrel_app.lessons import builtin_lesson
from rigidrel_app.live.keys import Action
from rigidrel_app.live.server import App
from rigidrel_app.view.layers import Layer
from rigidrel_app.view.scene_view import build_drawing
from rigidrel_app.view.state import Resolved, Settings, presets
from tests.browser.conftest import CHROMIUM, launch_chromium
from tests.viser_client import wait_until

ASSETS = Path(__file__).resolve().parents[1] / "assets"


#: The README's screenshots: a projector's resolution.
SCREENSHOT = {"width": 1280, "height": 720}


class _Tab:
    """One headless tab on a fresh app server, and a way to photograph its canvas once it is still."""

    def __init__(self, app: App, browser: Any, viewport: dict[str, int] = SCREENSHOT) -> None:
        self.viewport = viewport
        self.page = browser.new_page(viewport=viewport)
        self.page.goto(app.url)
        self.page.wait_for_selector("label:text-is('Scene')", timeout=60_000)
        self.session = wait_until(lambda: next(iter(app.sessions.values()), None), timeout=60)
        wait_until(lambda: self.session.painter.drawn is not None, timeout=60)
        for button in self.page.locator(".mantine-Notification-root button").all():
            button.click()  # the headless browser's "software WebGL" notice

    def show(self, settings: Settings, now: float | None = None) -> None:
        """``settings`` paused at ``now`` (by default halfway between the scene's first and last event)."""
        with self.session.lock:
            self.session.asks.change(settings, refit=True)
            drawn = self.session.painter.drawn
            assert drawn is not None and drawn.resolved.scene.kind == settings.scene, settings
            if now is None:
                times = [t for t, _ in drawn.resolved.scene.events_in(frame=drawn.resolved.frame).values()]
                now = 0.5 * (min(times) + max(times))
            self.session.asks.seek(now)

    def presenter(self, on: bool) -> None:
        if self.session.state.presenter != on:
            self.page.evaluate("() => document.activeElement && document.activeElement.blur()")
            self.page.keyboard.press("f")
            wait_until(lambda: self.session.state.presenter == on, timeout=60)

    def photograph(self, path: Path) -> None:
        """Once laid out for the canvas as it is now and no longer changing."""

        def laid_out() -> bool:  # for the canvas as the page has it: the panel docked, or minimised
            layout, size = self.session.painter.layout, self.session.painter.canvas_size
            if layout is None or (layout.width, layout.height) != (size.width, size.height):
                return False
            wide = layout.width > 0.9 * self.viewport["width"]
            return wide if self.session.state.presenter else size.measured and not wide

        wait_until(laid_out, timeout=60)
        shots: list[bytes] = [b""]

        def still() -> bool:  # the same PNG bytes twice: the canvas has stopped changing
            shots.append(self.page.screenshot(type="png"))
            return shots[-1] == shots[-2]

        wait_until(still, timeout=120, interval=1.5)
        path.write_bytes(shots[-1])


def app_screenshots(normal: Path, presenter: Path, scenes: Path) -> None:
    """The app as a lecturer opens it, then in presenter mode (key F): Fig. 3's collision from the
    barycentric frame paused mid-collision; then every registered scene at its defaults in both modes
    (``scenes/<kind>.png`` and ``scenes/<kind>-presenter.png``)."""
    from playwright.sync_api import sync_playwright

    scenes.mkdir(parents=True, exist_ok=True)
    with App(port=0) as app, sync_playwright() as p:
        browser = launch_chromium(p)
        tab = _Tab(app, browser)
        tab.show(presets()["Fig. 3: collision, M2 = 2 M1"], 0.15)  # its default, barycentric frame
        tab.photograph(normal)
        tab.presenter(True)
        tab.photograph(presenter)
        _scene_gallery(tab, scenes, list(rr.scene_descriptions()))
        browser.close()


def _scene_gallery(tab: _Tab, scenes: Path, kinds: Sequence[str]) -> None:
    """``scenes/<kind>.png`` and ``scenes/<kind>-presenter.png``: each of ``kinds`` at its defaults
    (all in one mode, then all in the other: the panel is docked back only once)."""
    for on in (False, True):
        tab.presenter(on)
        for kind in kinds:
            tab.show(Settings(kind))
            tab.photograph(scenes / f"{kind}{'-presenter' if on else ''}.png")


def scene_screenshots(scenes: Path, kinds: Sequence[str]) -> None:
    """Only the gallery pictures of ``kinds`` (as :func:`app_screenshots` makes them), e.g. after a
    change to how those scenes are drawn:
    ``scene_screenshots(ASSETS / "scenes", ["bell-spaceships", "pole-barn"])``."""
    from playwright.sync_api import sync_playwright

    scenes.mkdir(parents=True, exist_ok=True)
    with App(port=0) as app, sync_playwright() as p:
        browser = launch_chromium(p)
        _scene_gallery(_Tab(app, browser), scenes, kinds)
        browser.close()


#: The crash with every layer, light signals included: the rod's frame before the crash is the
#: chosen one (at ε = 0 the rod's frame after is the lab's).
WALL_CRASH_SIGNALS = presets()["Sec. 5: crash into a wall, V = 0.6"].with_layers(frozenset(Layer))
WALL_CRASH_FRAME = "rod before"
#: Lab time shown: the pulse from the contact is half-way along the rod in the lab.
WALL_CRASH_NOW = 0.5


def signals_screenshot(
    path: Path,
    settings: Settings = WALL_CRASH_SIGNALS,
    frame: str = WALL_CRASH_FRAME,
    now: float = WALL_CRASH_NOW,
    viewport: dict[str, int] = SCREENSHOT,
) -> None:
    """The app showing ``settings`` in ``frame`` with the light signals, paused at ``now``, once
    its canvas has stopped changing."""
    from playwright.sync_api import sync_playwright

    with App(port=0) as app, sync_playwright() as p:
        browser = launch_chromium(p)
        tab = _Tab(app, browser, viewport)
        tab.show(replace(settings, frame=frame), now)
        tab.photograph(path)
        browser.close()


#: The lesson step the README shows: the wall crash in the rod's frame, with its light signals.
LESSON_STEP = 6
LESSON_NOW = 0.5


#: The README shows a 1080p projector (at 1280x720 the caption band takes a sixth of the screen and
#: the canvas lays itself out more tightly under it).
LESSON_VIEWPORT = {"width": 1920, "height": 1080}


def lesson_screenshot(path: Path, step: int = LESSON_STEP, now: float = LESSON_NOW) -> None:
    """``rigidrel serve --lesson paper`` at step ``step`` (from 0) in presenter mode, paused at ``now``:
    the caption band over the lanes, as a hall sees it on a 1920x1080 projector."""
    from playwright.sync_api import sync_playwright

    with App(port=0, lesson=builtin_lesson("paper")) as app, sync_playwright() as p:
        browser = launch_chromium(p)
        tab = _Tab(app, browser, LESSON_VIEWPORT)
        tab.session.go_to_step(step)
        tab.presenter(True)
        with tab.session.lock:
            if tab.session.state.playback.playing:
                tab.session.perform(Action.TOGGLE_PLAY)
            tab.session.asks.seek(now)
        tab.photograph(path)
        browser.close()


#: The riding frame the README shows: the Born-rigid wall crash ridden by the rod's back end (its
#: right end, the one far from the wall), paused while that end brakes.
RIDE_SETTINGS = Settings.of("wall-collision", v=0.6, eps=0.0).riding(0, 1.0)
RIDE_NOW = -0.3


def dark_screenshot(path: Path, viewport: dict[str, int] = SCREENSHOT) -> None:
    """Fig. 3's collision (its barycentric frame) in presenter mode and the dark theme (keys F, T)."""
    from playwright.sync_api import sync_playwright

    with App(port=0) as app, sync_playwright() as p:
        browser = launch_chromium(p)
        tab = _Tab(app, browser, viewport)
        tab.show(presets()["Fig. 3: collision, M2 = 2 M1"], 0.15)
        tab.presenter(True)
        tab.page.keyboard.press("t")
        wait_until(lambda: tab.session.state.shade == "dark", timeout=60)
        tab.photograph(path)
        browser.close()


def ride_screenshot(path: Path, now: float = RIDE_NOW, viewport: dict[str, int] = SCREENSHOT) -> None:
    """The app riding the crashing rod's back end at ``now``: its lane keeps the rod at rest length."""
    from playwright.sync_api import sync_playwright

    with App(port=0) as app, sync_playwright() as p:
        browser = launch_chromium(p)
        tab = _Tab(app, browser, viewport)
        tab.show(RIDE_SETTINGS, now)
        tab.photograph(path)
        browser.close()


def lanes_gif(path: Path) -> None:
    scene = rr.rod_collision(0.6, 0.0, 1.0, 2.0, 1.0, 1.0, 1.0)
    drawn = build_drawing(Resolved(scene, scene.frame("barycentric")))
    write_gif(drawn, path, playback_times(drawn, 8.0, 10.0), 10.0, width=720)


def main() -> None:
    ASSETS.mkdir(exist_ok=True)
    app_screenshots(ASSETS / "app.png", ASSETS / "app-presenter.png", ASSETS / "scenes")
    write_figures(ASSETS / "figures")
    write_paradox_figures(ASSETS / "figures")
    lanes_gif(ASSETS / "rod-collision-lanes.gif")
    signals_screenshot(ASSETS / "wall-crash-signals.png")
    lesson_screenshot(ASSETS / "lesson-step.png")
    ride_screenshot(ASSETS / "riding-frame.png")
    dark_screenshot(ASSETS / "app-dark.png")
    print(f"assets written: {ASSETS} ({CHROMIUM})")


if __name__ == "__main__":
    main()
