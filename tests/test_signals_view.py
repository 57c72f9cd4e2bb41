"""The light-signal layer of the view: rays, cone, pulse and verdicts, checked against the core."""

from __future__ import annotations

import numpy as np
import pytest

import rigidrel_core as rr
from rigidrel_app.view.signals import future_cone, signal_items, signals_in, verdict_lines, with_signals
from rigidrel_app.view.vocabulary import Area, Label, Segments

KINDS = tuple(rr.scene_descriptions())
REL = 1e-12


def _frames(scene: rr.Scene, kind: str) -> list[rr.Frame]:
    return [scene.frame(name) for name in rr.describe(kind).frames] + [rr.Frame.from_velocity(-0.99)]


@pytest.mark.parametrize("kind", KINDS)
def test_every_leg_is_a_light_ray_ending_on_its_rod(kind: str) -> None:
    scene = rr.build_scene(kind)
    for frame in _frames(scene, kind):
        signals = signals_in(scene, frame)
        assert signals.legs, f"{kind}: no signal drawn in {frame.name}"
        for leg in signals.legs:
            (t0, x0), (t1, x1) = leg.source, leg.arrival
            scale = max(abs(t0), abs(t1), abs(x0), abs(x1), 1.0)
            assert t1 > t0
            assert abs(abs(x1 - x0) - (t1 - t0)) <= REL * scale * 10, (kind, frame.name, leg)
            rod = int(leg.name.split("_")[1]) - 1 if "_" in leg.name else 0
            ends = scene.positions(np.array([t1]), frame=frame)[rod, :, 0]
            assert np.min(np.abs(ends - x1)) <= REL * scale * 10, (kind, frame.name, leg, ends)


@pytest.mark.parametrize("kind", KINDS)
def test_the_signals_are_the_same_events_in_every_frame(kind: str) -> None:
    scene = rr.build_scene(kind)
    lab = signals_in(scene, rr.LAB)
    for frame in _frames(scene, kind):
        here = signals_in(scene, frame)
        assert [leg.name for leg in here.legs] == [leg.name for leg in lab.legs]
        for a, b in zip(lab.legs, here.legs, strict=True):
            boosted = frame @ np.array([a.arrival])
            scale = max(1.0, float(np.abs(boosted).max()))
            assert np.allclose(boosted[0], b.arrival, rtol=0, atol=1e-11 * scale), (kind, frame.name, a, b)


def test_wall_bounce_signal_reaches_the_far_end_at_2_2() -> None:
    """The worked case: V = 0.6, L0 = 1, elastic; the far end finished changing at T'_1 = (0.75, 1.25)."""
    scene = rr.wall_collision(0.6, 1.0, 1.0)
    signals = signals_in(scene, rr.LAB)
    assert signals.legs[0].arrival == pytest.approx((2.0, 2.0), rel=1e-15)
    # back toward the near end, which now moves at +0.6: 2 - (t - 2) = 0.6 t
    assert signals.legs[1].arrival == pytest.approx((2.5, 1.5), rel=1e-15)
    assert signals.pulse_positions(1.0).tolist() == pytest.approx([1.0])
    assert signals.pulse_positions(2.25).tolist() == pytest.approx([1.75])
    assert signals.pulse_positions(3.0).size == 0
    assert signals.pulse_positions(-0.5).size == 0


def test_the_cone_is_clipped_to_the_chart() -> None:
    cone = future_cone((0.0, 0.0), (-2.0, 3.0), (-1.0, 2.0))
    assert cone.shape[0] >= 3
    assert cone[:, 0].min() >= -2.0 and cone[:, 0].max() <= 3.0
    assert cone[:, 1].min() >= -1.0 and cone[:, 1].max() <= 2.0
    assert np.all(cone[:, 1] + 1e-12 >= np.abs(cone[:, 0]))  # every corner in the future cone
    assert {(2.0, 2.0), (-2.0, 2.0), (0.0, 0.0)} <= {(float(x), float(t)) for x, t in cone}
    assert future_cone((0.0, 0.0), (-1.0, 1.0), (-3.0, -0.5)).shape[0] == 0  # all before the event


def test_items_name_every_arrival() -> None:
    scene = rr.build_scene("rod-collision")
    signals = signals_in(scene, rr.LAB)
    items = signal_items(signals, (-3.0, 3.0), (-2.0, 3.0))
    labels = [i.text for i in items if isinstance(i, Label)]
    assert len(labels) == len(signals.legs) == 4
    assert any(isinstance(i, Area) for i in items)
    rays = [i for i in items if isinstance(i, Segments)]
    assert len(rays) == 1 and rays[0].x0.size == 4


@pytest.mark.parametrize("kind", KINDS)
def test_verdicts_are_words_from_the_core(kind: str) -> None:
    lines = verdict_lines(rr.build_scene(kind))
    assert lines and all(line.endswith(".") for line in lines)


def test_crash_verdict_says_no_signal_caused_the_far_end() -> None:
    (line,) = verdict_lines(rr.wall_collision(0.6, 1.0, 0.0))
    assert "outside the light cone of the contact" in line and "in any frame" in line


def test_with_signals_adds_the_layer_to_a_diagram() -> None:
    from rigidrel_app.view.diagrams import minkowski_in_frame

    scene = rr.wall_collision(0.6, 1.0, 0.0)
    chart = minkowski_in_frame(scene, rr.LAB, (400.0, 400.0))
    drawn = with_signals(chart, scene, rr.LAB)
    added = drawn.items[len(chart.items) :]
    assert drawn.items[: len(chart.items)] == chart.items
    assert {i.style.group for i in added} == {"signals"}
    assert [i.text for i in added if isinstance(i, Label)] == ["<b>S</b>", "<b>R</b>"]


def test_the_light_cone_of_a_named_event() -> None:
    from rigidrel_app.view.signals import event_cone_items

    scene = rr.wall_collision(0.6, 1.0, 0.0)
    frame = scene.frame("rod before")
    items = event_cone_items(scene, "T_1", frame, (-3.0, 3.0), (-3.0, 3.0))
    tk, xk = scene.events_in(frame=frame)["T_1"]
    areas = [i for i in items if isinstance(i, Area)]
    assert len(areas) == 2 and not any(a.style.name for a in areas)  # the legend names the rays
    for area, sign in zip(areas, (1.0, -1.0), strict=True):  # every corner on or inside its half of the cone
        dt, dx = sign * (area.y - tk), area.x - xk
        assert np.all(dt + 1e-12 >= np.abs(dx))
    (rays,) = [i for i in items if isinstance(i, Segments)]
    assert (rays.style.name, rays.style.dash) == ("light cone of <b>T<sub>1</sub></b>", "dot")
    slopes = (rays.y1 - rays.y0) / (rays.x1 - rays.x0)
    assert sorted(slopes.tolist()) == pytest.approx([-1.0, 1.0])
    assert event_cone_items(scene, "contact", frame, (-3.0, 3.0), (-3.0, 3.0))[-1].style.name == (
        "light cone of the contact"
    )
