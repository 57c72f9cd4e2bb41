"""Reference of Secs. 5-6 (Rigid body collisions, An elastic collision): rod 1 at ``V1`` hits rod 2 at ``V2 < V1``.

The velocities after follow Sec. 6's route at 50 digits: the barycentric velocity
``u = (M1 g1 V1 + M2 g2 V2)/(M1 g1 + M2 g2)`` (Eq. (26)), each rod's barycentric velocity
``bar V = (V - u)/(1 - u V)`` (Eq. (27)), the restitution ``bar g' bar V' = -eps bar g bar V``
(Eq. (29); ``V̄' = −V̄`` for eps = 1, Eq. (28)) and back by velocity addition
``V' = (u + bar V')/(1 + u bar V')`` (Eq. (31)). The touching ends jump at the origin; every
other point follows ``x = -+sqrt(xi^2 + t^2)`` (Eq. (23)) between Eqs. (22) and (24)-(25).
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
    Mp,
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
def ref_collision_velocities(v1: float, v2: float, m1: float, m2: float, eps: float) -> dict[str, Mp]:
    """Sec. 6 route: u (Eq. (26)), barycentric velocities (Eq. (27)), Eq. (29), velocity addition back (Eq. (31))."""
    V1, V2, M1, M2, e = F(v1), F(v2), F(m1), F(m2), F(eps)
    g1, g2 = gamma_of(V1), gamma_of(V2)
    u = (M1 * g1 * V1 + M2 * g2 * V2) / (M1 * g1 + M2 * g2)
    Vb1 = (V1 - u) / (1 - u * V1)
    Vb2 = (V2 - u) / (1 - u * V2)
    out = {"u": u, "Vb1": Vb1, "Vb2": Vb2}
    for i, Vb in ((1, Vb1), (2, Vb2)):
        p = -e * gamma_of(Vb) * Vb  # Eq. (29)
        Vbp = p / mp.sqrt(1 + p * p)
        out[f"Vbp{i}"] = Vbp
        out[f"Vp{i}"] = (u + Vbp) / (1 + u * Vbp)  # Eq. (31)
    # rest-mass gain: energy conservation in the barycentric frame, common factor k
    E_bar = M1 * gamma_of(Vb1) + M2 * gamma_of(Vb2)
    k = E_bar / (M1 * gamma_of(out["Vbp1"]) + M2 * gamma_of(out["Vbp2"]))
    out["k"] = k
    out["heat"] = (k - 1) * (M1 + M2)
    return out


@at_reference_precision
def ref_rod_collision(
    fractions: Sequence[float],
    v1: float,
    v2: float,
    mass1: float,
    mass2: float,
    length1: float,
    length2: float,
    eps: float,
) -> RefScene:
    """Both rods; events ``T_1``, ``T_1'``, ``T_2``, ``T_2'`` of the far ends (Eqs. (22), (24), (25))."""
    sol = ref_collision_velocities(v1, v2, mass1, mass2, eps)
    V1, V2, L1, L2 = F(v1), F(v2), F(length1), F(length2)
    Vp1, Vp2 = sol["Vp1"], sol["Vp2"]
    rod1, rod2 = [], []
    for f in fractions:
        xi1 = material_point(f, L1)
        xi2 = material_point(f, L2)
        rod1.append(hyperbola_point(mp.mpf(0), L1 - xi1, -1, V1, Vp1))
        rod2.append(hyperbola_point(mp.mpf(0), xi2, +1, V2, Vp2))
    g1, g2, gp1, gp2 = gamma_of(V1), gamma_of(V2), gamma_of(Vp1), gamma_of(Vp2)
    events = {  # Eqs. (22), (24), (25) with x from Eq. (23)
        "T_1": (-g1 * V1 * L1, -g1 * L1),
        "T_1'": (-gp1 * Vp1 * L1, -gp1 * L1),
        "T_2": (g2 * V2 * L2, g2 * L2),
        "T_2'": (gp2 * Vp2 * L2, gp2 * L2),
    }
    return RefScene([rod1, rod2], events, [V1, V2], [Vp1, Vp2], [L1, L2], sol)


def _draw(rng: random.Random) -> dict[str, float | None]:
    """Rod 1 at any velocity, rod 2 slower (at least 1e-12 below light speed); mass ratios and
    length ratios over 12 and 4 decades, any restitution."""
    length = log_uniform(rng, -6, 6)
    v1 = rng.uniform(-0.5, 1) * speed(rng)
    v2 = v1 - rng.uniform(0.01, 1) * (1 + v1)
    v2 = max(v2, -1 + 1e-12)
    return {
        "v1": v1,
        "v2": v2,
        "mass1": 1.0,
        "mass2": log_uniform(rng, -6, 6),
        "length1": length,
        "length2": length * log_uniform(rng, -2, 2),
        "eps": rng.random(),
    }


def _rods(**params: float) -> dict[str, float | None]:
    """Rod 1 at 0.6 onto rod 2 at rest, unit rest masses and lengths, elastic, unless given."""
    return {"v1": 0.6, "v2": 0.0, "mass1": 1.0, "mass2": 1.0, "length1": 1.0, "length2": 1.0, "eps": 1.0, **params}


ROD_COLLISION = SceneReference(
    "rod-collision",
    60,
    ref_rod_collision,
    (
        # Figs. 3 and 4, and Fig. 3's masses with eps = 1/2
        ReferenceCase("rod-collision", _rods(mass2=2.0), PAPER_EXAMPLES + 6),
        ReferenceCase("rod-collision", _rods(mass1=2.0), PAPER_EXAMPLES + 7),
        ReferenceCase("rod-collision", _rods(mass2=2.0, eps=0.5), PAPER_EXAMPLES + 8),
        ReferenceCase("rod-collision", _rods(v1=1 - 1e-12), ULTRA_RELATIVISTIC + 5),
        ReferenceCase(
            "rod-collision", _rods(v1=0.9, v2=-(1 - 1e-9), mass2=3.0, length2=0.5, eps=0.7), ULTRA_RELATIVISTIC + 6
        ),
        ReferenceCase("rod-collision", _rods(v1=1 - 1e-12, v2=1 - 1e-9), ULTRA_RELATIVISTIC + 7),
        ReferenceCase("rod-collision", _rods(mass2=1e6), MASS_RATIOS_AND_SIZES + 0),
        ReferenceCase("rod-collision", _rods(mass2=1e-6), MASS_RATIOS_AND_SIZES + 1),
        ReferenceCase(
            "rod-collision",
            _rods(v1=0.5, v2=-0.5, mass1=1e6, length1=1e-6, length2=1e6, eps=0.2),
            MASS_RATIOS_AND_SIZES + 2,
        ),
        ReferenceCase(
            "rod-collision", _rods(v1=0.3, v2=-0.2, length1=1e6, length2=1e-6, eps=0.0), MASS_RATIOS_AND_SIZES + 3
        ),
    ),
    _draw,
)

SCENES = (ROD_COLLISION,)
