"""Scene constructors by name, with their parameters and the paper's default values."""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass
from types import MappingProxyType

from ._scenes import (
    Scene,
    SceneKind,
    constant_acceleration,
    deceleration,
    impulsive_start,
    rod_collision,
    velocity_change,
    wall_collision,
)
from ._validate import ParameterError


@dataclass(frozen=True)
class ParameterSpec:
    """One scene parameter: its name, the paper's default value and its allowed range."""

    name: str
    default: float | None
    allowed: str
    description: str


_V = ParameterSpec("v", 0.6, "(0, 1)", "final speed V (c = 1)")
_LENGTH = ParameterSpec("length", 1.0, "> 0", "rest length L0")
_A_FRONT = ParameterSpec("a_front", 0.5, "a_front * length in (0, 1)", "front-end proper acceleration a'_F")
_MASS = ParameterSpec("mass", 1.0, "> 0", "rest mass M")
_EPS = ParameterSpec("eps", 1.0, "[0, 1]", "coefficient of restitution epsilon")

SCENE_PARAMETERS: Mapping[SceneKind, tuple[ParameterSpec, ...]] = MappingProxyType(
    {
        SceneKind.CONSTANT_ACCELERATION: (_V, _LENGTH, _A_FRONT, _MASS),
        SceneKind.DECELERATION: (_V, _LENGTH, _A_FRONT, _MASS),
        SceneKind.VELOCITY_CHANGE: (
            ParameterSpec("v_initial", 0.2, "(-1, 1)", "initial velocity"),
            ParameterSpec("v_final", 0.6, "(-1, 1), != v_initial", "final velocity"),
            _LENGTH,
            ParameterSpec("a_front", 0.5, "a_front * length in (0, 1); omit for an impulse", _A_FRONT.description),
            _MASS,
        ),
        SceneKind.IMPULSIVE_START: (_V, _LENGTH, _MASS),
        SceneKind.WALL_COLLISION: (_V, _LENGTH, _EPS, _MASS),
        SceneKind.ROD_COLLISION: (
            ParameterSpec("v1", 0.6, "(-1, 1)", "velocity V1 of rod 1 (left)"),
            ParameterSpec("v2", 0.0, "(-1, v1)", "velocity V2 of rod 2 (right)"),
            ParameterSpec("m1", 1.0, "> 0", "rest mass M1"),
            ParameterSpec("m2", 2.0, "> 0", "rest mass M2"),
            ParameterSpec("l1", 1.0, "> 0", "rest length L1"),
            ParameterSpec("l2", 1.0, "> 0", "rest length L2"),
            _EPS,
        ),
    }
)

_CONSTRUCTORS: Mapping[SceneKind, Callable[..., Scene]] = MappingProxyType(
    {
        SceneKind.CONSTANT_ACCELERATION: constant_acceleration,
        SceneKind.DECELERATION: deceleration,
        SceneKind.VELOCITY_CHANGE: velocity_change,
        SceneKind.IMPULSIVE_START: impulsive_start,
        SceneKind.WALL_COLLISION: wall_collision,
        SceneKind.ROD_COLLISION: rod_collision,
    }
)


def scene_kind(name: str | SceneKind) -> SceneKind:
    """The :class:`SceneKind` called ``name`` (e.g. ``"rod-collision"``)."""
    try:
        return SceneKind(name)
    except ValueError:
        allowed = ", ".join(k.value for k in SceneKind)
        raise ParameterError("scene", f"one of {allowed}", name) from None


def build_scene(kind: str | SceneKind, **params: float | None) -> Scene:
    """Build a scene by name; missing parameters take the paper's values (see ``SCENE_PARAMETERS``)."""
    k = scene_kind(kind)
    specs = {p.name: p for p in SCENE_PARAMETERS[k]}
    for name in params:
        if name not in specs:
            raise ParameterError(name, f"one of the parameters of {k.value}: {', '.join(specs)}", params[name])
    values = {n: params.get(n, p.default) for n, p in specs.items()}
    return _CONSTRUCTORS[k](**values)
