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

**Verdicts.** In any frame, the rear end's velocity only grows (it is braked toward rest in the
barn) while the door's is constant, so ``x'_rear - x'_door`` at equal frame time never increases
and is constant once the rear end rests in the barn: its least value is ``(X - D)/gamma'``, ``X``
the rear end's resting place; the front end never crosses the wall. So the pole is entirely inside
at some instant of a frame iff ``X <= D``: the same in every frame (each frame's samplers find it).
The door's closing and the rear end's passing the door are both at ``x = D`` in the barn: their
separation is timelike (or zero) and their order the same in every frame.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from enum import StrEnum
from types import MappingProxyType
from typing import Literal

import numpy as np

from .._build import IMPULSE, LENGTH, MASS, SIZE, V, checked_scene, rigid_motion
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
)
from .._exact import REST, ExactVelocity
from .._frame import LAB, Frame, check_frame
from .._objects import ObjectEvent, SceneObject
from .._plastic import PlasticMotion
from .._scene import EventSpec, Rod, Scene
from .._validate import ParameterError
from .wall import bounce

Model = Literal["born", "signal", "both"]
MODELS: tuple[Model, ...] = ("born", "signal", "both")

BARN_LENGTH = Parameter(
    "barn_length",
    "D",
    "D (barn)",
    "length unit",
    SIZE,
    0.8,
    "rest length D of the barn, back wall at 0, door at D (none: L0/γ, where the moving pole just fits; "
    "the default 0.8 is L0/γ at the default V = 0.6)",
    Slider(0.05, 2.0, 0.01),
    typical=(0.05, 2.0),
    optional=True,
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
    Interval(-math.inf, math.inf),
    0.0,
    "lab time t_d at which the front door closes (none: (L0/γ − D)/V, when the unstopped rear end would pass "
    "it; the default 0 is that instant for D = L0/γ)",
    Slider(-3.0, 3.0, 0.01),
    typical=(-3.0, 3.0),
    optional=True,
)


class DoorOrder(StrEnum):
    """When the door closes, relative to the rear end passing it (the same in every frame)."""

    AFTER = "after the rear end passes the door"
    SAME_EVENT = "as the rear end passes the door (the same event)"
    BEFORE = "before the rear end passes the door"
    NEVER_PASSES = "while the rear end never passes the door"


@dataclass(frozen=True)
class PoleVerdict:
    """What one pole does in the barn, found in two frames (they agree: see the module docstring)."""

    rod: int
    model: Literal["born", "signal"]
    rear_rest_x: float
    """Lab x where the rear end comes to rest (``L0`` Born-rigid, ``L1`` signal-limited)."""
    inside_barn_frame: bool
    inside_pole_frame: bool
    """Entirely inside at some instant of the pole's initial frame ("pole before")."""
    door_barn_frame: DoorOrder
    door_pole_frame: DoorOrder
    text: str


@dataclass(frozen=True, eq=False)
class PoleBarnScene(Scene):
    """The pole in the barn (module docstring): rod ``i`` is the pole of ``models[i]``."""

    barn_length: float = 1.0
    door_time: float = 0.0
    sound_speed: float = 1.0
    models: tuple[Literal["born", "signal"], ...] = ("born",)

    @property
    def rod_groups(self) -> tuple[int, ...]:
        """Each pole in its own group: the models are alternatives, never in the barn together."""
        return tuple(range(len(self.models)))

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
        """Lab event where pole ``rod``'s rear end reaches ``x = D`` (``None``: never; module docstring)."""
        motion = self.rods[rod].motion
        length, d = motion.length, self.barn_length
        speed = -motion.velocity_initial.value
        gamma = motion.velocity_initial.lorentz_factor()
        if d < self.rear_rest_x(rod):
            return None
        if self.models[rod] == "born" and d < gamma * length:
            return (-math.sqrt((d - length) * (d + length)), d)  # on x = sqrt(L0^2 + t^2), Eq. (23)
        return ((length / gamma - d) / speed, d)

    def inside_in(self, rod: int, *, frame: Frame) -> bool:
        """Whether pole ``rod`` is entirely inside the barn (``x'_wall <= x'_front``, ``x'_rear <=
        x'_door`` at one frame time) at some instant of ``frame``: sampled after every event of the
        scene in that frame, where ``x'_rear - x'_door`` has its least value (module docstring)."""
        frame = check_frame(frame)
        t_late = self.time_window(frame=frame, margin=1.0)[1]
        t_late = max(t_late, self.door_closing_in(frame=frame)[0] + 1.0)
        x = self.positions(np.array([t_late]), frame=frame)[rod, :, 0]
        wall, door = (float(o.positions(t_late, frame=frame)[0]) for o in self.objects)
        scale = 1e-12 * max(abs(t_late), self.barn_length, self.rods[rod].motion.length)
        return bool(x[1] - door <= scale and x[0] - wall >= -scale)

    def door_order_in(self, rod: int, *, frame: Frame) -> DoorOrder:
        """The door's closing against the rear end's passing the door, by their times in ``frame``."""
        frame = check_frame(frame)
        passes = self.rear_passes_door(rod)
        if passes is None:
            return DoorOrder.NEVER_PASSES
        if passes == self.door_closing:
            return DoorOrder.SAME_EVENT
        t_pass = float((frame @ np.array(passes))[0])
        t_door = self.door_closing_in(frame=frame)[0]
        return DoorOrder.AFTER if t_door > t_pass else DoorOrder.BEFORE

    def notes(self, *, frame: Frame = LAB) -> tuple[str, ...]:
        """The door's closing in ``frame`` and each pole's verdict (the same in every frame)."""
        t, x = self.door_closing_in(frame=frame)
        return (f"the door closes at (t, x) = ({t:.6g}, {x:.6g}) in this frame", *(v.text for v in self.verdicts()))

    def verdicts(self) -> tuple[PoleVerdict, ...]:
        """One :class:`PoleVerdict` per pole, in words for the readout and the command line."""
        pole = self.frames["pole before"]
        out: list[PoleVerdict] = []
        for i, model in enumerate(self.models):
            inside = (self.inside_in(i, frame=LAB), self.inside_in(i, frame=pole))
            door = (self.door_order_in(i, frame=LAB), self.door_order_in(i, frame=pole))
            x_rest = self.rear_rest_x(i)
            name = "Born-rigid pole" if model == "born" else f"signal-limited pole (c_s = {self.sound_speed:g})"
            if inside[0] == inside[1]:
                where = "is entirely inside the barn at some instant" if inside[0] else "is never entirely inside"
                where += " (in the barn's frame and in the pole's initial frame)"
            else:
                where = f"inside in the barn's frame: {inside[0]}; in the pole's initial frame: {inside[1]}"
            order = door[0].value if door[0] == door[1] else f"{door[0].value} (barn), {door[1].value} (pole)"
            text = (
                f"{name}: {where}; its rear end comes to rest at barn x = {x_rest:.4g}, the door is at "
                f"x = {self.barn_length:.4g}; the door closes at barn time {self.door_time:.4g}, {order}, "
                "in every frame."
            )
            out.append(PoleVerdict(i, model, x_rest, inside[0], inside[1], door[0], door[1], text))
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
    (the two poles as rods 0 and 1, the registry's scene).

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
    contracted = length / velocity.lorentz_factor()
    d = contracted if barn_length is None else BARN_LENGTH.check(barn_length)
    t_d = (contracted - d) / v if door_time is None else DOOR_TIME.check(door_time)
    models: tuple[Literal["born", "signal"], ...] = ("born", "signal") if model == "both" else (model,)
    rods: list[Rod] = []
    specs: list[EventSpec] = []
    heat = 0.0
    for i, m in enumerate(models):
        if m == "born":
            _, wall_heat = bounce(v, 0.0, mass)
            rods.append(Rod("Born-rigid pole", rigid_motion(velocity, REST, length, IMPULSE, 0.0), mass, mass))
            specs += [EventSpec("T_1", i, 1, "start"), EventSpec("T_1'", i, 1, "stop")]
            heat += wall_heat
        else:
            plastic = PlasticMotion.stop_at_wall(v, length, c_s)
            gamma = velocity.lorentz_factor()
            rods.append(Rod("signal-limited pole", plastic, mass, gamma * mass))
            specs.append(EventSpec("T_s", i, 1, "stop"))
            heat += (gamma - 1.0) * mass
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
        heat=heat,
        origin_event=OriginEvent.CONTACT,
        objects=(  # the wall's matter toward -x, the door's outside the barn (toward +x)
            SceneObject.inertial("back wall", ObjectKind.WALL, 0.0, REST, side=-1),
            SceneObject.inertial(
                "door", ObjectKind.BARN_DOOR, d, REST, side=1, event=ObjectEvent("door closes", (t_d, d))
            ),
        ),
        barn_length=d,
        door_time=t_d,
        sound_speed=c_s,
        models=models,
    )
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
    the signal-limited one dashed, the door dashed; every number and verdict the scene's."""
    assert isinstance(scene, PoleBarnScene)
    v, length = scene.parameters["v"], scene.parameters["length"]
    d, t_d = scene.barn_length, scene.door_time
    fits = " L0/γ =" if math.isclose(d, length * math.sqrt((1.0 - v) * (1.0 + v)), rel_tol=1e-12) else ""
    born, signal = scene.verdicts()
    return (
        f"The pole in the barn, V = {v:g}, L0 = {length:g}, barn D ={fits} {d:g} (back wall at x = 0, door dashed at "
        f"x = {d:g}, closing at t = {t_d:g}). Solid: the Born-rigid stop (Sec. 5, ε = 0): its rear end starts "
        f"braking at T_1, before the contact, and comes to rest at x = {born.rear_rest_x:.4g}; it "
        f"{'is' if born.inside_barn_frame else 'is never'} entirely inside the barn, in the barn's frame and in the "
        f"pole's, and the door closes {born.door_barn_frame.value}. Dashed: the signal-limited stop "
        f"(c_s = {scene.sound_speed:g}): every point moves on until the stop front from the contact reaches it; the "
        f"rear end stops at T_s, x = {signal.rear_rest_x:.4g}; it {'is' if signal.inside_barn_frame else 'is never'} "
        f"entirely inside, in both frames, and the door closes {signal.door_barn_frame.value}."
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
        "A pole moving at −V crashes into the back wall of a barn that, in the barn's frame, it just fits: "
        "the Born-rigid pole (Sec. 5) never fits; a pole stopped by a signal does."
    ),
    source="Sec. 5",
    constructor=_both,
    parameters=(V, LENGTH, BARN_LENGTH, SOUND_SPEED, DOOR_TIME),
    frames=("lab", "pole before"),
    default_frame="pole before",
    events=(
        EventDescription("T_1", "the Born-rigid pole's rear end starts to decelerate", "Sec. 5, Eq. (22)"),
        EventDescription("T_1'", "the Born-rigid pole's rear end comes to rest", "Sec. 5, Eq. (24)"),
        EventDescription("T_s", "the stop front reaches the signal-limited pole's rear end", "Sec. 5"),
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
    order=70,
)

SCENES = (POLE_BARN,)
