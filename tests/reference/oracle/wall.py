"""Reference of Sec. 5, Rigid body collisions: a rod hits a wall at ``x = 0`` with velocity ``-V``.

The wall's frame is the barycentric frame of an infinitely heavy wall, so the restitution
scales the proper velocity there: ``gamma' V' = eps gamma V`` (Eq. (29)). The touching end
jumps at the origin; each point at rest-distance ``xi`` from it follows
``x = sqrt(xi^2 + t^2)`` (Eq. (23)) from ``-gamma V xi`` to ``gamma' V' xi`` (Eqs. (22), (24)).
"""

from __future__ import annotations

import random
from collections.abc import Sequence

import mpmath as mp

from . import (
    MASS_RATIOS_AND_SIZES,
    PAPER_EXAMPLES,
    ULTRA_RELATIVISTIC,
    F,
    ReferenceCase,
    RefScene,
    SceneReference,
    at_reference_precision,
    gamma_of,
    hyperbola_point,
    log_uniform,
    material_point,
    speed,
)


@at_reference_precision
def ref_wall_collision(fractions: Sequence[float], v: float, length: float, eps: float) -> RefScene:
    """The rod at ``-v`` leaves with ``V'`` (Eq. (29)); events ``T_1``, ``T_1'`` of the far end; the heat
    given to the wall, ``gamma - gamma'`` per unit rest mass."""
    V, L, e = F(v), F(length), F(eps)
    p = e * gamma_of(V) * V
    Vp = p / mp.sqrt(1 + p * p)
    wl = [hyperbola_point(mp.mpf(0), material_point(f, L), +1, -V, Vp) for f in fractions]
    g, gp = gamma_of(V), gamma_of(Vp)
    events = {"T_1": (-g * V * L, g * L), "T_1'": (gp * Vp * L, gp * L)}
    return RefScene([wl], events, [-V], [Vp], [L], {"heat": g - gp})


def _draw(rng: random.Random) -> dict[str, float | None]:
    """Any length in [1e-6, 1e6], any speed, any restitution in [0, 1)."""
    length = log_uniform(rng, -6, 6)
    return {"v": speed(rng), "length": length, "eps": rng.random()}


WALL_COLLISION = SceneReference(
    "wall-collision",
    50,
    ref_wall_collision,
    (
        ReferenceCase("wall-collision", {"v": 0.6, "length": 1.0, "eps": 0.0}, PAPER_EXAMPLES + 3),
        ReferenceCase("wall-collision", {"v": 0.6, "length": 1.0, "eps": 0.5}, PAPER_EXAMPLES + 4),
        ReferenceCase("wall-collision", {"v": 0.6, "length": 1.0, "eps": 1.0}, PAPER_EXAMPLES + 5),
        ReferenceCase("wall-collision", {"v": 1 - 1e-12, "length": 1.0, "eps": 1.0}, ULTRA_RELATIVISTIC + 3),
        ReferenceCase("wall-collision", {"v": 1 - 1e-12, "length": 1.0, "eps": 0.3}, ULTRA_RELATIVISTIC + 4),
        ReferenceCase("wall-collision", {"v": 0.4, "length": 1e-6, "eps": 0.6}, MASS_RATIOS_AND_SIZES + 7),
    ),
    _draw,
)

SCENES = (WALL_COLLISION,)
