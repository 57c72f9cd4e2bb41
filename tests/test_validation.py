"""Bad input: every core entry point raises ValueError naming the parameter and its allowed range.

The scene parameters and their ranges come from the registry (``rr.scene_descriptions()``):
a scene registered in rigidrel_core/scenes/ has its bad values tested here with no edit.
"""

from __future__ import annotations

import inspect
import math
import re
from collections.abc import Callable
from typing import Any

import numpy as np
import numpy.typing as npt
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import rigidrel_core as rr
from tests.strategies import bad_numbers, bad_values, descriptions

FloatArray = npt.NDArray[np.float64]

#: Every (scene, parameter) pair of the registry, as pytest ids "kind:parameter".
PARAMETERS = [(d.kind, p.name) for d in descriptions() for p in d.parameters]
#: Frame velocities as extreme as the samplers promise to handle.
EXTREME_FRAMES = (rr.Frame.from_velocity(0.999999), rr.Frame.from_velocity(-0.999999))


def raised(build: Callable[[], object]) -> str:
    """The message of the ValueError ``build()`` raises (the test fails if it raises nothing)."""
    with pytest.raises(ValueError) as info:
        build()
    return str(info.value)


# ---------------------------------------------------------------- one parameter at a time
@pytest.mark.parametrize(("kind", "name"), PARAMETERS, ids=[f"{k}:{n}" for k, n in PARAMETERS])
def test_bad_parameter_is_named_with_its_range(kind: str, name: str) -> None:
    """Each value outside a parameter's domain, and each wrong type, is refused by the scene's
    constructor with a message that names the parameter and states the domain as the registry does."""
    description = rr.describe(kind)
    parameter = description.parameter(name)
    for bad in bad_values(parameter):
        values: dict[str, Any] = {name: bad}
        msg = raised(lambda values=values: description.build(**values))
        assert msg.startswith(f"{name} must be a finite number {parameter.domain.text()}"), (bad, msg)
        # the parameter's own check says the same
        assert raised(lambda bad=bad: parameter.check(bad)) == msg, bad


@settings(max_examples=400, deadline=None)
@given(data=st.data())
def test_any_bad_value_raises_value_error_naming_it(data: st.DataObject) -> None:
    """Any float outside the domain of any registered parameter is refused by name by the constructor itself."""
    description = data.draw(st.sampled_from(descriptions()))
    parameter = data.draw(st.sampled_from(description.parameters))
    bad = data.draw(bad_numbers(parameter))
    values: dict[str, Any] = {**description.defaults(), parameter.name: bad}
    with pytest.raises(
        ValueError, match=f"^{re.escape(parameter.name)} must be .*{re.escape(parameter.domain.text())}"
    ):
        description.constructor(**values)


def test_every_parameter_accepts_its_default_and_refuses_none_unless_optional() -> None:
    """The domain check is not vacuous: defaults pass, and ``None`` passes exactly where it is documented."""
    for description in descriptions():
        for p in description.parameters:
            if p.default is not None:
                assert p.check(p.default) == p.default
            if p.optional:
                description.build(**{p.name: None})
            else:
                assert raised(lambda p=p: p.check(None)).startswith(f"{p.name} must be")


# ---------------------------------------------------------------- parameters together
@pytest.mark.parametrize("maker", [rr.constant_acceleration, rr.deceleration])
@pytest.mark.parametrize("a_front", [1.0, 2.0, 1e100])
def test_acceleration_beyond_the_horizon_is_refused(maker: Callable[..., rr.Scene], a_front: float) -> None:
    """a'_F L0 >= 1 puts the back end at or behind the Rindler horizon (Eq. (15)): refused as a product."""
    msg = raised(lambda: maker(v=0.6, length=1.0, a_front=a_front))
    assert msg.startswith("a_front * length must be a finite number in (0, 1)"), msg
    msg = raised(lambda: maker(v=0.6, length=4.0, a_front=0.25))
    assert msg.startswith("a_front * length must be a finite number in (0, 1)"), msg


def test_velocity_change_accepts_the_impulsive_limit_and_refuses_beyond() -> None:
    """For a general velocity change a'_F L0 = 1 is the impulsive limit (the same scene as no a'_F);
    beyond it the product is refused with the closed range."""
    limit = rr.velocity_change(0.2, 0.6, 2.0, a_front=0.5)
    impulse = rr.velocity_change(0.2, 0.6, 2.0, a_front=None)
    assert limit.events == impulse.events
    assert [r.motion for r in limit.rods] == [r.motion for r in impulse.rods]
    for a_front in (0.5000000000000001, 2.0):
        msg = raised(lambda a_front=a_front: rr.velocity_change(0.2, 0.6, 2.0, a_front=a_front))
        assert msg.startswith("a_front * length must be a finite number in (0, 1]"), msg


@pytest.mark.parametrize("v2", [0.6, 0.7, 0.99])
def test_rods_that_do_not_approach_are_refused(v2: float) -> None:
    """Rod 2 must be slower than rod 1 (v2 < v1) for the rods to collide."""
    msg = raised(lambda: rr.rod_collision(0.6, v2, 1.0, 2.0, 1.0, 1.0, 1.0))
    assert msg.startswith("v2 must be less than v1"), msg


def test_velocity_change_needs_a_change() -> None:
    """v_final == v_initial is no velocity change."""
    msg = raised(lambda: rr.velocity_change(0.2, 0.2, 1.0, 0.5))
    assert msg.startswith("v_final must be different from v_initial"), msg


def test_unknown_parameter_is_named_with_the_valid_ones() -> None:
    """``build_scene`` names a parameter the scene does not have and lists the ones it has."""
    for description in descriptions():
        msg = raised(lambda kind=description.kind: rr.build_scene(kind, speed=0.5))
        assert msg.startswith("speed must be one of the parameters of"), msg
        assert description.kind in msg
        for p in description.parameters:
            assert p.name in msg, (p.name, msg)


def test_unknown_scene_lists_the_scenes() -> None:
    """``rr.describe`` and ``rr.build_scene`` list every registered scene when given an unknown name."""
    for ask in (lambda: rr.describe("nope"), lambda: rr.build_scene("nope")):
        msg = raised(ask)
        assert msg.startswith("scene must be one of"), msg
        assert "'nope'" in msg
        for kind in rr.scene_descriptions():
            assert kind in msg


@pytest.mark.parametrize("rapidity", [True, "0.5", None, math.nan, math.inf, 700.5, -701.0, 1j])
def test_bad_rapidity_is_named(rapidity: Any) -> None:
    with pytest.raises(rr.ParameterError, match=r"^rapidity must be a finite number with \|rapidity\| <= 700"):
        rr.Frame.from_rapidity(rapidity)


def test_unknown_frame_lists_the_frames() -> None:
    """``scene.frame`` lists the scene's preset frames when given an unknown name."""
    for description in descriptions():
        scene = description.build()
        msg = raised(lambda scene=scene: scene.frame("nope"))
        assert msg.startswith("frame must be one of"), msg
        for name in description.frames:
            assert repr(name) in msg, (name, msg)


# ---------------------------------------------------------------- frames
def samplers(scene: rr.Scene) -> dict[str, Callable[[Any], object]]:
    """Every entry point of a scene that takes a frame, called with ``frame`` and good other arguments."""
    t = np.array([0.0, 0.5])
    return {
        "positions": lambda frame: scene.positions(t, frame=frame),
        "material_positions": lambda frame: scene.material_positions(t, frame=frame, fractions=[0.5]),
        "velocities": lambda frame: scene.velocities(t, frame=frame),
        "proper_times": lambda frame: scene.proper_times(t, frame=frame),
        "lengths": lambda frame: scene.lengths(t, frame=frame),
        "snapshot": lambda frame: scene.snapshot(0.5, frame=frame, fractions=[0.0, 1.0]),
        "switch_times": lambda frame: scene.switch_times(frame=frame),
        "events_in": lambda frame: scene.events_in(frame=frame),
        "time_window": lambda frame: scene.time_window(frame=frame),
        "budget": lambda frame: scene.budget(frame=frame),
        **{f"object {o.name}": (lambda frame, o=o: o.positions(t, frame=frame)) for o in scene.objects},
        **{f"object {o.name} parted": (lambda frame, o=o: o.parted(t, frame=frame)) for o in scene.objects},
        **{f"object {o.name} event": (lambda frame, o=o: o.event_in(frame=frame)) for o in scene.objects if o.event},
        **{
            f"object {o.name} {o.field.name}": (lambda frame, field=o.field: field.values(t, frame=frame))
            for o in scene.objects
            if o.field is not None
        },
    }


FRAME_SCENES = [d.kind for d in descriptions()]


@pytest.mark.parametrize("kind", FRAME_SCENES)
@pytest.mark.parametrize(
    "frame", [0.5, 0.0, -0.3, 1, "lab", "0.1", None, math.nan, True, rr.ExactVelocity(0.5, 0.0, 0.5)]
)
def test_bad_frame_is_named(kind: str, frame: Any) -> None:
    """A float (the old frame velocity), a string or anything else but a Frame is refused by name
    by every sampler; a Frame of the same velocity is accepted."""
    scene = rr.build_scene(kind)
    calls = samplers(scene)
    for name, call in calls.items():
        with pytest.raises(rr.ParameterError, match=r"^frame must be a rigidrel_core\.Frame") as info:
            call(frame)
        assert info.value.parameter == "frame", name
        call(rr.Frame.from_velocity(0.5))


@pytest.mark.parametrize("t", [[0.0, math.nan], [math.inf], [-1e301], ["x"], [[0.0], [1.0, 2.0]], "0.5", None])
def test_bad_times(t: Any) -> None:
    s = rr.impulsive_start(0.6, 1.0)
    with pytest.raises(ValueError, match=r"^t must be finite real numbers with \|t\| <= 1e\+300"):
        s.positions(t)


COMPLEX_AND_OBJECT_TIMES = [
    1j,
    np.array([0.5 + 0j]),
    np.array([0.5 + 1j]),
    np.array([[0.0, 1.0 + 0j]]),
    np.complex128(0.5),
    np.array([0.5], dtype=object),
    np.array(["0.5"]),
    [0.5 + 0j],
]


@pytest.mark.parametrize("t", COMPLEX_AND_OBJECT_TIMES, ids=repr)
def test_complex_text_and_object_times_are_refused_not_cut_to_the_real_part(t: Any) -> None:
    """Complex times (even with a zero imaginary part), text and object arrays are refused by every
    sampler that takes times, naming ``t``; none of them is silently cut to its real part."""
    s = rr.wall_collision(0.6, 1.0, 0.5)
    frame = s.frame("rod before")
    calls: dict[str, Callable[[], object]] = {
        "positions": lambda: s.positions(t, frame=frame),
        "material_positions": lambda: s.material_positions(t, frame=frame, fractions=[0.5]),
        "velocities": lambda: s.velocities(t, frame=frame),
        "proper_times": lambda: s.proper_times(t, frame=frame),
        "lengths": lambda: s.lengths(t, frame=frame),
        "object": lambda: s.objects[0].positions(t, frame=frame),
        "object parted": lambda: s.objects[0].parted(t, frame=frame),
    }
    if np.ndim(t) == 0:
        calls["snapshot"] = lambda: s.snapshot(t, frame=frame, fractions=[0.0, 1.0])
    for name, call in calls.items():
        with pytest.raises(rr.ParameterError, match=r"^t must be finite real numbers") as info:
            call()
        assert info.value.parameter == "t", name


@pytest.mark.parametrize("t", [math.nan, math.inf, 1e301, "x", None, 1j, np.complex128(0.5)], ids=repr)
def test_bad_snapshot_time(t: Any) -> None:
    """``snapshot`` takes one frame time and refuses a bad one by name, like the other samplers."""
    s = rr.impulsive_start(0.6, 1.0)
    with pytest.raises(rr.ParameterError, match=r"^t must be finite real numbers with \|t\| <= 1e\+300"):
        s.snapshot(t, fractions=[0.0, 1.0])


BAD_FRACTIONS = [
    [-0.1],
    [1.5],
    [math.nan],
    [[0.5]],
    0.5,
    "0.5",
    ["0.5"],
    np.array([0.5 + 0j]),
    np.array([0.5], dtype=object),
    [0.5j],
]


@pytest.mark.parametrize("f", BAD_FRACTIONS, ids=repr)
def test_bad_fractions(f: Any) -> None:
    """Fractions are a 1-D real array in [0, 1]; complex, text and object arrays are refused by name."""
    s = rr.impulsive_start(0.6, 1.0)
    calls: dict[str, Callable[[], object]] = {
        "material_positions": lambda: s.material_positions([0.0], fractions=f),
        "velocities": lambda: s.velocities([0.0], fractions=f),
        "proper_times": lambda: s.proper_times([0.0], fractions=f),
        "switch_times": lambda: s.switch_times(fractions=f),
        "snapshot": lambda: s.snapshot(0.0, fractions=f),
    }
    for name, call in calls.items():
        with pytest.raises(rr.ParameterError, match=r"^fractions must be an array of numbers in \[0, 1\]") as info:
            call()
        assert info.value.parameter == "fractions", name


@pytest.mark.parametrize("f", [[0.5, 1.0], [0.0, 0.5], [0.0], [1.0, 0.0]])
def test_snapshot_fractions_must_span_the_rod(f: list[float]) -> None:
    s = rr.impulsive_start(0.6, 1.0)
    with pytest.raises(rr.ParameterError, match="fractions must be sorted fractions starting at 0 and ending at 1"):
        s.snapshot(0.0, fractions=f)


def test_fractions_are_keyword_only() -> None:
    """``fractions`` comes after ``t`` and must be named, like ``frame``."""
    s = rr.impulsive_start(0.6, 1.0)
    with pytest.raises(TypeError):
        s.material_positions([0.0], [0.5])  # type: ignore[misc]


FRAME_TAKERS = (
    rr.Scene,
    rr.BellScene,
    rr.PoleBarnScene,
    rr.SceneObject,
    rr.InertialWorldline,
    rr.MaterialWorldline,
    rr.ObjectEvent,
)


def test_frame_is_keyword_only_everywhere() -> None:
    """Every method of a scene (and of its objects, their worldlines and events) that takes a frame takes it by name,
    ``scene.positions(t, frame=f)``, so that no call reads differently from another."""
    found = []
    for cls in FRAME_TAKERS:
        for name, member in inspect.getmembers(cls, inspect.isfunction):
            if name.startswith("_"):
                continue  # the plan cache's own plumbing
            parameter = inspect.signature(member).parameters.get("frame")
            if parameter is not None:
                found.append(f"{cls.__name__}.{name}")
                assert parameter.kind is inspect.Parameter.KEYWORD_ONLY, f"{cls.__name__}.{name}"
    assert {
        "Scene.positions",
        "Scene.budget",
        "Scene.point_event",
        "SceneObject.positions",
        "SceneObject.parted",
    } <= set(found), found


@pytest.mark.parametrize("kind", [d.kind for d in descriptions()])
def test_a_positional_frame_is_refused(kind: str) -> None:
    """Given positionally, a frame is refused by Python itself (a ``TypeError``), not taken for
    another argument."""
    scene = rr.build_scene(kind)
    frame = rr.default_frame(scene)
    t = np.array([0.0, 0.5])
    calls: dict[str, Callable[[], object]] = {
        "positions": lambda: scene.positions(t, frame),  # type: ignore[misc]
        "lengths": lambda: scene.lengths(t, frame),  # type: ignore[misc]
        "velocities": lambda: scene.velocities(t, frame),  # type: ignore[misc]
        "proper_times": lambda: scene.proper_times(t, frame),  # type: ignore[misc]
        "events_in": lambda: scene.events_in(frame),  # type: ignore[misc]
        "time_window": lambda: scene.time_window(frame),  # type: ignore[misc]
        "budget": lambda: scene.budget(frame),  # type: ignore[misc]
        "notes": lambda: scene.notes(frame),  # type: ignore[misc]
        "horizon_event": lambda: scene.horizon_event(0, frame),  # type: ignore[misc]
    }
    for name, call in calls.items():
        try:
            call()
        except TypeError as exc:
            assert "positional argument" in str(exc), (name, exc)
        else:
            raise AssertionError(f"{name} took a positional frame")


# ---------------------------------------------------------------- shapes
@pytest.mark.parametrize("kind", [d.kind for d in descriptions()])
def test_times_of_any_shape(kind: str) -> None:
    """Samplers keep the shape of the times, after the rod and point axes."""
    s = rr.build_scene(kind)
    n = s.n_rods
    assert s.positions(0.0).shape == (n, 2)
    assert s.positions(np.zeros((3, 4))).shape == (n, 2, 3, 4)
    assert s.positions([]).shape == (n, 2, 0)
    assert s.lengths(np.zeros((3, 4))).shape == (n, 3, 4)
    f = np.linspace(0.0, 1.0, 5)
    assert s.material_positions(np.zeros((3, 4)), fractions=f).shape == (n, 5, 3, 4)
    assert s.velocities(np.zeros(7)).shape == (n, 2, 7)
    assert s.proper_times(np.zeros((2, 3)), fractions=f).shape == (n, 5, 2, 3)
    assert s.switch_times(fractions=f).shape == (n, 5, 2)
    x, tau = s.snapshot(0.0, fractions=f)
    assert x.shape == (n, 5) and tau.shape == (n, 2)
    for o in s.objects:
        assert o.positions(np.zeros((3, 4))).shape == (len(o.worldlines), 3, 4)
        assert o.parted(np.zeros((3, 4))).shape == (3, 4)
    frame = rr.Frame.from_velocity(0.5)
    for shape in [(), (1,), (3,), (2, 4)]:
        assert (frame @ np.zeros((*shape, 2))).shape == (*shape, 2)


@pytest.mark.parametrize("events", [np.zeros(3), np.zeros((2, 3)), [], np.array(["0", "1"]), [0.5j, 0.0], "ab", None])
def test_bad_events_are_named(events: Any) -> None:
    """``frame @ events`` wants a real array whose last axis holds (t, x)."""
    with pytest.raises(rr.ParameterError, match=r"^events must be a real array of shape \(\.\.\., 2\)"):
        _ = rr.Frame.from_velocity(0.5) @ events


# ---------------------------------------------------------------- extremes
def finite_everywhere(scene: rr.Scene) -> None:
    """Positions, lengths, velocities and clocks are finite over the scene's time window in frames at
    |beta| = 0.999999 and in every preset frame."""
    for frame in (*EXTREME_FRAMES, *scene.frames.values()):
        t = np.linspace(*scene.time_window(frame=frame), 64)
        assert np.all(np.isfinite(scene.positions(t, frame=frame))), frame
        assert np.all(np.isfinite(scene.lengths(t, frame=frame))), frame
        assert np.all(np.isfinite(scene.velocities(t, frame=frame))), frame
        assert np.all(np.isfinite(scene.proper_times(t, frame=frame))), frame
        assert all(np.isfinite(e).all() for e in scene.events_in(frame=frame).values()), frame


@pytest.mark.parametrize(
    "build",
    [
        lambda: rr.constant_acceleration(1 - 2**-53, 1.0, 1e-100),
        lambda: rr.constant_acceleration(0.5, 1e6, (1 - 2**-52) / 1e6),
        lambda: rr.rod_collision(1 - 2**-53, -1 + 2**-53, 1e-6, 1e6, 1e-6, 1e6, 0.0),
        lambda: rr.wall_collision(1 - 2**-53, 1e6, 1.0),
    ],
)
def test_extreme_but_accepted_parameters_give_finite_output(build: Callable[[], rr.Scene]) -> None:
    """Speeds one ulp below light, a'_F L0 one ulp below 1, mass and length ratios of 1e12: finite in
    frames at |beta| = 0.999999 and in every preset frame."""
    scene = build()
    forward, backward = EXTREME_FRAMES
    t = np.linspace(*scene.time_window(frame=forward), 64)
    assert np.all(np.isfinite(scene.positions(t, frame=forward)))
    assert np.all(np.isfinite(scene.lengths(t, frame=backward)))
    finite_everywhere(scene)


def domain_edges(domain: rr.Interval) -> list[float]:
    """The extreme accepted values of a domain: its closed ends or the floats next to its open ends."""
    lo = domain.lo if domain.lo_closed else math.nextafter(domain.lo, math.inf)
    hi = domain.hi if domain.hi_closed else math.nextafter(domain.hi, -math.inf)
    return [x for x in (lo, hi) if math.isfinite(x) and x in domain]


EDGES = [(d.kind, p.name, x) for d in descriptions() for p in d.parameters for x in domain_edges(p.domain)]


@pytest.mark.parametrize(("kind", "name", "value"), EDGES, ids=[f"{k}:{n}={x!r}" for k, n, x in EDGES])
def test_each_parameter_at_its_domain_edge_is_finite_or_refused_by_name(kind: str, name: str, value: float) -> None:
    """One parameter at the edge of its domain (the others at their defaults) gives a scene whose
    every sample is finite in extreme frames, or a refusal that names what went wrong."""
    try:
        scene = rr.build_scene(kind, **{name: value})
    except rr.ParameterError as error:
        assert error.parameter in {name, "a_front * length", "v2", "v_final", "parameters"}, str(error)
        return
    finite_everywhere(scene)


def test_unrepresentable_scene_is_refused_by_name() -> None:
    """A Rindler radius beyond 1e120 is refused: by the domain of a_front when a_front alone is too small,
    and by the generic check when the radius times gamma V (a lab event) leaves the range."""
    with pytest.raises(ValueError, match=r"^a_front must be a finite number > 1e-120; got 1e-300$"):
        rr.constant_acceleration(0.5, 1.0, 1e-300)
    generic = r"^parameters must be such that every lab event and Rindler radius lies within 1e\+120 of the origin"
    with pytest.raises(ValueError, match=generic):
        rr.constant_acceleration(0.999, 1.0, 1e-119)  # radius 1e119, gamma V = 22
    with pytest.raises(ValueError, match=generic):
        rr.wall_collision(0.9, 1e120, 1.0)  # radius 1e120, gamma V = 2
    # just inside: the same radius at a lower speed is accepted and finite
    finite_everywhere(rr.constant_acceleration(0.05, 1.0, 1e-119))
