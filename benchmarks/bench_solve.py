"""Per-scene solve and construction times, before and after, in one run (not a test: machines are noisy).

    python -m benchmarks.bench_solve [--repeat 41] [--number 200] [--baseline REV] [--only TEXT]
                                           [--clock cpu|wall] [--json] [--profile]

"Before" is ``rigidrel_core`` as of git revision ``--baseline`` (default: the last revision that
solved scenes in 60-digit ``decimal``), unpacked with ``git archive`` into a temporary directory
and imported as ``rigidrel_core_baseline`` beside today's ``rigidrel_core``. Both are warmed up,
then timed in alternation (one block of ``--number`` calls of every case per round, ``--repeat``
rounds), and the median over the rounds of each block's mean is printed, in microseconds. The
clock is this thread's CPU time (``--clock wall`` for wall time): on a shared machine, time given
to other processes is not counted, though their use of the caches still is.

* solve: a scene's scalar solution without the Scene object, its frame presets and checks:
  ``solve_collision`` for the collision (the target: under 10 us; the paper's defaults, the benchmark
  collision and :data:`EXTRA_COLLISIONS`); the bounce's velocity and heat
  plus ``rigid_motion`` for the wall; ``near_radius`` plus ``rigid_motion`` for the accelerations;
  ``rigid_motion`` for the impulse;
* build: ``rr.build_scene(kind)`` with the paper's defaults, and ``rr.rod_collision(0.6, -0.3,
  1.0, 2.0, 1.0, 1.5, 0.8)`` (the benchmark collision of ``bench_core``).

``--profile`` adds a cProfile of today's collision construction (functions by own time).
"""

from __future__ import annotations

import argparse
import cProfile
import importlib
import io
import json
import os
import pstats
import statistics
import subprocess
import sys
import tarfile
import tempfile
import time
import timeit
from collections.abc import Callable
from pathlib import Path
from types import ModuleType
from typing import Any

import rigidrel_core as rr

#: The last revision whose scenes were solved in 60-digit decimal.
DECIMAL_REVISION = "e1aa9d5"
BASELINE_NAME = "rigidrel_core_baseline"
#: The benchmark collision of bench_core: v1, v2, mass1, mass2, length1, length2, eps.
COLLISION = (0.6, -0.3, 1.0, 2.0, 1.0, 1.5, 0.8)

#: The other collisions of the speed-accuracy bench and its stability map (v1, v2, m1, m2, eps):
#: near light, lopsided sizes, and the light-cone branches of the solution.
EXTRA_COLLISIONS = {
    "V1 = 1 - 1e-12, equal masses": (1.0 - 1e-12, 0.0, 1.0, 1.0, 1.0),
    "0.5, -0.5, M1 = 1e6 M2, eps 0.2": (0.5, -0.5, 1e6, 1.0, 0.2),
    "V1 = 0.99, M2 = 2 M1": (0.99, 0.0, 1.0, 2.0, 1.0),
    "V1 = 1 - 1e-9, M2 = 2 M1": (1.0 - 1e-9, 0.0, 1.0, 2.0, 1.0),
    "1 - 1e-9, -(1 - 1e-7), M2 = 100 M1, eps 0.7": (0.999999999, -0.9999999, 1.0, 100.0, 0.7),
}

Case = Callable[[], object]


def load_baseline(revision: str, into: Path) -> ModuleType | None:
    """``rigidrel_core`` as of ``revision``, imported as :data:`BASELINE_NAME` (None without git)."""
    root = Path(__file__).resolve().parents[1]  # the checkout: benchmarks/ is top-level
    try:
        archive = subprocess.run(
            ["git", "-C", str(root), "archive", revision, "rigidrel_core"], capture_output=True, check=True
        ).stdout
    except (OSError, subprocess.CalledProcessError) as exc:
        print(f"no baseline ({exc}); timing today's code only", file=sys.stderr)
        return None
    with tarfile.open(fileobj=io.BytesIO(archive)) as tar:
        tar.extractall(into, filter="data")
    (into / "rigidrel_core").rename(into / BASELINE_NAME)
    sys.path.insert(0, str(into))
    return importlib.import_module(BASELINE_NAME)


def _zero_radius(core: ModuleType) -> object:
    """The near radius of an impulse: ``IMPULSE`` today, ``Decimal(0)`` in the decimal route."""
    build = importlib.import_module(f"{core.__name__}._build")
    if hasattr(build, "IMPULSE"):
        return build.IMPULSE
    from decimal import Decimal

    return Decimal(0)


def _wall_solution(core: ModuleType, v: float, eps: float, mass: float) -> tuple[Any, Any]:
    """The wall's velocity after and heat: ``bounce`` today; the decimal route's inline block before."""
    wall = importlib.import_module(f"{core.__name__}.scenes.wall")
    if hasattr(wall, "bounce"):
        return wall.bounce(v, eps, mass)
    from decimal import Decimal

    exact = importlib.import_module(f"{core.__name__}._exact")
    build = importlib.import_module(f"{core.__name__}._build")
    with build.decimal_context():  # the decimal route's wall_collision, verbatim
        dv = Decimal(v)
        gamma = exact.lorentz_factor_decimal(dv)
        u_after = Decimal(eps) * gamma * dv
        v_after = exact.velocity_from_proper_velocity(u_after)
        heat = Decimal(mass) * (gamma - (1 + u_after * u_after).sqrt())
    return v_after, heat


def cases(core: ModuleType) -> dict[str, Case]:
    """Every scene kind's solve and build, for one version of the core."""
    build = importlib.import_module(f"{core.__name__}._build")
    exact = importlib.import_module(f"{core.__name__}._exact")
    collision = importlib.import_module(f"{core.__name__}.scenes.collision")
    acceleration = importlib.import_module(f"{core.__name__}.scenes.acceleration")
    rest, velocity = exact.REST, exact.ExactVelocity.from_float
    rigid, near = build.rigid_motion, build.near_radius
    zero = _zero_radius(core)
    impulse_allowed = acceleration._IMPULSIVE_ALLOWED
    descriptions = core.scene_descriptions()
    d = {k: desc.defaults() for k, desc in descriptions.items()}

    def solve_constant() -> object:
        p = d["constant-acceleration"]
        return rigid(rest, velocity(p["v"]), p["length"], near(p["a_front"], p["length"]), 0.0)

    def solve_deceleration() -> object:
        p = d["deceleration"]
        return rigid(velocity(-p["v"]), rest, p["length"], near(p["a_front"], p["length"]), 0.0)

    def solve_velocity_change() -> object:
        p = d["velocity-change"]
        rho = near(p["a_front"], p["length"], impulse_allowed)
        return rigid(velocity(p["v_initial"]), velocity(p["v_final"]), p["length"], rho, 0.0)

    def solve_impulse() -> object:
        p = d["impulsive-start"]
        return rigid(rest, velocity(p["v"]), p["length"], zero, 0.0)

    def solve_wall() -> object:
        p = d["wall-collision"]
        after, _ = _wall_solution(core, p["v"], p["eps"], p["mass"])
        return rigid(velocity(-p["v"]), after, p["length"], zero, 0.0)

    p = d["rod-collision"]
    # the paper's defaults; the masses were named m1, m2 before the parameters took one name per quantity
    defaults = (p["v1"], p["v2"], *((p["mass1"], p["mass2"]) if "mass1" in p else (p["m1"], p["m2"])), p["eps"])

    def solve_default_collision() -> object:
        return collision.solve_collision(*defaults)

    v1, v2, m1, m2, _, _, eps = COLLISION
    out: dict[str, Case] = {
        "constant-acceleration solve": solve_constant,
        "deceleration solve": solve_deceleration,
        "velocity-change solve": solve_velocity_change,
        "impulsive-start solve": solve_impulse,
        "wall-collision solve": solve_wall,
        "rod-collision solve (defaults)": solve_default_collision,
        "rod-collision solve (0.6, -0.3, eps 0.8)": lambda: collision.solve_collision(v1, v2, m1, m2, eps),
    }
    for label, args in EXTRA_COLLISIONS.items():
        out[f"rod-collision solve ({label})"] = lambda args=args: collision.solve_collision(*args)
    for kind in descriptions:
        out[f"{kind} build"] = lambda kind=kind: core.build_scene(kind)
    out["rod-collision build (0.6, -0.3, eps 0.8)"] = lambda: core.rod_collision(*COLLISION)
    return out


def run(
    repeat: int = 41,
    number: int = 200,
    baseline: str | None = DECIMAL_REVISION,
    only: str = "",
    clock: Callable[[], float] = time.thread_time,
) -> dict[str, dict[str, float]]:
    """Median microseconds per call of every case (whose name contains ``only``), ``{"after": ..., "before": ...}``."""
    with tempfile.TemporaryDirectory() as tmp:
        versions = {"after": cases(rr)}
        old = load_baseline(baseline, Path(tmp)) if baseline else None
        if old is not None:
            versions["before"] = cases(old)
        versions = {v: {k: fn for k, fn in c.items() if only in k} for v, c in versions.items()}
        for version in versions.values():  # warm-up: imports, registries, caches
            for fn in version.values():
                for _ in range(max(10, number // 10)):
                    fn()
        samples: dict[str, dict[str, list[float]]] = {v: {k: [] for k in c} for v, c in versions.items()}
        for _ in range(repeat):
            for name in versions["after"]:
                for v, c in versions.items():
                    if name in c:  # a scene the baseline did not have yet is timed today only
                        samples[v][name].append(timeit.Timer(c[name], timer=clock).timeit(number) / number * 1e6)
    return {v: {k: statistics.median(s) for k, s in by_case.items() if s} for v, by_case in samples.items()}


def profile_collision(n: int = 2000, top: int = 18) -> str:
    """cProfile of ``n`` collision constructions today, by own time."""
    rr.rod_collision(*COLLISION)
    prof = cProfile.Profile()
    prof.enable()
    for _ in range(n):
        rr.rod_collision(*COLLISION)
    prof.disable()
    out = io.StringIO()
    pstats.Stats(prof, stream=out).sort_stats("tottime").print_stats(top)
    return out.getvalue()


def main() -> None:
    parser = argparse.ArgumentParser(description="Per-scene solve and construction, before and after (one run).")
    parser.add_argument("--repeat", type=int, default=41, help="rounds; the median over them is reported")
    parser.add_argument("--number", type=int, default=200, help="calls per timed block")
    parser.add_argument("--baseline", default=DECIMAL_REVISION, help="git revision timed as 'before' ('' for none)")
    parser.add_argument("--only", default="", help="time only the cases whose name contains this")
    parser.add_argument("--clock", choices=("cpu", "wall"), default="cpu", help="this thread's CPU time, or wall time")
    parser.add_argument("--json", action="store_true")
    parser.add_argument("--profile", action="store_true", help="add a cProfile of today's collision construction")
    args = parser.parse_args()
    clock = time.thread_time if args.clock == "cpu" else time.perf_counter
    print(f"load average (1 min) {os.getloadavg()[0]:.2f} on {os.cpu_count()} cores; clock: {args.clock}")
    figures = run(args.repeat, args.number, args.baseline or None, args.only, clock)
    if args.json:
        print(json.dumps(figures, indent=2))
    else:
        after, before = figures["after"], figures.get("before", {})
        print(f"{'median us per call':44s} {'before':>9s} {'after':>9s} {'ratio':>7s}")
        for name, t in after.items():
            b = before.get(name)
            was, ratio = (f"{b:9.2f}", f"{b / t:6.2f}x") if b is not None else ("-", "")
            print(f"{name:44s} {was:>9s} {t:9.2f} {ratio:>7s}")
    if args.profile:
        print(profile_collision(), file=sys.stderr if args.json else sys.stdout)


if __name__ == "__main__":
    main()
