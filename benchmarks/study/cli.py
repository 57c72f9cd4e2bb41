"""Entry point of ``rigidrel bench [--quick] --out DIR``: speed against accuracy of every method.

Writes into ``DIR``:

* ``bench.json``: the table (method, setting, regime, seconds per sample, max error against
  mpmath), every case's results, the stability maps, the sampling study, the environment;
* ``speed_accuracy.{html,png}``: log-log max error against seconds per sample, per regime;
* ``stability_maps.{html,png}``: each method's error over the speed V and frame velocity beta;
* ``sampling.{html,png}``: points drawn against max pixel deviation, fixed N and adaptive,
  and the redraw cost;
* ``throughput.{html,png}``: seconds per sample against samples per call (fixed and marginal cost).

Exit status 0; 2 with one line on stderr for a bad ``--out``; 1 if the PNGs could not be
rendered (no Chromium), after writing everything else.
"""

from __future__ import annotations

import datetime
import importlib.metadata
import os
import platform
import sys
import time
from collections.abc import Sequence
from typing import Any

import plotly.graph_objects as go

from rigidrel_app.export.paths import out_dir
from rigidrel_app.view.sampling import TOLERANCE_PX

from .charts import sampling_figure, speed_accuracy_figure, stability_figure, throughput_figure
from .config import FULL, QUICK, BenchConfig
from .methods import MethodName
from .methods.mpmath_slices import ROUNDING_LEVEL
from .output import ChartImages, ChromiumUnavailable, plain, write_html, write_json
from .runner import CaseResult, RegimeRow, ThroughputPoint, regime_rows, run_case, throughput, warm_up
from .sampling_study import STUDY_SCENES, SceneStudy, run_study
from .scenes import FIG3_BETA_HALF, Regime
from .stability import StabilityMap, stability_map, worst_by_method

PROG = "rigidrel bench"
#: The case of the cost-per-sample curves: Fig. 3's collision (two rods, four ends) in a frame at beta = 0.5.
THROUGHPUT_CASE = FIG3_BETA_HALF
METRIC = (
    "max over samples and rod ends of |x' - x'_ref| / max(|x'_ref|, L_ref(t')), L_ref the rod's equal-time "
    "length in the frame; x'_ref from mpmath at 50 digits (the paper's lab formulas sliced at each frame time)"
)
TIMING = (
    "seconds per sample = best wall time of repeated calls / samples; each call goes from the scene's "
    "parameters to the positions (scene solution, frame, slices); the core and the textbook formulas are "
    "called in turn, one call each; mpmath is timed once"
)


def run_bench(quick: bool, out: str) -> int:
    """``rigidrel bench [--quick] --out DIR``."""
    return run(QUICK if quick else FULL, out)


class _Log:
    def __init__(self) -> None:
        self.start = time.perf_counter()

    def __call__(self, text: str) -> None:
        print(f"{PROG}: [{time.perf_counter() - self.start:6.1f} s] {text}", file=sys.stderr, flush=True)

    @property
    def seconds(self) -> float:
        return time.perf_counter() - self.start


def _environment() -> dict[str, Any]:
    versions = {}
    for pkg in ("numpy", "scipy", "spacetimelib", "mpmath", "plotly", "kaleido"):
        try:
            versions[pkg] = importlib.metadata.version(pkg)
        except importlib.metadata.PackageNotFoundError:
            versions[pkg] = None
    return {
        "python": platform.python_version(),
        "platform": platform.platform(),
        "cpus": os.cpu_count(),
        "packages": versions,
    }


#: Errors within this factor of each other count as equal (and so do all errors at float64's
#: rounding level, :data:`~benchmarks.study.methods.mpmath_slices.ROUNDING_LEVEL`).
EQUAL_ERROR_FACTOR = 10.0


def dominance(rows: Sequence[RegimeRow]) -> dict[str, list[str]]:
    """Per regime, every method setting faster than the core at equal or better error (errors within
    a factor 10, or both at float64 rounding level, count as equal): where the core does not dominate."""
    out: dict[str, list[str]] = {}
    for regime in Regime:
        in_regime = [r for r in rows if r.regime is regime]
        core = next((r for r in in_regime if r.method is MethodName.CORE), None)
        if core is None or core.max_error is None:
            continue
        equal_error = max(EQUAL_ERROR_FACTOR * core.max_error, ROUNDING_LEVEL)
        out[regime.value] = [
            f"{r.series} {r.setting}"
            for r in in_regime
            if r.method is not MethodName.CORE
            and r.max_error is not None
            and r.max_error <= equal_error
            and r.seconds_per_sample < core.seconds_per_sample
        ]
    return out


def _exactness(row: RegimeRow) -> tuple[float, float]:
    return (float("inf") if row.max_error is None else row.max_error, row.seconds_per_sample)


def most_exact(rows: Sequence[RegimeRow]) -> list[RegimeRow]:
    """Per regime and series, the setting with the smallest error (failures last, then the fastest)."""
    best: dict[tuple[Regime, str], RegimeRow] = {}
    for r in rows:
        key = (r.regime, r.series)
        if key not in best or _exactness(r) < _exactness(best[key]):
            best[key] = r
    return list(best.values())


def _summary(rows: Sequence[RegimeRow]) -> str:
    lines = [f"{'regime':<20}{'method (most exact setting)':<44}{'s/sample':>11}{'max error':>11}"]
    for r in most_exact(rows):
        err = "failed" if r.max_error is None else f"{r.max_error:.2g}"
        lines.append(f"{r.regime.value:<20}{r.series + ' ' + r.setting:<44}{r.seconds_per_sample:>11.2g}{err:>11}")
    return "\n".join(lines)


def _measure_methods(config: BenchConfig, log: _Log) -> tuple[list[CaseResult], list[ThroughputPoint]]:
    """Every method setting on every case (one process, the core warmed up), then the cost curves."""
    settings = config.settings()
    warm_up(settings)
    results: list[CaseResult] = []
    cases = config.cases()
    for i, case in enumerate(cases):
        log(f"case {i + 1}/{len(cases)}: {case.regime.value}: {case.label}")
        results.extend(run_case(case, settings, config.samples, config.timing))
    log(f"cost per sample against samples per call ({THROUGHPUT_CASE.label})")
    speeds = throughput(
        THROUGHPUT_CASE,
        config.throughput_settings(),
        config.throughput_counts,
        config.timing,
        config.throughput_max_call_seconds,
    )
    return results, speeds


def _figures(
    config: BenchConfig,
    rows: Sequence[RegimeRow],
    maps: StabilityMap,
    studies: Sequence[SceneStudy],
    speeds: Sequence[ThroughputPoint],
    render_baseline: float | None,
) -> dict[str, go.Figure]:
    """The charts by file name; each chart's layout width and height are its PNG's size in pixels."""
    return {
        "speed_accuracy": speed_accuracy_figure(
            rows, f"Speed against accuracy ({config.name} run, {config.samples} frame times)"
        ),
        "stability_maps": stability_figure(
            maps, f"Stability maps: max error over V and β ({config.map_samples} frame times)"
        ),
        "sampling": sampling_figure(
            studies, "Model no more than a panel shows: fixed N against adaptive sampling", render_baseline
        ),
        "throughput": throughput_figure(speeds, f"Cost per sample against samples per call: {THROUGHPUT_CASE.label}"),
    }


def run(config: BenchConfig, out: str) -> int:
    """Measure, chart and write everything for ``config`` into the folder ``out``."""
    folder = out_dir(PROG, out)
    log = _Log()
    log(f"{config.name} run into {folder}")
    results, speeds = _measure_methods(config, log)
    rows = regime_rows(results)
    table_seconds = log.seconds
    log("stability maps")
    maps = stability_map(config.map_settings(), config.map_velocity_digits, config.map_frame_digits, config.map_samples)
    maps_seconds = log.seconds - table_seconds
    png_error: str | None = None
    with ChartImages() as images:
        log("sampling study (fixed N against adaptive)")
        repeats = config.sampling_render_repeats

        def render(fig: dict[str, Any], width: int, height: int) -> float | None:
            return images.render_seconds(fig, width, height, repeats=repeats)

        studies = run_study(
            config.sampling_fixed_counts,
            config.sampling_repeats,
            render=render if repeats > 0 else None,
            scenes=STUDY_SCENES[: config.sampling_scenes],
        )
        log("charts")
        baseline = images.baseline_seconds if repeats > 0 else None
        figures = _figures(config, rows, maps, studies, speeds, baseline)
        for name, fig in figures.items():
            write_html(fig, folder / f"{name}.html")
            if png_error is None:
                try:
                    images.write_png(fig, folder / f"{name}.png")
                except ChromiumUnavailable as exc:
                    png_error = str(exc)
    data = {
        "schema": "rigidrel-bench/1",
        "run": config.name,
        "created": datetime.datetime.now(datetime.UTC).isoformat(timespec="seconds"),
        "environment": _environment(),
        "metric": METRIC,
        "timing": TIMING,
        "samples_per_case": config.samples,
        "table": rows,
        "core_dominated_by": dominance(rows),
        "cases": results,
        "stability": {"map": maps, "worst": worst_by_method(maps)},
        "throughput": {"case": THROUGHPUT_CASE.label, "points": speeds},
        "sampling": _sampling_json(studies),
        "render_baseline_seconds": images.baseline_seconds,
        "png_error": png_error,
        "wall_seconds": {"table": table_seconds, "stability_maps": maps_seconds, "total": log.seconds},
    }
    write_json(folder / "bench.json", data)
    print(_summary(rows))
    kinds = ".html" if png_error else ".html, .png"
    print(f"wrote {folder}/bench.json and {', '.join(figures)} ({kinds}) in {log.seconds:.1f} s")
    if png_error is not None:
        print(f"{PROG}: error: {png_error}", file=sys.stderr)
        return 1
    return 0


def _sampling_json(studies: Sequence[SceneStudy]) -> list[dict[str, Any]]:
    out = []
    for st in studies:
        equal = st.fixed_at_equal_accuracy(TOLERANCE_PX)
        out.append(
            {
                "scene": st.label,
                "adaptive": plain(st.adaptive),
                "fixed": plain(st.fixed),
                "fixed_within_half_pixel": plain(equal),
                "points_ratio_fixed_within_half_pixel": equal.points / st.adaptive.points,
                "build_ms_saved_against_largest_fixed": 1e3 * (st.fixed[-1].build_seconds - st.adaptive.build_seconds),
            }
        )
    return out
