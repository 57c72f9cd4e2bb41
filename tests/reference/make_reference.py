"""Generate the 50-digit reference table for rigidrel_core's accuracy tests.

Independent of the core by construction:

* scene solutions follow the paper's own route in mpmath at 50 digits: rapidities via
  ``atanh``, the barycentric velocity ``u = (m1 g1 V1 + m2 g2 V2)/(m1 g1 + m2 g2)``,
  velocity addition ``(V - u)/(1 - u V)`` into and out of the barycentric frame, Eq.
  (epsilon) for the restitution (the core uses proper-velocity algebra in ``decimal``);
* worldlines are the paper's lab formulas, point by point (Eq. (deriv) for constant
  acceleration with each point's own ``a' = 1/(xi + 1/a'_B)``, Eq. (imp) for impulses,
  ``t -> -t`` for deceleration, Eqs. (t12)-(imp12) for collisions);
* a slice at frame time ``t'`` is found by bisection on lab time ``t`` of
  ``gamma (t - beta x(t)) = t'`` (the core never inverts anything: it evaluates closed
  forms in the frame).

The worldlines, scene solutions and frame slices live in :mod:`app.bench.reference` (also
the run-time reference of ``rigidrel bench``); this script picks the cases, frames and
sample times and writes the table. Floats are stored as ``float.hex`` (exact), reference
values as 30-digit strings.

Run from the repository root::

    python -m tests.reference.make_reference      # writes tests/reference/reference.json
"""

from __future__ import annotations

import itertools
import json
import random
import sys
import time
from pathlib import Path
from typing import Any

import mpmath as mp

from app.bench.reference import BUILDERS, F, Mp, RefScene, boost_event, frame_slice

mp.mp.dps = 50
OUT = Path(__file__).with_name("reference.json")
FRACTIONS = (0.0, 0.375, 1.0)


def s(x: Mp) -> str:
    return mp.nstr(x, 30, min_fixed=-mp.inf, max_fixed=mp.inf) if x != 0 else "0"


def sample_times(events_frame: list[Mp], scale: float, rng: random.Random) -> list[float]:
    """Event times, midpoints, points just beside each event, a margin, and +-1e6 lengths away."""
    ts = sorted({float(t) for t in events_frame} | {0.0})
    out = set(ts)
    span = max(ts[-1] - ts[0], scale)
    for a, b in itertools.pairwise(ts):
        out.add(0.5 * (a + b))
        out.add(a + rng.random() * (b - a))
    for t in ts:
        out.add(t + 1e-3 * span)
        out.add(t - 1e-3 * span)
    out.add(ts[0] - 0.5 * span)
    out.add(ts[-1] + 0.5 * span)
    out.add(1e6 * scale)
    out.add(-1e6 * scale)
    return sorted(out)


# ------------------------------------------------------------------ cases
def cases() -> list[dict[str, object]]:
    ca, dec, imp, vc, wall, rod = BUILDERS.keys()
    fixed: list[tuple[str, dict[str, object]]] = [
        # the paper's worked examples
        (ca, {"v": 0.6, "length": 1.0, "a_front": 0.5}),
        (dec, {"v": 0.6, "length": 1.0, "a_front": 0.5}),
        (imp, {"v": 0.6, "length": 1.0}),
        (wall, {"v": 0.6, "length": 1.0, "eps": 0.0}),
        (wall, {"v": 0.6, "length": 1.0, "eps": 0.5}),
        (wall, {"v": 0.6, "length": 1.0, "eps": 1.0}),
        (rod, {"v1": 0.6, "v2": 0.0, "m1": 1.0, "m2": 2.0, "l1": 1.0, "l2": 1.0, "eps": 1.0}),
        (rod, {"v1": 0.6, "v2": 0.0, "m1": 2.0, "m2": 1.0, "l1": 1.0, "l2": 1.0, "eps": 1.0}),
        (rod, {"v1": 0.6, "v2": 0.0, "m1": 1.0, "m2": 2.0, "l1": 1.0, "l2": 1.0, "eps": 0.5}),
        # ultra-relativistic
        (ca, {"v": 1 - 1e-12, "length": 1.0, "a_front": 0.5}),
        (ca, {"v": 1 - 1e-9, "length": 2.5, "a_front": 0.1}),
        (imp, {"v": 1 - 1e-12, "length": 1.0}),
        (wall, {"v": 1 - 1e-12, "length": 1.0, "eps": 1.0}),
        (wall, {"v": 1 - 1e-12, "length": 1.0, "eps": 0.3}),
        (rod, {"v1": 1 - 1e-12, "v2": 0.0, "m1": 1.0, "m2": 1.0, "l1": 1.0, "l2": 1.0, "eps": 1.0}),
        (rod, {"v1": 0.9, "v2": -(1 - 1e-9), "m1": 1.0, "m2": 3.0, "l1": 1.0, "l2": 0.5, "eps": 0.7}),
        (rod, {"v1": 1 - 1e-12, "v2": 1 - 1e-9, "m1": 1.0, "m2": 1.0, "l1": 1.0, "l2": 1.0, "eps": 1.0}),
        # near the horizon, and far from it
        (ca, {"v": 0.6, "length": 1.0, "a_front": 1 - 1e-6}),
        (dec, {"v": 0.8, "length": 1.0, "a_front": 1 - 1e-6}),
        (ca, {"v": 0.6, "length": 1.0, "a_front": 1e-6}),
        # mass ratios and sizes
        (rod, {"v1": 0.6, "v2": 0.0, "m1": 1.0, "m2": 1e6, "l1": 1.0, "l2": 1.0, "eps": 1.0}),
        (rod, {"v1": 0.6, "v2": 0.0, "m1": 1.0, "m2": 1e-6, "l1": 1.0, "l2": 1.0, "eps": 1.0}),
        (rod, {"v1": 0.5, "v2": -0.5, "m1": 1e6, "m2": 1.0, "l1": 1e-6, "l2": 1e6, "eps": 0.2}),
        (rod, {"v1": 0.3, "v2": -0.2, "m1": 1.0, "m2": 1.0, "l1": 1e6, "l2": 1e-6, "eps": 0.0}),
        (ca, {"v": 0.6, "length": 1e-6, "a_front": 2.5e5}),
        (ca, {"v": 0.6, "length": 1e6, "a_front": 2.5e-7}),
        (imp, {"v": 0.9, "length": 1e6}),
        (wall, {"v": 0.4, "length": 1e-6, "eps": 0.6}),
        # general velocity changes
        (vc, {"v_initial": 0.3, "v_final": 0.6, "length": 1.0, "a_front": 0.4}),
        (vc, {"v_initial": 0.6, "v_final": -0.5, "length": 1.0, "a_front": None}),
        (vc, {"v_initial": -0.999999, "v_final": 0.999999, "length": 1.0, "a_front": 0.9}),
        (vc, {"v_initial": 0.5, "v_final": 0.0, "length": 2.0, "a_front": 0.25}),
    ]
    rng = random.Random(20261121)
    out = [{"kind": k, "params": p} for k, p in fixed]

    def speed() -> float:
        return 1.0 - 10.0 ** (-rng.uniform(0.05, 12.0)) if rng.random() < 0.4 else rng.uniform(0.01, 0.99)

    def logu(lo: float, hi: float) -> float:
        return 10.0 ** rng.uniform(lo, hi)

    for _ in range(36):
        kind = rng.choice(list(BUILDERS))
        L = logu(-6, 6)
        if kind in (ca, dec):
            p = {"v": speed(), "length": L, "a_front": (1 - 10 ** -rng.uniform(0.01, 6)) / L}
        elif kind == imp:
            p = {"v": speed(), "length": L}
        elif kind == wall:
            p = {"v": speed(), "length": L, "eps": rng.random()}
        elif kind == vc:
            a, b = sorted([rng.uniform(-1, 1) * speed(), rng.uniform(-1, 1) * speed()])
            if rng.random() < 0.5:
                a, b = b, a
            p = {
                "v_initial": a,
                "v_final": b,
                "length": L,
                "a_front": None if rng.random() < 0.3 else rng.uniform(0.01, 0.999) / L,
            }
        else:
            v1 = rng.uniform(-0.5, 1) * speed()
            v2 = v1 - rng.uniform(0.01, 1) * (1 + v1)
            v2 = max(v2, -1 + 1e-12)
            p = {"v1": v1, "v2": v2, "m1": 1.0, "m2": logu(-6, 6), "l1": L, "l2": L * logu(-2, 2), "eps": rng.random()}
        out.append({"kind": kind, "params": p})
    return out


def frames_for(ref: RefScene, rng: random.Random) -> list[float]:
    betas = [0.0, 0.999999, -0.999999, rng.uniform(-0.9, 0.9)]
    betas += [float(v) for v in ref.final_velocities]  # each rod's rest frame after (to float64)
    if "u" in ref.extra:
        betas.append(float(ref.extra["u"]))
    return list(dict.fromkeys(betas))


def build_case(case: dict[str, object], rng: random.Random) -> dict[str, object]:
    kind = str(case["kind"])
    params: dict[str, Any] = dict(case["params"])  # type: ignore[arg-type]
    ref = BUILDERS[kind](FRACTIONS, **params)
    frames = []
    for beta_f in frames_for(ref, rng):
        beta = F(beta_f)
        ev_frame = {k: boost_event(e, beta) for k, e in ref.events.items()}
        scale = float(max(ref.lengths_rest))
        times = sample_times([e[0] for e in ev_frame.values()], scale, rng)
        exact = [[[frame_slice(w, beta, F(t)) for t in times] for w in rod] for rod in ref.worldlines]
        frames.append(
            {
                "beta": beta_f.hex(),
                "times": [t.hex() for t in times],
                "positions": [[[s(x) for x in pt] for pt in rod] for rod in exact],
                "lengths": [[s(b - a) for a, b in zip(rod[0], rod[-1])] for rod in exact],
                "events": {k: [s(e[0]), s(e[1])] for k, e in ev_frame.items()},
            }
        )
    return {
        "kind": kind,
        "params": {k: (None if v is None else float(v).hex()) for k, v in params.items()},
        "fractions": [f.hex() for f in FRACTIONS],
        "final_velocities": [s(v) for v in ref.final_velocities],
        "final_gaps": [s(1 - abs(v)) for v in ref.final_velocities],
        "extra": {k: s(v) for k, v in ref.extra.items()},
        "events_lab": {k: [s(e[0]), s(e[1])] for k, e in ref.events.items()},
        "frames": frames,
    }


def main() -> None:
    rng = random.Random(7)
    t0 = time.perf_counter()
    table = {
        "generator": "tests/reference/make_reference.py",
        "mp_dps": mp.mp.dps,
        "cases": [],
    }
    all_cases = cases()
    for i, case in enumerate(all_cases):
        table["cases"].append(build_case(case, rng))  # type: ignore[union-attr]
        print(f"{i + 1}/{len(all_cases)} {case['kind']} {time.perf_counter() - t0:.1f}s", file=sys.stderr)
    OUT.write_text(json.dumps(table, indent=None, separators=(",", ":")) + "\n")
    print(f"wrote {OUT} ({OUT.stat().st_size / 1e6:.2f} MB)", file=sys.stderr)


if __name__ == "__main__":
    main()
