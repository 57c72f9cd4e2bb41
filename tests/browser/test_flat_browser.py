"""The still picture's image, as the browser shows it, is the picture its lines, dots and labels
draw: upright, in place and at the canvas' pixels (a flipped, shifted or resampled image fails)."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np
import pytest
from PIL import Image
from playwright.sync_api import ViewportSize

from rigidrel_app.live.server import App
from rigidrel_app.view.state import presets
from tests.browser.test_app_browser import AppPage, show
from tests.viser_client import wait_until

pytestmark = pytest.mark.browser

#: The window the thresholds below were measured in (a smaller one packs more ink per pixel: the
#: right image then differs by about 10).
WINDOW: ViewportSize = {"width": 1440, "height": 900}
#: Largest mean difference (0-255 per channel) between the two forms over the diagrams (about
#: 7.7 measured; the image one pixel off gives 10 to 11, upside down 34).
MEAN_DIFFERENCE = 9.0
#: Largest share of the diagrams' pixels that differ by more than a third of the range (3.3 %
#: measured; one pixel off 4.4 to 5.7 %).
FAR_SHARE = 0.04


def test_the_image_shows_the_picture_its_nodes_draw(browser: Any, app_server: App, shots: Path) -> None:
    # the browser's resolution held at 1 (viser lowers it while frames are slow): both forms are
    # photographed at the same resolution
    tab = AppPage(browser, app_server, query="?fixedDpr=1", viewport=WINDOW)
    try:
        s = tab.session
        show(tab, presets()["Fig. 3: collision, M2 = 2 M1"], 0.0)
        lines = tab.canvas_after(np.zeros_like(tab.canvas()))
        s.painter.still_image.slow_canvas = True  # as when the browser has lowered its resolution
        with s.lock:
            s.asks.toggle_play()
        wait_until(
            lambda: (
                s.painter.renderer.flat_version == s.painter.renderer.version and not s.painter.renderer.vectors_shown
            ),
            timeout=30,
        )
        with s.lock:
            s.asks.toggle_play()
            s.asks.seek(0.0)
        assert not s.painter.renderer.vectors_shown
        flat = tab.canvas_after(np.zeros_like(lines))
        Image.fromarray(lines.astype(np.uint8)).save(shots / "lines.png")
        Image.fromarray(flat.astype(np.uint8)).save(shots / "image.png")
        layout = s.painter.layout
        assert layout is not None
        # the diagrams and the legend: the page below the lanes
        top = round(layout.height - layout.lanes[-1].band.z0)
        a, b = lines[top:], flat[top:]
        assert a.shape == b.shape
        difference = np.abs(a - b).max(axis=-1)
        assert difference.mean() < MEAN_DIFFERENCE, difference.mean()
        assert (difference > 85).mean() < FAR_SHARE, (difference > 85).mean()
        # not blank: the diagrams are there in both
        assert (a.sum(axis=-1) < 300).mean() > 0.01
    finally:
        tab.close()
