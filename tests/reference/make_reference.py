"""Generate the 50-digit reference table for rigidrel_core's accuracy tests.

Independent of the core by construction: the scenes are those of
:mod:`tests.reference.oracle` (one module per scene family; it never imports
rigidrel_core), which solves each scene by the paper's own route in mpmath at 50 digits,
follows the paper's lab formulas point by point and finds a slice at frame time ``t'`` by
bisection on lab time ``t`` of ``gamma (t - beta x(t)) = t'`` (the core never inverts
anything: it evaluates closed forms in the frame). At that lab time it also reads each
point's clock, its proper time ``tau(t)`` integrated in the lab (0 where the point starts
changing velocity). That package is also the run-time reference of ``rigidrel bench``.

This script knows no scene: it takes every scene family's fixed cases (in their ``order``:
the paper's examples, ultra-relativistic speeds, near and far from the horizon, mass ratios
and sizes, velocity changes, weak accelerations ``a'_F L0 = 1e-3 .. 1e-7``), then draws
:data:`RANDOM_CASES` more from one seeded stream (each draw picks a kind in teaching order and
lets that kind draw its parameters), then the groups added later, each after all before it:
the paradoxes, and the paradoxes at small speeds (``V = 1e-6``, ``1e-3``, Bell's string breaking
at strains down to ``1e-12``). It picks the frames (:func:`frames_for`: the lab, one random
frame, ``beta = +-0.999999``, ``+-(1 - 1e-7)``, ``+-(1 - 1e-9)``, each rod's rest frame before
and after, frames a rapidity of :data:`HAIR` either side of those, the barycentric frame) and
sample times (:func:`sample_times`; fewer for the random cases in the frames added with the
clocks, to keep the table near 6 MB), and writes the table.

Per case: kind, group, parameters, material fractions, rest lengths, final velocities and
their gaps to light speed, derived numbers, the lab events, and the lab arrival of a light
signal from the origin and from each named event at every material point (``"signals_lab"``,
:func:`~tests.reference.oracle.signal_arrival`; a frame's arrival is the boosted one);
per frame: its velocity and role, the sample times, and at each time the positions and clock
readings (``"proper_times"``) of every material point, each rod's end-to-end equal-time length,
and the events seen there.
Floats are stored as ``float.hex`` (exact), reference values as 30-digit strings. One stream
draws every case's frames and times in table order, so a case added before others shifts theirs
(a velocity change at ``a'_F = 1e-7`` once exceeded its bound when it did): add a case in a group
whose ``order`` follows every existing one (at or after :data:`AFTER_RANDOM`), so that the stream
reaches it last and every earlier case keeps its frames and times; ``--append`` then builds only
it, after replaying the stream through the committed cases and checking each replays its own.
A new scene family's random draws still change the stream: regenerate the table then.

Run from the repository root (about 8 minutes)::

    python -m tests.reference.make_reference                  # writes tests/reference/reference.json
    python -m tests.reference.make_reference --append         # only the cases the table lacks (the same result)
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

from tests.reference.oracle import (
    BUILDERS,
    PARADOXES,
    REFERENCE_DIGITS,
    REFERENCES,
    F,
    Mp,
    ReferenceCase,
    RefScene,
    boost_event,
    frame_slice_and_clock,
    reference_precision,
    signal_arrival,
)

OUT = Path(__file__).with_name("reference.json")
FRACTIONS = (0.0, 0.375, 1.0)
#: Random cases after the fixed ones, and the seed of the stream they are drawn from.
RANDOM_CASES = 36
CASES_SEED = 20261121
#: The seed of the stream the frames and sample times are drawn from, case after case.
FRAMES_SEED = 7
#: Fixed frames of every case: ``+-(1 - 10^-6)``, ``+-(1 - 10^-7)``, ``+-(1 - 10^-9)``.
FAST_FRAMES = (0.999999, -0.999999, 1 - 1e-7, -(1 - 1e-7), 1 - 1e-9, -(1 - 1e-9))
#: A frame "a hair off" a rod's rest frame: this much rapidity either side of the rod's velocity.
HAIR = 1e-9
#: Frame roles whose frames every case samples at all of :func:`sample_times`; the random cases
#: sample the others (``"fast"``: the :data:`FAST_FRAMES`; ``"rest-before"``; ``"near-rest"``) at
#: ``few`` times, which keeps the table near 8 MB; so do the small-speed cases (:data:`FEW_GROUPS`).
FULL_ROLES = frozenset({"lab", "random", "rest-after", "barycentric"})
#: Case groups sampled at ``few`` times outside :data:`FULL_ROLES`: the random cases, and the
#: paradoxes at small speeds (whose point is their derived numbers, the strains and the break).
FEW_GROUPS = frozenset({"random", "small-speeds"})


def s(x: Mp) -> str:
    return mp.nstr(x, 30, min_fixed=-mp.inf, max_fixed=mp.inf) if x != 0 else "0"


def sample_times(events_frame: list[Mp], scale: float, rng: random.Random, *, few: bool = False) -> list[float]:
    """Event times, midpoints, points just beside each event (1e-3 rest lengths: where a clock with a
    large radius has barely started), a margin, and +-1e6 lengths away.

    ``few``: the event times, one random time between the first and the last, and +-1e6 lengths
    away (about a third as many).
    """
    ts = sorted({float(t) for t in events_frame} | {0.0})
    out = set(ts)
    span = max(ts[-1] - ts[0], scale)
    out.add(1e6 * scale)
    out.add(-1e6 * scale)
    if few:
        out.add(ts[0] + rng.random() * (ts[-1] - ts[0]))
        return sorted(out)
    for a, b in itertools.pairwise(ts):
        out.add(0.5 * (a + b))
        out.add(a + rng.random() * (b - a))
    for t in ts:
        out.add(t + 1e-3 * scale)
        out.add(t - 1e-3 * scale)
    out.add(ts[0] - 0.5 * span)
    out.add(ts[-1] + 0.5 * span)
    return sorted(out)


# ------------------------------------------------------------------ cases
#: Fixed cases from this order on follow the random cases (groups added after the random cases were
#: drawn), so that adding them leaves every earlier case, frames and times included, as it was.
AFTER_RANDOM = PARADOXES


def cases() -> list[dict[str, object]]:
    """Every scene family's fixed cases by ``order`` up to :data:`AFTER_RANDOM`, then
    :data:`RANDOM_CASES` drawn cases, then the fixed cases from :data:`AFTER_RANDOM` on."""
    fixed = sorted((c for r in REFERENCES.values() for c in r.cases), key=lambda c: c.order)
    orders = [c.order for c in fixed]
    if len(set(orders)) != len(orders):
        raise ValueError(f"two reference cases share an order: {orders}")

    def entry(c: ReferenceCase) -> dict[str, object]:
        return {"kind": c.kind, "params": dict(c.params), "group": c.group}

    out: list[dict[str, object]] = [entry(c) for c in fixed if c.order < AFTER_RANDOM]
    rng = random.Random(CASES_SEED)
    drawn = [r for r in REFERENCES.values() if r.draw is not None]
    for _ in range(RANDOM_CASES):
        ref = rng.choice(drawn)
        assert ref.draw is not None
        out.append({"kind": ref.kind, "params": ref.draw(rng), "group": "random"})
    return out + [entry(c) for c in fixed if c.order >= AFTER_RANDOM]


def hair_off(v: Mp, sign: int) -> float:
    """``tanh(atanh(v) + sign HAIR)`` at 50 digits, rounded to float64 (it rounds back to ``v``
    itself when ``HAIR`` is below half an ulp of ``v``, i.e. at ``gamma`` of a few thousand)."""
    with reference_precision():
        off: Mp = mp.tanh(mp.atanh(v) + sign * F(HAIR))
        return float(off)


def frames_for(ref: RefScene, rng: random.Random) -> list[tuple[float, str]]:
    """``(beta, role)`` of each frame of a case, the first role of a velocity kept: the lab, one
    random frame, the :data:`FAST_FRAMES`, each rod's rest frame after and before (to float64),
    frames a hair off those (:func:`hair_off`) and the barycentric frame."""
    frames = [(0.0, "lab"), (rng.uniform(-0.9, 0.9), "random")]
    frames += [(b, "fast") for b in FAST_FRAMES]
    frames += [(float(v), "rest-after") for v in ref.final_velocities]
    frames += [(float(v), "rest-before") for v in ref.initial_velocities]
    frames += [
        (hair_off(v, sign), "near-rest") for v in (*ref.initial_velocities, *ref.final_velocities) for sign in (1, -1)
    ]
    if "u" in ref.extra:
        frames.append((float(ref.extra["u"]), "barycentric"))
    first: dict[float, str] = {}
    for beta, role in frames:
        first.setdefault(beta, role)
    return list(first.items())


def case_frames(
    case: dict[str, object], rng: random.Random
) -> tuple[RefScene, list[tuple[float, str, dict[str, tuple[Mp, Mp]], list[float]]]]:
    """A case's reference scene and its frames: ``(beta, role, events there, sample times)``; all of
    the case's draws from the stream ``rng`` (the slices at those times draw nothing)."""
    kind = str(case["kind"])
    params: dict[str, Any] = dict(case["params"])  # type: ignore[arg-type]
    few = case.get("group") in FEW_GROUPS
    with reference_precision():
        ref = BUILDERS[kind](FRACTIONS, **params)
        out = []
        for beta_f, role in frames_for(ref, rng):
            ev_frame = {k: boost_event(e, F(beta_f)) for k, e in ref.events.items()}
            scale = float(max(ref.lengths_rest))
            times = sample_times([e[0] for e in ev_frame.values()], scale, rng, few=few and role not in FULL_ROLES)
            out.append((beta_f, role, ev_frame, times))
    return ref, out


def build_case(case: dict[str, object], rng: random.Random) -> dict[str, object]:
    kind = str(case["kind"])
    params: dict[str, Any] = dict(case["params"])  # type: ignore[arg-type]
    ref, planned = case_frames(case, rng)
    with reference_precision():
        frames = []
        for beta_f, role, ev_frame, times in planned:
            beta = F(beta_f)
            exact = [[[frame_slice_and_clock(w, beta, F(t)) for t in times] for w in rod] for rod in ref.worldlines]
            frames.append(
                {
                    "beta": beta_f.hex(),
                    "role": role,
                    "times": [t.hex() for t in times],
                    "positions": [[[s(x) for x, _ in pt] for pt in rod] for rod in exact],
                    "proper_times": [[[s(tau) for _, tau in pt] for pt in rod] for rod in exact],
                    "lengths": [[s(b[0] - a[0]) for a, b in zip(rod[0], rod[-1])] for rod in exact],
                    "events": {k: [s(e[0]), s(e[1])] for k, e in ev_frame.items()},
                }
            )
        return {
            "kind": kind,
            "group": str(case["group"]),
            "params": {k: (None if v is None else float(v).hex()) for k, v in params.items()},
            "fractions": [f.hex() for f in FRACTIONS],
            "lengths_rest": [s(v) for v in ref.lengths_rest],
            "final_velocities": [s(v) for v in ref.final_velocities],
            "final_gaps": [s(1 - abs(v)) for v in ref.final_velocities],
            "extra": {k: s(v) for k, v in ref.extra.items()},
            "events_lab": {k: [s(e[0]), s(e[1])] for k, e in ref.events.items()},
            "signals_lab": {
                name: [[[s(c) for c in signal_arrival(w, source)] for w in rod] for rod in ref.worldlines]
                for name, source in {"origin": (mp.mpf(0), mp.mpf(0)), **ref.events}.items()
            },
            "frames": frames,
        }


def main(argv: list[str] | None = None) -> None:
    parser = argparse.ArgumentParser(
        prog="python -m tests.reference.make_reference", description=(__doc__ or "").splitlines()[0]
    )
    parser.add_argument("--out", type=Path, default=OUT, help=f"where to write the table (default: {OUT})")
    parser.add_argument(
        "--append",
        action="store_true",
        help="keep the cases the committed table already has (the generator's first cases, unchanged) and "
        "build only those after them, the stream replayed through the kept ones: the same table as a full run",
    )
    args = parser.parse_args(argv)
    out: Path = args.out
    rng = random.Random(FRAMES_SEED)
    t0 = time.perf_counter()
    all_cases = cases()
    built: list[dict[str, object]] = []
    if args.append:
        kept = json.loads(OUT.read_text())["cases"]
        for committed, case in zip(kept, all_cases):
            if committed["kind"] != case["kind"]:
                raise SystemExit("--append: the committed table's cases are not the generator's first cases")
            _, planned = case_frames(case, rng)  # the draws a full run makes for this case
            replayed = [[beta.hex(), [t.hex() for t in times]] for beta, _, _, times in planned]
            if replayed != [[f["beta"], f["times"]] for f in committed["frames"]]:
                raise SystemExit(f"--append: case {len(built)} does not replay its frames and times")
            built.append(committed)
    for i, case in enumerate(all_cases[len(built) :], start=len(built)):
        built.append(build_case(case, rng))
        print(f"{i + 1}/{len(all_cases)} {case['kind']} {time.perf_counter() - t0:.1f}s", file=sys.stderr)
    table = {"generator": "tests/reference/make_reference.py", "mp_dps": REFERENCE_DIGITS, "cases": built}
    out.write_text(json.dumps(table, indent=None, separators=(",", ":")) + "\n")
    print(f"wrote {out} ({out.stat().st_size / 1e6:.2f} MB)", file=sys.stderr)


if __name__ == "__main__":
    main()
