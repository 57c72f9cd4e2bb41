"""Method 5: mpmath at 50 digits, the accuracy limit and the reference for all the others.

The paper's lab formulas and scene solutions at 50 digits (:mod:`tests.reference.oracle`),
each end sliced at every frame time by bracketing root finding on lab time
(Anderson-Bjorck, bracket below ``1e-48`` of its scale). The values are kept as
double-double ``hi + lo`` so that the other methods' errors are measured below one
float64 ulp; the method's own output is ``hi``, the reference rounded to float64.
"""

from __future__ import annotations

import inspect
from dataclasses import dataclass

import numpy as np

from tests.reference.oracle import BUILDERS, F, SliceSolver, frame_slice, reference_precision

from ..scenes import BenchScene
from . import FloatArray

#: The ends of a rod, as material fractions of its rest length.
ENDS = (0.0, 1.0)
#: Relative errors below this are float64 rounding (a few ulp): they count as equal.
ROUNDING_LEVEL = 1e-15


@dataclass(frozen=True)
class ReferenceSlices:
    """50-digit ``x'`` of both ends of each rod, as ``hi + lo`` (shape ``(n_rods, 2, n)`` each),
    and each rod's equal-time length ``x'_right - x'_left`` (shape ``(n_rods, n)``)."""

    hi: FloatArray
    lo: FloatArray
    lengths: FloatArray


def reference_slices(
    scene: BenchScene, frame_velocity: float, t: FloatArray, solver: SliceSolver = "anderson-bjorck"
) -> ReferenceSlices:
    """The reference at frame times ``t`` (each float taken as exact), computed at 50 digits."""
    with reference_precision():
        build = BUILDERS[scene.kind]
        takes = inspect.signature(build).parameters  # its kinematics: a lone rod's mass moves nothing
        ref = build(ENDS, **{name: value for name, value in scene.params.items() if name in takes})
        beta = F(frame_velocity)
        times = [F(s) for s in t.tolist()]
        values = [[[frame_slice(w, beta, s, solver) for s in times] for w in rod] for rod in ref.worldlines]
        hi = np.array([[[float(v) for v in end] for end in rod] for rod in values])
        lo = np.array(
            [
                [[float(v - h) for v, h in zip(end, hrow)] for end, hrow in zip(rod, hrod)]
                for rod, hrod in zip(values, hi)
            ]
        )
        lengths = np.array([[float(b - a) for a, b in zip(rod[0], rod[1])] for rod in values])
    return ReferenceSlices(hi, lo, lengths)


def positions(scene: BenchScene, frame_velocity: float, t: FloatArray) -> FloatArray:
    """The reference rounded to float64."""
    return reference_slices(scene, frame_velocity, t).hi


def relative_errors(x: FloatArray, ref: ReferenceSlices) -> FloatArray:
    """``|x - x_ref| / max(|x_ref|, equal-time length)`` per end and sample (the metric of
    tests/test_accuracy.py); ``inf`` where ``x`` is not finite."""
    with np.errstate(invalid="ignore", over="ignore"):
        diff = np.abs((x - ref.hi) - ref.lo)
        scale = np.maximum(np.abs(ref.hi), np.abs(ref.lengths)[:, None, :])
        err = diff / scale
    return np.where(np.isfinite(err), err, np.inf)
