"""Collision of two rigid rods along x, solved in the barycentric frame (paper Secs. 5-6, Figs. 3-4).

The scalar solution is computed in double-double arithmetic (about 32 digits, see
:mod:`rigidrel_core._dd`), written out inline: a Python call costs as much as the few float
operations it would wrap, and this runs on every slider change.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from types import MappingProxyType

from .._build import EPS, IMPULSE, SIZE, checked_scene, rigid_motion
from .._dd import DD, NOISE, SPLITTER, div
from .._description import (
    VELOCITY,
    EventDescription,
    OriginEvent,
    Parameter,
    SceneDescription,
    ScenePreset,
    Slider,
)
from .._exact import REST, ExactVelocity, compose_velocities
from .._frame import LAB, Frame
from .._paper import FIG3_CASE_ONE, FIG4_CASE_TWO
from .._scene import EventSpec, Rod, Scene
from .._validate import ParameterError, refuse_renamed

#: Masses outside ``(2**-200, 2**200)`` are scaled by a common power of 2 (exactly) before
#: solving, so that no product of the solution overflows or underflows (only their ratio matters).
_MASS_MIN, _MASS_MAX = 2.0**-200, 2.0**200
#: Below this speed ``1 - |v|`` is taken from the double-double ``v`` itself (its error, ~1e-31,
#: is below 2**-70 of the gap, so the gap is correctly rounded); nearer light, where ``1 - v``
#: would cancel, from double-double light-cone components (positive terms), rounded once.
_NEAR_LIGHT = 1.0 - 2.0**-30
#: ``tanh(1)``: composing rapidities ``U`` and ``theta'`` of opposite signs with ``|U| + |theta'| > 1``
#: goes through light-cone components (see :func:`solve_collision`).
_TANH_ONE = math.tanh(1.0)
#: An ExactVelocity is made as ExactVelocity.__init__ would, without its call: a new instance
#: and its slots' setters (three per solve; the call itself costs about as much as the setters).
_NEW = object.__new__
_SET_HI, _SET_LO, _SET_GAP = (ExactVelocity.__dict__[name].__set__ for name in ("hi", "lo", "gap"))


def _exact(hi: float, lo: float, gap: float) -> ExactVelocity:
    """``ExactVelocity(hi, lo, gap)`` without the dataclass' ``__init__`` (a solve makes three)."""
    v = _NEW(ExactVelocity)
    _SET_HI(v, hi)
    _SET_LO(v, lo)
    _SET_GAP(v, gap)
    return v


@dataclass(frozen=True, init=False)
class CollisionSolution:
    """The barycentric solution of a rod-rod collision (paper Sec. 6), velocities to double-double.

    ``u``: barycentric velocity (Eq. (26)); ``after``: lab velocities after (Eq. (31));
    ``mass_gain``: ``k - 1``, with ``k`` the common factor by which both rest masses grow
    (0 for eps = 1); ``heat``: the rest energy created, ``(k - 1)(M1 + M2)``; ``before``: the
    lab velocities before. Each rod's velocity in the barycentric frame, before and after
    (Eqs. (27)-(29), ``gamma' V' = -eps gamma V``), is derived on demand:
    :attr:`bar_before`, :attr:`bar_after`.
    """

    u: ExactVelocity
    after: tuple[ExactVelocity, ExactVelocity]
    mass_gain: float
    heat: float
    before: tuple[float, float]

    def __init__(
        self,
        u: ExactVelocity,
        after: tuple[ExactVelocity, ExactVelocity],
        mass_gain: float,
        heat: float,
        before: tuple[float, float],
    ) -> None:
        # into the instance's dict, not through one object.__setattr__ call each (the generated __init__)
        fields = self.__dict__
        fields["u"] = u
        fields["after"] = after
        fields["mass_gain"] = mass_gain
        fields["heat"] = heat
        fields["before"] = before

    @property
    def mass_factor(self) -> float:
        """``k``: both rest masses are multiplied by it (1 for eps = 1)."""
        return 1.0 + self.mass_gain

    @property
    def bar_before(self) -> tuple[ExactVelocity, ExactVelocity]:
        """Each rod's velocity before, seen from the barycentric frame (``V_i`` composed with ``-u``)."""
        back = self.u.negated()
        return (
            compose_velocities(ExactVelocity.from_float(self.before[0]), back),
            compose_velocities(ExactVelocity.from_float(self.before[1]), back),
        )

    @property
    def bar_after(self) -> tuple[ExactVelocity, ExactVelocity]:
        """Each rod's velocity after, seen from the barycentric frame (``V'_i`` composed with ``-u``)."""
        back = self.u.negated()
        return compose_velocities(self.after[0], back), compose_velocities(self.after[1], back)


def _sum(ah: float, al: float, bh: float, bl: float) -> DD:
    """:func:`rigidrel_core._dd.add` of ``ah + al`` and ``bh + bl``, written out (same operations)."""
    s = ah + bh
    t = s - ah
    e = (ah - (s - t)) + (bh - t)
    f = al + bl
    t = f - al
    g = (al - (f - t)) + (bl - t)
    t = e + f
    h = s + t
    e = t - (h - s)
    t = e + g
    s = h + t
    return s, t - (s - h)


def _squares(xh: float, xl: float, yh: float, yl: float) -> tuple[float, float, float, float]:
    """``X^2`` and ``Y^2`` as :func:`rigidrel_core._dd.mul` makes them, written out (same operations)."""
    S = SPLITTER
    p = xh * xh
    t = S * xh
    h = t - (t - xh)
    lo = xh - h
    f = (((h * h - p) + h * lo + lo * h) + lo * lo) + (xh * xl + xl * xh)
    x2 = p + f
    x2_lo = f - (x2 - p)
    p = yh * yh
    t = S * yh
    h = t - (t - yh)
    lo = yh - h
    f = (((h * h - p) + h * lo + lo * h) + lo * lo) + (yh * yl + yl * yh)
    y2 = p + f
    return x2, x2_lo, y2, f - (y2 - p)


def _light_cone(xh: float, xl: float, yh: float, yl: float) -> tuple[float, float, float, float]:
    """Numerator and denominator of ``V' = (X^2 - Y^2)/(X^2 + Y^2)``, ``X/Y = exp(theta')``, in
    double-double: the composition's form when ``u`` and ``w`` are near light in opposite directions."""
    x2, x2_lo, y2, y2_lo = _squares(xh, xl, yh, yl)
    n, n_lo = _sum(x2, x2_lo, -y2, -y2_lo)
    d, d_lo = _sum(x2, x2_lo, y2, y2_lo)
    return n, n_lo, d, d_lo


def _gap_near_light(v: float, xh: float, xl: float, yh: float, yl: float) -> float:
    """``1 - |V'|`` within 2**-30 of light from ``X/Y = exp(theta')``: ``2 Y^2/(X^2 + Y^2)`` for
    ``V' > 0``, ``2 X^2/(X^2 + Y^2)`` otherwise (positive terms), rounded once (the operations of
    :func:`rigidrel_core._dd.div`, written out)."""
    x2, x2_lo, y2, y2_lo = _squares(xh, xl, yh, yl)
    d, d_lo = _sum(x2, x2_lo, y2, y2_lo)
    a, a_lo = (y2, y2_lo) if v > 0.0 else (x2, x2_lo)
    q = a / d
    p = q * d
    t = SPLITTER * q
    q_h = t - (t - q)
    q_t = q - q_h
    t = SPLITTER * d
    d_h = t - (t - d)
    d_t = d - d_h
    e = ((q_h * d_h - p) + q_h * d_t + q_t * d_h) + q_t * d_t
    return 2.0 * (q + (((a - p) - e) + a_lo - q * d_lo) / d)


def solve_collision(v1: float, v2: float, m1: float, m2: float, eps: float) -> CollisionSolution:
    """Final velocities of two colliding bodies from the barycentric frame (c = 1), in double-double.

    With ``c_i = 1/gamma_i = sqrt(1 - v_i^2)`` every quantity is carried times ``c1 c2`` (which
    cancels in every ratio): ``E = m1 c2 + m2 c1``, ``P = m1 v1 c2 + m2 v2 c1`` and the
    light-cone components ``P+- = E +- P = m1 (1 +- v1) c2 + m2 (1 +- v2) c1``, the smaller one
    summed from its positive terms; invariant mass ``M^2 = P+ P-``; the relative proper velocity
    ``sinh = v1 - v2``. Barycentric velocity ``u = P/E`` (Eq. (26)), ``1 -+ u = P-+/E``.

    Each rod's barycentric proper velocity ``m2 sinh/M`` (rod 1), ``-m1 sinh/M`` (rod 2) becomes
    ``-eps`` times itself (Eq. (29)): with ``k_1 = eps m2 sinh``, ``k_2 = eps m1 sinh`` and
    ``R_i = sqrt(M^2 + k_i^2)`` (``M`` times the barycentric gamma after), rod ``i`` leaves the
    barycentre with ``w_1 = -k_1/R_1``, ``w_2 = k_2/R_2``, and the lab velocity is their
    composition with ``u`` (Eq. (31)):

    * ``V'_i = (u R_i -+ k_i)/(R_i -+ u k_i)``, where ``u`` and ``w_i`` have the same sign or
      their rapidities add up to at most 1 (a cancellation here is one of the terms);
    * else, in light-cone form, ``exp(theta'_1) = P+/(R_1 + k_1)``, ``exp(-theta'_2) = P-/(R_2 + k_2)``,
      ``V' = (X^2 - Y^2)/(X^2 + Y^2)``, which does not cancel when both are near light.

    Gaps to light speed are ``1 - |V'|`` from the double-double ``V'``, or, within 2**-30 of light,
    ``2 Y^2/(X^2 + Y^2)`` (``V' > 0``; else ``2 X^2/(X^2 + Y^2)``) from those positive ``X`` and
    ``Y``; either way rounded once from double-double. 4-momentum is conserved with both rest
    masses scaled by ``k = M / (m1 g'_1 + m2 g'_2)``, ``g'_i = R_i/M``; ``k - 1 = (1 - eps^2)
    sum_i m_i b_i^2/(g_i + g'_i) / (m1 g'_1 + m2 g'_2)`` (``b_i``, ``g_i``: barycentric proper
    velocity and gamma before), without cancellation.

    A velocity whose terms cancel to below double-double's noise (``NOISE``, 2**-100 of the
    terms) is exactly 0: equal masses with V1 = -V2 have the lab as barycentric frame; an
    elastic hit on an equal rod at rest, or ``eps = M1/M2`` on a heavier one, stops rod 1 dead.
    ``eps = 0``: both rods move on with ``u`` itself. Speeds below ~1e-292 c, where a low part is
    subnormal, keep an absolute error of a few 1e-323 instead of a relative one.
    """
    S = SPLITTER
    sqrt = math.sqrt
    mass_sum = m1 + m2
    if not (_MASS_MIN < m1 < _MASS_MAX and _MASS_MIN < m2 < _MASS_MAX):
        shift = math.frexp(max(m1, m2))[1]
        m1, m2 = math.ldexp(m1, -shift), math.ldexp(m2, -shift)
    # ---- c_i = sqrt(1 - v_i^2): 1 - two_prod(v, v), normalised, then sqrt with its residual
    t = S * v1
    v1_h = t - (t - v1)
    v1_t = v1 - v1_h
    p = v1 * v1
    d = 1.0 - p
    d_lo = ((1.0 - d) - p) - (((v1_h * v1_h - p) + 2.0 * v1_h * v1_t) + v1_t * v1_t)
    t = d + d_lo
    d_lo -= t - d
    c1 = sqrt(t)
    d = S * c1
    c1_h = d - (d - c1)
    c1_t = c1 - c1_h
    p = c1 * c1
    c1_lo = (((t - p) - (((c1_h * c1_h - p) + 2.0 * c1_h * c1_t) + c1_t * c1_t)) + d_lo) / (c1 + c1)
    t = S * v2
    v2_h = t - (t - v2)
    v2_t = v2 - v2_h
    p = v2 * v2
    d = 1.0 - p
    d_lo = ((1.0 - d) - p) - (((v2_h * v2_h - p) + 2.0 * v2_h * v2_t) + v2_t * v2_t)
    t = d + d_lo
    d_lo -= t - d
    c2 = sqrt(t)
    d = S * c2
    c2_h = d - (d - c2)
    c2_t = c2 - c2_h
    p = c2 * c2
    c2_lo = (((t - p) - (((c2_h * c2_h - p) + 2.0 * c2_h * c2_t) + c2_t * c2_t)) + d_lo) / (c2 + c2)
    # ---- a_1 = m1 c2, a_2 = m2 c1 (two_prod plus the low parts)
    t = S * m1
    m1_h = t - (t - m1)
    m1_t = m1 - m1_h
    t = S * m2
    m2_h = t - (t - m2)
    m2_t = m2 - m2_h
    a1 = m1 * c2
    a1_lo = ((m1_h * c2_h - a1) + m1_h * c2_t + m1_t * c2_h) + m1_t * c2_t + m1 * c2_lo
    a2 = m2 * c1
    a2_lo = ((m2_h * c1_h - a2) + m2_h * c1_t + m2_t * c1_h) + m2_t * c1_t + m2 * c1_lo
    # ---- energy E = a1 + a2 (two_sum; like the other intermediate sums of positive terms below,
    # not renormalised: its low part stays within a few ulp of the high one)
    en = a1 + a2
    t = en - a1
    en_lo = ((a1 - (en - t)) + (a2 - t)) + (a1_lo + a2_lo)
    # ---- momentum P = v1 a1 + v2 a2; below the noise of its terms: exactly 0
    t = S * a1
    a1_h = t - (t - a1)
    a1_t = a1 - a1_h
    t = S * a2
    a2_h = t - (t - a2)
    a2_t = a2 - a2_h
    p1 = v1 * a1
    p1_lo = ((v1_h * a1_h - p1) + v1_h * a1_t + v1_t * a1_h) + v1_t * a1_t + v1 * a1_lo
    p2 = v2 * a2
    p2_lo = ((v2_h * a2_h - p2) + v2_h * a2_t + v2_t * a2_h) + v2_t * a2_t + v2 * a2_lo
    s = p1 + p2
    t = s - p1
    e = ((p1 - (s - t)) + (p2 - t)) + (p1_lo + p2_lo)
    mo = s + e
    mo_lo = e - (mo - s)
    t = NOISE * en  # above the noise of |p1| + |p2| (< E, as |v_i| < 1): then check against those
    if -t <= mo <= t and -NOISE * (abs(p1) + abs(p2)) <= mo <= NOISE * (abs(p1) + abs(p2)):
        mo = mo_lo = 0.0
    # ---- light-cone components P+- = E +- P: the larger E + |P| directly; the smaller E - |P| so too
    # while |P| <= E/2, else from its positive terms sum_i (1 -+ v_i) a_i
    if mo >= 0.0:
        big = en + mo
        e = (mo - (big - en)) + (en_lo + mo_lo)
        mo_abs, mo_abs_lo = mo, mo_lo
    else:
        big = en - mo
        e = (-mo - (big - en)) + (en_lo - mo_lo)
        mo_abs, mo_abs_lo = -mo, -mo_lo
    big_hi, big_lo = big, e
    if mo_abs + mo_abs <= en:
        small = en - mo_abs
        e = ((en - small) - mo_abs) + (en_lo - mo_abs_lo)
    else:
        y1, y2 = (1.0 - v1, 1.0 - v2) if mo >= 0.0 else (1.0 + v1, 1.0 + v2)
        t = S * y1
        y_h = t - (t - y1)
        y_t = y1 - y_h
        q1 = y1 * a1
        q1_lo = ((y_h * a1_h - q1) + y_h * a1_t + y_t * a1_h) + y_t * a1_t + y1 * a1_lo
        t = S * y2
        y_h = t - (t - y2)
        y_t = y2 - y_h
        q2 = y2 * a2
        q2_lo = ((y_h * a2_h - q2) + y_h * a2_t + y_t * a2_h) + y_t * a2_t + y2 * a2_lo
        if mo >= 0.0:  # the rounding errors of 1 - v_i (zero for v_i >= 1/2)
            q1_lo += ((1.0 - y1) - v1) * a1
            q2_lo += ((1.0 - y2) - v2) * a2
        else:
            q1_lo += ((1.0 - y1) + v1) * a1
            q2_lo += ((1.0 - y2) + v2) * a2
        small = q1 + q2
        t = small - q1
        e = ((q1 - (small - t)) + (q2 - t)) + (q1_lo + q2_lo)
    if mo >= 0.0:
        pp, pp_lo, pm, pm_lo = big_hi, big_lo, small, e
    else:
        pp, pp_lo, pm, pm_lo = small, e, big_hi, big_lo
    # ---- M^2 = P+ P- (two_prod plus the low parts)
    t = S * pp
    pp_h = t - (t - pp)
    pp_t = pp - pp_h
    t = S * pm
    pm_h = t - (t - pm)
    pm_t = pm - pm_h
    mm = pp * pm
    mm_lo = ((pp_h * pm_h - mm) + pp_h * pm_t + pp_t * pm_h) + pp_t * pm_t + (pp * pm_lo + pp_lo * pm)
    # ---- u = P / E: q = fl(P/E) plus the exact residual (P - q E)/E
    uq = mo / en
    t = S * uq
    u_h = t - (t - uq)
    u_t = uq - u_h
    t = S * en
    en_h = t - (t - en)
    en_t = en - en_h
    p = uq * en
    uq_lo = (((mo - p) - (((u_h * en_h - p) + u_h * en_t + u_t * en_h) + u_t * en_t)) + mo_lo - uq * en_lo) / en
    u = uq + uq_lo  # normalised for the barycentric frame; (uq, uq_lo) and its split serve below
    u_lo = uq_lo - (u - uq)
    if not mo:
        bary = REST
    elif 0.0 <= u < _NEAR_LIGHT:  # 1 - |u| from u itself, rounded once
        g = 1.0 - u
        gap = g + (((1.0 - g) - u) - u_lo)
        bary = _exact(u, u_lo, gap)
    elif -_NEAR_LIGHT < u < 0.0:
        g = 1.0 + u
        gap = g + (((1.0 - g) + u) + u_lo)
        bary = _exact(u, u_lo, gap)
    else:  # 1 -+ u = P-+/E
        bary = ExactVelocity(u, u_lo, div((pm, pm_lo) if u > 0.0 else (pp, pp_lo), (en, en_lo))[0])
    s = v1 - v2
    if eps == 0.0:  # perfectly inelastic: both move on with the barycentre; k - 1 = sum m_i (g_i - 1) / M
        mc = sqrt(mm)
        b1, b2 = m2 * s / mc, m1 * s / mc
        gain = (m1 * b1 * b1 / (sqrt(1.0 + b1 * b1) + 1.0) + m2 * b2 * b2 / (sqrt(1.0 + b2 * b2) + 1.0)) / (m1 + m2)
        return CollisionSolution(bary, (bary, bary), gain, gain * mass_sum, (v1, v2))
    # ---- K = eps (v1 - v2); k_1 = m2 K, k_2 = m1 K: the rods' barycentric proper velocities after, times M
    t = s - v1
    s_lo = (v1 - (s - t)) - (v2 + t)
    if eps == 1.0:
        kk, kk_lo = s, s_lo
    else:
        t = S * eps
        ep_h = t - (t - eps)
        ep_t = eps - ep_h
        t = S * s
        s_h = t - (t - s)
        s_t = s - s_h
        kk = eps * s
        kk_lo = ((ep_h * s_h - kk) + ep_h * s_t + ep_t * s_h) + ep_t * s_t + eps * s_lo
    t = S * kk
    kk_h = t - (t - kk)
    kk_t = kk - kk_h
    # The two rods, written out one after the other (a loop would pay for its signs and tuples).

    # ---- rod 1 leaves the barycentre with w_1 = -k_1/R_1: k_1 = m2 K, R_1 = sqrt(M^2 + k_1^2)
    k = m2 * kk
    k_lo = ((m2_h * kk_h - k) + m2_h * kk_t + m2_t * kk_h) + m2_t * kk_t + m2 * kk_lo
    t = S * k
    k_h = t - (t - k)
    k_t = k - k_h
    p = k * k
    e = ((k_h * k_h - p) + 2.0 * k_h * k_t) + k_t * k_t + 2.0 * k * k_lo
    r2 = mm + p
    t = r2 - mm
    r2_lo = ((mm - (r2 - t)) + (p - t)) + (mm_lo + e)
    r = r_1 = sqrt(r2)
    t = S * r
    r_h = t - (t - r)
    r_t = r - r_h
    p = r * r
    r_lo = (((r2 - p) - (((r_h * r_h - p) + 2.0 * r_h * r_t) + r_t * r_t)) + r2_lo) / (r + r)
    if u > 0.0 and u + (w := k / r) > _TANH_ONE * (1.0 + u * w):  # opposite signs, |U| + |theta'| > 1
        y, y_lo = _sum(r, r_lo, k, k_lo)
        n, e, dn, dn_lo = _light_cone(pp, pp_lo, y, y_lo)  # exp(theta'_1) = P+/(R + k)
        zero = -NOISE * dn <= n <= NOISE * dn
    else:  # V'_1 = (u R - k)/(R - u k)
        ur = uq * r
        ur_lo = ((u_h * r_h - ur) + u_h * r_t + u_t * r_h) + u_t * r_t + (uq * r_lo + uq_lo * r)
        uk = uq * k
        uk_lo = ((u_h * k_h - uk) + u_h * k_t + u_t * k_h) + u_t * k_t + (uq * k_lo + uq_lo * k)
        n = ur - k
        t = n - ur
        e = ((ur - (n - t)) - (k + t)) + (ur_lo - k_lo)
        t = n + e
        e -= t - n
        n = t
        dn = r - uk  # |u k| < R
        dn_lo = ((r - dn) - uk) + (r_lo - uk_lo)
        t = NOISE * (r + k)  # above the noise of the terms |u R| + k: then check against those
        zero = -t <= n <= t and -NOISE * (abs(ur) + k) <= n <= NOISE * (abs(ur) + k)
    if zero:  # below the noise of its terms: exactly 0
        after_1 = REST
    else:  # V' = n / dn: q = fl(n / dn) plus the exact residual
        q = n / dn
        t = S * q
        q_h = t - (t - q)
        q_t = q - q_h
        t = S * dn
        d = t - (t - dn)
        t = dn - d
        p = q * dn
        v_lo = (((n - p) - (((q_h * d - p) + q_h * t + q_t * d) + q_t * t)) + e - q * dn_lo) / dn
        v = q + v_lo
        v_lo -= v - q
        if 0.0 <= v < _NEAR_LIGHT:  # 1 - |V'| from V' itself, rounded once
            g = 1.0 - v
            gap = g + (((1.0 - g) - v) - v_lo)
        elif -_NEAR_LIGHT < v < 0.0:
            g = 1.0 + v
            gap = g + (((1.0 - g) + v) + v_lo)
        else:
            y, y_lo = _sum(r, r_lo, k, k_lo)
            gap = _gap_near_light(v, pp, pp_lo, y, y_lo)
        after_1 = _exact(v, v_lo, gap)

    # ---- rod 2 leaves the barycentre with w_2 = k_2/R_2: k_2 = m1 K, R_2 = sqrt(M^2 + k_2^2)
    k = m1 * kk
    k_lo = ((m1_h * kk_h - k) + m1_h * kk_t + m1_t * kk_h) + m1_t * kk_t + m1 * kk_lo
    t = S * k
    k_h = t - (t - k)
    k_t = k - k_h
    p = k * k
    e = ((k_h * k_h - p) + 2.0 * k_h * k_t) + k_t * k_t + 2.0 * k * k_lo
    r2 = mm + p
    t = r2 - mm
    r2_lo = ((mm - (r2 - t)) + (p - t)) + (mm_lo + e)
    r = r_2 = sqrt(r2)
    t = S * r
    r_h = t - (t - r)
    r_t = r - r_h
    p = r * r
    r_lo = (((r2 - p) - (((r_h * r_h - p) + 2.0 * r_h * r_t) + r_t * r_t)) + r2_lo) / (r + r)
    if u < 0.0 and (w := k / r) - u > _TANH_ONE * (1.0 - u * w):  # opposite signs, |U| + |theta'| > 1
        y, y_lo = _sum(r, r_lo, k, k_lo)
        n, e, dn, dn_lo = _light_cone(y, y_lo, pm, pm_lo)  # exp(theta'_2) = (R + k)/P-
        zero = -NOISE * dn <= n <= NOISE * dn
    else:  # V'_2 = (u R + k)/(R + u k)
        ur = uq * r
        ur_lo = ((u_h * r_h - ur) + u_h * r_t + u_t * r_h) + u_t * r_t + (uq * r_lo + uq_lo * r)
        uk = uq * k
        uk_lo = ((u_h * k_h - uk) + u_h * k_t + u_t * k_h) + u_t * k_t + (uq * k_lo + uq_lo * k)
        n = ur + k
        t = n - ur
        e = ((ur - (n - t)) + (k - t)) + (ur_lo + k_lo)
        t = n + e
        e -= t - n
        n = t
        dn = r + uk  # |u k| < R
        dn_lo = (uk - (dn - r)) + (r_lo + uk_lo)
        t = NOISE * (r + k)
        zero = -t <= n <= t and -NOISE * (abs(ur) + k) <= n <= NOISE * (abs(ur) + k)
    if zero:
        after_2 = REST
    else:
        q = n / dn
        t = S * q
        q_h = t - (t - q)
        q_t = q - q_h
        t = S * dn
        d = t - (t - dn)
        t = dn - d
        p = q * dn
        v_lo = (((n - p) - (((q_h * d - p) + q_h * t + q_t * d) + q_t * t)) + e - q * dn_lo) / dn
        v = q + v_lo
        v_lo -= v - q
        if 0.0 <= v < _NEAR_LIGHT:
            g = 1.0 - v
            gap = g + (((1.0 - g) - v) - v_lo)
        elif -_NEAR_LIGHT < v < 0.0:
            g = 1.0 + v
            gap = g + (((1.0 - g) + v) + v_lo)
        else:
            y, y_lo = _sum(r, r_lo, k, k_lo)
            gap = _gap_near_light(v, y, y_lo, pm, pm_lo)
        after_2 = _exact(v, v_lo, gap)

    if eps == 1.0:
        gain = 0.0
    else:  # k - 1 = (1 - eps^2) sum_i m_i b_i^2/(g_i + g'_i) / (m1 g'_1 + m2 g'_2)
        inv_m = 1.0 / sqrt(mm)
        b1, b2 = m2 * s * inv_m, m1 * s * inv_m
        g1, g2 = r_1 * inv_m, r_2 * inv_m
        gain = (
            (1.0 - eps)
            * (1.0 + eps)
            * (m1 * b1 * b1 / (sqrt(1.0 + b1 * b1) + g1) + m2 * b2 * b2 / (sqrt(1.0 + b2 * b2) + g2))
            / (m1 * g1 + m2 * g2)
        )
    sol = _NEW(CollisionSolution)  # as CollisionSolution.__init__ does, without its call
    fields = sol.__dict__
    fields["u"] = bary
    fields["after"] = (after_1, after_2)
    fields["mass_gain"] = gain
    fields["heat"] = gain * mass_sum
    fields["before"] = (v1, v2)
    return sol


#: The far ends' switches (Eqs. (22)-(25)); the same in every collision.
_EVENTS = (
    EventSpec("T_1", 0, 0, "start"),
    EventSpec("T_1'", 0, 0, "stop"),
    EventSpec("T_2", 1, 1, "start"),
    EventSpec("T_2'", 1, 1, "stop"),
)
#: The parameters' names before every scene took one name per quantity (``mass``, ``length``, with
#: the rod's number for two rods): refused, naming the new ones.
RENAMED = MappingProxyType({"m1": "mass1", "m2": "mass2", "l1": "length1", "l2": "length2"})


@refuse_renamed(RENAMED)
def rod_collision(
    v1: float, v2: float, mass1: float, mass2: float, length1: float, length2: float, eps: float
) -> Scene:
    """Collision of two rigid rods along x (Secs. 5-6, Figs. 3-4).

    Rod 1 (rest mass ``mass1`` = M1, rest length ``length1`` = L1, velocity ``v1``) is on the left,
    rod 2 on the right; ``v1 > v2``. Rod 1's right end meets rod 2's left end at ``x = 0, t = 0``
    and both contact ends change velocity at once (to the barycentric solution of
    :func:`solve_collision`). The far ends follow ``x = -sqrt(L1^2 + t^2)`` from
    ``T_1 = -gamma_1 V_1 L_1`` to ``T_1' = -gamma_1' V_1' L_1`` and ``x = sqrt(L2^2 + t^2)``
    from ``T_2 = gamma_2 V_2 L_2`` to ``T_2' = gamma_2' V_2' L_2`` (Eqs. (22)-(25)).
    Events: ``"T_1"``, ``"T_1'"``, ``"T_2"``, ``"T_2'"``.
    """
    v1 = V1.check(v1)
    v2 = V2.check(v2)
    if not v2 < v1:
        raise ParameterError("v2", f"less than v1 = {v1!r} so that the rods collide", v2)
    m1 = MASS1.check(mass1)
    m2 = MASS2.check(mass2)
    l1 = LENGTH1.check(length1)
    l2 = LENGTH2.check(length2)
    eps = EPS.check(eps)
    sol = solve_collision(v1, v2, m1, m2, eps)
    m1_after, m2_after = m1 + m1 * sol.mass_gain, m2 + m2 * sol.mass_gain
    rod1 = rigid_motion(ExactVelocity.from_float(v1), sol.after[0], l1, IMPULSE, -l1)
    rod2 = rigid_motion(ExactVelocity.from_float(v2), sol.after[1], l2, IMPULSE, 0.0)
    frames = MappingProxyType(
        {
            "lab": LAB,
            "rod 1 before": Frame(rod1.velocity_initial, "rod 1 before"),
            "rod 2 before": Frame(rod2.velocity_initial, "rod 2 before"),
            "rod 1 after": Frame(rod1.velocity_final, "rod 1 after"),
            "rod 2 after": Frame(rod2.velocity_final, "rod 2 after"),
            "barycentric": Frame(sol.u, "barycentric"),
        }
    )
    parameters = {"v1": v1, "v2": v2, "mass1": m1, "mass2": m2, "length1": l1, "length2": l2, "eps": eps}
    return checked_scene(
        Scene(
            kind=ROD_COLLISION.kind,
            parameters=MappingProxyType(parameters),
            rods=(Rod("rod 1", rod1, m1, m1_after), Rod("rod 2", rod2, m2, m2_after)),
            event_specs=_EVENTS,
            frames=frames,
            external_source="none",
            heat=sol.heat,
            origin_event=OriginEvent.CONTACT,
        )
    )


V1 = Parameter("v1", "V1", "V1", "c", VELOCITY, 0.6, "velocity V1 of rod 1 (left)", Slider(-0.99, 0.99, 0.01))
V2 = Parameter(
    "v2",
    "V2",
    "V2",
    "c",
    VELOCITY,
    0.0,
    "velocity V2 of rod 2 (right)",
    Slider(-0.99, 0.99, 0.01),
    constraint="less than v1",
)
MASS1 = Parameter("mass1", "M1", "M1", "mass unit", SIZE, 1.0, "rest mass M1 of rod 1", typical=(0.1, 10.0))
MASS2 = Parameter(
    "mass2",
    "M2",
    "M2/M1",
    "mass unit",
    SIZE,
    2.0,
    "rest mass M2 of rod 2 (in the app, in units of M1)",
    Slider(0.01, 100.0, 0.01, "log"),
)
LENGTH1 = Parameter("length1", "L1", "L1", "length unit", SIZE, 1.0, "rest length L1 of rod 1", typical=(0.1, 10.0))
LENGTH2 = Parameter(
    "length2",
    "L2",
    "L2/L1",
    "length unit",
    SIZE,
    1.0,
    "rest length L2 of rod 2 (in the app, in units of L1)",
    Slider(0.1, 5.0, 0.05),
)
ROD_COLLISION = SceneDescription(
    kind="rod-collision",
    title="Rod-rod collision",
    summary="Rod 1 at V1 hits rod 2 at V2 < V1; their touching ends take the barycentric solution at once.",
    source="Secs. 5-6",
    constructor=rod_collision,
    parameters=(V1, MASS2, V2, LENGTH2, EPS, MASS1, LENGTH1),
    frames=("lab", "rod 1 before", "rod 2 before", "rod 1 after", "rod 2 after", "barycentric"),
    default_frame="barycentric",
    events=(
        EventDescription("T_1", "the far (left) end of rod 1 starts changing velocity", "Sec. 5, Eq. (22)"),
        EventDescription("T_1'", "the far end of rod 1 has its final velocity", "Sec. 5, Eq. (24)"),
        EventDescription("T_2", "the far (right) end of rod 2 starts changing velocity", "Sec. 5, Eq. (22)"),
        EventDescription("T_2'", "the far end of rod 2 has its final velocity", "Sec. 5, Eq. (25)"),
    ),
    presets=(
        ScenePreset("Fig. 3: collision, M2 = 2 M1", FIG3_CASE_ONE),
        ScenePreset("Fig. 4: collision, M1 = 2 M2", FIG4_CASE_TWO),
    ),
    renamed=RENAMED,
    order=60,
)

SCENES = (ROD_COLLISION,)
