"""Method 2: the textbook formulas as the paper prints them, in float64, lab first and then boosted.

For each end (:mod:`benchmarks.study.paper`) and each frame time ``t'``:

1. find the lab time ``t`` of the event with ``gamma (t - beta x(t)) = t'``, in closed form per
   piece: on an inertial piece ``x = x_0 + v (t - t_0)``,
   ``t = (t'/gamma + beta (x_0 - v t_0)) / (1 - beta v)``; on a hyperbola
   ``x = c + sigma sqrt(d^2 + t^2)`` the quadratic's root
   ``t = gamma^2 (tau + sigma beta sqrt(tau^2 + d^2/gamma^2))`` with ``tau = t'/gamma + beta c``;
   the piece is chosen by the frame times ``gamma (t_s - beta x_s)`` of its switch events;
2. evaluate the printed lab formula ``x(t)``;
3. boost: ``x' = gamma (x - beta t)``, with ``gamma = 1/sqrt(1 - beta^2)``.
"""

from __future__ import annotations

import numpy as np

from ..paper import PaperEnd, inertial_slice, paper_ends, textbook_gamma
from ..scenes import BenchScene
from . import FloatArray


def end_positions(end: PaperEnd, beta: float, t_frame: FloatArray) -> FloatArray:
    """``x'`` of one end at frame times ``t_frame`` (steps 1-3 of the module docstring)."""
    gamma = textbook_gamma(beta)
    before = inertial_slice(end.x_start, end.t_start, end.v_before, beta, gamma, t_frame)
    after = inertial_slice(end.x_stop, end.t_stop, end.v_after, beta, gamma, t_frame)
    frame_start = gamma * (end.t_start - beta * end.x_start)
    frame_stop = gamma * (end.t_stop - beta * end.x_stop)
    if end.form == "kick":
        return np.where(t_frame <= frame_start, before, after)
    tau = t_frame / gamma + beta * end.centre
    d = end.radius
    geometric_side = 1.0 if end.form == "deriv" else end.side
    t = gamma * gamma * (tau + geometric_side * beta * np.sqrt(tau * tau + d * d / (gamma * gamma)))
    during = gamma * (end.accelerated_x(t) - beta * t)
    return np.where(t_frame < frame_start, before, np.where(t_frame > frame_stop, after, during))


def positions(scene: BenchScene, frame_velocity: float, t: FloatArray) -> FloatArray:
    """Both ends of each rod at frame times ``t``: shape ``(n_rods, 2, len(t))``."""
    return np.array([[end_positions(end, frame_velocity, t) for end in rod] for rod in paper_ends(scene)])
