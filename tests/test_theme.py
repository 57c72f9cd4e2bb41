"""The dark projector theme's colours and wiring, without a browser.

A dark page shows each light-theme colour with its HSL lightness flipped (hue and saturation kept);
the live canvas gets there by sending each colour's complement at equal lightness and letting the
browser invert the canvas exactly. The browser half is in ``tests/browser/test_theme_browser.py``.
"""

from __future__ import annotations

import colorsys
import json
import subprocess
import sys

import numpy as np
import pytest

from rigidrel_app.backends.viser import DARK_CANVAS_CSS, sent_for_shade
from rigidrel_app.cli import build_parser
from rigidrel_app.live.controls import caption_message, page_style
from rigidrel_app.live.keys import HOTKEYS, LESSON_HOTKEYS, Action, action_for
from rigidrel_app.view.layout import CAPTION_SHARE, NORMAL, PRESENTER, canvas_layout, caption_reserve
from rigidrel_app.view.objects import BARRIER_COLOR, MARKER_COLOR
from rigidrel_app.view.vocabulary import (
    FRAME_COLOR,
    INK,
    LIGHT_COLOR,
    ROD_COLORS,
    lightness_flipped,
    rgb,
    shaded,
)

PALETTE = (INK, *ROD_COLORS, FRAME_COLOR, LIGHT_COLOR, BARRIER_COLOR, MARKER_COLOR)
#: HSL hue and saturation survive the flip up to the 1/255 rounding of 8-bit channels.
HSL_TOLERANCE = 2.5 / 255


@pytest.fixture
def colors() -> np.ndarray:
    rng = np.random.default_rng(7)
    return rng.integers(0, 256, size=(4000, 3), dtype=np.uint8)


def test_the_flip_swaps_white_and_black_and_fixes_mid_grey() -> None:
    assert tuple(lightness_flipped([255, 255, 255])) == (0, 0, 0)
    assert tuple(lightness_flipped([0, 0, 0])) == (255, 255, 255)
    assert shaded(INK, "dark") == "#DDDDDD"
    assert shaded(ROD_COLORS[0], "dark") == "#4DBFFF"
    assert shaded(ROD_COLORS[0], "light") == ROD_COLORS[0]


def test_the_flip_is_its_own_inverse(colors: np.ndarray) -> None:
    np.testing.assert_array_equal(lightness_flipped(lightness_flipped(colors)), colors)


def test_the_flip_keeps_hue_and_saturation_and_flips_lightness(colors: np.ndarray) -> None:
    flipped = lightness_flipped(colors)
    for c, f in zip(colors / 255.0, flipped / 255.0, strict=True):
        h0, l0, s0 = colorsys.rgb_to_hls(*c)
        h1, l1, s1 = colorsys.rgb_to_hls(*f)
        assert l1 == pytest.approx(1.0 - l0, abs=1e-12)
        if 0.0 < l0 < 1.0 and s0 > 0.05:  # hue is meaningless for greys
            assert min(abs(h1 - h0), 1.0 - abs(h1 - h0)) <= HSL_TOLERANCE / max(s0, 1e-9)
            assert s1 == pytest.approx(s0, abs=HSL_TOLERANCE / min(l0, 1.0 - l0) + 1e-12)


def test_what_is_sent_for_a_dark_page_shows_the_flipped_colour_once_inverted(colors: np.ndarray) -> None:
    """The canvas' CSS ``invert(1)`` shows ``255 - sent``: that must be the flipped colour, exactly."""
    np.testing.assert_array_equal(255 - sent_for_shade(colors, "dark").astype(int), lightness_flipped(colors))
    np.testing.assert_array_equal(sent_for_shade(colors, "light"), colors)


def test_every_palette_colour_is_readable_on_black() -> None:
    """WCAG contrast of each flipped palette colour against black: at least 4.5 (text and thin lines)."""

    def luminance(c: tuple[int, int, int]) -> float:
        s = np.asarray(c) / 255.0
        lin = np.where(s <= 0.04045, s / 12.92, ((s + 0.055) / 1.055) ** 2.4)
        return float(lin @ [0.2126, 0.7152, 0.0722])

    for color in PALETTE:
        flipped = tuple(int(v) for v in lightness_flipped(rgb(color)))
        assert (luminance(flipped) + 0.05) / 0.05 >= 4.5, (color, flipped)  # type: ignore[arg-type]


def test_the_page_style_inverts_the_canvas_only_when_dark() -> None:
    assert page_style("light") == ""
    assert DARK_CANVAS_CSS in page_style("dark") and "invert(1)" in DARK_CANVAS_CSS
    dark = json.loads(caption_message("", False, "dark"))
    assert dark == {
        "html": "",
        "shown": False,
        "style": page_style("dark"),
        "reserve": caption_reserve(NORMAL),
        "share": CAPTION_SHARE,
    }
    band = json.loads(caption_message("<h2>Step</h2>", True))
    assert band["style"] == "" and band["shown"] and "<h2>Step</h2>" in band["html"]


def test_the_dark_theme_lays_the_page_out_as_the_light_one() -> None:
    from dataclasses import replace

    for theme in (NORMAL, PRESENTER):
        light = canvas_layout(1280, 720, theme)
        dark = canvas_layout(1280, 720, replace(theme, shade="dark"))
        assert dark.theme.shade == "dark" and replace(dark, theme=theme) == light


def test_t_toggles_the_theme_in_both_key_tables() -> None:
    for table in (HOTKEYS, LESSON_HOTKEYS):
        assert action_for("T", table) is Action.TOGGLE_THEME


def test_serve_takes_a_theme() -> None:
    args = build_parser().parse_args(["serve", "--theme", "dark"])
    assert args.theme == "dark"
    assert build_parser().parse_args(["serve"]).theme == "light"
    assert build_parser().parse_args(["serve", "--theme", "dark", "rod-collision"]).theme == "dark"


@pytest.mark.slow  # a new interpreter
def test_serve_refuses_an_unknown_theme_in_one_line() -> None:
    done = subprocess.run(
        [sys.executable, "-m", "rigidrel_app.cli", "serve", "--theme", "purple"],
        capture_output=True,
        text=True,
        timeout=60,
    )
    assert done.returncode == 2
    lines = done.stderr.strip().splitlines()
    assert len(lines) == 1 and "--theme" in lines[0] and "light" in lines[0] and "dark" in lines[0], done.stderr


# ---------------------------------------------------------------- the exports in the dark theme
def _colors(node: object, key: str = "") -> list[str]:
    """Every colour string in a plotly figure dict (values of keys ending in "color")."""
    if isinstance(node, dict):
        return [c for k, v in node.items() for c in _colors(v, str(k))]
    if isinstance(node, list):
        return [c for v in node for c in _colors(v, key)]
    return [node] if isinstance(node, str) and key.endswith("color") else []


def _six(color: str) -> str:
    """``#abc`` or ``#aabbcc`` as ``#AABBCC``."""
    c = color.upper()
    return "#" + "".join(2 * ch for ch in c[1:]) if len(c) == 4 else c


def test_a_dark_figure_flips_every_colour_and_makes_plotly_defaults_explicit() -> None:
    from rigidrel_app.backends.plotly import shaded_figure
    from rigidrel_app.export.diagram_html import diagram_figure
    from rigidrel_app.view.state import Settings

    light = diagram_figure(Settings.of("rod-collision"))
    assert shaded_figure(light, "light") is light
    dark = shaded_figure(light, "dark")
    layout = dark["layout"]
    assert layout["paper_bgcolor"] == layout["plot_bgcolor"] == "#000000"
    assert layout["font"]["color"] == "#DDDDDD"
    assert layout["xaxis"]["zerolinecolor"] == shaded("#444444", "dark")
    assert layout["sliders"][0]["bgcolor"] == shaded("#F8FAFC", "dark")
    assert layout["updatemenus"][0]["font"]["color"] == "#DDDDDD"
    light_colors = {_six(c) for c in _colors(light) if c.startswith("#")}
    dark_colors = {c.upper() for c in _colors(dark) if c.startswith("#")}
    assert {shaded(c, "dark") for c in light_colors} <= dark_colors
    assert shaded(ROD_COLORS[0], "dark") in dark_colors and ROD_COLORS[0] not in dark_colors
    assert len(dark["frames"]) == len(light["frames"])  # every slider frame is shaded too
    assert shaded(ROD_COLORS[1], "dark") in {c.upper() for c in _colors(dark["frames"][-1])}
    assert "frames" in light and _colors(light)  # the light figure is not changed in place
    assert light["layout"].get("paper_bgcolor") != "#000000"


def test_plotly_colour_strings_of_every_form_are_flipped() -> None:
    from rigidrel_app.backends.plotly import shaded_figure

    fig = {"data": [{"line": {"color": "rgba(0,114,178,0.3)"}, "marker": {"color": "#fff"}}], "layout": {}}
    dark = shaded_figure(fig, "dark")
    assert dark["data"][0]["line"]["color"] == "rgba(77,191,255,0.3)"
    assert dark["data"][0]["marker"]["color"] == "#000000"
    assert shaded_figure({"data": [{"fillcolor": "white"}]}, "dark")["data"][0]["fillcolor"] == "#000000"
    assert shaded_figure({"data": [{"color": "toself"}]}, "dark")["data"][0]["color"] == "toself"  # not a colour


@pytest.mark.slow  # records through a viser server
def test_the_dark_diagram_page_and_lanes_recording_are_dark() -> None:
    from rigidrel_app.export.diagram_html import diagram_html
    from rigidrel_app.export.recording import record_lanes_html
    from rigidrel_app.view.scene_view import build_drawing
    from rigidrel_app.view.state import Settings, resolve

    page = diagram_html(Settings.of("wall-collision"), "beside", "dark")
    assert "background: #000000" in page and '"paper_bgcolor":"#000000"' in page.replace(" ", "")
    assert "background: #000000" not in diagram_html(Settings.of("wall-collision"), "beside")
    resolved = resolve(Settings.of("wall-collision"))
    assert not isinstance(resolved, str)
    drawn = build_drawing(resolved)
    assert DARK_CANVAS_CSS in record_lanes_html(drawn, 0.2, 10.0, shade="dark")
    assert DARK_CANVAS_CSS not in record_lanes_html(drawn, 0.2, 10.0)


def test_dark_raster_frames_are_the_light_ones_flipped(tmp_path: object) -> None:
    from pathlib import Path

    from PIL import Image

    from rigidrel_app.backends.raster import lane_frames, write_gif
    from rigidrel_app.view.scene_view import build_drawing
    from rigidrel_app.view.state import Settings, resolve

    resolved = resolve(Settings.of("constant-acceleration"))
    assert not isinstance(resolved, str)
    drawn = build_drawing(resolved)
    (light,) = lane_frames(drawn, [0.5], 480)
    (dark,) = lane_frames(drawn, [0.5], 480, "dark")
    np.testing.assert_array_equal(np.asarray(dark), lightness_flipped(np.asarray(light)))
    gif = write_gif(drawn, Path(str(tmp_path)) / "dark.gif", np.array([0.0, 0.5]), 10.0, 480, "dark")
    first = np.asarray(Image.open(gif).convert("RGB"))
    assert tuple(first[2, 2]) == (0, 0, 0)  # the ground
    rod = lightness_flipped(rgb(ROD_COLORS[0]))
    assert (np.abs(first.astype(int) - rod).max(axis=-1) == 0).mean() > 0.01  # the rods, flipped, kept exact


def test_export_takes_a_theme_before_or_after_the_scene() -> None:
    parser = build_parser()
    assert parser.parse_args(["export", "rod-collision", "--out", "x", "--theme", "dark"]).theme == "dark"
    assert parser.parse_args(["export", "--theme", "dark", "rod-collision", "--out", "x"]).theme == "dark"
    assert parser.parse_args(["export", "rod-collision", "--out", "x"]).theme == "light"
    assert parser.parse_args(["export", "--lesson", "paper", "--out", "x", "--theme", "dark"]).theme == "dark"
