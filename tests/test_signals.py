"""Light signals, causal relations and comoving frames of every registered scene (c = 1).

Properties that need no reference: an arrival lies on the material point's worldline and on the
source's light cone, in every frame, and the arrival seen from another frame is the boosted one;
the causal relation of two events is the same in every frame; in a point's comoving frame the
point is at rest and the rod has its rest length.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import rigidrel_core as rr
from tests.strategies import scene_and_frame

SETTINGS = settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])

#: An arrival on the point's worldline: |x(t_arrival) - x_arrival|, relative to the largest of the
#: source's and the arrival's |t| and |x| and the rest length.
TOL_ON_WORLDLINE = 1e-13
#: The same arrival computed in two frames, relative to max(|t'|, |x'|, rest length) times gamma.
TOL_COVARIANT = 1e-12
#: A comoving frame: the point's speed in it, and the rod's equal-time length there relative to L0.
TOL_COMOVING = 1e-9


def test_wall_bounce_signal_reaches_the_far_end_after_its_change() -> None:
    """The worked case: elastic bounce, V = 0.6, L0 = 1. The contact's signal reaches the far end
    at lab (2, 2), after its change ends at T'_1 = (0.75, 1.25); the change is spacelike to the contact."""
    scene = rr.build_scene("wall-collision", v=0.6, length=1.0, eps=1.0)
    assert scene.signal_arrival("contact", 0, 1.0) == (2.0, 2.0)
    assert scene.events["T_1'"] == (0.75, 1.25)
    for name in ("T_1", "T_1'"):
        relation = rr.causal_relation((0.0, 0.0), scene.events[name])
        assert relation.kind == "spacelike" and not relation.can_signal
    assert rr.causal_relation((0.0, 0.0), (2.0, 2.0)).kind == "lightlike"


def test_a_signal_sent_away_from_the_point_never_reaches_it() -> None:
    scene = rr.build_scene("wall-collision", v=0.6, length=1.0, eps=1.0)
    assert scene.signal_arrival("contact", 0, 1.0, direction=-1) is None


def test_the_kick_is_the_far_ends_horizon() -> None:
    """A signal from the kick cannot catch the far end while it is on its hyperbola (the kick is
    that hyperbola's centre): it arrives after the far end has its final velocity."""
    scene = rr.build_scene("impulsive-start", v=0.6, length=1.0)
    t, x = scene.signal_arrival("kick", 0, 1.0) or (math.nan, math.nan)
    t_stop = scene.events["T_F"][0]
    assert t > t_stop
    assert x == pytest.approx(1.0 + 0.6 * (t - t_stop) + (scene.events["T_F"][1] - 1.0), rel=1e-15)


def test_an_arrival_far_from_its_source_is_on_the_light_cone_to_the_sources_rounding() -> None:
    """A source 26 units from where its signal arrives (a slow rod, a long window): the arrival is on
    the light cone to the rounding of coordinates that large (a case the property test below found,
    when its tolerance went only with the arrival's coordinates)."""
    scene = rr.build_scene("constant-acceleration", v=0.5569031991501275, length=1.9, a_front=0.010000000000000002)
    t0, _ = scene.time_window(frame=rr.LAB)
    source = (t0, 27.0)
    t, x = scene.signal_arrival(source, 0, 0.5) or (math.nan, math.nan)
    assert t - source[0] == pytest.approx(26.017190215183827, rel=1e-14)
    assert abs(abs(x - source[1]) - (t - source[0])) <= 4 * 2.0**-52 * 27.0


@SETTINGS
@given(scene_frame=scene_and_frame(), f=st.floats(0.0, 1.0), u=st.floats(0.0, 1.0), data=st.data())
def test_arrivals_lie_on_the_worldline_and_the_light_cone(
    scene_frame: tuple[rr.Scene, rr.Frame], f: float, u: float, data: st.DataObject
) -> None:
    scene, frame = scene_frame
    t0, t1 = scene.time_window(frame=frame)
    x_span = scene.positions(np.array([t0, t1]), frame=frame)
    source = (t0 + u * (t1 - t0), data.draw(st.floats(float(x_span.min()), float(x_span.max()))))
    rod = data.draw(st.integers(0, scene.n_rods - 1))
    length = scene.rods[rod].motion.length
    arrival = scene.signal_arrival(source, rod, f, frame=frame)
    assert arrival is not None  # toward the point, a signal always arrives (every change ends)
    t, x = arrival
    # the arrival is worked out from the source's coordinates: its rounding, and the rounding of the
    # differences below, go with the larger of the two events' coordinates
    scale = max(abs(t), abs(x), abs(source[0]), abs(source[1]), length)
    on_line = scene.material_positions(np.array([t]), frame=frame, fractions=[f])[rod, 0, 0]
    assert abs(on_line - x) <= TOL_ON_WORLDLINE * scale
    assert t >= source[0] - 4 * 2.0**-52 * scale  # in the source's future (to rounding)
    assert abs(abs(x - source[1]) - (t - source[0])) <= 4 * 2.0**-52 * scale  # on the light cone
    direction = 1 if x > source[1] else -1
    if abs(x - source[1]) > TOL_ON_WORLDLINE * scale:  # not a source on the worldline, to rounding
        assert scene.signal_arrival(source, rod, f, direction=-direction, frame=frame) is None


@SETTINGS
@given(scene_frame=scene_and_frame(), f=st.floats(0.0, 1.0), beta=st.floats(-0.999, 0.999))
def test_arrivals_are_covariant(scene_frame: tuple[rr.Scene, rr.Frame], f: float, beta: float) -> None:
    """The arrival of the origin event's signal computed in one frame is the boosted arrival of another."""
    scene, frame = scene_frame
    other = rr.Frame.from_velocity(beta)
    for rod in range(scene.n_rods):
        here = scene.signal_arrival(scene.origin_event.value, rod, f, frame=frame)
        there = scene.signal_arrival(scene.origin_event.value, rod, f, frame=other)
        assert (here is None) == (there is None)
        if here is None or there is None:
            continue
        boosted = other @ (frame.inverse() @ np.array(here))
        scale = max(abs(here[0]), abs(here[1]), scene.rods[rod].motion.length) * frame.lorentz_factor
        scale *= other.lorentz_factor
        assert np.all(np.abs(boosted - np.array(there)) <= TOL_COVARIANT * scale)


@SETTINGS
@given(scene_frame=scene_and_frame(), a=st.tuples(st.floats(-10, 10), st.floats(-10, 10)), b=st.data())
def test_causal_relations_are_the_same_in_every_frame(
    scene_frame: tuple[rr.Scene, rr.Frame], a: tuple[float, float], b: st.DataObject
) -> None:
    """The relation of each scene event to the origin event, and of two arbitrary events, in any frame."""
    scene, frame = scene_frame
    lab = {name: rr.causal_relation((0.0, 0.0), e) for name, e in scene.events.items()}
    here = {name: rr.causal_relation((0.0, 0.0), e) for name, e in scene.events_in(frame=frame).items()}
    for name, relation in lab.items():
        if relation.kind != "lightlike":
            assert here[name].kind == relation.kind, name
            assert here[name].order == relation.order, name
    other = b.draw(st.tuples(st.floats(-10, 10), st.floats(-10, 10)))
    r_lab = rr.causal_relation(a, other)
    r_frame = rr.causal_relation(frame @ np.array(a), frame @ np.array(other))
    if abs(r_lab.interval) > 1e-9 * (1 + abs(a[0]) + abs(a[1]) + abs(other[0]) + abs(other[1])) ** 2:
        assert (r_lab.kind, r_lab.order) == (r_frame.kind, r_frame.order)


@SETTINGS
@given(scene_frame=scene_and_frame(), f=st.floats(0.0, 1.0), u=st.floats(0.0, 1.0))
def test_in_its_comoving_frame_a_point_rests_and_the_rod_has_its_rest_length(
    scene_frame: tuple[rr.Scene, rr.Frame], f: float, u: float
) -> None:
    """Born rigidity: at each instant the momentarily comoving frame of any point sees the rod at rest
    length L0, with the point at rest (the comoving frame is the one the app's lane rides)."""
    scene, frame = scene_frame
    t0, t1 = scene.time_window(frame=frame)
    t = t0 + u * (t1 - t0)
    for rod in range(scene.n_rods):
        if not scene.rods[rod].motion.born_rigid:
            continue  # a signal-limited stop is not rigid (tests/test_paradoxes.py)
        comoving = scene.comoving_frame(rod, f, t=t, frame=frame)
        x = scene.material_positions(np.array([t]), frame=frame, fractions=[f])[rod, 0, 0]
        t_comoving = float((comoving @ (frame.inverse() @ np.array([t, x])))[0])
        v = scene.velocities(np.array([t_comoving]), frame=comoving, fractions=[f])[rod, 0, 0]
        assert abs(v) <= TOL_COMOVING
        length = scene.lengths(np.array([t_comoving]), frame=comoving)[rod, 0]
        assert length == pytest.approx(scene.rods[rod].motion.length, rel=TOL_COMOVING)


def test_comoving_frames_at_the_ends_of_the_change_are_the_rods_frames_exactly() -> None:
    scene = rr.build_scene("constant-acceleration")
    assert scene.comoving_frame(0, 0.5, proper_time=-1.0).same_velocity(scene.frame("rod before"))
    assert scene.comoving_frame(0, 0.5, proper_time=1e3).same_velocity(scene.frame("rod after"))


@pytest.mark.parametrize(
    ("call", "parameter"),
    [
        (lambda s: s.signal_arrival("T_9", 0, 1.0), "source"),
        (lambda s: s.signal_arrival("contact", 2, 1.0), "rod"),
        (lambda s: s.signal_arrival("contact", 0, 1.5), "fraction"),
        (lambda s: s.signal_arrival("contact", 0, 1.0, direction=2), "direction"),
        (lambda s: s.signal_arrival((0.0, math.nan), 0, 1.0), "source"),
        (lambda s: s.comoving_frame(0, 0.5), "proper_time"),
        (lambda s: s.comoving_frame(0, 0.5, t=math.inf), "t"),
        (lambda s: rr.causal_relation((0.0,), (1.0, 2.0)), "a"),
    ],
)
def test_bad_arguments_name_the_parameter(call: object, parameter: str) -> None:
    scene = rr.build_scene("wall-collision")
    with pytest.raises(rr.ParameterError) as info:
        call(scene)  # type: ignore[operator]
    assert info.value.parameter == parameter


def test_wall_crash_verdict_in_words() -> None:
    """The paper's Sec. 4 crash: the far end starts decelerating before the front touches the wall in
    the lab, but its whole change is spacelike to the contact: no signal caused it."""
    scene = rr.build_scene("wall-collision", v=0.6, length=1.0, eps=0.0)
    (verdict,) = scene.causal_verdicts()
    assert verdict.text.startswith(
        "the right end: its whole change, from T_1 to T_1', lies outside the light cone of the contact: "
        "no signal from the contact can have caused it, in any frame."
    )
    assert not verdict.caused_by_a_signal
    assert verdict.start[0] < 0.0  # before the contact, in the lab
    assert verdict.text.endswith("The first light signal from the contact reaches it at (lab t, x) = (1, 1).")


def test_a_verdict_gives_its_events_in_the_frame_asked_for() -> None:
    """The kinds are the lab's (invariants); the events and every coordinate pair in the words are the
    frame's, labelled with it: the wall crash seen at beta = 0.3 (lab arrival (1, 1), boosted)."""
    scene = rr.build_scene("wall-collision", v=0.6, length=1.0, eps=0.0)
    frame = rr.Frame.from_velocity(0.3, "custom")
    (lab,) = scene.causal_verdicts()
    (seen,) = scene.causal_verdicts(frame=frame)
    assert (seen.relation_start, seen.relation_stop) == (lab.relation_start, lab.relation_stop)
    assert seen.frame is frame and lab.frame is rr.LAB
    assert seen.arrival is not None
    assert seen.arrival == pytest.approx(tuple(frame @ np.array([1.0, 1.0])), rel=1e-15)
    assert seen.start == scene.events_in(frame=frame)["T_1"] and seen.stop == scene.events_in(frame=frame)["T_1'"]
    t, x = seen.arrival
    assert seen.text.endswith(f"reaches it at (t, x) = ({t:.4g}, {x:.4g}) in the frame 'custom' (β = 0.3).")
    assert "(1, 1)" not in seen.text


def test_fig1_front_stops_exactly_on_the_starts_light_cone() -> None:
    """V = 0.6, a'_F L0 = 1/2: T_F = (gamma V/a'_F, L0 + (gamma - 1)/a'_F) = (1.5, 1.5), on the light cone
    of the back end's start, since a'_F L0 = 1 - gamma (1 - V) = 1 - e^-theta exactly here."""
    scene = rr.build_scene("constant-acceleration", v=0.6, length=1.0, a_front=0.5)
    (verdict,) = scene.causal_verdicts()
    assert verdict.relation_start.kind == "spacelike"
    assert (verdict.relation_stop.kind, verdict.relation_stop.order) == ("lightlike", 1)
    assert verdict.arrival == (1.5, 1.5)


@SETTINGS
@given(scene_frame=scene_and_frame())
def test_verdicts_hold_in_every_frame(scene_frame: tuple[rr.Scene, rr.Frame]) -> None:
    """Each verdict's relations, recomputed from the change's events seen in any frame, are the same
    (relative to the scene's cause: the origin event, or a kick elsewhere)."""
    scene, frame = scene_frame
    cause = scene.cause()
    origin = (0.0, 0.0) if cause is None else cause[2]
    for verdict in scene.causal_verdicts():
        for event, relation in ((verdict.start, verdict.relation_start), (verdict.stop, verdict.relation_stop)):
            seen = rr.causal_relation(frame @ np.array(origin), frame @ np.array(event))
            size = (event[0] - origin[0]) ** 2 + (event[1] - origin[1]) ** 2
            if relation.kind != "lightlike" and abs(relation.interval) > 1e-9 * size:
                assert (seen.kind, seen.order) == (relation.kind, relation.order)
        if verdict.arrival is not None:  # off the origin, to the rounding of the arrival's t and x
            relation = rr.causal_relation(origin, verdict.arrival)
            size = (verdict.arrival[0] - origin[0]) ** 2 + (verdict.arrival[1] - origin[1]) ** 2
            assert relation.kind == "lightlike" if origin == (0.0, 0.0) else abs(relation.interval) <= 1e-14 * size
