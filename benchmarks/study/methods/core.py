"""Method 1: rigidrel's closed form (the core).

The scene is solved once in double-double arithmetic (final velocities as double-double), then
every end is sampled in the frame from Lorentz-covariant closed forms (hyperbola pieces
``x' = x'_h + sign t'(t' - 2 t'_C)/(sqrt(rho^2 + (t' - t'_C)^2) + q_0)`` and their tangents,
see ``rigidrel_core/_motion.py``): no boost of lab coordinates, no root finding.
"""

from __future__ import annotations

import rigidrel_core as rr

from ..scenes import BenchScene
from . import FloatArray


def positions(scene: BenchScene, frame_velocity: float, t: FloatArray) -> FloatArray:
    """Build the core's scene and its frame (``rr.Frame.from_velocity``) and sample both ends of each rod
    at frame times ``t``."""
    return scene.core().positions(t, frame=rr.Frame.from_velocity(frame_velocity))
