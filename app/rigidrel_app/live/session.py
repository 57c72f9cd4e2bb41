"""One browser tab: the wiring between its controls, its state, its canvas and its lesson.

A callback asks the tab's :class:`~.tab_state.TabState` for the state a change leads to (a pure
transition), takes it, and lets each part show it: the controls (:meth:`Controls.show`), the
canvas (:class:`~.painter.Painter`), the browser's runtime (:class:`~.browser_player.BrowserPlayer`,
its clock :class:`~.playing.Playing`), the page's words (:class:`~.page_words.PageWords`: the
caption band and the live region) and the lesson (:class:`~.lesson_steps.LessonSteps`). What a key
does is :func:`~.key_actions.key_actions`. Every value a client sends is checked first
(:mod:`.controls`); the physics is all in :mod:`rigidrel_core`.
"""

from __future__ import annotations

import threading
import time
from collections.abc import Callable

import viser

from ..view.scene_view import PLOT_HZ, Drawn
from ..view.state import Resolved, Settings
from ..view.state import frame_choice as frame_choice_of
from ..view.state import resolve as resolve_settings
from .browser_player import BrowserPlayer
from .canvas_report import add_canvas_report, follow_canvas_size
from .controls import build_controls, notice_place
from .cover import say_page_drawn
from .gestures import Gestures
from .key_actions import key_actions
from .keys import Action
from .lesson_part import GivenLesson, LessonPart, NoLesson
from .lesson_steps import LessonSteps
from .opening import Opening
from .page_words import PageWords
from .painter import Painter
from .painting import PaintingCache
from .playback import Playback
from .playing import Playing
from .requests import Requests
from .tab_state import TabState


class Session:
    """One client's tab, opened as ``opening`` says (:class:`~.opening.Opening`)."""

    def __init__(self, client: viser.ClientHandle, opening: Opening | None = None) -> None:
        opening = opening or Opening()
        self.client = client
        self.lock = threading.RLock()
        self.closed = False
        self.messages_handled = 0
        """Values a client sent that the session checked and acted on or refused (in any order)."""
        self.lesson: LessonPart = NoLesson()
        if opening.lesson is not None:
            hooks = opening.hooks
            self.lesson = GivenLesson(
                opening.lesson,
                lambda index: None if hooks is None else hooks.step_changed(self, index),
                lambda: None if hooks is None else hooks.lead(self),
                lambda token: hooks is not None and hooks.lecturer(self, token),
            )
        self.words = PageWords(client)
        self.steps = LessonSteps(self)
        self.playing = Playing(self)
        self.asks = Requests(self)
        """What the controls and keys ask (:mod:`.requests`)."""
        self._keys = key_actions(self, self.asks, self.steps)
        self.gestures = Gestures(self, self.asks)
        self._last_clock = 0.0
        self.state, resolved, notice = opening.state()
        with client.atomic():
            # the panel's look for the shade came with the server's own (the app's theme for new tabs)
            self.controls = build_controls(
                client.gui, self.state.settings, opening.lesson, opening.follow, self.words.key, opening.shade
            )
            self.canvas_report = add_canvas_report(client.gui)
            self.player = BrowserPlayer(client, opening.timelines)
            self.painter = Painter(
                client, opening.paintings or PaintingCache(capacity=2), self.player, opening.still_image
            )
            self.controls.wire(self.asks)
            self.resize = follow_canvas_size(self, self.canvas_report)
            """Lay the page out for the canvas at a new size (CSS px)."""
            if opening.timelines is not None:  # the browser plays: its runtime, reporting to these
                self.playing.connect(self.gestures)
            index = self.lesson.step(opening.first_step)
            if index is not None:
                self.steps.arrive(index)
            else:
                self.apply(resolved, refit=True)
                self.show(self.state.refused(notice))
                if opening.start_time is not None and not notice:
                    self.set_playback(self.state.playback.seek(opening.start_time))
                    self.draw_now(force_plots=True)
            if opening.timelines is None:  # the page is whole (else once its runtime draws, :class:`Playing`)
                say_page_drawn(client)

    # ------------------------------------------------------------------ showing a state
    def show(self, state: TabState, drawn: Drawn | None = None, put_back: bool = False) -> None:
        """Take ``state``: the panel shows it (with ``drawn``, the picture just put on screen;
        ``put_back``: the settings' controls too, as :meth:`Controls.show`), and the caption band
        and the page's style follow (sent when they change)."""
        self.state = state
        self.controls.show(state, drawn, self.lesson.lock_reason(state), put_back)
        self.words.caption(self.lesson.caption(state))

    def ask(self, new: Settings, refit: bool | None, shared: bool = False, draw: bool = True) -> None:
        """Try ``new``: draw it if it makes a scene, else keep the last valid one on screen and say
        why (the controls still show what was asked for). ``refit`` None: as "Auto-fit view" says."""
        resolved = resolve_settings(new)
        old = self.state.settings
        with self.client.atomic():
            if isinstance(resolved, str):
                self.show(self.state.asked(new, resolved, notice_place(old, new)))
                return
            self.state = self.state.asked(new)
            self.apply(resolved, self.controls.fit.value if refit is None else refit, shared, draw)

    def apply(self, resolved: Resolved, refit: bool, shared: bool | None = None, draw: bool = True) -> None:
        """Put ``resolved`` on screen: its painting (with ``shared``, a step the leading tab chose,
        the page shared by every tab on a canvas of this size; None: as the picture on screen is),
        the controls that follow it, the instant (unless ``draw`` is False: the caller draws it
        once it has set the clock)."""
        painter, state = self.painter, self.state
        redrawn = painter.drawn is not None and resolved is painter.drawn.resolved and state.shown is not None
        settings = state.shown if redrawn and state.shown is not None else state.settings
        painting = painter.paint(settings, resolved, state)
        painter.show(painting, painter.painting is not None if shared is None else shared)
        self.player.new_state()
        self.show(state.showing(settings, painting.drawn.window), painting.drawn)
        if refit:
            painter.fit_camera()
        if draw:
            self.draw_now(force_plots=True)
        if self.state.playback.playing:
            self.playing.play()
        self.say()

    def say(self, full: bool = False) -> None:
        """The canvas in words to the page's live region (:meth:`PageWords.say`)."""
        self.words.say(self.painter.drawn, self.state, self.lesson, self.frame_choice(), full)

    def draw_now(self, force_plots: bool = False) -> None:
        """The canvas at the clock, in one batch (one instant); the clock's box and the scenario
        line follow at :data:`PLOT_HZ`, or now if ``force_plots``."""
        if self.player.ready and self.player.pausing:
            return  # the runtime's frame where it paused is coming: it is the picture
        with self.client.atomic():
            self.painter.draw(self.state.playback.now)
            wall = time.monotonic()
            if force_plots or not self.state.playback.playing or wall - self._last_clock >= 1.0 / PLOT_HZ:
                self._last_clock = wall
                self.controls.show_clock(self.state)

    # ------------------------------------------------------------------ the clock, keys, values
    def set_playback(self, playback: Playback) -> None:
        """The clock: shown on the play button and followed by the browser's runtime."""
        was = self.state.playback
        self.state = self.state.with_playback(playback)
        self.controls.show_play(playback.playing)
        if self.player.clock_changed(was, playback):
            self.playing.play()

    def perform(self, action: Action) -> None:
        """What a key, the clicker or a button asks (:mod:`.keys`)."""
        with self.lock, self.client.atomic():
            if not self.closed:
                self._keys[action]()

    def frame_choice(self) -> str:
        d = self.painter.drawn
        return frame_choice_of(d.resolved.scene, d.resolved.frame, d.resolved.ride) if d is not None else "lab"

    def checked(self, respond: Callable[[], None], newest: Callable[[], bool] = lambda: True) -> None:
        """Respond to one value a client sent, under the lock, and count it whatever happened; then
        send the answer at once (viser would hold it for the rest of its 1/60 s send window). A
        session the server let go (``closed``) counts the value and does nothing more; so does a
        value that ``newest`` says a newer one of its control overtook while it waited."""
        with self.lock:
            try:
                if not self.closed and newest():
                    with self.client.atomic():
                        respond()
            finally:
                self.messages_handled += 1
        self.client.flush()

    def go_to_step(self, index: int, report: bool = True) -> None:
        self.steps.go_to(index, report)
