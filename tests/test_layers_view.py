"""The layers in the drawings the app, the recordings and the exports share (no browser): each
layer's items are drawn exactly when it is shown, the light signals' arrivals are named without
overprints, the lanes' pulses stand where the core's light is, and the readout says the verdicts."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

import rigidrel_core as rr
from rigidrel_app.view.canvas import chart_frame, still_picture
from rigidrel_app.view.layers import DEFAULT_LAYERS, Layer
from rigidrel_app.view.layout import canvas_layout
from rigidrel_app.view.placement import Box, _to_px, label_box, overlaps, place_labels
from rigidrel_app.view.scene_view import (
    Drawn,
    build_drawing,
    panels,
    readout_markdown,
    signals_readout,
)
from rigidrel_app.view.signals import GROUP, verdict_lines
from rigidrel_app.view.state import CUSTOM_FRAME, Resolved, Settings, presets, resolve
from rigidrel_app.view.vocabulary import LIGHT_COLOR, Area, Item, Label, Points, Polyline, Segments, names_html
from tests.viser_client import shown

LAYOUT = canvas_layout(1280, 720)
CRASH = presets()["Sec. 5: crash into a wall, V = 0.6"]
ALL = frozenset(Layer)


def drawn(settings: Settings, layers: frozenset[Layer]) -> Drawn:
    r = resolve(settings.with_layers(layers))
    assert isinstance(r, Resolved), r
    return build_drawing(r, areas=LAYOUT.chart_areas)


def groups(items: tuple[Item, ...]) -> set[str | None]:
    return {it.style.group for it in items if not isinstance(it, Label)}


def light_items(items: tuple[Item, ...]) -> list[Item]:
    return [it for it in items if not isinstance(it, Label) and it.style.group == GROUP]


@pytest.mark.parametrize("layer", [Layer.LIGHT_CONE, Layer.OTHER_AXES])
def test_a_hidden_layer_leaves_its_group_out_of_both_diagrams(layer: Layer) -> None:
    group = {Layer.LIGHT_CONE: "cone", Layer.OTHER_AXES: "axes"}[layer]
    shown, hidden = drawn(CRASH, DEFAULT_LAYERS), drawn(CRASH, DEFAULT_LAYERS - {layer})
    for a, b in zip(shown.charts[:2], hidden.charts[:2], strict=True):
        assert group in groups(a.items)
        assert group not in groups(b.items)


def test_world_tubes_and_interior_lines_are_separate_layers() -> None:
    def counts(layers: frozenset[Layer]) -> tuple[int, int]:
        items = drawn(CRASH, layers).lab_chart.items
        rod = [it for it in items if not isinstance(it, Label) and it.style.group == "rod"]
        return sum(isinstance(it, Area) for it in rod), sum(isinstance(it, Polyline) for it in rod)

    assert counts(DEFAULT_LAYERS) == (1, 5)  # the tube, both ends and three interior points
    assert counts(DEFAULT_LAYERS - {Layer.INTERIOR_LINES}) == (1, 2)
    assert counts(DEFAULT_LAYERS - {Layer.WORLD_TUBE}) == (0, 3)
    assert counts(DEFAULT_LAYERS - {Layer.WORLD_TUBE, Layer.INTERIOR_LINES}) == (0, 0)


def test_the_length_panel_hidden_gives_its_room_to_the_diagrams() -> None:
    d = drawn(CRASH, DEFAULT_LAYERS - {Layer.LENGTH_PANEL})
    assert d.length_chart.items == () and d.moving_items(0.3, [np.zeros((1, 2))] * 2)[2] == ()
    layout = canvas_layout(LAYOUT.width, LAYOUT.height, LAYOUT.theme, panels=panels(d.resolved))
    assert layout.charts[2] is None and len(layout.lanes) == 2
    lab, chosen = (shown(c) for c in layout.charts[:2])
    assert lab.outer.width == pytest.approx(chosen.outer.width)
    assert lab.outer.width > 1.4 * shown(LAYOUT.charts[0]).outer.width
    assert chosen.outer.x1 == pytest.approx(shown(LAYOUT.charts[2]).outer.x1)
    frames, picture = still_picture(d.charts, layout.charts, [], layout.legend, layout.theme)
    assert frames[2] is None and not [t for t in picture.texts if t.text.startswith("Equal-time length")]


def test_simultaneity_hidden_leaves_no_now_lines() -> None:
    ends = [np.zeros((1, 2))] * 2
    with_lines = drawn(CRASH, DEFAULT_LAYERS).moving_items(0.3, ends)
    without = drawn(CRASH, DEFAULT_LAYERS - {Layer.SIMULTANEITY}).moving_items(0.3, ends)
    for a, b in zip(with_lines[:2], without[:2], strict=True):
        assert any(isinstance(it, Polyline) for it in a)
        assert not any(isinstance(it, Polyline) for it in b)
        assert sum(isinstance(it, Points) for it in b) == 1  # the rods' places stay


def test_signals_are_drawn_in_both_diagrams_only_when_asked_for() -> None:
    off = drawn(CRASH, DEFAULT_LAYERS)
    assert off.signals is None
    assert not any(light_items(c.items) for c in off.charts)
    on = drawn(CRASH.with_layers(ALL), ALL)
    assert on.signals is not None
    scene = on.resolved.scene
    for chart, frame in zip(on.charts[:2], (rr.LAB, on.resolved.frame), strict=True):
        kinds = {type(it) for it in light_items(chart.items)}
        assert kinds == {Area, Segments, Points}
        rays = next(it for it in light_items(chart.items) if isinstance(it, Segments))
        assert rays.style.color == LIGHT_COLOR
        np.testing.assert_allclose(np.abs(rays.x1 - rays.x0), rays.y1 - rays.y0, rtol=1e-12, atol=1e-12)
        s_event = scene.signal_arrival("contact", 0, 1.0, frame=frame)
        assert s_event is not None
        assert np.min(np.hypot(rays.x1 - s_event[1], rays.y1 - s_event[0])) < 1e-12
        # the arrivals are named, placed with the events' labels
        names = [it for it in chart.items if isinstance(it, Label) and it.style.color == LIGHT_COLOR]
        assert {n.text for n in names} == {"<b>S</b>", "<b>R</b>"}
        assert all(n.movable for n in names)
    # the crash's window grows to show S in both frames (lab t = 1, the rod's frame t' = 2)
    assert on.window[1] >= 2.0 > off.window[1]


@pytest.mark.parametrize(
    ("settings", "frame"),
    [
        (CRASH, "rod before"),
        (Settings.of("wall-collision", v=0.99, eps=0.0), "rod before"),
        (CRASH, None),  # with beta = +0.99 below
        (Settings("constant-acceleration"), "lab"),
        (Settings.of("rod-collision", mass2=100.0), "barycentric"),
    ],
)
@pytest.mark.parametrize("beta", [0.0, 0.99, -0.99])
def test_no_label_overprints_another_with_the_signals(settings: Settings, frame: str | None, beta: float) -> None:
    s = replace(settings, frame=CUSTOM_FRAME if beta else frame, beta=beta)
    d = drawn(s, ALL)
    for chart, place in zip(d.charts[:2], LAYOUT.shown_charts[:2], strict=True):
        assert overlaps(chart) == []
        assert chart.area_px is not None
        # and as the canvas places them again for its plot area
        f = chart_frame(chart, place.plot)
        assert overlaps(place_labels(chart, (f.plot.width, f.plot.height))) == []


def test_the_lanes_pulse_is_where_the_light_is() -> None:
    d = drawn(CRASH.with_layers(ALL), ALL)
    assert d.signals is not None
    for now in (0.25, 0.5, 0.8):
        for lane, place, sig in zip(d.lane_pictures(now, LAYOUT), LAYOUT.lanes, d.signals, strict=True):
            light = lane.segments[-1]
            assert light.style.color == LIGHT_COLOR
            bars = light.x0[np.isclose(light.y0, place.rod_z - 0.95 * place.rod_px)]
            (x,) = sig.pulses_at(now)
            expected = lane.origin_px + x * lane.scale
            assert bars.size > 0
            assert abs(bars.mean() - expected) < 1e-9
    # the lab lane marks where the back end is when the first light reaches it: x = 1
    lab = d.lane_pictures(0.5, LAYOUT)[0]
    dashes = lab.segments[-1].x0[
        ~np.isclose(lab.segments[-1].y0, LAYOUT.lanes[0].rod_z - 0.95 * LAYOUT.lanes[0].rod_px)
    ]
    assert dashes.size == 4
    np.testing.assert_allclose(dashes, lab.origin_px + 1.0 * lab.scale)


def test_no_pulse_without_the_signal_layer() -> None:
    d = drawn(CRASH, DEFAULT_LAYERS)
    for lane in d.lane_pictures(0.5, LAYOUT):
        assert all(seg.style.color != LIGHT_COLOR for seg in lane.segments)


def test_the_readout_gives_the_verdicts_only_with_the_signals() -> None:
    off, on = drawn(CRASH, DEFAULT_LAYERS).resolved, drawn(CRASH.with_layers(ALL), ALL).resolved
    assert signals_readout(off) == ""
    text = signals_readout(on)
    for line in verdict_lines(on.scene):
        assert line in text
    assert "outside the light cone of the contact" in text
    assert names_html(text) in readout_markdown(on)  # its event names with their subscripts


@pytest.mark.parametrize("size", [(940, 720), (1580, 1080)])
@pytest.mark.parametrize("beta", [0.0, 0.99, -0.99])
def test_no_label_covers_a_marker_as_the_canvas_draws_it(size: tuple[float, float], beta: float) -> None:
    """The arrivals' and events' names clear every marker at the size the canvas draws it (larger
    than plotly's), in the crash with its signals."""
    layout = canvas_layout(*size)
    s = replace(CRASH, frame=CUSTOM_FRAME if beta else "rod before", beta=beta).with_layers(ALL)
    r = resolve(s)
    assert isinstance(r, Resolved)
    d = build_drawing(r, areas=layout.chart_areas)
    for chart, place in zip(d.charts[:2], layout.shown_charts[:2], strict=True):
        f = chart_frame(chart, place.plot)
        area = (f.plot.width, f.plot.height)
        placed = place_labels(chart, area)

        def inside(x: float, y: float, area: tuple[float, float] = area) -> bool:
            return 0.0 <= x <= area[0] and 0.0 <= y <= area[1]

        marks = []
        for it in placed.items:
            if isinstance(it, Points):
                px, py = _to_px(placed, area, np.asarray(it.x, float), np.asarray(it.y, float))
                h = 0.5 * max(it.size * layout.theme.line_scale * 1.2, 0.6 * layout.theme.text_px)
                marks += [Box(a - h, b - h, a + h, b + h) for a, b in zip(px, py, strict=True) if inside(a, b)]
        for label in (it for it in placed.items if isinstance(it, Label)):
            lx, ly = _to_px(placed, area, np.array([label.x]), np.array([label.y]))
            if not inside(float(lx[0]), float(ly[0])):
                continue  # the canvas draws neither a label nor a marker whose point is off the plot
            box = label_box(placed, area, label)
            assert not any(box.meets(m) for m in marks), (size, beta, label.text)
