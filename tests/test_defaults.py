"""Defaults that tell the paradoxes, the same in the API, the registry, the command line and the app.

The pole in the barn: a barn of ``L0/gamma`` (the moving pole just fits in the barn's frame) and the
door closing at the paradox's instant ``(L0/gamma - D)/V``, at every V, unless set; the summary and
the notes say "just fits" only when it does. Bell's spaceships: one ship length, ``s/10``.
"""

from __future__ import annotations

import json
import math

import pytest

import rigidrel_core as rr
from rigidrel_app.cli import main
from rigidrel_app.view.scenario import format_scenario, parse_scenario
from rigidrel_app.view.state import Settings, build


def cli_report(args: list[str], capsys: pytest.CaptureFixture[str]) -> dict[str, object]:
    assert main(["events", *args, "--json"]) == 0
    report = json.loads(capsys.readouterr().out)
    assert isinstance(report, dict)
    return report


@pytest.mark.parametrize("v", [1e-6, 0.3, 0.6, 0.8, 0.99])
def test_the_barn_is_l0_over_gamma_and_the_door_closes_at_the_paradoxs_instant(
    v: float, capsys: pytest.CaptureFixture[str]
) -> None:
    """At V = 0.3 a fixed barn of 0.8 would not hold even the unstopped pole; at V = 0.8 the door of a
    0.8 barn would not close at the instant the paradox names. The defaults follow V everywhere."""
    moving = 1.0 / rr.Frame.from_velocity(v).lorentz_factor
    api = rr.pole_barn(v, 1.0, model="both")
    registry = rr.build_scene("pole-barn", v=v)
    app = build(Settings("pole-barn").with_value("v", v)).scene
    for scene in (api, registry, app):
        assert isinstance(scene, rr.PoleBarnScene)
        assert scene.barn_length == moving and scene.door_time == 0.0
        assert scene.notes()[0].endswith("in the barn's frame the moving pole just fits")
        assert "the instant the paradox names" in scene.notes()[1]
    report = cli_report(["pole-barn", f"--v={v}"], capsys)
    door = report["object_events"]["door closes"]  # type: ignore[index]
    assert (door["t"], door["x"]) == (0.0, moving)
    assert Settings("pole-barn").with_value("v", v).value("barn_length") == moving  # what its slider shows


def test_a_barn_set_by_hand_stays_and_the_door_follows_it(capsys: pytest.CaptureFixture[str]) -> None:
    """Set, the barn keeps its length as V moves; the door still closes at the paradox's instant for
    it, and the notes say when the barn is too short to hold even the unstopped pole."""
    s = Settings("pole-barn").with_value("barn_length", 1.2).with_value("v", 0.3)
    scene = build(s).scene
    assert isinstance(scene, rr.PoleBarnScene)
    moving = 1.0 / rr.Frame.from_velocity(0.3).lorentz_factor
    assert scene.barn_length == 1.2 and scene.door_time == pytest.approx((moving - 1.2) / 0.3, rel=1e-15)
    assert s.value("door_time") == scene.door_time
    barn = scene.notes()[0]
    assert "longer than the moving pole" in barn and "just fits" not in barn
    short = rr.pole_barn(0.3, 1.0, 0.8, "both", door_time=0.0)
    assert "shorter than the moving pole" in short.notes()[0] and "just fits" not in short.notes()[0]
    assert "not the paradox's instant" in short.notes()[1]
    # a scenario line keeps a barn that follows V as "none", and one set by hand as its number
    assert "--barn-length none" in format_scenario(Settings("pole-barn"))
    line = format_scenario(Settings("pole-barn").with_value("barn_length", 0.5))
    assert "--barn-length 0.5" in line and parse_scenario(line).settings.chosen("barn_length") == 0.5


def test_the_summary_says_just_fits_only_of_the_default_barn() -> None:
    summary = rr.describe("pole-barn").summary
    assert "just fits" in summary and "by default L0/γ" in summary


@pytest.mark.parametrize("separation", [0.3, 1.0, 4.0, 10.0])
def test_one_ship_length_everywhere(separation: float, capsys: pytest.CaptureFixture[str]) -> None:
    """The API, the registry, the command line and the app give the ships ``s/10``: the same string,
    the same break event."""
    api = rr.bell_spaceships(0.6, separation, 0.5, breaking_strain=0.25)
    registry = rr.build_scene("bell-spaceships", separation=separation)
    settings = Settings("bell-spaceships").with_value("separation", separation)
    app = build(settings).scene
    assert settings.value("ship_length") == separation / 10  # what the app's slider shows
    for scene in (registry, app):
        assert isinstance(scene, rr.BellScene)
        assert scene.ship_length == api.ship_length == separation / 10
        assert scene.string_break == api.string_break
    report = cli_report(["bell-spaceships", f"--separation={separation}"], capsys)
    assert report["events_lab"]["T_F1"] == dict(zip("tx", api.events["T_F1"], strict=True))  # type: ignore[index]
    assert rr.describe("bell-spaceships").parameter("ship_length").default is None


def test_every_omitted_default_is_the_constructors() -> None:
    """Where omitting a parameter stands for a value, the registry's rule gives the constructor's."""
    for kind, d in rr.scene_descriptions().items():
        scene = d.build()
        resolved = d.resolved({})
        for p in d.parameters:
            if p.when_omitted is not None:
                value = resolved[p.name]
                assert value is not None and math.isfinite(value), (kind, p.name)
                assert getattr(scene, p.name) == value, (kind, p.name)
