"""The scalar solution of every scene, in double-double, against mpmath; exact zeros stay exact (c = 1).

The reference evaluates the paper's formulas as written (Sec. 6: gammas, E and P, the invariant
mass, the barycentric proper velocities scaled by -eps, back to the lab by Eq. (31); Sec. 5 for
the wall; Eq. (15) for the Rindler radii) in mpmath, independently of the core's algebra. Those
formulas cancel up to ~45 digits for speeds within 1e-15 of light, so they are carried at 100
digits to leave 50 good ones.

Tolerances: a velocity ``hi + lo`` to 1e-30 of the larger of itself and the terms that cancel in
it (double-double carries ~32 digits; a sum that cancels keeps them relative to its terms only);
a gap ``1 - |v|`` to 1e-15 relative (it is rounded from positive factors on its own).
"""

from __future__ import annotations

import math
from fractions import Fraction
from typing import NamedTuple

import mpmath
import pytest
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st
from mpmath import mpf

import rigidrel_core as rr
from rigidrel_core._build import near_radius
from rigidrel_core._exact import REST, compose_velocities, velocity_from_rapidity
from tests.strategies import log_uniform, parameter_values

SETTINGS = settings(max_examples=300, deadline=None, suppress_health_check=[HealthCheck.too_slow])
#: Double-double's promise, relative to the larger of a result and the terms that cancel in it.
TOL_DD = 1e-30
#: Gaps to light speed, relative.
TOL_GAP = 1e-15
#: Below ~1e-292 a double-double's low part is subnormal: its absolute error is a few 1e-323.
FLOOR = 1e-315
#: Working precision of the reference (50 digits survive the formulas' own cancellations).
DIGITS = 100

COLLISION = rr.describe("rod-collision")
#: Speeds drawn up to 1 - 1e-15 (within 1e-15 of light), log-uniformly in their gap beyond the sliders.
VMAX = 1.0 - 1e-15
velocities = parameter_values(COLLISION.parameter("v1"), vmax=VMAX)
restitutions = st.one_of(st.sampled_from([0.0, 1.0]), parameter_values(COLLISION.parameter("eps")))


def mp(x: float) -> mpf:
    return mpf(x)


def dd_value(v: rr.ExactVelocity) -> mpf:
    return mpf(v.hi) + mpf(v.lo)


# ---------------------------------------------------------------- the reference
class Reference(NamedTuple):
    u: mpf
    u_gap: mpf
    u_terms: mpf
    """The rods' momenta against the energy, ``(|p1| + |p2|)/E``: what cancels in ``u``."""
    after: list[tuple[mpf, mpf, mpf]]
    """Each rod's lab velocity after, its gap, and its velocity in the barycentric frame."""
    factor: mpf


def reference_collision(v1: float, v2: float, m1: float, m2: float, eps: float) -> Reference:
    """Sec. 6 in mpmath: u = P/E (Eq. (26)), barycentric proper velocities m2 sinh/M and -m1 sinh/M,
    scaled by -eps (Eq. (29)), then u'_i = (E b'_i + P g'_i)/M (Eq. (31)); the masses grow by M/sum m_i g'_i."""
    d1, d2, dm1, dm2, de = map(mp, (v1, v2, m1, m2, eps))
    g1, g2 = 1 / mpmath.sqrt((1 - d1) * (1 + d1)), 1 / mpmath.sqrt((1 - d2) * (1 + d2))
    p1, p2 = dm1 * g1 * d1, dm2 * g2 * d2
    energy, momentum = dm1 * g1 + dm2 * g2, p1 + p2
    rel_sinh, rel_cosh = g1 * g2 * (d1 - d2), g1 * g2 * (1 - d1 * d2)
    mass = mpmath.sqrt(dm1**2 + dm2**2 + 2 * dm1 * dm2 * rel_cosh)
    bar_after = (-de * dm2 * rel_sinh / mass, de * dm1 * rel_sinh / mass)
    bar_gamma_after = tuple(mpmath.sqrt(1 + b * b) for b in bar_after)
    after = []
    for b, g in zip(bar_after, bar_gamma_after):
        u_lab = (energy * b + momentum * g) / mass
        gamma = mpmath.sqrt(1 + u_lab * u_lab)
        after.append((u_lab / gamma, 1 / (gamma * (gamma + abs(u_lab))), b / g))
    u = momentum / energy
    one_minus_u = (dm1 * g1 * (1 - d1) + dm2 * g2 * (1 - d2)) if u >= 0 else (dm1 * g1 * (1 + d1) + dm2 * g2 * (1 + d2))
    factor = mass / (dm1 * bar_gamma_after[0] + dm2 * bar_gamma_after[1])
    return Reference(u, one_minus_u / energy, (abs(p1) + abs(p2)) / energy, after, factor)


@st.composite
def collisions(draw: st.DrawFn) -> tuple[float, float, float, float, float]:
    """v1 > v2 (speeds up to 1 - 1e-15), m1 from the registry, m2/m1 in 1e-6..1e6, any eps."""
    a, b = draw(velocities), draw(velocities)
    assume(a is not None and b is not None and a != b)
    assert a is not None and b is not None
    m1 = draw(parameter_values(COLLISION.parameter("mass1")))
    assert m1 is not None
    m2 = m1 * draw(log_uniform(1e-6, 1e6))
    eps = draw(restitutions)
    assert eps is not None
    return max(a, b), min(a, b), m1, m2, eps


# ---------------------------------------------------------------- the collision
@SETTINGS
@given(params=collisions())
def test_collision_agrees_with_mpmath(params: tuple[float, float, float, float, float]) -> None:
    """Barycentric and final velocities to ~1e-30, their gaps to 1e-15, the rest-mass gain and heat
    to 1e-14, for speeds up to 1 - 1e-15 and mass ratios 1e-6..1e6."""
    v1, v2, m1, m2, eps = params
    sol = rr.solve_collision(v1, v2, m1, m2, eps)
    with mpmath.workdps(DIGITS):
        ref = reference_collision(v1, v2, m1, m2, eps)
        u, u_terms = ref.u, ref.u_terms
        assert abs(dd_value(sol.u) - u) <= TOL_DD * (abs(u) + u_terms) + FLOOR
        assert abs(sol.u.gap - ref.u_gap) <= TOL_GAP * ref.u_gap
        for got, (v, gap, w) in zip(sol.after, ref.after):
            # the terms: the barycentric velocity (and its momenta) and the rod's velocity in it
            terms = min(mpf(1), abs(u) + u_terms + abs(w))
            assert abs(dd_value(got) - v) <= TOL_DD * (abs(v) + terms) + FLOOR, (got, v)
            assert abs(got.gap - gap) <= TOL_GAP * gap, (got.gap, gap)
        gain = ref.factor - 1
        assert abs(sol.mass_gain - gain) <= 1e-14 * gain + mpf(10) ** -90
        assert abs(sol.heat - gain * (mp(m1) + mp(m2))) <= 1e-14 * gain * (mp(m1) + mp(m2)) + mpf(10) ** -90
    if eps == 1.0:
        assert sol.mass_gain == 0.0 and sol.heat == 0.0


@pytest.mark.parametrize(
    "params",
    [
        (0.6, 0.0, 1.0, 2.0, 1.0),  # Fig. 3
        (0.6, -0.3, 1.0, 2.0, 0.8),  # bench_core's collision
        (1 - 1e-15, -(1 - 1e-15), 1.0, 1e6, 0.3),  # opposite near light: the light-cone route
        (1 - 1e-12, 0.0, 1e6, 1.0, 1.0),  # a light rod leaves at 1 - 2.9e-24
        (1e-300, 0.0, 1.0, 3.0, 0.5),  # tiny speeds keep their relative precision
        (0.5, 0.25, 1e-300, 1e120, 0.9),  # masses far outside (2**-200, 2**200): scaled first
    ],
)
def test_collision_agrees_with_mpmath_at_edges(params: tuple[float, float, float, float, float]) -> None:
    test_collision_agrees_with_mpmath.hypothesis.inner_test(params)  # type: ignore[attr-defined]


# ---------------------------------------------------------------- exact zeros
def assert_rest(v: rr.ExactVelocity) -> None:
    assert (v.hi, v.lo, v.gap) == (0.0, 0.0, 1.0), v


@pytest.mark.parametrize("v1", [0.6, 0.01, 0.99, 1 - 1e-12, 1e-200])
@pytest.mark.parametrize("m", [1.0, 1e-6, 3e5])
def test_elastic_hit_on_an_equal_rod_at_rest_stops_it_dead(v1: float, m: float) -> None:
    """Equal masses, eps = 1, rod 2 at rest: rod 1 stops exactly, and its rest frame after is the lab."""
    scene = rr.rod_collision(v1, 0.0, m, m, 1.0, 1.0, 1.0)
    assert_rest(scene.rods[0].motion.velocity_final)
    assert scene.frame("rod 1 after").key() == (0.0, 0.0)
    assert scene.frame("rod 1 after").same_velocity(rr.LAB)
    assert scene.final_velocities[1] == v1


@SETTINGS
@given(v1=velocities, ratio=st.sampled_from([(1, 1), (1, 2), (1, 4), (3, 4), (5, 8), (1, 16)]), k=st.integers(-30, 30))
def test_rod_1_stops_when_eps_is_the_mass_ratio(v1: float | None, ratio: tuple[int, int], k: int) -> None:
    """With rod 2 at rest, rod 1 stops when eps = M1/M2 (Eq. (29): eps M2 sinh = M1 sinh), for any V1
    above double-double's range floor (~1e-292; below, its low parts are subnormal and carry an
    absolute error of ~1e-323): e.g. eps = 1/2 of the paper's case I. The cancellation is noise, and is 0."""
    assume(v1 is not None and v1 > 1e-290)
    assert v1 is not None
    a, b = ratio
    m1, m2 = math.ldexp(float(a), k), math.ldexp(float(b), k)
    sol = rr.solve_collision(v1, 0.0, m1, m2, a / b)
    assert_rest(sol.after[0])


def test_case_I_at_half_restitution_stops_rod_1() -> None:
    scene = rr.rod_collision(0.6, 0.0, 1.0, 2.0, 1.0, 1.0, 0.5)
    assert_rest(scene.rods[0].motion.velocity_final)
    assert scene.frame("rod 1 after").key() == (0.0, 0.0)


@SETTINGS
@given(v=velocities, m=log_uniform(1e-6, 1e6), eps=restitutions)
def test_equal_and_opposite_rods_have_the_lab_as_barycentre(v: float | None, m: float, eps: float | None) -> None:
    """V1 = -V2 and equal masses: the barycentric frame is the lab, exactly, and the rods leave with
    exactly opposite velocities (the same rounding on both sides)."""
    assume(v is not None and v > 1e-290 and eps is not None)
    assert v is not None and eps is not None
    scene = rr.rod_collision(v, -v, m, m, 1.0, 1.0, eps)
    sol = rr.solve_collision(v, -v, m, m, eps)
    assert_rest(sol.u)
    assert scene.frame("barycentric").key() == (0.0, 0.0)
    a, b = sol.after
    assert (a.hi, a.lo, a.gap) == (-b.hi, -b.lo, b.gap)


def test_crash_moves_both_rods_with_the_barycentre() -> None:
    """eps = 0: both rods move on with u itself, so their frames after are the barycentric frame."""
    scene = rr.rod_collision(0.6, -0.3, 1.0, 2.0, 1.0, 1.5, 0.0)
    bary = scene.frame("barycentric")
    assert scene.frame("rod 1 after").same_velocity(bary)
    assert scene.frame("rod 2 after").same_velocity(bary)


# ---------------------------------------------------------------- the wall
def reference_wall(v: float, eps: float, mass: float) -> tuple[mpf, mpf, mpf]:
    """Sec. 5: the proper velocity gamma v becomes eps gamma v; heat M (gamma - gamma')."""
    dv = mp(v)
    gamma = 1 / mpmath.sqrt((1 - dv) * (1 + dv))
    u = mp(eps) * gamma * dv
    g = mpmath.sqrt(1 + u * u)
    return u / g, 1 / (g * (g + u)), mp(mass) * (gamma - g)


@SETTINGS
@given(
    v=parameter_values(rr.describe("wall-collision").parameter("v"), vmax=VMAX),
    eps=restitutions,
    mass=log_uniform(1e-6, 1e6),
)
def test_wall_agrees_with_mpmath(v: float | None, eps: float | None, mass: float) -> None:
    assert v is not None and eps is not None
    scene = rr.wall_collision(v, 1.0, eps, mass)
    got = scene.rods[0].motion.velocity_final
    with mpmath.workdps(DIGITS):
        ref_v, ref_gap, ref_heat = reference_wall(v, eps, mass)
        assert abs(dd_value(got) - ref_v) <= TOL_DD * ref_v + FLOOR
        assert abs(got.gap - ref_gap) <= TOL_GAP * ref_gap
        # (the reference's gamma - gamma' cancels to noise of 1e-100 gamma as eps -> 1)
        assert abs(scene.heat - ref_heat) <= 1e-15 * ref_heat + mpf(10) ** -80 * mp(mass) / (1 - mp(v) ** 2)
    if eps == 0.0:
        assert_rest(got)
    if eps == 1.0:
        assert (got.hi, got.lo) == (v, 0.0) and scene.heat == 0.0


# ---------------------------------------------------------------- frames: rapidities and composition
@SETTINGS
@given(
    psi=st.one_of(
        st.floats(-700.0, 700.0),
        log_uniform(1e-300, 1.0).map(lambda x: x),
        log_uniform(1e-300, 1.0).map(lambda x: -x),
    )
)
def test_velocity_from_rapidity_agrees_with_mpmath(psi: float) -> None:
    """tanh psi to ~1e-30 of itself, also for psi ~ 1e-300; its gap 2/(exp(2|psi|) + 1) to 1e-15."""
    v = velocity_from_rapidity(psi)
    with mpmath.workdps(DIGITS):
        ref = mpmath.tanh(mp(psi))
        gap = 2 / (mpmath.exp(2 * abs(mp(psi))) + 1)
        assert abs(dd_value(v) - ref) <= TOL_DD * abs(ref) + FLOOR
        assert abs(v.gap - gap) <= TOL_GAP * gap + FLOOR
    assert rr.Frame.from_rapidity(psi).velocity == v


def test_a_tiny_rapidity_keeps_its_relative_precision() -> None:
    v = velocity_from_rapidity(1e-300)
    assert v.hi == 1e-300 and v.gap == 1.0
    assert velocity_from_rapidity(-3e-200).hi == -3e-200
    assert velocity_from_rapidity(0.0) == REST


@SETTINGS
@given(x=st.floats(-18.0, 18.0), y=st.floats(-18.0, 18.0))
def test_composition_of_rapidity_frames_agrees_with_mpmath(x: float, y: float) -> None:
    """Frames from rapidities (double-double velocities, lo != 0) compose to ~1e-30, while ``hi + lo``
    resolves their gaps (beyond |psi| ~ 18.4 the stored gap takes over, and is the better one)."""
    a, b = velocity_from_rapidity(x), velocity_from_rapidity(y)
    composed = compose_velocities(a, b)
    with mpmath.workdps(DIGITS):
        va, vb = dd_value(a), dd_value(b)
        ref = (va + vb) / (1 + va * vb)
        terms = min(abs(va) + abs(vb), (1 - abs(va)) + (1 - abs(vb)))
        assert abs(dd_value(composed) - ref) <= TOL_DD * (abs(ref) + terms) + FLOOR
        gap = 1 - abs(ref)
        assert abs(composed.gap - gap) <= TOL_GAP * gap


# ---------------------------------------------------------------- Rindler radii (Eq. (15))
@SETTINGS
@given(
    v=st.floats(0.01, 0.99),
    length=log_uniform(1e-6, 1e6),
    a_length=st.floats(1e-9, 1.0, exclude_max=True),
)
def test_rindler_radii_are_correctly_rounded(v: float, length: float, a_length: float) -> None:
    """rho_B = (1 - a'_F L0)/a'_F and rho_F = rho_B + L0 from the exact product a'_F L0: within an ulp
    (correctly rounded but for double rounding), and the centre at -rho_B (the rod at rest on [0, L0])."""
    a_front = a_length / length
    assume(0.0 < a_front * length < 1.0)
    scene = rr.constant_acceleration(v, length, a_front)
    m = scene.rods[0].motion
    rho = (1 - Fraction(a_front) * Fraction(length)) / Fraction(a_front)
    for got, exact in ((m.radius_left, rho), (m.radius_right, rho + Fraction(length)), (m.horizon_x, -rho)):
        assert abs(Fraction(got) - exact) <= Fraction(math.ulp(float(exact))), (got, float(exact))
    assert near_radius(a_front, length)[0] == m.radius_left
