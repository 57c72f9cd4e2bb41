"""Defaults that tell the paradoxes, the same in the API, the registry, the command line and the app.

The pole in the barn: a barn of ``L0/gamma`` (the moving pole just fits in the barn's frame) and the
door closing at the paradox's instant ``(L0/gamma - D)/V``, at every V, unless set; the summary and
the notes say "just fits" only when it does. Bell's spaceships: one ship length, ``s/10``. Every
scene's one-line summary holds, claim by claim, for its scene at every speed.
"""

from __future__ import annotations

import json
import math

import numpy as np
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


def proper_accelerations(scene: rr.Scene, rod: int) -> tuple[float, float]:
    """``(left, right)`` end's proper acceleration during the change, ``1/radius`` (``inf``: an impulse)."""
    m = scene.rods[rod].motion
    return tuple(math.inf if r == 0.0 else 1.0 / r for r in (m.radius_left, m.radius_right))  # type: ignore[return-value]


@pytest.mark.parametrize("v", [1e-3, 0.3, 0.6, 0.8, 0.99])
def test_every_summary_holds_for_its_scene_at_every_speed(v: float) -> None:
    """Each scene's one-line summary, claim by claim, of its registry scene at its defaults with V (or V1,
    or V_f) set: no summary promises what the scene's own numbers do not show (as "just fits" once did
    of a fixed barn)."""
    summaries = {k: d.summary for k, d in rr.scene_descriptions().items()}

    acc = rr.build_scene("constant-acceleration", v=v)
    assert summaries["constant-acceleration"].startswith("A rod accelerates from rest to V, its back end harder")
    assert acc.rods[0].motion.velocity_initial.value == 0.0 and acc.final_velocities[0] == v
    back, front = proper_accelerations(acc, 0)
    assert back > front > 0.0

    dec = rr.build_scene("deceleration", v=v)
    assert summaries["deceleration"].startswith("A rod moving at −V brakes Born-rigidly to rest on [0, L0] at t = 0")
    assert dec.rods[0].motion.velocity_initial.value == -v and dec.final_velocities[0] == 0.0
    for t in (0.0, 1.0):
        np.testing.assert_allclose(dec.positions([t])[0, :, 0], [0.0, dec.rods[0].motion.length], atol=1e-15)

    kick = rr.build_scene("impulsive-start", v=v)
    assert summaries["impulsive-start"].startswith("A rod at rest is kicked at its back end, which jumps to V")
    assert kick.rods[0].motion.velocity_initial.value == 0.0 and kick.final_velocities[0] == v
    assert proper_accelerations(kick, 0)[0] == math.inf and math.isfinite(proper_accelerations(kick, 0)[1])

    change = rr.build_scene("velocity-change", v_final=v, v_initial=-0.2)
    assert "each point at its own constant proper acceleration" in summaries["velocity-change"]
    assert change.rods[0].motion.velocity_initial.value == -0.2 and change.final_velocities[0] == v
    impulse = rr.build_scene("velocity-change", v_final=v, v_initial=-0.2, a_front=None)
    assert math.inf in proper_accelerations(impulse, 0)  # "none: at once, an impulse"

    assert "stops (ε = 0), bounces back elastically (ε = 1)" in summaries["wall-collision"]
    for eps, after in ((0.0, 0.0), (1.0, v)):
        wall = rr.build_scene("wall-collision", v=v, eps=eps)
        assert wall.rods[0].motion.velocity_initial.value == -v
        assert wall.final_velocities[0] == pytest.approx(after, rel=1e-15, abs=0.0)

    bell = rr.build_scene("bell-spaceships", v=v)
    assert isinstance(bell, rr.BellScene)
    text = summaries["bell-spaceships"]
    assert "same proper acceleration stay a lab distance s apart" in text and "stretches towards γs − l" in text
    assert "breaks before it gets there if its breaking strain is lower" in text and "keeps its rest length" in text
    rear_ends = [proper_accelerations(bell, i)[0] for i in (0, 1, 2)]
    assert rear_ends[0] == rear_ends[1] == rear_ends[2]
    for t in (0.0, 1.0, 10.0):
        x = bell.positions([t])[:, 0, 0]
        assert x[1] - x[0] == pytest.approx(bell.separation, rel=1e-12)
    gamma = rr.Frame.from_velocity(v).lorentz_factor
    assert bell.string_final == pytest.approx(gamma * bell.separation - bell.ship_length, rel=1e-12)
    assert bell.breaking_strain is not None
    assert (bell.string_break is not None) is (bell.breaking_strain <= bell.final_strain)

    hit = rr.build_scene("rod-collision", v1=v)
    assert summaries["rod-collision"].startswith("Rod 1 at V1 hits rod 2 at V2 < V1; their touching ends")
    assert proper_accelerations(hit, 0)[1] == math.inf and proper_accelerations(hit, 1)[0] == math.inf

    pole = rr.build_scene("pole-barn", v=v)
    assert isinstance(pole, rr.PoleBarnScene)
    text = summaries["pole-barn"]
    assert "by default L0/γ, so that in the barn's frame the moving pole just fits" in text
    assert "door closes, by default, when the unstopped pole's rear end would pass it" in text
    assert "it closes on the Born-rigid pole (Sec. 5), in every frame, and behind a pole stopped by a signal" in text
    assert pole.barn_length == pole.moving_length  # just fits, unstopped, in the barn's frame
    assert pole.door_time == pole.paradox_door_time
    assert [pole.door_outcome(i) for i in (0, 1)] == [rr.DoorOutcome.ON_POLE, rr.DoorOutcome.CAUGHT]
    assert [pole.inside(i) for i in (0, 1)] == [False, True]
