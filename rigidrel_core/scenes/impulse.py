"""Impulsive acceleration: the back end of a rod at rest jumps to V (paper Sec. 4)."""

from __future__ import annotations

from types import MappingProxyType

from .._build import IMPULSE, LENGTH, MASS, SINGLE_ROD_FRAMES, V, checked_scene, rigid_motion, single_rod_frames
from .._description import EventDescription, OriginEvent, SceneDescription
from .._exact import REST, ExactVelocity
from .._scene import EventSpec, Rod, Scene

#: The front end reaching V (Eq. (21)); the same in every scene.
_EVENTS = (EventSpec("T_F", 0, 1, "stop"),)


def impulsive_start(v: float, length: float, mass: float = 1.0) -> Scene:
    """Impulsive acceleration (Sec. 4, Fig. 1 dashed curve).

    The rod rests on ``[0, length]`` for ``t < 0``; at ``t = 0`` its left end jumps to
    ``v`` (``a'_B -> infinity``, so ``a'_F = 1/L0`` by Eq. (14)). The right end follows
    ``x = sqrt(L0^2 + t^2)`` (Eq. (20)) until ``T_F = v gamma L0`` (Eq. (21)). Event: ``"T_F"``.
    """
    v = V.check(v)
    length = LENGTH.check(length)
    mass = MASS.check(mass)
    motion = rigid_motion(REST, ExactVelocity.from_float(v), length, IMPULSE, 0.0)
    return checked_scene(
        Scene(
            kind=IMPULSIVE_START.kind,
            parameters=MappingProxyType({"v": v, "length": length, "mass": mass}),
            rods=(Rod("rod", motion, mass, mass),),
            event_specs=_EVENTS,
            frames=single_rod_frames(motion),
            external_source="drive",
            heat=0.0,
            origin_event=OriginEvent.KICK,
        )
    )


IMPULSIVE_START = SceneDescription(
    kind="impulsive-start",
    title="Impulsive start",
    summary="A rod at rest is kicked at its back end, which jumps to V; the front follows a hyperbola.",
    source="Sec. 4",
    constructor=impulsive_start,
    parameters=(V, LENGTH, MASS),
    frames=SINGLE_ROD_FRAMES,
    default_frame="rod after",
    events=(EventDescription("T_F", "the front (right) end reaches its final velocity (lab V)", "Sec. 4, Eq. (21)"),),
    meanings=MappingProxyType({"v": "final speed V (c = 1): the kicked back end jumps from rest to +V"}),
    order=30,
)

SCENES = (IMPULSIVE_START,)
