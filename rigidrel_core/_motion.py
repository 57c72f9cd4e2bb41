r"""Born-rigid motion of one rod whose velocity changes once, evaluated in any frame.

Every scene of Franklin (2012) is built from one motion per rod (units c = 1):

1. inertial at velocity ``v_i`` (rapidity ``theta_i``);
2. a Born-rigid change: each material point moves on a hyperbola about one common
   centre event ``C`` (whose light cone is the Rindler horizon), the point at rest-distance ``rho`` from it
   with proper acceleration ``1/rho`` (paper Sec. 3, Eqs. (4), (15); ``rho = 0`` is the
   impulsive limit of Sec. 4);
3. inertial at velocity ``v_f``.

A hyperbola piece is Lorentz covariant: in lab coordinates its points are
``C + sign * rho * (sinh(theta), cosh(theta))`` for ``theta`` between ``theta_i`` and
``theta_f``; a boost into a frame of rapidity ``psi`` maps it to
``C' + sign * rho * (sinh(theta - psi), cosh(theta - psi))``. So a frame only changes the
centre event and shifts the rapidity interval; the piece stays a hyperbola and a slice
at equal frame time is closed form. With ``t'_C`` the centre's frame time, each piece is
anchored where it crosses the frame's ``t' = 0`` line (the line through every scene's key
event, the origin):

.. math::
    x'(t') = X'_0 + \tanh(\theta')\,t' \quad\text{(inertial; } X'_0 = a \cosh\theta/\cosh\theta'\text{)},

    x'(t') = X'_h + \sigma\,\frac{t'\,(t' - 2 t'_C)}{\sqrt{\rho^2 + (t' - t'_C)^2} + \sqrt{\rho^2 + t'^2_C}}
    \quad\text{(hyperbola)},

with ``a`` the inertial tangent's lab intercept and ``X'_h`` the hyperbola's ``t' = 0``
crossing, each formed without cancellation (see :func:`plan_motions`). Nothing
subtracts nearly equal numbers: the hyperbola's rise is a product over a sum of square
roots, and every rapidity difference comes from :func:`relative_rapidity` (double-double
velocities). Near the origin an ultra-relativistic rod keeps its length L/γ to full
relative precision.

Material points are labelled by ``f`` in [0, 1], the fraction of the rest length from the
rod's left end.
"""

from __future__ import annotations

import functools
import math
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import ClassVar, Literal, NamedTuple

import numpy as np
import numpy.typing as npt

from . import _dd as dd
from ._dd import DD, two_prod, two_sum
from ._exact import BELOW_ONE, ExactVelocity, one_minus_dd, one_plus_dd, relative_rapidity
from ._frame import Frame
from ._validate import non_decreasing

FloatArray = npt.NDArray[np.float64]

#: From this many sorted times on, rows are sampled piece by piece (measured crossover with the
#: branch-free form, quiet machine: about 750 times for 4 rows, 1200 for 22; at 1024 times the
#: piecewise path took 0.86 and 1.13 times the branch-free form's time).
PIECEWISE_MIN = 1024
#: From this many unsorted times on, rows are sampled by blocks (measured crossover: about 2048
#: times for 4 and for 22 rows).
_SHUFFLED_MIN = 2048
#: The sampler before these paths used its sorted form (which squares the radius with ``pow``)
#: from this many sorted times on, its branch-free form (``rho * rho``) below: the sorted path
#: squares as the form it stands for did, so its outputs are those of the old sampler bit for bit.
_POW_SQUARE_MIN = 2048
#: Times per block on the piecewise paths: a block's work arrays (256 KiB each) stay in the
#: caches, and numpy's cost per call (0.5 to 2 us on a shared 2-core machine) is spread over
#: enough samples: on such a machine 4096 was 1.3 times slower than 32768 on sorted curved
#: pieces, 65536 a few percent faster.
_BLOCK = 32768
#: Up to this many samples (rows x times) are computed in Python floats, one at a time (measured
#: crossover with the branch-free form's numpy calls, quiet machine: about 90 samples for 2 rows,
#: 120 for 4).
_SCALAR_MAX = 96
#: The three pieces of a row, in time order (see :func:`_piece`).
_BEFORE, _CURVED, _AFTER = 0, 1, 2
#: Stand-in for a zero radius in a denominator that is then multiplied by zero.
_TINY = 1e-300


class _Row(NamedTuple):
    """One row's constants as Python floats (see :class:`MotionPlan`).

    ``radius2`` is ``rho * rho``, the branch-free form's square; ``radius2_pow`` is ``rho ** 2`` on a
    numpy scalar (libm ``pow``), the sorted path's. The two can differ in the last bit (about one
    radius in a thousand); each path keeps the square it has always used, so no output changes.
    """

    sign: float
    radius2: float
    radius2_pow: float
    q0: float
    t_vertex: float
    two_t_vertex: float
    x_hyp: float
    t_start: float
    t_stop: float
    w_start: float
    x0_start: float
    w_stop: float
    x0_stop: float


class _RowArrays(NamedTuple):
    """One row's constants as 0-d arrays: numpy converts a Python float operand on every call,
    which costs about as much as the arithmetic of a few hundred samples."""

    sign: float
    radius2: FloatArray
    q0: FloatArray
    t_vertex: FloatArray
    two_t_vertex: FloatArray
    x_hyp: FloatArray
    w_start: FloatArray
    x0_start: FloatArray
    w_stop: FloatArray
    x0_stop: FloatArray
    t_start: FloatArray
    t_stop: FloatArray

    @classmethod
    def of(cls, row: _Row, radius2: float) -> _RowArrays:
        a = np.array
        return cls(
            row.sign,
            a(radius2),
            a(row.q0),
            a(row.t_vertex),
            a(row.two_t_vertex),
            a(row.x_hyp),
            a(row.w_start),
            a(row.x0_start),
            a(row.w_stop),
            a(row.x0_stop),
            a(row.t_start),
            a(row.t_stop),
        )


def _line(t: FloatArray, w: FloatArray, x0: FloatArray, out: FloatArray) -> FloatArray:
    """``w t + x0`` into ``out``: an inertial piece."""
    np.multiply(t, w, out)
    return np.add(out, x0, out)


def _piece(piece: int, t: FloatArray, c: _RowArrays, out: FloatArray, work: FloatArray) -> FloatArray:
    """One of a row's pieces (``_BEFORE``, ``_CURVED``, ``_AFTER``) at times ``t``, into ``out``."""
    if piece == _CURVED:
        return _hyperbola(t, c, out, work)
    if piece == _BEFORE:
        return _line(t, c.w_start, c.x0_start, out)
    return _line(t, c.w_stop, c.x0_stop, out)


def _hyperbola(t: FloatArray, c: _RowArrays, out: FloatArray, work: FloatArray) -> FloatArray:
    """``x_hyp + sign t (t - 2 t_vertex) / (sqrt((t - t_vertex)^2 + rho^2) + q0)`` into ``out``.

    The branch-free form's operations in its order; its ``* sign`` then ``+ x_hyp`` is one
    addition or subtraction here (negation is exact, and ``x + (-y)`` is ``x - y`` in IEEE).
    """
    np.subtract(t, c.t_vertex, out)
    np.multiply(out, out, out)
    np.add(out, c.radius2, out)
    np.sqrt(out, out)
    np.add(out, c.q0, out)
    np.subtract(t, c.two_t_vertex, work)
    np.multiply(work, t, work)
    np.divide(work, out, out)
    if c.sign == 1.0:
        return np.add(out, c.x_hyp, out)
    if c.sign == -1.0:
        return np.subtract(c.x_hyp, out, out)
    np.multiply(out, c.sign, out)
    return np.add(out, c.x_hyp, out)


@dataclass(frozen=True, init=False)
class RigidMotion:
    """One rod: inertial, one Born-rigid velocity change, inertial (lab description).

    The change's centre event is at lab ``(t, x) = (0, horizon_x)``. The hyperbola of the
    left end passes through rest at lab ``(0, vertex_left)``: at lab time 0 the whole
    (extended) family has the rod at rest on ``[vertex_left, vertex_left + length]``.
    """

    born_rigid: ClassVar[bool] = True
    """In the momentarily comoving frame of any of its points the rod has its rest length."""
    length: float
    """Rest length ``L`` (> 0)."""
    sign: Literal[1, -1]
    """+1 when the rapidity increases (rod to the right of its centre), -1 when it decreases."""
    horizon_x: float
    """Lab x of the centre event (at lab t = 0)."""
    radius_left: float
    """Distance ``rho`` of the left end from the centre, in the rod's rest frame (>= 0)."""
    radius_right: float
    """Distance ``rho`` of the right end from the centre (>= 0)."""
    vertex_left: float
    """Lab x of the left end's vertex: ``horizon_x + sign * radius_left``, stored exactly."""
    velocity_initial: ExactVelocity
    velocity_final: ExactVelocity
    _lab_rows: dict[bytes, tuple[LabRow, ...]] = field(
        default_factory=dict[bytes, "tuple[LabRow, ...]"], init=False, repr=False, compare=False
    )

    def __init__(
        self,
        length: float,
        sign: Literal[1, -1],
        horizon_x: float,
        radius_left: float,
        radius_right: float,
        vertex_left: float,
        velocity_initial: ExactVelocity,
        velocity_final: ExactVelocity,
    ) -> None:
        # the instance's dict filled at once, not through one object.__setattr__ call per field (the
        # generated __init__): every scene change makes its motions
        self.__dict__.update(
            length=length,
            sign=sign,
            horizon_x=horizon_x,
            radius_left=radius_left,
            radius_right=radius_right,
            vertex_left=vertex_left,
            velocity_initial=velocity_initial,
            velocity_final=velocity_final,
            _lab_rows={},
        )

    @property
    def length_final(self) -> float:
        """Rest length after the change: ``length`` (Born-rigid)."""
        return self.length

    @functools.cached_property
    def rapidity_change(self) -> float:
        """``|theta_f - theta_i|`` (lab rapidities, invariant): a point at rest-distance ``rho`` from
        the centre ages ``rho |theta_f - theta_i|`` during the change (proper acceleration ``1/rho``)."""
        return abs(relative_rapidity(self.velocity_final, self.velocity_initial))

    def radius(self, fraction: float) -> float:
        """Rest-distance of material point ``fraction`` from the centre (see :func:`lab_row`)."""
        return self.lab_rows(np.array([fraction]))[0].radius

    def lab_rows(self, fractions: FloatArray, *, exact: bool = False) -> tuple[LabRow, ...]:
        """The frame-independent constants of material points ``fractions`` (see :func:`lab_row`),
        worked out once per set of fractions; ``exact`` also fills their double-double low parts."""
        key = (b"x" if exact else b"") + fractions.tobytes()
        rows = self._lab_rows.get(key)
        if rows is None:
            if len(self._lab_rows) >= _MAX_CACHED_FRACTIONS:
                self._lab_rows.clear()
            if exact:
                sums = (*_anchor_sums(self.velocity_initial), *_anchor_sums(self.velocity_final))
                rows = tuple(lab_row(self, f, sums, True) for f in fractions.tolist())
            else:
                rows = _float_lab_rows(self, fractions.tolist())
            self._lab_rows[key] = rows
        return rows


#: A float sum that keeps less than 1/64 of its terms is redone in double-double.
_CANCELLATION = 64.0
#: Sets of fractions whose lab constants a motion keeps (the ends, the ticks, a few more).
_MAX_CACHED_FRACTIONS = 16


class LabRow(NamedTuple):
    """One material point's lab constants: its radius and vertex, the lab intercepts ``a`` of its
    two inertial lines, and the light-cone coordinates ``(-u, w) = (x - t, t + x)`` of its two
    switch events."""

    radius: float
    x_vertex: float
    intercept_initial: float
    minus_u_start: float
    w_start: float
    intercept_final: float
    minus_u_stop: float
    w_stop: float
    low: tuple[float, float, float, float, float, float]
    """The double-double low parts of the six values above from ``intercept_initial`` on: the
    light-cone coordinates of two switch events differ by far less than each can be (a light ray
    chasing an ultra-relativistic point), and their difference is then exact."""


def lab_row(m: RigidMotion, f: float, sums: Sequence[_AnchorSum], exact: bool = False) -> LabRow:
    """The lab constants of fraction ``f`` (``sums``: :func:`_anchor_sums` of the motion's
    ``1/gamma`` and ``exp(-+theta)`` before and after).

    Each is ``x_C + sign rho F`` (from the centre) or ``x_V + sign rho (F - 1)`` (from the vertex),
    whichever has the smaller terms. In float64 unless the two terms cancel (or ``exact`` asks for
    the low parts); then to double-double (:func:`_anchored_dd`, ``F`` from the velocity's exact
    parts), so that a switch event on (or a hair off) the origin's light cone, or a tangent through
    the origin, keeps its coordinate to ~1e-32 of the scene's size, and a boost of any ``gamma``
    multiplies an exact number. ``exact`` rows carry every value's low part (light signals take
    differences of two events' coordinates, which may agree in far more digits than float64 has).
    """
    sig, xc = float(m.sign), m.horizon_x
    # the point's rest-distance from the centre and its vertex, to double-double: the ends are
    # exactly L0 apart (rho_right - rho_left = L0), which float radii rounded apart would not be
    if f == 0.0:
        along, along_lo = 0.0, 0.0
    elif f == 1.0:
        along, along_lo = m.length, 0.0
    else:
        along, along_lo = two_prod(f, m.length)
    # two_sum(radius_left, sig along) and two_sum(vertex_left, along), written out
    a, b = m.radius_left, sig * along
    rho = a + b
    t = rho - a
    rho_lo = (a - (rho - t)) + (b - t) + sig * along_lo
    a = m.vertex_left
    x_lab = a + along
    t = x_lab - a
    x_lo = (a - (x_lab - t)) + (along - t) + along_lo
    if rho < 0.0:  # a point beyond the centre cannot be (radii are >= 0); only rounding gets here
        rho, rho_lo = 0.0, 0.0
    srho, srho_lo, axc, ax = sig * rho, sig * rho_lo, abs(xc), abs(x_lab)
    highs: list[float] = []
    lows: list[float] = []
    for k, (f_float, f1_float, abs_f, abs_f1) in enumerate(sums):
        by_centre, by_vertex = axc + rho * abs_f, ax + rho * abs_f1
        from_centre = by_centre <= by_vertex
        if not exact:
            total = xc + srho * f_float if from_centre else x_lab + srho * f1_float
            if abs(total) * _CANCELLATION >= (by_centre if from_centre else by_vertex):
                highs.append(total)
                lows.append(0.0)
                continue
        anchor = (xc, 0.0) if from_centre else (x_lab, x_lo)
        v = m.velocity_initial if k < 3 else m.velocity_final
        hi, lo = _anchored_dd(anchor, (srho, srho_lo), v, _FACTOR_SIGNS[k % 3], not from_centre)
        highs.append(hi)
        lows.append(lo)
    return LabRow._make((rho, x_lab, *highs, tuple(lows)))


_NO_LOW_PARTS = (0.0, 0.0, 0.0, 0.0, 0.0, 0.0)


def _float_lab_rows(m: RigidMotion, fractions: list[float]) -> tuple[LabRow, ...]:
    """``lab_row(m, f, sums)`` for every fraction: the same operations, written out for the common
    case where no sum cancels (each row is then six float sums, each from the centre or from the
    vertex); a row where one does is made by :func:`lab_row` itself (double-double)."""
    sig, xc = float(m.sign), m.horizon_x
    r_left, v_left, length = m.radius_left, m.vertex_left, m.length
    axc = abs(xc)
    sums = (*_anchor_sums(m.velocity_initial), *_anchor_sums(m.velocity_final))
    (
        (f1, g1, af1, ag1),
        (f2, g2, af2, ag2),
        (f3, g3, af3, ag3),
        (f4, g4, af4, ag4),
        (f5, g5, af5, ag5),
        (
            f6,
            g6,
            af6,
            ag6,
        ),
    ) = sums
    c = _CANCELLATION
    rows: list[LabRow] = []
    for f in fractions:
        along = 0.0 if f == 0.0 else length if f == 1.0 else f * length  # lab_row's, without the low parts
        rho = r_left + sig * along  # the high parts of lab_row's two_sums
        x_lab = v_left + along
        srho, ax = sig * rho, abs(x_lab)
        # each sum: from the centre (x_C + sign rho F) or the vertex (x_V + sign rho (F - 1)),
        # whichever has the smaller terms; kept if it keeps 1/64 of them
        b1, d1 = axc + rho * af1, ax + rho * ag1
        s1 = xc + srho * f1 if b1 <= d1 else x_lab + srho * g1
        b2, d2 = axc + rho * af2, ax + rho * ag2
        s2 = xc + srho * f2 if b2 <= d2 else x_lab + srho * g2
        b3, d3 = axc + rho * af3, ax + rho * ag3
        s3 = xc + srho * f3 if b3 <= d3 else x_lab + srho * g3
        b4, d4 = axc + rho * af4, ax + rho * ag4
        s4 = xc + srho * f4 if b4 <= d4 else x_lab + srho * g4
        b5, d5 = axc + rho * af5, ax + rho * ag5
        s5 = xc + srho * f5 if b5 <= d5 else x_lab + srho * g5
        b6, d6 = axc + rho * af6, ax + rho * ag6
        s6 = xc + srho * f6 if b6 <= d6 else x_lab + srho * g6
        if (
            rho >= 0.0
            and abs(s1) * c >= (b1 if b1 <= d1 else d1)
            and abs(s2) * c >= (b2 if b2 <= d2 else d2)
            and abs(s3) * c >= (b3 if b3 <= d3 else d3)
            and abs(s4) * c >= (b4 if b4 <= d4 else d4)
            and abs(s5) * c >= (b5 if b5 <= d5 else d5)
            and abs(s6) * c >= (b6 if b6 <= d6 else d6)
        ):
            rows.append(LabRow(rho, x_lab, s1, s2, s3, s4, s5, s6, _NO_LOW_PARTS))
        elif rho < 0.0:  # a radius below 0 (rounding): lab_row clamps it
            rows.append(lab_row(m, f, sums))
        else:  # a sum that cancels: that one to double-double, as lab_row does it
            rows.append(
                _redo_cancelled(
                    m, f, rho, x_lab, (s1, s2, s3, s4, s5, s6), (b1, b2, b3, b4, b5, b6), (d1, d2, d3, d4, d5, d6)
                )
            )
    return tuple(rows)


def _redo_cancelled(
    m: RigidMotion,
    f: float,
    rho: float,
    x_lab: float,
    totals: tuple[float, ...],
    by_centre: tuple[float, ...],
    by_vertex: tuple[float, ...],
) -> LabRow:
    """:func:`lab_row` for a row of :func:`_float_lab_rows` (``rho >= 0``) some of whose float sums
    cancel: those are redone to double-double (:func:`_anchored_dd`, with lab_row's low parts of
    the radius and the vertex), the others kept."""
    sig, xc = float(m.sign), m.horizon_x
    along_lo = 0.0 if f in (0.0, 1.0) else two_prod(f, m.length)[1]
    along = 0.0 if f == 0.0 else m.length if f == 1.0 else f * m.length
    rho_lo = two_sum(m.radius_left, sig * along)[1] + sig * along_lo
    x_lo = two_sum(m.vertex_left, along)[1] + along_lo
    srho = (sig * rho, sig * rho_lo)
    highs: list[float] = []
    lows: list[float] = []
    for k, (total, b, d) in enumerate(zip(totals, by_centre, by_vertex, strict=True)):
        from_centre = b <= d
        if abs(total) * _CANCELLATION >= (b if from_centre else d):
            highs.append(total)
            lows.append(0.0)
            continue
        v = m.velocity_initial if k < 3 else m.velocity_final
        anchor = (xc, 0.0) if from_centre else (x_lab, x_lo)
        hi, lo = _anchored_dd(anchor, srho, v, _FACTOR_SIGNS[k % 3], not from_centre)
        highs.append(hi)
        lows.append(lo)
    return LabRow._make((rho, x_lab, *highs, tuple(lows)))


def _factor_dd(v: ExactVelocity, sign: float) -> DD:
    """To double-double: ``1/gamma = sqrt((1 - v)(1 + v))`` for ``sign = 0``, else
    ``exp(sign theta) = sqrt((1 + sign v)/(1 - sign v))`` (``theta = atanh v``)."""
    plus, minus = one_plus_dd(v), one_minus_dd(v)
    if sign == 0.0:
        return dd.sqrt(dd.mul(plus, minus))
    return dd.sqrt(dd.div(plus, minus) if sign > 0.0 else dd.div(minus, plus))


#: ``(F, F - 1, |F|, |F - 1|)`` of one factor ``F`` (see :func:`_anchor_sums`).
_AnchorSum = tuple[float, float, float, float]
#: The ``sign`` of :func:`_factor_dd` for the three factors of :func:`_anchor_sums`, in its order.
_FACTOR_SIGNS = (0.0, -1.0, 1.0)


def _anchor_sums(v: ExactVelocity) -> tuple[_AnchorSum, _AnchorSum, _AnchorSum]:
    """``(F, F - 1, |F|, |F - 1|)`` in float64 for the three factors ``F`` of :func:`_factor_dd`
    (``sign`` 0, -1, +1: ``1/gamma``, ``exp(-theta)``, ``exp(theta)``).

    A row's tangent intercept and switch-event light-cone coordinates are ``x_C + sign rho F`` (from
    the centre) or ``x_V + sign rho (F - 1)`` (from the vertex); ``F - 1`` is
    ``-(gamma v)^2/((gamma + 1) gamma)`` for ``1/gamma`` and ``expm1(sign theta)`` for
    ``exp(sign theta)``, without cancellation. The velocity's ``1 -+ v``, ``gamma``, ``gamma v`` and
    ``theta`` are formed once, inline, with the operations of :class:`ExactVelocity`'s methods (this
    runs for every new scene).
    """
    hi, lo = v.hi, v.lo
    one_minus = v.gap if hi >= 0.5 else (1.0 - hi) - lo
    one_plus = v.gap if hi <= -0.5 else (1.0 + hi) + lo
    root = math.sqrt(one_minus * one_plus)
    g, u = 1.0 / root, hi / root  # lorentz_factor(), proper_velocity()
    if hi >= 0.0:  # rapidity()
        theta = 0.5 * math.log1p(2.0 * (hi + lo) / one_minus)
    else:
        theta = -0.5 * math.log1p(-2.0 * (hi + lo) / one_plus)
    f1 = -u * u / ((g + 1.0) * g)
    e_minus, e_minus1 = math.exp(-theta), math.expm1(-theta)
    e_plus, e_plus1 = math.exp(theta), math.expm1(theta)
    return (
        (1.0 / g, f1, abs(1.0 / g), abs(f1)),
        (e_minus, e_minus1, e_minus, abs(e_minus1)),
        (e_plus, e_plus1, e_plus, abs(e_plus1)),
    )


def _anchored_dd(anchor: DD, srho: DD, v: ExactVelocity, sign: float, minus_one: bool) -> DD:
    """``anchor + sign_rho (F - [1 if minus_one])`` to double-double, ``F`` from :func:`_factor_dd`:
    an exact product and an exact sum."""
    hi, lo = _factor_dd(v, sign)
    if minus_one:
        hi, e = two_sum(hi, -1.0)
        hi, lo = two_sum(hi, e + lo)
    p, pe = two_prod(srho[0], hi)
    s, se = two_sum(anchor[0], p)
    return two_sum(s, se + (pe + (srho[0] * lo + srho[1] * hi) + anchor[1]))


def plan_motions(motions: Sequence[RigidMotion], frame: Frame, fractions: FloatArray) -> MotionPlan:
    """Per-frame constants of every rod's material points ``fractions`` (rows: rod-major).

    **Switch events.** A point at rest-distance ``rho`` from its centre ``C = (0, x_C)`` starts and
    stops changing velocity at the lab events ``C + sign rho (sinh theta, cosh theta)``, ``theta``
    the lab rapidity before and after. Their light-cone coordinates ``u = t - x`` and ``w = t + x``
    are each a sum of two terms, anchored at the centre (``u = -x_C - sign rho e^-theta``,
    ``w = x_C + sign rho e^theta``) or at the point's vertex ``(0, x_V)``
    (``u = -x_V - sign rho expm1(-theta)``, ``w = x_V + sign rho expm1(theta)``), whichever has the
    smaller terms. A boost multiplies them, ``u' = e^psi u``, ``w' = e^-psi w``, and
    ``t' = (u' + w')/2``, ``x' = (w' - u')/2``: no frame-sized terms cancel, so the frame times
    the clocks are read from are good to the lab's own rounding. ``u``, ``w`` and the intercepts
    below depend on no frame: each motion works them out once per set of fractions
    (:meth:`RigidMotion.lab_rows`), and a new frame costs only the products.

    **Inertial pieces** of lab velocity ``v``: ``x' = X_0' + tanh(theta') t'`` with
    ``X_0' = a cosh(theta) / cosh(theta')`` and ``a`` the lab intercept at ``t = 0``:
    ``a = x_C + sign rho / gamma`` (the tangent's distance from the centre, contracted) or, when the
    centre lies on the other side, ``a = x_V - sign rho (gamma - 1)/gamma`` with
    ``gamma - 1 = (gamma v)^2 / (gamma + 1)``: a product, good to a few ulp of itself however
    small, so a point near the frame's origin keeps its relative precision.

    **Hyperbola**: ``x' = X_h + sign t'(t' - 2 t'_C) / (q + q_0)`` with ``t'_C = -x_C sinh psi``,
    ``q = sqrt(rho^2 + (t' - t'_C)^2)``, ``q_0 = sqrt(rho^2 + t'_C^2)`` and ``X_h`` its ``t' = 0``
    crossing ``x'_C + sign q_0``, or, when those two cancel, ``x_V (x_C - sign rho)/(x'_C - sign q_0)``
    (the product of the quadratic's roots). One row of plain float arithmetic per rod and fraction.
    """
    fv = frame.velocity
    f_hi, f_lo = fv.hi, fv.lo
    f_minus = fv.gap if f_hi >= 0.5 else (1.0 - f_hi) - f_lo  # the frame's 1 - beta, 1 + beta
    f_plus = fv.gap if f_hi <= -0.5 else (1.0 + f_hi) + f_lo
    root = math.sqrt(f_minus * f_plus)
    sh = f_hi / root  # sinh psi = gamma beta
    g = 1.0 / root
    ch = 1.0 + sh * sh / (math.sqrt(1.0 + sh * sh) + 1.0)  # 1 + (gamma - 1), accurate for small beta
    up, down = g * f_plus, g * f_minus  # exp(psi), exp(-psi)
    rows: list[tuple[float, ...]] = []
    # Plans have few rows (2 per rod for the ends, 11 for the ticks): float arithmetic on
    # Python floats is many times cheaper here than numpy calls on tiny arrays. Each velocity's
    # 1 -+ v, gamma and rapidity relative to the frame are written out with the operations of
    # ExactVelocity's methods and relative_rapidity (a call costs as much as the arithmetic).
    for m in motions:
        vi, vf = m.velocity_initial, m.velocity_final
        hi, lo = vi.hi, vi.lo
        i_minus = vi.gap if hi >= 0.5 else (1.0 - hi) - lo
        i_plus = vi.gap if hi <= -0.5 else (1.0 + hi) + lo
        d = (hi - f_hi) + (lo - f_lo)
        if d >= 0.0:
            th_i = 0.5 * math.log1p(2.0 * d / (i_minus * f_plus))
        else:
            th_i = -0.5 * math.log1p(-2.0 * d / (i_plus * f_minus))
        c_i = 1.0 / math.sqrt(i_minus * i_plus) / math.cosh(th_i)
        hi, lo = vf.hi, vf.lo
        s_minus = vf.gap if hi >= 0.5 else (1.0 - hi) - lo
        s_plus = vf.gap if hi <= -0.5 else (1.0 + hi) + lo
        d = (hi - f_hi) + (lo - f_lo)
        if d >= 0.0:
            th_f = 0.5 * math.log1p(2.0 * d / (s_minus * f_plus))
        else:
            th_f = -0.5 * math.log1p(-2.0 * d / (s_plus * f_minus))
        c_f = 1.0 / math.sqrt(s_minus * s_plus) / math.cosh(th_f)
        # |theta_f - theta_i|: the proper time the change takes per unit rest-distance
        d = (hi - vi.hi) + (lo - vi.lo)
        if d >= 0.0:
            turn = abs(0.5 * math.log1p(2.0 * d / (s_minus * i_plus)))
        else:
            turn = abs(-0.5 * math.log1p(-2.0 * d / (s_plus * i_minus)))
        sig, xc = float(m.sign), m.horizon_x
        sinh_i, sinh_f = math.sinh(th_i), math.sinh(th_f)
        w_i, w_f = math.tanh(th_i), math.tanh(th_f)
        t_c = -xc * sh
        two_t_c = 2.0 * t_c
        x_c = xc * ch
        same_side = sig * x_c >= 0.0  # the direct sum x'_C + sign q_0 does not cancel
        for rho, x_lab, a_i, minus_u, w, a_f, minus_u_stop, w_stop, _ in m.lab_rows(fractions):
            q0 = math.hypot(rho, t_c)
            x_hyp = x_c + sig * q0 if same_side else x_lab * (xc - sig * rho) / (x_c - sig * q0)
            srho = sig * rho
            u, w = -minus_u * up, w * down  # t' - x' and t' + x' of the start event
            t_start, x_start = 0.5 * (u + w), 0.5 * (w - u)
            u, w = -minus_u_stop * up, w_stop * down
            t_stop, x_stop = 0.5 * (u + w), 0.5 * (w - u)
            rows.append(
                (  # in MotionPlan's field order (a NamedTuple with keywords would cost ~1 us a row)
                    sig,
                    rho,
                    t_c,
                    q0 if (rho > 0.0 or q0 > 0.0) else _TINY,
                    x_hyp,
                    srho * sinh_i,
                    srho * sinh_f,
                    t_start,
                    t_stop,
                    x_start,
                    x_stop,
                    a_i * c_i,
                    w_i,
                    a_f * c_f,
                    w_f,
                    th_i,
                    th_f,
                    rho * turn,
                    rho * rho,
                    two_t_c,
                )
            )
    table = np.array(rows, dtype=np.float64) if rows else np.empty((0, len(_PLAN_FIELDS)))
    return plan_from_table(table)


def plan_from_table(table: FloatArray) -> MotionPlan:
    """A plan whose fields are the columns of ``table`` (``(rows, fields)``, in :data:`PLAN_FIELDS` order)."""
    # a frozen dataclass's __init__ sets each of its fields through object.__setattr__: filling
    # the instance dict at once is a third of the plan's cost cheaper, and the same object
    plan = object.__new__(MotionPlan)
    plan.__dict__["_table"] = table  # each field is a column of it, made on first use (__getattr__)
    return plan


@dataclass(frozen=True)
class MotionPlan:
    """Frame constants for a set of material points (rows); arrays have shape ``(rows,)``.

    Before ``t_start`` a row is at ``x0_start + w_start t'``; after ``t_stop`` at
    ``x0_stop + w_stop t'``; in between on its hyperbola
    ``x_hyp + sign t'(t' - 2 t_vertex) / (sqrt(rho^2 + (t' - t_vertex)^2) + q0)``.
    """

    sign: FloatArray
    radius: FloatArray
    t_vertex: FloatArray
    q0: FloatArray
    x_hyp: FloatArray
    s_start: FloatArray
    s_stop: FloatArray
    t_start: FloatArray
    t_stop: FloatArray
    x_start: FloatArray
    x_stop: FloatArray
    x0_start: FloatArray
    w_start: FloatArray
    x0_stop: FloatArray
    w_stop: FloatArray
    rapidity_start: FloatArray
    rapidity_stop: FloatArray
    proper_time_change: FloatArray
    """``rho |theta_f - theta_i|``: the proper time the change takes (lab rapidities, invariant)."""
    radius2: FloatArray
    """``rho * rho`` (the branch-free form's square)."""
    two_t_vertex: FloatArray
    """``2 t_vertex``."""
    _table: FloatArray = field(init=False, repr=False, compare=False)
    """Every field above as one ``(rows, fields)`` array (the fields are its columns)."""

    def __getattr__(self, name: str) -> FloatArray:
        """A field not yet looked up: its column of the plan's table, kept (a view each; the
        branch-free form reads none of them, only the table)."""
        index = _FIELD_INDEX.get(name)
        table = self.__dict__.get("_table")
        if index is None or table is None:
            raise AttributeError(name)
        column = table[:, index]
        self.__dict__[name] = column
        return column

    @property
    def rows(self) -> int:
        """How many rows (material points of all rods) the plan has."""
        return self._table.shape[0]

    @property
    def table(self) -> FloatArray:
        """Every field as one ``(rows, fields)`` array, columns in :data:`PLAN_FIELDS` order (read only)."""
        return self._table

    def column(self, name: str) -> FloatArray:
        return getattr(self, name)[:, None]

    @property
    def _rows(self) -> list[_Row]:
        """Each row's constants as Python floats, for the paths that take one row at a time (made once)."""
        rows = self.__dict__.get("_rows_kept")
        if rows is None:
            rows = self.__dict__["_rows_kept"] = self._make_rows()
        return rows

    def _make_rows(self) -> list[_Row]:
        table = self._table
        # the radius squared by numpy scalars (libm pow), as the sorted path has always squared
        pow_squares = [float(r**2) for r in table[:, _RADIUS]]
        return [
            _Row(
                row[_SIGN],
                row[_RADIUS2],
                pow_square,
                row[_Q0],
                row[_T_VERTEX],
                row[_TWO_T_VERTEX],
                row[_X_HYP],
                row[_T_START],
                row[_T_STOP],
                row[_W_START],
                row[_X0_START],
                row[_W_STOP],
                row[_X0_STOP],
            )
            for row, pow_square in zip(table.tolist(), pow_squares, strict=True)
        ]

    # ---------------------------------------------------------------- sampling
    def positions(self, t: FloatArray, *, ordered: bool | None = None) -> FloatArray:
        """Frame x of every row at frame times ``t`` (1-D). Shape ``(rows, len(t))``.

        The path depends on the input, never the result (each is bitwise the form it stands
        for, see tests/test_sampling_paths.py):

        * a handful of samples (rows x times <= ``_SCALAR_MAX``): Python float arithmetic,
          one sample at a time;
        * fewer than ``PIECEWISE_MIN`` times, or fewer than ``_SHUFFLED_MIN`` unsorted ones: the
          branch-free form over all rows at once;
        * more, sorted: each row's pieces are runs of the times, each evaluated with its own
          formula (2 operations a sample on the inertial pieces, 9 on the hyperbola);
        * more, unsorted: blocks of times, in each only the pieces its times reach.

        ``ordered`` says whether ``t`` is non-decreasing when the caller already knows (the
        time check finds out on the way); ``None``: find out here.
        """
        n = t.size
        if self.rows * n <= _SCALAR_MAX:
            return self._positions_scalar(t)
        if n < PIECEWISE_MIN:
            return self._positions_block(t)
        if ordered is None:
            ordered = non_decreasing(t)
        if ordered:
            return self._positions_sorted(t)
        return self._positions_shuffled(t) if n >= _SHUFFLED_MIN else self._positions_block(t)

    def _positions_scalar(self, t: FloatArray) -> FloatArray:
        """The branch-free form's arithmetic one sample at a time, on the sample's own piece only.

        For a few samples this costs less than the form's 18 numpy calls. Each sample goes
        through the same IEEE operations in the same order as there (``math.sqrt`` and
        ``np.sqrt`` both round correctly), so the results are bitwise the same.
        """
        times = t.tolist()
        sqrt = math.sqrt
        out: list[float] = []
        for sign, r2, _, q0, tv, two_tv, x_hyp, t_start, t_stop, w_start, x0_start, w_stop, x0_stop in self._rows:
            out += [
                w_stop * x + x0_stop
                if x > t_stop
                else w_start * x + x0_start
                if x < t_start
                else (x - two_tv) * x / (sqrt((s := x - tv) * s + r2) + q0) * sign + x_hyp
                for x in times
            ]
        return np.array(out, dtype=np.float64).reshape(self.rows, len(times))

    def _positions_block(self, t: FloatArray) -> FloatArray:
        with np.errstate(over="ignore", invalid="ignore"):  # lanes that overflow are discarded by np.where
            return self._positions_block_unchecked(t)

    def _positions_block_unchecked(self, t: FloatArray) -> FloatArray:
        """Every piece at every time for all rows at once, then the piece each time is on.

        The constants and the times are first spread over ``(rows, times)`` in two copies: an
        operation between two arrays of one shape costs numpy about a third of one that broadcasts
        a ``(rows, 1)`` column against the times, and a few hundred samples cost little more than
        the call. The same operations on the same values: bitwise the broadcast form.
        """
        grid = np.empty((_BLOCK_COLUMNS.size + 1, self.rows, t.shape[0]))
        np.copyto(grid[:-1], self._table.T[_BLOCK_COLUMNS, :, None])
        tv, r2, q0, two_tv, sign, x_hyp, w_start, x0_start, w_stop, x0_stop, t_start, t_stop, tt = grid
        np.copyto(tt, t)
        # hyperbola, anchored at t' = 0
        np.subtract(tt, tv, tv)
        np.multiply(tv, tv, tv)
        np.add(tv, r2, tv)
        np.sqrt(tv, tv)
        np.add(tv, q0, tv)
        h = np.subtract(tt, two_tv)  # the result: not a view that would keep the grid alive
        np.multiply(h, tt, h)
        np.divide(h, tv, h)
        np.multiply(h, sign, h)
        np.add(h, x_hyp, h)
        # the inertial pieces, before the start and after the stop
        np.multiply(w_start, tt, w_start)
        np.add(w_start, x0_start, w_start)
        np.multiply(w_stop, tt, w_stop)
        np.add(w_stop, x0_stop, w_stop)
        np.copyto(h, w_start, where=np.less(tt, t_start))
        np.copyto(h, w_stop, where=np.greater(tt, t_stop))
        return h

    def _positions_sorted(self, t: FloatArray) -> FloatArray:
        """Sorted times: each row's pieces are runs of ``t`` (two binary searches), each evaluated
        with its own formula only, in blocks of ``_BLOCK`` so that the work stays in cache."""
        n = t.size
        out = np.empty((self.rows, n))
        i0 = np.searchsorted(t, self.t_start, side="left").tolist()
        i1 = np.searchsorted(t, self.t_stop, side="right").tolist()
        work = np.empty(min(n, _BLOCK))
        for row, a, b, x in zip(self._rows, i0, i1, out, strict=True):
            c = _RowArrays.of(row, row.radius2_pow if n >= _POW_SQUARE_MIN else row.radius2)
            for j in range(0, a, _BLOCK):
                k = min(j + _BLOCK, a)
                _line(t[j:k], c.w_start, c.x0_start, x[j:k])
            for j in range(a, b, _BLOCK):
                k = min(j + _BLOCK, b)
                _hyperbola(t[j:k], c, x[j:k], work[: k - j])
            for j in range(b, n, _BLOCK):
                k = min(j + _BLOCK, n)
                _line(t[j:k], c.w_stop, c.x0_stop, x[j:k])
        return out

    def _positions_shuffled(self, t: FloatArray) -> FloatArray:
        """Unsorted times, in blocks of ``_BLOCK``.

        A row whose block of times lies on one piece (the block's extremes tell) gets that
        piece's formula alone, as on the sorted path. For any other row two masks tell which
        times lie before its hyperbola and which after; the piece most of them lie on (the
        hyperbola counting half: it costs several lines a sample) is evaluated over the whole
        block, each other piece only at its own times, gathered and put back by index (a
        selection by mask branches on every sample, which shuffled times make unpredictable).
        A row whose start is after its stop takes the branch-free form's precedence instead:
        after the stop, else before the start, else curved.

        Sorting instead (argsort, the sorted path, a scatter back; bitwise the same results)
        took 0.9 to 1 times as long at 4096 times and 1.6 to 8 times as long from 16384 to 1e6
        (4 and 22 rows): numpy's float64 argsort is not vectorised, and the scatter of every
        row back costs about as much again.
        """
        n = t.size
        out = np.empty((self.rows, n))
        m = min(n, _BLOCK)
        before, after, curved = np.empty(m, dtype=bool), np.empty(m, dtype=bool), np.empty(m, dtype=bool)
        work, gathered, values = np.empty(m), np.empty(m), np.empty(m)
        consts = [(row, _RowArrays.of(row, row.radius2)) for row in self._rows]
        with np.errstate(over="ignore", invalid="ignore"):  # as on the branch-free form: overwritten lanes
            for j in range(0, n, _BLOCK):
                k = min(j + _BLOCK, n)
                w = k - j
                tc, wk, bm, am = t[j:k], work[:w], before[:w], after[:w]
                lo, hi = float(np.minimum.reduce(tc)), float(np.maximum.reduce(tc))
                for r, (row, c) in enumerate(consts):
                    x = out[r, j:k]
                    if lo > row.t_stop:
                        _piece(_AFTER, tc, c, x, wk)
                    elif row.t_start > row.t_stop:  # overlapping pieces: the branch-free form's precedence
                        _hyperbola(tc, c, x, wk)
                        np.putmask(x, np.less(tc, c.t_start, bm), _line(tc, c.w_start, c.x0_start, wk))
                        np.putmask(x, np.greater(tc, c.t_stop, am), _line(tc, c.w_stop, c.x0_stop, wk))
                    elif hi < row.t_start:
                        _piece(_BEFORE, tc, c, x, wk)
                    elif row.t_start <= lo and hi <= row.t_stop:
                        _piece(_CURVED, tc, c, x, wk)
                    else:
                        nb = np.count_nonzero(np.less(tc, c.t_start, bm))
                        na = np.count_nonzero(np.greater(tc, c.t_stop, am))
                        counts = (nb, w - nb - na, na)  # before, curved, after
                        # the hyperbola costs ~4 lines a sample: over the whole block only where it dominates
                        weighted = (nb, counts[_CURVED] // 2, na)
                        base = weighted.index(max(weighted))
                        _piece(base, tc, c, x, wk)  # over the whole block
                        for piece, count in enumerate(counts):
                            if count and piece != base:
                                if piece == _CURVED:
                                    mask = np.logical_not(np.logical_or(bm, am, curved[:w]), curved[:w])
                                else:
                                    mask = bm if piece == _BEFORE else am
                                idx = np.flatnonzero(mask)
                                tg = tc.take(idx, out=gathered[: idx.size], mode="clip")
                                x[idx] = _piece(piece, tg, c, values[: idx.size], wk[: idx.size])
        return out

    def equal_time_lengths(
        self, t: FloatArray, rest_lengths: FloatArray, rest_lengths_after: FloatArray | None = None
    ) -> FloatArray:
        """``x_right - x_left`` for rows given as (left, right) pairs, one pair per rod.

        While both ends coast on the same inertial piece the length is exactly
        ``L / cosh(theta')`` (Lorentz contraction); otherwise the difference of positions.
        ``rest_lengths_after``: each rod's rest length after its change, if not ``rest_lengths``.
        """
        x = self.positions(t)
        left, right = slice(0, None, 2), slice(1, None, 2)
        out = x[right] - x[left]
        before = (t < self.t_start[left, None]) & (t < self.t_start[right, None])
        after = (t > self.t_stop[left, None]) & (t > self.t_stop[right, None])
        contracted_before = (rest_lengths / np.cosh(self.rapidity_start[left]))[:, None]
        after_rest = rest_lengths if rest_lengths_after is None else rest_lengths_after
        contracted_after = (after_rest / np.cosh(self.rapidity_stop[left]))[:, None]
        out = np.where(before, contracted_before, out)
        return np.where(after, contracted_after, out)

    def velocities(self, t: FloatArray) -> FloatArray:
        """Frame velocity dx'/dt' of every row; right-continuous at a kink (rho = 0)."""
        s = t[None, :] - self.column("t_vertex")
        sc = np.clip(s, self.column("s_start"), self.column("s_stop"))
        q = np.hypot(self.column("radius"), sc)
        during = self.column("sign") * np.divide(sc, q, out=np.zeros_like(sc), where=q > 0.0)
        v = np.where(s < self.column("s_start"), self.column("w_start"), during)
        v = np.where(s >= self.column("s_stop"), self.column("w_stop"), v)
        # tanh and s/hypot(rho, s) round to exactly +-1 within half an ulp of light speed
        return np.clip(v, -BELOW_ONE, BELOW_ONE)

    def proper_times(self, t: FloatArray) -> FloatArray:
        """Proper time of every row at frame times ``t``, zero where the point starts changing velocity.

        Everything is formed from the frame time elapsed since a switch event, ``t' - t'_S`` (the
        switch events are exact to the lab's rounding, see :func:`plan_motions`), never from two
        large times subtracted. Inertial pieces: ``tau = (t' - t'_S)/cosh(theta'_i)`` before,
        ``tau = rho |theta_f - theta_i| + (t' - t'_T)/cosh(theta'_f)`` after. Hyperbola:
        ``tau = sign rho (asinh a - asinh b)`` with ``b = sinh(theta'_i)``,
        ``a - b = sign (t' - t'_S)/rho`` and ``a`` itself either ``b + (a - b)`` or
        ``sign (t' - t'_C)/rho`` (the one with smaller terms), the difference taken as
        ``asinh(sinh(asinh a - asinh b))``, ``sinh(A - B) = (a - b)(a + b)/(a sqrt(1+b^2) + b sqrt(1+a^2))``
        when ``a`` and ``b`` share a sign (``a sqrt(1+b^2) - b sqrt(1+a^2)`` otherwise): no cancellation
        however weak the acceleration (``rho`` large) or fast the frame.
        """
        with np.errstate(divide="ignore", invalid="ignore", over="ignore"):  # rows with rho = 0 are masked
            return self._proper_times(t)

    def _proper_times(self, t: FloatArray) -> FloatArray:
        t = t[None, :]
        t_start, t_stop = self.column("t_start"), self.column("t_stop")
        rho, sig, t_centre = self.column("radius"), self.column("sign"), self.column("t_vertex")
        since_start = t - t_start
        t_change = np.clip(t, t_start, t_stop)
        b = np.sinh(self.column("rapidity_start"))
        delta = sig * (t_change - t_start) / rho  # a - b
        # a = sinh(theta'(t')) from the start (b + delta) or from the centre (sign (t' - t'_C)/rho),
        # whichever has the smaller terms
        from_start, from_centre = b + delta, sig * (t_change - t_centre) / rho
        a = np.where(
            np.maximum(np.abs(b), np.abs(delta)) * rho <= np.maximum(np.abs(t_change), np.abs(t_centre)),
            from_start,
            from_centre,
        )
        root_a, root_b = np.sqrt(1.0 + a * a), np.sqrt(1.0 + b * b)
        same_sign = a * b > 0.0
        sinh_turn = np.where(same_sign, delta * (a + b) / (a * root_b + b * root_a), a * root_b - b * root_a)
        during = np.where(rho > 0.0, sig * rho * np.arcsinh(sinh_turn), 0.0)
        before = since_start / np.cosh(self.column("rapidity_start"))
        after = self.column("proper_time_change") + (t - t_stop) / np.cosh(self.column("rapidity_stop"))
        tau = np.where(since_start < 0.0, before, during)
        return np.where(t > t_stop, after, tau)

    def switch_events(self) -> tuple[FloatArray, FloatArray]:
        """Frame events ``(t', x')`` where each row starts and stops changing velocity; each ``(rows, 2)``
        (formed in light-cone coordinates, see :func:`plan_motions`)."""
        return np.stack([self.t_start, self.x_start], axis=-1), np.stack([self.t_stop, self.x_stop], axis=-1)


#: MotionPlan's fields in declaration order (the columns ``plan_motions`` fills).
_PLAN_FIELDS = tuple(name for name in MotionPlan.__dataclass_fields__ if name != "_table")
#: The plan's fields in the order of its table's columns.
PLAN_FIELDS = _PLAN_FIELDS
_FIELD_INDEX = {name: i for i, name in enumerate(_PLAN_FIELDS)}
_SIGN, _RADIUS, _RADIUS2, _Q0, _T_VERTEX, _TWO_T_VERTEX, _X_HYP, _T_START, _T_STOP = (
    _PLAN_FIELDS.index(name)
    for name in ("sign", "radius", "radius2", "q0", "t_vertex", "two_t_vertex", "x_hyp", "t_start", "t_stop")
)
_W_START, _W_STOP, _X0_START, _X0_STOP = (_PLAN_FIELDS.index(n) for n in ("w_start", "w_stop", "x0_start", "x0_stop"))
#: The branch-free form's constants, in the order its arithmetic takes them (columns of the table).
_BLOCK_COLUMNS = np.array(
    [_T_VERTEX, _RADIUS2, _Q0, _TWO_T_VERTEX, _SIGN, _X_HYP, _W_START, _X0_START, _W_STOP, _X0_STOP, _T_START, _T_STOP]
)
