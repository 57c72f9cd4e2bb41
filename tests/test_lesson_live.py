"""A lesson given live, the logic without a browser: arriving at a step, locks, the lesson's keys,
the scenario box's notices and ``rigidrel serve --lesson`` refusing a bad lesson before it serves."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

from rigidrel_app.lessons import parse_lesson
from rigidrel_app.lessons.tour import (
    arrival,
    caption_html,
    clamp_step,
    lock_reason,
    locked_changes,
    step_labels,
)
from rigidrel_app.live.controls import caption_message, scenario_html
from rigidrel_app.live.keys import LESSON_HOTKEYS, Action, action_for, key_line
from rigidrel_app.live.tab_state import scenario_problem
from rigidrel_app.view.layers import Layer
from rigidrel_app.view.scenario import ScenarioError, parse_scenario

LESSON = parse_lesson(
    """title = "Two"

[[step]]
title = "Crash"
scene = "wall-collision --v 0.6 --eps 0 --frame lab --layers world-tube"
caption = "Braking at t = {event[T_1].t:.3g}; **before** contact."
window = [-1.5, 2.5]
start = -1.0
autoplay = true
lock = ["v", "frame"]

[[step]]
title = "Bounce"
scene = "wall-collision --v 0.6 --eps 1"
layers = ["signals", "light-cone"]
caption = "Free."
""",
    "two.toml",
)


def test_arrival_sets_what_the_step_asks() -> None:
    a = arrival(LESSON.steps[0])
    assert a.settings.scene == "wall-collision" and a.settings.value("v") == 0.6 and a.settings.frame == "lab"
    assert a.settings.layers == {Layer.WORLD_TUBE}  # the scene line's --layers, no layers key
    assert (a.window, a.start, a.autoplay, a.locked) == ((-1.5, 2.5), -1.0, True, frozenset({"v", "frame"}))
    b = arrival(LESSON.steps[1])
    assert b.settings.layers == {Layer.SIGNALS, Layer.LIGHT_CONE} and not b.autoplay and not b.locked


def test_steps_stay_inside_the_lesson() -> None:
    assert [clamp_step(LESSON, k) for k in (-1, 0, 1, 2, 9)] == [0, 0, 1, 1, 1]
    assert step_labels(LESSON) == ("1/2 · Crash", "2/2 · Bounce")


def test_locks_refuse_only_what_they_fix() -> None:
    s = arrival(LESSON.steps[0]).settings
    locked = frozenset({"v", "frame"})
    assert locked_changes(locked, s, s.with_value("v", 0.7)) == ("v",)
    assert locked_changes(locked, s, s.with_value("eps", 0.5)) == ()
    assert locked_changes(locked, s, parse_scenario("wall-collision --v 0.6 --eps 0").settings) == ("frame",)
    assert locked_changes(frozenset({"scene"}), s, parse_scenario("impulsive-start").settings) == ("scene",)
    assert locked_changes(locked, s, s.with_layers(frozenset())) == ()  # layers are never locked
    reason = lock_reason(LESSON, 0, s)
    assert reason.startswith("**Locked by step 1**: V, Frame") and lock_reason(LESSON, 1, s) == ""


def test_caption_band_is_the_filled_in_markdown() -> None:
    band = caption_html(LESSON.steps[0], presenter=True)
    assert "rr-caption-presenter" in band and "<h2>Crash</h2>" in band
    assert "Braking at t = −0.75; <strong>before</strong> contact." in band
    assert '"shown": false' in caption_message(band, False)
    assert "another scene" in caption_html(LESSON.steps[0], off_step=True) and "another scene" not in band


def test_lesson_keys() -> None:
    assert action_for("pagedown", LESSON_HOTKEYS) is action_for("arrowright", LESSON_HOTKEYS) is Action.NEXT_STEP
    assert action_for("pageup", LESSON_HOTKEYS) is action_for("arrowleft", LESSON_HOTKEYS) is Action.PREVIOUS_STEP
    assert action_for("L", LESSON_HOTKEYS) is Action.LEAD and action_for("C", LESSON_HOTKEYS) is Action.TOGGLE_CAPTION
    assert "← → PgUp PgDn step" in key_line(LESSON_HOTKEYS)


def test_scenario_notice_names_the_flag() -> None:
    with pytest.raises(ScenarioError) as bad:
        parse_scenario("rod-collision --v1 1.6")
    assert scenario_problem(bad.value).startswith("--v1: ") and "(-1, 1)" in scenario_problem(bad.value)
    with pytest.raises(ScenarioError) as unknown:
        parse_scenario("nope")
    assert scenario_problem(unknown.value).startswith("'nope' is not a scene")
    assert 'data-s="a &#x27;b c&#x27;"' in scenario_html("a 'b c'")  # quoted for its attribute


@pytest.mark.slow  # a new interpreter
@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ('title = "T"\n[[step]]\ntitle = "A"\nscene = "wall-collision"\ncaption = "x"\nlayers = ["rays"]\n',
         ':6: step 1 ("A"), key "layers": "rays" is not a layer; the layers are "world-tube"'),
        ('title = "T"\n[[step]]\ntitle = "A"\nscene = "wall-collision --v 1.6"\ncaption = "x"\n',
         ':4: step 1 ("A"), key "scene": '),
    ],
)  # fmt: skip
def test_serve_refuses_a_bad_lesson_before_serving(tmp_path: Path, text: str, expected: str) -> None:
    path = tmp_path / "bad.toml"
    path.write_text(text, encoding="utf-8")
    run = subprocess.run(
        [sys.executable, "-m", "rigidrel_app.cli", "serve", "--lesson", str(path), "--port", "0"],
        capture_output=True, text=True, timeout=120,
    )  # fmt: skip
    assert run.returncode == 2 and run.stdout == ""  # no "serving on" line: no server started
    assert run.stderr.count("\n") == 1 and expected in run.stderr, run.stderr


@pytest.mark.slow  # a new interpreter
def test_follow_needs_a_lesson() -> None:
    run = subprocess.run(
        [sys.executable, "-m", "rigidrel_app.cli", "serve", "--follow"], capture_output=True, text=True, timeout=120
    )
    assert run.returncode == 2 and "--follow needs --lesson" in run.stderr
