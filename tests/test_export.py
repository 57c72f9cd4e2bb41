"""``rigidrel export`` and ``rigidrel figures``: every file written, the right size, not blank."""

from __future__ import annotations

import re
import subprocess
import sys
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest
from PIL import Image

import rigidrel_core as rr
from rigidrel_app.cli import main
from rigidrel_app.export.diagram_html import SliderAxis, diagram_figure, slider_axes
from rigidrel_app.export.figures import paper_figures
from rigidrel_app.export.recording import record_lanes_html
from rigidrel_app.view.scene_view import build_drawing
from rigidrel_app.view.state import CUSTOM_FRAME, Resolved, Settings, settings_for
from rigidrel_app.view.vocabulary import Polyline

ROOT = Path(__file__).resolve().parents[1]
pytestmark = pytest.mark.slow


def rigidrel(*args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [sys.executable, "-m", "rigidrel_app.cli", *args], capture_output=True, text=True, cwd=ROOT, timeout=300
    )


def not_blank(img: Image.Image) -> bool:
    a = np.asarray(img.convert("RGB")).astype(int)
    return bool(a.std() > 10 and (a.sum(axis=-1) < 600).mean() > 0.01)


@pytest.fixture(scope="module")
def exported(tmp_path_factory: pytest.TempPathFactory) -> Path:
    out = tmp_path_factory.mktemp("export")
    r = rigidrel(
        "export", "rod-collision", "--mass2", "2", "--out", str(out), "--seconds", "2", "--fps", "10", "--gif-fps", "5"
    )
    assert r.returncode == 0, r.stderr
    return out


def test_export_writes_every_format(exported: Path) -> None:
    names = sorted(p.name for p in exported.iterdir())
    assert names == sorted(
        f"rod-collision-{s}"
        for s in ("3d.html", "diagram.html", "diagram.png", "diagram.svg", "lanes.gif", "lanes.mp4")
    )


def test_3d_html_is_standalone_and_small(exported: Path) -> None:
    html = (exported / "rod-collision-3d.html").read_text()
    assert len(html.encode()) < 3e6
    assert "__VISER_EMBED_DATA__" in html
    assert "http://" not in html.split("__VISER_EMBED_DATA__")[1][:200]


def test_diagram_images(exported: Path) -> None:
    png = Image.open(exported / "rod-collision-diagram.png")
    assert png.size == (1520, 1280)  # 760 x 640 at scale 2
    assert not_blank(png)
    a = np.asarray(png.convert("RGB")).astype(int)
    blue = ((a[..., 2] - a[..., 0]) > 80).mean()
    orange = ((a[..., 0] - a[..., 2]) > 120).mean()
    assert blue > 0.001 and orange > 0.001  # both rods drawn
    svg = (exported / "rod-collision-diagram.svg").read_text()
    assert svg.startswith("<svg") and svg.count("<path") > 10
    assert "Minkowski diagram" in svg
    # no --frame: the app's default frame (a collision's barycentric frame), not the lab twice
    assert "barycentric" in svg


def test_gif_and_mp4_animate(exported: Path) -> None:
    gif = Image.open(exported / "rod-collision-lanes.gif")
    n_frames = int(getattr(gif, "n_frames", 1))
    assert n_frames == 10  # 2 s at 5 fps
    gif.seek(0)
    first = np.asarray(gif.convert("RGB")).astype(int)
    gif.seek(n_frames - 1)
    last = np.asarray(gif.convert("RGB")).astype(int)
    assert not_blank(Image.fromarray(first.astype(np.uint8)))
    assert (np.abs(first - last).sum(axis=-1) > 60).mean() > 0.005  # the rods moved
    import imageio_ffmpeg

    frames, seconds = imageio_ffmpeg.count_frames_and_secs(str(exported / "rod-collision-lanes.mp4"))
    assert frames == 20 and seconds == pytest.approx(2.0, abs=0.2)


def test_figures_regenerate_the_paper(tmp_path: Path) -> None:
    r = rigidrel("figures", "--out", str(tmp_path))
    assert r.returncode == 0, r.stderr
    for n in (1, 2, 3, 4):
        png = Image.open(tmp_path / f"fig{n}.png")
        assert png.size == (1280, 1120) and not_blank(png)
        svg = (tmp_path / f"fig{n}.svg").read_text()
        assert svg.startswith("<svg")
    for name in ("bell-spaceships", "pole-barn"):  # the paradoxes' figures, with their verdicts as captions
        assert not_blank(Image.open(tmp_path / f"{name}.png"))
        assert (tmp_path / f"{name}.svg").read_text().startswith("<svg")
    assert "the door closes on it" in (tmp_path / "pole-barn.txt").read_text()  # on the Born-rigid pole
    fig1 = (tmp_path / "fig1.svg").read_text().replace("\u200b", "")  # plotly pads labels with zero-width spaces
    assert "stroke-dasharray" in fig1  # the impulsive curve, dashed
    for label in (">T<", ">B<", ">F<"):
        assert label in fig1
    fig3 = (tmp_path / "fig3.svg").read_text().replace("\u200b", "")
    assert fig3.count(">T<") + fig3.count(">T′<") >= 4
    # every sampled vertex reaches the SVG: plotly's line simplification would drop the ones it
    # judges collinear and leave visible corners on the hyperbolas
    sampled = max(it.x.size for it in paper_figures()[2].chart.items if isinstance(it, Polyline))
    drawn = max(path.count("L") + 1 for path in re.findall(r'd="(M[^"]+)"', fig3))
    assert drawn == sampled > 30


@pytest.mark.parametrize(
    ("args", "needle"),
    [
        (["export", "wall-collision", "--eps", "2", "--out", "{tmp}"], "eps must be a finite number in [0, 1]"),
        (["export", "rod-collision", "--out", "/proc/rigidrel-cannot"], "--out '/proc/rigidrel-cannot' cannot"),
        (["export", "rod-collision", "--out", "{tmp}", "--fps", "0"], "must be in (0, 1e4)"),
        (["export", "rod-collision"], "--out"),
        (["figures", "--out", "/proc/rigidrel-cannot"], "cannot be created"),
    ],
)
def test_bad_export_arguments(args: list[str], needle: str, tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    """In-process (``rigidrel_app.cli.main``); the missing ``--out`` in a new interpreter too, below."""
    with pytest.raises(SystemExit) as exit_:
        main([a.replace("{tmp}", str(tmp_path)) for a in args])
    assert exit_.value.code == 2
    err = capsys.readouterr().err
    assert len(err.splitlines()) == 1 and needle in err, err


def test_a_bad_export_argument_from_a_new_interpreter() -> None:
    r = rigidrel("export", "rod-collision")
    assert r.returncode == 2
    assert len(r.stderr.splitlines()) == 1 and "--out" in r.stderr, r.stderr


@pytest.mark.parametrize("kind", list(rr.scene_descriptions()))
def test_every_registered_scene_exports_its_pages(kind: str) -> None:
    """The offline pages come from the registry: every scene gets a diagram page with two working
    sliders and a 3-D recording, at its defaults and in its default frame."""
    scene = rr.build_scene(kind)
    frame = rr.default_frame(scene)
    figure = diagram_figure(settings_for(scene, frame))
    sliders = figure["layout"]["sliders"]
    assert len(sliders) == 2 and all(len(s["steps"]) >= 2 for s in sliders)
    assert len(figure["frames"]) >= 4
    x_title = figure["layout"]["xaxis"]["title"]["text"]
    assert x_title.endswith("(in the scene's length unit, c = 1)") and "rod 1" not in x_title  # ships, poles too
    assert figure["layout"]["xaxis2"]["title"]["text"] == "lab t, or t′ of the frame chosen"  # whose time
    settings = settings_for(scene, frame)
    for axis in slider_axes(settings):
        assert_evenly_spaced(axis.values, is_log(settings, axis))
    html = record_lanes_html(build_drawing(Resolved(scene, frame)), seconds=1.0, fps=5.0)
    assert "__VISER_EMBED_DATA__" in html


def is_log(settings: Settings, axis: SliderAxis) -> bool:
    """Whether a page slider is a log slider (a parameter's with ``scale="log"``; the frame's is linear)."""
    if axis.parameter is None:
        return False
    slider = settings.description.parameter(axis.parameter).slider
    return slider is not None and slider.scale == "log"


def assert_evenly_spaced(values: tuple[float, ...], log: bool) -> None:
    """A page slider's ticks step evenly: equal differences (equal ratios on a log slider)."""
    v = np.log10(values) if log else np.asarray(values)
    assert len(values) >= 2 and np.allclose(np.diff(v), np.diff(v)[0], atol=1e-6), values


@pytest.mark.parametrize(
    "settings",
    [
        Settings("rod-collision"),
        Settings.of("rod-collision", v1=0.99, mass2=0.01),
        Settings.of("rod-collision", v1=0.37, mass2=3.0),
        Settings.of("constant-acceleration", v=0.99),
        Settings("impulsive-start"),
        replace(Settings("impulsive-start"), frame=CUSTOM_FRAME, beta=0.25),
    ],
    ids=lambda s: f"{s.scene}-{s.values}-{s.beta}",
)
def test_page_sliders_step_evenly_through_the_settings(settings: Settings) -> None:
    """Each slider's values are evenly spaced and hold the settings' own value, where the page opens."""
    figure = diagram_figure(settings)
    for axis, slider in zip(slider_axes(settings), figure["layout"]["sliders"], strict=True):
        log = is_log(settings, axis)
        shown = tuple(v for v in axis.values if axis.fmt(v) in {s["label"] for s in slider["steps"]})
        assert_evenly_spaced(shown, log)
        own = axis.own(settings)
        assert own is not None and slider["steps"][slider["active"]]["label"] == axis.fmt(own)


def test_diagram_page_names_each_frames_axes_and_is_sized_for_a_hall() -> None:
    """t′ and x′ in the barycentric frame (every precomputed frame carries its own names: t and x
    where the slider reaches the lab); text and lines large enough to project."""
    figure = diagram_figure(Settings("rod-collision"))
    layout = figure["layout"]
    assert layout["yaxis"]["title"]["text"] == "t′" and layout["xaxis"]["title"]["text"].startswith("x′ ")
    lab = diagram_figure(Settings("impulsive-start"))
    names = {(f["layout"]["yaxis"]["title"]["text"], f["layout"]["xaxis"]["title"]["text"][:2]) for f in lab["frames"]}
    assert names == {("t′", "x′"), ("t", "x ")}  # the frame slider passes β = 0, the lab
    for fig in (figure, lab):
        lay = fig["layout"]
        for ax in ("xaxis", "yaxis", "xaxis2", "yaxis2"):
            assert lay[ax]["tickfont"]["size"] >= 14 and lay[ax]["title"]["font"]["size"] >= 16
        assert lay["title"]["font"]["size"] >= 16
        assert all(s["font"]["size"] >= 14 and s["currentvalue"]["font"]["size"] >= 16 for s in lay["sliders"])
        for frame in fig["frames"]:
            assert all(a["font"]["size"] >= 16 for a in frame["layout"]["annotations"])
            widths = [t["line"]["width"] for t in frame["data"] if t.get("line", {}).get("width")]
            assert widths and min(widths) >= 2.5


def test_a_frame_beyond_the_apps_slider_still_exports() -> None:
    """The app's β slider stops at 0.99, the exports do not: a diagram page in a frame at -0.995."""
    scene = rr.build_scene("constant-acceleration")
    figure = diagram_figure(settings_for(scene, rr.Frame.from_velocity(-0.995)))
    assert "β = -0.995" in figure["layout"]["title"]["text"] and len(figure["frames"]) >= 4
