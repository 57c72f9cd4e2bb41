"""Fixtures for tests in a real browser: Debian's chromium driven by Python playwright.

Never downloads a browser: ``executable_path=/usr/bin/chromium``. Every server binds
127.0.0.1 on a free port and is stopped when its test ends, pass or fail. Screenshots go
to ``test-artifacts/screenshots/<test name>/`` for a person to look at.
"""

from __future__ import annotations

import os
import re
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest
from playwright.sync_api import Browser, Playwright, ViewportSize

CHROMIUM = os.environ.get("RIGIDREL_CHROMIUM", "/usr/bin/chromium")
CHROMIUM_ARGS = [
    "--headless",
    "--no-sandbox",
    "--use-angle=swiftshader",
    "--enable-unsafe-swiftshader",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
]
ARTIFACTS = Path(__file__).resolve().parents[2] / "test-artifacts" / "screenshots"
VIEWPORT: ViewportSize = {"width": 1440, "height": 900}


def launch_chromium(p: Playwright) -> Browser:
    """Debian's chromium, headless, software WebGL, no background network (never a download)."""
    return p.chromium.launch(executable_path=CHROMIUM, args=CHROMIUM_ARGS, headless=True)


@pytest.fixture(scope="session")
def browser() -> Iterator[Any]:
    if not Path(CHROMIUM).exists():
        pytest.fail(f"{CHROMIUM} is missing: tests/run.sh installs Debian's chromium")
    from playwright.sync_api import sync_playwright

    with sync_playwright() as p:
        b = launch_chromium(p)
        try:
            yield b
        finally:
            b.close()


@pytest.fixture(scope="module")
def app_server() -> Iterator[object]:
    """One app server for a test file's tabs (each test opens tabs of its own, and a tab is a
    session of its own): its recorder process, which imports the app in a second or two, starts
    once per file, and the timelines it makes are shared as in a lecture hall."""
    from rigidrel_app.live.server import App

    app = App(host="127.0.0.1", port=0)
    try:
        yield app
    finally:
        app.stop()


@pytest.fixture
def tab(browser: Any, app_server: Any) -> Iterator[Any]:
    """One tab on the app (an ``AppPage``), closed after the test, passed or failed."""
    from tests.browser.test_app_browser import AppPage  # the tab's helper lives with the app's tests

    page = AppPage(browser, app_server)
    try:
        yield page
    finally:
        page.close()


@pytest.fixture
def shots(request: pytest.FixtureRequest) -> Path:
    """The folder this test writes its screenshots to."""
    folder = ARTIFACTS / re.sub(r"[^\w.-]+", "_", request.node.name)
    folder.mkdir(parents=True, exist_ok=True)
    return folder
