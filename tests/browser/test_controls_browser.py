"""The controls as a lecturer uses them, in a real browser: keys and a clicker, typed values and
their notices, the mass ratio typed as a ratio, the paper-figure menu, resetting the view.

Keys are pressed with nothing focused (as after a click on the 3-D view); values are typed key
by key where that matters (the server sees every keystroke, as it does from a person). The tests
share one tab, reset before each to where a new tab opens (:meth:`AppPage.reset`), on the first
scene (``tab``) or on the rod collision (``collision``).
"""

from __future__ import annotations

import re
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from rigidrel_app.live.controls import LOG_SLIDER_LABEL
from rigidrel_app.live.playback import FRAME_RATE, PLAY_SECONDS
from rigidrel_app.view.pointer import BETA_PER_WIDTH
from rigidrel_app.view.state import CUSTOM_FRAME, NO_PRESET, Settings, event_times, preset_menu
from rigidrel_app.view.vocabulary import ROD_COLORS
from tests.browser.test_app_browser import AppPage
from tests.viser_client import shown, wait_until

pytestmark = pytest.mark.browser

FIG3, FIG4 = preset_menu(Settings("rod-collision")).options[1:3]


@pytest.fixture
def tab(shared_tab: AppPage) -> AppPage:
    """The file's one tab, back where a new tab opens (the first scene's defaults)."""
    shared_tab.reset()
    return shared_tab


@pytest.fixture
def collision(shared_tab: AppPage) -> AppPage:
    """The file's one tab, back where a new tab opens, on the rod collision (the paper's Fig. 3)."""
    shared_tab.reset(Settings("rod-collision"))
    return shared_tab


# ---------------------------------------------------------------- finding things as a user does
def row(tab: AppPage, label: str) -> Any:
    """The control row whose label reads ``label``."""
    name = tab.page.locator("label").filter(has_text=re.compile(f"^{re.escape(label)}$"))
    return name.locator("xpath=ancestor::div[contains(@class, 'mantine-Flex-root')][1]")


def box(tab: AppPage, label: str) -> Any:
    """The box a person types into: a text box, or a slider's own number box."""
    return row(tab, label).locator("input.mantine-TextInput-input, input.mantine-NumberInput-input").first


def press(tab: AppPage, key: str) -> None:
    """A key with nothing focused (keys typed into a box are the box's)."""
    tab.page.evaluate("() => document.activeElement && document.activeElement.blur()")
    tab.page.keyboard.press(key)


def type_keys(tab: AppPage, label: str, text: str) -> None:
    """Select what the box holds and type ``text`` key by key, as a person does."""
    b = box(tab, label)
    b.click()
    b.press("Control+a")
    b.press_sequentially(text, delay=40)


def notice(tab: AppPage) -> str:
    shown = tab.page.locator("p", has_text=re.compile("^⚠")).all_inner_texts()
    return " ".join(shown)


# ---------------------------------------------------------------- keys
def test_space_plays_and_pauses_and_the_clock_readout_follows(tab: AppPage, shots: Path) -> None:
    clock = box(tab, "t, t'")
    start = clock.input_value()
    press(tab, " ")
    wait_until(lambda: tab.session.state.playback.playing)
    wait_until(lambda: clock.input_value() != start)  # the time readout runs
    press(tab, " ")
    wait_until(lambda: tab.session.playing.settled)  # paused where the browser's frame was
    stopped = tab.session.state.playback.now
    # paused: the readout shows the clock the rods stopped at, and stays there
    wait_until(lambda: float(clock.input_value()) == pytest.approx(stopped, abs=1e-6))
    tab.page.screenshot(path=str(shots / "paused_by_space.png"))
    assert tab.session.state.playback.now == stopped and not tab.session.state.playback.playing


def test_arrows_step_one_frame(tab: AppPage) -> None:
    p = tab.session.state.playback
    frame = (p.window[1] - p.window[0]) * p.speed / (PLAY_SECONDS * FRAME_RATE)
    clock = box(tab, "t, t'")
    press(tab, "ArrowRight")
    wait_until(lambda: tab.session.state.playback.now == pytest.approx(p.now + frame, abs=1e-12))
    wait_until(lambda: float(clock.input_value()) == pytest.approx(round(p.now + frame, 6), abs=1e-6))
    press(tab, "ArrowLeft")
    press(tab, "ArrowLeft")
    wait_until(lambda: tab.session.state.playback.now == pytest.approx(p.now - frame, abs=1e-12))
    assert not tab.session.state.playback.playing


def test_a_drag_a_wheel_and_ten_arrows_leave_the_picture_upright(tab: AppPage, shots: Path) -> None:
    """The mouse and the arrows do not move the camera: a drag across the canvas, the wheel, and ten
    presses of ← after a click on the canvas leave the camera where the server put it, and the ten
    presses step exactly ten frames back."""
    camera = tab.session.client.camera
    pose = (camera.position.copy(), camera.look_at.copy(), camera.up_direction.copy())
    assert tab.page.evaluate("() => window.__rigidrelPlayback.cameraLocked()")
    before = tab.canvas()
    box_ = tab.page.locator("canvas[data-engine]").bounding_box()
    x, y = box_["x"] + 0.5 * box_["width"], box_["y"] + 0.3 * box_["height"]
    tab.page.mouse.move(x, y)
    tab.page.mouse.down()
    tab.page.mouse.move(x + 300, y + 150, steps=12)
    tab.page.mouse.up()
    tab.page.mouse.wheel(0, -800)
    tab.page.mouse.click(x, y)  # a click on the canvas (no drag): the keys are the page's
    p = tab.session.state.playback
    expected = p
    for _ in range(10):
        expected = expected.stepped(-1)
    for _ in range(10):
        tab.page.keyboard.press("ArrowLeft")
    wait_until(lambda: tab.session.state.playback.now == pytest.approx(expected.now, abs=1e-12))
    tab.canvas_after(before)
    tab.page.screenshot(path=str(shots / "after_drag_wheel_arrows.png"))
    # the browser reports its camera as it is: where the server put it
    wait_until(lambda: np.allclose(camera.position, pose[0]) and np.allclose(camera.look_at, pose[1]))
    assert np.allclose(camera.up_direction, pose[2])
    assert tab.page.evaluate("() => window.__rigidrelPlayback.cameraLocked()")


def test_the_mouse_scrubs_the_clock_chooses_a_cone_and_drags_beta(collision: AppPage, shots: Path) -> None:
    """On Fig. 3 with a real mouse: a click on the lab's diagram puts the clock at the time under it
    and a drag down it follows; a click on an event's dot draws that event's light cone; a drag
    across the barycentric frame's diagram, away from its now-line, sets a custom β by the share
    of the plot's width dragged. The camera never moves."""
    tab = collision
    s = tab.session
    canvas = tab.page.locator("canvas[data-engine]").bounding_box()
    assert canvas is not None
    # the page laid out for the canvas as it is (a tab's first layout is for the size first reported)
    wait_until(
        lambda: (
            s.painter.layout is not None
            and abs(s.painter.layout.width - canvas["width"]) < 1
            and abs(s.painter.layout.height - canvas["height"]) < 1
        )
    )
    camera = s.client.camera  # as the browser reports it, once it looks at that page's centre
    wait_until(lambda: abs(camera.position[0] - 0.5 * canvas["width"]) < 1)
    pose = camera.position.copy()

    def mouse_at(px: float, pz: float) -> tuple[float, float]:  # a page point (z up) under the mouse
        col, row = tab.page_to_pixel(px, pz)
        return canvas["x"] + col, canvas["y"] + row

    lab, chosen = (shown(f) for f in s.painter.chart_frames[:2])
    w = s.state.playback.window
    per_px = (lab.y_range[1] - lab.y_range[0]) / lab.plot.height  # the time one pixel of the diagram spans
    left = lab.x_range[0] + 0.03 * (lab.x_range[1] - lab.x_range[0])  # no event this far left
    t1, t2 = w[0] + 0.3 * (w[1] - w[0]), w[0] + 0.7 * (w[1] - w[0])
    tab.page.mouse.click(*mouse_at(*lab.px_one(left, t1)))
    wait_until(lambda: abs(s.state.playback.now - t1) <= per_px)
    tab.page.mouse.move(*mouse_at(*lab.px_one(left, t1)))
    tab.page.mouse.down()
    tab.page.mouse.move(*mouse_at(*lab.px_one(left, t2)), steps=8)
    tab.page.mouse.up()
    wait_until(lambda: abs(s.state.playback.now - t2) <= per_px)
    assert not s.state.playback.playing
    # an event with no other within reach of its dot
    drawn = s.painter.drawn
    assert drawn is not None
    events = drawn.resolved.scene.events_in()
    dots = {name: lab.px_one(x, t) for name, (t, x) in events.items()}
    alone = [
        n for n, (a, b) in dots.items() if all(np.hypot(a - c, b - d) > 30 for m, (c, d) in dots.items() if m != n)
    ]
    tab.page.mouse.click(*mouse_at(*dots[alone[0]]))
    wait_until(lambda: s.painter.drawn is not None and s.painter.drawn.resolved.cone == alone[0])
    # β: a drag of a fifth of the plot's width, along a line far from the now-line
    beta = s.state.settings.beta if s.state.settings.frame == CUSTOM_FRAME else drawn.resolved.frame.beta
    now_z = chosen.px_one(0.0, s.state.playback.now)[1]
    z = chosen.plot.z0 + 0.1 * chosen.plot.height if now_z > chosen.plot.z0 + 0.5 * chosen.plot.height else (
        chosen.plot.z1 - 0.1 * chosen.plot.height)  # fmt: skip
    x0 = chosen.plot.x0 + 0.05 * chosen.plot.width
    tab.page.mouse.move(*mouse_at(x0, z))
    tab.page.mouse.down()
    tab.page.mouse.move(*mouse_at(x0 + 0.2 * chosen.plot.width, z), steps=10)
    tab.page.mouse.up()
    expected = beta + 0.2 * BETA_PER_WIDTH
    wait_until(lambda: s.state.settings.frame == CUSTOM_FRAME and abs(s.state.settings.beta - expected) < 0.01)
    wait_until(lambda: s.painter.drawn is not None and abs(s.painter.drawn.resolved.frame.beta - expected) < 0.01)
    drawn = s.painter.drawn
    assert drawn is not None
    beta_shown = f"custom (β = {drawn.resolved.frame.beta:.4g}) frame"  # as the lane's title has it
    wait_until(lambda: (tab.nodes("/page/title/1")[0] or {}).get("props", {}).get("text", "").startswith(beta_shown))
    tab.page.screenshot(path=str(shots / "after_mouse.png"))
    assert np.allclose(camera.position, pose)


def test_n_and_p_jump_to_the_named_events(collision: AppPage) -> None:
    """N: the clock at the next named event's time (lab t or frame t′), the readout with it; P back."""
    tab = collision
    drawn = tab.session.painter.drawn
    assert drawn is not None
    p = tab.session.state.playback
    ahead = [t for t in event_times(drawn.resolved) if p.now + 1e-9 < t <= p.window[1]]
    press(tab, "n")
    wait_until(lambda: tab.session.state.playback.now == ahead[0])
    wait_until(lambda: float(box(tab, "t, t'").input_value()) == pytest.approx(round(ahead[0], 6), abs=1e-6))
    press(tab, "n")
    wait_until(lambda: tab.session.state.playback.now == ahead[1])
    press(tab, "p")
    wait_until(lambda: tab.session.state.playback.now == ahead[0])
    assert not tab.session.state.playback.playing


def test_enter_and_escape_give_the_keys_back_to_the_page(collision: AppPage) -> None:
    """A value typed and Enter: applied, and the box lets go, so the clicker's PageDown moves on;
    Escape does the same."""
    tab = collision
    wait_until(lambda: tab.control("Paper figure").input_value() == FIG3)
    type_keys(tab, "V1", "0.7")
    tab.page.keyboard.press("Enter")
    wait_until(lambda: tab.session.state.settings.value("v1") == 0.7)
    wait_until(lambda: tab.page.evaluate("() => document.activeElement === document.body"))
    tab.page.keyboard.press("PageDown")  # nothing focused: the clicker's "next" is the page's
    wait_until(lambda: tab.control("Paper figure").input_value() == FIG3)  # from no figure, the first
    type_keys(tab, "V1", "0.65")
    tab.page.keyboard.press("Escape")
    wait_until(lambda: tab.page.evaluate("() => document.activeElement === document.body"))
    now = tab.session.state.playback.now
    tab.page.keyboard.press("ArrowRight")  # the arrows step the clock again
    wait_until(lambda: tab.session.state.playback.now > now)


def test_the_canvas_is_described_in_a_polite_live_region(collision: AppPage) -> None:
    """A screen reader hears the scene and its frames when they change (not every frame), and
    everything at the clock on key D, in a polite live region nobody sees."""
    tab = collision
    region = tab.page.locator("#rigidrel-said")
    assert region.get_attribute("aria-live") == "polite" and region.get_attribute("role") == "status"
    wait_until(lambda: region.text_content().startswith("Rod-rod collision"))
    assert not region.is_visible() or region.bounding_box()["width"] <= 1  # type: ignore[index]
    tab.choose("Frame", "lab")
    wait_until(lambda: "One lane: the lab frame" in region.text_content())  # the lab once
    said = region.text_content()
    press(tab, " ")  # playing: the words stay (no announcement per frame)
    wait_until(lambda: tab.session.player.playing)
    clock = tab.session.state.playback.now
    wait_until(lambda: tab.session.state.playback.now > clock + 0.2)
    assert region.text_content() == said
    press(tab, " ")
    wait_until(lambda: tab.session.playing.settled)
    press(tab, "d")
    wait_until(lambda: "The lab lane at t = " in region.text_content() and "Causality:" in region.text_content())


def test_arrows_on_a_focused_slider_move_only_that_slider(tab: AppPage) -> None:
    """A slider keeps the focus after a drag: then → moves that slider, and does not also step
    playback; the clicker's PageDown still goes to the next figure."""
    tab.slider("V").locator("[role=slider]").focus()
    now = tab.session.state.playback.now
    tab.page.keyboard.press("ArrowRight")
    wait_until(lambda: tab.session.state.settings.value("v") == pytest.approx(0.61))
    tab.page.keyboard.press("PageDown")  # the scene's first figure (Fig. 1): V back to 0.6
    wait_until(lambda: tab.session.state.settings.overlay and tab.session.state.settings.value("v") == 0.6)
    assert tab.session.state.playback.now == now  # no frame was stepped
    press(tab, "ArrowRight")  # with nothing focused, → steps
    wait_until(lambda: tab.session.state.playback.now > now)


def test_page_down_and_up_walk_the_scenes_figures(collision: AppPage, shots: Path) -> None:
    tab = collision
    wait_until(lambda: tab.control("Paper figure").input_value() == FIG3)
    press(tab, "PageDown")  # a clicker's "next"
    wait_until(lambda: tab.control("Paper figure").input_value() == FIG4)
    assert tab.session.state.settings.value("mass2") == 0.5
    wait_until(lambda: box(tab, "M2/M1").input_value() == "0.5")  # the ratio, not its log
    tab.page.screenshot(path=str(shots / "fig4_by_page_down.png"))
    press(tab, "PageDown")  # past the last figure: nothing happens
    press(tab, "PageUp")
    wait_until(lambda: tab.control("Paper figure").input_value() == FIG3)
    wait_until(lambda: box(tab, "M2/M1").input_value() == "2")
    assert tab.session.state.settings.value("mass2") == 2.0


def rod_bounds(img: np.ndarray, lanes: bool = False) -> np.ndarray:
    """Top, bottom, left and right pixel of the rods' colour: where the view puts them. ``lanes``:
    only in the canvas' top quarter (the diagrams below draw that colour around labels too)."""
    rgb = np.array([int(ROD_COLORS[0][i : i + 2], 16) for i in (1, 3, 5)], dtype=float)
    if lanes:
        img = img[: img.shape[0] // 4]
    rows, cols = np.nonzero(np.abs(img - rgb).sum(axis=-1) < 60)
    assert rows.size, "no rod on the canvas"
    return np.array([rows.min(), rows.max(), cols.min(), cols.max()])


def test_the_view_stays_under_a_drag_and_r_and_the_button_keep_it(
    tab: AppPage, shots: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """A drag across the canvas no longer orbits the picture (the camera is locked); R and the
    Reset view button still put the camera where the page fits, and the picture stays the same."""
    wait_until(lambda: tab.session.painter.drawn is not None)
    home = tab.canvas_after(np.zeros_like(tab.canvas()))  # the default view, settled
    canvas = tab.page.locator("canvas[data-engine]")
    b = canvas.bounding_box()
    assert b is not None
    x, y = b["x"] + 0.5 * b["width"], b["y"] + 0.8 * b["height"]
    painter = tab.session.painter
    fit, resets = painter.fit_camera, []

    def fit_and_count(force: bool = False) -> None:
        resets.append(force)
        fit(force)

    monkeypatch.setattr(painter, "fit_camera", fit_and_count)  # the shared tab's own is back after the test
    for reset in ("key", "button"):
        tab.page.mouse.move(x, y)
        tab.page.mouse.down()
        tab.page.mouse.move(x + 240, y - 120, steps=8)  # as a lecturer's orbit did
        tab.page.mouse.up()
        if reset == "key":
            press(tab, "r")
        else:
            tab.page.locator("button:visible", has_text="Reset view").click()
        wait_until(lambda reset=reset: resets == [True] * (1 if reset == "key" else 2))  # the pose was sent
        after = tab.canvas()
        off = np.abs(rod_bounds(after, True) - rod_bounds(home, True)).max()
        assert off <= 1, (reset, off)  # the rods where they were: the drag moved nothing
    tab.page.screenshot(path=str(shots / "view_kept.png"))


def test_keys_typed_into_a_box_stay_in_the_box(collision: AppPage) -> None:
    tab = collision
    type_keys(tab, "M2/M1", "r 2")  # a space and an r, typed: neither plays nor resets anything
    wait_until(lambda: "M2/M1 = 'r 2' refused" in tab.session.state.notice.text)
    assert not tab.session.state.playback.playing
    assert box(tab, "M2/M1").input_value() == "r 2"


# ---------------------------------------------------------------- typed values and notices
def test_the_mass_ratio_is_typed_and_shown_as_a_ratio(collision: AppPage, shots: Path) -> None:
    tab = collision
    uid = row(tab, LOG_SLIDER_LABEL).locator("label").get_attribute("for")
    thumb = tab.page.locator(f"[id='{uid}'] [role=slider]")

    def thumb_at(position: float) -> bool:  # within half a step of the slider
        return abs(float(thumb.get_attribute("aria-valuenow") or "nan") - position) < 0.005

    assert box(tab, "M2/M1").input_value() == "2" and thumb_at(np.log10(2.0))
    assert tab.page.locator(f"[id='{uid}'] + .mantine-NumberInput-root").count() == 1
    assert not tab.page.locator(f"[id='{uid}'] + .mantine-NumberInput-root").is_visible()  # no box of log10
    for typed, ratio in (("0.01", 0.01), ("100", 100.0), ("0.5", 0.5)):
        type_keys(tab, "M2/M1", typed)
        wait_until(lambda ratio=ratio: tab.session.painter.drawn.resolved.scene.parameters["mass2"] == ratio)  # type: ignore[union-attr]
        wait_until(lambda ratio=ratio: thumb_at(np.log10(ratio)))
        assert box(tab, "M2/M1").input_value() == typed
        wait_until(lambda: notice(tab) == "")  # "0" and "0.0" were refused on the way to 0.01; 0.01 is not
        tab.page.screenshot(path=str(shots / f"m2_{typed}.png"))


def test_abc_gives_a_notice_and_a_valid_value_clears_it(collision: AppPage, shots: Path) -> None:
    tab = collision
    type_keys(tab, "V2", "0.9")  # faster than V1: an older notice, about something else
    wait_until(lambda: "so that the rods collide" in notice(tab))
    type_keys(tab, "M2/M1", "abc")
    wait_until(lambda: "M2/M1 = 'abc' refused" in notice(tab))
    assert "[0.01, 100]" in notice(tab) and "rods collide" not in notice(tab)  # the older notice is gone
    tab.page.screenshot(path=str(shots / "abc_refused.png"))
    type_keys(tab, "M2/M1", "3")
    wait_until(lambda: tab.session.state.settings.value("mass2") == 3.0)
    # V2 = 0.9 is still asked for, so the scene still refuses it: its notice is back, not the abc one
    wait_until(lambda: "so that the rods collide" in notice(tab))
    type_keys(tab, "V2", "0")
    # the scene drawn before V2 = 0.9 had V2 = 0 too: wait for the new one, which keeps M2/M1 = 3
    wait_until(lambda: tab.session.painter.drawn.resolved.scene.parameters["mass2"] == 3.0)  # type: ignore[union-attr]
    assert tab.session.painter.drawn.resolved.scene.parameters["v2"] == 0.0  # type: ignore[union-attr]
    wait_until(lambda: notice(tab) == "")


def test_beta_beyond_its_slider_is_refused_not_clamped(tab: AppPage, shots: Path) -> None:
    type_keys(tab, "β (custom)", "0.999")
    wait_until(lambda: "β (custom) = 0.999 refused" in notice(tab))
    assert "[-0.99, 0.99]" in notice(tab)
    tab.page.keyboard.press("Tab")  # leaving the box changes nothing: no clamp to 0.99
    assert box(tab, "β (custom)").input_value() == "0.999"
    assert "β (custom) = 0.999 refused" in notice(tab)  # still explained, not silently taken as 0.99
    # the notice is where the lecturer is looking: in the Frame folder, under β, above Playback
    shown = tab.page.locator("p", has_text=re.compile("^⚠")).bounding_box()
    beta = row(tab, "β (custom)").bounding_box()
    playback = tab.page.locator("text=Playback").first.bounding_box()
    assert shown is not None and beta is not None and playback is not None
    assert beta["y"] < shown["y"] < playback["y"]
    tab.page.screenshot(path=str(shots / "beta_0.999_refused.png"))


def test_typing_key_by_key_gives_the_typed_value(tab: AppPage) -> None:
    """0 is out of V's range [0.01, 0.99]: typing 0.5 must still give 0.5 (a refused keystroke that is
    put back under the typist's fingers turns it into 0.65 or the like), and 1.2 a notice."""
    type_keys(tab, "V", "0.5")
    wait_until(lambda: tab.session.state.settings.value("v") == 0.5)
    tab.page.keyboard.press("Tab")
    wait_until(lambda: notice(tab) == "")
    assert box(tab, "V").input_value() == "0.5"
    type_keys(tab, "V", "1.2")
    wait_until(lambda: "V = 1.2 refused" in notice(tab) and "[0.01, 0.99]" in notice(tab))
    tab.page.keyboard.press("Tab")  # the refused text stays to be corrected, beside its notice
    assert box(tab, "V").input_value() == "1.2" and "V = 1.2 refused" in notice(tab)
    assert tab.session.state.settings.value("v") == 0.5
    assert tab.slider("V").locator("[role=slider]").get_attribute("aria-valuenow") == "0.5"  # no jump to the end


def test_typed_text_is_read_as_typed_and_refused_with_a_notice(tab: AppPage) -> None:
    """What the box holds is what the server reads: a minus is not dropped, ``1e5`` is not 15,
    and text that is no number is refused in words, each replacing the notice before it."""
    for typed, said in (("-0.5", "V = -0.5 refused"), ("1e5", "V = 1e5 refused"), ("abc", "V = 'abc' refused")):
        type_keys(tab, "V", typed)
        wait_until(lambda said=said: said in notice(tab))
        assert "[0.01, 0.99]" in notice(tab) and notice(tab).count("⚠") == 1
        assert box(tab, "V").input_value() == typed and tab.session.state.settings.value("v") == 0.6
    type_keys(tab, "V", "0.75")
    wait_until(lambda: tab.session.state.settings.value("v") == 0.75 and notice(tab) == "")


def test_the_figure_menu_follows_the_scene(collision: AppPage, shots: Path) -> None:
    tab = collision
    wait_until(lambda: tab.control("Paper figure").input_value() == FIG3)
    tab.choose("Scene", "Constant acceleration")
    wait_until(lambda: tab.session.state.settings.scene == "constant-acceleration")
    wait_until(lambda: tab.control("Paper figure").input_value() == NO_PRESET)
    tab.control("Paper figure").click()
    options = tab.page.locator("[role=option]:visible").all_inner_texts()
    tab.page.keyboard.press("Escape")
    assert options == list(preset_menu(Settings("constant-acceleration")).options)
    assert not any(o.startswith("Fig. 3") for o in options)
    tab.page.screenshot(path=str(shots / "menu_after_scene_change.png"))
