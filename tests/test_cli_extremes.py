"""Hypothesis over every scene's parameters at their extremes: no accepted value crashes a later step.

For each registered scene, any subset of its parameters is set to a value at an edge of what it
accepts (its domain's ends or the floats just inside them, its slider's and typical range's ends,
the smallest and largest floats, ``none`` for an optional one), in any frame from the lab to
``|beta| = 1 - 2**-53``. ``rigidrel events`` (in-process: the events, the budget of each physical
system, the light signals, the verdicts and the notes, as text and as JSON) then either prints
everything, finite, or refuses in one line on stderr with exit status 2, as for any bad argument;
the app, given the same values as a scenario line, refuses it with a notice or draws it.
"""

from __future__ import annotations

import json
import math
import shlex

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import rigidrel_core as rr
from rigidrel_app.cli import main
from rigidrel_app.view.scenario import parse_scenario
from rigidrel_app.view.scene_view import build_drawing, lane_states, readout_markdown
from rigidrel_app.view.state import build

SCENES = list(rr.scene_descriptions())
#: Frames from the lab to the fastest a float64 velocity allows.
FRAMES = ["lab", "0.3", "-0.999999", "0.9999999999999999", "-0.9999999999999999"]


def extremes(p: rr.Parameter) -> tuple[list[str], list[str]]:
    """Values at the edges of what ``p`` accepts, as the command line takes them: ``(accepted, refused)``
    by its own domain (the scene may still refuse an accepted one for what it makes of the others)."""
    d = p.domain
    values: set[float] = {5e-324, -5e-324, 1e-300, 1e-120, 1e120, 1e300, 1.7976931348623157e308, -1e300, 0.0}
    for end, closed, inward in ((d.lo, d.lo_closed, math.inf), (d.hi, d.hi_closed, -math.inf)):
        if math.isfinite(end):
            values |= {end, math.nextafter(end, inward), math.nextafter(math.nextafter(end, inward), inward)}
            if not closed:
                values.add(math.nextafter(end, -inward))
    if p.slider is not None or p.typical is not None:
        values |= set(p.sample_range())
    if p.default is not None:
        values.add(p.default)
    accepted = [repr(v) for v in sorted(values) if v in d]
    refused = [repr(v) for v in sorted(values) if v not in d]
    return ([*accepted, "none"] if p.optional else accepted), refused


@st.composite
def command(draw: st.DrawFn) -> list[str]:
    kind = draw(st.sampled_from(SCENES))
    d = rr.describe(kind)
    args = ["events", kind]
    for p in d.parameters:
        if draw(st.booleans()):
            accepted, refused = extremes(p)
            pool = refused if refused and draw(st.integers(0, 9)) == 0 else accepted
            args.append(f"--{p.name.replace('_', '-')}={draw(st.sampled_from(pool))}")  # = for -1e300
    frame = draw(st.sampled_from([*FRAMES, *d.frames]))
    return [*args, f"--frame={frame}", *(["--json"] if draw(st.booleans()) else [])]


@settings(max_examples=200, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(args=command())
def test_every_accepted_extreme_prints_and_every_refused_one_is_one_line(
    args: list[str], capsys: pytest.CaptureFixture[str]
) -> None:
    try:
        code = main(args)
    except SystemExit as exc:
        code = int(exc.code or 0)
    out, err = capsys.readouterr()
    if code == 0:
        assert err == ""
        assert "nan" not in out.lower() and "inf" not in out.replace("infinite", "").lower(), out
        if "--json" in args:
            json.loads(out)  # allow_nan=False when written: finite
        else:
            assert "event" in out
    else:
        assert code == 2, (code, err)
        assert out == ""
        assert len(err.splitlines()) == 1 and err.startswith("rigidrel"), err


@pytest.mark.parametrize("value", ["1e300", "-1e300", "1e121", "1.7976931348623157e308"])
def test_a_door_time_beyond_the_scene_is_refused_in_one_line(value: str, capsys: pytest.CaptureFixture[str]) -> None:
    """``--door-time 1e300`` once printed a traceback from a later step and exited 1."""
    with pytest.raises(SystemExit) as info:
        main(["events", "pole-barn", f"--door-time={value}"])
    assert info.value.code == 2
    err = capsys.readouterr().err
    assert len(err.splitlines()) == 1 and "door_time must be a finite number in [-1e+120, 1e+120]" in err


def test_a_door_time_at_the_bound_prints(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["events", "pole-barn", "--door-time", "1e120", "--frame", "pole before"]) == 0
    assert "door closes" in capsys.readouterr().out


@settings(max_examples=80, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(args=command())
def test_the_app_draws_every_accepted_extreme(args: list[str]) -> None:
    """The same edges as a scenario line: the app refuses the line with a notice, or draws it (the
    diagrams, the lanes at the window's ends, the readout): no accepted value fails a later step."""
    frame = next(a for a in args if a.startswith("--frame=")).split("=", 1)[1]
    options = [a.replace("=", " ", 1) for a in args[2:] if a.startswith("--") and a not in ("--json",)]
    line = " ".join([args[1], *(o for o in options if not o.startswith("--frame")), "--frame", shlex.quote(frame)])
    try:
        resolved = build(parse_scenario(line + " --layers all").settings)
    except ValueError:  # a ScenarioError or the core's ParameterError: a notice in the app
        return
    drawn = build_drawing(resolved)
    for now in drawn.window:
        lane_states(drawn, now)
    assert readout_markdown(resolved)
