"""The app's pure parts: settings, playback, drawing vocabulary, diagrams, lanes, camera (no browser).

Scenes are taken from the core's registry: a scene registered there is drawn here with no edit.
"""

from __future__ import annotations

import json
import math
import re
from dataclasses import replace

import numpy as np
import pytest

import rigidrel_core as rr
from rigidrel_app.backends.plotly import SplicedFigure, decode_array
from rigidrel_app.backends.viser import line_rgb
from rigidrel_app.live.playback import PLAY_SECONDS, Playback
from rigidrel_app.view import camera as cam
from rigidrel_app.view.canvas import (
    CURVES,
    DASHES,
    MOVING,
    PageText,
    chart_picture,
    clip_segments,
    dashed,
    fill_grid,
    items_picture,
    page_text,
    page_texts,
)
from rigidrel_app.view.diagrams import View, equal_scale_ranges, length_static, minkowski_now, minkowski_static
from rigidrel_app.view.lanes import ROD_SHARE, TICK_FRACTIONS, lane_geometry, lane_state
from rigidrel_app.view.layers import Layer
from rigidrel_app.view.layout import (
    ALL_PANELS,
    LEGEND_ROWS,
    MIN_PLOT_PX,
    MIN_TEXT_PX,
    NORMAL,
    PRESENTER,
    Rect,
    _canvas_layout,  # pyright: ignore[reportPrivateUsage]
    canvas_layout,
    lane_title_text,
    text_width,
    titles_fit_one_line,
)
from rigidrel_app.view.objects import BARRIER_COLOR
from rigidrel_app.view.placement import SUB_SCALE
from rigidrel_app.view.sampling import TOLERANCE_PX, sample_lengths, sample_worldlines
from rigidrel_app.view.scene_view import (
    CLOCK_RULE,
    NOW_MARKER,
    NOW_MARKER_NAME,
    RULER_NAMES,
    build_drawing,
    camera_pose,
    readout_markdown,
)
from rigidrel_app.view.state import (
    CUSTOM_FRAME,
    NO_PRESET,
    Resolved,
    Settings,
    frame_from_text,
    preset_of,
    presets,
    resolve,
    settings_for,
)
from rigidrel_app.view.vocabulary import (
    FRAME_COLOR,
    INK,
    LIGHT_COLOR,
    ROD_COLORS,
    Chart,
    Label,
    Points,
    Polyline,
    Style,
    event_label,
    markdown_literal,
    rgb,
)

#: Every registered scene at its defaults (the app offers each one).
ALL_SETTINGS = [Settings(kind) for kind in rr.scene_descriptions()]


def scene_id(s: Settings) -> str:
    return s.scene


# ---------------------------------------------------------------- settings
def test_presets_reproduce_the_papers_figures() -> None:
    p = presets()
    fig1 = resolve(p["Fig. 1: acceleration to V = 0.6"])
    assert isinstance(fig1, Resolved) and fig1.overlay is not None
    assert fig1.scene.events["T_F"] == pytest.approx((1.5, 1.5), rel=1e-15)
    fig3 = resolve(p["Fig. 3: collision, M2 = 2 M1"])
    fig4 = resolve(p["Fig. 4: collision, M1 = 2 M2"])
    assert isinstance(fig3, Resolved) and isinstance(fig4, Resolved)
    assert fig3.scene.final_velocities == pytest.approx((-9 / 41, 39 / 89), rel=1e-14)
    assert fig4.scene.final_velocities == pytest.approx((9 / 41, 21 / 29), rel=1e-14)


def test_every_description_preset_is_in_the_menu_and_names_itself() -> None:
    labels = [p.label for d in rr.scene_descriptions().values() for p in d.presets]
    assert list(presets()) == labels
    for label, s in presets().items():
        assert preset_of(s) == label
        assert preset_of(s.with_value(s.values[0][0], 0.123)) == NO_PRESET  # the menu follows the controls


def test_invalid_settings_give_a_notice_not_an_exception() -> None:
    notice = resolve(Settings.of("rod-collision", v1=0.5, v2=0.7))
    assert isinstance(notice, str) and notice.startswith("V2 = 0.7 refused") and "so that the rods collide" in notice
    assert "last valid scene" in notice
    notice = resolve(Settings("wall-collision", frame=CUSTOM_FRAME, beta=1.0))
    assert isinstance(notice, str) and notice.startswith("β = 1.0 refused") and "(-1, 1)" in notice
    notice = resolve(Settings("rod-collision", frame="rod after"))
    assert isinstance(notice, str) and "'barycentric'" in notice  # a frame the scene lacks names those it has


def test_settings_carry_shared_parameters_across_scenes() -> None:
    s = Settings.of("constant-acceleration", v=0.8)
    wall = s.with_scene("wall-collision")
    assert wall.value("v") == 0.8 and wall.value("eps") == 1.0 and wall.frame is None
    assert Settings("wall-collision") == Settings.of("wall-collision", v=0.6)  # defaults filled in
    with pytest.raises(ValueError, match="nope must be one of the parameters of wall-collision"):
        Settings.of("wall-collision", nope=1.0)


def test_default_frames_differ_from_the_lab() -> None:
    for s in ALL_SETTINGS:
        r = resolve(s)
        assert isinstance(r, Resolved)
        assert not r.frame.same_velocity(rr.LAB), s.scene
    # a velocity change that ends at rest: its "rod after" is the lab, so the default moves on
    r = resolve(Settings.of("velocity-change", v_initial=0.5, v_final=0.0))
    assert isinstance(r, Resolved) and r.frame.name == "rod before"


def test_settings_round_trip_and_frames_from_text() -> None:
    scene = rr.build_scene("rod-collision", mass2=3.0)
    for frame in (scene.frame("barycentric"), rr.Frame.from_velocity(0.3, "custom")):
        r = resolve(settings_for(scene, frame))
        assert isinstance(r, Resolved) and r.frame == frame and r.scene.parameters == scene.parameters
    assert frame_from_text(scene, "rod 2 after") == scene.frame("rod 2 after")
    assert frame_from_text(scene, "-0.25").beta == -0.25
    assert frame_from_text(scene, None) == scene.frame("barycentric")
    with pytest.raises(ValueError, match="frame must be a velocity in \\(-1, 1\\) or one of 'lab'"):
        frame_from_text(scene, "sideways")


def test_settings_keep_an_omitted_optional_parameter_omitted() -> None:
    """A velocity change built as an impulse (no a′_F) is shown, exported and served as that impulse,
    not with the slider's default acceleration."""
    scene = rr.velocity_change(0.2, 0.7, 1.0, None)
    s = settings_for(scene, rr.default_frame(scene))
    assert s.value("a_front") is None
    r = resolve(s)
    assert isinstance(r, Resolved) and "a_front" not in r.scene.parameters
    assert r.scene.events == scene.events


def test_readout_names_every_parameter_by_its_symbol() -> None:
    r = resolve(Settings("rod-collision"))
    assert isinstance(r, Resolved)
    text = readout_markdown(r)
    for p in rr.describe("rod-collision").parameters:
        assert f"{p.symbol} = " in text


# ---------------------------------------------------------------- playback clock
def test_playback_advances_loops_and_stops_exactly_at_the_end() -> None:
    p = Playback.start((-1.0, 1.0))
    assert p.now == 0.0 and not p.playing
    assert p.advance(1.0) == p  # paused: nothing moves
    playing = p.toggled()
    quarter = playing.advance(PLAY_SECONDS / 8)  # 1/8 of the playing time: 1/8 of the window
    assert quarter.now == pytest.approx(0.25)
    looped = playing.advance(PLAY_SECONDS * 0.75)
    assert looped.playing and looped.now == pytest.approx(-0.5)
    once = replace(playing, loop=False).advance(PLAY_SECONDS)
    assert once.now == 1.0 and not once.playing  # the window's end, not short of it
    again = once.toggled()
    assert again.now == -1.0 and again.playing  # play from the start once at the end
    assert playing.seek(5.0).now == 1.0 and not playing.seek(0.5).playing
    assert replace(playing, speed=2.0).advance(PLAY_SECONDS / 8).now == pytest.approx(0.5)
    assert playing.with_window((0.5, 2.0)).now == 0.5


# ---------------------------------------------------------------- drawing vocabulary
def test_spliced_figure_is_valid_plotly_json_with_exact_arrays() -> None:
    x = np.array([0.1, 0.2, 1 / 3])
    chart = Chart(
        (Polyline(x, x * 2, Style(name="a")), Label(0.5, 0.5, event_label("T_1'"))),
        "x",
        "t",
        (0, 1),
        (0, 1),
        equal_aspect=True,
    )
    fig = SplicedFigure(chart, {"displayModeBar": False})
    base = json.loads(fig.to_json())
    dyn = json.loads(fig.with_dynamic([Points(np.array([0.25]), np.array([0.75])), Label(0.1, 0.2, "now")]))
    assert len(base["data"]) == 1 and len(dyn["data"]) == 2
    assert [a["text"] for a in dyn["layout"]["annotations"]] == ["<b>T′<sub>1</sub></b>", "now"]
    assert np.array_equal(decode_array(base["data"][0]["x"]), x)  # bit-exact
    assert dyn["config"] == {"displayModeBar": False}
    assert base["layout"]["yaxis"]["scaleanchor"] == "x"


def test_event_labels_in_the_papers_notation() -> None:
    assert event_label("T_B") == "<b>T<sub>B</sub></b>"
    assert event_label("T_2'") == "<b>T′<sub>2</sub></b>"  # the prime the captions write
    assert event_label("-T_F") == "<b>−T<sub>F</sub></b>"


# ---------------------------------------------------------------- sampling
@pytest.mark.parametrize("settings", ALL_SETTINGS, ids=scene_id)
@pytest.mark.parametrize("beta", [0.0, 0.9])
def test_worldlines_are_exact_and_within_half_a_pixel(settings: Settings, beta: float) -> None:
    r = resolve(settings)
    assert isinstance(r, Resolved)
    frame = rr.Frame.from_velocity(beta)
    window = r.scene.time_window(frame=frame)
    px_per_x = 300.0
    fractions = np.array([0.0, 0.5, 1.0])
    lines = sample_worldlines(r.scene, frame, fractions, window, px_per_x)
    dense_t = np.linspace(*window, 4001)
    dense = r.scene.material_positions(dense_t, frame=frame, fractions=fractions)
    for i in range(r.scene.n_rods):
        for k in range(fractions.size):
            w = lines[i][k]
            exact = r.scene.material_positions(w.t, frame=frame, fractions=[fractions[k]])[i, 0]
            assert np.array_equal(w.x, exact)  # exact samples
            error_px = np.abs(np.interp(dense_t, w.t, w.x) - dense[i, k]).max() * px_per_x
            assert error_px <= TOLERANCE_PX + 1e-9
            assert w.t.size < 200  # no finer than needed


def test_lengths_within_half_a_pixel_and_flat_while_coasting() -> None:
    scene = rr.rod_collision(0.6, 0.0, 1.0, 2.0, 1.0, 1.0, 1.0)
    window = scene.time_window(frame=rr.LAB)
    curves = sample_lengths(scene, rr.LAB, window, px_per_length=200.0)
    dense_t = np.linspace(*window, 4001)
    dense = scene.lengths(dense_t)
    for r, c in enumerate(curves):
        assert np.abs(np.interp(dense_t, c.t, c.x) - dense[r]).max() * 200.0 <= TOLERANCE_PX + 1e-9
        assert c.t.size < 40


# ---------------------------------------------------------------- diagrams
def test_minkowski_diagrams_carry_worldlines_events_cone_and_axes() -> None:
    scene = rr.rod_collision(0.6, 0.0, 1.0, 2.0, 1.0, 1.0, 1.0)
    lab, bary = rr.LAB, scene.frame("barycentric")
    chart = minkowski_static(scene, View(lab, bary, "", "'"), (-1, 1), (-2, 2), 300.0)
    names = {i.style.name for i in chart.items if i.style.name}
    assert {"rod 1", "rod 2", "light cone of the origin", "events"} <= names
    assert any(n and "axes of barycentric" in n for n in names)
    labels = {i.text for i in chart.items if isinstance(i, Label)}
    assert {event_label(k) for k in scene.events} <= labels
    # the events drawn where the core puts them
    pts = next(i for i in chart.items if isinstance(i, Points))
    ev = np.array(list(scene.events.values()))
    assert np.array_equal(pts.y, ev[:, 0]) and np.array_equal(pts.x, ev[:, 1])
    now = minkowski_now(View(lab, bary, "", "'"), 0.3, 10.0, scene.positions([0.3])[:, :, 0])
    other_now = next(i for i in now if isinstance(i, Polyline) and i.style.name and "t′ = 0.3" in i.style.name)
    # the chosen frame's line of simultaneity t' = 0.3, drawn in the lab
    t_prime = (bary @ np.stack([other_now.y, other_now.x], axis=-1))[:, 0]
    assert np.allclose(t_prime, 0.3, atol=1e-12)


def test_length_chart_marks_the_papers_events() -> None:
    scene = rr.constant_acceleration(0.6, 1.0, 0.5)
    chart = length_static(scene, rr.LAB, rr.LAB, (-0.5, 2.0), (300.0, 200.0))
    labels = {i.text for i in chart.items if isinstance(i, Label)}
    assert {event_label("T_B"), event_label("T_F")} <= labels
    curve = next(i for i in chart.items if isinstance(i, Polyline))
    assert curve.x[0] == -0.5 and curve.y[-1] == pytest.approx(0.8, rel=1e-12)  # L0/gamma after T_F


def test_markdown_literal_shows_typed_text_as_typed() -> None:
    """A notice quotes what was typed; viser renders markdown with raw HTML, so nothing typed may
    become markup."""
    typed = "<img src=x onerror=alert(1)> **bold** _it_ [a](b) `c` # 1. x & y"
    escaped = markdown_literal(typed)
    assert "<" not in escaped and ">" not in escaped and "&lt;img" in escaped
    unescaped = re.sub(r"\\(.)", r"\1", escaped).replace("&lt;", "<").replace("&gt;", ">").replace("&amp;", "&")
    assert unescaped == typed
    assert all(f"\\{c}" in escaped for c in "*_[]`#.")


# ---------------------------------------------------------------- lanes and camera
def test_lane_ticks_sit_on_the_cores_material_points() -> None:
    scene = rr.rod_collision(0.6, 0.0, 1.0, 2.0, 1.0, 1.5, 1.0)
    geo = lane_geometry(scene)
    frame = rr.Frame.from_velocity(0.5)
    st = lane_state(scene, frame, 0.3, geo, "title", -1.0)
    expected = scene.material_positions([0.3], frame=frame, fractions=TICK_FRACTIONS)[:, :, 0].ravel() / geo.unit
    assert np.array_equal(st.segments.x0[: expected.size], expected)
    assert [b.x0 for b in st.boxes] == list(expected.reshape(2, -1)[:, 0])
    assert len(st.labels) == 1 and "clocks" in st.labels[0].text and st.labels[0].text.startswith("title")


def test_the_rulers_are_named_by_their_frames_coordinate() -> None:
    r = resolve(Settings("rod-collision"))
    assert isinstance(r, Resolved)
    d = build_drawing(r)
    geo = lane_geometry(r.scene)
    assert RULER_NAMES == ("x", "x′")
    for (ruler, labels), name, (_, hi) in zip(d.lane_statics(), RULER_NAMES, d.lane_ranges, strict=True):
        named = [lab for lab in labels if lab.text == name]
        assert len(named) == 1 and named[0].x == pytest.approx(hi / geo.unit) and named[0].anchor == "right"
        line = ruler.y0[0]  # the name sits above the ruler's line, its numbers below
        numbers = [lab for lab in labels if lab.text != name and "origin" not in lab.text]
        assert numbers and named[0].y > line and all(lab.y < line for lab in numbers)


def test_the_readout_states_the_clock_rule() -> None:
    r = resolve(Settings("wall-collision"))
    assert isinstance(r, Resolved)
    text = readout_markdown(r)
    assert f"**Clocks** {CLOCK_RULE}" in text
    assert CLOCK_RULE == "every clock reads 0 where its point starts changing velocity"


def test_wall_lane_has_the_wall_moving_in_a_boosted_frame() -> None:
    scene = rr.wall_collision(0.6, 1.0, 0.5)
    st = lane_state(scene, rr.Frame.from_velocity(0.5), 2.0, lane_geometry(scene), "t", 0.0)
    wall = st.boxes[-1]
    assert wall.x1 == pytest.approx(-1.0)  # x' = -beta t'


def test_camera_projection_and_fit() -> None:
    pose = camera_pose((-1.0, 2.0), aspect=0.8)
    w, h = 800, 1000
    centre = cam.project(np.array([pose.look_at]), pose, w, h)[0]
    assert np.allclose(centre, (w / 2, h / 2))
    corners = np.array([[-1.0, 0.0, z] for z in (-0.9, 1.05)] + [[2.0, 0.0, z] for z in (-0.9, 1.05)])
    uv = cam.project(corners, pose, w, h)
    assert np.all((uv >= 0) & (uv <= (w, h)))
    assert uv[:, 0].min() < 0.1 * w  # the lanes fill the width


def test_equal_scale_ranges_keep_light_at_45_degrees() -> None:
    (x0, x1), (t0, t1) = equal_scale_ranges((-1.0, 3.0), (-0.5, 0.5), area=(300.0, 200.0))
    assert (x1 - x0) / (t1 - t0) == pytest.approx(1.5)
    assert x0 <= -1.0 and x1 >= 3.0 and t0 <= -0.5 and t1 >= 0.5


@pytest.mark.parametrize("settings", ALL_SETTINGS, ids=scene_id)
def test_every_scene_builds_a_drawing(settings: Settings) -> None:
    r = resolve(settings)
    assert isinstance(r, Resolved)
    d = build_drawing(r)
    for chart in d.charts:
        data = json.loads(SplicedFigure(chart).with_dynamic(()))
        for trace in data["data"]:
            for axis in ("x", "y"):
                values = decode_array(trace[axis])  # NaN separates segments; nothing infinite
                assert not np.isinf(values).any() and np.isfinite(values).any()
    assert d.window[0] < 0.0 < d.window[1]  # the origin event (start, kick, contact) is in the window
    assert math.isfinite(d.x_range[0]) and d.x_range[0] < d.x_range[1]


def test_playback_markers_come_from_the_core() -> None:
    r = resolve(presets()["Fig. 3: collision, M2 = 2 M1"])
    assert isinstance(r, Resolved)
    d = build_drawing(r)
    now = 0.4
    lanes = d.lane_pictures(now, canvas_layout(936, 720))
    lab_items, frame_items, length_items = d.moving_items(now, [lane.ends for lane in lanes])
    # the rods' ends on each diagram (one diamond pair per rod, in its colour), and their equal-time
    # lengths on the length plot
    for items, lane, frame in ((lab_items, lanes[0], rr.LAB), (frame_items, lanes[1], r.frame)):
        markers = [it for it in items if isinstance(it, Points)]
        assert [m.symbol for m in markers] == [NOW_MARKER] * r.scene.n_rods
        assert [m.style.color for m in markers] == list(ROD_COLORS[: r.scene.n_rods])
        np.testing.assert_array_equal(np.concatenate([m.x for m in markers]), lane.ends.ravel())
        x, _ = r.scene.snapshot(now, frame=frame, fractions=TICK_FRACTIONS)
        np.testing.assert_array_equal(lane.ends, x[:, [0, -1]])
    lengths = [it for it in length_items if isinstance(it, Points)]
    got = np.stack([m.y for m in lengths])  # (rods, frames)
    expected = np.stack([r.scene.lengths(now), r.scene.lengths(now, frame=r.frame)]).T
    np.testing.assert_array_equal(got, expected)
    # no marker of the rods now looks like the events' black dots
    events = [it for it in d.lab_chart.items if isinstance(it, Points) and it.style.name == "events"]
    assert events and all((m.symbol, m.style.color) != (events[0].symbol, events[0].style.color) for m in markers)
    names = {e.name for e in d.legend()}
    assert NOW_MARKER_NAME in names and "events" in names
    assert {n for n in names if n.startswith("now")} == {"now: t", "now: t′"}  # no number in the legend


#: Settings at the sliders' extremes: every lane must keep its rods in view and large enough.
EXTREMES = [
    Settings.of("constant-acceleration", v=0.99),
    Settings.of("constant-acceleration", v=0.99, a_front=0.01),
    Settings.of("wall-collision", v=0.99),
    Settings("constant-acceleration", (), CUSTOM_FRAME, 0.99),
    Settings("constant-acceleration", (), CUSTOM_FRAME, -0.99),
    Settings.of("rod-collision", mass2=0.01),
    Settings.of("rod-collision", mass2=100.0),
    Settings.of("rod-collision", length2=0.1),
    Settings.of("velocity-change", v_initial=-0.99, v_final=0.99),
    *ALL_SETTINGS,
]


@pytest.mark.parametrize("settings", EXTREMES, ids=lambda s: f"{s.scene}-{dict(s.values)}-{s.beta}")
def test_lanes_keep_their_rods_in_view_and_large(settings: Settings) -> None:
    """At every instant of playback, in both lanes: every rod inside the lane's track, at least
    ROD_SHARE of the track (times its rest length over the largest) or 12 px, the ruler's numbers
    true (page x = origin + x * scale), and the dials inside the track."""
    r = resolve(settings)
    assert isinstance(r, Resolved)
    layout = canvas_layout(936, 720)
    d = build_drawing(r, areas=layout.chart_areas)
    rest = np.array([rod.motion.length for rod in r.scene.rods])
    for now in np.linspace(d.window[0], d.window[1], 61):
        for lane, place, frame in zip(
            d.lane_pictures(float(now), layout), layout.lanes, (rr.LAB, r.frame), strict=True
        ):
            track = place.track
            x, _ = r.scene.snapshot(float(now), frame=frame, fractions=TICK_FRACTIONS)
            px = lane.origin_px + x[:, [0, -1]] * lane.scale
            assert px.min() >= track.x0 - 1e-6 and px.max() <= track.x1 + 1e-6, (now, px)
            shares = (px[:, 1] - px[:, 0]) / track.width
            need = np.minimum(ROD_SHARE * rest / rest.max(), 12.0 / track.width)
            assert np.all(shares >= need * (1 - 1e-9)), (now, shares)
            rods = lane.boxes[: r.scene.n_rods]
            np.testing.assert_allclose([[b.x0, b.x1] for b in rods], px, rtol=0, atol=1e-6)
            assert np.all((lane.dials[:, 0] >= track.x0) & (lane.dials[:, 0] <= track.x1))


def test_a_lane_keeps_one_scale_while_no_rod_is_too_short() -> None:
    """Lorentz contraction shows: at V = 0.6 the lane's scale never changes, so the rod gets shorter
    on screen; at V = 0.99 it zooms only once the rod is shorter than ROD_SHARE of the lane."""
    r = resolve(Settings.of("constant-acceleration", v=0.6))
    assert isinstance(r, Resolved)
    layout = canvas_layout(936, 720)
    d = build_drawing(r)
    times = np.linspace(d.window[0], d.window[1], 41)
    scales = {round(d.lane_pictures(float(t), layout)[0].scale, 9) for t in times}
    assert len(scales) == 1
    lengths = [np.diff(d.lane_pictures(float(t), layout)[0].ends[0])[0] for t in times]
    assert max(lengths) / min(lengths) == pytest.approx(1.25, rel=1e-3)  # gamma(0.6)


def test_the_canvas_layout_keeps_text_large_and_regions_apart() -> None:
    for w, h, theme in ((936, 720, NORMAL), (1240, 720, PRESENTER), (1576, 1080, NORMAL), (1920, 1080, PRESENTER)):
        layout = canvas_layout(w, h, theme)
        assert theme.text_px >= 14.0 and theme.title_px >= theme.text_px and theme.line_px >= 2.0
        lab, frame = layout.lanes
        assert lab.band.z0 > frame.band.z1  # the lanes do not overlap
        top_of_charts = max(c.outer.z1 for c in layout.shown_charts)
        assert frame.band.z0 > top_of_charts and min(c.outer.z0 for c in layout.shown_charts) > layout.legend.z1
        for lane in layout.lanes:  # title above the dials above the rod above the ruler, the wall below the title
            assert lane.title_z - 2.4 * theme.title_px > lane.dial_z[1] + lane.clock_px
            assert lane.dial_z[0] - lane.clock_px > lane.rod_z + 0.5 * lane.rod_px
            assert lane.rod_z - lane.rod_px / 2 - lane.wall_px + lane.wall_px <= lane.dial_z[1] + lane.clock_px + 1e-9
            assert lane.ruler_z < lane.rod_z - 0.5 * lane.rod_px
            assert lane.ruler_z - lane.tick_px - 1.3 * theme.text_px >= lane.band.z0 - 1e-9
        for a, b in zip(layout.shown_charts, layout.shown_charts[1:]):
            assert a.outer.x1 < b.outer.x0
        assert all(c.plot.width > 150 and c.plot.height > 120 for c in layout.shown_charts), (w, h, theme.name)


@pytest.mark.parametrize(("w", "h"), [(1280, 624), (1280, 594), (1280, 560), (936, 590)])
def test_a_short_canvas_puts_lane_titles_on_one_line_then_steps_the_text_down(w: int, h: int) -> None:
    """Under a lesson's caption at 1280x720 the diagrams still get MIN_PLOT_PX of height: the lanes'
    titles take one line first, then the text takes the desk sizes (never under MIN_TEXT_PX)."""
    for theme in (NORMAL, PRESENTER):
        full = _canvas_layout(w, h, theme, LEGEND_ROWS, 2, ALL_PANELS)
        layout = canvas_layout(w, h, theme)
        if full.diagram.plot.height >= MIN_PLOT_PX:
            assert layout == full
            continue
        assert layout.diagram.plot.height >= MIN_PLOT_PX, (w, h, theme.name)
        assert all(lane.title_lines == 1 for lane in layout.lanes)
        assert layout.theme.text_px >= MIN_TEXT_PX and layout.theme.line_px == theme.line_px
        assert layout.theme.name == theme.name and layout.theme.shade == theme.shade
        lab, frame = layout.lanes
        assert lab.band.z0 > frame.band.z1 and frame.band.z0 > max(c.outer.z1 for c in layout.shown_charts)
        for lane in layout.lanes:  # one title line above the dials
            assert lane.title_z - 1.2 * layout.theme.title_px > lane.dial_z[1] + lane.clock_px


def test_a_one_line_title_shrinks_to_fit_its_lane_and_never_under_the_smallest_text() -> None:
    layout = canvas_layout(1280, 560, PRESENTER)
    lane = layout.lanes[0]
    assert lane.title_lines == 1
    short = "lab frame:   t = +0.150\nclocks τ (left | right end)   rod: +0.843 | +0.146"
    text, px = lane_title_text(short, lane, 16.0)
    assert "\n" not in text and px == 16.0
    long = "riding: comoving with rod 2 at f = 0.35:   its clock τ = +0.795\n" + "clocks τ " + "x" * 60
    text, px = lane_title_text(long, lane, 16.0)
    assert "\n" not in text and MIN_TEXT_PX <= px < 16.0 and text_width(text, px) <= lane.band.width + 1e-6
    text, px = lane_title_text(long + "y" * 200, lane, 16.0)
    assert "\n" in text and px == 16.0  # too long even at the smallest size: two lines
    assert lane_title_text(short, canvas_layout(1920, 1080, PRESENTER).lanes[0], 21.0) == (short, 21.0)


def test_titles_too_long_for_one_line_keep_two_and_the_text_steps_down_instead() -> None:
    """The pole-barn names both poles in its titles: too long for one line at 14 px on 1260 px."""
    layout = canvas_layout(1280, 560, PRESENTER)
    assert layout.lanes[0].title_lines == 1
    r = resolve(Settings.of("pole-barn"))
    assert isinstance(r, Resolved)
    d = build_drawing(r, areas=layout.chart_areas)
    titles = [p.title for p in d.lane_pictures(d.window[0], layout)]
    assert not titles_fit_one_line(titles, layout)
    short = "lab frame:   t = +0.150\nclocks τ (left | right end)   rod: +0.843 | +0.146"
    assert titles_fit_one_line([short, short], layout)
    two = canvas_layout(1280, 560, PRESENTER, title_lines=2)
    assert all(lane.title_lines == 2 for lane in two.lanes) and two.theme.text_px == NORMAL.text_px
    for lane in two.lanes:  # two title lines above the dials
        assert lane.title_z - 2.4 * two.theme.title_px > lane.dial_z[1] + lane.clock_px


@pytest.mark.parametrize("settings", ALL_SETTINGS, ids=scene_id)
def test_chart_pictures_stay_in_their_plots_at_light_speed_45_degrees(settings: Settings) -> None:
    r = resolve(settings)
    assert isinstance(r, Resolved)
    layout = canvas_layout(936, 720)
    d = build_drawing(r, areas=layout.chart_areas)
    for chart, place in zip(d.charts, layout.shown_charts, strict=True):
        f, picture = chart_picture(chart, place, NORMAL)
        p = f.plot
        curves = [ln for ln in picture.lines if ln.layer >= CURVES]
        assert curves
        for ln in curves:
            assert ln.width >= NORMAL.line_px
            xs, zs = ln.points[..., 0], ln.points[..., 1]
            assert np.all((xs >= p.x0 - 1e-6) & (xs <= p.x1 + 1e-6) & (zs >= p.z0 - 1e-6) & (zs <= p.z1 + 1e-6))
        # the axes' numbers at the theme's size; a crowded plot's event labels step down (Bell's
        # length panel), never under 14 px, nor do their subscripts
        small = [t for t in picture.texts if t.px < NORMAL.text_px and not t.sub]
        assert all(t.px >= MIN_TEXT_PX and not re.fullmatch(r"[-−]?[\d.]+", t.text) for t in small), small
        assert all(t.px >= MIN_TEXT_PX for t in picture.texts if t.sub)
        if chart.equal_aspect:  # one unit of x as long as one unit of t
            per_x = p.width / (f.x_range[1] - f.x_range[0])
            per_t = p.height / (f.y_range[1] - f.y_range[0])
            assert per_x == pytest.approx(per_t, rel=1e-9)
            assert f.x_range[0] <= chart.x_range[0] and f.y_range[0] <= chart.y_range[0]


def test_the_now_lines_sit_at_the_lanes_time() -> None:
    """The moving parts drawn on the canvas put each diagram's now-line at the lanes' t (one instant)."""
    r = resolve(presets()["Fig. 3: collision, M2 = 2 M1"])
    assert isinstance(r, Resolved)
    layout = canvas_layout(936, 720)
    d = build_drawing(r, areas=layout.chart_areas)
    now = 0.37
    lanes = d.lane_pictures(now, layout)
    assert lanes[0].title.startswith(f"lab frame:   t = {now:+.3f}")
    for items, chart, place in zip(d.moving_items(now, [lane.ends for lane in lanes]), d.charts, layout.shown_charts):
        f, _ = chart_picture(chart, place, NORMAL)
        now_line = items_picture(tuple(items)[:1], f, NORMAL, MOVING)  # the first moving item
        _, z_now = f.px(np.array([0.0]), np.array([now]))
        x_now, _ = f.px(np.array([now]), np.array([0.0]))
        first = now_line.lines[0].points
        if chart.equal_aspect:  # horizontal: t = now
            np.testing.assert_allclose(first[..., 1], z_now[0], atol=1e-9)
        else:  # the length plot's vertical line at t = now
            np.testing.assert_allclose(first[..., 0], x_now[0], atol=1e-9)


def test_clipping_dashes_and_fills() -> None:
    box = Rect(0.0, 0.0, 10.0, 10.0)
    a, b = clip_segments(
        np.array([[-5.0, 5.0], [20.0, 20.0], [2.0, 2.0]]), np.array([[15.0, 5.0], [30.0, 30.0], [3.0, 3.0]]), box
    )
    np.testing.assert_allclose(a, [[0.0, 5.0], [2.0, 2.0]])
    np.testing.assert_allclose(b, [[10.0, 5.0], [3.0, 3.0]])
    a, b = dashed(np.array([0.0, 100.0]), np.array([0.0, 0.0]), DASHES["dash"], 1.0)
    on = float(np.sum(b[:, 0] - a[:, 0]))
    assert on == pytest.approx(100.0 * 9.0 / 15.0, abs=3.0)
    square = fill_grid(np.array([0.0, 40.0, 40.0, 0.0]), np.array([0.0, 0.0, 40.0, 40.0]), Rect(0.0, 0.0, 20.0, 100.0))
    assert square[:, 0].max() < 20.0 and square[:, 1].max() < 40.0 and len(square) == pytest.approx(50, abs=6)
    assert page_text("T<sub>1</sub>'") == "T₁'" and page_text("<b>T<sub>B</sub></b>") == "T_B"


@pytest.mark.parametrize("anchor", ["center-left", "center-right", "center-center"])
def test_event_names_are_drawn_with_subscripts_alike(anchor: str) -> None:
    """T_B1, T_1 and T'_1 as the paper writes them: the letter, then its subscript as a smaller text
    of its own, lowered, starting exactly where the letter ends (both anchored at that point)."""
    for name, head, sub in (("T_B1", "T", "B1"), ("T_1", "T", "1"), ("T_1'", "T′", "1"), ("-T_F", "−T", "F")):
        parts = page_texts(100.0, 50.0, event_label(name), 20.0, anchor)  # type: ignore[arg-type]
        assert [(t.text, t.sub) for t in parts] == [(head, False), (sub, True)]
        letter, small = parts
        assert (letter.anchor, small.anchor) == ("center-right", "center-left") and letter.x == small.x
        assert (letter.px, small.px) == (20.0, SUB_SCALE * 20.0) and small.z < letter.z == 50.0
    # the whole at its anchor: starting at x, ending at it, or centred on it
    left = page_texts(100.0, 50.0, "T<sub>B</sub>, T<sub>F</sub> (t′)", 20.0, anchor)  # type: ignore[arg-type]
    assert [t.text for t in left] == ["T", "B", ", T", "F", " (t′)"]
    joints = [t.x for t in left]
    assert joints == sorted(joints)
    # Arial's widths: T, then B and F at 0.8 of the size, ", T" and " (t′)"
    em = 0.611 + 0.8 * 0.667 + (0.278 + 0.278 + 0.611) + 0.8 * 0.611 + (0.278 + 0.333 + 0.278 + 0.25 + 0.333)
    start = joints[0] - 20.0 * 0.611
    ends = {"center-left": 0.0, "center-right": 20.0 * em, "center-center": 10.0 * em}
    assert start + ends[anchor] == pytest.approx(100.0)
    # a subscript is never under the canvas's least text size, nor larger than its letter
    assert [t.px for t in page_texts(0.0, 0.0, "T<sub>B</sub>", 15.0, anchor)] == [15.0, MIN_TEXT_PX]  # type: ignore[arg-type]
    assert [t.px for t in page_texts(0.0, 0.0, "T<sub>B</sub>", 14.0, anchor)] == [14.0, 14.0]  # type: ignore[arg-type]
    # text without a subscript, and a title's top anchor, stay one text
    assert page_texts(1.0, 2.0, "<b>rod</b>", 20.0, anchor) == (PageText(1.0, 2.0, "rod", 20.0, anchor),)  # type: ignore[arg-type]


def test_lines_show_their_colour_through_the_tone_mapping() -> None:
    """viser's lines are tone-mapped (ACES filmic); :func:`line_rgb` undoes it for every palette colour
    (within 25 of 255: the gold's and the orange's blue would need a negative value; the rest within 2)."""
    IN = np.array([[0.59719, 0.35458, 0.04823], [0.07600, 0.90834, 0.01566], [0.02840, 0.13383, 0.83777]])
    OUT = np.array([[1.60475, -0.53108, -0.07367], [-0.10208, 1.10813, -0.00605], [-0.00327, -0.07276, 1.07602]])

    def shown(value: tuple[int, int, int]) -> np.ndarray:
        x = np.asarray(value) / 255.0 / 0.6
        v = IN @ x
        y = np.clip(OUT @ ((v * (v + 0.0245786) - 0.000090537) / (v * (0.983729 * v + 0.4329510) + 0.238081)), 0, 1)
        return 255.0 * np.where(y <= 0.0031308, 12.92 * y, 1.055 * y ** (1 / 2.4) - 0.055)

    for color in (*ROD_COLORS, FRAME_COLOR, LIGHT_COLOR, BARRIER_COLOR, INK, "#000000"):
        target = np.array(rgb(color))
        assert np.abs(shown(line_rgb(tuple(int(c) for c in target))) - target).max() <= 25.0, color  # type: ignore[arg-type]


@pytest.mark.parametrize("kind", sorted(rr.scene_descriptions()))
def test_separate_segments_are_stroked_as_one_by_one(kind: str) -> None:
    """A chart's Segments item (the signals' rays, the interior lines...) is stroked in one go, each
    segment clipped and dashed from its own start: the same lines as stroking them one at a time."""
    from rigidrel_app.view import canvas
    from rigidrel_app.view.vocabulary import Segments

    r = resolve(Settings(kind, layers=frozenset(Layer)))
    assert isinstance(r, Resolved)
    layout = canvas_layout(936, 720)
    d = build_drawing(r, areas=layout.chart_areas)
    checked = 0
    for chart, place in zip(d.charts, layout.shown_charts, strict=True):
        f = canvas.chart_frame(chart, place.plot)
        for it in chart.items:
            if not isinstance(it, Segments):
                continue
            x0, z0 = f.px(it.x0, it.y0)
            x1, z1 = f.px(it.x1, it.y1)
            whole = canvas.items_picture((it,), f, NORMAL).lines
            parts = []
            for k in range(x0.size):  # each segment alone: clipped, then dashed from its own start
                a, b = canvas.clip_segments(np.array([[x0[k], z0[k]]]), np.array([[x1[k], z1[k]]]), f.plot)
                pattern, width = canvas.DASHES[it.style.dash], canvas.line_width(it.style, NORMAL)
                a, b = canvas.dash_segments(a, b, pattern, width / 2.0)
                if len(a):
                    parts.append(np.stack([a, b], axis=1))
            if not whole:
                assert parts == []
                continue
            assert len(whole) == 1
            np.testing.assert_allclose(whole[0].points, np.concatenate(parts), rtol=0, atol=1e-9)
            checked += 1
    assert checked > 0 or kind in {"impulsive-start"}


def test_dashed_separate_segments_each_start_their_pattern() -> None:
    """Two dashed segments stroked in one go: each starts its pattern at its own start, as when
    stroked alone (measured along a line through both, the second would start mid-pattern)."""
    from rigidrel_app.view import canvas
    from rigidrel_app.view.vocabulary import Chart, Segments

    chart = Chart((), "x", "t", (0.0, 100.0), (0.0, 100.0))
    f = canvas.chart_frame(chart, canvas.Rect(0.0, 0.0, 100.0, 100.0))
    style = Style(width=2.0, dash="dash")
    x0, y0, x1, y1 = np.array([10.0, 10.0]), np.array([10.0, 50.0]), np.array([47.0, 47.0]), np.array([10.0, 50.0])
    whole = canvas.items_picture((Segments(x0, y0, x1, y1, style),), f, NORMAL).lines
    alone = [
        canvas.items_picture((Polyline(np.array([x0[k], x1[k]]), np.array([y0[k], y1[k]]), style),), f, NORMAL).lines
        for k in range(2)
    ]
    assert len(whole) == 1 and all(len(a) == 1 for a in alone)
    np.testing.assert_allclose(whole[0].points, np.concatenate([a[0].points for a in alone]), atol=1e-9)
    assert len(whole[0].points) > 2  # dashed: cut into pieces


@pytest.mark.parametrize("kind", sorted(rr.scene_descriptions()))
def test_a_run_of_solid_curves_is_stroked_as_each_alone(kind: str) -> None:
    """Consecutive solid curves of one style (a rod's interior lines) are stroked in one go: the
    same segments, colours, widths and layers, in the same order, as stroking each item alone."""
    from rigidrel_app.view import canvas

    r = resolve(Settings(kind, layers=frozenset(Layer)))
    assert isinstance(r, Resolved)
    layout = canvas_layout(936, 720)
    d = build_drawing(r, areas=layout.chart_areas)

    def flat(lines: tuple[canvas.PageLines, ...]) -> tuple[np.ndarray, np.ndarray, list[tuple[float, int]]]:
        pts = np.concatenate([ln.points for ln in lines]) if lines else np.zeros((0, 2, 2))
        colors = np.concatenate([ln.colors for ln in lines]) if lines else np.zeros((0, 3))
        keys = [(ln.width, ln.layer) for ln in lines for _ in range(len(ln.points))]
        return pts, colors, keys

    runs = 0
    for chart, place in zip(d.charts, layout.shown_charts, strict=True):
        f = canvas.chart_frame(chart, place.plot)
        together = canvas.items_picture(chart.items, f, NORMAL)
        alone = [canvas.items_picture((it,), f, NORMAL) for it in chart.items]
        a_pts, a_col, a_keys = flat(together.lines)
        b_pts, b_col, b_keys = flat(tuple(ln for p in alone for ln in p.lines))
        assert a_keys == b_keys
        np.testing.assert_array_equal(a_pts, b_pts)
        np.testing.assert_array_equal(a_col, b_col)
        assert together.texts == tuple(t for p in alone for t in p.texts)
        runs += len(together.lines) < sum(len(p.lines) for p in alone)
    assert runs > 0  # some chart has a run of more than one curve


def test_a_value_for_no_parameter_of_the_scene_is_an_error_not_ignored() -> None:
    """``with_value`` with a name the scene does not have (``"V"`` for ``"v"``) raises, naming the
    scene's parameters, instead of returning the settings unchanged."""
    s = Settings("rod-collision")
    with pytest.raises(KeyError, match="its parameters: v1, "):
        s.with_value("V1", 0.9)
    assert s.with_value("v1", 0.9).value("v1") == 0.9


@pytest.mark.parametrize("kind", list(rr.scene_descriptions()))
def test_the_legend_names_each_look_of_a_body_once(kind: str) -> None:
    """The length panel's lab curve of a rod looks as the rod does on the diagrams (its colour, solid):
    the legend has it once, under the rod's name; the chosen frame's dashed curve keeps its entry."""
    r = resolve(Settings(kind))
    assert isinstance(r, Resolved)
    entries = build_drawing(r).legend()
    looks = {e.name: (e.style.color, e.style.dash, e.dot) for e in entries}
    for e in entries:
        body = e.name.split(", ")[0]
        if body != e.name and body in looks:
            assert looks[body] != looks[e.name], e.name
    names = [e.name for e in entries]
    for rod in r.scene.rods:
        assert rod.name in names and f"{rod.name}, lab (t)" not in names
        if not r.frame.same_velocity(rr.LAB):
            assert any(n.startswith(f"{rod.name}, ") and n.endswith("(t′)") for n in names), names
