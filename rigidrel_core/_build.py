"""What every scene constructor shares: the Born-rigid change of one rod (its Rindler radii in
double-double), the frame presets, the shared parameters and the check that a scene fits in float64."""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from types import MappingProxyType
from typing import Literal

from . import _dd
from ._dd import DD, SPLITTER
from ._description import SPEED, UNIT_CLOSED, Interval, Parameter, Slider
from ._exact import ExactVelocity
from ._frame import LAB, Frame
from ._motion import RigidMotion
from ._scene import Rod, Scene
from ._validate import ParameterError

# ---------------------------------------------------------------------- shared parameters
#: Largest |coordinate| of a lab event or Rindler radius a scene may have; squares of
#: anything a frame makes of it (times gamma <= 7e7) stay far inside float64.
MAX_SCENE_COORDINATE = 1e120
#: Smallest length or mass a scene may have: a product or quotient of two sizes (a window's width,
#: a drawing's scale, Bell's r/s) stays a normal float, never 0 (a subnormal rod once made a drawing
#: of no width).
MIN_SCENE_SIZE = 1.0 / MAX_SCENE_COORDINATE
#: Lengths and masses: from 1e-120 to 1e120 (so every product a frame forms stays finite and none
#: underflows).
SIZE = Interval(MIN_SCENE_SIZE, MAX_SCENE_COORDINATE, lo_closed=True, hi_closed=True)
#: Proper accelerations: a Rindler radius 1/a of at most 1e120.
ACCELERATION = Interval(1.0 / MAX_SCENE_COORDINATE, math.inf)
V = Parameter(
    "v",
    "V",
    "V",
    "c",
    SPEED,
    0.6,
    "speed V (c = 1): the final speed of a rod that starts at rest, or the approach speed of one that moves "
    "at −V toward its stop (each scene's help says which)",
    Slider(0.01, 0.99, 0.01),
)
LENGTH = Parameter("length", "L0", "L0", "length unit", SIZE, 1.0, "rest length L0", typical=(0.1, 10.0))
A_FRONT = Parameter(
    "a_front",
    "a′_F",
    "a′_F L0",
    "1/length unit",
    ACCELERATION,
    0.5,
    "front-end proper acceleration a′_F (the paper's prime: measured in the end's momentary rest frame); the "
    "back end has a′_B = a′_F/(1 − a′_F L0) (Sec. 3, Eq. (15))",
    Slider(0.01, 0.99, 0.01),
    constraint="a_front * length in (0, 1)",
)
MASS = Parameter("mass", "M", "M", "mass unit", SIZE, 1.0, "rest mass M", typical=(0.1, 10.0))
EPS = Parameter(
    "eps",
    "ε",
    "ε (restitution)",
    "",
    UNIT_CLOSED,
    1.0,
    "coefficient of restitution ε, as the paper defines it (Sec. 6, Eq. (29)): the ratio of each body's "
    "proper velocity γV after the impact to before, reversed, in the barycentric frame (zero total "
    "momentum; for a wall, the wall's frame); 0 sticks (crash), 1 is elastic. Not the ratio of speeds: "
    "a rod at V = 0.6 against a wall with ε = 0.5 has γV = 0.75 halved and leaves at 0.3511, not 0.3",
    Slider(0.0, 1.0, 0.01),
)
#: Frame presets of a one-rod scene, in menu order.
SINGLE_ROD_FRAMES = ("lab", "rod before", "rod after")


# ---------------------------------------------------------------------- one rod's change
#: ``rho_near`` of an impulse (Sec. 4): the near end is at the centre.
IMPULSE: DD = (0.0, 0.0)


def rigid_motion(
    v_initial: ExactVelocity,
    v_final: ExactVelocity,
    length: float,
    rho_near: DD,
    vertex_left: float,
) -> RigidMotion:
    """Born-rigid change ``v_initial -> v_final``; at lab t = 0 the (extended) family is at rest on
    ``[vertex_left, vertex_left + length]``; the end nearest the centre is ``rho_near`` (a
    double-double) from it (``rho_near = 0``: the impulsive limit of Sec. 4).

    The centre lies behind the rod: at ``vertex_left - rho_near`` when it speeds up to the
    right (``sign = 1``), at ``vertex_left + rho_near + length`` otherwise; the far end's radius
    is ``rho_near + length``. Each is summed in double-double and rounded once, so the
    floats stored are the exact sums correctly rounded."""
    sign: Literal[1, -1] = 1 if (v_final.hi, v_final.lo) > (v_initial.hi, v_initial.lo) else -1
    if rho_near == IMPULSE:  # single float operations, each correctly rounded
        horizon, r_left, r_right = (vertex_left, 0.0, length) if sign == 1 else (vertex_left + length, length, 0.0)
        return RigidMotion(length, sign, horizon, r_left, r_right, vertex_left, v_initial, v_final)
    # two_sum written out (this runs on every slider change): far = rho_near + length
    rho, rho_lo = rho_near
    far = rho + length
    t = far - rho
    far_lo = ((rho - (far - t)) + (length - t)) + rho_lo
    if sign == 1:  # horizon = vertex_left - rho_near
        h = vertex_left - rho
        t = h - vertex_left
        horizon = h + (((vertex_left - (h - t)) - (rho + t)) - rho_lo)
        r_left, r_right = rho, far + far_lo
    else:  # horizon = vertex_left + far
        h = vertex_left + far
        t = h - vertex_left
        horizon = h + (((vertex_left - (h - t)) + (far - t)) + far_lo)
        r_left, r_right = far + far_lo, rho
    return RigidMotion(length, sign, horizon, r_left, r_right, vertex_left, v_initial, v_final)


#: ``a'_F L0`` of a constant acceleration: 1 would be the impulsive limit (a scene of its own).
BELOW_HORIZON = Interval(0.0, 1.0)


def near_radius(a_front: float, length: float, allowed: Interval = BELOW_HORIZON) -> DD:
    """``a_front * length`` in ``allowed`` (the product taken exactly, as a double-double);
    returns ``rho_near = (1 - a L)/a`` in double-double.

    Sec. 3, Eq. (15): ``a'_B = a'_F / (1 - a'_F L0)``, so the near (back) end sits at
    ``1/a'_B = (1 - a'_F L0)/a'_F`` from the centre; ``a'_F L0 = 1`` is the impulsive limit.
    """
    if a_front > 2.0**500:  # scaled by 2**-600 (exactly), so that splitting it cannot overflow
        a = a_front * 2.0**-600
        aL = _dd.two_prod(a, length)
        aL = (aL[0] * 2.0**600, aL[1] * 2.0**600)
        rho = _dd.div(_dd.add_float((-aL[0], -aL[1]), 1.0), (a, 0.0))
        rho = (rho[0] * 2.0**-600, rho[1] * 2.0**-600)
    else:  # two_prod, 1 - aL and the division by a, written out (every slider change runs this)
        p = a_front * length
        t = SPLITTER * a_front
        a_h = t - (t - a_front)
        a_t = a_front - a_h
        t = SPLITTER * length
        l_h = t - (t - length)
        l_t = length - l_h
        e = ((a_h * l_h - p) + a_h * l_t + a_t * l_h) + a_t * l_t
        aL = (p, e)
        s = 1.0 - p
        t = s - 1.0
        s_lo = ((1.0 - (s - t)) - (p + t)) - e  # 1 - aL = s + s_lo
        q = s / a_front
        t = SPLITTER * q
        q_h = t - (t - q)
        p = q * a_front
        q_lo = ((s - p) - (((q_h * a_h - p) + q_h * a_t + (q - q_h) * a_h) + (q - q_h) * a_t) + s_lo) / a_front
        rho = (q + q_lo, q_lo - ((q + q_lo) - q))
    # positive, as both factors are; below 1, or (the impulsive limit, where allowed) exactly 1
    if not (aL[0] < 1.0 or (aL[0] == 1.0 and (aL[1] < 0.0 or (allowed.hi_closed and aL[1] == 0.0)))):
        raise ParameterError("a_front * length", f"a finite number {allowed.text()}", aL[0])
    return rho


def single_rod_frames(motion: RigidMotion) -> Mapping[str, Frame]:
    return MappingProxyType(
        {
            "lab": LAB,
            "rod before": Frame(motion.velocity_initial, "rod before"),
            "rod after": Frame(motion.velocity_final, "rod after"),
        }
    )


def checked_scene(scene: Scene) -> Scene:
    """Reject parameter combinations whose derived numbers leave the representable range."""
    checked_rods(scene.rods, scene.parameters)
    return scene


def checked_rods(rods: Sequence[Rod], parameters: Mapping[str, float]) -> None:
    """:func:`checked_scene` on a scene's rods before the scene is made (a constructor that derives
    more from them, such as Bell's string, checks them first); ``parameters`` for the error."""
    bound = MAX_SCENE_COORDINATE
    for r in rods:
        m = r.motion
        v_i, v_f = m.velocity_initial, m.velocity_final
        if not (v_i.gap > 0.0 and v_f.gap > 0.0):
            below_light = "such that every velocity stays below light speed"
            raise ParameterError("parameters", below_light, dict(parameters))
        # the lab events of the ends: the centre, the radii, the mass, radius times gamma v of the
        # faster velocity (the smaller gap); NaN fails too
        reach = max(m.radius_left, m.radius_right) * abs((v_i if v_i.gap < v_f.gap else v_f).proper_velocity())
        if not (abs(m.horizon_x) <= bound and m.radius_left <= bound and m.radius_right <= bound):
            raise ParameterError("parameters", _OUT_OF_RANGE, dict(parameters))
        if not (r.mass_after <= bound and reach <= bound):
            raise ParameterError("parameters", _OUT_OF_RANGE, dict(parameters))


_OUT_OF_RANGE = f"such that every lab event and Rindler radius lies within {MAX_SCENE_COORDINATE:g} of the origin"
