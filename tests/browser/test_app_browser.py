"""The app in a real browser: it loads, draws the core's positions, and reacts to a user.

The tests that use the app as a person does share one tab on the file's server (``tab``: reset
before each test to where a new tab opens, :meth:`AppPage.reset`); the tests of a tab's start-up,
of a screen's density and of tabs side by side open their own (``new_tab``, or more) and come
first, so that the shared tab (opened by the first test that takes it) draws beside none of them.
Servers bind 127.0.0.1 on a free port; screenshots land in ``test-artifacts/screenshots/<test>/``.
The tests that set the state they look at and read the canvas are in ``test_canvas_browser.py``.
"""

from __future__ import annotations

import contextlib
import io
import json
import re
import time
from collections.abc import Iterator
from dataclasses import replace
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from PIL import Image
from playwright.sync_api import ViewportSize

import rigidrel_core as rr
from rigidrel_app.backends._viser import handle_uuid, run_javascript
from rigidrel_app.live.canvas_report import LABEL as CANVAS_REPORT_LABEL
from rigidrel_app.live.keys import Action
from rigidrel_app.live.playback import Playback
from rigidrel_app.live.server import App
from rigidrel_app.live.session import Session
from rigidrel_app.view.state import Settings
from rigidrel_app.view.vocabulary import ROD_COLORS
from tests.browser.conftest import VIEWPORT, element_png
from tests.viser_client import shown, wait_until

pytestmark = pytest.mark.browser

#: Detected rod edges must lie this close to the core's positions projected through the camera.
PIXEL_TOLERANCE = 3.0


@contextlib.contextmanager
def tab_on_own_server(browser: Any, **app: Any) -> Iterator[AppPage]:
    """One tab on a server of its own (``App(**app)`` on a free port); both are let go on the way
    out, passed or failed."""
    server = App(host="127.0.0.1", port=0, **app)
    page = None
    try:
        page = AppPage(browser, server)
        yield page
    finally:
        if page is not None:
            page.close()
        server.stop()


def slider_of(page: Any, session: Session, label: str) -> Any:
    """The slider of the number control named ``label`` (it sits under the control's text box,
    which carries the name), found by its handle's id."""
    c = session.controls
    numbers = [*c.parameters.values(), c.beta, c.ride_point, c.time, c.speed]
    (found,) = [n for n in numbers if n.entry.label == label and n.box.visible]
    return page.locator(f"[id='{handle_uuid(found.slider)}']")


def number_box(page: Any, label: str) -> Any:
    """The text box of the number control named ``label`` (viser's text box label names no id)."""
    return page.locator(f'label:text-is("{label}")').first.locator("xpath=following::input[1]")


#: viser's note on a page drawn in software WebGL.
SOFTWARE_NOTE = ".mantine-Notification-root:has-text('Software WebGL rendering detected')"


class AppPage:
    """One browser tab on the app, with the server-side session behind it."""

    def __init__(
        self,
        browser: Any,
        app: App,
        device_scale_factor: float = 1.0,
        query: str = "",
        viewport: ViewportSize = VIEWPORT,
    ) -> None:
        """``query``: added to the app's address (``"?fixedDpr=1"`` holds viser's resolution)."""
        self.app = app
        self.viewport = viewport
        self.marks = 0
        """Marks sent to the page (:meth:`wait_taken`)."""
        self.errors: list[str] = []
        before = set(app.sessions)
        self.page = browser.new_page(viewport=viewport, device_scale_factor=device_scale_factor)
        self.external: list[str] = []

        def route(r: Any) -> None:  # the app needs nothing beyond its own server
            if r.request.url.startswith(("http://127.0.0.1", "ws://127.0.0.1", "data:", "blob:")):
                r.continue_()
            else:
                self.external.append(r.request.url)
                r.abort()

        self.page.route("**/*", route)
        self.page.on("pageerror", lambda e: self.errors.append(f"pageerror: {e}"))
        self.page.on("console", lambda m: self.errors.append(f"console: {m.text}") if m.type == "error" else None)
        self.received: list[tuple[float, int, str]] = []
        """Websocket frames the page received: (time, bytes, the first 200 characters if text)."""

        def on_socket(ws: Any) -> None:
            def frame(payload: Any) -> None:
                if payload is None:
                    return
                head = payload[:200] if isinstance(payload, str) else bytes(payload[:4000]).decode("latin-1")
                size = len(payload)
                self.received.append((time.monotonic(), size, head))

            ws.on("framereceived", frame)

        self.page.on("websocket", on_socket)
        self.opened = time.monotonic()
        self.page.goto(app.url + query)
        self.page.wait_for_selector("label:text-is('Scene')", timeout=60_000)
        new = wait_until(lambda: set(app.sessions) - before)
        self.session: Session = app.sessions[min(new)]
        wait_until(
            lambda: self.session.painter.drawn is not None and self.session.painter.layout is not None, timeout=60
        )
        # the page's playback runtime draws the moving parts (the server only its answers' frames)
        wait_until(lambda: self.session.player.ready, timeout=60)
        # viser's "Software WebGL rendering detected" (headless Chromium draws in software) would
        # cover the lanes' titles: the page closes it by itself
        wait_until(lambda: self.page.locator(SOFTWARE_NOTE).count() == 0, timeout=30)

    def close(self) -> None:
        self.page.close()

    def reset(self, start: Settings | None = None) -> None:
        """Put the tab back where a new tab on its server opens, for the next test that shares it.

        The session: ``start`` (default: the server's start) with its values, frame, layers and
        cone, paused at the start of its window at speed 1 and looping, presenter mode off, the
        server's theme, no notice, every box showing its value (typed text that was refused too),
        "Auto-fit view" on and the camera fitted. The page: its window at the size it opened
        with, no menu open, nothing focused. Returns once the page has taken all of it (a mark
        sent after it has run there), is laid out for its canvas and its canvas holds still; the
        page's errors are counted from here. The tab's resolution is not the reset's: a shared tab
        is held at a new tab's (``?fixedDpr=1``, conftest's ``shared_tab``)."""
        page, s = self.page, self.session
        assert not s.painter.still_image.slow_canvas, "the canvas was taken for a slow one: hold its resolution"
        if page.locator("[role=listbox]:visible").count():
            page.keyboard.press("Escape")  # a menu left open
        page.evaluate("() => document.activeElement && document.activeElement.blur()")
        resized = s.state.presenter or page.viewport_size != self.viewport
        if page.viewport_size != self.viewport:
            page.set_viewport_size(self.viewport)
        if s.state.playback.playing:  # paused first: the browser's frame where it stops sets the clock
            s.perform(Action.TOGGLE_PLAY)
            s.client.flush()
        wait_until(lambda: s.playing.settled, timeout=30)
        with s.lock, s.client.atomic():
            if s.state.presenter:
                s.asks.set_presenter(False)
            s.asks.set_shade(self.app.shade)
            s.controls.fit.value = True
            s.controls.loop.value = True
            s.controls.speed.show(1.0)
            s.asks.change(start or (self.app.start.settings if self.app.start else Settings()), refit=True)
            s.asks.set_playback(Playback.start(s.state.playback.window))
            s.show(s.state, put_back=True)
            s.draw_now(force_plots=True)
            s.painter.fit_camera(force=True)
        s.client.flush()
        if resized:  # the page has unfolded its panel and taken its size before its canvas is measured
            self.wait_taken()
        self.wait_laid_out(stable=resized)
        self.wait_taken()
        box = page.locator("canvas[data-engine]").bounding_box()
        assert box is not None
        shots = [self.clip(box)]

        def still() -> bool:
            shots.append(self.clip(box))
            a, b = shots[-2], shots[-1]
            return a.shape == b.shape and _changed_fraction(a, b) < 1e-4

        wait_until(still, timeout=30, interval=0.1)
        self.errors.clear()

    def wait_taken(self) -> None:
        """Until the page has taken everything the server sent it so far, and drawn it: a mark sent
        now (one websocket, read in order) set two animation frames after the page has run it."""
        s = self.session
        self.marks += 1
        with s.lock:
            run_javascript(
                s.client,
                "requestAnimationFrame(() => requestAnimationFrame(() => {"
                f" window.__rigidrelTaken = {self.marks}; }}));",
            )
        s.client.flush()
        self.page.wait_for_function("(n) => window.__rigidrelTaken === n", arg=self.marks, timeout=30_000)

    def wait_laid_out(self, stable: bool = True) -> None:
        """Until the session's page is laid out for the canvas as the browser has it now (with
        ``stable``, the same over two reads 0.1 s apart: a panel folding away resizes it over a
        few frames)."""
        s = self.session
        sizes: list[Any] = []

        def laid_out() -> bool:
            css = self.page.evaluate(
                "() => { const c = document.querySelector('canvas[data-engine]');"
                " return c ? [c.clientWidth, c.clientHeight] : null; }"
            )
            layout = s.painter.layout
            sizes.append(css)
            return (
                css is not None
                and (not stable or sizes[-2:] == [css, css])
                and layout is not None
                and s.painter.canvas_size.measured
                and (layout.width, layout.height) == (css[0], css[1])
            )

        wait_until(laid_out, timeout=30, interval=0.1)

    def clip(self, box: Any) -> np.ndarray:
        """What the page shows in ``box`` (page px) now, as RGB (int16)."""
        png = self.page.screenshot(clip=box)
        return np.asarray(Image.open(io.BytesIO(png)).convert("RGB")).astype(np.int16)

    def nodes(self, *names: str) -> list[dict[str, Any] | None]:
        """What viser's client holds of these scene nodes now, read in one go (one instant of the
        page): each node's props and visibility, or None."""
        return self.page.evaluate("(names) => names.map((n) => window.__rigidrelPlayback.node(n))", list(names))

    def title_and_now_lines(self) -> tuple[str, list[float]]:
        """In one instant of the page: the lab lane's title, and the z (page px) of every moving
        segment of the diagrams (now-lines: each one horizontal) that is shown."""
        return self.page.evaluate(
            """() => {
              const r = window.__rigidrelPlayback;
              const title = r.node('/page/title/0');
              const zs = [];
              for (const name of r.created) {
                if (!name.startsWith('/page/moving/')) continue;
                const n = r.node(name);
                if (!n || !n.visible) continue;
                const p = n.props.points;
                for (let i = 0; i + 5 < p.length; i += 6) if (p[i + 2] === p[i + 5]) zs.push(p[i + 2]);
              }
              return [title ? title.props.text : '', zs];
            }"""
        )

    # ---------------------------------------------------------------- as a user
    def control(self, label: str) -> Any:
        uid = self.page.locator(f'label:text-is("{label}")').get_attribute("for")
        return self.page.locator(f"[id='{uid}']")

    def slider(self, label: str) -> Any:
        return slider_of(self.page, self.session, label)

    def type_into_slider(self, label: str, value: float) -> None:
        """Type ``value`` into the box of the number control named ``label`` and press Enter."""
        box = number_box(self.page, label)
        box.fill(str(value))
        box.press("Enter")

    def choose(self, label: str, option: str) -> None:
        self.control(label).click()
        self.page.locator(f'[role=option]:has-text("{option}")').first.click()

    # ---------------------------------------------------------------- reading the page
    def texts(self) -> list[str]:
        """Every text the canvas shows (the diagrams' titles, numbers, event names, legend), a
        subscript joined to its letter as the paper's source writes it: ``T_B1``, ``T′_1``
        (the canvas draws it as a smaller text of its own, lower, starting where the letter ends)."""
        r = self.session.painter.renderer
        out: list[str] = []
        before: tuple[str, tuple[float, float, float], float, str] | None = None
        for label in (*r.static_texts.shown, *r.axis_names.shown, *r.titles.shown):
            text, place, scale, anchor = label
            if (
                before is not None
                and (before[3], anchor) == ("center-right", "center-left")
                and abs(place[0] - before[1][0]) < 4.0  # the same joint, each drawn from its ink
                and place[2] < before[1][2]
                and scale < before[2]
            ):
                out[-1] += "_" + text
                before = None
                continue
            out.append(text)
            before = label
        return out

    def page_to_pixel(self, x: float, z: float) -> tuple[float, float]:
        """A page point (px, z up) as a canvas pixel (column, row): the camera makes one page px one CSS px."""
        layout = self.session.painter.layout
        assert layout is not None
        return x, layout.height - z

    def canvas(self) -> np.ndarray:
        return element_png(self.page, "canvas[data-engine]")

    def canvas_after(self, before: np.ndarray, timeout: float = 30.0) -> np.ndarray:
        """The canvas once it shows a change from ``before`` and has stopped changing (the
        server's update has arrived and been drawn), instead of a fixed sleep."""
        shots = [self.canvas()]

        def settled() -> bool:
            shots.append(self.canvas())
            a, b = shots[-2], shots[-1]
            if not a.shape == b.shape == before.shape:
                return False
            return _changed_fraction(b, before) > 1e-3 and _changed_fraction(a, b) < 1e-4

        wait_until(settled, timeout=timeout, interval=0.25)
        return shots[-1]


def _changed_fraction(a: np.ndarray, b: np.ndarray) -> float:
    """Share of pixels that differ visibly between two canvases of one size."""
    return float((np.abs(a - b).sum(axis=-1) > 30).mean())


def show(tab: AppPage, settings: Settings, now: float) -> None:
    """Put the session in a known state, paused at ``now`` (server side, as a preset would)."""
    s = tab.session
    with s.lock:
        s.controls.fit.value = True
        s.asks.change(settings, refit=True)
        s.asks.seek(now)


def rod_runs(row: np.ndarray, color: str) -> list[tuple[int, int]]:
    """[start, end] pixel columns of runs of rod-coloured pixels in one image row."""
    r, g, b = row[:, 0], row[:, 1], row[:, 2]
    if color == "blue":
        mask = (b > 110) & (b - r > 60) & (b - g > 20)
    else:
        mask = (r > 140) & (r - b > 80) & (g > 50) & (g < 190)
    cols = np.flatnonzero(mask)
    if cols.size == 0:
        return []
    breaks = np.flatnonzero(np.diff(cols) > 4)
    starts = np.concatenate([[cols[0]], cols[breaks + 1]])
    ends = np.concatenate([cols[breaks], [cols[-1]]])
    return [(int(a), int(e)) for a, e in zip(starts, ends, strict=True) if e - a >= 3]


def measured_rods(tab: AppPage, img: np.ndarray) -> list[list[tuple[int, int]]]:
    """Each lane's rods as drawn: [lane][rod] = (left, right) pixel columns, found on the row of
    the lane's rod axis (ticks and the origin mark drawn over a rod split it: runs are joined)."""
    layout = tab.session.painter.layout
    assert layout is not None
    out = []
    for place, lane in zip(layout.lanes, tab.session.painter.renderer_lanes, strict=True):
        _, row = tab.page_to_pixel(0.0, place.rod_z + 0.25 * place.rod_px)
        found = []
        for r, color in zip(range(lane.ends.shape[0]), ("blue", "orange"), strict=False):
            lo, hi = lane.origin_px + lane.ends[r] * lane.scale
            runs = rod_runs(img[round(row)], color)
            near = [ab for ab in runs if ab[1] >= lo - 2 * PIXEL_TOLERANCE and ab[0] <= hi + 2 * PIXEL_TOLERANCE]
            assert near, f"no {color} rod near columns {lo:.0f}..{hi:.0f}; runs {runs}"
            found.append((min(a for a, _ in near), max(b for _, b in near)))
        out.append(found)
    return out


def rods_drawn(tab: AppPage, timeout: float = 30.0) -> list[list[tuple[int, int]]]:
    """:func:`measured_rods` on the canvas once every rod is where its lane puts it now: the still
    picture and the instant's frame reach the canvas one after the other, and a canvas that held
    still between the two shows the new page with the old rods, or none."""

    def drawn() -> list[list[tuple[int, int]]] | None:
        try:
            return measured_rods(tab, tab.canvas())
        except AssertionError:
            return None

    return wait_until(drawn, timeout=timeout, interval=0.2)


# ====================================================================== tests
@pytest.fixture
def tab(shared_tab: AppPage) -> AppPage:
    """The file's one tab, back where a new tab opens."""
    shared_tab.reset()
    return shared_tab


def test_page_loads_and_renders(new_tab: AppPage, shots: Path) -> None:
    tab = new_tab

    def drawn() -> tuple[int, int] | None:
        # not blank: the rods' blue and the ink of ticks, clocks and axes are on the canvas
        img = tab.canvas()
        blue, dark = int((img[..., 2] - img[..., 0] > 60).sum()), int((img.sum(axis=-1) < 200).sum())
        return (blue, dark) if blue > 2000 and dark > 300 else None

    wait_until(drawn, timeout=30)
    texts = tab.texts()
    assert "Minkowski diagram, lab frame" in texts and "Equal-time length (Fig. 2)" in texts
    assert any(t.startswith("lab frame:   t = ") for t in texts)
    tab.page.screenshot(path=str(shots / "loaded.png"))
    assert tab.page.locator(".js-plotly-plot").count() == 0  # the diagrams are on the canvas
    assert tab.errors == []
    assert tab.external == []


def test_no_plotly_and_a_light_connection(new_tab: AppPage) -> None:
    """A tab receives no plotly.js and at most 300 kB over the websocket until its first picture
    (the whole default scene drawn: lanes, diagrams, legend)."""
    tab = new_tab
    wait_until(lambda: tab.texts() and any("Equal-time" in t for t in tab.texts()), timeout=30)
    first_picture = time.monotonic()
    received = sum(n for t, n, _ in tab.received if t <= first_picture)
    assert 0 < received <= 300_000, received
    assert not any("plotly" in head.lower() for _, _, head in tab.received)
    scripts = tab.page.evaluate("() => Array.from(document.scripts).map(s => s.src + s.text.slice(0, 200))")
    assert not any("plotly" in src.lower() for src in scripts)


@pytest.mark.parametrize("density", [2.0, 1.25])
def test_a_high_density_screen_gets_the_page_laid_out_in_css_px(browser: Any, app_server: App, density: float) -> None:
    """A laptop's screen has 2 pixels per CSS px, a zoomed page 1.25: the camera reports rendered pixels,
    the page reports its CSS size, and the layout (whose labels are sized in CSS px) uses the latter."""
    tab = AppPage(browser, app_server, device_scale_factor=density)
    try:
        css = tab.page.evaluate(
            "() => { const c = document.querySelector('canvas[data-engine]'); return [c.clientWidth, c.clientHeight]; }"
        )
        s = tab.session
        wait_until(
            lambda: (
                s.painter.layout is not None and (s.painter.layout.width, s.painter.layout.height) == (css[0], css[1])
            )
        )
        camera = s.client.camera
        assert abs(camera.image_height - density * css[1]) <= 1.5  # what viser alone would have laid out in
        assert s.painter.canvas_size.measured
        assert not tab.page.locator(f'label:text-is("{CANVAS_REPORT_LABEL}")').is_visible()  # the box is hidden
        assert tab.errors == []
    finally:
        tab.close()


def test_each_tab_is_its_own_session(browser: Any, app_server: App) -> None:
    a = AppPage(browser, app_server)
    b = AppPage(browser, app_server)
    try:
        a.type_into_slider("V", 0.3)
        wait_until(lambda: a.session.state.settings.value("v") == 0.3)
        # a's change is complete; b's session has had no control's value at all and still shows the default
        assert b.session.state.settings.value("v") == Settings().value("v") and b.session.messages_handled == 0
        assert a.session is not b.session
        value = b.slider("V").locator("[role=slider]").get_attribute("aria-valuenow")
        assert float(value) == pytest.approx(Settings().value("v"))
    finally:
        a.close()
        b.close()


def test_a_stale_tab_after_an_upgrade_is_told(browser: Any) -> None:
    old = App(port=0, version="0.0.1-old")
    port = old.server.get_port()
    page = AppPage(browser, old)
    new = None
    try:
        # the tab has recorded the version it runs (viser prefixes the keys it writes)
        recorded = """() => Object.keys(localStorage).some(
            k => k.endsWith('rigidrel_version') && localStorage.getItem(k) === '0.0.1-old')"""
        wait_until(lambda: page.page.evaluate(recorded))
        old.stop()
        new = App(port=port, version="9.9.9-new")
        assert new.server.get_port() == port
        # the tab reconnects by itself and is told what happened
        page.page.wait_for_selector("text=rigidrel was updated", timeout=60_000)
        text = page.page.locator(".mantine-Notification-root").all_inner_texts()
        assert any("0.0.1-old" in t and "9.9.9-new" in t and "reload" in t for t in text), text
    finally:
        page.close()
        if new is not None:
            new.stop()
        else:
            old.stop()


def test_user_slider_changes_scene_and_plots(tab: AppPage, shots: Path) -> None:
    before_charts = tab.session.painter.drawn.charts  # type: ignore[union-attr]
    before_velocity = tab.session.painter.drawn.resolved.scene.final_velocities  # type: ignore[union-attr]
    img = tab.canvas_after(np.zeros_like(tab.canvas()))
    tab.type_into_slider("V", 0.85)
    wait_until(lambda: tab.session.state.settings.value("v") == 0.85)
    after = tab.canvas_after(img)
    assert tab.session.painter.drawn.resolved.scene.final_velocities != before_velocity  # type: ignore[union-attr]
    assert all(a is not b for a, b in zip(tab.session.painter.drawn.charts, before_charts, strict=True))  # type: ignore[union-attr]
    # the diagrams' area of the canvas changed (the curves follow V), not only the lanes
    layout = tab.session.painter.layout
    assert layout is not None
    top = round(layout.height - layout.diagram.outer.z1)
    assert _changed_fraction(after[top:], img[top:]) > 1e-3
    tab.page.screenshot(path=str(shots / "after_V_0.85.png"))
    assert tab.errors == []


def test_frame_dropdown_changes_the_chosen_lane_only(tab: AppPage, shots: Path) -> None:
    default_scene = tab.canvas()
    show(tab, Settings("rod-collision", frame="lab"), 0.2)
    img0 = tab.canvas_after(default_scene)
    tab.choose("Frame", "rod 2 after")
    wait_until(lambda: tab.session.painter.drawn.resolved.frame.name == "rod 2 after")  # type: ignore[union-attr]
    img1 = tab.canvas_after(img0)
    tab.page.screenshot(path=str(shots / "frame_rod2_after.png"))
    layout = tab.session.painter.layout
    assert layout is not None
    lab, frame = layout.lanes
    lab_rows = slice(round(layout.height - lab.band.z1), round(layout.height - lab.band.z0))
    frame_rows = slice(round(layout.height - frame.band.z1), round(layout.height - frame.band.z0))
    Image.fromarray(img0.astype(np.uint8)).save(shots / "canvas_before.png")
    Image.fromarray(img1.astype(np.uint8)).save(shots / "canvas_after.png")
    # Compare where the rods are drawn, not raw pixels: swiftshader may re-rasterise
    # an unchanged lane one pixel over (antialiasing of the stripes and labels).
    before_lab, before_frame = rod_extents(img0[lab_rows]), rod_extents(img0[frame_rows])
    after_lab, after_frame = rod_extents(img1[lab_rows]), rod_extents(img1[frame_rows])
    assert np.abs(after_lab - before_lab).max() <= 3, (before_lab, after_lab, layout.height, img0.shape)
    assert np.abs(after_frame - before_frame).max() >= 8, (before_frame, after_frame)


def rod_extents(img: np.ndarray) -> np.ndarray:
    """Leftmost and rightmost pixel column of each rod colour, shape (rods, 2)."""
    out = []
    for color in ROD_COLORS[:2]:  # the two rods of the scenes drawn here (a third colour is for a third rod)
        rgb = np.array([int(color[i : i + 2], 16) for i in (1, 3, 5)], dtype=float)
        columns = np.nonzero((np.abs(img - rgb).sum(axis=-1) < 60).any(axis=0))[0]
        assert columns.size, f"no pixel of rod colour {color}"
        out.append((columns.min(), columns.max()))
    return np.array(out)


def test_every_text_is_at_least_14_px(tab: AppPage, shots: Path) -> None:
    """Sent sizes (viser's label em is 12 CSS px times its scale) and, measured on the canvas, the
    height of a ruler's digits (a digit is about 0.7 em high)."""
    from rigidrel_app.backends.viser import LABEL_EM_PX

    tab.page.set_viewport_size({"width": 1280, "height": 720})
    wait_until(lambda: tab.session.painter.layout is not None and tab.session.painter.layout.height == 720)
    r = tab.session.painter.renderer
    sizes = [t[2] * LABEL_EM_PX for t in (*r.static_texts.shown, *r.axis_names.shown, *r.titles.shown)]
    assert min(sizes) >= 14.0, min(sizes)
    show(tab, Settings(), 0.3)
    img = tab.canvas_after(np.zeros_like(tab.canvas()))
    tab.page.screenshot(path=str(shots / "text_1280x720.png"))
    layout = tab.session.painter.layout
    assert layout is not None
    place = layout.lanes[0]
    _, top = tab.page_to_pixel(0.0, place.ruler_z - place.tick_px - 1.0)
    _, bottom = tab.page_to_pixel(0.0, place.band.z0)
    left, _ = tab.page_to_pixel(place.track.x0 + 40, 0.0)
    band = img[round(top) : round(bottom), round(left) : round(place.track.x1)]
    dark_rows = np.flatnonzero((band.sum(axis=-1) < 3 * 140).any(axis=1))
    assert dark_rows.size, "no ruler numbers found"
    digit_height = dark_rows.max() - dark_rows.min() + 1
    assert digit_height >= 0.68 * 14.0, digit_height


def test_playback_keeps_lanes_and_diagrams_at_one_instant(tab: AppPage, shots: Path) -> None:
    """While playing, the lanes' clock and the diagrams' now-lines are one update; paused, the lab
    diagram's now-line is on the canvas at the lanes' t."""
    tab.page.click("button:has-text('Play')")
    wait_until(lambda: tab.session.player.playing)  # the browser plays the state's timeline
    f = shown(tab.session.painter.chart_frames[0])
    seen = set()
    for _ in range(20):  # during playback, the page as the browser holds it: both from one frame
        title, zs = tab.title_and_now_lines()
        m = re.match(r"lab frame:\s+t = ([+-]\d+\.\d+)", title)
        assert m, title
        now = float(m.group(1))
        seen.add(now)
        _, z_now = f.px(np.array([0.0]), np.array([now]))
        # the lab diagram's now-line at the title's t (to the title's rounding to 0.001)
        rounding = abs(float(f.px(np.array([0.0]), np.array([now + 0.0005]))[1][0] - z_now[0]))
        assert min(abs(z - z_now[0]) for z in zs) <= rounding + 1e-2, (title, zs)
        time.sleep(0.05)
    assert len(seen) > 5  # it played
    tab.page.click("button:has-text('Pause')")
    wait_until(lambda: tab.session.playing.settled)
    now = tab.session.state.playback.now
    img = tab.canvas_after(np.zeros_like(tab.canvas()))
    tab.page.screenshot(path=str(shots / "paused.png"))
    f = shown(tab.session.painter.chart_frames[0])
    _, z_now = f.px(np.array([0.0]), np.array([now]))
    _, row = tab.page_to_pixel(0.0, float(z_now[0]))
    x0, _ = tab.page_to_pixel(f.plot.x0 + 2, 0.0)
    x1, _ = tab.page_to_pixel(f.plot.x1 - 2, 0.0)
    strip = img[round(row) - 6 : round(row) + 7, round(x0) : round(x1)]
    dark = (strip.sum(axis=-1) < 3 * 100).mean(axis=1)  # the black now-line crosses the whole plot
    assert dark.max() > 0.6 and abs(int(np.argmax(dark)) - 6) <= 2, dark
    assert json.dumps(tab.errors) == "[]"


def test_a_play_without_loop_stops_exactly_at_the_end(tab: AppPage) -> None:
    s = tab.session
    with s.lock:
        s.set_playback(
            replace(
                s.state.playback.seek(
                    s.state.playback.window[1] - 0.05 * (s.state.playback.window[1] - s.state.playback.window[0])
                ),
                loop=False,
                speed=4.0,
            )
        )
    end = s.state.playback.window[1]
    tab.page.click("button:has-text('Play')")
    # the last 5 % at 4x can play through between two polls: wait for playing, or for the end
    wait_until(lambda: s.player.playing or s.state.playback.now == end)
    wait_until(lambda: not s.state.playback.playing, timeout=30)
    wait_until(lambda: s.playing.settled)
    with s.lock:  # the browser's last frame, the window's end, is where the clock stopped
        assert s.state.playback.now == end
    # the page shows it once viser has drawn the runtime's last frame
    wait_until(lambda: (tab.nodes("/page/title/0")[0] or {}).get("props", {}).get("text", "").startswith(
        f"lab frame:   t = {end:+.3f}"))  # fmt: skip
    wait_until(lambda: tab.session.controls.time.slider.value == pytest.approx(end, abs=1e-6))


def test_f_toggles_presenter_mode(tab: AppPage, shots: Path) -> None:
    tab.page.set_viewport_size({"width": 1280, "height": 720})
    wait_until(lambda: tab.session.painter.layout is not None and tab.session.painter.layout.height == 720)
    normal = tab.session.painter.layout
    assert normal is not None and normal.width < 1000  # the control panel takes its side
    tab.page.evaluate("() => document.activeElement && document.activeElement.blur()")
    tab.page.keyboard.press("f")
    wait_until(lambda: tab.session.state.presenter)
    wait_until(lambda: tab.session.painter.layout is not None and tab.session.painter.layout.width > 1200, timeout=30)
    wide = tab.session.painter.layout
    assert wide is not None and wide.theme.text_px > normal.theme.text_px and wide.theme.line_px > normal.theme.line_px
    tab.canvas_after(np.zeros_like(tab.canvas()))
    tab.page.screenshot(path=str(shots / "presenter_1280x720.png"))
    tab.page.keyboard.press("f")
    wait_until(lambda: not tab.session.state.presenter)
    wait_until(lambda: tab.session.painter.layout is not None and tab.session.painter.layout.width < 1000, timeout=30)
    assert tab.page.locator("label:text-is('Scene')").is_visible()


def test_invalid_combination_shows_a_notice_and_keeps_the_scene(tab: AppPage, shots: Path) -> None:
    tab.choose("Scene", "Rod-rod collision")
    wait_until(lambda: tab.session.painter.drawn.resolved.scene.kind == "rod-collision")  # type: ignore[union-attr]
    scene_before = tab.session.painter.drawn.resolved.scene  # type: ignore[union-attr]
    tab.type_into_slider("V2", 0.9)  # faster than V1 = 0.6: the rods never meet
    tab.page.wait_for_selector("text=so that the rods collide", timeout=20_000)
    assert tab.session.painter.drawn.resolved.scene is scene_before  # type: ignore[union-attr]
    tab.page.screenshot(path=str(shots / "notice.png"))
    assert all(np.isfinite(ln.points).all() for ln in tab.session.painter.renderer.still.lines)  # no NaN drawn
    tab.type_into_slider("V2", -0.3)
    wait_until(lambda: tab.session.painter.drawn.resolved.scene is not scene_before)  # type: ignore[union-attr]
    wait_until(lambda: not tab.page.locator("text=so that the rods collide").is_visible())


def test_every_registered_scene_is_in_the_menu_and_draws(tab: AppPage, shots: Path) -> None:
    """The scene menu is the registry: choosing each scene as a user draws it, with its own controls."""
    tab.control("Scene").click()
    options = tab.page.locator("[role=option]:visible").all_inner_texts()
    tab.page.keyboard.press("Escape")
    titles = [d.title for d in rr.scene_descriptions().values()]
    assert options == titles
    for kind, d in rr.scene_descriptions().items():
        before = tab.canvas()
        tab.choose("Scene", d.title)
        wait_until(lambda kind=kind: tab.session.painter.drawn.resolved.scene.kind == kind)  # type: ignore[union-attr]
        for p in d.parameters:
            if p.slider is not None:  # this scene's controls are shown
                label = tab.page.locator("label").filter(has_text=re.compile(f"^{re.escape(p.label)}$"))
                label.wait_for(state="visible", timeout=20_000)
        if kind != "constant-acceleration":
            tab.canvas_after(before)
        tab.page.screenshot(path=str(shots / f"{kind}.png"))
    assert tab.errors == []
