"""The ``rigidrel`` command: events tables for slides, the app server, exports, figures, benchmarks.

Every bad argument ends in one line on stderr and exit status 2.
"""

from __future__ import annotations

import argparse
import json
import os
import sys
from collections.abc import Sequence
from pathlib import Path
from typing import NoReturn

import rigidrel_core as rr

from .settings import choose_frame

EXIT_USAGE = 2


class OneLineParser(argparse.ArgumentParser):
    """argparse, but a usage error is one line on stderr and exit status 2."""

    def error(self, message: str) -> NoReturn:
        sys.stderr.write(f"{self.prog}: error: {message}\n")
        raise SystemExit(EXIT_USAGE)


def fail(prog: str, message: str) -> NoReturn:
    sys.stderr.write(f"{prog}: error: {message.splitlines()[0] if message else 'failed'}\n")
    raise SystemExit(EXIT_USAGE)


# ---------------------------------------------------------------- events
def _all_parameters() -> dict[str, rr.ParameterSpec]:
    out: dict[str, rr.ParameterSpec] = {}
    for specs in rr.SCENE_PARAMETERS.values():
        for p in specs:
            out.setdefault(p.name, p)
    return out


def _number_or_none(text: str) -> float | None:
    if text.strip().lower() in ("none", "impulse", "impulsive"):
        return None
    try:
        return float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"not a number: {text!r}") from None


def add_scene_arguments(parser: argparse.ArgumentParser, frame_default: str | None = "lab") -> None:
    """``SCENE`` and one ``--name VALUE`` option per scene parameter (defaults: the paper's).

    ``frame_default=None`` means the app's default frame (the rod's rest frame after, or
    the barycentric frame).
    """
    parser.add_argument("scene", choices=[k.value for k in rr.SceneKind], help="which scene")
    for name, spec in _all_parameters().items():
        flags = dict.fromkeys(["--" + name.replace("_", "-"), f"--{name}"])
        parser.add_argument(
            *flags,
            dest=name,
            type=_number_or_none,
            default=argparse.SUPPRESS,
            metavar=name.upper(),
            help=f"{spec.description}; allowed {spec.allowed}",
        )
    parser.add_argument(
        "--frame",
        default=frame_default,
        help="frame velocity beta in (-1, 1), or a preset name such as 'barycentric' or 'rod 1 after' (default: "
        + ("the lab" if frame_default == "lab" else "the app's: the rod's rest frame after, or the barycentric frame")
        + ")",
    )


def scene_from_args(prog: str, args: argparse.Namespace) -> tuple[rr.Scene, rr.Frame]:
    names = set(_all_parameters())
    params = {k: v for k, v in vars(args).items() if k in names}
    try:
        scene = rr.build_scene(args.scene, **params)
        frame = choose_frame(scene, args.frame)
    except ValueError as exc:
        fail(prog, str(exc))
    return scene, frame


def events_report(scene: rr.Scene, frame: rr.Frame) -> dict[str, object]:
    """Everything ``rigidrel events`` prints, as plain data."""
    budget = scene.budget(frame)
    return {
        "scene": scene.kind.value,
        "parameters": dict(scene.parameters),
        "frame": {"name": frame.name, "velocity": frame.beta},
        "events": {k: {"t": t, "x": x} for k, (t, x) in scene.events_in(frame).items()},
        "events_lab": {k: {"t": t, "x": x} for k, (t, x) in scene.events.items()},
        "initial_velocities": list(scene.initial_velocities),
        "final_velocities": list(scene.final_velocities),
        "frame_presets": {k: f.beta for k, f in scene.frames.items()},
        "budget": budget.as_dict(),
    }


def _g(x: float) -> str:
    return f"{x:.10g}" if x != 0 else "0"


def format_events(scene: rr.Scene, frame: rr.Frame) -> str:
    budget = scene.budget(frame)
    lines = [
        f"scene      {scene.kind.value}   (c = 1)",
        "parameters " + "  ".join(f"{k}={_g(v)}" for k, v in scene.parameters.items()),
        f"frame      {frame.name}  (beta = {_g(frame.beta)})",
        "",
        f"{'event':<8}{'t':>20}{'x':>20}",
    ]
    for name, (t, x) in scene.events_in(frame).items():
        lines.append(f"{name:<8}{_g(t):>20}{_g(x):>20}")
    lines += ["", f"{'rod':<8}{'V before (lab)':>20}{'V after (lab)':>20}"]
    for rod, v0, v1 in zip(scene.rods, scene.initial_velocities, scene.final_velocities):
        lines.append(f"{rod.name:<8}{_g(v0):>20}{_g(v1):>20}")
    presets = "  ".join(f"{k}: {_g(f.beta)}" for k, f in scene.frames.items())
    lines += ["", f"frame presets  {presets}", "", f"4-momentum in this frame (E, p)  {'M':>12}{'E':>16}{'p':>16}"]
    for phase, masses, em in (
        ("before", budget.rest_mass_before, budget.before),
        ("after", budget.rest_mass_after, budget.after),
    ):
        for name, m, (e, p) in zip(budget.bodies, masses, em):
            lines.append(f"  {name + ' ' + phase:<31}{_g(m):>12}{_g(e):>16}{_g(p):>16}")
    lines.append(f"  {'total before':<31}{'':>12}{_g(budget.total_before[0]):>16}{_g(budget.total_before[1]):>16}")
    lines.append(f"  {'total after':<31}{'':>12}{_g(budget.total_after[0]):>16}{_g(budget.total_after[1]):>16}")
    if budget.external_source != "none":
        src = {"drive": "from the drive", "wall": "from the wall"}[budget.external_source]
        lines.append(f"  {src:<31}{'':>12}{_g(budget.external[0]):>16}{_g(budget.external[1]):>16}")
    lines.append(f"  heat (rest energy created): {_g(budget.heat)}")
    return "\n".join(lines)


def cmd_events(args: argparse.Namespace) -> int:
    scene, frame = scene_from_args("rigidrel events", args)
    if args.json:
        print(json.dumps(events_report(scene, frame), indent=2, allow_nan=False))
    else:
        print(format_events(scene, frame))
    return 0


# ---------------------------------------------------------------- main
def build_parser() -> OneLineParser:
    parser = OneLineParser(prog="rigidrel", description="Born-rigid rods in special relativity (Franklin 2012).")
    sub = parser.add_subparsers(dest="command", required=True, parser_class=OneLineParser)
    ev = sub.add_parser("events", help="events, final velocities and 4-momentum budget of a scene")
    add_scene_arguments(ev)
    ev.add_argument("--json", action="store_true", help="machine-readable output")
    ev.set_defaults(func=cmd_events)
    sv = sub.add_parser("serve", help="start the app: open the printed URL in a browser")
    sv.add_argument("--host", default="127.0.0.1", help="interface to bind (default 127.0.0.1: this machine only)")
    sv.add_argument("--port", type=_port, default=8080, help="port to try first; the next free one is used if busy")
    sv.set_defaults(func=cmd_serve)
    ex = sub.add_parser("export", help="offline HTML (3-D and diagram), PNG, SVG, GIF and MP4 of a scene")
    add_scene_arguments(ex, frame_default=None)
    ex.add_argument("--out", required=True, help="folder to write into (created if missing)")
    ex.add_argument("--seconds", type=_positive, default=10.0, help="length of the animations (default 10 s)")
    ex.add_argument("--fps", type=_positive, default=30.0, help="frames per second of the 3-D HTML and MP4")
    ex.add_argument("--gif-fps", type=_positive, default=15.0, help="frames per second of the GIF")
    ex.set_defaults(func=cmd_export)
    fg = sub.add_parser("figures", help="regenerate the paper's Figs. 1-4 as SVG and PNG")
    fg.add_argument("--out", required=True, help="folder to write into (created if missing)")
    fg.set_defaults(func=cmd_figures)
    bn = sub.add_parser("bench", help="speed against accuracy of every method, charted (needs rigidrel[bench])")
    bn.add_argument("--quick", action="store_true", help="a reduced run that finishes in under a minute")
    bn.add_argument("--out", required=True, help="folder for the JSON table, charts and stability maps")
    bn.set_defaults(func=cmd_bench)
    return parser


def _positive(text: str) -> float:
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"not a number: {text!r}") from None
    if not (value > 0 and value < 1e4):
        raise argparse.ArgumentTypeError(f"must be in (0, 1e4); got {text}")
    return value


def out_dir(prog: str, text: str) -> Path:
    """The folder ``--out`` names (``~`` expanded), created if missing; a one-line error and exit
    status 2 for an empty name or a folder that cannot be created or written to."""
    if not text.strip():
        fail(prog, "--out: an empty folder name")
    out = Path(text).expanduser()
    try:
        out.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        fail(prog, f"--out {text!r} cannot be created: {exc.strerror or exc}")
    if not os.access(out, os.W_OK | os.X_OK):
        fail(prog, f"--out {text!r} is not a writable folder")
    return out


def cmd_export(args: argparse.Namespace) -> int:
    from .export.bundle import export_scene

    prog = "rigidrel export"
    scene, frame = scene_from_args(prog, args)
    out = out_dir(prog, args.out)
    try:
        written = export_scene(scene, frame, out, seconds=args.seconds, fps=args.fps, gif_fps=args.gif_fps)
    except (RuntimeError, ValueError) as exc:
        fail(prog, str(exc))
    for w in written:
        print(f"{w.path!s:60s} {w.megabytes:8.2f} MB {w.seconds:7.2f} s")
    return 0


def cmd_figures(args: argparse.Namespace) -> int:
    from .figures import write_figures

    prog = "rigidrel figures"
    out = out_dir(prog, args.out)
    try:
        for path in write_figures(out):
            print(path)
    except RuntimeError as exc:
        fail(prog, str(exc))
    return 0


def cmd_bench(args: argparse.Namespace) -> int:
    try:
        from .bench.cli import run_bench
    except ImportError as exc:  # scipy / spacetimelib / mpmath are the [bench] extra
        fail("rigidrel bench", f"{exc.name or exc} is missing: pip install -e '.[bench]'")
    return run_bench(quick=args.quick, out=args.out)


def _port(text: str) -> int:
    try:
        port = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"not a port number: {text!r}") from None
    if not 0 <= port <= 65535:
        raise argparse.ArgumentTypeError(f"port must be in [0, 65535]; got {port}")
    return port


def cmd_serve(args: argparse.Namespace) -> int:
    from .server import serve  # viser is imported only here

    return serve(args.host, args.port)


def main(argv: Sequence[str] | None = None) -> int:
    parser = build_parser()
    args = parser.parse_args(argv)
    return int(args.func(args))


if __name__ == "__main__":
    raise SystemExit(main())
