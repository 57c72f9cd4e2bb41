"""Event labels that overprint nothing: the placement in the pure view layer, at the settings the
sliders allow, for every registered scene, as the app and the diagram page draw them.

The fast lane places the cases the hall found overprinted at each canvas size, and settings drawn
at random (hypothesis) from the sliders' ranges; the slow lane sweeps every scene with each slider
at either end, in frames at beta = +-0.99, at each canvas size.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import rigidrel_core as rr
from rigidrel_app.backends.plotly import label_to_annotation
from rigidrel_app.export.diagram_html import DIAGRAM_PX, LENGTH_PX
from rigidrel_app.view.canvas import legend_rows
from rigidrel_app.view.diagrams import (
    ENDS_NOW_NAME,
    ENDS_NOW_SYMBOL,
    View,
    length_now,
    length_static,
    minkowski_in_frame,
    minkowski_now,
)
from rigidrel_app.view.layout import LEGEND_ROWS, MIN_TEXT_PX, NORMAL, PRESENTER, canvas_layout
from rigidrel_app.view.placement import (
    Box,
    Obstacles,
    axis_name_boxes,
    label_box,
    obstacles,
    overlaps,
    place_labels,
    text_box_px,
)
from rigidrel_app.view.scene_view import build_drawing
from rigidrel_app.view.state import CUSTOM_FRAME, Resolved, Settings, presets, resolve
from rigidrel_app.view.vocabulary import Chart, Label, Points, Polyline, Style, event_label


def extreme_settings() -> list[Settings]:
    """Every scene at its defaults, with each slider parameter at either end of its range, and in a
    frame at β = ±0.99; the settings the hall found overprinted; invalid combinations left out."""
    out: list[Settings] = []
    for kind, d in rr.scene_descriptions().items():
        base = Settings(kind)
        variants = [base]
        for p in d.parameters:
            if p.slider is not None:
                variants += [base.with_value(p.name, p.slider.lo), base.with_value(p.name, p.slider.hi)]
        for s in list(variants):
            variants += [replace(s, frame=CUSTOM_FRAME, beta=b) for b in (-0.99, 0.99)]
        out += [s for s in variants if not isinstance(resolve(s), str)]
    return out


HALL = [
    Settings.of("constant-acceleration", v=0.99),
    replace(presets()["Fig. 1: acceleration to V = 0.6"]),
    Settings.of("rod-collision", mass2=0.01),
    Settings.of("rod-collision", mass2=100.0),
    Settings.of("rod-collision", length2=0.1),
]


def setting_id(s: Settings) -> str:
    values = ",".join(f"{k}={v:g}" for k, v in s.values if v is not None)
    frame = f",beta={s.beta:+g}" if s.frame == CUSTOM_FRAME else ""
    return f"{s.scene}[{values}{frame}]"


def app_and_page_charts(s: Settings) -> list[Chart]:
    """The app's three charts and the diagram page's two, for these settings."""
    r = resolve(s)
    assert isinstance(r, Resolved)
    d = build_drawing(r)
    page = [
        minkowski_in_frame(r.scene, r.frame, DIAGRAM_PX, r.overlay),
        length_static(r.scene, rr.LAB, r.frame, r.scene.time_window(frame=r.frame), LENGTH_PX),
    ]
    return [*d.charts, *page]


def assert_placed_clear(chart: Chart) -> None:
    """No two label boxes meet; every moved label lies in the plot area, off every marker and off
    the axis names the canvas writes inside the plot."""
    assert chart.area_px is not None
    assert overlaps(chart) == [], chart.title
    w, h = chart.area_px
    obs = obstacles(chart, chart.area_px)
    moved = [i for i in chart.items if isinstance(i, Label) and i.offset_px is not None]
    names = axis_name_boxes(chart, chart.area_px, max(i.size for i in moved)) if moved else []
    for label in moved:
        box = label_box(chart, chart.area_px, label)
        assert box.inside(w, h), (label.text, box)
        assert not any(box.meets(m) for m in obs.markers), label.text
        assert not any(box.meets(n) for n in names), (label.text, "an axis name")


#: The canvases the labels are placed for: the app's own sizes and the diagram page's (``None``),
#: and a projector's canvas in presenter mode (the panel folded, a lesson's caption above).
CANVASES = {
    "app-and-page": None,
    "presenter-1280x720": (1240.0, 720.0 - 100.0),
    "presenter-1920x1080": (1880.0, 1080.0 - 120.0),
}


def placed_charts(s: Settings, canvas: tuple[float, float] | None) -> list[Chart]:
    return app_and_page_charts(s) if canvas is None else placed_on_the_canvas(s, *canvas, presenter=True)


@pytest.mark.parametrize("canvas", CANVASES.values(), ids=CANVASES.keys())
@pytest.mark.parametrize("settings", HALL, ids=setting_id)
def test_the_hall_cases_overprint_nothing(settings: Settings, canvas: tuple[float, float] | None) -> None:
    for chart in placed_charts(settings, canvas):
        assert_placed_clear(chart)


@st.composite
def slider_settings(draw: st.DrawFn) -> Settings:
    """Any scene, each slider anywhere in its range (log sliders over their decades), in a frame of
    any beta the slider allows; combinations the scene refuses are drawn again."""
    kind = draw(st.sampled_from(sorted(rr.scene_descriptions())))
    s = Settings(kind)
    for p in rr.describe(kind).parameters:
        if p.slider is not None:
            lo, hi = p.slider.lo, p.slider.hi
            if p.slider.scale == "log":
                value = draw(
                    st.floats(np.log10(lo), np.log10(hi)).map(lambda u, lo=lo, hi=hi: min(max(10.0**u, lo), hi))
                )
            else:
                value = draw(st.floats(lo, hi))
            s = s.with_value(p.name, value)
    s = replace(s, frame=CUSTOM_FRAME, beta=draw(st.floats(-0.99, 0.99)))
    if isinstance(resolve(s), str):
        return draw(slider_settings())
    return s


@settings(max_examples=12, deadline=None, derandomize=True)
@given(slider_settings(), st.sampled_from(list(CANVASES.values())))
def test_labels_overprint_nothing_anywhere_the_sliders_go(
    settings: Settings, canvas: tuple[float, float] | None
) -> None:
    for chart in placed_charts(settings, canvas):
        assert_placed_clear(chart)


@pytest.mark.slow  # every scene at every slider's ends, in three frames, at three canvases: about 10 s in all
@pytest.mark.parametrize("canvas", CANVASES.values(), ids=CANVASES.keys())
@pytest.mark.parametrize("kind", sorted(rr.scene_descriptions()))
def test_labels_overprint_nothing_at_the_slider_extremes(kind: str, canvas: tuple[float, float] | None) -> None:
    cases = [s for s in extreme_settings() if s.scene == kind]
    assert cases
    for s in cases:
        for chart in placed_charts(s, canvas):
            try:
                assert_placed_clear(chart)
            except AssertionError as e:
                raise AssertionError(f"{setting_id(s)}: {e}") from e


def test_the_hall_cases_overprinted_before_placement() -> None:
    """The old placement (text 6 px right of its point) overprints in each of the cases a lecturer
    met: the placed charts above are clear where these are not."""
    for s in HALL:
        charts = app_and_page_charts(s)
        unplaced = [
            replace(
                c,
                items=tuple(
                    replace(i, offset_px=None, anchor="left", leader=False) if isinstance(i, Label) else i
                    for i in c.items
                ),
            )
            for c in charts
        ]
        if s.scene == "constant-acceleration" and s.value("v") == 0.99:
            assert any(overlaps(c) for c in unplaced), setting_id(s)  # "TT_BF" and the length plot
        if s.scene == "rod-collision" and s.value("mass2") in (0.01, 100.0):
            assert any(overlaps(c) for c in unplaced), setting_id(s)  # T_1 / T'_1, T_2 / T'_2
        assert all(overlaps(c) == [] for c in charts)


def test_fig1_dashed_curve_crosses_no_event_label() -> None:
    """Fig. 1's preset: the impulsive (dashed) curve passes through neither T_B's nor T_F's text."""
    r = resolve(presets()["Fig. 1: acceleration to V = 0.6"])
    assert isinstance(r, Resolved) and r.overlay is not None
    d = build_drawing(r)
    for chart in (d.lab_chart, d.frame_chart):
        assert chart.area_px is not None
        dashed = replace(
            chart, items=tuple(i for i in chart.items if isinstance(i, Polyline) and i.style.dash == "dash")
        )
        curves = obstacles(dashed, chart.area_px)
        for label in (
            i for i in chart.items if isinstance(i, Label) and i.text in {event_label("T_B"), event_label("T_F")}
        ):
            assert curves.crossings(label_box(chart, chart.area_px, label)) == 0, label.text


def test_placement_is_deterministic_and_moves_only_movable_labels() -> None:
    r = resolve(Settings.of("rod-collision", mass2=0.01))
    assert isinstance(r, Resolved)
    a, b = build_drawing(r), build_drawing(r)
    for ca, cb in zip(a.charts, b.charts, strict=True):
        la = [(i.text, i.offset_px, i.leader) for i in ca.items if isinstance(i, Label)]
        lb = [(i.text, i.offset_px, i.leader) for i in cb.items if isinstance(i, Label)]
        assert la == lb
    fixed = Label(0.5, 0.5, "fixed")
    chart = place_labels(Chart((fixed, Label(0.5, 0.5, "moved", movable=True)), "x", "t", (0, 1), (0, 1)), (200, 100))
    assert chart.items[0] == fixed
    moved = chart.items[1]
    assert isinstance(moved, Label) and moved.offset_px is not None and moved.anchor == "center"
    assert overlaps(chart) == []


def test_a_label_avoids_a_curve_through_its_first_spot() -> None:
    """A horizontal line just right of the point blocks the first spot (right of it): the label moves."""
    line = Polyline(np.array([0.5, 1.0]), np.array([0.5, 0.5]), Style(width=2.0))
    event = Points(np.array([0.5]), np.array([0.5]), size=7)
    label = Label(0.5, 0.5, event_label("T_B"), movable=True, size=16)
    chart = place_labels(Chart((line, event, label), "x", "t", (0, 1), (0, 1)), (300, 300))
    placed = chart.items[2]
    assert isinstance(placed, Label) and placed.offset_px is not None
    assert chart.area_px is not None
    assert obstacles(chart, chart.area_px).crossings(label_box(chart, chart.area_px, placed)) == 0
    assert placed.offset_px[1] != 0.0 or placed.offset_px[0] < 0.0  # not straight right, onto the line


def test_a_label_with_no_free_spot_beside_its_point_gets_a_leader_line() -> None:
    """A point hemmed in by eight other labels: its own label goes farther out, with a leader line,
    and the plotly annotation draws that line."""
    around = [(dx, dy) for dx in (-0.065, 0.0, 0.065) for dy in (-0.06, 0.0, 0.06) if dx or dy]
    labels = tuple(
        Label(0.5 + dx, 0.5 + dy, f"<b>X{k}</b>", anchor="center", size=16) for k, (dx, dy) in enumerate(around)
    )
    target = Label(0.5, 0.5, "<b>T</b>", movable=True, size=16)
    chart = place_labels(Chart((*labels, target), "x", "t", (0, 1), (0, 1)), (400, 400))
    placed = chart.items[-1]
    assert isinstance(placed, Label) and placed.leader and placed.offset_px is not None
    assert overlaps(chart) == []
    ann = label_to_annotation(placed)
    assert ann["showarrow"] is True and ann["ax"] == placed.offset_px[0] and ann["ay"] == -placed.offset_px[1]


def test_segment_box_crossings() -> None:
    box = Box(10.0, 10.0, 20.0, 20.0)
    segs = Obstacles(
        np.array([0.0, 0.0, 15.0, 0.0, 25.0]),
        np.array([0.0, 15.0, 0.0, 30.0, 0.0]),
        np.array([30.0, 30.0, 15.0, 8.0, 25.0]),
        np.array([30.0, 15.0, 5.0, 30.0, 30.0]),
        (),
    )
    # the diagonal and the horizontal cross; the short vertical stops short; two miss
    assert segs.crossings(box) == 2
    assert text_box_px("<b>T<sub>1</sub></b>", 16.0)[0] < text_box_px("<b>T1</b>", 16.0)[0]
    # a subscript the canvas draws smaller, letters (B) as digits
    assert text_box_px("T<sub>B</sub>", 16.0)[0] == pytest.approx(text_box_px("T<sub>1</sub>", 16.0)[0])


def test_area_must_be_positive() -> None:
    with pytest.raises(ValueError, match="area_px"):
        place_labels(Chart((), "x", "t", (0, 1), (0, 1)), (0.0, 100.0))


def test_rod_ends_now_are_not_drawn_as_events() -> None:
    """The rods' current ends: open diamonds with their own legend entry, not the events' black dots."""
    scene = rr.rod_collision(0.6, 0.0, 1.0, 2.0, 1.0, 1.0, 1.0)
    now = minkowski_now(View(rr.LAB, rr.LAB, "", ""), 0.3, 10.0, scene.positions([0.3])[:, :, 0])
    ends = [i for i in now if isinstance(i, Points)]
    assert len(ends) == 1 and ends[0].symbol == ENDS_NOW_SYMBOL != "circle"
    assert ends[0].style.name == ENDS_NOW_NAME
    lengths = [i for i in length_now(0.3, 1.2, scene.lengths(0.3)) if isinstance(i, Points)]
    assert len(lengths) == 1 and lengths[0].symbol == ENDS_NOW_SYMBOL and lengths[0].style.name
    chart = minkowski_in_frame(scene, rr.LAB, DIAGRAM_PX)
    events = next(i for i in chart.items if isinstance(i, Points))
    assert events.style.name == "events" and events.symbol == "circle"


def placed_on_the_canvas(s: Settings, width: float, height: float, presenter: bool) -> list[Chart]:
    """The app's three charts as the live canvas places them: for its plot areas (the legend given
    the rows it needs, as the session does), and for labels of the size it draws them at (the
    presenter theme's are larger; in a crowded plot they step down, never under MIN_TEXT_PX)."""
    r = resolve(s)
    assert isinstance(r, Resolved)
    theme = PRESENTER if presenter else NORMAL
    layout = canvas_layout(width, height, theme)
    d = build_drawing(r, areas=layout.chart_areas, label_px=layout.theme.text_px)
    rows = legend_rows(d.legend(), layout.legend.width, layout.theme)
    if rows != LEGEND_ROWS:
        layout = canvas_layout(width, height, theme, rows)
        d = build_drawing(r, areas=layout.chart_areas, label_px=layout.theme.text_px)
    for chart in d.charts:
        labels = [i for i in chart.items if isinstance(i, Label) and i.movable]
        assert all(MIN_TEXT_PX <= label.size <= layout.theme.text_px for label in labels)
    return list(d.charts)


def test_a_crowded_plot_steps_its_labels_down() -> None:
    """Bell's spaceships' length panel on a 1280 x 720 projector in presenter mode: ten labels in a
    plot about 320 x 180 px do not all fit at 19 px; they step down, and no further than needed."""
    charts = placed_on_the_canvas(Settings("bell-spaceships"), 1240.0, 720.0, presenter=True)
    sizes = {i.size for i in charts[2].items if isinstance(i, Label) and i.movable}
    assert len(sizes) == 1 and MIN_TEXT_PX <= min(sizes) < PRESENTER.text_px
    assert_placed_clear(charts[2])
    roomy = placed_on_the_canvas(Settings("bell-spaceships"), 1880.0, 1080.0, presenter=True)
    assert {i.size for i in roomy[2].items if isinstance(i, Label) and i.movable} == {PRESENTER.text_px}
