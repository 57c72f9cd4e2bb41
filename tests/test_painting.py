"""A state painted once per canvas and shared (``rigidrel_app.live.painting``): the same painting
whatever the first guess, made once per key, its page the still picture under the shared root, its
frame the moving parts as the timeline draws them; and a hall of tabs that follow a leader getting
one painting per canvas size."""

from __future__ import annotations

import itertools
from dataclasses import replace
from typing import Any

import numpy as np
import pytest

import rigidrel_core as rr
from rigidrel_app.backends.viser import SHARED_ROOT, shared_root
from rigidrel_app.live.painting import Painting, PaintingCache, PaintingKey, paint
from rigidrel_app.live.timeline import TimelineKey, record_timeline
from rigidrel_app.view.layers import Layer
from rigidrel_app.view.layout import (
    CAPTION_SHARE,
    LEGEND_ROWS,
    MARGIN,
    MIN_PLOT_PX,
    NORMAL,
    PHONE_BAR_PX,
    PRESENTER,
    Theme,
    canvas_layout,
    caption_reserve,
    is_portrait,
)
from rigidrel_app.view.scene_view import panels
from rigidrel_app.view.state import CUSTOM_FRAME, Resolved, Settings, resolve
from tests.test_timeline import read_payload, same
from tests.viser_client import shown


def resolved_of(settings: Settings) -> Resolved:
    r = resolve(settings)
    assert isinstance(r, Resolved)
    return r


#: The pole in the barn in presenter mode on a short canvas: its legend needs more rows than the
#: default and its lane titles two lines (the guesses that a first painting gets wrong).
POLE = Settings("pole-barn")
SHORT = PaintingKey(POLE, 1240.0, 560.0, PRESENTER)


def test_a_painting_does_not_depend_on_the_first_guess() -> None:
    resolved = resolved_of(POLE)
    first = paint(resolved, SHORT)
    assert first.legend_rows != LEGEND_ROWS and first.title_lines >= 2  # both guesses were wrong
    for guess in ((first.legend_rows, first.title_lines), (1, 2), (1, 4), (LEGEND_ROWS + 2, 1)):
        again = paint(resolved, SHORT, guess)
        assert again.layout == first.layout
        assert (again.legend_rows, again.title_lines) == (first.legend_rows, first.title_lines)
        assert [t.text for t in again.still.texts] == [t.text for t in first.still.texts]
        assert len(again.still.lines) == len(first.still.lines)
        for a, b in zip(again.still.lines, first.still.lines, strict=True):
            np.testing.assert_array_equal(a.points, b.points)


def test_the_cache_makes_a_painting_once_and_lets_the_oldest_go() -> None:
    cache = PaintingCache(capacity=2)
    keys = [PaintingKey(Settings.of("constant-acceleration", v=v), 1280.0, 720.0, NORMAL) for v in (0.3, 0.5, 0.7)]
    first = cache.get(resolved_of(keys[0].settings), keys[0])
    assert cache.get(resolved_of(keys[0].settings), keys[0]) is first and cache.made == 1
    assert cache.find(keys[1]) is None
    for key in keys[1:]:
        cache.get(resolved_of(key.settings), key)
    assert cache.made == 3 and cache.find(keys[0]) is None and cache.find(keys[2]) is not None


def test_the_page_is_the_still_picture_under_the_shared_root() -> None:
    painting = paint(resolved_of(POLE), SHORT)
    page = painting.page()
    assert painting.page() is page  # made once
    head, frames = read_payload(page)
    assert head["nodeset"] == f"page-{painting.id}" and head["count"] == 1
    assert head["nodes"][0] == SHARED_ROOT and all(n.startswith(SHARED_ROOT + "/") for n in head["nodes"][1:])
    labels = [m["props"]["text"] for m in head["prologue"] if m["type"] == "LabelMessage"]
    expected = [t.text for t in painting.still.texts if t.text.strip()]
    assert sorted(labels) == sorted([*expected, *("x", "x′")]) or set(expected) <= set(labels)
    lines = {m["name"] for m in head["prologue"] if m["type"] == "LineSegmentsMessage"}
    (state,) = frames  # every node's state, once
    sent = sum(np.size(state[("props", name, "points")]) for name in lines)
    assert sent == 2 * 3 * sum(len(ln.points) for ln in painting.still.lines)  # every segment: two 3-D points


@pytest.mark.parametrize("settings", [POLE, Settings("rod-collision"), Settings("bell-spaceships")])
def test_a_frame_is_the_moving_parts_as_the_timeline_draws_them(settings: Settings) -> None:
    painting = paint(resolved_of(settings), PaintingKey(settings, 1280.0, 720.0, NORMAL))
    window = painting.drawn.window
    frame = painting.frame(window[0])
    assert painting.frame(window[0]) is frame  # made once per instant
    head, (state,) = read_payload(frame)
    assert head["times"] == [window[0]] and all(n.startswith("/page") for n in head["nodes"])
    timeline = record_timeline(TimelineKey(settings, painting.layout, window), painting.resolved, count=3)
    theirs, frames = read_payload(timeline.blocks[0])
    assert set(head["nodes"]) <= set(theirs["nodes"])  # the timeline has room for every frame's labels

    def shown(frame: dict[Any, Any]) -> set[str]:
        return {k[1] for k, v in frame.items() if k[0] == "visible" and v} | {
            n for n in {k[1] for k in frame} if ("visible", n) not in frame
        }

    assert shown(state) == shown(frames[0])  # the same nodes on screen
    for key, value in state.items():
        if key[1] in shown(state):
            theirs_value = frames[0][key]
            if key[-1].startswith("batched_"):  # the timeline reserves instances for its busiest frame
                theirs_value = np.asarray(theirs_value).ravel()[: np.size(value)]
            assert same(value, theirs_value), key


LAB_STEP = Settings("bell-spaceships", frame="lab")  # the lesson's Bell step: the chosen frame is the lab


@pytest.mark.parametrize("theme", [NORMAL, PRESENTER])
def test_a_lab_step_under_a_caption_shows_the_lab_once_with_diagrams_of_150_px(theme: Theme) -> None:
    """At 1280x720 under a lesson's caption band (the rest of the viewport beyond the canvas
    height the band leaves, :func:`caption_reserve`, at most CAPTION_SHARE), Bell's lab step (titles of four
    lines) gets one lane, one Minkowski diagram and the lengths chart, and its plots 150 px or more;
    its legend names nothing of a frame not shown."""
    canvas_px = caption_reserve(theme)
    band = min(720 - canvas_px, CAPTION_SHARE * 720)
    assert band >= 4 * 23  # a title and three lines of the caption at 17 px
    width = 1280 if theme is PRESENTER else 1280 - 345  # presenter mode folds the panel away
    painting = paint(resolved_of(LAB_STEP), PaintingKey(LAB_STEP, width, 720 - band, theme))
    layout = painting.layout
    assert len(layout.lanes) == 1 and layout.charts[1] is None and layout.charts[2] is not None
    assert all(c.plot.height >= MIN_PLOT_PX for c in layout.shown_charts), layout
    assert painting.chart_frames[1] is None
    names = {e.name for e in painting.drawn.legend()}
    assert "now: t" in names and not any("′" in n for n in names), names
    lanes = painting.drawn.lane_pictures(painting.drawn.window[0], layout)
    assert [lane.title.split(":")[0] for lane in lanes] == ["lab frame"]
    # the same scene in a custom frame of β = 0 keeps both lanes (a slider dragged through 0)
    custom = replace(LAB_STEP, frame=CUSTOM_FRAME, beta=0.0)
    two = paint(resolved_of(custom), PaintingKey(custom, width, 720 - band, theme)).layout
    assert len(two.lanes) == 2 and None not in two.charts


def test_every_canvas_at_the_reserve_gives_the_diagrams_their_height() -> None:
    """:func:`caption_reserve` is the height at which two lanes with one-line titles leave the plots
    MIN_PLOT_PX, at the desk's sizes (to which a short canvas steps presenter text down)."""
    for theme in (NORMAL, PRESENTER):
        h = caption_reserve(theme)
        for w in (935.0, 1280.0, 1575.0, 1920.0):
            layout = canvas_layout(w, h, theme, LEGEND_ROWS, 1)
            assert layout.diagram.plot.height >= MIN_PLOT_PX, (theme.name, w)
            assert canvas_layout(w, h - 12, theme, LEGEND_ROWS, 1).diagram.plot.height < MIN_PLOT_PX


@pytest.mark.parametrize("settings", [Settings("rod-collision"), LAB_STEP])
def test_zoomed_one_diagram_takes_the_canvas_and_is_drawn_larger(settings: Settings) -> None:
    """Key Z: one Minkowski diagram (the chosen frame's; the lab's in a lab step) over the whole
    canvas, no lanes; it keeps one scale for x and t, and the room makes that scale larger."""
    flat, zoomed = (paint(resolved_of(settings), PaintingKey(settings, 935.0, 546.0, NORMAL, z)) for z in (False, True))
    k = 0 if resolved_of(settings).lab_only else 1
    assert zoomed.layout.lanes == () and [c is not None for c in zoomed.layout.charts] == [k == 0, k == 1, False]
    one = shown(zoomed.layout.charts[k])
    assert (
        one.outer.x0 == flat.layout.shown_charts[0].outer.x0 and one.outer.x1 == flat.layout.shown_charts[-1].outer.x1
    )
    assert one.plot.height > 1.5 * shown(flat.layout.charts[k]).plot.height

    def px_per_unit(p: Painting) -> float:
        f = shown(p.chart_frames[k])
        return abs(f.px_one(0.0, 1.0)[1] - f.px_one(0.0, 0.0)[1])

    assert px_per_unit(zoomed) > 1.5 * px_per_unit(flat)
    names = {e.name for e in zoomed.drawn.legend(zoomed.layout.panels.charts)}
    assert not any("length" in n for n in names), names
    window = zoomed.drawn.window
    lanes = zoomed.drawn.lane_pictures(window[0], zoomed.layout)
    assert lanes == [] and len(zoomed.drawn.moving_items(window[0], [])[k]) > 0  # the diagram still plays
    zoomed.frame(window[0])  # the frame a runtime shows: drawn without lanes


def test_a_new_picture_is_drawn_under_a_root_of_its_own() -> None:
    """Two paintings' pages hang under roots named for each (:func:`shared_root`): viser's client
    draws a new page's labels as new nodes, never an old label moved before its text changes."""
    a = paint(resolved_of(LAB_STEP), PaintingKey(LAB_STEP, 935.0, 546.0, NORMAL))
    b = paint(resolved_of(POLE), PaintingKey(POLE, 935.0, 546.0, NORMAL))
    (head_a, _), (head_b, _) = read_payload(a.page()), read_payload(b.page())
    assert head_a["nodes"][:2] == [SHARED_ROOT, shared_root(a.id)] and shared_root(a.id) != shared_root(b.id)
    labels = [n for n in head_b["nodes"] if "/text/" in n]
    assert labels and all(n.startswith(shared_root(b.id) + "/text/") for n in labels)


# ---------------------------------------------------------------------------- a hall that follows
@pytest.mark.slow  # a served lesson and light clients
def test_followers_share_one_painting_per_canvas_and_get_their_own_back() -> None:
    from rigidrel_app.lessons import lesson_from
    from rigidrel_app.live.server import App
    from tests.viser_client import ClientLoop, RuntimeClient, wait_until

    with App(port=0, lesson=lesson_from("paper"), follow=True) as app:
        loop = ClientLoop()
        try:
            clients = [RuntimeClient(app.lead_url or "")] + [RuntimeClient(app.url) for _ in range(2)]
            for c in clients:  # the first, at the lecturer's address, leads
                loop.run(c.connect())
                loop.start(c.run(3600))
                wait_until(lambda c=c: c.report_uuid is not None and c.still_frames, timeout=60)
            sessions = wait_until(lambda: list(app.sessions.values()) if len(app.sessions) == 3 else None)
            wait_until(lambda: all(s.player.ready for s in sessions), timeout=60)
            made = app.paintings.made
            before = [len(c.still_frames) for c in clients]
            loop.run(clients[0].set_value("Next step", True))
            followers = sessions[1:]
            wait_until(lambda: all(s.state.step == 1 and s.painter.painting is not None for s in followers), timeout=60)
            wait_until(lambda: all(len(c.still_frames) > b for c, b in zip(clients, before, strict=True)), timeout=60)
            assert app.paintings.made == made + 1  # the leader's, then every follower's (one canvas size)
            # the leader's own move shows the same shared page: sent whole, never mixed with the
            # step before (its own picture would be updated node by node)
            wait_until(lambda: sessions[0].painter.painting is not None, timeout=30)
            assert sessions[0].painter.painting is followers[0].painter.painting is followers[1].painter.painting
            assert all(s.painter.renderer.still_lent for s in sessions)
            wait_until(lambda: all(c.pages and c.pages[-1][1] for c in clients), timeout=30)
            # a follower's own move (a layer): its own picture comes back, the shared page goes
            followers[0].asks.set_layer(Layer.SIGNALS, Layer.SIGNALS not in followers[0].state.settings.layers)
            wait_until(lambda: clients[1].pages[-1] == (clients[1].pages[-1][0], False), timeout=30)
            assert followers[0].painter.painting is None and not followers[0].painter.renderer.still_lent
            errors: list[Any] = [e for c in clients for e in c.stats.errors]
            assert not errors and app.errors == 0
            for c in clients:
                c.stop()
                loop.run(c.close())
        finally:
            loop.close()


@pytest.mark.parametrize("kind", list(rr.scene_descriptions()))
def test_a_phone_held_upright_shows_the_lanes_and_one_diagram_under_them(kind: str) -> None:
    """390x844: the lanes, then one diagram as wide as the phone (the chosen frame's, the lab's in a
    lab step), then the legend above the folded panel's bar; nothing overlaps, each lane's title is
    its first line (the dials show the clocks), and the diagram's plot keeps a readable height
    (150 px; the paradoxes, whose objects take more title lines, 120). Turned sideways, the phone
    shows every chart again."""
    settings = Settings(kind)
    painting = paint(resolved_of(settings), PaintingKey(settings, 390.0, 844.0, NORMAL))
    layout = painting.layout
    assert is_portrait(390.0, 844.0) and not is_portrait(844.0, 390.0) and not is_portrait(936.0, 1080.0)
    one_lab = painting.resolved.lab_only
    assert [c is not None for c in layout.charts] == [one_lab, not one_lab, False]
    chart = layout.shown_charts[0]
    assert chart.outer.x0 == MARGIN and chart.outer.x1 == 390.0 - MARGIN
    boxes = [lane.band for lane in layout.lanes] + [chart.outer, layout.legend]
    for upper, lower in itertools.pairwise(boxes):  # top to bottom, none into the next
        assert upper.z0 >= lower.z1, (upper, lower)
    assert layout.legend.z0 >= MARGIN + PHONE_BAR_PX
    assert all(not lane.clocks_titled for lane in layout.lanes)
    least = MIN_PLOT_PX if kind not in ("bell-spaceships", "pole-barn") else 120.0
    assert chart.plot.height >= least, chart.plot.height
    sideways = paint(resolved_of(settings), PaintingKey(settings, 844.0, 390.0, NORMAL)).layout
    assert sideways.panels == panels(painting.resolved) and all(lane.clocks_titled for lane in sideways.lanes)
