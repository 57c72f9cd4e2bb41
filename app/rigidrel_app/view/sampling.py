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

#: Half a pixel: finer than a panel can show.
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
    All curves' pending intervals live in flat arrays (curve index, ends, end values), so a
    round is a few array operations whatever the number of curves.
    """
    n = len(knots)
    all_t = np.unique(np.concatenate(knots))
    values_all = evaluate(all_t)
    curve = np.repeat(np.arange(n), [k.size for k in knots])
    t_pts = np.concatenate(knots)
    x_pts = values_all[curve, np.searchsorted(all_t, t_pts)]
    points = [(curve, t_pts, x_pts)]
    # pending intervals: every pair of consecutive knots of one curve
    left = np.flatnonzero(curve[:-1] == curve[1:])
    c, ta, tb, xa, xb = curve[left], t_pts[left], t_pts[left + 1], x_pts[left], x_pts[left + 1]
    span = float(all_t[-1] - all_t[0]) if all_t.size > 1 else 1.0
    for _ in range(MAX_DEPTH):
        if c.size == 0:
            break
        tm = 0.5 * (ta + tb)
        unique_t = np.unique(tm)
        xm = evaluate(unique_t)[c, np.searchsorted(unique_t, tm)]
        bad = (np.abs(xm - 0.5 * (xa + xb)) > tol) & ((tb - ta) > 1e-12 * span)
        c, ta, tb, xa, xb, tm, xm = c[bad], ta[bad], tb[bad], xa[bad], xb[bad], tm[bad], xm[bad]
        points.append((c, tm, xm))
        # each split interval becomes two pending halves
        c, ta, tb = np.concatenate([c, c]), np.concatenate([ta, tm]), np.concatenate([tm, tb])
        xa, xb = np.concatenate([xa, xm]), np.concatenate([xm, xb])
    curve = np.concatenate([p[0] for p in points])
    t_all = np.concatenate([p[1] for p in points])
    x_all = np.concatenate([p[2] for p in points])
    order = np.lexsort((t_all, curve))
    curve, t_all, x_all = curve[order], t_all[order], x_all[order]
    bounds = np.searchsorted(curve, np.arange(n + 1))
    return [Sampled(t_all[bounds[i] : bounds[i + 1]], x_all[bounds[i] : bounds[i + 1]]) for i in range(n)]


#: A curved piece starts as this many equal intervals (saves the first rounds of halving).
SEED_INTERVALS = 8


def _knots(switches: FloatArray, t_range: tuple[float, float]) -> FloatArray:
    """Start and end of the range, the switch times inside it, and a seed grid on the curved piece.

    A handful of numbers per curve: plain Python floats are faster here than array calls.
    """
    t0, t1 = t_range
    s = switches.ravel().tolist()
    points = {t0, t1, *(v for v in s if t0 < v < t1)}
    lo, hi = max(t0, min(s)), min(t1, max(s))
    if hi > lo:
        step = (hi - lo) / SEED_INTERVALS
        points.update(lo + k * step for k in range(SEED_INTERVALS))
        points.add(hi)
    return np.array(sorted(points))


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
    switches = scene.switch_times(frame=frame, fractions=fractions)  # (rods, fractions, 2)
    knots = [_knots(switches[r, k], t_range) for r in range(scene.n_rods) for k in range(fractions.size)]

    def evaluate(t: FloatArray) -> FloatArray:
        return scene.material_positions(t, frame=frame, fractions=fractions).reshape(-1, t.size)

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
    switches = scene.switch_times(frame=frame)  # (rods, 2 ends, 2)
    knots = [_knots(switches[r].ravel(), t_range) for r in range(scene.n_rods)]
    return refine(lambda t: scene.lengths(t, frame=frame), knots, tol_px / px_per_length)


def sample_tie_span(
    scene: rr.Scene,
    tie: rr.SceneObject,
    frame: rr.Frame,
    t_range: tuple[float, float],
    px_per_length: float,
    tol_px: float = TOLERANCE_PX,
) -> Sampled:
    """A tie's ends' equal-time separation ``x'_2 - x'_1`` against time of ``frame`` (Bell's string:
    the ships' gap it spans), adaptively sampled from the rods' switch times (its ends move with
    the rods' material points)."""
    knots = _knots(scene.switch_times(frame=frame).ravel(), t_range)

    def evaluate(t: FloatArray) -> FloatArray:
        x = tie.positions(t, frame=frame)
        return (x[1] - x[0])[np.newaxis]

    return refine(evaluate, [knots], tol_px / px_per_length)[0]


@dataclass(frozen=True)
class Sampler:
    """How the diagrams sample their curves: adaptively to ``tol_px`` (the app, the exports), or,
    with ``fixed_n``, at that many equally spaced times (what ``rigidrel bench`` compares with)."""

    tol_px: float = TOLERANCE_PX
    fixed_n: int | None = None

    def worldlines(
        self, scene: rr.Scene, frame: rr.Frame, fractions: FloatArray, t_range: tuple[float, float], px_per_x: float
    ) -> list[list[Sampled]]:
        """``[rod][fraction]`` worldlines over ``t_range`` of the frame."""
        if self.fixed_n is None:
            return sample_worldlines(scene, frame, fractions, t_range, px_per_x, self.tol_px)
        t = np.linspace(t_range[0], t_range[1], self.fixed_n)
        x = scene.material_positions(t, frame=frame, fractions=fractions)
        return [[Sampled(t, x[r, k]) for k in range(fractions.size)] for r in range(scene.n_rods)]

    def lengths(
        self, scene: rr.Scene, frame: rr.Frame, t_range: tuple[float, float], px_per_length: float
    ) -> list[Sampled]:
        """Each rod's equal-time length against frame time over ``t_range``."""
        if self.fixed_n is None:
            return sample_lengths(scene, frame, t_range, px_per_length, self.tol_px)
        t = np.linspace(t_range[0], t_range[1], self.fixed_n)
        lengths = scene.lengths(t, frame=frame)
        return [Sampled(t, lengths[r]) for r in range(scene.n_rods)]

    def tie_span(
        self, scene: rr.Scene, tie: rr.SceneObject, frame: rr.Frame, t_range: tuple[float, float], px_per_length: float
    ) -> Sampled:
        """A tie's ends' equal-time separation against frame time over ``t_range``."""
        if self.fixed_n is None:
            return sample_tie_span(scene, tie, frame, t_range, px_per_length, self.tol_px)
        t = np.linspace(t_range[0], t_range[1], self.fixed_n)
        x = tie.positions(t, frame=frame)
        return Sampled(t, x[1] - x[0])


#: The app's sampler: chord error below half a pixel.
ADAPTIVE = Sampler()
