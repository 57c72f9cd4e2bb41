"""The core's examples (examples/01_core/) run as scripts and print the numbers they promise.

Each file runs with runpy as ``__main__``, as ``python examples/01_core/NN_name.py`` would; scenes
an example registers are forgotten afterwards. A new example needs its expected numbers here.
"""

from __future__ import annotations

import ast
import runpy
from pathlib import Path

import pytest

import rigidrel_core as rr
from tests.strategies import isolated_registry

EXAMPLES = Path(__file__).parents[1] / "examples" / "01_core"

#: What each example must print (substrings of its stdout).
EXPECTED: dict[str, list[str]] = {
    "01_paper_scene.py": [
        # lab: T_1 = -3/4 at x = -5/4, T'_1 = 9/40, T_2 = 0 at x = L0, T'_2 = 39/80 at x = 89/80
        "T_1   t = -0.750000  x = -1.250000",
        "T_1'  t = +0.225000  x = -1.025000",
        "T_2   t = +0.000000  x = +1.000000",
        "T_2'  t = +0.487500  x = +1.112500",
        # the barycentric frame moves at u = 3/13; there the far ends stop as late as they started early
        "barycentric frame (beta = 0.230769)",
        "T_1   t = -0.474342",
        "T_1'  t = +0.474342",
        "T_2   t = -0.237171",
        "T_2'  t = +0.237171",
        "V' = -0.219512 = -9/41",
        "V' = +0.438202 = 39/89",
    ],
    "02_custom_frame.py": [
        "0.6 (+) 0.6 = 0.882353 (15/17 = 0.882353)",
        "0.693147 + 0.693147 = 1.386294",
        "seen from a: [[1.25, -0.75], [1.75, -0.25]]",
        "seen from b @ a: [[2.125, -1.875], [2.375, -1.625]]",
        "seen from b after a: [[2.125, -1.875], [2.375, -1.625]]",
        "beta = 0.5: t' = 5.773503e-01, x' = 5.773503e-01, t' - x' = 0.0",
        "beta = 0.99: t' = 7.088812e-02, x' = 7.088812e-02, t' - x' = 0.0",
        "beta = 0.999999999: t' = 2.236068e-05, x' = 2.236068e-05, t' - x' = 0.0",
        "a rocket at 0.882353 in the lab sees T_F at t' = -0.750000, x' = 1.250000",
    ],
    "03_new_scene.py": [
        "Kick from the right: final velocity -0.600000",
        # the kicked right end jumps at once; the left end follows x = 1 - sqrt(1 + t^2) until gamma V L0 = 3/4
        "T_B   lab t = +0.000000 x = +1.000000   rod after t' = +0.750000",
        "T_F0  lab t = +0.000000 x = +0.000000   rod after t' = +0.000000",
        "T_F   lab t = +0.750000 x = -0.250000   rod after t' = +0.750000",
        "(the end F stops changing velocity)",
    ],
    "04_light_signals.py": [
        "light from the contact reaches the far end at lab (t, x) = (2.0, 2.0)",
        # the time order of T_1 and the contact depends on the frame; the arrival is after T_1' in each
        "lab         T_1 t = -0.7500 (before the contact)  T_1' t = +0.7500  arrival t = +2.0000",
        "rod before  T_1 t = +0.0000 (at the same time as the contact)  T_1' t = +1.8750  arrival t = +4.0000",
        "rod after   T_1 t = -1.8750 (before the contact)  T_1' t = +0.0000  arrival t = +1.0000",
        "(the lab's arrival carried over: +4.0000)",
        "contact -> T_1: spacelike, interval -1.0000",
        "contact -> T_1': spacelike, interval -1.0000",
        "no signal from the contact can have caused it, in any frame",
    ],
    "05_bell_spaceships.py": [
        "rear ends in the ships' frame after: 1.250000 apart",
        "string rest length: 0.900000 -> 1.150000",
        "the string breaks at strain 0.2: lab (t, x) = (1.055865, 0.350500)",
    ],
    "06_pole_barn.py": [
        "Born-rigid pole: rear end at rest at x = 1.000000",
        "the door closes on the Born-rigid pole, in every frame",
        "signal-limited pole: rear end at rest at x = 0.333333",
        "is caught: its rear end passes the door as the door closes",
    ],
}

FILES = sorted(p.name for p in EXAMPLES.glob("*.py"))


def test_every_example_has_expectations() -> None:
    assert FILES, f"no examples in {EXAMPLES}"
    assert sorted(EXPECTED) == FILES


@pytest.mark.parametrize("name", FILES)
def test_example_prints_its_numbers(name: str, capsys: pytest.CaptureFixture[str]) -> None:
    """Run the example as a script; its output holds every expected line, and it leaves the registry as it was."""
    before = dict(rr.scene_descriptions())
    with isolated_registry():
        runpy.run_path(str(EXAMPLES / name), run_name="__main__")
    out = capsys.readouterr().out
    for expected in EXPECTED.get(name, []):
        assert expected in out, f"{name} does not print {expected!r}:\n{out}"
    assert dict(rr.scene_descriptions()) == before


@pytest.mark.parametrize("name", FILES)
def test_example_is_shaped_like_one(name: str) -> None:
    """A title docstring whose first line says the one idea, ``def main() -> None`` and a ``__main__`` guard."""
    tree = ast.parse((EXAMPLES / name).read_text(encoding="utf-8"))
    doc = ast.get_docstring(tree)
    assert doc and doc.splitlines()[0].strip() and doc.splitlines()[0].rstrip().endswith("."), name
    mains = [n for n in tree.body if isinstance(n, ast.FunctionDef) and n.name == "main"]
    assert len(mains) == 1 and not mains[0].args.args, name
    assert isinstance(mains[0].returns, ast.Constant) and mains[0].returns.value is None, name
    guard = tree.body[-1]
    assert isinstance(guard, ast.If) and ast.unparse(guard.test) == "__name__ == '__main__'", name
    assert ast.unparse(guard.body[0]) == "main()", name
