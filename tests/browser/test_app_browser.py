"""The app in a real browser: it loads, draws the core's positions, and reacts to a user.

Each test starts its own server (127.0.0.1, free port) and page; screenshots land in
``test-artifacts/screenshots/<test>/``.
"""

from __future__ import annotations

import io
import json
import re
import time
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from PIL import Image

import rigidrel_core as rr
from rigidrel_app.backends.viser import ROD_DEPTH
from rigidrel_app.live.server import App
from rigidrel_app.live.session import Session
from rigidrel_app.view import camera as cam
from rigidrel_app.view.lanes import lane_geometry
from rigidrel_app.view.scene_view import FRAME_Z, LAB_Z
from rigidrel_app.view.state import CUSTOM_FRAME, Settings
from rigidrel_app.view.vocabulary import ROD_COLORS
from tests.browser.conftest import VIEWPORT
from tests.viser_client import wait_until

pytestmark = pytest.mark.browser

#: Detected rod edges must lie this close to the core's positions projected through the camera.
PIXEL_TOLERANCE = 3.0


class AppPage:
    """One browser tab on the app, with the server-side session behind it."""

    def __init__(self, browser: Any, app: App) -> None:
        self.app = app
        self.errors: list[str] = []
        before = set(app.sessions)
        self.page = browser.new_page(viewport=VIEWPORT)
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
        self.opened = time.monotonic()
        self.page.goto(app.url)
        self.page.wait_for_selector("label:text-is('Scene')", timeout=60_000)
        self.page.wait_for_function("() => document.querySelectorAll('.js-plotly-plot').length >= 2", timeout=60_000)
        new = wait_until(lambda: set(app.sessions) - before)
        self.session: Session = app.sessions[min(new)]
        for button in self.page.locator(".mantine-Notification-root button").all():
            button.click()

    def close(self) -> None:
        self.page.close()

    # ---------------------------------------------------------------- as a user
    def control(self, label: str) -> Any:
        uid = self.page.locator(f'label:text-is("{label}")').get_attribute("for")
        return self.page.locator(f"[id='{uid}']")

    def type_into_slider(self, label: str, value: float) -> None:
        box = self.control(label).locator("xpath=..").locator("input.mantine-NumberInput-input")
        box.fill(str(value))
        box.press("Enter")

    def choose(self, label: str, option: str) -> None:
        self.control(label).click()
        self.page.locator(f'[role=option]:has-text("{option}")').first.click()

    # ---------------------------------------------------------------- reading the page
    def open_tab(self, name: str) -> None:
        self.page.locator(f'[role=tab]:has-text("{name}")').click()

    def lengths_plot(self) -> dict[str, Any]:
        """The Fig. 2 panel (in the left panel's second tab); leaves that tab open."""
        self.open_tab("Lengths")
        return wait_until(lambda: next((p for p in self.plots() if "Equal-time" in p["title"]), None))

    def diagrams(self) -> list[dict[str, Any]]:
        """The two Minkowski diagrams (first tab of the left panel)."""
        self.open_tab("Minkowski")
        return wait_until(lambda: [p for p in self.plots() if "Minkowski" in p["title"]] or None)

    def plots(self) -> list[dict[str, Any]]:
        return self.page.evaluate(
            """() => Array.from(document.querySelectorAll('.js-plotly-plot')).map(gd => ({
                title: gd.layout.title ? gd.layout.title.text : '',
                names: gd._fullData.filter(t => t.showlegend).map(t => t.name),
                annotations: (gd.layout.annotations || []).map(a => a.text),
                traces: gd._fullData.map(t => ({x: Array.from(t.x || []), y: Array.from(t.y || [])})),
            }))"""
        )

    def canvas(self) -> np.ndarray:
        png = self.page.locator("canvas[data-engine]").screenshot()
        return np.asarray(Image.open(io.BytesIO(png)).convert("RGB")).astype(np.int16)

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


@pytest.fixture
def tab(browser: Any, app_server: App) -> Any:
    page = AppPage(browser, app_server)
    try:
        yield page
    finally:
        page.close()


def show(tab: AppPage, settings: Settings, now: float) -> None:
    """Put the session in a known state, paused at ``now`` (server side, as a preset would)."""
    s = tab.session
    with s.lock:
        s.controls.fit.value = True
        s.change(settings, refit=True)
        s.seek(now)


def current_pose(tab: AppPage) -> cam.CameraPose:
    c = tab.session.client.camera
    return cam.CameraPose(tuple(c.position), tuple(c.look_at), tuple(c.up_direction), c.fov)


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


def expected_extent(x0: float, x1: float, z: float, pose: cam.CameraPose, w: int, h: int) -> tuple[float, float, float]:
    """Pixel columns of a box's silhouette (front and back faces) and the row of its middle."""
    corners = np.array([[x, y, z] for x in (x0, x1) for y in (-0.5 * ROD_DEPTH, 0.5 * ROD_DEPTH)])
    uv = cam.project(corners, pose, w, h)
    mid = cam.project(np.array([[0.5 * (x0 + x1), -0.5 * ROD_DEPTH, z]]), pose, w, h)[0]
    return float(uv[:, 0].min()), float(uv[:, 0].max()), float(mid[1])


# ====================================================================== tests
def test_page_loads_and_renders(tab: AppPage, shots: Path) -> None:
    wait_until(lambda: len(tab.diagrams()) == 2 and all(p["traces"] for p in tab.diagrams()))
    assert tab.lengths_plot()["traces"]
    tab.open_tab("Minkowski")

    def drawn() -> tuple[int, int] | None:
        # not blank: the rods' blue and the ink of ticks and clocks are on the canvas
        img = tab.canvas()
        blue, dark = int((img[..., 2] - img[..., 0] > 60).sum()), int((img.sum(axis=-1) < 200).sum())
        return (blue, dark) if blue > 2000 and dark > 300 else None

    wait_until(drawn, timeout=30)
    tab.page.screenshot(path=str(shots / "loaded.png"))
    assert tab.errors == []
    assert tab.external == []


def test_rod_pixels_match_the_core_in_both_lanes(tab: AppPage, shots: Path) -> None:
    """Both lanes put each rod end where the core says, projected through the known camera.

    The chosen frame moves at beta = 0.8 and the clock is mid-collision, so lab positions
    drawn in the frame lane would be off by far more than the tolerance (checked).
    """
    settings = Settings.of("rod-collision", v1=0.6, v2=0.0, m2=2.0, eps=1.0)
    settings = Settings(settings.scene, settings.values, CUSTOM_FRAME, 0.8)
    now = 0.4
    default_scene = tab.canvas()
    show(tab, settings, now)
    scene = tab.session.drawn.resolved.scene  # type: ignore[union-attr]
    frame = tab.session.drawn.resolved.frame  # type: ignore[union-attr]
    unit = lane_geometry(scene).unit
    img = tab.canvas_after(default_scene)
    pose = current_pose(tab)
    h, w = img.shape[:2]
    tab.page.screenshot(path=str(shots / "collision_beta_0.8_t_0.4.png"))
    lanes = {LAB_Z: rr.LAB, FRAME_Z: frame}
    separation = []
    for z, lane_frame in lanes.items():
        x = scene.positions(np.array([now]), lane_frame)[:, :, 0] / unit
        x_lab = scene.positions(np.array([now]), rr.LAB)[:, :, 0] / unit
        for r, color in ((0, "blue"), (1, "orange")):
            lo, hi, v = expected_extent(x[r, 0], x[r, 1], z, pose, w, h)
            runs = rod_runs(img[round(v)], color)
            assert runs, f"no {color} rod found in row {v:.0f} (lane z={z})"
            # lines drawn over the box (ticks, the origin mark) split it into runs: join those
            # that overlap the expected place
            near = [ab for ab in runs if ab[1] >= lo - 2 * PIXEL_TOLERANCE and ab[0] <= hi + 2 * PIXEL_TOLERANCE]
            assert near, f"no {color} rod near columns {lo:.0f}..{hi:.0f} (lane z={z}); runs {runs}"
            a, b = min(ab[0] for ab in near), max(ab[1] for ab in near)
            assert abs(a - lo) <= PIXEL_TOLERANCE and abs(b - hi) <= PIXEL_TOLERANCE, (z, r, (a, b), (lo, hi))
            lab_lo, lab_hi, _ = expected_extent(x_lab[r, 0], x_lab[r, 1], z, pose, w, h)
            separation.append(max(abs(lab_lo - lo), abs(lab_hi - hi)))
    # in the frame lane, lab positions would be visibly wrong: the test can fail for the right reason
    assert max(separation[2:]) > 10 * PIXEL_TOLERANCE


def test_user_slider_changes_scene_and_plots(tab: AppPage, shots: Path) -> None:
    lengths_before = tab.lengths_plot()
    before = tab.diagrams()
    before_velocity = tab.session.drawn.resolved.scene.final_velocities  # type: ignore[union-attr]
    tab.type_into_slider("V", 0.85)
    wait_until(lambda: tab.session.settings.value("v") == 0.85)
    wait_until(lambda: tab.diagrams()[0]["traces"] != before[0]["traces"])
    after = tab.diagrams()
    assert tab.session.drawn.resolved.scene.final_velocities != before_velocity  # type: ignore[union-attr]
    assert after[0]["traces"] != before[0]["traces"]
    assert after[1]["traces"] != before[1]["traces"]
    assert tab.lengths_plot()["traces"] != lengths_before["traces"]  # the lengths follow too
    tab.page.screenshot(path=str(shots / "after_V_0.85.png"))
    assert tab.errors == []


def test_frame_dropdown_changes_the_chosen_lane_only(tab: AppPage, shots: Path) -> None:
    default_scene = tab.canvas()
    show(tab, Settings("rod-collision", frame="lab"), 0.2)
    img0 = tab.canvas_after(default_scene)
    pose = current_pose(tab)
    with tab.session.lock:
        tab.session.controls.fit.value = False  # keep the camera: compare pixels
    tab.choose("Frame", "rod 2 after")
    wait_until(lambda: tab.session.drawn.resolved.frame.name == "rod 2 after")  # type: ignore[union-attr]
    img1 = tab.canvas_after(img0)
    tab.page.screenshot(path=str(shots / "frame_rod2_after.png"))
    h, w = img0.shape[:2]
    top = int(cam.project(np.array([[0.0, 0.0, 0.5 * (LAB_Z + FRAME_Z)]]), pose, w, h)[0, 1])
    Image.fromarray(img0.astype(np.uint8)).save(shots / "canvas_before.png")
    Image.fromarray(img1.astype(np.uint8)).save(shots / "canvas_after.png")
    # Compare where the rods are drawn, not raw pixels: swiftshader may re-rasterise
    # an unchanged lane one pixel over (antialiasing of the stripes and labels).
    before_lab, before_frame = rod_extents(img0[:top]), rod_extents(img0[top:])
    after_lab, after_frame = rod_extents(img1[:top]), rod_extents(img1[top:])
    assert np.abs(after_lab - before_lab).max() <= 3, (before_lab, after_lab)
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


def test_plotly_panels_carry_traces_and_event_labels(tab: AppPage) -> None:
    show(tab, Settings("rod-collision", frame="barycentric"), 0.0)
    wait_until(lambda: any("T<sub>2</sub>" in "".join(p["annotations"]) for p in tab.diagrams()))
    lab, frame = tab.diagrams()
    lengths = tab.lengths_plot()
    assert "lab frame" in lab["title"] and "barycentric" in frame["title"]
    for plot in (lab, frame):
        text = " ".join(plot["annotations"])
        for label in ("T<sub>1</sub>", "T'<sub>1</sub>", "T<sub>2</sub>", "T'<sub>2</sub>"):
            assert label in text, (plot["title"], label)
        assert {"rod 1", "rod 2", "light cone of the origin", "events"} <= set(plot["names"])
        assert any(n.startswith("now: t") for n in plot["names"])
    assert any("axes of barycentric" in n for n in lab["names"])
    assert "Equal-time length" in lengths["title"]
    assert {"rod 1, lab (t)", "rod 2, lab (t)"} <= set(lengths["names"])


def test_each_tab_is_its_own_session(browser: Any, app_server: App) -> None:
    a = AppPage(browser, app_server)
    b = AppPage(browser, app_server)
    try:
        a.type_into_slider("V", 0.3)
        wait_until(lambda: a.session.settings.value("v") == 0.3)
        # a's change is complete; b's session has had no message at all and still shows the default
        assert b.session.settings.value("v") == Settings().value("v") and b.session.messages_handled == 0
        assert a.session is not b.session
        value = b.control("V").locator("[role=slider]").get_attribute("aria-valuenow")
        assert float(value) == pytest.approx(Settings().value("v"))
    finally:
        a.close()
        b.close()


def test_invalid_combination_shows_a_notice_and_keeps_the_scene(tab: AppPage, shots: Path) -> None:
    tab.choose("Scene", "Rod-rod collision")
    wait_until(lambda: tab.session.drawn.resolved.scene.kind == "rod-collision")  # type: ignore[union-attr]
    scene_before = tab.session.drawn.resolved.scene  # type: ignore[union-attr]
    tab.type_into_slider("V2", 0.9)  # faster than V1 = 0.6: the rods never meet
    tab.page.wait_for_selector("text=so that the rods collide", timeout=20_000)
    assert tab.session.drawn.resolved.scene is scene_before  # type: ignore[union-attr]
    tab.page.screenshot(path=str(shots / "notice.png"))
    for p in tab.diagrams():  # still the last valid scene's curves, no NaN
        assert p["traces"] and all(np.isfinite(v) for t in p["traces"] for v in t["x"] if v is not None)
    tab.type_into_slider("V2", -0.3)
    wait_until(lambda: tab.session.drawn.resolved.scene is not scene_before)  # type: ignore[union-attr]
    wait_until(lambda: not tab.page.locator("text=so that the rods collide").is_visible())


def test_playback_moves_the_rods_and_the_now_lines(tab: AppPage) -> None:
    wait_until(lambda: tab.diagrams()[0]["traces"])
    tab.page.click("button:has-text('Play')")
    wait_until(lambda: tab.session.playback.playing)
    t0 = tab.session.playback.now
    wait_until(lambda: tab.session.playback.now > t0)

    def now_lines() -> list[str]:
        return [n for n in tab.diagrams()[0]["names"] if n.startswith("now: t =")]

    names = wait_until(now_lines)
    wait_until(lambda: now_lines() not in ([], names))  # the diagram's now line follows playback
    tab.page.click("button:has-text('Pause')")
    wait_until(lambda: not tab.session.playback.playing)
    assert json.dumps(tab.errors) == "[]"


def test_share_button_is_hidden(tab: AppPage) -> None:
    """viser's share button (it needs the internet) is hidden: the header, drawn with its other icons,
    has no share icon, and no header icon is labelled "Share"."""
    icons = tab.page.locator("button.mantine-ActionIcon-root")
    visible = [icons.nth(k) for k in range(icons.count()) if icons.nth(k).is_visible()]
    assert visible, "the header's icons are not drawn yet"
    assert tab.page.locator("svg.tabler-icon").count() > 0  # tabler icons are drawn: the check can see one
    assert tab.page.locator("svg.tabler-icon-share").count() == 0
    assert all("share" not in (icon.get_attribute("aria-label") or "").lower() for icon in visible)


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
        wait_until(lambda kind=kind: tab.session.drawn.resolved.scene.kind == kind)  # type: ignore[union-attr]
        for p in d.parameters:
            if p.slider is not None:  # this scene's controls are shown
                label = tab.page.locator("label").filter(has_text=re.compile(f"^{re.escape(p.label)}$"))
                label.wait_for(state="visible", timeout=20_000)
        if kind != "constant-acceleration":
            tab.canvas_after(before)
        tab.page.screenshot(path=str(shots / f"{kind}.png"))
    assert tab.errors == []
