"""``rigidrel events`` prints the light signals and the causal verdicts the core computes."""

from __future__ import annotations

import json

import pytest

from rigidrel_app.cli import main


def test_wall_crash_prints_the_signal_and_the_verdict(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["events", "wall-collision", "--eps", "0"]) == 0
    out = capsys.readouterr().out
    rows = {line.split()[0]: line.split()[1:3] for line in out.splitlines() if line[:2] in ("S ", "R ")}
    assert rows["S"] == ["1", "1"]  # the far end, at rest at x = 1 since t = 0, sees the contact's light at t = 1
    assert rows["R"] == ["2", "0"]
    assert "lies outside the light cone of the contact" in out
    assert "in any frame" in out


def test_json_has_the_same_signals_in_a_boosted_frame(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["events", "wall-collision", "--v", "0.6", "--eps", "1", "--frame", "rod before", "--json"]) == 0
    report = json.loads(capsys.readouterr().out)
    first = report["signals"][0]
    assert first["arrival"] == "S"
    # lab (2, 2) seen from the rod before (beta = -0.6): t' = x' = 2 * sqrt(1.6 / 0.4) = 4
    assert (first["t"], first["x"]) == pytest.approx((4.0, 4.0), rel=1e-15)
    assert report["verdicts"] and all(v.endswith(".") for v in report["verdicts"])
