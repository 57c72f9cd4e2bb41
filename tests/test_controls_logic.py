"""The pure rules behind the app's controls (no server, no browser): number boxes and log sliders,
the notices of refused values, the paper-figure menu per scene, the keys, one frame's step.

Scenes and parameters come from the core's registry: a scene or a log-scale parameter
registered there is covered with no edit here.
"""

from __future__ import annotations

import itertools
import math
import typing

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st
from viser._messages import HotkeyKey

import rigidrel_core as rr
from rigidrel_app.live.controls import BETA, LOG_SLIDER_LABEL, SPEED, notice_place
from rigidrel_app.live.keys import HOTKEYS, LESSON_HOTKEYS, RESERVED, Action, action_for, key_line
from rigidrel_app.live.playback import FRAME_RATE, PLAY_SECONDS, Playback
from rigidrel_app.view.entry import NumberEntry, Refuse, Typing, Use, read_number, refusal
from rigidrel_app.view.state import (
    CUSTOM_FRAME,
    NO_PRESET,
    Resolved,
    Settings,
    event_times,
    preset_menu,
    preset_step,
    resolve,
)

#: Every parameter the app sets with a slider, from the registry.
SLIDER_PARAMETERS = list(
    {p.name: p for d in rr.scene_descriptions().values() for p in d.parameters if p.slider is not None}.values()
)
LOG_PARAMETERS = [p for p in SLIDER_PARAMETERS if p.slider is not None and p.slider.scale == "log"]
#: A log-scale parameter no scene has: the rules are the slider's, not the mass ratio's.
OTHER_LOG = NumberEntry("k", 1e-3, 1e3, 0.01, "log")


def param_id(p: rr.Parameter) -> str:
    return p.name


# ---------------------------------------------------------------- log sliders show the number
def test_the_mass_ratio_is_a_log_slider_whose_box_takes_the_ratio() -> None:
    m2 = rr.describe("rod-collision").parameter("mass2")
    assert m2 in LOG_PARAMETERS  # the registry says so; nothing below names m2
    e = NumberEntry.of(m2)
    assert e.is_log and e.slider_range == (-2.0, 2.0)
    for typed, value in (("2", 2.0), ("0.01", 0.01), ("100", 100.0), ("0.5", 0.5), ("1e2", 100.0), ("1/3", 1 / 3)):
        assert e.read(typed) == Use(value), typed
    assert [e.text(v) for v in (2.0, 0.01, 100.0, 0.5)] == ["2", "0.01", "100", "0.5"]
    assert e.to_slider(2.0) == math.log10(2.0) and e.from_slider(math.log10(2.0)) == 2.0
    assert e.slider_marks() == ((-2.0, "0.01"), (-1.0, "0.1"), (0.0, "1"), (1.0, "10"), (2.0, "100"))


@pytest.mark.parametrize("entry", [*(NumberEntry.of(p) for p in LOG_PARAMETERS), OTHER_LOG], ids=lambda e: e.label)
def test_log_slider_positions_map_to_round_values_in_range_and_back(entry: NumberEntry) -> None:
    lo, hi = entry.slider_range
    positions = np.arange(lo, hi + 0.5 * entry.step, entry.step)
    values = [entry.from_slider(float(k)) for k in positions]
    assert values[0] == entry.lo and values[-1] == entry.hi
    assert all(entry.lo <= v <= entry.hi for v in values)
    assert all(b > a for a, b in itertools.pairwise(values))  # every step moves the value
    assert all(len(f"{v:.6g}".replace(".", "").lstrip("0")) <= 4 for v in values)  # 2, 1.02, 97.7: not 1.99526
    for v, k in zip(values, positions, strict=True):  # the slider stays put when the server shows its own value
        assert entry.shows(float(k), v)
    for v in (entry.lo, 1.0, 2.0, entry.hi):  # a typed value puts the slider where it belongs
        assert entry.to_slider(v) == pytest.approx(math.log10(v)) and entry.shows(entry.to_slider(v), v)


@pytest.mark.parametrize("parameter", [p for p in SLIDER_PARAMETERS if p not in LOG_PARAMETERS], ids=param_id)
def test_linear_sliders_hold_the_value_itself(parameter: rr.Parameter) -> None:
    e = NumberEntry.of(parameter)
    assert not e.is_log and e.slider_marks() is None  # viser's own marks: the two ends
    assert e.slider_range == (e.lo, e.hi) and e.to_slider(0.37) == 0.37 == e.from_slider(0.37)


# ---------------------------------------------------------------- notices
@pytest.mark.parametrize("parameter", SLIDER_PARAMETERS, ids=param_id)
def test_every_refused_value_names_the_control_and_its_range(parameter: rr.Parameter) -> None:
    e = NumberEntry.of(parameter)
    assert parameter.slider is not None
    span = f"[{parameter.slider.lo:g}, {parameter.slider.hi:g}]"
    beyond = repr(parameter.slider.hi * 10 + 1)
    for typed in ("abc", beyond, "1,5", "1e999", "1/0"):
        verdict = e.read(typed)
        assert isinstance(verdict, Refuse), typed
        assert verdict.notice.startswith(f"{parameter.label} = ") and span in verdict.notice, verdict.notice
        assert not verdict.put_back  # typed text stays on screen: never put back under the typist's fingers
    for typed in ("", " ", "-", "+", ".", "1e", "1e-", "2/", "−"):  # on its way to a number: no notice yet
        assert e.read(typed) == Typing(), typed


def test_notice_texts() -> None:
    assert BETA.read("0.999") == Refuse(
        "β (custom) = 0.999 refused: it must be a number in [-0.99, 0.99]. The last valid scene stays on screen.",
        put_back=False,
    )
    abc = OTHER_LOG.read(" abc ")
    assert isinstance(abc, Refuse) and abc.notice.startswith("k = 'abc' refused: not a number; it must be")
    comma = SPEED.read("0,5")
    assert isinstance(comma, Refuse) and "decimal point" in comma.notice
    assert refusal("Scene", "'Warp'", "one of the listed scenes").startswith("Scene = 'Warp' refused: it must be")


def test_read_number_takes_what_a_lecturer_types() -> None:
    assert read_number("0.5") == 0.5 and read_number(" −0.25 ") == -0.25 and read_number("+.5") == 0.5
    assert read_number("2e-2") == 0.02 and read_number("1 / 4") == 0.25 and read_number("-1/-4") == 0.25
    assert read_number("") == Typing() and read_number("1e+") == Typing()
    for text in ("abc", "nan", "inf", "0x10", "1.2.3", "½", "1/2/3"):
        assert isinstance(read_number(text), str), text


@given(st.text(max_size=12))
def test_reading_any_text_never_raises(text: str) -> None:
    for e in (BETA, SPEED, OTHER_LOG):
        verdict = e.read(text)
        assert isinstance(verdict, (Use, Typing, Refuse))
        if isinstance(verdict, Use):
            assert e.lo <= verdict.value <= e.hi


def test_a_slider_beyond_its_ends_is_refused_and_put_back() -> None:
    """Nobody types into a slider (its own number box is hidden; the control's text box takes typed
    numbers): a position beyond its ends, or no number, comes from no person and is put back."""
    assert BETA.judge_position(0.99) == Use(0.99)  # the end itself, dragged
    assert BETA.judge_position(0.5) == Use(0.5)
    for hostile in (0.999, -3.0, math.nan, math.inf, "x", None, True):
        verdict = BETA.judge_position(hostile)
        assert isinstance(verdict, Refuse) and verdict.put_back, hostile
    verdict = OTHER_LOG.judge_position(5.0)  # beyond a log slider's ends: named as the power of ten
    assert isinstance(verdict, Refuse) and verdict.put_back and "10^5" in verdict.notice
    assert OTHER_LOG.judge_position(math.log10(20.0)) == Use(20.0)


def test_a_scenes_refusal_shows_where_the_change_was_made() -> None:
    """The notice of a value the scene refuses shows in the folder of the control that asked for it."""
    s = Settings("rod-collision")
    assert notice_place(s, s.with_value("v2", 0.9)) == "scene"
    assert notice_place(s, Settings("rod-collision", s.values, CUSTOM_FRAME, 0.5)) == "frame"
    assert notice_place(s, Settings("rod-collision", s.values, "rod 1 after")) == "frame"
    framed = Settings("rod-collision", s.values, "rod 1 after")
    assert notice_place(framed, framed.with_scene("wall-collision")) == "scene"  # a new scene resets the frame


def test_the_log_slider_label_is_not_a_parameter_label() -> None:
    assert LOG_SLIDER_LABEL not in {p.label for p in SLIDER_PARAMETERS}


# ---------------------------------------------------------------- the paper-figure menu
@pytest.mark.parametrize("kind", list(rr.scene_descriptions()))
def test_the_figure_menu_lists_this_scenes_figures_only(kind: str) -> None:
    d = rr.describe(kind)
    labels = [p.label for p in d.presets]
    menu = preset_menu(Settings(kind))
    assert menu.options == (NO_PRESET, *labels)
    assert menu.value in menu.options
    for label in labels:
        figure = next(p for p in d.presets if p.label == label)
        shown = preset_menu(Settings(kind, tuple(figure.values.items()), figure.frame, 0.0, figure.overlay))
        assert shown.value == label


def test_the_figure_menu_follows_a_scene_change() -> None:
    fig3 = Settings.of("rod-collision", mass2=2.0)
    assert preset_menu(fig3).value.startswith("Fig. 3")
    for kind in rr.scene_descriptions():
        if kind != "rod-collision":
            menu = preset_menu(fig3.with_scene(kind))
            assert not any(o.startswith("Fig. 3") for o in menu.options) and not menu.value.startswith("Fig. 3")
    moved = preset_menu(fig3.with_value("mass2", 3.0))
    assert moved.value == NO_PRESET and any(o.startswith("Fig. 3") for o in moved.options)


def test_page_up_and_down_walk_this_scenes_figures() -> None:
    fig3, fig4 = (preset_menu(Settings("rod-collision")).options[k] for k in (1, 2))
    at3 = Settings.of("rod-collision", mass2=2.0)
    assert preset_menu(at3).value == fig3
    nxt = preset_step(at3, 1)
    assert nxt is not None and preset_menu(nxt).value == fig4 and nxt.value("mass2") == 0.5
    assert preset_step(nxt, 1) is None  # the last figure: a clicker's extra press does nothing
    back = preset_step(nxt, -1)
    assert back is not None and preset_menu(back).value == fig3 and preset_step(back, -1) is None
    off = at3.with_value("mass2", 3.0)  # no figure: forward is the first, back the last
    first, last = preset_step(off, 1), preset_step(off, -1)
    assert first is not None and last is not None
    assert (preset_menu(first).value, preset_menu(last).value) == (fig3, fig4)
    bare = next(k for k, d in rr.scene_descriptions().items() if not d.presets)
    assert preset_step(Settings(bare), 1) is None and preset_step(Settings(bare), -1) is None


# ---------------------------------------------------------------- keys and clicker
def test_each_action_has_one_key_viser_knows() -> None:
    viser_keys = set(typing.get_args(HotkeyKey))
    keys = [h.key for h in HOTKEYS]
    assert len(set(keys)) == len(keys) and set(keys) <= viser_keys
    assert sorted({h.action.value for h in HOTKEYS + LESSON_HOTKEYS}) == sorted(a.value for a in Action)
    assert {k: action_for(k) for k in keys} == {
        "space": Action.TOGGLE_PLAY,
        "arrowleft": Action.STEP_BACK,
        "arrowright": Action.STEP_FORWARD,
        "P": Action.PREVIOUS_EVENT,
        "N": Action.NEXT_EVENT,
        "pageup": Action.PREVIOUS_FIGURE,  # a presentation clicker's "back"
        "pagedown": Action.NEXT_FIGURE,  # and "next"
        "R": Action.RESET_VIEW,
        "F": Action.TOGGLE_PRESENTER,
        "T": Action.TOGGLE_THEME,
        "D": Action.DESCRIBE,
        "Z": Action.TOGGLE_ZOOM,
    }
    assert action_for("Q") is None
    assert not set(RESERVED) & set(keys) and set(RESERVED) <= viser_keys


def test_n_and_p_walk_the_named_events_of_the_lab_and_the_frame() -> None:
    """N and P jump between the named events' times on the playback clock (lab t and the frame's
    t′), each pressed again moving on, and stay put past the last or the first."""
    resolved = resolve(Settings("rod-collision"))
    assert isinstance(resolved, Resolved)
    times = event_times(resolved)
    lab = {t for t, _ in resolved.scene.events.values()}
    framed = {t for t, _ in resolved.scene.events_in(frame=resolved.frame).values()}
    assert set(times) == lab | framed and list(times) == sorted(set(times))
    window = (min(times) - 0.5, max(times) + 0.5)
    p = Playback(window, window[0])
    seen = []
    for _ in range(len(times) + 2):  # past the last: it stays there, paused
        p = p.to_event(times, 1)
        seen.append(p.now)
    assert seen == [*times, times[-1], times[-1]] and not p.playing
    for t in reversed(times[:-1]):
        p = p.to_event(times, -1)
        assert p.now == t
    assert p.to_event(times, -1).now == times[0]
    inside = Playback((times[1], times[-2]), times[1])  # times outside the window are skipped
    assert inside.to_event(times, -1).now == times[1] and inside.to_event(times, 1).now == times[2]


def test_the_key_line_lists_every_key() -> None:
    line = key_line()
    assert line.startswith("Keys: ") and all(h.shown in line for h in HOTKEYS)
    assert "← → step" in line and "PgUp PgDn figure" in line


def test_an_arrow_key_steps_one_frame_and_pauses() -> None:
    p = Playback.start((-1.0, 3.0)).toggled()
    frame = (3.0 - -1.0) / (PLAY_SECONDS * FRAME_RATE)
    forward = p.stepped(1)
    assert not forward.playing and forward.now == pytest.approx(p.now + frame, rel=1e-12)
    assert forward.stepped(-1).now == pytest.approx(p.now, abs=1e-15)
    fast = Playback((-1.0, 3.0), 0.0, speed=2.0)
    assert fast.stepped(1).now == pytest.approx(2 * frame)  # one frame of playing at that speed
    assert Playback((-1.0, 3.0), 3.0).stepped(1).now == 3.0  # held at the window's ends
    assert Playback((-1.0, 3.0), -1.0).stepped(-5).now == -1.0
