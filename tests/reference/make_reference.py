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

Floats are stored as ``float.hex`` (exact), reference values as 30-digit strings.

Run from the repository root::

    python -m tests.reference.make_reference      # writes tests/reference/reference.json
"""

from __future__ import annotations

import itertools
import json
import random
import sys
import time
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import mpmath as mp

mp.mp.dps = 50
OUT = Path(__file__).with_name("reference.json")
FRACTIONS = (0.0, 0.375, 1.0)

#: An mpmath number (mpmath ships no precise type hints).
Mp = Any
Worldline = Callable[[Mp], Mp]


def F(x: float) -> Mp:
    """A float taken as exact."""
    return mp.mpf(float(x))


def gamma_of(v: Mp) -> Mp:
    return 1 / mp.sqrt(1 - v * v)


@dataclass
class RefScene:
    """Reference description: per rod, a lab worldline for each material fraction."""

    worldlines: list[list[Worldline]]  # [rod][fraction] -> x(t)
    events: dict[str, tuple[Mp, Mp]]
    final_velocities: list[Mp]
    lengths_rest: list[Mp]
    extra: dict[str, Mp]


# ------------------------------------------------------------------ worldlines
def accelerating_point(xi: Mp, alpha: Mp, V: Mp) -> Worldline:
    """Eq. (deriv): a point at rest at xi for t <= 0, proper acceleration alpha until speed V."""
    T = gamma_of(V) * V / alpha
    X = xi + (gamma_of(V) - 1) / alpha

    def x(t: Mp) -> Mp:
        if t <= 0:
            return xi
        if t <= T:
            return xi + (mp.sqrt(1 + alpha * alpha * t * t) - 1) / alpha
        return X + V * (t - T)

    return x


def hyperbola_point(centre: Mp, d: Mp, side: int, v_before: Mp, v_after: Mp) -> Worldline:
    """A point at rest-distance d from a centre event (0, centre) on side +1/-1.

    Eq. (imp12): x = centre + side sqrt(d^2 + t^2) between the times where its velocity
    is v_before and v_after; the tangent lines outside.
    """

    def t_at(v: Mp) -> Mp:  # dx/dt = side t / sqrt(d^2 + t^2) = v
        return side * d * gamma_of(v) * v

    t0, t1 = t_at(v_before), t_at(v_after)
    x0 = centre + side * d * gamma_of(v_before)
    x1 = centre + side * d * gamma_of(v_after)

    def x(t: Mp) -> Mp:
        if t < t0:
            return x0 + v_before * (t - t0)
        if t > t1:
            return x1 + v_after * (t - t1)
        return centre + side * mp.sqrt(d * d + t * t)

    return x


# ------------------------------------------------------------------ scenes
def ref_constant_acceleration(v: float, length: float, a_front: float) -> RefScene:
    V, L, aF = F(v), F(length), F(a_front)
    aB = aF / (1 - aF * L)  # Eq. (gl)
    wl = []
    for f in FRACTIONS:
        xi = F(f) * L if f != 1.0 else L
        alpha = 1 / (xi + 1 / aB)
        wl.append(accelerating_point(xi, alpha, V))
    g = gamma_of(V)
    events = {
        "T_B": (g * V / aB, (g - 1) / aB),
        "T_F": (g * V / aF, L + (g - 1) / aF),
    }
    return RefScene([wl], events, [V], [L], {"a_B": aB})


def ref_deceleration(v: float, length: float, a_front: float) -> RefScene:
    acc = ref_constant_acceleration(v, length, a_front)
    wl = [[(lambda t, w=w: w(-t)) for w in acc.worldlines[0]]]
    events = {
        "-T_F": (-acc.events["T_F"][0], acc.events["T_F"][1]),
        "-T_B": (-acc.events["T_B"][0], acc.events["T_B"][1]),
    }
    return RefScene(wl, events, [mp.mpf(0)], acc.lengths_rest, {})


def ref_impulsive_start(v: float, length: float) -> RefScene:
    V, L = F(v), F(length)
    wl = []
    for f in FRACTIONS:
        xi = F(f) * L if f != 1.0 else L
        wl.append(hyperbola_point(mp.mpf(0), xi, +1, mp.mpf(0), V))
    g = gamma_of(V)
    return RefScene([wl], {"T_F": (V * g * L, g * L)}, [V], [L], {})  # Eq. (tf)


def ref_velocity_change(v_initial: float, v_final: float, length: float, a_front: float | None) -> RefScene:
    Vi, Vf, L = F(v_initial), F(v_final), F(length)
    near = mp.mpf(0) if a_front is None else (1 - F(a_front) * L) / F(a_front)
    side = 1 if Vf > Vi else -1
    centre = -near if side == 1 else L + near
    wl = []
    for f in FRACTIONS:
        xi = F(f) * L if f != 1.0 else L
        d = abs(xi - centre)
        wl.append(hyperbola_point(centre, d, side, Vi, Vf))
    near_xi, far_xi = (mp.mpf(0), L) if side == 1 else (L, mp.mpf(0))
    events = {}
    for name, xi in (("B", near_xi), ("F", far_xi)):
        d = abs(xi - centre)
        for suffix, v in (("0", Vi), ("", Vf)):
            g = gamma_of(v)
            events[f"T_{name}{suffix}"] = (side * d * g * v, centre + side * d * g)
    return RefScene([wl], events, [Vf], [L], {})


def ref_wall_collision(v: float, length: float, eps: float) -> RefScene:
    V, L, e = F(v), F(length), F(eps)
    # wall frame = barycentric frame of an infinitely heavy wall: gamma' V' = eps gamma V
    p = e * gamma_of(V) * V
    Vp = p / mp.sqrt(1 + p * p)
    wl = []
    for f in FRACTIONS:
        xi = F(f) * L if f != 1.0 else L
        wl.append(hyperbola_point(mp.mpf(0), xi, +1, -V, Vp))
    g, gp = gamma_of(V), gamma_of(Vp)
    events = {"T_1": (-g * V * L, g * L), "T_1'": (gp * Vp * L, gp * L)}
    return RefScene([wl], events, [Vp], [L], {"heat": g - gp})


def ref_collision_velocities(v1: float, v2: float, m1: float, m2: float, eps: float) -> dict[str, Mp]:
    """Sec. 6 route: u, barycentric velocities, Eq. (epsilon), velocity addition back."""
    V1, V2, M1, M2, e = F(v1), F(v2), F(m1), F(m2), F(eps)
    g1, g2 = gamma_of(V1), gamma_of(V2)
    u = (M1 * g1 * V1 + M2 * g2 * V2) / (M1 * g1 + M2 * g2)
    Vb1 = (V1 - u) / (1 - u * V1)
    Vb2 = (V2 - u) / (1 - u * V2)
    out = {"u": u, "Vb1": Vb1, "Vb2": Vb2}
    for i, Vb in ((1, Vb1), (2, Vb2)):
        p = -e * gamma_of(Vb) * Vb  # Eq. (epsilon)
        Vbp = p / mp.sqrt(1 + p * p)
        out[f"Vbp{i}"] = Vbp
        out[f"Vp{i}"] = (u + Vbp) / (1 + u * Vbp)  # Eq. (vp)
    # rest-mass gain: energy conservation in the barycentric frame, common factor k
    E_bar = M1 * gamma_of(Vb1) + M2 * gamma_of(Vb2)
    k = E_bar / (M1 * gamma_of(out["Vbp1"]) + M2 * gamma_of(out["Vbp2"]))
    out["k"] = k
    out["heat"] = (k - 1) * (M1 + M2)
    return out


def ref_rod_collision(v1: float, v2: float, m1: float, m2: float, l1: float, l2: float, eps: float) -> RefScene:
    sol = ref_collision_velocities(v1, v2, m1, m2, eps)
    V1, V2, L1, L2 = F(v1), F(v2), F(l1), F(l2)
    Vp1, Vp2 = sol["Vp1"], sol["Vp2"]
    rod1, rod2 = [], []
    for f in FRACTIONS:
        xi1 = F(f) * L1 if f != 1.0 else L1
        xi2 = F(f) * L2 if f != 1.0 else L2
        rod1.append(hyperbola_point(mp.mpf(0), L1 - xi1, -1, V1, Vp1))
        rod2.append(hyperbola_point(mp.mpf(0), xi2, +1, V2, Vp2))
    g1, g2, gp1, gp2 = gamma_of(V1), gamma_of(V2), gamma_of(Vp1), gamma_of(Vp2)
    events = {  # Eqs. (t12), (t'1), (t'12) with x from Eq. (imp12)
        "T_1": (-g1 * V1 * L1, -g1 * L1),
        "T_1'": (-gp1 * Vp1 * L1, -gp1 * L1),
        "T_2": (g2 * V2 * L2, g2 * L2),
        "T_2'": (gp2 * Vp2 * L2, gp2 * L2),
    }
    return RefScene([rod1, rod2], events, [Vp1, Vp2], [L1, L2], sol)


BUILDERS: dict[str, Callable[..., RefScene]] = {
    "constant-acceleration": ref_constant_acceleration,
    "deceleration": ref_deceleration,
    "impulsive-start": ref_impulsive_start,
    "velocity-change": ref_velocity_change,
    "wall-collision": ref_wall_collision,
    "rod-collision": ref_rod_collision,
}


# ------------------------------------------------------------------ frame slices
def frame_slice(x: Worldline, beta: Mp, t_frame: Mp) -> Mp:
    """x' at frame time t': bisection on lab t of gamma (t - beta x(t)) = t' (strictly increasing)."""
    g = gamma_of(beta)

    def f(t: Mp) -> Mp:
        return g * (t - beta * x(t)) - t_frame

    lo, hi = mp.mpf(-1), mp.mpf(1)
    while f(lo) > 0:
        lo *= 4
    while f(hi) < 0:
        hi *= 4
    scale = max(abs(lo), abs(hi), mp.mpf(1))
    tol = scale * mp.mpf(10) ** (-(mp.mp.dps - 2))
    while hi - lo > tol:
        mid = (lo + hi) / 2
        if f(mid) < 0:
            lo = mid
        else:
            hi = mid
    t = (lo + hi) / 2
    return g * (x(t) - beta * t)


def boost_event(e: tuple[Mp, Mp], beta: Mp) -> tuple[Mp, Mp]:
    g = gamma_of(beta)
    t, x = e
    return g * (t - beta * x), g * (x - beta * t)


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
    ref = BUILDERS[kind](**params)
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
