"""Sample curves no finer than a panel can show: chord error below half a pixel.

A curve here is any function of frame time that the core evaluates exactly (a worldline
``x(t)``, an equal-time length ``L(t)``). Between the core's switch times the pieces are
straight or hyperbolic, so the samples start at those knots and an interval is halved
only where the curve's midpoint leaves the chord by more than the tolerance. Every
sample is an exact core evaluation; nothing is interpolated.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

import rigidrel_core as rr

FloatArray = npt.NDArray[np.float64]

#: Half a pixel (issue 5's target).
TOLERANCE_PX = 0.5
MAX_DEPTH = 24


@dataclass(frozen=True)
class Sampled:
    """One curve: times and values, increasing in time."""

    t: FloatArray
    x: FloatArray


def refine(
    evaluate: Callable[[FloatArray], FloatArray],
    knots: list[FloatArray],
    tol: float,
) -> list[Sampled]:
    """Adaptive samples of several curves at once.

    ``evaluate(t)`` returns every curve's value at times ``t``: shape ``(n_curves, t.size)``.
    ``knots[i]`` are curve ``i``'s starting samples (sorted, unique). An interval is split
    while its midpoint deviates from the chord by more than ``tol`` (value units); an
    interval once accepted is not tested again, so each round evaluates only new midpoints.
    """
    n = len(knots)
    all_t = np.unique(np.concatenate(knots))
    values_all = evaluate(all_t)
    ts = list(knots)
    xs = [values_all[i, np.searchsorted(all_t, ts[i])] for i in range(n)]
    pending = [np.ones(t.size - 1, dtype=bool) for t in ts]  # intervals not yet accepted
    span = float(all_t[-1] - all_t[0]) if all_t.size > 1 else 1.0
    for _ in range(MAX_DEPTH):
        mids = [0.5 * (t[:-1] + t[1:])[p] for t, p in zip(ts, pending, strict=True)]
        stacked = np.unique(np.concatenate(mids))
        if stacked.size == 0:
            break
        vm = evaluate(stacked)
        for i in range(n):
            if not pending[i].any():
                continue
            t, x, p = ts[i], xs[i], pending[i]
            k = np.flatnonzero(p)  # the tested intervals
            m = mids[i]
            xm = vm[i, np.searchsorted(stacked, m)]
            chord = 0.5 * (x[k] + x[k + 1])
            bad = (np.abs(xm - chord) > tol) & ((t[k + 1] - t[k]) > 1e-12 * span)
            split = k[bad]
            # accepted intervals stay, split ones become two pending halves
            new_pending = np.zeros(t.size - 1, dtype=bool)
            new_pending[split] = True
            ts[i] = np.insert(t, split + 1, m[bad])
            xs[i] = np.insert(x, split + 1, xm[bad])
            pending[i] = np.insert(new_pending, split + 1, True)
    return [Sampled(t, x) for t, x in zip(ts, xs, strict=True)]


#: A curved piece starts as this many equal intervals (saves the first rounds of halving).
SEED_INTERVALS = 8


def _knots(switches: FloatArray, t_range: tuple[float, float]) -> FloatArray:
    """Start and end of the range, the switch times inside it, and a seed grid on the curved piece."""
    t0, t1 = t_range
    inner = switches[(switches > t0) & (switches < t1)]
    lo, hi = max(t0, float(switches.min())), min(t1, float(switches.max()))
    seed = np.linspace(lo, hi, SEED_INTERVALS + 1) if hi > lo else np.empty(0)
    return np.unique(np.concatenate([[t0, t1], inner, seed]))


def sample_worldlines(
    scene: rr.Scene,
    frame: rr.Frame,
    fractions: FloatArray,
    t_range: tuple[float, float],
    px_per_x: float,
    tol_px: float = TOLERANCE_PX,
) -> list[list[Sampled]]:
    """``[rod][fraction]`` worldlines over ``t_range`` of the frame, adaptively sampled.

    ``px_per_x`` is the panel's horizontal scale; the error is measured horizontally
    (an upper bound of the distance to the chord).
    """
    switches = scene.switch_times(frame, fractions)  # (rods, fractions, 2)
    knots = [_knots(switches[r, k], t_range) for r in range(scene.n_rods) for k in range(fractions.size)]

    def evaluate(t: FloatArray) -> FloatArray:
        return scene.material_positions(fractions, t, frame).reshape(-1, t.size)

    flat = refine(evaluate, knots, tol_px / px_per_x)
    return [flat[r * fractions.size : (r + 1) * fractions.size] for r in range(scene.n_rods)]


def sample_lengths(
    scene: rr.Scene,
    frame: rr.Frame,
    t_range: tuple[float, float],
    px_per_length: float,
    tol_px: float = TOLERANCE_PX,
) -> list[Sampled]:
    """Each rod's equal-time length against frame time, adaptively sampled (constant while coasting)."""
    switches = scene.switch_times(frame)  # (rods, 2 ends, 2)
    knots = [_knots(switches[r].ravel(), t_range) for r in range(scene.n_rods)]
    return refine(lambda t: scene.lengths(t, frame), knots, tol_px / px_per_length)
