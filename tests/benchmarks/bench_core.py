"""Speed of rigidrel_core's samplers, as ratios measured in one run (not a test: machines are noisy).

    python -m tests.benchmarks.bench_core [--n 1000000] [--repeat 15]

Prints, for 2 rods (4 ends) in a boosted frame:
* 1e6 sorted times: time per call, and its ratio to four bare ``np.sqrt(1.0 + t*t)``
  passes over 1e6 floats (target <= 2.5);
* the same 1e6 times shuffled (the branch-free path);
* 256 times: microseconds per call (target < 50 us);
* scene construction (the 60-digit scalar solution) and a new frame's plan.
"""

from __future__ import annotations

import argparse
import json
import timeit
from collections.abc import Callable

import numpy as np

import rigidrel_core as rr


def best(fn: Callable[[], object], repeat: int, number: int = 1) -> float:
    return min(timeit.repeat(fn, number=number, repeat=repeat)) / number


def run(n: int = 1_000_000, repeat: int = 15) -> dict[str, float]:
    scene = rr.rod_collision(v1=0.6, v2=-0.3, m1=1.0, m2=2.0, l1=1.0, l2=1.5, eps=0.8)
    frame = rr.Frame.from_velocity(0.5)
    t0, t1 = scene.time_window(frame)
    t = np.linspace(t0, t1, n)
    shuffled = np.random.default_rng(0).permutation(t)
    t256 = np.linspace(t0, t1, 256)
    scene.positions(t256, frame)  # plan for this frame, once

    def baseline() -> None:
        for _ in range(4):
            np.sqrt(1.0 + t * t)

    base = best(baseline, repeat)
    sorted_s = best(lambda: scene.positions(t, frame), repeat)
    shuffled_s = best(lambda: scene.positions(shuffled, frame), max(3, repeat // 3))
    small = best(lambda: scene.positions(t256, frame), 7, number=2000)
    build = best(lambda: rr.rod_collision(0.6, -0.3, 1.0, 2.0, 1.0, 1.5, 0.8), 7, number=50)
    fresh = iter(np.linspace(-0.9, 0.9, 10_000))
    new_frame = best(lambda: scene.positions(t256, rr.Frame.from_velocity(float(next(fresh)))), 5, number=200)
    return {
        "n_times": float(n),
        "baseline_4_sqrt_passes_ms": base * 1e3,
        "positions_sorted_ms": sorted_s * 1e3,
        "ratio_sorted_to_baseline": sorted_s / base,
        "positions_shuffled_ms": shuffled_s * 1e3,
        "ratio_shuffled_to_baseline": shuffled_s / base,
        "positions_256_times_us": small * 1e6,
        "positions_256_times_new_frame_us": new_frame * 1e6,
        "scene_construction_us": build * 1e6,
    }


def main() -> None:
    parser = argparse.ArgumentParser(description="Speed of rigidrel_core's samplers (ratios in one run).")
    parser.add_argument("--n", type=int, default=1_000_000)
    parser.add_argument("--repeat", type=int, default=15)
    parser.add_argument("--json", action="store_true")
    args = parser.parse_args()
    figures = run(args.n, args.repeat)
    if args.json:
        print(json.dumps(figures, indent=2))
        return
    for k, v in figures.items():
        print(f"{k:36s} {v:12.3f}")


if __name__ == "__main__":
    main()
