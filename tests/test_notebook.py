"""The example of docs/notebooks.md, run outside a notebook; the live view's callbacks, run without a browser."""

from __future__ import annotations

import math
import re
import sys
from dataclasses import replace
from pathlib import Path
from typing import Any

import numpy as np
import plotly.graph_objects as go
import pytest

import rigidrel_core as rr
from rigidrel_app.backends.plotly import dumps
from rigidrel_app.backends.viser import DARK_CANVAS_CSS
from rigidrel_app.lessons import lesson_from
from rigidrel_app.notebook import diagram, explore, inline, lesson, recording
from rigidrel_app.notebook.live_state import (
    at_time,
    figure_arrays,
    live_figure,
    moving_traces,
    slider_parameters,
    start,
    static_trace_count,
    with_beta,
    with_parameter,
)
from rigidrel_app.notebook.widget import LiveView
from rigidrel_app.view.comoving import RIDE_LINE_NAME
from rigidrel_app.view.state import CUSTOM_FRAME, DEFAULT_RIDE, RIDE_FRAME
from rigidrel_app.view.vocabulary import lightness_flipped, rgb

NOTEBOOKS_PAGE = Path(__file__).resolve().parents[1] / "docs" / "notebooks.md"


def notebook_block() -> str:
    text = NOTEBOOKS_PAGE.read_text()
    m = re.search(r"<!-- notebook-example[^>]*-->\s*```python\n(.*?)```", text, re.S)
    assert m, "docs/notebooks.md has no notebook example"
    return m.group(1)


@pytest.mark.slow  # records through a viser server
def test_the_notebook_page_example_runs() -> None:
    namespace: dict[str, object] = {}
    exec(compile(notebook_block(), "docs/notebooks.md", "exec"), namespace)
    fig = namespace["fig"]
    rec = namespace["rec"]
    assert isinstance(fig, go.Figure)
    texts = [a.text for a in fig.layout.annotations]
    assert any("T<sub>1</sub>" in t for t in texts) and any("T′<sub>2</sub>" in t for t in texts)
    html = rec._repr_html_()  # type: ignore[attr-defined]
    assert html.startswith("<iframe srcdoc=") and "__VISER_EMBED_DATA__" in html
    assert len(html) > 100_000


# ---------------------------------------------------------------------------------- the live view
# The callbacks run in this process as they would in a kernel: a slider's value is set, ipywidgets
# calls the view's observer, and the FigureWidget's traces are compared with the core's numbers.


def traces(view: LiveView) -> list[Any]:
    """The FigureWidget's traces (plotly's generated trace classes, untyped here)."""
    return list(view.figure.data)


def widget_arrays(view: LiveView) -> list[tuple[np.ndarray, np.ndarray]]:
    return [(np.asarray(t.x, dtype=float), np.asarray(t.y, dtype=float)) for t in traces(view)]


def same_arrays(a: list[tuple[np.ndarray, np.ndarray]], b: list[tuple[np.ndarray, np.ndarray]]) -> bool:
    return len(a) == len(b) and all(
        np.array_equal(xa, xb, equal_nan=True) and np.array_equal(ya, yb, equal_nan=True)
        for (xa, ya), (xb, yb) in zip(a, b)
    )


def test_a_parameter_slider_redraws_the_figure_as_the_core_says() -> None:
    view = explore("rod-collision", v1=0.6, frame="barycentric", t=0.5)
    before = widget_arrays(view)
    view.sliders["v1"].value = 0.8  # as a person dragging it: ipywidgets calls the observer
    after = widget_arrays(view)
    assert not same_arrays(before, after)
    assert view.state.settings.value("v1") == 0.8 and view.state.notice == "" and view.notice.value == ""
    # the very figure the app's builders make of the core's scene with v1 = 0.8, in the same frame at the same time
    assert same_arrays(after, figure_arrays(live_figure(start("rod-collision", "barycentric", 0.5, v1=0.8))))
    # and, straight from the core: the rods' ends now (diamonds on the lab diagram) and the lengths now
    scene = rr.build_scene("rod-collision", v1=0.8)
    frame = scene.frame("barycentric")
    lab_ends = scene.snapshot(0.5, frame=rr.LAB, fractions=[0.0, 1.0])[0]
    drawn_ends = sorted(x for t in traces(view) if t.xaxis == "x" and t.legendgroup == "rods now" for x in t.x)
    assert np.array_equal(np.sort(lab_ends.ravel()), np.array(drawn_ends))
    length_markers = [t for t in traces(view) if t.xaxis == "x3" and t.legendgroup == "rods now"]
    drawn_lengths = sorted(y for t in length_markers for y in t.y)
    core_lengths = np.concatenate([scene.lengths(0.5, frame=rr.LAB), scene.lengths(0.5, frame=frame)])
    assert np.array_equal(np.sort(core_lengths), np.array(drawn_lengths))
    assert f"{scene.final_velocities[0]:+.4f}" in view.readout.value


def test_the_time_slider_moves_only_the_moving_parts() -> None:
    view = explore("wall-collision", v=0.6)
    n_static = static_trace_count(view.state.drawn)
    before = widget_arrays(view)
    t0, t1 = view.state.drawn.window
    view.time.value = round(0.5 * (t0 + t1), 3)
    after = widget_arrays(view)
    assert same_arrays(before[:n_static], after[:n_static])  # the curves stay
    assert not same_arrays(before[n_static:], after[n_static:])  # the now-lines and diamonds move
    assert same_arrays(after, figure_arrays(live_figure(view.state)))
    scene = rr.build_scene("wall-collision", v=0.6)
    frame = view.state.drawn.resolved.frame
    now = view.time.value
    length_markers = [t for t in traces(view) if t.xaxis == "x3" and t.legendgroup == "rods now"]
    drawn = sorted(y for t in length_markers for y in t.y)
    assert np.array_equal(
        np.sort(np.concatenate([scene.lengths(now, frame=rr.LAB), scene.lengths(now, frame=frame)])), drawn
    )


def test_a_refused_value_shows_a_notice_and_keeps_the_picture() -> None:
    view = explore("rod-collision", v1=0.6, frame="barycentric")
    before = widget_arrays(view)
    view.sliders["v1"].value = 0.0  # within the slider, but the rods (v2 = 0) would never meet
    assert "v2 must be less than v1" in view.state.notice and "V2 = 0 refused" in view.notice.value
    assert same_arrays(before, widget_arrays(view))
    assert view.sliders["v1"].value == 0.6  # the slider goes back to the scene on screen
    view.set("mass2", -1.0)  # beyond the core's range: its range is named
    assert view.state.notice.startswith("M2/M1 = -1 refused: mass2 must be a finite number in [1e-120, ")
    assert same_arrays(before, widget_arrays(view)) and view.sliders["mass2"].value == 2.0
    view.set("mass2", 1000.0)  # beyond the log slider but a scene: the slider widens to show it, never clamps
    assert view.state.notice == "" and view.sliders["mass2"].value == 1000.0 and view.sliders["mass2"].max == 3.0
    # the next valid change clears the notice
    view.sliders["mass2"].value = 10.0
    assert view.state.notice == "" and view.notice.value == "" and not same_arrays(before, widget_arrays(view))


def test_refusals_name_the_control_and_its_range() -> None:
    s = start("rod-collision", v1=0.6, frame="barycentric")
    assert with_parameter(s, "v1", 1.2).notice.startswith("V1 = 1.2 refused: v1 must be a finite number in (-1, 1)")
    assert with_parameter(s, "v1", 1.2).drawn is s.drawn
    t0, t1 = s.drawn.window
    assert f"it must be a time in [{t0:g}, {t1:g}]" in at_time(s, t1 + 1.0).notice
    assert "it must be a number in [-0.99, 0.99]" in with_beta(s, 0.995).notice
    assert "not a parameter of rod-collision" in with_parameter(s, "mass", 1.0).notice
    with pytest.raises(rr.ParameterError, match="v1"):
        explore("rod-collision", v1=1.5)  # the opening values are the caller's: the core's error, naming v1


def test_the_frame_menu_and_the_beta_slider() -> None:
    view = explore("rod-collision", v1=0.6)
    assert tuple(view.frame.options) == (*rr.build_scene("rod-collision", v1=0.6).frames, CUSTOM_FRAME, RIDE_FRAME)
    view.frame.value = "rod 2 after"
    beta = rr.build_scene("rod-collision", v1=0.6).frame("rod 2 after").beta
    assert view.state.drawn.resolved.frame.beta == beta and view.beta.value == pytest.approx(beta)
    view.beta.value = -0.5  # the custom frame
    assert view.frame.value == CUSTOM_FRAME and view.state.drawn.resolved.frame.beta == -0.5
    assert same_arrays(widget_arrays(view), figure_arrays(live_figure(view.state)))
    view.frame.value = RIDE_FRAME  # riding the first rod's middle: its comoving line sweeps the diagrams
    assert view.state.drawn.resolved.ride == DEFAULT_RIDE
    assert same_arrays(widget_arrays(view), figure_arrays(live_figure(view.state)))
    names = {t.get("name") for t in live_figure(view.state)["data"]}
    assert RIDE_LINE_NAME in names, names


@pytest.mark.parametrize("kind", sorted(rr.scene_descriptions()))
def test_sliders_are_the_registry_parameters(kind: str) -> None:
    view = explore(kind)
    d = rr.describe(kind)
    assert list(view.sliders) == [p.name for p in d.parameters if p.slider is not None]
    for p, entry in slider_parameters(kind):
        slider = view.sliders[p.name]
        assert slider.description == p.label
        assert p.slider is not None
        if p.slider.scale == "log":
            assert type(slider).__name__ == "FloatLogSlider"
            assert (slider.min, slider.max) == (math.log10(p.slider.lo), math.log10(p.slider.hi))
        else:
            assert (slider.min, slider.max, slider.step) == (p.slider.lo, p.slider.hi, p.slider.step)
        assert entry.label == p.label
    assert (view.time.min, view.time.max) == pytest.approx(view.state.drawn.window, rel=1e-12)


@pytest.mark.parametrize(
    ("values", "frame"),
    [
        ({"v1": 0.99}, 0.99),
        ({"v1": 0.99, "v2": -0.99}, -0.99),
        ({"mass2": 0.01}, "barycentric"),
        ({"mass2": 100.0}, None),
    ],
)
def test_extremes_draw_finite_figures(values: dict[str, float], frame: float | str | None) -> None:
    s = start("rod-collision", frame, theme="light", **values)
    fig = live_figure(s)
    dumps(fig["layout"])  # allow_nan=False: no NaN or infinity in any range, label place or title
    for ax in ("xaxis", "yaxis", "xaxis2", "yaxis2", "xaxis3", "yaxis3"):
        assert all(math.isfinite(v) for v in fig["layout"][ax]["range"])
    for x, y in figure_arrays(fig):
        assert np.isfinite(x[~np.isnan(x)]).all() and np.isfinite(y[~np.isnan(y)]).all()


def test_explore_says_which_extra_it_needs(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setitem(sys.modules, "ipywidgets", None)  # as if not installed
    monkeypatch.delitem(sys.modules, "rigidrel_app.notebook.widget")
    with pytest.raises(ImportError, match=r"pip install 'rigidrel\[notebook\]'"):
        explore("rod-collision")


def test_a_time_that_comes_back_with_float_noise_is_the_same_time() -> None:
    """A browser slider computes ``min + k * step`` in floating point: 0.3 may come back as
    0.29999999999999977, and must not redraw a different picture."""
    s = at_time(start("rod-collision", v1=0.6), 0.3)
    noisy = at_time(s, 0.29999999999999977)
    assert noisy.now == s.now == 0.3 and same_arrays(figure_arrays(live_figure(noisy)), figure_arrays(live_figure(s)))


# ---------------------------------------------------------------------------------- the dark theme
# theme="dark" is the app's projector theme: every colour of a figure lightness-flipped, nothing else changed.


Color = tuple[int, int, int, str]
"""A plotly colour as (r, g, b, alpha as written, "" if none)."""


def color_of(text: str) -> Color:
    """A plotly colour string (``#RGB``, ``#RRGGBB``, ``rgb()``, ``rgba()``, white, black) as a :data:`Color`."""
    c = {"white": "#FFFFFF", "black": "#000000"}.get(text, text)
    if m := re.fullmatch(r"rgba?\((\d+),\s*(\d+),\s*(\d+)(?:,\s*([\d.]+))?\)", c):
        return int(m[1]), int(m[2]), int(m[3]), m[4] or ""
    c = "#" + "".join(2 * ch for ch in c[1:]) if len(c) == 4 else c
    return (*rgb(c), "")


def colors(node: object, key: str = "") -> list[Color]:
    """Every colour in a plotly figure (dict, or a figure's ``to_plotly_json()``), in order:
    the values of keys ending in "color"."""
    if isinstance(node, dict):
        return [c for k, v in node.items() for c in colors(v, str(k))]
    if isinstance(node, list | tuple):
        return [c for v in node for c in colors(v, key)]
    return [color_of(node)] if isinstance(node, str) and key.endswith("color") else []


def flipped(color: Color) -> Color:
    r, g, b = (int(v) for v in lightness_flipped(color[:3]))
    return r, g, b, color[3]


def trace_colors(data: list[Any]) -> list[Color]:
    """Each trace's line, marker and fill colours, in order."""
    return colors([{k: t[k] for k in ("line", "marker", "fillcolor") if k in t} for t in data])


def assert_flipped(light: dict[str, Any], dark: dict[str, Any]) -> None:
    """``dark`` is ``light`` with every trace and annotation colour lightness-flipped, on black."""
    assert dark["layout"]["paper_bgcolor"] == dark["layout"]["plot_bgcolor"] == "#000000"
    lt, dt = trace_colors(light["data"]), trace_colors(dark["data"])
    assert lt and dt == [flipped(c) for c in lt] and dt != lt
    la, da = colors(light["layout"]["annotations"]), colors(dark["layout"]["annotations"])
    assert la and da == [flipped(c) for c in la]


def shown_colors(view: LiveView) -> list[Color]:
    """The colours of the FigureWidget's traces, as :func:`trace_colors` reads a figure dict's."""
    return trace_colors([t.to_plotly_json() for t in traces(view)])


def test_a_dark_diagram_and_lesson_flip_every_colour(monkeypatch: pytest.MonkeyPatch) -> None:
    scene = rr.rod_collision(v1=0.6, v2=0.0, mass1=1.0, mass2=2.0, length1=1.0, length2=1.0, eps=1.0)
    light = diagram(scene, scene.frame("barycentric")).to_plotly_json()
    dark = diagram(scene, scene.frame("barycentric"), theme="dark").to_plotly_json()
    assert_flipped(light, dark)
    assert [t["name"] for t in dark["data"] if "name" in t] == [t["name"] for t in light["data"] if "name" in t]
    light_page, dark_page = lesson("paper").html, lesson("paper", theme="dark").html
    assert dark_page != light_page and dark_page.count("<h3>") == light_page.count("<h3>")
    assert '"paper_bgcolor":"#000000"' in dark_page.replace(" ", "")
    assert '"paper_bgcolor":"#000000"' not in light_page.replace(" ", "")
    shown: list[dict[str, Any]] = []  # each step's figure, as the lesson puts it into its page
    monkeypatch.setattr(inline, "offline_html", lambda fig: shown.append(fig.to_plotly_json()) or "")
    lesson("paper")
    n = len(shown)
    lesson("paper", theme="dark")
    assert n == len(shown) - n == len(lesson_from("paper").steps)
    for light_step, dark_step in zip(shown[:n], shown[n:]):
        assert_flipped(light_step, dark_step)


@pytest.mark.slow  # records through a viser server
def test_a_dark_recording_is_the_exports_dark_recording() -> None:
    scene = rr.build_scene("wall-collision", v=0.6)
    dark, light = recording(scene, seconds=0.2, fps=10.0, theme="dark"), recording(scene, seconds=0.2, fps=10.0)
    assert DARK_CANVAS_CSS in dark.html and DARK_CANVAS_CSS not in light.html


def test_the_dark_live_view_flips_every_colour_and_keeps_them_through_changes() -> None:
    light = live_figure(start("rod-collision", "barycentric", 0.5, v1=0.6))
    dark_state = start("rod-collision", "barycentric", 0.5, theme="dark", v1=0.6)
    dark = live_figure(dark_state)
    assert_flipped(light, dark)
    assert same_arrays(figure_arrays(dark), figure_arrays(light))  # the same curves, as numpy arrays
    # the time slider's traces are coloured as the same traces of the whole dark figure
    n = static_trace_count(dark_state.drawn)
    assert trace_colors(moving_traces(dark_state)) == trace_colors(dark["data"][n:])
    view = explore("rod-collision", v1=0.6, frame="barycentric", t=0.5, theme="dark")
    assert shown_colors(view) == trace_colors(dark["data"]) and view.figure.layout.paper_bgcolor == "#000000"
    view.set("v1", 0.8)  # a new scene: redrawn, still dark
    redrawn = live_figure(start("rod-collision", "barycentric", 0.5, v1=0.8))
    assert view.state.shade == "dark" and view.figure.layout.paper_bgcolor == "#000000"
    assert shown_colors(view) == [flipped(c) for c in trace_colors(redrawn["data"])]
    view.frame.value = "lab"
    assert view.state.shade == "dark" and view.figure.layout.paper_bgcolor == "#000000"
    t0, t1 = view.state.drawn.window
    view.time.value = round(0.5 * (t0 + t1), 3)  # the moving traces follow, in their dark colours
    assert view.state.shade == "dark"
    assert shown_colors(view) == trace_colors(live_figure(view.state)["data"])
    assert same_arrays(widget_arrays(view), figure_arrays(live_figure(view.state)))
    assert trace_colors(moving_traces(view.state)) == [
        flipped(c) for c in trace_colors(moving_traces(replace(view.state, shade="light")))
    ]


@pytest.mark.parametrize("theme", ["blue", "Dark", "", None, 1])
def test_a_bad_theme_is_refused_naming_it(theme: Any) -> None:
    scene = rr.build_scene("wall-collision", v=0.6)
    for show in (
        lambda: diagram(scene, theme=theme),
        lambda: recording(scene, seconds=0.2, fps=10.0, theme=theme),
        lambda: lesson("paper", theme=theme),
        lambda: explore("wall-collision", theme=theme),
    ):
        with pytest.raises(rr.ParameterError, match=r"^theme must be 'light' or 'dark'; got ") as err:
            show()
        assert err.value.parameter == "theme"
