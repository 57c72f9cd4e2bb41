"""A lesson given live (``rigidrel serve --lesson``) in a real browser: the keyboard and a clicker's
keys walk the steps, the caption band follows, ``--follow`` tabs follow the leading tab, a step's
locks disable controls, and the scenario box round-trips a state and refuses a bad one."""

from __future__ import annotations

from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from rigidrel_app.backends.viser import shared_root
from rigidrel_app.lessons import builtin_lesson, parse_lesson
from rigidrel_app.live.keys import Action
from rigidrel_app.live.server import App
from rigidrel_app.live.session import Session
from rigidrel_app.view.layers import Layer
from rigidrel_app.view.layout import CAPTION_SHARE, MIN_PLOT_PX, NORMAL, CanvasLayout, caption_reserve
from rigidrel_app.view.scenario import parse_scenario
from tests.browser.conftest import element_png
from tests.browser.test_app_browser import SOFTWARE_NOTE, slider_of
from tests.viser_client import wait_until

pytestmark = pytest.mark.browser

PAPER = builtin_lesson("paper")

LOCKED = parse_lesson(
    """title = "Locks"

[[step]]
title = "The crash, V fixed"
scene = "wall-collision --v 0.6 --eps 0 --frame lab"
caption = "The back end brakes at t = {event[T_1].t:.3g}."
lock = ["v", "frame"]

[[step]]
title = "Free"
scene = "wall-collision --v 0.8 --eps 1"
caption = "Anything goes."
""",
    "locks.toml",
)


class LessonTab:
    """One tab giving the lesson, with the session behind it."""

    def __init__(self, page: Any, app: App, url: str | None = None) -> None:
        """``url``: the address opened (the app's own by default; its lead address for the lecturer)."""
        before = set(app.sessions)
        self.page = page
        self.errors: list[str] = []
        self.page.on("pageerror", lambda e: self.errors.append(str(e)))
        self.page.goto(url or app.url)
        self.page.wait_for_selector("label:text-is('Step')", timeout=120_000)  # a busy machine is slow
        new = wait_until(lambda: set(app.sessions) - before, timeout=60)
        self.session: Session = app.sessions[min(new)]
        wait_until(lambda: self.session.painter.drawn is not None, timeout=60)
        wait_until(lambda: self.page.locator(SOFTWARE_NOTE).count() == 0, timeout=30)  # closed by the page

    def caption(self) -> str:
        band = self.page.locator("#rigidrel-caption")
        return band.inner_text() if band.count() and band.is_visible() else ""

    def wait_caption(self, title: str) -> None:
        wait_until(lambda: title in self.caption(), timeout=30)

    def control(self, label: str) -> Any:
        uid = self.page.locator(f'label:text-is("{label}")').first.get_attribute("for")
        return self.page.locator(f"[id='{uid}']")

    def slider(self, label: str) -> Any:
        return slider_of(self.page, self.session, label)

    def text_box(self, label: str) -> Any:
        """A text box by its label (viser's text box label names no id)."""
        return self.page.locator(f'label:text-is("{label}")').first.locator("xpath=following::input[1]")

    def canvas(self) -> np.ndarray:
        return element_png(self.page, "canvas[data-engine]")

    def screenshot(self, path: Path) -> None:
        """The page once paused and drawn (two canvases half a second apart the same), for a person to look at."""
        if self.session.state.playback.playing:
            self.session.perform(Action.TOGGLE_PLAY)
        shots = [self.canvas()]

        def still() -> bool:
            shots.append(self.canvas())
            a, b = shots[-2], shots[-1]
            return a.shape == b.shape and float((np.abs(a - b).sum(axis=-1) > 30).mean()) < 1e-4

        wait_until(still, timeout=60, interval=0.5)
        self.page.screenshot(path=str(path))

    def caption_px(self) -> float:
        """The caption text's font size (CSS px)."""
        return float(
            self.page.evaluate(
                "() => parseFloat(getComputedStyle(document.querySelector('#rigidrel-caption p')).fontSize)"
            )
        )

    def press(self, key: str) -> None:
        self.page.evaluate("() => document.activeElement && document.activeElement.blur()")  # no box has the focus
        self.page.keyboard.press(key)


#: Whether the page's runtime shows the node of a name (present, and not hidden).
SHOWN_NODE = "(r) => { const n = window.__rigidrelPlayback.node(r); return !!n && n.visible !== false; }"


#: The ``open_tab`` fixture: ``open_tab(app, width=1280, height=720)`` -> a tab on ``app``.
OpenTab = Callable[..., LessonTab]


@pytest.fixture
def open_tab(browser: Any) -> Iterator[OpenTab]:
    """Opens tabs on an app; every one is closed after the test, passed or failed (an open tab keeps
    drawing, and the software renderer's time is the whole suite's)."""
    pages: list[Any] = []

    def open_one(app: App, width: int = 1280, height: int = 720, url: str | None = None) -> LessonTab:
        pages.append(browser.new_page(viewport={"width": width, "height": height}))
        return LessonTab(pages[-1], app, url)

    try:
        yield open_one
    finally:
        for page in pages:
            page.close()


@pytest.fixture(scope="module")
def lesson_app() -> Iterator[App]:
    """The paper's lesson, not followed (each tab walks it on its own), for this file's tests."""
    app = App(host="127.0.0.1", port=0, lesson=PAPER)
    try:
        yield app
    finally:
        app.stop()


def test_keyboard_walk_through_the_paper_lesson(open_tab: OpenTab, lesson_app: App, shots: Path) -> None:
    tab = open_tab(lesson_app)
    s = tab.session
    tab.wait_caption(PAPER.steps[0].title)
    assert s.state.step == 0 and "a′_F = 0.5" in tab.caption()  # a number the core filled in
    tab.screenshot(shots / "step-1-1280.png")
    wait_until(lambda: s.player.ready, timeout=60)  # the page's runtime plays: steps come as shared pages
    walk = [("PageDown", 1), ("PageDown", 2), ("ArrowRight", 3), ("PageUp", 2), ("ArrowLeft", 1), ("PageUp", 0)]
    for key, step in walk:
        tab.press(key)
        tab.wait_caption(PAPER.steps[step].title)
        assert s.state.step == step
        expected = PAPER.steps[step].scenario.settings
        wait_until(lambda expected=expected: s.state.settings.values == expected.values, timeout=30)
        # the step's page, whole: the one shared by every tab on this canvas (sent under a root of
        # its own, so never mixed with the step before), its own still picture hidden
        painting = s.painter.painting
        assert painting is not None and painting.key.settings == s.state.settings and s.painter.renderer.still_lent
        root = shared_root(painting.id)
        wait_until(lambda root=root: tab.page.evaluate(SHOWN_NODE, root), timeout=30)
    tab.press("PageUp")  # at the first step: stays
    assert s.state.step == 0
    # the step list in the panel
    tab.control("Step").click()
    tab.page.locator('[role=option]:has-text("4/15")').first.click()
    tab.wait_caption(PAPER.steps[3].title)
    assert s.state.settings.scene == "impulsive-start" and Layer.SIGNALS in s.state.settings.layers
    assert tab.page.locator("label:text-is('Light signals')").count() == 1
    # keys typed into a box stay in the box
    field = tab.text_box("Load")
    field.click()
    field.press("PageDown")
    field.press("ArrowRight")
    field.type("abc")
    assert field.input_value() == "abc" and s.state.step == 3
    # presenter mode keeps the caption, larger
    tab.press("f")
    wait_until(lambda: tab.page.locator("#rigidrel-caption .rr-caption-presenter").count() == 1, timeout=30)
    tab.press("PageDown")
    tab.wait_caption(PAPER.steps[4].title)
    assert tab.page.locator("#rigidrel-caption .rr-caption-presenter").count() == 1
    assert tab.caption_px() >= 18  # read from the back of a hall, on a 1280x720 projector (the canvas text: 15-21)
    tab.screenshot(shots / "presenter-step-5-1280.png")
    tab.press("c")  # the caption band folds away, and back
    wait_until(lambda: tab.caption() == "", timeout=30)
    tab.press("c")
    tab.wait_caption(PAPER.steps[4].title)
    assert tab.errors == []


@pytest.mark.parametrize(("width", "height"), [(1280, 720), (1920, 1080)])
def test_bell_and_the_barn_keep_their_diagrams_under_their_captions(
    open_tab: OpenTab, lesson_app: App, shots: Path, width: int, height: int
) -> None:
    """Steps 13 and 14 (captions of five to seven lines, both in the lab frame): the band takes what
    the viewport has beyond the canvas the diagrams need (at most CAPTION_SHARE), the rest of the caption
    scrolls in it, and the canvas shows the lab once, its plots 150 px high or more."""
    tab = open_tab(lesson_app, width, height)
    tab.wait_caption(PAPER.steps[0].title)
    band_px = max(min(height - caption_reserve(NORMAL), CAPTION_SHARE * height), 88)
    band = tab.page.locator("#rigidrel-caption")
    for index in (12, 13):
        tab.session.go_to_step(index)
        tab.wait_caption(PAPER.steps[index].title)

        def laid_out() -> CanvasLayout | None:
            box, canvas = band.bounding_box(), tab.page.locator("canvas[data-engine]").bounding_box()
            size, layout = tab.session.painter.canvas_size, tab.session.painter.layout
            if box is None or canvas is None or layout is None or not size.measured:
                return None
            fits = (size.width, size.height) == (round(canvas["width"]), round(canvas["height"]))
            return layout if fits and (layout.width, layout.height) == (size.width, size.height) else None

        layout = wait_until(laid_out, timeout=60)
        box = band.bounding_box()
        assert box is not None and abs(box["height"] - band_px) <= 1, (box, band_px)
        assert len(layout.lanes) == 1 and layout.charts[1] is None
        assert all(c.plot.height >= MIN_PLOT_PX for c in layout.shown_charts), layout.shown_charts
        # a caption longer than its band (at 720 px, always) scrolls there, and says so: a shadow at
        # its foot, and the focus it takes for the keys that scroll it; one that fits has neither
        over, shadow, focusable = band.evaluate(
            "(b) => [b.scrollHeight > b.clientHeight, b.classList.contains('rr-more'), b.tabIndex]"
        )
        assert (over or height != 720) and shadow == over and focusable == (0 if over else -1), (over, shadow)
        tab.screenshot(shots / f"step-{index + 1}-{width}.png")
    # Z: the step's one diagram over the whole canvas, drawn larger; Z again: the page back
    before = layout
    tab.press("z")

    def zoomed_in() -> CanvasLayout | None:
        lay = laid_out()
        return lay if lay is not None and not lay.lanes else None

    zoomed = wait_until(zoomed_in, timeout=60)
    grown = zoomed.diagram.plot.height - before.diagram.plot.height  # by the lane's height, at least
    assert zoomed.charts[1:] == (None, None) and grown >= sum(lane.band.height for lane in before.lanes)
    tab.screenshot(shots / f"step-14-zoomed-{width}.png")
    tab.press("z")
    wait_until(lambda: (lay := laid_out()) is not None and lay == before, timeout=60)
    if height != 720:
        presenter_caption_at_1920(tab, shots)
        return
    # the band scrolled by the keys that read it; a clicker's PageUp still moves the lesson
    band.focus()
    tab.page.keyboard.press("ArrowDown")
    wait_until(lambda: band.evaluate("(b) => b.scrollTop") > 0, timeout=10)
    tab.page.keyboard.press("PageUp")
    tab.wait_caption(PAPER.steps[12].title)


def presenter_caption_at_1920(tab: LessonTab, shots: Path) -> None:
    """Presenter mode at 1920x1080 (F): the caption band larger, to be read from the back of a hall,
    and the canvas below it, laid out again for the size it has once the panel has folded away."""
    tab.press("f")
    wait_until(lambda: tab.page.locator("#rigidrel-caption .rr-caption-presenter").count() == 1, timeout=30)

    def laid_out_for_the_canvas() -> bool:  # as the page measured it, once the panel has folded away
        box = tab.page.locator("canvas[data-engine]").bounding_box()
        band = tab.page.locator("#rigidrel-caption").bounding_box()
        size, layout = tab.session.painter.canvas_size, tab.session.painter.layout
        return (
            box is not None and band is not None and layout is not None and size.measured
            and box["width"] > 1800 and box["height"] < 1080 - band["height"] + 2
            and box["y"] >= band["y"] + band["height"] - 1  # the lanes start below the caption
            and (size.width, size.height) == (round(box["width"]), round(box["height"]))
            and (layout.width, layout.height) == (size.width, size.height)
        )  # fmt: skip

    wait_until(laid_out_for_the_canvas, timeout=30)
    assert tab.caption_px() >= 28
    tab.screenshot(shots / "presenter-step-14-1920.png")
    tab.press("f")


def test_the_riding_step_rides_its_point(open_tab: OpenTab, lesson_app: App, shots: Path) -> None:
    """The built-in lesson's riding step, reached from the step list: its lower lane rides the rod's
    back end (the lane's title says so, and the rod keeps its rest length there)."""
    k = next(i for i, step in enumerate(PAPER.steps) if step.ride is not None)
    tab = open_tab(lesson_app)
    tab.wait_caption(PAPER.steps[0].title)
    tab.control("Step").click()
    tab.page.locator(f'[role=option]:has-text("{k + 1}/{len(PAPER.steps)}")').first.click()
    tab.wait_caption(PAPER.steps[k].title)
    s = tab.session
    wait_until(lambda: s.painter.drawn is not None and s.painter.drawn.resolved.ride == PAPER.steps[k].ride, timeout=30)

    def lanes() -> list[Any]:  # as the page shows them now (the step's shared page and its frames)
        d, layout, now = s.painter.drawn, s.painter.layout, s.state.playback.now
        assert d is not None and layout is not None
        return d.lane_pictures(now, layout, d.ride_instant(now))

    wait_until(lambda: len(lanes()) == 2 and lanes()[1].title.startswith("riding:"), timeout=30)
    lane = lanes()[1]
    rest = s.painter.drawn.resolved.scene.rods[0].motion.length  # type: ignore[union-attr]
    assert float(np.diff(lane.ends[0])[0]) == pytest.approx(rest, rel=1e-12)
    assert "default frame" not in tab.caption()
    tab.screenshot(shots / f"riding-step-{k + 1}-1280.png")
    assert tab.errors == []


def test_follow_the_lecturers_tab(open_tab: OpenTab, shots: Path) -> None:
    """The lecturer's tab, opened at the lead address the server printed, leads; a student's tab
    follows, has no Lead button, and its L is refused with a notice while the lecturer's tab stays."""
    app = App(host="127.0.0.1", port=0, lesson=PAPER, follow=True)
    try:
        student = open_tab(app)
        assert app.leader is None  # a student's tab, first to come, does not lead
        wait_until(lambda: "lecturer" in student.session.controls.lesson.status.content, timeout=30)  # type: ignore[union-attr]
        assert app.lead_url is not None and app.lead_token is not None
        lead = open_tab(app, url=app.lead_url)
        wait_until(lambda: app.leader == lead.session.client.client_id, timeout=30)
        assert lead.session.state.lecturer and not student.session.state.lecturer
        # the token leaves the lecturer's address bar (a projector shows it); a reload keeps the lead
        assert app.lead_token not in lead.page.url
        assert lead.page.get_by_role("button", name="Lead the other tabs").count() == 1
        assert student.page.get_by_role("button", name="Lead the other tabs").count() == 0
        lead.press("PageDown")
        lead.press("PageDown")
        lead.wait_caption(PAPER.steps[2].title)
        student.wait_caption(PAPER.steps[2].title)
        assert student.session.state.step == 2
        wait_until(lambda: "lecturer's step" in student.session.controls.lesson.status.content, timeout=30)  # type: ignore[union-attr]

        def node(tab: Any, name: str) -> dict[str, Any] | None:
            return tab.page.evaluate("(n) => window.__rigidrelPlayback.node(n)", name)

        # the follower shows the step's shared page (its own still picture hidden), and so does the
        # leader: one page, made once, sent whole
        def root() -> str:
            painting = student.session.painter.painting
            return "" if painting is None else shared_root(painting.id)

        wait_until(lambda: (node(student, f"{root()}/text/0") or {}).get("visible"), timeout=30)
        assert not (node(student, "/page/static") or {}).get("visible", True)
        assert lead.session.painter.painting is not None and lead.session.painter.renderer.still_lent
        wait_until(lambda: node(lead, "/shared") is not None, timeout=30)

        def shows_its_painting() -> bool:
            """The page's shared texts are those of the painting the follower's session shows now (a
            painting for a new canvas size may replace the first while its page is on its way)."""
            painting = student.session.painter.painting
            if painting is None:
                return False
            labels = student.page.evaluate(
                "(root) => Array.from({length: 40}, (_, k) => window.__rigidrelPlayback.node(root + '/text/' + k))"
                ".filter((n) => n && n.visible).map((n) => n.props.text)",
                shared_root(painting.id),
            )
            return sorted(labels) == sorted(t.text for t in painting.still.texts if t.text.strip())

        wait_until(shows_its_painting, timeout=30)
        student.page.screenshot(path=str(shots / "follower-shared-page.png"))
        # a student's L: refused, said in the Lesson folder; the lecturer's tab does not move
        student.press("L")
        notice = student.session.controls.notices["lesson"]
        wait_until(lambda: notice.visible and "Only the lecturer's tab leads" in notice.content, timeout=30)
        assert app.leader == lead.session.client.client_id and lead.session.state.step == 2
        student.press("PageDown")  # the student's own move: the lecturer's tab stays where it is
        student.wait_caption(PAPER.steps[3].title)
        assert lead.session.state.step == 2 and app.leader_step == 2
        student.page.screenshot(path=str(shots / "student-lead-refused.png"))
        # the lecturer reloads: the address without the token still leads (the tab kept it)
        lead.page.reload()
        lead.page.wait_for_selector("label:text-is('Step')", timeout=120_000)
        wait_until(lambda: app.leader is not None and app.leader != lead.session.client.client_id, timeout=60)
        assert app.leader in app.lecturers
        assert lead.errors == [] and student.errors == []
    finally:
        app.stop()


def test_a_locked_control_is_disabled_and_says_why(open_tab: OpenTab, shots: Path) -> None:
    app = App(host="127.0.0.1", port=0, lesson=LOCKED)
    try:
        tab = open_tab(app)
        tab.wait_caption("The crash, V fixed")
        v_thumb = tab.slider("V").locator("[role=slider]")
        wait_until(lambda: v_thumb.get_attribute("aria-disabled") == "true", timeout=30)
        assert tab.control("Frame").is_disabled()
        assert tab.text_box("V").is_disabled()  # its box too
        assert tab.slider("ε (restitution)").locator("[role=slider]").get_attribute("aria-disabled") != "true"
        assert not tab.text_box("ε (restitution)").is_disabled()
        assert tab.page.get_by_text("Locked by step 1: V, Frame").count() == 1
        tab.page.screenshot(path=str(shots / "locked.png"))
        # a value sent for the locked control anyway is refused on the server
        with tab.session.lock:
            tab.session.asks.change(tab.session.state.settings.with_value("v", 0.9))
        assert tab.session.state.settings.value("v") == 0.6 and "locked by step 1" in tab.session.state.notice.text
        tab.press("PageDown")
        tab.wait_caption("Free")
        wait_until(lambda: v_thumb.get_attribute("aria-disabled") != "true", timeout=30)
        assert not tab.control("Frame").is_disabled()
    finally:
        app.stop()


def test_scenario_box_round_trip_and_a_bad_one(open_tab: OpenTab, lesson_app: App, shots: Path) -> None:
    tab = open_tab(lesson_app)
    s = tab.session
    tab.wait_caption(PAPER.steps[0].title)
    line = (
        "rod-collision --v1 0.6 --mass2 2 --v2 0 --length2 1 --eps 1 --frame barycentric "
        "--layers world-tube,signals --t 0.3"
    )
    box = tab.text_box("Load")
    box.fill(line)
    wait_until(lambda: s.controls.scenario_box.value == line, timeout=30)
    tab.page.locator("button:has-text('Load scenario')").click()
    wait_until(lambda: s.state.settings.scene == "rod-collision" and abs(s.state.playback.now - 0.3) < 1e-9, timeout=30)
    assert s.state.settings.layers == {Layer.WORLD_TUBE, Layer.SIGNALS} and s.state.notice.text == ""
    wait_until(lambda: "now shows another scene" in tab.caption(), timeout=30)  # the step's caption says so
    shown = tab.page.locator("code.rigidrel-scenario")
    wait_until(lambda: shown.inner_text() == line, timeout=30)  # the same line comes back
    assert parse_scenario(shown.inner_text()).settings == s.state.settings
    assert not s.controls.layers[Layer.LIGHT_CONE].value and s.controls.layers[Layer.SIGNALS].value
    # a bad line: a notice naming the flag and its range, the state unchanged
    box.fill("rod-collision --v1 1.6")
    wait_until(lambda: s.controls.scenario_box.value == "rod-collision --v1 1.6", timeout=30)
    tab.page.locator("button:has-text('Load scenario')").click()
    notice = tab.page.locator("text=Scenario refused")
    wait_until(lambda: notice.count() == 1 and notice.is_visible(), timeout=30)
    assert "--v1" in notice.inner_text() and "(-1, 1)" in notice.inner_text()
    assert s.state.settings.value("v1") == 0.6
    tab.page.screenshot(path=str(shots / "scenario-refused.png"))
    assert tab.errors == []
