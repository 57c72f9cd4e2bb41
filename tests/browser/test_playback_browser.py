"""Playback in the browser: the tab's runtime plays the state's timeline, and the server sends it
nothing while it plays; a pause comes back as the frame on screen."""

from __future__ import annotations

import time
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from rigidrel_app.live.server import App
from rigidrel_app.view.state import presets
from tests.browser.test_app_browser import AppPage
from tests.viser_client import wait_until

pytestmark = pytest.mark.browser


def runtime_frames(tab: AppPage) -> int:
    return int(tab.page.evaluate("() => window.__rigidrelPlayback.stats.frames"))


def test_the_browser_plays_and_the_server_sends_nothing_per_frame(tab: AppPage, shots: Path) -> None:
    s = tab.session
    with s.lock:
        s.asks.change(presets()["Fig. 3: collision, M2 = 2 M1"], refit=True)
    tab.page.click("button:has-text('Play')")
    wait_until(lambda: s.player.playing, timeout=60)
    wait_until(lambda: runtime_frames(tab) > 5)
    count0, frames0, t0 = len(tab.received), runtime_frames(tab), time.monotonic()
    time.sleep(3.0)
    count1, frames1 = len(tab.received), runtime_frames(tab)
    span = time.monotonic() - t0
    tab.page.screenshot(path=str(shots / "playing.png"))
    # the picture moves (software WebGL here: several new pictures a second) ...
    assert frames1 - frames0 > 3 * span, (frames1 - frames0, span)
    # ... and the server sends none of them: a few frames of its own at most (the panel's clock is the runtime's)
    assert count1 - count0 <= 2 * span, tab.received[count0:count1]
    tab.page.click("button:has-text('Pause')")
    wait_until(lambda: s.playing.settled)
    timeline = s.player.timeline
    assert timeline is not None
    frame = timeline.frame_of(s.state.playback.now)
    assert frame is not None  # paused on a frame the browser showed: the clock is that frame's time
    state = tab.page.evaluate("() => [window.__rigidrelPlayback.applied, window.__rigidrelPlayback.playing]")
    assert state == [frame, False]


def test_every_tab_in_a_state_gets_the_one_timeline(browser: Any) -> None:
    server = App(host="127.0.0.1", port=0)  # a server of its own: it counts every timeline it makes
    a, b = AppPage(browser, server), AppPage(browser, server)
    try:
        for tab in (a, b):
            with tab.session.lock:
                tab.session.asks.change(presets()["Fig. 3: collision, M2 = 2 M1"], refit=True)
            tab.page.click("button:has-text('Play')")
        wait_until(lambda: a.session.player.playing and b.session.player.playing, timeout=60)
        assert a.session.player.timeline is b.session.player.timeline  # made once, for both
        assert server.timelines.recorded == 1
        assert np.isfinite(a.session.player.timeline.times).all()  # type: ignore[union-attr]
    finally:
        a.close()
        b.close()
        server.stop()
