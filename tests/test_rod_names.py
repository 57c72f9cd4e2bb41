"""Rods that share a row carry their names on their bars, so that colour is not all that tells them
apart (in the lanes of the app, its playback and its exports), and the name's short form or none
where a bar is too short for it. Pure view layer, and the GIF frames' pixels."""

from __future__ import annotations

import numpy as np
import pytest

import rigidrel_core as rr
from rigidrel_app.backends._viser import SceneFold
from rigidrel_app.backends.raster import LaneRaster
from rigidrel_app.view.lanes import MIN_NAME_PX, Box, name_on_bar, rod_names
from rigidrel_app.view.layout import NORMAL, PRESENTER, Theme, canvas_layout, text_width
from rigidrel_app.view.scene_view import LANE_Z, build_drawing, lane_states
from rigidrel_app.view.state import Settings, build

from .test_lane_scale import _drawn, recorded_playback

SCENES = {
    "rod-collision": Settings("rod-collision"),
    "bell-spaceships": Settings("bell-spaceships"),
    "pole-barn": Settings("pole-barn"),
    "wall-collision": Settings("wall-collision"),
}


@pytest.mark.parametrize("theme", [NORMAL, PRESENTER], ids=lambda t: t.name)
@pytest.mark.parametrize("kind", list(SCENES))
def test_rods_sharing_a_row_are_named_on_their_bars(kind: str, theme: Theme) -> None:
    layout = canvas_layout(1280, 720, theme)
    d = _drawn(SCENES[kind], layout)
    scene = d.resolved.scene
    groups = list(scene.rod_groups)
    sharing = [rod.name for rod, g in zip(scene.rods, groups, strict=True) if groups.count(g) > 1]
    for now in np.linspace(*d.window, 5):
        for lane in d.lane_pictures(float(now), layout):
            named = {n.text: n for n in lane.names}
            shorts = {s.split()[-1] for s in sharing} | {s.split()[0] for s in sharing}
            assert set(named) <= set(sharing) | shorts  # only rods that share a row, by name or short name
            for rod, bar in zip(scene.rods, lane.boxes[: scene.n_rods], strict=False):
                if rod.name not in sharing or bar.x1 - bar.x0 < text_width(rod.name, theme.text_px) + theme.text_px:
                    continue
                n = named[rod.name]  # room on the bar: the whole name, in its middle, no smaller than allowed
                assert bar.x0 < n.x - 0.5 * text_width(n.text, n.px) and n.x + 0.5 * text_width(n.text, n.px) < bar.x1
                assert n.z == bar.z and MIN_NAME_PX <= n.px <= theme.text_px
    if not sharing:  # one rod in a row: its colour and place tell it (and the title names it)
        assert all(not lane.names for lane in d.lane_pictures(d.window[0], layout))


def test_the_rod_collision_names_both_rods_in_both_lanes() -> None:
    layout = canvas_layout(1280, 720, NORMAL)
    d = _drawn(SCENES["rod-collision"], layout)
    for lane in d.lane_pictures(0.0, layout):
        assert [n.text for n in lane.names] == ["rod 1", "rod 2"]
        assert lane.names[0].x < lane.names[1].x


def test_a_short_bar_takes_the_short_name_or_none() -> None:
    assert name_on_bar("rod 2", 100.0, 15.0) == "rod 2"
    assert name_on_bar("rod 2", 2 * 15.0, 15.0) == "2"
    assert name_on_bar("rear ship", 5.5 * 15.0, 15.0) == "rear"
    assert name_on_bar("rod 2", 10.0, 15.0) is None
    scene = rr.build_scene("rod-collision", length2=0.1)
    bars = [Box(0.0, 400.0, 18.0, "#000", 50.0), Box(400.0, 430.0, 18.0, "#000", 50.0)]
    assert [n.text for n in rod_names(scene, bars, 15.0)] == ["rod 1", "2"]
    bars[1] = Box(400.0, 400.0, 18.0, "#000", 50.0)  # out of view
    assert [n.text for n in rod_names(scene, bars, 15.0)] == ["rod 1"]


def _white_on_bars(kind: str) -> list[bool]:
    """Whether each rod's bar, in each lane of a GIF frame, holds white pixels in its middle (a
    name's box: a bar of one colour with black ticks has none)."""
    d = build_drawing(build(SCENES[kind]))
    raster = LaneRaster(d, 960)
    states = lane_states(d, 0.0)
    img = np.asarray(raster.frame(states)).astype(int)
    found = []
    for st, z in zip(states, LANE_Z, strict=True):
        for b in st.boxes[: d.resolved.scene.n_rods]:
            (u0, u1), (v,) = raster.px(np.array([b.x0, b.x1]), np.array([z + b.z]))
            mid_u, mid_v = round(0.5 * float(u0 + u1)), round(float(v))
            patch = img[mid_v - 3 : mid_v + 4, mid_u - 12 : mid_u + 13]
            found.append(bool((patch == 255).all(axis=-1).any()))
    return found


def test_the_exported_lanes_carry_the_names_too() -> None:
    assert _white_on_bars("rod-collision") == [True] * 4
    assert _white_on_bars("wall-collision") == [False] * 2  # one rod: no name, nothing white on it


def test_the_names_move_with_the_rods_in_a_recorded_playback() -> None:
    """The browser's playback of the rod collision (the renderer on a recording scene, each frame
    folded into its full state, as a timeline is made): every frame shows both rods' names, each
    over its own bar."""
    layout = canvas_layout(1280, 720, NORMAL)
    d = build_drawing(build(SCENES["rod-collision"]), areas=layout.chart_areas, label_px=layout.theme.text_px)
    for lanes, fold in recorded_playback(d, layout, 10):
        shown = _shown_labels(fold)
        for lane in lanes:
            assert [n.text for n in lane.names] == ["rod 1", "rod 2"]
            for name, bar in zip(lane.names, lane.boxes[:2], strict=True):
                assert (name.text, round(name.x, 3)) in shown and bar.x0 < name.x < bar.x1


def _shown_labels(fold: SceneFold) -> set[tuple[str, float]]:
    """Every visible label of a recorded frame: its text and page x."""
    out = set()
    for key in fold.state:
        if key[0] == "props" and key[2] == "text" and fold.state.get(("visible", key[1]), True):
            position = fold.state.get(("position", key[1]))
            if not isinstance(position, tuple):
                position = fold.created[key[1]].props.position  # type: ignore[attr-defined]
            out.add((str(fold.state[key]), round(float(position[0]), 3)))
    return out
