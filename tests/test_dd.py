"""Double-double operations (rigidrel_core._dd) against exact rational arithmetic.

Each operation's result is compared with the exact value (``fractions.Fraction``) of the same
operation on its double-double inputs, within the bound its docstring promises: a few ``2**-104``
of the result (or of the terms, where those may cancel). Every result is normalised: its high part
is the value rounded to float64. Values stay between 1e-60 and 1e60 in size, where nothing
overflows, underflows or is subnormal.
"""

from __future__ import annotations

import math
from fractions import Fraction

import mpmath
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

from rigidrel_core import _dd
from rigidrel_core._dd import DD

SETTINGS = settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])
#: One operation's promise, relative: a few 2**-104 (the bounds of Joldes, Muller and Popescu 2017
#: are 3 to 10 times 2**-106 for these algorithms).
U2 = 2.0**-101

magnitudes = st.floats(1e-60, 1e60)
signs = st.sampled_from([1.0, -1.0])
fractions_of_ulp = st.floats(-0.5, 0.5)


@st.composite
def doubles(draw: st.DrawFn, positive: bool = False) -> DD:
    """A normalised double-double: a float and up to half an ulp of it below its last bit."""
    hi = draw(magnitudes) * (1.0 if positive else draw(signs))
    lo = draw(fractions_of_ulp) * math.ulp(hi)
    s = hi + lo
    return s, lo - (s - hi)


def exact(a: DD) -> Fraction:
    return Fraction(a[0]) + Fraction(a[1])


def assert_normalised(a: DD) -> None:
    assert a[0] + a[1] == a[0], a


def assert_near(got: DD, want: Fraction, scale: Fraction | float) -> None:
    assert_normalised(got)
    assert abs(exact(got) - want) <= Fraction(U2) * abs(Fraction(scale)), (got, float(want))


@SETTINGS
@given(a=doubles(), b=doubles())
def test_add_and_mul(a: DD, b: DD) -> None:
    s = exact(a) + exact(b)
    assume(s != 0 and abs(s) > Fraction(1e-90))
    assert_near(_dd.add(a, b), s, s)
    assert_near(_dd.mul(a, b), exact(a) * exact(b), exact(a) * exact(b))
    assert_near(_dd.div(a, b), exact(a) / exact(b), exact(a) / exact(b))
    assert_near(_dd.add_float(a, b[0]), exact(a) + Fraction(b[0]), abs(exact(a)) + abs(Fraction(b[0])))
    assert_near(_dd.mul_float(a, b[0]), exact(a) * Fraction(b[0]), exact(a) * Fraction(b[0]))


@SETTINGS
@given(a=doubles(positive=True))
def test_sqrt(a: DD) -> None:
    root = _dd.sqrt(a)
    assert_normalised(root)
    assert abs(exact(root) ** 2 - exact(a)) <= 2 * Fraction(U2) * exact(a)


@SETTINGS
@given(v=st.floats(-1.0, 1.0), lo=fractions_of_ulp)
def test_one_minus_abs_is_rounded_once(v: float, lo: float) -> None:
    """``1 - |v|`` within an ulp of itself, for any ``|v| <= 1``, correctly rounded when ``|v| >= 1/2``
    (then ``1 - |v_hi|`` is exact, and the low part is taken from it in one rounding)."""
    a = (v, lo * math.ulp(v) if abs(v) < 1.0 else 0.0)
    assume(abs(exact(a)) <= 1)
    got = _dd.one_minus_abs(a)
    want = 1 - abs(exact(a))
    assert abs(Fraction(got) - want) <= Fraction(math.ulp(got)) / (2 if abs(v) >= 0.5 else 1)


# ---------------------------------------------------------------- a collision's two compounds
#: Velocities: anywhere below light, within 1e-15 of it, tiny (down to 1e-200: low parts stay normal), and 0.
collision_velocities = st.one_of(
    st.floats(-0.999, 0.999),
    st.builds(lambda x, s: s * (1.0 - 10.0**x), st.floats(-15.0, -1.0), signs),
    st.builds(lambda x, s: s * 10.0**x, st.floats(-200.0, -1.0), signs),
    st.just(0.0),
).filter(lambda v: v == 0.0 or abs(v) >= 1e-200)
restitutions = st.one_of(st.just(1.0), st.floats(0.001, 1.0))


def mp_dd(hi: float, lo: float) -> mpmath.mpf:
    return mpmath.mpf(hi) + mpmath.mpf(lo)


@st.composite
def collisions(draw: st.DrawFn) -> tuple[float, float, float, float, float]:
    """``(m1, v1, m2, v2, eps)`` with ``v1 > v2``, ``m1`` in 1e-3..1e3 and ``m2/m1`` in 1e-6..1e6."""
    a, b = draw(collision_velocities), draw(collision_velocities)
    assume(a != b)
    m1 = 10.0 ** draw(st.floats(-3.0, 3.0))
    return m1, max(a, b), m1 * 10.0 ** draw(st.floats(-6.0, 6.0)), min(a, b), draw(restitutions)


@SETTINGS
@given(params=collisions())
def test_barycentre_agrees_with_mpmath(params: tuple[float, float, float, float, float]) -> None:
    """``u = P/E`` to a few 2**-104 of ``|u|`` plus its momenta ``(|v1 a1| + |v2 a2|)/E`` (``a1 = m1 c2``,
    ``a2 = m2 c1``), its gap correctly rounded; ``P+-``, ``M^2 = P+ P-`` and ``k_1 = -eps m2 (v1 - v2)``,
    ``k_2 = eps m1 (v1 - v2)`` to a few 2**-104 of themselves (60-digit mpmath of the same formulas).
    Gaps to light speed here and below: within an ulp, correctly rounded for speeds from 1/2 on."""
    m1, v1, m2, v2, eps = params
    u, u_lo, gap, pp, pp_lo, pm, pm_lo, mm, mm_lo, k1, k1_lo, k2, k2_lo = _dd.barycentre(m1, v1, m2, v2, eps)
    assert_normalised((u, u_lo))
    with mpmath.workdps(60):
        d1, d2, dm1, dm2, de = map(mpmath.mpf, (v1, v2, m1, m2, eps))
        a1, a2 = dm1 * mpmath.sqrt(1 - d2 * d2), dm2 * mpmath.sqrt(1 - d1 * d1)
        energy, momentum = a1 + a2, d1 * a1 + d2 * a2
        terms = abs(d1 * a1) + abs(d2 * a2)
        want = momentum / energy
        if u or abs(momentum) > _dd.NOISE * terms:  # else below the noise of its terms: 0
            assert abs(mp_dd(u, u_lo) - want) <= 2 * U2 * (abs(want) + terms / energy)
        assert abs(mpmath.mpf(gap) - (1 - abs(want))) <= math.ulp(gap) / (2 if abs(u) >= 0.5 else 1)
        plus, minus = energy + momentum, energy - momentum
        assert abs(mp_dd(pp, pp_lo) - plus) <= 2 * U2 * plus
        assert abs(mp_dd(pm, pm_lo) - minus) <= 2 * U2 * minus
        assert abs(mp_dd(mm, mm_lo) - plus * minus) <= 2 * U2 * plus * minus
        for got, k in (((k1, k1_lo), -de * dm2 * (d1 - d2)), ((k2, k2_lo), de * dm1 * (d1 - d2))):
            assert abs(mp_dd(*got) - k) <= 2 * U2 * abs(k)


@SETTINGS
@given(params=collisions())
def test_leave_barycentre_composes_velocities(params: tuple[float, float, float, float, float]) -> None:
    """Each body's ``V' = tanh(U + asinh(k/M))`` (60-digit mpmath, from the double-double ``u``, ``M^2`` and
    ``k`` it is given; the frame's rapidity ``U`` from ``P+-`` where ``|u| >= 1/2``, as its light-cone
    form has it) to a few 2**-104 of ``|V'|`` plus its terms ``(|u R| + |k|)/|R + u k|`` (at most 1),
    normalised; its gap rounded once; ``R = sqrt(M^2 + k^2)`` to a few ulp."""
    centre = _dd.barycentre(*params)
    u, u_lo, _, pp, pp_lo, pm, pm_lo, mm, mm_lo, k1, k1_lo, k2, k2_lo = centre
    leaving = _dd.leave_barycentre(centre)
    with mpmath.workdps(60):
        mass2 = mp_dd(mm, mm_lo)
        rapidity = mpmath.atanh(mp_dd(u, u_lo)) if abs(u) < 0.5 else mpmath.log(mp_dd(pp, pp_lo) / mp_dd(pm, pm_lo)) / 2
        frame = mpmath.tanh(rapidity)
        for (v, v_lo, gap, r), k in ((leaving[:4], mp_dd(k1, k1_lo)), (leaving[4:], mp_dd(k2, k2_lo))):
            assert_normalised((v, v_lo))
            r_want = mpmath.sqrt(mass2 + k * k)
            want = mpmath.tanh(rapidity + mpmath.asinh(k / mpmath.sqrt(mass2)))
            terms = min(1, (abs(frame * r_want) + abs(k)) / abs(r_want + frame * k))
            # (a velocity below the noise of its terms is 0: within NOISE of them)
            bound = (_dd.NOISE if v == 0.0 else 2 * U2) * (abs(want) + terms)
            assert abs(mp_dd(v, v_lo) - want) <= bound, (v, v_lo, str(want))
            rounding = math.ulp(gap) / (2 if abs(v) >= 0.5 else 1)
            assert abs(mpmath.mpf(gap) - (1 - abs(want))) <= rounding + (bound if v == 0.0 else 0)
            assert abs(mpmath.mpf(r) - r_want) <= 4 * math.ulp(r)
