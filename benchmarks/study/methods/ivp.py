"""Method 3: numerical integration of the equations of motion with scipy's ``solve_ivp``.

What a user without closed forms would write (c = 1):

1. For each accelerated end, integrate the lab equations of motion of a point with
   constant proper acceleration ``a'`` (paper Sec. 3, before Eq. (2): ``a' = gamma^3 dv/dt``)::

       dx/dt = v,    dv/dt = side * a' * (1 - v^2)^(3/2)

   from its start event (``t_start, x_start``, velocity ``v_before``) with ``rtol`` and
   ``atol = (rtol * L, rtol)`` (``L`` the rod's rest length: the default ``atol = 1e-6``
   would be the whole rod for a rod of length 1e-6), dense output on, and a terminal event
   when ``v`` reaches the final velocity. ``1 - v^2`` is clipped at 0 so that a stage
   overshooting light speed gives ``dv/dt = 0`` instead of NaN. The start events, proper
   accelerations and final velocities are the paper's, in float64 (:mod:`benchmarks.study.paper`):
   the integrator replaces only the closed-form worldlines. Kicked ends jump and need no
   integration. Before the start and after the event the end coasts (straight lines).
2. Slice at frame times ``t'``: on the straight lines invert ``t' = gamma (t - beta x)`` in
   closed form; on the integrated piece, start from linear interpolation of the inverse map
   over the solver's own steps and polish with Newton's method on the dense output,
   ``t <- t - (gamma (t - beta x(t)) - t') / (gamma (1 - beta v(t)))``.
3. Boost: ``x' = gamma (x(t) - beta t)``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, Literal

import numpy as np
from scipy.integrate import solve_ivp

from ..paper import PaperEnd, inertial_slice, paper_ends, textbook_gamma
from ..scenes import BenchScene
from . import FloatArray

IvpMethod = Literal["RK45", "DOP853"]
#: Newton iterations at most when slicing the dense output at frame times.
NEWTON_STEPS = 8


class IntegrationFailed(RuntimeError):
    """solve_ivp stopped without reaching the final velocity."""


class _ReachesFinalVelocity:
    """Terminal event ``v - v_final = 0`` (solve_ivp reads ``terminal`` and ``direction``)."""

    terminal = True

    def __init__(self, v_final: float, side: float) -> None:
        self.v_final = v_final
        self.direction = side

    def __call__(self, t: float, y: FloatArray) -> float:
        return float(y[1] - self.v_final)


@dataclass(frozen=True)
class IntegratedEnd:
    """One end: the paper's straight pieces joined by an integrated accelerated piece."""

    end: PaperEnd
    t_stop: float
    """Lab time at which the integration reached the final velocity."""
    x_stop: float
    solution: Any
    """scipy's ``OdeSolution`` (dense output), or None for a kicked end."""
    step_times: FloatArray


def integrate(end: PaperEnd, method: IvpMethod, rtol: float, length: float) -> IntegratedEnd:
    """Step 1 of the module docstring for one end."""
    if end.form == "kick":
        return IntegratedEnd(end, end.t_stop, end.x_stop, None, np.array([end.t_start]))
    a, side = end.accel, end.side

    def rhs(t: float, y: FloatArray) -> FloatArray:
        v = y[1]
        return np.array([v, side * a * max(1.0 - v * v, 0.0) ** 1.5])

    def proper_velocity(v: float) -> float:
        return v * textbook_gamma(v)

    duration = abs(proper_velocity(end.v_after) - proper_velocity(end.v_before)) / a  # Eq. (2): a' t = gamma v
    t_end = end.t_start + 2.0 * duration + math.ulp(end.t_start) * 4
    sol = solve_ivp(
        rhs,
        (end.t_start, t_end),
        [end.x_start, end.v_before],
        method=method,
        rtol=rtol,
        atol=[rtol * length, rtol],
        events=_ReachesFinalVelocity(end.v_after, side),
        dense_output=True,
    )
    if sol.status != 1 or len(sol.t_events[0]) == 0:
        raise IntegrationFailed(f"solve_ivp {method} rtol={rtol:g}: {sol.message}")
    t_stop = float(sol.t_events[0][0])
    x_stop = float(sol.y_events[0][0][0])
    return IntegratedEnd(end, t_stop, x_stop, sol.sol, np.asarray(sol.t, dtype=np.float64))


def end_positions(track: IntegratedEnd, beta: float, t_frame: FloatArray) -> FloatArray:
    """Steps 2-3 of the module docstring for one integrated end."""
    end = track.end
    gamma = textbook_gamma(beta)
    out = np.where(
        t_frame <= gamma * (end.t_start - beta * end.x_start),
        inertial_slice(end.x_start, end.t_start, end.v_before, beta, gamma, t_frame),
        inertial_slice(track.x_stop, track.t_stop, end.v_after, beta, gamma, t_frame),
    )
    if track.solution is None:
        return out
    frame_start = gamma * (end.t_start - beta * end.x_start)
    frame_stop = gamma * (track.t_stop - beta * track.x_stop)
    inside = (t_frame > frame_start) & (t_frame < frame_stop)
    if not inside.any():
        return out
    target = t_frame[inside]
    steps = track.step_times
    step_frame_times = gamma * (steps - beta * track.solution(steps)[0])
    t = np.interp(target, step_frame_times, steps)
    for _ in range(NEWTON_STEPS):
        x, v = track.solution(t)
        step = (gamma * (t - beta * x) - target) / (gamma * (1.0 - beta * v))
        t = np.clip(t - step, end.t_start, track.t_stop)
        if np.all(np.abs(step) <= 4.0 * np.spacing(np.abs(t))):
            break
    x = track.solution(t)[0]
    out[inside] = gamma * (x - beta * t)
    return out


def positions(scene: BenchScene, frame_velocity: float, t: FloatArray, method: IvpMethod, rtol: float) -> FloatArray:
    """Both ends of each rod at frame times ``t``; raises :class:`IntegrationFailed`."""
    out = []
    for rod, length in zip(paper_ends(scene), scene.rest_lengths, strict=True):
        out.append([end_positions(integrate(end, method, rtol, length), frame_velocity, t) for end in rod])
    return np.array(out)
