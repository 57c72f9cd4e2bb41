r"""The pole in the barn: the paper's wall crash (Sec. 5, ``eps = 0``) at the back wall of a barn.

Units c = 1; the lab is the barn's frame. A pole of rest length ``L0`` moves with velocity ``-V``
(``gamma = 1/sqrt(1 - V^2)``) toward a barn with its brick back wall at ``x = 0`` and its open
front door at ``x = D`` (``barn_length``, by default ``L0/gamma``: in the barn's frame the moving
pole "just fits"). The pole's front (left) end hits the wall at the origin. The door closes at
lab time ``t_d`` (``door_time``); by default at ``(L0/gamma - D)/V``, the instant the paradox
names: when the rear end, were the pole not stopped, would pass the door (``0`` for the default
``D``, the instant of the contact).

**Born-rigid stop** (``model="born"``, Sec. 5 with ``eps = 0``): the rear end coasts on
``x = L0/gamma - V t`` until ``T_1 = -gamma V L0`` (Eq. (22)), before the contact, then follows
``x = sqrt(L0^2 + t^2)`` (Eq. (23)) to rest at ``(0, L0)`` (``T_1'``, Eq. (24)): the pole ends at
rest with length ``L0``, its rear end never nearer the wall than ``L0``. It passes the door
(``x = D``) at ``t = (L0/gamma - D)/V`` if ``D >= gamma L0``, at ``t = -sqrt(D^2 - L0^2)`` if
``L0 <= D < gamma L0``, and never if ``D < L0``.

**Signal-limited stop** (``model="signal"``, :mod:`rigidrel_core._plastic`): each point moves at
``-V`` until a stop front leaving the contact at ``sound_speed`` ``c_s`` reaches it, then rests.
The rear end stops at ``t_s = L0/(gamma (c_s + V))``, ``x = L1 = c_s t_s``: the pole ends
compressed by ``c_s/(gamma (c_s + V))``, ``sqrt((1 - V)/(1 + V))`` at ``c_s = 1``. It passes the
door at ``(L0/gamma - D)/V`` if ``D >= L1``, never otherwise. The kinetic energy becomes heat in
the pole, whose rest mass grows to ``gamma M``: in the barn's frame the wall takes the momentum
``gamma M V`` and gives no energy.

**Verdicts.** What the door does is decided by three events on the door's worldline ``x = D``:
the door closes (``t_d``), the front end passes the door (``-D/V``: the front coasts until the
contact) and the rear end passes it (above; never if ``D < X``). Events on one timelike worldline
have the same order in every frame, so each verdict holds in every frame: the pole is **caught**
(entirely inside when the door closes, in every frame's time too: the rear end's passing is in the
door event's causal past) iff the rear end passes the door at or before ``t_d``; the door closes
**on the pole** (the pole spans the doorway, front in, rear out) iff the front end has passed and
the rear end has not; else it closes **in front of the pole**, which would hit it. The scene does
not model the door's effect on the pole: it is a marker.

Apart from the door: in any frame, the rear end's velocity only grows (it is braked toward rest in
the barn) while the door's is constant, so ``x'_rear - x'_door`` at equal frame time never increases
and is constant once the rear end rests in the barn: its least value is ``(X - D)/gamma'``, ``X``
the rear end's resting place; the front end never crosses the wall. So the pole, the door left
open, ends entirely inside iff ``X <= D``: the same in every frame.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from enum import StrEnum
from types import MappingProxyType
from typing import Literal

import numpy as np

from .._budget import PhysicalSystem
from .._build import IMPULSE, LENGTH, MASS, MAX_SCENE_COORDINATE, SIZE, V, checked_scene, rigid_motion
from .._description import (
    EventDescription,
    Interval,
    ObjectKind,
    OriginEvent,
    Parameter,
    PresetFigure,
    SceneDescription,
    ScenePreset,
    Slider,
    given,
)
from .._exact import REST, ExactVelocity
from .._frame import LAB, Frame, check_frame
from .._objects import ObjectEvent, SceneObject
from .._plastic import PlasticMotion
from .._scene import EventSpec, Rod, Scene
from .._validate import ParameterError
from .._words import event_in_words
from .wall import bounce

Model = Literal["born", "signal", "both"]
MODELS: tuple[Model, ...] = ("born", "signal", "both")


def moving_length(v: float, length: float) -> float:
    """``L0/gamma``: the length in the barn's frame of the pole moving at ``V`` (Sec. 3, Eq. (17))."""
    return length / ExactVelocity.from_float(v).lorentz_factor()


def paradox_door_time(v: float, length: float, barn_length: float) -> float:
    """``(L0/gamma - D)/V``: the lab time at which the pole's rear end, were the pole not stopped
    (on ``x = L0/gamma - V t``), would pass the door at ``x = D``: the instant the paradox names
    (``0``, the contact, for ``D = L0/gamma``)."""
    return (moving_length(v, length) - barn_length) / v


#: Largest |t_d|: the door's event, like every lab event of a scene, within this of the origin.
_DOOR_TIMES = Interval(-MAX_SCENE_COORDINATE, MAX_SCENE_COORDINATE, lo_closed=True, hi_closed=True)

BARN_LENGTH = Parameter(
    "barn_length",
    "D",
    "D (barn)",
    "length unit",
    SIZE,
    None,
    "rest length D of the barn, back wall at 0, door at D (default none: L0/γ, the moving pole's length in "
    "the barn's frame, so that it just fits there at every V)",
    Slider(0.05, 2.0, 0.01),
    typical=(0.05, 2.0),
    optional=True,
    when_omitted=lambda p: moving_length(given(p, "v"), given(p, "length")),
)
SOUND_SPEED = Parameter(
    "sound_speed",
    "c_s",
    "c_s (stop front)",
    "c",
    Interval(0.0, 1.0, hi_closed=True),
    1.0,
    "speed c_s of the stop front of the signal-limited pole, in the barn's frame (1: light speed)",
    Slider(0.05, 1.0, 0.01),
)
DOOR_TIME = Parameter(
    "door_time",
    "t_d",
    "t_d (door closes)",
    "length unit",
    _DOOR_TIMES,
    None,
    "lab (barn) time t_d at which the front door closes (default none: (L0/γ − D)/V, the instant the paradox "
    "names, when the rear end, were the pole not stopped, would pass the door; 0 for D = L0/γ)",
    Slider(-3.0, 3.0, 0.01),
    typical=(-3.0, 3.0),
    optional=True,
    when_omitted=lambda p: paradox_door_time(given(p, "v"), given(p, "length"), given(p, "barn_length")),
)


class DoorOrder(StrEnum):
    """When the door closes, relative to the rear end passing it (the same in every frame)."""

    AFTER = "after the rear end passes the door"
    SAME_EVENT = "as the rear end passes the door (the same event)"
    BEFORE = "before the rear end passes the door"
    NEVER_PASSES = "but the rear end never passes the door"

    def words(self) -> str:
        """``"the door closes after the rear end passes the door"``; ``"the door closes, but the rear end
        never passes the door"``."""
        return f"the door closes, {self.value}" if self is DoorOrder.NEVER_PASSES else f"the door closes {self.value}"


class DoorOutcome(StrEnum):
    """What the door's closing does to a pole, in every frame (module docstring, **Verdicts**)."""

    CAUGHT = "the door closes with the pole entirely inside"
    """The rear end passes the door at or before the door closes."""
    ON_POLE = "the door closes on the pole, which spans the doorway"
    """The front end has passed the door, the rear end has not (or never does): a real door would strike
    the pole."""
    SHUT_OUT = "the door closes in front of the pole"
    """The front end has not passed the door (or reaches it as it closes): the pole would hit the closed door."""


#: Each outcome as a lane's title says it once the door has closed, after the pole's name.
OUTCOME_WORDS: dict[DoorOutcome, str] = {
    DoorOutcome.CAUGHT: "inside",
    DoorOutcome.ON_POLE: "spans the doorway",
    DoorOutcome.SHUT_OUT: "outside",
}


@dataclass(frozen=True)
class PoleVerdict:
    """What one pole does in the barn (module docstring, **Verdicts**): each question answered by one
    exact criterion in the barn's frame, whose answer is the same in every frame."""

    rod: int
    model: Literal["born", "signal"]
    rear_rest_x: float
    """Lab x where the rear end comes to rest (``L0`` Born-rigid, ``L1`` signal-limited)."""
    inside: bool
    """With the door left open, the pole ends at rest entirely inside the barn: ``X <= D``."""
    door: DoorOrder
    """The door's closing against the rear end's passing the door, in every frame."""
    outcome: DoorOutcome
    """What the door's closing does to the pole, in every frame: decided by :attr:`door` and the front
    end's passing the door alone."""
    text: str


@dataclass(frozen=True, eq=False)
class PoleBarnScene(Scene):
    """The pole in the barn (module docstring): rod ``i`` is the pole of ``models[i]``."""

    barn_length: float = 1.0
    door_time: float = 0.0
    sound_speed: float = 1.0
    models: tuple[Literal["born", "signal"], ...] = ("born",)
    heats: tuple[float, ...] = (0.0,)
    """The rest energy each pole's stop creates: the Born-rigid pole's goes into the wall, the
    signal-limited pole's into the pole (``M (gamma - 1)`` each)."""

    @property
    def rod_groups(self) -> tuple[int, ...]:
        """Each pole in its own group: the models are alternatives, never in the barn together."""
        return tuple(range(len(self.models)))

    @property
    def systems(self) -> tuple[PhysicalSystem, ...]:
        """One physical system per model: a pole and the barn's wall that stops it (the two poles are
        two models of one pole, never in the barn together: their 4-momenta are never summed)."""
        return tuple(
            PhysicalSystem(
                f"the {rod.name}, of rest mass M = {rod.mass_before:g} before the stop"
                + (", the scene's unit (it has no mass option)," if rod.mass_before == 1.0 else ",")
                + " and the barn's back wall (one model)",
                (i,),
                "wall",
                heat,
            )
            for i, (rod, heat) in enumerate(zip(self.rods, self.heats, strict=True))
        )

    @property
    def moving_length(self) -> float:
        """``L0/gamma``: the moving pole's length in the barn's frame."""
        motion = self.rods[0].motion
        return moving_length(-motion.velocity_initial.value, motion.length)

    @property
    def paradox_door_time(self) -> float:
        """``(L0/gamma - D)/V``: when the unstopped rear end would pass the door (lab), the paradox's instant."""
        motion = self.rods[0].motion
        return paradox_door_time(-motion.velocity_initial.value, motion.length, self.barn_length)

    @property
    def door_closing(self) -> tuple[float, float]:
        """Lab ``(t_d, D)``: the door closes (the door's event)."""
        return (self.door_time, self.barn_length)

    def door_closing_in(self, *, frame: Frame = LAB) -> tuple[float, float]:
        """The door's closing as ``(t', x')`` of ``frame``."""
        t, x = (check_frame(frame) @ np.array(self.door_closing)).tolist()
        return (t, x)

    def rear_rest_x(self, rod: int) -> float:
        """Lab x where pole ``rod``'s rear end rests after the stop."""
        return self.rods[rod].motion.length_final if self.models[rod] == "signal" else self.rods[rod].motion.length

    def rear_passes_door(self, rod: int) -> tuple[float, float] | None:
        """Lab event where pole ``rod``'s rear end reaches ``x = D`` (``None``: never, ``D < X``; module
        docstring)."""
        motion = self.rods[rod].motion
        length, d = motion.length, self.barn_length
        gamma = motion.velocity_initial.lorentz_factor()
        if d < self.rear_rest_x(rod):
            return None
        if self.models[rod] == "born" and d < gamma * length:
            return (-math.sqrt((d - length) * (d + length)), d)  # on x = sqrt(L0^2 + t^2), Eq. (23)
        return (self.paradox_door_time, d)

    @property
    def front_passes_door(self) -> tuple[float, float]:
        """Lab event where the poles' front end passes the door: ``(-D/V, D)`` (it coasts until the
        contact at the origin, in either model)."""
        v = -self.rods[0].motion.velocity_initial.value
        return (-self.barn_length / v, self.barn_length)

    def rear_at_door_time(self, rod: int) -> float:
        """Lab x of pole ``rod``'s rear end when the door closes (lab time ``t_d``)."""
        return float(self.positions(np.array([self.door_time]))[rod, 1, 0])

    def inside(self, rod: int) -> bool:
        """Whether pole ``rod``, the door left open, ends at rest entirely inside the barn: ``X <= D``,
        ``X`` its rear end's resting place, exactly. The same in every frame (module docstring,
        **Verdicts**: in any frame ``x'_rear - x'_door`` at equal time never increases and ends at
        ``(X - D)/gamma'``), and the same criterion as the rear end's passing the door
        (:meth:`rear_passes_door`). Whether the door catches it is :meth:`door_outcome`."""
        return self.rear_rest_x(rod) <= self.barn_length

    def inside_in(self, rod: int, *, frame: Frame) -> bool:
        """:meth:`inside`, asked in ``frame``: the answer is the same in every frame (module docstring)."""
        check_frame(frame)
        return self.inside(rod)

    def door_order(self, rod: int) -> DoorOrder:
        """The door's closing against pole ``rod``'s rear end passing the door, by their lab times,
        exactly: both events are at the barn's ``x = D``, a timelike (or null) separation, so their
        order is the same in every frame."""
        passes = self.rear_passes_door(rod)
        if passes is None:
            return DoorOrder.NEVER_PASSES
        if passes[0] == self.door_time:
            return DoorOrder.SAME_EVENT
        return DoorOrder.AFTER if self.door_time > passes[0] else DoorOrder.BEFORE

    def door_order_in(self, rod: int, *, frame: Frame) -> DoorOrder:
        """:meth:`door_order`, asked in ``frame``: the same in every frame."""
        check_frame(frame)
        return self.door_order(rod)

    def door_outcome(self, rod: int) -> DoorOutcome:
        """What the door's closing does to pole ``rod`` (module docstring, **Verdicts**): caught iff its
        rear end passes the door at or before the door closes (:meth:`door_order`); else on the pole iff
        the front end passed the door before it closes; else in front of it. Each comparison is of two
        events on the door's worldline: the same in every frame."""
        if self.door_order(rod) in (DoorOrder.AFTER, DoorOrder.SAME_EVENT):
            return DoorOutcome.CAUGHT
        if self.door_time > self.front_passes_door[0]:
            return DoorOutcome.ON_POLE
        return DoorOutcome.SHUT_OUT

    def notes(self, *, frame: Frame = LAB) -> tuple[str, ...]:
        """The barn against the moving pole, the door's closing (as an event of ``frame``, labelled)
        and each pole's verdict (the same in every frame; lengths and times of the barn's frame, the
        lab, labelled so)."""
        frame = check_frame(frame)
        d, moving = self.barn_length, self.moving_length
        if math.isclose(d, moving, rel_tol=1e-12):
            barn = (
                f"the barn is D = {d:.4g} long in its own frame (the lab), the moving pole's length there, "
                f"L0/γ = {moving:.4g}: in the barn's frame the moving pole just fits"
            )
        elif d < moving:
            barn = (
                f"the barn, D = {d:.4g} in its own frame (the lab), is shorter than the moving pole there "
                f"(L0/γ = {moving:.4g}): even unstopped, the pole does not fit in the barn's frame"
            )
        else:
            barn = (
                f"the barn, D = {d:.4g} in its own frame (the lab), is longer than the moving pole there "
                f"(L0/γ = {moving:.4g}): the moving pole fits with room to spare"
            )
        paradox = self.paradox_door_time
        if self.door_time == paradox:
            when = "the instant the paradox names, when the rear end, were the pole not stopped, would pass it"
        else:
            when = (
                "not the paradox's instant (the rear end, were the pole not stopped, would pass the door at "
                f"lab t = {paradox:.4g})"
            )
        seen = event_in_words(self.door_closing_in(frame=frame), frame)
        door = f"the door closes at lab t_d = {self.door_time:.4g}, {when}: at {seen}"
        return (barn, door, *(v.text for v in self.verdicts()))

    def pole_name(self, rod: int) -> str:
        """``"the Born-rigid pole"``; ``"the signal-limited pole (its stop front at c_s = 1, light speed,
        in the barn's frame)"``."""
        if self.models[rod] == "born":
            return "the Born-rigid pole"
        light = ", light speed," if self.sound_speed == 1.0 else ""
        return f"the signal-limited pole (its stop front at c_s = {self.sound_speed:g}{light} in the barn's frame)"

    def verdicts(self) -> tuple[PoleVerdict, ...]:
        """One :class:`PoleVerdict` per pole, in words for the readout and the command line: what the
        door's closing does to it (:meth:`door_outcome`), with the events that decide it (lab times, all
        at the door), and where it comes to rest."""
        out: list[PoleVerdict] = []
        d, t_d = self.barn_length, self.door_time
        same_x = f"both events are at the door, lab x = {d:.4g}, so no frame reverses them"
        for i, model in enumerate(self.models):
            inside, door, outcome, x_rest = (
                self.inside(i),
                self.door_order(i),
                self.door_outcome(i),
                self.rear_rest_x(i),
            )
            name = self.pole_name(i)
            passes = self.rear_passes_door(i)
            rest = (
                f"it comes to rest with its rear end at lab x = {x_rest:.4g}"
                if model == "born"
                else f"it comes to rest compressed to rest length {x_rest:.4g}, its rear end at lab x = {x_rest:.4g}"
            )
            spot = "at" if x_rest == d else "inside"
            if outcome is DoorOutcome.CAUGHT:
                assert passes is not None
                when = (
                    "as the door closes (the same event)"
                    if door is DoorOrder.SAME_EVENT
                    else f"at lab t = {passes[0]:.4g}, before the door closes at lab t = {t_d:.4g} ({same_x})"
                )
                text = (
                    f"{name} is caught: its rear end passes the door {when}, so the whole pole is inside the "
                    f"barn when the door closes, in every frame; {rest}."
                )
            elif outcome is DoorOutcome.ON_POLE:
                head = (
                    f"the door closes on {name}, in every frame: at lab t = {t_d:.4g} the pole spans the doorway, "
                    f"its rear end at lab x = {self.rear_at_door_time(i):.4g}, outside the door at lab x = {d:.4g}"
                )
                if passes is None:
                    tail = f"its rear end never passes the door: {rest}, beyond the door"
                else:
                    tail = (
                        f"its rear end passes the door only at lab t = {passes[0]:.4g}, after the door closes "
                        f"({same_x}); only with the door left open does the pole end entirely inside ({rest}, "
                        f"{spot} the door)"
                    )
                text = f"{head}; {tail}."
            else:
                if inside:
                    tail = f"only with the door left open does the pole end entirely inside ({rest}, {spot} the door)"
                else:
                    tail = f"even with the door left open it would stick out of the barn: {rest}, beyond the door"
                text = (
                    f"the door closes in front of {name}, in every frame: at lab t = {t_d:.4g}, before its front end "
                    f"reaches the door at lab t = {self.front_passes_door[0]:.4g} ({same_x}); the pole would hit "
                    f"the closed door; {tail}."
                )
            out.append(PoleVerdict(i, model, x_rest, inside, door, outcome, text))
        return tuple(out)


def pole_barn(
    v: float,
    length: float,
    barn_length: float | None = None,
    model: Model = "born",
    sound_speed: float = 1.0,
    door_time: float | None = None,
    mass: float = 1.0,
) -> PoleBarnScene:
    """The pole in the barn (module docstring); ``model`` ``"born"``, ``"signal"`` or ``"both"``
    (the two poles as rods 0 and 1, the registry's scene). ``barn_length`` ``None``: ``L0/gamma``
    (:func:`moving_length`, the pole just fits in the barn's frame); ``door_time`` ``None``: the
    paradox's instant (:func:`paradox_door_time`).

    Events: ``"T_1"``, ``"T_1'"`` (the Born-rigid pole's rear end starts and ends its deceleration,
    Sec. 5, Eqs. (22), (24)), ``"T_s"`` (the stop front reaches the signal-limited pole's rear end).
    Frames: ``"lab"`` (the barn's), ``"pole before"`` (the pole's initial frame).
    """
    v = V.check(v)
    length = LENGTH.check(length)
    if model not in MODELS:
        raise ParameterError("model", "one of 'born', 'signal', 'both'", model)
    c_s = SOUND_SPEED.check(sound_speed)
    mass = MASS.check(mass)
    velocity = ExactVelocity.from_float(-v)
    d = moving_length(v, length) if barn_length is None else BARN_LENGTH.check(barn_length)
    t_d = None if door_time is None else DOOR_TIME.check(door_time)
    # the events the verdicts and notes name, like every lab event of a scene, within 1e120 of the
    # origin: the unstopped rear end's passing the door (the default door time) and the stop front's
    # reaching the signal-limited pole's rear end, at L0/(gamma (c_s + V))
    paradox = paradox_door_time(v, length, d)
    stop_front = moving_length(v, length) / (c_s + v)
    if paradox not in _DOOR_TIMES or (model != "born" and not stop_front <= MAX_SCENE_COORDINATE):
        within = f"within {MAX_SCENE_COORDINATE:g} of the origin"
        raise ParameterError(
            "parameters",
            f"such that the unstopped rear end passes the door, at lab t = (L0/γ − D)/V, and the stop front "
            f"reaches the rear end, at lab t = L0/(γ (c_s + V)), {within}",
            {"v": v, "length": length, "barn_length": d, "sound_speed": c_s},
        )
    if t_d is None:
        t_d = paradox
    models: tuple[Literal["born", "signal"], ...] = ("born", "signal") if model == "both" else (model,)
    rods: list[Rod] = []
    specs: list[EventSpec] = []
    heats: list[float] = []
    for i, m in enumerate(models):
        if m == "born":
            _, wall_heat = bounce(v, 0.0, mass)  # M (gamma - 1), into the wall
            rods.append(Rod("Born-rigid pole", rigid_motion(velocity, REST, length, IMPULSE, 0.0), mass, mass))
            specs += [EventSpec("T_1", i, 1, "start"), EventSpec("T_1'", i, 1, "stop")]
            heats.append(wall_heat)
        else:
            plastic = PlasticMotion.stop_at_wall(v, length, c_s)
            heat = mass * velocity.lorentz_factor_minus_one()  # M (gamma - 1), into the pole: a product
            rods.append(Rod("signal-limited pole", plastic, mass, mass + heat))
            specs.append(EventSpec("T_s", i, 1, "stop"))
            heats.append(heat)
    params: dict[str, float] = {"v": v, "length": length, "sound_speed": c_s}
    if barn_length is not None:
        params["barn_length"] = d
    if door_time is not None:
        params["door_time"] = t_d
    scene = PoleBarnScene(
        kind=POLE_BARN.kind,
        parameters=MappingProxyType(params),
        rods=tuple(rods),
        event_specs=tuple(specs),
        frames=MappingProxyType({"lab": LAB, "pole before": Frame(velocity, "pole before")}),
        external_source="wall",
        heat=heats[0],
        origin_event=OriginEvent.CONTACT,
        objects=(  # the wall's matter toward -x, the door's outside the barn (toward +x)
            SceneObject.inertial("back wall", ObjectKind.WALL, 0.0, REST, side=-1),
            SceneObject.inertial(
                "door",
                ObjectKind.BARN_DOOR,
                d,
                REST,
                side=1,
                event=ObjectEvent(
                    "door closes",
                    (t_d, d),
                    state="closed",
                    meaning="the barn's front door closes",
                    closes=True,
                    before="open",
                ),
            ),
        ),
        barn_length=d,
        door_time=t_d,
        sound_speed=c_s,
        models=models,
        heats=tuple(heats),
    )
    door = scene.objects[1]
    assert door.event is not None
    outcome = ", ".join(f"{rod.name} {OUTCOME_WORDS[scene.door_outcome(i)]}" for i, rod in enumerate(scene.rods))
    scene = replace(scene, objects=(scene.objects[0], replace(door, event=replace(door.event, outcome=outcome))))
    checked_scene(scene)
    return scene


def _both(
    v: float,
    length: float,
    barn_length: float | None = None,
    sound_speed: float = 1.0,
    door_time: float | None = None,
) -> PoleBarnScene:
    """The registry's pole in the barn: both models, one above the other."""
    return pole_barn(v, length, barn_length, "both", sound_speed, door_time)


def _figure_caption(scene: Scene) -> str:
    """The print figure's caption (:class:`~rigidrel_core.PresetFigure`): the Born-rigid pole solid,
    the signal-limited one dashed, the door dashed; every number and verdict the scene's, every
    coordinate the lab's (the figure is the lab's diagram)."""
    assert isinstance(scene, PoleBarnScene)
    v, length = scene.parameters["v"], scene.parameters["length"]
    d, t_d = scene.barn_length, scene.door_time
    fits = " L0/γ =" if math.isclose(d, scene.moving_length, rel_tol=1e-12) else ""
    born, signal = scene.verdicts()
    fate = {
        DoorOutcome.CAUGHT: "the door closes behind it: it is caught inside, in every frame",
        DoorOutcome.ON_POLE: "the door closes on it, in every frame, while it spans the doorway",
        DoorOutcome.SHUT_OUT: "the door closes in front of it, in every frame",
    }
    return (
        f"The pole in the barn, V = {v:g}, L0 = {length:g}, barn D ={fits} {d:g}; lab coordinates (the barn's frame): "
        f"back wall at x = 0, door dashed at x = {d:g}, closing at t = {t_d:g}. Solid: the Born-rigid stop (Sec. 5, "
        f"ε = 0): its rear end starts braking at T_1, before the contact in the lab, and comes to rest at "
        f"x = {born.rear_rest_x:.4g}; {fate[born.outcome]}. Dashed: the signal-limited stop (a stop front from the "
        f"contact at c_s = {scene.sound_speed:g} in the barn's frame): every point moves on until the stop front "
        f"reaches it; the rear end stops at T_s, x = {signal.rear_rest_x:.4g}; {fate[signal.outcome]}."
    )


#: The print figure of the first preset: the barn's wall and door, both poles, their rear ends' events
#: and the door's closing.
_FIGURE = PresetFigure(
    "pole-barn",
    (-1.8, 1.2),
    (("T_1", "left"), ("T_1'", "left"), ("T_s", "left"), ("door closes", "right")),
    _figure_caption,
)

POLE_BARN = SceneDescription(
    kind="pole-barn",
    title="Pole in the barn",
    summary=(
        "A pole moving at −V crashes into the back wall of a barn of length D (by default L0/γ, so that in the "
        "barn's frame the moving pole just fits), whose door closes, by default, when the unstopped pole's rear "
        "end would pass it. With both defaults it closes on the Born-rigid pole (Sec. 5), in every frame, and "
        "behind a pole stopped by a signal from the contact (at light speed); other values can change either "
        "verdict, and the notes say which holds."
    ),
    source="Sec. 5",
    constructor=_both,
    parameters=(V, LENGTH, BARN_LENGTH, SOUND_SPEED, DOOR_TIME),
    frames=("lab", "pole before"),
    default_frame="pole before",
    events=(
        EventDescription("T_1", "the Born-rigid pole's rear (right) end starts changing velocity", "Sec. 5, Eq. (22)"),
        EventDescription(
            "T_1'", "the Born-rigid pole's rear end has its final velocity (at rest in the barn)", "Sec. 5, Eq. (24)"
        ),
        EventDescription("T_s", "the stop front reaches the signal-limited pole's rear (right) end", "Sec. 5"),
    ),
    objects=(ObjectKind.WALL, ObjectKind.BARN_DOOR),
    presets=(
        ScenePreset(
            "Pole in the barn, V = 0.8, D = 0.6", {"v": 0.8, "length": 1.0, "barn_length": 0.6}, figure=_FIGURE
        ),
        ScenePreset(
            "Pole in the barn, stop front at c/2", {"v": 0.8, "length": 1.0, "barn_length": 0.6, "sound_speed": 0.5}
        ),
    ),
    meanings=MappingProxyType(
        {"v": "approach speed V (c = 1): the pole moves at −V toward the barn's back wall at x = 0"}
    ),
    order=70,
)

SCENES = (POLE_BARN,)
