"""One scale for both lanes, and rulers that number every tick.

Pure view layer (no browser): the app's lanes (:meth:`Drawn.lane_pictures`) on canvases a hall uses,
checked against the core's numbers; the rulers' numbers also as a playback's recorded frames hold
them (the renderer on a recording scene, as the timelines are made).
"""

from __future__ import annotations

import itertools
import re
from collections.abc import Iterator

import numpy as np
import pytest

import rigidrel_core as rr
from rigidrel_app.backends._viser import RecordingScene, SceneFold
from rigidrel_app.backends.viser import PageRenderer
from rigidrel_app.live.timeline import frame_times
from rigidrel_app.view.canvas import still_picture
from rigidrel_app.view.lanes import DIAL_SPACING, LanePicture, LaneScale, ruler_text, spread_dials
from rigidrel_app.view.layout import NORMAL, PRESENTER, CanvasLayout, Theme, canvas_layout, text_width
from rigidrel_app.view.page import frame_pictures, room
from rigidrel_app.view.scene_view import Drawn, build_drawing
from rigidrel_app.view.state import Resolved, Settings, build, presets

BELL = presets()["Bell's spaceships, V = 0.6"]
#: The Born-rigid wall crash ridden by the rod's back end (its right end, far from the wall).
RIDE_BACK_END = Settings.of("wall-collision", v=0.6, eps=0.0).riding(0, 1.0)
#: Canvases: the desk's (the panel docked at 1280x720), a projector's, a 1080p one.
CANVASES: tuple[tuple[float, float, Theme], ...] = ((936, 720, NORMAL), (1280, 720, PRESENTER), (1920, 1080, NORMAL))
#: The data -> px scale is the same in both lanes to this relative tolerance.
SCALE_RTOL = 1e-9


def _drawn(settings: Settings, layout: CanvasLayout, lane_scale: LaneScale = LaneScale.SHARED) -> Drawn:
    return build_drawing(
        build(settings), areas=layout.chart_areas, label_px=layout.theme.text_px, lane_scale=lane_scale
    )


def _rod_px(lane: LanePicture, n_rods: int) -> np.ndarray:
    """The rods' drawn lengths (page px): their boxes, the first ``n_rods`` of the lane's."""
    return np.array([b.x1 - b.x0 for b in lane.boxes[:n_rods]])


def _core_lengths(d: Drawn, now: float) -> tuple[np.ndarray, np.ndarray]:
    """The rods' equal-time lengths the core gives in the lab at ``now`` and in the lower lane's frame
    (riding: the point's comoving frame at the ride's instant)."""
    r = d.resolved
    lab = r.scene.lengths(now, frame=rr.LAB)
    instant = d.ride_instant(now)
    lower = r.scene.lengths(now, frame=r.frame) if instant is None else np.array(instant.lengths)
    return lab, lower


@pytest.mark.parametrize("w, h, theme", CANVASES, ids=lambda v: str(v) if not isinstance(v, Theme) else v.name)
@pytest.mark.parametrize("settings", [BELL, RIDE_BACK_END], ids=["bell-spaceships", "ride-wall-crash-back-end"])
def test_a_rod_is_drawn_in_both_lanes_in_the_ratio_of_its_lengths(
    settings: Settings, w: float, h: float, theme: Theme
) -> None:
    """The lecturer's complaint: Bell's Born-rigid rod, 0.8 long in the lab and 1.0 in the ships'
    frame, was drawn 513 px and 523 px; the ridden crash's rod, 0.84 and 1.0, 592 px and 353 px.
    Now one px-per-unit scale serves both lanes (to 1e-9), so each rod's drawn lengths are in the
    ratio of the core's lengths (to a pixel)."""
    layout = canvas_layout(w, h, theme)
    d = _drawn(settings, layout)
    n = d.resolved.scene.n_rods
    for now in np.linspace(d.window[0], d.window[1], 23):
        lanes = d.lane_pictures(float(now), layout)
        lab_px, lower_px = (_rod_px(lane, n) for lane in lanes)
        assert lanes[0].scale == pytest.approx(lanes[1].scale, rel=SCALE_RTOL)
        lab, lower = _core_lengths(d, float(now))
        np.testing.assert_allclose(lab_px, lab * lanes[0].scale, atol=1.0)  # the boxes: the core's lengths
        np.testing.assert_allclose(lab_px * lower, lower_px * lab, atol=1.0 * lower.max())
        for lane, place in zip(lanes, layout.lanes, strict=True):  # and the rods stay inside their lanes
            ends = lane.origin_px + lane.ends * lane.scale
            assert place.track.x0 - 1e-6 <= ends.min() and ends.max() <= place.track.x1 + 1e-6


def test_bells_rod_is_drawn_four_fifths_as_long_in_the_lab() -> None:
    """At the end of Bell's acceleration the Born-rigid rod is 0.8 long in the lab and 1.0 in the
    ships' frame after (gamma = 1.25): drawn 0.8 as long, to a pixel."""
    layout = canvas_layout(936, 720)
    d = _drawn(BELL, layout)
    now = d.window[1]
    lab, lower = _core_lengths(d, now)
    rod = 2  # the Born-rigid rod (the two ships are rods 0 and 1)
    assert lab[rod] == pytest.approx(0.8, rel=1e-12) and lower[rod] == pytest.approx(1.0, rel=1e-12)
    lab_px, lower_px = (_rod_px(lane, 3)[rod] for lane in d.lane_pictures(now, layout))
    assert lab_px == pytest.approx(0.8 * lower_px, abs=1.0)


def test_each_lane_on_its_own_scale_is_still_there_when_asked_for() -> None:
    """:attr:`LaneScale.OWN` keeps the per-lane fit (the rods' lengths then do not compare by eye):
    the ridden crash's lanes differ in scale by the ride's wider reach."""
    layout = canvas_layout(936, 720)
    own = _drawn(RIDE_BACK_END, layout, LaneScale.OWN).lane_pictures(-0.3, layout)
    shared = _drawn(RIDE_BACK_END, layout).lane_pictures(-0.3, layout)
    assert own[0].scale > 1.5 * own[1].scale
    assert shared[0].scale == pytest.approx(shared[1].scale, rel=SCALE_RTOL) == pytest.approx(own[1].scale)


#: A contracted rod makes the lanes zoom (v = 0.99: gamma = 7.1).
ZOOMING = [Settings.of("constant-acceleration", v=0.99), Settings.of("wall-collision", v=0.99)]


@pytest.mark.parametrize("settings", ZOOMING, ids=lambda s: s.scene)
def test_the_lanes_zoom_together_and_say_so(settings: Settings) -> None:
    """When a rod would be too short to see, both lanes zoom by the same factor, their titles say
    "zoom ×…", and their rulers' ticks come closer (the numbers show the new scale); at the steady
    scale the titles say nothing of a zoom."""
    layout = canvas_layout(936, 720)
    d = _drawn(settings, layout)
    zoomed = steady = 0
    for now in np.linspace(d.window[0], d.window[1], 41):
        lanes = d.lane_pictures(float(now), layout)
        assert lanes[0].scale == pytest.approx(lanes[1].scale, rel=SCALE_RTOL)
        assert lanes[0].zoom == pytest.approx(lanes[1].zoom, rel=SCALE_RTOL)
        for lane in lanes:
            said = re.search(r"zoom ×([\d.]+)", lane.title.split("\n")[0])
            if lane.zoom > 1.01:
                assert said is not None and float(said.group(1)) == pytest.approx(lane.zoom, rel=0.05)
            elif lane.zoom < 1.0 + 1e-6:
                assert said is None
        zoomed += lanes[0].zoom > 1.01
        steady += abs(lanes[0].zoom - 1.0) < 1e-9
    assert zoomed and steady, (zoomed, steady)


#: Scenes whose lanes show a body (a wall, a barn's doors) that leaves a lane at some instant.
WITH_BODIES = [
    presets()["Sec. 5: crash into a wall, V = 0.6"],
    presets()["Pole in the barn, V = 0.8, D = 0.6"],
    Settings.of("wall-collision", v=0.99),
]


@pytest.mark.parametrize("settings", WITH_BODIES, ids=lambda s: f"{s.scene}-{dict(s.values)}")
def test_a_body_out_of_the_lane_is_marked_at_its_edge(settings: Settings) -> None:
    """Every body (wall, door) is either drawn in the lane or marked at the edge on its side, with
    its name and its distance beyond the nearest rod end (the core's positions, to the ruler's
    decimals)."""
    layout = canvas_layout(936, 720)
    d = _drawn(settings, layout)
    r = d.resolved
    marked = both_out = 0
    for now in np.linspace(d.window[0], d.window[1], 31):
        for lane, place, frame in zip(
            d.lane_pictures(float(now), layout), layout.lanes, (rr.LAB, r.frame), strict=True
        ):
            bodies = [o for o in r.scene.objects if o.role is not rr.ObjectRole.TIE]
            drawn = {b.color for b in lane.boxes[r.scene.n_rods :]}
            marks = {m.name: m for m in lane.edge_marks}
            for body in bodies:
                face = float(body.positions(float(now), frame=frame)[0])
                face_px = lane.origin_px + face * lane.scale
                inside = place.track.x0 <= face_px <= place.track.x1
                if inside:
                    assert body.name not in marks and drawn
                    continue
                if body.name not in marks:  # its bar may still reach into the track
                    continue
                m = marks[body.name]
                marked += 1
                assert m.side == (-1 if face_px < place.track.x0 else 1)
                assert m.x == (place.track.x0 if m.side < 0 else place.track.x1)
                gap = lane.ends.min() - face if m.side < 0 else face - lane.ends.max()
                assert m.distance == pytest.approx(gap, rel=1e-12) and gap > 0
                assert body.name in m.text and ("←" if m.side < 0 else "→") in m.text
                number = float(re.search(r"\d+(\.\d+)?", m.text.replace(body.name, "")).group(0))  # type: ignore[union-attr]
                assert number == pytest.approx(gap, abs=max(lane.ruler_step, 1.0 if gap >= 10 else 0.0))
            # bodies out on one side (the barn's door and back wall) named one after the other from
            # the edge, the nearest first: their words never overprint
            for side in (-1, 1):
                row = sorted((m for m in lane.edge_marks if m.side == side), key=lambda m: abs(m.distance))
                if row:
                    assert row[0].text_x == (place.track.x0 if side < 0 else place.track.x1)
                for a, b in itertools.pairwise(row):
                    width = text_width(a.text, place.text_px)
                    assert -side * (b.text_x - a.text_x) > width, (a, b)
                both_out = max(both_out, len(row))
    assert marked
    assert both_out == (2 if settings.scene == "pole-barn" else 1)  # the barn's door and back wall out at once


# ---------------------------------------------------------------------- rulers
def _check_ruler(lane: LanePicture, place_x: tuple[float, float]) -> None:
    """Every tick of the lane's ruler inside the track, and each with its number."""
    x0, x1 = place_x
    ruler = lane.segments[1]
    ticks_px = ruler.x0[1 : 1 + lane.ruler_ticks.size]
    expected = lane.origin_px + lane.ruler_ticks * lane.ruler_step * lane.scale
    np.testing.assert_allclose(ticks_px, expected, rtol=0, atol=1e-6)
    inside = np.arange(
        np.ceil((x0 - lane.origin_px) / (lane.ruler_step * lane.scale) - 1e-9),
        np.floor((x1 - lane.origin_px) / (lane.ruler_step * lane.scale) + 1e-9) + 1,
    )
    np.testing.assert_array_equal(lane.ruler_ticks, inside)  # no tick left out
    assert len(lane.ruler_numbers) == lane.ruler_ticks.size >= 3
    assert list(lane.ruler_numbers) == [ruler_text(n * lane.ruler_step, lane.ruler_step) for n in lane.ruler_ticks]
    assert len(set(lane.ruler_numbers)) == len(lane.ruler_numbers)  # each its own number


RULER_CASES = [BELL, RIDE_BACK_END, *ZOOMING, presets()["Fig. 3: collision, M2 = 2 M1"]]


@pytest.mark.parametrize("settings", RULER_CASES, ids=lambda s: f"{s.scene}-{s.frame}-{s.ride}")
def test_every_ruler_tick_carries_its_number(settings: Settings) -> None:
    layout = canvas_layout(1280, 720, PRESENTER)
    d = _drawn(settings, layout)
    for now in np.linspace(d.window[0], d.window[1], 17):
        for lane, place in zip(d.lane_pictures(float(now), layout), layout.lanes, strict=True):
            _check_ruler(lane, (place.track.x0, place.track.x1))


def _recorded_ruler_numbers(fold: SceneFold, lane: int) -> dict[float, str]:
    """The ruler numbers a recorded frame shows in lane ``lane``: page x (relative to the ruler's
    origin node) -> text, the visible labels only."""
    prefix = f"/page/ruler{lane}/n/"
    names = {key[1] for key in fold.state if key[1].startswith(prefix)}
    shown: dict[float, str] = {}
    for name in names:
        if fold.state.get(("visible", name)):
            text = fold.state[("props", name, "text")]
            position = fold.state.get(("position", name))
            x = float(position[0]) if isinstance(position, tuple) else float(fold.created[name].props.position[0])  # type: ignore[attr-defined]
            shown[round(x, 6)] = str(text)
    return shown


def recorded_playback(d: Drawn, layout: CanvasLayout, frames: int) -> Iterator[tuple[list[LanePicture], SceneFold]]:
    """A playback of ``d`` as :func:`~rigidrel_app.live.timeline.record_timeline` records it (the
    renderer on a recording scene), in ``frames`` frames: each one's lanes, and the full state of
    the scene after it."""
    charts, picture = still_picture(d.charts, layout.charts, d.legend(), layout.legend, layout.theme)
    still, moving = RecordingScene(), RecordingScene()
    renderer = PageRenderer(still.scene, moving.scene)
    renderer.set_static(layout, picture, d.ruler_names)
    pictures = frame_pictures(d, layout, charts, frame_times(d.window, frames))
    renderer.reserve(*room(pictures))
    fold = SceneFold()
    for m in moving.take():
        fold.add(m)
    for lanes, moving_part in pictures:
        renderer.update(lanes, moving_part)
        for m in moving.take():
            fold.add(m)
        yield list(lanes), fold


@pytest.mark.parametrize("step", [3, 4], ids=["impulsive-start", "deceleration"])
def test_while_playing_both_rulers_number_every_tick(step: int) -> None:
    """The lesson's steps as their playback is recorded (:func:`~rigidrel_app.live.timeline.record_timeline`
    does this: the renderer on a recording scene, each frame folded into its full state): at every
    frame both rulers show one number per tick, each the tick's own, not only one of them."""
    from rigidrel_app.lessons import builtin_lesson

    resolved = builtin_lesson("paper").steps[step].resolved
    assert isinstance(resolved, Resolved)
    layout = canvas_layout(1280, 600, PRESENTER)
    d = build_drawing(resolved, areas=layout.chart_areas, label_px=layout.theme.text_px)
    for lanes, fold in recorded_playback(d, layout, 25):
        for k, lane in enumerate(lanes):
            want = {
                round(float(n * lane.ruler_step * lane.scale), 6): text
                for n, text in zip(lane.ruler_ticks, lane.ruler_numbers, strict=True)
            }
            assert _recorded_ruler_numbers(fold, k) == want
            assert len(want) >= 3


# ---------------------------------------------------------------------- clock dials
@pytest.mark.parametrize("kind", list(rr.scene_descriptions()))
def test_no_two_dials_overlap_and_each_stays_by_its_end(kind: str) -> None:
    """Two ends at one place (the barn's two poles, both rear ends at the wall; rods in contact)
    keep a dial each, side by side in their row; a dial with room sits on its end, and its hand
    turns about its centre."""
    layout = canvas_layout(936, 720)
    d = _drawn(Settings(kind), layout)
    moved = 0
    for now in np.linspace(d.window[0], d.window[1], 13):
        for lane, place in zip(d.lane_pictures(float(now), layout), layout.lanes, strict=True):
            r = place.clock_px
            for z in np.unique(lane.dials[:, 1]):
                xs = np.sort(lane.dials[lane.dials[:, 1] == z, 0])
                assert np.all(np.diff(xs) >= 2.0 * r - 1e-9), (now, xs)
            ends = lane.origin_px + lane.scale * lane.ends.ravel()
            shown = (ends >= place.track.x0) & (ends <= place.track.x1)
            off = np.abs(np.sort(lane.dials[:, 0]) - np.sort(ends[shown]))
            moved += int(np.count_nonzero(off > 1e-6))
            assert np.all(off <= 0.5 * len(ends) * DIAL_SPACING * r)
    if kind == "pole-barn":
        assert moved  # its poles' rear ends at the back wall: their dials side by side


def test_spread_dials() -> None:
    row = np.array([0.0, 0.0, 1.0, 0.0])
    out = spread_dials(np.array([10.0, 10.5, 10.0, 40.0]), row, radius=2.0)
    np.testing.assert_allclose(out, [10.25 - 2.3, 10.25 + 2.3, 10.0, 40.0])  # the third dial: another row
    chain = spread_dials(np.array([0.0, 0.0, 5.0]), np.zeros(3), radius=2.0)  # a spread pair reaches the third
    assert np.all(np.diff(np.sort(chain)) >= 4.6 - 1e-9)
