"""The pointer on the canvas asks for physics (``view/pointer.py``): on the page the app paints for
a 1280 x 720 tab, a press on an event's dot chooses its light cone, on the lab's diagram or the
length panel it scrubs the clock, and on the chosen frame's diagram away from its now-line it
drags β; each read back through the chart's own data-to-px map."""

from __future__ import annotations

import pytest

import rigidrel_core as rr
from rigidrel_app.live.painting import PaintingKey, paint
from rigidrel_app.live.playback import Playback
from rigidrel_app.view.layout import NORMAL
from rigidrel_app.view.pointer import (
    BETA_PER_WIDTH,
    EVENT_REACH_PX,
    ChooseCone,
    Diagrams,
    DragBeta,
    Scrub,
    dragged_beta,
    press,
    scrubbed,
)
from rigidrel_app.view.state import CUSTOM_BETA, Resolved, Settings, cone_events, resolve
from tests.viser_client import shown


def _diagrams(settings: Settings, cone: str | None = None) -> Diagrams:
    r = resolve(settings)
    assert isinstance(r, Resolved)
    painting = paint(r, PaintingKey(settings, 960, 720, NORMAL))
    return Diagrams(painting.chart_frames, (rr.LAB, r.frame), r.scene, cone_events(r.scene), cone, r.frame.beta)


def _window(settings: Settings) -> tuple[float, float]:
    r = resolve(settings)
    assert isinstance(r, Resolved)
    return paint(r, PaintingKey(settings, 960, 720, NORMAL)).drawn.window


FIG3 = Settings("rod-collision")


def test_a_press_on_an_events_dot_chooses_its_cone_and_a_second_takes_it_away() -> None:
    d = _diagrams(FIG3)
    for k in (0, 1):
        for name, (t, x) in d.scene.events_in(frame=d.diagram_frames[k]).items():
            px, pz = shown(d.frames[k]).px_one(x, t)
            asked = press(d, px + 0.5 * EVENT_REACH_PX, pz, 0.0)
            assert isinstance(asked, ChooseCone)
            # the nearest dot wins: events drawn on one spot give one of them
            tn, xn = d.scene.events_in(frame=d.diagram_frames[k])[asked.event or ""]
            qx, qz = shown(d.frames[k]).px_one(xn, tn)
            assert abs(qx - px) <= EVENT_REACH_PX and abs(qz - pz) <= EVENT_REACH_PX, (name, asked)
        name, (t, x) = next(iter(d.scene.events_in(frame=d.diagram_frames[k]).items()))
    chosen = _diagrams(FIG3, cone=name)
    px, pz = shown(chosen.frames[1]).px_one(x, t)
    assert press(chosen, px, pz, 0.0) == ChooseCone(None)


def test_a_press_on_the_lab_diagram_or_the_length_panel_scrubs_to_the_time_under_it() -> None:
    d, window = _diagrams(FIG3), _window(FIG3)
    lab, panel = shown(d.frames[0]), shown(d.frames[2])
    t = 0.5 * (window[0] + window[1]) + 0.1
    x_free = lab.x_range[0] + 0.02 * (lab.x_range[1] - lab.x_range[0])  # the plot's left edge: no event there
    px, pz = lab.px_one(x_free, t)
    asked = press(d, px, pz, 0.0)
    assert isinstance(asked, Scrub) and asked.chart == 0 and asked.time == pytest.approx(t, abs=1e-12)
    qx, qz = panel.px_one(t, panel.y_range[0] + 0.95 * (panel.y_range[1] - panel.y_range[0]))
    asked = press(d, qx, qz, 0.0)
    assert isinstance(asked, Scrub) and asked.chart == 2 and asked.time == pytest.approx(t, abs=1e-12)
    # dragged beyond the plot: a time beyond the window, which the tab's clock keeps to its ends
    later, earlier = (
        shown(scrubbed(d, Scrub(0, t), px, lab.plot.z1 + 500.0)),
        shown(scrubbed(d, Scrub(2, t), panel.plot.x0 - 500.0, qz)),
    )
    assert later > window[1] and earlier < window[0]
    clock = Playback.start(window)
    assert (clock.seek(later).now, clock.seek(earlier).now) == (window[1], window[0])


def test_the_chosen_frames_now_line_scrubs_and_elsewhere_a_drag_sets_beta_in_the_sliders_range() -> None:
    d, window = _diagrams(FIG3), _window(FIG3)
    f = shown(d.frames[1])
    now = 0.5 * (window[0] + window[1])
    x_free = f.x_range[0] + 0.02 * (f.x_range[1] - f.x_range[0])
    px, pz = f.px_one(x_free, now)
    on_line = press(d, px, pz + 3.0, now)
    assert isinstance(on_line, Scrub) and on_line.chart == 1
    off_line = press(d, px, pz + 60.0, now)
    assert off_line == DragBeta(d.beta, f.plot.width, px)
    assert isinstance(off_line, DragBeta)
    assert dragged_beta(off_line, px + 0.1 * f.plot.width) == pytest.approx(d.beta + 0.1 * BETA_PER_WIDTH)
    assert dragged_beta(off_line, px + 10 * f.plot.width) == CUSTOM_BETA[1]
    assert dragged_beta(off_line, px - 10 * f.plot.width) == CUSTOM_BETA[0]


def test_a_press_on_the_lanes_the_legend_or_a_margin_asks_for_nothing() -> None:
    d = _diagrams(FIG3)
    top = max(f.plot.z1 for f in d.frames if f is not None)
    assert press(d, 100.0, top + 80.0, 0.0) is None  # the lanes, above the diagrams
    assert press(d, shown(d.frames[0]).plot.x0 - 5.0, shown(d.frames[0]).plot.z0 + 5.0, 0.0) is None  # the axis' margin
