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
call (composing frames, a frame from its rapidity, the wall, the accelerations, the
barycentric velocities of a collision). A Python call costs about as much as a few float
operations, so each operation writes its error-free transformations out (one call per
operation, none nested); :func:`one_minus_abs` gives a velocity's gap to light speed.
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
