"""The pointer on a tab's canvas, carried out: a press, a drag and a release that the page's runtime
reports (:class:`~.runtime.Report`, ``pointer``) become what :mod:`rigidrel_app.view.pointer` says
they ask for, through the tab's requests: a light cone chosen, the clock scrubbed, the chosen
frame's β dragged. So a step that fixes a control refuses the pointer as it refuses the control,
with the same notice.

A press pauses playback first (a scrub then holds the picture where the pointer is). A drag's
reports come at most every 50 ms (the runtime throttles them); β is set at each, the clock too.
"""

from __future__ import annotations

from dataclasses import replace

import rigidrel_core as rr

from ..view.pointer import ChooseCone, Diagrams, DragBeta, Scrub, dragged_beta, press, scrubbed
from ..view.state import CUSTOM_FRAME, cone_events
from .requests import Requests
from .runtime import PointerEvent, Report
from .tab import Tab


class Gestures:
    """The pointer on ``tab``'s canvas, carried out through ``asks``."""

    def __init__(self, tab: Tab, asks: Requests) -> None:
        self.tab, self.asks = tab, asks
        self.gesture: Scrub | DragBeta | None = None
        """The drag under way, if any."""
        self.run, self.seen = "", 0
        """The runtime whose events these are, and the last of them taken."""

    def _diagrams(self) -> Diagrams | None:
        tab = self.tab
        drawn, frames, state = tab.painter.drawn, tab.painter.chart_frames, tab.state
        if drawn is None or len(frames) < 2 or state.shown is None:
            return None
        r = drawn.resolved
        return Diagrams(
            frames,
            (rr.LAB, r.frame),
            r.scene,
            cone_events(r.scene),
            state.shown.cone,
            r.frame.beta,
        )

    def reported(self, report: Report) -> None:
        """A pointer report: each event not seen yet, in its order. Called under the tab's lock, in
        one batch."""
        if report.run != self.run:  # a runtime of its own numbers its events from 1
            self.run, self.seen = report.run, 0
        for event in report.pointer:
            if event.seq > self.seen:
                self.seen = event.seq
                self._event(event)

    def _event(self, event: PointerEvent) -> None:
        """A press reads what lies under it, a drag carries its gesture on, a release ends it."""
        tab = self.tab
        layout = tab.painter.layout
        if layout is None:
            return
        x, z = event.x, layout.height - event.y  # the canvas' CSS px, y down, to the page's px, z up
        if event.phase == "up":
            self.gesture = None
            return
        d = self._diagrams()
        if d is None:
            return
        if event.phase == "down":
            self.gesture = None
            asked = press(d, x, z, tab.state.playback.now)
            if asked is None:
                return
            if tab.state.playback.playing:
                tab.set_playback(replace(tab.state.playback, playing=False))
            if isinstance(asked, ChooseCone):
                self.asks.change(replace(tab.state.settings, cone=asked.event), refit=False)
                return
            self.gesture = asked
            if isinstance(asked, Scrub):
                self.asks.seek(asked.time)
            return
        gesture = self.gesture
        if isinstance(gesture, Scrub):
            t = scrubbed(d, gesture, x, z)
            if t is not None:
                self.asks.seek(t)
        elif isinstance(gesture, DragBeta):
            beta = dragged_beta(gesture, x)
            if beta != tab.state.settings.beta or tab.state.settings.frame != CUSTOM_FRAME:
                self.asks.change(replace(tab.state.settings, frame=CUSTOM_FRAME, beta=beta), refit=False)
