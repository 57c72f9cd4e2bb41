"""A lane's title never runs off its lane: titles too long for two lines (Bell's string with its
colour key, the pole-barn's poles, any scene on a phone) are broken between their parts, and the
layout gives them the lines they take, at every instant of the playback. On a phone held upright a
title is its first line (the frame, its time, the objects): the dials show the clocks."""

from __future__ import annotations

import pytest

import rigidrel_core as rr
from rigidrel_app.live.painting import PaintingKey, paint
from rigidrel_app.view.layout import NORMAL, PRESENTER, Theme, lane_title_text, text_width, title_shown, wrap_title
from rigidrel_app.view.state import Resolved, Settings, resolve

#: The canvases a lecture meets: the app at 1280x720 beside its panel, presenter mode at 720p and
#: 1080p, the app at 1080p, and a phone held upright.
CANVASES: dict[str, tuple[float, float, Theme]] = {
    "720p": (936.0, 720.0, NORMAL),
    "720p-presenter": (1280.0, 720.0, PRESENTER),
    "1080p": (1576.0, 1080.0, NORMAL),
    "1080p-presenter": (1920.0, 1080.0, PRESENTER),
    "phone": (390.0, 844.0, NORMAL),
}


def words(text: str) -> list[str]:
    return text.split()


def test_a_title_breaks_between_its_parts_and_loses_nothing() -> None:
    title = "lab frame:   t = +1.125   string strain 22.0 % (faint → strong)\nclocks τ   rear: +1.0 | +1.1"
    px = 15.0
    wide = wrap_title(title, 10_000.0, px)
    assert wide == "lab frame:   t = +1.125   string strain 22.0 % (faint → strong)\nclocks τ   rear: +1.0 | +1.1"
    narrow = wrap_title(title, text_width("lab frame:   t = +1.125", px), px)
    assert narrow.split("\n")[:2] == ["lab frame:   t = +1.125", "string strain 22.0 %"]  # a part too wide: by words
    assert words(narrow) == words(title)
    for width in (60.0, 150.0, 300.0, 600.0):
        lines = wrap_title(title, width, px).split("\n")
        assert words("\n".join(lines)) == words(title)
        # only a single word wider than the lane may be wider than the lane
        assert all(text_width(line, px) <= width or " " not in line for line in lines)


@pytest.mark.parametrize("canvas", list(CANVASES))
@pytest.mark.parametrize("kind", list(rr.scene_descriptions()))
def test_every_title_fits_its_lane_at_every_instant(kind: str, canvas: str) -> None:
    width, height, theme = CANVASES[canvas]
    settings = Settings(kind)
    resolved = resolve(settings)
    assert isinstance(resolved, Resolved)
    painting = paint(resolved, PaintingKey(settings, width, height, theme))
    layout, drawn = painting.layout, painting.drawn
    t0, t1 = drawn.window
    for now in (t0 + k * (t1 - t0) / 8 for k in range(9)):
        pictures = drawn.lane_pictures(now, layout)
        # the layout's titles, found without drawing the lanes, are the drawn lanes' own
        assert drawn.lane_titles_at(now, layout) == [p.title for p in pictures]
        for picture, lane in zip(pictures, layout.lanes, strict=True):
            text, px = lane_title_text(picture.title, lane, layout.theme.title_px)
            lines = text.split("\n")
            assert len(lines) <= max(lane.title_lines, 1), (now, text)
            assert all(text_width(line, px) <= lane.band.width for line in lines), (now, text)
            assert words(text) == words(title_shown(picture.title, lane))  # broken, not cut
            assert ("clocks τ" in picture.title) and ("clocks τ" in text) == (canvas != "phone"), text


@pytest.mark.parametrize("kind", ["velocity-change", "rod-collision", "bell-spaceships", "pole-barn"])
def test_a_riding_lane_s_title_found_without_drawing_it_is_the_drawn_one(kind: str) -> None:
    settings = Settings(kind).riding(fraction=0.25)
    resolved = resolve(settings)
    assert isinstance(resolved, Resolved) and resolved.ride is not None
    painting = paint(resolved, PaintingKey(settings, *CANVASES["720p"][:2], NORMAL))
    drawn, layout = painting.drawn, painting.layout
    t0, t1 = drawn.window
    for now in (t0 + k * (t1 - t0) / 6 for k in range(7)):
        titles = drawn.lane_titles_at(now, layout)
        assert titles == [p.title for p in drawn.lane_pictures(now, layout)]
        assert titles[1].startswith("riding: ")
