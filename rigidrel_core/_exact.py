"""Velocities carried to double-double precision, and rapidity differences without cancellation.

Units: c = 1. A velocity ``v`` in (-1, 1) has rapidity ``theta = atanh(v)``, Lorentz
factor ``gamma = cosh(theta)`` and proper velocity ``gamma v = sinh(theta)``.

Why double-double: every quantity a frame needs is a *difference* of rapidities,
``theta_piece - theta_frame``. When a frame moves with (almost) the rod's velocity that
difference is tiny, and two float64 rapidities subtracted lose everything they had in
common. Storing each velocity as ``hi + lo`` (about 32 significant digits) together with
its gap to light speed ``1 - |v|`` (correctly rounded on its own, so that even
``1 - 1e-30`` is represented) lets :func:`relative_rapidity` return the difference to a
few ulp of *itself*, for any pair of velocities.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from decimal import Decimal, localcontext

#: Working precision (decimal digits) of the scalar scene construction.
DECIMAL_DIGITS = 60
#: The largest float64 below 1 (``1 - 2**-53``): a speed closer to light than float64 can show
#: is reported as this, so that every float velocity the core returns has ``|v| < 1``.
BELOW_ONE = math.nextafter(1.0, 0.0)


@dataclass(frozen=True, slots=True)
class ExactVelocity:
    """A velocity ``v = hi + lo`` (c = 1) with ``gap = 1 - |v|`` kept separately.

    ``hi`` is ``v`` rounded to float64, ``lo`` the float64 residual, ``gap`` is
    ``1 - |v|`` rounded to float64 (never computed as ``1 - hi``).
    """

    hi: float
    lo: float
    gap: float

    @classmethod
    def from_float(cls, v: float) -> ExactVelocity:
        """The float ``v`` taken as exact. ``1 - |v|`` is exact for ``|v| >= 1/2`` (Sterbenz)."""
        v = float(v)
        return cls(v, 0.0, 1.0 - abs(v))

    @classmethod
    def from_decimal(cls, v: Decimal) -> ExactVelocity:
        """Round a high-precision velocity to ``hi + lo`` and its gap to light speed."""
        with localcontext() as ctx:
            ctx.prec = DECIMAL_DIGITS
            hi = float(v)
            lo = float(v - Decimal(hi))
            gap = float(1 - abs(v))
        return cls(hi, lo, gap)

    @property
    def value(self) -> float:
        """The velocity rounded to float64, except that a speed within half an ulp of light
        (``gap < 5.6e-17``, which would round to 1) is rounded toward zero, to :data:`BELOW_ONE`:
        ``|value| < 1`` always, one ulp from the exact speed at most. ``gap`` keeps the exact distance."""
        return math.copysign(min(abs(self.hi), BELOW_ONE), self.hi)

    def as_decimal(self) -> Decimal:
        """``hi + lo`` as an exact decimal (the gap is not used)."""
        return Decimal(self.hi) + Decimal(self.lo)

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

    def rapidity(self) -> float:
        """``theta = atanh(v) = sign(v)/2 * log1p(2|v| / (1 - |v|))``."""
        if self.hi >= 0.0:
            return 0.5 * math.log1p(2.0 * (self.hi + self.lo) / self.one_minus())
        return -0.5 * math.log1p(-2.0 * (self.hi + self.lo) / self.one_plus())

    def negated(self) -> ExactVelocity:
        """``-v``, exactly."""
        return ExactVelocity(-self.hi, -self.lo, self.gap)


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


def _one_minus_decimal(v: ExactVelocity) -> Decimal:
    """``1 - v`` as an exact decimal, using the stored gap where it is the accurate part."""
    return Decimal(v.gap) if v.hi >= 0.5 else 1 - v.as_decimal()


def _one_plus_decimal(v: ExactVelocity) -> Decimal:
    return Decimal(v.gap) if v.hi <= -0.5 else 1 + v.as_decimal()


def compose_velocities(a: ExactVelocity, b: ExactVelocity) -> ExactVelocity:
    """Relativistic velocity addition ``(a + b) / (1 + a b)`` (rapidities add), in 60 digits.

    The gap to light speed comes from the products ``1 - v = (1 - a)(1 - b)/(1 + ab)`` and
    ``1 + v = (1 + a)(1 + b)/(1 + ab)``, so two velocities within 1e-30 of light compose
    without cancellation.
    """
    with localcontext() as ctx:
        ctx.prec = DECIMAL_DIGITS
        da, db = a.as_decimal(), b.as_decimal()
        denominator = 1 + da * db
        v = (da + db) / denominator
        if v >= 0:
            gap = _one_minus_decimal(a) * _one_minus_decimal(b) / denominator
        else:
            gap = _one_plus_decimal(a) * _one_plus_decimal(b) / denominator
        if gap <= 0:  # both within float64's reach of light: below the represented gap
            raise ValueError("composed velocity reaches light speed")
        hi = float(v)
        return ExactVelocity(hi, float(v - Decimal(hi)), float(gap))


def velocity_from_rapidity(psi: float) -> ExactVelocity:
    """``tanh psi`` to double-double, its gap ``2/(exp(2|psi|) + 1)`` beside it (60 digits, ``psi`` exact).

    ``exp(2|psi|) - 1`` loses as many digits as ``2|psi|`` has leading zeros: the working
    precision grows by those, so a tiny rapidity keeps its 60 digits too."""
    if psi == 0.0:
        return REST
    with localcontext() as ctx:
        ctx.prec = DECIMAL_DIGITS + max(0, -math.floor(math.log10(2.0 * abs(psi))))
        e = (2 * Decimal(abs(psi))).exp()  # exp(2|psi|)
        speed = (e - 1) / (e + 1)
        gap = 2 / (e + 1)
        v = speed if psi >= 0 else -speed
        hi = float(v)
        return ExactVelocity(hi, float(v - Decimal(hi)), float(gap))


def lorentz_factor_decimal(v: Decimal) -> Decimal:
    """``gamma = 1/sqrt((1 - v)(1 + v))`` in the ambient decimal context."""
    return 1 / ((1 - v) * (1 + v)).sqrt()


def velocity_from_proper_velocity(u: Decimal) -> ExactVelocity:
    """``v = u / sqrt(1 + u**2)`` with ``1 - |v| = 1 / (sqrt(1+u^2) (sqrt(1+u^2) + |u|))``."""
    with localcontext() as ctx:
        ctx.prec = DECIMAL_DIGITS
        g = (1 + u * u).sqrt()
        v = u / g
        gap = 1 / (g * (g + abs(u)))
        hi = float(v)
        lo = float(v - Decimal(hi))
        return ExactVelocity(hi, lo, float(gap))
