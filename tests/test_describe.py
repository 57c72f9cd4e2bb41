"""The canvas in words (``rigidrel_app.view.describe``): every number from the core, every rod and
its ends, the events passed, the verdicts; and ``rigidrel describe`` prints it."""

from __future__ import annotations

import re

import pytest

import rigidrel_core as rr
from rigidrel_app.cli import main
from rigidrel_app.view.describe import describe
from rigidrel_app.view.objects import object_words
from rigidrel_app.view.signals import verdict_lines
from rigidrel_app.view.state import Resolved, Settings, resolve


def _resolved(kind: str) -> Resolved:
    r = resolve(Settings(kind))
    assert isinstance(r, Resolved)
    return r


def _spoken(x: float) -> str:
    return f"{round(float(x), 3) + 0.0:.3f}".replace("-", "minus ")


def _object_said(obj: rr.SceneObject, frame: rr.Frame, now: float) -> str:
    value = None if obj.field is None else float(obj.field.values([now], frame=frame)[0])
    return object_words(obj, value, bool(obj.happened([now], frame=frame)[0]))


@pytest.mark.parametrize("kind", list(rr.scene_descriptions()))
def test_each_rod_of_each_lane_is_where_the_core_puts_it(kind: str) -> None:
    r = _resolved(kind)
    window = r.scene.time_window(frame=r.frame)
    for now in (window[0], 0.0, 0.5 * (window[0] + window[1]), window[1]):
        d = describe(r, now)
        assert len(d.lanes) == 2
        for lane, frame in zip(d.lanes, (rr.LAB, r.frame), strict=True):
            x, tau = r.scene.snapshot(now, frame=frame, fractions=(0.0, 1.0))
            lengths = r.scene.lengths(now, frame=frame)
            switches = r.scene.switch_times(frame=frame)
            parts = lane.split(": ", 1)[1].rstrip(".").split("; ")
            things = [_object_said(o, frame, now) for o in r.scene.objects]
            assert parts[r.scene.n_rods :] == [t for t in things if t]  # after the rods, the door or the string
            for k, (rod, part) in enumerate(zip(r.scene.rods, parts[: r.scene.n_rods], strict=True)):
                assert part.startswith(rod.name + " from x")
                assert f"= {_spoken(x[k, 0])} to {_spoken(x[k, 1])}, length {_spoken(lengths[k])}," in part
                assert f"reading {_spoken(tau[k, 0])} (left) and {_spoken(tau[k, 1])} (right)" in part
                moving = [switches[k, e, 0] <= now < switches[k, e, 1] for e in range(2)]
                said = {
                    (True, True): "both ends accelerating",
                    (True, False): "its left end accelerating",
                    (False, True): "its right end accelerating",
                    (False, False): "neither end accelerating",
                }[(moving[0], moving[1])]
                assert said in part


def test_events_passed_and_verdicts_are_the_cores() -> None:
    r = _resolved("rod-collision")
    lab = r.scene.events
    for now in sorted(t for t, _ in lab.values()):
        text = describe(r, now).events[0]
        named = set(re.findall(r"(\S+) at t = ", text))
        assert named == {e for e, (t, _) in lab.items() if t <= now}
    before = min(t for t, _ in lab.values()) - 1.0
    assert "no named event has happened yet" in describe(r, before).events[0]
    assert describe(r, 0.0).verdicts == tuple(f"Causality: {v}" for v in verdict_lines(r.scene))


def test_the_summary_names_the_scene_its_parameters_and_both_frames() -> None:
    r = _resolved("wall-collision")
    d = describe(r, 0.0)
    desc = rr.describe(r.scene)
    assert d.summary.startswith(desc.title) and desc.source in d.summary
    for key in r.scene.parameters:
        assert desc.parameter(key).label in d.scene
    assert "Upper lane: the lab frame" in d.summary and "Lower lane:" in d.summary
    assert d.full.splitlines()[:2] == [d.scene, d.frames]


def test_a_lab_step_is_said_as_its_one_lane() -> None:
    """The chosen frame the lab's own: the canvas shows one lane (and one diagram), and says so."""
    r = resolve(Settings("wall-collision", frame="lab"))
    assert isinstance(r, Resolved) and r.lab_only
    d = describe(r, 0.0)
    assert "One lane: the lab frame" in d.summary and "Lower lane" not in d.full
    assert len(d.lanes) == len(d.events) == 1 and d.lanes[0].startswith("The lab lane")


def test_rigidrel_describe_prints_it_and_refuses_a_bad_time(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["describe", "impulsive-start", "--v", "0.8", "--at", "0.25"]) == 0
    out = capsys.readouterr().out
    r = resolve(Settings("impulsive-start").with_value("v", 0.8))
    assert isinstance(r, Resolved)
    assert out.strip() == describe(r, 0.25).full
    with pytest.raises(SystemExit) as bad:
        main(["describe", "impulsive-start", "--at", "inf"])
    assert bad.value.code == 2
    assert "--at must be a finite time" in capsys.readouterr().err


def test_the_barn_door_is_said_open_or_closed_at_its_closing_instant_in_each_lane() -> None:
    """Between the lab's closing instant and the pole's, the lab lane says the door is closed and
    the pole's lane that it is still open (the event's time differs between the frames)."""
    r = resolve(Settings("pole-barn", frame="pole before"))
    assert isinstance(r, Resolved)
    door = next(o for o in r.scene.objects if o.kind is rr.ObjectKind.BARN_DOOR)
    lab_close, pole_close = door.event_in(frame=rr.LAB), door.event_in(frame=r.frame)
    assert lab_close is not None and pole_close is not None and lab_close[0] < pole_close[0]
    lab, pole = describe(r, 0.5 * (lab_close[0] + pole_close[0])).lanes
    assert lab.endswith("; door closed (Born-rigid pole spans the doorway, signal-limited pole inside).")
    assert pole.endswith("; door open.")
