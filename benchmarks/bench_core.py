"""Speed of rigidrel_core's position sampler, against bare numpy doing the same amount of work.

    python -m benchmarks.bench_core [--n 1000000] [--repeat 21] [--json]

A script that prints figures, not a test: the machine is shared and noisy, so only the
ratios of one run mean anything. To time another copy of the core with this script, run
it by path with that copy first on the path:
``PYTHONPATH=/other/checkout python benchmarks/bench_core.py`` (the first line says
which ``rigidrel_core`` was imported).

**Target.** ``scene.positions(t, frame=frame)`` for 2 rods x 2 ends at ``n = 1e6`` times costs at
most 2.5x four bare ``np.sqrt(1.0 + t * t)`` passes over ``n`` floats (the baseline: the same
``4n`` outputs, each a square root), in every case:

(a) ``paper``: the paper's Fig. 3 collision (``rr.build_scene("rod-collision")`` defaults) in
    the frame of velocity 0.5, ``n`` sorted times across its ``time_window``; few samples lie
    on a curved piece (the printed fraction), most on straight lines;
(b) ``curved``: two Born-rigid constant accelerations with a small ``a_front`` (two rods of
    one scene), in the same frame, ``n`` sorted times inside [latest start, earliest stop] of
    the 4 ends, so that every sample of every end lies on its hyperbola (fraction printed,
    checked with ``scene.switch_times``): the sampler's most expensive sorted input;
(c) ``shuffled``: a random permutation of (a)'s times, and one of (b)'s times.

Per call (microseconds, no ratio): 256 sorted times in a frame whose plan is cached (target
< 50 us), 256 times in a new frame each call (each call plans a frame never seen before),
1 time in a planned frame (the fixed cost of a call), and building the Fig. 3 scene. These
are absolute, so they move with the machine's load: the header prints its load average.

**Method.** Both sides are warm (each runs untimed first, so their arrays' pages are
mapped and the plan is cached), all inputs are made before timing, the two sides of a
ratio are alternated A, B, A, B, ... ``repeat`` times with the garbage collector off, and
each side's median is reported; a ratio is the ratio of the medians. The clock is this
thread's CPU time (``--clock wall`` for wall time): on a shared machine, time given to
other processes is not counted, though their use of the caches still is.
"""

from __future__ import annotations

import argparse
import gc
import itertools
import json
import os
import statistics
import time
from collections.abc import Callable, Sequence
from dataclasses import replace

import numpy as np
import numpy.typing as npt

import rigidrel_core as rr

FloatArray = npt.NDArray[np.float64]

#: The stated target: positions of 2 rods x 2 ends cost at most this many four-sqrt baselines.
TARGET_RATIO = 2.5
#: The stated target for 256 times in a planned frame, microseconds.
TARGET_256_US = 50.0
#: The frame of cases (a) to (c): velocity 0.5 relative to the lab (a boosted frame, as this benchmark always used).
FRAME_BETA = 0.5


def paper_case(n: int) -> tuple[rr.Scene, rr.Frame, FloatArray]:
    """Case (a): Fig. 3's collision, ``n`` sorted times across its time window in the boosted frame."""
    scene = rr.build_scene("rod-collision")
    frame = rr.Frame.from_velocity(FRAME_BETA)
    return scene, frame, np.linspace(*scene.time_window(frame=frame), n)


def curved_case(n: int) -> tuple[rr.Scene, rr.Frame, FloatArray]:
    """Case (b): two accelerating rods (one scene), ``n`` sorted times while all 4 ends are on hyperbolas.

    A small ``a_front`` makes each change last long (lab ``T_F = gamma v / a_front``, about 40);
    the times run from just after the latest start to just before the earliest stop.
    """
    first = rr.constant_acceleration(v=0.9, length=1.0, a_front=0.05)
    second = rr.constant_acceleration(v=0.8, length=1.5, a_front=0.04)
    scene = replace(first, rods=first.rods + second.rods)
    frame = rr.Frame.from_velocity(FRAME_BETA)
    switch = scene.switch_times(frame=frame).reshape(-1, 2)
    start, stop = float(switch[:, 0].max()), float(switch[:, 1].min())
    pad = 1e-6 * (stop - start)
    return scene, frame, np.linspace(start + pad, stop - pad, n)


def curved_fraction(scene: rr.Scene, frame: rr.Frame, t: FloatArray) -> float:
    """Share of (end, time) samples on a curved piece: ``start <= t <= stop`` of that end (``switch_times``)."""
    switch = scene.switch_times(frame=frame).reshape(-1, 2)
    on = [np.count_nonzero((t >= a) & (t <= b)) for a, b in switch.tolist()]
    return sum(on) / (len(on) * t.size)


#: The clock of every figure; ``--clock wall`` switches to ``time.perf_counter``.
CLOCKS: dict[str, Callable[[], float]] = {"cpu": time.thread_time, "wall": time.perf_counter}
clock_name = "cpu"
clock = CLOCKS[clock_name]


def alternated(a: Callable[[], object], b: Callable[[], object], repeat: int, number: int = 1) -> tuple[float, float]:
    """Median seconds per call of ``a`` and of ``b``, timed A, B, A, B, ... after one warm-up call of each."""
    a()
    b()
    times_a: list[float] = []
    times_b: list[float] = []
    gc_was_enabled = gc.isenabled()
    gc.disable()
    try:
        for _ in range(repeat):
            for fn, times in ((a, times_a), (b, times_b)):
                t0 = clock()
                for _ in range(number):
                    fn()
                times.append((clock() - t0) / number)
    finally:
        if gc_was_enabled:
            gc.enable()
    return statistics.median(times_a), statistics.median(times_b)


def per_call(fn: Callable[[], object], repeat: int, number: int) -> float:
    """Median seconds per call of ``fn`` over ``repeat`` loops of ``number`` calls, after one warm-up loop."""
    times = []
    gc_was_enabled = gc.isenabled()
    gc.disable()
    try:
        for _ in range(repeat + 1):
            t0 = clock()
            for _ in range(number):
                fn()
            times.append((clock() - t0) / number)
    finally:
        if gc_was_enabled:
            gc.enable()
    return statistics.median(times[1:])


def run(n: int = 1_000_000, repeat: int = 21) -> dict[str, float]:
    """Every figure of the benchmark, in the order printed."""
    paper, frame_a, t_a = paper_case(n)
    curved, frame_b, t_b = curved_case(n)
    rng = np.random.default_rng(0)
    cases: Sequence[tuple[str, rr.Scene, rr.Frame, FloatArray]] = (
        ("a_paper", paper, frame_a, t_a),
        ("b_curved", curved, frame_b, t_b),
        ("c_shuffled_a", paper, frame_a, rng.permutation(t_a)),
        ("c_shuffled_b", curved, frame_b, rng.permutation(t_b)),
    )

    def baseline(t: FloatArray) -> Callable[[], object]:
        def four_sqrt_passes() -> None:
            for _ in range(4):
                np.sqrt(1.0 + t * t)

        return four_sqrt_passes

    figures: dict[str, float] = {"n_times": float(n), "rows": 4.0, "repeat": float(repeat)}
    figures["load_average_before"] = os.getloadavg()[0]
    for name, scene, frame, t in cases:
        assert scene.positions(t[:1], frame=frame).shape == (2, 2, 1)  # 2 rods x 2 ends: the same 4n outputs
        base, sampled = alternated(baseline(t), lambda s=scene, f=frame, tt=t: s.positions(tt, frame=f), repeat)
        figures[f"{name}_curved_fraction"] = curved_fraction(scene, frame, t)
        figures[f"{name}_baseline_ms"] = base * 1e3
        figures[f"{name}_positions_ms"] = sampled * 1e3
        figures[f"{name}_ratio"] = sampled / base

    t256 = np.linspace(*paper.time_window(frame=frame_a), 256)
    t1 = np.array([0.25])
    fresh = [rr.Frame.from_velocity(float(b)) for b in np.linspace(-0.9, 0.9, 20_001)]
    frames = itertools.cycle(fresh)  # the plan cache holds at most 64 frames: each call plans anew
    figures["calls_256_times_planned_frame_us"] = per_call(lambda: paper.positions(t256, frame=frame_a), 15, 1000) * 1e6
    figures["calls_256_times_new_frame_us"] = (
        per_call(lambda: paper.positions(t256, frame=next(frames)), 15, 1000) * 1e6
    )
    figures["calls_1_time_planned_frame_us"] = per_call(lambda: paper.positions(t1, frame=frame_a), 15, 2000) * 1e6
    figures["scene_construction_us"] = per_call(lambda: rr.build_scene("rod-collision"), 9, 100) * 1e6
    figures["load_average_after"] = os.getloadavg()[0]
    return figures


def table(figures: dict[str, float]) -> str:
    """The figures as a compact table, with each target's verdict."""
    n = int(figures["n_times"])
    lines = [
        f"rigidrel_core: {rr.__file__}",
        f"numpy {np.__version__}; n = {n} times, 2 rods x 2 ends; "
        f"{int(figures['repeat'])} alternated pairs, warm, medians of {clock_name} time",
        f"load average (1 min) {figures['load_average_before']:.2f} before, {figures['load_average_after']:.2f} after "
        f"on {os.cpu_count()} cores: other processes share the caches",
        "",
        f"{'case':30s} {'curved':>7s} {'4 sqrt ms':>10s} {'positions ms':>13s} {'ratio':>6s}  target <= {TARGET_RATIO}",
    ]
    labels = {
        "a_paper": "(a) paper, Fig. 3, beta 0.5",
        "b_curved": "(b) all on curved pieces",
        "c_shuffled_a": "(c) shuffled times of (a)",
        "c_shuffled_b": "(c) shuffled times of (b)",
    }
    for key, label in labels.items():
        ratio = figures[f"{key}_ratio"]
        lines.append(
            f"{label:30s} {100 * figures[f'{key}_curved_fraction']:6.1f}% {figures[f'{key}_baseline_ms']:10.2f} "
            f"{figures[f'{key}_positions_ms']:13.2f} {ratio:6.2f}  {'met' if ratio <= TARGET_RATIO else 'MISSED'}"
        )
    small = figures["calls_256_times_planned_frame_us"]
    new = figures["calls_256_times_new_frame_us"]
    lines += [
        "",
        f"{'per call':45s} {'us':>8s}",
        f"{'256 times, planned frame':45s} {small:8.1f}  target < {TARGET_256_US:g}: "
        f"{'met' if small < TARGET_256_US else 'MISSED'}",
        f"{'256 times, a new frame each call':45s} {new:8.1f}  (planning adds {new - small:.1f})",
        f"{'1 time, planned frame (fixed cost)':45s} {figures['calls_1_time_planned_frame_us']:8.1f}",
        f"{'scene construction (Fig. 3 defaults)':45s} {figures['scene_construction_us']:8.1f}",
    ]
    return "\n".join(lines)


def main() -> None:
    parser = argparse.ArgumentParser(description="Speed of rigidrel_core's position sampler (ratios in one run).")
    parser.add_argument("--n", type=int, default=1_000_000, help="times per call in cases (a) to (c)")
    parser.add_argument("--repeat", type=int, default=21, help="alternated pairs per case")
    parser.add_argument("--json", action="store_true", help="print the figures as JSON instead of a table")
    parser.add_argument(
        "--clock", choices=sorted(CLOCKS), default="cpu", help="this thread's CPU time (default) or wall time"
    )
    args = parser.parse_args()
    global clock, clock_name
    clock_name, clock = args.clock, CLOCKS[args.clock]
    figures = run(args.n, args.repeat)
    print(json.dumps(figures, indent=2) if args.json else table(figures))


if __name__ == "__main__":
    main()
