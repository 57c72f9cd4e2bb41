"""The scene registry: every registered description agrees with the scenes its constructor builds.

Each test runs over ``rr.scene_descriptions()``, so a scene added to rigidrel_core/scenes/ is
checked here with no edit. Citations of Franklin (2012) are checked against the paper's printed
numbering: Secs. 1-7, Eqs. (1)-(35).
"""

from __future__ import annotations

import ast
import dataclasses
import inspect
import math
import re
from collections.abc import Callable, Iterator
from pathlib import Path
from types import MappingProxyType

import pytest

import rigidrel_core as rr
from tests.strategies import descriptions, isolated_registry

CORE = Path(rr.__file__).parent
#: The paper's printed equation numbers, by section (Sec. 1-2 have no numbered equations, Sec. 7 neither).
EQUATIONS_BY_SECTION = {3: range(1, 20), 4: range(20, 22), 5: range(22, 26), 6: range(26, 36)}
N_EQUATIONS = 35
N_SECTIONS = 7
#: "Sec. 3", "Secs. 5-6", "Sec. 5, Eq. (24)", "Secs. 3-4".
SECTION = re.compile(r"\bSecs?\. (\d+)(?:\s*[-–]\s*(\d+))?")
#: An equation citation and the parenthesised references that follow it: "Eq. (15)", "Eqs. (22)-(25)", "Eqs. (4), (15)".
EQUATION = re.compile(r"\bEqs?\.\s*((?:\([^()]*\)(?:\s*(?:,|[-–]|and)\s*)?)+)")

KINDS = [d.kind for d in descriptions()]


# ---------------------------------------------------------------- descriptions and the scenes they build
def check_builds(kind: str) -> None:
    """With the defaults the constructor builds a scene of this kind, with the described frames,
    events, objects and rods; ``build_scene`` and ``description.build`` build the same."""
    d = rr.describe(kind)
    scene = d.constructor(**d.defaults())
    assert scene.kind == d.kind
    assert rr.describe(scene) is d
    assert tuple(scene.frames) == d.frames
    assert list(scene.events) == [e.name for e in d.events]
    assert tuple(o.kind for o in scene.objects) == d.objects
    for name in scene.events:
        assert 0 <= scene.event_rod(name) < scene.n_rods
        assert d.event(name).name == name
    for name, frame in scene.frames.items():
        assert scene.frame(name) is frame
    assert scene.frames["lab"].same_velocity(rr.LAB)
    assert isinstance(scene.origin_event, rr.OriginEvent)
    for other in (rr.build_scene(kind), d.build()):
        assert other.kind == kind and other.events == scene.events


def check_default_frame(kind: str) -> None:
    """The frame a lecturer compares the lab with first is one of the scene's presets and, for the
    default parameters, not the lab itself."""
    d = rr.describe(kind)
    assert d.default_frame in d.frames and d.default_frame != "lab"
    scene = d.build()
    frame = rr.default_frame(scene)
    assert not frame.same_velocity(rr.LAB), frame
    assert any(frame is f for f in scene.frames.values())


def check_presets(kind: str) -> None:
    """Every preset (a paper figure) builds from values of existing parameters and names a frame the scene has."""
    d = rr.describe(kind)
    for preset in d.presets:
        assert set(preset.values) <= set(d.parameter_map), preset.label
        scene = d.build(**preset.values)
        assert scene.kind == kind
        if preset.frame is not None:
            assert preset.frame in scene.frames, preset.label
        if preset.overlay:
            assert d.overlay is not None, preset.label
            assert isinstance(d.overlay.build(dict(scene.parameters)), rr.Scene)


def check_parameters(kind: str) -> None:
    """Defaults, slider ranges and the ranges the tests draw from lie inside each parameter's domain,
    so the app never offers a value the constructor refuses on its own."""
    d = rr.describe(kind)
    assert len({p.name for p in d.parameters}) == len(d.parameters)
    for p in d.parameters:
        assert d.parameter(p.name) is p
        if p.default is None:
            assert p.optional, p.name
        else:
            assert p.default in p.domain, p.name
            assert p.check(p.default) == p.default
        if p.slider is not None:
            assert p.slider.lo in p.domain and p.slider.hi in p.domain, p.name
            assert p.slider.lo < p.slider.hi
            if p.slider.scale == "log":
                assert p.slider.lo > 0.0, p.name
        lo, hi = p.sample_range()
        assert lo < hi and lo in p.domain and hi in p.domain, p.name
        assert p.domain.text() in p.allowed()
        if p.constraint:
            assert p.constraint in p.allowed()


CHECKS = [check_builds, check_default_frame, check_presets, check_parameters]


@pytest.mark.parametrize("check", CHECKS, ids=[c.__name__ for c in CHECKS])
@pytest.mark.parametrize("kind", KINDS)
def test_description_agrees_with_its_scene(kind: str, check: Callable[[str], None]) -> None:
    check(kind)


@pytest.mark.parametrize("kind", KINDS)
def test_unknown_event_and_parameter_are_named(kind: str) -> None:
    d = rr.describe(kind)
    with pytest.raises(rr.ParameterError, match=r"^event must be one of"):
        d.event("nope")
    with pytest.raises(rr.ParameterError, match=r"^nope must be one of the parameters of"):
        d.parameter("nope")
    with pytest.raises(rr.ParameterError, match=r"^event must be one of"):
        d.build().event_rod("nope")


#: Every renamed parameter, ``(kind, old, new)``.
RENAMED = [(d.kind, old, new) for d in descriptions() for old, new in d.renamed.items()]
#: The constructors' keywords, one name per quantity: the paper's V is ``v``, a rest length
#: ``length``, a rest mass ``mass``, an end's proper acceleration ``a_front``/``a_back``.
VOCABULARY = {
    "constant_acceleration": ("v", "length", "a_front", "mass"),
    "deceleration": ("v", "length", "a_front", "mass"),
    "velocity_change": ("v_initial", "v_final", "length", "a_front", "mass"),
    "impulsive_start": ("v", "length", "mass"),
    "wall_collision": ("v", "length", "eps", "mass"),
    "rod_collision": ("v1", "v2", "mass1", "mass2", "length1", "length2", "eps"),
    "bell_spaceships": ("v", "separation", "a_back", "ship_length", "breaking_strain", "mass"),
    "pole_barn": ("v", "length", "barn_length", "model", "sound_speed", "door_time", "mass"),
}


@pytest.mark.parametrize(("constructor", "names"), VOCABULARY.items())
def test_constructors_share_one_vocabulary(constructor: str, names: tuple[str, ...]) -> None:
    """Every constructor names a quantity as the others do (and as its registry description does)."""
    assert tuple(inspect.signature(getattr(rr, constructor)).parameters) == names


def test_the_old_names_are_listed() -> None:
    assert {(kind, old) for kind, old, _ in RENAMED} >= {
        ("rod-collision", "m1"),
        ("rod-collision", "m2"),
        ("rod-collision", "l1"),
        ("rod-collision", "l2"),
        ("bell-spaceships", "acceleration"),
    }


@pytest.mark.parametrize(("kind", "old", "new"), RENAMED)
def test_an_old_parameter_name_is_refused_naming_the_new_one(kind: str, old: str, new: str) -> None:
    """The constructor, ``build_scene`` and the description refuse an old name with a ``TypeError``
    (a ``ParameterError`` too) that names the new one; the new name builds the same scene."""
    d = rr.describe(kind)
    assert old not in d.parameter_map and new in d.parameter_map
    values = d.defaults()
    name = d.constructor.__name__
    with pytest.raises(TypeError, match=rf"^{name}\(\) got '{old}'; it is now '{new}'$"):
        d.constructor(**{old if k == new else k: v for k, v in values.items()})
    with pytest.raises(TypeError, match=rf"^the scene '{kind}' got '{old}'; it is now '{new}'$") as info:
        rr.build_scene(kind, **{old: values[new]})
    assert isinstance(info.value, rr.ParameterError) and info.value.parameter == old
    with pytest.raises(rr.ParameterError, match=f"it is now '{new}'"):
        d.parameter(old)
    assert rr.build_scene(kind, **{new: values[new]}).parameters == d.build().parameters


def test_several_old_names_are_named_together() -> None:
    with pytest.raises(TypeError, match=r"^rod_collision\(\) got 'm1', 'l2'; they are now 'mass1', 'length2'$"):
        rr.rod_collision(0.6, 0.0, m1=1.0, mass2=2.0, length1=1.0, l2=1.0, eps=1.0)  # type: ignore[call-arg]


def test_a_description_cannot_rename_to_a_name_it_lacks() -> None:
    base = rr.describe("rod-collision")
    with pytest.raises(ValueError, match="renamed"):
        dataclasses.replace(base, renamed=MappingProxyType({"mass2": "m2"}))


def test_descriptions_are_in_teaching_order() -> None:
    """``scene_descriptions`` lists the scenes by ``order`` (the app's menu), each under its own kind."""
    registry = rr.scene_descriptions()
    assert len(registry) >= 6
    orders = [(d.order, d.kind) for d in registry.values()]
    assert orders == sorted(orders)
    for kind, d in registry.items():
        assert d.kind == kind
        assert rr.describe(kind) is d


# ---------------------------------------------------------------- registering a scene
KICK = "test-kick-from-the-right"


def kick_from_the_right(v: float, length: float, mass: float = 1.0) -> rr.Scene:
    """A rod at rest on [0, length] whose right end is kicked to -v (an impulsive velocity change)."""
    scene = rr.velocity_change(0.0, -v, length, None, mass)
    return dataclasses.replace(scene, kind=KICK, parameters=MappingProxyType({"v": v, "length": length, "mass": mass}))


def kick_description(kind: str = KICK) -> rr.SceneDescription:
    base = rr.describe("velocity-change")
    return rr.SceneDescription(
        kind=kind,
        title="Kick from the right",
        summary="A rod at rest is kicked at its right end, which jumps to −V.",
        source="Sec. 4",
        constructor=kick_from_the_right,
        parameters=(rr.describe("impulsive-start").parameter("v"), base.parameter("length"), base.parameter("mass")),
        frames=base.frames,
        default_frame="rod after",
        events=base.events,
        order=35,
    )


def test_register_scene_adds_a_description_and_refuses_a_second_under_its_name() -> None:
    """``register_scene`` makes a new scene buildable by name and subject to every check above;
    registering the same description again is harmless, a different one under a taken name is refused."""
    with isolated_registry():
        kick = kick_description()
        assert rr.register_scene(kick) is kick
        assert rr.register_scene(kick) is kick
        assert rr.describe(kick.kind) is kick
        kinds = list(rr.scene_descriptions())
        assert kinds.index("impulsive-start") < kinds.index(KICK) < kinds.index("velocity-change")  # order 35
        for check in CHECKS:
            check(KICK)
        scene = rr.build_scene(KICK, v=0.8, length=1.0)
        assert scene.final_velocities == (-0.8,)
        assert scene.events["T_B"] == (0.0, 1.0)  # the kicked right end jumps at once
        assert scene.events["T_F"][0] == pytest.approx(0.8 / 0.6, rel=1e-15)  # T_F = gamma V L0, Eq. (21)
        with pytest.raises(ValueError, match=r"^description\.kind must be a name no other scene has"):
            rr.register_scene(kick_description())
        with pytest.raises(ValueError, match=r"^description\.kind must be a name no other scene has"):
            rr.register_scene(kick_description("rod-collision"))
        with pytest.raises(ValueError, match=r"^description must be a SceneDescription"):
            rr.register_scene("rod-collision")  # type: ignore[arg-type]
    assert KICK not in rr.scene_descriptions()


# ---------------------------------------------------------------- citations of the paper
def sources() -> Iterator[tuple[str, str]]:
    for d in descriptions():
        yield f"{d.kind} source", d.source
        for e in d.events:
            yield f"{d.kind} event {e.name}", e.source


def cited_sections(text: str) -> list[int]:
    out: list[int] = []
    for m in SECTION.finditer(text):
        first = int(m.group(1))
        last = int(m.group(2)) if m.group(2) else first
        out.extend(range(first, last + 1))
    return out


def cited_equations(text: str) -> list[str]:
    """Everything cited in parentheses after "Eq." or "Eqs.", as written: "15", "gl", "14.26"."""
    return [ref for m in EQUATION.finditer(text) for ref in re.findall(r"\(([^()]*)\)", m.group(1))]


def test_citation_parsers() -> None:
    """The citation parsers find what they must (so that the checks below are not vacuous)."""
    assert cited_sections("Secs. 3-4") == [3, 4]
    assert cited_sections("Sec. 5, Eq. (24)") == [5]
    assert cited_equations("Eqs. (22)-(25)") == ["22", "25"]
    assert cited_equations("paper Eqs. (deriv), (gl); rho = 0") == ["deriv", "gl"]
    assert cited_equations("a′_B = a′_F/(1 − a′_F L0) (Sec. 3, Eq. (15))") == ["15"]
    assert cited_equations("Eq. (epsilon) and (vp)") == ["epsilon", "vp"]


@pytest.mark.parametrize(("where", "source"), list(sources()), ids=[w for w, _ in sources()])
def test_every_source_names_a_section_of_the_paper(where: str, source: str) -> None:
    """A description's and each event's source names a section of the paper; an equation it cites is
    printed in that section."""
    sections = cited_sections(source)
    assert sections, f"{where}: {source!r} names no section"
    assert all(1 <= s <= N_SECTIONS for s in sections), source
    for ref in cited_equations(source):
        assert ref.isdigit(), f"{where}: {source!r}"
        assert any(int(ref) in EQUATIONS_BY_SECTION.get(s, ()) for s in sections), f"{where}: {source!r}"


def printed_number(ref: str) -> bool:
    return ref.isdigit() and 1 <= int(ref) <= N_EQUATIONS


def core_files() -> list[Path]:
    return sorted(CORE.rglob("*.py"))


def docstrings(path: Path) -> Iterator[tuple[int, str]]:
    """Every docstring of a module (module, classes, functions, attributes), with its line."""
    tree = ast.parse(path.read_text(encoding="utf-8"))
    for node in ast.walk(tree):
        if isinstance(node, ast.Expr) and isinstance(node.value, ast.Constant) and isinstance(node.value.value, str):
            yield node.lineno, node.value.value


def test_core_cites_equations_by_their_printed_numbers() -> None:
    """Docstrings, comments and help texts of the core cite the paper's equations by the numbers printed
    in it, (1)-(35), never by the LaTeX labels of its source ("Eq. (gl)", "Eq. (epsilon)")."""
    files = core_files()
    assert CORE / "scenes" / "collision.py" in files
    bad: list[str] = []
    n_cited = 0
    for path in files:
        name = path.relative_to(CORE.parent)
        for lineno, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
            refs = cited_equations(line)
            n_cited += len(refs)
            bad += [f"{name}:{lineno}: Eq. ({ref})" for ref in refs if not printed_number(ref)]
            bad += [f"{name}:{lineno}: Sec. {n}" for n in cited_sections(line) if not 1 <= n <= N_SECTIONS]
        for lineno, text in docstrings(path):  # citations broken over a docstring's lines
            refs = cited_equations(" ".join(text.split()))
            bad += [f"{name}:{lineno} (docstring): Eq. ({ref})" for ref in refs if not printed_number(ref)]
    assert n_cited > 10, "the core cites almost no equations: is the pattern wrong?"
    assert not bad, "equations cited by label, or citations out of range:\n" + "\n".join(sorted(set(bad)))


def test_interval_text_and_membership() -> None:
    """``Interval.text`` is what error messages print; ``in`` honours open and closed ends."""
    assert rr.Interval(0.0, 1.0).text() == "in (0, 1)"
    assert rr.Interval(0.0, 1.0, True, True).text() == "in [0, 1]"
    assert rr.Interval(0.0, math.inf).text() == "> 0"
    assert rr.Interval(0.0, math.inf, lo_closed=True).text() == ">= 0"
    assert 0.0 not in rr.Interval(0.0, 1.0) and 0.0 in rr.Interval(0.0, 1.0, lo_closed=True)
    assert 1.0 not in rr.Interval(0.0, 1.0) and 1.0 in rr.Interval(0.0, 1.0, hi_closed=True)
