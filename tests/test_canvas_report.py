"""The page's report of its canvas' CSS size: what is decoded, what is ignored, what it overrides."""

from __future__ import annotations

import math
from html import unescape

import pytest

from rigidrel_app.live.canvas_report import RATIO_BASE, SIZE_BASE, CssSize, decode, encode, script
from rigidrel_app.view.layout import CanvasSize


def test_a_report_decodes_to_both_sides_and_the_ratio() -> None:
    assert decode(encode(1280, 720, 2.0)) == CssSize(1280, 720, 2.0)
    assert decode(float(encode(1, 1, 0.875))) == CssSize(1, 1, 0.875)
    assert decode(encode(65535, 65535, 8.191)) == CssSize(65535, 65535, 8.191)


@pytest.mark.parametrize(
    "value",
    [
        0.0,
        -5.0,
        math.nan,
        math.inf,
        encode(1280, 720, 1.0) + 0.5,  # not a whole number
        (1280 * SIZE_BASE) * RATIO_BASE + 1000,  # no height
        (720) * RATIO_BASE + 1000,  # no width
        encode(1280, 720, 0.05),  # a ratio no screen has
        1e30,
    ],
)
def test_values_no_page_sends_are_ignored(value: float) -> None:
    assert decode(value) is None


def test_the_page_measures_a_high_density_screen() -> None:
    measured = CanvasSize.measured_by_page(1096, 720, 2.0)  # 2 pixels per CSS px
    assert (measured.width, measured.height, measured.measured) == (1096, 720, True)
    slow = measured.reported(1918, 1260)  # the client renders at 0.875 for a while: the page is the same
    assert (slow.width, slow.height, slow.measured) == (1096, 720, True) and slow.resolution == 1.75
    # a new size in the camera's pixels waits for the page's own report: pixels cannot tell a new
    # size at the same resolution (1280 x 720 at 1.75) from another at another (1120 x 630 at 2)
    assert slow.reported(2240, 1260) == slow
    # and a camera report that arrives after the page's (the canvas before the panel folded away)
    wide = CanvasSize.measured_by_page(1280, 720, 2.0)
    assert wide.reported(2192, 1440) == wide
    assert wide.reported(2240, 1260) == CanvasSize(1280, 720, 1.75, True)  # only a step of the resolution


def test_without_the_page_a_step_of_the_clients_resolution_is_not_a_new_canvas() -> None:
    first = CanvasSize(1096.0, 900.0)
    slow = first.reported(959, 787)  # 1096 x 900 at 0.875, rounded down by the browser
    assert (slow.width, slow.height, slow.resolution) == (1096.0, 900.0, 0.875)
    slower = slow.reported(822, 675)
    assert (slower.width, slower.height) == (1096.0, 900.0) and slower.resolution == pytest.approx(0.75)
    resized = slower.reported(600, 450)  # a new window while at 0.75: read in CSS px at that resolution
    assert (resized.width, resized.height) == pytest.approx((800.0, 600.0))
    fast = resized.reported(800, 600)  # fast again: full resolution, the same page
    assert (fast.width, fast.height) == pytest.approx((800.0, 600.0)) and fast.resolution == pytest.approx(1.0)
    # a real resize is a new size, even one close to a step (only one side matches)
    assert first.reported(959, 900) == CanvasSize(959.0, 900.0, 1.0)
    assert first.reported(1096, 900) == first
    assert first.reported(1000, 700) == CanvasSize(1000.0, 700.0, 1.0)


def test_the_panel_folding_away_while_the_resolution_steps_keeps_the_height() -> None:
    """Presenter mode on a slow machine, on a page that cannot run its script: the panel folds away
    (the canvas 936 -> 1240 CSS px wide, the same 720 high) just as the client steps its resolution
    down to 0.875. Only the camera speaks: its height says which resolution it is at."""
    docked = CanvasSize(936.0, 720.0, 1.0)
    wide = docked.reported(1085, 630)  # 1240 x 720 at 0.875
    assert (wide.width, wide.height) == pytest.approx((1240.0, 720.0)) and wide.resolution == 0.875
    back = wide.reported(936, 720)  # the panel back, full resolution again
    assert (back.width, back.height) == pytest.approx((936.0, 720.0)) and back.resolution == pytest.approx(1.0)
    assert docked.reported(1096, 630) == CanvasSize(1096.0 / 0.875, 720.0, 0.875)  # read so, not as 630 high


def test_the_script_hides_only_its_own_box() -> None:
    html = script("abc-123")
    assert '[for="abc-123"]' in html and "getElementById('abc-123')" in unescape(html)  # the onerror attribute
    assert "<script" not in html  # viser's HTML element would not run it
