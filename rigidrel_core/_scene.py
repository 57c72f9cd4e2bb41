"""A solved scene: rods with Born-rigid motions, objects that are not rods, named events and frame presets.

Every sampler takes times of a frame and returns that frame's coordinates, with the
signature ``(t, *, frame=LAB, fractions=...)`` (units c = 1); every query that takes a frame
takes it by name. Nothing here knows which scene it is: the constructors in
:mod:`rigidrel_core.scenes` fill it in.
"""

from __future__ import annotations

import functools
import math
import numbers
from collections.abc import Mapping
from dataclasses import dataclass, field
from types import MappingProxyType
from typing import Literal

import numpy as np
import numpy.typing as npt

from ._budget import ExternalSource, FourMomentumBudget, PhysicalSystem, SystemBudget, heat_where
from ._exact import relative_rapidity
from ._frame import LAB, Frame, check_frame
from ._kinds import OriginEvent
from ._motion import PIECEWISE_MIN, MotionPlan
from ._objects import SceneObject
from ._plastic import Motion, plan_rods
from ._signals import ChangeVerdict, Exact, as_event, change_verdict, signal_arrival_on
from ._validate import ParameterError, as_real, check_fractions, check_times, check_times_ordered

FloatArray = npt.NDArray[np.float64]

#: The two ends of a rod as material coordinates (fractions of the rest length from the left end).
#: Read-only, and for good (a view of immutable bytes: its ``writeable`` flag cannot be set again):
#: it is the samplers' default argument and part of the plan cache's key.
ENDS: FloatArray = np.frombuffer(np.array([0.0, 1.0]).tobytes(), dtype=np.float64)
_ENDS_BYTES = ENDS.tobytes()
_MAX_CACHED_PLANS = 64
#: Plans by (frame velocity, fractions' bytes, rod or None for all).
PlanCache = dict[tuple[object, ...], MotionPlan]


@dataclass(frozen=True, init=False)
class Rod:
    """One rod of a scene: its motion and its rest mass before and after (heat adds mass)."""

    name: str
    motion: Motion
    """Born-rigid (:class:`RigidMotion`) or stopped point by point (:class:`PlasticMotion`)."""
    mass_before: float
    mass_after: float

    def __init__(self, name: str, motion: Motion, mass_before: float, mass_after: float) -> None:
        # into the instance's dict at once (the generated __init__ calls object.__setattr__ per field)
        self.__dict__.update(name=name, motion=motion, mass_before=mass_before, mass_after=mass_after)


@dataclass(frozen=True)
class EventSpec:
    """A named event: where end ``end`` (0 left, 1 right) of rod ``rod`` starts or stops changing velocity."""

    name: str
    rod: int
    end: Literal[0, 1]
    phase: Literal["start", "stop"]


@dataclass(frozen=True, eq=False, init=False)
class Scene:
    """A solved scene (see :func:`rigidrel_core.build_scene` and the constructors).

    All samplers take times of a :class:`Frame` (default: the lab) and return that frame's
    coordinates; material points are fractions of the rest length from each rod's left end.
    """

    kind: str
    """The scene's registry name, e.g. ``"rod-collision"`` (see :func:`rigidrel_core.describe`)."""
    parameters: Mapping[str, float]
    """The constructor's arguments, validated (an omitted optional one is left out)."""
    rods: tuple[Rod, ...]
    event_specs: tuple[EventSpec, ...]
    frames: Mapping[str, Frame]
    """Frame presets by name: the lab, each rod's rest frame before and after, the barycentric frame."""
    external_source: ExternalSource
    heat: float
    """Invariant rest energy created (epsilon < 1), see :class:`FourMomentumBudget`: in the scene's one
    physical system; a scene of alternatives gives each system its own (:attr:`systems`), and this is
    the first's."""
    origin_event: OriginEvent
    objects: tuple[SceneObject, ...] = ()
    """What the scene holds that is not a rod (a wall, a barn's door, Bell's string), each with its
    drawing description: front ends draw them from it alone."""
    kick: str = ""
    """The named event where an end is kicked (jumps to its final velocity at once) when that is not
    the origin event: an impulsive velocity change pushed toward -x kicks its right end, at lab
    ``(0, L0)``. The causal verdicts and the light signals then leave from it; ``""``: none."""
    _plans: PlanCache = field(default_factory=PlanCache, init=False, repr=False)

    def __init__(
        self,
        kind: str,
        parameters: Mapping[str, float],
        rods: tuple[Rod, ...],
        event_specs: tuple[EventSpec, ...],
        frames: Mapping[str, Frame],
        external_source: ExternalSource,
        heat: float,
        origin_event: OriginEvent,
        objects: tuple[SceneObject, ...] = (),
        kick: str = "",
    ) -> None:
        # the instance's dict filled at once: the generated __init__ of a frozen dataclass calls
        # object.__setattr__ once per field, and every slider change builds a scene
        self.__dict__.update(
            kind=kind,
            parameters=parameters,
            rods=rods,
            event_specs=event_specs,
            frames=frames,
            external_source=external_source,
            heat=heat,
            origin_event=origin_event,
            objects=objects,
            kick=kick,
            _plans={},
        )

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

    def frame(self, name: str) -> Frame:
        """The frame preset called ``name``; ``ValueError`` listing the valid names otherwise."""
        try:
            return self.frames[name]
        except (KeyError, TypeError):
            raise ParameterError("frame", f"one of {', '.join(repr(k) for k in self.frames)}", name) from None

    @functools.cached_property
    def events(self) -> Mapping[str, tuple[float, float]]:
        """Named events as lab ``(t, x)``, in the paper's notation."""
        return self.events_in(frame=LAB)

    def events_in(self, *, frame: Frame = LAB) -> Mapping[str, tuple[float, float]]:
        """The named events as ``(t', x')`` of ``frame`` (computed there, not boosted)."""
        frame = check_frame(frame)
        out: dict[str, tuple[float, float]] = {}
        for spec in self.event_specs:
            start, stop = self._plan(frame, ENDS, spec.rod).switch_events()
            e = (start if spec.phase == "start" else stop)[spec.end]
            out[spec.name] = (float(e[0]), float(e[1]))
        return MappingProxyType(out)

    def event_rod(self, name: str) -> int:
        """Which rod the named event belongs to."""
        for spec in self.event_specs:
            if spec.name == name:
                return spec.rod
        raise ParameterError("event", f"one of {', '.join(s.name for s in self.event_specs)}", name)

    # ----------------------------------------------------------------- sampling
    def _plan(self, frame: Frame, fractions: FloatArray, rod: int | None = None) -> MotionPlan:
        key = (frame.key(), _ENDS_BYTES if fractions is ENDS else fractions.tobytes(), rod)
        plan = self._plans.get(key)
        if plan is None:
            rods = self.rods if rod is None else (self.rods[rod],)
            plan = plan_rods([r.motion for r in rods], frame, fractions)
            if len(self._plans) >= _MAX_CACHED_PLANS:
                self._plans.clear()
            self._plans[key] = plan
        return plan

    def positions(self, t: npt.ArrayLike, *, frame: Frame = LAB) -> FloatArray:
        """x' of [left end, right end] of each rod at times ``t'`` of ``frame``.

        Shape ``(n_rods, 2, *t.shape)``. Closed form, see :mod:`rigidrel_core._motion`.
        """
        frame = check_frame(frame)
        tt, ordered = check_times_ordered("t", t, PIECEWISE_MIN)
        x = self._plan(frame, ENDS).positions(tt.ravel(), ordered=ordered)
        return x.reshape((self.n_rods, 2, *tt.shape))

    def material_positions(self, t: npt.ArrayLike, *, frame: Frame = LAB, fractions: npt.ArrayLike) -> FloatArray:
        """x' of material points (fractions of the rest length from the left end, in [0, 1]).

        Shape ``(n_rods, len(fractions), *t.shape)``.
        """
        frame = check_frame(frame)
        tt, ordered = check_times_ordered("t", t, PIECEWISE_MIN)
        f = check_fractions("fractions", fractions)
        x = self._plan(frame, f).positions(tt.ravel(), ordered=ordered)
        return x.reshape((self.n_rods, f.size, *tt.shape))

    def velocities(self, t: npt.ArrayLike, *, frame: Frame = LAB, fractions: npt.ArrayLike = ENDS) -> FloatArray:
        """dx'/dt' of material points (default: the ends). Shape ``(n_rods, len(fractions), *t.shape)``."""
        frame = check_frame(frame)
        tt = check_times("t", t)
        f = check_fractions("fractions", fractions)
        v = self._plan(frame, f).velocities(tt.ravel())
        return v.reshape((self.n_rods, f.size, *tt.shape))

    def proper_times(self, t: npt.ArrayLike, *, frame: Frame = LAB, fractions: npt.ArrayLike = ENDS) -> FloatArray:
        """Clock readings of material points at frame times ``t'``.

        Every clock reads 0 where its point starts changing velocity: the clocks are
        synchronised in the rod's initial rest frame (the starts are simultaneous there).
        After the change they are not synchronised in the final rest frame: the point at
        distance ``rho`` from the centre ages ``rho |theta_f - theta_i|`` during it.
        """
        frame = check_frame(frame)
        tt = check_times("t", t)
        f = check_fractions("fractions", fractions)
        tau = self._plan(frame, f).proper_times(tt.ravel())
        return tau.reshape((self.n_rods, f.size, *tt.shape))

    def snapshot(self, t: float, *, frame: Frame = LAB, fractions: npt.ArrayLike) -> tuple[FloatArray, FloatArray]:
        """Positions of material points and the ends' clock readings at one frame time.

        The per-frame call of an animation: ``(x' of shape (n_rods, len(fractions)),
        proper times of shape (n_rods, 2) at the ends)``; one plan, two evaluations.
        ``fractions`` must start at 0 and end at 1.
        """
        frame = check_frame(frame)
        tt = check_times("t", t)
        if tt.shape != ():
            raise ParameterError("t", "one time (a real number)", t)
        tt = tt.reshape(1)
        f = check_fractions("fractions", fractions)
        if f.size < 2 or f[0] != 0.0 or f[-1] != 1.0:
            raise ParameterError("fractions", "sorted fractions starting at 0 and ending at 1", fractions)
        plan = self._plan(frame, f)
        x = plan.positions(tt).reshape(self.n_rods, f.size)
        tau = plan.proper_times(tt).reshape(self.n_rods, f.size)
        return x, tau[:, [0, -1]]

    def lengths(self, t: npt.ArrayLike, *, frame: Frame = LAB) -> FloatArray:
        """Equal-time length ``x'_right(t') - x'_left(t')`` of each rod in ``frame`` (Fig. 2).

        Shape ``(n_rods, *t.shape)``. Exactly ``L / cosh(theta')`` while both ends coast.
        """
        frame = check_frame(frame)
        tt = check_times("t", t)
        rest = np.array([r.motion.length for r in self.rods])
        rest_after = np.array([r.motion.length_final for r in self.rods])
        lengths = self._plan(frame, ENDS).equal_time_lengths(tt.ravel(), rest, rest_after)
        return lengths.reshape((self.n_rods, *tt.shape))

    def switch_times(self, *, frame: Frame = LAB, fractions: npt.ArrayLike = ENDS) -> FloatArray:
        """Frame times at which each material point starts and stops changing velocity.

        Shape ``(n_rods, len(fractions), 2)``; between them the point is on its hyperbola,
        outside on straight lines (so a plot needs 2 samples there).
        """
        frame = check_frame(frame)
        f = check_fractions("fractions", fractions)
        plan = self._plan(frame, f)
        return np.stack([plan.t_start, plan.t_stop], axis=-1).reshape((self.n_rods, f.size, 2))

    def time_window(self, *, frame: Frame = LAB, margin: float = 0.35) -> tuple[float, float]:
        """A frame-time interval that holds every named event and the origin, padded by ``margin``."""
        frame = check_frame(frame)
        times = [0.0]
        for i in range(self.n_rods):
            start, stop = self._plan(frame, ENDS, i).switch_events()
            times.extend(start[:, 0].tolist())
            times.extend(stop[:, 0].tolist())
        t0, t1 = min(times), max(times)
        scale = max(t1 - t0, max(r.motion.length for r in self.rods) / frame.lorentz_factor)
        return (t0 - margin * scale, t1 + margin * scale)

    def notes(self, *, frame: Frame = LAB) -> tuple[str, ...]:
        """What a scene says in words beside its events, seen from ``frame`` (a paradox's verdicts);
        none for most scenes."""
        del frame
        return ()

    @property
    def rod_groups(self) -> tuple[int, ...]:
        """Which rods share one world, per rod (``0, 1, ...``): rods of different groups never meet,
        because they are alternatives (two models of one body) or a comparison (a body beside others
        it does not touch, occupying the same place); a picture draws each group apart. All ``0``
        unless a scene says otherwise."""
        return (0,) * len(self.rods)

    @property
    def systems(self) -> tuple[PhysicalSystem, ...]:
        """The physical systems of the scene: rods that exist together, with what acts on them (one per
        rod group, :attr:`rod_groups`). One system of all the rods, with the scene's drive or wall and
        :attr:`heat`, unless a scene of alternatives says otherwise."""
        if any(self.rod_groups):
            raise NotImplementedError(f"{type(self).__name__} has several rod groups: it must name its systems")
        names = [r.name for r in self.rods]
        name = f"the {names[0]}" if len(names) == 1 else ", ".join(names[:-1]) + " and " + names[-1]
        return (PhysicalSystem(name, tuple(range(self.n_rods)), self.external_source, self.heat),)

    # ------------------------------------------------------------------- budget
    def budget(self, *, frame: Frame = LAB) -> FourMomentumBudget:
        """Energy and momentum of every rod before and after, in ``frame`` (c = 1), and the totals of
        each physical system (:attr:`systems`), never of rods that do not exist together."""
        frame = check_frame(frame)
        m0 = np.array([r.mass_before for r in self.rods])
        m1 = np.array([r.mass_after for r in self.rods])
        th0 = np.array([relative_rapidity(r.motion.velocity_initial, frame.velocity) for r in self.rods])
        th1 = np.array([relative_rapidity(r.motion.velocity_final, frame.velocity) for r in self.rods])
        before = np.stack([m0 * np.cosh(th0), m0 * np.sinh(th0)], axis=-1)
        after = np.stack([m1 * np.cosh(th1), m1 * np.sinh(th1)], axis=-1)
        systems: list[SystemBudget] = []
        for system in self.systems:
            rods = list(system.rods)
            total_before, total_after = before[rods].sum(axis=0), after[rods].sum(axis=0)
            external = np.zeros(2) if system.external_source == "none" else total_after - total_before
            names = tuple(r.name for r in self.rods)
            where = heat_where(system, names, m0, m1, tuple(not r.motion.born_rigid for r in self.rods))
            systems.append(SystemBudget(system, total_before, total_after, external, where))
        return FourMomentumBudget(
            frame_velocity=frame.beta,
            bodies=tuple(r.name for r in self.rods),
            rest_mass_before=m0,
            rest_mass_after=m1,
            before=before,
            after=after,
            kinetic_before=2.0 * m0 * np.sinh(0.5 * th0) ** 2,
            kinetic_after=2.0 * m1 * np.sinh(0.5 * th1) ** 2,
            systems=tuple(systems),
        )

    # ------------------------------------------------------------------ signals
    def _rod_index(self, rod: object) -> int:
        """``rod`` as an index of :attr:`rods`: an integer (a Python or numpy one, not a bool) in range."""
        if isinstance(rod, bool) or not isinstance(rod, numbers.Integral) or not 0 <= int(rod) < self.n_rods:
            raise ParameterError("rod", f"a rod index from 0 to {self.n_rods - 1}", rod)
        return int(rod)

    def _fraction(self, fraction: object) -> float:
        f = as_real("fraction", fraction, "a number in [0, 1]")
        if not 0.0 <= f <= 1.0:
            raise ParameterError("fraction", "a number in [0, 1]", fraction)
        return f

    def source_event(self, source: str | npt.ArrayLike, *, frame: Frame = LAB) -> tuple[float, float]:
        """An event as frame ``(t', x')``: a named event (``"T_1"``), the scene's origin event by its
        name (``"contact"``, ``"kick"``, ... which is ``(0, 0)`` in every frame), or a ``(t', x')`` pair."""
        frame = check_frame(frame)
        if isinstance(source, str):
            if source == self.origin_event.value:
                return (0.0, 0.0)
            events = self.events_in(frame=frame)
            if source not in events:
                names = ", ".join(repr(n) for n in (self.origin_event.value, *events))
                raise ParameterError("source", f"one of {names} or a (t, x) pair", source)
            return events[source]
        return as_event("source", source)

    def signal_arrival(
        self,
        source: str | npt.ArrayLike,
        rod: int,
        fraction: float,
        *,
        direction: Literal[1, -1] | None = None,
        frame: Frame = LAB,
    ) -> tuple[float, float] | None:
        """Where a light signal from ``source`` first reaches material point ``fraction`` of ``rod``.

        Returns the arrival as ``(t', x')`` of ``frame``, or ``None`` when the signal never reaches
        the point (a ray sent away from it). ``source`` is an event name, the origin event's name or
        a ``(t', x')`` pair of ``frame``; ``direction`` is +1 (toward +x), -1, or ``None`` (toward the
        point). Closed form on each piece of the worldline, in light-cone coordinates
        (:mod:`rigidrel_core._signals`): the arrival lies exactly on the source's light cone.

        Example: an elastic wall bounce at V = 0.6, L0 = 1. The signal leaving the contact (0, 0)
        reaches the far end at lab (2, 2), after that end's change ends at T'_1 = (0.75, 1.25).
        """
        frame = check_frame(frame)
        i = self._rod_index(rod)
        f = self._fraction(fraction)
        if direction is not None and direction not in (1, -1):
            raise ParameterError("direction", "+1, -1 or None (toward the point)", direction)
        return signal_arrival_on(self.rods[i].motion, f, frame, self._light_cone(source, frame=frame), direction)

    def _light_cone(self, source: str | npt.ArrayLike, *, frame: Frame) -> tuple[Exact, Exact]:
        """The lab ``(t - x, t + x)`` of a source to double-double: exact for the scene's own events
        (the motion's lab rows), from the given frame pair (boosted back) otherwise."""
        if isinstance(source, str) and source != self.origin_event.value:
            self.source_event(source, frame=frame)  # names the valid sources if this one is not
            spec = next(s for s in self.event_specs if s.name == source)
            row = self.rods[spec.rod].motion.lab_rows(ENDS, exact=True)[spec.end]
            if spec.phase == "start":
                return (-row.minus_u_start, -row.low[1]), (row.w_start, row.low[2])
            return (-row.minus_u_stop, -row.low[4]), (row.w_stop, row.low[5])
        t, x = self.source_event(source, frame=frame)
        up, down = frame.doppler_factors()
        return ((t - x) / up, 0.0), ((t + x) / down, 0.0)

    def comoving_frame(
        self,
        rod: int,
        fraction: float,
        *,
        proper_time: float | None = None,
        t: float | None = None,
        frame: Frame = LAB,
    ) -> Frame:
        """The momentarily comoving inertial frame of material point ``fraction`` of ``rod``, at its
        clock reading ``proper_time`` or at time ``t`` of ``frame`` (give one).

        Before the change it is the rod's frame before, exactly; from the end of the change on, the
        frame after; in between the rapidity grows linearly with the point's proper time,
        ``theta = theta_i + sign tau / rho`` (constant proper acceleration ``1/rho``, Sec. 3, Eq. (15)).
        The samplers take it like any frame; in it the rod has its rest length at that instant.
        """
        frame = check_frame(frame)
        i = self._rod_index(rod)
        f = self._fraction(fraction)
        if (proper_time is None) == (t is None):
            raise ParameterError("proper_time", "given alone, or t given instead", (proper_time, t))
        if t is not None:
            tt = check_times("t", t)
            if tt.shape != ():
                raise ParameterError("t", "one time (a real number)", t)
            tau = float(self.proper_times(tt.reshape(1), frame=frame, fractions=np.array([f]))[i, 0, 0])
        else:
            tau = as_real("proper_time", proper_time, "a finite number")
        motion = self.rods[i].motion
        name = f"comoving with {self.rods[i].name} at f = {f:g}"
        rho = motion.radius(f)
        if tau >= rho * motion.rapidity_change:
            return Frame(motion.velocity_final, name)
        if tau <= 0.0:
            return Frame(motion.velocity_initial, name)
        return Frame.from_rapidity(motion.velocity_initial.rapidity() + motion.sign * tau / rho, name)

    def point_event(self, rod: int, fraction: float, *, proper_time: float, frame: Frame = LAB) -> tuple[float, float]:
        """The event ``(t', x')`` of ``frame`` where material point ``fraction`` of ``rod`` reads
        ``proper_time`` (its clock reads 0 where its change starts; negative before).

        Anchored at the point's own switch event ``E_s`` (start) or ``E_e`` (stop), never at a far
        centre: on the straight pieces ``E = E_s + tau (cosh theta, sinh theta)`` (or from ``E_e``), and
        on the hyperbola (constant proper acceleration ``1/rho``, Sec. 3, Eqs. (5)-(6)), with
        ``theta = theta_s + sign tau / rho`` and ``m = (theta + theta_s) / 2``,

        .. math::
            t - t_s = 2 \\rho \\cosh m \\, \\sinh\\frac{\\tau}{2\\rho}, \\qquad
            x - x_s = 2 \\rho \\sinh m \\, \\sinh\\frac{\\tau}{2\\rho}

        (differences of hyperbolic functions as products: no cancellation); rapidities in ``frame``.
        """
        frame = check_frame(frame)
        i = self._rod_index(rod)
        f = self._fraction(fraction)
        tau = as_real("proper_time", proper_time, "a finite number")
        motion = self.rods[i].motion
        start, stop = self._plan(frame, np.array([f]), i).switch_events()
        rho = motion.radius(f)
        change = rho * motion.rapidity_change
        theta_s = relative_rapidity(motion.velocity_initial, frame.velocity)
        if tau <= 0.0:
            t0, x0 = float(start[0, 0]), float(start[0, 1])
            return t0 + tau * math.cosh(theta_s), x0 + tau * math.sinh(theta_s)
        if tau >= change:
            theta_f = relative_rapidity(motion.velocity_final, frame.velocity)
            t1, x1 = float(stop[0, 0]), float(stop[0, 1])
            late = tau - change
            return t1 + late * math.cosh(theta_f), x1 + late * math.sinh(theta_f)
        m = theta_s + motion.sign * 0.5 * tau / rho
        h = 2.0 * rho * math.sinh(0.5 * tau / rho)
        return float(start[0, 0]) + h * math.cosh(m), float(start[0, 1]) + h * math.sinh(m)

    def horizon_event(self, rod: int, *, frame: Frame = LAB) -> tuple[float, float]:
        """The centre event of ``rod``'s change, ``(t', x')`` of ``frame``: every hyperbola of the change
        is centred on it, so the comoving frames' lines of simultaneity all pass through it (Sec. 3;
        it is the horizon of the points' accelerated frame). Lab ``(0, horizon_x)``, one boost here."""
        frame = check_frame(frame)
        motion = self.rods[self._rod_index(rod)].motion
        t, x = frame @ np.array([0.0, motion.horizon_x])
        return float(t), float(x)

    def cause(self) -> tuple[str, str, tuple[float, float]] | None:
        """The event the causal verdicts are measured from: its name as a :meth:`signal_arrival` source,
        its phrase (``"the contact"``) and its lab ``(t, x)``. The kick (:attr:`kick`) where an end is
        kicked away from the origin, else the origin event; ``None`` where nothing happens at the origin
        and nothing is kicked (a general velocity change's vertex): no single event causes that change."""
        if self.kick:
            return self.kick, OriginEvent.KICK.phrase, self.events[self.kick]
        if self.origin_event is OriginEvent.VERTEX:
            return None
        return self.origin_event.value, self.origin_event.phrase, (0.0, 0.0)

    def causal_verdicts(self, *, frame: Frame = LAB) -> tuple[ChangeVerdict, ...]:
        """For every rod end whose change does not begin or end at the cause (:meth:`cause`: the
        origin event, or a kick away from it): where the change lies relative to the cause's light
        cone, and where its first light signal arrives.

        The kinds (timelike, lightlike, spacelike) are invariants, found from the exact lab events,
        so the verdicts hold in every frame; the events, and every coordinate pair in the words, are
        those of ``frame`` (each pair labelled: ``"(lab t, x) = ..."`` in the lab, ``"(t, x) = ... in
        the frame ..."`` elsewhere). E.g. a wall crash: "the right end: its whole change, T_1 to T_1',
        lies outside the light cone of the contact: no signal from the contact can have caused it, in
        any frame". A scene without a cause (a general velocity change's vertex) has no verdicts.
        """
        frame = check_frame(frame)
        cause = self.cause()
        if cause is None:
            return ()
        source, phrase, cause_lab = cause
        named = {(s.rod, s.end, s.phase): s.name for s in self.event_specs}
        out: list[ChangeVerdict] = []
        for i, rod in enumerate(self.rods):
            start, stop = self._plan(LAB, ENDS, i).switch_events()
            seen_start, seen_stop = self._plan(frame, ENDS, i).switch_events()
            for end in (0, 1):
                s_event = (float(start[end, 0]), float(start[end, 1]))
                t_event = (float(stop[end, 0]), float(stop[end, 1]))
                if cause_lab in (s_event, t_event):
                    continue  # this end's change begins or ends at the cause itself
                side = "left" if end == 0 else "right"
                article = "" if rod.name.startswith("rod ") else "the "
                label = f"the {side} end" + (f" of {article}{rod.name}" if self.n_rods > 1 else "")
                names = (named.get((i, end, "start"), ""), named.get((i, end, "stop"), ""))
                arrival = self.signal_arrival(source, i, float(end), frame=frame)
                seen = (
                    (float(seen_start[end, 0]), float(seen_start[end, 1])),
                    (float(seen_stop[end, 0]), float(seen_stop[end, 1])),
                    arrival,
                )
                out.append(change_verdict(i, end, names, (s_event, t_event), seen, frame, phrase, label, cause_lab))
        return tuple(out)
