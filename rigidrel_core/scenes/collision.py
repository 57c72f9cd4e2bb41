"""Collision of two rigid rods along x, solved in the barycentric frame (paper Secs. 5-6, Figs. 3-4).

The scalar solution is computed in double-double arithmetic (about 32 digits) by the two compounds
of :mod:`rigidrel_core._dd` made for it, one call each (it runs on every slider change):
:func:`~rigidrel_core._dd.barycentre` (the barycentric frame and each rod's proper velocity in it
after, Eqs. (26)-(29)) and :func:`~rigidrel_core._dd.leave_barycentre` (the rods back in the lab,
Eq. (31)).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from types import MappingProxyType

from .._build import EPS, IMPULSE, SIZE, checked_scene, rigid_motion
from .._dd import barycentre, leave_barycentre
from .._description import (
    VELOCITY,
    EventDescription,
    OriginEvent,
    Parameter,
    SceneDescription,
    ScenePreset,
    Slider,
)
from .._exact import REST, ExactVelocity, compose_velocities
from .._frame import LAB, Frame
from .._paper import FIG3_CASE_ONE, FIG4_CASE_TWO
from .._scene import EventSpec, Rod, Scene
from .._validate import ParameterError, refuse_renamed

#: Masses outside ``(2**-200, 2**200)`` are scaled by a common power of 2 (exactly) before
#: solving, so that no product of the solution overflows or underflows (only their ratio matters).
_MASS_MIN, _MASS_MAX = 2.0**-200, 2.0**200
#: An ExactVelocity is made as ExactVelocity.__init__ would, without its call: a new instance
#: and its slots' setters (three per solve; the call itself costs about as much as the setters).
_NEW = object.__new__
_SET_HI, _SET_LO, _SET_GAP = (ExactVelocity.__dict__[name].__set__ for name in ("hi", "lo", "gap"))


def _exact(hi: float, lo: float, gap: float) -> ExactVelocity:
    """``ExactVelocity(hi, lo, gap)`` without the dataclass' ``__init__`` (a solve makes three)."""
    v = _NEW(ExactVelocity)
    _SET_HI(v, hi)
    _SET_LO(v, lo)
    _SET_GAP(v, gap)
    return v


@dataclass(frozen=True, init=False)
class CollisionSolution:
    """The barycentric solution of a rod-rod collision (paper Sec. 6), velocities to double-double.

    ``u``: barycentric velocity (Eq. (26)); ``after``: lab velocities after (Eq. (31));
    ``mass_gain``: ``k - 1``, with ``k`` the common factor by which both rest masses grow
    (0 for eps = 1); ``heat``: the rest energy created, ``(k - 1)(M1 + M2)``; ``before``: the
    lab velocities before. Each rod's velocity in the barycentric frame, before and after
    (Eqs. (27)-(29), ``gamma' V' = -eps gamma V``), is derived on demand:
    :attr:`bar_before`, :attr:`bar_after`.
    """

    u: ExactVelocity
    after: tuple[ExactVelocity, ExactVelocity]
    mass_gain: float
    heat: float
    before: tuple[float, float]

    def __init__(
        self,
        u: ExactVelocity,
        after: tuple[ExactVelocity, ExactVelocity],
        mass_gain: float,
        heat: float,
        before: tuple[float, float],
    ) -> None:
        # into the instance's dict, not through one object.__setattr__ call each (the generated __init__)
        fields = self.__dict__
        fields["u"] = u
        fields["after"] = after
        fields["mass_gain"] = mass_gain
        fields["heat"] = heat
        fields["before"] = before

    @property
    def mass_factor(self) -> float:
        """``k``: both rest masses are multiplied by it (1 for eps = 1)."""
        return 1.0 + self.mass_gain

    @property
    def bar_before(self) -> tuple[ExactVelocity, ExactVelocity]:
        """Each rod's velocity before, seen from the barycentric frame (``V_i`` composed with ``-u``)."""
        back = self.u.negated()
        return (
            compose_velocities(ExactVelocity.from_float(self.before[0]), back),
            compose_velocities(ExactVelocity.from_float(self.before[1]), back),
        )

    @property
    def bar_after(self) -> tuple[ExactVelocity, ExactVelocity]:
        """Each rod's velocity after, seen from the barycentric frame (``V'_i`` composed with ``-u``)."""
        back = self.u.negated()
        return compose_velocities(self.after[0], back), compose_velocities(self.after[1], back)


def solve_collision(v1: float, v2: float, m1: float, m2: float, eps: float) -> CollisionSolution:
    """Final velocities of two colliding bodies from the barycentric frame (c = 1), in double-double.

    With ``c_i = 1/gamma_i = sqrt(1 - v_i^2)`` every quantity is carried times ``c1 c2`` (which
    cancels in every ratio): ``E = m1 c2 + m2 c1``, ``P = m1 v1 c2 + m2 v2 c1`` and the
    light-cone components ``P+- = E +- P = m1 (1 +- v1) c2 + m2 (1 +- v2) c1``, the smaller one
    summed from its positive terms; invariant mass ``M^2 = P+ P-``; the relative proper velocity
    ``sinh = v1 - v2``. Barycentric velocity ``u = P/E`` (Eq. (26)), ``1 -+ u = P-+/E``.

    Each rod's barycentric proper velocity ``m2 sinh/M`` (rod 1), ``-m1 sinh/M`` (rod 2) becomes
    ``-eps`` times itself (Eq. (29)): with ``k_1 = eps m2 sinh``, ``k_2 = eps m1 sinh`` and
    ``R_i = sqrt(M^2 + k_i^2)`` (``M`` times the barycentric gamma after), rod ``i`` leaves the
    barycentre with ``w_1 = -k_1/R_1``, ``w_2 = k_2/R_2``, and the lab velocity is their
    composition with ``u`` (Eq. (31)):

    * ``V'_i = (u R_i -+ k_i)/(R_i -+ u k_i)``, where ``u`` and ``w_i`` have the same sign or
      their rapidities add up to at most 1 (a cancellation here is one of the terms);
    * else, in light-cone form, ``exp(theta'_1) = P+/(R_1 + k_1)``, ``exp(-theta'_2) = P-/(R_2 + k_2)``,
      ``V' = (X^2 - Y^2)/(X^2 + Y^2)``, which does not cancel when both are near light.

    Gaps to light speed are ``1 - |V'|`` from the double-double ``V'``, or, within 2**-30 of light,
    ``2 Y^2/(X^2 + Y^2)`` (``V' > 0``; else ``2 X^2/(X^2 + Y^2)``) from those positive ``X`` and
    ``Y``; either way rounded once from double-double. 4-momentum is conserved with both rest
    masses scaled by ``k = M / (m1 g'_1 + m2 g'_2)``, ``g'_i = R_i/M``; ``k - 1 = (1 - eps^2)
    sum_i m_i b_i^2/(g_i + g'_i) / (m1 g'_1 + m2 g'_2)`` (``b_i``, ``g_i``: barycentric proper
    velocity and gamma before), without cancellation.

    A velocity whose terms cancel to below double-double's noise (``NOISE``, 2**-100 of the
    terms) is exactly 0: equal masses with V1 = -V2 have the lab as barycentric frame; an
    elastic hit on an equal rod at rest, or ``eps = M1/M2`` on a heavier one, stops rod 1 dead.
    ``eps = 0``: both rods move on with ``u`` itself. Speeds below ~1e-292 c, where a low part is
    subnormal, keep an absolute error of a few 1e-323 instead of a relative one.
    """
    mass_sum = m1 + m2
    if not (_MASS_MIN < m1 < _MASS_MAX and _MASS_MIN < m2 < _MASS_MAX):
        shift = math.frexp(max(m1, m2))[1]
        m1, m2 = math.ldexp(m1, -shift), math.ldexp(m2, -shift)
    centre = barycentre(m1, v1, m2, v2, eps)  # u, 1 - |u|, P+-, M^2, k_1, k_2 (Eqs. (26)-(29))
    u, u_lo, u_gap = centre[0], centre[1], centre[2]
    bary = _exact(u, u_lo, u_gap) if u else REST
    s = v1 - v2
    if eps == 0.0:  # perfectly inelastic: both move on with the barycentre; k - 1 = sum m_i (g_i - 1) / M
        mc = math.sqrt(centre[7])  # M, from M^2's high part
        b1, b2 = m2 * s / mc, m1 * s / mc
        gain = (m1 * b1 * b1 / (math.sqrt(1.0 + b1 * b1) + 1.0) + m2 * b2 * b2 / (math.sqrt(1.0 + b2 * b2) + 1.0)) / (
            m1 + m2
        )
        return CollisionSolution(bary, (bary, bary), gain, gain * mass_sum, (v1, v2))
    v, v_lo, gap, r_1, w, w_lo, w_gap, r_2 = leave_barycentre(centre)  # V'_i, 1 - |V'_i|, R_i (Eq. (31))
    after_1 = _exact(v, v_lo, gap) if v else REST
    after_2 = _exact(w, w_lo, w_gap) if w else REST
    if eps == 1.0:
        gain = 0.0
    else:  # k - 1 = (1 - eps^2) sum_i m_i b_i^2/(g_i + g'_i) / (m1 g'_1 + m2 g'_2)
        inv_m = 1.0 / math.sqrt(centre[7])  # 1/M
        b1, b2 = m2 * s * inv_m, m1 * s * inv_m
        g1, g2 = r_1 * inv_m, r_2 * inv_m
        gain = (
            (1.0 - eps)
            * (1.0 + eps)
            * (m1 * b1 * b1 / (math.sqrt(1.0 + b1 * b1) + g1) + m2 * b2 * b2 / (math.sqrt(1.0 + b2 * b2) + g2))
            / (m1 * g1 + m2 * g2)
        )
    sol = _NEW(CollisionSolution)  # as CollisionSolution.__init__ does, without its call
    fields = sol.__dict__
    fields["u"] = bary
    fields["after"] = (after_1, after_2)
    fields["mass_gain"] = gain
    fields["heat"] = gain * mass_sum
    fields["before"] = (v1, v2)
    return sol


#: The far ends' switches (Eqs. (22)-(25)); the same in every collision.
_EVENTS = (
    EventSpec("T_1", 0, 0, "start"),
    EventSpec("T_1'", 0, 0, "stop"),
    EventSpec("T_2", 1, 1, "start"),
    EventSpec("T_2'", 1, 1, "stop"),
)
#: The parameters' names before every scene took one name per quantity (``mass``, ``length``, with
#: the rod's number for two rods): refused, naming the new ones.
RENAMED = MappingProxyType({"m1": "mass1", "m2": "mass2", "l1": "length1", "l2": "length2"})


@refuse_renamed(RENAMED)
def rod_collision(
    v1: float, v2: float, mass1: float, mass2: float, length1: float, length2: float, eps: float
) -> Scene:
    """Collision of two rigid rods along x (Secs. 5-6, Figs. 3-4).

    Rod 1 (rest mass ``mass1`` = M1, rest length ``length1`` = L1, velocity ``v1``) is on the left,
    rod 2 on the right; ``v1 > v2``. Rod 1's right end meets rod 2's left end at ``x = 0, t = 0``
    and both contact ends change velocity at once (to the barycentric solution of
    :func:`solve_collision`). The far ends follow ``x = -sqrt(L1^2 + t^2)`` from
    ``T_1 = -gamma_1 V_1 L_1`` to ``T_1' = -gamma_1' V_1' L_1`` and ``x = sqrt(L2^2 + t^2)``
    from ``T_2 = gamma_2 V_2 L_2`` to ``T_2' = gamma_2' V_2' L_2`` (Eqs. (22)-(25)).
    Events: ``"T_1"``, ``"T_1'"``, ``"T_2"``, ``"T_2'"``.
    """
    v1 = V1.check(v1)
    v2 = V2.check(v2)
    if not v2 < v1:
        raise ParameterError("v2", f"less than v1 = {v1!r} so that the rods collide", v2)
    m1 = MASS1.check(mass1)
    m2 = MASS2.check(mass2)
    l1 = LENGTH1.check(length1)
    l2 = LENGTH2.check(length2)
    eps = EPS.check(eps)
    sol = solve_collision(v1, v2, m1, m2, eps)
    m1_after, m2_after = m1 + m1 * sol.mass_gain, m2 + m2 * sol.mass_gain
    rod1 = rigid_motion(ExactVelocity.from_float(v1), sol.after[0], l1, IMPULSE, -l1)
    rod2 = rigid_motion(ExactVelocity.from_float(v2), sol.after[1], l2, IMPULSE, 0.0)
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
    parameters = {"v1": v1, "v2": v2, "mass1": m1, "mass2": m2, "length1": l1, "length2": l2, "eps": eps}
    return checked_scene(
        Scene(
            kind=ROD_COLLISION.kind,
            parameters=MappingProxyType(parameters),
            rods=(Rod("rod 1", rod1, m1, m1_after), Rod("rod 2", rod2, m2, m2_after)),
            event_specs=_EVENTS,
            frames=frames,
            external_source="none",
            heat=sol.heat,
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
MASS1 = Parameter("mass1", "M1", "M1", "mass unit", SIZE, 1.0, "rest mass M1 of rod 1", typical=(0.1, 10.0))
MASS2 = Parameter(
    "mass2",
    "M2",
    "M2/M1",
    "mass unit",
    SIZE,
    2.0,
    "rest mass M2 of rod 2 (in the app, in units of M1)",
    Slider(0.01, 100.0, 0.01, "log"),
)
LENGTH1 = Parameter("length1", "L1", "L1", "length unit", SIZE, 1.0, "rest length L1 of rod 1", typical=(0.1, 10.0))
LENGTH2 = Parameter(
    "length2",
    "L2",
    "L2/L1",
    "length unit",
    SIZE,
    1.0,
    "rest length L2 of rod 2 (in the app, in units of L1)",
    Slider(0.1, 5.0, 0.05),
)
ROD_COLLISION = SceneDescription(
    kind="rod-collision",
    title="Rod-rod collision",
    summary=(
        "Rod 1 at V1 hits rod 2 at V2 < V1; their touching ends take the barycentric (zero total momentum) "
        "solution at once."
    ),
    source="Secs. 5-6",
    constructor=rod_collision,
    parameters=(V1, MASS2, V2, LENGTH2, EPS, MASS1, LENGTH1),
    frames=("lab", "rod 1 before", "rod 2 before", "rod 1 after", "rod 2 after", "barycentric"),
    default_frame="barycentric",
    events=(
        EventDescription("T_1", "the far (left) end of rod 1 starts changing velocity", "Sec. 5, Eq. (22)"),
        EventDescription("T_1'", "the far end of rod 1 has its final velocity", "Sec. 5, Eq. (24)"),
        EventDescription("T_2", "the far (right) end of rod 2 starts changing velocity", "Sec. 5, Eq. (22)"),
        EventDescription("T_2'", "the far end of rod 2 has its final velocity", "Sec. 5, Eq. (25)"),
    ),
    presets=(
        ScenePreset("Fig. 3: collision, M2 = 2 M1", FIG3_CASE_ONE),
        ScenePreset("Fig. 4: collision, M1 = 2 M2", FIG4_CASE_TWO),
    ),
    renamed=RENAMED,
    order=60,
)

SCENES = (ROD_COLLISION,)
