"""The canvas in a real browser, measured: rods where the core puts them, legible at the sliders'
extremes, the diagrams' labels and legend drawn, no share button.

These tests share one tab (opening one takes seconds): each puts the session in the state it looks
at (:func:`~tests.browser.test_app_browser.show`: the scene, its values, the frame, the clock) and
changes nothing else of the page (its size, presenter mode, a control typed into). The tab is
closed when the module ends, so that no other test's tab renders beside it. Screenshots land in
``test-artifacts/screenshots/<test>/``.
"""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path
from typing import Any

import numpy as np
import pytest

import rigidrel_core as rr
from rigidrel_app.view.state import CUSTOM_FRAME, Settings
from tests.browser.test_app_browser import PIXEL_TOLERANCE, AppPage, rods_drawn, show, tab_on_own_server
from tests.viser_client import wait_until

pytestmark = pytest.mark.browser


@pytest.fixture(scope="module")
def one_tab(browser: Any) -> Iterator[AppPage]:
    with tab_on_own_server(browser) as page:
        yield page


@pytest.fixture
def tab(one_tab: AppPage) -> AppPage:
    """The module's one tab; the page's errors are counted from each test's start."""
    one_tab.errors.clear()
    return one_tab


def test_rod_pixels_match_the_core_in_both_lanes(tab: AppPage, shots: Path) -> None:
    """Both lanes put each rod end where the core says, on their rulers' scales.

    The chosen frame moves at beta = 0.8 and the clock is mid-collision, so lab positions
    drawn in the frame lane would be off by far more than the tolerance (checked).
    """
    settings = Settings.of("rod-collision", v1=0.6, v2=0.0, mass2=2.0, eps=1.0)
    settings = Settings(settings.scene, settings.values, CUSTOM_FRAME, 0.8)
    now = 0.4
    default_scene = tab.canvas()
    show(tab, settings, now)
    scene = tab.session.painter.drawn.resolved.scene  # type: ignore[union-attr]
    frame = tab.session.painter.drawn.resolved.frame  # type: ignore[union-attr]
    tab.canvas_after(default_scene)
    found = rods_drawn(tab)
    tab.page.screenshot(path=str(shots / "collision_beta_0.8_t_0.4.png"))
    separation = []
    for lane, runs, lane_frame in zip(tab.session.painter.renderer_lanes, found, (rr.LAB, frame), strict=True):
        x = scene.positions(np.array([now]), frame=lane_frame)[:, :, 0]
        x_lab = scene.positions(np.array([now]), frame=rr.LAB)[:, :, 0]
        for r in range(2):
            lo, hi = lane.origin_px + x[r] * lane.scale
            a, b = runs[r]
            assert abs(a - lo) <= PIXEL_TOLERANCE and abs(b - hi) <= PIXEL_TOLERANCE, (r, (a, b), (lo, hi))
            lab_lo, lab_hi = lane.origin_px + x_lab[r] * lane.scale
            separation.append(max(abs(lab_lo - lo), abs(lab_hi - hi)))
    # in the frame lane, lab positions would be visibly wrong: the test can fail for the right reason
    assert max(separation[2:]) > 10 * PIXEL_TOLERANCE


@pytest.mark.parametrize(("width", "height"), [(1280, 720), (1920, 1080)])
def test_both_lanes_are_drawn_at_one_scale(tab: AppPage, shots: Path, width: int, height: int) -> None:
    """Bell's ships late in their window, at V = 0.6: each 0.08 long in the lab and 0.1 in the
    ships' frame after. Measured on the canvas, each ship is drawn in both lanes in the ratio of
    the lengths the core gives, so contraction reads off the picture (both lanes at one scale)."""
    tab.page.set_viewport_size({"width": width, "height": height})
    settings = Settings("bell-spaceships", frame="ships after")
    d = build_drawing_for(settings)
    now = d.window[0] + 0.95 * (d.window[1] - d.window[0])
    show(tab, settings, now)
    wait_until(lambda: (lay := tab.session.painter.layout) is not None and lay.height > 0.5 * height, timeout=60)
    tab.canvas_after(np.zeros_like(tab.canvas()))  # at its new size (rods_drawn waits for the rods)
    lab, frame = rods_drawn(tab)
    tab.page.screenshot(path=str(shots / f"one-scale-bell-{width}x{height}.png"))
    lanes = tab.session.painter.renderer_lanes
    assert lanes[0].scale == pytest.approx(lanes[1].scale, rel=1e-12)
    for r in range(2):
        lab_len, frame_len = (float(np.diff(lane.ends[r])[0]) for lane in lanes)
        assert lab_len == pytest.approx(0.08, rel=1e-3) and frame_len == pytest.approx(0.1, rel=1e-3)
        lab_px, frame_px = lab[r][1] - lab[r][0], frame[r][1] - frame[r][0]
        assert lab_px / frame_px == pytest.approx(lab_len / frame_len, abs=3 * PIXEL_TOLERANCE / frame_px), (
            r,
            lab_px,
            frame_px,
        )


#: Slider extremes where the old view lost its rods; each lane must show each rod at least this
#: share of its track times its rest length over the largest (or 12 px).
LEGIBLE_SHARE = 0.15
EXTREMES = [
    ("V_0.99", Settings.of("constant-acceleration", v=0.99), 0.9),
    ("V_0.99_aF_0.01", Settings.of("constant-acceleration", v=0.99, a_front=0.01), 0.9),
    ("wall_V_0.99", Settings.of("wall-collision", v=0.99), 0.6),
    ("beta_+0.99", Settings("constant-acceleration", (), CUSTOM_FRAME, 0.99), 0.5),
    ("beta_-0.99", Settings("constant-acceleration", (), CUSTOM_FRAME, -0.99), 0.5),
    ("M2_0.01", Settings.of("rod-collision", mass2=0.01), 0.9),
    ("M2_100", Settings.of("rod-collision", mass2=100.0), 0.9),
    ("L2_0.1", Settings.of("rod-collision", length2=0.1), 0.6),
]


@pytest.mark.parametrize(("name", "settings", "fraction"), EXTREMES, ids=[e[0] for e in EXTREMES])
def test_rods_stay_large_at_the_sliders_extremes(
    tab: AppPage, shots: Path, name: str, settings: Settings, fraction: float
) -> None:
    """Measured on the canvas: every rod of both lanes is drawn where the core puts it and at least
    LEGIBLE_SHARE of its lane (scaled by its rest length), late in the window (rods fastest)."""
    before = tab.canvas()
    d = build_drawing_for(settings)
    now = d.window[0] + fraction * (d.window[1] - d.window[0])
    show(tab, settings, now)
    tab.canvas_after(before)
    measured = rods_drawn(tab)
    tab.page.screenshot(path=str(shots / f"{name}.png"))
    layout = tab.session.painter.layout
    assert layout is not None
    rest = np.array([rod.motion.length for rod in d.resolved.scene.rods])
    for place, runs in zip(layout.lanes, measured, strict=True):
        for r, (a, b) in enumerate(runs):
            need = max(min(LEGIBLE_SHARE * rest[r] / rest.max() * place.track.width, 12.0), 8.0)
            assert b - a >= need, (name, r, b - a, need)


def test_the_canvas_carries_the_diagrams_event_labels_and_legend(tab: AppPage) -> None:
    show(tab, Settings("rod-collision", frame="barycentric"), 0.0)
    wait_until(lambda: any("barycentric" in t for t in tab.texts()))
    texts = tab.texts()
    assert "Minkowski diagram, lab frame" in texts
    assert any(t.startswith("Minkowski diagram,") and "barycentric" in t for t in texts)
    assert "Equal-time length (Fig. 2)" in texts
    for label in ("T_1", "T′_1", "T_2", "T′_2"):
        assert sum(t.startswith(label) for t in texts) >= 2, label  # on both Minkowski diagrams
    for name in ("rod 1", "rod 2", "light cone of the origin", "events", "rods now", "now: t", "now: t′"):
        assert name in texts, name
    assert any("axes of barycentric" in t for t in texts)
    # the length panel's solid lab curves are the rods' entries; the frame's dashed ones have their own
    assert not {"rod 1, lab (t)", "rod 2, lab (t)"} & set(texts)
    assert {"rod 1, barycentric (t′)", "rod 2, barycentric (t′)"} <= set(texts)
    assert {"t", "x", "t′", "x′"} <= set(texts)  # the axes are named in each frame's coordinates
    assert {"x", "x′"} <= set(texts)  # and so are the rulers


def test_share_button_is_hidden(tab: AppPage) -> None:
    """viser's share button (it needs the internet) is hidden: the header, drawn with its other icons,
    has no share icon, and no header icon is labelled "Share"."""
    icons = tab.page.locator("button.mantine-ActionIcon-root")
    visible = [icons.nth(k) for k in range(icons.count()) if icons.nth(k).is_visible()]
    assert visible, "the header's icons are not drawn yet"
    assert tab.page.locator("svg.tabler-icon").count() > 0  # tabler icons are drawn: the check can see one
    assert tab.page.locator("svg.tabler-icon-share").count() == 0
    assert all("share" not in (icon.get_attribute("aria-label") or "").lower() for icon in visible)


def build_drawing_for(settings: Settings) -> Any:
    from rigidrel_app.view.scene_view import build_drawing
    from rigidrel_app.view.state import resolve

    r = resolve(settings)
    assert not isinstance(r, str)
    return build_drawing(r)
