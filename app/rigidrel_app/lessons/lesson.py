"""A lesson: a title and steps, read from a TOML file and checked whole before anything is shown.

The file format (``docs/lessons.md`` has the full reference)::

    title = "Rigid rods"

    [[step]]
    title = "The wall crash"
    caption = "The back end starts braking at t = {event[T_1].t:.3g}, before the contact."
    scene = "wall-collision --v 0.6 --eps 0 --frame lab"   # a scenario string
    layers = ["world-tube", "light-cone", "signals"]       # optional; default: --layers, else all but signals
    window = [-1.5, 2.5]                                   # optional: the time window shown
    start = -1.0                                           # optional, or --t in the scene line
    autoplay = true                                        # optional, default false
    lock = ["v", "eps"]                                    # optional: controls the step fixes
    ride = { rod = 1, fraction = 1.0 }                     # optional: the frame rides that point

Every mistake is a :class:`LessonError` that names the file, the line, the step, the key and what
is allowed; a lesson with any mistake is refused whole.
"""

from __future__ import annotations

import math
import re
import tomllib
from collections.abc import Mapping
from dataclasses import dataclass, replace
from pathlib import Path
from typing import Any

from ..view.comoving import RidePoint
from ..view.layers import Layer
from ..view.scenario import Scenario, ScenarioError, parse_scenario
from ..view.state import Resolved, build
from .captions import CaptionError, render_caption

#: Controls a step can lock besides the scene's parameters.
FIXED_CONTROLS = ("scene", "frame", "time")
_STEP_KEYS = ("title", "caption", "scene", "layers", "window", "start", "autoplay", "lock", "ride")
_REQUIRED = ("title", "caption", "scene")
_TOP_KEYS = ("title", "subtitle", "step")


class LessonError(ValueError):
    """One mistake in a lesson file, located: ``path:line: step N ("title"), key "k": what is wrong``."""

    def __init__(self, path: str, line: int, message: str, step: int | None = None, key: str | None = None) -> None:
        self.path, self.line, self.step, self.key = path, line, step, key
        where = f"{path}:{line}: "
        if step is not None:
            where += f"step {step}"
        if key is not None:
            where += (", " if step is not None else "") + f'key "{key}"'
        super().__init__(where + (": " if step is not None or key is not None else "") + message)


@dataclass(frozen=True)
class Step:
    """One step of a lesson, checked: its scenario builds, its caption's numbers are filled in."""

    title: str
    caption: str
    """Markdown, with every ``{...}`` field replaced by the core's number."""
    scenario: Scenario
    resolved: Resolved
    layers: frozenset[Layer]
    window: tuple[float, float] | None
    start: float | None
    autoplay: bool
    locked: frozenset[str]
    """Names of the controls this step fixes: parameter names and any of :data:`FIXED_CONTROLS`."""
    ride: RidePoint | None
    """The material point the frame rides (its ``rod`` counted from 0), or None for a fixed frame."""
    line: int
    """Line of the step's ``[[step]]`` header in its file."""


@dataclass(frozen=True)
class Lesson:
    title: str
    subtitle: str
    steps: tuple[Step, ...]
    source: str
    """Where it was read from (a path, or ``"built-in: paper"``)."""


class _Lines:
    """Line numbers of the ``[[step]]`` headers and of the keys inside each step (tomllib gives none)."""

    _HEADER = re.compile(r"^\s*\[\[\s*step\s*\]\]")
    _KEY = re.compile(r"^\s*([A-Za-z0-9_-]+)\s*=")

    def __init__(self, text: str) -> None:
        self.headers: list[int] = []
        self.keys: list[dict[str, int]] = []
        self.top: dict[str, int] = {}
        in_string = False
        for n, line in enumerate(text.splitlines(), start=1):
            if line.count('"""') % 2 == 1 or line.count("'''") % 2 == 1:
                was = in_string
                in_string = not in_string
                if was:
                    continue
            elif in_string:
                continue
            if self._HEADER.match(line):
                self.headers.append(n)
                self.keys.append({})
                continue
            m = self._KEY.match(line)
            if m:
                (self.keys[-1] if self.keys else self.top).setdefault(m.group(1), n)

    def of(self, step: int, key: str | None = None) -> int:
        """Line of ``key`` in step ``step`` (0-based), or of the step's header."""
        if step >= len(self.headers):
            return 1
        if key is not None and key in self.keys[step]:
            return self.keys[step][key]
        return self.headers[step]


def _string(value: object) -> str | None:
    return value if isinstance(value, str) else None


def _number(value: object) -> float | None:
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        return None
    return float(value) if math.isfinite(float(value)) else None


def load_lesson(path: str | Path) -> Lesson:
    """Read and check a lesson file (UTF-8 TOML)."""
    p = Path(path)
    try:
        text = p.read_text(encoding="utf-8")
    except OSError as exc:
        raise LessonError(str(p), 1, f"cannot read the file ({exc.strerror})") from None
    return parse_lesson(text, str(p))


def parse_lesson(text: str, source: str = "<lesson>") -> Lesson:
    """A lesson from TOML text; ``source`` names it in errors."""
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        line = int(m.group(1)) if (m := re.search(r"line (\d+)", str(exc))) else 1
        raise LessonError(source, line, f"not valid TOML ({exc})") from None
    lines = _Lines(text)
    for key in data:
        if key not in _TOP_KEYS:
            raise LessonError(
                source, lines.top.get(key, 1), f"unknown key; a lesson has {', '.join(_TOP_KEYS)}", key=key
            )
    title = _string(data.get("title"))
    if not title:
        raise LessonError(source, lines.top.get("title", 1), "a lesson needs a title (a non-empty string)", key="title")
    subtitle = data.get("subtitle", "")
    if not isinstance(subtitle, str):
        raise LessonError(source, lines.top.get("subtitle", 1), "must be a string", key="subtitle")
    raw_steps = data.get("step")
    if not isinstance(raw_steps, list) or not raw_steps:
        raise LessonError(source, 1, "a lesson needs at least one [[step]] table", key="step")
    steps = tuple(_step(source, lines, k, raw) for k, raw in enumerate(raw_steps))
    return Lesson(title, subtitle, steps, source)


def _step(source: str, lines: _Lines, k: int, raw: Mapping[str, Any]) -> Step:
    name = raw.get("title") if isinstance(raw.get("title"), str) else None

    def fail(key: str | None, message: str) -> LessonError:
        label = f'{k + 1} ("{name}")' if name else f"{k + 1}"
        err = LessonError(source, lines.of(k, key), message, step=k + 1, key=key)
        err.args = (str(err).replace(f"step {k + 1}", f"step {label}", 1),)
        return err

    for key in raw:
        if key not in _STEP_KEYS:
            raise fail(key, f"unknown key; a step has {', '.join(_STEP_KEYS)}")
    for key in _REQUIRED:
        if key not in raw:
            raise fail(key, "missing; every step needs title, caption and scene")
    title, caption, line = _string(raw["title"]), _string(raw["caption"]), _string(raw["scene"])
    if not title:
        raise fail("title", "must be a non-empty string")
    if caption is None:
        raise fail("caption", "must be a string (Markdown)")
    if line is None:
        raise fail("scene", 'must be a scenario string, e.g. "wall-collision --v 0.6 --eps 0"')
    try:
        scenario = parse_scenario(line)
    except ScenarioError as exc:
        raise fail("scene", str(exc)) from None
    resolved = build(scenario.settings)
    d = scenario.settings.description

    layers = scenario.settings.layers  # without the key, the scene line's --layers (or the default)
    if "layers" in raw:
        given = raw["layers"]
        allowed = ", ".join(f'"{layer.value}"' for layer in Layer)
        if not isinstance(given, list) or not all(isinstance(v, str) for v in given):
            raise fail("layers", f"must be a list of layer names: {allowed}")
        unknown = [v for v in given if v not in Layer.__members__.values()]
        if unknown:
            raise fail("layers", f'"{unknown[0]}" is not a layer; the layers are {allowed}')
        layers = frozenset(Layer(v) for v in given)

    window: tuple[float, float] | None = None
    if "window" in raw:
        w = raw["window"]
        pair = [_number(v) for v in w] if isinstance(w, list) and len(w) == 2 else None
        if pair is None or pair[0] is None or pair[1] is None or not pair[0] < pair[1]:
            raise fail("window", "must be [start, end], two finite numbers with start < end")
        window = (pair[0], pair[1])

    start = scenario.t
    if "start" in raw:
        if scenario.t is not None:
            raise fail("start", "given twice: as start and as --t in the scene line; keep one")
        start = _number(raw["start"])
        if start is None:
            raise fail("start", "must be a finite number (a time of the step's frame)")
    if start is not None and window is not None and not window[0] <= start <= window[1]:
        raise fail("start", f"{start:g} lies outside the window [{window[0]:g}, {window[1]:g}]")

    autoplay = raw.get("autoplay", False)
    if not isinstance(autoplay, bool):
        raise fail("autoplay", "must be true or false")

    controls = (*(p.name for p in d.parameters), *FIXED_CONTROLS)
    locked: frozenset[str] = frozenset()
    if "lock" in raw:
        given = raw["lock"]
        if given == "all":
            locked = frozenset(controls)
        else:
            if not isinstance(given, list) or not all(isinstance(v, str) for v in given):
                raise fail("lock", f'must be "all" or a list of controls: {", ".join(controls)}')
            bad = [v for v in given if v not in controls]
            if bad and bad[0] in d.renamed:  # a lesson written before the parameter was renamed
                raise fail("lock", f'"{bad[0]}" is now "{d.renamed[bad[0]]}"')
            if bad:
                raise fail("lock", f'"{bad[0]}" is not a control of {d.kind}; the controls are {", ".join(controls)}')
            locked = frozenset(given)

    ride: RidePoint | None = None
    if "ride" in raw:
        r = raw["ride"]
        n_rods = resolved.scene.n_rods
        allowed = f"{{ rod = 1..{n_rods}, fraction = 0..1 }}"
        if not isinstance(r, dict) or set(r) != {"rod", "fraction"}:
            raise fail("ride", f"must be an inline table {allowed}")
        rod, fraction = r["rod"], _number(r["fraction"])
        if isinstance(rod, bool) or not isinstance(rod, int) or not 1 <= rod <= n_rods:
            raise fail("ride", f"rod = {rod!r}: {d.kind} has rods 1..{n_rods}")
        if fraction is None or not 0.0 <= fraction <= 1.0:
            raise fail("ride", f"fraction = {r['fraction']!r}: must be in [0, 1] (0 the left end, 1 the right)")
        if scenario.settings.frame is not None:
            raise fail("ride", "the step names a frame in its scene line too; a riding step has no other frame")
        ride = RidePoint(rod - 1, fraction)
        scenario = replace(scenario, settings=scenario.settings.riding(ride.rod, ride.fraction))
        resolved = build(scenario.settings)
    ride = resolved.ride  # also from the scene line's --ride

    try:
        text = render_caption(caption, resolved.scene, resolved.frame)
    except CaptionError as exc:
        raise fail("caption", str(exc)) from None
    resolved = replace(resolved, layers=layers)  # what the step draws, live and exported
    return Step(title, text, scenario, resolved, layers, window, start, autoplay, locked, ride, lines.of(k))
