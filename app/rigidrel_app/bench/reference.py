"""The 50-digit reference: the paper's lab formulas in mpmath, sliced at frame times by root finding.

Independent of :mod:`rigidrel_core` by construction (units c = 1):

* scene solutions follow the paper's own route at 50 digits: rapidities via ``atanh``,
  the barycentric velocity ``u = (m1 g1 V1 + m2 g2 V2)/(m1 g1 + m2 g2)``, velocity
  addition ``(V - u)/(1 - u V)`` into and out of the barycentric frame, Eq. (epsilon) for
  the restitution (the core uses proper-velocity algebra in ``decimal``);
* worldlines are the paper's lab formulas, point by point: Eq. (deriv)
  ``x = xi + (sqrt(1 + a'^2 t^2) - 1)/a'`` for constant acceleration with each point's own
  ``a' = 1/(xi + 1/a'_B)`` (Eq. (gl)), Eq. (imp) ``x = sqrt(L0^2 + t^2)`` for impulses,
  ``t -> -t`` for deceleration, Eqs. (t12)-(imp12) for collisions;
* a slice at frame time ``t'`` solves ``gamma (t - beta x(t)) = t'`` for the lab time ``t``
  (strictly increasing in ``t``) by bracketing root finding, then boosts:
  ``x' = gamma (x(t) - beta t)``. The core never inverts anything: it evaluates closed
  forms in the frame.

Used at run time by ``rigidrel bench`` (the mpmath method and the reference for every
other method) and by ``tests/reference/make_reference.py`` (the committed table of the
accuracy tests). mpmath ships without precise type hints: its numbers are typed ``Any``.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Any, Literal

import mpmath as mp

#: Working precision of the reference (decimal digits).
REFERENCE_DIGITS = 50
mp.mp.dps = REFERENCE_DIGITS

#: An mpmath number (mpmath ships no precise type hints).
Mp = Any
Worldline = Callable[[Mp], Mp]
#: How a frame slice finds its lab time: plain bisection (the committed table), or the
#: Anderson-Bjorck bracketing secant (same bracket and tolerance, about 10x fewer steps).
SliceSolver = Literal["bisection", "anderson-bjorck"]


def F(x: float) -> Mp:
    """A float taken as exact."""
    return mp.mpf(float(x))


def gamma_of(v: Mp) -> Mp:
    """``gamma = 1/sqrt(1 - v^2)`` (harmless at 50 digits)."""
    return 1 / mp.sqrt(1 - v * v)


@dataclass
class RefScene:
    """Reference description: per rod, a lab worldline for each material fraction."""

    worldlines: list[list[Worldline]]  # [rod][fraction] -> x(t)
    events: dict[str, tuple[Mp, Mp]]
    final_velocities: list[Mp]
    lengths_rest: list[Mp]
    extra: dict[str, Mp]


# ------------------------------------------------------------------ worldlines
def accelerating_point(xi: Mp, alpha: Mp, V: Mp) -> Worldline:
    """Eq. (deriv): a point at rest at xi for t <= 0, proper acceleration alpha until speed V."""
    T = gamma_of(V) * V / alpha
    X = xi + (gamma_of(V) - 1) / alpha

    def x(t: Mp) -> Mp:
        if t <= 0:
            return xi
        if t <= T:
            return xi + (mp.sqrt(1 + alpha * alpha * t * t) - 1) / alpha
        return X + V * (t - T)

    return x


def hyperbola_point(centre: Mp, d: Mp, side: int, v_before: Mp, v_after: Mp) -> Worldline:
    """A point at rest-distance d from a centre event (0, centre) on side +1/-1.

    Eq. (imp12): x = centre + side sqrt(d^2 + t^2) between the times where its velocity
    is v_before and v_after; the tangent lines outside.
    """

    def t_at(v: Mp) -> Mp:  # dx/dt = side t / sqrt(d^2 + t^2) = v
        return side * d * gamma_of(v) * v

    t0, t1 = t_at(v_before), t_at(v_after)
    x0 = centre + side * d * gamma_of(v_before)
    x1 = centre + side * d * gamma_of(v_after)

    def x(t: Mp) -> Mp:
        if t < t0:
            return x0 + v_before * (t - t0)
        if t > t1:
            return x1 + v_after * (t - t1)
        return centre + side * mp.sqrt(d * d + t * t)

    return x


def _material_point(f: float, length: Mp) -> Mp:
    """Rest-frame distance of fraction ``f`` from the left end (the right end exactly ``L``)."""
    return F(f) * length if f != 1.0 else length


# ------------------------------------------------------------------ scenes
def ref_constant_acceleration(fractions: Sequence[float], v: float, length: float, a_front: float) -> RefScene:
    V, L, aF = F(v), F(length), F(a_front)
    aB = aF / (1 - aF * L)  # Eq. (gl)
    wl = []
    for f in fractions:
        xi = _material_point(f, L)
        alpha = 1 / (xi + 1 / aB)
        wl.append(accelerating_point(xi, alpha, V))
    g = gamma_of(V)
    events = {
        "T_B": (g * V / aB, (g - 1) / aB),
        "T_F": (g * V / aF, L + (g - 1) / aF),
    }
    return RefScene([wl], events, [V], [L], {"a_B": aB})


def ref_deceleration(fractions: Sequence[float], v: float, length: float, a_front: float) -> RefScene:
    acc = ref_constant_acceleration(fractions, v, length, a_front)
    wl = [[(lambda t, w=w: w(-t)) for w in acc.worldlines[0]]]
    events = {
        "-T_F": (-acc.events["T_F"][0], acc.events["T_F"][1]),
        "-T_B": (-acc.events["T_B"][0], acc.events["T_B"][1]),
    }
    return RefScene(wl, events, [mp.mpf(0)], acc.lengths_rest, {})


def ref_impulsive_start(fractions: Sequence[float], v: float, length: float) -> RefScene:
    V, L = F(v), F(length)
    wl = [hyperbola_point(mp.mpf(0), _material_point(f, L), +1, mp.mpf(0), V) for f in fractions]
    g = gamma_of(V)
    return RefScene([wl], {"T_F": (V * g * L, g * L)}, [V], [L], {})  # Eq. (tf)


def ref_velocity_change(
    fractions: Sequence[float], v_initial: float, v_final: float, length: float, a_front: float | None
) -> RefScene:
    Vi, Vf, L = F(v_initial), F(v_final), F(length)
    near = mp.mpf(0) if a_front is None else (1 - F(a_front) * L) / F(a_front)
    side = 1 if Vf > Vi else -1
    centre = -near if side == 1 else L + near
    wl = []
    for f in fractions:
        d = abs(_material_point(f, L) - centre)
        wl.append(hyperbola_point(centre, d, side, Vi, Vf))
    near_xi, far_xi = (mp.mpf(0), L) if side == 1 else (L, mp.mpf(0))
    events = {}
    for name, xi in (("B", near_xi), ("F", far_xi)):
        d = abs(xi - centre)
        for suffix, vel in (("0", Vi), ("", Vf)):
            g = gamma_of(vel)
            events[f"T_{name}{suffix}"] = (side * d * g * vel, centre + side * d * g)
    return RefScene([wl], events, [Vf], [L], {})


def ref_wall_collision(fractions: Sequence[float], v: float, length: float, eps: float) -> RefScene:
    V, L, e = F(v), F(length), F(eps)
    # wall frame = barycentric frame of an infinitely heavy wall: gamma' V' = eps gamma V
    p = e * gamma_of(V) * V
    Vp = p / mp.sqrt(1 + p * p)
    wl = [hyperbola_point(mp.mpf(0), _material_point(f, L), +1, -V, Vp) for f in fractions]
    g, gp = gamma_of(V), gamma_of(Vp)
    events = {"T_1": (-g * V * L, g * L), "T_1'": (gp * Vp * L, gp * L)}
    return RefScene([wl], events, [Vp], [L], {"heat": g - gp})


def ref_collision_velocities(v1: float, v2: float, m1: float, m2: float, eps: float) -> dict[str, Mp]:
    """Sec. 6 route: u, barycentric velocities, Eq. (epsilon), velocity addition back (Eq. (vp))."""
    V1, V2, M1, M2, e = F(v1), F(v2), F(m1), F(m2), F(eps)
    g1, g2 = gamma_of(V1), gamma_of(V2)
    u = (M1 * g1 * V1 + M2 * g2 * V2) / (M1 * g1 + M2 * g2)
    Vb1 = (V1 - u) / (1 - u * V1)
    Vb2 = (V2 - u) / (1 - u * V2)
    out = {"u": u, "Vb1": Vb1, "Vb2": Vb2}
    for i, Vb in ((1, Vb1), (2, Vb2)):
        p = -e * gamma_of(Vb) * Vb  # Eq. (epsilon)
        Vbp = p / mp.sqrt(1 + p * p)
        out[f"Vbp{i}"] = Vbp
        out[f"Vp{i}"] = (u + Vbp) / (1 + u * Vbp)  # Eq. (vp)
    # rest-mass gain: energy conservation in the barycentric frame, common factor k
    E_bar = M1 * gamma_of(Vb1) + M2 * gamma_of(Vb2)
    k = E_bar / (M1 * gamma_of(out["Vbp1"]) + M2 * gamma_of(out["Vbp2"]))
    out["k"] = k
    out["heat"] = (k - 1) * (M1 + M2)
    return out


def ref_rod_collision(
    fractions: Sequence[float], v1: float, v2: float, m1: float, m2: float, l1: float, l2: float, eps: float
) -> RefScene:
    sol = ref_collision_velocities(v1, v2, m1, m2, eps)
    V1, V2, L1, L2 = F(v1), F(v2), F(l1), F(l2)
    Vp1, Vp2 = sol["Vp1"], sol["Vp2"]
    rod1, rod2 = [], []
    for f in fractions:
        xi1 = _material_point(f, L1)
        xi2 = _material_point(f, L2)
        rod1.append(hyperbola_point(mp.mpf(0), L1 - xi1, -1, V1, Vp1))
        rod2.append(hyperbola_point(mp.mpf(0), xi2, +1, V2, Vp2))
    g1, g2, gp1, gp2 = gamma_of(V1), gamma_of(V2), gamma_of(Vp1), gamma_of(Vp2)
    events = {  # Eqs. (t12), (t'1), (t'12) with x from Eq. (imp12)
        "T_1": (-g1 * V1 * L1, -g1 * L1),
        "T_1'": (-gp1 * Vp1 * L1, -gp1 * L1),
        "T_2": (g2 * V2 * L2, g2 * L2),
        "T_2'": (gp2 * Vp2 * L2, gp2 * L2),
    }
    return RefScene([rod1, rod2], events, [Vp1, Vp2], [L1, L2], sol)


#: Reference builders by scene kind (the core's ``SceneKind`` values); the first
#: argument is the material fractions to follow, the rest the scene's parameters.
BUILDERS: dict[str, Callable[..., RefScene]] = {
    "constant-acceleration": ref_constant_acceleration,
    "deceleration": ref_deceleration,
    "impulsive-start": ref_impulsive_start,
    "velocity-change": ref_velocity_change,
    "wall-collision": ref_wall_collision,
    "rod-collision": ref_rod_collision,
}


# ------------------------------------------------------------------ frame slices
def frame_slice(x: Worldline, beta: Mp, t_frame: Mp, solver: SliceSolver = "bisection") -> Mp:
    """x' at frame time t': solve gamma (t - beta x(t)) = t' for lab t, then x' = gamma (x(t) - beta t).

    The left side is strictly increasing in ``t`` (|dx/dt| < 1). The root is bracketed by
    quadrupling ``[-1, 1]`` and narrowed until the bracket is below ``10^-(dps - 2)`` of
    its scale, by bisection or by the Anderson-Bjorck secant (which falls back to a
    bisection step whenever an iteration fails to halve the bracket).
    """
    g = gamma_of(beta)

    def f(t: Mp) -> Mp:
        return g * (t - beta * x(t)) - t_frame

    lo, hi = mp.mpf(-1), mp.mpf(1)
    while f(lo) > 0:
        lo *= 4
    while f(hi) < 0:
        hi *= 4
    scale = max(abs(lo), abs(hi), mp.mpf(1))
    tol = scale * mp.mpf(10) ** (-(mp.mp.dps - 2))
    if solver == "bisection":
        while hi - lo > tol:
            mid = (lo + hi) / 2
            if f(mid) < 0:
                lo = mid
            else:
                hi = mid
        t = (lo + hi) / 2
    else:
        t = _anderson_bjorck(f, lo, hi, tol)
    return g * (x(t) - beta * t)


def _anderson_bjorck(f: Callable[[Mp], Mp], lo: Mp, hi: Mp, tol: Mp) -> Mp:
    """Root of increasing ``f`` in ``[lo, hi]`` (f(lo) <= 0 <= f(hi)) to a bracket below ``tol``."""
    f_lo, f_hi = f(lo), f(hi)
    if f_lo == 0:
        return lo
    if f_hi == 0:
        return hi
    kept = 0  # +1: hi was kept last time, -1: lo was kept
    while hi - lo > tol:
        width = hi - lo
        t = hi - f_hi * (hi - lo) / (f_hi - f_lo)
        if not lo < t < hi:
            t = (lo + hi) / 2
        f_t = f(t)
        if f_t == 0:
            return t
        if f_t < 0:
            if kept == 1:  # hi kept twice: shrink its weight (Anderson-Bjorck)
                m = 1 - f_t / f_lo
                f_hi = f_hi * (m if m > 0 else mp.mpf(0.5))
            lo, f_lo, kept = t, f_t, 1
        else:
            if kept == -1:
                m = 1 - f_t / f_hi
                f_lo = f_lo * (m if m > 0 else mp.mpf(0.5))
            hi, f_hi, kept = t, f_t, -1
        if hi - lo > width / 2:  # no halving: guarantee progress with a bisection step
            mid = (lo + hi) / 2
            f_mid = f(mid)
            if f_mid == 0:
                return mid
            if f_mid < 0:
                lo, f_lo = mid, f_mid
            else:
                hi, f_hi = mid, f_mid
            kept = 0
    return (lo + hi) / 2


def boost_event(e: tuple[Mp, Mp], beta: Mp) -> tuple[Mp, Mp]:
    """``(t', x') = gamma (t - beta x, x - beta t)``."""
    g = gamma_of(beta)
    t, x = e
    return g * (t - beta * x), g * (x - beta * t)
