"""The worst error of rigidrel_core against the 50-digit reference table, check by check.

Loads the committed table (tests/reference/reference.json, or ``--table``), evaluates the core at
every case, frame and sample time with the error functions of ``tests/test_accuracy.py`` (errors
in units of their named tolerance: a check passes at <= 1), and prints one line per check class
x frame class x case group: the worst error and where it is (case number, kind and parameters,
frame velocity, rod, material fraction and frame time, or the event's name).

Check classes: positions (``TOL_POSITION``), equal-time lengths (``TOL_LENGTH_REL`` plus
``TOL_LENGTH_ULP`` ulp), named events (``TOL_EVENT``), clock readings (``TOL_CLOCK``).

Frame classes (each frame in exactly one): ``lab``; ``chasing``, a rod's rest frame before or
after (to float64) or a rapidity of 1e-9 either side of one; else by speed, ``moderate`` below
``|beta| = 0.999999``, then ``>=1-1e-6``, ``>=1-1e-7`` and ``>=1-1e-9`` (bands: ``>=1-1e-6``
holds ``0.999999 <= |beta| < 1 - 1e-7``).

Case groups: the table's fixed groups (paper examples, ultra-relativistic, horizon, mass ratios
and sizes, velocity changes, weak acceleration) and the random cases.

Run from the repository root (a few seconds)::

    python -m tests.reference.error_report              # every class
    python -m tests.reference.error_report --failing    # only classes above their tolerance
    python -m tests.reference.error_report --no-groups  # one line per check x frame class

Exit status 1 when some check is above its tolerance.
"""

from __future__ import annotations

import argparse
import json
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from tests.test_accuracy import (
    FloatArray,
    build,
    clock_errors,
    event_errors,
    length_errors,
    position_errors,
    signal_errors,
    where,
)

TABLE = Path(__file__).with_name("reference.json")
CHECKS = ("positions", "lengths", "events", "clocks", "signals")
FRAME_CLASSES = ("lab", "moderate", ">=1-1e-6", ">=1-1e-7", ">=1-1e-9", "chasing")
#: Frame roles of the table that chase a rod (its rest frame, or a hair off it).
CHASING = frozenset({"rest-before", "rest-after", "near-rest"})


def frame_class(beta: float, role: str) -> str:
    """The frame class of a table frame (see the module docstring)."""
    if role in CHASING:
        return "chasing"
    speed = abs(beta)
    if speed == 0.0:
        return "lab"
    if speed >= 1 - 1e-9:
        return ">=1-1e-9"
    if speed >= 1 - 1e-7:
        return ">=1-1e-7"
    if speed >= 0.999999:
        return ">=1-1e-6"
    return "moderate"


@dataclass(frozen=True)
class Worst:
    """The worst error of one class, in units of its tolerance, and where it is."""

    error: float
    case: int
    beta: float
    at: str


def describe_case(i: int, case: dict[str, Any]) -> str:
    params = ", ".join(
        f"{k}={'None' if v is None else format(float.fromhex(v), '.12g')}" for k, v in case["params"].items()
    )
    return f"#{i:02d} {case['kind']}({params})"


def worst_errors(cases: list[dict[str, Any]]) -> dict[tuple[str, str, str], Worst]:
    """``(check, frame class, group) -> Worst`` over every case, frame and sample time."""
    worst: dict[tuple[str, str, str], Worst] = {}

    def record(check: str, cls: str, group: str, found: Worst) -> None:
        key = (check, cls, group)
        if key not in worst or found.error > worst[key].error:
            worst[key] = found

    def record_array(check: str, cls: str, group: str, err: FloatArray, i: int, fr: dict[str, Any]) -> None:
        # NaN (a non-finite core value) counts as infinitely wrong
        err = np.where(np.isnan(err), np.inf, err)
        record(check, cls, group, Worst(float(err.max()), i, float.fromhex(fr["beta"]), where(err, fr, cases[i])))

    def record_events(
        cls: str, group: str, errors: dict[str, float], i: int, beta: float, check: str = "events"
    ) -> None:
        name = max(errors, key=lambda k: np.nan_to_num(errors[k], nan=np.inf))
        what = f"event {name}" if check == "events" else f"signal from {name}"
        record(check, cls, group, Worst(float(np.nan_to_num(errors[name], nan=np.inf)), i, beta, what))

    with np.errstate(all="ignore"):
        for i, case in enumerate(cases):
            scene = build(case)
            group = case["group"]
            record_events("lab", group, event_errors(scene, case, 0.0, case["events_lab"]), i, 0.0)
            record_events("lab", group, signal_errors(scene, case, 0.0), i, 0.0, "signals")
            for fr in case["frames"]:
                beta = float.fromhex(fr["beta"])
                cls = frame_class(beta, fr["role"])
                record_array("positions", cls, group, position_errors(scene, case, fr), i, fr)
                record_array("lengths", cls, group, length_errors(scene, fr), i, fr)
                record_array("clocks", cls, group, clock_errors(scene, case, fr), i, fr)
                record_events(cls, group, event_errors(scene, case, beta, fr["events"]), i, beta)
                record_events(cls, group, signal_errors(scene, case, beta), i, beta, "signals")
    return worst


def report(cases: list[dict[str, Any]], *, by_group: bool = True, failing_only: bool = False) -> tuple[list[str], bool]:
    """The report's lines (a header, then one line per class that has samples) and whether any check fails."""
    worst = worst_errors(cases)
    groups = list(dict.fromkeys(c["group"] for c in cases)) if by_group else ["all"]
    if not by_group:
        merged: dict[tuple[str, str, str], Worst] = {}
        for (check, cls, _), w in worst.items():
            key = (check, cls, "all")
            if key not in merged or w.error > merged[key].error:
                merged[key] = w
        worst = merged
    lines = [f"{'check':<9} {'frames':<9} {'group':<18} {'err/tol':>8}       worst at"]
    failing = False
    for check in CHECKS:
        for cls in FRAME_CLASSES:
            for group in groups:
                w = worst.get((check, cls, group))
                if w is None:
                    continue
                fails = not w.error <= 1.0
                failing |= fails
                if failing_only and not fails:
                    continue
                lines.append(
                    f"{check:<9} {cls:<9} {group:<18} {w.error:>8.2g} {'FAIL' if fails else '    '}  "
                    f"{describe_case(w.case, cases[w.case])} beta={w.beta!r} {w.at}"
                )
    return lines, failing


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(
        prog="python -m tests.reference.error_report", description=(__doc__ or "").splitlines()[0]
    )
    parser.add_argument("--table", type=Path, default=TABLE, help=f"the reference table (default: {TABLE})")
    parser.add_argument("--failing", action="store_true", help="only the classes above their tolerance")
    parser.add_argument("--no-groups", action="store_true", help="one line per check x frame class")
    args = parser.parse_args(argv)
    cases: list[dict[str, Any]] = json.loads(args.table.read_text())["cases"]
    lines, failing = report(cases, by_group=not args.no_groups, failing_only=args.failing)
    print("\n".join(lines))
    return 1 if failing else 0


if __name__ == "__main__":
    raise SystemExit(main())
