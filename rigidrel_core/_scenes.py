"""The scenes of Franklin (2012), exact in every frame (c = 1).

Each constructor validates its inputs, solves the scene's scalar physics once in 60-digit
decimal arithmetic (final velocities, barycentric frame, rest-mass gain), rounds the
results to double-double velocities and float64 lengths, and returns a frozen
:class:`Scene` whose samplers are pure float64 numpy.
"""

from __future__ import annotations

import functools
import math
from collections.abc import Mapping
from contextlib import AbstractContextManager
from dataclasses import dataclass, field
from decimal import Context, Decimal, localcontext
from enum import StrEnum
from types import MappingProxyType
from typing import Literal, TypeVar

import numpy as np
import numpy.typing as npt

from ._boost import Frame, FrameLike, as_frame
from ._budget import ExternalSource, FourMomentumBudget
from ._exact import (
    DECIMAL_DIGITS,
    REST,
    ExactVelocity,
    lorentz_factor_decimal,
    relative_rapidity,
    velocity_from_proper_velocity,
)
from ._motion import MotionPlan, RigidMotion, plan_motions
from ._validate import (
    ParameterError,
    check_fractions,
    check_positive,
    check_restitution,
    check_speed,
    check_times,
    check_velocity,
)

FloatArray = npt.NDArray[np.float64]

_ENDS = np.array([0.0, 1.0])
_MAX_CACHED_PLANS = 64


class SceneKind(StrEnum):
    """The scene families (CLI names)."""

    CONSTANT_ACCELERATION = "constant-acceleration"
    DECELERATION = "deceleration"
    VELOCITY_CHANGE = "velocity-change"
    IMPULSIVE_START = "impulsive-start"
    WALL_COLLISION = "wall-collision"
    ROD_COLLISION = "rod-collision"


@dataclass(frozen=True)
class Rod:
    """One rod of a scene: its motion and its rest mass before and after (heat adds mass)."""

    name: str
    motion: RigidMotion
    mass_before: float
    mass_after: float


@dataclass(frozen=True)
class EventSpec:
    """A named event: where end ``end`` (0 left, 1 right) of rod ``rod`` starts or stops changing velocity."""

    name: str
    rod: int
    end: Literal[0, 1]
    phase: Literal["start", "stop"]


@dataclass(frozen=True, eq=False)
class Scene:
    """A solved scene: rods with Born-rigid motions, named events, frame presets.

    All samplers take times of the chosen frame and return that frame's coordinates;
    ``frame_velocity`` is a float in (-1, 1) or a :class:`Frame` (e.g. from ``frames``).
    """

    kind: SceneKind
    parameters: Mapping[str, float]
    rods: tuple[Rod, ...]
    event_specs: tuple[EventSpec, ...]
    frames: Mapping[str, Frame]
    """Frame presets: the lab, each rod's rest frame before and after, the barycentric frame."""
    external_source: ExternalSource
    heat: float
    """Invariant rest energy created (epsilon < 1), see :class:`FourMomentumBudget`."""
    origin_event: str
    """What happens at the lab origin (0, 0): "start", "kick", "contact" or "rest"."""
    has_wall: bool = False
    _plans: dict[tuple[object, ...], MotionPlan] = field(default_factory=dict, repr=False)

    # ------------------------------------------------------------------ summary
    @property
    def n_rods(self) -> int:
        return len(self.rods)

    @property
    def final_velocities(self) -> tuple[float, ...]:
        """Lab velocity of each rod after the change (float64)."""
        return tuple(r.motion.velocity_final.value for r in self.rods)

    @property
    def initial_velocities(self) -> tuple[float, ...]:
        return tuple(r.motion.velocity_initial.value for r in self.rods)

    @functools.cached_property
    def events(self) -> Mapping[str, tuple[float, float]]:
        """Named events as lab ``(t, x)``, in the paper's notation."""
        return self.events_in(0.0)

    def events_in(self, frame_velocity: FrameLike = 0.0) -> Mapping[str, tuple[float, float]]:
        """The named events as ``(t', x')`` of the given frame (computed there, not boosted)."""
        frame = as_frame(frame_velocity)
        out: dict[str, tuple[float, float]] = {}
        for spec in self.event_specs:
            start, stop = self._plan(frame, _ENDS, spec.rod).switch_events()
            e = (start if spec.phase == "start" else stop)[spec.end]
            out[spec.name] = (float(e[0]), float(e[1]))
        return MappingProxyType(out)

    # ----------------------------------------------------------------- sampling
    def _plan(self, frame: Frame, fractions: FloatArray, rod: int | None = None) -> MotionPlan:
        key = (frame.key(), fractions.tobytes(), rod)
        plan = self._plans.get(key)
        if plan is None:
            rods = self.rods if rod is None else (self.rods[rod],)
            plan = plan_motions([r.motion for r in rods], frame, fractions)
            if len(self._plans) >= _MAX_CACHED_PLANS:
                self._plans.clear()
            self._plans[key] = plan
        return plan

    def positions(self, t: npt.ArrayLike, frame_velocity: FrameLike = 0.0) -> FloatArray:
        """x of [left end, right end] of each rod at times ``t`` of the frame.

        Shape ``(n_rods, 2, *t.shape)``. Closed form, see :mod:`rigidrel_core._motion`.
        """
        tt = check_times("t", t)
        x = self._plan(as_frame(frame_velocity), _ENDS).positions(tt.ravel())
        return x.reshape((self.n_rods, 2, *tt.shape))

    def material_positions(
        self, fractions: npt.ArrayLike, t: npt.ArrayLike, frame_velocity: FrameLike = 0.0
    ) -> FloatArray:
        """x of material points (fractions of the rest length from the left end, in [0, 1]).

        Shape ``(n_rods, len(fractions), *t.shape)``.
        """
        f = check_fractions("fractions", fractions)
        tt = check_times("t", t)
        frame = as_frame(frame_velocity)
        x = self._plan(frame, f).positions(tt.ravel())
        return x.reshape((self.n_rods, f.size, *tt.shape))

    def velocities(
        self, t: npt.ArrayLike, frame_velocity: FrameLike = 0.0, fractions: npt.ArrayLike = _ENDS
    ) -> FloatArray:
        """dx'/dt' of material points (default: the ends). Shape ``(n_rods, len(fractions), *t.shape)``."""
        f = check_fractions("fractions", fractions)
        tt = check_times("t", t)
        v = self._plan(as_frame(frame_velocity), f).velocities(tt.ravel())
        return v.reshape((self.n_rods, f.size, *tt.shape))

    def proper_times(
        self, t: npt.ArrayLike, frame_velocity: FrameLike = 0.0, fractions: npt.ArrayLike = _ENDS
    ) -> FloatArray:
        """Clock readings of material points at frame times ``t``.

        Every clock reads 0 where its point starts changing velocity: the clocks are
        synchronised in the rod's initial rest frame (the starts are simultaneous
        there). After the change they are not synchronised in the final rest frame: the
        point at distance ``rho`` from the centre ages ``rho |theta_f - theta_i|`` during it.
        """
        f = check_fractions("fractions", fractions)
        tt = check_times("t", t)
        tau = self._plan(as_frame(frame_velocity), f).proper_times(tt.ravel())
        return tau.reshape((self.n_rods, f.size, *tt.shape))

    def snapshot(self, t: float, frame_velocity: FrameLike, fractions: npt.ArrayLike) -> tuple[FloatArray, FloatArray]:
        """Positions of material points and the ends' clock readings at one frame time.

        The per-frame call of an animation: ``(x of shape (n_rods, len(fractions)),
        proper times of shape (n_rods, 2) at the ends)``; one plan, two evaluations.
        ``fractions`` must start at 0 and end at 1.
        """
        tt = check_times("t", np.array([t], dtype=np.float64))
        f = check_fractions("fractions", fractions)
        if f.size < 2 or f[0] != 0.0 or f[-1] != 1.0:
            raise ParameterError("fractions", "sorted fractions starting at 0 and ending at 1", fractions)
        plan = self._plan(as_frame(frame_velocity), f)
        x = plan.positions(tt).reshape(self.n_rods, f.size)
        tau = plan.proper_times(tt).reshape(self.n_rods, f.size)
        return x, tau[:, [0, -1]]

    def lengths(self, t: npt.ArrayLike, frame_velocity: FrameLike = 0.0) -> FloatArray:
        """Equal-time length ``x_right(t') - x_left(t')`` of each rod in the frame (Fig. 2).

        Shape ``(n_rods, *t.shape)``. Exactly ``L / cosh(theta')`` while both ends coast.
        """
        tt = check_times("t", t)
        rest = np.array([r.motion.length for r in self.rods])
        lengths = self._plan(as_frame(frame_velocity), _ENDS).equal_time_lengths(tt.ravel(), rest)
        return lengths.reshape((self.n_rods, *tt.shape))

    def switch_times(self, frame_velocity: FrameLike = 0.0, fractions: npt.ArrayLike = _ENDS) -> FloatArray:
        """Frame times at which each material point starts and stops changing velocity.

        Shape ``(n_rods, len(fractions), 2)``; between them the point is on its hyperbola,
        outside on straight lines (so a plot needs 2 samples there).
        """
        f = check_fractions("fractions", fractions)
        plan = self._plan(as_frame(frame_velocity), f)
        return np.stack([plan.t_start, plan.t_stop], axis=-1).reshape((self.n_rods, f.size, 2))

    def wall_x(self, t: npt.ArrayLike, frame_velocity: FrameLike = 0.0) -> FloatArray:
        """x' of the wall (lab x = 0) at frame times ``t``: ``x' = -beta t'``."""
        if not self.has_wall:
            raise ValueError(f"scene {self.kind.value!r} has no wall")
        tt = check_times("t", t)
        return -as_frame(frame_velocity).beta * tt

    def time_window(self, frame_velocity: FrameLike = 0.0, margin: float = 0.35) -> tuple[float, float]:
        """A frame-time interval that holds every named event and the origin, padded by ``margin``."""
        frame = as_frame(frame_velocity)
        times = [0.0]
        for i in range(self.n_rods):
            start, stop = self._plan(frame, _ENDS, i).switch_events()
            times.extend(start[:, 0].tolist())
            times.extend(stop[:, 0].tolist())
        t0, t1 = min(times), max(times)
        scale = max(t1 - t0, max(r.motion.length for r in self.rods) / frame.lorentz_factor)
        return (t0 - margin * scale, t1 + margin * scale)

    # ------------------------------------------------------------------- budget
    def budget(self, frame_velocity: FrameLike = 0.0) -> FourMomentumBudget:
        """Energy and momentum of every rod before and after, in the frame (c = 1)."""
        frame = as_frame(frame_velocity)
        m0 = np.array([r.mass_before for r in self.rods])
        m1 = np.array([r.mass_after for r in self.rods])
        th0 = np.array([relative_rapidity(r.motion.velocity_initial, frame.velocity) for r in self.rods])
        th1 = np.array([relative_rapidity(r.motion.velocity_final, frame.velocity) for r in self.rods])
        before = np.stack([m0 * np.cosh(th0), m0 * np.sinh(th0)], axis=-1)
        after = np.stack([m1 * np.cosh(th1), m1 * np.sinh(th1)], axis=-1)
        if self.external_source == "none":
            external = np.zeros(2)
        else:
            external = after.sum(axis=0) - before.sum(axis=0)
        return FourMomentumBudget(
            frame_velocity=frame.beta,
            bodies=tuple(r.name for r in self.rods),
            rest_mass_before=m0,
            rest_mass_after=m1,
            before=before,
            after=after,
            kinetic_before=2.0 * m0 * np.sinh(0.5 * th0) ** 2,
            kinetic_after=2.0 * m1 * np.sinh(0.5 * th1) ** 2,
            external=external,
            external_source=self.external_source,
            heat=self.heat,
        )


# ====================================================================== builders
def _ctx() -> AbstractContextManager[Context]:
    """A 60-digit decimal context for the scalar scene solution."""
    return localcontext(prec=DECIMAL_DIGITS)


def _rigid_motion(
    v_initial: ExactVelocity,
    v_final: ExactVelocity,
    length: float,
    rho_near: Decimal,
    vertex_left: float,
) -> RigidMotion:
    """Born-rigid change ``v_initial -> v_final``; at lab t = 0 the (extended) family is at rest on
    ``[vertex_left, vertex_left + length]``; the end nearest the centre is ``rho_near`` from it."""
    sign: Literal[1, -1] = 1 if (v_final.hi, v_final.lo) > (v_initial.hi, v_initial.lo) else -1
    if rho_near == 0:  # an impulse: single float operations, each correctly rounded, suffice
        horizon, r_left, r_right = _horizon_and_radii(sign, vertex_left, 0.0, length)
    else:
        with _ctx():
            horizon, r_left, r_right = _horizon_and_radii(
                sign, Decimal(vertex_left), rho_near, rho_near + Decimal(length)
            )
    return RigidMotion(
        length=length,
        sign=sign,
        horizon_x=float(horizon),
        radius_left=float(r_left),
        radius_right=float(r_right),
        vertex_left=vertex_left,
        velocity_initial=v_initial,
        velocity_final=v_final,
    )


_Num = TypeVar("_Num", float, Decimal)


def _horizon_and_radii(sign: Literal[1, -1], vertex_left: _Num, near: _Num, far: _Num) -> tuple[_Num, _Num, _Num]:
    """Centre x and the left and right ends' radii of a family at rest on ``[vertex_left, vertex_left
    + length]``, its ends ``near`` and ``far = near + length`` from the centre: the centre lies behind
    the rod (on the left when it speeds up to the right, ``sign = 1``)."""
    if sign == 1:
        return vertex_left - near, near, far
    return vertex_left + far, far, near


def _check_acceleration(a_front: float, length: float) -> Decimal:
    """``a_front * length`` in (0, 1), evaluated exactly; returns ``rho_near = (1 - a L)/a``.

    Paper Eq. (gl): ``a'_B = a'_F / (1 - a'_F L0)``, so the near (back) end sits at
    ``1/a'_B = (1 - a'_F L0)/a'_F`` from the centre.
    """
    with _ctx():
        aL = Decimal(a_front) * Decimal(length)
        if not (0 < aL < 1):
            raise ParameterError("a_front * length", "a finite number in (0, 1)", float(aL))
        return (1 - aL) / Decimal(a_front)


#: Largest |coordinate| of a lab event or Rindler radius a scene may have; squares of
#: anything a frame makes of it (times gamma <= 7e7) stay far inside float64.
MAX_SCENE_COORDINATE = 1e120


def _finite(scene: Scene) -> Scene:
    """Reject parameter combinations whose derived numbers leave the representable range."""
    allowed = f"such that every lab event and Rindler radius lies within {MAX_SCENE_COORDINATE:g} of the origin"
    for r in scene.rods:
        m = r.motion
        nums = [m.horizon_x, m.radius_left, m.radius_right, r.mass_after]
        for v in (m.velocity_initial, m.velocity_final):
            if not v.gap > 0.0:
                below_light = "such that every velocity stays below light speed"
                raise ParameterError("parameters", below_light, dict(scene.parameters))
            nums.append(max(m.radius_left, m.radius_right) * v.proper_velocity())
        if not all(math.isfinite(x) and abs(x) <= MAX_SCENE_COORDINATE for x in nums):
            raise ParameterError("parameters", allowed, dict(scene.parameters))
    return scene


def _single_rod_frames(motion: RigidMotion) -> Mapping[str, Frame]:
    return MappingProxyType(
        {
            "lab": Frame.lab(),
            "rod before": Frame(motion.velocity_initial, "rod before"),
            "rod after": Frame(motion.velocity_final, "rod after"),
        }
    )


def _velocity_change_scene(
    kind: SceneKind,
    parameters: dict[str, float],
    v_initial: ExactVelocity,
    v_final: ExactVelocity,
    length: float,
    rho_near: Decimal,
    mass: float,
    event_names: Mapping[tuple[Literal["near", "far"], Literal["start", "stop"]], str],
    origin_event: str,
) -> Scene:
    motion = _rigid_motion(v_initial, v_final, length, rho_near, 0.0)
    near_end: Literal[0, 1] = 0 if motion.sign == 1 else 1
    far_end: Literal[0, 1] = 1 if motion.sign == 1 else 0
    specs = tuple(
        EventSpec(name, 0, near_end if which == "near" else far_end, phase)
        for (which, phase), name in event_names.items()
    )
    return _finite(
        Scene(
            kind=kind,
            parameters=MappingProxyType(parameters),
            rods=(Rod("rod", motion, mass, mass),),
            event_specs=specs,
            frames=_single_rod_frames(motion),
            external_source="drive",
            heat=0.0,
            origin_event=origin_event,
        )
    )


def constant_acceleration(v: float, length: float, a_front: float, mass: float = 1.0) -> Scene:
    """Born-rigid constant acceleration from rest to ``v`` (paper Sec. 3, Fig. 1 solid curve).

    The rod rests on ``[0, length]`` for ``t <= 0``. Its front (right) end has proper
    acceleration ``a'_F = a_front``, its back end ``a'_B = a'_F/(1 - a'_F L0)`` (Eq. (gl));
    each point coasts once it reaches ``v``: the back end at lab ``T_B = gamma v / a'_B``,
    the front at ``T_F = gamma v / a'_F`` (Eq. (tlt)), at equal rest-frame time.
    Events: ``"T_B"``, ``"T_F"``. Requires ``0 < v < 1``, ``0 < a_front * length < 1``.
    """
    v = check_speed("v", v)
    length = check_positive("length", length)
    a_front = check_positive("a_front", a_front)
    mass = check_positive("mass", mass)
    rho_near = _check_acceleration(a_front, length)
    return _velocity_change_scene(
        SceneKind.CONSTANT_ACCELERATION,
        {"v": v, "length": length, "a_front": a_front, "mass": mass},
        REST,
        ExactVelocity.from_float(v),
        length,
        rho_near,
        mass,
        {("near", "stop"): "T_B", ("far", "stop"): "T_F"},
        "start",
    )


def deceleration(v: float, length: float, a_front: float, mass: float = 1.0) -> Scene:
    """Born-rigid deceleration from velocity ``-v`` to rest (paper Sec. 3, last paragraph).

    The time reverse of :func:`constant_acceleration`: the rod comes in from the right
    with velocity ``-v`` and is at rest on ``[0, length]`` from ``t = 0`` on. The right end
    (the paper's F of Fig. 1, trailing in the motion) has proper deceleration
    ``a_front``; it starts braking first, at ``-T_F``, the left end at ``-T_B``.
    Events: ``"-T_F"``, ``"-T_B"`` (the paper relabels these ends B and F after
    reversing time; we keep Fig. 1's labels). Requires ``0 < v < 1``, ``0 < a_front * length < 1``.
    """
    v = check_speed("v", v)
    length = check_positive("length", length)
    a_front = check_positive("a_front", a_front)
    mass = check_positive("mass", mass)
    rho_near = _check_acceleration(a_front, length)
    return _velocity_change_scene(
        SceneKind.DECELERATION,
        {"v": v, "length": length, "a_front": a_front, "mass": mass},
        ExactVelocity.from_float(-v),
        REST,
        length,
        rho_near,
        mass,
        {("far", "start"): "-T_F", ("near", "start"): "-T_B"},
        "rest",
    )


def velocity_change(
    v_initial: float,
    v_final: float,
    length: float,
    a_front: float | None = None,
    mass: float = 1.0,
) -> Scene:
    """Any Born-rigid change of velocity ``v_initial -> v_final`` at constant proper accelerations.

    ``a_front`` is the proper acceleration of the end that leads in the direction of the
    push (the end farther from the Rindler horizon, the paper's ``a'_F``); the other end
    has ``a_front / (1 - a_front * length)``. ``a_front=None`` is the impulsive limit
    (Sec. 4): the near end jumps. At lab ``t = 0`` the rod's extended family of
    hyperbolas has it at rest on ``[0, length]``, so ``velocity_change(0, v, ...)`` is
    :func:`constant_acceleration` and ``velocity_change(-v, 0, ...)`` is
    :func:`deceleration`. Events: ``"T_B0"``, ``"T_F0"`` (back/front end starts),
    ``"T_B"``, ``"T_F"`` (stops), with B the end nearer the horizon.
    """
    vi = check_velocity("v_initial", v_initial)
    vf = check_velocity("v_final", v_final)
    if vi == vf:
        raise ParameterError("v_final", "different from v_initial", v_final)
    length = check_positive("length", length)
    mass = check_positive("mass", mass)
    if a_front is None:
        rho_near = Decimal(0)
    else:
        rho_near = _check_acceleration(check_positive("a_front", a_front), length)
    params = {"v_initial": vi, "v_final": vf, "length": length, "mass": mass}
    if a_front is not None:
        params["a_front"] = float(a_front)
    return _velocity_change_scene(
        SceneKind.VELOCITY_CHANGE,
        params,
        ExactVelocity.from_float(vi),
        ExactVelocity.from_float(vf),
        length,
        rho_near,
        mass,
        {
            ("near", "start"): "T_B0",
            ("far", "start"): "T_F0",
            ("near", "stop"): "T_B",
            ("far", "stop"): "T_F",
        },
        "start" if vi == 0.0 else ("rest" if vf == 0.0 else "vertex"),
    )


def impulsive_start(v: float, length: float, mass: float = 1.0) -> Scene:
    """Impulsive acceleration (paper Sec. 4, Fig. 1 dashed curve).

    The rod rests on ``[0, length]`` for ``t < 0``; at ``t = 0`` its left end jumps to
    ``v``. The right end follows ``x = sqrt(L0^2 + t^2)`` (Eq. (imp)) until
    ``T_F = v gamma L0`` (Eq. (tf)). Event: ``"T_F"``.
    """
    v = check_speed("v", v)
    length = check_positive("length", length)
    mass = check_positive("mass", mass)
    return _velocity_change_scene(
        SceneKind.IMPULSIVE_START,
        {"v": v, "length": length, "mass": mass},
        REST,
        ExactVelocity.from_float(v),
        length,
        Decimal(0),
        mass,
        {("far", "stop"): "T_F"},
        "kick",
    )


def wall_collision(v: float, length: float, eps: float, mass: float = 1.0) -> Scene:
    """A rod hits a wall at x = 0 (paper Sec. 5).

    The rod lies in ``x > 0`` moving with velocity ``-v``; its left end meets the wall at
    ``t = 0`` and leaves with proper velocity ``eps * gamma v`` (epsilon scales the proper
    velocity in the wall's frame, the barycentric frame of an infinitely heavy wall;
    ``eps = 0`` is the crash, ``eps = 1`` the elastic bounce). The far (right) end
    follows ``x = sqrt(L0^2 + t^2)`` from ``T_1 = -gamma v L0`` to
    ``T_1' = gamma' v' L0``. Events: ``"T_1"``, ``"T_1'"``. The wall absorbs the heat
    ``M (gamma - gamma')``.
    """
    v = check_speed("v", v)
    length = check_positive("length", length)
    eps = check_restitution("eps", eps)
    mass = check_positive("mass", mass)
    with _ctx():
        dv = Decimal(v)
        gamma = lorentz_factor_decimal(dv)
        u_after = Decimal(eps) * gamma * dv
        v_after = velocity_from_proper_velocity(u_after)
        heat = Decimal(mass) * (gamma - (1 + u_after * u_after).sqrt())
    motion = _rigid_motion(ExactVelocity.from_float(-v), v_after, length, Decimal(0), 0.0)
    specs = (EventSpec("T_1", 0, 1, "start"), EventSpec("T_1'", 0, 1, "stop"))
    return _finite(
        Scene(
            kind=SceneKind.WALL_COLLISION,
            parameters=MappingProxyType({"v": v, "length": length, "eps": eps, "mass": mass}),
            rods=(Rod("rod", motion, mass, mass),),
            event_specs=specs,
            frames=_single_rod_frames(motion),
            external_source="wall",
            heat=float(heat),
            origin_event="contact",
            has_wall=True,
        )
    )


@dataclass(frozen=True)
class CollisionSolution:
    """The barycentric solution of a rod-rod collision (paper Sec. 6), to 60 digits.

    ``u``: barycentric velocity (Eq. for u); ``bar_before``/``bar_after``: each rod's
    velocity in the barycentric frame before and after (``gamma' V' = -eps gamma V``,
    Eq. (epsilon)); ``after``: lab velocities (Eq. (vp)); ``mass_factor``: the common
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
    with _ctx():
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
        if de == 1:  # elastic: bar g' = bar g, so denom = M exactly
            factor, heat = Decimal(1), Decimal(0)
        else:
            factor = mass / denom
            heat = (mass - denom) / denom * (dm1 + dm2)
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
    """Collision of two rigid rods along x (paper Secs. 5-6, Figs. 3-4).

    Rod 1 (mass ``m1``, rest length ``l1``, velocity ``v1``) is on the left, rod 2 on the
    right; ``v1 > v2``. Rod 1's right end meets rod 2's left end at ``x = 0, t = 0`` and
    both contact ends change velocity at once (to the barycentric solution of
    :func:`solve_collision`). The far ends follow ``x = -sqrt(L1^2 + t^2)`` from
    ``T_1 = -gamma_1 V_1 L_1`` to ``T_1' = -gamma_1' V_1' L_1`` and ``x = sqrt(L2^2 + t^2)``
    from ``T_2 = gamma_2 V_2 L_2`` to ``T_2' = gamma_2' V_2' L_2`` (Eqs. (t12)-(t'12)).
    Events: ``"T_1"``, ``"T_1'"``, ``"T_2"``, ``"T_2'"``.
    """
    v1 = check_velocity("v1", v1)
    v2 = check_velocity("v2", v2)
    if not v2 < v1:
        raise ParameterError("v2", f"less than v1 = {v1!r} so that the rods collide", v2)
    m1 = check_positive("m1", m1)
    m2 = check_positive("m2", m2)
    l1 = check_positive("l1", l1)
    l2 = check_positive("l2", l2)
    eps = check_restitution("eps", eps)
    sol = solve_collision(v1, v2, m1, m2, eps)
    k = sol.mass_factor
    with _ctx():
        m1_after, m2_after = float(Decimal(m1) * k), float(Decimal(m2) * k)
    rod1 = _rigid_motion(ExactVelocity.from_float(v1), sol.after[0], l1, Decimal(0), -l1)
    rod2 = _rigid_motion(ExactVelocity.from_float(v2), sol.after[1], l2, Decimal(0), 0.0)
    frames = MappingProxyType(
        {
            "lab": Frame.lab(),
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
    return _finite(
        Scene(
            kind=SceneKind.ROD_COLLISION,
            parameters=MappingProxyType({"v1": v1, "v2": v2, "m1": m1, "m2": m2, "l1": l1, "l2": l2, "eps": eps}),
            rods=(Rod("rod 1", rod1, m1, m1_after), Rod("rod 2", rod2, m2, m2_after)),
            event_specs=specs,
            frames=frames,
            external_source="none",
            heat=float(sol.heat),
            origin_event="contact",
        )
    )
