r"""A signal-limited (plastic) stop: not Born-rigid, each material point stops when a front reaches it.

The pole-in-the-barn's second model of "rigid" (units c = 1). A rod of rest length ``L0`` moves
with velocity ``-V`` (``gamma = 1/sqrt(1 - V^2)``); its left end meets a wall at the origin. A stop
front leaves the contact at ``sound_speed`` ``c_s`` (``<= 1``, in the wall's frame, the lab) into
the rod: ``x = c_s t``. Material point ``f`` (fraction of the rest length from the left end) moves
on ``x = f L0 / gamma - V t`` until the front meets it, at

.. math::
    t_f = \frac{f L_0}{\gamma (c_s + V)}, \qquad x_f = c_s t_f,

and rests at ``x_f`` from then on: one kink per point, its worldline two straight lines. The rod
ends at rest with rest length ``L1 = c_s L0 / (gamma (c_s + V))`` (``sqrt((1 - V)/(1 + V)) L0`` at
``c_s = 1``). Nothing here is rigid: no point moves before the front (a signal from the contact)
reaches it.

Each kink is an event, exact in the lab to double-double: ``t_f`` from ``1/gamma =
sqrt((1 - V)(1 + V))`` (the velocity's own ``1 -+ V``), its light-cone coordinates ``t - x = t_f
(1 - c_s)`` and ``t + x = t_f (1 + c_s)``, products. A frame gets them as every motion's switch
events do, ``u' = e^psi u``, ``w' = e^-psi w`` (:func:`rigidrel_core._motion.plan_motions`), so the
same :class:`~rigidrel_core._motion.MotionPlan` samples them: a kink is a row of radius 0 whose
"hyperbola" is its one event (sign 0, ``x_hyp`` the kink's ``x'``).
"""

from __future__ import annotations

import functools
import math
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import ClassVar, Literal

import numpy as np
import numpy.typing as npt

from . import _dd as dd
from ._dd import DD, two_sum
from ._exact import REST, ExactVelocity, one_minus_dd, one_plus_dd, relative_rapidity
from ._frame import Frame
from ._motion import PLAN_FIELDS, LabRow, MotionPlan, RigidMotion, plan_from_table, plan_motions

FloatArray = npt.NDArray[np.float64]


@dataclass(frozen=True)
class PlasticMotion:
    """A rod at velocity ``-V`` stopped point by point by a front leaving the origin at ``sound_speed``
    (module docstring). The attributes a scene reads of every motion are those of a rigid one with
    its centre at the origin and every radius 0."""

    born_rigid: ClassVar[bool] = False
    """Not Born-rigid: no point moves before the stop front reaches it."""
    length: float
    """Rest length ``L0`` before the stop."""
    speed: float
    """``V`` (> 0): the rod moves toward -x."""
    sound_speed: float
    """``c_s`` in (0, 1], in the lab (the wall's frame)."""
    velocity_initial: ExactVelocity
    velocity_final: ExactVelocity = REST
    sign: Literal[1, -1] = 1
    horizon_x: float = 0.0
    radius_left: float = 0.0
    radius_right: float = 0.0
    vertex_left: float = 0.0
    _lab_rows: dict[bytes, tuple[LabRow, ...]] = field(
        default_factory=dict[bytes, "tuple[LabRow, ...]"], init=False, repr=False, compare=False
    )

    @classmethod
    def stop_at_wall(cls, speed: float, length: float, sound_speed: float) -> PlasticMotion:
        return cls(length, speed, sound_speed, ExactVelocity.from_float(-speed))

    @functools.cached_property
    def _per_fraction(self) -> tuple[DD, DD, DD, DD]:
        """Double-doubles: ``L0 / gamma`` (the before line's intercept per unit ``f``), ``t_1`` (the
        kink time per unit ``f``), ``1 - c_s`` and ``1 + c_s``."""
        v = ExactVelocity.from_float(self.speed)
        inv_gamma = dd.sqrt(dd.mul(one_plus_dd(v), one_minus_dd(v)))
        contracted = dd.mul_float(inv_gamma, self.length)
        t_one = dd.div(contracted, two_sum(self.sound_speed, self.speed))
        return contracted, t_one, two_sum(1.0, -self.sound_speed), two_sum(1.0, self.sound_speed)

    @functools.cached_property
    def length_final(self) -> float:
        """Rest length after the stop: ``L1 = c_s L0 / (gamma (c_s + V))``."""
        _, t_one, _, _ = self._per_fraction
        return dd.mul_float(t_one, self.sound_speed)[0]

    @functools.cached_property
    def rapidity_change(self) -> float:
        """``atanh V``: the rapidity each point loses at its kink."""
        return abs(relative_rapidity(self.velocity_final, self.velocity_initial))

    def radius(self, fraction: float) -> float:
        """0: every point stops at once (a kink)."""
        return 0.0

    def kink(self, fraction: float) -> tuple[float, float]:
        """Lab ``(t_f, x_f)`` where the stop front meets material point ``fraction``."""
        row = self.lab_rows(np.array([fraction]), exact=True)[0]
        t = 0.5 * ((row.w_start - row.minus_u_start) + (row.low[2] - row.low[1]))
        return (t, row.x_vertex)

    def lab_rows(self, fractions: FloatArray, *, exact: bool = False) -> tuple[LabRow, ...]:
        """Each point's lab constants in :class:`~rigidrel_core._motion.LabRow` form (radius 0; vertex,
        final intercept and both switch events at its kink), always with their low parts."""
        key = fractions.tobytes()
        rows = self._lab_rows.get(key)
        if rows is None:
            rows = tuple(self._row(f) for f in fractions.tolist())
            if len(self._lab_rows) >= 16:
                self._lab_rows.clear()
            self._lab_rows[key] = rows
        return rows

    def _row(self, f: float) -> LabRow:
        contracted, t_one, one_minus_c, one_plus_c = self._per_fraction
        if f == 1.0:
            a_i, t_f = contracted, t_one
        else:
            a_i, t_f = dd.mul_float(contracted, f), dd.mul_float(t_one, f)
        x_f = dd.mul_float(t_f, self.sound_speed)
        u = dd.mul(t_f, one_minus_c)  # t - x
        w = dd.mul(t_f, one_plus_c)  # t + x
        return LabRow(0.0, x_f[0], a_i[0], -u[0], w[0], x_f[0], -u[0], w[0], (a_i[1], -u[1], w[1], x_f[1], -u[1], w[1]))

    def plan(self, frame: Frame, fractions: FloatArray) -> MotionPlan:
        """Frame constants of points ``fractions``: the kink ``(t', x')`` from ``u' = e^psi u``,
        ``w' = e^-psi w``; the lines ``x' = X'_0 + tanh(theta') t'`` with ``X'_0 = a cosh(theta) /
        cosh(theta')`` (``a`` the lab intercept at ``t = 0``: ``f L0 / gamma`` before, ``x_f`` after)."""
        up, down = frame.doppler_factors()
        th_i = relative_rapidity(self.velocity_initial, frame.velocity)
        th_f = relative_rapidity(self.velocity_final, frame.velocity)
        c_i = self.velocity_initial.lorentz_factor() / math.cosh(th_i)
        c_f = 1.0 / math.cosh(th_f)
        w_i, w_f = math.tanh(th_i), math.tanh(th_f)
        rows: list[list[float]] = []
        for row in self.lab_rows(fractions):
            u, w = -row.minus_u_start * up, row.w_start * down
            t_k, x_k = 0.5 * (u + w), 0.5 * (w - u)
            values = {
                "sign": 0.0,
                "radius": 0.0,
                "t_vertex": t_k,
                "q0": 1.0,
                "x_hyp": x_k,
                "s_start": 0.0,
                "s_stop": 0.0,
                "t_start": t_k,
                "t_stop": t_k,
                "x_start": x_k,
                "x_stop": x_k,
                "x0_start": row.intercept_initial * c_i,
                "w_start": w_i,
                "x0_stop": row.intercept_final * c_f,
                "w_stop": w_f,
                "rapidity_start": th_i,
                "rapidity_stop": th_f,
                "proper_time_change": 0.0,
                "radius2": 0.0,
                "two_t_vertex": 2.0 * t_k,
            }
            rows.append([values[name] for name in PLAN_FIELDS])
        return plan_from_table(np.array(rows, dtype=np.float64).reshape(-1, len(PLAN_FIELDS)))


#: Any rod's motion: Born-rigid, or stopped point by point.
Motion = RigidMotion | PlasticMotion


def plan_rods(motions: Sequence[Motion], frame: Frame, fractions: FloatArray) -> MotionPlan:
    """:func:`~rigidrel_core._motion.plan_motions` for rods of either kind (rows rod-major); scenes of
    Born-rigid rods alone take it directly."""
    rigid = [m for m in motions if isinstance(m, RigidMotion)]
    if len(rigid) == len(motions):
        return plan_motions(rigid, frame, fractions)
    parts = [
        plan_motions([m], frame, fractions) if isinstance(m, RigidMotion) else m.plan(frame, fractions) for m in motions
    ]
    return plan_from_table(np.concatenate([p.table for p in parts]))
