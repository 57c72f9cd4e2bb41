"""4-momentum bookkeeping of a scene in one frame (c = 1: E = M cosh(theta), p = M sinh(theta))."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

import numpy as np
import numpy.typing as npt

FloatArray = npt.NDArray[np.float64]

ExternalSource = Literal["none", "drive", "wall"]


@dataclass(frozen=True)
class FourMomentumBudget:
    """Energy and momentum of each rod before and after, in the frame ``frame_velocity``.

    ``external`` is the 4-momentum delivered to the rods from outside: zero for a rod-rod
    collision (a closed system), the agent's push for the driven scenes, minus what the
    wall absorbed for a wall collision. ``heat`` is the invariant rest energy the process
    creates: for epsilon < 1 the rods of a collision come out heavier
    (``rest_mass_after > rest_mass_before``), so that 4-momentum is conserved in every
    frame; in a wall collision the (infinitely heavy) wall takes it.
    """

    frame_velocity: float
    bodies: tuple[str, ...]
    rest_mass_before: FloatArray
    """Shape ``(n_rods,)``."""
    rest_mass_after: FloatArray
    before: FloatArray
    """``(E, p)`` of each rod before; shape ``(n_rods, 2)``."""
    after: FloatArray
    kinetic_before: FloatArray
    """``E - M = 2 M sinh^2(theta/2)`` of each rod before (no cancellation at low speed)."""
    kinetic_after: FloatArray
    external: FloatArray
    """``(E, p)`` from outside; shape ``(2,)``."""
    external_source: ExternalSource
    heat: float

    @property
    def total_before(self) -> FloatArray:
        return self.before.sum(axis=0)

    @property
    def total_after(self) -> FloatArray:
        return self.after.sum(axis=0)

    def as_dict(self) -> dict[str, object]:
        return {
            "frame_velocity": self.frame_velocity,
            "bodies": list(self.bodies),
            "rest_mass_before": self.rest_mass_before.tolist(),
            "rest_mass_after": self.rest_mass_after.tolist(),
            "energy_momentum_before": self.before.tolist(),
            "energy_momentum_after": self.after.tolist(),
            "kinetic_before": self.kinetic_before.tolist(),
            "kinetic_after": self.kinetic_after.tolist(),
            "total_before": self.total_before.tolist(),
            "total_after": self.total_after.tolist(),
            "external": self.external.tolist(),
            "external_source": self.external_source,
            "heat": self.heat,
        }
