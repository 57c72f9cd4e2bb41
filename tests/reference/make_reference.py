"""Generate the 50-digit reference table for rigidrel_core's accuracy tests.

Independent of the core by construction: the scenes are those of
:mod:`rigidrel_app.bench.reference` (one module per scene family; it never imports
rigidrel_core), which solves each scene by the paper's own route in mpmath at 50 digits,
follows the paper's lab formulas point by point and finds a slice at frame time ``t'`` by
bisection on lab time ``t`` of ``gamma (t - beta x(t)) = t'`` (the core never inverts
anything: it evaluates closed forms in the frame). That package is also the run-time
reference of ``rigidrel bench``.

This script knows no scene: it takes every scene family's fixed cases (in their ``order``),
then draws :data:`RANDOM_CASES` more from one seeded stream (each draw picks a kind in
teaching order and lets that kind draw its parameters), picks the frames (the lab,
``beta = +-0.999999``, one random frame, each rod's rest frame after and the barycentric
frame) and sample times, and writes the table. Floats are stored as ``float.hex`` (exact),
reference values as 30-digit strings. Adding a scene family to the reference package
changes the random stream, hence the table: regenerate it.

Run from the repository root (a few minutes)::

    python -m tests.reference.make_reference                  # writes tests/reference/reference.json
    python -m tests.reference.make_reference --out /tmp/r.json  # elsewhere, e.g. to compare
"""

from __future__ import annotations

import argparse
import itertools
import json
import random
import sys
import time
from pathlib import Path
from typing import Any

import mpmath as mp

from rigidrel_app.bench.reference import (
    BUILDERS,
    REFERENCE_DIGITS,
    REFERENCES,
    F,
    Mp,
    RefScene,
    boost_event,
    frame_slice,
    reference_precision,
)

OUT = Path(__file__).with_name("reference.json")
FRACTIONS = (0.0, 0.375, 1.0)
#: Random cases after the fixed ones, and the seed of the stream they are drawn from.
RANDOM_CASES = 36
CASES_SEED = 20261121
#: The seed of the stream the frames and sample times are drawn from, case after case.
FRAMES_SEED = 7


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
    """Every scene family's fixed cases by ``order``, then :data:`RANDOM_CASES` drawn cases."""
    fixed = sorted((c for r in REFERENCES.values() for c in r.cases), key=lambda c: c.order)
    orders = [c.order for c in fixed]
    if len(set(orders)) != len(orders):
        raise ValueError(f"two reference cases share an order: {orders}")
    out: list[dict[str, object]] = [{"kind": c.kind, "params": dict(c.params)} for c in fixed]
    rng = random.Random(CASES_SEED)
    drawn = [r for r in REFERENCES.values() if r.draw is not None]
    for _ in range(RANDOM_CASES):
        ref = rng.choice(drawn)
        assert ref.draw is not None
        out.append({"kind": ref.kind, "params": ref.draw(rng)})
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
    with reference_precision():
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


def main(argv: list[str] | None = None) -> None:
    parser = argparse.ArgumentParser(
        prog="python -m tests.reference.make_reference", description=(__doc__ or "").splitlines()[0]
    )
    parser.add_argument("--out", type=Path, default=OUT, help=f"where to write the table (default: {OUT})")
    out: Path = parser.parse_args(argv).out
    rng = random.Random(FRAMES_SEED)
    t0 = time.perf_counter()
    all_cases = cases()
    built = []
    for i, case in enumerate(all_cases):
        built.append(build_case(case, rng))
        print(f"{i + 1}/{len(all_cases)} {case['kind']} {time.perf_counter() - t0:.1f}s", file=sys.stderr)
    table = {"generator": "tests/reference/make_reference.py", "mp_dps": REFERENCE_DIGITS, "cases": built}
    out.write_text(json.dumps(table, indent=None, separators=(",", ":")) + "\n")
    print(f"wrote {out} ({out.stat().st_size / 1e6:.2f} MB)", file=sys.stderr)


if __name__ == "__main__":
    main()
