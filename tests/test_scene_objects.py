"""Objects that are not rods come with their own drawing description (:class:`rigidrel_core.SceneObject`),
and the view, the backends and the exports draw them from it alone, by role.

A scene registered at run time with an object kind no front end has heard of (a piston pushing a rod)
is drawn on the canvas, in the recordings and in print without a line of drawing code of its own; and
nothing outside the scene modules names a scene, its class or an object kind to draw it.
"""

from __future__ import annotations

import ast
import dataclasses
from collections.abc import Iterator
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest
from PIL import Image, ImageSequence

import rigidrel_core as rr
from rigidrel_app.backends.raster import LaneRaster, page_image, write_gif
from rigidrel_app.export.figures import print_style
from rigidrel_app.export.paradox_figures import paradox_figures, preset_figure
from rigidrel_app.view.canvas import legend_rows, moving_picture, still_picture
from rigidrel_app.view.layout import canvas_layout
from rigidrel_app.view.objects import BARRIER_COLOR, OBJECT_STYLES, PRINT_GREY
from rigidrel_app.view.scene_view import build_drawing, lane_states, readout_markdown
from rigidrel_app.view.state import Resolved, Settings, resolve
from rigidrel_app.view.vocabulary import Polyline, rgb

ROOT = Path(__file__).resolve().parents[1]
LAYOUT = canvas_layout(1280, 720)

#: An object kind of a known role that the catalogue does not have.
PISTON = rr.ObjectKind("piston", rr.ObjectRole.BARRIER)
KIND = "piston-push-registered"


def pushed_by_a_piston(v: float, length: float, a_front: float, mass: float = 1.0) -> rr.Scene:
    """Sec. 3's constant acceleration, the rod pushed at its back end by a piston: the piston's face is
    the rod's left end (its matter toward -x), and it stops pushing where that end stops accelerating."""
    scene = rr.constant_acceleration(v, length, a_front, mass)
    face = rr.MaterialWorldline(0, 0.0, scene.rods[0].motion)
    piston = rr.SceneObject("piston", PISTON, (face,), side=-1, event=rr.ObjectEvent("push ends", scene.events["T_B"]))
    return dataclasses.replace(scene, objects=(piston,))


def _caption(scene: rr.Scene) -> str:
    t, x = scene.events["T_B"]
    return f"A rod pushed by a piston (grey) to V = {scene.parameters['v']:g}; the push ends at ({t:.4g}, {x:.4g})."


def piston_description() -> rr.SceneDescription:
    base = rr.describe("constant-acceleration")
    figure = rr.PresetFigure(KIND, (0.0, 2.2), (("T_B", "right"), ("push ends", "left")), _caption)
    return rr.SceneDescription(
        kind=KIND,
        title="Rod pushed by a piston",
        summary="A piston pushes a rod's back end; the rod accelerates Born-rigidly.",
        source="Sec. 3",
        constructor=pushed_by_a_piston,
        parameters=base.parameters,
        frames=base.frames,
        default_frame=base.default_frame,
        events=base.events,
        objects=(PISTON,),
        presets=(rr.ScenePreset("piston, V = 0.6", {"v": 0.6, "length": 1.0, "a_front": 0.5}, figure=figure),),
        order=15,
    )


@pytest.fixture
def piston_scene() -> Iterator[rr.SceneDescription]:
    description = rr.register_scene(piston_description())
    try:
        yield description
    finally:
        rr.unregister_scene(KIND)


def _has_color(img: np.ndarray, color: str) -> bool:
    return bool(np.all(np.asarray(img)[..., :3] == np.array(rgb(color), dtype=np.uint8), axis=-1).any())


def test_every_role_has_a_style() -> None:
    assert set(OBJECT_STYLES) == set(rr.ObjectRole)


def test_a_new_object_kind_registered_at_run_time_is_drawn_by_its_role(
    piston_scene: rr.SceneDescription, tmp_path: Path
) -> None:
    """The piston: in both lanes a bar in the barriers' colour whose face is the rod's left end, on the
    diagrams its worldline (the rod's left end's, as finely sampled) named in the legend, in the page's
    still picture and the recordings' frames in its colour, in print in the print style's grey."""
    r = resolve(Settings(KIND))
    assert isinstance(r, Resolved) and r.scene.objects[0].kind == PISTON
    d = build_drawing(r, areas=LAYOUT.chart_areas, label_px=LAYOUT.theme.text_px)
    barrier = OBJECT_STYLES[rr.ObjectRole.BARRIER].diagram
    assert barrier is not None and barrier.color == BARRIER_COLOR
    for chart, frame in ((d.lab_chart, rr.LAB), (d.frame_chart, r.frame)):
        (line,) = [it for it in chart.items if isinstance(it, Polyline) and it.style.name == "piston"]
        assert line.style == replace(barrier, name="piston")
        np.testing.assert_array_equal(line.x, r.scene.material_positions(line.y, frame=frame, fractions=[0.0])[0, 0])
    assert "piston" in {e.name for e in d.legend()}
    shown = 0
    for now in np.linspace(*d.window, 7):
        for lane in d.lane_pictures(float(now), LAYOUT):
            rod, *objects = lane.boxes
            (piston,) = objects if objects else (None,)
            if piston is None:  # out of the lane's view
                continue
            assert piston.color == BARRIER_COLOR and piston.x0 < piston.x1
            if rod.x0 > LAYOUT.lanes[0].track.x0:
                assert piston.x1 == rod.x0  # its face on the rod's back end, its matter behind it
                shown += 1
    assert shown > 0
    legend = d.legend()
    layout = canvas_layout(1280, 720, LAYOUT.theme, legend_rows(legend, LAYOUT.legend.width, LAYOUT.theme))
    frames, still = still_picture(d.charts, layout.charts, legend, layout.legend, layout.theme)
    assert _has_color(page_image(still, layout.width, layout.height), BARRIER_COLOR)
    now = 0.5 * sum(d.window)
    lanes = d.lane_pictures(now, layout)
    moving = moving_picture(frames, d.moving_items(now, [lane.ends for lane in lanes]), layout.theme)
    assert page_image(moving, layout.width, layout.height).shape == (720, 1280, 3)
    assert _has_color(np.asarray(LaneRaster(d, 640).frame(lane_states(d, now))), BARRIER_COLOR)
    gif = write_gif(d, tmp_path / "piston.gif", np.linspace(*d.window, 4), 4.0, 320)
    with Image.open(gif) as img:
        assert sum(1 for _ in ImageSequence.Iterator(img)) == 4
    assert "Scene" in readout_markdown(r)
    # in print: its worldline in the barriers' print style, its event marked and named
    (preset,) = piston_scene.presets
    figure = preset_figure(piston_scene, preset)
    assert figure.name == KIND and figure.caption.startswith("A rod pushed by a piston")
    greys = [it for it in figure.chart.items if isinstance(it, Polyline) and it.style.color == PRINT_GREY]
    assert greys and greys[0].style.width == 5.0
    assert "push ends" in {getattr(it, "text", None) for it in figure.chart.items}
    assert print_style(figure.chart)["data"]
    assert KIND in [f.name for f in paradox_figures()]


def test_an_object_has_the_worldlines_its_role_draws() -> None:
    """A body has one worldline (its face), a tie two (its ends); a body's matter lies on one side."""
    face = rr.InertialWorldline(0.0, rr.ExactVelocity.from_float(0.0))
    assert rr.SceneObject("wall", rr.ObjectKind.WALL, (face,)).positions([0.0, 1.0]).shape == (1, 2)
    with pytest.raises(rr.ParameterError, match=r"^worldlines must be 2 worldlines for an object of role 'tie'"):
        rr.SceneObject("string", rr.ObjectKind.STRING, (face,))
    with pytest.raises(rr.ParameterError, match=r"^worldlines must be 1 worldline for an object of role 'barrier'"):
        rr.SceneObject("wall", rr.ObjectKind.WALL, (face, face))
    with pytest.raises(rr.ParameterError, match=r"^side must be -1 or 1"):
        rr.SceneObject("wall", rr.ObjectKind.WALL, (face,), side=0)  # type: ignore[arg-type]


def test_the_figures_are_the_presets_figures() -> None:
    """``rigidrel figures``' scene figures are every preset figure of the registry, none written by hand."""
    expected = [p.figure.name for d in rr.scene_descriptions().values() for p in d.presets if p.figure is not None]
    assert [f.name for f in paradox_figures()] == expected == ["bell-spaceships", "pole-barn"]


# ------------------------------------------------------------------ no special cases outside the scenes
def _scene_classes() -> set[type]:
    rr.scene_descriptions()  # the catalogue loaded: every scene module imported

    def below(c: type) -> Iterator[type]:
        for s in c.__subclasses__():
            yield s
            yield from below(s)

    return set(below(rr.Scene))


def _front_end_files() -> tuple[list[Path], list[Path]]:
    """The app's modules (but the speed-accuracy study's, which compares each scene with its own
    textbook formulas and 50-digit reference by design), and the core's outside its scene modules (and
    the package's re-exports)."""
    app = [p for p in (ROOT / "app" / "rigidrel_app").rglob("*.py") if "bench" not in p.parts]
    core = [p for p in (ROOT / "rigidrel_core").rglob("*.py") if "scenes" not in p.parts and p.name != "__init__.py"]
    return sorted(app), sorted(core)


def _motion_class_tests(node: ast.AST) -> list[str]:
    """The ``isinstance`` calls under ``node`` that ask whether a motion is of a class."""
    return [
        ast.unparse(call)
        for call in ast.walk(node)
        if isinstance(call, ast.Call)
        and ast.unparse(call.func) == "isinstance"
        and len(call.args) == 2
        and any(name in ast.unparse(call.args[1]) for name in ("RigidMotion", "PlasticMotion"))
    ]


def _dotted(node: ast.AST) -> str:
    return ast.unparse(node)


def test_nothing_outside_the_scene_modules_special_cases_a_scene() -> None:
    """No ``isinstance(..., rr.BellScene)``, no scene class, no scene's own API (``string_strains``,
    ``door_closing``, ...), no object kind by name (``ObjectKind.WALL``) and no comparison with or table
    keyed by a scene's name (``kind == "pole-barn"``) in the app or in the core outside
    ``rigidrel_core/scenes/``, and no test of a motion's class in the app: they draw every scene and
    object from its description."""
    classes = _scene_classes()
    class_names = {c.__name__ for c in classes}
    own_api = {a for c in classes for a in vars(c) if not a.startswith("_")} - set(dir(rr.Scene))
    kinds = set(rr.scene_descriptions())
    object_names = {k.name for d in rr.scene_descriptions().values() for k in d.objects}
    found: list[str] = []
    app, core = _front_end_files()
    for path in app + core:
        tree = ast.parse(path.read_text(encoding="utf-8"))
        where = path.relative_to(ROOT)
        if path in app:
            found += [f"{where}: {call}" for call in _motion_class_tests(tree)]
        for node in ast.walk(tree):
            at = f"{where}:{getattr(node, 'lineno', 0)}"
            if isinstance(node, ast.Name) and node.id in class_names:
                found.append(f"{at}: names the scene class {node.id}")
            elif isinstance(node, ast.Attribute):
                if node.attr in class_names:
                    found.append(f"{at}: names the scene class {node.attr}")
                elif node.attr in own_api and _dotted(node.value) != "self":
                    found.append(f"{at}: uses a scene's own API, {_dotted(node)}")
                elif (  # naming one to draw it, not defining it (the catalogue's, in rigidrel_core/_kinds.py)
                    node.attr.isupper()
                    and _dotted(node.value).split(".")[-1] == "ObjectKind"
                    and not isinstance(node.ctx, ast.Store)
                ):
                    found.append(f"{at}: names an object kind, {_dotted(node)}")
            elif isinstance(node, ast.Compare):
                for side in (node.left, *node.comparators):
                    if isinstance(side, ast.Constant) and side.value in kinds | object_names:
                        found.append(f"{at}: compares with {side.value!r}")
            elif isinstance(node, ast.Dict):
                for key in node.keys:
                    if isinstance(key, ast.Constant) and key.value in kinds:
                        found.append(f"{at}: a table keyed by the scene {key.value!r}")
            elif (
                isinstance(node, ast.MatchValue)
                and isinstance(node.value, ast.Constant)
                and node.value.value in kinds | object_names
            ):
                found.append(f"{at}: a case for {node.value.value!r}")
    assert found == []


def test_no_test_skips_a_rod_by_its_motions_class() -> None:
    """A test that holds only for Born-rigid rods asks the motion (``motion.born_rigid``), not its class."""
    found = []
    for path in sorted((ROOT / "tests").rglob("*.py")):
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.If):
                found += [f"{path.relative_to(ROOT)}:{node.lineno}: {call}" for call in _motion_class_tests(node.test)]
    assert found == []
