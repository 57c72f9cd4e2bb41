"""The two paradoxes: Bell's spaceships and the pole in the barn (Born-rigid beside signal-limited).

Checks named in the scenes' docstrings: Bell's rear ends end gamma s apart in the ships' frame
(1.25 at V = 0.6); the string's rest length by its definition (the comoving frame, sliced by the
scene's own samplers) and against the 50-digit reference; the pole's rear end never nearer the
wall than L0 (Born-rigid) and resting at x = 1/3 (signal-limited, V = 0.8, c_s = 1); verdicts the
same in every frame; the signal-limited stop's causality and its 4-momentum bookkeeping with heat.
"""

from __future__ import annotations

import json
import math
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import rigidrel_core as rr
from rigidrel_core.scenes.bell import COMPARISON_ROD, REAR_SHIP

SETTINGS = settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
#: Relative tolerance of closed forms against each other and against the 50-digit reference.
TOL = 1e-12
#: Born rigidity as the property tests check it (a comoving frame formed from a sampled velocity).
TOL_RIGID = 1e-9

REFERENCE = json.loads((Path(__file__).parent / "reference" / "reference.json").read_text())

speeds = st.floats(0.05, 0.99)
frames = st.floats(-0.99, 0.99).map(rr.Frame.from_velocity)


@st.composite
def bell_scenes(draw: st.DrawFn) -> rr.BellScene:
    separation = draw(st.floats(0.1, 10.0))
    return rr.bell_spaceships(
        draw(speeds),
        separation,
        draw(st.floats(0.05, 5.0)),
        ship_length=draw(st.floats(0.01, 0.9)) * separation,
        breaking_strain=draw(st.none() | st.floats(0.01, 2.0)),
    )


@st.composite
def pole_scenes(draw: st.DrawFn) -> rr.PoleBarnScene:
    length = draw(st.floats(0.1, 10.0))
    return rr.pole_barn(
        draw(speeds),
        length,
        barn_length=draw(st.floats(0.05, 2.0)) * length,
        model="both",
        sound_speed=draw(st.floats(0.05, 1.0)),
        door_time=draw(st.none() | st.floats(-3.0, 3.0)),
    )


# ---------------------------------------------------------------- Bell's spaceships
def test_bell_rear_ends_end_gamma_separation_apart_at_six_tenths() -> None:
    """V = 0.6, s = 1, a = 0.5: both rear ends stop at lab t = gamma V / a = 1.5; in the ships' frame
    after, their rear ends are gamma s = 1.25 apart, the string 1.15 long (0.9 at the start)."""
    scene = rr.bell_spaceships(0.6, 1.0, 0.5)
    assert scene.events["T_B1"][0] == scene.events["T_B2"][0] == 1.5
    after = scene.frame("ships after")
    t_late = scene.events_in(frame=after)["T_Frod"][0] + 1.0
    x = scene.positions([t_late], frame=after)
    assert x[1, 0, 0] - x[0, 0, 0] == pytest.approx(1.25, rel=TOL)
    assert scene.string_unstretched == pytest.approx(0.9, rel=TOL)
    assert scene.string_final == pytest.approx(1.15, rel=TOL)
    assert scene.string_rest_lengths([-1.0, 100.0]) == pytest.approx([0.9, 1.15], rel=TOL)


@SETTINGS
@given(scene=bell_scenes(), frame=frames, u=st.floats(0.0, 1.0))
def test_bell_separation_in_the_ships_frame_is_gamma_separation(scene: rr.BellScene, frame: rr.Frame, u: float) -> None:
    """Once every end coasts, the rear ends are gamma s apart in the ships' frame; at every instant of
    any frame the lab distance of the rear ends is s while both are seen at equal lab time."""
    after = scene.frame("ships after")
    g = scene.rods[0].motion.velocity_final.lorentz_factor()
    t_late = max(t for t, _ in scene.events_in(frame=after).values()) + 1.0
    x = scene.positions([t_late], frame=after)
    assert x[1, 0, 0] - x[0, 0, 0] == pytest.approx(g * scene.separation, rel=TOL)
    t0, t1 = scene.time_window(frame=rr.LAB)
    x_lab = scene.positions([t0 + u * (t1 - t0)])
    assert x_lab[1, 0, 0] - x_lab[0, 0, 0] == pytest.approx(scene.separation, rel=TOL)
    del frame


@SETTINGS
@given(scene=bell_scenes(), u=st.floats(0.0, 1.0))
def test_bell_string_rest_length_is_its_length_in_the_rear_ships_comoving_frame(scene: rr.BellScene, u: float) -> None:
    """The closed form against the definition: the comoving frame of the string's rear end (the
    scene's own), the front ship's rear end sliced there at the same frame time."""
    t_end = scene.events["T_F2"][0]
    t = u * 1.2 * t_end
    comoving = scene.comoving_frame(REAR_SHIP, 1.0, t=t)
    rear_end = comoving @ np.array([t, scene.positions([t])[0, 1, 0]])
    front_rear = scene.positions([rear_end[0]], frame=comoving)[1, 0, 0]
    scale = scene.separation * scene.rods[0].motion.velocity_final.lorentz_factor()
    assert abs(scene.string_rest_lengths([t])[0] - (front_rear - rear_end[1])) <= 1e-10 * scale


@SETTINGS
@given(scene=bell_scenes(), frame=frames)
def test_bell_string_stretches_monotonically_and_breaks_where_its_strain_is_the_breaking_strain(
    scene: rr.BellScene, frame: rr.Frame
) -> None:
    t0, t1 = scene.time_window(frame=frame)
    lengths = scene.string_rest_lengths(np.linspace(t0, t1, 101), frame=frame)
    assert np.all(np.diff(lengths) >= -1e-12 * scene.string_final)
    assert scene.string_unstretched * (1 - TOL) <= lengths.min() <= lengths.max() <= scene.string_final * (1 + TOL)
    event = scene.string_break_in(frame=frame)
    if scene.breaking_strain is None or scene.breaking_strain > scene.final_strain:
        assert event is None
    else:
        assert event is not None
        strain = scene.string_strains([event[0]], frame=frame)[0]
        assert strain == pytest.approx(scene.breaking_strain, rel=1e-9, abs=1e-12)
        x_end = scene.positions([event[0]], frame=frame)[REAR_SHIP, 1, 0]
        assert x_end == pytest.approx(event[1], rel=1e-12, abs=1e-12 * scene.separation)


@SETTINGS
@given(scene=bell_scenes(), frame=frames, f=st.floats(0.0, 1.0), u=st.floats(0.0, 1.0))
def test_bell_comparison_rod_keeps_its_rest_length_and_its_front_accelerates_less(
    scene: rr.BellScene, frame: rr.Frame, f: float, u: float
) -> None:
    """The Born-rigid rod on [0, s]: its rest length s in the comoving frame of any of its points, its
    rear end on the rear ship's worldline, its front end reaching V at gamma V (1/a + s) (Eq. (15):
    ``a'_F = a / (1 + a s)``), after the front ship's rear end."""
    rod = COMPARISON_ROD
    t0, t1 = scene.time_window(frame=frame)
    t = t0 + u * (t1 - t0)
    comoving = scene.comoving_frame(rod, f, t=t, frame=frame)
    x = scene.material_positions([t], frame=frame, fractions=[f])[rod, 0, 0]
    t_c = float((comoving @ (frame.inverse() @ np.array([t, x])))[0])
    assert scene.lengths([t_c], frame=comoving)[rod, 0] == pytest.approx(scene.separation, rel=TOL_RIGID)
    both = scene.positions([t], frame=frame)
    assert both[rod, 0, 0] == both[REAR_SHIP, 0, 0]
    g = scene.rods[0].motion.velocity_final.lorentz_factor()
    v = scene.rods[0].motion.velocity_final.value
    assert scene.events["T_Frod"][0] == pytest.approx(g * v * (1.0 / scene.a_back + scene.separation), rel=TOL)
    assert scene.events["T_Frod"][0] > scene.events["T_B2"][0]


def reference_cases(kind: str) -> list[dict[str, Any]]:
    return [c for c in REFERENCE["cases"] if c["kind"] == kind]


@pytest.mark.parametrize("case", reference_cases("bell-spaceships"), ids=lambda c: str(c["params"]))
def test_bell_string_against_the_50_digit_reference(case: dict[str, Any]) -> None:
    """The string's final rest length and the break event (found there by bisection on the definition)."""
    params: dict[str, Any] = {k: None if v is None else float.fromhex(v) for k, v in case["params"].items()}
    scene = rr.bell_spaceships(**params)  # the constructor's defaults, as the reference's
    extra = {k: float(v) for k, v in case["extra"].items()}
    assert scene.string_final == pytest.approx(extra["string_final"], rel=TOL)
    if "break_t" in extra:
        assert scene.string_break == pytest.approx((extra["break_t"], extra["break_x"]), rel=TOL)
    else:
        assert scene.string_break is None


@pytest.mark.parametrize("case", reference_cases("bell-spaceships"), ids=lambda c: str(c["params"]))
def test_bell_strains_hold_1e_12_relative_at_every_speed(case: dict[str, Any]) -> None:
    """The final strain, the strain at three rapidities of the rear ship (its string's front end on its
    hyperbola, then coasting) and the break event, each within 1e-12 of itself against the 50-digit
    reference, also at V = 1e-6 (strains of 5e-13) and breaking strains of 1e-12 (the small-speed
    group): ``gamma - 1``, ``cosh theta - 1`` and the strain are products, never differences of
    nearly equal numbers. The strains read along the string's rear end (at its lab time) agree."""
    params: dict[str, Any] = {k: None if v is None else float.fromhex(v) for k, v in case["params"].items()}
    scene = rr.bell_spaceships(**params)
    extra = {k: float(v) for k, v in case["extra"].items()}
    assert scene.final_strain == pytest.approx(extra["final_strain"], rel=TOL, abs=0.0)
    radius = 1.0 / scene.a_back + scene.ship_length
    for k in (1, 2, 3):
        theta, strain = extra[f"rapidity_{k}"], extra[f"strain_{k}"]
        assert float(scene.string.strain_at_rapidity(theta)) == pytest.approx(strain, rel=TOL, abs=0.0)
        t_lab = radius * math.sinh(theta)  # the string's rear end there (Sec. 3, Eq. (4))
        assert float(scene.string_strains([t_lab])[0]) == pytest.approx(strain, rel=1e-12, abs=0.0)
    if "break_t" in extra:
        t, x = scene.string_break or (math.nan, math.nan)
        assert t == pytest.approx(extra["break_t"], rel=TOL, abs=0.0)
        assert x == pytest.approx(extra["break_x"], rel=TOL, abs=0.0)


@pytest.mark.parametrize("v", [1e-8, 1e-6, 1e-3])
def test_bell_strain_at_small_speeds_is_gamma_minus_one_to_the_last_digits(v: float) -> None:
    """``(gamma - 1) s/(s - l)`` with ``gamma - 1 = V^2/2 + 3 V^4/8 + ...`` (a series, exact to float64
    here): a subtraction ``gamma - 1`` would keep none of the digits at V = 1e-8."""
    scene = rr.bell_spaceships(v, 1.0, 0.5)
    series = (v * v / 2 + 3 * v**4 / 8 + 5 * v**6 / 16) / 0.9
    assert scene.final_strain == pytest.approx(series, rel=4e-16)
    assert scene.string_final - scene.string_unstretched == pytest.approx(0.9 * series, rel=1e-15)


@pytest.mark.parametrize("case", reference_cases("bell-spaceships"), ids=lambda c: str(c["params"]))
@pytest.mark.parametrize("frame_name", ["lab", "ships after"])
def test_bell_string_is_broken_from_the_reference_break_event_on(case: dict[str, Any], frame_name: str) -> None:
    """``string_broken`` flips at the 50-digit reference's break event, boosted into each frame (a
    hair before it: intact; a hair after: broken); never, where the reference has no break."""
    params: dict[str, Any] = {k: None if v is None else float.fromhex(v) for k, v in case["params"].items()}
    scene = rr.bell_spaceships(**params)
    frame = scene.frame(frame_name)
    t0, t1 = scene.time_window(frame=frame)
    extra = {k: float(v) for k, v in case["extra"].items()}
    if "break_t" not in extra:
        assert not scene.string_broken(np.linspace(t0, t1 + 10.0, 50), frame=frame).any()
        return
    t_break = float((frame @ np.array([extra["break_t"], extra["break_x"]]))[0])
    hair = 1e-9 * (t1 - t0)
    broken = scene.string_broken([t0, t_break - hair, t_break + hair, t1], frame=frame)
    assert broken.tolist() == [False, False, True, True]
    assert scene.string_strains([t_break + hair], frame=frame)[0] >= scene.breaking_strain


def test_rod_groups_part_the_alternatives_and_the_comparison_rod() -> None:
    """The ships share a group and the Born-rigid comparison rod has its own; the pole-barn's two models
    are two groups (one with a single model); every other scene's rods share one."""
    assert rr.bell_spaceships(0.6, 1.0, 0.5).rod_groups == (0, 0, 1)
    assert rr.pole_barn(0.8, 1.0, 0.6, model="both").rod_groups == (0, 1)
    assert rr.pole_barn(0.8, 1.0, 0.6, model="signal").rod_groups == (0,)
    assert rr.build_scene("rod-collision").rod_groups == (0, 0)


def test_bell_events_command_prints_the_string(capsys: pytest.CaptureFixture[str]) -> None:
    from rigidrel_app.cli import main

    assert main(["events", "bell-spaceships", "--v", "0.6", "--separation", "1", "--a-back", "0.5"]) == 0
    out = capsys.readouterr().out
    assert "γs = 1.25 apart" in out
    assert "γs − l = 1.15" in out


def test_pole_barn_events_command_prints_the_verdicts(capsys: pytest.CaptureFixture[str]) -> None:
    from rigidrel_app.cli import main

    assert main(["events", "pole-barn", "--v", "0.8", "--length", "1", "--barn-length", "0.6", "--json"]) == 0
    notes = json.loads(capsys.readouterr().out)["notes"]
    assert notes[0].endswith("in the barn's frame the moving pole just fits")
    assert notes[1].startswith("the door closes at lab t_d = 0, the instant the paradox names")
    assert notes[1].endswith(": at (lab t, x) = (0, 0.6)")
    assert notes[2].startswith("the door closes on the Born-rigid pole, in every frame: at lab t = 0 the pole")
    assert "its rear end at lab x = 1, outside the door at lab x = 0.6" in notes[2]
    assert notes[3].startswith("the signal-limited pole (its stop front at c_s = 1, light speed, in the barn's")
    assert "is caught: its rear end passes the door as the door closes (the same event)" in notes[3]


@pytest.mark.parametrize("kind", ["pole-barn", "bell-spaceships"])
def test_the_events_command_totals_each_physical_system_apart(kind: str, capsys: pytest.CaptureFixture[str]) -> None:
    """The two poles (alternatives) and Bell's comparison rod (drawn instead of the ships) never share a
    total: the command line prints one labelled block per system, whose totals are its own rods', and
    its JSON has no scene-wide total."""
    from rigidrel_app.cli import main

    assert main(["events", kind, "--frame=0.3"]) == 0
    out = capsys.readouterr().out
    assert "one block per physical system (alternatives, never summed)" in out
    scene = rr.build_scene(kind)
    budget = scene.budget(frame=rr.Frame.from_velocity(0.3))
    blocks = out.split("  system: ")[1:]
    assert [b.splitlines()[0] for b in blocks] == [s.name for s in budget.systems]
    assert len(blocks) == 2
    for block, system in zip(blocks, budget.systems, strict=True):
        rows = {line[:44].strip(): line[44:].split() for line in block.splitlines()[1:] if line.startswith("    ")}
        assert [float(v) for v in rows["total before"]] == pytest.approx(list(system.total_before), rel=1e-9)
        rods = [scene.rods[i].name for i in system.system.rods]
        assert {k.removesuffix(" before") for k in rows if k.endswith(" before") and k != "total before"} == set(rods)
    assert main(["events", kind, "--json"]) == 0
    report = json.loads(capsys.readouterr().out)["budget"]
    assert "total_before" not in report and len(report["systems"]) == 2


# ---------------------------------------------------------------- the pole in the barn
def test_pole_barn_checks_at_eight_tenths() -> None:
    """V = 0.8, L0 = 1, D = 0.6 (= L0/gamma): the Born-rigid pole's rear end never gets nearer the wall
    than 1.0; the signal-limited pole's (c_s = 1) stops at x = 1/3, inside the barn."""
    scene = rr.pole_barn(0.8, 1.0, 0.6, model="both")
    t = np.linspace(-5.0, 5.0, 20001)
    rear = scene.positions(t)[:, 1]
    assert rear[0].min() == pytest.approx(1.0, rel=TOL)
    assert rear[0].min() >= 1.0 - 1e-15
    assert rear[1, -1] == pytest.approx(1.0 / 3.0, rel=TOL)
    assert scene.events["T_s"] == pytest.approx((1.0 / 3.0, 1.0 / 3.0), rel=TOL)
    born, signal = scene.verdicts()
    assert not born.inside
    assert born.door is rr.DoorOrder.NEVER_PASSES
    assert born.outcome is rr.DoorOutcome.ON_POLE  # the door, at lab (0, 0.6), closes on the pole
    assert signal.inside
    assert signal.door is rr.DoorOrder.SAME_EVENT  # the default door time: as the rear passes
    assert signal.outcome is rr.DoorOutcome.CAUGHT
    c_s = 0.5
    slow = rr.pole_barn(0.8, 1.0, 0.6, model="signal", sound_speed=c_s)
    assert slow.rods[0].motion.length_final == pytest.approx(c_s / ((5 / 3) * (c_s + 0.8)), rel=TOL)


@SETTINGS
@given(scene=pole_scenes(), frame=frames)
def test_pole_barn_verdicts_are_the_same_in_every_frame(scene: rr.PoleBarnScene, frame: rr.Frame) -> None:
    """Whether each pole is ever entirely inside, and the door's order against its rear end, are each one
    exact criterion of the barn's frame; the frame's own samplers agree with them wherever the margin
    exceeds rounding: late in ``frame``, ``x'_rear - x'_door`` is ``(X - D)/gamma'`` (module docstring),
    and the door's closing and the rear end's passing the door have the lab's time order."""
    late = max(scene.time_window(frame=frame, margin=1.0)[1], scene.door_closing_in(frame=frame)[0] + 1.0)
    door = float(scene.objects[1].positions(late, frame=frame)[0])
    for verdict in scene.verdicts():
        i = verdict.rod
        assert scene.inside_in(i, frame=frame) is verdict.inside is (verdict.rear_rest_x <= scene.barn_length)
        assert scene.door_order_in(i, frame=frame) is verdict.door
        gap = verdict.rear_rest_x - scene.barn_length
        rear = float(scene.positions(np.array([late]), frame=frame)[i, 1, 0])
        if abs(gap) > 1e-9 * max(scene.barn_length, abs(late)):
            assert (rear - door <= 0.0) is verdict.inside
        passes = scene.rear_passes_door(i)
        assert (passes is None) is (verdict.door is rr.DoorOrder.NEVER_PASSES) is (not verdict.inside)
        if passes is not None and verdict.door is not rr.DoorOrder.SAME_EVENT:
            t_pass = float((frame @ np.array(passes))[0])
            t_door = scene.door_closing_in(frame=frame)[0]
            if abs(t_door - t_pass) > 1e-9 * max(1.0, abs(t_door)):
                assert (t_door > t_pass) is (verdict.door is rr.DoorOrder.AFTER)


@SETTINGS
@given(scene=pole_scenes(), frame=frames)
def test_the_door_outcome_is_what_every_frame_sees_as_the_door_closes(scene: rr.PoleBarnScene, frame: rr.Frame) -> None:
    """Each verdict's outcome is what ``frame`` sees at its own time of the door's closing: caught, the
    rear end at or inside the door; on the pole, the front end inside and the rear end outside; in front
    of it, the front end not yet in (wherever the margin exceeds rounding). One criterion decides it,
    the order of three events on the door's worldline, and the words say it."""
    t_door, x_door = scene.door_closing_in(frame=frame)
    ends = scene.positions(np.array([t_door]), frame=frame)[:, :, 0]
    margin = 1e-9 * max(1.0, abs(t_door), abs(x_door))
    door = scene.objects[1].event
    assert door is not None and door.closes and (door.before, door.state) == ("open", "closed")
    words = {
        rr.DoorOutcome.CAUGHT: "inside",
        rr.DoorOutcome.ON_POLE: "spans the doorway",
        rr.DoorOutcome.SHUT_OUT: "outside",
    }
    said = ", ".join(f"{scene.rods[v.rod].name} {words[v.outcome]}" for v in scene.verdicts())
    assert door.outcome == said  # what a lane's title says from the door's closing on
    for verdict in scene.verdicts():
        front, rear = ends[verdict.rod] - x_door
        outcome = verdict.outcome
        assert outcome is scene.door_outcome(verdict.rod)
        assert (outcome is rr.DoorOutcome.CAUGHT) is (verdict.door in (rr.DoorOrder.AFTER, rr.DoorOrder.SAME_EVENT))
        if outcome is rr.DoorOutcome.CAUGHT:
            assert rear <= margin
            assert " is caught: " in verdict.text and "closes on" not in verdict.text
        elif outcome is rr.DoorOutcome.ON_POLE:
            assert front <= margin and rear >= -margin
            assert verdict.text.startswith("the door closes on ") and "spans the doorway" in verdict.text
        else:
            assert front >= -margin
            assert verdict.text.startswith("the door closes in front of ")
        if outcome is not rr.DoorOutcome.CAUGHT:  # "inside" only with the door left open, and said so
            assert "is caught" not in verdict.text
            assert ("entirely inside" in verdict.text) is verdict.inside
            assert verdict.inside is ("door left open" in verdict.text) or outcome is rr.DoorOutcome.SHUT_OUT


def test_a_roomy_barn_closes_its_door_on_the_born_rigid_pole() -> None:
    """D = 1.1 between L0 and gamma L0 (V = 0.6), the door at the paradox's instant t_d = (L0/gamma - D)/V
    = -0.5: the Born-rigid rear end, braking since T_1 = -0.75, is then at sqrt(1 + 0.25) = 1.118 on
    x = sqrt(1 + t^2), outside the door; it passes the door only at -sqrt(1.1^2 - 1) = -0.4583. The
    door closes on the pole, though once at rest (x = 1) it would lie inside."""
    scene = rr.pole_barn(0.6, 1.0, 1.1, "both")
    assert scene.door_time == pytest.approx(-0.5, rel=TOL)
    born, signal = scene.verdicts()
    assert born.inside and born.door is rr.DoorOrder.BEFORE and born.outcome is rr.DoorOutcome.ON_POLE
    assert scene.rear_at_door_time(0) == pytest.approx(math.sqrt(1.25), rel=TOL)
    passes = scene.rear_passes_door(0)
    assert passes is not None and passes[0] == pytest.approx(-math.sqrt(0.21), rel=TOL)
    assert "rear end at lab x = 1.118, outside the door at lab x = 1.1" in born.text
    assert "passes the door only at lab t = -0.4583" in born.text
    assert "only with the door left open does the pole end entirely inside" in born.text
    assert signal.outcome is rr.DoorOutcome.CAUGHT  # its rear end passes as the door closes


@pytest.mark.parametrize("v", [1e-300, 1e-12, 1e-9, 1.5e-6, 1e-6, 1e-3])
@pytest.mark.parametrize("model", ["born", "signal"])
def test_pole_verdicts_agree_with_each_other_at_small_speeds(v: float, model: str) -> None:
    """At small V the moving pole is shorter than at rest by only ``L0 V^2/2``: below V ~ 1.5e-6 that is
    under 1e-12 L0, and two criteria (one sampled with a tolerance, one exact) once said "entirely
    inside" and "the rear end never passes the door" of one pole. One exact criterion, ``X <= D``,
    answers both: the default barn ``L0/gamma`` holds the signal-limited pole, and the Born-rigid one
    only where ``L0/gamma`` rounds to ``L0`` itself (V below ~1e-8): then it fits exactly, at the door."""
    scene = rr.pole_barn(v, 1.0, model=model)  # type: ignore[arg-type]
    (verdict,) = scene.verdicts()
    assert verdict.inside is (verdict.rear_rest_x <= scene.barn_length)
    assert verdict.inside is (model == "signal" or scene.barn_length == 1.0)
    assert (verdict.door is rr.DoorOrder.NEVER_PASSES) is (not verdict.inside)
    if verdict.inside:
        assert verdict.door is rr.DoorOrder.SAME_EVENT  # the default door: the paradox's instant
    assert (verdict.outcome is rr.DoorOutcome.CAUGHT) is verdict.inside
    text = verdict.text
    assert (" is caught: " in text) is verdict.inside and ("never passes" in text) is (not verdict.inside)


@SETTINGS
@given(scene=pole_scenes(), frame=frames, f=st.floats(0.0, 1.0), u=st.floats(0.0, 1.0))
def test_born_pole_keeps_its_rest_length(scene: rr.PoleBarnScene, frame: rr.Frame, f: float, u: float) -> None:
    t0, t1 = scene.time_window(frame=frame)
    t = t0 + u * (t1 - t0)
    comoving = scene.comoving_frame(0, f, t=t, frame=frame)
    x = scene.material_positions([t], frame=frame, fractions=[f])[0, 0, 0]
    t_c = float((comoving @ (frame.inverse() @ np.array([t, x])))[0])
    length = scene.rods[0].motion.length
    assert scene.lengths([t_c], frame=comoving)[0, 0] == pytest.approx(length, rel=TOL_RIGID)


@SETTINGS
@given(scene=pole_scenes(), frame=frames, u=st.floats(0.0, 1.0))
def test_signal_pole_changes_velocity_only_inside_the_stop_fronts_future_cone(
    scene: rr.PoleBarnScene, frame: rr.Frame, u: float
) -> None:
    """Every material point of the signal-limited pole keeps its initial velocity at every event outside
    the future light cone of the contact (the stop front leaves it at c_s <= 1); its kink lies on the
    front ``x = c_s t`` in the lab, inside or on that cone in every frame."""
    fractions = np.linspace(0.0, 1.0, 9)
    t0, t1 = scene.time_window(frame=frame)
    t = np.linspace(t0, t1, 41)
    x = scene.material_positions(t, frame=frame, fractions=fractions)[1]
    v = scene.velocities(t, frame=frame, fractions=fractions)[1]
    v_initial = math.tanh(rr.Frame(scene.rods[1].motion.velocity_initial).rapidity_relative_to(frame))
    outside = t[None, :] < np.abs(x)
    assert np.all(np.abs(v[outside] - v_initial) <= 1e-12)
    motion = scene.rods[1].motion
    assert isinstance(motion, rr.PlasticMotion)
    for f in fractions:
        t_k, x_k = motion.kink(float(f))
        assert x_k == pytest.approx(scene.sound_speed * t_k, rel=1e-15, abs=1e-300)
        t_f, x_f = frame @ np.array([t_k, x_k])
        assert t_f >= abs(x_f) - 1e-12 * max(abs(t_f), 1.0)
    del u


@SETTINGS
@given(scene=pole_scenes(), frame=frames)
def test_signal_pole_four_momentum_with_heat(scene: rr.PoleBarnScene, frame: rr.Frame) -> None:
    """The plastic stop turns the kinetic energy into heat in the pole: its rest mass grows from M to
    gamma M; in the barn's frame the wall gives momentum gamma M V and no energy; in every frame
    before + from the wall = after, and the masses are invariants."""
    single = rr.pole_barn(
        -scene.rods[1].motion.velocity_initial.value,
        scene.rods[1].motion.length,
        model="signal",
        sound_speed=scene.sound_speed,
    )
    g = single.rods[0].motion.velocity_initial.lorentz_factor()
    lab = single.budget(frame=rr.LAB)
    assert lab.rest_mass_after[0] == pytest.approx(g, rel=TOL)
    assert single.heat == pytest.approx(g - 1.0, rel=1e-9)
    assert abs(lab.external[0]) <= TOL * g
    assert lab.external[1] == pytest.approx(g * -single.rods[0].motion.velocity_initial.value, rel=TOL)
    here = scene.budget(frame=frame)
    for system in here.systems:  # one pole and the wall each: never both poles summed
        (rod,) = system.system.rods
        np.testing.assert_allclose(system.total_before, here.before[rod], rtol=1e-15)
        np.testing.assert_allclose(system.total_after, here.after[rod], rtol=1e-15)
        np.testing.assert_allclose(system.total_before + system.external, system.total_after, rtol=1e-12, atol=1e-12)
        assert system.heat == pytest.approx(g - 1.0, rel=1e-12)  # M (gamma - 1), into the wall or into the pole
    with pytest.raises(ValueError, match="2 physical systems"):
        _ = here.total_before
    e, p = here.after[1]
    assert math.sqrt((e - p) * (e + p)) == pytest.approx(scene.rods[1].mass_after, rel=1e-9)


@pytest.mark.parametrize("case", reference_cases("pole-barn"), ids=lambda c: str(c["params"]))
def test_pole_barn_against_the_50_digit_reference(case: dict[str, Any]) -> None:
    params = {k: None if v is None else float.fromhex(v) for k, v in case["params"].items()}
    scene = rr.build_scene("pole-barn", **params)
    extra = {k: float(v) for k, v in case["extra"].items()}
    assert scene.rods[1].motion.length_final == pytest.approx(extra["rest_length_signal"], rel=TOL)
    for system in scene.systems:  # each stop's own heat, never the two models' summed: exact at V = 1e-6 too
        assert system.heat == pytest.approx(extra["heat"], rel=1e-12, abs=0.0)


def test_pole_barn_refuses_an_unknown_model() -> None:
    with pytest.raises(rr.ParameterError, match=r"^model must be one of"):
        rr.pole_barn(0.8, 1.0, model="elastic")  # type: ignore[arg-type]


def test_paradox_figures_state_the_verdicts() -> None:
    """The captions of the two figures carry the core's numbers and verdicts."""
    from rigidrel_app.export.paradox_figures import paradox_figures

    bell, pole = paradox_figures()
    assert "γs = 1.25 apart" in bell.caption and "from rest length 0.9 to 1.15" in bell.caption
    assert "comes to rest at x = 1; the door closes on it, in every frame" in pole.caption
    assert "x = 0.3333; the door closes behind it: it is caught inside" in pole.caption
    assert bell.chart.items and pole.chart.items
