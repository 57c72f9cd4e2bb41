"""Model no more than a panel shows: fixed-N against adaptive sampling of the app's diagrams.

The app draws each curve (worldlines of five material points per rod in two Minkowski
diagrams, each rod's equal-time length) with :mod:`rigidrel_app.view.sampling`: samples start at the
core's switch times and an interval is halved only while its midpoint leaves the chord
by more than half a pixel at the panel's size, over the visible time window only. The
alternative is a fixed number ``N`` of equally spaced times per curve.

For a few of the app's scenes this module rebuilds the whole drawing
(:func:`rigidrel_app.view.scene_view.build_drawing`, what every slider change costs on the
server) once with the app's sampler and once with a fixed-``N``
:class:`~rigidrel_app.view.sampling.Sampler` passed in, and records

* points used: all samples of all curves of the drawing;
* max deviation: the largest horizontal (worldlines) or vertical (lengths) distance, in
  pixels of the panel, between a drawn polyline and the exact curve, checked at 9 points
  inside every segment (exact values from the core);
* redraw cost: best wall time of ``build_drawing``, the JSON bytes sent to the browser, and
  optionally the time Chromium (through kaleido) takes to draw the three diagrams.
"""

from __future__ import annotations

import json
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field, replace
from typing import Any, Literal

import numpy as np
import numpy.typing as npt

import rigidrel_core as rr
from rigidrel_app.backends.plotly import APP_CONFIG, SplicedFigure
from rigidrel_app.view.sampling import ADAPTIVE, TOLERANCE_PX, Sampled, Sampler
from rigidrel_app.view.scene_view import LENGTH_ASPECT, PLOT_ASPECT, PLOT_PANEL_PX, Drawn, build_drawing
from rigidrel_app.view.state import Resolved, Settings, presets, resolve

FloatArray = npt.NDArray[np.float64]
SamplerKind = Literal["adaptive", "fixed"]
#: Points checked inside every drawn segment (fractions 0.1 .. 0.9 of it).
_INSIDE = np.linspace(0.0, 1.0, 11)[1:-1]


@dataclass(frozen=True)
class StudyScene:
    """An app scene (as the controls set it) and its name in the charts."""

    label: str
    short: str
    settings: Settings


STUDY_SCENES: tuple[StudyScene, ...] = (
    StudyScene("Fig. 1, rod's final rest frame", "Fig. 1", presets()["Fig. 1: acceleration to V = 0.6"]),
    StudyScene("Fig. 3, barycentric frame", "Fig. 3", presets()["Fig. 3: collision, M2 = 2 M1"]),
    StudyScene("impulsive start to V = 0.99", "impulse V=0.99", Settings.of("impulsive-start", v=0.99)),
    StudyScene(
        "V = 0.9, a'_F L0 = 0.99 (near the horizon)",
        "a'_F L0=0.99",
        Settings.of("constant-acceleration", v=0.9, a_front=0.99),
    ),
)


@dataclass(frozen=True)
class _Curve:
    """One drawn curve and how to evaluate it exactly (frame times -> panel pixels)."""

    sampled: Sampled
    exact: Callable[[FloatArray], FloatArray]
    px_per_unit: float


@dataclass(frozen=True)
class SamplingPoint:
    """One drawing of one scene with one sampler."""

    sampler: SamplerKind
    n_fixed: int | None
    points: int
    max_deviation_px: float
    build_seconds: float
    json_bytes: int
    render_seconds: float | None = None
    """Browser (Chromium via kaleido) time to draw the three diagrams, best of repeats, summed."""


@dataclass(frozen=True)
class SceneStudy:
    """One scene drawn adaptively and with every fixed N tried (ascending)."""

    label: str
    short: str
    adaptive: SamplingPoint
    fixed: tuple[SamplingPoint, ...]

    def fixed_at_equal_accuracy(self, tol_px: float) -> SamplingPoint:
        """The smallest fixed N from which on every N tried draws within ``tol_px`` (a kink between grid
        points makes the deviation jump about with N), else the largest N tried."""
        for i, p in enumerate(self.fixed):
            if all(q.max_deviation_px <= tol_px for q in self.fixed[i:]):
                return p
        return self.fixed[-1]


@dataclass(frozen=True)
class _RecordingSampler(Sampler):
    """A sampler that also keeps every curve it draws, with the exact curve to compare it with."""

    curves: list[_Curve] = field(default_factory=list)

    def worldlines(
        self, scene: rr.Scene, frame: rr.Frame, fractions: FloatArray, t_range: tuple[float, float], px_per_x: float
    ) -> list[list[Sampled]]:
        out = super().worldlines(scene, frame, fractions, t_range, px_per_x)
        for r, rod in enumerate(out):
            for k, s in enumerate(rod):
                self.curves.append(_Curve(s, _worldline_exact(scene, frame, float(fractions[k]), r), px_per_x))
        return out

    def lengths(
        self, scene: rr.Scene, frame: rr.Frame, t_range: tuple[float, float], px_per_length: float
    ) -> list[Sampled]:
        out = super().lengths(scene, frame, t_range, px_per_length)
        for r, s in enumerate(out):
            self.curves.append(_Curve(s, _length_exact(scene, frame, r), px_per_length))
        return out


def _sampler(kind: SamplerKind, n: int) -> Sampler:
    return ADAPTIVE if kind == "adaptive" else Sampler(fixed_n=n)


def _worldline_exact(scene: rr.Scene, frame: rr.Frame, fraction: float, rod: int) -> Callable[[FloatArray], FloatArray]:
    return lambda t: scene.material_positions(t, frame=frame, fractions=np.array([fraction]))[rod, 0]


def _length_exact(scene: rr.Scene, frame: rr.Frame, rod: int) -> Callable[[FloatArray], FloatArray]:
    return lambda t: scene.lengths(t, frame=frame)[rod]


def max_deviation_px(curve: _Curve) -> float:
    """Largest distance (pixels) between the polyline and the exact curve inside its segments."""
    t, x = curve.sampled.t, curve.sampled.x
    if t.size < 2:
        return 0.0
    dt = np.diff(t)[:, None]
    inside_t = t[:-1, None] + dt * _INSIDE
    chord = x[:-1, None] + np.diff(x)[:, None] * _INSIDE
    exact = curve.exact(inside_t.ravel()).reshape(inside_t.shape)
    return float(np.max(np.abs(exact - chord)) * curve.px_per_unit)


#: The figure JSON of each diagram of one drawing, as sent to the browser, with its height / width.
Sent = tuple[tuple[str, float], ...]


def _sent(d: Drawn) -> Sent:
    aspects = (PLOT_ASPECT, PLOT_ASPECT, LENGTH_ASPECT)
    return tuple((SplicedFigure(chart, APP_CONFIG).to_json(), a) for chart, a in zip(d.charts, aspects, strict=True))


def measure(resolved: Resolved, kind: SamplerKind, n: int, repeats: int) -> tuple[SamplingPoint, Sent]:
    """Points, deviation, best build time and payload of one drawing; and its figures as sent."""
    base = _sampler(kind, n)
    recorder = _RecordingSampler(base.tol_px, base.fixed_n)
    sent = _sent(build_drawing(resolved, recorder))
    curves = recorder.curves
    best = float("inf")
    for _ in range(repeats):
        start = time.perf_counter()
        build_drawing(resolved, base)
        best = min(best, time.perf_counter() - start)
    point = SamplingPoint(
        sampler=kind,
        n_fixed=None if kind == "adaptive" else n,
        points=sum(c.sampled.t.size for c in curves),
        max_deviation_px=max(max_deviation_px(c) for c in curves),
        build_seconds=best,
        json_bytes=sum(len(text) for text, _ in sent),
    )
    return point, sent


#: ``render(figure dict, width, height) -> seconds`` (None without a browser): the browser's time
#: to draw a figure.
Renderer = Callable[[dict[str, Any], int, int], float | None]


def _with_render(point: SamplingPoint, sent: Sent, render: Renderer) -> SamplingPoint:
    """Add the browser's time to draw all three diagrams of the drawing (each at its panel size)."""
    width = int(PLOT_PANEL_PX)
    total = 0.0
    for text, aspect in sent:
        seconds = render(json.loads(text), width, int(width * aspect))
        if seconds is None:
            return point
        total += seconds
    return replace(point, render_seconds=total)


def run_study(
    fixed_counts: Sequence[int],
    repeats: int,
    render: Renderer | None = None,
    scenes: Sequence[StudyScene] = STUDY_SCENES,
) -> list[SceneStudy]:
    """Adaptive and every fixed N for each scene; with ``render``, also the browser's time to draw
    all three diagrams for adaptive, fixed N at equal accuracy and the largest fixed N."""
    out = []
    for scene in scenes:
        resolved = resolve(scene.settings)
        if not isinstance(resolved, Resolved):
            raise ValueError(f"study scene {scene.label!r}: {resolved}")
        adaptive, adaptive_sent = measure(resolved, "adaptive", 0, repeats)
        fixed_sent = [measure(resolved, "fixed", n, repeats) for n in fixed_counts]
        fixed = tuple(p for p, _ in fixed_sent)
        study = SceneStudy(scene.label, scene.short, adaptive, fixed)
        if render is not None:
            equal = study.fixed_at_equal_accuracy(TOLERANCE_PX)
            fixed = tuple(_with_render(p, sent, render) if p in (equal, fixed[-1]) else p for p, sent in fixed_sent)
            study = SceneStudy(scene.label, scene.short, _with_render(adaptive, adaptive_sent, render), fixed)
        out.append(study)
    return out
