"""Fixtures for tests in a real browser: Debian's chromium driven by Python playwright.

Never downloads a browser: ``executable_path=/usr/bin/chromium``. Every server binds
127.0.0.1 on a free port and is stopped when its test ends, pass or fail. Screenshots go
to ``test-artifacts/screenshots/<test name>/`` for a person to look at.
"""

from __future__ import annotations

import io
import os
import re
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from PIL import Image
from playwright.sync_api import Browser, Playwright, ViewportSize

from tests.viser_client import wait_until

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
VIEWPORT: ViewportSize = {"width": 1280, "height": 720}


def launch_chromium(p: Playwright) -> Browser:
    """Debian's chromium, headless, software WebGL, no background network (never a download)."""
    return p.chromium.launch(executable_path=CHROMIUM, args=CHROMIUM_ARGS, headless=True)


def element_png(page: Any, selector: str, timeout_ms: float = 30_000) -> np.ndarray:
    """What the first element matching ``selector`` shows now, as RGB (int16): a clip of the
    page's screenshot at the element's box, once two reads of that box 0.1 s apart agree (a page
    re-laid out after a resize has settled). Not ``locator.screenshot()``, whose own wait for a
    still element counts animation frames: a page playing in software WebGL on a busy machine
    can take longer than playwright's 30 s to give two. ``timeout_ms`` bounds the screenshot
    itself, for a page that keeps the renderer busy."""
    element = page.locator(selector).first
    boxes: list[Any] = []

    def box_settled() -> Any:
        boxes.append(element.bounding_box())
        return boxes[-1] is not None and boxes[-2:] == [boxes[-1]] * 2 and boxes[-1]

    box = wait_until(box_settled, timeout=30, interval=0.1)
    png = page.screenshot(clip=box, timeout=timeout_ms)
    return np.asarray(Image.open(io.BytesIO(png)).convert("RGB")).astype(np.int16)


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


@pytest.fixture(autouse=True)
def no_page_left_open(request: pytest.FixtureRequest) -> Iterator[None]:
    """A test that uses the browser closes every page it opened, passed or failed: a page left
    open keeps drawing in software WebGL for the rest of the session, and starves the tests after
    it (a screenshot then waits past its timeout)."""
    if "browser" not in request.fixturenames:
        yield
        return
    browser: Browser = request.getfixturevalue("browser")
    before = {id(page) for context in browser.contexts for page in context.pages}
    yield
    left = [page.url for context in browser.contexts for page in context.pages if id(page) not in before]
    for context in browser.contexts:  # let them go, so one leak does not starve the tests after it
        if any(id(page) not in before for page in context.pages):
            context.close()
    assert not left, f"pages left open: {left}"


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
def new_tab(browser: Any, app_server: Any) -> Iterator[Any]:
    """A new tab on the app (an ``AppPage``), closed after the test, passed or failed."""
    from tests.browser.test_app_browser import AppPage  # the tab's helper lives with the app's tests

    page = AppPage(browser, app_server)
    try:
        yield page
    finally:
        page.close()


@pytest.fixture
def tab(new_tab: Any) -> Any:
    """A tab on the app: a new one. A file whose tests can share one overrides this with
    :func:`shared_tab`, reset for each test."""
    return new_tab


@pytest.fixture(scope="module")
def shared_tab(browser: Any, app_server: Any) -> Iterator[Any]:
    """One tab on the file's app server for the file's tests that share it (opening a tab takes
    seconds, most of them viser's client starting in software WebGL): each of those tests takes it
    through a fixture of its file that resets it first (``AppPage.reset``: the session back where
    a new tab opens). Closed when the file's tests end, so that it renders beside no other file's
    tabs; opened by the first test that needs it, so the file's tests before it run beside none.

    Its resolution is held where a new tab's starts (``?fixedDpr=1``): viser lowers a canvas'
    resolution after a few seconds of slow frames (here, software WebGL on a busy machine: most
    tests' worth) and never raises it while the canvas is idle, and the session then takes the
    canvas for a slow one (:mod:`rigidrel_app.live.still_image`). Held, every test starts at the
    same resolution whatever ran before it, and none sees it change halfway."""
    from tests.browser.test_app_browser import AppPage

    page = AppPage(browser, app_server, query="?fixedDpr=1")
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
