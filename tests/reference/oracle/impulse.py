"""Reference of Sec. 4, Impulsive acceleration: the back end jumps from rest to ``V`` at the origin.

Each material point at rest-distance ``xi`` from the back end follows Eq. (20)
``x = sqrt(xi^2 + t^2)`` until it moves with ``V``; the front end stops at
``T_F = gamma V L0`` (Eq. (21)), at ``x = gamma L0``.
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
def ref_impulsive_start(fractions: Sequence[float], v: float, length: float) -> RefScene:
    """From rest to ``v`` by a kick of the back end; the event ``T_F`` (Eq. (21))."""
    V, L = F(v), F(length)
    wl = [hyperbola_point(mp.mpf(0), material_point(f, L), +1, mp.mpf(0), V) for f in fractions]
    g = gamma_of(V)
    return RefScene([wl], {"T_F": (V * g * L, g * L)}, [mp.mpf(0)], [V], [L], {})


def _draw(rng: random.Random) -> dict[str, float | None]:
    """Any length in [1e-6, 1e6], any speed."""
    length = log_uniform(rng, -6, 6)
    return {"v": speed(rng), "length": length}


IMPULSIVE_START = SceneReference(
    "impulsive-start",
    30,
    ref_impulsive_start,
    (
        ReferenceCase("impulsive-start", {"v": 0.6, "length": 1.0}, PAPER_EXAMPLES + 2),
        ReferenceCase("impulsive-start", {"v": 1 - 1e-12, "length": 1.0}, ULTRA_RELATIVISTIC + 2),
        ReferenceCase("impulsive-start", {"v": 0.9, "length": 1e6}, MASS_RATIOS_AND_SIZES + 6),
    ),
    _draw,
)

SCENES = (IMPULSIVE_START,)
