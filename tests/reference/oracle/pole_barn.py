"""Reference of the pole in the barn: the paper's wall crash (Sec. 5, ``eps = 0``) beside a signal-limited stop.

Rod 0, Born-rigid: each point at rest-distance ``xi`` from the front (left) end follows
``x = sqrt(xi^2 + t^2)`` (Eq. (23)) from ``-gamma V xi`` (Eq. (22)) to rest at ``t = 0``. Rod 1,
signal-limited: each point moves on ``x = xi / gamma - V t`` until the stop front ``x = c_s t``
(leaving the contact at the origin) meets it, where the two lines cross, and rests there; its
clock reads ``(t - t_f)/gamma`` before and ``t - t_f`` after. The barn (its length, the door)
changes no worldline.
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
    at_reference_precision,
    gamma_of,
    hyperbola_point,
    material_point,
)


@at_reference_precision
def stopped_point(xi: Mp, V: Mp, c_s: Mp) -> Worldline:
    """The point at rest-distance ``xi`` from the front of the pole moving at ``-V``, stopped where
    ``xi / gamma - V t = c_s t``."""
    g = gamma_of(V)
    t_f = (xi / g) / (c_s + V)
    x_f = c_s * t_f

    def x(t: Mp) -> Mp:
        return xi / g - V * t if t <= t_f else x_f

    def tau(t: Mp) -> Mp:
        return (t - t_f) / g if t <= t_f else t - t_f

    return Worldline(x, tau, t_f, t_f)


@at_reference_precision
def ref_pole_barn(
    fractions: Sequence[float],
    v: float,
    length: float,
    barn_length: float | None = None,
    sound_speed: float = 1.0,
    door_time: float | None = None,
) -> RefScene:
    """Both poles; events ``T_1``, ``T_1'`` (Eqs. (22), (24)) and ``T_s``; extras: the signal-limited
    pole's rest length after, ``L1``, and the heat of each stop (``gamma - 1`` per unit mass: the
    Born-rigid pole's kinetic energy goes into the wall, the signal-limited pole's into the pole; the
    two stops are alternatives, never summed)."""
    V, L, c_s = F(v), F(length), F(sound_speed)
    g = gamma_of(V)
    born = [hyperbola_point(mp.mpf(0), material_point(f, L), +1, -V, mp.mpf(0)) for f in fractions]
    signal = [stopped_point(material_point(f, L), V, c_s) for f in fractions]
    rear = stopped_point(L, V, c_s)
    events = {"T_1": (-g * V * L, g * L), "T_1'": (mp.mpf(0), L), "T_s": (rear.start, rear.x(rear.start))}
    extra = {"rest_length_signal": rear.x(rear.start), "heat": g - 1}
    zero = mp.mpf(0)
    return RefScene([born, signal], events, [-V, -V], [zero, zero], [L, L], extra)


POLE_BARN = SceneReference(
    "pole-barn",
    70,
    ref_pole_barn,
    (
        ReferenceCase("pole-barn", {"v": 0.8, "length": 1.0, "barn_length": 0.6}, PARADOXES + 11),
        ReferenceCase(
            "pole-barn",
            {"v": 0.8, "length": 1.0, "barn_length": 0.6, "sound_speed": 0.5, "door_time": 0.2},
            PARADOXES + 12,
        ),
        ReferenceCase("pole-barn", {"v": 1 - 1e-9, "length": 1.0, "sound_speed": 0.3}, PARADOXES + 13),
        ReferenceCase("pole-barn", {"v": 1e-6, "length": 1.0}, SMALL_SPEEDS + 11),
        ReferenceCase("pole-barn", {"v": 1e-3, "length": 1.0, "sound_speed": 0.5}, SMALL_SPEEDS + 12),
    ),
)

SCENES = (POLE_BARN,)
