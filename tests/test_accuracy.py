"""rigidrel_core against the independent 50-digit reference (tests/reference/make_reference.py).

The reference (tests.reference.oracle, which never imports the core) solves each scene
by the paper's route in mpmath, slices worldlines by bisection on lab time and reads each
material point's clock there (its proper time, integrated piece by piece in the lab, 0 where
the point starts changing velocity); the core evaluates closed forms in the frame.

Cases: the paper's examples; V = 1 - 1e-12 and 1 - 1e-9; a'_F L0 = 1 - 1e-6 and 1e-6;
weak accelerations a'_F L0 = 1e-3, 1e-5 and 1e-7 (constant acceleration, deceleration and
velocity changes, V from 0.1 to 0.99 and 1 - 1e-9: radii of 1e3..1e7 rest lengths); mass
ratios 1e-6..1e6; lengths 1e-6..1e6; 36 random scenes; Bell's spaceships and the pole in the barn,
also at V = 1e-6 and 1e-3 with breaking strains down to 1e-12 (their strains and breaks are checked
in tests/test_paradoxes.py). Frames of every case: the lab, a
random one, beta = +-0.999999, +-(1 - 1e-7) and +-(1 - 1e-9), each rod's rest frame before
and after (to float64), frames a rapidity of 1e-9 either side of those, and the barycentric
frame. Times: every event, points between and beside them, and 1e6 lengths away. Checked in
every frame: positions and clock readings of three material points, equal-time lengths, named
events, and where a light signal from the origin and from each named event reaches each of the
three points (the reference's lab arrival, found by bisection, boosted at 50 digits); once:
final velocities and their gaps to light speed.

The error functions below give errors in units of their tolerance (a check passes at <= 1);
``python -m tests.reference.error_report`` tabulates the worst of each by frame and case class.
"""

from __future__ import annotations

import json
import math
from pathlib import Path
from typing import Any

import mpmath
import numpy as np
import numpy.typing as npt
import pytest

import rigidrel_core as rr

FloatArray = npt.NDArray[np.float64]

#: Position error, relative to max(|x|, the rod's equal-time length at that time).
TOL_POSITION = 1e-12
#: Equal-time length error: relative part ...
TOL_LENGTH_REL = 1e-9
#: ... plus this many ulp of the larger end coordinate.
TOL_LENGTH_ULP = 64
#: Event coordinates, relative to max(|t|, |x|, rest length).
TOL_EVENT = 1e-12
#: Clock readings, relative to max(|tau_ref|, |t'|, the rod's rest length): the reading itself;
#: the frame time it is read at (a clock moving fast in the frame reads tau ~ t'/gamma' << |t'|,
#: formed from t', so its rounding scales with |t'|); the rod's size (readings near their zero).
TOL_CLOCK = 1e-12
#: Light-signal arrivals, relative to max(|t'|, |x'|, rest length) (as events).
TOL_SIGNAL = 1e-12
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


def decimals(values: object) -> FloatArray:
    """The table's decimal strings (nested lists) as a float64 array of the same shape."""
    return np.asarray(values, dtype=str).astype(np.float64)


# ------------------------------------------------------------------ errors in units of the tolerance
def position_errors(scene: rr.Scene, case: dict[str, Any], fr: dict[str, Any]) -> FloatArray:
    """``|x' - x'_ref| / (TOL_POSITION max(|x'_ref|, L_ref(t')))`` of every rod, material point and
    time of the table's frame ``fr``; shape ``(rods, fractions, times)``."""
    fractions = np.array([float.fromhex(f) for f in case["fractions"]])
    t = np.array([float.fromhex(x) for x in fr["times"]])
    ref = decimals(fr["positions"])
    got = scene.material_positions(t, frame=frame(float.fromhex(fr["beta"])), fractions=fractions)
    assert got.shape == ref.shape
    ref_len = decimals(fr["lengths"])  # end-to-end equal-time lengths, reference at 50 digits
    scale = np.maximum(np.abs(ref), np.abs(ref_len)[:, None, :])
    return np.abs(got - ref) / (TOL_POSITION * scale)


def length_errors(scene: rr.Scene, fr: dict[str, Any]) -> FloatArray:
    """``|L - L_ref|`` over its bound ``TOL_LENGTH_REL |L_ref| + TOL_LENGTH_ULP ulp(max |x'_end|)``;
    shape ``(rods, times)``."""
    t = np.array([float.fromhex(x) for x in fr["times"]])
    ref = decimals(fr["positions"])
    ref_len = decimals(fr["lengths"])
    got = scene.lengths(t, frame=frame(float.fromhex(fr["beta"])))
    assert got.shape == ref_len.shape
    ends = np.maximum(np.abs(ref[:, 0]), np.abs(ref[:, -1]))
    return np.abs(got - ref_len) / (TOL_LENGTH_REL * np.abs(ref_len) + TOL_LENGTH_ULP * np.spacing(ends))


def clock_errors(scene: rr.Scene, case: dict[str, Any], fr: dict[str, Any]) -> FloatArray:
    """``|tau - tau_ref| / (TOL_CLOCK max(|tau_ref|, |t'|, L_rod))`` of every rod, material point and
    time; shape ``(rods, fractions, times)``."""
    fractions = np.array([float.fromhex(f) for f in case["fractions"]])
    t = np.array([float.fromhex(x) for x in fr["times"]])
    ref = decimals(fr["proper_times"])
    got = scene.proper_times(t, frame=frame(float.fromhex(fr["beta"])), fractions=fractions)
    assert got.shape == ref.shape
    rest = decimals(case["lengths_rest"])[:, None, None]
    scale = np.maximum(np.maximum(np.abs(ref), np.abs(t)), rest)
    return np.abs(got - ref) / (TOL_CLOCK * scale)


def event_errors(scene: rr.Scene, case: dict[str, Any], beta: float, ref_events: dict[str, Any]) -> dict[str, float]:
    """Per named event, ``max(|t' - t'_ref|, |x' - x'_ref|) / (TOL_EVENT max(|t'_ref|, |x'_ref|, L))``
    with ``L`` the largest rest length of the case."""
    got = scene.events_in(frame=frame(beta))
    assert set(got) == set(ref_events)
    scale_len = float(max(decimals(case["lengths_rest"])))
    out = {}
    for name, (rt, rx) in ref_events.items():
        t_ref, x_ref = float(rt), float(rx)
        scale = max(abs(t_ref), abs(x_ref), scale_len)
        gt, gx = got[name]
        out[name] = max(abs(gt - t_ref), abs(gx - x_ref)) / (TOL_EVENT * scale)
    return out


def signal_errors(scene: rr.Scene, case: dict[str, Any], beta: float) -> dict[str, float]:
    """Per source, the worst ``|arrival - arrival_ref| / (TOL_SIGNAL max(|t'_ref|, |x'_ref|, L))`` over
    every rod and material point; the reference's lab arrival is boosted at 50 digits."""
    fractions = [float.fromhex(f) for f in case["fractions"]]
    scale_len = float(max(decimals(case["lengths_rest"])))
    fr = frame(beta)
    out: dict[str, float] = {}
    with mpmath.workdps(50):
        b = mpmath.mpf(beta)
        g = 1 / mpmath.sqrt((1 - b) * (1 + b))
        for name, rods in case["signals_lab"].items():
            source = scene.origin_event.value if name == "origin" else name
            worst = 0.0
            for rod, points in enumerate(rods):
                for f, (rt, rx) in zip(fractions, points, strict=True):
                    t, x = mpmath.mpf(rt), mpmath.mpf(rx)
                    t_ref, x_ref = float(g * (t - b * x)), float(g * (x - b * t))
                    got = scene.signal_arrival(source, rod, f, frame=fr)
                    assert got is not None, (name, rod, f)
                    scale = max(abs(t_ref), abs(x_ref), scale_len)
                    worst = max(worst, abs(got[0] - t_ref) / scale, abs(got[1] - x_ref) / scale)
            out[name] = worst / TOL_SIGNAL
    return out


def frames_with_events(case: dict[str, Any]) -> list[tuple[float, dict[str, Any]]]:
    """``(beta, reference events)``: the lab's events as the reference computed them, then each frame's."""
    return [(0.0, case["events_lab"])] + [(float.fromhex(f["beta"]), f["events"]) for f in case["frames"]]


def where(err: FloatArray, fr: dict[str, Any], case: dict[str, Any]) -> str:
    """The worst entry of a ``(rods, fractions, times)`` or ``(rods, times)`` error array, in words."""
    index = np.unravel_index(int(err.argmax()), err.shape)
    t = float.fromhex(fr["times"][index[-1]])
    point = f" f={float.fromhex(case['fractions'][index[1]])}" if err.ndim == 3 else ""
    return f"rod {index[0]}{point} t'={t!r}"


# ------------------------------------------------------------------ tests
@pytest.mark.parametrize("case", CASES, ids=ids())
def test_positions_and_lengths(case: dict[str, Any]) -> None:
    scene = build(case)
    for fr in case["frames"]:
        beta = float.fromhex(fr["beta"])
        err = position_errors(scene, case, fr)
        assert err.max() <= 1.0, (
            f"beta={beta!r}: position error {err.max():.3g} x TOL_POSITION at {where(err, fr, case)}"
        )
        err = length_errors(scene, fr)
        assert err.max() <= 1.0, f"beta={beta!r}: length error {err.max():.3g} x its bound at {where(err, fr, case)}"


@pytest.mark.parametrize("case", CASES, ids=ids())
def test_proper_times(case: dict[str, Any]) -> None:
    """Clock readings of three material points at every sample time of every frame."""
    scene = build(case)
    for fr in case["frames"]:
        beta = float.fromhex(fr["beta"])
        err = clock_errors(scene, case, fr)
        assert err.max() <= 1.0, f"beta={beta!r}: clock error {err.max():.3g} x TOL_CLOCK at {where(err, fr, case)}"


@pytest.mark.parametrize("case", CASES, ids=ids())
def test_events_in_every_frame(case: dict[str, Any]) -> None:
    scene = build(case)
    for beta, ref_events in frames_with_events(case):
        errors = event_errors(scene, case, beta, ref_events)
        name = max(errors, key=errors.__getitem__)
        assert errors[name] <= 1.0, f"beta={beta!r}: event {name} off by {errors[name]:.3g} x TOL_EVENT"


@pytest.mark.parametrize("case", CASES, ids=ids())
def test_signal_arrivals(case: dict[str, Any]) -> None:
    """Where a light signal from the origin event and from each named event first reaches each
    material point, in every frame of the case."""
    scene = build(case)
    for beta, _ in frames_with_events(case):
        errors = signal_errors(scene, case, beta)
        name = max(errors, key=errors.__getitem__)
        assert errors[name] <= 1.0, f"beta={beta!r}: signal from {name} off by {errors[name]:.3g} x TOL_SIGNAL"


@pytest.mark.parametrize("case", CASES, ids=ids())
def test_final_velocities(case: dict[str, Any]) -> None:
    scene = build(case)
    for rod, ref in zip(scene.rods, case["final_velocities"]):
        v_ref = float(ref)
        got = rod.motion.velocity_final
        if abs(v_ref) <= 1e-30:
            # a true zero (e.g. eps = 1/2 of case I stops rod 1), which the paper's route at 50 digits
            # leaves as noise up to ~1e-40: the core's double-double solution keeps it exactly zero
            assert (got.hi, got.lo) == (0.0, 0.0)
        else:
            assert abs(got.value - v_ref) <= TOL_VELOCITY * abs(v_ref)

    for rod, ref in zip(scene.rods, case["final_gaps"]):
        # the gap to light speed 1 - |v| is carried separately and must be as good
        assert math.isclose(rod.motion.velocity_final.gap, float(ref), rel_tol=TOL_VELOCITY)
