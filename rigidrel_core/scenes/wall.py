"""A rod hits a wall: crash, bounce, or anything between (paper Sec. 5)."""

from __future__ import annotations

from types import MappingProxyType

from .. import _dd
from .._build import EPS, IMPULSE, LENGTH, MASS, SINGLE_ROD_FRAMES, V, checked_scene, rigid_motion, single_rod_frames
from .._description import EventDescription, ObjectKind, OriginEvent, SceneDescription, ScenePreset
from .._exact import REST, ExactVelocity
from .._objects import SceneObject
from .._scene import EventSpec, Rod, Scene

#: The far end's switches (Eqs. (22)-(24)) and the wall at rest at x = 0, its matter toward -x (the rod
#: lies in x > 0); the same in every scene.
_EVENTS = (EventSpec("T_1", 0, 1, "start"), EventSpec("T_1'", 0, 1, "stop"))
_OBJECTS = (SceneObject.inertial("wall", ObjectKind.WALL, 0.0, REST, side=-1),)


def bounce(v: float, eps: float, mass: float) -> tuple[ExactVelocity, float]:
    """Velocity after the bounce and the heat (c = 1): the proper velocity ``gamma v`` becomes
    ``eps gamma v`` (Sec. 5; Eq. (29) with the wall as an infinitely heavy partner).

    In double-double: ``v' = eps v / d`` with ``d = sqrt(1 - v^2 + eps^2 v^2)``, its gap
    ``1 - v' = (1 - v^2) / (d (d + eps v))``, and the heat ``M (gamma - gamma') =
    M (1 - eps^2) v^2 / (c (1 + d))`` with ``c = sqrt(1 - v^2)``: sums of positive terms only,
    each rounded once. ``eps = 1`` returns ``v`` itself and no heat, ``eps = 0`` rest, exactly.
    """
    if eps == 1.0:
        return ExactVelocity.from_float(v), 0.0
    v2 = _dd.two_prod(v, v)
    one_minus_v2 = _dd.add_float((-v2[0], -v2[1]), 1.0)  # 1 - v^2
    eps_v = _dd.two_prod(eps, v)
    d = _dd.sqrt(_dd.add(one_minus_v2, _dd.mul(eps_v, eps_v)))
    e2 = _dd.two_prod(eps, eps)
    lost = _dd.mul(_dd.add_float((-e2[0], -e2[1]), 1.0), v2)  # (1 - eps^2) v^2
    heat = _dd.div(_dd.mul_float(lost, mass), _dd.mul(_dd.sqrt(one_minus_v2), _dd.add_float(d, 1.0)))[0]
    if eps == 0.0:
        return REST, heat
    hi, lo = _dd.div(eps_v, d)
    gap = _dd.div(one_minus_v2, _dd.mul(d, _dd.add(d, eps_v)))[0]
    return ExactVelocity(hi, lo, gap), heat


def wall_collision(v: float, length: float, eps: float, mass: float = 1.0) -> Scene:
    """A rod hits a wall at x = 0 (Sec. 5).

    The rod lies in ``x > 0`` moving with velocity ``-v``; its left end meets the wall at
    ``t = 0`` and leaves with proper velocity ``eps * gamma v`` (epsilon scales the proper
    velocity in the wall's frame, the barycentric frame of an infinitely heavy wall, as
    Eq. (29) does; ``eps = 0`` is the crash, ``eps = 1`` the elastic bounce). The far (right)
    end follows ``x = sqrt(L0^2 + t^2)`` (Eq. (23)) from ``T_1 = -gamma v L0`` to
    ``T_1' = gamma' v' L0``. Events: ``"T_1"``, ``"T_1'"``. The wall absorbs the heat
    ``M (gamma - gamma')``.
    """
    v = V.check(v)
    length = LENGTH.check(length)
    eps = EPS.check(eps)
    mass = MASS.check(mass)
    v_after, heat = bounce(v, eps, mass)
    motion = rigid_motion(ExactVelocity.from_float(-v), v_after, length, IMPULSE, 0.0)
    return checked_scene(
        Scene(
            kind=WALL_COLLISION.kind,
            parameters=MappingProxyType({"v": v, "length": length, "eps": eps, "mass": mass}),
            rods=(Rod("rod", motion, mass, mass),),
            event_specs=_EVENTS,
            frames=single_rod_frames(motion),
            external_source="wall",
            heat=heat,
            origin_event=OriginEvent.CONTACT,
            objects=_OBJECTS,
        )
    )


WALL_COLLISION = SceneDescription(
    kind="wall-collision",
    title="Wall crash / bounce",
    summary=(
        "A rod moving at −V hits a wall at x = 0 and stops (ε = 0), bounces back elastically (ε = 1) or anything "
        "between (by default it bounces, ε = 1)."
    ),
    source="Sec. 5",
    constructor=wall_collision,
    parameters=(V, LENGTH, EPS, MASS),
    frames=SINGLE_ROD_FRAMES,
    default_frame="rod before",
    events=(
        EventDescription("T_1", "the far (right) end starts changing velocity", "Sec. 5, Eq. (22)"),
        EventDescription("T_1'", "the far end has its final velocity", "Sec. 5, Eq. (24)"),
    ),
    objects=(ObjectKind.WALL,),
    presets=(
        ScenePreset("Sec. 5: crash into a wall, V = 0.6", {"v": 0.6, "length": 1.0, "eps": 0.0, "mass": 1.0}),
        ScenePreset("Sec. 5: elastic bounce, V = 0.6", {"v": 0.6, "length": 1.0, "eps": 1.0, "mass": 1.0}),
    ),
    meanings=MappingProxyType({"v": "approach speed V (c = 1): the rod moves at −V toward the wall at x = 0"}),
    order=50,
)

SCENES = (WALL_COLLISION,)
