"""Lesson files: the built-in walk through the paper, and one clear, located error for each mistake."""

from __future__ import annotations

from pathlib import Path

import pytest

from rigidrel_app.lessons import BUILTIN, LessonError, builtin_lesson, lesson_from, load_lesson, parse_lesson
from rigidrel_app.view.layers import DEFAULT_LAYERS, Layer

GOOD = '''title = "Two steps"

[[step]]
title = "Crash"
scene = "wall-collision --v 0.6 --eps 0 --frame lab"
caption = "T_1 at t = {event[T_1].t:.3g}; light arrives at {signal[S].t:g}."
layers = ["world-tube", "signals"]
window = [-1.0, 2.0]
start = -0.5
autoplay = true
lock = ["v", "frame"]

[[step]]
title = "Ride"
scene = "wall-collision --v 0.6 --eps 0"
caption = """
Rest length {rod[1].rest_length:g}.
"""
ride = { rod = 1, fraction = 0.5 }
'''


def test_a_good_lesson() -> None:
    lesson = parse_lesson(GOOD, "two.toml")
    first, second = lesson.steps
    assert first.caption == "T_1 at t = −0.75; light arrives at 1."  # a number's sign is the minus sign
    assert first.layers == {Layer.WORLD_TUBE, Layer.SIGNALS}
    assert first.window == (-1.0, 2.0) and first.start == -0.5 and first.autoplay
    assert first.locked == {"v", "frame"}
    assert second.layers == DEFAULT_LAYERS and second.ride is not None and second.ride.rod == 0
    assert second.caption.strip() == "Rest length 1."
    assert (first.line, second.line) == (3, 13)


def _error(text: str) -> LessonError:
    with pytest.raises(LessonError) as info:
        parse_lesson(text, "l.toml")
    return info.value


@pytest.mark.parametrize(
    ("old", "new", "line", "key", "words"),
    [
        ('layers = ["world-tube", "signals"]', 'layers = ["world-tube", "rays"]', 7, "layers", '"rays" is not a layer'),
        ('--v 0.6 --eps 0 --frame lab"', '--v 1.6 --eps 0 --frame lab"', 5, "scene", "(0, 1)"),
        ("--frame lab", "--frame sideways", 5, "scene", "'rod before'"),
        ("window = [-1.0, 2.0]", "window = [2.0, -1.0]", 8, "window", "start < end"),
        ("start = -0.5", "start = 5.0", 9, "start", "outside the window"),
        ("autoplay = true", 'autoplay = "yes"', 10, "autoplay", "true or false"),
        ('lock = ["v", "frame"]', 'lock = ["v", "speed"]', 11, "lock", '"speed" is not a control of wall-collision'),
        ("{event[T_1].t:.3g}", "{event[T_9].t:.3g}", 6, "caption", "event[T_9] does not exist; event has T_1, T_1'"),
        ("{event[T_1].t:.3g}", "{event[T_1].when}", 6, "caption", "'when' is not a value there"),
        ("{event[T_1].t:.3g}", "{speed}", 6, "caption", "{speed} is not a caption value"),
        ("{event[T_1].t:.3g}", "{event.__class__}", 6, "caption", "no private names"),
        ("autoplay = true", "autoplay = true\ncolour = 3", 11, "colour", "unknown key"),
        ("ride = { rod = 1, fraction = 0.5 }", "ride = { rod = 2, fraction = 0.5 }", 19, "ride", "rods 1..1"),
        ("ride = { rod = 1, fraction = 0.5 }", "ride = { rod = 1, fraction = 1.5 }", 19, "ride", "[0, 1]"),
        ('--v 0.6 --eps 0"\ncaption', '--v 0.6 --eps 0 --frame lab"\ncaption', 19, "ride", "no other frame"),
        ("start = -0.5", "start = -0.5\n", 9, None, None),  # unchanged: a control case that must pass
    ],
)
def test_each_mistake_is_located(old: str, new: str, line: int, key: str | None, words: str | None) -> None:
    assert old in GOOD
    text = GOOD.replace(old, new, 1)
    if key is None:
        parse_lesson(text, "l.toml")
        return
    err = _error(text)
    assert (err.line, err.key) == (line, key), str(err)
    assert words is not None and words in str(err)
    assert str(err).startswith(f"l.toml:{line}: step ")


def test_the_step_is_named_by_number_and_title() -> None:
    err = _error(GOOD.replace("autoplay = true", "autoplay = 1"))
    assert 'step 1 ("Crash"), key "autoplay": must be true or false' in str(err)


def test_missing_and_malformed_files() -> None:
    assert _error("title = 'x'\n").key == "step"
    assert "not valid TOML" in str(_error('title = "x"\n[[step]\n'))
    assert _error('[[step]]\ntitle = "a"\n').key == "title"  # the lesson's own title is missing
    missing = _error('title = "x"\n[[step]]\ntitle = "a"\nscene = "wall-collision"\n')
    assert (missing.key, missing.line, missing.step) == ("caption", 2, 1)
    with pytest.raises(LessonError, match="cannot read the file"):
        load_lesson(Path("/nonexistent/lesson.toml"))
    with pytest.raises(LessonError, match="the built-in lessons are paper"):
        builtin_lesson("relativity")


def test_the_built_in_paper_lesson() -> None:
    assert BUILTIN == ("paper",)
    lesson = lesson_from("paper")
    assert len(lesson.steps) >= 12
    text = "\n".join(s.caption for s in lesson.steps)
    assert "{" not in text and "}" not in text  # every field filled in
    # numbers from the core, with the paper's misprints flagged beside them
    assert "V′2 = 0.4382" in text and "prints V′2 = 0.439" in text
    assert "T′_2 = 1.05" in text and "prints T′_2 = 1.052" in text
    assert "Outside the light cone of the contact" not in text  # the verdict reads as a sentence
    assert "lies outside the light cone of the contact" in text
    kinds = {s.resolved.scene.kind for s in lesson.steps}
    assert {"constant-acceleration", "impulsive-start", "wall-collision", "rod-collision"} <= kinds
    assert {"bell-spaceships", "pole-barn"} <= kinds
    assert "γs = 1.25 apart" in text and "its rear end at lab x = 0.3333" in text
    assert any(s.ride is not None for s in lesson.steps)
    assert any(Layer.SIGNALS in s.layers for s in lesson.steps)


def test_a_file_on_disk(tmp_path: Path) -> None:
    path = tmp_path / "two.toml"
    path.write_text(GOOD, encoding="utf-8")
    assert len(lesson_from(str(path)).steps) == 2
    path.write_text(GOOD.replace("--eps 0 --frame lab", "--eps 2 --frame lab"), encoding="utf-8")
    with pytest.raises(LessonError, match=rf"^{path}:5: step 1"):
        lesson_from(str(path))


OLD_NAMES = """title = "Written before the parameters took one name per quantity"

[[step]]
title = "Case I"
scene = "rod-collision --v1 0.6 --mass2 2 --v2 0 --length2 1 --eps 1 --frame lab"
caption = "M2 = {param[mass2]:g} M1."
lock = ["mass2"]
"""


@pytest.mark.parametrize(
    ("old", "new", "line", "key", "words"),
    [
        ("--mass2 2", "--m2 2", 5, "scene", "--m2 is now --mass2"),
        ("--length2 1", "--l2 1", 5, "scene", "--l2 is now --length2"),
        ("{param[mass2]:g}", "{param[m2]:g}", 6, "caption", "param[m2] is now param[mass2]"),
        ('lock = ["mass2"]', 'lock = ["m2"]', 7, "lock", '"m2" is now "mass2"'),
    ],
)
def test_an_old_parameter_name_is_refused_naming_the_new_one(
    old: str, new: str, line: int, key: str, words: str
) -> None:
    """A lesson written with a parameter's old name gets a located error that names the new one."""
    parse_lesson(OLD_NAMES, "l.toml")
    err = _error(OLD_NAMES.replace(old, new, 1))
    assert (err.line, err.key) == (line, key), str(err)
    assert words in str(err), str(err)


def test_an_old_bell_lesson_names_a_back() -> None:
    text = GOOD.replace("wall-collision --v 0.6 --eps 0 --frame lab", "bell-spaceships --v 0.6 --acceleration 0.5", 1)
    err = _error(text.replace("{event[T_1].t:.3g}", "{event[T_B1].t:.3g}").replace("{signal[S].t:g}", "1"))
    assert (err.line, err.key) == (5, "scene") and "--acceleration is now --a-back" in str(err), str(err)
