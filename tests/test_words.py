"""Words a student can trust: every coordinate pair in words is of the frame shown, or says it is the lab's.

``rigidrel events`` in three frames (in-process): every ``(t, x) = (a, b)`` its words give (the causal
verdicts, the paradoxes' notes) names the frame of the output and matches a row of that output's
tables (events, light arrivals, the changes the verdicts name); in the lab each is labelled
``(lab t, x)``. The app's readout labels every pair ``(lab t, x)`` and each matches a lab event; the
built-in lesson's captions label every pair with the step's frame. No heading calls coordinates the
same in every frame. Bell's strain names the frame it is measured in wherever it is shown; loose
words the physics once had do not come back; V's help says whether it is a final or an approach speed.
"""

from __future__ import annotations

import re
from dataclasses import replace
from decimal import Decimal
from pathlib import Path
from typing import Any

import numpy as np
import pytest

import rigidrel_core as rr
from rigidrel_app.cli import main
from rigidrel_app.lessons import lesson_from
from rigidrel_app.view.layers import Layer
from rigidrel_app.view.scenario import flag
from rigidrel_app.view.scene_view import readout_markdown
from rigidrel_app.view.signals import signals_in, verdict_lines
from rigidrel_app.view.state import Settings, build

NUMBER = r"[-−]?(?:\d+\.?\d*|\.\d+)(?:e[+-]?\d+)?"
#: A coordinate pair in words, with what precedes it: ``(lab t, x) = (1, 1)``, ``(t, x) = (0.75, 0.75) in
#: the frame 'custom' (β = 0.3)``.
PAIR = re.compile(
    rf"(?P<label>\((?:lab )?t, x\) = )?\((?P<t>{NUMBER}), (?P<x>{NUMBER})\)"
    rf"(?P<after> in the frame (?:'[^']*' \(β = {NUMBER}\)|β = {NUMBER}))?"
)
#: The headers of the tables whose rows (name ..., t, x) words may cite.
TABLES = ("event ", "arrival ", "change ")


def frame_words(frame: rr.Frame) -> str:
    return (
        f" in the frame '{frame.name}' (β = {frame.beta:.4g})" if frame.name else f" in the frame β = {frame.beta:.4g}"
    )


def tables_and_words(out: str) -> tuple[list[tuple[float, float]], str]:
    """The ``(t, x)`` of every row of the event, arrival and change tables, and the words (the notes
    and the verdicts, wrapped lines joined)."""
    rows: list[tuple[float, float]] = []
    words: list[str] = []
    table = ""
    for line in out.splitlines():
        if not line.strip():
            table = ""
        elif line.startswith(TABLES):
            table = line.split()[0]
        elif table in ("event", "arrival"):  # name, then t and x in columns of 20 (the events' meaning after)
            rows.append((float(line[12:32]), float(line[32:52])))
        elif table == "change" and not line.startswith(" "):
            t, x = line.split()[-2:]
            rows.append((float(t), float(x)))
        elif line.startswith(("note ", "  ")) and not line.startswith(("  heat", "  total", "  from", "  system")):
            table = ""
            words.append(line.strip().removeprefix("note").strip())
    return rows, " ".join(words)


def matches(pair: tuple[str, str], rows: list[tuple[float, float]]) -> bool:
    """Whether a pair printed with a few significant digits is one of the rows (to half a unit of
    its last printed digit)."""

    def near(text: str, value: float) -> bool:
        text = text.replace("−", "-")  # a caption's minus sign
        last = Decimal(text).as_tuple().exponent
        assert isinstance(last, int)
        return abs(float(text) - value) <= 0.5 * 10.0**last * (1 + 1e-9) + 1e-12 * abs(value)

    return any(near(pair[0], row[0]) and near(pair[1], row[1]) for row in rows)


def events_output(kind: str, frame: str, capsys: pytest.CaptureFixture[str]) -> str:
    assert main(["events", kind, f"--frame={frame}"]) == 0
    return capsys.readouterr().out


@pytest.mark.parametrize("kind", list(rr.scene_descriptions()))
def test_every_coordinate_in_words_is_a_row_of_the_frame_shown(kind: str, capsys: pytest.CaptureFixture[str]) -> None:
    """Three frames: the lab, a custom velocity and the scene's default preset."""
    d = rr.describe(kind)
    scene = d.build()
    for frame_text in ("lab", "-0.45", d.default_frame):
        out = events_output(kind, frame_text, capsys)
        frame = scene.frame(frame_text) if frame_text in scene.frames else rr.Frame.from_velocity(-0.45, "custom")
        lab = frame.same_velocity(rr.LAB)
        assert "the same in every frame)" not in out  # no heading makes coordinates read as invariants
        rows, words = tables_and_words(out)
        assert rows, out
        pairs = list(PAIR.finditer(words))
        if scene.causal_verdicts():
            assert pairs, words  # the verdicts give at least the first light's arrival
        for m in pairs:
            pair = (m["t"], m["x"])
            assert m["label"] is not None, f"{m[0]!r}: a coordinate pair without its frame in {words!r}"
            if lab:
                assert m["label"] == "(lab t, x) = " and m["after"] is None, m[0]
            else:
                assert m["label"] == "(t, x) = " and m["after"] == frame_words(frame), m[0]
            assert matches(pair, rows), f"{m[0]!r} is no row of the {frame_text} tables: {rows}"


def lab_events(scene: rr.Scene) -> list[tuple[float, float]]:
    """Every lab event the readout's words may give: named events, the objects' events, and each
    verdict's start, stop and first light."""
    events = list(scene.events.values())
    events += [o.event.lab for o in scene.objects if o.event is not None]
    for v in scene.causal_verdicts():
        events += [v.start, v.stop] + ([v.arrival] if v.arrival is not None else [])
    return events


@pytest.mark.parametrize("kind", list(rr.scene_descriptions()))
def test_the_readout_labels_every_pair_as_the_labs(kind: str) -> None:
    """The readout's events are the lab's; its notes and verdicts say so for every pair, whatever the
    frame chosen, and each pair is a lab event of the scene."""
    d = rr.describe(kind)
    settings = replace(Settings(kind), frame=d.default_frame).with_layers(frozenset(Layer))
    r = build(settings)
    text = readout_markdown(r)
    words = text.split("**Clocks**", 1)[1]
    events = lab_events(r.scene)
    for m in PAIR.finditer(words):
        assert m["label"] == "(lab t, x) = " and m["after"] is None, m[0]
        assert matches((m["t"], m["x"]), events), m[0]


def test_the_lesson_captions_label_every_pair_with_the_steps_frame() -> None:
    """Every coordinate pair a caption gives is labelled: ``(lab t, x)`` in a lab step, the step's frame
    by name in any other; and it is an event of that frame."""
    lesson = lesson_from("paper")
    checked = 0
    for step in lesson.steps:
        scene, frame = step.resolved.scene, step.resolved.frame
        events = [frame @ np.array(e) for e in lab_events(scene)]
        events += [np.array(leg) for leg in scene.events_in(frame=frame).values()]
        rows = [(float(e[0]), float(e[1])) for e in events]
        rows += [leg.arrival for leg in signals_in(scene, frame).legs]
        text = " ".join(step.caption.split())
        for m in PAIR.finditer(text):
            if m["label"] is None and not re.search(r"= $", text[: m.start()]):
                continue  # not a coordinate pair (Eq. (28)'s misprinted Lorentz factors)
            assert m["label"] is not None, f"step {step.title!r}: {m[0]!r} has no frame"
            if frame.same_velocity(rr.LAB):
                assert m["label"] == "(lab t, x) = ", m[0]
            else:
                assert m["after"] == frame_words(frame), m[0]
            assert matches((m["t"], m["x"]), rows), f"step {step.title!r}: {m[0]!r}"
            checked += 1
    assert checked >= 14  # every step that gives an event in words


#: Bell's string's length, and so its strain and its break, is measured in this frame: a convention
#: the numbers depend on (in the front ship's frame the same strain is reached at another event).
STRAIN_FRAME = re.compile(r"rear ship's (?:momentarily )?comoving frame")


def test_bells_strain_names_its_frame_wherever_it_is_shown(capsys: pytest.CaptureFixture[str]) -> None:
    """The string's strain and break event are shown with the frame they are measured in: the notes
    (command line and readout), the break event's meaning, the summary, the print figure's caption and
    the lesson's caption."""
    scene = rr.bell_spaceships(0.6, 1.0, 0.5, breaking_strain=0.25)
    strain_notes = [n for n in scene.notes() if "strain" in n]
    assert len(strain_notes) == 2 and all(STRAIN_FRAME.search(n) for n in strain_notes), strain_notes
    assert "front ship's frame" in strain_notes[-1]  # the convention matters: another event there
    (string,) = scene.objects
    assert string.event is not None and STRAIN_FRAME.search(string.event.meaning)
    d = rr.describe("bell-spaceships")
    assert STRAIN_FRAME.search(d.summary)
    (figure,) = [p.figure for p in d.presets if p.figure is not None]
    assert STRAIN_FRAME.search(figure.caption(d.build(**next(p for p in d.presets if p.figure).values)))
    readout = readout_markdown(build(Settings("bell-spaceships")))
    assert len(STRAIN_FRAME.findall(readout)) >= 2, readout
    out = events_output("bell-spaceships", "ships after", capsys)
    assert len(STRAIN_FRAME.findall(" ".join(out.split()))) >= 3, out  # the break's meaning and two notes
    (step,) = [s for s in lesson_from("paper").steps if s.resolved.scene.kind == "bell-spaceships"]
    assert len(STRAIN_FRAME.findall(" ".join(step.caption.split()))) >= 3, step.caption


#: Words the physics once had wrong or loose, and why: none may come back in the README, the docs,
#: the lesson, a scene's summary or help, or what the core writes.
LOOSE_WORDS = {
    r"kick is the (?:\(?Rindler\)? )?horizon": "the kick is an event; the horizon is its light cone",
    r"centre event \(the Rindler horizon\)": "the centre event is the horizon's vertex, not the horizon",
    r"from the wall told": "light from the wall before the contact does reach the back end in time",
    r"respond to the wall": "the rod stops at the wall; what no frame sees is a response to the contact",
    r"in faster frames after": "only frames with β < −V see the braking start after the contact",
    r"happens before the contact": "the back end's change starts before the contact and ends at its lab time",
    r"two meanings of rigid": "the signal-limited pole is compressed: not rigid in any sense",
    r"\(the same in every frame\)": "coordinates differ between frames; only the verdicts' kinds do not",
    r"c²": "c = 1 everywhere: energies are in mass units",
    r"(?:on|spanning) the same (?:two )?rear ends": "the rod starts between them; its front falls behind",
    r"gamma s\b|\bs - l\b": "γs and s − l, as everywhere else",
    r"breaks where its strain": "the strain reaches the breaking strain at an event on the string's rear end",
    r"vertex of the hyperbolas": "the origin is the vertex of one hyperbola, the left end's",
    r"where nothing happens": "an impulsive change has its kick; say what the origin is",
    r"nearer the horizon": "jargon the output never defines: B is the end behind, seen along the push",
    r"back end's stop": "the deceleration's left end leads: it is the left end's stop",
    r"'none' omits it": "none gives a default, the impulsive limit or no break: never nothing",
}


def texts_a_student_reads() -> dict[str, str]:
    """The README, every docs page, the lesson files, and every scene's summary, help and notes."""
    root = Path(__file__).parent.parent
    pages = [root / "README.md", *sorted((root / "docs").glob("*.md")), *sorted((root / "app").rglob("lessons/*.toml"))]
    texts = {str(p.relative_to(root)): p.read_text() for p in pages}
    for kind, d in rr.scene_descriptions().items():
        scene = d.build()
        helps = [d.help_for(p) for p in d.parameters]
        light = signals_in(scene, rr.LAB)
        texts[kind] = "\n".join(
            [
                d.summary,
                *helps,
                *scene.notes(),
                light.key_definition,
                *verdict_lines(scene),
                *(e.meaning for e in d.events),
            ]
        )
    return texts


def test_no_loose_words_come_back() -> None:
    for name, text in texts_a_student_reads().items():
        flat = " ".join(text.split())
        for pattern, why in LOOSE_WORDS.items():
            found = re.search(pattern, flat, re.IGNORECASE)
            assert found is None, f"{name}: {found[0]!r}: {why}"


@pytest.mark.parametrize("kind", list(rr.scene_descriptions()))
def test_v_says_whether_it_is_a_final_or_an_approach_speed(kind: str) -> None:
    """Where a scene has one speed V, its help says what V is there: the final speed of a rod that starts
    at rest, or the approach speed of one that moves at −V toward its stop."""
    d = rr.describe(kind)
    if "v" not in d.parameter_map:
        return
    scene = d.build()
    before = {r.motion.velocity_initial.value for r in scene.rods}
    after = {r.motion.velocity_final.value for r in scene.rods}
    v = scene.parameters["v"]
    help_text = d.help_for(d.parameter("v"))
    if before == {0.0}:
        assert v in after and help_text.startswith("final speed V"), help_text
    else:
        assert before == {-v} and help_text.startswith("approach speed V") and "−V" in help_text, help_text


@pytest.mark.parametrize(
    ("kind", "values"),
    [
        ("wall-collision", {"eps": 0.0}),
        ("wall-collision", {"eps": 0.5}),
        ("pole-barn", {}),
        ("rod-collision", {"eps": 0.5}),
        ("rod-collision", {"eps": 0.0, "mass2": 0.5}),
        ("bell-spaceships", {}),
    ],
)
def test_the_heat_names_the_body_it_is_in(
    kind: str, values: dict[str, float], capsys: pytest.CaptureFixture[str]
) -> None:
    """Each system's heat says where it is, and that is where the 4-momenta put it: in the wall when the
    rods keep their rest masses (in the lab the wall, at rest, takes exactly that energy), in the rods
    when their rest masses grow by it (in proportion to rest mass when by one factor). The command line
    prints it beside the number."""
    scene = rr.build_scene(kind, **values)
    budget = scene.budget()
    for system in budget.systems:
        rods = list(system.system.rods)
        grown = budget.rest_mass_after[rods] - budget.rest_mass_before[rods]
        if system.heat == 0.0:
            assert system.heat_where == "" and not grown.any()
        elif not grown.any():
            assert system.heat_where.startswith("all in the wall (") and system.external_source == "wall"
            assert system.external[0] == pytest.approx(-system.heat, rel=1e-12)  # into the wall, in the lab
        else:
            assert grown.sum() == pytest.approx(system.heat, rel=1e-12)
            assert system.heat_where.startswith("in ") and "wall" not in system.heat_where
            if len(rods) > 1:
                factor = budget.rest_mass_after[rods] / budget.rest_mass_before[rods]
                assert factor == pytest.approx(factor[0], rel=1e-12)
                assert f"each rest mass × {factor[0]:.6g}" in system.heat_where
    flags = [f"--{k.replace('_', '-')}={v}" for k, v in values.items()]
    assert main(["events", kind, *flags]) == 0
    out = capsys.readouterr().out
    heat_lines = [line.strip() for line in out.splitlines() if line.strip().startswith("heat (rest energy created)")]
    assert len(heat_lines) == len(budget.systems)
    for line, system in zip(heat_lines, budget.systems, strict=True):
        assert line.endswith(f", {system.heat_where}" if system.heat_where else ": 0"), line


def test_the_lessons_heat_is_in_the_wall_and_in_mass_units() -> None:
    """The partly elastic bounce's heat: the Born-rigid rod keeps its rest mass M, so the kinetic energy
    it loses, (γ − γ′) M = 0.182 M at V = 0.6 and ε = 0.5, is the wall's."""
    (step,) = [s for s in lesson_from("paper").steps if s.title == "A partly elastic bounce makes heat"]
    text = " ".join(step.caption.split())
    assert "0.182 M (c = 1: energy in mass units)" in text
    assert "all in the wall (the rod keeps its rest mass)" in text
    rod = step.resolved.scene.rods[0]
    assert rod.mass_after == rod.mass_before


#: Words that describe a velocity change as one frame sees it: in another the same change may speed
#: the end up, or reverse it, and the end comes to rest instead of "reaching V". An event's meaning is
#: printed under every frame's table, so it says "changing velocity" or "its final velocity", or names
#: the frame its word holds in.
FRAME_BOUND = re.compile(r"decelerat|brak|slows|speeds up|comes to rest|trailing|leading|reaches V\b", re.IGNORECASE)


@pytest.mark.parametrize("kind", list(rr.scene_descriptions()))
def test_event_meanings_hold_in_every_frame(kind: str) -> None:
    for event in rr.describe(kind).events:
        found = FRAME_BOUND.search(event.meaning)
        assert found is None or re.search(r"in the (?:lab|barn)\b", event.meaning), (event.name, event.meaning)


def test_the_order_of_two_spacelike_starts_names_its_frame() -> None:
    """The deceleration's two starts are spacelike apart: "first" is said of the lab, and the caption
    says that in the rod's frame before they are simultaneous (the core's numbers)."""
    (step,) = [s for s in lesson_from("paper").steps if s.resolved.scene.kind == "deceleration"]
    text = " ".join(step.caption.split())
    scene = step.resolved.scene
    trailing, leading = scene.events["-T_F"], scene.events["-T_B"]
    assert rr.causal_relation(trailing, leading).kind == "spacelike"
    assert "In the lab its trailing (right) end starts braking first" in text
    before = scene.events_in(frame=scene.frame("rod before"))
    assert before["-T_F"][0] == pytest.approx(before["-T_B"][0], rel=1e-12)
    t = f"{before['-T_F'][0]:.4g}".replace("-", "−")
    assert f"In the rod's frame before, both ends start together, at t′ = {t}" in text


@pytest.mark.parametrize("kind", list(rr.scene_descriptions()))
def test_every_light_signal_row_says_what_it_is(kind: str, capsys: pytest.CaptureFixture[str]) -> None:
    """The light-signal table names each arrival (which end of which rod), and says what the key event
    is ("the start" of Bell's ships is where the rear ship's rear end starts, at the origin)."""
    scene = rr.describe(kind).build()
    signals = signals_in(scene, rr.LAB)
    assert signals.key_definition.startswith(f"{signals.key_phrase}: ")
    for leg in signals.legs:
        if leg.name.startswith("S"):
            assert leg.meaning.startswith(f"light from {signals.key_phrase} reaches the ")
        else:
            assert leg.meaning.startswith("its echo is back at the ")
        if scene.n_rods > 1:
            rod = scene.rods[int(leg.name.split("_")[1]) - 1].name
            assert leg.meaning.endswith(rod), leg.meaning
    out = " ".join(events_output(kind, "lab", capsys).split())
    assert f"({signals.key_definition})" in out
    for leg in signals.legs:
        assert leg.meaning in out
    if kind == "bell-spaceships":
        assert "the start: the event at the origin of every frame, where the rear ship's left end starts" in out


def test_the_scene_listing_reads_by_column_and_says_which_frame_each_command_shows(
    capsys: pytest.CaptureFixture[str],
) -> None:
    """Every option stands apart from its symbol (``--breaking-strain`` once ran into ``e_b``); each scene
    says which frame ``events`` shows (the lab) and which ``serve`` and ``export`` open in (its default);
    the barycentric frame says what it is."""
    assert main(["scenes"]) == 0
    out = capsys.readouterr().out
    symbols = {flag(p): p.symbol for d in rr.scene_descriptions().values() for p in d.parameters}
    rows = re.findall(r"^  (--\S+) {2,}(\S+) ", out, re.MULTILINE)
    assert len(rows) == sum(len(d.parameters) for d in rr.scene_descriptions().values())
    for option, symbol in rows:
        assert symbols[option] == symbol, (option, symbol)
    for kind, d in rr.scene_descriptions().items():
        block = out.split(f"\n{kind}  (", 1)[-1] if not out.startswith(kind) else out
        block = block.split("\n\n", 1)[0]
        assert f"`serve` and `export` open in {d.default_frame}; `events` shows the lab unless --frame" in block
    assert "barycentric (zero total momentum)" in out


@pytest.mark.parametrize("kind", list(rr.scene_descriptions()))
def test_options_help_names_only_the_scenes_own_frames_and_units(kind: str, capsys: pytest.CaptureFixture[str]) -> None:
    with pytest.raises(SystemExit):
        main(["events", kind, "--help"])
    text = " ".join(capsys.readouterr().out.split())
    own = set(rr.describe(kind).frames)
    for other in {f for d in rr.scene_descriptions().values() for f in d.frames} - own:
        assert f"'{other}'" not in text and f" {other}," not in text and not text.endswith(f" {other}"), other
    assert "[1/L0]" not in text  # a proper acceleration is in 1/(length unit), whatever L0 is
    if "--a-front" in text:
        assert "[1/length unit]" in text


def row_numbers(out: str, first: str) -> list[str]:
    """The numbers of the last row of ``out`` that starts with ``first`` (after its indent)."""
    row = [line for line in out.splitlines() if line.strip().startswith(first)][-1]
    return row.strip().removeprefix(first).split()


@pytest.mark.parametrize(
    ("args", "first", "column"),
    [
        # T_1 = (-gamma V L0, gamma L0) in the lab: t' = gamma (t + V x) = 0 in the pole's frame
        (["pole-barn", "--v=0.3", "--frame=pole before"], "T_1 ", 0),
        # the signal-limited pole's wall gives no energy in the barn's frame: gamma M - gamma M
        (["pole-barn", "--v=0.9"], "from the wall (negative: into the wall)", 0),
        # the barycentric frame's momenta cancel
        (["rod-collision", "--eps=0.5", "--frame=barycentric"], "total after", 1),
    ],
)
def test_rounding_noise_is_not_printed_as_data(
    args: list[str], first: str, column: int, capsys: pytest.CaptureFixture[str]
) -> None:
    """A value that is zero in exact arithmetic, formed from terms of order 1, prints as 0, not as
    5.6e-17; and every row of the budget keeps its numbers apart."""
    assert main(["events", *args]) == 0
    out = capsys.readouterr().out
    assert row_numbers(out, first)[column] == "0", row_numbers(out, first)
    budget = out.split("4-momentum", 1)[1].split("\n\n", 1)[0]
    for label in ("total before", "total after"):
        assert len(row_numbers(budget, label)) == 2  # E and p, never run together


def test_a_small_value_is_shown_and_noise_is_not() -> None:
    """Noise is judged against the terms a value was formed from, never against other rows: in the lab
    nothing changes; a tiny true coordinate (V = 1e-9) stays; the boost's noise goes."""
    scene = rr.pole_barn(1e-9, 1.0)
    before = scene.frame("pole before")
    assert rr.event_shown(scene.events["T_1"], rr.LAB) == scene.events["T_1"]
    t1, t1_end = scene.events_in(frame=before)["T_1"], scene.events_in(frame=before)["T_1'"]
    assert rr.event_shown(t1, before)[0] == 0.0
    assert rr.event_shown(t1_end, before)[0] == pytest.approx(1e-9, rel=1e-6)
    assert rr.shown(1e-12, 1.0) == 0.0 and rr.shown(2e-12, 1.0) == 2e-12


def test_defaults_the_words_name_are_the_registrys() -> None:
    """The lesson's pole step says what the command line defaults to (a student runs it beside the
    lesson), and the wall's summary which bounce its default is."""
    (step,) = [s for s in lesson_from("paper").steps if s.resolved.scene.kind == "pole-barn"]
    text = " ".join(step.caption.split())
    default = rr.describe("pole-barn").parameter("v").default
    assert f"`rigidrel events pole-barn` defaults to V = {default:g}" in text
    assert f"add `--v {step.resolved.scene.parameters['v']:g}` for these numbers" in text
    wall = rr.describe("wall-collision")
    assert f"by default it bounces, ε = {wall.parameter('eps').default:g}" in wall.summary


def event_rows(out: str) -> dict[str, tuple[float, float]]:
    """The event table of ``rigidrel events`` output: name -> (t, x) of its frame."""
    rows: dict[str, tuple[float, float]] = {}
    table = False
    for line in out.splitlines():
        if line.startswith("event "):
            table = True
        elif not line.strip():
            table = False
        elif table:
            rows[line[:12].strip()] = (float(line[12:32]), float(line[32:52]))
    return rows


@pytest.mark.parametrize("values", [{}, {"v_initial": 0.6, "v_final": -0.2}, {"v_initial": -0.2, "v_final": -0.6}])
@pytest.mark.parametrize("frame", ["lab", "rod before", "rod after", "-0.45", "0.9"])
def test_which_end_starts_first_is_said_from_the_events_of_each_frame(
    values: dict[str, float], frame: str, capsys: pytest.CaptureFixture[str]
) -> None:
    """A general velocity change's key event is where an end starts first in the lab; the two starts are
    spacelike apart, so "first" is said of the lab, and the order in the frame shown is the one its own
    event table gives (together in the rod's frame before)."""
    flags = [f"--{k.replace('_', '-')}={v}" for k, v in values.items()]
    assert main(["events", "velocity-change", *flags, f"--frame={frame}"]) == 0
    out = capsys.readouterr().out
    flat = " ".join(out.split())
    lab = event_rows(_events(["velocity-change", *flags], capsys))
    here = event_rows(out)
    key = min(("T_B0", "T_F0"), key=lambda n: lab[n][0])
    other = "T_F0" if key == "T_B0" else "T_B0"
    assert lab[key][0] < lab[other][0]
    assert f"the start of the change: the event {key}, where" in flat
    assert "; in the lab it is the first thing that happens to the rod" in flat
    assert "the first thing that happens to the rod)" not in flat  # never as a bare fact
    scene = rr.build_scene("velocity-change", **values)
    side = {0: "left", 1: "right"}
    other_side = side[next(s.end for s in scene.event_specs if s.name == other)]
    dt = here[other][0] - here[key][0]
    if frame == "rod before":
        assert dt == pytest.approx(0.0, abs=1e-9)
        assert "in the frame 'rod before' both ends start together" in flat
    elif frame != "lab":
        if dt > 1e-9:
            assert "it is first too" in flat
        else:
            assert f"the {other_side} end starts first" in flat


def _events(args: list[str], capsys: pytest.CaptureFixture[str]) -> str:
    assert main(["events", *args]) == 0
    return capsys.readouterr().out


@pytest.mark.parametrize(
    ("values", "kick", "side"),
    [
        # pushed toward +x: B, the left end, is kicked at the origin; F is on x = sqrt(1 + t^2)
        ({"v_initial": 0.2, "v_final": 0.6}, (0.0, 0.0), 1),
        # pushed toward -x: B, the right end, is kicked at lab (0, 1); F is on x = 1 - sqrt(1 + t^2)
        ({"v_initial": 0.6, "v_final": -0.2}, (0.0, 1.0), -1),
    ],
)
@pytest.mark.parametrize("a_front", ["none", "1"])
def test_an_impulsive_velocity_change_is_caused_by_its_kick(
    values: dict[str, float],
    kick: tuple[float, float],
    side: int,
    a_front: str,
    capsys: pytest.CaptureFixture[str],
) -> None:
    """With a′_F L0 = 1 (or none) the end B jumps at once: that kick is the event the light leaves from
    and the verdict is measured from (not "a vertex where nothing happens"); the other end's whole
    change lies outside its light cone. The numbers against 50-digit closed forms: F, at L0 = 1 from
    the kick, has velocity v at (t, x) = (side γv, x_kick + side γ), and the light x = x_kick + side t
    meets it coasting at V_f after T_F."""
    import mpmath as mp

    mp.mp.dps = 50
    flags = [f"--{k.replace('_', '-')}={v}" for k, v in values.items()]
    out = _events(["velocity-change", *flags, f"--a-front={a_front}"], capsys)
    flat = " ".join(out.split())
    assert "nothing happens" not in flat and "vertex" not in flat
    assert "light from the kick: S reaches" in flat
    assert "lies outside the light cone of the kick: no signal from the kick can have caused it" in flat
    rows = event_rows(out)
    assert rows["T_B0"] == rows["T_B"] == kick

    def on_f(v: float) -> tuple[Any, Any]:  # mpf numbers (the stubs type their arithmetic loosely)
        g = 1 / mp.sqrt(1 - mp.mpf(v) ** 2)
        return side * g * mp.mpf(v), kick[1] + side * g

    t_start, x_start = on_f(values["v_initial"])
    t_stop, x_stop = on_f(values["v_final"])
    vf = mp.mpf(values["v_final"])
    t_light = (x_stop - kick[1] - vf * t_stop) / (side - vf)
    x_light = kick[1] + side * t_light
    scene = rr.build_scene("velocity-change", **values, a_front=None if a_front == "none" else 1.0)
    for name, (t, x) in (("T_F0", (t_start, x_start)), ("T_F", (t_stop, x_stop))):
        assert scene.events[name] == pytest.approx((float(t), float(x)), rel=1e-12), name
    (verdict,) = scene.causal_verdicts()
    (far,) = [leg for leg in signals_in(scene, rr.LAB).legs if leg.name == "S"]
    assert verdict.arrival == far.arrival == pytest.approx((float(t_light), float(x_light)), rel=1e-12)
    assert f"reaches it at (lab t, x) = ({float(t_light):.4g}, {float(x_light):.4g})" in flat


def test_the_decelerations_reference_event_is_named_for_the_end_the_table_names() -> None:
    """Deceleration's origin event is where its left end, the leading one in the lab, comes to rest: the
    light's key event says "left" and "leading", as the event table does, never "back"."""
    scene = rr.build_scene("deceleration")
    signals = signals_in(scene, rr.LAB)
    assert signals.key_phrase == "the left end's stop"
    assert "left end (B, leading in the lab) comes to rest in the lab" in signals.key_definition
    assert "leading" in rr.describe("deceleration").event("-T_B").meaning
    assert "left end" in rr.describe("deceleration").event("-T_B").meaning
    for verdict in verdict_lines(scene):
        assert "back end" not in verdict


@pytest.mark.parametrize(
    ("args", "frame", "owners"),
    [
        (["wall-collision", "--eps=0"], "rod before", ["the wall's"]),
        (["wall-collision", "--eps=0.5"], "rod after", ["the wall's"]),
        (["wall-collision", "--eps=1"], "-0.45", [None]),
        (["pole-barn"], "pole before", ["the wall's", "the signal-limited pole's"]),
    ],
)
def test_a_moving_wall_does_work_while_the_heat_stays_where_it_is(
    args: list[str], frame: str, owners: list[str | None], capsys: pytest.CaptureFixture[str]
) -> None:
    """In a frame where the wall moves, its row can be positive: that is work the wall does on the rod,
    not heat leaving the wall. Each system says so, with the wall's velocity there, and that the heat is
    still the growth of the same body's rest energy, the same in every frame. In the lab, nothing."""
    out = _events([*args, f"--frame={frame}"], capsys)
    scene = rr.build_scene(args[0], **{a.split("=")[0][2:]: float(a.split("=")[1]) for a in args[1:]})
    f = scene.frame(frame) if frame in scene.frames else rr.Frame.from_velocity(float(frame), "custom")
    flat = " ".join(out.split())
    notes = re.findall(r"\(the wall moves at (\S+) in this frame: (.*?)\)(?= system:| light from|$)", flat)
    assert len(notes) == len(owners), flat
    for (speed, text), owner, system in zip(notes, owners, scene.budget(frame=f).systems, strict=True):
        assert float(speed) == pytest.approx(-f.beta, rel=1e-9)
        assert "its E is the work the wall does on" in text
        if owner is None:
            assert system.heat == 0.0 and "heat" not in text
        else:
            assert f"the heat, {system.heat:.10g}, the same in every frame, is still the growth of {owner} rest" in text
    assert "the wall moves" not in _events([*args, "--frame=lab"], capsys)


def test_the_lessons_first_stop_is_the_labs() -> None:
    """Constant acceleration: T_B and T_F are spacelike apart, simultaneous in the rod's new frame, so
    the step that says the back end reaches V first says it of the lab, and that they are together there."""
    (step, *_) = [s for s in lesson_from("paper").steps if s.resolved.scene.kind == "constant-acceleration"]
    text = " ".join(step.caption.split())
    scene = step.resolved.scene
    assert rr.causal_relation(scene.events["T_B"], scene.events["T_F"]).kind == "spacelike"
    after = scene.events_in(frame=scene.frame("rod after"))
    assert after["T_B"][0] == pytest.approx(after["T_F"][0], rel=1e-12)
    assert "In the lab the back end reaches V first" in text
    assert "in the rod's new frame both ends stop accelerating together" in text
    for other in lesson_from("paper").steps:
        flat = " ".join(other.caption.split())
        for m in re.finditer(r"[^.]*\bfirst\b[^.]*", flat):
            if "first light" in m[0] or "light from" in m[0]:
                continue
            assert "lab" in m[0] or "frame" in m[0], f"{other.title!r}: {m[0]!r}"  # "first" names its frame


def test_a_lane_in_the_lab_is_not_labelled_as_another_frame() -> None:
    """Where the chosen frame is the lab, its lane's time is t and its ruler x (a prime belongs to another
    frame), and a frame at rest in the lab that has another name (the custom frame at β = 0, a
    preset) says that it is the lab."""
    from rigidrel_app.view.diagrams import frame_title
    from rigidrel_app.view.scene_view import build_drawing, lane_titles, ruler_names

    for step in lesson_from("paper").steps:
        r = step.resolved
        _, second = lane_titles(r, 0.25)
        if r.ride is None and r.frame.same_velocity(rr.LAB):
            assert "t' =" not in second and "t′ =" not in second and second.startswith("lab frame (chosen):")
            assert ruler_names(r) == ("x", "x")
        elif r.ride is None:
            assert "t′ =" in second and ruler_names(r) == ("x", "x′")
    assert frame_title(rr.Frame.from_velocity(0.0, "custom")) == "custom (β = 0: the lab)"
    assert frame_title(rr.build_scene("deceleration").frame("rod after")) == "rod after (β = 0: the lab)"
    assert frame_title(rr.LAB) == "lab"
    lab_step = build(replace(Settings("wall-collision"), frame="lab"))
    labels = [lab.text for _, texts in build_drawing(lab_step).lane_statics() for lab in texts]
    assert "x′" not in labels


def test_every_exported_step_says_when_each_clock_reads_zero() -> None:
    """Two clocks on one worldline (the two poles' rear ends before the stop) can read differently: each
    end's clock reads 0 where that end starts changing velocity. Every exported step page says so, and
    it is what the core's clocks do."""
    from rigidrel_app.export.lesson_site import _step_page  # pyright: ignore[reportPrivateUsage]

    lesson = lesson_from("paper")
    for k, step in enumerate(lesson.steps):
        page = _step_page(lesson, k, step)
        assert (
            "read each end&#x27;s proper time τ: every clock reads 0 where its point starts changing velocity" in page
        )
        # its picture in words names the events as the canvas does, never as typed (T_1)
        words = page[page.index("<details class='words'>") :]
        assert "T_" not in words and ("Events passed" not in words or "T<sub>" in words or "none" in words)
    scene = rr.build_scene("pole-barn", v=0.8, barn_length=0.6)
    for rod in range(scene.n_rods):
        for end in (0.0, 1.0):
            start = scene.point_event(rod, end, proper_time=0.0)
            spec = [s for s in scene.event_specs if (s.rod, s.end, s.phase) == (rod, int(end), "start")]
            if spec:
                assert start == pytest.approx(scene.events[spec[0].name], abs=1e-12)
            tau = scene.proper_times(np.array([start[0]]), fractions=np.array([end]))[rod, 0, 0]
            assert tau == pytest.approx(0.0, abs=1e-12)


@pytest.mark.parametrize("kind", ["wall-collision", "rod-collision"])
def test_restitution_is_defined_as_the_paper_defines_it(kind: str) -> None:
    """ε is the paper's relativistic coefficient of restitution (Sec. 6, Eq. (29): γ̄′V̄′ = −ε γ̄V̄ in the
    barycentric frame), a ratio of proper velocities, not of speeds: the help says so with a number
    the core gives, checked against 50 digits; the docs say it too."""
    import mpmath as mp

    mp.mp.dps = 50
    d = rr.describe(kind)
    text = " ".join(d.help_for(d.parameter("eps")).split())
    assert "(Sec. 6, Eq. (29))" in text and "proper velocity γV after the impact to before, reversed" in text
    assert "in the barycentric frame (zero total momentum; for a wall, the wall's frame)" in text
    v = mp.mpf("0.6")
    w = v / mp.sqrt(1 - v**2) / 2
    exact = w / mp.sqrt(1 + w**2)
    (rod,) = rr.wall_collision(0.6, 1.0, 0.5).rods
    assert rod.motion.velocity_final.value == pytest.approx(float(exact), rel=1e-15)
    assert f"leaves at {float(exact):.4g}, not 0.3" in text
    root = Path(__file__).parent.parent
    for page in ("core.md", "conventions.md"):
        flat = " ".join((root / "docs" / page).read_text().split())
        assert "Sec. 6, Eq. (29)" in flat and "γ̄′V̄′ = −ε γ̄V̄" in flat and "not 0.3" in flat, page


def test_every_event_a_caption_names_is_inside_its_steps_diagram() -> None:
    """A student looks for the event a caption names on the step's exported diagram: its first view
    (the step's own state, its layers: with the light signals, the window reaches their arrivals)
    contains every coordinate pair the caption gives."""
    from rigidrel_app.export.diagram_html import _panels  # pyright: ignore[reportPrivateUsage]
    from rigidrel_app.view.state import resolve, settings_for

    checked = 0
    for step in lesson_from("paper").steps:
        r = resolve(settings_for(step.resolved.scene, step.resolved.frame).with_layers(step.layers))
        assert not isinstance(r, str)
        ranges = _panels(r)[2]
        (t0, t1), (x0, x1) = ranges["yaxis.range"], ranges["xaxis.range"]
        for m in PAIR.finditer(" ".join(step.caption.split())):
            if m["label"] is None:
                continue
            t, x = (float(v.replace("−", "-")) for v in (m["t"], m["x"]))
            assert t0 <= t <= t1 and x0 <= x <= x1, f"step {step.title!r}: {m[0]} outside {ranges}"
            checked += 1
    assert checked >= 14


def test_each_caption_states_what_its_numbers_depend_on() -> None:
    """The wall crash names V and ε and gives T′_1, spelled as the paper does and tied once to the
    command line's T_1'; the bounces and the collision say they are elastic; the collision's lengths
    are L0 for both rods, as in the paper; Bell's s and a are given; the pole moves at −V; the
    paper's primes are explained where the first one appears."""
    steps = {s.title: (" ".join(s.caption.split()), s.resolved.scene) for s in lesson_from("paper").steps}
    text, scene = steps["Born-rigid constant acceleration"]
    assert "a′ is a proper acceleration, measured in the end's own momentary rest frame" in text
    assert "t′ and x′ are another frame's coordinates" in text
    text, scene = steps["The wall crash (Sec. 5)"]
    v, eps = scene.parameters["v"], scene.parameters["eps"]
    assert f"moving at −V = −{v:g}" in text and f"(ε = {eps:g}, a crash)" in text
    t, x = scene.events["T_1'"]
    assert f"From T′_1 (`T_1'` on the command line), (lab t, x) = ({t:.3g}, {x:.3g}), it is at rest" in text
    assert sum("on the command line" in s[0] for s in steps.values()) == 1
    assert "With ε = 1, an elastic bounce" in steps["An elastic bounce"][0]
    text, scene = steps["Two rods collide: case I in the lab"]
    assert f"elastically (ε = {scene.parameters['eps']:g})" in text
    assert [r.motion.length for r in scene.rods] == [1.0, 1.0] and "(L1 = L2 = L0)" in text
    assert "−γ1V1L0 = " in text and "L1 =" not in text.split("(L1 = L2 = L0)")[1]
    text, scene = steps["Bell's spaceships"]
    p = scene.parameters
    assert (
        f"rear ends start s = {p['separation']:g} apart in the lab, each with proper acceleration a = {p['a_back']:g}"
        in text
    )
    text, scene = steps["The pole in the barn: a Born-rigid stop beside a stop by signals"]
    assert f"moving at −V = −{scene.parameters['v']:g}" in text
    assert scene.rods[0].motion.velocity_initial.value == -scene.parameters["v"]


def test_a_caption_writes_every_negative_number_with_the_minus_sign() -> None:
    """The prose writes −V and 1 − a′_F L0; a number filled in is written the same way, −0.75, never
    -0.75 beside it (a command line in a code span is left as typed)."""
    from rigidrel_app.lessons.captions import with_minus_signs

    for step in lesson_from("paper").steps:
        prose = "".join(part for k, part in enumerate(step.caption.split("`")) if k % 2 == 0)
        assert re.search(r"(?<![\w′'.\])-])-\.?\d", prose) is None, step.title
    assert "(lab t, x) = (−0.75, 1.25)" in " ".join(lesson_from("paper").steps[5].caption.split())
    assert with_minus_signs("x = -0.3, 1e-5, Born-rigid, `--v -0.3`") == "x = −0.3, 1e-5, Born-rigid, `--v -0.3`"


#: An end named by its place in the motion (front, back, rear) where the light and causality blocks
#: name it by its side: the first time each body's end is named so in a scene's events, its side is
#: given too, "the back (left) end", so one output never leaves two names for one end untied.
END_BY_MOTION = re.compile(
    r"(?:(?P<owner>[\w-]+(?: [\w-]+)?'s) |the )(?P<which>front|back|rear)(?P<side> \((?:left|right)\))? end"
)


@pytest.mark.parametrize("kind", list(rr.scene_descriptions()))
def test_an_end_named_front_or_back_is_tied_to_its_side(kind: str) -> None:
    tied: set[tuple[str, str]] = set()
    for event in rr.describe(kind).events:
        for m in END_BY_MOTION.finditer(event.meaning):
            if (m["owner"] or "").endswith("string's"):
                continue  # the string's rear end is the rear ship's front end, named beside it
            key = (m["owner"] or "", m["which"])
            assert m["side"] is not None or key in tied, (event.name, event.meaning)
            tied.add(key)
    scene = rr.describe(kind).build()
    if scene.n_rods > 1 and all(r.name.endswith("pole") for r in scene.rods):
        assert "each rod" not in signals_in(scene, rr.LAB).key_definition


@pytest.mark.parametrize("kind", list(rr.scene_descriptions()))
def test_none_is_said_to_give_what_each_help_says(kind: str, capsys: pytest.CaptureFixture[str]) -> None:
    """'none' never omits a barn, a door or a ship: each optional parameter's help says what 'none'
    gives (a default from the other parameters, the impulsive limit, a string that never breaks),
    and the option's line points there; a summary that states a verdict of the defaults says so."""
    d = rr.describe(kind)
    with pytest.raises(SystemExit):
        main(["events", kind, "--help"])
    text = " ".join(capsys.readouterr().out.split())
    assert "omits it" not in text
    for p in d.parameters:
        if p.optional:
            assert re.search(r"\bnone\b", d.help_for(p)), p.name
    if kind == "pole-barn":
        assert "With both defaults it closes on the Born-rigid pole" in d.summary


def test_masses_the_scene_chooses_and_rest_energy_in_compression_are_said() -> None:
    """Bell's ships and rod and the barn's poles have rest mass 1 because the scene has no mass option:
    each system says so. The signal-limited pole ends compressed, so its new rest energy is not all
    heat: part is the energy of its compression; a Born-rigid body's is never said to be."""
    for kind in ("bell-spaceships", "pole-barn"):
        d = rr.describe(kind)
        assert "mass" not in d.parameter_map
        for system in d.build().systems:
            assert "rest mass M = 1" in system.name, system.name
    budget = rr.build_scene("pole-barn").budget()
    born, plastic = budget.systems
    assert plastic.heat_where.startswith(
        "in the signal-limited pole: not all heat, part is the energy of its compression"
    )
    assert "compression" not in born.heat_where
    for values in ({"eps": 0.5}, {"eps": 0.0}):
        for system in rr.build_scene("rod-collision", **values).budget().systems:
            assert "compression" not in system.heat_where


def test_the_frame_line_writes_beta_as_the_prose_does(capsys: pytest.CaptureFixture[str]) -> None:
    """The frame's velocity is β in the header, as in every sentence below it (never "beta")."""
    out = _events(["wall-collision", "--frame=rod before"], capsys)
    assert "frame      rod before  (β = -0.6): every table below is in this frame" in out
    assert "beta" not in out
