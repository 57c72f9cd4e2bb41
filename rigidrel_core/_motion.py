r"""Born-rigid motion of one rod whose velocity changes once, evaluated in any frame.

Every scene of Franklin (2012) is built from one motion per rod (units c = 1):

1. inertial at velocity ``v_i`` (rapidity ``theta_i``);
2. a Born-rigid change: each material point moves on a hyperbola about one common
   centre event ``C`` (the Rindler horizon), the point at rest-distance ``rho`` from it
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
from typing import Literal, NamedTuple

import numpy as np
import numpy.typing as npt

from . import _dd as dd
from ._dd import DD, two_prod, two_sum
from ._exact import BELOW_ONE, ExactVelocity, one_minus_dd, one_plus_dd, relative_rapidity
from ._frame import Frame
from ._validate import non_decreasing

FloatArray = npt.NDArray[np.float64]

#: From this many sorted times on, rows are sampled piece by piece (measured crossover with the
#: branch-free form: 1024 to 2048 times for 4 or 22 rows).
PIECEWISE_MIN = 2048
#: From this many unsorted times on, rows are sampled by blocks (measured crossover: 2048 to 4096).
_SHUFFLED_MIN = 4096
#: Times per block on the piecewise paths: a block's work arrays (256 KiB each) stay in the
#: caches, and numpy's cost per call (0.5 to 2 us on a shared 2-core machine) is spread over
#: enough samples: on such a machine 4096 was 1.3 times slower than 32768 on sorted curved
#: pieces, 65536 a few percent faster.
_BLOCK = 32768
#: Up to this many samples (rows x times) are computed in Python floats, one at a time.
_SCALAR_MAX = 32
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


@dataclass(frozen=True)
class RigidMotion:
    """One rod: inertial, one Born-rigid velocity change, inertial (lab description).

    The change's centre event is at lab ``(t, x) = (0, horizon_x)``. The hyperbola of the
    left end passes through rest at lab ``(0, vertex_left)``: at lab time 0 the whole
    (extended) family has the rod at rest on ``[vertex_left, vertex_left + length]``.
    """

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
            sums = [
                _two_anchor_sums(v, sign)
                for v in (self.velocity_initial, self.velocity_final)
                for sign in (0.0, -1.0, 1.0)
            ]
            rows = tuple(lab_row(self, f, sums, exact) for f in fractions.tolist())
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
    """The lab constants of fraction ``f`` (``sums``: :func:`_two_anchor_sums` of the motion's
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
    rho, rho_lo = two_sum(m.radius_left, sig * along)
    rho_lo += sig * along_lo
    x_lab, x_lo = two_sum(m.vertex_left, along)
    x_lo += along_lo
    if rho < 0.0:  # a point beyond the centre cannot be (radii are >= 0); only rounding gets here
        rho, rho_lo = 0.0, 0.0
    srho, srho_lo, axc, ax = sig * rho, sig * rho_lo, abs(xc), abs(x_lab)
    highs, lows = [], []
    for f_float, f1_float, abs_f, abs_f1, v, sign in sums:
        by_centre, by_vertex = axc + rho * abs_f, ax + rho * abs_f1
        from_centre = by_centre <= by_vertex
        if not exact:
            total = xc + srho * f_float if from_centre else x_lab + srho * f1_float
            if abs(total) * _CANCELLATION >= (by_centre if from_centre else by_vertex):
                highs.append(total)
                lows.append(0.0)
                continue
        anchor = (xc, 0.0) if from_centre else (x_lab, x_lo)
        hi, lo = _anchored_dd(anchor, (srho, srho_lo), v, sign, not from_centre)
        highs.append(hi)
        lows.append(lo)
    return LabRow(rho, x_lab, *highs, low=tuple(lows))  # type: ignore[arg-type]


def _factor_dd(v: ExactVelocity, sign: float) -> DD:
    """To double-double: ``1/gamma = sqrt((1 - v)(1 + v))`` for ``sign = 0``, else
    ``exp(sign theta) = sqrt((1 + sign v)/(1 - sign v))`` (``theta = atanh v``)."""
    plus, minus = one_plus_dd(v), one_minus_dd(v)
    if sign == 0.0:
        return dd.sqrt(dd.mul(plus, minus))
    return dd.sqrt(dd.div(plus, minus) if sign > 0.0 else dd.div(minus, plus))


_AnchorSum = tuple[float, float, float, float, ExactVelocity, float]


def _two_anchor_sums(v: ExactVelocity, sign: float) -> _AnchorSum:
    """``(F, F - 1, |F|, |F - 1|, v, sign)`` in float64 for the factor ``F`` of :func:`_factor_dd`.

    A row's tangent intercept and switch-event light-cone coordinates are ``x_C + sign rho F`` (from
    the centre) or ``x_V + sign rho (F - 1)`` (from the vertex); ``F - 1`` is
    ``-(gamma v)^2/((gamma + 1) gamma)`` for ``1/gamma`` and ``expm1(sign theta)`` for
    ``exp(sign theta)``, without cancellation.
    """
    if sign == 0.0:
        g, u = v.lorentz_factor(), v.proper_velocity()
        f, f1 = 1.0 / g, -u * u / ((g + 1.0) * g)
    else:
        theta = sign * v.rapidity()
        f, f1 = math.exp(theta), math.expm1(theta)
    return f, f1, abs(f), abs(f1), v, sign


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
    sh = frame.proper_velocity
    chm1 = frame.lorentz_factor_minus_one()
    ch = 1.0 + chm1
    up, down = frame.doppler_factors()  # exp(psi), exp(-psi)
    rows: list[tuple[float, ...]] = []
    # Plans have few rows (2 per rod for the ends, 11 for the ticks): float arithmetic on
    # Python floats is many times cheaper here than numpy calls on tiny arrays.
    for m in motions:
        th_i = relative_rapidity(m.velocity_initial, frame.velocity)
        th_f = relative_rapidity(m.velocity_final, frame.velocity)
        sig, xc = float(m.sign), m.horizon_x
        sinh_i, sinh_f = math.sinh(th_i), math.sinh(th_f)
        w_i, w_f = math.tanh(th_i), math.tanh(th_f)
        t_c = -xc * sh
        x_c = xc * ch
        same_side = sig * x_c >= 0.0  # the direct sum x'_C + sign q_0 does not cancel
        c_i = m.velocity_initial.lorentz_factor() / math.cosh(th_i)
        c_f = m.velocity_final.lorentz_factor() / math.cosh(th_f)
        turn = m.rapidity_change  # the proper time the change takes per unit rest-distance
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
                )
            )
    table = np.array(rows, dtype=np.float64).reshape(-1, len(_PLAN_FIELDS)).T
    # a frozen dataclass's __init__ sets each of its fields through object.__setattr__: filling
    # the instance dict at once is a third of the plan's cost cheaper, and the same object
    plan = object.__new__(MotionPlan)
    plan.__dict__.update(zip(_PLAN_FIELDS, table, strict=True))
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

    def column(self, name: str) -> FloatArray:
        return getattr(self, name)[:, None]

    @functools.cached_property
    def _columns(self) -> tuple[FloatArray, ...]:
        """The branch-free form's constants as ``(rows, 1)`` columns: sign, radius squared (an
        array multiply), q0, t_vertex, 2 t_vertex, x_hyp, t_start, t_stop; then the two lines'
        slopes and intercepts as ``(2, rows, 1)`` (before the start, after the stop)."""
        tv = self.t_vertex[:, None]
        return (
            self.sign[:, None],
            self.radius[:, None] ** 2,
            self.q0[:, None],
            tv,
            2.0 * tv,
            self.x_hyp[:, None],
            self.t_start[:, None],
            self.t_stop[:, None],
            np.array([self.w_start, self.w_stop])[:, :, None],
            np.array([self.x0_start, self.x0_stop])[:, :, None],
        )

    @functools.cached_property
    def _rows(self) -> list[_Row]:
        """Each row's constants as Python floats, for the paths that take one row at a time."""
        return [
            _Row(sign, rho * rho, float(pow_rho), q0, tv, 2.0 * tv, *rest)
            for sign, rho, pow_rho, q0, tv, *rest in zip(
                self.sign.tolist(),
                self.radius.tolist(),
                [r**2 for r in self.radius],  # numpy scalars: libm pow, as the sorted path has always squared
                self.q0.tolist(),
                self.t_vertex.tolist(),
                self.x_hyp.tolist(),
                self.t_start.tolist(),
                self.t_stop.tolist(),
                self.w_start.tolist(),
                self.x0_start.tolist(),
                self.w_stop.tolist(),
                self.x0_stop.tolist(),
                strict=True,
            )
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
        if self.radius.size * n <= _SCALAR_MAX:
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
        out: list[float] = []
        for sign, r2, _, q0, tv, two_tv, x_hyp, t_start, t_stop, w_start, x0_start, w_stop, x0_stop in self._rows:
            for x in times:
                if x > t_stop:
                    out.append(w_stop * x + x0_stop)
                elif x < t_start:
                    out.append(w_start * x + x0_start)
                else:
                    s = x - tv
                    out.append((x - two_tv) * x / (math.sqrt(s * s + r2) + q0) * sign + x_hyp)
        return np.array(out, dtype=np.float64).reshape(self.radius.size, len(times))

    def _positions_block(self, t: FloatArray) -> FloatArray:
        with np.errstate(over="ignore", invalid="ignore"):  # lanes that overflow are discarded by np.where
            return self._positions_block_unchecked(t)

    def _positions_block_unchecked(self, t: FloatArray) -> FloatArray:
        """Every piece at every time for all rows at once, then the piece each time is on."""
        sign, r2, q0, tv, two_tv, x_hyp, t_start, t_stop, slopes, intercepts = self._columns
        # hyperbola, anchored at t' = 0
        s = np.subtract(t, tv)
        np.multiply(s, s, s)
        np.add(s, r2, s)
        np.sqrt(s, s)
        np.add(s, q0, s)
        h = np.subtract(t, two_tv)
        np.multiply(h, t, h)
        np.divide(h, s, h)
        np.multiply(h, sign, h)
        np.add(h, x_hyp, h)
        # inertial pieces, both at once: (before, after)
        lines = np.multiply(slopes, t)
        np.add(lines, intercepts, lines)
        h = np.where(t < t_start, lines[0], h)
        return np.where(t > t_stop, lines[1], h)

    def _positions_sorted(self, t: FloatArray) -> FloatArray:
        """Sorted times: each row's pieces are runs of ``t`` (two binary searches), each evaluated
        with its own formula only, in blocks of ``_BLOCK`` so that the work stays in cache."""
        n = t.size
        out = np.empty((self.radius.size, n))
        i0 = np.searchsorted(t, self.t_start, side="left").tolist()
        i1 = np.searchsorted(t, self.t_stop, side="right").tolist()
        work = np.empty(min(n, _BLOCK))
        for row, a, b, x in zip(self._rows, i0, i1, out, strict=True):
            c = _RowArrays.of(row, row.radius2_pow)
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
        out = np.empty((self.radius.size, n))
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
_PLAN_FIELDS = tuple(MotionPlan.__dataclass_fields__)
