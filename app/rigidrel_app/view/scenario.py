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

The grammar is written once, here, as argparse options (:func:`add_scene_options`,
:func:`add_scenario_options`): the command line adds them to its scene sub-commands, and
:func:`parse_scenario` reads a line with the same options, its errors raised as
:class:`ScenarioError` instead of ending the program.
"""

from __future__ import annotations

import argparse
import math
import shlex
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from types import MappingProxyType
from typing import Any, NoReturn

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
        value = settings.chosen(p.name)  # "none" for an omitted one: it keeps following the others
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


#: What an optional parameter takes to be omitted (``--a-front none``: the impulsive limit).
OMITTED = ("none", "impulse", "impulsive")


def parameter_value(parameter: rr.Parameter) -> Callable[[str], float | None]:
    """The text after ``--name`` as the number it names (or None, ``none``, for an optional
    parameter); its range is the core's to check when the scene is built."""

    def value(text: str) -> float | None:
        if parameter.optional and text.strip().lower() in OMITTED:
            return None
        try:
            return float(text)
        except ValueError:
            # what 'none' gives, each optional parameter's help says (a default worked out from the
            # others, the impulsive limit, a string that never breaks): never a value left out
            takes = parameter.allowed() + (
                ", or 'none' (its --help says what that gives)" if parameter.optional else ""
            )
            raise argparse.ArgumentTypeError(f"not a number: {text!r}; {flag(parameter)} takes {takes}") from None

    value.__name__ = parameter.name
    return value


def _finite(what: str) -> Callable[[str], float]:
    def value(text: str) -> float:
        try:
            number = float(text)
        except ValueError:
            number = math.nan
        if not math.isfinite(number):
            raise argparse.ArgumentTypeError(f"needs {what}; got {text!r}")
        return number

    return value


#: What ``--ride`` takes, in the words of its errors.
RIDE_ALLOWED = "ROD:F, a rod (from 1) and a point F in [0, 1] of it (0 its left end, 1 its right), or F alone for rod 1"


def ride_from_text(text: str) -> RidePoint:
    """``2:0.5`` -> rod 2 (index 1) at its middle; ``1`` -> rod 1's right end. The rod's range is
    checked against the scene when the scenario is built."""
    rod_text, _, f_text = text.rpartition(":")
    problem = ScenarioError("ride", f"--ride needs {RIDE_ALLOWED}; got {text!r}")
    rod = 1
    if rod_text:
        try:
            rod = int(rod_text)
        except ValueError:
            raise problem from None
    try:
        fraction = float(f_text)
    except ValueError:
        raise problem from None
    if not 0.0 <= fraction <= 1.0:
        raise problem
    return RidePoint(rod - 1, fraction)


def _ride(text: str) -> RidePoint:
    try:
        return ride_from_text(text)
    except ScenarioError as exc:
        raise argparse.ArgumentTypeError(str(exc)) from None


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
            raise argparse.ArgumentTypeError(
                f"{n!r} is not a layer; --layers takes a comma-separated list of {', '.join(known)} (or none, all)"
            )
    return frozenset(known[n] for n in names)


class _Renamed(argparse.Action):
    """The option of a renamed parameter: refused, naming the new option."""

    def __init__(self, option_strings: list[str], dest: str, new: str, **kwargs: Any) -> None:
        super().__init__(option_strings, dest, nargs=1, default=argparse.SUPPRESS, **kwargs)
        self.new = "--" + new.replace("_", "-")

    def __call__(self, parser: argparse.ArgumentParser, namespace: argparse.Namespace, *_: object) -> None:
        old = self.option_strings[0]
        raise argparse.ArgumentError(self, f"{old} is now {self.new} (the parameter was renamed)")


FRAME_HELP = "frame velocity beta in (-1, 1), or a preset's name (quoted if it has spaces)"
#: Frame presets whose name a student may not know, with what they are.
FRAME_GLOSSES: Mapping[str, str] = MappingProxyType({"barycentric": "zero total momentum"})


def add_scene_options(parser: argparse.ArgumentParser, description: rr.SceneDescription, frame_help: str) -> None:
    """The scene's own options: one ``--name VALUE`` per parameter (its range and default in the
    help; left out of the namespace when not given), and ``--frame``."""
    for p in description.parameters:
        unit = f" [{p.unit}]" if p.unit else ""
        parser.add_argument(
            flag(p),
            dest=p.name,
            type=parameter_value(p),
            default=argparse.SUPPRESS,
            metavar=p.symbol.replace("′", "'"),
            help=f"{description.help_for(p)}{unit}; allowed: {p.allowed()}; default {format_value(p.default)}"
            + ("; or 'none', which gives what the text above says" if p.optional else ""),
        )
    for old, new in description.renamed.items():  # a line written before a parameter was renamed
        parser.add_argument("--" + old.replace("_", "-"), action=_Renamed, new=new, help=argparse.SUPPRESS)
    presets = ", ".join(f"{f} ({FRAME_GLOSSES[f]})" if f in FRAME_GLOSSES else f for f in description.frames)
    parser.add_argument("--frame", default=None, help=f"{frame_help}; presets: {presets}")


def add_scenario_options(parser: argparse.ArgumentParser) -> None:
    """What a scenario names besides the scene: the time shown, the overlay, the layers, a riding
    point and a light cone."""
    parser.add_argument(
        "--t", type=_finite("a time (a finite number)"), default=None, help="the time shown, in the frame"
    )
    parser.add_argument("--overlay", action="store_true", help="draw the description's comparison curve")
    parser.add_argument(
        "--layers",
        type=_layers,
        default=DEFAULT_LAYERS,
        help=f"the layers drawn, comma-separated ({', '.join(layer.value for layer in Layer)}), or all, or none",
    )
    parser.add_argument(
        "--ride",
        type=_ride,
        default=None,
        metavar="ROD:F",
        help="the lower lane rides point F in [0, 1] (0 the left end, 1 the right) of rod ROD (from 1; "
        "F alone: rod 1), instead of a --frame",
    )
    parser.add_argument("--cone", default=None, metavar="EVENT", help="the diagrams draw this event's light cone")


def scenario_from_args(kind: str, args: argparse.Namespace) -> Scenario:
    """The state the parsed options of scene ``kind`` name (the options of :func:`add_scene_options`
    and :func:`add_scenario_options`), checked by building it: a :class:`ScenarioError` names the
    flag at fault."""
    d = rr.describe(kind)
    values = {p.name: getattr(args, p.name) for p in d.parameters if hasattr(args, p.name)}
    frame, beta = args.frame, 0.0
    if frame is not None and frame not in d.frames:
        allowed = f"a velocity in (-1, 1) or one of {', '.join(repr(f) for f in d.frames)}"
        try:
            beta = float(frame)
        except ValueError:
            beta = math.nan
        if not -1.0 < beta < 1.0:
            raise ScenarioError("frame", str(rr.ParameterError("frame", allowed, frame)))
        frame = CUSTOM_FRAME
    ride: RidePoint | None = getattr(args, "ride", None)
    if ride is not None and frame is not None:
        raise ScenarioError("ride", "--ride is a frame of its own (the lane rides the point): give --ride or --frame")
    layers = getattr(args, "layers", DEFAULT_LAYERS)
    overlay, cone = getattr(args, "overlay", False), getattr(args, "cone", None)
    settings = Settings(kind, tuple(values.items()), frame, beta, overlay, layers, cone=cone)
    if ride is not None:
        settings = settings.riding(ride.rod, ride.fraction)
    try:
        build(settings)
    except ValueError as exc:
        parameter = getattr(exc, "parameter", "scene")
        raise ScenarioError(str(parameter).replace("_", "-"), str(exc)) from None
    return Scenario(settings, getattr(args, "t", None))


class _LineParser(argparse.ArgumentParser):
    """argparse over one scenario line: its errors are :class:`ScenarioError` s, never an exit."""

    def __init__(self, kind: str) -> None:
        super().__init__(prog=kind, add_help=False, allow_abbrev=False, exit_on_error=False)

    def error(self, message: str) -> NoReturn:
        raise ScenarioError("scene", message)


def _line_parser(kind: str) -> _LineParser:
    parser = _LineParser(kind)
    add_scene_options(parser, rr.describe(kind), FRAME_HELP)
    add_scenario_options(parser)
    return parser


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
    parser = _line_parser(kind)
    try:
        args, extra = parser.parse_known_args(rest)
    except argparse.ArgumentError as exc:
        name = exc.argument_name or "--scene"
        needs = "needs a value" if exc.message.startswith("expected one argument") else exc.message
        text = needs if needs.startswith(name) else f"{name} {needs}"
        raise ScenarioError(name.split("/")[0].lstrip("-"), text) from None
    if extra:
        options = ", ".join(o for a in parser._actions for o in a.option_strings)  # pyright: ignore[reportPrivateUsage]
        raise ScenarioError("scene", f"{extra[0]!r} is not an option of {kind}; its options are {options}")
    return scenario_from_args(kind, args)
