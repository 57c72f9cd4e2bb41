"""The paper's lab formulas typed in as printed, in float64 (c = 1).

This is what the textbook method, the solve_ivp method and the spacetimelib polylines
start from: every rod end's lab worldline, as three pieces,

* ``t <= t_start``: inertial, ``x = x_start + v_before (t - t_start)``;
* ``t_start <= t <= t_stop``: accelerated, by the formula the paper prints for it:
  Eq. (4) ``x = xi + (sqrt(1 + a'^2 t^2) - 1)/a'`` for constant acceleration from rest
  at ``t = 0`` (Sec. 3; ``a'_F`` given, ``a'_B = a'_F / (1 - a'_F L0)``, Eq. (15)), or Eqs. (20),
  (23) ``x = side sqrt(L^2 + t^2)`` for the far end of a kicked rod (Secs. 4-5);
* ``t >= t_stop``: inertial, ``x = x_stop + v_after (t - t_stop)``.

Switch times from Eqs. (9), (21), (22), (25); Lorentz factors ``gamma = 1/sqrt(1 - V^2)``;
collision velocities by the route of Sec. 6 (barycentric ``u``, Eq. (26), velocity addition,
Eq. (29), Eq. (31)), all in float64 exactly as a reader would type them.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Literal

import numpy as np
import numpy.typing as npt

from .scenes import BenchScene

FloatArray = npt.NDArray[np.float64]
#: Which printed formula the accelerated piece uses: "deriv" Eq. (4), "imp" Eqs. (20), (23), "kick" none
#: (the velocity jumps).
PieceForm = Literal["kick", "deriv", "imp"]


def textbook_gamma(v: float) -> float:
    """``gamma = 1/sqrt(1 - V^2)``, as printed."""
    return 1.0 / math.sqrt(1.0 - v * v)


def inertial_slice(x0: float, t0: float, v: float, beta: float, gamma: float, t_frame: FloatArray) -> FloatArray:
    """``x'`` at frame times ``t_frame`` of the lab line ``x = x0 + v (t - t0)``, as printed: the lab time
    ``t = (t'/gamma + beta (x0 - v t0)) / (1 - beta v)`` of each slice, then ``x' = gamma (x - beta t)``."""
    t = (t_frame / gamma + beta * (x0 - v * t0)) / (1.0 - beta * v)
    return gamma * ((x0 + v * (t - t0)) - beta * t)


def textbook_collision(v1: float, v2: float, m1: float, m2: float, eps: float) -> tuple[float, float]:
    """Sec. 6 as printed: ``u = (M1 g1 V1 + M2 g2 V2)/(M1 g1 + M2 g2)``, ``bar V = (V - u)/(1 - u V)``,
    ``bar g' bar V' = -eps bar g bar V`` (Eq. (29)), ``V' = (u + bar V')/(1 + u bar V')`` (Eq. (31))."""
    g1, g2 = textbook_gamma(v1), textbook_gamma(v2)
    u = (m1 * g1 * v1 + m2 * g2 * v2) / (m1 * g1 + m2 * g2)
    out = []
    for v in (v1, v2):
        vb = (v - u) / (1.0 - u * v)
        p = -eps * textbook_gamma(vb) * vb
        vbp = p / math.sqrt(1.0 + p * p)
        out.append((u + vbp) / (1.0 + u * vbp))
    return out[0], out[1]


@dataclass(frozen=True)
class PaperEnd:
    """One rod end's lab worldline in the paper's formulas (see the module docstring)."""

    form: PieceForm
    t_start: float
    t_stop: float
    x_start: float
    x_stop: float
    v_before: float
    v_after: float
    accel: float = 0.0
    """Proper acceleration ``a'`` of the accelerated piece (``1/L`` for Eq. (20)); 0 for a kick."""
    side: float = 1.0
    """+1 if the velocity increases, -1 if it decreases."""
    xi: float = 0.0
    """Eq. (4): the rest position before the push."""

    @property
    def radius(self) -> float:
        """Distance of the end from its hyperbola's centre (rest frame): ``1/a'``."""
        return 1.0 / self.accel

    @property
    def centre(self) -> float:
        """Lab x of the hyperbola's centre at ``t = 0``: ``xi - 1/a'`` (Eq. (4)) or 0 (Eq. (20))."""
        return self.xi - 1.0 / self.accel if self.form == "deriv" else 0.0

    def accelerated_x(self, t: FloatArray) -> FloatArray:
        """The printed formula of the accelerated piece at lab times ``t``."""
        if self.form == "deriv":
            a = self.accel
            return self.xi + (np.sqrt(1.0 + a * a * t * t) - 1.0) / a
        d = self.radius
        return self.side * np.sqrt(d * d + t * t)


def _deriv_end(xi: float, a: float, v: float) -> PaperEnd:
    """Eq. (4) from rest at ``xi`` until speed ``v``, reached at ``T = gamma v / a'`` (Eq. (9))
    and ``X = xi + (gamma - 1)/a'`` (Eq. (8))."""
    g = textbook_gamma(v)
    return PaperEnd("deriv", 0.0, g * v / a, xi, xi + (g - 1.0) / a, 0.0, v, accel=a, side=1.0, xi=xi)


def _kick_end(v_before: float, v_after: float) -> PaperEnd:
    """An end kicked at the origin: inertial before and after."""
    return PaperEnd("kick", 0.0, 0.0, 0.0, 0.0, v_before, v_after)


def _far_end(length: float, side: float, v_before: float, v_after: float) -> PaperEnd:
    """Eq. (23) ``x = side sqrt(L^2 + t^2)`` from ``T = side gamma V L`` to ``T' = side gamma' V' L``
    (Eqs. (22), (25)); ``x = side gamma L`` at either end."""
    g0, g1 = textbook_gamma(v_before), textbook_gamma(v_after)
    return PaperEnd(
        "imp",
        side * g0 * v_before * length,
        side * g1 * v_after * length,
        side * g0 * length,
        side * g1 * length,
        v_before,
        v_after,
        accel=1.0 / length,
        side=1.0 if v_after > v_before else -1.0,
    )


def paper_ends(scene: BenchScene) -> tuple[tuple[PaperEnd, PaperEnd], ...]:
    """``((left, right), ...)`` for each rod of the scene, in float64 textbook formulas."""
    p = scene.params
    if scene.kind == "constant-acceleration":
        v, length, a_front = p["v"], p["length"], p["a_front"]
        a_back = a_front / (1.0 - a_front * length)  # Eq. (15)
        return ((_deriv_end(0.0, a_back, v), _deriv_end(length, a_front, v)),)
    if scene.kind == "impulsive-start":
        v, length = p["v"], p["length"]
        return ((_kick_end(0.0, v), _far_end(length, 1.0, 0.0, v)),)
    v1, v2 = p["v1"], p["v2"]
    w1, w2 = textbook_collision(v1, v2, p["mass1"], p["mass2"], p["eps"])
    rod1 = (_far_end(p["length1"], -1.0, v1, w1), _kick_end(v1, w1))
    rod2 = (_kick_end(v2, w2), _far_end(p["length2"], 1.0, v2, w2))
    return (rod1, rod2)
