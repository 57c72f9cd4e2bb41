"""The app's pure parts: settings, drawing vocabulary, diagrams, lanes, camera (no browser)."""

from __future__ import annotations

import json
import math

import numpy as np
import pytest

import rigidrel_core as rr
from app import camera as cam
from app.diagrams import View, equal_scale_ranges, length_static, minkowski_now, minkowski_static
from app.draw import Chart, Label, Points, Polyline, SplicedFigure, Style, decode_array, event_label
from app.drawing import build_drawing, camera_pose, lane_states
from app.lanes import TICK_FRACTIONS, lane_geometry, lane_state
from app.sampling import TOLERANCE_PX, sample_lengths, sample_worldlines
from app.settings import CUSTOM_FRAME, PRESETS, Preset, Resolved, Settings, resolve

ALL_SETTINGS = [
    Settings(kind)
    for kind in (
        rr.SceneKind.CONSTANT_ACCELERATION,
        rr.SceneKind.DECELERATION,
        rr.SceneKind.IMPULSIVE_START,
        rr.SceneKind.WALL_COLLISION,
        rr.SceneKind.ROD_COLLISION,
    )
]


# ---------------------------------------------------------------- settings
def test_presets_reproduce_the_papers_figures() -> None:
    fig1 = resolve(PRESETS[Preset.FIG1])
    assert isinstance(fig1, Resolved) and fig1.overlay is not None
    assert fig1.scene.events["T_F"] == pytest.approx((1.5, 1.5), rel=1e-15)
    fig3 = resolve(PRESETS[Preset.FIG3])
    fig4 = resolve(PRESETS[Preset.FIG4])
    assert isinstance(fig3, Resolved) and isinstance(fig4, Resolved)
    assert fig3.scene.final_velocities == pytest.approx((-9 / 41, 39 / 89), rel=1e-14)
    assert fig4.scene.final_velocities == pytest.approx((9 / 41, 21 / 29), rel=1e-14)


def test_invalid_settings_give_a_notice_not_an_exception() -> None:
    notice = resolve(Settings(rr.SceneKind.ROD_COLLISION, v=0.5, v2=0.7))
    assert isinstance(notice, str) and "never catches" in notice and "last valid scene" in notice
    notice = resolve(Settings(rr.SceneKind.WALL_COLLISION, frame=CUSTOM_FRAME, beta=1.0))
    assert isinstance(notice, str) and "frame_velocity" in notice


def test_frame_falls_back_to_the_scenes_default() -> None:
    r = resolve(Settings(rr.SceneKind.IMPULSIVE_START, frame="barycentric"))
    assert isinstance(r, Resolved) and r.frame.name == "rod after"
    r = resolve(Settings(rr.SceneKind.ROD_COLLISION, frame="rod after"))
    assert isinstance(r, Resolved) and r.frame.name == "barycentric"


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
    assert [a["text"] for a in dyn["layout"]["annotations"]] == ["<b>T'<sub>1</sub></b>", "now"]
    assert np.array_equal(decode_array(base["data"][0]["x"]), x)  # bit-exact
    assert dyn["config"] == {"displayModeBar": False}
    assert base["layout"]["yaxis"]["scaleanchor"] == "x"


def test_event_labels_in_the_papers_notation() -> None:
    assert event_label("T_B") == "<b>T<sub>B</sub></b>"
    assert event_label("T_2'") == "<b>T'<sub>2</sub></b>"
    assert event_label("-T_F") == "<b>−T<sub>F</sub></b>"


# ---------------------------------------------------------------- sampling
@pytest.mark.parametrize("settings", ALL_SETTINGS, ids=lambda s: s.scene.value)
@pytest.mark.parametrize("beta", [0.0, 0.9])
def test_worldlines_are_exact_and_within_half_a_pixel(settings: Settings, beta: float) -> None:
    r = resolve(settings)
    assert isinstance(r, Resolved)
    frame = rr.Frame.from_velocity(beta)
    window = r.scene.time_window(frame)
    px_per_x = 300.0
    fractions = np.array([0.0, 0.5, 1.0])
    lines = sample_worldlines(r.scene, frame, fractions, window, px_per_x)
    dense_t = np.linspace(*window, 4001)
    dense = r.scene.material_positions(fractions, dense_t, frame)
    for i in range(r.scene.n_rods):
        for k in range(fractions.size):
            w = lines[i][k]
            assert np.array_equal(w.x, r.scene.material_positions([fractions[k]], w.t, frame)[i, 0])  # exact samples
            error_px = np.abs(np.interp(dense_t, w.t, w.x) - dense[i, k]).max() * px_per_x
            assert error_px <= TOLERANCE_PX + 1e-9
            assert w.t.size < 200  # no finer than needed


def test_lengths_within_half_a_pixel_and_flat_while_coasting() -> None:
    scene = rr.rod_collision(0.6, 0.0, 1.0, 2.0, 1.0, 1.0, 1.0)
    window = scene.time_window(0.0)
    curves = sample_lengths(scene, rr.Frame.lab(), window, px_per_length=200.0)
    dense_t = np.linspace(*window, 4001)
    dense = scene.lengths(dense_t)
    for r, c in enumerate(curves):
        assert np.abs(np.interp(dense_t, c.t, c.x) - dense[r]).max() * 200.0 <= TOLERANCE_PX + 1e-9
        assert c.t.size < 40


# ---------------------------------------------------------------- diagrams
def test_minkowski_diagrams_carry_worldlines_events_cone_and_axes() -> None:
    scene = rr.rod_collision(0.6, 0.0, 1.0, 2.0, 1.0, 1.0, 1.0)
    lab, bary = rr.Frame.lab(), scene.frames["barycentric"]
    chart = minkowski_static(scene, View(lab, bary, "lab", "", "'"), (-1, 1), (-2, 2), 300.0)
    names = {i.style.name for i in chart.items if i.style.name}
    assert {"rod 1", "rod 2", "light cone of the origin", "events"} <= names
    assert any(n and "axes of barycentric" in n for n in names)
    labels = {i.text for i in chart.items if isinstance(i, Label)}
    assert {event_label(k) for k in scene.events} <= labels
    # the events drawn where the core puts them
    pts = next(i for i in chart.items if isinstance(i, Points))
    ev = np.array(list(scene.events.values()))
    assert np.array_equal(pts.y, ev[:, 0]) and np.array_equal(pts.x, ev[:, 1])
    now = minkowski_now(View(lab, bary, "lab", "", "'"), 0.3, 10.0, scene.positions([0.3])[:, :, 0])
    other_now = next(i for i in now if isinstance(i, Polyline) and i.style.name and "t' = 0.3" in i.style.name)
    # the chosen frame's line of simultaneity t' = 0.3, drawn in the lab
    t_prime = rr.Boost.from_velocity(bary.beta).apply(np.stack([other_now.y, other_now.x], axis=-1))[:, 0]
    assert np.allclose(t_prime, 0.3, atol=1e-12)


def test_length_chart_marks_the_papers_events() -> None:
    scene = rr.constant_acceleration(0.6, 1.0, 0.5)
    chart = length_static(scene, rr.Frame.lab(), rr.Frame.lab(), (-0.5, 2.0), (300.0, 200.0))
    labels = {i.text for i in chart.items if isinstance(i, Label)}
    assert {event_label("T_B"), event_label("T_F")} <= labels
    curve = next(i for i in chart.items if isinstance(i, Polyline))
    assert curve.x[0] == -0.5 and curve.y[-1] == pytest.approx(0.8, rel=1e-12)  # L0/gamma after T_F


# ---------------------------------------------------------------- lanes and camera
def test_lane_ticks_sit_on_the_cores_material_points() -> None:
    scene = rr.rod_collision(0.6, 0.0, 1.0, 2.0, 1.0, 1.5, 1.0)
    geo = lane_geometry(scene)
    frame = rr.Frame.from_velocity(0.5)
    st = lane_state(scene, frame, 0.3, geo, "title", -1.0)
    expected = scene.material_positions(TICK_FRACTIONS, [0.3], frame)[:, :, 0].ravel() / geo.unit
    assert np.array_equal(st.segments.x0[: expected.size], expected)
    assert [b.x0 for b in st.boxes] == list(expected.reshape(2, -1)[:, 0])
    assert len(st.labels) == 1 and "clocks" in st.labels[0].text and st.labels[0].text.startswith("title")


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


@pytest.mark.parametrize("settings", ALL_SETTINGS, ids=lambda s: s.scene.value)
def test_every_scene_builds_a_drawing(settings: Settings) -> None:
    r = resolve(settings)
    assert isinstance(r, Resolved)
    d = build_drawing(r)
    for fig in (d.lab_chart, d.frame_chart, d.length_chart):
        data = json.loads(fig.with_dynamic(()))
        for trace in data["data"]:
            for axis in ("x", "y"):
                values = decode_array(trace[axis])  # NaN separates segments; nothing infinite
                assert not np.isinf(values).any() and np.isfinite(values).any()
    assert d.window[0] < 0.0 < d.window[1]  # the origin event (start, kick, contact) is in the window
    assert math.isfinite(d.x_range[0]) and d.x_range[0] < d.x_range[1]


def test_playback_markers_come_from_the_core() -> None:
    r = resolve(PRESETS[Preset.FIG3])
    assert isinstance(r, Resolved)
    d = build_drawing(r)
    now = 0.4
    states = lane_states(d, now)
    lab_json, frame_json, length_json = d.plot_figures(now, states)
    # the rods' ends on each diagram, and their equal-time lengths on the length plot
    for text, state in ((lab_json, states[0]), (frame_json, states[1])):
        ends = json.loads(text)["data"][-1]
        np.testing.assert_array_equal(decode_array(ends["x"]), state.ends.ravel())
    lengths = json.loads(length_json)["data"][-1]
    expected = np.concatenate([r.scene.lengths(now), r.scene.lengths(now, r.frame)])
    np.testing.assert_array_equal(decode_array(lengths["y"]), expected)
