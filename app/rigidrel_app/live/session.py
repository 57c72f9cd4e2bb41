"""One browser tab: the wiring between its controls, its settings, its playback clock and its drawings.

Callbacks only replace a field of a :class:`Settings` or a :class:`Playback` and assign
what pure builders made (:func:`build_drawing`, :func:`lane_states`); the physics is all
in :mod:`rigidrel_core`. Every value a client sends is checked first (:mod:`.controls`).
"""

from __future__ import annotations

import threading
import time
import uuid
from collections.abc import Callable
from dataclasses import replace
from typing import Protocol, overload

import numpy as np
import viser

import rigidrel_core as rr

from ..backends._viser import PlaybackMessage, handle_uuid, queue_to_client, run_javascript, scene_owner
from ..backends.viser import PageRenderer
from ..lessons import Lesson
from ..lessons.tour import arrival, caption_html, clamp_step, lock_notice, lock_reason, locked_changes
from ..view import camera as cam
from ..view.canvas import ChartFrame, moving_picture
from ..view.lanes import LanePicture
from ..view.layers import Layer
from ..view.layout import (
    LEGEND_ROWS,
    NORMAL,
    PRESENTER,
    CanvasLayout,
    CanvasSize,
    canvas_layout,
)
from ..view.scenario import ScenarioError, format_scenario, parse_scenario
from ..view.scene_view import PLOT_HZ, Drawn, nice_step
from ..view.scene_view import readout_markdown as readout
from ..view.state import (
    Resolved,
    Settings,
    beta_problem,
    cone_events,
    frame_choice,
    frame_choices,
    preset_step,
    scene_presets,
)
from ..view.state import resolve as resolve_settings
from ..view.vocabulary import Shade, markdown_literal, shaded
from .canvas_report import add_canvas_report, decode
from .controls import (
    NO_CONE,
    Place,
    build_controls,
    caption_message,
    configure_panel,
    notice_place,
    time_entry,
)
from .keys import Action
from .painting import Painting, PaintingCache, PaintingKey
from .playback import Playback
from .runtime import Report, RuntimeConfig, add_playback_report, clock_controls, parse_report, runtime_script
from .still_image import StillImage
from .timeline import FRAMES_PER_BLOCK, Mirror, Timeline, TimelineCache, TimelineKey
from .timeline import timeline_id as timeline_id_of

#: A notice is dark red (and starts with ⚠ and is bold, for those who do not see the red).
NOTICE_COLOR = "#B00020"


class LessonHooks(Protocol):
    """What a tab giving a lesson tells the server (:class:`~rigidrel_app.live.server.App`)."""

    def step_changed(self, session: Session, index: int) -> None:
        """This tab went to step ``index`` (with ``--follow``, the leading tab's step is followed)."""
        ...

    def lead(self, session: Session) -> None:
        """This tab asks to lead (key L)."""
        ...


#: What the scenario box also accepts in front of a scenario string (copied from a command line).
SERVE_PREFIXES = ("rigidrel serve ", "serve ")


def scenario_problem(exc: ScenarioError) -> str:
    """A scenario string's mistake, led by the flag at fault (``--v1: v1 must be ... in (-1, 1); got 1.6``)."""
    text, flag = str(exc), f"--{exc.parameter}"
    return text if exc.parameter == "scene" or text.startswith(flag) else f"{flag}: {text}"


#: Timelines a tab's runtime keeps (the oldest is forgotten past these).
RUNTIME_TIMELINES = 4


class Session:
    """State and controls of one client; :meth:`tick` is called by the server's animation loop."""

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
        """``lesson``: the tab gives it, opening on ``first_step`` (from 0); ``follow``: ``--follow``
        (the Lesson folder says who leads); ``hooks``: where step changes and key L are reported;
        ``shade``: the theme the tab opens in (key T changes it); ``start_time``: the time the tab
        opens at, in the settings' frame (a scenario line's ``--t``; not with a lesson); ``timelines``:
        where the tab's browser gets its playback from (None: the server draws every frame);
        ``paintings``: the server's paintings, shared by its tabs (None: the tab's own);
        ``still_image``: the still picture as one image while a slow canvas plays (:mod:`.still_image`)."""
        self.client = client
        self.shade: Shade = shade
        """The tab's theme: light, or the dark projector theme (key T)."""
        self.lesson = lesson
        self.hooks = hooks
        self.step_index = 0
        """The lesson's step this tab shows (from 0)."""
        self.locked: frozenset[str] = frozenset()
        """The controls the current step fixes."""
        self.step_window: tuple[str, tuple[float, float]] | None = None
        """The current step's scene and time window: the playback window while that scene shows."""
        self.caption_shown = True
        """The caption band over the lanes (key C hides it)."""
        self.caption_key = f"rigidrel_caption_{uuid.uuid4().hex}"
        """This tab's localStorage key for the caption band (see :mod:`.controls`)."""
        self.caption_off_step = False
        """The caption band says the tab shows another scene than its step's."""
        self.shown_settings: Settings | None = None
        """The settings of what is on screen (the scenario box shows them)."""
        self._scenario_of: tuple[Settings, float | None] | None = None
        """What the scenario line on screen names (settings, and the time while paused)."""
        self.lock = threading.RLock()
        self.settings = settings or Settings()
        self.notice = ""
        """The notice on screen ("" for none): why the last value was refused."""
        self._notice_place: Place = "scene"
        self.closed = False
        self.messages_handled = 0
        """Control values a client sent that the session has checked and acted on or refused (in any order)."""
        self.drawn: Drawn | None = None
        self.presenter = False
        """Presenter mode (key F): the control panel minimized, the projector theme."""
        self.legend_rows = LEGEND_ROWS
        """The legend's rows in the page last laid out (the first guess for the next drawing's)."""
        self.one_line_titles = True
        """Whether this scene's lane titles may go on one line on a short canvas (False once they
        were found too long for it; tried again for another scene)."""
        self.layout: CanvasLayout | None = None
        camera = client.camera
        self.canvas_size = CanvasSize(float(camera.image_width), float(camera.image_height))
        """The canvas in CSS px, which the page is laid out in (its camera reports rendered pixels)."""
        self.chart_frames: tuple[ChartFrame, ...] = ()
        """Each diagram's data -> page px (the plot areas of this layout)."""
        self.renderer_lanes: list[LanePicture] = []
        """The lanes as last drawn."""
        self._last_plot = 0.0
        self.timelines = timelines
        self.paintings = paintings or PaintingCache(capacity=2)
        self._sent_page: str | None = None
        """The painting whose page the runtime shows (its id), if any."""
        self._sent_frame: tuple[str, float] | None = None
        """The painting's frame the runtime shows (its id and time), if it shows one."""
        self.painting: Painting | None = None
        """The painting whose shared page (and frames) the tab's runtime shows, if any (a step the
        leading tab chose); None while the tab draws its own picture."""
        self.runtime_ready = False
        """The tab's playback runtime said it is ready: it draws the moving parts (:mod:`.timeline`)."""
        self.mirror: Mirror | None = None
        """What the runtime shows of the server's own frames (once it is ready)."""
        self._runtime_nodeset: str | None = None
        """The node set the runtime draws on, as far as the server told it."""
        self.timeline: Timeline | None = None
        """The timeline of the state on screen, once made and sent."""
        self._timeline_wanted: TimelineKey | None = None
        self._timelines_sent: list[str] = []
        """Timelines the runtime holds (the newest last)."""
        self.runtime_playing = False
        """The runtime plays :attr:`timeline` (the server's clock only follows it)."""
        self._pausing = False
        """A pause was sent to the runtime and its frame has not come back yet."""
        self.still_image = StillImage(still_image)
        """The still picture as one image while a slow canvas plays (:mod:`.still_image`)."""
        resolved = resolve_settings(self.settings)
        if isinstance(resolved, str):  # a start state given from outside that makes no scene
            self.notice, self.settings = resolved, Settings()
            resolved = resolve_settings(self.settings)
            assert isinstance(resolved, Resolved)
        with client.atomic():
            # the panel's look for ``shade`` came with the server's own (the app's theme for new tabs)
            self.controls = build_controls(client.gui, self.settings, lesson, follow, self.caption_key, shade)
            self.canvas_report = add_canvas_report(client.gui)
            self.renderer = PageRenderer(client.scene)
            self.playback = Playback.start((-1.0, 1.0))
            self._wire()
            if timelines is not None:
                self.playback_report = add_playback_report(client.gui)
                self.playback_report.on_update(lambda _: self._runtime_said(self.playback_report.value))
                config = RuntimeConfig(
                    scene_owner(client), handle_uuid(self.playback_report), clock_controls(self.controls.time.handles)
                )
                run_javascript(client, runtime_script(config))
            if lesson is not None:
                self._arrive(clamp_step(lesson, first_step))
            else:
                self._apply(resolved, refit=True)
                self._set_notice(self.notice, "scene")
                if start_time is not None and not self.notice:
                    self.set_playback(self.playback.seek(start_time))
                if shade != "light":
                    self._send_page()

    # ------------------------------------------------------------------ wiring
    def _wire(self) -> None:
        self.controls.wire(self)

        @self.client.camera.on_update
        def _(camera: viser.CameraHandle) -> None:
            # the docked panel, presenter mode or the window change the canvas' size: lay it out again
            with self.lock:
                if self.closed or self.drawn is None or self.layout is None:
                    return
                # a step of the client's adaptive resolution is not a new page
                self._resize(self.canvas_size.reported(camera.image_width, camera.image_height))

        @self.canvas_report.on_update
        def _(event: viser.GuiEvent) -> None:
            size = decode(self.canvas_report.value)
            if event.client is None or size is None:  # not a size any page of ours sends: ignored
                return
            with self.lock:
                if not self.closed:
                    self._resize(CanvasSize.measured_by_page(size.width, size.height, size.resolution))
            self.client.flush()

    def _resize(self, size: CanvasSize) -> None:
        """Take the canvas' new size (CSS px); lay the page out again if it changed. The same size
        at a lower resolution is the browser finding its frames slow (:mod:`.still_image`)."""
        resized = (size.width, size.height) != (self.canvas_size.width, self.canvas_size.height)
        if not resized and size.resolution < self.canvas_size.resolution - 1e-3:
            self.still_image.canvas_slowed()
        self.canvas_size = size
        if resized and self.drawn is not None and self.layout is not None:
            with self.client.atomic():
                self._apply(self.drawn.resolved, refit=True)

    def _canvas_layout(self, legend_rows: int = LEGEND_ROWS, one_line_titles: bool = True) -> CanvasLayout:
        """The page for this tab's canvas size and mode."""
        theme = replace(PRESENTER if self.presenter else NORMAL, shade=self.shade)
        return canvas_layout(self.canvas_size.width, self.canvas_size.height, theme, legend_rows, one_line_titles)

    # ------------------------------------------------------------------ state
    def change(self, new: Settings, refit: bool | None = None) -> None:
        """Try ``new``: draw it if it makes a scene, else keep the last valid one on screen and explain
        (the controls still show what was asked for, the paper-figure menu included). The camera
        refits if ``refit``, or, when that is None, if "Auto-fit view" is on. A change of a control
        the lesson's step fixes is refused (the GUI disables those; a client may send anything)."""
        with self.lock:
            changed = locked_changes(self.locked, self.settings, new)
            if changed and self.lesson is not None:
                with self.client.atomic():
                    text = lock_notice(self.lesson, self.step_index, self.settings, changed)
                    self._set_notice(text, notice_place(self.settings, new))
                    self.controls.show_settings(self.settings)
                return
            self._show(new, refit)

    def _show(self, new: Settings, refit: bool | None, shared: bool = False, draw: bool = True) -> None:
        """``shared``, ``draw``: as :meth:`_apply`."""
        with self.lock:
            resolved = resolve_settings(new)
            old, self.settings = self.settings, new
            with self.client.atomic():
                if isinstance(resolved, str):
                    self._set_notice(resolved, notice_place(old, new))
                    self.controls.show_settings(new)
                    return
                self._set_notice("")
                self._apply(resolved, self.controls.fit.value if refit is None else refit, shared, draw)

    def set_parameter(self, parameter: rr.Parameter, value: float) -> None:
        """A parameter control moved; a control of another scene (hidden here) changes nothing."""
        with self.lock:
            if parameter not in self.settings.description.parameters:
                self._set_notice(f"{parameter.label} is not a control of this scene; nothing changed.", "scene")
                return
            self.change(self.settings.with_value(parameter.name, value))

    def choose_preset(self, label: str) -> None:
        """Show a paper figure of this scene (the menu's "—" changes nothing)."""
        chosen = scene_presets(self.settings.scene).get(label)
        if chosen is not None:
            self.change(chosen, refit=True)

    def seek(self, now: float) -> None:
        with self.lock:
            if "time" in self.locked and self.lesson is not None:
                self._set_notice(lock_notice(self.lesson, self.step_index, self.settings, ("time",)), "playback")
                self.controls.time.show(round(self.playback.now, 6))
                return
            self.set_playback(self.playback.seek(now))
            self.draw_now(force_plots=True)

    def toggle_play(self) -> None:
        with self.lock:
            self.set_playback(self.playback.toggled())

    def perform(self, action: Action) -> None:
        """What a key, the clicker or a button asks (:mod:`.keys`); each assigns what a pure function made."""
        with self.lock, self.client.atomic():
            if self.closed:
                return
            if action is Action.TOGGLE_PLAY:
                self.toggle_play()
                if not self.playback.playing:  # paused: the diagrams and readouts catch up with the rods
                    self.draw_now(force_plots=True)
            elif action in (Action.STEP_BACK, Action.STEP_FORWARD):
                self.set_playback(self.playback.stepped(-1 if action is Action.STEP_BACK else 1))
                self.draw_now(force_plots=True)
            elif action in (Action.PREVIOUS_FIGURE, Action.NEXT_FIGURE):
                figure = preset_step(self.settings, -1 if action is Action.PREVIOUS_FIGURE else 1)
                if figure is not None:
                    self.change(figure, refit=True)
            elif action is Action.RESET_VIEW:
                self.fit_camera(force=True)
            elif action is Action.TOGGLE_PRESENTER:
                self.set_presenter(not self.presenter)
            elif action is Action.TOGGLE_THEME:
                self.set_shade("light" if self.shade == "dark" else "dark")
            elif action in (Action.PREVIOUS_STEP, Action.NEXT_STEP):
                if self.lesson is not None:  # past either end nothing happens (the step is not reset)
                    index = clamp_step(self.lesson, self.step_index + (-1 if action is Action.PREVIOUS_STEP else 1))
                    if index != self.step_index:
                        self.go_to_step(index)
            elif action is Action.TOGGLE_CAPTION:
                self.caption_shown = not self.caption_shown
                self._send_page()
            elif action is Action.LEAD:
                if self.hooks is not None:
                    self.hooks.lead(self)
            else:  # a new Action must be handled here
                raise AssertionError(action)

    def set_presenter(self, on: bool) -> None:
        """Presenter mode: the control panel minimized and the canvas in the projector theme (larger
        text, thicker lines); off: the panel back and the normal theme. The canvas' new size
        arrives from the browser and lays the page out again."""
        with self.lock, self.client.atomic():
            self.presenter = on
            panel = self.client.gui.main_panel
            if on:
                panel.minimize()
            else:
                panel.expand()
            if self.drawn is not None:
                self._apply(self.drawn.resolved, refit=True)
            self._send_page()

    def set_shade(self, shade: Shade) -> None:
        """The tab's theme: the dark projector theme (light ink on black: the canvas inverted by the
        page's style, every colour sent for it, the panel in viser's dark mode) or the light one.
        The page is drawn again as it is (the camera stays)."""
        with self.lock, self.client.atomic():
            if shade == self.shade:
                return
            self.shade = shade
            if self.controls.dark.value != (shade == "dark"):
                self.controls.dark.value = shade == "dark"
            configure_panel(self.client.gui, shade)
            self._set_notice(self.notice, self._notice_place)
            if self.drawn is not None:
                self._apply(self.drawn.resolved, refit=False)
            self._send_page()

    # ------------------------------------------------------------------ a lesson
    def go_to_step(self, index: int, report: bool = True) -> None:
        """Show the lesson's step ``index`` (from 0; kept inside the lesson) as it asks; ``report``:
        tell the server (a followed tab's own moves are reported, the server's are not)."""
        if self.lesson is None:
            return
        with self.lock:
            if self.closed:
                return
            index = clamp_step(self.lesson, index)
            moved = index != self.step_index
            with self.client.atomic():
                self._arrive(index, shared=not report)
        if moved and report and self.hooks is not None:
            self.hooks.step_changed(self, index)

    def _arrive(self, index: int, shared: bool = False) -> None:
        """Arrive at step ``index``: its settings, window, start, autoplay, locks and caption
        (``shared``: a step the leading tab chose, drawn as a page shared by the tabs that follow)."""
        assert self.lesson is not None
        step = self.lesson.steps[index]
        a = arrival(step)
        self.step_index, self.locked = index, a.locked
        self.step_window = (a.settings.scene, a.window) if a.window is not None else None
        self._show(a.settings, refit=True, shared=shared, draw=False)
        playback = self.playback
        if a.start is not None:
            playback = playback.seek(a.start)
        else:
            playback = replace(playback, now=Playback.start(playback.window).now)
        self.set_playback(replace(playback, playing=a.autoplay))
        self.draw_now(force_plots=True)
        c = self.controls
        c.lock(a.settings, a.locked)
        reason = lock_reason(self.lesson, index, a.settings)
        if c.locks is not None:
            if c.locks.content != reason:
                c.locks.content = reason
            if c.locks.visible != bool(reason):
                c.locks.visible = bool(reason)
        if c.lesson is not None:
            c.lesson.show_step(index)
        self._send_page()

    def preview_step(self, index: int) -> None:
        """The picture of step ``index`` that the leading tab chose, before anything else of it: the
        page and first instant shared by every tab on a canvas of this size, and the caption (the
        rest follows with :meth:`go_to_step`). Only with a runtime ready; else nothing."""
        with self.lock:
            if self.lesson is None or self.closed or not self.runtime_ready:
                return
            index = clamp_step(self.lesson, index)
            a = arrival(self.lesson.steps[index])
            painting = self._painting(a.settings, None)
            if painting is None:
                return  # a step that makes no scene: go_to_step says so
            window = a.window if a.window is not None else painting.drawn.window
            playback = self.playback.with_window(window)
            now = playback.seek(a.start).now if a.start is not None else Playback.start(playback.window).now
            with self.client.atomic():
                self._lend_page(painting)
                if self._sent_frame != (painting.id, now):
                    self._to_runtime("frame", payload=painting.frame(now))
                    self._sent_frame = (painting.id, now)
                    self._runtime_nodeset = painting.id
                step = self.lesson.steps[index]
                band = caption_html(step, self.presenter, False)
                self.client.local_storage.set_item(
                    self.caption_key, caption_message(band, self.caption_shown, self.shade)
                )
        self.client.flush()

    def _lend_page(self, painting: Painting) -> None:
        """Show ``painting``'s shared page (sent once) instead of the tab's own still picture."""
        self.renderer.lend_still(painting.layout)
        if self._sent_page != painting.id:
            self._to_runtime("page", painting.id, 1.0, payload=painting.page())
            self._sent_page = painting.id

    def show_leader(self, leads: bool | None) -> None:
        """The Lesson folder's line on who leads (``None``: no tab leads)."""
        with self.lock:
            if self.closed or self.controls.lesson is None:
                return
            if leads:
                text = "**This tab leads**: the other tabs follow its step."
            elif leads is None:
                text = "No tab leads: press L (or the button) to lead."
            else:
                text = "Following the leading tab's step (L here to lead instead)."
            if self.controls.lesson.status.content != text:
                self.controls.lesson.status.content = text

    def _send_page(self) -> None:
        """The caption band over the lanes and the page's style (the theme), through the tab's
        localStorage (the panel may be folded away)."""
        if self.lesson is None:
            self.client.local_storage.set_item(self.caption_key, caption_message("", False, self.shade))
            return
        step = self.lesson.steps[self.step_index]
        self.caption_off_step = self.settings.scene != step.scenario.settings.scene
        band = caption_html(step, self.presenter, self.caption_off_step)
        self.client.local_storage.set_item(self.caption_key, caption_message(band, self.caption_shown, self.shade))

    # ------------------------------------------------------------------ scenario box and layers
    def load_scenario(self, text: str) -> None:
        """Show the state a scenario string names (the same syntax as ``rigidrel serve SCENE ...``);
        a string that names none is refused with a notice naming the flag and what it allows."""
        with self.lock:
            line = text.strip()
            for prefix in SERVE_PREFIXES:
                if line.startswith(prefix):
                    line = line[len(prefix) :]
            try:
                scenario = parse_scenario(line)
            except ScenarioError as exc:
                self._set_notice(f"Scenario refused: {scenario_problem(exc)}", "scenario")
                return
            s = scenario.settings
            if (problem := beta_problem(s)) is not None:
                self._set_notice(f"Scenario refused: {problem}", "scenario")
                return
            changed = locked_changes(self.locked, self.settings, s)
            if scenario.t is not None and "time" in self.locked:
                changed += ("time",)
            if changed and self.lesson is not None:
                self._set_notice(lock_notice(self.lesson, self.step_index, self.settings, changed), "scenario")
                return
            self._show(s, refit=True)
            if scenario.t is not None and not self.notice:
                self.set_playback(self.playback.seek(scenario.t))
                self.draw_now(force_plots=True)

    def set_layer(self, layer: Layer, on: bool) -> None:
        """A layer toggle: the settings' layers with ``layer`` added (``on``) or removed."""
        with self.lock:
            layers = self.settings.layers | {layer} if on else self.settings.layers - {layer}
            self.change(self.settings.with_layers(frozenset(layers)), refit=False)

    def checked(self, respond: Callable[[], None], newest: Callable[[], bool] = lambda: True) -> None:
        """Respond to one value a client sent, under the lock, and count it whatever happened; then
        send the answer at once (viser would hold it for the rest of its 1/60 s send window).

        A session the server has let go (``closed``: the tab left, or was dropped for flooding)
        counts the value and does nothing more; so does a value that ``newest`` says a newer one of
        its control has overtaken while it waited for the lock."""
        with self.lock:
            try:
                if not self.closed and newest():
                    with self.client.atomic():
                        respond()
            finally:
                self.messages_handled += 1
        self.client.flush()

    def set_playback(self, playback: Playback) -> None:
        was = self.playback
        self.playback = playback
        if playback.playing != was.playing:
            self.controls.play.label = "Pause" if playback.playing else "Play"
            self.controls.play.icon = viser.Icon.PLAYER_PAUSE if playback.playing else viser.Icon.PLAYER_PLAY
        if not self.runtime_ready:
            return
        if self.runtime_playing and (playback.speed, playback.loop) != (was.speed, was.loop):
            self._to_runtime("speed", value=playback.speed)
            self._to_runtime("loop", value=float(playback.loop))
        if playback.playing and not was.playing:
            self._play_in_browser()
        elif was.playing and not playback.playing and self.runtime_playing:
            # stopped by a key or a button, or the clock's estimate reached the end: either way the
            # browser's frame where it stops (it ends by itself) comes back and sets the clock
            self.runtime_playing, self._pausing = False, True
            if playback.now != was.window[1] or playback.loop:
                self._to_runtime("pause", self.timeline.id if self.timeline is not None else "")

    def refuse(self, text: str, place: Place = "scene") -> None:
        with self.lock:
            self._set_notice(text, place)

    def _set_notice(self, text: str, place: Place = "scene") -> None:
        """Show ``text`` as the one notice, in the folder ``place`` (it replaces any older one, wherever
        that was); "" clears it."""
        self.notice, self._notice_place = text, place
        content = f'<span style="color: {shaded(NOTICE_COLOR, self.shade)}"><b>⚠ {markdown_literal(text)}</b></span>'
        for where, handle in self.controls.notices.items():
            shown = bool(text) and where == place
            if shown and handle.content != content:
                handle.content = content
            if handle.visible != shown:
                handle.visible = shown

    def frame_choice(self) -> str:
        d = self.drawn
        return frame_choice(d.resolved.scene, d.resolved.frame, d.resolved.ride) if d is not None else "lab"

    # ------------------------------------------------------------------ drawing
    @overload
    def _painting(self, settings: Settings, resolved: Resolved) -> Painting: ...
    @overload
    def _painting(self, settings: Settings, resolved: None) -> Painting | None: ...
    def _painting(self, settings: Settings, resolved: Resolved | None) -> Painting | None:
        """``settings`` (resolved as ``resolved``, or here if None) laid out and drawn for this tab's
        canvas and look (shared, :mod:`.painting`); the legend rows and title lines of the last one
        are the first guess. None if ``settings`` make no scene."""
        theme = replace(PRESENTER if self.presenter else NORMAL, shade=self.shade)
        key = PaintingKey(settings, self.canvas_size.width, self.canvas_size.height, theme)
        found = self.paintings.find(key)
        if found is not None:
            return found
        if resolved is None:
            made = resolve_settings(settings)
            if isinstance(made, str):
                return None
            resolved = made
        if self.drawn is not None and self.drawn.resolved.scene.kind != resolved.scene.kind:
            self.one_line_titles = True
        return self.paintings.get(resolved, key, (self.legend_rows, self.one_line_titles))

    def _apply(self, resolved: Resolved, refit: bool, shared: bool | None = None, draw: bool = True) -> None:
        """Show ``resolved``: its painting, the controls that follow the state, the picture. With
        ``shared`` (a step the leading tab chose) and a runtime ready, the picture is the painting's
        own payloads, made once for every tab on a canvas of this size; else the tab draws it.
        ``shared`` None: as the picture on screen is (the same state on a new canvas, in another
        look). ``draw``: False if the caller draws the moving parts (once it has set the clock)."""
        if shared is None:
            shared = self.painting is not None
        c = self.controls
        # the state on screen drawn again (a new canvas or look), else the settings just taken
        shown = self.shown_settings if self.drawn is not None and resolved is self.drawn.resolved else None
        painting = self._painting(shown or self.settings, resolved)
        self.layout, self.drawn = layout, d = painting.layout, painting.drawn
        self.legend_rows, self.one_line_titles = painting.legend_rows, painting.one_line_titles
        self.chart_frames = painting.chart_frames
        c.show_settings(self.settings)
        choices = frame_choices(resolved.scene)
        if tuple(c.frame.options) != choices:
            c.frame.options = choices
        chosen = frame_choice(resolved.scene, resolved.frame, resolved.ride)
        if c.frame.value != chosen:  # each assignment is a message to the browser
            c.frame.value = chosen
        rods = tuple(rod.name for rod in resolved.scene.rods)
        if tuple(c.ride_rod.options) != rods:
            c.ride_rod.options = rods
        if c.ride_rod.visible != (len(rods) > 1):
            c.ride_rod.visible = len(rods) > 1
        ridden = rods[min(self.settings.ride.rod, len(rods) - 1)]
        if c.ride_rod.value != ridden:
            c.ride_rod.value = ridden
        cones = (NO_CONE, *cone_events(resolved.scene))
        if tuple(c.cone.options) != cones:
            c.cone.options = cones
        if c.cone.value != (resolved.cone or NO_CONE):
            c.cone.value = resolved.cone or NO_CONE
        window = d.window
        if self.step_window is not None and self.step_window[0] == resolved.scene.kind:
            window = self.step_window[1]  # the lesson's step shows its own window
        self.shown_settings = self.settings
        self.set_playback(self.playback.with_window(window))
        c.time.retarget(time_entry(window, nice_step(window[1] - window[0])))
        self.painting = painting if shared and self.runtime_ready else None
        if self.painting is not None:
            self._lend_page(painting)
        else:
            if self._sent_page is not None:
                self._to_runtime("page", "", 0.0)  # the shared page goes: the tab's own comes back
                self._sent_page = None
            self.renderer.set_static(layout, painting.still, painting.drawn.ruler_names)
        self.timeline, self.runtime_playing, self._pausing = None, False, False  # the runtime's were another state's
        if refit:
            self.fit_camera()
        c.readout.content = readout(resolved)
        if draw:
            self.draw_now(force_plots=True)
        if self.playback.playing:
            self._play_in_browser()
        if self.lesson is not None and self.caption_off_step != (
            resolved.scene.kind != self.lesson.steps[self.step_index].scenario.settings.scene
        ):
            self._send_page()

    def fit_camera(self, force: bool = False) -> None:
        """Put the camera where it shows the whole page. Nothing is sent when the camera is already
        there as far as the browser last reported (a slider's redraw with "Auto-fit view" on), unless
        ``force`` (key R: the browser may have moved it since its last report)."""
        if self.layout is None:
            return
        camera = self.client.camera
        pose = self.renderer.pose(self.layout)
        if not force and self._camera_at(pose):
            return
        distance = abs(pose.position[1])
        camera.near, camera.far = 0.1 * distance, 3.0 * distance  # depth resolution for the page's layers
        camera.up_direction, camera.fov = pose.up, pose.fov
        # viser skips an assignment equal to the camera state it last heard of, and that lags the
        # browser while the user orbits: step aside first, so the exact pose is always sent
        aside = np.array([0.0, 1e-3 * distance, 0.0])
        camera.position, camera.look_at = np.asarray(pose.position) + aside, np.asarray(pose.look_at) + aside
        camera.position, camera.look_at = pose.position, pose.look_at

    def _camera_at(self, pose: cam.CameraPose) -> bool:
        """Whether the camera, as the browser last reported it, has ``pose``."""
        camera = self.client.camera
        return bool(
            np.allclose(camera.position, pose.position)
            and np.allclose(camera.look_at, pose.look_at)
            and np.allclose(camera.up_direction, pose.up)
            and np.isclose(camera.fov, pose.fov)
        )

    def draw_now(self, force_plots: bool = False) -> None:
        """Draw the lanes and the diagrams' moving parts at the clock, in one batch (one instant);
        the playback clock's box follows at :data:`PLOT_HZ`, or now if ``force_plots``."""
        d, layout = self.drawn, self.layout
        if d is None or layout is None:
            return
        now = self.playback.now
        wall = time.monotonic()
        if self.runtime_ready and self._pausing:
            return  # the runtime's frame where it paused is coming: it is the picture
        painting = self.painting  # a page shared with other tabs (None: the tab draws its own)
        # the riding lane's instant (None unless it rides a point)
        instant = None if painting is not None else d.ride_instant(now)
        lanes = [] if painting is not None else d.lane_pictures(now, layout, instant)
        if painting is None:
            self.renderer_lanes = lanes
        with self.client.atomic():
            if self._runtime_frame(now):
                pass  # a frame of the timeline the runtime holds: it shows it
            elif painting is not None:  # the painting's frame, made once for all the tabs that show it
                if self._sent_frame != (painting.id, now):
                    self._to_runtime("frame", payload=painting.frame(now))
                    self._sent_frame = (painting.id, now)
                self._runtime_nodeset = painting.id  # not the mirror's: its next frame goes whole
            else:
                ends = [lane.ends for lane in lanes]
                moving = moving_picture(self.chart_frames, d.moving_items(now, ends, instant), layout.theme)
                self.renderer.update(lanes, moving)
                if self.mirror is not None:  # the runtime draws the moving parts: they go to it
                    self._sent_frame = None
                    prologue = self._runtime_nodeset != self.mirror.nodeset
                    self._to_runtime("frame", payload=self.mirror.frame(now, prologue))
                    self._runtime_nodeset = self.mirror.nodeset
            if force_plots or not self.playback.playing or wall - self._last_plot >= 1.0 / PLOT_HZ:
                self._last_plot = wall
                self.controls.time.show(round(now, 6))
                t = None if self.playback.playing else round(now, 6)
                if self.shown_settings is not None and (self.shown_settings, t) != self._scenario_of:
                    self._scenario_of = (self.shown_settings, t)
                    self.controls.show_scenario(format_scenario(self.shown_settings, t))

    # ------------------------------------------------------------------ playback in the browser
    def _runtime_said(self, text: str) -> None:
        """A report of the tab's runtime (:class:`~rigidrel_app.live.runtime.Report`), answered at once."""
        report = parse_report(text)
        with self.lock:
            if report is None or self.closed:
                return
            with self.client.atomic():
                if report.event == "ready":
                    self._runtime_ready()
                else:
                    self._runtime_stopped(report)
        self.client.flush()

    @property
    def playback_settled(self) -> bool:
        """Paused with the picture and the clock agreeing: not playing, and no pause on its way back
        from the browser (whose frame where it paused sets the clock)."""
        return not self.playback.playing and not self._pausing

    def _runtime_ready(self) -> None:
        """The runtime takes the moving parts over: drawn from now on into the mirror, sent as frames."""
        if self.runtime_ready:
            return
        self.runtime_ready = True
        self.mirror = Mirror(f"tab{self.client.client_id}")
        self.renderer.draw_moving_into(self.mirror.scene)
        self.draw_now(force_plots=True)
        if self.playback.playing:
            self._play_in_browser()

    def _runtime_stopped(self, report: Report) -> None:
        """The runtime paused or ended on a frame of the timeline on screen: the server's clock is there."""
        timeline = self.timeline
        if timeline is None or report.timeline != timeline.id or report.frame is None:
            return
        self._pausing = False
        if report.frame >= len(timeline.times):
            return
        now = float(timeline.times[report.frame])
        self.runtime_playing = False
        self.set_playback(replace(self.playback, now=now, playing=False))
        self.draw_now(force_plots=True)  # its frame is on screen: only the time controls follow

    def _to_runtime(
        self, action: str, timeline: str = "", value: float = 0.0, payload: np.ndarray | None = None
    ) -> None:
        message = PlaybackMessage(action, timeline, float(value))
        if payload is not None:
            message.payload = payload
        queue_to_client(self.client, message)

    def _timeline_key(self) -> TimelineKey | None:
        if self.shown_settings is None or self.layout is None:
            return None
        return TimelineKey(self.shown_settings, self.layout, self.playback.window)

    def _play_in_browser(self) -> None:
        """Playing: the runtime plays the state's timeline from the clock's frame, once it has it
        (asked for now; meanwhile the picture holds, and so does the clock)."""
        key = self._timeline_key()
        if not self.runtime_ready or self.timelines is None or key is None or self.drawn is None:
            return
        timeline = self.timeline
        if timeline is None or self._timeline_wanted is not None:
            self._timeline_wanted = key
            timeline = self.timelines.request(key, self.drawn.resolved, self._timeline_made)
            if timeline is None:
                return
        self._start_timeline(timeline)

    def _timeline_made(self, timeline: Timeline) -> None:
        """On the timelines' thread: a timeline this tab asked for is made."""
        with self.lock:
            if self.closed or self._timeline_wanted is None or timeline.id != timeline_id_of(self._timeline_wanted):
                return
            with self.client.atomic():
                self._start_timeline(timeline)
        self.client.flush()

    def _start_timeline(self, timeline: Timeline) -> None:
        self.timeline, self._timeline_wanted = timeline, None
        if timeline.id not in self._timelines_sent:
            for k, block in enumerate(timeline.blocks):  # the value: the block's first frame
                self._to_runtime("block", timeline.id, k * FRAMES_PER_BLOCK, payload=block)
            self._timelines_sent.append(timeline.id)
            if len(self._timelines_sent) > RUNTIME_TIMELINES:
                self._to_runtime("forget", self._timelines_sent.pop(0))
        if not self.playback.playing:
            return
        self._to_runtime("speed", value=self.playback.speed)
        self._to_runtime("loop", value=float(self.playback.loop))
        t0, t1 = self.playback.window
        frame = (self.playback.now - t0) / (t1 - t0) * (len(timeline.times) - 1) if t1 > t0 else 0.0
        self._sent_frame = None
        self._to_runtime("play", timeline.id, frame)
        self.runtime_playing, self._pausing = True, False
        self._runtime_nodeset = timeline.id

    def _runtime_frame(self, now: float) -> bool:
        """Show ``now`` from the timeline the runtime holds, if it is one of its frames (a step, a
        seek onto a frame): True if so, and nothing else needs drawing."""
        timeline = self.timeline
        if not self.runtime_ready or timeline is None or timeline.id not in self._timelines_sent:
            return False
        frame = timeline.frame_of(now)
        if frame is None:
            return False
        self._sent_frame = None
        self._to_runtime("seek", timeline.id, frame)
        self._runtime_nodeset = timeline.id
        return True

    def tick(self, dt: float) -> None:
        """Advance playback by ``dt`` wall seconds and redraw (called by the animation loop)."""
        with self.lock:
            if self.closed or not self.playback.playing:
                return
            if self.runtime_ready:  # the browser plays: the server's clock follows it, nothing is drawn
                if self.runtime_playing:
                    self.set_playback(self.playback.advance(dt))
            else:
                self.set_playback(self.playback.advance(dt))
                self.draw_now(force_plots=not self.playback.playing)  # stopped at the end: the box shows the end
            self.still_image.tick(self.renderer, self.layout, self.canvas_size.resolution, self._send_still_image)

    def _send_still_image(self, show: Callable[[], None]) -> None:
        """From the still image's thread: ``show`` it, under the lock and in one batch."""
        with self.lock:
            if self.closed:
                return
            with self.client.atomic():
                show()
        self.client.flush()
