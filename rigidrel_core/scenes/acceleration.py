"""Born-rigid constant acceleration, deceleration and any velocity change (paper Sec. 3)."""

from __future__ import annotations

from collections.abc import Mapping
from types import MappingProxyType
from typing import Literal

from .._build import (
    A_FRONT,
    IMPULSE,
    LENGTH,
    MASS,
    SINGLE_ROD_FRAMES,
    V,
    checked_scene,
    near_radius,
    rigid_motion,
)
from .._build import single_rod_frames as _frames
from .._dd import DD
from .._description import (
    VELOCITY,
    EventDescription,
    Interval,
    OriginEvent,
    Overlay,
    Parameter,
    SceneDescription,
    ScenePreset,
    Slider,
)
from .._exact import REST, ExactVelocity
from .._paper import FIG1_CONSTANT_ACCELERATION
from .._scene import EventSpec, Rod, Scene
from .._validate import ParameterError
from .impulse import impulsive_start

Which = Literal["near", "far"]
Phase = Literal["start", "stop"]
EventsBySign = Mapping[int, tuple[EventSpec, ...]]


def _event_specs(event_names: Mapping[tuple[Which, Phase], str]) -> EventsBySign:
    """A scene's named events for a change up (``sign = 1``: the near end, the paper's B, is the left
    one) and down (the right one); made once, at import."""
    ends: dict[tuple[int, Which], Literal[0, 1]] = {(1, "near"): 0, (1, "far"): 1, (-1, "near"): 1, (-1, "far"): 0}
    return MappingProxyType(
        {
            sign: tuple(EventSpec(name, 0, ends[sign, which], phase) for (which, phase), name in event_names.items())
            for sign in (1, -1)
        }
    )


_CONSTANT_ACCELERATION_EVENTS = _event_specs({("near", "stop"): "T_B", ("far", "stop"): "T_F"})
_DECELERATION_EVENTS = _event_specs({("far", "start"): "-T_F", ("near", "start"): "-T_B"})
_VELOCITY_CHANGE_EVENTS = _event_specs(
    {("near", "start"): "T_B0", ("far", "start"): "T_F0", ("near", "stop"): "T_B", ("far", "stop"): "T_F"}
)


def _velocity_change_scene(
    kind: str,
    parameters: Mapping[str, float],
    v_initial: ExactVelocity,
    v_final: ExactVelocity,
    length: float,
    rho_near: DD,
    mass: float,
    events: EventsBySign,
    origin_event: OriginEvent,
    kick: str = "",
) -> Scene:
    """One rod changing velocity once; ``near`` is the end nearer the Rindler horizon (the paper's B);
    ``kick`` names the event where it is kicked, if that is not the origin (:attr:`Scene.kick`)."""
    motion = rigid_motion(v_initial, v_final, length, rho_near, 0.0)
    return checked_scene(
        Scene(
            kind=kind,
            parameters=MappingProxyType(dict(parameters)),
            rods=(Rod("rod", motion, mass, mass),),
            event_specs=events[motion.sign],
            frames=_frames(motion),
            external_source="drive",
            heat=0.0,
            origin_event=origin_event,
            kick=kick,
        )
    )


# ====================================================================== constant acceleration
def constant_acceleration(v: float, length: float, a_front: float, mass: float = 1.0) -> Scene:
    """Born-rigid constant acceleration from rest to ``v`` (Sec. 3, Fig. 1 solid curve).

    The rod rests on ``[0, length]`` for ``t <= 0``. Its front (right) end has proper
    acceleration ``a'_F = a_front``, its back end ``a'_B = a'_F/(1 - a'_F L0)`` (Eq. (15));
    each point coasts once it reaches ``v``: the back end at lab ``T_B = gamma v / a'_B``,
    the front at ``T_F = gamma v / a'_F`` (Eq. (9)), at equal rest-frame time (Eq. (16)).
    Events: ``"T_B"``, ``"T_F"``. Requires ``0 < v < 1``, ``0 < a_front * length < 1``.
    """
    v = V.check(v)
    length = LENGTH.check(length)
    a_front = A_FRONT.check(a_front)
    mass = MASS.check(mass)
    return _velocity_change_scene(
        CONSTANT_ACCELERATION.kind,
        {"v": v, "length": length, "a_front": a_front, "mass": mass},
        REST,
        ExactVelocity.from_float(v),
        length,
        near_radius(a_front, length),
        mass,
        _CONSTANT_ACCELERATION_EVENTS,
        OriginEvent.START,
    )


def _fig1_impulsive(values: Mapping[str, float | None]) -> Scene:
    """Fig. 1's dashed curve: the impulsive start to the same ``V`` and rest length."""
    v, length = values["v"], values["length"]
    assert v is not None and length is not None
    return impulsive_start(v=v, length=length)


CONSTANT_ACCELERATION = SceneDescription(
    kind="constant-acceleration",
    title="Constant acceleration",
    summary="A rod accelerates from rest to V, its back end harder than its front (Born rigid).",
    source="Sec. 3",
    constructor=constant_acceleration,
    parameters=(V, LENGTH, A_FRONT, MASS),
    frames=SINGLE_ROD_FRAMES,
    default_frame="rod after",
    events=(
        EventDescription("T_B", "the back (left) end stops accelerating", "Sec. 3, Eq. (9)"),
        EventDescription("T_F", "the front (right) end stops accelerating", "Sec. 3, Eq. (9)"),
    ),
    presets=(ScenePreset("Fig. 1: acceleration to V = 0.6", FIG1_CONSTANT_ACCELERATION, overlay=True),),
    meanings=MappingProxyType({"v": "final speed V (c = 1): the rod starts at rest and ends moving at +V"}),
    overlay=Overlay("impulsive (Fig. 1 dashed)", _fig1_impulsive),
    order=10,
)


# ====================================================================== deceleration
def deceleration(v: float, length: float, a_front: float, mass: float = 1.0) -> Scene:
    """Born-rigid deceleration from velocity ``-v`` to rest (Sec. 3, last paragraph).

    The time reverse of :func:`constant_acceleration`: the rod comes in from the right
    with velocity ``-v`` and is at rest on ``[0, length]`` from ``t = 0`` on. The right end
    (the paper's F of Fig. 1, trailing in the motion) has proper deceleration
    ``a_front``; it starts braking first, at ``-T_F``, the left end at ``-T_B``.
    Events: ``"-T_F"``, ``"-T_B"`` (the paper relabels these ends B and F after
    reversing time; we keep Fig. 1's labels). Requires ``0 < v < 1``, ``0 < a_front * length < 1``.
    """
    v = V.check(v)
    length = LENGTH.check(length)
    a_front = A_FRONT.check(a_front)
    mass = MASS.check(mass)
    return _velocity_change_scene(
        DECELERATION.kind,
        {"v": v, "length": length, "a_front": a_front, "mass": mass},
        ExactVelocity.from_float(-v),
        REST,
        length,
        near_radius(a_front, length),
        mass,
        _DECELERATION_EVENTS,
        OriginEvent.REST,
    )


DECELERATION = SceneDescription(
    kind="deceleration",
    title="Deceleration",
    summary="A rod moving at −V brakes Born-rigidly to rest on [0, L0] at t = 0 (Fig. 1 read downwards).",
    source="Sec. 3",
    constructor=deceleration,
    parameters=(V, LENGTH, A_FRONT, MASS),
    frames=SINGLE_ROD_FRAMES,
    default_frame="rod before",
    events=(
        EventDescription(
            "-T_F", "the right end (trailing, in the lab) starts changing velocity", "Sec. 3, Eq. (9) with t → −t"
        ),
        EventDescription(
            "-T_B", "the left end (leading, in the lab) starts changing velocity", "Sec. 3, Eq. (9) with t → −t"
        ),
    ),
    meanings=MappingProxyType({"v": "approach speed V (c = 1): the rod moves at −V until it brakes to rest"}),
    order=20,
)


# ====================================================================== any velocity change
V_INITIAL = Parameter(
    "v_initial", "V_i", "V initial", "c", VELOCITY, 0.2, "initial velocity", Slider(-0.99, 0.99, 0.01)
)
V_FINAL = Parameter(
    "v_final",
    "V_f",
    "V final",
    "c",
    VELOCITY,
    0.6,
    "final velocity",
    Slider(-0.99, 0.99, 0.01),
    constraint="different from v_initial",
)
#: ``a'_F L0 = 1`` is the impulsive limit: the near end's radius 1/a'_B is 0.
_IMPULSIVE_ALLOWED = Interval(0.0, 1.0, hi_closed=True)
A_FRONT_OR_IMPULSE = Parameter(
    "a_front",
    A_FRONT.symbol,
    "a′_F L0 (1: impulse)",
    A_FRONT.unit,
    A_FRONT.domain,
    0.5,
    "proper acceleration a′_F of the end that leads in the direction of the push; a′_F L0 = 1 "
    "(or none) is the impulsive limit of Sec. 4",
    Slider(0.01, 1.0, 0.01),
    optional=True,
    constraint="a_front * length in (0, 1]",
)


def velocity_change(
    v_initial: float,
    v_final: float,
    length: float,
    a_front: float | None = None,
    mass: float = 1.0,
) -> Scene:
    """Any Born-rigid change of velocity ``v_initial -> v_final`` at constant proper accelerations.

    ``a_front`` is the proper acceleration of the end that leads in the direction of the
    push (the end farther from the Rindler horizon, the paper's ``a'_F``); the other end
    has ``a_front / (1 - a_front * length)`` (Eq. (15)). ``a_front=None`` or ``a_front * length
    = 1`` is the impulsive limit (Sec. 4): the near end jumps. At lab ``t = 0`` the rod's
    extended family of hyperbolas has it at rest on ``[0, length]``, so
    ``velocity_change(0, v, ...)`` is :func:`constant_acceleration` and
    ``velocity_change(-v, 0, ...)`` is :func:`deceleration`. Events: ``"T_B0"``, ``"T_F0"``
    (back/front end starts), ``"T_B"``, ``"T_F"`` (stops), with B the end nearer the horizon.
    """
    vi = V_INITIAL.check(v_initial)
    vf = V_FINAL.check(v_final)
    if vi == vf:
        raise ParameterError("v_final", "different from v_initial", v_final)
    length = LENGTH.check(length)
    mass = MASS.check(mass)
    if a_front is None:
        rho_near = IMPULSE
    else:
        rho_near = near_radius(A_FRONT_OR_IMPULSE.check(a_front), length, _IMPULSIVE_ALLOWED)
    params = {"v_initial": vi, "v_final": vf, "length": length, "mass": mass}
    if a_front is not None:
        params["a_front"] = float(a_front)
    # the impulsive limit kicks B: at the origin when the push is toward +x (B is the left end), at
    # lab (0, L0) otherwise (B is the right end; the origin is then F's vertex)
    impulsive = rho_near == IMPULSE
    if impulsive and vf > vi:
        origin = OriginEvent.KICK
    else:
        origin = OriginEvent.START if vi == 0.0 else (OriginEvent.REST if vf == 0.0 else OriginEvent.VERTEX)
    return _velocity_change_scene(
        VELOCITY_CHANGE.kind,
        params,
        ExactVelocity.from_float(vi),
        ExactVelocity.from_float(vf),
        length,
        rho_near,
        mass,
        _VELOCITY_CHANGE_EVENTS,
        origin,
        "T_B0" if impulsive and vf < vi else "",
    )


VELOCITY_CHANGE = SceneDescription(
    kind="velocity-change",
    title="Any velocity change",
    summary=(
        "A rod changes velocity from V_i to V_f Born-rigidly, each point at its own constant proper "
        "acceleration (a′_F L0 = 1 or none: at once, an impulse)."
    ),
    source="Secs. 3-4",
    constructor=velocity_change,
    parameters=(V_INITIAL, V_FINAL, LENGTH, A_FRONT_OR_IMPULSE, MASS),
    frames=SINGLE_ROD_FRAMES,
    default_frame="rod after",
    events=(
        EventDescription(
            "T_B0",
            "the end B (at the back, seen along the push: the larger proper acceleration) starts changing velocity",
            "Sec. 3",
        ),
        EventDescription("T_F0", "the end F (at the front, seen along the push) starts changing velocity", "Sec. 3"),
        EventDescription("T_B", "the end B stops changing velocity (at T_B0 itself when kicked)", "Sec. 3, Eq. (9)"),
        EventDescription("T_F", "the end F stops changing velocity", "Sec. 3, Eq. (9)"),
    ),
    order=40,
)

SCENES = (CONSTANT_ACCELERATION, DECELERATION, VELOCITY_CHANGE)
