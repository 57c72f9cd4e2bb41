"""Where textbook float64 formulas fail and the core holds (against the same 50-digit reference).

The textbook route, typed in as printed: gamma = 1/sqrt(1 - V^2), velocity addition
(V - u)/(1 - u V) into and out of the barycentric frame, lab positions first and then the
boost x' = gamma (x - beta t). For an exact float input V these are fine (1 - V is exact
for V >= 1/2, and V*V rounds to 1 - 2(1 - V)); they fail on *derived* velocities, whose
gap to light speed rounding destroys, and in frames that chase the rod, where
``x - beta t`` cancels.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from benchmarks.study.paper import textbook_collision, textbook_gamma
from tests.test_accuracy import CASES, build, frame

#: The core holds this (relative) ...
TOL_CORE = 1e-12
#: ... where the textbook formulas have lost five or more of float64's 16 digits.
LOST = 1e-11


def find_case(kind: str, **params: float) -> dict[str, Any]:
    for c in CASES:
        p = {k: float.fromhex(v) for k, v in c["params"].items() if v is not None}
        if c["kind"] == kind and all(p.get(k) == v for k, v in params.items()):
            return c
    raise LookupError((kind, params))


def test_equal_masses_rod_one_stops_but_not_in_textbook_floats() -> None:
    """Equal masses, elastic, V1 = 1 - 1e-12 onto a rod at rest: rod 1 must stop dead.

    The textbook route leaves it drifting at ~3.5e-7 c: a third of a rod length after
    1e6 lengths of time.
    """
    params = {"v1": 1 - 1e-12, "v2": 0.0, "mass1": 1.0, "mass2": 1.0, "eps": 1.0}
    case = find_case("rod-collision", **params)
    assert abs(float(case["final_velocities"][0])) < 1e-40  # the 50-digit reference: zero
    textbook_v1, _ = textbook_collision(*params.values())
    core_v1 = build(case).final_velocities[0]
    assert abs(core_v1) < 1e-40
    assert abs(textbook_v1) > 1e-8
    assert abs(textbook_v1) * 1e6 > 0.1  # drift over 1e6 L0, in units of L0


def test_gap_to_light_speed_of_a_derived_velocity() -> None:
    """Two ultra-relativistic rods exchange velocities; 1 - |V'| decides Lorentz factors."""
    params = {"v1": 1 - 1e-12, "v2": 1 - 1e-9, "mass1": 1.0, "mass2": 1.0, "eps": 1.0}
    case = find_case("rod-collision", **params)
    scene = build(case)
    textbook = textbook_collision(*params.values())
    for i in (0, 1):
        gap_ref = float(case["final_gaps"][i])
        assert math.isclose(scene.rods[i].motion.velocity_final.gap, gap_ref, rel_tol=TOL_CORE)
    worst = max(abs((1 - textbook[i]) - float(case["final_gaps"][i])) / float(case["final_gaps"][i]) for i in (0, 1))
    assert worst >= LOST


def test_lab_first_then_boost_loses_digits_in_a_chasing_frame() -> None:
    """Impulsive start to V = 1 - 1e-12, seen from beta = 0.999999 and from the rod's rest frame."""
    case = find_case("impulsive-start", v=1 - 1e-12)
    scene = build(case)
    v, L = 1 - 1e-12, 1.0
    g = textbook_gamma(v)
    t_front_stops = v * g * L
    for beta, textbook_at_least in ((0.999999, LOST), (v, 0.5)):
        fr = next(f for f in case["frames"] if float.fromhex(f["beta"]) == beta)
        t = np.array([float.fromhex(x) for x in fr["times"]])
        ref = np.array([float(x) for x in fr["positions"][0][-1]])  # the front (right) end
        gb = textbook_gamma(beta)
        # invert t' = gamma_b (t - beta x(t)) for x(t) = gamma L + v (t - T_F), then boost
        t_lab = (t / gb + beta * (g * L - v * t_front_stops)) / (1 - beta * v)
        late = t_lab > t_front_stops
        x_lab = g * L + v * (t_lab - t_front_stops)
        textbook = gb * (x_lab - beta * t_lab)
        core = scene.positions(t, frame=frame(beta))[0, 1]
        ref_len = np.abs(np.array([float(x) for x in fr["lengths"][0]]))
        scale = np.maximum(np.abs(ref), ref_len)
        assert np.all(np.abs(core - ref) <= TOL_CORE * scale)
        assert np.max((np.abs(textbook - ref) / scale)[late]) >= textbook_at_least
