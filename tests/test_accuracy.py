"""rigidrel_core against the independent 50-digit reference (tests/reference/make_reference.py).

The reference (rigidrel_app.bench.reference, which never imports the core) solves each scene
by the paper's route in mpmath and slices worldlines by bisection on lab time; the core
evaluates closed forms in the frame. Cases cover the
paper's examples, V = 1 - 1e-12, frames at |beta| = 0.999999 and each rod's rest frame
after, a'_F L0 = 1 - 1e-6 and 1e-6, mass ratios 1e-6..1e6, lengths 1e-6..1e6, and times
1e6 lengths away.
"""

from __future__ import annotations

import json
import math
from pathlib import Path
from typing import Any

import numpy as np
import pytest

import rigidrel_core as rr

#: Position error, relative to max(|x|, the rod's equal-time length at that time).
TOL_POSITION = 1e-12
#: Equal-time length error: relative part ...
TOL_LENGTH_REL = 1e-9
#: ... plus this many ulp of the larger end coordinate.
TOL_LENGTH_ULP = 64
#: Event coordinates, relative to max(|t|, |x|, rest length).
TOL_EVENT = 1e-12
#: Final velocities and their gaps 1 - |v| to light speed, relative.
TOL_VELOCITY = 1e-14

REFERENCE = json.loads((Path(__file__).parent / "reference" / "reference.json").read_text())
CASES: list[dict[str, Any]] = REFERENCE["cases"]


def unhex(x: str | None) -> float | None:
    return None if x is None else float.fromhex(x)


def build(case: dict[str, Any]) -> rr.Scene:
    """The core's scene of a table case (parameters it does not list take the core's defaults)."""
    params = {k: unhex(v) for k, v in case["params"].items()}
    return rr.build_scene(case["kind"], **params)


def frame(beta: float) -> rr.Frame:
    """The frame moving with ``beta`` (c = 1), as every sampler of the core takes it."""
    return rr.Frame.from_velocity(beta)


def ids() -> list[str]:
    return [f"{i:02d}-{c['kind']}" for i, c in enumerate(CASES)]


@pytest.mark.parametrize("case", CASES, ids=ids())
def test_positions_and_lengths(case: dict[str, Any]) -> None:
    scene = build(case)
    fractions = np.array([float.fromhex(f) for f in case["fractions"]])
    for fr in case["frames"]:
        beta = float.fromhex(fr["beta"])
        t = np.array([float.fromhex(x) for x in fr["times"]])
        ref = np.array([[[float(v) for v in pt] for pt in rod] for rod in fr["positions"]])
        got = scene.material_positions(t, frame(beta), fractions=fractions)
        assert got.shape == ref.shape
        # end-to-end equal-time lengths, reference at 50 digits
        ref_len = np.array([[float(v) for v in rod] for rod in fr["lengths"]])
        scale = np.maximum(np.abs(ref), np.abs(ref_len)[:, None, :])
        err = np.abs(got - ref) / scale
        assert err.max() <= TOL_POSITION, (
            f"beta={beta!r}: position error {err.max():.3g} at index {np.unravel_index(err.argmax(), err.shape)}"
        )
        got_len = scene.lengths(t, frame(beta))
        ends = np.maximum(np.abs(ref[:, 0]), np.abs(ref[:, -1]))
        allowed = TOL_LENGTH_REL * np.abs(ref_len) + TOL_LENGTH_ULP * np.spacing(ends)
        excess = np.abs(got_len - ref_len) - allowed
        assert excess.max() <= 0.0, f"beta={beta!r}: length error exceeds bound by {excess.max():.3g}"


@pytest.mark.parametrize("case", CASES, ids=ids())
def test_events_in_every_frame(case: dict[str, Any]) -> None:
    scene = build(case)
    scale_len = max(unhex(v) or 0.0 for k, v in case["params"].items() if k.startswith("l"))
    checks = [(0.0, case["events_lab"])] + [(float.fromhex(f["beta"]), f["events"]) for f in case["frames"]]
    for beta, ref_events in checks:
        got = scene.events_in(frame(beta))
        assert set(got) == set(ref_events)
        for name, (rt, rx) in ref_events.items():
            t_ref, x_ref = float(rt), float(rx)
            scale = max(abs(t_ref), abs(x_ref), scale_len)
            gt, gx = got[name]
            assert abs(gt - t_ref) <= TOL_EVENT * scale, (beta, name, gt, t_ref)
            assert abs(gx - x_ref) <= TOL_EVENT * scale, (beta, name, gx, x_ref)


@pytest.mark.parametrize("case", CASES, ids=ids())
def test_final_velocities(case: dict[str, Any]) -> None:
    scene = build(case)
    for rod, ref in zip(scene.rods, case["final_velocities"]):
        v_ref = float(ref)
        got = rod.motion.velocity_final
        # an exact zero (e.g. eps = 1/2 of case I stops rod 1) comes out as +-1e-52 or so
        assert abs(got.value - v_ref) <= TOL_VELOCITY * abs(v_ref) + 1e-40

    for rod, ref in zip(scene.rods, case["final_gaps"]):
        # the gap to light speed 1 - |v| is carried separately and must be as good
        assert math.isclose(rod.motion.velocity_final.gap, float(ref), rel_tol=TOL_VELOCITY)
