"""Reference of Sec. 3, Constant acceleration: acceleration from rest, deceleration to rest, any velocity change.

Each material point at rest-distance ``xi`` from the back end has its own proper
acceleration ``a' = 1/(xi + 1/a'_B)`` with ``a'_B = a'_F / (1 - a'_F L0)`` (Eq. (15)) and
follows Eq. (4) ``x = xi + (sqrt(1 + a'^2 t^2) - 1)/a'`` until it reaches ``V``, at
``T = gamma V / a'`` (Eq. (9)); deceleration is the same worldlines with ``t -> -t`` (Sec. 3:
Eqs. (5)-(6) with ``t -> -t``).
A general change ``V_i -> V_f`` is a family of hyperbolas about one centre (Eq. (23)).
"""

from __future__ import annotations

import random
from collections.abc import Sequence

import mpmath as mp

from . import (
    HORIZON,
    MASS_RATIOS_AND_SIZES,
    PAPER_EXAMPLES,
    ULTRA_RELATIVISTIC,
    VELOCITY_CHANGES,
    WEAK_ACCELERATION,
    F,
    ReferenceCase,
    RefScene,
    SceneReference,
    accelerating_point,
    at_reference_precision,
    gamma_of,
    hyperbola_point,
    log_uniform,
    material_point,
    speed,
    time_reversed,
)


# ------------------------------------------------------------------ builders
@at_reference_precision
def ref_constant_acceleration(fractions: Sequence[float], v: float, length: float, a_front: float) -> RefScene:
    """From rest to ``v``; the events ``T_B``, ``T_F`` where the back and front end stop (Eqs. (9), (8))."""
    V, L, aF = F(v), F(length), F(a_front)
    aB = aF / (1 - aF * L)  # Eq. (15)
    wl = []
    for f in fractions:
        xi = material_point(f, L)
        alpha = 1 / (xi + 1 / aB)
        wl.append(accelerating_point(xi, alpha, V))
    g = gamma_of(V)
    events = {
        "T_B": (g * V / aB, (g - 1) / aB),
        "T_F": (g * V / aF, L + (g - 1) / aF),
    }
    return RefScene([wl], events, [mp.mpf(0)], [V], [L], {"a_B": aB})


@at_reference_precision
def ref_deceleration(fractions: Sequence[float], v: float, length: float, a_front: float) -> RefScene:
    """From ``-v`` to rest on ``[0, L0]`` at ``t = 0``: :func:`ref_constant_acceleration` with ``t -> -t``."""
    acc = ref_constant_acceleration(fractions, v, length, a_front)
    wl = [[time_reversed(w) for w in acc.worldlines[0]]]
    events = {
        "-T_F": (-acc.events["T_F"][0], acc.events["T_F"][1]),
        "-T_B": (-acc.events["T_B"][0], acc.events["T_B"][1]),
    }
    return RefScene(wl, events, [-F(v)], [mp.mpf(0)], acc.lengths_rest, {})


@at_reference_precision
def ref_velocity_change(
    fractions: Sequence[float], v_initial: float, v_final: float, length: float, a_front: float | None
) -> RefScene:
    """``v_initial -> v_final``; the end nearer the horizon (B) is ``(1 - a'_F L0)/a'_F`` from the centre
    (Eq. (15)), 0 for ``a_front=None`` (the impulsive limit, Sec. 4). Events ``T_B0``, ``T_F0`` (starts)
    and ``T_B``, ``T_F`` (stops)."""
    Vi, Vf, L = F(v_initial), F(v_final), F(length)
    near = mp.mpf(0) if a_front is None else (1 - F(a_front) * L) / F(a_front)
    side = 1 if Vf > Vi else -1
    centre = -near if side == 1 else L + near
    wl = []
    for f in fractions:
        d = abs(material_point(f, L) - centre)
        wl.append(hyperbola_point(centre, d, side, Vi, Vf))
    near_xi, far_xi = (mp.mpf(0), L) if side == 1 else (L, mp.mpf(0))
    events = {}
    for name, xi in (("B", near_xi), ("F", far_xi)):
        d = abs(xi - centre)
        for suffix, vel in (("0", Vi), ("", Vf)):
            g = gamma_of(vel)
            events[f"T_{name}{suffix}"] = (side * d * g * vel, centre + side * d * g)
    return RefScene([wl], events, [Vi], [Vf], [L], {})


# ------------------------------------------------------------------ random cases
def _draw_acceleration(rng: random.Random) -> dict[str, float | None]:
    """Any length in [1e-6, 1e6], any speed, ``a'_F L0 = 1 - 10^-k`` with ``k`` in [0.01, 6]."""
    length = log_uniform(rng, -6, 6)
    return {"v": speed(rng), "length": length, "a_front": (1 - 10 ** -rng.uniform(0.01, 6)) / length}


def _draw_velocity_change(rng: random.Random) -> dict[str, float | None]:
    """Two velocities of random sign and speed in random order; impulsive in 30% of the cases."""
    length = log_uniform(rng, -6, 6)
    a, b = sorted([rng.uniform(-1, 1) * speed(rng), rng.uniform(-1, 1) * speed(rng)])
    if rng.random() < 0.5:
        a, b = b, a
    return {
        "v_initial": a,
        "v_final": b,
        "length": length,
        "a_front": None if rng.random() < 0.3 else rng.uniform(0.01, 0.999) / length,
    }


# ------------------------------------------------------------------ fixed cases
def _weak(kind: str, a_front_length: float, position: int, length: float = 1.0, **velocities: float) -> ReferenceCase:
    """A case of :data:`WEAK_ACCELERATION`: ``a'_F L0`` given, so every radius is about ``L0 / (a'_F L0)``."""
    return ReferenceCase(
        kind, {**velocities, "length": length, "a_front": a_front_length / length}, WEAK_ACCELERATION + position
    )


CONSTANT_ACCELERATION = SceneReference(
    "constant-acceleration",
    10,
    ref_constant_acceleration,
    (
        ReferenceCase("constant-acceleration", {"v": 0.6, "length": 1.0, "a_front": 0.5}, PAPER_EXAMPLES + 0),
        ReferenceCase("constant-acceleration", {"v": 1 - 1e-12, "length": 1.0, "a_front": 0.5}, ULTRA_RELATIVISTIC + 0),
        ReferenceCase("constant-acceleration", {"v": 1 - 1e-9, "length": 2.5, "a_front": 0.1}, ULTRA_RELATIVISTIC + 1),
        ReferenceCase("constant-acceleration", {"v": 0.6, "length": 1.0, "a_front": 1 - 1e-6}, HORIZON + 0),
        ReferenceCase("constant-acceleration", {"v": 0.6, "length": 1.0, "a_front": 1e-6}, HORIZON + 2),
        ReferenceCase("constant-acceleration", {"v": 0.6, "length": 1e-6, "a_front": 2.5e5}, MASS_RATIOS_AND_SIZES + 4),
        ReferenceCase("constant-acceleration", {"v": 0.6, "length": 1e6, "a_front": 2.5e-7}, MASS_RATIOS_AND_SIZES + 5),
        _weak("constant-acceleration", 1e-3, 0, v=0.1),
        _weak("constant-acceleration", 1e-5, 1, v=0.6),
        _weak("constant-acceleration", 1e-7, 2, v=0.99),
        _weak("constant-acceleration", 1e-5, 3, v=1 - 1e-9, length=1e-3),
    ),
    _draw_acceleration,
)

DECELERATION = SceneReference(
    "deceleration",
    20,
    ref_deceleration,
    (
        ReferenceCase("deceleration", {"v": 0.6, "length": 1.0, "a_front": 0.5}, PAPER_EXAMPLES + 1),
        ReferenceCase("deceleration", {"v": 0.8, "length": 1.0, "a_front": 1 - 1e-6}, HORIZON + 1),
        _weak("deceleration", 1e-3, 4, v=0.99),
        _weak("deceleration", 1e-5, 5, v=0.1),
        _weak("deceleration", 1e-7, 6, v=0.6),
        _weak("deceleration", 1e-7, 7, v=1 - 1e-9, length=1e3),
    ),
    _draw_acceleration,
)

VELOCITY_CHANGE = SceneReference(
    "velocity-change",
    40,
    ref_velocity_change,
    (
        ReferenceCase(
            "velocity-change",
            {"v_initial": 0.3, "v_final": 0.6, "length": 1.0, "a_front": 0.4},
            VELOCITY_CHANGES + 0,
        ),
        ReferenceCase(
            "velocity-change",
            {"v_initial": 0.6, "v_final": -0.5, "length": 1.0, "a_front": None},
            VELOCITY_CHANGES + 1,
        ),
        ReferenceCase(
            "velocity-change",
            {"v_initial": -0.999999, "v_final": 0.999999, "length": 1.0, "a_front": 0.9},
            VELOCITY_CHANGES + 2,
        ),
        ReferenceCase(
            "velocity-change",
            {"v_initial": 0.5, "v_final": 0.0, "length": 2.0, "a_front": 0.25},
            VELOCITY_CHANGES + 3,
        ),
        _weak("velocity-change", 1e-3, 8, v_initial=0.1, v_final=0.99),
        _weak("velocity-change", 1e-5, 9, v_initial=0.6, v_final=-0.3),
        _weak("velocity-change", 1e-7, 10, v_initial=-0.99, v_final=0.5),
        _weak("velocity-change", 1e-5, 11, v_initial=0.5, v_final=1 - 1e-9),
    ),
    _draw_velocity_change,
)

SCENES = (CONSTANT_ACCELERATION, DECELERATION, VELOCITY_CHANGE)
