"""The methods compared by ``rigidrel bench``, one module each, with one signature.

Every method takes a :class:`~benchmarks.study.scenes.BenchScene`, a frame velocity ``beta``
(c = 1, ``|beta| < 1``, a float: the core's method makes its ``rr.Frame`` inside the call) and an
array of the frame's times ``t'``, and returns ``x'`` of [left end, right end] of each rod at
those times: shape ``(n_rods, 2, len(t'))``, float64.
Everything from the scene's parameters to the positions happens inside the call, so its
wall time is the method's whole cost for that scene, frame and set of times.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from enum import StrEnum

import numpy as np
import numpy.typing as npt

from ..scenes import BenchScene

FloatArray = npt.NDArray[np.float64]
#: ``(scene, frame velocity, frame times) -> x'`` of shape ``(n_rods, 2, n)``.
Evaluate = Callable[[BenchScene, float, FloatArray], FloatArray]


class MethodName(StrEnum):
    """The five methods compared."""

    CORE = "rigidrel core"
    TEXTBOOK = "textbook float64"
    SOLVE_IVP = "scipy solve_ivp"
    SPACETIMELIB = "spacetimelib polylines"
    MPMATH = "mpmath 50 digits"


@dataclass(frozen=True)
class MethodSetting:
    """A method at one setting (tolerance, vertex count), as charted: one point of a series."""

    method: MethodName
    series: str
    """Chart series, e.g. "solve_ivp RK45" (one line through its tolerances)."""
    setting: str
    """e.g. "rtol=1e-06", "N=1000", "closed form"."""
    evaluate: Evaluate
