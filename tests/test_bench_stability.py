"""Stability of the methods ``rigidrel bench`` compares, against the 50-digit reference.

* the textbook formulas (float64, lab first, then boosted) lose at least 4 of float64's
  digits where the core holds 1e-12;
* solve_ivp's error tracks its tolerance (within two decades, slope ~1 in log-log);
* spacetimelib's polyline error falls as N^-2.

Each check uses a dozen frame times, so the mpmath reference costs milliseconds.
"""

from __future__ import annotations

import warnings

import numpy as np
import pytest

from benchmarks.study import scenes as bs
from benchmarks.study.methods import core, ivp, polyline, textbook
from benchmarks.study.methods.mpmath_slices import ReferenceSlices, reference_slices, relative_errors

#: float64's unit roundoff; "losing k digits" means an error of at least 10^k of it.
UNIT_ROUNDOFF = 2.0**-53
#: The core's promise (tests/test_accuracy.py).
CORE_TOLERANCE = 1e-12
SAMPLES = 12


def reference(case: bs.BenchCase) -> tuple[np.ndarray, ReferenceSlices]:
    t = bs.sample_times(case, SAMPLES)
    return t, reference_slices(case.scene, case.frame_velocity, t)


def max_error(x: np.ndarray, ref: ReferenceSlices) -> float:
    return float(relative_errors(x, ref).max())


#: Where the printed formulas cancel: a frame chasing an ultra-relativistic rod, derived
#: velocities of a collision, |beta| = 0.999999, 1e6 lengths of time in the rod's rest frame,
#: a 1e-6 rod far from the origin in a frame moving with it.
TEXTBOOK_FAILS = [
    bs.BenchCase(bs.Regime.ULTRA_RELATIVISTIC, bs.ULTRA_9, 1.0 - 1e-9, "rod after"),
    bs.BenchCase(bs.Regime.ULTRA_RELATIVISTIC, bs.ULTRA_12, 0.0, "lab"),
    bs.BenchCase(bs.Regime.EXTREME_FRAMES, bs.FIG3, 0.999999, "custom"),
    bs.BenchCase(bs.Regime.LONG_TIMES, bs.FIG1, 0.6, "rod after", "long"),
    bs.BenchCase(bs.Regime.ROD_SIZES, bs.SIZES, 0.5, "custom"),
]


@pytest.mark.parametrize("case", TEXTBOOK_FAILS, ids=lambda c: f"{c.regime.value}, beta={c.frame_velocity:.12g}")
def test_textbook_formulas_lose_four_digits_where_the_core_holds(case: bs.BenchCase) -> None:
    t, ref = reference(case)
    core_error = max_error(core.positions(case.scene, case.frame_velocity, t), ref)
    with np.errstate(all="ignore"):
        textbook_error = max_error(textbook.positions(case.scene, case.frame_velocity, t), ref)
    assert core_error <= CORE_TOLERANCE, f"core error {core_error:.3g}"
    digits_lost = np.log10(textbook_error / UNIT_ROUNDOFF)
    assert digits_lost >= 4.0, f"textbook error {textbook_error:.3g}: only {digits_lost:.1f} digits lost"


IVP_CASE = bs.BenchCase(bs.Regime.ORDINARY, bs.FIG3, 0.5, "custom")
RTOLS = [10.0**-k for k in range(3, 13)]


@pytest.mark.parametrize("method", ["RK45", "DOP853"])
def test_solve_ivp_error_tracks_its_tolerance(method: ivp.IvpMethod) -> None:
    """Fig. 3's collision at beta = 0.5: error / rtol stays within [1e-2, 1e2] and the log-log slope is ~1."""
    t, ref = reference(IVP_CASE)
    with warnings.catch_warnings(), np.errstate(all="ignore"):
        warnings.simplefilter("ignore")
        errors = np.array([max_error(ivp.positions(bs.FIG3, 0.5, t, method, r), ref) for r in RTOLS])
    ratios = errors / np.array(RTOLS)
    assert np.all((ratios >= 1e-2) & (ratios <= 1e2)), dict(zip(RTOLS, ratios.round(3)))
    slope = np.polyfit(np.log10(RTOLS), np.log10(errors), 1)[0]
    assert 0.8 <= slope <= 1.2, f"log-log slope of error against rtol: {slope:.2f}"


POLYLINE_CASES = [
    bs.BenchCase(bs.Regime.ORDINARY, bs.FIG1, 0.0, "lab"),
    bs.BenchCase(bs.Regime.ORDINARY, bs.FIG3, 0.5, "custom"),
]


@pytest.mark.parametrize("case", POLYLINE_CASES, ids=lambda c: f"{c.scene.label[:6]}, beta={c.frame_velocity}")
def test_spacetimelib_error_falls_as_n_to_the_minus_two(case: bs.BenchCase) -> None:
    """Chords of a hyperbola: the sagitta of N vertices falls as N^-2 (slope -2 in log-log)."""
    t, ref = reference(case)
    counts = [10, 30, 100, 300, 1000]
    errors = [max_error(polyline.positions(case.scene, case.frame_velocity, t, n), ref) for n in counts]
    slope = np.polyfit(np.log10(counts), np.log10(errors), 1)[0]
    assert -2.2 <= slope <= -1.8, f"log-log slope of error against N: {slope:.2f} ({errors})"
    assert errors[-1] > 1e3 * UNIT_ROUNDOFF, "the polyline error must be above rounding to see its order"
