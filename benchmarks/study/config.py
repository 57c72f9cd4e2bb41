"""How much a bench run measures: the full run (committed to assets/bench), ``--quick``, and a smoke run."""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Literal

from .methods import MethodSetting
from .runner import Timing, method_settings
from .scenes import CASES, BenchCase

RunName = Literal["full", "quick", "smoke"]


@dataclass(frozen=True)
class BenchConfig:
    """Everything that differs between runs; the methods, metric and scenes are always the same."""

    name: RunName
    samples: int
    """Frame times per case (the same for every method)."""
    quick_cases_only: bool
    rk45_rtols: tuple[float, ...]
    dop853_rtols: tuple[float, ...]
    vertex_counts: tuple[int, ...]
    timing: Timing
    map_velocity_digits: tuple[float, ...]
    """Stability map speeds ``V = 1 - 10^-k``."""
    map_frame_digits: tuple[float, ...]
    """Stability map frames ``beta = 0, +-(1 - 10^-k)``."""
    map_samples: int
    map_rtol: float
    """solve_ivp (DOP853) tolerance on the stability map."""
    map_vertices: int
    """spacetimelib vertices per hyperbola on the stability map."""
    sampling_fixed_counts: tuple[int, ...]
    sampling_repeats: int
    sampling_render_repeats: int
    """Browser (kaleido) renders per drawing for the redraw time; 0: skip."""
    sampling_scenes: int
    throughput_counts: tuple[int, ...]
    """Samples per call for the cost-per-sample curves."""
    throughput_max_call_seconds: float

    def cases(self) -> tuple[BenchCase, ...]:
        return tuple(c for c in CASES if c.quick or not self.quick_cases_only)

    def settings(self) -> tuple[MethodSetting, ...]:
        return method_settings(self.rk45_rtols, self.dop853_rtols, self.vertex_counts)

    def map_settings(self) -> tuple[MethodSetting, ...]:
        """One setting per method for the stability map."""
        return method_settings((), (self.map_rtol,), (self.map_vertices,))

    def throughput_settings(self) -> tuple[MethodSetting, ...]:
        """One middle setting per method for the cost-per-sample curves."""
        return method_settings((1e-6,), (1e-9,), (1000,))


_RTOLS_FULL = tuple(10.0**-k for k in range(3, 13))
#: ``V = 1/2`` and ``beta = 1/2`` exactly: ``1 - 10^-log10(2)``.
_HALF = math.log10(2.0)

FULL = BenchConfig(
    name="full",
    samples=256,
    quick_cases_only=False,
    rk45_rtols=_RTOLS_FULL,
    dop853_rtols=_RTOLS_FULL,
    vertex_counts=(10, 30, 100, 300, 1000, 3000, 10_000, 30_000, 100_000),
    timing=Timing(min_repeats=3, max_repeats=5000, min_seconds=0.2, max_seconds=2.0),
    map_velocity_digits=(_HALF, 0.5, 1.0, 1.5, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 9.0, 10.0, 11.0, 12.0),
    map_frame_digits=(_HALF, 1.0, 2.0, 3.0, 4.0, 6.0, 8.0, 10.0),
    map_samples=16,
    map_rtol=1e-12,
    map_vertices=1000,
    sampling_fixed_counts=(16, 32, 64, 128, 256, 512, 1024, 2048, 4096, 8192),
    sampling_repeats=7,
    sampling_render_repeats=5,
    sampling_scenes=4,
    throughput_counts=(16, 64, 256, 1024, 4096, 16_384, 65_536, 262_144, 1_048_576),
    throughput_max_call_seconds=1.0,
)

QUICK = BenchConfig(
    name="quick",
    samples=32,
    quick_cases_only=True,
    rk45_rtols=(1e-3, 1e-6, 1e-9),
    dop853_rtols=(1e-6, 1e-9, 1e-12),
    vertex_counts=(10, 100, 1000),
    timing=Timing(min_repeats=3, max_repeats=200, min_seconds=0.01, max_seconds=0.3),
    map_velocity_digits=(_HALF, 1.0, 3.0, 6.0, 9.0, 12.0),
    map_frame_digits=(1.0, 3.0, 6.0),
    map_samples=12,
    map_rtol=1e-12,
    map_vertices=1000,
    sampling_fixed_counts=(16, 64, 256, 1024, 4096),
    sampling_repeats=3,
    sampling_render_repeats=1,
    sampling_scenes=4,
    throughput_counts=(16, 256, 4096, 65_536),
    throughput_max_call_seconds=0.1,
)

#: For the CLI test: every stage and output, as little work as possible.
SMOKE = BenchConfig(
    name="smoke",
    samples=12,
    quick_cases_only=True,
    rk45_rtols=(1e-4,),
    dop853_rtols=(1e-8,),
    vertex_counts=(10, 100),
    timing=Timing(min_repeats=1, max_repeats=2, min_seconds=0.0, max_seconds=0.05),
    map_velocity_digits=(_HALF, 9.0),
    map_frame_digits=(6.0,),
    map_samples=6,
    map_rtol=1e-8,
    map_vertices=100,
    sampling_fixed_counts=(16, 256),
    sampling_repeats=1,
    sampling_render_repeats=0,
    sampling_scenes=1,
    throughput_counts=(16, 256),
    throughput_max_call_seconds=0.01,
)
