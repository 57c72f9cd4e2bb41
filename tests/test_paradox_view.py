"""The paradoxes on screen: Bell's string coloured by its strain, the comparison rod on its own row,
the pole-barn's two models one above the other (the lanes the app, the recordings and the exports share)."""

from __future__ import annotations

import itertools
from typing import Any

import numpy as np
import pytest

import rigidrel_core as rr
from rigidrel_app.view.lanes import (
    Box,
    LanePicture,
    bar_rows,
    lane_geometry,
    lane_state,
    object_picture,
    rows_key,
)
from rigidrel_app.view.layout import canvas_layout
from rigidrel_app.view.objects import BARRIER_COLOR, FIELD_RAMP, MARKER_COLOR
from rigidrel_app.view.scene_view import build_drawing
from rigidrel_app.view.state import Resolved, Settings, resolve
from rigidrel_app.view.vocabulary import ROD_COLORS, ramp_color, rgb

LAYOUT = canvas_layout(1280, 720)
#: V = 0.6, s = 1, a = 0.5: the string's strain ends at (gamma - 1) s / (s - l) = 0.25 / 0.9.
BELL = rr.bell_spaceships(0.6, 1.0, 0.5, breaking_strain=0.1)


def strain_color(fraction: float) -> str:
    """The string's colour at ``fraction`` of its full scale: on the objects' field ramp."""
    return ramp_color(fraction, FIELD_RAMP)


def _z_span(b: Box) -> tuple[float, float]:
    return b.z - 0.5 * b.height, b.z + 0.5 * b.height


def _luminance(color: str) -> float:
    def lin(c: int) -> float:
        x = c / 255.0
        return x / 12.92 if x <= 0.04045 else ((x + 0.055) / 1.055) ** 2.4

    r, g, b = (lin(c) for c in rgb(color))
    return 0.2126 * r + 0.7152 * g + 0.0722 * b


def _pictures(settings: Settings, now: float) -> list[LanePicture]:
    r = resolve(settings)
    assert isinstance(r, Resolved)
    return build_drawing(r, areas=LAYOUT.chart_areas).lane_pictures(now, LAYOUT)


# ---------------------------------------------------------------- the string
def test_the_strain_ramp_darkens_monotonically_and_is_no_rods_colour() -> None:
    """Unstretched and breaking differ; the lightness falls all the way (readable in any colour vision
    and in grey); the ramp's colours are not the rods'."""
    assert strain_color(0.0) == FIELD_RAMP[0] and strain_color(1.0) == FIELD_RAMP[-1]
    assert strain_color(0.0) != strain_color(1.0)
    lum = [_luminance(strain_color(f)) for f in np.linspace(0.0, 1.0, 51)]
    assert all(b < a for a, b in itertools.pairwise(lum))
    assert not set(FIELD_RAMP) & set(ROD_COLORS)
    assert strain_color(-1.0) == strain_color(0.0) and strain_color(7.0) == strain_color(1.0)


@pytest.mark.parametrize("frame_name", ["lab", "ships after"])
def test_the_string_joins_the_ships_in_the_colour_of_the_cores_strain(frame_name: str) -> None:
    """Before the start the string is unstretched (the ramp's first colour); just before it breaks it is
    nearly the breaking colour; it runs from the rear ship's front end to the front ship's rear end on
    the ships' row; the lane's title gives the core's strain in per cent."""
    frame = BELL.frame(frame_name)
    geo = lane_geometry(BELL)
    t_break = BELL.string_break_in(frame=frame)
    assert t_break is not None
    colors = []
    for now in (BELL.time_window(frame=frame)[0], t_break[0] - 1e-6):
        st = lane_state(BELL, frame, now, geo, "title", 0.0)
        ships, string = st.boxes[:2], st.boxes[3]
        x = BELL.positions([now], frame=frame) / geo.unit
        assert (string.x0, string.x1) == pytest.approx((x[0, 1, 0], x[1, 0, 0]))
        assert string.z == ships[0].z and string.height < ships[0].height
        strain = BELL.string_strains([now], frame=frame)[0]
        title = " ".join(st.labels[0].text.split())
        assert f"string strain {100 * strain:.1f} % in the rear ship's comoving frame (faint" in title
        colors.append(string.color)
    assert colors[0] == strain_color(0.0)
    assert colors[1] == strain_color(1.0)  # within the ramp's last 1/50 of the breaking strain
    assert colors[0] != colors[1]


def test_a_string_without_a_breaking_strain_runs_up_to_its_final_strain() -> None:
    scene = rr.bell_spaceships(0.6, 1.0, 0.5)
    late = scene.time_window()[1]
    geo = lane_geometry(scene)
    (string,) = scene.objects
    pic = object_picture(scene, string, rr.LAB, late, scene.positions([late])[:, :, 0] / geo.unit, geo)
    assert not pic.parted and len(pic.boxes) == 1
    assert pic.color == strain_color(1.0) and pic.value == pytest.approx(scene.final_strain)
    assert "its final" in pic.text and f"{100 * scene.final_strain:.3g} %" in pic.text


@pytest.mark.parametrize("frame_name", ["lab", "ships after"])
def test_after_the_break_the_string_is_two_loose_ends_and_the_title_says_so(frame_name: str) -> None:
    frame = BELL.frame(frame_name)
    geo = lane_geometry(BELL)
    event = BELL.string_break_in(frame=frame)
    assert event is not None
    before = lane_state(BELL, frame, event[0] - 1e-6, geo, "title", 0.0)
    after = lane_state(BELL, frame, event[0] + 1e-6, geo, "title", 0.0)
    n_rods, n_others = BELL.n_rods, len(BELL.objects) - 1  # the objects beside the string (its first)
    assert len(before.boxes) == n_rods + 1 + n_others
    assert len(after.boxes) == n_rods + 2 + n_others
    assert "string broken" not in before.labels[0].text
    assert "string broken" in after.labels[0].text.split("\n")[0]
    rear_front, front_rear = after.boxes[0].x1, after.boxes[1].x0
    ends = after.boxes[n_rods : n_rods + 2]
    assert ends[0].x0 == pytest.approx(rear_front) and ends[1].x1 == pytest.approx(front_rear)
    assert ends[0].x1 < ends[1].x0  # a gap between the loose ends


# ---------------------------------------------------------------- the comparison rod
@pytest.mark.parametrize("now", [0.0, 1.0, 2.5])
def test_the_comparison_rod_is_a_thinner_bar_below_the_ships(now: float) -> None:
    """On the canvas, in both lanes: the Born-rigid rod's bar lies wholly below the ships' bars (no
    overlap in z), is thinner, and starts where the rear ship does (one x scale); the lanes' titles
    name it."""
    for lane in _pictures(Settings("bell-spaceships"), now):
        rear, front, rod = lane.boxes[:3]
        assert rod.color == ROD_COLORS[2]
        for ship in (rear, front):
            assert _z_span(rod)[1] < _z_span(ship)[0]
            assert rod.height < ship.height
        assert rod.x0 == pytest.approx(rear.x0)
        assert "lower bar: Born-rigid rod" in lane.title.split("\n")[0]


def test_the_rows_are_stacked_without_overlap_inside_the_rod_band() -> None:
    for groups in [(0, 0, 1), (0, 1), (0, 1, 2)]:
        rows = bar_rows(groups)
        spans = [(c - 0.5 * h, c + 0.5 * h) for c, h in rows]
        assert spans[0][1] == pytest.approx(0.5) and spans[-1][0] == pytest.approx(-0.5)
        assert all(lower[1] < upper[0] for upper, lower in itertools.pairwise(spans))
    ships, rod = bar_rows((0, 0, 1))
    assert ships[1] == pytest.approx(2.0 * rod[1])
    assert bar_rows((0, 0)) == ((0.0, 1.0),)


def test_a_scene_of_one_group_keeps_its_full_bars() -> None:
    scene = rr.build_scene("rod-collision")
    geo = lane_geometry(scene)
    st = lane_state(scene, rr.LAB, 0.3, geo, "title", 0.0)
    assert [(b.z, b.height) for b in st.boxes[:2]] == [(0.0, geo.rod_height)] * 2
    assert rows_key(scene) == "" and st.labels[0].text.startswith("title\n")


# ---------------------------------------------------------------- the pole in the barn
@pytest.mark.parametrize("now", [-0.5, 0.5, 1.2])
def test_pole_barn_lanes_show_both_poles_one_above_the_other_under_one_barn(now: float) -> None:
    """The registry's pole-barn: in both lanes two pole bars (Born-rigid above, signal-limited below)
    that do not overlap in z, both reaching the wall's face, and the wall and the door spanning both
    rows; the titles name the bars."""
    settings = Settings("pole-barn")
    r = resolve(settings)
    assert isinstance(r, Resolved) and r.scene.rod_groups == (0, 1)
    for lane in _pictures(settings, now):
        born, signal = lane.boxes[:2]
        assert (born.color, signal.color) == ROD_COLORS[:2]
        assert _z_span(signal)[1] < _z_span(born)[0]
        barn = [b for b in lane.boxes if b.color in (BARRIER_COLOR, MARKER_COLOR)]  # those in the lane's view
        assert len(barn) == len(lane.boxes) - 2
        if now == 0.5:  # the wall and the door both in view
            assert len(barn) == 2
        for obstacle in barn:  # a closed door and the wall span both rows; an open door hangs above them
            assert _z_span(obstacle)[1] >= _z_span(born)[1]
            low = _z_span(obstacle)[0]
            assert low <= _z_span(signal)[0] or low > _z_span(born)[1]
        head = lane.title.split("\n")[0]
        assert "upper bar: Born-rigid pole; lower bar: signal-limited pole" in head


def test_the_barns_walls_stay_below_the_lane_titles_in_the_exports() -> None:
    """In the recordings' lanes the wall and the door reach the upper dials, not the title."""
    scene = rr.build_scene("pole-barn")
    geo = lane_geometry(scene)
    st = lane_state(scene, rr.LAB, 0.5, geo, "title", 0.0)
    title = st.labels[0]
    for obstacle in st.boxes[2:]:
        assert _z_span(obstacle)[1] == pytest.approx(geo.clock_rows[1] + geo.clock_radius)
        assert _z_span(obstacle)[1] < title.y - 0.05


@pytest.mark.parametrize("frame_name", ["lab", "pole before"])
def test_the_barn_door_is_open_until_it_closes_in_the_lanes_own_frame(frame_name: str) -> None:
    """The door is a raised stub, clear of the rods' bars, until its closing event's time in the
    lane's frame, then a whole bar down to the rods' lowest edge; the title says open, then closed."""
    scene = rr.build_scene("pole-barn")
    frame, geo = scene.frame(frame_name), lane_geometry(scene)
    door = next(o for o in scene.objects if o.kind is rr.ObjectKind.BARN_DOOR)
    closing = door.event_in(frame=frame)
    assert closing is not None
    rods_top = max(_z_span(b)[1] for b in lane_state(scene, frame, closing[0], geo, "t", 0.0).boxes[:2])

    def door_at(now: float) -> Any:
        return object_picture(scene, door, frame, now, scene.positions([now], frame=frame)[:, :, 0] / geo.unit, geo)

    before, after = door_at(closing[0] - 1e-9), door_at(closing[0])
    assert (before.closed, after.closed) == (False, True)
    outcome = "Born-rigid pole spans the doorway, signal-limited pole inside"  # the defaults' verdicts
    assert (before.text, after.text) == ("door open", f"door closed ({outcome})")
    (stub,), (whole,) = before.boxes, after.boxes
    assert _z_span(whole) == pytest.approx((-0.5 * geo.rod_height, geo.wall_height - 0.5 * geo.rod_height))
    assert _z_span(stub)[1] == pytest.approx(_z_span(whole)[1])  # hanging from the same top
    assert _z_span(stub)[0] > rods_top  # the poles pass beneath it
    assert (stub.x0, stub.x1) == pytest.approx((whole.x0, whole.x1))  # the door's face, 1e-9 later


def test_the_door_closes_at_another_instant_of_the_poles_frame() -> None:
    """The lab's closing instant t = 0 is not the pole's: at t = t' = 0.3 the lab lane shows the door
    closed and the pole's lane shows it still open (the closing is at t' = γ (t − V x) there)."""
    scene = rr.build_scene("pole-barn")
    door = next(o for o in scene.objects if o.kind is rr.ObjectKind.BARN_DOOR)
    pole_frame = scene.frame("pole before")
    lab_close, pole_close = door.event_in(frame=rr.LAB), door.event_in(frame=pole_frame)
    assert lab_close is not None and pole_close is not None
    now = 0.5 * (lab_close[0] + pole_close[0])
    assert lab_close[0] < now < pole_close[0]
    geo = lane_geometry(scene)
    lab_title = lane_state(scene, rr.LAB, now, geo, "t", 0.0).labels[0].text
    pole_title = lane_state(scene, pole_frame, now, geo, "t", 0.0).labels[0].text
    assert "door closed" in " ".join(lab_title.split()) and "door open" in " ".join(pole_title.split())


@pytest.mark.parametrize("frame_name", ["lab", "ships after"])
def test_the_length_panel_draws_the_strings_span_and_marks_its_break(frame_name: str) -> None:
    """Bell's length panel: beside each ship's length, the string's (the gap between the ships it
    spans, its ends' separation at equal time), in the lab and in the chosen frame, each sample the
    core's; its break a square on that curve at the break's time in each frame, named once in the
    legend."""
    from rigidrel_app.view.diagrams import TIE_EVENT_SYMBOL, length_static
    from rigidrel_app.view.vocabulary import Points, Polyline

    frame = BELL.frame(frame_name)
    (string,) = BELL.objects
    window = BELL.time_window(frame=frame)
    chart = length_static(BELL, rr.LAB, frame, window, (320.0, 180.0))
    shown = [(rr.LAB, "string, lab (t)")] + ([] if frame_name == "lab" else [(frame, "string, ships after (t′)")])
    breaks = [i for i in chart.items if isinstance(i, Points) and i.symbol == TIE_EVENT_SYMBOL]
    assert len(breaks) == len(shown) and {b.style.name for b in breaks} == {"string: break"}
    for (f, name), mark in zip(shown, breaks, strict=True):
        (curve,) = [i for i in chart.items if isinstance(i, Polyline) and i.style.name == name]
        ends = string.positions(curve.x, frame=f)
        assert np.array_equal(curve.y, ends[1] - ends[0])  # every sample the core's, nothing interpolated
        assert (curve.x[0], curve.x[-1]) == window
        event = string.event_in(frame=f)
        assert event is not None
        at = string.positions([event[0]], frame=f)[:, 0]
        assert (mark.x[0], mark.y[0]) == (event[0], at[1] - at[0])
        assert chart.y_range[1] > float(np.max(curve.y))  # in view
