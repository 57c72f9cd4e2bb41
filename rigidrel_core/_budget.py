"""4-momentum bookkeeping of a scene in one frame (c = 1: E = M cosh(theta), p = M sinh(theta)).

A scene's rods need not all exist together: the pole in the barn shows two models of one pole
(Born-rigid and signal-limited) side by side, and Bell's spaceships a Born-rigid rod that spans
the ships' rear ends instead of them. Each set of rods that does exist together, with what acts on
it from outside, is a :class:`PhysicalSystem`; a budget totals each system on its own and never
adds rods of different systems.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

import numpy as np
import numpy.typing as npt

FloatArray = npt.NDArray[np.float64]

ExternalSource = Literal["none", "drive", "wall"]


@dataclass(frozen=True)
class PhysicalSystem:
    """Rods of a scene that exist together, and what acts on them from outside: one model of the
    scene (the Born-rigid pole and the barn's wall; Bell's two ships)."""

    name: str
    """In words: ``"the two ships (and their string)"``."""
    rods: tuple[int, ...]
    """Indices of the scene's rods."""
    external_source: ExternalSource
    """What delivers 4-momentum from outside: nothing, the agent's drive, or a wall."""
    heat: float
    """Invariant rest energy the process creates in this system (epsilon < 1, a plastic stop)."""


#: Who takes the heat when the rods keep their rest masses, by what acts on them from outside.
_TAKEN_BY: dict[ExternalSource, str] = {"wall": "in the wall"}


def _the(name: str) -> str:
    """``"the rod"``, ``"rod 1"``: a rod's name with its article."""
    return name if name.startswith("rod ") else f"the {name}"


def heat_where(
    system: PhysicalSystem,
    names: tuple[str, ...],
    mass_before: FloatArray,
    mass_after: FloatArray,
    compressed: tuple[bool, ...] = (),
) -> str:
    """Which body the heat of ``system`` is in, in words (c = 1, energy in mass units): the wall, when
    the rods keep their rest masses (a Born-rigid stop: an infinitely heavy wall takes the momentum and
    the rest energy); else the rods, whose rest masses grow by it (shared in proportion to rest mass
    when they grow by one factor, as in a collision with ε < 1); ``""`` when there is no heat. A rod
    that ends compressed (``compressed``, by rod: one stopped by a signal, not Born rigid) holds part
    of it as the energy of its compression, and the words say so."""
    rods = list(system.rods)
    m0, m1 = mass_before[rods], mass_after[rods]
    if system.heat == 0.0:
        return ""
    if np.array_equal(m0, m1):
        keeps = "keeps its rest mass" if len(rods) == 1 else "keep their rest masses"
        where = _TAKEN_BY.get(system.external_source, "outside the rods")
        return f"all {where} ({' and '.join(_the(names[i]) for i in rods)} {keeps})"
    if len(rods) == 1:
        part = (
            ": not all heat, part is the energy of its compression"
            if rods[0] < len(compressed) and (compressed[rods[0]])
            else ""
        )
        return f"in {_the(names[rods[0]])}{part} (its rest mass grows from {m0[0]:.6g} to {m1[0]:.6g})"
    factors = m1 / m0
    if np.allclose(factors, factors[0], rtol=1e-12, atol=0.0):
        return f"in the rods, shared in proportion to rest mass (each rest mass × {factors[0]:.6g})"
    grows = ", ".join(f"{_the(names[i])} {a:.6g} → {b:.6g}" for i, a, b in zip(rods, m0, m1, strict=True))
    return f"in the rods (their rest masses grow: {grows})"


@dataclass(frozen=True)
class SystemBudget:
    """One physical system's totals in one frame (:class:`FourMomentumBudget`)."""

    system: PhysicalSystem
    total_before: FloatArray
    """``(E, p)`` of the system's rods before; shape ``(2,)``."""
    total_after: FloatArray
    external: FloatArray
    """``(E, p)`` delivered from outside: ``total_after - total_before`` (zero for a closed system)."""
    heat_where: str = ""
    """Which body the heat is in, in words (:func:`heat_where`): ``"all in the wall (the rod keeps its
    rest mass)"``, ``"in the signal-limited pole (its rest mass grows from 1 to 1.25)"``; ``""``: no heat."""

    @property
    def name(self) -> str:
        return self.system.name

    @property
    def heat(self) -> float:
        return self.system.heat

    @property
    def external_source(self) -> ExternalSource:
        return self.system.external_source

    def as_dict(self) -> dict[str, object]:
        return {
            "system": self.system.name,
            "rods": list(self.system.rods),
            "total_before": self.total_before.tolist(),
            "total_after": self.total_after.tolist(),
            "external": self.external.tolist(),
            "external_source": self.system.external_source,
            "heat": self.system.heat,
            "heat_where": self.heat_where,
        }


@dataclass(frozen=True)
class FourMomentumBudget:
    """Energy and momentum of each rod before and after, in the frame ``frame_velocity``, and the
    totals of each physical system (:attr:`systems`).

    ``external`` is the 4-momentum delivered to a system from outside: zero for a rod-rod
    collision (a closed system), the agent's push for the driven scenes, minus what the
    wall absorbed for a wall collision. ``heat`` is the invariant rest energy the process
    creates: for epsilon < 1 the rods of a collision come out heavier
    (``rest_mass_after > rest_mass_before``), so that 4-momentum is conserved in every
    frame; in a wall collision the (infinitely heavy) wall takes it.

    The totals (:attr:`total_before`, :attr:`total_after`, :attr:`external`, :attr:`heat`) are
    those of the scene's one system; a scene of several systems (alternatives, a comparison rod)
    has no such single total: read each system's in :attr:`systems`.
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
    systems: tuple[SystemBudget, ...]
    """Each physical system's totals, summed over its own rods only."""

    def _single(self) -> SystemBudget:
        if len(self.systems) != 1:
            names = "; ".join(s.name for s in self.systems)
            raise ValueError(
                f"this scene holds {len(self.systems)} physical systems that never coexist ({names}): "
                "their rods are not summed; read each system's totals in budget.systems"
            )
        return self.systems[0]

    @property
    def total_before(self) -> FloatArray:
        """``(E, p)`` of the scene's one system before (``ValueError`` for a scene of several)."""
        return self._single().total_before

    @property
    def total_after(self) -> FloatArray:
        return self._single().total_after

    @property
    def external(self) -> FloatArray:
        """``(E, p)`` from outside to the scene's one system; shape ``(2,)``."""
        return self._single().external

    @property
    def external_source(self) -> ExternalSource:
        return self._single().external_source

    @property
    def heat(self) -> float:
        return self._single().heat

    def as_dict(self) -> dict[str, object]:
        """Plain data: the rods' 4-momenta and each system's totals (``"systems"``); a scene of one
        system also gives its totals at the top level, as before."""
        out: dict[str, object] = {
            "frame_velocity": self.frame_velocity,
            "bodies": list(self.bodies),
            "rest_mass_before": self.rest_mass_before.tolist(),
            "rest_mass_after": self.rest_mass_after.tolist(),
            "energy_momentum_before": self.before.tolist(),
            "energy_momentum_after": self.after.tolist(),
            "kinetic_before": self.kinetic_before.tolist(),
            "kinetic_after": self.kinetic_after.tolist(),
            "systems": [s.as_dict() for s in self.systems],
        }
        if len(self.systems) == 1:
            single = self.systems[0].as_dict()
            out.update({k: single[k] for k in ("total_before", "total_after", "external", "external_source", "heat")})
        return out
