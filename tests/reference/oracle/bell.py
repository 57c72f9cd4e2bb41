"""Reference of Bell's spaceships (the paper's Sec. 1 citation, with Sec. 3's constant acceleration).

Each material point at lab ``xi`` (at rest before ``t = 0``) follows Eq. (4) with its own proper
acceleration ``alpha = 1/(1/a + d)``, ``d`` its rest-distance from its rod's rear end (Eq. (15)):
the rear ship on ``[0, l]``, the front ship on ``[s, s + l]``, the Born-rigid comparison rod on
``[0, s]``. Each reaches ``V`` at ``T = gamma V / alpha`` (Eq. (9)).

The string's rest length is found by its definition, not by the core's closed form: at the rear
ship's rapidity ``theta`` its front end is at lab ``(R sinh theta, -1/a + R cosh theta)``
(``R = 1/a + l``); boosted into the frame of rapidity ``theta`` (the rear ship's momentarily
comoving frame: the convention of the strain) it has a frame time, at which the front ship's rear
end is sliced by root finding (:func:`frame_slice`); the difference of the two positions is the
string's rest length, and ``L/(s - l) - 1`` its strain (at 50 digits the subtraction keeps ~35
digits of a strain of 1e-13). The break (given a breaking strain) is the ``theta`` where that
length reaches ``(1 + e_b)(s - l)``, by bisection.
"""

from __future__ import annotations

from collections.abc import Sequence

import mpmath as mp

from . import (
    PARADOXES,
    SMALL_SPEEDS,
    F,
    Mp,
    ReferenceCase,
    RefScene,
    SceneReference,
    Worldline,
    accelerating_point,
    at_reference_precision,
    boost_event,
    frame_slice,
    gamma_of,
    material_point,
)


@at_reference_precision
def string_rest_length(theta: Mp, a: Mp, ship: Mp, front_rear: Worldline) -> Mp:
    """The string's rest length in the rear ship's comoving frame at its rapidity ``theta``."""
    r = 1 / a
    big_r = r + ship
    end = (big_r * mp.sinh(theta), -r + big_r * mp.cosh(theta))
    beta = mp.tanh(theta)
    t_frame, x_frame = boost_event(end, beta)
    return frame_slice(front_rear, beta, t_frame) - x_frame


@at_reference_precision
def ref_bell_spaceships(
    fractions: Sequence[float],
    v: float,
    separation: float,
    a_back: float,
    ship_length: float | None = None,
    breaking_strain: float | None = None,
) -> RefScene:
    """Three rods (rear ship, front ship, comparison rod); events ``T_B1``, ``T_F1``, ``T_B2``, ``T_F2``,
    ``T_Frod``; extras: the string's final rest length and strain, its strain at three rapidities of the
    rear ship (``rapidity_k``, ``theta_V k/4`` rounded to float64 and taken as exact, and ``strain_k``,
    ``k = 1, 2, 3``: the string's front end on its hyperbola, then coasting, for the default ships)
    and, given a breaking strain it reaches, the break event's lab ``(t, x)`` (``break_t``, ``break_x``)."""
    V, s, a = F(v), F(separation), F(a_back)
    ship = s / 10 if ship_length is None else F(ship_length)
    g = gamma_of(V)
    r = 1 / a

    def point(start: Mp, d: Mp) -> Worldline:
        return accelerating_point(start + d, 1 / (r + d), V)

    def stop(start: Mp, d: Mp) -> tuple[Mp, Mp]:
        return (g * V * (r + d), start + d + (g - 1) * (r + d))

    rear = [point(mp.mpf(0), material_point(f, ship)) for f in fractions]
    front = [point(s, material_point(f, ship)) for f in fractions]
    rod = [point(mp.mpf(0), material_point(f, s)) for f in fractions]
    events = {
        "T_B1": stop(mp.mpf(0), mp.mpf(0)),
        "T_F1": stop(mp.mpf(0), ship),
        "T_B2": stop(s, mp.mpf(0)),
        "T_F2": stop(s, ship),
        "T_Frod": stop(mp.mpf(0), s),
    }
    front_rear = point(s, mp.mpf(0))
    theta_v = mp.atanh(V)
    unstretched = s - ship
    final = string_rest_length(theta_v, a, ship, front_rear)
    extra = {"string_final": final, "rears_apart_after": g * s, "final_strain": final / unstretched - 1}
    for k in (1, 2, 3):
        theta = F(float(theta_v * k / 4))
        extra[f"rapidity_{k}"] = theta
        extra[f"strain_{k}"] = string_rest_length(theta, a, ship, front_rear) / unstretched - 1
    if breaking_strain is not None:
        target = (1 + F(breaking_strain)) * (s - ship)
        if string_rest_length(theta_v, a, ship, front_rear) >= target:
            lo, hi = mp.mpf(0), theta_v
            while hi - lo > theta_v * mp.mpf(10) ** -45:
                mid = (lo + hi) / 2
                if string_rest_length(mid, a, ship, front_rear) < target:
                    lo = mid
                else:
                    hi = mid
            theta = (lo + hi) / 2
            extra["break_t"] = (r + ship) * mp.sinh(theta)
            extra["break_x"] = -r + (r + ship) * mp.cosh(theta)
    zero = mp.mpf(0)
    return RefScene([rear, front, rod], events, [zero, zero, zero], [V, V, V], [ship, ship, s], extra)


BELL_SPACESHIPS = SceneReference(
    "bell-spaceships",
    60,
    ref_bell_spaceships,
    (
        ReferenceCase("bell-spaceships", {"v": 0.6, "separation": 1.0, "a_back": 0.5}, PARADOXES + 1),
        ReferenceCase(
            "bell-spaceships",
            {"v": 0.9, "separation": 2.0, "a_back": 3.0, "ship_length": 0.5, "breaking_strain": 0.5},
            PARADOXES + 2,
        ),
        ReferenceCase(
            "bell-spaceships",
            {"v": 0.6, "separation": 1.0, "a_back": 0.5, "breaking_strain": 0.1},
            PARADOXES + 3,
        ),
        ReferenceCase("bell-spaceships", {"v": 1 - 1e-9, "separation": 1.0, "a_back": 1e-3}, PARADOXES + 4),
        # small speeds and small breaking strains, after every other case (their own group)
        ReferenceCase("bell-spaceships", {"v": 1e-6, "separation": 1.0, "a_back": 0.5}, SMALL_SPEEDS + 1),
        ReferenceCase(
            "bell-spaceships", {"v": 1e-6, "separation": 1.0, "a_back": 0.5, "breaking_strain": 2e-13}, SMALL_SPEEDS + 2
        ),
        ReferenceCase(
            "bell-spaceships", {"v": 1e-3, "separation": 1.0, "a_back": 0.5, "breaking_strain": 1e-6}, SMALL_SPEEDS + 3
        ),
        ReferenceCase(
            "bell-spaceships", {"v": 1e-3, "separation": 1.0, "a_back": 0.5, "breaking_strain": 1e-9}, SMALL_SPEEDS + 4
        ),
        ReferenceCase(
            "bell-spaceships", {"v": 1e-3, "separation": 1.0, "a_back": 0.5, "breaking_strain": 1e-12}, SMALL_SPEEDS + 5
        ),
        ReferenceCase(
            "bell-spaceships",
            {"v": 1e-3, "separation": 2.0, "a_back": 3.0, "ship_length": 0.5, "breaking_strain": 1e-12},
            SMALL_SPEEDS + 6,
        ),
        ReferenceCase(  # the break where the front ship's rear already coasts
            "bell-spaceships", {"v": 1e-3, "separation": 1.0, "a_back": 0.5, "breaking_strain": 5e-7}, SMALL_SPEEDS + 7
        ),
    ),
)

SCENES = (BELL_SPACESHIPS,)
