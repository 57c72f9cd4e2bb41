"""What the controls say, as a frozen value, and the scene and frame it means.

Everything here is generated from the core's scene registry: a :class:`Settings` holds a
scene's name and a value for each of its parameters, the paper's presets are the
descriptions' presets, and the frame menu is the scene's frame presets. The GUI only ever
replaces one field of a :class:`Settings` and asks :func:`resolve` for the scene: invalid
combinations come back as a notice, never as an exception.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, field, replace
from types import MappingProxyType

import rigidrel_core as rr

from .comoving import RidePoint
from .layers import DEFAULT_LAYERS, Layer

#: The frame dropdown's entry for a frame set by the β slider.
CUSTOM_FRAME = "custom (β slider)"
#: The frame dropdown's entry for the frame that rides a material point (the ride controls choose it).
RIDE_FRAME = "riding a point (ride f)"
#: The point a riding frame rides until one is chosen: the middle of the first rod.
DEFAULT_RIDE = RidePoint(0, 0.5)
#: The range of the app's β slider (the core, the exports and the command line take any |β| < 1).
CUSTOM_BETA = (-0.99, 0.99)
#: The preset menu's entry when the controls show no paper figure.
NO_PRESET = "—"
#: The scene a new tab opens on.
DEFAULT_SCENE = "constant-acceleration"

Values = tuple[tuple[str, float | None], ...]


def _all_values(kind: str, given: Mapping[str, float | None]) -> Values:
    d = rr.describe(kind)
    for name in given:
        d.parameter(name)  # an unknown name is refused, naming it
    return tuple((p.name, given.get(p.name, p.default)) for p in d.parameters)


@dataclass(frozen=True)
class Settings:
    """Every control's value: a scene, each of its parameters, the frame, the overlay.

    ``values`` always lists every parameter of ``scene`` (defaults filled in), so two
    settings that mean the same scene compare equal. An optional parameter left out is ``None`` there
    (:meth:`chosen`); :meth:`value` gives what it stands for (the barn's ``L0/γ``, which follows V
    until a person sets the barn's length).
    """

    scene: str = DEFAULT_SCENE
    values: Values = ()
    frame: str | None = None
    """A frame preset of the scene, :data:`CUSTOM_FRAME`, or ``None`` for the scene's default frame."""
    beta: float = 0.0
    """The custom frame's velocity."""
    overlay: bool = False
    """Draw the description's comparison scene (Fig. 1's dashed impulsive curve) dashed over the scene."""
    layers: frozenset[Layer] = DEFAULT_LAYERS
    """What the drawings show (:class:`~.layers.Layer`): the light signals are off unless asked for."""
    ride: RidePoint = DEFAULT_RIDE
    """The material point the frame rides while ``frame`` is :data:`RIDE_FRAME` (kept, unused, otherwise)."""
    cone: str | None = None
    """An event of the scene (its name, or the origin event's: ``"contact"``) whose light cone both
    diagrams draw, or ``None``."""
    _by_name: Mapping[str, float | None] = field(init=False, repr=False, compare=False)
    _resolved: Mapping[str, float | None] = field(init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        values = _all_values(self.scene, dict(self.values))
        object.__setattr__(self, "values", values)
        object.__setattr__(self, "_by_name", MappingProxyType(dict(values)))
        object.__setattr__(self, "_resolved", MappingProxyType(rr.describe(self.scene).resolved(dict(values))))

    def __reduce__(self) -> tuple[type[Settings], tuple[object, ...]]:
        """Pickled as its fields (a timeline is recorded in a process of its own)."""
        fields = (self.scene, self.values, self.frame, self.beta, self.overlay, self.layers, self.ride, self.cone)
        return (Settings, fields)

    @classmethod
    def of(cls, scene: str, **values: float | None) -> Settings:
        """The settings of ``scene`` with ``values`` (the rest at their defaults)."""
        return cls(scene, tuple(values.items()))

    @property
    def description(self) -> rr.SceneDescription:
        return rr.describe(self.scene)

    def chosen(self, name: str) -> float | None:
        """The value set for ``name``: ``None`` for an optional parameter left out (the pole's barn
        then follows ``L0/γ``: :attr:`rigidrel_core.Parameter.when_omitted`)."""
        return self._by_name[name]

    def value(self, name: str) -> float | None:
        """The value the scene uses for ``name``, as its control shows it: the one set, or for an
        optional one left out that stands for a value (the barn's ``L0/γ`` at the current V, Bell's
        ship length ``s/10``), that value; ``None`` where omitting means no value."""
        return self._resolved[name]

    def parameters(self) -> dict[str, float | None]:
        """Every parameter's value as :meth:`value` gives it."""
        return dict(self._resolved)

    def with_value(self, name: str, value: float | None) -> Settings:
        """``name`` (a parameter of this scene: KeyError for any other) set to ``value``."""
        if name not in self._by_name:
            raise KeyError(f"{name!r} is not a parameter of {self.scene} (its parameters: {', '.join(self._by_name)})")
        return replace(self, values=tuple((k, value if k == name else v) for k, v in self.values))

    def with_scene(self, kind: str) -> Settings:
        """Another scene: parameters of the same name keep their values, the frame its default."""
        if kind == self.scene:
            return self
        keep = {p.name: self._by_name[p.name] for p in rr.describe(kind).parameters if p.name in self._by_name}
        ride = replace(self.ride, rod=0)  # the same share of the new scene's first rod
        return Settings(kind, tuple(keep.items()), None, self.beta, False, self.layers, ride)  # no event's cone

    def with_layers(self, layers: frozenset[Layer]) -> Settings:
        return replace(self, layers=frozenset(layers))

    def riding(self, rod: int | None = None, fraction: float | None = None) -> Settings:
        """The riding frame, on rod ``rod`` (from 0) at point ``fraction`` of it (each kept if not given)."""
        point = RidePoint(self.ride.rod if rod is None else rod, self.ride.fraction if fraction is None else fraction)
        return replace(self, frame=RIDE_FRAME, ride=point)


@dataclass(frozen=True)
class Resolved:
    """The scene and frame the settings mean, and the overlay scene if one is drawn."""

    scene: rr.Scene
    frame: rr.Frame
    overlay: rr.Scene | None = None
    layers: frozenset[Layer] = DEFAULT_LAYERS
    """The layers the settings ask to be drawn."""
    ride: RidePoint | None = None
    """The material point whose momentarily comoving frame the lower lane rides, or ``None``. While
    riding, ``frame`` is the scene's default frame: the second diagram and the exports are drawn in it."""
    cone: str | None = None
    """The event whose light cone the diagrams draw (checked against the scene), or ``None``."""

    @property
    def lab_only(self) -> bool:
        """Whether the chosen frame is the scene's own lab preset, unridden: its lane and diagram
        would repeat the lab's, so the canvas shows the lab once
        (:func:`~rigidrel_app.view.scene_view.panels`). A custom β of 0 is not: a slider dragged
        through 0 keeps its lane."""
        return self.ride is None and self.frame.name == "lab" and self.frame.same_velocity(rr.LAB)


def event_times(resolved: Resolved) -> tuple[float, ...]:
    """The times of the scene's named events on the playback clock, sorted, each once: their lab
    ``t`` (the lab lane shows t = the clock) and their ``t′`` in the chosen frame (the lower lane
    shows t′ = the clock), each computed by the core in its frame (keys N and P jump to them)."""
    scene = resolved.scene
    times = {t for t, _ in scene.events.values()} | {t for t, _ in scene.events_in(frame=resolved.frame).values()}
    return tuple(sorted(times))


def presets() -> dict[str, Settings]:
    """Every paper figure of every registered scene, by its menu label, in teaching order."""
    return {label: s for kind in rr.scene_descriptions() for label, s in scene_presets(kind).items()}


def scene_presets(kind: str) -> dict[str, Settings]:
    """The paper figures of one scene, by menu label, in the description's order."""
    return {
        p.label: Settings(kind, tuple(p.values.items()), p.frame, 0.0, p.overlay) for p in rr.describe(kind).presets
    }


def preset_of(settings: Settings) -> str:
    """The preset menu's entry for ``settings``: the figure they reproduce, or :data:`NO_PRESET`."""
    for label, s in scene_presets(settings.scene).items():
        if s.values == settings.values and s.overlay == settings.overlay:
            return label
    return NO_PRESET


@dataclass(frozen=True)
class PresetMenu:
    """What the paper-figure menu offers and shows: it follows the scene."""

    options: tuple[str, ...]
    """:data:`NO_PRESET`, then the scene's own figures (only that one entry for a scene without any)."""
    value: str
    """The figure the settings reproduce, or :data:`NO_PRESET`."""


def preset_menu(settings: Settings) -> PresetMenu:
    return PresetMenu((NO_PRESET, *scene_presets(settings.scene)), preset_of(settings))


def preset_step(settings: Settings, step: int) -> Settings | None:
    """The scene's paper figure ``step`` places after (``step`` > 0) or before the one ``settings``
    show (a clicker's next and previous). From no figure, forward is the first and back the last;
    ``None`` beyond either end, or for a scene with no figure (nothing to go to)."""
    figures = list(scene_presets(settings.scene).values())
    if not figures or step == 0:
        return None
    current = preset_of(settings)
    if current == NO_PRESET:
        return figures[0] if step > 0 else figures[-1]
    k = list(scene_presets(settings.scene)).index(current) + step
    return figures[k] if 0 <= k < len(figures) else None


def beta_problem(s: Settings) -> str | None:
    """Why the app cannot show ``s``'s custom frame (its β slider's range), or ``None``: the core, the
    exports and the command line take any |β| < 1, a tab only what the slider holds."""
    lo, hi = CUSTOM_BETA
    if s.frame == CUSTOM_FRAME and not lo <= s.beta <= hi:
        return f"--frame must be in [{lo:g}, {hi:g}] (the app's β slider) or one of the scene's frames; got {s.beta!r}"
    return None


def frame_choices(scene: rr.Scene) -> tuple[str, ...]:
    return (*scene.frames.keys(), CUSTOM_FRAME, RIDE_FRAME)


def frame_choice(scene: rr.Scene, frame: rr.Frame, ride: RidePoint | None = None) -> str:
    """The frame dropdown's entry for ``frame``: its preset name, or the custom (β slider) entry;
    :data:`RIDE_FRAME` while the lane rides a point (``ride``)."""
    if ride is not None:
        return RIDE_FRAME
    if frame.name is not None and frame.name in scene.frames and scene.frames[frame.name] == frame:
        return frame.name
    return CUSTOM_FRAME


def settings_for(scene: rr.Scene, frame: rr.Frame) -> Settings:
    """The settings that show ``scene`` in ``frame`` (the inverse of :func:`resolve`)."""
    choice = frame_choice(scene, frame)
    # every parameter of the description: an optional one the scene was built without stays None
    values = tuple((p.name, scene.parameters.get(p.name)) for p in rr.describe(scene).parameters)
    return Settings(scene.kind, values, choice, frame.beta if choice == CUSTOM_FRAME else 0.0)


def frame_from_text(scene: rr.Scene, text: str | None) -> rr.Frame:
    """The frame a user named in text (command line, lesson): a preset name of the scene, a velocity
    in (-1, 1), or ``None`` for the scene's default frame. A ``ValueError`` names the choices."""
    if text is None:
        return rr.default_frame(scene)
    if text in scene.frames:
        return scene.frames[text]
    try:
        beta = float(text)
    except ValueError:
        names = ", ".join(repr(k) for k in scene.frames)
        raise rr.ParameterError("frame", f"a velocity in (-1, 1) or one of {names}", text) from None
    return rr.Frame.from_velocity(beta, name="custom")


def build(s: Settings) -> Resolved:
    """The scene and frame the settings mean; a ``ValueError`` names the parameter that makes none."""
    scene = s.description.build(**dict(s.values))  # an omitted optional value: the core's own default
    ride: RidePoint | None = None
    if s.frame == CUSTOM_FRAME:
        frame = rr.Frame.from_velocity(s.beta, name="custom")
    elif s.frame is None:
        frame = rr.default_frame(scene)
    elif s.frame == RIDE_FRAME:
        frame, ride = rr.default_frame(scene), check_ride(scene, s.ride)
    else:
        frame = scene.frame(s.frame)
    d = s.description
    overlay = d.overlay.build(scene.parameters) if s.overlay and d.overlay is not None else None
    return Resolved(scene, frame, overlay, s.layers, ride, None if s.cone is None else check_cone(scene, s.cone))


def cone_events(scene: rr.Scene) -> tuple[str, ...]:
    """The events whose light cone can be drawn: the origin event (by its name, ``"contact"``), then
    the scene's named events in the lab's time order."""
    lab = scene.events_in(frame=rr.LAB)
    return (scene.origin_event.value, *sorted(lab, key=lambda name: lab[name][0]))


def check_cone(scene: rr.Scene, name: str) -> str:
    """``name`` if it is one of :func:`cone_events`, else a ``ParameterError`` naming ``cone``."""
    events = cone_events(scene)
    if name not in events:
        raise rr.ParameterError("cone", f"an event of the scene: {', '.join(events)}", name)
    return name


def check_ride(scene: rr.Scene, point: RidePoint) -> RidePoint:
    """``point`` if ``scene`` has it: a rod of the scene (counted from 0 here, from 1 where a person
    types it) and a share of its rest length in [0, 1]; else a ``ParameterError`` naming ``ride``."""
    n = scene.n_rods
    if not 0 <= point.rod < n:
        raise rr.ParameterError("ride", f"a rod of the scene, 1..{n}", point.rod + 1)
    if not 0.0 <= point.fraction <= 1.0:  # also refuses NaN
        raise rr.ParameterError("ride", "a point f in [0, 1] (0 the left end, 1 the right)", point.fraction)
    return point


def resolve(s: Settings) -> Resolved | str:
    """The scene and frame, or a one-sentence notice of why they cannot be built (for the app)."""
    try:
        return build(s)
    except ValueError as exc:
        return notice(s, exc)


def notice(s: Settings, exc: ValueError) -> str:
    """Why ``s`` makes no scene, in the words of the control that holds the offending value."""
    name = getattr(exc, "parameter", "")
    d = s.description
    if name in d.parameter_map:
        p = d.parameter_map[name]
        value = s.value(name)
        shown = "none" if value is None else f"{value:.6g}"
        return f"{p.label} = {shown} refused: {exc}. The last valid scene stays on screen."
    if name == "beta":
        return f"β = {s.beta!r} refused: {exc}. The last valid scene stays on screen."
    if name == "ride":
        return f"Ride point refused: {exc}. The last valid scene stays on screen."
    if name == "cone":
        return f"Light cone refused: {exc}. The last valid scene stays on screen."
    return f"{exc}. The last valid scene stays on screen."


def format_value(value: float | None) -> str:
    """A parameter value as the readouts and command lines show it (``none`` for an omitted one)."""
    if value is None:
        return "none"
    if value == 0.0:
        return "0"
    return f"{value:.6g}" if math.isfinite(value) else str(value)
