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

from ._exact import BELOW_ONE, ExactVelocity, relative_rapidity
from ._frame import Frame

FloatArray = npt.NDArray[np.float64]

#: Columns per block on the branch-free path: keeps the work arrays in cache.
_CHUNK = 8192
#: From this many sorted times on, rows are sampled piece by piece.
_PIECEWISE_MIN = 2048
#: Stand-in for a zero radius in a denominator that is then multiplied by zero.
_TINY = 1e-300


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

    def lab_rows(self, fractions: FloatArray) -> tuple[LabRow, ...]:
        """The frame-independent constants of material points ``fractions`` (see :func:`lab_row`),
        worked out once per set of fractions."""
        key = fractions.tobytes()
        rows = self._lab_rows.get(key)
        if rows is None:
            if len(self._lab_rows) >= _MAX_CACHED_FRACTIONS:
                self._lab_rows.clear()
            sums = [
                _two_anchor_sums(v, sign)
                for v in (self.velocity_initial, self.velocity_final)
                for sign in (0.0, -1.0, 1.0)
            ]
            rows = tuple(lab_row(self, f, sums) for f in fractions.tolist())
            self._lab_rows[key] = rows
        return rows


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


def lab_row(m: RigidMotion, f: float, sums: Sequence[_AnchorSum]) -> LabRow:
    """The lab constants of fraction ``f`` (``sums``: :func:`_two_anchor_sums` of the motion's
    ``1/gamma`` and ``exp(-+theta)`` before and after), each to double-double.

    Each is ``x_C + sign rho F`` (from the centre) or ``x_V + sign rho (F - 1)`` (from the vertex),
    whichever has the smaller terms, with ``F`` to double-double from the velocity's exact parts
    (:func:`_factor_dd`): an exact product and an exact sum, so that a switch event on (or a hair
    off) the origin's light cone, or a tangent through the origin, keeps its coordinate to ~1e-32
    of the scene's size, and a boost of any ``gamma`` multiplies an exact number.
    """
    sig, xc = float(m.sign), m.horizon_x
    # the point's rest-distance from the centre and its vertex, to double-double: the ends are
    # exactly L0 apart (rho_right - rho_left = L0), which float radii rounded apart would not be
    if f == 0.0:
        along, along_lo = 0.0, 0.0
    elif f == 1.0:
        along, along_lo = m.length, 0.0
    else:
        along, along_lo = _two_prod(f, m.length)
    rho, rho_lo = _two_sum(m.radius_left, sig * along)
    rho_lo += sig * along_lo
    x_lab, x_lo = _two_sum(m.vertex_left, along)
    x_lo += along_lo
    if rho < 0.0:  # a point beyond the centre cannot be (radii are >= 0); only rounding gets here
        rho, rho_lo = 0.0, 0.0
    srho, srho_lo, axc, ax = sig * rho, sig * rho_lo, abs(xc), abs(x_lab)
    highs, lows = [], []
    for f_hi, f_lo, g_hi, g_lo, abs_f, abs_g in sums:
        if axc + rho * abs_f <= ax + rho * abs_g:
            anchor, anchor_lo, hi, lo = xc, 0.0, f_hi, f_lo
        else:
            anchor, anchor_lo, hi, lo = x_lab, x_lo, g_hi, g_lo
        p, pe = _two_prod(srho, hi)
        s, se = _two_sum(anchor, p)
        s, e = _two_sum(s, se + (pe + (srho * lo + srho_lo * hi) + anchor_lo))
        highs.append(s)
        lows.append(e)
    return LabRow(rho, x_lab, *highs, low=tuple(lows))  # type: ignore[arg-type]


_SPLITTER = 134217729.0  # 2^27 + 1 (Veltkamp)


def _two_sum(a: float, b: float) -> tuple[float, float]:
    """``a + b`` as ``(s, e)`` with ``s + e`` exact (Knuth)."""
    s = a + b
    bb = s - a
    return s, (a - (s - bb)) + (b - bb)


def _two_prod(a: float, b: float) -> tuple[float, float]:
    """``a * b`` as ``(p, e)`` with ``p + e`` exact (Dekker; no fma in Python 3.11)."""
    p = a * b
    c = _SPLITTER * a
    ah = c - (c - a)
    al = a - ah
    c = _SPLITTER * b
    bh = c - (c - b)
    bl = b - bh
    return p, ((ah * bh - p) + ah * bl + al * bh) + al * bl


def _one_plus_dd(sign: float, v: ExactVelocity) -> tuple[float, float]:
    """``1 + sign v`` to double-double from the velocity's parts."""
    s, e = _two_sum(1.0, sign * v.hi)
    return _two_sum(s, e + sign * v.lo)


def _sqrt_dd(q1: float, q2: float) -> tuple[float, float]:
    """``sqrt(q1 + q2)`` to double-double (one Newton step from the float root)."""
    r = math.sqrt(q1)
    p, pe = _two_prod(r, r)
    return _two_sum(r, (((q1 - p) - pe) + q2) / (2.0 * r))


def _factor_dd(v: ExactVelocity, sign: float) -> tuple[float, float]:
    """To double-double: ``1/gamma = sqrt((1 - v)(1 + v))`` for ``sign = 0``, else
    ``exp(sign theta) = sqrt((1 + sign v)/(1 - sign v))`` (``theta = atanh v``)."""
    if sign == 0.0:
        a1, a2 = _one_plus_dd(1.0, v)
        b1, b2 = _one_plus_dd(-1.0, v)
        p, pe = _two_prod(a1, b1)
        return _sqrt_dd(*_two_sum(p, pe + a1 * b2 + a2 * b1))
    a1, a2 = _one_plus_dd(sign, v)
    b1, b2 = _one_plus_dd(-sign, v)
    q1 = a1 / b1
    p, pe = _two_prod(q1, b1)
    return _sqrt_dd(*_two_sum(q1, (((a1 - p) - pe) + a2 - q1 * b2) / b1))


_AnchorSum = tuple[float, float, float, float, float, float]


def _two_anchor_sums(v: ExactVelocity, sign: float) -> _AnchorSum:
    """``(F, F - 1)`` to double-double for the factor ``F`` of :func:`_factor_dd`, and their float
    magnitudes: ``F_hi, F_lo, (F-1)_hi, (F-1)_lo, |F|, |F - 1|``.

    A row's tangent intercept and switch-event light-cone coordinates are ``x_C + sign rho F`` (from
    the centre) or ``x_V + sign rho (F - 1)`` (from the vertex).
    """
    f_hi, f_lo = _factor_dd(v, sign)
    g_hi, g_lo = _two_sum(f_hi, -1.0)
    g_hi, g_lo = _two_sum(g_hi, g_lo + f_lo)
    return f_hi, f_lo, g_hi, g_lo, abs(f_hi), abs(g_hi)


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
        # proper time the change takes per unit rest-distance: the lab rapidity change (invariant)
        turn = abs(relative_rapidity(m.velocity_final, m.velocity_initial))
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
    return MotionPlan(**dict(zip(_PLAN_FIELDS, table, strict=True)))


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
    def _columns(self) -> dict[str, FloatArray]:
        names = ("sign", "t_vertex", "q0", "x_hyp", "t_start", "t_stop", "x0_start", "w_start", "x0_stop", "w_stop")
        c = {k: self.column(k) for k in names}
        c["radius2"] = self.column("radius") ** 2
        c["two_t_vertex"] = 2.0 * c["t_vertex"]
        return c

    # ---------------------------------------------------------------- sampling
    def positions(self, t: FloatArray) -> FloatArray:
        """Frame x of every row at frame times ``t`` (1-D). Shape ``(rows, len(t))``.

        Sorted long inputs take a piecewise path (2 flops a sample on the inertial pieces,
        10 on the hyperbola); others a branch-free form over all rows at once.
        """
        n = t.size
        if n >= _PIECEWISE_MIN and bool(np.all(t[1:] >= t[:-1])):
            return self._positions_sorted(t)
        if n <= _CHUNK:
            return self._positions_block(t)
        out = np.empty((self.radius.size, n))
        for j in range(0, n, _CHUNK):
            tc = t[j : j + _CHUNK]
            out[:, j : j + tc.size] = self._positions_block(tc)
        return out

    def _positions_block(self, t: FloatArray) -> FloatArray:
        with np.errstate(over="ignore", invalid="ignore"):  # lanes that overflow are discarded by np.where
            return self._positions_block_unchecked(t)

    def _positions_block_unchecked(self, t: FloatArray) -> FloatArray:
        c = self._columns
        # hyperbola, anchored at t' = 0
        s = t - c["t_vertex"]
        s *= s
        s += c["radius2"]
        np.sqrt(s, out=s)
        s += c["q0"]
        h = t - c["two_t_vertex"]
        h *= t
        h /= s
        h *= c["sign"]
        h += c["x_hyp"]
        # inertial pieces
        before = c["w_start"] * t
        before += c["x0_start"]
        after = c["w_stop"] * t
        after += c["x0_stop"]
        h = np.where(t < c["t_start"], before, h)
        return np.where(t > c["t_stop"], after, h)

    def _positions_sorted(self, t: FloatArray) -> FloatArray:
        rows = self.radius.size
        out = np.empty((rows, t.size))
        i0 = np.searchsorted(t, self.t_start, side="left")
        i1 = np.searchsorted(t, self.t_stop, side="right")
        for r in range(rows):
            a, b = int(i0[r]), int(i1[r])
            row = out[r]
            if a > 0:
                np.multiply(t[:a], self.w_start[r], out=row[:a])
                row[:a] += self.x0_start[r]
            if b > a:
                seg = row[a:b]
                ts = t[a:b]
                np.subtract(ts, self.t_vertex[r], out=seg)
                seg *= seg
                seg += self.radius[r] ** 2
                np.sqrt(seg, out=seg)
                seg += self.q0[r]
                num = ts - 2.0 * self.t_vertex[r]
                num *= ts
                np.divide(num, seg, out=seg)
                seg *= self.sign[r]
                seg += self.x_hyp[r]
            if b < t.size:
                np.multiply(t[b:], self.w_stop[r], out=row[b:])
                row[b:] += self.x0_stop[r]
        return out

    def equal_time_lengths(self, t: FloatArray, rest_lengths: FloatArray) -> FloatArray:
        """``x_right - x_left`` for rows given as (left, right) pairs, one pair per rod.

        While both ends coast on the same inertial piece the length is exactly
        ``L / cosh(theta')`` (Lorentz contraction); otherwise the difference of positions.
        """
        x = self.positions(t)
        left, right = slice(0, None, 2), slice(1, None, 2)
        out = x[right] - x[left]
        before = (t < self.t_start[left, None]) & (t < self.t_start[right, None])
        after = (t > self.t_stop[left, None]) & (t > self.t_stop[right, None])
        contracted_before = (rest_lengths / np.cosh(self.rapidity_start[left]))[:, None]
        contracted_after = (rest_lengths / np.cosh(self.rapidity_stop[left]))[:, None]
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
