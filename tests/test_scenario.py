"""Scenario strings: the command line's syntax for a whole state, both ways."""

from __future__ import annotations

import pytest

import rigidrel_core as rr
from rigidrel_app.view.layers import DEFAULT_LAYERS, Layer
from rigidrel_app.view.scenario import ScenarioError, format_scenario, parse_scenario
from rigidrel_app.view.state import CUSTOM_FRAME, Settings, build, presets


def test_the_example_line() -> None:
    s = parse_scenario("rod-collision --v1 0.6 --mass2 2 --frame barycentric --t 0.3")
    assert s.settings == Settings("rod-collision", (("v1", 0.6), ("mass2", 2.0)), "barycentric")
    assert s.t == 0.3
    line = format_scenario(s.settings, s.t)
    assert line.startswith("rod-collision --v1 0.6 --mass2 2 ")
    assert line.endswith("--frame barycentric --t 0.3")


@pytest.mark.parametrize("label", list(presets()))
def test_every_paper_figure_round_trips(label: str) -> None:
    settings = presets()[label]
    assert parse_scenario(format_scenario(settings)).settings == settings


def test_frames_with_spaces_and_velocities() -> None:
    s = parse_scenario("wall-collision --v 0.9 --frame 'rod before'").settings
    assert s.frame == "rod before" and build(s).frame.beta == pytest.approx(-0.9)
    custom = parse_scenario("wall-collision --frame -0.99 --t -1").settings
    assert custom.frame == CUSTOM_FRAME and custom.beta == -0.99
    assert parse_scenario(format_scenario(custom)).settings == custom
    assert "--frame 'rod before'" in format_scenario(s)


def test_layers_are_written_only_when_not_the_default() -> None:
    plain = parse_scenario("wall-collision --v 0.6").settings
    assert plain.layers == DEFAULT_LAYERS and "--layers" not in format_scenario(plain)
    with_signals = plain.with_layers((DEFAULT_LAYERS | {Layer.SIGNALS}) - {Layer.OTHER_AXES})
    line = format_scenario(with_signals)
    assert "--layers world-tube,interior-lines,light-cone,signals,simultaneity,length-panel" in line
    assert parse_scenario(line).settings == with_signals
    assert build(with_signals).layers == with_signals.layers  # the drawing is told what to show
    every = plain.with_layers(frozenset(Layer))
    assert (
        format_scenario(every).endswith("--layers all")
        and parse_scenario("wall-collision --layers all").settings == every
    )
    bare = plain.with_layers(frozenset())
    assert "--layers none" in format_scenario(bare) and parse_scenario(format_scenario(bare)).settings == bare
    assert plain.with_scene("rod-collision").layers == plain.layers  # a new scene keeps the layers


def test_optional_parameter_omitted() -> None:
    s = parse_scenario("velocity-change --v-initial 0.2 --v-final -0.5 --a-front none").settings
    assert s.value("a_front") is None
    assert "--a-front none" in format_scenario(s)


@pytest.mark.parametrize(
    ("line", "parameter", "words"),
    [
        ("", "scene", "start with a scene"),
        ("rocket --v 0.5", "scene", "is not a scene"),
        ("wall-collision --speed 0.5", "scene", "is not an option of wall-collision"),
        ("wall-collision --v", "v", "needs a value"),
        ("wall-collision --v fast", "v", "number in (0, 1)"),
        ("wall-collision --v 1.2", "v", "(0, 1)"),
        ("wall-collision --frame sideways", "frame", "'rod before'"),
        ("wall-collision --frame 1", "frame", "(-1, 1)"),
        ("wall-collision --t nan", "t", "finite"),
        ("rod-collision --v1 0.2 --v2 0.5", "v2", "less than"),
        ("wall-collision --frame 'rod", "scene", "cannot read"),
        ("wall-collision --layers signals,cones", "layers", "'cones' is not a layer"),
        ("wall-collision --layers", "layers", "needs a value"),
    ],
)
def test_bad_lines_name_the_flag(line: str, parameter: str, words: str) -> None:
    with pytest.raises(ScenarioError) as info:
        parse_scenario(line)
    assert info.value.parameter == parameter
    assert words in str(info.value)


@pytest.mark.parametrize("kind", list(rr.scene_descriptions()))
def test_every_scene_default_round_trips(kind: str) -> None:
    settings = Settings(kind)
    line = format_scenario(settings, 0.25)
    back = parse_scenario(line)
    assert back.settings == settings and back.t == 0.25


@pytest.mark.parametrize("kind", list(rr.scene_descriptions()))
def test_rigidrel_serve_reads_every_line_the_app_writes(kind: str) -> None:
    """One grammar: the line the Scenario folder shows, pasted after ``rigidrel serve``, opens the
    same state the scenario box would (every option of a scenario line is an option of serve)."""
    import shlex

    from rigidrel_app.cli import build_parser, start_scenario

    settings = Settings(kind).with_layers(frozenset(Layer))
    for line in (format_scenario(settings, 0.25), format_scenario(settings.riding(0, 0.5), -0.5)):
        args = build_parser().parse_args(["serve", *shlex.split(line)])
        assert start_scenario("rigidrel serve", args) == parse_scenario(line), line


@pytest.mark.parametrize(
    ("line", "flag", "words"),
    [
        ("rod-collision --v1 0.6 --m2 2 --frame barycentric", "m2", "--m2 is now --mass2"),
        ("rod-collision --l1 2", "l1", "--l1 is now --length1"),
        ("bell-spaceships --v 0.6 --acceleration 0.5", "acceleration", "--acceleration is now --a-back"),
    ],
)
def test_an_old_parameter_name_is_refused_naming_the_new_one(line: str, flag: str, words: str) -> None:
    """A scenario string written before a parameter was renamed names the new flag."""
    with pytest.raises(ScenarioError) as info:
        parse_scenario(line)
    assert info.value.parameter == flag
    assert words in str(info.value)
