"""What is measured: scenes, frames, sample times and the regimes they stand for.

Units c = 1; lengths in units of the rod's rest length ``L0`` unless a scene says otherwise.
A frame of velocity ``beta`` has ``t' = gamma (t - beta x)``, ``x' = gamma (x - beta t)``.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from enum import StrEnum
from typing import Literal

import numpy as np
import numpy.typing as npt

import rigidrel_core as rr
from rigidrel_core.examples import FIG1_CONSTANT_ACCELERATION, FIG3_CASE_ONE

FloatArray = npt.NDArray[np.float64]

#: Scene kinds (the core's names) every method of the bench implements: the textbook, solve_ivp
#: and polyline methods type in the paper's formulas for these three only.
BenchKind = Literal["constant-acceleration", "impulsive-start", "rod-collision"]
#: How a case's frame times are spread: over the frame's event window, or out to 1e6 lengths.
TimeSpread = Literal["window", "long"]

#: "Long times" reach this many rest lengths (of the longest rod) before and after the origin.
LONG_TIME_LENGTHS = 1e6


class Regime(StrEnum):
    """The regimes the bench measures, each where some method loses digits."""

    ORDINARY = "ordinary"
    ULTRA_RELATIVISTIC = "ultra-relativistic"
    NEAR_HORIZON = "near the horizon"
    EXTREME_FRAMES = "extreme frames"
    LONG_TIMES = "long times"
    ROD_SIZES = "tiny and huge rods"


@dataclass(frozen=True)
class BenchScene:
    """A scene every method can compute: one of the core's scene kinds and its parameters."""

    label: str
    kind: BenchKind
    parameters: tuple[tuple[str, float], ...]
    rest_lengths: tuple[float, ...] = field(init=False, compare=False)
    """Each rod's rest length, from the core's scene built once here (so no method's timing pays for it,
    and bad parameters fail when the bench scene is made)."""

    def __post_init__(self) -> None:
        object.__setattr__(self, "rest_lengths", tuple(rod.motion.length for rod in self.core().rods))

    @property
    def params(self) -> dict[str, float]:
        return dict(self.parameters)

    def core(self) -> rr.Scene:
        """The core's scene (solved in double-double, sampled in float64), built afresh each call."""
        return rr.build_scene(self.kind, **self.params)


def constant_acceleration(label: str, v: float, length: float, a_front: float) -> BenchScene:
    """Paper Sec. 3: from rest to ``v``, front-end proper acceleration ``a'_F = a_front`` (Eq. (15))."""
    return BenchScene(label, "constant-acceleration", (("v", v), ("length", length), ("a_front", a_front)))


def impulsive_start(label: str, v: float, length: float) -> BenchScene:
    """Paper Sec. 4: the back end jumps to ``v``; the front follows Eq. (20)."""
    return BenchScene(label, "impulsive-start", (("v", v), ("length", length)))


def rod_collision(
    label: str, v1: float, v2: float, mass1: float, mass2: float, length1: float, length2: float, eps: float
) -> BenchScene:
    """Paper Secs. 5-6: rod 1 (left) at ``v1`` hits rod 2 at ``v2``; restitution ``eps`` (Eq. (29))."""
    names = ("v1", "v2", "mass1", "mass2", "length1", "length2", "eps")
    return BenchScene(label, "rod-collision", tuple(zip(names, (v1, v2, mass1, mass2, length1, length2, eps))))


def paper_case(label: str, kind: BenchKind, values: Mapping[str, float | None]) -> BenchScene:
    """One of the paper's canonical cases (:mod:`rigidrel_core.examples`), as the scenes' presets are."""
    parameters = tuple((name, value) for name, value in values.items() if value is not None)
    return BenchScene(label, kind, parameters)


FIG1 = paper_case("Fig. 1: acceleration to V = 0.6, a'_F L0 = 1/2", "constant-acceleration", FIG1_CONSTANT_ACCELERATION)
FIG3 = paper_case("Fig. 3: collision V1 = 0.6, M2 = 2 M1", "rod-collision", FIG3_CASE_ONE)
ULTRA_9 = constant_acceleration("acceleration to V = 1 - 1e-9", 1.0 - 1e-9, 1.0, 0.5)
ULTRA_12 = rod_collision("collision V1 = 1 - 1e-12, equal masses", 1.0 - 1e-12, 0.0, 1.0, 1.0, 1.0, 1.0, 1.0)
HORIZON = constant_acceleration("acceleration with a'_F L0 = 1 - 1e-6", 0.6, 1.0, 1.0 - 1e-6)
SIZES = rod_collision("collision of a 1e-6 rod with a 1e6 rod", 0.5, -0.5, 1e6, 1.0, 1e-6, 1e6, 0.2)
TINY = constant_acceleration("acceleration of a rod of length 1e-6", 0.6, 1e-6, 5e5)
HUGE = constant_acceleration("acceleration of a rod of length 1e6", 0.6, 1e6, 5e-7)

#: The frame of the paper's worked examples for the rod 2 after the ultra-relativistic collision:
#: equal masses, elastic, so rod 2 leaves with V1 (and rod 1 stops dead).
ULTRA_12_ROD2_AFTER = 1.0 - 1e-12


@dataclass(frozen=True)
class BenchCase:
    """One scene seen from one frame at one set of frame times; every method gets exactly these."""

    regime: Regime
    scene: BenchScene
    frame_velocity: float
    frame_name: str
    """The frame's velocity (c = 1), as the methods that take floats get it."""
    spread: TimeSpread = "window"
    quick: bool = False
    """Part of ``rigidrel bench --quick``."""

    @property
    def frame(self) -> rr.Frame:
        """The frame as the core takes it: ``rr.Frame.from_velocity(frame_velocity)``."""
        return rr.Frame.from_velocity(self.frame_velocity)

    @property
    def label(self) -> str:
        times = ", times to 1e6 L0" if self.spread == "long" else ""
        return f"{self.scene.label}; {self.frame_name} frame (beta = {self.frame_velocity:.12g}){times}"


#: Fig. 3's collision in a frame at beta = 0.5 (neither scene frame): also the case of the cost-per-sample curves.
FIG3_BETA_HALF = BenchCase(Regime.ORDINARY, FIG3, 0.5, "custom")

CASES: tuple[BenchCase, ...] = (
    BenchCase(Regime.ORDINARY, FIG1, 0.0, "lab"),
    BenchCase(Regime.ORDINARY, FIG1, 0.6, "rod after", quick=True),
    BenchCase(Regime.ORDINARY, FIG3, 0.0, "lab", quick=True),
    FIG3_BETA_HALF,
    BenchCase(Regime.ULTRA_RELATIVISTIC, ULTRA_9, 0.0, "lab"),
    BenchCase(Regime.ULTRA_RELATIVISTIC, ULTRA_9, 1.0 - 1e-9, "rod after", quick=True),
    BenchCase(Regime.ULTRA_RELATIVISTIC, ULTRA_12, 0.0, "lab"),
    BenchCase(Regime.ULTRA_RELATIVISTIC, ULTRA_12, ULTRA_12_ROD2_AFTER, "rod 2 after", quick=True),
    BenchCase(Regime.NEAR_HORIZON, HORIZON, 0.0, "lab", quick=True),
    BenchCase(Regime.NEAR_HORIZON, HORIZON, 0.6, "rod after"),
    BenchCase(Regime.EXTREME_FRAMES, FIG3, 0.999999, "custom", quick=True),
    BenchCase(Regime.EXTREME_FRAMES, FIG3, -0.999999, "custom"),
    BenchCase(Regime.EXTREME_FRAMES, FIG1, 0.999999, "custom"),
    BenchCase(Regime.LONG_TIMES, FIG1, 0.0, "lab", "long"),
    BenchCase(Regime.LONG_TIMES, FIG1, 0.6, "rod after", "long", quick=True),
    BenchCase(Regime.LONG_TIMES, FIG3, 0.5, "custom", "long"),
    BenchCase(Regime.ROD_SIZES, SIZES, 0.0, "lab"),
    BenchCase(Regime.ROD_SIZES, SIZES, 0.5, "custom", quick=True),
    BenchCase(Regime.ROD_SIZES, TINY, 0.6, "rod after"),
    BenchCase(Regime.ROD_SIZES, HUGE, 0.6, "rod after"),
)


def sample_times(case: BenchCase, n: int) -> FloatArray:
    """``n`` sorted frame times: the frame's named events plus a uniform grid over the event window
    (``"window"``), or geometrically spaced out to +-1e6 rest lengths (``"long"``).

    The core only chooses *where* to look (its event times and window); the values there
    come from each method, and the reference from :mod:`tests.reference.oracle`.
    """
    scene = case.scene.core()
    frame = case.frame
    t0, t1 = scene.time_window(frame=frame)
    events = np.array([t for t, _ in scene.events_in(frame=frame).values()])
    if case.spread == "window":
        grid = np.linspace(t0, t1, max(n - events.size, 2))
    else:
        reach = LONG_TIME_LENGTHS * max(case.scene.rest_lengths)
        near = max(abs(t0), abs(t1))
        half = max((n - events.size) // 2, 1)
        far = np.geomspace(near, reach, half)
        grid = np.concatenate([-far, far])
    return np.unique(np.concatenate([grid, events]))
