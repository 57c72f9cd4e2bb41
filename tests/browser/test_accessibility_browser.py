"""The live app as axe-core (WCAG 2.0/2.1, A and AA) finds it: no serious or critical violation on
the default page, in presenter mode, in the dark theme, with a notice shown, and on a lesson's page
with its caption; viser's own panel is named and darkened from outside (``live/assets/a11y.js``)."""

from __future__ import annotations

from collections.abc import Iterator
from importlib import resources
from pathlib import Path
from typing import Any

import pytest
from axe_playwright_python.sync_playwright import Axe

from rigidrel_app.lessons import lesson_from
from rigidrel_app.live.server import App
from rigidrel_app.view.describe import describe
from tests.browser.test_app_browser import AppPage, tab_on_own_server
from tests.browser.test_controls_browser import press, type_keys
from tests.viser_client import wait_until

pytestmark = pytest.mark.browser

WCAG_21_AA = ["wcag2a", "wcag2aa", "wcag21a", "wcag21aa"]


def serious_violations(page: Any, within: str | None = None) -> list[str]:
    """axe-core's serious and critical violations of WCAG 2.1 A/AA on ``page`` (only inside the
    elements the CSS selector ``within`` picks, if given), one line each."""
    context = None if within is None else {"include": [[within]]}
    result = Axe().run(page, context=context, options={"runOnly": {"type": "tag", "values": WCAG_21_AA}})
    return [
        f"{v['id']} ({v['impact']}): " + " | ".join(n["html"][:120] for n in v["nodes"][:3])
        for v in result.response["violations"]
        if v["impact"] in ("serious", "critical")
    ]


@pytest.fixture
def lesson_tab(browser: Any) -> Iterator[AppPage]:
    with tab_on_own_server(browser, lesson=lesson_from("paper")) as page:
        yield page


def test_the_app_is_axe_clean_in_every_look(tab: AppPage) -> None:
    assert serious_violations(tab.page) == []
    type_keys(tab, "V", "5")  # a refused value (beyond its slider): its notice in the Scene folder
    wait_until(lambda: bool(tab.session.state.notice))
    assert serious_violations(tab.page) == []
    press(tab, "t")  # the dark theme
    wait_until(lambda: tab.session.state.shade == "dark")
    tab.page.wait_for_function("() => document.documentElement.dataset.mantineColorScheme === 'dark'")
    assert serious_violations(tab.page) == []
    press(tab, "f")  # presenter mode: the panel folded away
    wait_until(lambda: tab.session.state.presenter)
    assert serious_violations(tab.page) == []


def test_a_lessons_page_with_its_caption_is_axe_clean(lesson_tab: AppPage) -> None:
    tab = lesson_tab
    tab.page.wait_for_selector("#rigidrel-caption h2")
    assert serious_violations(tab.page) == []
    press(tab, "PageDown")
    wait_until(lambda: tab.session.state.step == 1)
    assert serious_violations(tab.page) == []


def test_reduced_motion_keeps_every_step_still(browser: Any) -> None:
    """A browser that asks for reduced motion: the lesson's autoplaying steps open paused, and Space
    still plays."""
    app = App(host="127.0.0.1", port=0, lesson=lesson_from("paper"))
    page = browser.new_page(viewport={"width": 1280, "height": 720}, reduced_motion="reduce")
    try:
        page.goto(app.url)
        page.wait_for_selector("label:text-is('Step')", timeout=120_000)
        session = wait_until(lambda: next(iter(app.sessions.values()), None), timeout=60)
        wait_until(lambda: session.player.ready and session.state.still, timeout=60)
        assert app.lesson is not None and app.lesson.steps[0].autoplay
        assert not session.state.playback.playing
        page.evaluate("() => document.activeElement && document.activeElement.blur()")
        page.keyboard.press("PageDown")
        page.keyboard.press("PageDown")  # step 3 plays by itself, but not here
        wait_until(lambda: session.state.step == 2, timeout=30)
        assert app.lesson.steps[2].autoplay and not session.state.playback.playing
        page.keyboard.press(" ")
        wait_until(lambda: session.state.playback.playing, timeout=30)
    finally:
        page.close()
        app.stop()


def test_exported_pages_are_axe_clean_and_carry_the_words(browser: Any, tmp_path: Path) -> None:
    """The exported lesson (index, a step, its lanes and diagram) and a scene's diagram and 3-D
    pages: no serious or critical violation; a step's page carries its picture in words."""
    from rigidrel_app.cli import main

    # the built-in lesson's first two steps (every step's pages have the same markup; the whole
    # lesson's export takes 9 s of a quiet machine, and its pages are checked by their own tests)
    paper = (resources.files("rigidrel_app.lessons") / "paper.toml").read_text(encoding="utf-8")
    two = tmp_path / "two.toml"
    two.write_text("[[step]]".join(paper.split("[[step]]")[:3]), encoding="utf-8")
    assert main(["export", "--lesson", str(two), "--out", str(tmp_path / "lesson")]) == 0
    # the scene's pages as every export writes them; short animations (their length changes no markup)
    wall = [
        "export",
        "wall-collision",
        "--out",
        str(tmp_path / "wall"),
        "--seconds",
        "2",
        "--fps",
        "10",
        "--gif-fps",
        "5",
    ]
    assert main(wall) == 0
    pages = [
        tmp_path / "lesson" / name
        for name in ("index.html", "step-01.html", "step-01-canvas.html", "step-01-diagram.html")
    ] + [tmp_path / "wall" / name for name in ("wall-collision-diagram.html", "wall-collision-3d.html")]
    page = browser.new_page(viewport={"width": 1280, "height": 720})
    try:
        for path in pages:
            page.goto(path.as_uri())
            page.wait_for_load_state("load")
            if path.name.endswith(("canvas.html", "3d.html")):  # viser's client: named once it has drawn its panel
                page.wait_for_function("() => window.rigidrelA11y && document.querySelector('[aria-label]')")
            assert serious_violations(page) == [], path.name
        page.goto((tmp_path / "lesson" / "step-01.html").as_uri())
        words = page.locator("details.words")
        assert words.locator("summary").inner_text() == "The picture in words"
        assert "Upper lane: the lab frame" in (words.text_content() or "")
    finally:
        page.close()


def _focused(page: Any) -> dict[str, Any]:
    """What has the keyboard focus: its tag, role, name (a label's text or its aria-label) and
    whether the browser draws a focus ring on it (an outline or a box shadow)."""
    return page.evaluate(
        """() => {
          const el = document.activeElement;
          if (!el || el === document.body) return {tag: 'body', role: '', type: '', name: '', ring: false};
          const s = getComputedStyle(el);
          const label = el.id && document.querySelector('label[for="' + CSS.escape(el.id) + '"]');
          return {
            tag: el.tagName.toLowerCase(), role: el.getAttribute('role') || '', type: el.type || '',
            name: (el.getAttribute('aria-label') || (label && label.textContent) || el.textContent || '').trim(),
            ring: (s.outlineStyle !== 'none' && parseFloat(s.outlineWidth) > 0) || s.boxShadow !== 'none',
          };
        }"""
    )


def _tab_to(page: Any, want: Any, limit: int = 120) -> dict[str, Any]:
    """Press Tab until ``want(focused)``; every stop on the way has a visible focus ring."""
    for _ in range(limit):
        page.keyboard.press("Tab")
        f = _focused(page)
        if f["tag"] != "body":
            assert f["ring"], f"no visible focus on {f}"
        if want(f):
            return f
    raise AssertionError(f"Tab never reached it in {limit} presses")


def test_a_whole_lecture_with_the_keyboard_alone(browser: Any) -> None:
    """Open the lesson, walk every step, change a slider, toggle a layer, switch the frame, play and
    pause: with Tab, Enter, Space, the arrows and the clicker's keys only; the focus is always
    visible, and Tab goes on past everything (no trap, the canvas included)."""
    lesson = lesson_from("paper")
    app = App(host="127.0.0.1", port=0, lesson=lesson)
    # a student who asks for reduced motion: no step plays by itself, so D reads a still instant
    page = browser.new_page(viewport={"width": 1280, "height": 720}, reduced_motion="reduce")
    try:
        page.goto(app.url)
        page.wait_for_selector("label:text-is('Step')", timeout=120_000)
        session = wait_until(lambda: next(iter(app.sessions.values()), None), timeout=60)
        wait_until(lambda: session.player.ready and session.state.still, timeout=60)
        region = page.locator("#rigidrel-said")
        said = lambda: region.text_content() or ""  # noqa: E731
        n = len(lesson.steps)
        for k in range(n):  # the clicker walks every step; the live region says each, and D all of it
            if k:
                page.keyboard.press("PageDown")
                wait_until(lambda k=k: session.state.step == k, timeout=30)
            wait_until(lambda k=k: f"Step {k + 1} of {n}: {lesson.steps[k].title}." in said(), timeout=30)
            resolved = session.painter.drawn.resolved  # type: ignore[union-attr]  # said once the step's picture is on screen
            assert describe(resolved, 0.0).summary in said()  # the scene, its parameters and both lanes' frames
            assert not session.state.playback.playing  # reduced motion: the step waits for Space
            page.keyboard.press("d")
            wait_until(lambda r=resolved: describe(r, session.state.playback.now).full in said())
            full = said()
            for name in [r.name for r in resolved.scene.rods]:  # every rod, in each lane
                primed = full.count(f"{name} from x′")  # the lower lane's, none where the lab shows once
                assert full.count(f"{name} from x") >= 1, (k, name)
                assert primed == 0 if resolved.lab_only else primed >= 1, (k, name, primed)
            lanes = ("One lane: the lab frame",) if resolved.lab_only else ("Upper lane: ", "Lower lane: ")
            assert all(words in full for words in lanes), (k, lanes)
        for k in range(len(lesson.steps) - 2, -1, -1):
            page.keyboard.press("PageUp")
            wait_until(lambda k=k: session.state.step == k, timeout=30)
            # the page has the step (its panel and its words) before a key goes to its controls
            wait_until(lambda k=k: f"Step {k + 1} of {n}: {lesson.steps[k].title}." in said(), timeout=30)
        # a slider: Tab to V's, then the arrows move it
        before = session.state.settings.value("v")
        _tab_to(page, lambda f: f["role"] == "slider" and f["name"].startswith("V"))
        page.keyboard.press("ArrowRight")
        wait_until(lambda: session.state.settings.value("v") != before, timeout=30)
        # a layer: Tab to its box, Space toggles it
        _tab_to(page, lambda f: f["type"] == "checkbox" and f["name"] == "Light signals")
        had = "signals" in {layer.value for layer in session.state.settings.layers}
        page.keyboard.press("Space")
        wait_until(lambda: ("signals" in {layer.value for layer in session.state.settings.layers}) != had, timeout=30)
        # the frame: Tab to its menu, the arrows open it and move, Enter chooses
        frame = session.frame_choice()
        _tab_to(page, lambda f: f["role"] == "combobox" and f["name"] == "Frame")
        page.keyboard.press("ArrowDown")
        page.locator("[role=listbox]:visible").wait_for()
        page.keyboard.press("ArrowDown")
        page.keyboard.press("Enter")
        wait_until(lambda: session.frame_choice() != frame, timeout=30)
        # play and pause: Tab to the Play (or Pause) button; Enter plays or pauses, and Enter again
        _tab_to(page, lambda f: f["tag"] == "button" and f["name"] in ("Play", "Pause"))
        for _ in range(2):
            was = session.state.playback.playing
            page.keyboard.press("Enter")
            wait_until(
                lambda was=was: session.state.playback.playing != was and session.playing.settled is was, timeout=30
            )
        # no trap: Tab goes on and comes round again to the step list
        seen = {_tab_to(page, lambda f: True)["name"] for _ in range(3)}
        assert len(seen) > 1
        _tab_to(page, lambda f: f["name"] == "Step" or f["name"].startswith("1/15") or "Step" in f["name"], limit=200)
    finally:
        page.close()
        app.stop()
