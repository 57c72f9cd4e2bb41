"""Every path of the position sampler gives bitwise the outputs of the sampler before it was made faster.

``MotionPlan.positions`` picks a path by input: one sample at a time in Python floats for a
handful of samples, the branch-free form over all rows for short inputs, blocks of the
pieces each row is on for long sorted inputs, and per-block piece masks for long shuffled
ones. The references below are copies of the two forms the sampler had before those paths
(and of its choice between them); every path must reproduce them byte for byte, on many
scenes, frames, material points and time sets, shuffled times and exact switch times
included.
"""

from __future__ import annotations

import math

import numpy as np
import numpy.typing as npt
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import rigidrel_core as rr
from rigidrel_core._motion import MotionPlan
from rigidrel_core._plastic import plan_rods
from tests.strategies import scene_and_frame

FloatArray = npt.NDArray[np.float64]

SETTINGS = settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
#: Input sizes around every threshold of the sampler's choice of path (and several blocks long).
SIZES = (1, 2, 3, 5, 8, 11, 17, 31, 32, 33, 63, 64, 65, 256, 2047, 2048, 2049, 4095, 4096, 32768, 32769, 70000)


def reference_branch_free(plan: MotionPlan, t: FloatArray) -> FloatArray:
    """The branch-free form as it was: every piece at every time, then two selections."""
    col = {k: getattr(plan, k)[:, None] for k in ("sign", "t_vertex", "q0", "x_hyp", "t_start", "t_stop")}
    col |= {k: getattr(plan, k)[:, None] for k in ("x0_start", "w_start", "x0_stop", "w_stop")}
    with np.errstate(over="ignore", invalid="ignore"):
        s = t - col["t_vertex"]
        s *= s
        s += plan.radius[:, None] ** 2
        np.sqrt(s, out=s)
        s += col["q0"]
        h = t - 2.0 * col["t_vertex"]
        h *= t
        h /= s
        h *= col["sign"]
        h += col["x_hyp"]
        before = col["w_start"] * t
        before += col["x0_start"]
        after = col["w_stop"] * t
        after += col["x0_stop"]
        h = np.where(t < col["t_start"], before, h)
        return np.where(t > col["t_stop"], after, h)


def reference_sorted(plan: MotionPlan, t: FloatArray) -> FloatArray:
    """The piecewise form for sorted times as it was: each row's three pieces over all times at once."""
    rows = plan.radius.size
    out = np.empty((rows, t.size))
    i0 = np.searchsorted(t, plan.t_start, side="left")
    i1 = np.searchsorted(t, plan.t_stop, side="right")
    for r in range(rows):
        a, b = int(i0[r]), int(i1[r])
        row = out[r]
        if a > 0:
            np.multiply(t[:a], plan.w_start[r], out=row[:a])
            row[:a] += plan.x0_start[r]
        if b > a:
            seg = row[a:b]
            ts = t[a:b]
            np.subtract(ts, plan.t_vertex[r], out=seg)
            seg *= seg
            seg += plan.radius[r] ** 2
            np.sqrt(seg, out=seg)
            seg += plan.q0[r]
            num = ts - 2.0 * plan.t_vertex[r]
            num *= ts
            np.divide(num, seg, out=seg)
            seg *= plan.sign[r]
            seg += plan.x_hyp[r]
        if b < t.size:
            np.multiply(t[b:], plan.w_stop[r], out=row[b:])
            row[b:] += plan.x0_stop[r]
    return out


def reference_positions(plan: MotionPlan, t: FloatArray) -> FloatArray:
    """The sampler as it was: the sorted form from 2048 sorted times on, the branch-free form otherwise."""
    if t.size >= 2048 and bool(np.all(t[1:] >= t[:-1])):
        return reference_sorted(plan, t)
    return reference_branch_free(plan, t)


@st.composite
def time_sets(draw: st.DrawFn, scene: rr.Scene, frame: rr.Frame, fractions: FloatArray) -> FloatArray:
    """Times of one call: sorted across the scene's window (or past it), shuffled, or in blocks;
    with the switch times themselves repeated in, and now and then a time of +-1e300."""
    n = draw(st.sampled_from(SIZES))
    lo, hi = scene.time_window(frame=frame)
    scale = draw(st.sampled_from([1.0, 0.1, 3.0]))
    centre = 0.5 * (lo + hi)
    t = np.linspace(centre - scale * (centre - lo), centre + scale * (hi - centre), n)
    switch = scene.switch_times(frame=frame, fractions=fractions).ravel()
    if draw(st.booleans()):  # exact switch times (where two pieces meet), each twice
        k = min(n, 2 * switch.size)
        t[:k] = np.repeat(switch, 2)[:k]
        t.sort()
    order = draw(st.sampled_from(["sorted", "shuffled", "reversed", "blocks"]))
    rng = np.random.default_rng(draw(st.integers(0, 2**32 - 1)))
    if order == "shuffled":
        t = rng.permutation(t)
    elif order == "reversed":
        t = t[::-1].copy()
    elif order == "blocks":  # sorted within blocks, not across them
        t = np.concatenate([rng.permutation(b) for b in np.array_split(t, max(1, n // 3000))])
    if draw(st.booleans()) and n > 1 and order != "sorted":
        t[rng.integers(0, n)] = draw(st.sampled_from([1e300, -1e300]))
    return t


fraction_sets = st.one_of(
    st.just(np.array([0.0, 1.0])),
    st.lists(st.floats(0.0, 1.0), min_size=1, max_size=11).map(lambda f: np.array(sorted(f))),
)


@SETTINGS
@given(scene_frame=scene_and_frame(), fractions=fraction_sets, data=st.data())
def test_every_path_matches_the_sampler_as_it_was(
    scene_frame: tuple[rr.Scene, rr.Frame], fractions: FloatArray, data: st.DataObject
) -> None:
    """Through the plan and through the scene's samplers (which pass the order their time check
    found): the path chosen, whichever it is, gives what the sampler gave before."""
    scene, frame = scene_frame
    plan = plan_rods([r.motion for r in scene.rods], frame, fractions)
    t = data.draw(time_sets(scene, frame, fractions))
    expected = reference_positions(plan, t)
    assert plan.positions(t).tobytes() == expected.tobytes()
    got = scene.material_positions(t, frame=frame, fractions=fractions)
    assert got.tobytes() == expected.reshape(scene.n_rods, fractions.size, t.size).tobytes()
    if np.array_equal(fractions, rr.ENDS):
        assert scene.positions(t, frame=frame).tobytes() == got.tobytes()


@SETTINGS
@given(scene_frame=scene_and_frame(), fractions=fraction_sets, data=st.data())
def test_each_path_matches_its_reference_at_any_size(
    scene_frame: tuple[rr.Scene, rr.Frame], fractions: FloatArray, data: st.DataObject
) -> None:
    """Each path called directly, at sizes it is not chosen for too: the sorted path equals the
    sorted reference on sorted times; the Python-float, branch-free and shuffled paths equal the
    branch-free reference on any times."""
    scene, frame = scene_frame
    plan = plan_rods([r.motion for r in scene.rods], frame, fractions)
    lo, hi = scene.time_window(frame=frame)
    n = data.draw(st.sampled_from(SIZES))
    t = np.linspace(lo, hi, n)
    shuffled = np.random.default_rng(n).permutation(t)
    assert plan._positions_sorted(t).tobytes() == reference_sorted(plan, t).tobytes()
    for times in (t, shuffled):
        expected = reference_branch_free(plan, times).tobytes()
        assert plan._positions_block(times).tobytes() == expected
        assert plan._positions_shuffled(times).tobytes() == expected
        if n <= 64:
            assert plan._positions_scalar(times).tobytes() == expected


def test_the_benchmark_cases_match() -> None:
    """The cases of benchmarks/bench_core.py at a tenth of their size, sorted and shuffled."""
    from benchmarks.bench_core import curved_case, paper_case

    rng = np.random.default_rng(0)
    for scene, frame, t in (paper_case(100_000), curved_case(100_000)):
        plan = plan_rods([r.motion for r in scene.rods], frame, rr.ENDS)
        assert scene.positions(t, frame=frame).tobytes() == reference_sorted(plan, t).tobytes()
        shuffled = rng.permutation(t)
        assert scene.positions(shuffled, frame=frame).tobytes() == reference_branch_free(plan, shuffled).tobytes()


@pytest.mark.parametrize("a_front", [0.09994998749687423, 0.1883720930232558])
def test_each_path_keeps_its_own_square_of_the_radius(a_front: float) -> None:
    """Scenes whose radius squared differs in the last bit between ``rho ** 2`` (libm ``pow``, the
    sorted path's) and ``rho * rho`` (the branch-free form's): the two forms disagree there in the
    last bit of some positions, and each path must still give exactly what its form gave."""
    scene = rr.constant_acceleration(v=0.8, length=1.0, a_front=a_front)
    plan = plan_rods([r.motion for r in scene.rods], rr.LAB, rr.ENDS)
    assert any(r**2 != r * r for r in plan.radius)
    switch = scene.switch_times(frame=rr.LAB).reshape(-1, 2)
    t = np.linspace(switch[:, 0].max(), switch[:, 1].min(), 40_000)
    sorted_form, branch_free = reference_sorted(plan, t), reference_branch_free(plan, t)
    assert sorted_form.tobytes() != branch_free.tobytes()
    assert scene.positions(t).tobytes() == sorted_form.reshape(1, 2, -1).tobytes()
    shuffled = t[np.random.default_rng(1).permutation(t.size)]
    assert scene.positions(shuffled).tobytes() == reference_branch_free(plan, shuffled).reshape(1, 2, -1).tobytes()
    for n in (1, 5, 300):
        assert scene.positions(t[:n]).tobytes() == branch_free[:, :n].reshape(1, 2, -1).tobytes()


@pytest.mark.parametrize("bad", [float("nan"), float("inf"), -float("inf"), 1e301, -1e301])
@pytest.mark.parametrize("where", [0, 2500, -1])
def test_a_bad_time_in_a_long_sorted_input_is_refused(bad: float, where: int) -> None:
    """Sorted times are checked through their ends; a NaN anywhere breaks the order, an
    out-of-range value is an end: either way the call is refused, naming the value."""
    scene = rr.build_scene("rod-collision")
    t = np.linspace(-1.0, 1.0, 5000)
    t[where] = bad
    if not math.isnan(bad):
        t.sort()  # still sorted, the bad value at an end
    with pytest.raises(rr.ParameterError, match="t must be finite real numbers") as caught:
        scene.positions(t)
    assert repr(bad) in str(caught.value)


def test_ends_are_read_only() -> None:
    """``rr.ENDS`` is the samplers' default argument and part of the plan cache's key (by identity):
    writing to it, or making it writeable again, is refused, and the scene's answers stay put."""
    scene = rr.build_scene("rod-collision")
    before = scene.velocities([0.1]).tobytes()
    with pytest.raises(ValueError, match="read-only"):
        rr.ENDS[1] = 0.5
    with pytest.raises(ValueError, match="WRITEABLE"):
        rr.ENDS.flags.writeable = True
    with pytest.raises(ValueError, match="read-only"):
        rr.ENDS *= 2.0
    assert rr.ENDS.tolist() == [0.0, 1.0]
    assert scene.velocities([0.1]).tobytes() == before


def test_sorted_times_below_the_old_threshold_square_as_the_old_sampler_did() -> None:
    """From 1024 to 2047 sorted times the sorted path runs, where the old sampler used its
    branch-free form, which squares the radius as ``rho * rho`` (``pow`` can differ in the last bit:
    this radius, found by the test above, is one such). Bit for bit, on both sides of 2048."""
    scene = rr.build_scene("constant-acceleration", v=0.5, a_front=0.2657163731543798)
    plan = plan_rods([r.motion for r in scene.rods], rr.LAB, np.array([0.0, 1.0]))
    radius = float(plan.radius[1])
    assert radius * radius != float(np.float64(radius) ** 2)  # the case: the two squares differ
    lo, hi = scene.time_window(frame=rr.LAB)
    for n in (1024, 2047, 2048, 4096):
        t = np.linspace(lo, hi, n)
        assert plan.positions(t).tobytes() == reference_positions(plan, t).tobytes(), n
