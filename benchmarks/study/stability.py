"""Stability maps: each method's error over the rod's speed ``V`` and the frame velocity ``beta``.

The scene is Fig. 3's collision with ``V1 = V`` (rod 1 of rest mass M1 = 1 and length 1 hits
rod 2 of mass 2 at rest, elastic), so the map sees derived velocities (the barycentric
``u``, velocity additions, the recoil ``V'``) as well as the input ``V``. The speed axis is
``V = 1 - 10^-k``; the frame axis is ``beta = 0`` and ``beta = +-(1 - 10^-k)``. In each cell
every method is evaluated at the same ``n`` frame times over the frame's event window,
and its max relative error against the 50-digit reference is recorded (no timing).
"""

from __future__ import annotations

import functools
from collections.abc import Sequence
from dataclasses import dataclass

from .methods import MethodSetting
from .methods.mpmath_slices import reference_slices
from .runner import MPMATH, ONCE, max_error, timed
from .scenes import BenchCase, BenchScene, Regime, rod_collision, sample_times


def speed_from_digits(k: float) -> float:
    """``V = 1 - 10^-k`` (rounded to float64)."""
    return 1.0 - 10.0 ** (-k)


def map_scene(v: float) -> BenchScene:
    return rod_collision(f"collision V1 = {v:.15g}, M2 = 2 M1", v, 0.0, 1.0, 2.0, 1.0, 1.0, 1.0)


def frame_velocities(digits: Sequence[float]) -> tuple[float, ...]:
    """``-(1 - 10^-k)`` for ``k`` descending, 0, then ``+(1 - 10^-k)`` ascending."""
    positive = [speed_from_digits(k) for k in sorted(digits)]
    return (*(-b for b in reversed(positive)), 0.0, *positive)


@dataclass(frozen=True)
class StabilityMap:
    """``errors[method series][i_beta][i_v]``: max relative error, ``None`` where the method failed."""

    velocity_digits: tuple[float, ...]
    velocities: tuple[float, ...]
    frame_velocities: tuple[float, ...]
    samples: int
    series: tuple[str, ...]
    settings: tuple[str, ...]
    errors: dict[str, list[list[float | None]]]
    failures: dict[str, list[str]]


def stability_map(
    settings: Sequence[MethodSetting], velocity_digits: Sequence[float], frame_digits: Sequence[float], n_samples: int
) -> StabilityMap:
    """Errors of ``settings`` (one per method) and of mpmath (rounded to float64) on the grid."""
    velocities = tuple(speed_from_digits(k) for k in velocity_digits)
    betas = frame_velocities(frame_digits)
    series = (*(s.series for s in settings), MPMATH.series)
    errors: dict[str, list[list[float | None]]] = {s: [] for s in series}
    failures: dict[str, list[str]] = {s: [] for s in series}
    for beta in betas:
        rows: dict[str, list[float | None]] = {s: [] for s in series}
        for v in velocities:
            case = BenchCase(Regime.ORDINARY, map_scene(v), beta, "map")
            t = sample_times(case, n_samples)
            ref = reference_slices(case.scene, beta, t)
            for ms in settings:
                out, why, _, _ = timed(functools.partial(ms.evaluate, case.scene, beta, t), ONCE)
                if why is not None:
                    failures[ms.series].append(f"V={v!r}, beta={beta!r}: {why}")
                rows[ms.series].append(max_error(out, ref)[0])
            rows[MPMATH.series].append(max_error(ref.hi, ref)[0])
        for s in series:
            errors[s].append(rows[s])
    return StabilityMap(
        velocity_digits=tuple(velocity_digits),
        velocities=velocities,
        frame_velocities=betas,
        samples=n_samples,
        series=series,
        settings=(*(s.setting for s in settings), MPMATH.setting),
        errors=errors,
        failures=failures,
    )


def worst_by_method(m: StabilityMap) -> dict[str, float | None]:
    """The largest error on the map per method (``None`` if it failed anywhere)."""
    out: dict[str, float | None] = {}
    for s in m.series:
        cells = [e for row in m.errors[s] for e in row]
        out[s] = None if any(e is None for e in cells) else max(e for e in cells if e is not None)
    return out
