"""The ``rigidrel`` command: events tables for slides, the app server, exports, figures, benchmarks.

The scene options are generated from the core's scene registry: ``rigidrel events SCENE``
has one ``--name VALUE`` option per parameter of that scene, with its range and default
in ``--help``. Every bad argument ends in one line on stderr and exit status 2.
"""

from __future__ import annotations

import argparse
import importlib
import json
import math
import sys
import textwrap
import time
from collections.abc import Sequence
from pathlib import Path
from typing import Any, NoReturn

import numpy as np

import rigidrel_core as rr

from .export.paths import EXIT_USAGE, fail, out_dir
from .view.describe import describe
from .view.scenario import (
    FRAME_GLOSSES,
    FRAME_HELP,
    Scenario,
    ScenarioError,
    add_scenario_options,
    add_scene_options,
    flag,
    scenario_from_args,
)
from .view.signals import signals_in, verdict_lines
from .view.state import Resolved, beta_problem, format_value, frame_from_text
from .view.vocabulary import SHADES, Shade

__all__ = ["EXIT_USAGE", "build_parser", "main"]


class OneLineParser(argparse.ArgumentParser):
    """argparse, but a usage error is one line on stderr and exit status 2, and an option is never
    guessed from a prefix (``--v`` is not ``--v1``)."""

    def __init__(self, *args: Any, **kwargs: Any) -> None:
        kwargs.setdefault("allow_abbrev", False)
        super().__init__(*args, **kwargs)

    def error(self, message: str) -> NoReturn:
        sys.stderr.write(f"{self.prog}: error: {message}\n")
        raise SystemExit(EXIT_USAGE)


class SceneParser(OneLineParser):
    """The options of one scene (its ``scene_kind``)."""

    scene_kind = ""


def _number(text: str) -> float:
    try:
        return float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"not a number: {text!r}") from None


def add_scene_subparsers(
    parser: argparse.ArgumentParser,
    common: list[SceneParser],
    frame_help: str,
    required: bool = True,
    scenario: bool = False,
) -> None:
    """One sub-command per registered scene, with the scenario grammar's options (defaults: the
    paper's): the scene's parameters and ``--frame``, and with ``scenario`` the rest of a scenario
    line (``--t``, ``--overlay``, ``--layers``, ``--ride``, ``--cone``)."""
    sub = parser.add_subparsers(dest="scene", metavar="SCENE", required=required, parser_class=SceneParser)
    for kind, d in rr.scene_descriptions().items():
        sp = sub.add_parser(kind, help=d.summary, description=f"{d.title} ({d.source}). {d.summary}", parents=common)
        assert isinstance(sp, SceneParser)  # parser_class above
        sp.scene_kind = kind
        add_scene_options(sp, d, frame_help)
        if scenario:
            add_scenario_options(sp)


def scene_values(args: argparse.Namespace) -> dict[str, float | None]:
    d = rr.describe(args.scene)
    return {p.name: getattr(args, p.name) for p in d.parameters if hasattr(args, p.name)}


def scene_from_args(prog: str, args: argparse.Namespace, default_frame: str | None) -> tuple[rr.Scene, rr.Frame]:
    """The scene and frame the arguments name (``--frame`` omitted: ``default_frame``, None for the
    scene's default frame); a bad value is one line and exit status 2."""
    try:
        scene = rr.build_scene(args.scene, **scene_values(args))
        frame = frame_from_text(scene, args.frame if args.frame is not None else default_frame)
    except ValueError as exc:
        fail(prog, str(exc))
    return scene, frame


# ---------------------------------------------------------------- events
def object_events(scene: rr.Scene, frame: rr.Frame) -> dict[str, tuple[tuple[float, float], str]]:
    """The events of the scene's objects (the door closes, the string breaks) as ``(t', x')`` of
    ``frame``, each with its meaning."""
    out: dict[str, tuple[tuple[float, float], str]] = {}
    for obj in scene.objects:
        event = obj.event_in(frame=frame)
        if obj.event is not None and event is not None:
            out[obj.event.name] = (event, obj.event.meaning or f"an event of the {obj.name}")
    return out


def change_rows(scene: rr.Scene, frame: rr.Frame) -> list[tuple[str, tuple[float, float]]]:
    """Every event a causal verdict names, as rows ``(what, (t', x'))`` of ``frame``: each changing end's
    start, stop and first light from the key event (the verdicts' words give the same numbers)."""
    rows: list[tuple[str, tuple[float, float]]] = []
    for v in scene.causal_verdicts(frame=frame):
        end = v.end_label.removeprefix("the ")
        start, stop = (f" ({name})" if name else "" for name in v.names)
        rows += [(f"{end}: starts{start}", v.start), (f"{end}: ends{stop}", v.stop)]
        if v.arrival is not None:
            rows.append((f"{end}: first light", v.arrival))
    return rows


def events_report(scene: rr.Scene, frame: rr.Frame) -> dict[str, object]:
    """Everything ``rigidrel events`` prints, as plain data (every event in ``frame``, and the named
    ones in the lab too)."""
    budget = scene.budget(frame=frame)
    return {
        "scene": scene.kind,
        "parameters": dict(scene.parameters),
        "frame": {"name": frame.label(), "velocity": frame.beta},
        "events": {k: {"t": t, "x": x} for k, (t, x) in scene.events_in(frame=frame).items()},
        "object_events": {k: {"t": t, "x": x} for k, ((t, x), _) in object_events(scene, frame).items()},
        "events_lab": {k: {"t": t, "x": x} for k, (t, x) in scene.events.items()},
        "initial_velocities": list(scene.initial_velocities),
        "final_velocities": list(scene.final_velocities),
        "frame_presets": {k: f.beta for k, f in scene.frames.items()},
        "budget": budget.as_dict(),
        "notes": list(scene.notes(frame=frame)),
        "signals": [
            {
                "arrival": leg.name,
                "t": leg.arrival[0],
                "x": leg.arrival[1],
                "meaning": leg.meaning,
                "from": {"t": leg.source[0], "x": leg.source[1]},
            }
            for leg in signals_in(scene, frame).legs
        ],
        "changes": [{"event": what, "t": t, "x": x} for what, (t, x) in change_rows(scene, frame)],
        "verdicts": list(verdict_lines(scene, frame)),
    }


def _g(x: float, scale: float | None = None) -> str:
    """``x`` to 10 significant digits; with ``scale``, the size of the terms it was formed from, ``0``
    where it is rounding noise of them (:func:`rigidrel_core.shown`)."""
    if scale is not None:
        x = rr.shown(x, scale)
    return f"{x:.10g}" if x != 0 else "0"


def _cells(event: tuple[float, float], frame: rr.Frame) -> str:
    """An event of ``frame`` as the t and x columns of a table, the boost's rounding noise shown as 0."""
    t, x = rr.event_shown(event, frame)
    return f"{_g(t):>20}{_g(x):>20}"


def format_events(scene: rr.Scene, frame: rr.Frame) -> str:
    """The text of ``rigidrel events``: every table in ``frame`` (the rods' velocities excepted, which
    are the lab's and say so), every coordinate in words labelled with its frame."""
    d = rr.describe(scene)
    lines = [
        f"scene      {scene.kind}   ({d.title}, {d.source}; c = 1)",
        "parameters " + "  ".join(f"{k}={_g(v)}" for k, v in scene.parameters.items()),
        f"frame      {frame.label()}  (β = {_g(frame.beta)}): every table below is in this frame, unless it says lab",
        "",
        f"{'event':<12}{'t':>20}{'x':>20}   meaning",
    ]
    for name, event in scene.events_in(frame=frame).items():
        lines.append(f"{name:<12}{_cells(event, frame)}   {d.event(name).meaning}")
    for name, (event, meaning) in object_events(scene, frame).items():
        lines.append(f"{name:<12}{_cells(event, frame)}   {meaning}")
    width = max(len(r.name) for r in scene.rods) + 2
    lines += ["", f"{'body':<{width}}{'V before (lab)':>20}{'V after (lab)':>20}"]
    for rod, v0, v1 in zip(scene.rods, scene.initial_velocities, scene.final_velocities, strict=True):
        lines.append(f"{rod.name:<{width}}{_g(v0):>20}{_g(v1):>20}")
    presets = "  ".join(f"{k}: {_g(f.beta)}" for k, f in scene.frames.items())
    lines += ["", f"frame presets  {presets}", ""]
    lines += budget_lines(scene, frame)
    return "\n".join(lines + signal_lines(scene, frame) + note_lines(scene, frame))


def budget_lines(scene: rr.Scene, frame: rr.Frame) -> list[str]:
    """The 4-momentum budget in ``frame``: each physical system (rods that exist together) on its own,
    labelled, with its totals; the rods of different systems (alternatives, a comparison) never summed."""
    budget = scene.budget(frame=frame)
    several = len(budget.systems) > 1
    head = "4-momentum in this frame (E, p)"
    if several:  # the title on its own line, the columns' heads below it
        lines = [f"{head}: one block per physical system (alternatives, never summed)"]
        lines.append(f"{'':<44}{'M':>12}{'E':>16}{'p':>16}")
    else:
        lines = [f"{head:<44}{'M':>12}{'E':>16}{'p':>16}"]
    for system in budget.systems:
        indent = "    " if several else "  "
        if several:
            lines.append(f"  system: {system.name}")
        for phase, masses, em in (
            ("before", budget.rest_mass_before, budget.before),
            ("after", budget.rest_mass_after, budget.after),
        ):
            for i in system.system.rods:
                name, m, (e, p) = budget.bodies[i], masses[i], em[i]
                lines.append(f"{indent}{name + ' ' + phase:<{44 - len(indent)}}{_g(m):>12} {_g(e):>15} {_g(p):>15}")
        # the totals, and what came from outside, are sums: noise of their terms' size is shown as 0
        rods = list(system.system.rods)
        size_before, size_after = np.abs(budget.before[rods]).sum(axis=0), np.abs(budget.after[rods]).sum(axis=0)
        rows = [("total before", system.total_before, size_before), ("total after", system.total_after, size_after)]
        if system.external_source != "none":
            src = {"drive": "from the drive", "wall": "from the wall (negative: into the wall)"}[system.external_source]
            rows.append((src, system.external, size_before + size_after))
        for label, (e, p), (size_e, size_p) in rows:
            lines.append(f"{indent}{label:<{44 - len(indent)}}{'':>12} {_g(e, size_e):>15} {_g(p, size_p):>15}")
        where = f", {system.heat_where}" if system.heat_where else ""
        lines.append(f"{indent}heat (rest energy created): {_g(system.heat)}{where}")
        # a barrier the system pushes on (not a drive): its velocity in this frame
        wall = _wall_speed(scene, frame) if system.external_source not in ("none", "drive") else 0.0
        if wall != 0.0:  # a moving wall does work: say so, or its row reads as energy from nowhere
            bodies = " and ".join(_the(budget.bodies[i]) for i in rods)
            text = (
                f"(the wall moves at {_g(wall)} in this frame: the row 'from the wall' is what it gives "
                f"{bodies}, so its E is the work the wall does on {bodies} (negative: work done on the wall)"
            )
            if system.heat != 0.0:
                if system.heat_where.startswith("all in the wall"):
                    owner = "the wall's"
                else:
                    owner = f"{bodies}'s" if len(rods) == 1 else "the rods'"
                heat = _g(system.heat)
                text += f"; the heat, {heat}, the same in every frame, is still the growth of {owner} rest energy"
            lines += textwrap.wrap(
                text + ")", 100, initial_indent=indent, subsequent_indent=indent + " ", break_on_hyphens=False
            )
    return lines


def _the(name: str) -> str:
    return name if name.startswith("rod ") else f"the {name}"


def _wall_speed(scene: rr.Scene, frame: rr.Frame) -> float:
    """The velocity of the scene's wall (its first barrier) in ``frame``, 0 where it is at rest there."""
    for obj in scene.objects:
        if obj.kind.role is rr.ObjectRole.BARRIER:
            line = obj.worldlines[0]
            if isinstance(line, rr.InertialWorldline):
                v, b = line.velocity.value, frame.beta
                return rr.shown((v - b) / (1.0 - v * b), 1.0)
    return 0.0


def note_lines(scene: rr.Scene, frame: rr.Frame) -> list[str]:
    """The scene's notes (a paradox's verdicts), last; each coordinate pair in them labelled with its frame."""
    notes = scene.notes(frame=frame)
    if not notes:
        return []
    out = [""]
    for n in notes:
        out += textwrap.wrap(n, 100, initial_indent="note  ", subsequent_indent="        ")
    return out


def signal_lines(scene: rr.Scene, frame: rr.Frame) -> list[str]:
    """The light-signal table (from the key event to each far end, S, and back to the near end, R),
    the events the causal verdicts name and the verdicts themselves, wrapped for a terminal; every
    table in ``frame``, every coordinate pair in the words labelled with its frame."""
    signals = signals_in(scene, frame)
    lines = ["", f"light from {signals.key_phrase}: S reaches a far end, R is the echo back at its near end"]
    lines += textwrap.wrap(f"({signals.key_definition})", 100, subsequent_indent=" ")
    lines.append(f"{'arrival':<12}{'t':>20}{'x':>20}   meaning")
    for leg in signals.legs:
        lines.append(f"{leg.name:<12}{_cells(leg.arrival, frame)}   {leg.meaning}")
    rows = change_rows(scene, frame)
    lines += [
        "",
        "causality: whether a signal could have caused each change is the same in every frame; the events",
        "are given in this frame",
    ]
    if rows:
        width = max(len(what) for what, _ in rows) + 2
        lines.append(f"{'change':<{width}}{'t':>20}{'x':>20}")
        for what, event in rows:
            lines.append(f"{what:<{width}}{_cells(event, frame)}")
    for verdict in verdict_lines(scene, frame):
        lines += textwrap.wrap(verdict, 100, initial_indent="  ", subsequent_indent="    ")
    return lines


def cmd_events(args: argparse.Namespace) -> int:
    scene, frame = scene_from_args("rigidrel events", args, "lab")
    if args.json:
        print(json.dumps(events_report(scene, frame), indent=2, allow_nan=False))
    else:
        print(format_events(scene, frame))
    return 0


def cmd_describe(args: argparse.Namespace) -> int:
    """The canvas of ``rigidrel serve SCENE ...`` at clock time ``--at``, in the words a tab's
    screen reader hears (:func:`~rigidrel_app.view.describe.describe`)."""
    scene, frame = scene_from_args("rigidrel describe", args, None)
    if not math.isfinite(args.at):
        fail("rigidrel describe", f"--at must be a finite time (c = 1, units of rod 1's rest length); got {args.at!r}")
    print(describe(Resolved(scene, frame), args.at).full)
    return 0


def cmd_scenes(args: argparse.Namespace) -> int:
    """Every registered scene, its parameters with their ranges, its frames and events."""
    del args
    descriptions = rr.scene_descriptions().values()
    width = max(len(flag(p)) for d in descriptions for p in d.parameters) + 2  # a flag never runs into its symbol
    for kind, d in rr.scene_descriptions().items():
        print(f"{kind}  ({d.title}; {d.source})\n  {d.summary}")
        for p in d.parameters:
            print(f"  {flag(p):<{width}}{p.symbol:<6}{p.allowed():<52} default {format_value(p.default)}")
        frames = ", ".join(f"{f} ({FRAME_GLOSSES[f]})" if f in FRAME_GLOSSES else f for f in d.frames)
        print(f"  frames: {frames}")
        print(f"  default frame: `serve` and `export` open in {d.default_frame}; `events` shows the lab unless --frame")
        print(f"  events: {', '.join(f'{e.name} ({e.meaning})' for e in d.events)}\n")
    return 0


# ---------------------------------------------------------------- main
def _positive(text: str) -> float:
    value = _number(text)
    if not (value > 0 and value < 1e4):
        raise argparse.ArgumentTypeError(f"must be in (0, 1e4); got {text}")
    return value


def _port(text: str) -> int:
    try:
        port = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"not a port number: {text!r}") from None
    if not 0 <= port <= 65535:
        raise argparse.ArgumentTypeError(f"port must be in [0, 65535]; got {port}")
    return port


def build_parser() -> OneLineParser:
    parser = OneLineParser(prog="rigidrel", description="Born-rigid rods in special relativity (Franklin 2012).")
    sub = parser.add_subparsers(dest="command", required=True, parser_class=OneLineParser)
    frame_help = FRAME_HELP

    ev_common = SceneParser(add_help=False)
    ev_common.add_argument("--json", action="store_true", help="machine-readable output")
    ev = sub.add_parser("events", help="events, final velocities and 4-momentum budget of a scene")
    add_scene_subparsers(ev, [ev_common], frame_help + " (default: the lab)")
    ev.set_defaults(func=cmd_events)

    ds_common = SceneParser(add_help=False)
    ds_common.add_argument(
        "--at", type=float, default=0.0, metavar="T",
        help="the playback clock: the lab lane's t and the lower lane's t' (default 0, the origin event)",
    )  # fmt: skip
    ds = sub.add_parser("describe", help="what the canvas shows at one instant, in words (as a screen reader hears it)")
    add_scene_subparsers(ds, [ds_common], frame_help + " (default: the scene's default frame, as the app opens)")
    ds.set_defaults(func=cmd_describe)

    sc = sub.add_parser("scenes", help="list every scene with its parameters, ranges, frames and events")
    sc.set_defaults(func=cmd_scenes)

    def server_options(defaults: bool) -> SceneParser:
        # the scene's sub-command repeats them without defaults, so that "serve --port P SCENE" keeps P
        common = SceneParser(add_help=False)
        host = "127.0.0.1" if defaults else argparse.SUPPRESS
        port = 8080 if defaults else argparse.SUPPRESS
        common.add_argument("--host", default=host, help="interface to bind (default 127.0.0.1: this machine only)")
        common.add_argument("--port", type=_port, default=port, help="port to try first; the next free one if busy")
        common.add_argument(
            "--theme",
            choices=SHADES,
            default="light" if defaults else argparse.SUPPRESS,
            help="the theme every tab opens in: light, or dark for a projector (key T switches a tab)",
        )
        common.add_argument(
            "--no-still-image",
            dest="still_image",
            action="store_false",
            default=True if defaults else argparse.SUPPRESS,
            help="never send a slow canvas its still picture as one image while it plays",
        )
        return common

    sv = sub.add_parser(
        "serve",
        help="start the app: open the printed URL in a browser",
        parents=[server_options(True)],
        description="Start the app. With a SCENE and its options, every new tab opens on that state.",
    )
    sv.add_argument("--lesson", help="give a lesson: a lesson file (TOML) or a built-in lesson's name (paper)")
    sv.add_argument(
        "--follow",
        action="store_true",
        help="with --lesson: every tab follows the lecturer's step (whose tab opens the printed lead address)",
    )
    add_scene_subparsers(
        sv,
        [server_options(False)],
        frame_help + " (default: the scene's default frame)",
        required=False,
        scenario=True,  # a scenario line, as the app's Scenario folder writes it
    )
    sv.set_defaults(func=cmd_serve)

    ex_common = SceneParser(add_help=False)
    ex_common.add_argument("--out", required=True, help="folder to write into (created if missing)")
    ex_common.add_argument("--seconds", type=_positive, default=10.0, help="length of the animations (default 10 s)")
    ex_common.add_argument("--fps", type=_positive, default=30.0, help="frames per second of the 3-D HTML and MP4")
    ex_common.add_argument("--gif-fps", type=_positive, default=15.0, help="frames per second of the GIF")
    theme_help = "light, or dark for a projector (light on black, every colour's lightness flipped)"
    ex_common.add_argument("--theme", choices=SHADES, default=argparse.SUPPRESS, help=theme_help)
    ex = sub.add_parser(
        "export",
        help="offline HTML (3-D and diagram), PNG, SVG, GIF and MP4 of a scene, or a lesson as a page set",
        description="Export a scene (every lecture format) or, with --lesson, a lesson as a folder of pages.",
    )
    ex.add_argument("--lesson", help="a lesson file (TOML) or a built-in lesson's name (paper)")
    ex.add_argument("--out", dest="lesson_out", help="with --lesson: folder to write into")
    ex.add_argument("--theme", choices=SHADES, default="light", help=theme_help)
    add_scene_subparsers(ex, [ex_common], frame_help + " (default: the scene's default frame)", required=False)
    ex.set_defaults(func=cmd_export)

    fg = sub.add_parser(
        "figures", help="regenerate the paper's Figs. 1-4 and the two paradoxes' figures as SVG and PNG"
    )
    fg.add_argument("--out", required=True, help="folder to write into (created if missing)")
    fg.set_defaults(func=cmd_figures)
    bn = sub.add_parser("bench", help="speed against accuracy of every method, charted (needs rigidrel[bench])")
    bn.add_argument("--quick", action="store_true", help="a reduced run that finishes in under a minute")
    bn.add_argument("--out", required=True, help="folder for the JSON table, charts and stability maps")
    bn.set_defaults(func=cmd_bench)
    return parser


def cmd_export(args: argparse.Namespace) -> int:
    from .export.bundle import export_scene

    prog = "rigidrel export"
    if args.lesson is not None:
        if getattr(args, "scene", None) is not None:
            fail(prog, "give a SCENE or --lesson, not both")
        return export_lesson_folder(prog, args.lesson, args.lesson_out, args.theme)
    if getattr(args, "scene", None) is None:
        fail(prog, "give a SCENE (see rigidrel scenes) or --lesson FILE")
    scene, frame = scene_from_args(prog, args, None)
    out = out_dir(prog, args.out)
    try:
        written = export_scene(
            scene, frame, out, seconds=args.seconds, fps=args.fps, gif_fps=args.gif_fps, shade=args.theme
        )
    except (RuntimeError, ValueError) as exc:
        fail(prog, str(exc))
    for w in written:
        print(f"{w.path!s:60s} {w.megabytes:8.2f} MB {w.seconds:7.2f} s")
    return 0


def export_lesson_folder(prog: str, lesson_name: str, out_text: str | None, shade: Shade = "light") -> int:
    """``rigidrel export --lesson FILE --out DIR``: the lesson checked whole, then its pages."""
    from .export.lesson_site import export_lesson
    from .lessons import LessonError, lesson_from

    if out_text is None:
        fail(prog, "--lesson needs --out DIR, the folder to write the pages into")
    try:
        lesson = lesson_from(lesson_name)
    except LessonError as exc:
        fail(prog, str(exc))
    out = out_dir(prog, out_text)
    t0 = time.perf_counter()
    written = export_lesson(lesson, out, progress=lambda p: print(p, flush=True), shade=shade)
    size = sum(p.stat().st_size for p in written) / 1e6
    seconds, index = time.perf_counter() - t0, out / "index.html"
    print(f"{len(lesson.steps)} steps, {len(written)} files, {size:.1f} MB in {seconds:.1f} s: open {index}")
    return 0


def cmd_figures(args: argparse.Namespace) -> int:
    from .export.figures import write_figures
    from .export.paradox_figures import write_paradox_figures

    prog = "rigidrel figures"
    out = out_dir(prog, args.out)
    try:
        for path in [*write_figures(out), *write_paradox_figures(out)]:
            print(path)
    except RuntimeError as exc:
        fail(prog, str(exc))
    return 0


def checkout_root() -> Path | None:
    """The source checkout this package runs from (an editable install), or None for a wheel.

    The benchmarks (``benchmarks/``) and the 50-digit oracle (``tests/reference/oracle/``) live in the
    checkout, beside ``app/rigidrel_app``; the wheel ships neither.
    """
    root = Path(__file__).resolve().parents[2]
    study, oracle = root / "benchmarks" / "study" / "cli.py", root / "tests" / "reference" / "oracle" / "__init__.py"
    return root if study.is_file() and oracle.is_file() else None


def cmd_bench(args: argparse.Namespace) -> int:
    prog = "rigidrel bench"
    root = checkout_root()
    if root is None:
        fail(
            prog,
            "runs from a source checkout (its benchmarks/ are not installed): clone the repository, "
            "pip install -e '.[bench]' there and run it again",
        )
    if str(root) not in sys.path:
        sys.path.insert(0, str(root))
    try:
        study = importlib.import_module("benchmarks.study.cli")
    except ImportError as exc:  # scipy / spacetimelib / mpmath are the [bench] extra
        fail(prog, f"{exc.name or exc} is missing: pip install -e '.[bench]'")
    return study.run_bench(quick=args.quick, out=args.out)


def start_scenario(prog: str, args: argparse.Namespace) -> Scenario | None:
    """The state ``rigidrel serve SCENE ...`` (a scenario line) opens every tab on (None: the app's
    default); a line that names none is one line on stderr and exit status 2."""
    if args.scene is None:
        return None
    try:
        scenario = scenario_from_args(args.scene, args)
    except ScenarioError as exc:
        fail(prog, str(exc) if str(exc).startswith("--") else f"--{exc.parameter}: {exc}")
    if (problem := beta_problem(scenario.settings)) is not None:  # every tab shows it on the β slider
        fail(prog, problem)
    return scenario


def cmd_serve(args: argparse.Namespace) -> int:
    """``rigidrel serve [SCENE ...]``, or ``rigidrel serve --lesson FILE [--follow]``: a lesson is
    checked whole before the server starts (a mistake is one located line and exit status 2)."""
    prog = "rigidrel serve"
    lesson = None
    if args.lesson is not None:
        from .lessons import LessonError, lesson_from

        if args.scene is not None:
            fail(prog, "give a SCENE or --lesson, not both")
        try:
            lesson = lesson_from(args.lesson)
        except LessonError as exc:
            fail(prog, str(exc))
    elif args.follow:
        fail(prog, "--follow needs --lesson FILE (the tabs follow the leading tab's step)")
    start = start_scenario(prog, args)
    from .live.server import serve  # viser is imported only here

    return serve(args.host, args.port, start, lesson, args.follow, args.theme, args.still_image)


def main(argv: Sequence[str] | None = None) -> int:
    parser = build_parser()
    args, extra = parser.parse_known_args(argv)
    if extra:  # an option the scene does not have: name it, and the ones it has
        kind = getattr(args, "scene", None)
        if kind is None:
            parser.error(f"unrecognized arguments: {' '.join(extra)}")
        options = ", ".join(flag(p) for p in rr.describe(kind).parameters)
        fail(f"rigidrel {args.command} {kind}", f"{extra[0]} is not an option of {kind}; its parameters are {options}")
    return int(args.func(args))


if __name__ == "__main__":
    raise SystemExit(main())
