"""One browser tab: the wiring between its controls, its state, its canvas and its lesson.

A callback asks the tab's :class:`~.tab_state.TabState` for the state a change leads to (a pure
transition), takes it, and lets each part show it: the controls (:meth:`Controls.show`), the
canvas (:class:`~.painter.Painter`), the browser's runtime (:class:`~.browser_player.BrowserPlayer`)
and the lesson's caption band (:mod:`.lesson_part`). Every value a client sends is checked first
(:mod:`.controls`); the physics is all in :mod:`rigidrel_core`.
"""

from __future__ import annotations

import threading
import time
import uuid
from collections.abc import Callable
from dataclasses import replace
from typing import Protocol

import viser

import rigidrel_core as rr

from ..backends._viser import handle_uuid, run_javascript, scene_owner
from ..lessons import Lesson
from ..view.describe import describe
from ..view.layers import Layer
from ..view.layout import CanvasSize
from ..view.notice import Place
from ..view.scene_view import PLOT_HZ, Drawn
from ..view.state import Resolved, Settings, event_times, preset_menu, preset_step, scene_presets
from ..view.state import frame_choice as frame_choice_of
from ..view.state import resolve as resolve_settings
from ..view.vocabulary import Shade
from .browser_player import BrowserPlayer
from .canvas_report import add_canvas_report, decode
from .controls import build_controls, notice_place, said_message
from .keys import Action
from .lesson_part import BLANK_CAPTION, GivenLesson, LessonPart, NoLesson
from .painter import Painter
from .painting import PaintingCache
from .playback import Playback
from .runtime import RuntimeConfig, add_playback_report, clock_controls, parse_report, runtime_script
from .tab_state import TabState, read_scenario
from .timeline import Timeline, TimelineCache, TimelineKey


class LessonHooks(Protocol):
    """What a tab giving a lesson tells the server (:class:`~rigidrel_app.live.server.App`)."""

    def step_changed(self, session: Session, index: int) -> None:
        """This tab went to step ``index`` (with ``--follow``, the leading tab's step is followed)."""
        ...

    def lead(self, session: Session) -> str | None:
        """This tab asks to lead (key L): None if it leads now (or nothing follows), else why not."""
        ...

    def lecturer(self, session: Session, token: str) -> bool:
        """This tab's address carried the lead ``token``: True if it is the lecturer's (it leads)."""
        ...


class Session:
    """One client's tab; :meth:`tick` is called by the server's animation loop.

    ``lesson``: the tab gives it, opening on ``first_step`` (from 0); ``follow``: ``--follow``
    (the Lesson folder says who leads); ``hooks``: where step changes and key L go; ``shade``: the
    theme the tab opens in; ``start_time``: the time it opens at (a scenario line's ``--t``; not
    with a lesson); ``timelines``: where the browser's playback comes from (None: the server draws
    every frame); ``paintings``: the server's, shared by its tabs (None: the tab's own);
    ``still_image``: the still picture as one image while a slow canvas plays."""

    def __init__(
        self,
        client: viser.ClientHandle,
        settings: Settings | None = None,
        lesson: Lesson | None = None,
        follow: bool = False,
        hooks: LessonHooks | None = None,
        first_step: int = 0,
        shade: Shade = "light",
        start_time: float | None = None,
        timelines: TimelineCache | None = None,
        paintings: PaintingCache | None = None,
        still_image: bool = True,
    ) -> None:
        self.client = client
        self.lock = threading.RLock()
        self.closed = False
        self.messages_handled = 0
        """Values a client sent that the session checked and acted on or refused (in any order)."""
        self.lesson: LessonPart = NoLesson()
        if lesson is not None:
            self.lesson = GivenLesson(
                lesson,
                lambda index: None if hooks is None else hooks.step_changed(self, index),
                lambda: None if hooks is None else hooks.lead(self),
                lambda token: hooks is not None and hooks.lecturer(self, token),
            )
        self.caption_key = f"rigidrel_caption_{uuid.uuid4().hex}"
        """This tab's localStorage key for the caption band and the page's style (:mod:`.controls`)."""
        self._caption_sent = BLANK_CAPTION
        self._said_of: tuple[object, ...] | None = None
        self._said = 0
        self._keys = self._key_actions()
        self._last_clock = 0.0
        asked, notice = settings or Settings(), ""
        resolved = resolve_settings(asked)
        if isinstance(resolved, str):  # a start state given from outside that makes no scene
            notice, asked = resolved, Settings()
            resolved = resolve_settings(asked)
            assert isinstance(resolved, Resolved)
        self.state = TabState.opening(asked, shade)
        with client.atomic():
            # the panel's look for ``shade`` came with the server's own (the app's theme for new tabs)
            self.controls = build_controls(client.gui, self.state.settings, lesson, follow, self.caption_key, shade)
            self.canvas_report = add_canvas_report(client.gui)
            self.player = BrowserPlayer(client, timelines)
            self.painter = Painter(client, paintings or PaintingCache(capacity=2), self.player, still_image)
            self._wire(timelines is not None)
            index = self.lesson.step(first_step)
            if index is not None:
                self._arrive(index)
            else:
                self._apply(resolved, refit=True)
                self._show(self.state.refused(notice))
                if start_time is not None and not notice:
                    self.set_playback(self.state.playback.seek(start_time))
                    self.draw_now(force_plots=True)

    def _wire(self, runtime: bool) -> None:
        self.controls.wire(self)
        client = self.client

        @client.camera.on_update
        def _(camera: viser.CameraHandle) -> None:
            # the docked panel, presenter mode or the window change the canvas' size: lay it out again
            with self.lock:
                if not self.closed and self.painter.drawn is not None:
                    # a step of the client's adaptive resolution is not a new page
                    self._resize(self.painter.canvas_size.reported(camera.image_width, camera.image_height))

        @self.canvas_report.on_update
        def _(event: viser.GuiEvent) -> None:
            size = decode(self.canvas_report.value)
            if event.client is None or size is None:  # not a size any page of ours sends: ignored
                return
            with self.lock:
                if not self.closed:
                    self._resize(CanvasSize.measured_by_page(size.width, size.height, size.resolution))
            client.flush()

        if runtime:  # the browser plays: its runtime, and the hidden control it reports through
            report = add_playback_report(client.gui)
            report.on_update(lambda _: self._runtime_said(report.value))
            clock = clock_controls(self.controls.time.handles)
            run_javascript(client, runtime_script(RuntimeConfig(scene_owner(client), handle_uuid(report), clock)))

    def _resize(self, size: CanvasSize) -> None:
        drawn = self.painter.drawn
        if self.painter.resized(size) and drawn is not None:
            with self.client.atomic():
                self._apply(drawn.resolved, refit=True)

    # ------------------------------------------------------------------ showing a state
    def _show(self, state: TabState, drawn: Drawn | None = None, put_back: bool = False) -> None:
        """Take ``state``: the panel shows it (with ``drawn``, the picture just put on screen;
        ``put_back``: the settings' controls too, as :meth:`Controls.show`), and the caption band
        and the page's style follow (sent when they change)."""
        self.state = state
        self.controls.show(state, drawn, self.lesson.lock_reason(state), put_back)
        caption = self.lesson.caption(state)
        if caption != self._caption_sent:
            self.client.local_storage.set_item(self.caption_key, caption)
            self._caption_sent = caption

    def _ask(self, new: Settings, refit: bool | None, shared: bool = False, draw: bool = True) -> None:
        """Try ``new``: draw it if it makes a scene, else keep the last valid one on screen and say
        why (the controls still show what was asked for). ``refit`` None: as "Auto-fit view" says."""
        resolved = resolve_settings(new)
        old = self.state.settings
        with self.client.atomic():
            if isinstance(resolved, str):
                self._show(self.state.asked(new, resolved, notice_place(old, new)))
                return
            self.state = self.state.asked(new)
            self._apply(resolved, self.controls.fit.value if refit is None else refit, shared, draw)

    def _apply(self, resolved: Resolved, refit: bool, shared: bool | None = None, draw: bool = True) -> None:
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
        self._show(state.showing(settings, painting.drawn.window), painting.drawn)
        if refit:
            painter.fit_camera()
        if draw:
            self.draw_now(force_plots=True)
        if self.state.playback.playing:
            self._play_in_browser()
        self._say()

    def _say(self, full: bool = False) -> None:
        """What the canvas shows, in words, to the page's live region (:mod:`~rigidrel_app.view.describe`):
        its summary when the scene, figure, frame, look or step changed (never every frame), with the
        step's caption; everything at the clock if ``full`` (key D)."""
        drawn, s = self.painter.drawn, self.state
        if drawn is None or s.shown is None:
            return
        key = (s.shown.scene, preset_menu(s.shown).value, self.frame_choice(), s.step)
        if not full and key == self._said_of:
            return
        self._said_of, self._said = key, self._said + 1
        words = describe(drawn.resolved, s.playback.now)
        text = " ".join(filter(None, (self.lesson.said(s), words.full if full else words.summary)))
        self.client.local_storage.set_item(f"{self.caption_key}-said", said_message(text, self._said))

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

    # ------------------------------------------------------------------ what the controls ask
    def change(self, new: Settings, refit: bool | None = None) -> None:
        """Try ``new``; a change of a control the lesson's step fixes is refused (the GUI disables
        those; a client may send anything)."""
        with self.lock:
            changed = self.state.locks_against(new)
            if not changed:
                self._ask(new, refit)
                return
            with self.client.atomic():
                text = self.lesson.lock_notice(self.state, changed)
                self._show(self.state.refused(text, notice_place(self.state.settings, new)), put_back=True)

    def set_parameter(self, parameter: rr.Parameter, value: float) -> None:
        """A parameter control moved; a control of another scene (hidden here) changes nothing."""
        with self.lock:
            if parameter not in self.state.settings.description.parameters:
                self.refuse(f"{parameter.label} is not a control of this scene; nothing changed.")
                return
            self.change(self.state.settings.with_value(parameter.name, value))

    def choose_preset(self, label: str) -> None:
        """Show a paper figure of this scene (the menu's "—" changes nothing)."""
        chosen = scene_presets(self.state.settings.scene).get(label)
        if chosen is not None:
            self.change(chosen, refit=True)

    def seek(self, now: float) -> None:
        with self.lock:
            if "time" in self.state.locked:
                self.refuse(self.lesson.lock_notice(self.state, ("time",)), "playback")
                self.controls.show_clock(self.state)
                return
            self.set_playback(self.state.playback.seek(now))
            self.draw_now(force_plots=True)

    def toggle_play(self) -> None:
        with self.lock:
            self.set_playback(self.state.playback.toggled())

    def set_playback(self, playback: Playback) -> None:
        """The clock: shown on the play button and followed by the browser's runtime."""
        was = self.state.playback
        self.state = self.state.with_playback(playback)
        self.controls.show_play(playback.playing)
        if self.player.clock_changed(was, playback):
            self._play_in_browser()

    def perform(self, action: Action) -> None:
        """What a key, the clicker or a button asks (:mod:`.keys`)."""
        with self.lock, self.client.atomic():
            if not self.closed:
                self._keys[action]()

    def _key_actions(self) -> dict[Action, Callable[[], None]]:
        s = lambda: self.state  # noqa: E731  (the state when the key is pressed)

        def step(by: int) -> None:  # past either end of the lesson nothing happens
            index = self.lesson.step(s().step + by)
            if index is not None and index != s().step:
                self.go_to_step(index)

        def toggle_play() -> None:
            self.toggle_play()
            if not s().playback.playing:  # paused: the diagrams and readouts catch up with the rods
                self.draw_now(force_plots=True)

        def frames(by: int) -> None:
            self.set_playback(s().playback.stepped(by))
            self.draw_now(force_plots=True)

        def event(by: int) -> None:
            drawn = self.painter.drawn
            if drawn is not None:
                self.set_playback(s().playback.to_event(event_times(drawn.resolved), by))
                self.draw_now(force_plots=True)

        def figure(by: int) -> None:
            if (chosen := preset_step(s().settings, by)) is not None:
                self.change(chosen, refit=True)

        return {
            Action.TOGGLE_PLAY: toggle_play,
            Action.STEP_BACK: lambda: frames(-1),
            Action.STEP_FORWARD: lambda: frames(1),
            Action.PREVIOUS_EVENT: lambda: event(-1),
            Action.NEXT_EVENT: lambda: event(1),
            Action.PREVIOUS_FIGURE: lambda: figure(-1),
            Action.NEXT_FIGURE: lambda: figure(1),
            Action.RESET_VIEW: lambda: self.painter.fit_camera(force=True),
            Action.TOGGLE_PRESENTER: lambda: self.set_presenter(not s().presenter),
            Action.TOGGLE_THEME: lambda: self.set_shade("light" if s().shade == "dark" else "dark"),
            Action.PREVIOUS_STEP: lambda: step(-1),
            Action.NEXT_STEP: lambda: step(1),
            Action.TOGGLE_CAPTION: lambda: self._show(s().with_caption(not s().caption_shown)),
            Action.LEAD: self._lead,
            Action.DESCRIBE: lambda: self._say(full=True),
        }

    def set_presenter(self, on: bool) -> None:
        """Presenter mode: the panel minimized, the projector theme on the canvas (the canvas' new
        size arrives from the browser and lays the page out again); off: both back."""
        self._relook(self.state.with_presenter(on), refit=True)

    def set_shade(self, shade: Shade) -> None:
        """The dark projector theme (light ink on black, the panel dark) or the light one; the page
        is drawn again as it is (the camera stays)."""
        if shade != self.state.shade:
            self._relook(self.state.with_shade(shade), refit=False)

    def _relook(self, state: TabState, refit: bool) -> None:
        with self.lock, self.client.atomic():
            self._show(state)
            if self.painter.drawn is not None:
                self._apply(self.painter.drawn.resolved, refit=refit)

    def load_scenario(self, text: str) -> None:
        """Show the state a scenario string names (:func:`read_scenario`), or say why it names none."""
        with self.lock:
            scenario = read_scenario(text)
            if isinstance(scenario, str):
                self.refuse(scenario, "scenario")
            elif changed := self.state.locks_against(scenario.settings, scenario.t is not None):
                self.refuse(self.lesson.lock_notice(self.state, changed), "scenario")
            else:
                self._ask(scenario.settings, refit=True)
                if scenario.t is not None and not self.state.notice:
                    self.set_playback(self.state.playback.seek(scenario.t))
                    self.draw_now(force_plots=True)

    def set_layer(self, layer: Layer, on: bool) -> None:
        """A layer toggle: the settings' layers with ``layer`` added (``on``) or removed."""
        with self.lock:
            layers = self.state.settings.layers
            self.change(self.state.settings.with_layers(layers | {layer} if on else layers - {layer}), refit=False)

    def refuse(self, text: str, place: Place = "scene") -> None:
        with self.lock:
            self._show(self.state.refused(text, place))

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

    # ------------------------------------------------------------------ a lesson
    def go_to_step(self, index: int, report: bool = True) -> None:
        """Show the lesson's step ``index`` (kept inside the lesson); ``report``: tell the server
        (a tab's own moves are reported, the leading tab's steps passed on by the server are not)."""
        with self.lock:
            step = self.lesson.step(index)
            if step is None or self.closed:
                return
            moved = step != self.state.step
            with self.client.atomic():
                self._arrive(step, shared=not report)
        if moved and report:
            self.lesson.changed_step(step)

    def _arrive(self, index: int, shared: bool = False) -> None:
        """Arrive at step ``index``: its settings, window, start, autoplay, locks and caption
        (``shared``: a step the leading tab chose, drawn as a page shared by the tabs that follow)."""
        a = self.lesson.arrival(index)
        self.state = self.state.arriving(index, a)
        self._ask(a.settings, refit=True, shared=shared, draw=False)
        self.set_playback(self.state.step_start(a))
        self._show(self.state)
        self.draw_now(force_plots=True)

    def preview_step(self, index: int) -> None:
        """The picture of step ``index`` that the leading tab chose, before anything else of it: the
        page and first instant shared by every tab on a canvas of this size, and the caption (the
        rest follows with :meth:`go_to_step`). Only with a runtime ready."""
        with self.lock:
            step = self.lesson.step(index)
            if step is None or self.closed or not self.player.ready:
                return
            a = self.lesson.arrival(step)
            painting = self.painter.paint_settings(a.settings, self.state)
            if painting is None:
                return  # a step that makes no scene: go_to_step says so
            clock = self.state.playback.with_window(a.window or painting.drawn.window)
            now = (clock.seek(a.start) if a.start is not None else Playback.start(clock.window)).now
            with self.client.atomic():
                self.painter.preview(painting, now)
                self._caption_sent = self.lesson.caption(self.state, step)
                self.client.local_storage.set_item(self.caption_key, self._caption_sent)
        self.client.flush()

    def _lead(self) -> None:
        """Key L or the Lead button: the lecturer's tab leads; any other is told why not."""
        refusal = self.lesson.lead()
        if refusal is not None:
            self.refuse(refusal, "lesson")

    def show_leader(self, leads: bool | None) -> None:
        """Who leads, in the Lesson folder (``None``: no tab leads)."""
        with self.lock:
            if not self.closed:
                self.controls.show_leader(leads, self.state.lecturer)

    # ------------------------------------------------------------------ playback in the browser
    @property
    def playback_settled(self) -> bool:
        """Paused with the picture and the clock agreeing (no pause on its way back from the browser)."""
        return not self.state.playback.playing and not self.player.pausing

    def _runtime_said(self, text: str) -> None:
        """A report of the tab's runtime (:class:`~rigidrel_app.live.runtime.Report`), answered at once."""
        report = parse_report(text)
        with self.lock:
            if report is None or self.closed:
                return
            with self.client.atomic():
                if report.event == "ready" and report.lead is not None and self.lesson.claim(report.lead):
                    self._show(self.state.as_lecturer())
                if report.event == "ready" and report.still and not self.state.still:
                    self.state = replace(self.state, still=True)  # reduced motion: an autoplaying step pauses
                    if self.state.playback.playing:
                        self.set_playback(replace(self.state.playback, playing=False))
                if report.event == "ready" and not self.player.ready:
                    self.painter.runtime_ready()
                    self.draw_now(force_plots=True)
                    if self.state.playback.playing:
                        self._play_in_browser()
                elif report.event != "ready" and (now := self.player.stopped_at(report)) is not None:
                    self.set_playback(replace(self.state.playback, now=now, playing=False))
                    self.draw_now(force_plots=True)  # its frame is on screen: only the time controls follow
        self.client.flush()

    def _play_in_browser(self) -> None:
        drawn, layout, shown = self.painter.drawn, self.painter.layout, self.state.shown
        key = None if shown is None or layout is None else TimelineKey(shown, layout, self.state.playback.window)
        self.player.play(key, None if drawn is None else drawn.resolved, self.state.playback, self._timeline_made)

    def _timeline_made(self, timeline: Timeline) -> None:
        """On the timelines' thread: a timeline this tab asked for is made."""
        with self.lock:
            if self.closed or not self.player.is_wanted(timeline):
                return
            with self.client.atomic():
                self.player.start(timeline, self.state.playback)
        self.client.flush()

    def tick(self, dt: float) -> None:
        """Advance playback by ``dt`` wall seconds (called by the animation loop): while the browser
        plays, the server's clock follows it and nothing is drawn; else the server draws."""
        with self.lock:
            if self.closed or not self.state.playback.playing:
                return
            if not self.player.ready:
                self.set_playback(self.state.playback.advance(dt))
                self.draw_now(force_plots=not self.state.playback.playing)  # stopped at the end: the box shows it
            elif self.player.playing:
                self.set_playback(self.state.playback.advance(dt))
            self.painter.tick_still_image(self._send_still_image)

    def _send_still_image(self, show: Callable[[], None]) -> None:
        """From the still image's thread: ``show`` it, under the lock and in one batch."""
        with self.lock:
            if self.closed:
                return
            with self.client.atomic():
                show()
        self.client.flush()
