"""A tab's clock while its browser plays: the runtime started on the page, its reports, the
timeline it asks for, the animation loop's tick and the still picture of a slow canvas.

The runtime (:mod:`.runtime`) plays a state's timeline in the browser and reports back (ready,
paused, stopped at the end); the server's clock follows it and draws nothing. A tab whose runtime
is not ready yet is drawn by the server, frame by frame, until it is.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import replace

from ..backends._viser import handle_uuid, run_javascript, scene_owner
from .cover import say_page_drawn
from .gestures import Gestures
from .runtime import Report, RuntimeConfig, add_playback_report, clock_controls, parse_report, runtime_script
from .tab import Tab
from .timeline import Timeline, TimelineKey


class Playing:
    """The clock of ``tab`` as its browser plays it."""

    def __init__(self, tab: Tab) -> None:
        self.tab = tab

    @property
    def settled(self) -> bool:
        """Paused with the picture and the clock agreeing (no pause on its way back from the browser)."""
        return not self.tab.state.playback.playing and not self.tab.player.pausing

    def connect(self, gestures: Gestures) -> None:
        """Start the browser's runtime on the tab's page, with the hidden control it reports
        through: on its clock (here) and on the pointer over the canvas (``gestures``)."""
        tab = self.tab
        report = add_playback_report(tab.client.gui)
        report.on_update(lambda _: self._heard(report.value, gestures))
        clock = clock_controls(tab.controls.time.handles)
        config = RuntimeConfig(scene_owner(tab.client), handle_uuid(report), clock)
        run_javascript(tab.client, runtime_script(config))

    def _heard(self, text: str, gestures: Gestures) -> None:
        """A report of the runtime; anything else a client sends there is ignored."""
        report = parse_report(text)
        if report is None:
            return
        if report.event != "pointer":
            self.reported(report)
            return
        tab = self.tab
        with tab.lock:
            if not tab.closed:
                with tab.client.atomic():
                    gestures.reported(report)
        tab.client.flush()

    def reported(self, report: Report) -> None:
        """A report of the tab's runtime on its clock (ready, paused, ended), answered at once."""
        tab = self.tab
        with tab.lock:
            if tab.closed:
                return
            with tab.client.atomic():
                if report.event == "ready":
                    self._ready(report.lead, report.still)
                elif (now := tab.player.stopped_at(report)) is not None:
                    tab.set_playback(replace(tab.state.playback, now=now, playing=False))
                    tab.draw_now(force_plots=True)  # its frame is on screen: only the time controls follow
        tab.client.flush()

    def _ready(self, lead: str | None, still: bool) -> None:
        tab = self.tab
        if lead is not None and tab.lesson.claim(lead):
            tab.show(tab.state.as_lecturer())
        if still and not tab.state.still:
            tab.state = replace(tab.state, still=True)  # reduced motion: an autoplaying step pauses
            if tab.state.playback.playing:
                tab.set_playback(replace(tab.state.playback, playing=False))
        if not tab.player.ready:
            tab.painter.runtime_ready()
            tab.draw_now(force_plots=True)
            say_page_drawn(tab.client)  # the first page is whole: the page's cover leaves once it is drawn
            if tab.state.playback.playing:
                self.play()

    def play(self) -> None:
        """Ask for the timeline of the state on screen (made once for every tab in that state), and
        play it once it is made."""
        tab = self.tab
        drawn, layout, shown = tab.painter.drawn, tab.painter.layout, tab.state.shown
        key = None if shown is None or layout is None else TimelineKey(shown, layout, tab.state.playback.window)
        tab.player.play(key, None if drawn is None else drawn.resolved, tab.state.playback, self._made)

    def _made(self, timeline: Timeline) -> None:
        """On the timelines' thread: a timeline this tab asked for is made."""
        tab = self.tab
        with tab.lock:
            if tab.closed or not tab.player.is_wanted(timeline):
                return
            with tab.client.atomic():
                tab.player.start(timeline, tab.state.playback)
        tab.client.flush()

    def tick(self, dt: float) -> None:
        """Advance playback by ``dt`` wall seconds (called by the animation loop): while the browser
        plays, the server's clock follows it and nothing is drawn; else the server draws."""
        tab = self.tab
        with tab.lock:
            if tab.closed or not tab.state.playback.playing:
                return
            if not tab.player.ready:
                tab.set_playback(tab.state.playback.advance(dt))
                tab.draw_now(force_plots=not tab.state.playback.playing)  # stopped at the end: the box shows it
            elif tab.player.playing:
                tab.set_playback(tab.state.playback.advance(dt))
            tab.painter.tick_still_image(self._send_still_image)

    def _send_still_image(self, show: Callable[[], None]) -> None:
        """From the still image's thread: ``show`` it, under the lock and in one batch."""
        tab = self.tab
        with tab.lock:
            if tab.closed:
                return
            with tab.client.atomic():
                show()
        tab.client.flush()
