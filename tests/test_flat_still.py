"""The still picture's flat form: :func:`page_image` draws a page's lines, dots and labels as
viser shows them (upright, in layer order, level lines on whole pixels, labels black on their
white box), :func:`flat_still` cuts and colours it for the page, and a playing tab whose
canvas is slow sends it and then hides the picture's nodes, while a control's redraw brings the
nodes back in its own batch (the answer never waits for an image)."""

from __future__ import annotations

import io
import time
from collections.abc import Callable, Iterator
from dataclasses import replace
from typing import Any

import numpy as np
import pytest
from PIL import Image

from rigidrel_app.backends.raster import page_image
from rigidrel_app.backends.viser import FlatStill, flat_still, sent_for_shade
from rigidrel_app.live.session import Session
from rigidrel_app.live.still_image import AFTER_S as FLAT_AFTER_S
from rigidrel_app.live.still_image import SWAP_S as FLAT_SWAP_S
from rigidrel_app.view.canvas import PageDots, PageLines, PagePicture, PageText
from rigidrel_app.view.layout import CanvasSize
from rigidrel_app.view.state import presets
from tests.viser_client import Recorder, recorded_tab, wait_until

BLUE = np.array([0, 114, 178], dtype=np.uint8)
ORANGE = np.array([230, 159, 0], dtype=np.uint8)


def line(
    x0: float, z0: float, x1: float, z1: float, width: float = 2.0, layer: int = 3, color: np.ndarray = BLUE
) -> PageLines:
    return PageLines(np.array([[[x0, z0], [x1, z1]]], dtype=float), color[None, :], width, layer)


def test_a_level_line_covers_whole_pixel_rows() -> None:
    """A 2 px level line at z = 50.3 (page px, z up) on a 100 px page: two rows of its colour
    exactly, white above and below (as a GPU fills it, not three rows of partial grey)."""
    img = page_image(PagePicture(lines=(line(10, 50.3, 90, 50.3),)), 100, 100)
    column = img[:, 50]
    inked = np.flatnonzero(np.any(column != 255, axis=-1))
    assert len(inked) == 2, inked
    assert np.array_equal(column[inked], np.stack([BLUE, BLUE]))
    assert inked[0] == 49  # rows 49 and 50 span z in [49.3, 51.3] -> snapped to [49, 51]


def test_the_image_is_upright_and_at_scale() -> None:
    """Page z is up: a dot near the top left lands in the image's first rows; at scale 2 the
    image has twice the pixels along each side and the dot twice the diameter."""
    dot = PageDots(np.array([[20.0, 70.0]]), ORANGE[None, :], 10.0, "square", 0)
    for scale in (1.0, 2.0):
        img = page_image(PagePicture(dots=(dot,)), 100, 80, scale)
        assert img.shape == (round(80 * scale), round(100 * scale), 3)
        rows, cols = np.nonzero(np.any(img != 255, axis=-1))
        # pixel k spans [k, k + 1): the dot's centre, 10 px from the top, is between pixels 9 and 10
        assert abs(rows.mean() + 0.5 - 10 * scale) < 0.75 and abs(cols.mean() + 0.5 - 20 * scale) < 0.75
        assert rows.max() - rows.min() + 1 == pytest.approx(10 * scale, abs=1.01)
        assert np.array_equal(img[round(10 * scale), round(20 * scale)], ORANGE)


def test_layers_draw_in_order_and_labels_on_top() -> None:
    """A line of a higher layer covers a fill dot of layer 0; a label is black over both."""
    fill = PageDots(np.array([[50.0, 50.0]]), ORANGE[None, :], 30.0, "square", 0)
    over = line(20, 50, 80, 50, width=4.0, layer=3)
    img = page_image(PagePicture(lines=(over,), dots=(fill,)), 100, 100)
    assert np.array_equal(img[50, 45], BLUE) and np.array_equal(img[40, 45], ORANGE)
    text = PageText(50.0, 50.0, "T₁", 20.0, "center-center")
    labelled = page_image(PagePicture(lines=(over,), dots=(fill,), texts=(text,)), 100, 100)
    box = labelled[38:62, 40:60]
    assert box.min() < 40  # black ink (the subscript drawn by the fallback font, not a blank box)
    assert not np.array_equal(labelled[40:60, 40:60], img[40:60, 40:60])


def test_a_subscript_is_drawn_not_a_missing_glyph_box() -> None:
    """T₁ and T₂ differ (a font without subscripts draws both as the same empty box)."""
    ones = page_image(PagePicture(texts=(PageText(50, 50, "T₁", 20.0, "center-center"),)), 100, 100)
    twos = page_image(PagePicture(texts=(PageText(50, 50, "T₂", 20.0, "center-center"),)), 100, 100)
    assert np.abs(ones.astype(int) - twos.astype(int)).sum() > 255 * 10


def test_the_flat_image_is_cut_to_its_ink_and_coloured_for_the_page() -> None:
    image = np.full((40, 60, 3), 255, dtype=np.uint8)
    image[10:20, 30:50] = BLUE
    flat = flat_still(image, 2.0, "dark", 7)
    assert isinstance(flat, FlatStill) and flat.version == 7 and flat.scale == 2.0
    # page px (scale 2): columns 30..50 -> x 15..25; rows 10..20 of 40 -> z (40 - 20) / 2 .. (40 - 10) / 2
    assert flat.box == (15.0, 10.0, 25.0, 15.0)
    sent = np.asarray(Image.open(io.BytesIO(flat.png)).convert("RGB"))
    assert sent.shape == (10, 20, 3)
    assert np.array_equal(sent[0, 0], sent_for_shade(BLUE, "dark"))
    assert flat_still(np.full((4, 4, 3), 255, dtype=np.uint8), 1.0, "light", 1) is None


# --------------------------------------------------------------------------- a tab


@pytest.fixture
def tab() -> Iterator[tuple[Session, Recorder]]:
    with recorded_tab() as t:
        yield t


def _visibility(messages: list[dict[str, Any]], name: str) -> list[bool]:
    return [m["visible"] for m in messages if m["type"] == "SetSceneNodeVisibilityMessage" and m["name"] == name]


def _wait_saying(session: Session, client: Recorder, done: Callable[[], bool], timeout: float = 30.0) -> None:
    """:func:`wait_until` ``done``; on a timeout, the failure says where the still image stood."""
    try:
        wait_until(done, timeout=timeout)
    except AssertionError as timed_out:
        with session.lock:
            r, still, playback = session.painter.renderer, session.painter.still_image, session.state.playback
            state = {
                "playing": playback.playing,
                "now": playback.now,
                "canvas": session.painter.canvas_size,
                "slow_canvas": still.slow_canvas,
                "asked (version, scale)": still._asked,  # pyright: ignore[reportPrivateUsage]
                "version": r.version,
                "flat (version, scale)": (r.flat_version, r.flat_scale),
                "vectors_shown": r.vectors_shown,
                "still_lent": r.still_lent,
                "still stood (s)": time.monotonic() - r.still_at,
            }
        sent = {
            "images": sum(m["type"] == "ImageMessage" for m in client.messages),
            "visibility": {root: _visibility(client.messages, root)[-3:] for root in (*ROOTS, "/page/flat")},
        }
        raise AssertionError(f"{timed_out}; still image {state}; the client got {sent}") from None


#: The still picture's nodes that its image replaces.
ROOTS = ("/page/static", "/page/static_dots", "/page/text")


@pytest.mark.slow  # a served tab
def test_a_canvas_that_keeps_up_never_gets_the_image(tab: tuple[Session, Recorder]) -> None:
    session, client = tab
    with session.lock:
        session.asks.toggle_play()
    # A slow canvas has its image asked for FLAT_AFTER_S after the still picture and shown
    # FLAT_SWAP_S later. Frames are sent in order on one socket: once ten frames of playback that
    # left after that have arrived, an image asked for by then would have arrived before them.
    image_due = time.monotonic() + FLAT_AFTER_S + FLAT_SWAP_S
    wait_until(lambda: sum(t > image_due for t in client.stats.lane_times) >= 10, timeout=30)
    with session.lock:
        session.asks.toggle_play()
        assert session.painter.renderer.flat_version is None and session.painter.renderer.vectors_shown
    assert not any(m.get("name") == "/page/flat" for m in client.messages)


@pytest.mark.slow  # a served tab
def test_a_slow_canvas_plays_the_image_and_a_control_brings_the_lines_back(tab: tuple[Session, Recorder]) -> None:
    session, client = tab
    r = session.painter.renderer
    with session.lock:
        # the browser lowered its resolution: its frames come slow
        session.painter.canvas_size = replace(session.painter.canvas_size, resolution=0.75)
        session.painter.still_image.slow_canvas = True
        session.asks.toggle_play()
    roots = ROOTS
    _wait_saying(session, client, lambda: all(_visibility(client.messages, root)[-1:] == [False] for root in roots))
    assert not r.vectors_shown
    version = r.version
    images = [m for m in client.messages if m["type"] == "ImageMessage" and m["name"] == "/page/flat"]
    assert len(images) == 1
    png = Image.open(io.BytesIO(images[0]["props"]["_data"]))
    layout = session.painter.layout
    assert layout is not None
    # drawn at the canvas' rendered pixels: 0.75 image px per page px, the diagrams' width or so
    assert 0.5 * 0.75 * layout.width < png.size[0] <= 0.75 * layout.width + 1
    for root in roots:  # shown from the start, hidden once
        assert _visibility(client.messages, root) in ([False], [True, False])
    # a slider's answer: the nodes back in the batch that redraws them, the image hidden
    before = len(client.messages)
    other = presets()["Fig. 3: collision, M2 = 2 M1"]
    session.checked(lambda: session.asks.change(other))
    _wait_saying(session, client, lambda: any(m.get("name") == "/page/flat" for m in client.messages[before:]))
    after = client.messages[before:]
    for root in roots:
        assert _visibility(after, root)[:1] == [True]
    assert _visibility(after, "/page/flat")[:1] == [False]
    assert r.version == version + 1
    # once the new picture stands, its own image follows, and the nodes go again
    _wait_saying(session, client, lambda: not r.vectors_shown and r.flat_version == r.version)
    with session.lock:
        session.asks.toggle_play()


@pytest.mark.slow  # a served tab
def test_the_same_canvas_at_a_lower_resolution_marks_it_slow(tab: tuple[Session, Recorder]) -> None:
    """The browser lowering its resolution (the same CSS size, fewer rendered pixels) is what marks
    a canvas slow; a new size at another resolution (a window moved to another screen) is not."""
    session, _ = tab
    with session.lock:
        w, h = session.painter.canvas_size.width, session.painter.canvas_size.height
        session.resize(CanvasSize.measured_by_page(w + 10, h, 1.0))
        session.resize(CanvasSize.measured_by_page(w, h, 2.0))
        assert not session.painter.still_image.slow_canvas
        session.resize(CanvasSize.measured_by_page(w, h, 1.5))
        assert session.painter.still_image.slow_canvas


def test_the_off_switch_keeps_a_slow_canvas_drawing_its_lines() -> None:
    """``--no-still-image``: the seam never marks a canvas slow, so no image is ever made."""
    from rigidrel_app.cli import build_parser
    from rigidrel_app.live.still_image import StillImage

    off, on = StillImage(enabled=False), StillImage()
    off.canvas_slowed()
    on.canvas_slowed()
    assert not off.slow_canvas and on.slow_canvas
    made: list[object] = []
    off.tick(None, None, 1.0, made.append)  # type: ignore[arg-type]  # returns before touching either
    assert made == []
    args = build_parser().parse_args(["serve", "--no-still-image"])
    assert args.still_image is False and build_parser().parse_args(["serve"]).still_image is True
    scene_args = build_parser().parse_args(["serve", "constant-acceleration", "--no-still-image"])
    assert scene_args.still_image is False
