"""Bad input: every core entry point raises ValueError naming the parameter and its allowed range."""

from __future__ import annotations

import math
import re
from collections.abc import Callable
from typing import Any

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import rigidrel_core as rr

GOOD: dict[str, tuple[Callable[..., rr.Scene], dict[str, Any]]] = {
    "constant_acceleration": (rr.constant_acceleration, {"v": 0.6, "length": 1.0, "a_front": 0.5}),
    "deceleration": (rr.deceleration, {"v": 0.6, "length": 1.0, "a_front": 0.5}),
    "velocity_change": (rr.velocity_change, {"v_initial": 0.2, "v_final": 0.6, "length": 1.0, "a_front": 0.5}),
    "impulsive_start": (rr.impulsive_start, {"v": 0.6, "length": 1.0}),
    "wall_collision": (rr.wall_collision, {"v": 0.6, "length": 1.0, "eps": 0.5}),
    "rod_collision": (
        rr.rod_collision,
        {"v1": 0.6, "v2": 0.0, "m1": 1.0, "m2": 2.0, "l1": 1.0, "l2": 1.0, "eps": 1.0},
    ),
}

#: (parameter, bad value, allowed-range text that must appear)
BAD = [
    ("v", 0.0, "(0, 1)"),
    ("v", 1.0, "(0, 1)"),
    ("v", -0.5, "(0, 1)"),
    ("v", 1.5, "(0, 1)"),
    ("length", 0.0, "> 0"),
    ("length", -1.0, "> 0"),
    ("length", math.inf, "> 0"),
    ("a_front", 0.0, "> 0"),
    ("a_front", 2.0, "(0, 1)"),
    ("a_front", 1.0, "(0, 1)"),
    ("eps", -0.1, "[0, 1]"),
    ("eps", 1.1, "[0, 1]"),
    ("v1", 1.0, "(-1, 1)"),
    ("v2", -1.0, "(-1, 1)"),
    ("v2", 0.6, "less than v1"),
    ("v2", 0.7, "less than v1"),
    ("m1", 0.0, "> 0"),
    ("m2", -2.0, "> 0"),
    ("m2", math.inf, "> 0"),
    ("l1", 0.0, "> 0"),
    ("l2", math.nan, "> 0"),
    ("v_initial", 1.0, "(-1, 1)"),
    ("v_final", 0.2, "different from v_initial"),
]


def cases() -> list[tuple[str, str, Any, str]]:
    out = []
    for fname, (_, good) in GOOD.items():
        for name, value, allowed in BAD:
            if name in good:
                out.append((fname, name, value, allowed))
    return out


@pytest.mark.parametrize(("fname", "name", "value", "allowed"), cases())
def test_bad_parameter_is_named_with_its_range(fname: str, name: str, value: Any, allowed: str) -> None:
    maker, good = GOOD[fname]
    with pytest.raises(ValueError) as info:
        maker(**{**good, name: value})
    msg = str(info.value)
    named = name if name != "a_front" or value <= 0 else "a_front * length"
    assert named in msg and allowed in msg, msg


UNIVERSALLY_BAD = st.sampled_from([math.nan, math.inf, -math.inf, None, "0.5", True, 1j, [0.5], object()])
VELOCITY_NAMES = {"v", "v1", "v2", "v_initial", "v_final"}


def bad_values(name: str) -> st.SearchStrategy[Any]:
    """Values outside the documented range of ``name`` (plus wrong types)."""
    if name in VELOCITY_NAMES:
        out = st.one_of(st.floats(1.0, 1e300), st.floats(-1e300, -1.0))
        if name == "v":
            out = st.one_of(out, st.floats(-1.0, 0.0))
    elif name == "eps":
        out = st.one_of(st.floats(-1e300, -1e-300), st.floats(1.0, 1e300, exclude_min=True))
    else:  # lengths and masses
        out = st.floats(-1e300, 0.0)
    return st.one_of(UNIVERSALLY_BAD, out)


@settings(max_examples=400, deadline=None)
@given(fname=st.sampled_from(list(GOOD)), data=st.data())
def test_any_bad_value_raises_value_error_naming_it(fname: str, data: st.DataObject) -> None:
    maker, good = GOOD[fname]
    name = data.draw(st.sampled_from(sorted(k for k in good if k != "a_front")))
    bad = data.draw(bad_values(name))
    with pytest.raises(ValueError, match=re.escape(name)):
        maker(**{**good, name: bad})


@pytest.mark.parametrize("beta", [1.0, -1.0, 1.5, math.nan, math.inf, None, "0.1", True])
def test_bad_frame_velocity(beta: Any) -> None:
    s = rr.impulsive_start(0.6, 1.0)
    with pytest.raises(ValueError, match=r"frame_velocity must be a finite number in \(-1, 1\)"):
        s.positions(np.array([0.0]), beta)
    with pytest.raises(ValueError, match="frame_velocity"):
        s.events_in(beta)


@pytest.mark.parametrize("t", [[0.0, math.nan], [math.inf], [-1e301], ["x"], [[0.0], [1.0, 2.0]]])
def test_bad_times(t: Any) -> None:
    s = rr.impulsive_start(0.6, 1.0)
    with pytest.raises(ValueError, match=r"^t must be finite real numbers with \|t\| <= 1e\+300"):
        s.positions(t)


@pytest.mark.parametrize("f", [[-0.1], [1.5], [math.nan], [[0.5]]])
def test_bad_fractions(f: Any) -> None:
    s = rr.impulsive_start(0.6, 1.0)
    with pytest.raises(ValueError, match=r"fractions must be an array of numbers in \[0, 1\]"):
        s.material_positions(f, [0.0])


def test_times_of_any_shape() -> None:
    s = rr.rod_collision(0.6, 0.0, 1.0, 2.0, 1.0, 1.0, 1.0)
    assert s.positions(0.0).shape == (2, 2)
    assert s.positions(np.zeros((3, 4))).shape == (2, 2, 3, 4)
    assert s.positions([]).shape == (2, 2, 0)
    assert s.lengths(np.zeros((3, 4))).shape == (2, 3, 4)


def test_extreme_but_accepted_parameters_give_finite_output() -> None:
    for scene in (
        rr.constant_acceleration(1 - 2**-53, 1.0, 1e-100),
        rr.constant_acceleration(0.5, 1e6, (1 - 2**-52) / 1e6),
        rr.rod_collision(1 - 2**-53, -1 + 2**-53, 1e-6, 1e6, 1e-6, 1e6, 0.0),
        rr.wall_collision(1 - 2**-53, 1e6, 1.0),
    ):
        t = np.linspace(*scene.time_window(0.999999), 64)
        assert np.all(np.isfinite(scene.positions(t, 0.999999)))
        assert np.all(np.isfinite(scene.lengths(t, -0.999999)))


def test_unrepresentable_scene_is_refused_by_name() -> None:
    with pytest.raises(ValueError, match=r"parameters must be such that every lab event .* within 1e\+120"):
        rr.constant_acceleration(0.5, 1.0, 1e-300)
