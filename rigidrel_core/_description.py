"""What a scene is, for everything that is not physics: one frozen description per scene.

A :class:`SceneDescription` names a scene's constructor and says, for the app, the command
line, the exports, the benchmarks and the tests, what its parameters are (symbol, unit,
allowed range, slider, default, help), which of the paper's figures it reproduces, which
frames it offers, what its named events mean, which objects that are not rods it holds and how its
presets are drawn as print figures. Every one of
those front ends is generated from the description; the constructor validates with the
very same :class:`Parameter` objects, so the ranges shown are the ranges enforced.
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from types import MappingProxyType
from typing import TYPE_CHECKING, Literal

from ._kinds import ObjectKind as ObjectKind
from ._kinds import OriginEvent as OriginEvent
from ._validate import ParameterError, RenamedParameterError, as_real

if TYPE_CHECKING:
    from ._scene import Scene

Scale = Literal["linear", "log"]
Side = Literal["left", "right"]


@dataclass(frozen=True)
class Interval:
    """A range of real numbers with open or closed ends (``math.inf`` for none)."""

    lo: float
    hi: float
    lo_closed: bool = False
    hi_closed: bool = False

    def __contains__(self, x: float) -> bool:
        above = x >= self.lo if self.lo_closed else x > self.lo
        below = x <= self.hi if self.hi_closed else x < self.hi
        return above and below

    def text(self) -> str:
        """``"in (0, 1)"``, ``"in [0, 1]"``, ``"> 0"``."""
        if math.isinf(self.hi) and self.hi > 0:
            return f"{'>=' if self.lo_closed else '>'} {self.lo:g}"
        left = "[" if self.lo_closed else "("
        right = "]" if self.hi_closed else ")"
        return f"in {left}{self.lo:g}, {self.hi:g}{right}"


#: Speeds (0, 1), velocities (-1, 1), restitution [0, 1].
SPEED = Interval(0.0, 1.0)
VELOCITY = Interval(-1.0, 1.0)
UNIT_CLOSED = Interval(0.0, 1.0, True, True)


def given(values: Mapping[str, float | None], name: str) -> float:
    """``values[name]`` for a rule of :attr:`Parameter.when_omitted`: a ``TypeError`` if it is not a
    number (the rule then gives no value, and the constructor says what is wrong)."""
    value = values.get(name)
    if isinstance(value, bool) or not isinstance(value, int | float):
        raise TypeError(f"{name} is not a number")
    return float(value)


@dataclass(frozen=True)
class Slider:
    """How the app shows a parameter: a slider from ``lo`` to ``hi``.

    ``scale="log"`` is a slider over ``log10`` of the value (``step`` in decades) whose value
    is still shown and typed as the number itself (a mass ratio of 2, not 0.30103).
    """

    lo: float
    hi: float
    step: float
    scale: Scale = "linear"

    def __post_init__(self) -> None:
        if not (self.lo < self.hi and self.step > 0) or (self.scale == "log" and self.lo <= 0):
            raise ValueError(f"bad slider {self}")


@dataclass(frozen=True)
class Parameter:
    """One scene parameter.

    ``domain`` is the validator's allowed range (:meth:`check` enforces it); ``slider`` is
    the app's control (``None``: not on the slider page, it keeps its default there);
    ``typical`` is the range property tests and benchmarks draw from.
    """

    name: str
    """Keyword of the constructor and the command line option (``--name``)."""
    symbol: str
    """As the paper writes it: ``"V"``, ``"a′_F"``, ``"M2"``."""
    label: str
    """The app's control label (rod 1 sets the units there: ``"M2/M1"``, ``"a′_F L0"``)."""
    unit: str
    """``"c"`` for velocities, ``"length unit"`` for lengths, ``"1/length unit"`` for accelerations, ``""``."""
    domain: Interval
    default: float | None
    help: str
    slider: Slider | None = None
    typical: tuple[float, float] | None = None
    """Where property tests and benchmarks draw values (default: the slider's range)."""
    optional: bool = False
    """``None`` is a value (e.g. no acceleration given: the impulsive limit)."""
    constraint: str = ""
    """A condition that involves other parameters, in words (checked by the constructor)."""
    when_omitted: Callable[[Mapping[str, float | None]], float] | None = field(default=None, compare=False)
    """For an optional parameter whose omission (``None``) stands for a value that follows the others
    (the pole's barn: ``L0/gamma``, so that it just fits at every ``V``), that value, from the scene's
    values by name (those before it in the description already resolved); the constructor computes it
    with the same function. ``None``: omitting it means no value (no breaking strain)."""

    def allowed(self) -> str:
        text = f"a finite number {self.domain.text()}"
        return f"{text} ({self.constraint})" if self.constraint else text

    def check(self, value: object) -> float:
        """``value`` as a float if it lies in :attr:`domain`; else :class:`ParameterError` naming it."""
        domain = self.domain
        if type(value) is float and (
            domain.lo < value < domain.hi or (-math.inf < value < math.inf and value in domain)
        ):
            return value  # the common case (a float in range, so finite), without composing the message
        allowed = f"a finite number {self.domain.text()}"
        x = as_real(self.name, value, allowed)
        if x not in self.domain:
            raise ParameterError(self.name, allowed, value)
        return x

    def sample_range(self) -> tuple[float, float]:
        if self.typical is not None:
            return self.typical
        if self.slider is not None:
            return (self.slider.lo, self.slider.hi)
        raise ValueError(f"parameter {self.name!r} has neither a slider nor a typical range")


@dataclass(frozen=True)
class EventDescription:
    """A named event in the paper's notation and what it marks."""

    name: str
    """``"T_1'"``: as the paper writes it, ``_`` before the subscript, ``'`` for a prime."""
    meaning: str
    source: str
    """Where the paper gives it: ``"Sec. 5, Eq. (24)"``."""


@dataclass(frozen=True)
class Overlay:
    """A second scene drawn dashed over the first for comparison (Fig. 1's impulsive curve)."""

    label: str
    build: Callable[[Mapping[str, float | None]], Scene]
    """The comparison scene, from the first scene's parameters."""


@dataclass(frozen=True)
class PresetFigure:
    """A preset drawn as a print figure (``rigidrel figures``): the lab Minkowski diagram over
    :attr:`t_range`, at equal scales. Every front end draws it from the scene alone: the objects'
    worldlines by their roles, then each rod's world tube, those of the first rod group
    (:attr:`~rigidrel_core.Scene.rod_groups`) solid and shaded, the others' (alternatives, a
    comparison) dashed, then the :attr:`marks`; :attr:`caption` says so in words."""

    name: str
    """The figure's file name, without extension: ``"bell-spaceships"``."""
    t_range: tuple[float, float]
    """Lab times shown."""
    marks: tuple[tuple[str, Side], ...]
    """Events marked with a dot and named, each with the side of its label: the scene's named events
    (``"T_B1"``) or its objects' (``"break"``, ``"door closes"``)."""
    caption: Callable[[Scene], str]
    """The caption, from the scene the preset builds: every number in it the core's."""


@dataclass(frozen=True)
class ScenePreset:
    """A paper figure: a scene's parameter values, frame and overlay, exactly as printed."""

    label: str
    """The app's menu entry, ``"Fig. 3: collision, M2 = 2 M1"``."""
    values: Mapping[str, float | None]
    frame: str | None = None
    """The frame to show it in (``None``: the scene's default frame)."""
    overlay: bool = False
    figure: PresetFigure | None = None
    """How ``rigidrel figures`` draws it in print, if it does."""


@dataclass(frozen=True)
class SceneDescription:
    """Everything the front ends need to know about a scene, beside its constructor."""

    kind: str
    """The command line's name: ``"wall-collision"``."""
    title: str
    """The app's menu entry: ``"Wall crash / bounce"``."""
    summary: str
    """One sentence for help texts."""
    source: str
    """Where the paper treats it: ``"Sec. 5"``."""
    constructor: Callable[..., Scene]
    parameters: tuple[Parameter, ...]
    frames: tuple[str, ...]
    """The names of the frame presets every scene of this kind offers, ``"lab"`` first."""
    default_frame: str
    """The frame a lecturer compares the lab with first (never one that equals the lab)."""
    events: tuple[EventDescription, ...]
    objects: tuple[ObjectKind, ...] = ()
    """The kinds of the scene's objects that are not rods, in the order the scene holds them."""
    presets: tuple[ScenePreset, ...] = ()
    overlay: Overlay | None = None
    order: int = 100
    """Position in the app's menu (teaching order)."""
    meanings: Mapping[str, str] = field(default_factory=lambda: MappingProxyType({}))
    """What a parameter shared with other scenes means in this one, where its own help must cover them
    all (``{"v": "approach speed V: the rod moves at −V toward the wall"}``): the command line's help
    and the docs give it (:meth:`help_for`)."""
    renamed: Mapping[str, str] = field(default_factory=lambda: MappingProxyType({}))
    """Old parameter names and the names that replaced them (``{"m2": "mass2"}``): the constructor,
    the registry, scenario strings, lesson files and the command line refuse an old name and name
    the new one."""
    parameter_map: Mapping[str, Parameter] = field(init=False, repr=False, compare=False)
    _defaults: Mapping[str, float | None] = field(init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        names = [p.name for p in self.parameters]
        if len(set(names)) != len(names):
            raise ValueError(f"{self.kind}: duplicate parameter names {names}")
        stale = [old for old, new in self.renamed.items() if old in names or new not in names]
        if stale:
            raise ValueError(f"{self.kind}: renamed {stale} must be old names of its parameters, not current ones")
        if self.default_frame not in self.frames or self.frames[:1] != ("lab",) or self.default_frame == "lab":
            raise ValueError(f"{self.kind}: frames must start with 'lab' and hold a default other than the lab")
        object.__setattr__(self, "parameter_map", MappingProxyType({p.name: p for p in self.parameters}))
        object.__setattr__(self, "_defaults", MappingProxyType(self.defaults()))

    def parameter(self, name: str) -> Parameter:
        try:
            return self.parameter_map[name]
        except KeyError:
            if name in self.renamed:
                raise RenamedParameterError(f"the scene {self.kind!r}", self.renamed, (name,)) from None
            allowed = f"one of the parameters of {self.kind}: {', '.join(self.parameter_map)}"
            raise ParameterError(name, allowed, name) from None

    def help_for(self, parameter: Parameter) -> str:
        """What ``parameter`` means in this scene: :attr:`meanings`' entry, else its own help."""
        return self.meanings.get(parameter.name, parameter.help)

    def defaults(self) -> dict[str, float | None]:
        return {p.name: p.default for p in self.parameters}

    def resolved(self, values: Mapping[str, float | None]) -> dict[str, float | None]:
        """Every parameter's value: ``values``, the defaults for the others, and for an omitted one
        that stands for a value (:attr:`Parameter.when_omitted`) that value (``None`` left where the
        other values give none: the constructor says what is wrong with them)."""
        out = {**self._defaults, **values}
        for p in self.parameters:
            if out.get(p.name) is None and p.when_omitted is not None:
                try:
                    value = float(p.when_omitted(out))
                except (ArithmeticError, TypeError, ValueError):
                    continue
                if math.isfinite(value):
                    out[p.name] = value
        return out

    def build(self, **values: float | None) -> Scene:
        """The scene with ``values``; missing parameters take their defaults (the paper's).

        A constructor that builds on another scene's (a registered variant) gets its scene
        stamped with this description's kind and parameters, so that the scene names its own
        description (:func:`rigidrel_core.describe`)."""
        known = self.parameter_map
        for name in values:
            if name not in known:
                if name in self.renamed:  # every old name given, with its new one
                    raise RenamedParameterError(f"the scene {self.kind!r}", self.renamed, values)
                self.parameter(name)  # names the parameters there are
        given = {**self._defaults, **values}
        scene = self.constructor(**given)
        if scene.kind == self.kind:
            return scene
        own = MappingProxyType({k: float(v) for k, v in given.items() if v is not None})
        return dataclasses.replace(scene, kind=self.kind, parameters=own)

    def event(self, name: str) -> EventDescription:
        for e in self.events:
            if e.name == name:
                return e
        raise ParameterError("event", f"one of {', '.join(e.name for e in self.events)}", name)
