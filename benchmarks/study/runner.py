"""Measure every method on the same scenes, frames and frame times, in one process run.

For each case (:data:`benchmarks.study.scenes.CASES`) the 50-digit reference is computed once
(that call is also the mpmath method's timing); then every other method setting is
called on exactly the same ``(scene, frame velocity, times)``:

* seconds per sample = the best wall time of repeated calls / number of samples
  (each call does everything from the scene's parameters to the positions); the two closed
  forms (the core and the textbook formulas, microseconds a call) are called in turn, one
  call each, so that a busy spell on a shared machine falls on both alike;
* max error = max over samples and rod ends of ``|x' - x'_ref| / max(|x'_ref|, L_ref(t'))``,
  ``L_ref`` the rod's equal-time length in the frame (the metric of tests/test_accuracy.py),
  from the first call's output.

A method that raises (solve_ivp stopping early, spacetimelib rejecting a polyline) or
returns non-finite numbers fails the case; its error is then ``None`` with the reason.
"""

from __future__ import annotations

import functools
import time
import warnings
from collections.abc import Callable, Sequence
from dataclasses import dataclass

import numpy as np

from .methods import FloatArray, MethodName, MethodSetting, core, ivp, mpmath_slices, polyline, textbook
from .methods.mpmath_slices import ReferenceSlices, reference_slices, relative_errors
from .scenes import CASES, BenchCase, Regime, sample_times

#: The mpmath method (the reference): timed once per case, charted as one series of one setting.
MPMATH = MethodSetting(MethodName.MPMATH, "mpmath 50 digits", "50 digits", mpmath_slices.positions)


@dataclass(frozen=True)
class Timing:
    """How long to repeat a call: at least ``min_repeats`` and ``min_seconds`` in total, at most
    ``max_repeats`` calls or ``max_seconds``; the best call counts."""

    min_repeats: int
    max_repeats: int
    min_seconds: float
    max_seconds: float


#: One call, no repeats (mpmath, and the untimed stability maps).
ONCE = Timing(1, 1, 0.0, 0.0)
#: The two closed forms (microseconds a call): timed alternately, call for call.
CLOSED_FORMS = frozenset({MethodName.CORE, MethodName.TEXTBOOK})


@dataclass(frozen=True)
class CaseResult:
    """One method setting on one case."""

    method: MethodName
    series: str
    setting: str
    regime: Regime
    case: str
    frame_velocity: float
    samples: int
    seconds_per_sample: float
    repeats: int
    max_error: float | None
    failure: str | None = None


@dataclass(frozen=True)
class RegimeRow:
    """One method setting over all cases of a regime: the JSON table's row."""

    method: MethodName
    series: str
    setting: str
    regime: Regime
    seconds_per_sample: float
    """Total best-call seconds over the regime's cases / total samples."""
    max_error: float | None
    """Largest error over the regime's cases; ``None`` if the method failed in any of them."""
    samples: int
    cases: int
    failures: tuple[str, ...]


def method_settings(
    rk45_rtols: Sequence[float], dop853_rtols: Sequence[float], vertex_counts: Sequence[int]
) -> tuple[MethodSetting, ...]:
    """Every method but mpmath (always run: it is the reference) at the given settings."""
    out = [
        MethodSetting(MethodName.CORE, "rigidrel core", "closed form", core.positions),
        MethodSetting(MethodName.TEXTBOOK, "textbook float64", "as printed", textbook.positions),
    ]
    integrators: tuple[tuple[ivp.IvpMethod, Sequence[float]], ...] = (("RK45", rk45_rtols), ("DOP853", dop853_rtols))
    for name, rtols in integrators:
        for rtol in rtols:
            fn = functools.partial(ivp.positions, method=name, rtol=rtol)
            out.append(MethodSetting(MethodName.SOLVE_IVP, f"solve_ivp {name}", f"rtol={rtol:.0e}", fn))
    for n in vertex_counts:
        fn = functools.partial(polyline.positions, n_vertices=n)
        out.append(MethodSetting(MethodName.SPACETIMELIB, "spacetimelib", f"N={n}", fn))
    return tuple(out)


Timed = tuple[FloatArray | None, str | None, float, int]
"""``(first output, failure, best seconds, repeats)`` of one timed method setting."""


def _failure(exc: Exception) -> str:
    return f"{type(exc).__name__}: {str(exc).splitlines()[0] if str(exc) else ''}"


def timed(call: Callable[[], FloatArray], timing: Timing) -> Timed:
    """``(first output, failure, best seconds, repeats)``; a failing call is timed once. Warnings are
    silenced around the whole loop, not inside the timed calls."""
    best = float("inf")
    first: FloatArray | None = None
    total = 0.0
    repeats = 0
    with warnings.catch_warnings(), np.errstate(all="ignore"):
        warnings.simplefilter("ignore")
        while True:
            start = time.perf_counter()
            try:
                out = call()
            except (ValueError, ArithmeticError, RuntimeError) as exc:
                return None, _failure(exc), time.perf_counter() - start, 1
            elapsed = time.perf_counter() - start
            if first is None:
                first = out
            best = min(best, elapsed)
            total += elapsed
            repeats += 1
            enough = repeats >= timing.min_repeats and total >= timing.min_seconds
            if enough or repeats >= timing.max_repeats or total >= timing.max_seconds:
                return first, None, best, repeats


def timed_alternately(calls: Sequence[Callable[[], FloatArray]], timing: Timing) -> list[Timed]:
    """:func:`timed` for several calls at once, one call of each in turn, so that a busy spell on a
    shared machine falls on all of them alike; each stops on its own limits (a failing call is
    timed once and dropped)."""
    best = [float("inf")] * len(calls)
    first: list[FloatArray | None] = [None] * len(calls)
    failure: list[str | None] = [None] * len(calls)
    total = [0.0] * len(calls)
    repeats = [0] * len(calls)
    running = list(range(len(calls)))
    with warnings.catch_warnings(), np.errstate(all="ignore"):
        warnings.simplefilter("ignore")
        while running:
            for i in list(running):
                start = time.perf_counter()
                try:
                    out = calls[i]()
                except (ValueError, ArithmeticError, RuntimeError) as exc:
                    failure[i], best[i], repeats[i] = _failure(exc), time.perf_counter() - start, 1
                    running.remove(i)
                    continue
                elapsed = time.perf_counter() - start
                if first[i] is None:
                    first[i] = out
                best[i] = min(best[i], elapsed)
                total[i] += elapsed
                repeats[i] += 1
                enough = repeats[i] >= timing.min_repeats and total[i] >= timing.min_seconds
                if enough or repeats[i] >= timing.max_repeats or total[i] >= timing.max_seconds:
                    running.remove(i)
    return [(None if failure[i] else first[i], failure[i], best[i], repeats[i]) for i in range(len(calls))]


def max_error(x: FloatArray | None, ref: ReferenceSlices) -> tuple[float | None, str | None]:
    if x is None:
        return None, None
    if x.shape != ref.hi.shape:
        return None, f"wrong shape {x.shape}"
    err = float(relative_errors(x, ref).max())
    if not np.isfinite(err):
        return None, "non-finite positions"
    return err, None


def run_case(case: BenchCase, settings: Sequence[MethodSetting], n_samples: int, timing: Timing) -> list[CaseResult]:
    """Every method setting on one case; the mpmath reference first (timed once)."""
    t = sample_times(case, n_samples)
    start = time.perf_counter()
    ref = reference_slices(case.scene, case.frame_velocity, t)
    mp_seconds = time.perf_counter() - start

    def result(ms: MethodSetting, seconds: float, repeats: int, err: float | None, why: str | None) -> CaseResult:
        return CaseResult(
            method=ms.method,
            series=ms.series,
            setting=ms.setting,
            regime=case.regime,
            case=case.label,
            frame_velocity=case.frame_velocity,
            samples=int(t.size),
            seconds_per_sample=seconds / t.size,
            repeats=repeats,
            max_error=err,
            failure=why,
        )

    mp_error, _ = max_error(ref.hi, ref)
    results = [result(MPMATH, mp_seconds, 1, mp_error, None)]
    calls = [functools.partial(ms.evaluate, case.scene, case.frame_velocity, t) for ms in settings]
    closed = [i for i, ms in enumerate(settings) if ms.method in CLOSED_FORMS]
    timings = dict(zip(closed, timed_alternately([calls[i] for i in closed], timing), strict=True))
    for i, ms in enumerate(settings):
        out, failure, seconds, repeats = timings[i] if i in timings else timed(calls[i], timing)
        err, bad = max_error(out, ref)
        results.append(result(ms, seconds, repeats, err, failure or bad))
    return results


def warm_up(settings: Sequence[MethodSetting]) -> None:
    """One untimed call of every fast method (imports, caches, numpy's first-call costs)."""
    case = CASES[0]
    t = sample_times(case, 8)
    for ms in settings:
        if ms.method in (MethodName.CORE, MethodName.TEXTBOOK):
            ms.evaluate(case.scene, case.frame_velocity, t)


def regime_rows(results: Sequence[CaseResult]) -> list[RegimeRow]:
    """Aggregate case results per (method setting, regime), in first-seen order."""
    groups: dict[tuple[str, str, Regime], list[CaseResult]] = {}
    for r in results:
        groups.setdefault((r.series, r.setting, r.regime), []).append(r)
    rows = []
    for (series, setting, regime), rs in groups.items():
        samples = sum(r.samples for r in rs)
        seconds = sum(r.seconds_per_sample * r.samples for r in rs)
        failures = tuple(f"{r.case}: {r.failure}" for r in rs if r.failure is not None)
        errors = [r.max_error for r in rs if r.max_error is not None]
        rows.append(
            RegimeRow(
                method=rs[0].method,
                series=series,
                setting=setting,
                regime=regime,
                seconds_per_sample=seconds / samples,
                max_error=None if failures or not errors else max(errors),
                samples=samples,
                cases=len(rs),
                failures=failures,
            )
        )
    return rows


@dataclass(frozen=True)
class ThroughputPoint:
    """Seconds per sample of one method setting at one number of samples per call."""

    method: MethodName
    series: str
    setting: str
    samples: int
    seconds_per_sample: float


def throughput(
    case: BenchCase,
    settings: Sequence[MethodSetting],
    counts: Sequence[int],
    timing: Timing,
    max_call_seconds: float,
) -> list[ThroughputPoint]:
    """How the cost per sample falls with the number of samples per call (fixed cost per scene and
    frame, plus a marginal cost per sample). A method stops growing once one call takes longer
    than ``max_call_seconds``; mpmath is timed once per count."""
    out: list[ThroughputPoint] = []
    closed = [ms for ms in settings if ms.method in CLOSED_FORMS]
    for n in counts:  # the closed forms alternately, as in run_case
        t = sample_times(case, n)
        calls = [functools.partial(ms.evaluate, case.scene, case.frame_velocity, t) for ms in closed]
        growing = []
        for ms, (_, failure, seconds, _) in zip(closed, timed_alternately(calls, timing), strict=True):
            if failure is not None:
                continue
            out.append(ThroughputPoint(ms.method, ms.series, ms.setting, int(t.size), seconds / t.size))
            if seconds <= max_call_seconds:
                growing.append(ms)
        closed = growing
    for ms in (*(ms for ms in settings if ms.method not in CLOSED_FORMS), MPMATH):
        how = ONCE if ms.method is MethodName.MPMATH else timing
        for n in counts:
            t = sample_times(case, n)
            _, failure, seconds, _ = timed(functools.partial(ms.evaluate, case.scene, case.frame_velocity, t), how)
            if failure is not None:
                break
            out.append(ThroughputPoint(ms.method, ms.series, ms.setting, int(t.size), seconds / t.size))
            if seconds > max_call_seconds:
                break
    return out
