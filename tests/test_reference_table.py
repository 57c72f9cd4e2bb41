"""The committed reference table is what its generator produces (first case re-derived), and the
reference it is made from is independent of rigidrel_core and leaves mpmath's precision alone."""

from __future__ import annotations

import json
import random
import subprocess
import sys
import textwrap
from pathlib import Path

import mpmath as mp
import pytest

from tests.reference import make_reference
from tests.reference.oracle import (
    REFERENCE_DIGITS,
    REFERENCES,
    boost_event,
    frame_slice,
    proper_time_by_quadrature,
    reference_precision,
)

TABLE = Path(__file__).parent / "reference" / "reference.json"


@pytest.mark.slow  # 1.5-3.5 s of 50-digit bisection
def test_first_case_regenerates_identically() -> None:
    table = json.loads(TABLE.read_text())
    assert table["mp_dps"] == REFERENCE_DIGITS == 50
    case0 = make_reference.cases()[0]
    regenerated = make_reference.build_case(case0, random.Random(make_reference.FRAMES_SEED))
    assert regenerated == table["cases"][0]


def test_table_lists_the_generators_cases_in_order() -> None:
    """Kinds and parameters of every committed case, fixed and random, are the generator's."""
    table = json.loads(TABLE.read_text())
    cases = make_reference.cases()
    assert [c["kind"] for c in table["cases"]] == [c["kind"] for c in cases]
    for committed, case in zip(table["cases"], cases):
        params: dict[str, float | None] = case["params"]  # type: ignore[assignment]
        assert committed["params"] == {k: None if v is None else float(v).hex() for k, v in params.items()}


@pytest.mark.slow  # a new interpreter
def test_reference_never_imports_the_core_nor_changes_mpmaths_precision() -> None:
    """Import-linter-style: the reference package, its builders and slices, in a fresh interpreter,
    load no rigidrel_core module; mpmath's global precision stays at its default throughout."""
    script = textwrap.dedent(
        """
        import sys
        import mpmath as mp
        dps = mp.mp.dps
        from tests.reference.oracle import REFERENCES, F, boost_event, frame_slice
        assert mp.mp.dps == dps, ("import", mp.mp.dps)
        for ref in REFERENCES.values():
            scene = ref.build((0.0, 1.0), **ref.cases[0].params)
            frame_slice(scene.worldlines[0][-1], F(0.5), F(0.25))
            boost_event(next(iter(scene.events.values())), F(-0.5))
            assert mp.mp.dps == dps, (ref.kind, mp.mp.dps)
        core = sorted(m for m in sys.modules if m == "rigidrel_core" or m.startswith("rigidrel_core."))
        assert not core, core
        print(len(REFERENCES))
        """
    )
    proc = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, timeout=120)
    assert proc.returncode == 0, proc.stderr
    assert int(proc.stdout) == len(REFERENCES) >= 6


def test_slices_and_boosts_compute_at_50_digits_whatever_the_callers_precision() -> None:
    """Impulsive start to V = 1/2 (L0 = 1): the front end at lab t = 1/4 is at sqrt(17)/4 (Eq. (20)), and
    T_F = (gamma/2, gamma) (Eq. (21)) seen from beta = 1/4 is at t' = 2/(3 sqrt 5): to 1e-45 both at
    mpmath's default 15 digits and inside a 30-digit block, which stay as they were."""
    ref = REFERENCES["impulsive-start"].build((1.0,), v=0.5, length=1.0)
    front = ref.worldlines[0][0]
    for dps in (15, 30):
        with mp.workdps(dps):
            x = frame_slice(front, mp.mpf(0), mp.mpf(0.25))
            t_prime, _ = boost_event(ref.events["T_F"], mp.mpf(0.25))
            assert mp.mp.dps == dps
        with mp.workdps(REFERENCE_DIGITS):
            assert abs(x - mp.sqrt(17) / 4) < mp.mpf(10) ** -45
            assert abs(t_prime - 2 / (3 * mp.sqrt(5))) < mp.mpf(10) ** -45


def test_every_registered_scene_has_an_independent_reference() -> None:
    """A scene is its constructor, its description and its reference entry: the 50-digit reference
    has a builder for every scene in the registry, and the committed table has cases of each."""
    import rigidrel_core as rr
    from tests.reference.oracle import BUILDERS

    table = json.loads((Path(__file__).parent / "reference" / "reference.json").read_text())
    kinds = set(rr.scene_descriptions())
    assert kinds <= set(BUILDERS), kinds - set(BUILDERS)
    assert kinds <= {case["kind"] for case in table["cases"]}


@pytest.mark.slow  # about 3 s of 30-digit quadrature
@pytest.mark.parametrize(
    ("kind", "params"),
    [
        ("constant-acceleration", {"v": 0.6, "length": 1.0, "a_front": 0.5}),
        ("deceleration", {"v": 0.99, "length": 1.0, "a_front": 1e-3}),
        ("velocity-change", {"v_initial": -0.99, "v_final": 0.5, "length": 1.0, "a_front": 1e-7}),
        (
            "rod-collision",
            {"v1": 0.6, "v2": 0.0, "mass1": 1.0, "mass2": 2.0, "length1": 1.0, "length2": 1.0, "eps": 0.5},
        ),
    ],
)
def test_clocks_agree_with_quadrature_of_the_worldline(kind: str, params: dict[str, float]) -> None:
    """Each worldline's closed-form clock ``tau(t)`` (0 at ``start``) against ``int sqrt(1 - (dx/dt)^2) dt``
    from its position alone, before, during and after the change, to 1e-25 of max(|tau|, 1)."""
    with reference_precision():
        ref = REFERENCES[kind].build((0.0, 0.375, 1.0), **params)
    with mp.workdps(30):
        for rod in ref.worldlines:
            for w in rod:
                span = max(w.stop - w.start, 1)
                for t in (w.start - span / 3, w.start + span / 7, (w.start + w.stop) / 2, w.stop + span / 5):
                    tau = w.tau(t)
                    assert abs(tau - proper_time_by_quadrature(w, t)) < mp.mpf(10) ** -25 * max(abs(tau), 1)
                assert abs(w.tau(w.start)) < mp.mpf(10) ** -25 * span


def test_error_report_has_a_line_per_check_and_frame_class() -> None:
    """The report of the first case (the paper's Fig. 1: every frame class) lists each check in each
    frame class once, worst error first after the names."""
    from tests.reference import error_report

    table = json.loads(TABLE.read_text())
    lines, _ = error_report.report(table["cases"][:1], by_group=False)
    rows = [line.split()[:3] for line in lines[1:]]
    assert rows == [[c, f, "all"] for c in error_report.CHECKS for f in error_report.FRAME_CLASSES]
    for line in lines[1:]:
        float(line.split()[3])
