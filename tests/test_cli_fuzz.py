"""Hypothesis over the command line: any bad parameter is one line on stderr and exit status 2.

Scenes and options come from the core's registry (every parameter of every scene, plus options
that belong to another scene).
"""

from __future__ import annotations

import math

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import rigidrel_core as rr
from rigidrel_app.cli import main

SCENES = list(rr.scene_descriptions())
OPTIONS = sorted({"--" + p.name.replace("_", "-") for d in rr.scene_descriptions().values() for p in d.parameters})
OPTIONS.append("--frame")

garbage = st.one_of(
    st.sampled_from(
        [
            "nan",
            "inf",
            "-inf",
            "1e309",
            "-1e309",
            "1e-400",
            "0",
            "-0",
            "1",
            "-1",
            "2",
            "abc",
            "",
            "0x10",
            "1,5",
            "none",
            "True",
            "[0.5]",
        ]
    ),
    st.floats(allow_nan=True, allow_infinity=True).map(repr),
    st.text(max_size=12),
)


@settings(max_examples=300, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(scene=st.sampled_from(SCENES), option=st.sampled_from(OPTIONS), value=garbage)
def test_any_parameter_gives_a_table_or_one_line(
    scene: str, option: str, value: str, capsys: pytest.CaptureFixture[str]
) -> None:
    try:
        code = main(["events", scene, option, value])
    except SystemExit as exc:
        code = int(exc.code or 0)
    out, err = capsys.readouterr()
    if code == 0:
        assert err == "" and "event" in out and "nan" not in out.lower()
    else:
        assert code == 2
        assert out == ""
        assert len(err.splitlines()) == 1 and err.startswith("rigidrel")
        assert "Traceback" not in err


def test_numbers_that_parse_but_are_out_of_range_name_the_parameter(capsys: pytest.CaptureFixture[str]) -> None:
    for args, name in (
        (["--v", "1.0"], "v must"),
        (["--eps", str(math.nextafter(1.0, 2.0))], "eps must"),
        (["--a-front", "1e-300"], "a_front must be a finite number > 1e-120"),
        (["--a-front", "1e-115", "--v", "0.9999999999999999"], "parameters must"),
    ):
        with pytest.raises(SystemExit) as info:
            main(["events", "constant-acceleration" if "--eps" not in args else "wall-collision", *args])
        assert info.value.code == 2
        assert name in capsys.readouterr().err
