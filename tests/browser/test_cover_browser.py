"""The page's cover in a real browser: from the first paint a tab shows rigidrel's cover, never
viser's own page (its panel with "Inactive" and the ``ws://`` address, its scene tree, its note on
software WebGL), until the app's page is drawn; a server that stops is said on the cover in plain
words, and the page carries on when a server answers again.

The page is watched from its first moment by a script added before any of the page's own
(:data:`WATCH`): at every animation frame and every change of the document it writes down the text a
person could see (``innerText``: hidden elements give none; and what its visible text boxes hold) and whether the
cover is up. A control
test runs the same watch on viser's own page, where it must see viser's words.
"""

from __future__ import annotations

import contextlib
import socket
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import numpy as np
import pytest
import viser
from PIL import Image
from playwright.sync_api import ViewportSize

from rigidrel_app.backends._viser import PageServer
from rigidrel_app.live.cover import GROUND, TITLE, cover_page
from rigidrel_app.live.server import App
from rigidrel_app.view.layout import MARGIN, MIN_PLOT_PX
from rigidrel_app.view.vocabulary import Shade, rgb
from tests.browser.conftest import VIEWPORT
from tests.browser.test_accessibility_browser import serious_violations
from tests.viser_client import wait_until

pytestmark = [pytest.mark.browser, pytest.mark.slow]

#: What viser's own page says before the app's arrives (seen on a screenshot of an unpatched start):
#: its connection state, the server's address, its panel's buttons and scene tree, its WebGL note.
VISER_WORDS = (
    "Inactive",
    "Connecting...",
    "Connected",
    "ws://",
    "Save Canvas",
    "Reset View",
    "Orbit Origin Tool",
    "Dev Settings",
    "Scene tree",
    "WorldAxes",
    "Software WebGL rendering detected",
)

#: Added before the page's own scripts: writes down, at every frame and every change of the
#: document, what a person could read on the page (a new entry only when it changes).
WATCH = r"""
(() => {
  const WORDS = %s;
  const seen = window.__rigidrelWatch = [];
  const t0 = performance.now();
  let last = '';
  const look = () => {
    if (window.__rigidrelWatchStop) return;
    const body = document.body;
    const cover = document.getElementById('rigidrel-cover');
    const up = !!cover && !cover.hidden && getComputedStyle(cover).display !== 'none';
    // what the page's text says, and what its visible boxes hold (innerText leaves out a box's value)
    const boxes = Array.from(document.querySelectorAll('input, textarea'))
      .filter((el) => el.checkVisibility({visibilityProperty: true, opacityProperty: true}))
      .map((el) => el.value).filter((v) => v).join('\n');
    const text = (body ? body.innerText : '') + (boxes ? '\n' + boxes : '');
    const coverText = up ? cover.innerText : '';
    const entry = {
      cover: up,
      covered: document.documentElement.classList.contains('rigidrel-covered'),  // the rest hidden
      coverText: coverText.replace(/\s+/g, ' ').trim(),
      other: (up ? text.replace(cover.innerText, '') : text).trim().slice(0, 300),
      viser: WORDS.filter((w) => text.includes(w)),
      title: document.title,
      panel: !!Array.from(document.querySelectorAll('label')).find((l) => l.textContent.trim() === 'Scene'),
    };
    const key = JSON.stringify(entry);
    if (key === last) return;
    last = key;
    entry.t = Math.round(performance.now() - t0);
    seen.push(entry);
  };
  new MutationObserver(look).observe(document, {subtree: true, childList: true, attributes: true, characterData: true});
  const frame = () => { look(); if (!window.__rigidrelWatchStop) requestAnimationFrame(frame); };
  requestAnimationFrame(frame);
})();
""" % (list(VISER_WORDS),)  # noqa: UP031 -- the script's own braces

COVER_UP = "() => { const c = document.getElementById('rigidrel-cover'); return !!c && !c.hidden; }"
COVER_GONE = "() => { const c = document.getElementById('rigidrel-cover'); return !!c && c.hidden; }"


def watched_page(browser: Any, viewport: ViewportSize = VIEWPORT, **options: Any) -> Any:
    page = browser.new_page(viewport=viewport, **options)
    page.add_init_script(WATCH)
    return page


def watch(page: Any) -> list[dict[str, Any]]:
    """What the page showed so far, one entry per change (and stop watching)."""
    entries = page.evaluate("() => { window.__rigidrelWatchStop = true; return window.__rigidrelWatch; }")
    assert entries, "the watch saw nothing"
    return entries


def cover_text(page: Any) -> str:
    return page.evaluate("() => document.getElementById('rigidrel-cover-text').textContent")


@contextlib.contextmanager
def cover_alone(shade: Shade = "light") -> Iterator[PageServer]:
    """A server that serves the cover's page and nothing else: a tab connects, and no app says its
    page is drawn, so the cover stays up, saying the scene is loading."""
    server = PageServer(cover_page(shade), host="127.0.0.1", port=0, verbose=False)
    try:
        yield server
    finally:
        server.stop()


def test_the_first_paint_is_the_cover_and_viser_s_own_page_never_shows(browser: Any, app_server: App) -> None:
    page = watched_page(browser)
    try:
        page.goto(app_server.url, wait_until="commit")
        page.wait_for_selector("label:text-is('Scene')", timeout=60_000)  # visible: the cover has gone
        page.wait_for_function(COVER_GONE, timeout=30_000)
        seen = watch(page)
        assert page.evaluate("() => document.documentElement.className") == ""
    finally:
        page.close()
    shown = [e for e in seen if e["coverText"] or e["other"]]  # something to read
    # the first thing the page ever showed is the cover, saying that the scene is loading
    assert shown[0]["cover"] and shown[0]["coverText"] == "rigidrel Loading the scene…", shown[0]
    # while it covers the page, nothing else can be read (as it fades out, the app's page can); viser's
    # words never, before or after; the title is ours
    assert [e for e in seen if e["covered"] and e["other"]] == []
    assert [e for e in seen if e["viser"]] == []
    assert {e["title"] for e in seen} == {TITLE}
    # it went once, when the app's panel was there, and did not come back
    up = [e["covered"] for e in shown]
    gone = up.index(False)
    assert not any(up[gone:]), up
    assert shown[gone]["panel"] and "Scene" in shown[gone]["other"]


def test_the_watch_sees_viser_s_own_page_where_there_is_no_cover(browser: Any) -> None:
    """The control of the test above: on viser's own page the same watch reads viser's words."""
    server = viser.ViserServer(host="127.0.0.1", port=0, verbose=False)
    page = watched_page(browser)
    try:
        page.goto(f"http://127.0.0.1:{server.get_port()}", wait_until="commit")
        page.wait_for_selector("text=Scene tree", timeout=60_000)
        seen = watch(page)
    finally:
        page.close()
        server.stop()
    words = {w for e in seen for w in e["viser"]}
    assert {"Scene tree", "ws://", "Save Canvas"} <= words, words
    assert not any(e["cover"] for e in seen)


def test_a_stopped_server_is_said_on_the_cover_and_the_page_carries_on(browser: Any, shots: Path) -> None:
    app = App(host="127.0.0.1", port=0)
    port = app.server.get_port()
    host = f"127.0.0.1:{port}"
    new: App | None = None
    page = watched_page(browser)
    try:
        page.goto(app.url, wait_until="commit")
        page.wait_for_selector("label:text-is('Scene')", timeout=60_000)
        page.wait_for_function(COVER_GONE, timeout=30_000)
        app.stop()
        page.wait_for_function(COVER_UP, timeout=30_000)
        wait_until(lambda: cover_text(page).startswith("Cannot reach"), timeout=30)
        said = cover_text(page)
        then = (
            "This page keeps trying, and carries on by itself once the server answers.",
            "Click this page to try again.",
        )
        assert said in {f"Cannot reach the rigidrel server at {host} — is it still running? {t}" for t in then}, said
        page.screenshot(path=str(shots / "server-stopped.png"))
        new = App(host="127.0.0.1", port=port)
        assert new.server.get_port() == port
        page.wait_for_function(COVER_GONE, timeout=60_000)  # it reconnected, and the new page is drawn
        page.wait_for_selector("label:text-is('Scene')", timeout=30_000)
        seen = watch(page)
    finally:
        page.close()
        (new or app).stop()
    assert [e for e in seen if e["viser"]] == []
    assert [e for e in seen if e["covered"] and e["other"]] == []  # viser's dimmed panel never showed
    words = [e["coverText"] for e in seen if e["cover"]]
    assert any(w.startswith("rigidrel Lost the connection to the rigidrel server at " + host) for w in words), words
    assert any(w.startswith("rigidrel Cannot reach") for w in words), words


def test_a_server_that_never_answers_is_said_on_the_cover(browser: Any) -> None:
    """The page arrived, and the server stopped before the page's connection was made (or just
    after it): the cover says it cannot reach the server."""
    with cover_alone() as server:
        url = f"http://127.0.0.1:{server.get_port()}"
        page = watched_page(browser)
        try:
            page.goto(url, wait_until="domcontentloaded")
            server.stop()
            wait_until(lambda: cover_text(page).startswith("Cannot reach"), timeout=30)
            assert f"the rigidrel server at 127.0.0.1:{server.get_port()} — is it still running?" in cover_text(page)
            seen = watch(page)
        finally:
            page.close()
    assert all(e["covered"] and not e["other"] and not e["viser"] for e in seen if e["coverText"] or e["other"])


def ground_share(png: Path, ground: str) -> float:
    """The share of a screenshot's pixels that are the ground's colour."""
    img = np.asarray(Image.open(png).convert("RGB")).astype(np.int16)
    return float((np.abs(img - np.array(rgb(ground))).max(axis=-1) <= 2).mean())


@pytest.mark.parametrize("shade", ["light", "dark"])
def test_the_cover_is_axe_clean_and_in_the_theme_at_both_screen_sizes(browser: Any, shots: Path, shade: Shade) -> None:
    with cover_alone(shade) as server:
        url = f"http://127.0.0.1:{server.get_port()}"
        page = browser.new_page(viewport={"width": 1280, "height": 720})
        try:
            page.goto(url, wait_until="commit")
            page.wait_for_function(
                "() => window.rigidrelCover && document.getElementById('rigidrel-cover-text')"
                ".textContent === 'Loading the scene…'"
            )
            for width, height in ((1280, 720), (1920, 1080)):  # one page, at each screen size
                page.set_viewport_size({"width": width, "height": height})
                page.wait_for_function(f"() => window.innerWidth === {width} && window.innerHeight === {height}")
                assert page.evaluate(COVER_UP)
                assert serious_violations(page) == []
                png = shots / f"cover-{shade}-{width}x{height}.png"
                page.screenshot(path=str(png))
                assert ground_share(png, GROUND[shade]) > 0.95  # a calm page in the theme's ground
        finally:
            page.close()
        server.stop()  # now the cover says that the server cannot be reached
        page = browser.new_page(viewport=VIEWPORT)
        try:
            with cover_alone(shade) as other:
                page.goto(f"http://127.0.0.1:{other.get_port()}", wait_until="domcontentloaded")
                other.stop()
                wait_until(lambda: cover_text(page).startswith("Cannot reach"), timeout=30)
            assert serious_violations(page) == []
            page.screenshot(path=str(shots / f"cover-{shade}-unreachable-1280x720.png"))
        finally:
            page.close()


def test_a_drawn_page_said_before_the_connection_is_kept_until_it_is_up(browser: Any) -> None:
    """The word that the page is drawn can reach the cover before viser's client says that it is
    connected (on a loaded machine its store says so late, at first and after a drop): the cover
    keeps that word and leaves once the connection is up, not never. Here the page's connection
    goes to a port where no server listens yet (viser's ``?websocket=``), and one starts there after
    the word; then it stops, the word comes again, and one starts there again."""
    with contextlib.closing(socket.socket()) as probe:
        probe.bind(("127.0.0.1", 0))
        port = probe.getsockname()[1]
    later: PageServer | None = None
    with cover_alone() as server:
        page = browser.new_page(viewport=VIEWPORT)
        try:
            page.goto(f"http://127.0.0.1:{server.get_port()}/?websocket=ws://127.0.0.1:{port}", wait_until="commit")
            # the cover follows viser's connection once it has found viser's viewer (before, a word
            # that the page is drawn is taken as it comes: no connection to wait for is known)
            page.wait_for_function("() => document.getElementById('rigidrel-cover').dataset.viewer === 'found'")
            page.evaluate("() => window.rigidrelCover.ready()")
            page.wait_for_function("() => document.getElementById('rigidrel-cover').dataset.waits === 'connection'")
            assert page.evaluate(COVER_UP)
            later = PageServer(cover_page("light"), host="127.0.0.1", port=port, verbose=False)
            page.wait_for_function(COVER_GONE, timeout=30_000)
            # the same after a drop: the word, while viser's store still says it is reconnecting
            later.stop()
            later = None
            page.wait_for_function(COVER_UP, timeout=30_000)
            page.evaluate("() => { delete document.getElementById('rigidrel-cover').dataset.waits; }")
            page.evaluate("() => window.rigidrelCover.ready()")
            page.wait_for_function("() => document.getElementById('rigidrel-cover').dataset.waits === 'connection'")
            later = PageServer(cover_page("light"), host="127.0.0.1", port=port, verbose=False)
            page.wait_for_function(COVER_GONE, timeout=30_000)
        finally:
            page.close()
            if later is not None:
                later.stop()


def test_the_cover_stays_while_viser_s_own_note_is_on_the_page(browser: Any) -> None:
    """viser's note "Software WebGL rendering detected" comes as the page connects, and the panel's
    script closes it a frame or more later; still on the page when the page is drawn, it would show
    through the cover as it fades out. The cover leaves once it has gone. (Here the note is a stand-in
    of the same markup, on a page with no panel to close it.)"""
    with cover_alone() as server:
        page = browser.new_page(viewport=VIEWPORT)
        try:
            page.goto(f"http://127.0.0.1:{server.get_port()}", wait_until="commit")
            page.wait_for_function("() => document.getElementById('rigidrel-cover').dataset.viewer === 'found'")
            page.evaluate(
                """() => {
                  const note = document.createElement('div');
                  note.className = 'mantine-Notification-root';
                  note.id = 'stand-in';
                  note.innerHTML = '<div class="mantine-Notification-title">Software WebGL rendering detected</div>';
                  document.body.appendChild(note);
                  window.rigidrelCover.ready();
                }"""
            )
            page.wait_for_function("() => document.getElementById('rigidrel-cover').dataset.waits === 'note'")
            assert page.evaluate(COVER_UP)
            page.evaluate("() => document.getElementById('stand-in').remove()")
            page.wait_for_function(COVER_GONE, timeout=30_000)
        finally:
            page.close()


def test_reduced_motion_keeps_the_cover_still(browser: Any) -> None:
    with cover_alone() as server:
        page = browser.new_page(viewport=VIEWPORT, reduced_motion="reduce")
        try:
            page.goto(f"http://127.0.0.1:{server.get_port()}", wait_until="commit")
            page.wait_for_function("() => !!window.rigidrelCover")
            bar = page.evaluate(
                """() => {
                  const span = document.querySelector('#rigidrel-cover .rr-cover-bar span');
                  return [getComputedStyle(span).animationName, getComputedStyle(span.parentElement).visibility];
                }"""
            )
            assert bar == ["none", "hidden"]
            # and it leaves without fading when told that the page is drawn
            fade = "() => getComputedStyle(document.getElementById('rigidrel-cover')).transitionDuration"
            assert page.evaluate(fade) == "0s"
            page.evaluate("() => window.rigidrelCover.ready()")
            page.wait_for_function(COVER_GONE)
        finally:
            page.close()


def test_a_phone_held_upright_folds_the_panel_and_stacks_the_page(browser: Any, app_server: App, shots: Path) -> None:
    """On a phone (390x844, touch), viser shows its panel as a sheet over the lower canvas, open: the
    page folds it to its bar at the foot (page script ``phone.js``), and the canvas is laid out for
    the phone (the lanes, one diagram under them as wide as the phone, the legend above the bar)."""
    before = set(app_server.sessions)
    page = browser.new_page(viewport={"width": 390, "height": 844}, is_mobile=True, has_touch=True)
    try:
        page.goto(app_server.url, wait_until="commit")
        page.wait_for_function(COVER_GONE, timeout=60_000)
        sheet = (
            "() => { const s = Array.from(document.querySelectorAll('.mantine-Paper-root')).find("
            "(el) => el.style.position === 'fixed' && el.style.bottom === '0px'); "
            "return s ? s.getBoundingClientRect().height : null; }"
        )
        page.wait_for_function(f"() => {{ const h = ({sheet})(); return h !== null && h < 80; }}", timeout=30_000)
        session = wait_until(lambda: next((s for k, s in app_server.sessions.items() if k not in before), None))
        wait_until(lambda: (lay := session.painter.layout) is not None and (lay.width, lay.height) == (390, 844))
        layout = session.painter.layout
        assert layout is not None and len(layout.shown_charts) == 1 and len(layout.lanes) >= 1
        assert layout.shown_charts[0].outer.width == 390 - 2 * MARGIN and layout.diagram.plot.height >= MIN_PLOT_PX
        assert serious_violations(page) == []
        page.screenshot(path=str(shots / "phone-390x844.png"))
    finally:
        page.close()
