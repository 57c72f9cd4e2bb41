"""A tab's playback runtime as the server knows it: what it holds, what it shows, what to send it.

The runtime (:mod:`.runtime`, ``assets/runtime.js``) plays a state's :class:`~.timeline.Timeline`
in the browser, shows single frames the server sends, and shows a page shared by the tabs on a
canvas of one size (:mod:`.painting`). A :class:`BrowserPlayer` keeps the server's side of that
conversation: which timelines the runtime holds, which page and frame it shows, whether it plays,
and a pause on its way back. It sends, and never draws.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np
import viser

from ..backends._viser import PlaybackMessage, queue_to_client
from ..view.state import Resolved
from .painting import Painting
from .playback import Playback
from .runtime import Report
from .timeline import FRAMES_PER_BLOCK, OWN_FRAME_LEVEL, Mirror, Timeline, TimelineCache, TimelineKey, timeline_id

#: Timelines a tab's runtime keeps (the oldest is forgotten past these).
RUNTIME_TIMELINES = 4


class BrowserPlayer:
    """The server's side of one tab's runtime; ``timelines``: where its timelines come from (None:
    the tab has no runtime, and the server draws every frame)."""

    def __init__(self, client: viser.ClientHandle, timelines: TimelineCache | None) -> None:
        self.client = client
        self.timelines = timelines
        self.ready = False
        """The runtime said it is ready: it draws the moving parts."""
        self.mirror: Mirror | None = None
        """What the runtime shows of the server's own frames (once it is ready)."""
        self.nodeset: str | None = None
        """The node set the runtime draws on, as far as the server told it."""
        self.timeline: Timeline | None = None
        """The timeline of the state on screen, once made and sent."""
        self.wanted: TimelineKey | None = None
        """The timeline asked for and not made yet."""
        self.held: list[str] = []
        """Timelines the runtime holds (the newest last)."""
        self.playing = False
        """The runtime plays :attr:`timeline` (the server's clock only follows it)."""
        self.pausing = False
        """A pause was sent and its frame has not come back yet."""
        self.page: str | None = None
        """The shared page the runtime shows (its painting's id), if any."""
        self.frame: tuple[str, float] | None = None
        """The shared frame the runtime shows (its painting's id and time), if it shows one."""

    def send(self, action: str, timeline: str = "", value: float = 0.0, payload: np.ndarray | None = None) -> None:
        message = PlaybackMessage(action, timeline, float(value))
        if payload is not None:
            message.payload = payload
        queue_to_client(self.client, message)

    def become_ready(self) -> Mirror | None:
        """The runtime said it is ready: its mirror of the server's frames (None if it already was)."""
        if self.ready:
            return None
        self.ready = True
        self.mirror = Mirror(f"tab{self.client.client_id}")
        return self.mirror

    def new_state(self) -> None:
        """Another state is on screen: the timeline the runtime plays or holds for the old one is not its."""
        self.timeline, self.playing, self.pausing = None, False, False

    # ------------------------------------------------------------------ pages and frames
    def lend_page(self, painting: Painting) -> None:
        """Show ``painting``'s page, shared by the tabs on a canvas of its size (sent once)."""
        if self.page != painting.id:
            self.send("page", painting.id, 1.0, payload=painting.page())
            self.page = painting.id

    def drop_page(self) -> None:
        """The shared page goes: the tab's own still picture shows again."""
        if self.page is not None:
            self.send("page", "", 0.0)
            self.page = None

    def shared_frame(self, painting: Painting, now: float) -> None:
        """``painting``'s frame at ``now``, made once for every tab that shows it."""
        if self.frame != (painting.id, now):
            self.send("frame", payload=painting.frame(now))
            self.frame = (painting.id, now)
        self.nodeset = painting.id  # not the mirror's: its next frame goes whole

    def own_frame(self, now: float) -> None:
        """The tab's own frame at ``now``, drawn into the mirror: the runtime shows it."""
        if self.mirror is None:
            return
        self.frame = None
        prologue = self.nodeset != self.mirror.nodeset
        self.send("frame", payload=self.mirror.frame(now, prologue, OWN_FRAME_LEVEL))
        self.nodeset = self.mirror.nodeset

    def seek(self, now: float) -> bool:
        """Show ``now`` from the timeline the runtime holds, if it is one of its frames (a step, a
        seek onto a frame): True if so, and nothing else needs drawing."""
        timeline = self.timeline
        if not self.ready or timeline is None or timeline.id not in self.held:
            return False
        frame = timeline.frame_of(now)
        if frame is None:
            return False
        self.frame = None
        self.send("seek", timeline.id, frame)
        self.nodeset = timeline.id
        return True

    # ------------------------------------------------------------------ playing
    def play(
        self, key: TimelineKey | None, resolved: Resolved | None, playback: Playback, made: Callable[[Timeline], None]
    ) -> None:
        """Play the state's timeline from the clock's frame, once the runtime has it (asked for now;
        ``made`` is called on the timelines' thread when it is made; meanwhile the picture holds)."""
        if not self.ready or self.timelines is None or key is None or resolved is None:
            return
        timeline = self.timeline
        if timeline is None or self.wanted is not None:
            self.wanted = key
            timeline = self.timelines.request(key, resolved, made)
            if timeline is None:
                return
        self.start(timeline, playback)

    def is_wanted(self, timeline: Timeline) -> bool:
        return self.wanted is not None and timeline.id == timeline_id(self.wanted)

    def start(self, timeline: Timeline, playback: Playback) -> None:
        """``timeline`` is the state's: sent if the runtime lacks it, and played if ``playback`` plays."""
        self.timeline, self.wanted = timeline, None
        if timeline.id not in self.held:
            for k, block in enumerate(timeline.blocks):  # the value: the block's first frame
                self.send("block", timeline.id, k * FRAMES_PER_BLOCK, payload=block)
            self.held.append(timeline.id)
            if len(self.held) > RUNTIME_TIMELINES:
                self.send("forget", self.held.pop(0))
        if not playback.playing:
            return
        self.send("speed", value=playback.speed)
        self.send("loop", value=float(playback.loop))
        t0, t1 = playback.window
        frame = (playback.now - t0) / (t1 - t0) * (len(timeline.times) - 1) if t1 > t0 else 0.0
        self.frame = None
        self.send("play", timeline.id, frame)
        self.playing, self.pausing = True, False
        self.nodeset = timeline.id

    def clock_changed(self, was: Playback, playback: Playback) -> bool:
        """Follow the clock from ``was`` to ``playback``; True if it now plays and needs
        :meth:`play`. A pause (by a key, a button, or the clock's estimate reaching the end) waits
        for the browser's frame where it stops, which sets the clock."""
        if not self.ready:
            return False
        if self.playing and (playback.speed, playback.loop) != (was.speed, was.loop):
            self.send("speed", value=playback.speed)
            self.send("loop", value=float(playback.loop))
        if playback.playing and not was.playing:
            return True
        if was.playing and not playback.playing and self.playing:
            self.playing, self.pausing = False, True
            if playback.now != was.window[1] or playback.loop:  # at the end it stops by itself
                self.send("pause", self.timeline.id if self.timeline is not None else "")
        return False

    def stopped_at(self, report: Report) -> float | None:
        """The time of the frame the runtime paused or ended on, if it is of the timeline on screen."""
        timeline = self.timeline
        if timeline is None or report.timeline != timeline.id or report.frame is None:
            return None
        self.pausing = False
        if report.frame >= len(timeline.times):
            return None
        self.playing = False
        return float(timeline.times[report.frame])
