"""Velocities carried to double-double precision, and rapidity differences without cancellation.

Units: c = 1. A velocity ``v`` in (-1, 1) has rapidity ``theta = atanh(v)``, Lorentz
factor ``gamma = cosh(theta)`` and proper velocity ``gamma v = sinh(theta)``.

Why double-double: every quantity a frame needs is a *difference* of rapidities,
``theta_piece - theta_frame``. When a frame moves with (almost) the rod's velocity that
difference is tiny, and two float64 rapidities subtracted lose everything they had in
common. Storing each velocity as ``hi + lo`` (about 32 significant digits) together with
its gap to light speed ``1 - |v|`` (correctly rounded on its own, so that even
``1 - 1e-30`` is represented) lets :func:`relative_rapidity` return the difference to a
few ulp of *itself*, for any pair of velocities. The velocities themselves are computed in
double-double arithmetic (:mod:`rigidrel_core._dd`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from . import _dd
from ._dd import DD

#: The largest float64 below 1 (``1 - 2**-53``): a speed closer to light than float64 can show
#: is reported as this, so that every float velocity the core returns has ``|v| < 1``.
BELOW_ONE = math.nextafter(1.0, 0.0)


@dataclass(frozen=True, slots=True, init=False)
class ExactVelocity:
    """A velocity ``v = hi + lo`` (c = 1) with ``gap = 1 - |v|`` kept separately.

    ``hi`` is ``v`` rounded to float64, ``lo`` the float64 residual, ``gap`` is
    ``1 - |v|`` rounded to float64 (never computed as ``1 - hi``).
    """

    hi: float
    lo: float
    gap: float

    def __init__(self, hi: float, lo: float, gap: float) -> None:
        # A frozen dataclass's generated __init__ sets each field through object.__setattr__;
        # the slots' own descriptors do the same in a third less time (velocities are made on
        # every scene change).
        _SET_HI(self, hi)
        _SET_LO(self, lo)
        _SET_GAP(self, gap)

    @classmethod
    def from_float(cls, v: float) -> ExactVelocity:
        """The float ``v`` taken as exact. ``1 - |v|`` is exact for ``|v| >= 1/2`` (Sterbenz)."""
        v = float(v)
        return cls(v, 0.0, 1.0 - abs(v))

    @property
    def value(self) -> float:
        """The velocity rounded to float64, except that a speed within half an ulp of light
        (``gap < 5.6e-17``, which would round to 1) is rounded toward zero, to :data:`BELOW_ONE`:
        ``|value| < 1`` always, one ulp from the exact speed at most. ``gap`` keeps the exact distance."""
        return math.copysign(min(abs(self.hi), BELOW_ONE), self.hi)

    def one_minus(self) -> float:
        """``1 - v`` to a few ulp, also when ``v`` is within 1e-30 of 1."""
        if self.hi >= 0.5:
            return self.gap
        return (1.0 - self.hi) - self.lo

    def one_plus(self) -> float:
        """``1 + v`` to a few ulp, also when ``v`` is within 1e-30 of -1."""
        if self.hi <= -0.5:
            return self.gap
        return (1.0 + self.hi) + self.lo

    def lorentz_factor(self) -> float:
        """``gamma = 1 / sqrt((1 - v)(1 + v))``: no ``1 - v**2`` cancellation."""
        return 1.0 / math.sqrt(self.one_minus() * self.one_plus())

    def proper_velocity(self) -> float:
        """``gamma v = sinh(theta)``."""
        return self.hi / math.sqrt(self.one_minus() * self.one_plus())

    def lorentz_factor_minus_one(self) -> float:
        """``gamma - 1 = (gamma v)^2 / (gamma + 1) = 2 sinh^2(theta/2)``: a product, good to a few ulp
        of itself however small ``v`` is (``gamma - 1`` formed by subtraction keeps none of its
        digits below ``v ~ 1e-8``)."""
        u = self.proper_velocity()
        return u * u / (math.sqrt(1.0 + u * u) + 1.0)

    def rapidity(self) -> float:
        """``theta = atanh(v) = sign(v)/2 * log1p(2|v| / (1 - |v|))``."""
        if self.hi >= 0.0:
            return 0.5 * math.log1p(2.0 * (self.hi + self.lo) / self.one_minus())
        return -0.5 * math.log1p(-2.0 * (self.hi + self.lo) / self.one_plus())

    def negated(self) -> ExactVelocity:
        """``-v``, exactly."""
        return ExactVelocity(-self.hi, -self.lo, self.gap)


_SET_HI, _SET_LO, _SET_GAP = (ExactVelocity.__dict__[name].__set__ for name in ("hi", "lo", "gap"))
REST = ExactVelocity(0.0, 0.0, 1.0)


def relative_rapidity(v: ExactVelocity, frame: ExactVelocity) -> float:
    """Rapidity of velocity ``v`` seen from a frame moving with velocity ``frame``.

    .. math::
        \\theta_v - \\theta_\\beta
        = \\tfrac12 \\ln\\frac{(1+v)(1-\\beta)}{(1-v)(1+\\beta)}
        = \\tfrac12 \\operatorname{log1p}\\frac{2 (v - \\beta)}{(1 - v)(1 + \\beta)}
        \\quad (v \\ge \\beta),

    and the mirror form for ``v < beta``. ``v - beta`` is formed from the double-double
    parts (exact when the two are within a factor 2, Sterbenz), and both log1p
    arguments are positive, so the result is good to a few ulp of itself: the rest
    frame of a rod gives exactly 0, a frame off by 1e-17 gives 1e-17 to 16 digits.
    """
    d = (v.hi - frame.hi) + (v.lo - frame.lo)
    if d >= 0.0:
        return 0.5 * math.log1p(2.0 * d / (v.one_minus() * frame.one_plus()))
    return -0.5 * math.log1p(-2.0 * d / (v.one_plus() * frame.one_minus()))


#: Below this gap the stored ``gap`` (good to half an ulp) is a better ``1 - |v|`` than
#: ``1 - (hi + lo)``, whose absolute error (a few 1e-33) is then no longer small against it.
_TINY_GAP = 2.0**-53


def one_minus_dd(v: ExactVelocity) -> DD:
    """``1 - v`` as a double-double: from ``hi + lo`` (exactly), or the stored gap where that is the
    more accurate (``v`` within 2**-53 of light)."""
    if v.hi >= 0.5 and v.gap < _TINY_GAP:
        return v.gap, 0.0
    return _dd.add_float((-v.hi, -v.lo), 1.0)


def one_plus_dd(v: ExactVelocity) -> DD:
    """``1 + v`` as a double-double (see :func:`one_minus_dd`)."""
    if v.hi <= -0.5 and v.gap < _TINY_GAP:
        return v.gap, 0.0
    return _dd.add_float((v.hi, v.lo), 1.0)


def compose_velocities(a: ExactVelocity, b: ExactVelocity) -> ExactVelocity:
    """Relativistic velocity addition ``v = (a + b) / (1 + a b)`` (rapidities add), in double-double.

    The gap to light speed comes from the products ``1 - v = (1 - a)(1 - b)/(1 + ab)`` and
    ``1 + v = (1 + a)(1 + b)/(1 + ab)``, and ``1 + ab`` itself, for ``a`` and ``b`` near light
    in opposite directions, from ``((1 + a)(1 + b) + (1 - a)(1 - b))/2``: two velocities
    within 1e-30 of light compose without cancellation, and the gap is correctly rounded.
    ``ValueError`` if the composed gap is below float64's range (the speed would be light's).
    """
    a_minus, a_plus, b_minus, b_plus = one_minus_dd(a), one_plus_dd(a), one_minus_dd(b), one_plus_dd(b)
    if a.hi * b.hi < 0.0 and abs(a.hi) >= 0.5 and abs(b.hi) >= 0.5:
        s = _dd.add(_dd.mul(a_plus, b_plus), _dd.mul(a_minus, b_minus))
        denominator = (0.5 * s[0], 0.5 * s[1])
    else:  # 1 + ab >= 1/2: no cancellation
        denominator = _dd.add_float(_dd.mul((a.hi, a.lo), (b.hi, b.lo)), 1.0)
    v = _dd.div(_dd.add((a.hi, a.lo), (b.hi, b.lo)), denominator)
    if abs(v[0]) < 0.5:  # 1 - |v| >= 1/2: no cancellation
        gap = _dd.one_minus_abs(v)
    elif v[0] > 0.0:
        gap = _dd.div(_dd.mul(a_minus, b_minus), denominator)[0]
    else:
        gap = _dd.div(_dd.mul(a_plus, b_plus), denominator)[0]
    if not gap > 0.0:  # both within float64's reach of light: below the represented gap
        raise ValueError("composed velocity reaches light speed")
    return ExactVelocity(v[0], v[1], gap)


def velocity_from_rapidity(psi: float) -> ExactVelocity:
    """``tanh psi`` to double-double (``psi`` taken as exact), with its gap ``1 - |tanh psi| = 2/(exp(2|psi|) + 1)``.

    With ``x = 2|psi|``: for ``x < 1``, ``tanh|psi| = e/(e + 2)`` and the gap ``2/(e + 2)``, with
    ``e = expm1(x)`` from its Taylor series, so a tiny rapidity keeps its relative precision;
    beyond, ``tanh|psi| = (1 - z)/(1 + z)`` and the gap ``2 z/(1 + z)`` with ``z = exp(-x)``
    (the gap underflows to 0 beyond ``|psi| ~ 372``)."""
    if psi == 0.0:
        return REST
    x = 2.0 * abs(psi)
    if x < 1.0:
        e = _dd.expm1_small((x, 0.0))
        denominator = _dd.add_float(e, 2.0)
        speed, gap = _dd.div(e, denominator), _dd.div((2.0, 0.0), denominator)
    else:
        z = _dd.exp_negative(x)
        denominator = _dd.add_float(z, 1.0)
        speed = _dd.div(_dd.add_float((-z[0], -z[1]), 1.0), denominator)
        gap = _dd.div((2.0 * z[0], 2.0 * z[1]), denominator)
    if psi < 0.0:
        return ExactVelocity(-speed[0], -speed[1], gap[0])
    return ExactVelocity(speed[0], speed[1], gap[0])
