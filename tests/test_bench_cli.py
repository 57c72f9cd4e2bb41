"""``rigidrel bench``: a reduced run writes the JSON table and readable charts; bad --out is one line, status 2.

The smoke run goes through every stage of ``--quick`` (table, cost-per-sample curves,
stability maps, sampling study, HTML and PNG charts) with the smallest settings (about 10 s:
its tests are marked slow). PNGs need Chromium through kaleido: if it cannot start, this test
fails and says why.
"""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from PIL import Image

from benchmarks.study.cli import run
from benchmarks.study.config import SMOKE
from benchmarks.study.methods import MethodName
from benchmarks.study.scenes import Regime

ROOT = Path(__file__).resolve().parents[1]
CHARTS = ("speed_accuracy", "stability_maps", "sampling", "throughput")


@pytest.fixture(scope="module")
def smoke(tmp_path_factory: pytest.TempPathFactory) -> tuple[int, Path, dict[str, Any]]:
    out = tmp_path_factory.mktemp("bench") / "out"
    code = run(SMOKE, str(out))
    data = json.loads((out / "bench.json").read_text())
    return code, out, data


@pytest.mark.slow
def test_smoke_run_renders_pngs(smoke: tuple[int, Path, dict[str, Any]]) -> None:
    code, _, data = smoke
    if data["png_error"] is not None:
        pytest.fail(f"PNG charts were not rendered: {data['png_error']}")
    assert code == 0


@pytest.mark.slow
def test_json_table_schema(smoke: tuple[int, Path, dict[str, Any]]) -> None:
    _, _, data = smoke
    assert data["schema"] == "rigidrel-bench/1"
    assert data["run"] == "smoke"
    rows = data["table"]
    assert {r["method"] for r in rows} == {m.value for m in MethodName}
    assert {r["regime"] for r in rows} == {r.value for r in Regime}
    for r in rows:
        assert set(r) >= {"method", "setting", "regime", "seconds_per_sample", "max_error", "samples", "failures"}
        assert r["seconds_per_sample"] > 0.0
        if r["max_error"] is None:
            assert r["failures"], r
        else:
            assert r["max_error"] >= 0.0
    core = [r for r in rows if r["method"] == MethodName.CORE.value]
    assert core and all(r["max_error"] is not None and r["max_error"] <= 1e-12 for r in core)
    maps = data["stability"]["map"]
    n_beta, n_v = len(maps["frame_velocities"]), len(maps["velocities"])
    for grid in maps["errors"].values():
        assert len(grid) == n_beta and all(len(row) == n_v for row in grid)
    study = data["sampling"][0]
    assert study["adaptive"]["max_deviation_px"] <= 0.5 + 1e-9
    assert study["adaptive"]["points"] < study["fixed"][-1]["points"]
    assert {p["series"] for p in data["throughput"]["points"]} >= {"rigidrel core", "textbook float64"}


@pytest.mark.slow
@pytest.mark.parametrize("name", CHARTS)
def test_chart_files_exist_and_pngs_are_not_blank(smoke: tuple[int, Path, dict[str, Any]], name: str) -> None:
    _, out, data = smoke
    html = (out / f"{name}.html").read_text()
    assert "plotly" in html and len(html) > 2000
    if data["png_error"] is not None:
        pytest.fail(f"PNG charts were not rendered: {data['png_error']}")
    img = np.asarray(Image.open(out / f"{name}.png").convert("L"), dtype=float)
    assert img.shape[0] >= 400 and img.shape[1] >= 800
    ink = (img < 200).mean()
    assert 0.01 < ink < 0.9, f"{name}.png: {ink:.1%} of the pixels are dark"
    assert img.std() > 20.0


def _rigidrel(*args: str, cwd: Path = ROOT) -> subprocess.CompletedProcess[str]:
    """``rigidrel ARGS`` (the installed package's command line) in ``cwd``."""
    return subprocess.run(
        [sys.executable, "-m", "rigidrel_app.cli", *args],
        cwd=cwd,
        capture_output=True,
        text=True,
        timeout=120,
    )


def _bench(*args: str) -> subprocess.CompletedProcess[str]:
    return _rigidrel("bench", *args)


@pytest.mark.slow  # each run imports the bench's methods (scipy, spacetimelib, plotly): 1-3 s
@pytest.mark.parametrize("where", ["file", "under-a-file"])
def test_bad_out_is_one_line_and_exit_status_2(tmp_path: Path, where: str) -> None:
    a_file = tmp_path / "a-file"
    a_file.write_text("not a folder")
    out = a_file if where == "file" else a_file / "sub"
    proc = _bench("--quick", "--out", str(out))
    assert proc.returncode == 2
    lines = proc.stderr.strip().splitlines()
    assert len(lines) == 1, proc.stderr
    assert "--out" in lines[0] and "Traceback" not in proc.stderr
    assert proc.stdout == ""


@pytest.mark.slow  # a new interpreter
def test_missing_out_is_a_usage_error() -> None:
    proc = _bench("--quick")
    assert proc.returncode == 2
    assert "--out" in proc.stderr and "Traceback" not in proc.stderr


@pytest.mark.parametrize(
    "command",
    [
        pytest.param(["export", "rod-collision"], id="export"),
        pytest.param(["figures"], id="figures"),
        pytest.param(["bench", "--quick"], id="bench", marks=pytest.mark.slow),  # imports the bench: 1-3 s
    ],
)
@pytest.mark.parametrize("name", ["", "  "], ids=["empty", "blank"])
def test_empty_out_is_one_line_naming_out_and_exit_status_2(
    tmp_path: Path,
    command: list[str],
    name: str,
    monkeypatch: pytest.MonkeyPatch,
    capsys: pytest.CaptureFixture[str],
) -> None:
    """``--out ""`` is a usage error, not the current folder (every command shares
    :func:`rigidrel_app.export.paths.out_dir`). In-process, from ``tmp_path``; the bad ``--out``
    above runs in a new interpreter."""
    from rigidrel_app import cli

    monkeypatch.chdir(tmp_path)
    with pytest.raises(SystemExit) as exit_:
        cli.main([*command, "--out", name])
    assert exit_.value.code == 2
    out, err = capsys.readouterr()
    lines = err.strip().splitlines()
    assert len(lines) == 1, err
    assert "--out" in lines[0] and "Traceback" not in err
    assert out == ""
    assert list(tmp_path.iterdir()) == [], "nothing is written into the current folder"


def test_bench_outside_a_checkout_says_where_it_runs(
    monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    """Installed from the wheel (no benchmarks/ beside the package): one line, status 2, no traceback."""
    from rigidrel_app import cli

    assert cli.checkout_root() == ROOT  # the suite runs from the checkout
    monkeypatch.setattr(cli, "checkout_root", lambda: None)
    with pytest.raises(SystemExit) as exit_:
        cli.main(["bench", "--quick", "--out", str(tmp_path / "out")])
    assert exit_.value.code == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "source checkout" in err and "Traceback" not in err
