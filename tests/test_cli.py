"""``rigidrel events``: the table a lecturer copies into slides, its JSON, and one-line errors."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

RIGIDREL = [sys.executable, "-m", "app.cli"]
ROOT = Path(__file__).resolve().parents[1]


def run(*args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run([*RIGIDREL, *args], capture_output=True, text=True, cwd=ROOT, timeout=60)


def test_events_table_for_case_one() -> None:
    r = run("events", "rod-collision")
    assert r.returncode == 0, r.stderr
    rows = {line.split()[0]: line.split()[1:] for line in r.stdout.splitlines() if line.strip()}
    assert rows["T_1"] == ["-0.75", "-1.25"]
    assert rows["T_1'"] == ["0.225", "-1.025"]
    assert rows["T_2'"] == ["0.4875", "1.1125"]
    assert "0.4382022472" in r.stdout  # V'_2 = 39/89
    assert "heat (rest energy created): 0" in r.stdout


def test_events_json_in_a_preset_frame() -> None:
    r = run("events", "rod-collision", "--eps", "0.5", "--frame", "barycentric", "--json")
    assert r.returncode == 0, r.stderr
    data = json.loads(r.stdout)
    assert data["frame"]["name"] == "barycentric"
    budget = data["budget"]
    # the barycentric frame: zero total momentum, conserved; heat appears as rest mass
    assert abs(budget["total_before"][1]) < 1e-15
    assert abs(budget["total_after"][1]) < 1e-15
    assert budget["heat"] > 0
    assert all(a > b for a, b in zip(budget["rest_mass_after"], budget["rest_mass_before"], strict=True))
    assert set(data["events"]) == {"T_1", "T_1'", "T_2", "T_2'"}


@pytest.mark.parametrize(
    ("args", "needle"),
    [
        (["events", "constant-acceleration", "--v", "1.5"], "v must be a finite number in (0, 1)"),
        (["events", "constant-acceleration", "--a-front", "2"], "a_front * length must be"),
        (["events", "rod-collision", "--v2", "0.9"], "v2 must be less than v1"),
        (["events", "rod-collision", "--v", "0.3"], "v must be one of the parameters of rod-collision"),
        (["events", "rod-collision", "--m1", "nan"], "m1 must be a finite number > 0"),
        (["events", "wall-collision", "--eps", "abc"], "not a number"),
        (["events", "wall-collision", "--frame", "1"], "frame_velocity must be a finite number in (-1, 1)"),
        (["events", "wall-collision", "--frame", "sideways"], "frame must be a velocity in (-1, 1) or one of"),
        (["events", "no-such-scene"], "invalid choice"),
        (["events"], "required"),
        (["frobnicate"], "invalid choice"),
    ],
)
def test_bad_parameters_one_line_exit_2(args: list[str], needle: str) -> None:
    r = run(*args)
    assert r.returncode == 2
    assert r.stdout == ""
    lines = r.stderr.splitlines()
    assert len(lines) == 1, r.stderr
    assert needle in lines[0]


def test_every_scene_prints() -> None:
    for scene in ("constant-acceleration", "deceleration", "velocity-change", "impulsive-start", "wall-collision"):
        r = run("events", scene, "--json")
        assert r.returncode == 0, r.stderr
        data = json.loads(r.stdout)
        assert data["events"], scene
