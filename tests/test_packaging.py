"""The wheel ships the two packages and their data, and neither the benchmarks nor the tests' oracle."""

from __future__ import annotations

import subprocess
import sys
import zipfile
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]


@pytest.mark.slow  # pip builds the wheel in a subprocess: 5-20 s
def test_the_wheel_holds_no_benchmark_or_oracle(tmp_path: Path) -> None:
    build = subprocess.run(
        [
            sys.executable,
            "-m",
            "pip",
            "wheel",
            "-q",
            "--no-deps",
            "--disable-pip-version-check",
            "-w",
            str(tmp_path),
            str(ROOT),
        ],
        capture_output=True,
        text=True,
        timeout=600,
    )
    assert build.returncode == 0, build.stderr
    (wheel,) = tmp_path.glob("rigidrel-*.whl")
    names = zipfile.ZipFile(wheel).namelist()
    tops = {n.split("/")[0] for n in names}
    assert tops == {"rigidrel_core", "rigidrel_app", f"{wheel.name.split('-py')[0]}.dist-info"}, tops
    modules = [n for n in names if n.endswith(".py")]
    benchmark_or_oracle = [
        n
        for n in modules
        if {"bench", "benchmarks", "study", "oracle", "reference", "tests"} & set(n.split("/")[:-1])
        or n.rsplit("/", 1)[-1].startswith(("bench_", "measure_"))
        or n.rsplit("/", 1)[-1] in {"load.py", "mpmath_slices.py"}
    ]
    assert benchmark_or_oracle == [], benchmark_or_oracle
    assert "rigidrel_app/lessons/paper.toml" in names and "rigidrel_core/py.typed" in names
