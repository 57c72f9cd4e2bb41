"""``rigidrel events``: the table a lecturer copies into slides, its JSON, and one-line errors.

The command runs in-process (:func:`rigidrel_app.cli.main`, its output captured) but for a few
representative cases run as a user runs it, in a new interpreter (marked slow): the first table, a
bad value's exit status, and ``serve``'s refusals (in-process, a regression would start a server).
``python -m tests.sweeps.cli_subprocess`` runs every case here in a new interpreter.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
from collections.abc import Callable
from pathlib import Path

import pytest

import rigidrel_core as rr
from rigidrel_app.cli import main

RIGIDREL = [sys.executable, "-m", "rigidrel_app.cli"]
ROOT = Path(__file__).resolve().parents[1]
#: Every case in a new interpreter (the full sweep), not only the representative ones.
ALL_IN_SUBPROCESS = os.environ.get("RIGIDREL_FULL_SWEEP") == "1"
pytestmark = [pytest.mark.slow] if ALL_IN_SUBPROCESS else []
Run = Callable[..., subprocess.CompletedProcess[str]]


def subprocess_run(*args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run([*RIGIDREL, *args], capture_output=True, text=True, cwd=ROOT, timeout=60)


@pytest.fixture
def run(capsys: pytest.CaptureFixture[str]) -> Run:
    """``run(*args)``: the command's exit status, stdout and stderr, from ``main`` in this process."""

    def run(*args: str) -> subprocess.CompletedProcess[str]:
        if ALL_IN_SUBPROCESS:
            return subprocess_run(*args)
        capsys.readouterr()
        try:
            code = main(list(args))
        except SystemExit as exc:
            code = exc.code if isinstance(exc.code, int) else 0 if exc.code is None else 1
        out, err = capsys.readouterr()
        return subprocess.CompletedProcess([*RIGIDREL, *args], code, out, err)

    return run


@pytest.mark.slow  # a new interpreter, as a user runs it
def test_events_table_for_case_one() -> None:
    r = subprocess_run("events", "rod-collision")
    assert r.returncode == 0, r.stderr
    rows = {line.split()[0]: line.split()[1:] for line in r.stdout.splitlines() if line.strip()}
    assert rows["T_1"][:2] == ["-0.75", "-1.25"]
    assert rows["T_1'"][:2] == ["0.225", "-1.025"]
    assert rows["T_2'"][:2] == ["0.4875", "1.1125"]
    assert " ".join(rows["T_2'"][2:]) == rr.describe("rod-collision").event("T_2'").meaning
    assert "0.4382022472" in r.stdout  # V'_2 = 39/89
    assert "heat (rest energy created): 0" in r.stdout


def test_events_json_in_a_preset_frame(run: Run) -> None:
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


BAD_EVENTS = [
    (["events", "constant-acceleration", "--v", "1.5"], "v must be a finite number in (0, 1)"),
    (["events", "constant-acceleration", "--a-front", "2"], "a_front * length must be"),
    (["events", "rod-collision", "--v2", "0.9"], "v2 must be less than v1"),
    (["events", "rod-collision", "--v", "0.3"], "--v is not an option of rod-collision; its parameters are --v1"),
    (["events", "rod-collision", "--mass2", "0"], "mass2 must be a finite number in [1e-120, 1e+120]; got 0.0"),
    (["events", "rod-collision", "--mass1", "nan"], "mass1 must be a finite number in [1e-120, 1e+120]"),
    (["events", "rod-collision", "--m2", "2"], "--m2 is now --mass2"),
    (["events", "bell-spaceships", "--acceleration", "0.5"], "--acceleration is now --a-back"),
    (["events", "wall-collision", "--eps", "abc"], "not a number"),
    (["events", "wall-collision", "--frame", "1"], "beta must be a finite number in (-1, 1)"),
    (["events", "wall-collision", "--frame", "sideways"], "frame must be a velocity in (-1, 1) or one of"),
    (["events", "no-such-scene"], "invalid choice"),
    (["events"], "required"),
    (["frobnicate"], "invalid choice"),
]
#: ``serve``'s refusals: always in a new interpreter (in-process, a regression would serve forever).
BAD_SERVE = [
    (["serve", "rod-collision", "--v2", "0.9"], "v2 must be less than v1 = 0.6"),
    (["serve", "wall-collision", "--frame", "barycentric"], "frame must be a velocity in (-1, 1) or one of"),
    (
        ["serve", "rod-collision", "--frame", "0.999"],
        "--frame must be in [-0.99, 0.99] (the app's β slider) or one of the scene's frames; got 0.999",
    ),
]


def assert_one_line_exit_2(r: subprocess.CompletedProcess[str], needle: str) -> None:
    assert r.returncode == 2
    assert r.stdout == ""
    lines = r.stderr.splitlines()
    assert len(lines) == 1, r.stderr
    assert needle in lines[0]


@pytest.mark.parametrize(("args", "needle"), BAD_EVENTS)
def test_bad_parameters_one_line_exit_2(run: Run, args: list[str], needle: str) -> None:
    assert_one_line_exit_2(run(*args), needle)


@pytest.mark.slow  # a new interpreter: its exit status and its stderr as a shell sees them
@pytest.mark.parametrize(("args", "needle"), [BAD_EVENTS[0], *BAD_SERVE])
def test_bad_parameters_one_line_exit_2_from_a_new_interpreter(args: list[str], needle: str) -> None:
    assert_one_line_exit_2(subprocess_run(*args), needle)


@pytest.mark.parametrize("scene", list(rr.scene_descriptions()))
def test_every_registered_scene_prints(run: Run, scene: str) -> None:
    r = run("events", scene, "--json")
    assert r.returncode == 0, r.stderr
    data = json.loads(r.stdout)
    assert list(data["events"]) == [e.name for e in rr.describe(scene).events]


def test_options_and_help_come_from_the_registry(run: Run) -> None:
    r = run("events", "rod-collision", "--help")
    assert r.returncode == 0
    for p in rr.describe("rod-collision").parameters:
        assert "--" + p.name.replace("_", "-") in r.stdout
    assert "--v " not in r.stdout  # another scene's option
    listing = run("scenes")
    assert listing.returncode == 0
    for kind, d in rr.scene_descriptions().items():
        assert kind in listing.stdout and d.title in listing.stdout


def test_velocity_change_takes_none_for_an_impulse(run: Run) -> None:
    r = run("events", "velocity-change", "--v-initial", "0.3", "--a-front", "none", "--json")
    assert r.returncode == 0, r.stderr
    events = json.loads(r.stdout)["events"]
    assert events["T_B0"] == events["T_B"]  # the near end jumps: starts and stops at once
