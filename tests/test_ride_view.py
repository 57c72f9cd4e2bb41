"""The riding frame in the app's drawings: the lower lane rides a material point's comoving frame.

Born rigidity on screen: in the riding lane the ridden rod always spans its rest length, with the
point still at the lane's centre; the comoving lines of simultaneity on the diagrams pass through
the point's event and the horizon event; the length panel's comoving curve is the core's rest
length. And the ways a person asks for a ride: the frame menu, ``--ride`` in scenario strings and
``rigidrel serve``, and lesson steps.
"""

from __future__ import annotations

import subprocess
import sys
from dataclasses import replace

import numpy as np
import pytest

import rigidrel_core as rr
from rigidrel_app.lessons import lesson_from
from rigidrel_app.lessons.tour import arrival, caption_html
from rigidrel_app.view.comoving import HORIZON_NAME, RIDE_LINE_NAME, RidePoint, ride_at, simultaneity_items
from rigidrel_app.view.layout import canvas_layout
from rigidrel_app.view.scenario import ScenarioError, format_scenario, parse_scenario
from rigidrel_app.view.scene_view import RIDE_LENGTH_NAME, build_drawing, readout_markdown
from rigidrel_app.view.state import (
    CUSTOM_FRAME,
    RIDE_FRAME,
    Resolved,
    Settings,
    build,
    frame_choice,
    frame_choices,
    resolve,
)
from rigidrel_app.view.vocabulary import Label, Points, Polyline

KINDS = sorted(rr.scene_descriptions())
LAYOUT = canvas_layout(940, 720)
#: Born rigidity is exact in the core: the riding lane's rod spans its rest length to a few ulp.
REST_LENGTH_RTOL = 1e-12


def riding(kind: str, rod: int, fraction: float) -> Resolved:
    r = build(Settings(kind).riding(rod, fraction))
    assert r.ride == RidePoint(rod, fraction)
    return r


@pytest.mark.parametrize("kind", KINDS)
def test_the_riding_lane_keeps_the_rod_at_rest_length_and_the_point_still(kind: str) -> None:
    for rod in range(rr.build_scene(kind).n_rods):
        for fraction in (0.0, 0.5, 1.0):
            r = riding(kind, rod, fraction)
            d = build_drawing(r)
            length = r.scene.rods[rod].motion.length
            for now in np.linspace(*d.window, 7):
                instant = d.ride_instant(float(now))
                assert instant is not None
                lanes = d.lane_pictures(float(now), LAYOUT, instant)
                lower, place = lanes[1], LAYOUT.lanes[1]
                left, right = lower.ends[rod]
                if r.scene.rods[rod].motion.born_rigid:  # a plastic pole is not Born rigid
                    assert right - left == pytest.approx(length, rel=REST_LENGTH_RTOL), (kind, rod, fraction, now)
                    assert left + fraction * length == pytest.approx(instant.event[1], abs=1e-12 * length)
                page_x = lower.origin_px + instant.event[1] * lower.scale
                assert page_x == pytest.approx(0.5 * (place.track.x0 + place.track.x1), abs=1e-6)
                # the lab lane shows the lab at t = now, as ever
                assert lanes[0].ends == pytest.approx(r.scene.positions(np.array([now]))[:, :, 0])


def _line(items: tuple[object, ...], name: str) -> Polyline:
    lines = [it for it in items if isinstance(it, Polyline) and it.style.name == name]
    assert len(lines) == 1, [getattr(it, "style", None) for it in items]
    return lines[0]


def _on_line(line: Polyline, x: float, t: float) -> float:
    """How far (in t) the event (t, x) lies off the straight line."""
    (x0, x1), (t0, t1) = line.x, line.y
    return abs(t0 + (x - x0) * (t1 - t0) / (x1 - x0) - t)


RIDES = [
    ("constant-acceleration", 0, 0.0),
    ("wall-collision", 0, 1.0),
    ("rod-collision", 1, 0.5),
    ("bell-spaceships", 0, 0.0),
]


@pytest.mark.parametrize(("kind", "rod", "fraction"), RIDES)
def test_the_comoving_line_sweeps_through_the_point_and_the_horizon(kind: str, rod: int, fraction: float) -> None:
    r = riding(kind, rod, fraction)
    d = build_drawing(r)
    lab_frame, chosen = rr.LAB, r.frame
    scale = max(abs(v) for v in (*d.window, *d.x_range))
    slopes = set()
    met = 0
    for now in np.linspace(*d.window, 9):
        instant = d.ride_instant(float(now))
        assert instant is not None
        lanes = d.lane_pictures(float(now), LAYOUT, instant)
        lab, frame, length = d.moving_items(float(now), [lane.ends for lane in lanes], instant)
        motion = r.scene.rods[rod].motion
        ends_of_change = (motion.velocity_initial, motion.velocity_final)
        changing = not any(instant.frame.same_velocity(rr.Frame(v)) for v in ends_of_change)
        for items, seen_from in ((lab, lab_frame), (frame, chosen)):
            line = _line(items, RIDE_LINE_NAME)
            te, xe = seen_from @ np.array(instant.event_lab)
            th, xh = r.scene.horizon_event(rod, frame=seen_from)
            assert _on_line(line, float(xe), float(te)) <= 1e-9 * scale
            if changing:  # while the point accelerates, its line of simultaneity meets the horizon event
                assert _on_line(line, float(xh), float(th)) <= 1e-9 * scale * max(1.0, abs(xh))
                met += 1
        # the second diagram marks the riding lane's rod ends, boosted there: on the comoving line
        line = _line(frame, RIDE_LINE_NAME)
        marks = [it for it in frame if isinstance(it, Points) and it.symbol == "diamond"]
        assert marks
        assert all(_on_line(line, float(x), float(t)) <= 1e-9 * scale for m in marks for x, t in zip(m.x, m.y))
        slopes.add(round(float(np.diff(_line(lab, RIDE_LINE_NAME).y)[0]), 9))
        # the length panel's marker for the riding lane: the ridden rod at its rest length
        assert any(
            isinstance(it, Points) and np.isclose(it.y, r.scene.rods[rod].motion.length, rtol=1e-12).any()
            for it in length
        )
    assert len(slopes) > 1, "the comoving line must sweep as the point accelerates"
    assert met > 0, "no instant of the change was sampled"


def test_the_length_panel_and_the_diagrams_name_the_ride() -> None:
    r = riding("constant-acceleration", 0, 0.0)
    d = build_drawing(r)
    assert d.ride is not None
    np.testing.assert_allclose(d.ride.lengths[0], r.scene.rods[0].motion.length, rtol=REST_LENGTH_RTOL)
    names = {getattr(it, "style", None) and it.style.name for it in d.length_chart.items}  # type: ignore[union-attr]
    assert f"rod, {RIDE_LENGTH_NAME}" in names
    assert "rod, rod after (t′)" not in names  # the chosen frame's curve gives way to the ride's
    # the horizon (lab (-1, 0) here: 1/a_B = 1/a_F - L0 = 1) is on both diagrams
    for chart in (d.lab_chart, d.frame_chart):
        assert any(isinstance(it, Points) and it.style.name == HORIZON_NAME for it in chart.items)
    text = readout_markdown(r)
    assert "rides: comoving with rod at f = 0" in text and "rod after" in text


def test_the_pivot_event_is_named_an_event_not_a_horizon() -> None:
    """Every comoving line of simultaneity passes one event, the centre of the point's hyperbola: the
    horizon is that event's light cone, so the square's legend and label call it the pivot event."""
    assert HORIZON_NAME == "pivot event (the horizon's vertex)"
    r = riding("wall-collision", 0, 1.0)
    instant = ride_at(r.scene, RidePoint(0, 1.0), -0.5)
    assert instant.horizon_lab == pytest.approx((0.0, 0.0), abs=1e-15)  # the contact itself
    labels = [it.text for it in simultaneity_items(instant, 1.0) if isinstance(it, Label)]
    assert labels == ["pivot"]


def test_the_frame_menu_and_the_settings() -> None:
    s = Settings.of("rod-collision").riding(1, 0.25)
    r = build(s)
    assert RIDE_FRAME in frame_choices(r.scene)
    assert frame_choice(r.scene, r.frame, r.ride) == RIDE_FRAME
    assert r.frame == rr.default_frame(r.scene)  # the second diagram keeps the scene's default frame
    # another scene rides the same share of its first rod
    assert s.with_scene("wall-collision").ride == RidePoint(0, 0.25)
    # a rod the scene does not have is a notice naming the ride, never an exception
    bad = resolve(Settings.of("wall-collision").riding(1, 0.5))
    assert isinstance(bad, str) and bad.startswith("Ride point refused: ride must be a rod of the scene, 1..1; got 2")
    bad = resolve(Settings.of("wall-collision").riding(0, float("nan")))
    assert isinstance(bad, str) and "[0, 1]" in bad
    # not riding: the ride is kept but unused
    assert build(Settings.of("rod-collision")).ride is None
    assert build(Settings("rod-collision", (), CUSTOM_FRAME, 0.3).riding(1, 0.5)).ride is not None


def test_scenario_strings_ride() -> None:
    line = "rod-collision --v1 0.6 --mass2 2 --v2 0 --length2 1 --eps 1 --ride 2:0.25"
    scenario = parse_scenario(line)
    assert scenario.settings.frame == RIDE_FRAME and scenario.settings.ride == RidePoint(1, 0.25)
    assert format_scenario(scenario.settings) == line
    assert parse_scenario("wall-collision --ride 1").settings.ride == RidePoint(0, 1.0)
    bad = ("rod-collision --ride 3:0.5", "wall-collision --ride 1.5", "wall-collision --ride x:1",
           "wall-collision --ride 1 --frame lab")  # fmt: skip
    for text in bad:
        with pytest.raises(ScenarioError) as err:
            parse_scenario(text)
        assert err.value.parameter == "ride" and "ride" in str(err.value)


def test_a_riding_lesson_step_rides_live() -> None:
    lesson = lesson_from("paper")
    step = next(s for s in lesson.steps if s.ride is not None)
    a = arrival(step)
    r = build(a.settings)
    assert r.ride == step.ride
    assert "default frame" not in caption_html(step)


@pytest.mark.slow  # a new interpreter
@pytest.mark.parametrize(
    ("args", "message"),
    [
        (["rod-collision", "--ride", "3:0.5"], "--ride: ride must be a rod of the scene, 1..2; got 3"),
        (["wall-collision", "--ride", "x"], "--ride needs ROD:F"),
        (["wall-collision", "--ride", "1", "--frame", "lab"], "give --ride or --frame"),
    ],
)
def test_serve_refuses_a_bad_ride_in_one_line(args: list[str], message: str) -> None:
    done = subprocess.run(
        [sys.executable, "-m", "rigidrel_app.cli", "serve", *args], capture_output=True, text=True, timeout=60
    )
    assert done.returncode == 2
    lines = done.stderr.strip().splitlines()
    assert len(lines) == 1 and message in lines[0], done.stderr


def test_the_riding_lane_carries_the_light_pulse_boosted_from_the_lab() -> None:
    """With the light-signal layer, the riding lane shows the lab's rays as its frame sees them:
    each leg still at 45 degrees (the core's boost is exact on the light cone)."""
    from rigidrel_app.view.layers import DEFAULT_LAYERS, Layer
    from rigidrel_app.view.vocabulary import LIGHT_COLOR

    r = build(
        replace(Settings.of("wall-collision", v=0.6, eps=0.0), layers=DEFAULT_LAYERS | {Layer.SIGNALS}).riding(0, 1.0)
    )
    d = build_drawing(r)
    assert d.signals is not None
    now = 0.3  # the first light from the contact is on its way to the back end
    instant = d.ride_instant(now)
    assert instant is not None
    seen = d.signals[0].seen_from(instant.frame)
    for leg in seen.legs:
        (t0, x0), (t1, x1) = leg.source, leg.arrival
        assert abs(t1 - t0) == pytest.approx(abs(x1 - x0), rel=1e-12)
    pulses = seen.pulses_at(instant.event[0])
    assert pulses, "a pulse is in flight at this instant"
    lower = d.lane_pictures(now, LAYOUT, instant)[1]
    light = [s for s in lower.segments if s.style.color == LIGHT_COLOR]
    assert light and light[0].x0.size > 0
    centre = lower.origin_px + pulses[0] * lower.scale
    assert np.min(np.abs(light[0].x0 - centre)) < 4.0  # the pulse bar is drawn where the boosted ray is


@pytest.mark.parametrize("kind", KINDS)
def test_every_scene_rides_with_its_signals_and_verdicts(kind: str) -> None:
    """The signal layer in the riding frame, in every scene: pulses in the riding lane where the
    lab's rays cross its instant, the verdicts in words (frame-independent) in the readout."""
    from rigidrel_app.view.layers import DEFAULT_LAYERS, Layer

    settings = replace(Settings(kind), layers=DEFAULT_LAYERS | {Layer.SIGNALS}).riding(0, 0.5)
    r = build(settings)
    d = build_drawing(r)
    assert d.signals is not None
    for now in np.linspace(*d.window, 5):
        instant = d.ride_instant(float(now))
        lanes = d.lane_pictures(float(now), LAYOUT, instant)
        charts = d.moving_items(float(now), [lane.ends for lane in lanes], instant)
        assert all(np.all(np.isfinite(lane.ends)) for lane in lanes)
        assert len(charts) == 3
    text = readout_markdown(r)
    fixed = readout_markdown(build(replace(settings, frame=None)))
    assert "**Light**" in text
    assert text.split("**Light**", 1)[1] == fixed.split("**Light**", 1)[1]  # the same verdicts, riding or not
