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
