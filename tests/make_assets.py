"""Regenerate the pictures in assets/ from the code as it is today (keep the README true).

    python -m tests.make_assets

Writes assets/app.png (the app in headless Chromium: Fig. 3's collision seen from the
barycentric frame, paused mid-collision), assets/figures/fig1-4.{svg,png} (the paper's
figures), assets/figures/{bell-spaceships,pole-barn}.{svg,png,txt} (the paradoxes) and
assets/rod-collision-lanes.gif (the lanes of that collision).
"""

from __future__ import annotations

import time
from pathlib import Path

import rigidrel_core as rr
from rigidrel_app.backends.raster import write_gif
from rigidrel_app.export.figures import write_figures
from rigidrel_app.export.paradox_figures import write_paradox_figures
from rigidrel_app.export.recording import playback_times
from rigidrel_app.live.server import App
from rigidrel_app.view.scene_view import build_drawing
from rigidrel_app.view.state import Resolved, presets
from tests.browser.conftest import CHROMIUM, VIEWPORT, launch_chromium
from tests.viser_client import wait_until

ASSETS = Path(__file__).resolve().parents[1] / "assets"


def app_screenshot(path: Path) -> None:
    from playwright.sync_api import sync_playwright

    with App(port=0) as app, sync_playwright() as p:
        browser = launch_chromium(p)
        page = browser.new_page(viewport=VIEWPORT)
        page.goto(app.url)
        page.wait_for_selector("label:text-is('Scene')", timeout=60_000)
        wait_until(lambda: app.sessions, timeout=60)
        session = next(iter(app.sessions.values()))
        session.change(presets()["Fig. 3: collision, M2 = 2 M1"], refit=True)  # in its default, barycentric frame
        session.seek(0.15)
        for button in page.locator(".mantine-Notification-root button").all():
            button.click()  # the headless browser's "software WebGL" notice
        time.sleep(2.5)
        page.screenshot(path=str(path))
        browser.close()


def lanes_gif(path: Path) -> None:
    scene = rr.rod_collision(0.6, 0.0, 1.0, 2.0, 1.0, 1.0, 1.0)
    drawn = build_drawing(Resolved(scene, scene.frame("barycentric")))
    write_gif(drawn, path, playback_times(drawn, 8.0, 10.0), 10.0, width=720)


def main() -> None:
    ASSETS.mkdir(exist_ok=True)
    app_screenshot(ASSETS / "app.png")
    write_figures(ASSETS / "figures")
    write_paradox_figures(ASSETS / "figures")
    lanes_gif(ASSETS / "rod-collision-lanes.gif")
    print(f"assets written: {ASSETS} ({CHROMIUM})")


if __name__ == "__main__":
    main()
