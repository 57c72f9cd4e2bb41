"""Scenario strings: one line that names a whole state, the way the command line writes it.

    rod-collision --v1 0.6 --mass2 2 --v2 0 --length2 1 --eps 1 --frame barycentric --t 0.3

The scene's name, then one ``--flag value`` per parameter (the flag is the parameter's name with
``-`` for ``_``; ``none`` omits an optional one), then ``--frame`` (a preset name, quoted if it has
spaces, or a velocity in (-1, 1)), ``--t`` (the time shown, in that frame), ``--overlay``
(the description's comparison curve) and ``--layers`` (the layers drawn, comma-separated, written
only when they are not the default: ``--layers world-tube,light-cone,signals``, or ``all``) and
``--ride ROD:F`` instead of ``--frame`` (the lower lane rides point F, in [0, 1], of rod ROD, from 1;
``--ride F`` rides rod 1), and ``--cone EVENT`` (the diagrams draw that event's light cone: ``T_1``,
or the origin event's name, ``contact``). ``rigidrel
serve``, lesson files and the app's scenario box all read this syntax, and the app shows the
current state in it, so a state can be copied from a student's screen into a lesson. Everything
is generated from the scene registry.
"""

from __future__ import annotations

import math
import shlex
from dataclasses import dataclass

import rigidrel_core as rr

from .comoving import RidePoint
from .layers import DEFAULT_LAYERS, Layer
from .state import CUSTOM_FRAME, RIDE_FRAME, Settings, build, format_value


class ScenarioError(ValueError):
    """A scenario string that names no state; ``parameter`` is the flag at fault (without ``--``)."""

    def __init__(self, parameter: str, message: str) -> None:
        super().__init__(message)
        self.parameter = parameter


@dataclass(frozen=True)
class Scenario:
    """A state: the controls' settings and, optionally, the time shown (in the chosen frame)."""

    settings: Settings
    t: float | None = None


def flag(parameter: rr.Parameter) -> str:
    """``a_front`` -> ``--a-front``."""
    return "--" + parameter.name.replace("_", "-")


def _quote(text: str) -> str:
    return shlex.quote(text)


def format_scenario(settings: Settings, t: float | None = None) -> str:
    """The line that names ``settings`` (and the time ``t``): every parameter the app has a control
    for, any other one that is not at its default, the frame, the overlay and the time."""
    d = settings.description
    parts = [settings.scene]
    for p in d.parameters:
        value = settings.value(p.name)
        if p.slider is not None or value != p.default:
            parts += [flag(p), format_value(value)]
    if settings.frame == CUSTOM_FRAME:
        parts += ["--frame", format_value(settings.beta)]
    elif settings.frame == RIDE_FRAME:
        parts += ["--ride", f"{settings.ride.rod + 1}:{format_value(settings.ride.fraction)}"]
    elif settings.frame is not None:
        parts += ["--frame", _quote(settings.frame)]
    if settings.overlay:
        parts.append("--overlay")
    if settings.cone is not None:
        parts += ["--cone", _quote(settings.cone)]
    if settings.layers != DEFAULT_LAYERS:
        shown = ",".join(layer.value for layer in Layer if layer in settings.layers)
        parts += ["--layers", "all" if settings.layers == frozenset(Layer) else shown or "none"]
    if t is not None:
        parts += ["--t", format_value(t)]
    return " ".join(parts)


def _number(name: str, text: str, allowed: str) -> float:
    try:
        value = float(text)
    except ValueError:
        raise ScenarioError(name, f"--{name} needs {allowed}; got {text!r}") from None
    if not math.isfinite(value):
        raise ScenarioError(name, f"--{name} needs {allowed}; got {text!r}")
    return value


#: What ``--ride`` takes, in the words of its errors.
RIDE_ALLOWED = "ROD:F, a rod (from 1) and a point F in [0, 1] of it (0 its left end, 1 its right), or F alone for rod 1"


def ride_from_text(text: str) -> RidePoint:
    """``2:0.5`` -> rod 2 (index 1) at its middle; ``1`` -> rod 1's right end. The rod's range is
    checked against the scene when the scenario is built."""
    rod_text, _, f_text = text.rpartition(":")
    rod = 1
    if rod_text:
        try:
            rod = int(rod_text)
        except ValueError:
            raise ScenarioError("ride", f"--ride needs {RIDE_ALLOWED}; got {text!r}") from None
    fraction = _number("ride", f_text, RIDE_ALLOWED)
    if not 0.0 <= fraction <= 1.0:
        raise ScenarioError("ride", f"--ride needs {RIDE_ALLOWED}; got {text!r}")
    return RidePoint(rod - 1, fraction)


def _layers(text: str) -> frozenset[Layer]:
    """``world-tube,signals`` -> those layers; ``all`` -> every layer; ``none`` -> no layer."""
    if text.strip().lower() == "none":
        return frozenset()
    if text.strip().lower() == "all":
        return frozenset(Layer)
    names = [n.strip() for n in text.split(",")]
    known = {layer.value: layer for layer in Layer}
    for n in names:
        if n not in known:
            raise ScenarioError(
                "layers", f"{n!r} is not a layer; --layers takes a comma-separated list of {', '.join(known)} (or none)"
            )
    return frozenset(known[n] for n in names)


def parse_scenario(text: str) -> Scenario:
    """The state a scenario string names. A :class:`ScenarioError` names the flag at fault and what
    it allows; the values are checked by building the scene, so the line always names a scene."""
    try:
        tokens = shlex.split(text)
    except ValueError as exc:
        raise ScenarioError("scene", f"cannot read the line ({exc})") from None
    kinds = rr.scene_descriptions()
    if not tokens:
        raise ScenarioError("scene", f"an empty line; start with a scene: {', '.join(kinds)}")
    kind, rest = tokens[0], tokens[1:]
    if kind not in kinds:
        raise ScenarioError("scene", f"{kind!r} is not a scene; the scenes are {', '.join(kinds)}")
    d = kinds[kind]
    by_flag = {flag(p): p for p in d.parameters}
    values: dict[str, float | None] = {}
    frame: str | None = None
    beta = 0.0
    overlay = False
    layers = DEFAULT_LAYERS
    t: float | None = None
    ride: RidePoint | None = None
    cone: str | None = None
    i = 0
    while i < len(rest):
        name = rest[i]
        if name == "--overlay":
            overlay, i = True, i + 1
            continue
        if name not in (*by_flag, "--frame", "--t", "--layers", "--ride", "--cone"):
            old = name.removeprefix("--").replace("-", "_")
            if name.startswith("--") and old in d.renamed:  # a line written before the parameter was renamed
                new = "--" + d.renamed[old].replace("_", "-")
                raise ScenarioError(old.replace("_", "-"), f"{name} is now {new} (the parameter was renamed)")
            options = ", ".join((*by_flag, "--frame", "--t", "--overlay", "--layers", "--ride", "--cone"))
            raise ScenarioError("scene", f"{name!r} is not an option of {kind}; its options are {options}")
        if i + 1 >= len(rest):
            raise ScenarioError(name.lstrip("-"), f"{name} needs a value")
        value = rest[i + 1]
        i += 2
        if name == "--frame":
            if value in d.frames:
                frame = value
            else:
                allowed = f"a velocity in (-1, 1) or one of {', '.join(repr(f) for f in d.frames)}"
                beta = _number("frame", value, allowed)
                if not -1.0 < beta < 1.0:
                    raise ScenarioError("frame", f"--frame needs {allowed}; got {value!r}")
                frame = CUSTOM_FRAME
        elif name == "--t":
            t = _number("t", value, "a time (a finite number)")
        elif name == "--layers":
            layers = _layers(value)
        elif name == "--ride":
            ride = ride_from_text(value)
        elif name == "--cone":
            cone = value
        else:
            p = by_flag[name]
            if p.optional and value.strip().lower() == "none":
                values[p.name] = None
            else:
                values[p.name] = _number(p.name.replace("_", "-"), value, p.allowed())
    if ride is not None and frame is not None:
        raise ScenarioError("ride", "--ride is a frame of its own (the lane rides the point): give --ride or --frame")
    settings = Settings(kind, tuple(values.items()), frame, beta, overlay, layers, cone=cone)
    if ride is not None:
        settings = settings.riding(ride.rod, ride.fraction)
    try:
        build(settings)
    except ValueError as exc:
        parameter = getattr(exc, "parameter", "scene")
        raise ScenarioError(str(parameter).replace("_", "-"), str(exc)) from None
    return Scenario(settings, t)
