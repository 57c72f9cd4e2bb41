"""Double-double arithmetic on Python floats: about 32 significant digits from float64 alone.

A double-double is an unevaluated sum ``hi + lo`` of two float64, normalised when
``|lo| <= ulp(hi)/2`` (then ``hi`` is the value rounded to float64). Every operation is
built from error-free transformations of single float64 operations (Python 3.11 has no
``math.fma``):

* :func:`two_sum`: ``s = fl(a + b)`` and ``e = (a + b) - s`` exactly (Knuth, 6 operations);
* :func:`fast_two_sum`: the same for ``|a| >= |b|`` (Dekker, 3 operations);
* Veltkamp's split ``a = ah + al``, each half with at most 26 significant bits (multiplier
  ``2**27 + 1``), so that products of halves are exact;
* :func:`two_prod`: ``p = fl(a b)`` and ``e = a b - p`` exactly (Dekker, from the splits).

One operation on double-doubles is good to a few ``2**-104`` (5e-32) of its result; a chain
of ten is good to ~1e-30. The transformations are exact while nothing overflows or
underflows: splitting needs ``|a| < 2**996``, and below ``2**-969`` the low part is
subnormal, so a value under ~1e-292 carries an absolute (not relative) error of ~1e-323.

These are plain functions on floats and ``(hi, lo)`` tuples, for code that runs once per
call (composing frames, a frame from its rapidity, the wall, the accelerations). A Python call
costs about as much as a few float operations, so each operation writes its error-free
transformations out (one call per operation, none nested); :func:`one_minus_abs` gives a
velocity's gap to light speed.

A collision, solved on every slider change, has two compounds of its own, one call each, written
out the same way with each operand split once: :func:`barycentre` (the barycentric frame and the
bodies' proper velocities in it after, paper Eqs. (26)-(29)) and :func:`leave_barycentre` (each
body back in the lab, Eq. (31)). A solve made of the operations above, one call each, took
~22 calls and 1.3-1.5 times as long.
"""

from __future__ import annotations

import math
from fractions import Fraction

#: A double-double ``(hi, lo)``: the value ``hi + lo``.
DD = tuple[float, float]

#: Veltkamp's multiplier ``2**27 + 1``: ``t = SPLITTER * a; hi = t - (t - a)`` keeps 26 bits of ``a``.
SPLITTER = 134217729.0
#: Where double-double cancellation stops meaning anything: a sum below ``NOISE`` times the
#: sum of its terms' magnitudes is rounding noise of the terms (a few ``2**-104`` each, after
#: about ten operations; symmetric collisions leave at most ``2**-104``) and is taken as exactly zero.
NOISE = 2.0**-100
#: ``ln 2`` as a double-double (to ~1e-33).
LN2 = (0.6931471805599453, 2.3190468138462996e-17)


def two_sum(a: float, b: float) -> DD:
    """``(s, e)`` with ``s = fl(a + b)`` and ``s + e == a + b`` exactly (Knuth)."""
    s = a + b
    bb = s - a
    return s, (a - (s - bb)) + (b - bb)


def fast_two_sum(a: float, b: float) -> DD:
    """``(s, e)`` with ``s = fl(a + b)``, ``s + e == a + b`` exactly, given ``|a| >= |b|`` (Dekker)."""
    s = a + b
    return s, b - (s - a)


def two_prod(a: float, b: float) -> DD:
    """``(p, e)`` with ``p = fl(a b)`` and ``p + e == a b`` exactly (Dekker)."""
    p = a * b
    t = SPLITTER * a
    ah = t - (t - a)
    al = a - ah
    t = SPLITTER * b
    bh = t - (t - b)
    bl = b - bh
    return p, ((ah * bh - p) + ah * bl + al * bh) + al * bl


def add(a: DD, b: DD) -> DD:
    """``a + b``, normalised; also accurate when the two nearly cancel (both parts summed exactly):
    two_sum of the high parts and of the low parts, then two fast_two_sums (written out, here and
    in the operations below: a call costs as much as a few float operations)."""
    ah, al = a
    bh, bl = b
    s = ah + bh
    t = s - ah
    e = (ah - (s - t)) + (bh - t)
    f = al + bl
    t = f - al
    g = (al - (f - t)) + (bl - t)
    e += f
    h = s + e
    e -= h - s
    e += g
    s = h + e
    return s, e - (s - h)


def add_float(a: DD, b: float) -> DD:
    """``a + b`` for a float ``b``, normalised."""
    s = a[0] + b
    t = s - a[0]
    e = ((a[0] - (s - t)) + (b - t)) + a[1]
    h = s + e
    return h, e - (h - s)


def mul(a: DD, b: DD) -> DD:
    """``a b``, normalised: two_prod of the high parts plus the cross terms."""
    ah, al = a
    bh, bl = b
    p = ah * bh
    t = SPLITTER * ah
    a_h = t - (t - ah)
    a_t = ah - a_h
    t = SPLITTER * bh
    b_h = t - (t - bh)
    b_t = bh - b_h
    e = (((a_h * b_h - p) + a_h * b_t + a_t * b_h) + a_t * b_t) + (ah * bl + al * bh)
    s = p + e
    return s, e - (s - p)


def mul_float(a: DD, b: float) -> DD:
    """``a b`` for a float ``b``, normalised."""
    ah = a[0]
    p = ah * b
    t = SPLITTER * ah
    a_h = t - (t - ah)
    a_t = ah - a_h
    t = SPLITTER * b
    b_h = t - (t - b)
    b_t = b - b_h
    e = (((a_h * b_h - p) + a_h * b_t + a_t * b_h) + a_t * b_t) + a[1] * b
    s = p + e
    return s, e - (s - p)


def one_minus_abs(a: DD) -> float:
    """``1 - |a|`` for ``|a| <= 1``, rounded once to float64 (``1 - |a_hi|`` is taken exactly, by
    fast_two_sum): the gap of a velocity to light speed, correctly rounded where ``|a| >= 1/2``."""
    ah, al = a
    if ah < 0.0:
        ah, al = -ah, -al
    g = 1.0 - ah
    return g + (((1.0 - g) - ah) - al)


def div(a: DD, b: DD) -> DD:
    """``a / b``, normalised: ``q = fl(a_hi / b_hi)`` corrected by the exact residual ``(a - q b) / b``."""
    bh = b[0]
    q = a[0] / bh
    p = q * bh
    t = SPLITTER * q
    q_h = t - (t - q)
    q_t = q - q_h
    t = SPLITTER * bh
    b_h = t - (t - bh)
    b_t = bh - b_h
    e = ((q_h * b_h - p) + q_h * b_t + q_t * b_h) + q_t * b_t
    r = (((a[0] - p) - e) + a[1] - q * b[1]) / bh
    s = q + r
    return s, r - (s - q)


def sqrt(a: DD) -> DD:
    """``sqrt(a)`` for ``a >= 0``, normalised: ``r = fl(sqrt(a_hi))`` plus ``(a - r^2) / (2 r)``."""
    ah = a[0]
    if ah <= 0.0:
        return 0.0, 0.0
    r = math.sqrt(ah)
    p = r * r
    t = SPLITTER * r
    h = t - (t - r)
    lo = r - h
    c = (((ah - p) - (((h * h - p) + h * lo + lo * h) + lo * lo)) + a[1]) / (2.0 * r)
    s = r + c
    return s, c - (s - r)


# ---------------------------------------------------------------------- a collision of two bodies
# The two compounds a collision solves with, one call each (paper Sec. 6): the barycentric frame and
# the bodies' proper velocities in it after (Eqs. (26)-(29)), then the bodies back in the lab (Eq. (31)).

#: Below this speed ``1 - |v|`` is taken from a double-double ``v`` itself (its error, ~1e-31, is
#: below 2**-70 of the gap, so the gap is correctly rounded); nearer light, where ``1 - |v|`` would
#: cancel, from light-cone components (positive terms), rounded once.
NEAR_LIGHT = 1.0 - 2.0**-30
#: ``tanh(1)``: :func:`leave_barycentre` composes rapidities of opposite signs whose sizes add up to
#: more than 1 in light-cone form.
_TANH_ONE = math.tanh(1.0)
#: Above this, a velocity composed as ``(u R + k)/(R + u k)`` is no rounding noise of its terms:
#: ``(|u R| + |k|)/|R + u k|`` is at most 1 (same signs) or ``2/(1 - tanh(1/2)^2) < 2.6`` (opposite
#: signs, rapidities adding up to at most 1 in size).
_ZERO_SCALE = 16.0 * NOISE

#: A collision in its barycentric frame (:func:`barycentre`): ``u``, ``1 - |u|``, ``P+``, ``P-``,
#: ``M^2``, ``k_1``, ``k_2``, a double-double as its two parts (flat: a tuple costs as much as a few
#: float operations).
Barycentre = tuple[float, float, float, float, float, float, float, float, float, float, float, float, float]
#: The two bodies leaving the barycentre (:func:`leave_barycentre`): ``V'_1`` (two parts),
#: ``1 - |V'_1|``, ``R_1``, then the same for body 2.
Leaving = tuple[float, float, float, float, float, float, float, float]


def barycentre(m1: float, v1: float, m2: float, v2: float, eps: float) -> Barycentre:
    """Masses ``m1``, ``m2`` at velocities ``v1 > v2`` (``|v_i| < 1``, masses within ``2**+-200``) that
    collide with restitution ``eps``, seen from their centre of momentum: its velocity ``u = P/E``
    (Eq. (26)) and gap ``1 - |u|``; and, every quantity times ``c1 c2`` (``c_i = sqrt(1 - v_i^2)``,
    which cancels in every ratio), its light-cone components ``P+- = E +- P``, the invariant mass
    squared ``M^2 = P+ P-`` and ``k_1 = -eps m2 K``, ``k_2 = eps m1 K`` with ``K = v1 - v2``: ``M`` times
    the bodies' proper velocities in that frame after the collision (before: ``-k_i/eps``, Eqs.
    (27)-(29)).

    ``E = a1 + a2``, ``P = v1 a1 + v2 a2`` with ``a1 = m1 c2``, ``a2 = m2 c1``; a ``P`` below ``NOISE``
    times ``|v1 a1| + |v2 a2|`` is rounding noise, and exactly 0 (then ``u = 0``, gap 1). The larger
    of ``P+-`` is ``E + |P|``; the smaller ``E - |P|`` while ``|P| <= E/2``, else the sum of its positive
    terms ``(1 -+ v1) a1 + (1 -+ v2) a2``. The gap is ``1 - |u|`` from ``u`` below ``NEAR_LIGHT``, else
    ``P-+/E``, rounded once.

    Accuracy: ``u`` normalised, to a few ``2**-104`` of ``|u| + (|v1 a1| + |v2 a2|)/E``; ``P+-``,
    ``M^2`` and ``k_i`` to a few ``2**-104`` of themselves, with low parts within a few ulp of the high
    ones (not renormalised).

    Written out, each operand split once and sums of positive terms left unnormalised: a Python call
    or tuple costs as much as a few float operations, and this runs on every slider change.
    """
    S = SPLITTER
    sqrt = math.sqrt
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
    # ---- k_1 = -m2 eps K, k_2 = m1 eps K, K = v1 - v2 (two_sum, two_prod plus the low parts)
    kk = v1 - v2
    t = kk - v1
    kk_lo = (v1 - (kk - t)) - (v2 + t)
    if eps != 1.0:
        t = S * eps
        ep_h = t - (t - eps)
        ep_t = eps - ep_h
        t = S * kk
        s_h = t - (t - kk)
        s_t = kk - s_h
        p = eps * kk
        kk_lo = ((ep_h * s_h - p) + ep_h * s_t + ep_t * s_h) + ep_t * s_t + eps * kk_lo
        kk = p
    t = S * kk
    kk_h = t - (t - kk)
    kk_t = kk - kk_h
    p = m2 * kk
    k1_lo = -(((m2_h * kk_h - p) + m2_h * kk_t + m2_t * kk_h) + m2_t * kk_t + m2 * kk_lo)
    k1 = -p
    k2 = m1 * kk
    k2_lo = ((m1_h * kk_h - k2) + m1_h * kk_t + m1_t * kk_h) + m1_t * kk_t + m1 * kk_lo
    # ---- E = a1 + a2 (two_sum; like the other sums of positive terms below, not renormalised)
    en = a1 + a2
    t = en - a1
    en_lo = ((a1 - (en - t)) + (a2 - t)) + (a1_lo + a2_lo)
    # ---- P = v1 a1 + v2 a2; below the noise of its terms: exactly 0
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
    # ---- P+- = E +- P: the larger E + |P|; the smaller E - |P| while |P| <= E/2, else from its
    # positive terms (1 -+ v1) a1 + (1 -+ v2) a2
    if mo >= 0.0:
        big = en + mo
        big_lo = (mo - (big - en)) + (en_lo + mo_lo)
        size, size_lo = mo, mo_lo
    else:
        big = en - mo
        big_lo = (-mo - (big - en)) + (en_lo - mo_lo)
        size, size_lo = -mo, -mo_lo
    if size + size <= en:
        small = en - size
        small_lo = ((en - small) - size) + (en_lo - size_lo)
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
        if mo >= 0.0:  # the rounding errors of 1 -+ v_i (zero for |v_i| >= 1/2)
            q1_lo += ((1.0 - y1) - v1) * a1
            q2_lo += ((1.0 - y2) - v2) * a2
        else:
            q1_lo += ((1.0 - y1) + v1) * a1
            q2_lo += ((1.0 - y2) + v2) * a2
        small = q1 + q2
        t = small - q1
        small_lo = ((q1 - (small - t)) + (q2 - t)) + (q1_lo + q2_lo)
    if mo >= 0.0:
        pp, pp_lo, pm, pm_lo = big, big_lo, small, small_lo
    else:
        pp, pp_lo, pm, pm_lo = small, small_lo, big, big_lo
    # ---- M^2 = P+ P- (two_prod plus the low parts)
    t = S * pp
    pp_h = t - (t - pp)
    pp_t = pp - pp_h
    t = S * pm
    pm_h = t - (t - pm)
    pm_t = pm - pm_h
    mm = pp * pm
    mm_lo = ((pp_h * pm_h - mm) + pp_h * pm_t + pp_t * pm_h) + pp_t * pm_t + (pp * pm_lo + pp_lo * pm)
    # ---- u = P/E: q = fl(P/E) plus the exact residual (P - q E)/E
    q = mo / en
    t = S * q
    q_h = t - (t - q)
    q_t = q - q_h
    t = S * en
    en_h = t - (t - en)
    en_t = en - en_h
    p = q * en
    e = (((mo - p) - (((q_h * en_h - p) + q_h * en_t + q_t * en_h) + q_t * en_t)) + mo_lo - q * en_lo) / en
    u = q + e
    u_lo = e - (u - q)
    if 0.0 <= u < NEAR_LIGHT:  # 1 - |u| from u itself, rounded once
        g = 1.0 - u
        gap = g + (((1.0 - g) - u) - u_lo)
    elif -NEAR_LIGHT < u < 0.0:
        g = 1.0 + u
        gap = g + (((1.0 - g) + u) + u_lo)
    else:  # 1 -+ u = P-+/E
        gap = div((pm, pm_lo) if u > 0.0 else (pp, pp_lo), (en, en_lo))[0]
    return u, u_lo, gap, pp, pp_lo, pm, pm_lo, mm, mm_lo, k1, k1_lo, k2, k2_lo


def leave_barycentre(centre: Barycentre) -> Leaving:
    """The two bodies of ``centre`` (:func:`barycentre`) leaving the barycentre, in the frame of their
    velocities before (Eq. (31)): for body ``i``, with ``R_i = sqrt(M^2 + k_i^2)`` (``M`` times its
    gamma in the barycentric frame), the velocity ``V'_i = tanh(atanh(u) + asinh(k_i/M))``, its gap
    ``1 - |V'_i|``, and ``R_i`` rounded.

    ``V' = (u R + k)/(R + u k)``, unless ``u`` and ``k`` have opposite signs (``u > 0`` for body 1,
    ``u < 0`` for body 2: ``k_1 < 0 < k_2``) and rapidities adding up to more than 1 in size (then
    ``R + u k`` cancels): light-cone form (:func:`_light_cone_velocity`).
    A ``V'`` below the noise of its terms, ``NOISE (|u R| + |k|)``, is exactly 0 (gap 1). The gap is
    ``1 - |V'|`` from ``V'`` below ``NEAR_LIGHT``; nearer light, the light-cone form's.

    Accuracy: ``V'`` normalised, to a few ``2**-104`` of ``|V'|`` plus the terms that cancel in it,
    ``(|u R| + |k|)/|R + u k| < 2.6`` (light-cone form: plus ``1 - |V'|``).

    Written out, the two bodies one after the other (a loop would pay for its tuples), each operand
    split once.
    """
    S = SPLITTER
    sqrt = math.sqrt
    uq, uq_lo, _, pp, pp_lo, pm, pm_lo, mm, mm_lo, k1, k1_lo, k2, k2_lo = centre
    t = S * uq
    u_h = t - (t - uq)
    u_t = uq - u_h
    # ---- body 1 (k_1 < 0, as v1 > v2): R = sqrt(M^2 + k^2), with its residual (not renormalised)
    t = S * k1
    k1_h = t - (t - k1)
    k1_t = k1 - k1_h
    p = k1 * k1
    e = ((k1_h * k1_h - p) + 2.0 * k1_h * k1_t) + k1_t * k1_t + 2.0 * k1 * k1_lo
    rr = mm + p
    t = rr - mm
    rr_lo = ((mm - (rr - t)) + (p - t)) + (mm_lo + e)
    r1 = sqrt(rr)
    t = S * r1
    r1_h = t - (t - r1)
    r1_t = r1 - r1_h
    p = r1 * r1
    r1_lo = (((rr - p) - (((r1_h * r1_h - p) + 2.0 * r1_h * r1_t) + r1_t * r1_t)) + rr_lo) / (r1 + r1)
    if uq > 0.0 and uq - (w := k1 / r1) > _TANH_ONE * (1.0 - uq * w):  # opposite signs, |U| + |theta'| > 1
        v1, v1_lo, gap1 = _light_cone_velocity(r1, r1_lo, k1, k1_lo, pp, pp_lo, pm, pm_lo)
    else:  # V' = n/d, n = u R + k (normalised), d = R + u k (|u k| < R)
        ur = uq * r1
        ur_lo = ((u_h * r1_h - ur) + u_h * r1_t + u_t * r1_h) + u_t * r1_t + (uq * r1_lo + uq_lo * r1)
        uk = uq * k1
        uk_lo = ((u_h * k1_h - uk) + u_h * k1_t + u_t * k1_h) + u_t * k1_t + (uq * k1_lo + uq_lo * k1)
        n = ur + k1
        t = n - ur
        e = ((ur - (n - t)) + (k1 - t)) + (ur_lo + k1_lo)
        t = n + e
        e -= t - n
        n = t
        d = r1 + uk
        d_lo = (uk - (d - r1)) + (r1_lo + uk_lo)
        q = n / d  # q = fl(n/d) plus the exact residual
        t = S * q
        q_h = t - (t - q)
        q_t = q - q_h
        t = S * d
        d_h = t - (t - d)
        d_t = d - d_h
        p = q * d
        v1_lo = (((n - p) - (((q_h * d_h - p) + q_h * d_t + q_t * d_h) + q_t * d_t)) + e - q * d_lo) / d
        v1 = q + v1_lo
        v1_lo -= v1 - q
        if 0.0 <= v1 < NEAR_LIGHT:  # 1 - |V'| from V' itself, rounded once; below the noise of its terms: 0
            if v1 < _ZERO_SCALE and v1 * d <= NOISE * (abs(ur) + abs(k1)):
                v1 = v1_lo = 0.0
            g = 1.0 - v1
            gap1 = g + (((1.0 - g) - v1) - v1_lo)
        elif -NEAR_LIGHT < v1 < 0.0:
            if v1 > -_ZERO_SCALE and -v1 * d <= NOISE * (abs(ur) + abs(k1)):
                v1 = v1_lo = 0.0
            g = 1.0 + v1
            gap1 = g + (((1.0 - g) + v1) + v1_lo)
        else:  # within 2**-30 of light
            v1, v1_lo, gap1 = _light_cone_velocity(r1, r1_lo, k1, k1_lo, pp, pp_lo, pm, pm_lo)
    # ---- body 2 (k_2 > 0, as v1 > v2): R = sqrt(M^2 + k^2), with its residual (not renormalised)
    t = S * k2
    k2_h = t - (t - k2)
    k2_t = k2 - k2_h
    p = k2 * k2
    e = ((k2_h * k2_h - p) + 2.0 * k2_h * k2_t) + k2_t * k2_t + 2.0 * k2 * k2_lo
    rr = mm + p
    t = rr - mm
    rr_lo = ((mm - (rr - t)) + (p - t)) + (mm_lo + e)
    r2 = sqrt(rr)
    t = S * r2
    r2_h = t - (t - r2)
    r2_t = r2 - r2_h
    p = r2 * r2
    r2_lo = (((rr - p) - (((r2_h * r2_h - p) + 2.0 * r2_h * r2_t) + r2_t * r2_t)) + rr_lo) / (r2 + r2)
    if uq < 0.0 and (w := k2 / r2) - uq > _TANH_ONE * (1.0 - uq * w):  # opposite signs, |U| + |theta'| > 1
        v2, v2_lo, gap2 = _light_cone_velocity(r2, r2_lo, k2, k2_lo, pp, pp_lo, pm, pm_lo)
    else:  # V' = n/d, n = u R + k (normalised), d = R + u k (|u k| < R)
        ur = uq * r2
        ur_lo = ((u_h * r2_h - ur) + u_h * r2_t + u_t * r2_h) + u_t * r2_t + (uq * r2_lo + uq_lo * r2)
        uk = uq * k2
        uk_lo = ((u_h * k2_h - uk) + u_h * k2_t + u_t * k2_h) + u_t * k2_t + (uq * k2_lo + uq_lo * k2)
        n = ur + k2
        t = n - ur
        e = ((ur - (n - t)) + (k2 - t)) + (ur_lo + k2_lo)
        t = n + e
        e -= t - n
        n = t
        d = r2 + uk
        d_lo = (uk - (d - r2)) + (r2_lo + uk_lo)
        q = n / d  # q = fl(n/d) plus the exact residual
        t = S * q
        q_h = t - (t - q)
        q_t = q - q_h
        t = S * d
        d_h = t - (t - d)
        d_t = d - d_h
        p = q * d
        v2_lo = (((n - p) - (((q_h * d_h - p) + q_h * d_t + q_t * d_h) + q_t * d_t)) + e - q * d_lo) / d
        v2 = q + v2_lo
        v2_lo -= v2 - q
        if 0.0 <= v2 < NEAR_LIGHT:  # 1 - |V'| from V' itself, rounded once; below the noise of its terms: 0
            if v2 < _ZERO_SCALE and v2 * d <= NOISE * (abs(ur) + abs(k2)):
                v2 = v2_lo = 0.0
            g = 1.0 - v2
            gap2 = g + (((1.0 - g) - v2) - v2_lo)
        elif -NEAR_LIGHT < v2 < 0.0:
            if v2 > -_ZERO_SCALE and -v2 * d <= NOISE * (abs(ur) + abs(k2)):
                v2 = v2_lo = 0.0
            g = 1.0 + v2
            gap2 = g + (((1.0 - g) + v2) + v2_lo)
        else:  # within 2**-30 of light
            v2, v2_lo, gap2 = _light_cone_velocity(r2, r2_lo, k2, k2_lo, pp, pp_lo, pm, pm_lo)
    return v1, v1_lo, gap1, r1, v2, v2_lo, gap2, r2


def _light_cone_velocity(
    r: float, r_lo: float, k: float, k_lo: float, pp: float, pp_lo: float, pm: float, pm_lo: float
) -> tuple[float, float, float]:
    """:func:`leave_barycentre`'s ``V' = tanh(U + theta')``, ``U = atanh(u)``, ``theta' = asinh(k/M)``, in
    light-cone form, from positive terms: ``exp(2 U) = P+/P-`` and ``exp(theta') = (R + k)/M``, with
    ``M^2 = P+ P-``, give ``exp(2 (U + theta')) = X^2/Y^2``, ``X = P+``, ``Y = R - k`` (``k < 0``) or
    ``X = R + k``, ``Y = P-`` (``k > 0``); ``V' = (X^2 - Y^2)/(X^2 + Y^2)``, exactly 0 below
    ``NOISE (X^2 + Y^2)``, and within ``2**-30`` of light ``1 - |V'| = 2 Y^2/(X^2 + Y^2)`` (``V' > 0``;
    else ``2 X^2/(X^2 + Y^2)``), rounded once: ``(V'_hi, V'_lo, 1 - |V'|)``, ``V'`` to a few ``2**-104``.

    Written out although it runs only near light (operations of :func:`add` for ``X^2 - Y^2``, of
    :func:`mul` for the squares and of :func:`div` for the quotients; two_sums of positive terms for
    ``R -+ k`` and ``X^2 + Y^2``): the study's collisions near light are benchmarked too.
    """
    S = SPLITTER
    if k < 0.0:  # X = P+, Y = R - k
        xh, xl = pp, pp_lo
        s = r - k
        t = s - r
        e = ((r - (s - t)) - (k + t)) + (r_lo - k_lo)
        yh = s + e
        yl = e - (yh - s)
    else:  # X = R + k, Y = P-
        s = r + k
        t = s - r
        e = ((r - (s - t)) + (k - t)) + (r_lo + k_lo)
        xh = s + e
        xl = e - (xh - s)
        yh, yl = pm, pm_lo
    # ---- X^2, Y^2
    p = xh * xh
    t = S * xh
    h = t - (t - xh)
    lo = xh - h
    e = (((h * h - p) + h * lo + lo * h) + lo * lo) + (xh * xl + xl * xh)
    x2 = p + e
    x2_lo = e - (x2 - p)
    p = yh * yh
    t = S * yh
    h = t - (t - yh)
    lo = yh - h
    e = (((h * h - p) + h * lo + lo * h) + lo * lo) + (yh * yl + yl * yh)
    y2 = p + e
    y2_lo = e - (y2 - p)
    # ---- d = X^2 + Y^2 (positive terms)
    s = x2 + y2
    t = s - x2
    e = ((x2 - (s - t)) + (y2 - t)) + (x2_lo + y2_lo)
    d = s + e
    d_lo = e - (d - s)
    # ---- n = X^2 - Y^2 (both parts summed exactly: they may cancel); below the noise of d: 0
    s = x2 - y2
    t = s - x2
    e = (x2 - (s - t)) - (y2 + t)
    f = x2_lo - y2_lo
    t = f - x2_lo
    g = (x2_lo - (f - t)) - (y2_lo + t)
    e += f
    h = s + e
    e -= h - s
    e += g
    n = h + e
    e -= n - h
    if -NOISE * d <= n <= NOISE * d:
        return 0.0, 0.0, 1.0
    # ---- V' = n/d: q = fl(n/d) plus the exact residual
    q = n / d
    t = S * q
    q_h = t - (t - q)
    q_t = q - q_h
    t = S * d
    d_h = t - (t - d)
    d_t = d - d_h
    p = q * d
    v_lo = (((n - p) - (((q_h * d_h - p) + q_h * d_t + q_t * d_h) + q_t * d_t)) + e - q * d_lo) / d
    v = q + v_lo
    v_lo -= v - q
    if 0.0 <= v < NEAR_LIGHT:  # 1 - |V'| from V' itself, rounded once
        g = 1.0 - v
        return v, v_lo, g + (((1.0 - g) - v) - v_lo)
    if -NEAR_LIGHT < v < 0.0:
        g = 1.0 + v
        return v, v_lo, g + (((1.0 - g) + v) + v_lo)
    a, a_lo = (y2, y2_lo) if v > 0.0 else (x2, x2_lo)  # 1 - |V'| = 2 a/d, the quotient as for V'
    q = a / d
    t = S * q
    q_h = t - (t - q)
    q_t = q - q_h
    p = q * d
    a_lo = (((a - p) - (((q_h * d_h - p) + q_h * d_t + q_t * d_h) + q_t * d_t)) + a_lo - q * d_lo) / d
    return v, v_lo, 2.0 * (q + a_lo)


def _exact_dd(x: Fraction) -> DD:
    hi = float(x)
    return hi, float(x - Fraction(hi))


#: ``1/(n+1)!`` for n = 0..10 as double-doubles: ``expm1(y) = y sum_n y^n/(n+1)!``; the first
#: term left out, ``y^11/12!``, is below ``2**-110 y`` for ``|y| <= 1/256``.
_EXPM1_TERMS = tuple(_exact_dd(Fraction(1, math.factorial(n + 1))) for n in range(11))


def expm1_small(x: DD) -> DD:
    """``exp(x) - 1`` for ``|x| <= 1``, to a few ``2**-104`` of itself (also for tiny ``x``).

    Taylor series of ``y = x / 2**k`` (``k = 8`` halvings, ``|y| <= 1/256``; none for
    ``|x| <= 2**-20``) by Horner's rule, then ``k`` doublings ``e(2y) = e(y) (e(y) + 2)``,
    which keep the relative error. Written out (two_prod and two_sum inline): it runs
    for every frame made from a rapidity.
    """
    k = 8 if abs(x[0]) > 2.0**-20 else 0
    yh, yl = math.ldexp(x[0], -k), math.ldexp(x[1], -k)
    t = SPLITTER * yh
    y_h = t - (t - yh)
    y_t = yh - y_h
    sh, sl = _EXPM1_TERMS[10]
    for ch, cl in _EXPM1_TERMS[9::-1]:  # s = s y + 1/(n+1)!
        p = sh * yh
        t = SPLITTER * sh
        s_h = t - (t - sh)
        s_t = sh - s_h
        e = ((s_h * y_h - p) + s_h * y_t + s_t * y_h) + s_t * y_t + (sh * yl + sl * yh)
        sh = p + ch
        t = sh - p
        sl = ((p - (sh - t)) + (ch - t)) + (e + cl)
    p = sh * yh  # e = s y
    t = SPLITTER * sh
    s_h = t - (t - sh)
    s_t = sh - s_h
    e = ((s_h * y_h - p) + s_h * y_t + s_t * y_h) + s_t * y_t + (sh * yl + sl * yh)
    eh = p + e
    el = e - (eh - p)
    for _ in range(k):  # e = e (e + 2)
        fh = eh + 2.0  # |e| < 2 for |y| <= 1: fast_two_sum(2, e)
        fl = (eh - (fh - 2.0)) + el
        p = eh * fh
        t = SPLITTER * eh
        a_h = t - (t - eh)
        a_t = eh - a_h
        t = SPLITTER * fh
        b_h = t - (t - fh)
        b_t = fh - b_h
        e = ((a_h * b_h - p) + a_h * b_t + a_t * b_h) + a_t * b_t + (eh * fl + el * fh)
        eh = p + e
        el = e - (eh - p)
    return eh, el


def exp_negative(x: float) -> DD:
    """``exp(-x)`` for ``0 <= x <= 1500``: ``x = n ln 2 + r`` with ``|r| <= ln(2)/2``, so
    ``exp(-x) = 2**-n (1 + expm1(-r))``; below ``2**-969`` the low part underflows."""
    n = round(x / LN2[0])
    p, e = two_prod(float(n), LN2[0])
    r = add((x, 0.0), (-p, -e - n * LN2[1]))
    z = add_float(expm1_small((-r[0], -r[1])), 1.0)
    return math.ldexp(z[0], -n), math.ldexp(z[1], -n)
