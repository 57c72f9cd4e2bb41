"""Collision of two rigid rods along x, solved in the barycentric frame (paper Secs. 5-6, Figs. 3-4)."""

from __future__ import annotations

from dataclasses import dataclass
from decimal import Decimal
from types import MappingProxyType

from .._build import EPS, SIZE, checked_scene, decimal_context, rigid_motion
from .._description import (
    VELOCITY,
    EventDescription,
    OriginEvent,
    Parameter,
    SceneDescription,
    ScenePreset,
    Slider,
)
from .._exact import ExactVelocity, lorentz_factor_decimal, velocity_from_proper_velocity
from .._frame import LAB, Frame
from .._scene import EventSpec, Rod, Scene
from .._validate import ParameterError


@dataclass(frozen=True)
class CollisionSolution:
    """The barycentric solution of a rod-rod collision (paper Sec. 6), to 60 digits.

    ``u``: barycentric velocity (Eq. (26)); ``bar_before``/``bar_after``: each rod's
    velocity in the barycentric frame before and after (``gamma' V' = -eps gamma V``,
    Eq. (29)); ``after``: lab velocities (Eq. (31)); ``mass_factor``: the common
    factor by which both rest masses grow (1 for eps = 1).
    """

    u: ExactVelocity
    bar_proper_before: tuple[Decimal, Decimal]
    """Barycentric proper velocities ``gamma v`` before (60 digits)."""
    bar_proper_after: tuple[Decimal, Decimal]
    after: tuple[ExactVelocity, ExactVelocity]
    mass_factor: Decimal
    heat: Decimal

    @property
    def bar_before(self) -> tuple[ExactVelocity, ExactVelocity]:
        a, b = self.bar_proper_before
        return velocity_from_proper_velocity(a), velocity_from_proper_velocity(b)

    @property
    def bar_after(self) -> tuple[ExactVelocity, ExactVelocity]:
        a, b = self.bar_proper_after
        return velocity_from_proper_velocity(a), velocity_from_proper_velocity(b)


def _cancelled_sum(a: Decimal, b: Decimal) -> Decimal:
    """``a + b``, exactly 0 when the sum is below the 60-digit arithmetic's noise (1e-45 of the terms).

    E.g. equal masses, elastic: rod 1 stops dead rather than at 1e-61 c.
    """
    total = a + b
    if abs(total) <= Decimal("1e-45") * (abs(a) + abs(b)):
        return Decimal(0)
    return total


def solve_collision(v1: float, v2: float, m1: float, m2: float, eps: float) -> CollisionSolution:
    """Final velocities of two colliding bodies from the barycentric frame (c = 1).

    With ``g_i = gamma_i``, ``u_i = gamma_i v_i``: ``E = m1 g1 + m2 g2``, ``P = m1 u1 + m2 u2``,
    invariant mass ``M = sqrt(m1^2 + m2^2 + 2 m1 m2 gamma_rel)``, relative
    ``sinh = g1 g2 (v1 - v2)``, ``cosh = g1 g2 (1 - v1 v2)``. Barycentric proper velocities
    ``bar u_1 = m2 sinh / M``, ``bar u_2 = -m1 sinh / M`` (no cancellation), after:
    ``-eps bar u_i``; back to the lab: ``u_i' = (E bar u_i' + P bar g_i') / M``. 4-momentum
    is conserved with both rest masses scaled by ``k = M / (m1 bar g_1' + m2 bar g_2')``.
    """
    with decimal_context():
        d1, d2, dm1, dm2, de = Decimal(v1), Decimal(v2), Decimal(m1), Decimal(m2), Decimal(eps)
        g1, g2 = lorentz_factor_decimal(d1), lorentz_factor_decimal(d2)
        u1, u2 = g1 * d1, g2 * d2
        energy = dm1 * g1 + dm2 * g2
        momentum = _cancelled_sum(dm1 * u1, dm2 * u2)
        rel_sinh = g1 * g2 * (d1 - d2)
        rel_cosh = g1 * g2 * (1 - d1 * d2)
        mass = (dm1 * dm1 + dm2 * dm2 + 2 * dm1 * dm2 * rel_cosh).sqrt()
        bar_u = (dm2 * rel_sinh / mass, -dm1 * rel_sinh / mass)
        bar_u_after = (-de * bar_u[0], -de * bar_u[1])
        bar_g_after = tuple((1 + b * b).sqrt() for b in bar_u_after)
        lab_u_after = tuple(_cancelled_sum(energy * b, momentum * g) / mass for b, g in zip(bar_u_after, bar_g_after))
        denom = dm1 * bar_g_after[0] + dm2 * bar_g_after[1]
        excess = _cancelled_sum(mass, -denom)  # M - (m1 bar g1' + m2 bar g2') >= 0: no heat below the noise
        if de == 1 or excess <= 0:  # elastic: bar g' = bar g, so denom = M exactly
            factor, heat = Decimal(1), Decimal(0)
        else:
            factor = mass / denom
            heat = excess / denom * (dm1 + dm2)
        # barycentric velocity u = P / E, with 1 - |u| = (E - |P|)/E formed without cancellation
        e_minus_p = dm1 * g1 * (1 - d1) + dm2 * g2 * (1 - d2)
        e_plus_p = dm1 * g1 * (1 + d1) + dm2 * g2 * (1 + d2)
        u = momentum / energy
        u_gap = (e_minus_p if u >= 0 else e_plus_p) / energy
        u_hi = float(u)
        u_exact = ExactVelocity(u_hi, float(u - Decimal(u_hi)), float(u_gap))
        return CollisionSolution(
            u=u_exact,
            bar_proper_before=bar_u,
            bar_proper_after=bar_u_after,
            after=(velocity_from_proper_velocity(lab_u_after[0]), velocity_from_proper_velocity(lab_u_after[1])),
            mass_factor=factor,
            heat=heat,
        )


def rod_collision(v1: float, v2: float, m1: float, m2: float, l1: float, l2: float, eps: float) -> Scene:
    """Collision of two rigid rods along x (Secs. 5-6, Figs. 3-4).

    Rod 1 (mass ``m1``, rest length ``l1``, velocity ``v1``) is on the left, rod 2 on the
    right; ``v1 > v2``. Rod 1's right end meets rod 2's left end at ``x = 0, t = 0`` and
    both contact ends change velocity at once (to the barycentric solution of
    :func:`solve_collision`). The far ends follow ``x = -sqrt(L1^2 + t^2)`` from
    ``T_1 = -gamma_1 V_1 L_1`` to ``T_1' = -gamma_1' V_1' L_1`` and ``x = sqrt(L2^2 + t^2)``
    from ``T_2 = gamma_2 V_2 L_2`` to ``T_2' = gamma_2' V_2' L_2`` (Eqs. (22)-(25)).
    Events: ``"T_1"``, ``"T_1'"``, ``"T_2"``, ``"T_2'"``.
    """
    v1 = V1.check(v1)
    v2 = V2.check(v2)
    if not v2 < v1:
        raise ParameterError("v2", f"less than v1 = {v1!r} so that the rods collide", v2)
    m1 = M1.check(m1)
    m2 = M2.check(m2)
    l1 = L1.check(l1)
    l2 = L2.check(l2)
    eps = EPS.check(eps)
    sol = solve_collision(v1, v2, m1, m2, eps)
    k = sol.mass_factor
    with decimal_context():
        m1_after, m2_after = float(Decimal(m1) * k), float(Decimal(m2) * k)
    rod1 = rigid_motion(ExactVelocity.from_float(v1), sol.after[0], l1, Decimal(0), -l1)
    rod2 = rigid_motion(ExactVelocity.from_float(v2), sol.after[1], l2, Decimal(0), 0.0)
    frames = MappingProxyType(
        {
            "lab": LAB,
            "rod 1 before": Frame(rod1.velocity_initial, "rod 1 before"),
            "rod 2 before": Frame(rod2.velocity_initial, "rod 2 before"),
            "rod 1 after": Frame(rod1.velocity_final, "rod 1 after"),
            "rod 2 after": Frame(rod2.velocity_final, "rod 2 after"),
            "barycentric": Frame(sol.u, "barycentric"),
        }
    )
    specs = (
        EventSpec("T_1", 0, 0, "start"),
        EventSpec("T_1'", 0, 0, "stop"),
        EventSpec("T_2", 1, 1, "start"),
        EventSpec("T_2'", 1, 1, "stop"),
    )
    return checked_scene(
        Scene(
            kind=ROD_COLLISION.kind,
            parameters=MappingProxyType({"v1": v1, "v2": v2, "m1": m1, "m2": m2, "l1": l1, "l2": l2, "eps": eps}),
            rods=(Rod("rod 1", rod1, m1, m1_after), Rod("rod 2", rod2, m2, m2_after)),
            event_specs=specs,
            frames=frames,
            external_source="none",
            heat=float(sol.heat),
            origin_event=OriginEvent.CONTACT,
        )
    )


V1 = Parameter("v1", "V1", "V1", "c", VELOCITY, 0.6, "velocity V1 of rod 1 (left)", Slider(-0.99, 0.99, 0.01))
V2 = Parameter(
    "v2",
    "V2",
    "V2",
    "c",
    VELOCITY,
    0.0,
    "velocity V2 of rod 2 (right)",
    Slider(-0.99, 0.99, 0.01),
    constraint="less than v1",
)
M1 = Parameter("m1", "M1", "M1", "mass unit", SIZE, 1.0, "rest mass M1 of rod 1", typical=(0.1, 10.0))
M2 = Parameter(
    "m2",
    "M2",
    "M2/M1",
    "mass unit",
    SIZE,
    2.0,
    "rest mass M2 of rod 2 (in the app, in units of M1)",
    Slider(0.01, 100.0, 0.01, "log"),
)
L1 = Parameter("l1", "L1", "L1", "length unit", SIZE, 1.0, "rest length L1 of rod 1", typical=(0.1, 10.0))
L2 = Parameter(
    "l2",
    "L2",
    "L2/L1",
    "length unit",
    SIZE,
    1.0,
    "rest length L2 of rod 2 (in the app, in units of L1)",
    Slider(0.1, 5.0, 0.05),
)
_PAPER = {"v1": 0.6, "v2": 0.0, "l1": 1.0, "l2": 1.0, "eps": 1.0}

ROD_COLLISION = SceneDescription(
    kind="rod-collision",
    title="Rod-rod collision",
    summary="Rod 1 at V1 hits rod 2 at V2 < V1; their touching ends take the barycentric solution at once.",
    source="Secs. 5-6",
    constructor=rod_collision,
    parameters=(V1, M2, V2, L2, EPS, M1, L1),
    frames=("lab", "rod 1 before", "rod 2 before", "rod 1 after", "rod 2 after", "barycentric"),
    default_frame="barycentric",
    events=(
        EventDescription("T_1", "the far (left) end of rod 1 starts changing velocity", "Sec. 5, Eq. (22)"),
        EventDescription("T_1'", "the far end of rod 1 has its final velocity", "Sec. 5, Eq. (24)"),
        EventDescription("T_2", "the far (right) end of rod 2 starts changing velocity", "Sec. 5, Eq. (22)"),
        EventDescription("T_2'", "the far end of rod 2 has its final velocity", "Sec. 5, Eq. (25)"),
    ),
    presets=(
        ScenePreset("Fig. 3: collision, M2 = 2 M1", {**_PAPER, "m1": 1.0, "m2": 2.0}),
        ScenePreset("Fig. 4: collision, M1 = 2 M2", {**_PAPER, "m1": 1.0, "m2": 0.5}),
    ),
    order=60,
)

SCENES = (ROD_COLLISION,)
