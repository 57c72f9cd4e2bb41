"""The canvas names its scene and parameters (``view/headline.py``): on the lab lane's first title
line, at its right end, never over that line's own words at any instant of playback, the whole
headline where there is room, the scene's name alone where there is less, nothing on a phone."""

from __future__ import annotations

import pytest

import rigidrel_core as rr
from rigidrel_app.live.painting import Painting, PaintingKey, paint
from rigidrel_app.view.headline import GAP_EM, headlines
from rigidrel_app.view.layout import lane_title_text, text_width
from rigidrel_app.view.state import Resolved, Settings, resolve
from tests.test_lane_titles import CANVASES


def _painted(settings: Settings, canvas: str) -> Painting:
    width, height, theme = CANVASES[canvas]
    resolved = resolve(settings)
    assert isinstance(resolved, Resolved)
    return paint(resolved, PaintingKey(settings, width, height, theme))


@pytest.mark.parametrize("canvas", list(CANVASES))
@pytest.mark.parametrize("kind", list(rr.scene_descriptions()))
def test_the_headline_never_covers_the_lab_lanes_first_line(kind: str, canvas: str) -> None:
    painting = _painted(Settings(kind), canvas)
    layout, drawn = painting.layout, painting.drawn
    named = [t for t in painting.still.texts if t.anchor == "top-right"]
    assert len(named) <= 1
    if not named:
        return
    (h,) = named
    lane = layout.lanes[0]
    assert h.text in headlines(Settings(kind)) and (h.x, h.z) == (lane.band.x1, lane.title_z)
    left = lane.band.x1 - text_width(h.text, h.px)
    t0, t1 = drawn.window
    for now in (t0 + k * (t1 - t0) / 8 for k in range(9)):
        title = drawn.lane_pictures(now, layout)[0].title
        text, px = lane_title_text(title, lane, layout.theme.title_px)
        assert lane.band.x0 + text_width(text.split("\n")[0], px) + 0.5 * GAP_EM * px <= left, (now, text, h.text)


def test_presenter_mode_names_the_scene_and_its_values() -> None:
    """Fig. 3 in presenter mode at 720p and 1080p, and beside the panel at 1080p: the whole headline."""
    for canvas in ("720p-presenter", "1080p-presenter", "1080p"):
        painting = _painted(Settings("rod-collision"), canvas)
        (h,) = [t for t in painting.still.texts if t.anchor == "top-right"]
        assert h.text == "Rod-rod collision: V1 = 0.6, M2/M1 = 2, V2 = 0, L2/L1 = 1, ε = 1", canvas
        assert h.text == headlines(Settings("rod-collision"))[0]
