"""A rod hits a wall: crash, bounce, or anything between (paper Sec. 5)."""

from __future__ import annotations

from decimal import Decimal
from types import MappingProxyType

from .._build import (
    EPS,
    LENGTH,
    MASS,
    SINGLE_ROD_FRAMES,
    V,
    checked_scene,
    decimal_context,
    rigid_motion,
    single_rod_frames,
)
from .._description import EventDescription, ObstacleKind, OriginEvent, SceneDescription, ScenePreset
from .._exact import REST, ExactVelocity, lorentz_factor_decimal, velocity_from_proper_velocity
from .._scene import EventSpec, Obstacle, Rod, Scene


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
    with decimal_context():
        dv = Decimal(v)
        gamma = lorentz_factor_decimal(dv)
        u_after = Decimal(eps) * gamma * dv
        v_after = velocity_from_proper_velocity(u_after)
        heat = Decimal(mass) * (gamma - (1 + u_after * u_after).sqrt())
    motion = rigid_motion(ExactVelocity.from_float(-v), v_after, length, Decimal(0), 0.0)
    specs = (EventSpec("T_1", 0, 1, "start"), EventSpec("T_1'", 0, 1, "stop"))
    return checked_scene(
        Scene(
            kind=WALL_COLLISION.kind,
            parameters=MappingProxyType({"v": v, "length": length, "eps": eps, "mass": mass}),
            rods=(Rod("rod", motion, mass, mass),),
            event_specs=specs,
            frames=single_rod_frames(motion),
            external_source="wall",
            heat=float(heat),
            origin_event=OriginEvent.CONTACT,
            obstacles=(Obstacle("wall", ObstacleKind.WALL, 0.0, REST),),
        )
    )


WALL_COLLISION = SceneDescription(
    kind="wall-collision",
    title="Wall crash / bounce",
    summary="A rod moving at −V hits a wall at x = 0 and sticks (ε = 0), bounces (ε = 1) or anything between.",
    source="Sec. 5",
    constructor=wall_collision,
    parameters=(V, LENGTH, EPS, MASS),
    frames=SINGLE_ROD_FRAMES,
    default_frame="rod before",
    events=(
        EventDescription("T_1", "the far end starts to decelerate", "Sec. 5, Eq. (22)"),
        EventDescription("T_1'", "the far end has its final velocity", "Sec. 5, Eq. (24)"),
    ),
    obstacles=(ObstacleKind.WALL,),
    presets=(
        ScenePreset("Sec. 5: crash into a wall, V = 0.6", {"v": 0.6, "length": 1.0, "eps": 0.0, "mass": 1.0}),
        ScenePreset("Sec. 5: elastic bounce, V = 0.6", {"v": 0.6, "length": 1.0, "eps": 1.0, "mass": 1.0}),
    ),
    order=50,
)

SCENES = (WALL_COLLISION,)
