"""The paradoxes' lanes as the browser draws them: the pole-barn's two poles one above the other, Bell's
string coloured by its strain between the ships and the comparison rod on its own row below them.
The tests share one tab, reset before each to where a new tab opens."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from rigidrel_app.view.lanes import Box
from rigidrel_app.view.state import Settings
from tests.browser.test_app_browser import PIXEL_TOLERANCE, AppPage, rod_runs, show

pytestmark = pytest.mark.browser


@pytest.fixture
def tab(shared_tab: AppPage) -> AppPage:
    """The file's one tab, back where a new tab opens (:meth:`AppPage.reset`)."""
    shared_tab.reset()
    return shared_tab


def _row(tab: AppPage, img: np.ndarray, z: float) -> np.ndarray:
    _, row = tab.page_to_pixel(0.0, z)
    return img[round(row)]


def _covers(runs: list[tuple[int, int]], lo: float, hi: float) -> bool:
    """Whether the runs near ``[lo, hi]`` reach from ``lo`` to ``hi`` (ticks and the door split them)."""
    near = [ab for ab in runs if ab[1] >= lo - 2 * PIXEL_TOLERANCE and ab[0] <= hi + 2 * PIXEL_TOLERANCE]
    if not near:
        return False
    return abs(min(a for a, _ in near) - lo) <= PIXEL_TOLERANCE and abs(max(b for _, b in near) - hi) <= PIXEL_TOLERANCE


def _off(runs: list[tuple[int, int]], boxes: tuple[Box, ...]) -> list[tuple[int, int]]:
    """The runs that touch none of ``boxes``."""
    return [(a, e) for a, e in runs if not any(a <= o.x1 + 2 and e >= o.x0 - 2 for o in boxes)]


def test_pole_barn_shows_both_poles_one_above_the_other(tab: AppPage, shots: Path) -> None:
    """In both lanes: on the upper row's centre line the Born-rigid pole (blue) from end to end and no
    orange; on the lower row's the signal-limited pole (orange) from end to end and no blue."""
    before = tab.canvas()
    show(tab, Settings("pole-barn"), 0.5)
    img = tab.canvas_after(before)
    tab.page.screenshot(path=str(shots / "pole_barn_t_0.5.png"))
    for lane in tab.session.painter.renderer_lanes:
        born, signal = lane.boxes[:2]
        upper, lower = _row(tab, img, born.z), _row(tab, img, signal.z)
        assert _covers(rod_runs(upper, "blue"), born.x0, born.x1), rod_runs(upper, "blue")
        assert _covers(rod_runs(lower, "orange"), signal.x0, signal.x1), rod_runs(lower, "orange")
        barn = lane.boxes[2:]  # the wall and the door (the door's brown, lit, may pass for orange)
        assert not _off(rod_runs(upper, "orange"), barn) and not _off(rod_runs(lower, "blue"), barn)


def test_bell_string_darkens_with_strain_and_the_comparison_rod_has_its_own_row(tab: AppPage, shots: Path) -> None:
    """The string's middle is lighter just after the start than near the breaking strain; on the ships'
    row between the ships it is the string, not the green comparison rod, which is on the row below."""
    settings = Settings("bell-spaceships")
    brightness = []
    for now in (0.05, 1.2):
        before = tab.canvas()
        show(tab, settings, now)
        img = tab.canvas_after(before)
        tab.page.screenshot(path=str(shots / f"bell_t_{now}.png"))
        lane = tab.session.painter.renderer_lanes[0]
        rear, front, rod, string = lane.boxes[:4]
        middle = round(0.5 * (string.x0 + string.x1))
        ships_row, rod_row = _row(tab, img, string.z), _row(tab, img, rod.z)
        r, g, b = (int(c) for c in ships_row[middle])
        assert not (g - r > 40 and g - b > 10), (r, g, b)  # not the comparison rod's green
        rg, gg, bg = (int(c) for c in rod_row[middle])
        assert gg - rg > 40, (rg, gg, bg)  # the comparison rod's green, on its own row
        assert rear.x1 <= string.x0 + 1 and string.x1 <= front.x0 + 1
        brightness.append(r + g + b)
    assert brightness[0] > brightness[1] + 150, brightness
