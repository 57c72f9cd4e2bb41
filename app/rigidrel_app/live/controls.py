"""One tab's controls, generated from the scene registry, and the server-side check of every value.

Every control a client can move is *guarded*: the value a client sends is checked on the
server (a hostile websocket client can send anything), a legal value goes to the session,
and a refused one gets a notice that names the control and its range, replacing any older
notice. What a number means (its range, its slider's scale, how typed text reads) is
:mod:`rigidrel_app.view.entry`'s; here it is only wired to viser. Parameter controls are keyed
by the core's :class:`~rigidrel_core.Parameter`, so scenes that share a parameter share its
control.
"""

from __future__ import annotations

import asyncio
import functools
import html
import itertools
import json
from collections.abc import Callable, Sequence
from dataclasses import dataclass, replace
from typing import Any, Protocol, TypeVar

import viser

import rigidrel_core as rr

from ..backends._viser import handle_uuid, panel_a11y_js
from ..backends.viser import DARK_CANVAS_CSS
from ..lessons import Lesson
from ..lessons.tour import LAYER_LABELS, step_labels
from ..view.entry import NumberEntry, Refuse, Typing, Use, Verdict, control_value, refusal
from ..view.layers import Layer
from ..view.layout import CAPTION_SHARE, NORMAL, Theme, caption_reserve
from ..view.notice import Notice, Place, notice_markup
from ..view.scenario import format_scenario
from ..view.scene_view import CONTROL_PX, Drawn, nice_step
from ..view.scene_view import readout_markdown as readout
from ..view.state import CUSTOM_BETA, CUSTOM_FRAME, Settings, cone_events, frame_choice, frame_choices, preset_menu
from ..view.vocabulary import ROD_COLORS, Shade, markdown_literal, shaded
from .keys import HOTKEYS, LESSON_HOTKEYS, Action, Hotkey, key_line
from .playback import Playback
from .runtime import page_asset
from .tab_state import TabState

T = TypeVar("T")

#: A log slider's label (it sits under the box that carries the number's name).
LOG_SLIDER_LABEL = "log scale"
#: A linear slider's label: none shown (it sits under the box that carries the number's name; a
#: screen reader hears the box's name and "slider", ``backends/assets/a11y.js``). viser draws an
#: empty label as no label at all, and the slider would then not line up with the others.
LINEAR_SLIDER_LABEL = "\u2002"


class Actions(Protocol):
    """What the controls ask of a tab (:class:`~rigidrel_app.live.requests.Requests`)."""

    @property
    def state(self) -> TabState: ...

    def change(self, new: Settings, refit: bool | None = None) -> None: ...
    def set_parameter(self, parameter: rr.Parameter, value: float) -> None: ...
    def choose_preset(self, label: str) -> None: ...
    def seek(self, now: float) -> None: ...
    def set_playback(self, playback: Playback) -> None: ...
    def perform(self, action: Action) -> None: ...
    def refuse(self, text: str, place: Place) -> None: ...
    def frame_choice(self) -> str: ...
    def go_to_step(self, index: int) -> None: ...
    def load_scenario(self, text: str) -> None: ...
    def set_layer(self, layer: Layer, on: bool) -> None: ...
    def set_shade(self, shade: Shade) -> None: ...
    def checked(self, respond: Callable[[], None], newest: Callable[[], bool] = lambda: True) -> None:
        """Run ``respond`` to one client message under the session's lock (unless ``newest`` then says
        a newer value of its control has arrived), and count it."""
        ...


def _on_client_value(handle: viser.GuiInputHandle[T], a: Actions, respond: Callable[[T], None]) -> None:
    """Call ``respond`` with the values a client sends to ``handle`` (values the server sets itself
    are the session's own and not checked), newest first: a value that is still waiting for the
    session when a newer one of the same control arrives is counted and dropped, so a fast drag, a
    held arrow key or a flood queues no redraws behind the newest value (a control's state is its
    last value). Arrivals are numbered on viser's event loop, in the order they came; the response
    runs on a worker thread and reads the value under the session's lock."""
    arrivals = itertools.count(1)
    latest = 0

    @handle.on_update
    async def _(event: viser.GuiEvent) -> None:
        nonlocal latest
        if event.client is None:
            return
        latest = ticket = next(arrivals)
        loop = asyncio.get_running_loop()
        done = loop.run_in_executor(None, a.checked, lambda: respond(handle.value), lambda: ticket == latest)
        done.add_done_callback(functools.partial(_report, loop))


def _report(loop: asyncio.AbstractEventLoop, done: asyncio.Future[None]) -> None:
    """A response that raised: to the event loop's exception handler (the server logs it in one line)."""
    if not done.cancelled() and (exc := done.exception()) is not None:
        loop.call_exception_handler({"message": "a control's value", "exception": exc})


def guard_number(
    handle: viser.GuiInputHandle[T],
    a: Actions,
    *,
    judge: Callable[[T], Verdict],
    act: Callable[[float], None],
    put_back: Callable[[], T],
    place: Place,
) -> None:
    """A number control: ``act`` on what ``judge`` accepts; a refusal replaces the notice and is put
    back unless it is text a person is typing; text on its way to a number waits."""

    def respond(value: T) -> None:
        verdict = judge(value)
        if isinstance(verdict, Use):
            act(verdict.value)
        elif isinstance(verdict, Refuse):
            a.refuse(verdict.notice, place)
            if verdict.put_back:
                handle.value = put_back()
        else:
            assert isinstance(verdict, Typing)

    _on_client_value(handle, a, respond)


def guard_choice(
    handle: viser.GuiInputHandle[T],
    a: Actions,
    *,
    label: str,
    allowed: str,
    legal: Callable[[T], bool],
    current: Callable[[], T],
    act: Callable[[T], None],
    place: Place,
) -> None:
    """A menu or checkbox: ``act`` on a legal value; put a refused one back (``current()``) and
    replace the notice with one naming ``label`` and what is ``allowed``."""

    def respond(value: T) -> None:
        if legal(value):
            act(value)
            return
        a.refuse(refusal(label, repr(value), allowed), place)
        handle.value = current()

    _on_client_value(handle, a, respond)


class NumberControl:
    """A number set with a slider and typed into a box.

    A text box of the control's own, above the slider, shows and takes the number itself (0.6, 2,
    0.01, 100) as typed: ``-0.5``, ``1e5`` and ``abc`` reach the server as text and are read or
    refused there, with a notice (:meth:`NumberEntry.read`). The slider's own number box is hidden
    (:func:`hidden_box_css`): it drops the minus of a range that starts at 0 and the ``e`` of
    ``1e5``, erases what it cannot read without a word, shows ``log10`` beside a log slider, and
    loses keys typed while the page is busy drawing the previous value. Typed text that is refused
    stays on screen with its notice rather than being put back under the typist's fingers.
    """

    def __init__(self, gui: viser.GuiApi, entry: NumberEntry, value: float, hint: str | None = None) -> None:
        self.entry = entry
        self.box: viser.GuiTextHandle = gui.add_text(entry.label, entry.text(value), hint=hint)
        lo, hi = entry.slider_range
        self.slider: viser.GuiSliderHandle[float] = gui.add_slider(
            LOG_SLIDER_LABEL if entry.is_log else LINEAR_SLIDER_LABEL,  # under its box, which carries the name
            lo,
            hi,
            entry.step,
            entry.to_slider(value),
            marks=entry.slider_marks(),
            hint=hint,
        )
        self._box_text: str | None = None
        """The box's text as the server last read or wrote it; the box holding other text means the
        client has typed on since, and that text's own message is on its way."""

    @property
    def handles(self) -> tuple[viser.GuiInputHandle[float] | viser.GuiTextHandle, ...]:
        return (self.box, self.slider)

    def retarget(self, entry: NumberEntry) -> None:
        """A new range (the time slider follows the scene's window)."""
        self.entry = entry
        lo, hi = entry.slider_range
        s = self.slider
        if (s.min, s.max, s.step) != (lo, hi, entry.step):
            s.min, s.max, s.step = lo, hi, entry.step

    def show(self, value: float, visible: bool = True, order: float | None = None) -> None:
        """Show the control holding ``value`` (each handle written only if it shows something else,
        so a box being typed into keeps ``2.50`` while it means 2.5), at ``order`` in its folder."""
        for k, h in enumerate(self.handles):
            if h.visible != visible:
                h.visible = visible
            if order is not None and h.order != order + 0.001 * k:
                h.order = order + 0.001 * k
        if not visible:
            return
        shown = self.box.value
        typed_on = self._box_text is not None and shown != self._box_text
        if not typed_on and self.entry.read(shown) != Use(value):  # never over keys still arriving
            self.box.value = self._box_text = self.entry.text(value)
        if not self.entry.shows(self.slider.value, value):
            self.slider.value = self.entry.to_slider(value)

    def hide(self) -> None:
        for h in self.handles:
            if h.visible:
                h.visible = False

    def wire(self, a: Actions, current: Callable[[], float], act: Callable[[float], None], place: Place) -> None:
        """Guard the slider (and the box); either one sets the number through ``act``; a refusal's
        notice shows in the folder ``place``."""

        def judge_slider(position: float) -> Verdict:
            return self.entry.judge_position(position)

        def slider_position() -> float:
            return self.entry.to_slider(current())

        def box_text() -> str:
            self._box_text = self.entry.text(current())
            return self._box_text

        def judge_box(text: str) -> Verdict:
            self._box_text = text  # read now: text arriving after it is newer typing
            return self.entry.read(text)

        guard_number(self.slider, a, judge=judge_slider, act=act, put_back=slider_position, place=place)
        guard_number(self.box, a, judge=judge_box, act=act, put_back=box_text, place=place)


def hidden_box_css(controls: Sequence[NumberControl]) -> str:
    """Style rules that hide the browser's own number box of each slider (the control's own text
    box above it shows and takes the number, :class:`NumberControl`) and keep the row tall enough
    for the slider's marks. viser draws a slider's box as the next sibling of the slider element,
    whose id is the handle's id."""
    ids = [handle_uuid(c.slider) for c in controls]
    if not ids:
        return ""
    boxes = ", ".join(f'[id="{i}"] + .mantine-NumberInput-root' for i in ids)
    rows = ", ".join(f'.mantine-Flex-root:has(> [id="{i}"])' for i in ids)
    # as tall as a row with a box (1.875em, viser's box height): room for the marks' labels
    return f"<style>{boxes} {{ display: none !important; }} {rows} {{ min-height: 1.875em; }}</style>"


#: A slider's handle keeps the keyboard focus after a drag, and then ← and → move that slider (the
#: browser's way); they must not also step playback, as viser's hotkeys listen on the whole page
#: (dragging V and then stepping would change V too). A listener on the page's body stops those two
#: keys on their way up from a slider handle, after the slider has used them and before the
#: hotkeys hear them. Enter and Escape in a box give the keys back to the page (the box lets go of
#: the focus once it has taken the key), so a clicker's PageDown and Space work again after a value
#: is typed. viser's HTML element runs no ``<script>``; an image that fails to load runs its
#: ``onerror`` (the listener is added once per page).
ARROWS_STAY_IN_SLIDERS = (
    f'<img alt="" src="data:," style="display: none" onerror="{html.escape(page_asset("arrows.js"), quote=True)}">'
)
#: Accessible names for viser's sliders, boxes and icon buttons, and labels and grey buttons dark
#: enough to read (4.5:1), put on the panel from outside by a page script (``backends/assets/a11y.js``).
PANEL_NAMED = f'<img alt="" src="data:," style="display: none" onerror="{html.escape(panel_a11y_js(), quote=True)}">'


def parameter_controls(gui: viser.GuiApi) -> dict[rr.Parameter, NumberControl]:
    """One control per distinct slider parameter of every registered scene, in teaching order."""
    out: dict[rr.Parameter, NumberControl] = {}
    for d in rr.scene_descriptions().values():
        for p in d.parameters:
            if p.slider is not None and p not in out:
                value = float(p.default) if p.default is not None else p.slider.hi
                entry = NumberEntry.of(p)  # the hint gives the range the control takes, as its notices do
                also = f" ({p.constraint})" if p.constraint else ""
                out[p] = NumberControl(gui, entry, value, f"{p.help}; {entry.allowed()}{also}")
    return out


def time_entry(window: tuple[float, float], step: float) -> NumberEntry:
    return NumberEntry("t, t'", window[0], window[1], step, noun="a time")


SPEED = NumberEntry("Speed", 0.1, 4.0, 0.1)
BETA = NumberEntry("β (custom)", *CUSTOM_BETA, 0.01)
#: The light-cone menu's entry for no event.
NO_CONE = "none"
#: The riding frame's point: a share of the rod's rest length, 0 its left end, 1 its right.
RIDE_POINT = NumberEntry("Ride: point f", 0.0, 1.0, 0.05, noun="a share of the rest length")


@dataclass
class Controls:
    """Every handle of one tab, built once; the session wires them, and they show its state (:meth:`show`)."""

    gui: viser.GuiApi
    preset: viser.GuiDropdownHandle[str]
    scene: viser.GuiDropdownHandle[str]
    parameters: dict[rr.Parameter, NumberControl]
    overlay: viser.GuiCheckboxHandle
    notices: dict[Place, viser.GuiMarkdownHandle]
    """One notice slot at the end of each folder; at most one shows."""
    frame: viser.GuiDropdownHandle[str]
    beta: NumberControl
    ride_rod: viser.GuiDropdownHandle[str]
    """Which rod the riding frame rides (shown for scenes of more than one rod)."""
    ride_point: NumberControl
    """Which point of it: moving it selects the riding frame."""
    play: viser.GuiButtonHandle
    time: NumberControl
    speed: NumberControl
    loop: viser.GuiCheckboxHandle
    fit: viser.GuiCheckboxHandle
    reset_view: viser.GuiButtonHandle
    presenter: viser.GuiButtonHandle
    dark: viser.GuiCheckboxHandle
    """The dark projector theme (key T)."""
    readout: viser.GuiMarkdownHandle
    commands: tuple[tuple[Hotkey, viser.CommandHandle], ...]
    """The keyboard's and the clicker's commands (:mod:`.keys`)."""
    layers: dict[Layer, viser.GuiCheckboxHandle]
    """One toggle per layer of the drawings."""
    cone: viser.GuiDropdownHandle[str]
    """The event whose light cone both diagrams draw (:data:`NO_CONE` for none): the scene's events."""
    scenario_shown: viser.GuiHtmlHandle
    """The current state as a scenario string, with a copy button."""
    scenario_box: viser.GuiTextHandle
    scenario_load: viser.GuiButtonHandle
    lesson: LessonControls | None = None
    """The lesson's folder (``rigidrel serve --lesson``), else None."""
    locks: viser.GuiMarkdownHandle | None = None
    """Why controls are disabled: the step of the lesson that fixes them (top of the Scene folder)."""
    fixed: frozenset[str] = frozenset()
    """The controls the lesson's current step fixes (disabled)."""
    look: tuple[Shade, bool] = ("light", False)
    """The theme and presenter mode the panel shows."""
    settings_of: Settings | None = None
    """The settings the controls show."""
    scenario_of: tuple[Settings, float | None] | None = None
    """What the scenario line names (the settings on screen, and the time while paused)."""
    readout_of: Drawn | None = None
    """The drawing the readout describes."""

    def control_for(self, settings: Settings, name: str) -> NumberControl | None:
        return self.parameters.get(settings.description.parameter(name))

    def wire(self, a: Actions) -> None:
        """Guard every control a client can move, and send what passes to ``a``."""
        for param, control in self.parameters.items():
            control.wire(
                a,
                current=lambda p=param: control_value(p, a.state.settings.parameters().get(p.name)),
                act=lambda v, p=param: a.set_parameter(p, v),
                place="scene",
            )
        in_scene = functools.partial(guard_choice, a=a, place="scene")
        in_frame = functools.partial(guard_choice, a=a, place="frame")
        in_playback = functools.partial(guard_choice, a=a, place="playback")
        titles = scene_titles()
        in_scene(self.scene, label="Scene", allowed="one of the listed scenes", legal=one_of(list(titles)),
                 current=lambda: a.state.settings.description.title,
                 act=lambda title: a.change(a.state.settings.with_scene(titles[title])))  # fmt: skip
        in_scene(self.preset, label="Paper figure", allowed="one of the listed figures",
                 legal=lambda v: one_of(preset_menu(a.state.settings).options)(v),
                 current=lambda: preset_menu(a.state.settings).value, act=a.choose_preset)  # fmt: skip
        in_scene(self.overlay, label="Overlay", allowed="on or off", legal=on_or_off,
                 current=lambda: a.state.settings.overlay,
                 act=lambda v: a.change(replace(a.state.settings, overlay=v)))  # fmt: skip
        in_frame(self.frame, label="Frame", allowed="one of the listed frames",
                 legal=lambda v: v in self.frame.options, current=a.frame_choice,
                 act=lambda v: a.change(replace(a.state.settings, frame=v)))  # fmt: skip
        self.beta.wire(a, current=lambda: a.state.settings.beta, place="frame",
                       act=lambda b: a.change(replace(a.state.settings, frame=CUSTOM_FRAME, beta=b)))  # fmt: skip
        self.ride_point.wire(a, current=lambda: a.state.settings.ride.fraction, place="frame",
                             act=lambda f: a.change(a.state.settings.riding(fraction=f)))  # fmt: skip
        in_frame(self.ride_rod, label="Ride: rod", allowed="one of the scene's rods",
                 legal=lambda v: v in self.ride_rod.options,
                 current=lambda: self.ride_rod.options[min(a.state.settings.ride.rod, len(self.ride_rod.options) - 1)],
                 act=lambda v: a.change(a.state.settings.riding(rod=list(self.ride_rod.options).index(v))))  # fmt: skip
        self.time.wire(a, current=lambda: round(a.state.playback.now, 6), act=a.seek, place="playback")
        self.speed.wire(a, current=lambda: a.state.playback.speed, place="playback",
                        act=lambda v: a.set_playback(replace(a.state.playback, speed=v)))  # fmt: skip
        in_playback(self.loop, label="Loop", allowed="on or off", legal=on_or_off,
                    current=lambda: a.state.playback.loop,
                    act=lambda v: a.set_playback(replace(a.state.playback, loop=v)))  # fmt: skip
        self.play.on_click(lambda _: a.perform(Action.TOGGLE_PLAY))
        self.reset_view.on_click(lambda _: a.perform(Action.RESET_VIEW))
        self.presenter.on_click(lambda _: a.perform(Action.TOGGLE_PRESENTER))
        in_playback(self.dark, label="Dark theme", allowed="on or off", legal=on_or_off,
                    current=lambda: a.state.shade == "dark",
                    act=lambda v: a.set_shade("dark" if v else "light"))  # fmt: skip
        for hotkey, command in self.commands:
            command.on_trigger(lambda _, action=hotkey.action: a.perform(action))
        for layer, box in self.layers.items():
            in_scene_layers = functools.partial(guard_choice, a=a, place="scenario")
            in_scene_layers(box, label=LAYER_LABELS[layer], allowed="on or off", legal=on_or_off,
                            current=lambda layer=layer: layer in a.state.settings.layers,
                            act=lambda v, layer=layer: a.set_layer(layer, v))  # fmt: skip
        in_layers = functools.partial(guard_choice, a=a, place="scenario")

        def show_cone(v: str) -> None:
            a.change(replace(a.state.settings, cone=None if v == NO_CONE else v), refit=False)

        in_layers(self.cone, label="Light cone of", allowed="none or one of the scene's events",
                  legal=lambda v: v in self.cone.options, current=lambda: a.state.settings.cone or NO_CONE,
                  act=show_cone)  # fmt: skip
        self.scenario_load.on_click(lambda _: a.checked(lambda: a.load_scenario(self.scenario_box.value)))
        if self.lesson is not None:
            self.lesson.wire(a)

    def show(self, state: TabState, drawn: Drawn | None = None, lock_reason: str = "", put_back: bool = False) -> None:
        """Show ``state``: the settings asked for (a refused one too) when they change, or when
        ``put_back`` (a client moved a locked control), what the step locks and why, Play or Pause,
        the look, the notice; with ``drawn`` (the picture just put on screen) also the menus that
        follow its scene, the time slider's range and the readout. Each handle is written only if it
        shows something else (each write is a message to the browser). A refusal alone leaves the
        controls as the client moved them: typed text stays beside its notice."""
        if put_back or state.settings != self.settings_of or state.locked != self.fixed:
            self.settings_of = state.settings
            self.lock(state.settings, state.locked)
        if drawn is not None:
            self._show_drawn(state, drawn)
        self.show_play(state.playback.playing)
        self._show_look(state.shade, state.presenter)
        self._show_notice(state.notice, state.shade)
        if self.locks is not None:
            if self.locks.content != lock_reason:
                self.locks.content = lock_reason
            if self.locks.visible != bool(lock_reason):
                self.locks.visible = bool(lock_reason)
        if self.lesson is not None:
            self.lesson.show_step(state.step)
            if self.lesson.lead.visible != state.lecturer:  # only the lecturer's tab leads
                self.lesson.lead.visible = state.lecturer

    def _show_drawn(self, state: TabState, drawn: Drawn) -> None:
        r = drawn.resolved
        choices = frame_choices(r.scene)
        if tuple(self.frame.options) != choices:
            self.frame.options = choices
        chosen = frame_choice(r.scene, r.frame, r.ride)
        if self.frame.value != chosen:
            self.frame.value = chosen
        rods = tuple(rod.name for rod in r.scene.rods)
        if tuple(self.ride_rod.options) != rods:
            self.ride_rod.options = rods
        if self.ride_rod.visible != (len(rods) > 1):
            self.ride_rod.visible = len(rods) > 1
        ridden = rods[min(state.settings.ride.rod, len(rods) - 1)]
        if self.ride_rod.value != ridden:
            self.ride_rod.value = ridden
        cones = (NO_CONE, *cone_events(r.scene))
        if tuple(self.cone.options) != cones:
            self.cone.options = cones
        if self.cone.value != (r.cone or NO_CONE):
            self.cone.value = r.cone or NO_CONE
        t0, t1 = state.playback.window
        self.time.retarget(time_entry((t0, t1), nice_step(t1 - t0)))
        if drawn is not self.readout_of:
            self.readout_of = drawn
            self.readout.content = readout(r)

    def show_play(self, playing: bool) -> None:
        """The play button: Pause while playing, else Play."""
        label = "Pause" if playing else "Play"
        if self.play.label != label:
            self.play.label = label
            self.play.icon = viser.Icon.PLAYER_PAUSE if playing else viser.Icon.PLAYER_PLAY

    def show_clock(self, state: TabState) -> None:
        """The playback clock's box, and the scenario line of what is on screen (with its time
        while paused)."""
        now = round(state.playback.now, 6)
        self.time.show(now)
        t = None if state.playback.playing else now
        if state.shown is not None and (state.shown, t) != self.scenario_of:
            self.scenario_of = (state.shown, t)
            self.show_scenario(format_scenario(state.shown, t))

    def _show_look(self, shade: Shade, presenter: bool) -> None:
        """The panel's theme, the dark-theme box, and the panel minimized in presenter mode."""
        old_shade, old_presenter = self.look
        self.look = (shade, presenter)
        if self.dark.value != (shade == "dark"):
            self.dark.value = shade == "dark"
        if shade != old_shade:
            configure_panel(self.gui, shade)
        if presenter != old_presenter:
            if presenter:
                self.gui.main_panel.minimize()
            else:
                self.gui.main_panel.expand()

    def _show_notice(self, notice: Notice, shade: Shade) -> None:
        """The one notice, in its folder (any older one, wherever it was, goes)."""
        content = notice_markup(markdown_literal(notice.text), shade)
        for where, handle in self.notices.items():
            shown = bool(notice) and where == notice.place
            if shown and handle.content != content:
                handle.content = content
            if handle.visible != shown:
                handle.visible = shown

    def show_leader(self, leads: bool | None, lecturer: bool) -> None:
        """The Lesson folder's line on who leads (``None``: no tab leads); ``lecturer``: this tab
        was opened at the lead address and may lead."""
        if self.lesson is None:
            return
        if leads:
            text = "**This tab leads**: the other tabs follow its step."
        elif lecturer:
            text = "No tab leads: press L (or the button) to lead." if leads is None else (
                "Following your other tab's step (L here to lead instead).")  # fmt: skip
        else:
            text = "Waiting for the lecturer's tab, which leads the steps." if leads is None else (
                "Following the lecturer's step.")  # fmt: skip
        if self.lesson.status.content != text:
            self.lesson.status.content = text

    def show_settings(self, s: Settings) -> None:
        """Show the controls of ``s``'s scene with its values, in its description's order; hide the
        others. The paper-figure menu lists this scene's figures and names the one shown, if any."""
        d = s.description
        mine = {p: k for k, p in enumerate(d.parameters) if p.slider is not None}
        for p, control in self.parameters.items():
            if p in mine:
                control.show(control_value(p, s.value(p.name)), True, PARAMETER_ORDER + 0.01 * mine[p])
            else:
                control.hide()
        if self.overlay.visible != (d.overlay is not None):
            self.overlay.visible = d.overlay is not None
        if d.overlay is not None and self.overlay.label != d.overlay.label:
            self.overlay.label = d.overlay.label
        if self.overlay.value != s.overlay:
            self.overlay.value = s.overlay
        if self.scene.value != d.title:
            self.scene.value = d.title
        menu = preset_menu(s)
        if tuple(self.preset.options) != menu.options:
            self.preset.options = menu.options
        if self.preset.value != menu.value:
            self.preset.value = menu.value
        # a scene without a figure of the paper, or a step that fixes what a figure would set
        fixed = "scene" in self.fixed or any(p.name in self.fixed for p in d.parameters)
        if self.preset.disabled != (len(menu.options) == 1 or fixed):
            self.preset.disabled = len(menu.options) == 1 or fixed
        self.beta.show(s.beta)
        self.ride_point.show(s.ride.fraction)
        for layer, box in self.layers.items():
            if box.value != (layer in s.layers):
                box.value = layer in s.layers
        cone = s.cone or NO_CONE
        if self.cone.value != cone and cone in self.cone.options:
            self.cone.value = cone

    def show_scenario(self, text: str) -> None:
        """The scenario string of what is on screen, with its copy button."""
        content = scenario_html(text)
        if self.scenario_shown.content != content:
            self.scenario_shown.content = content

    def lock(self, settings: Settings, locked: frozenset[str]) -> None:
        """Disable the controls a lesson's step fixes (``locked``), enable the others."""
        scene_locked = "scene" in locked
        for p, control in self.parameters.items():
            for h in control.handles:
                off = p.name in locked and p in settings.description.parameters
                if h.disabled != off:
                    h.disabled = off
        for h in (self.scene, self.overlay):
            if h.disabled != scene_locked:
                h.disabled = scene_locked
        self.fixed = locked
        self.show_settings(settings)
        for h in (self.frame, *self.beta.handles, self.ride_rod, *self.ride_point.handles):
            if h.disabled != ("frame" in locked):
                h.disabled = "frame" in locked
        for h in self.time.handles:
            if h.disabled != ("time" in locked):
                h.disabled = "time" in locked


#: The copy button copies its ``data-s`` (the clipboard API where the page is a secure context, as
#: on 127.0.0.1, else a selected text area and the browser's copy command).
_COPY_JS = page_asset("copy.js")


def scenario_html(text: str) -> str:
    """The scenario string in a code box, and a button that copies it."""
    s = html.escape(text, quote=True)
    return (
        f'<div style="font-size: 0.85em"><code class="rigidrel-scenario" style="display: block; '
        f'white-space: pre-wrap; word-break: break-word; user-select: all">{s}</code>'
        f'<button type="button" class="rigidrel-copy" data-s="{s}" onclick="{html.escape(_COPY_JS, quote=True)}" '
        'style="margin-top: 4px; padding: 2px 10px; cursor: pointer">Copy</button></div>'
    )


#: The caption band over the lanes, and the page's own style sheet (the dark theme's canvas). The
#: panel is unmounted while it is minimized (presenter mode), so neither can live in it: this page
#: script (run once, from an image that fails to load, as viser's HTML element runs no ``<script>``)
#: adds the band above the app and moves the app below it, so the canvas shrinks and the server lays
#: the page out again under the band, and keeps one ``<style>`` element in the page's head. The
#: server sends the band's content and the style through the tab's localStorage (a message viser
#: always delivers) under the session's own key; the script takes them from there and removes them.
_CAPTION_JS = page_asset("caption.js")
#: The band's colours: dark text on a pale band, a rule in the rods' blue below it.
CAPTION_GROUND, CAPTION_INK, CAPTION_RULE = "#FFFCEB", "#111111", ROD_COLORS[0]
#: The band's looks: 17 px text (in presenter mode 19 px on a 1280x720 screen, 28 px on 1920x1080).
CAPTION_CSS = f"<style>{page_asset('caption.css', ground=CAPTION_GROUND, ink=CAPTION_INK, rule=CAPTION_RULE)}</style>"

#: viser's client stores the server's ``local_storage`` items under this prefix.
VISER_STORAGE_PREFIX = "viser-user:"


def caption_installer(key: str) -> str:
    """The panel's HTML that installs the caption band (see :data:`_CAPTION_JS`); ``key`` is the
    session's ``local_storage`` key."""
    stored = html.escape(VISER_STORAGE_PREFIX + key, quote=True)
    return (
        f'<img alt="" src="data:," style="display: none" data-key="{stored}" '
        f'onerror="{html.escape(_CAPTION_JS, quote=True)}">'
    )


#: The band in the dark theme: its colours as the dark canvas shows every colour (lightness flipped).
CAPTION_DARK_CSS = page_asset(
    "caption-dark.css",
    ground=shaded(CAPTION_GROUND, "dark"),
    ink=shaded(CAPTION_INK, "dark"),
    rule=shaded(CAPTION_RULE, "dark"),
)


def page_style(shade: Shade) -> str:
    """The page's own style sheet for a ``shade`` tab: none for light; for dark the canvas inverted
    (:data:`~rigidrel_app.backends.viser.DARK_CANVAS_CSS`) and the caption band dark."""
    return "" if shade == "light" else DARK_CANVAS_CSS + " " + CAPTION_DARK_CSS


def caption_message(band_html: str, shown: bool, shade: Shade = "light", theme: Theme = NORMAL) -> str:
    """What the server puts in the tab's localStorage for the band and the page's style (read by
    :data:`_CAPTION_JS`); ``band_html`` "" and ``shown`` False for a tab without a lesson. Its
    ``reserve`` is the canvas height the band leaves (:func:`caption_reserve`)."""
    band = CAPTION_CSS + band_html if band_html else ""
    message = {
        "html": band, "shown": shown, "style": page_style(shade),
        "reserve": caption_reserve(theme), "share": CAPTION_SHARE,
    }  # fmt: skip
    return json.dumps(message)


def said_message(text: str, count: int) -> str:
    """What the server puts in the tab's localStorage (under the caption's key and ``-said``) for
    the page's polite live region to announce (read by :data:`_CAPTION_JS`); ``count`` makes the
    same words a new message."""
    return json.dumps({"text": text, "n": count})


#: The panel's look: viser's, in the app's blue, wide controls, no logo and no share button (it
#: needs the internet).
PANEL_LOOK: dict[str, Any] = {
    "show_share_button": False, "show_logo": False, "control_width": "large", "brand_color": (0, 114, 178),
}  # fmt: skip


def configure_panel(gui: viser.GuiApi, shade: Shade) -> None:
    """Give the panel its look for a ``shade`` tab (viser's dark mode for dark). viser resets every
    setting a call leaves out, so every call gives them all (:data:`PANEL_LOOK`)."""
    gui.configure_theme(dark_mode=shade == "dark", **PANEL_LOOK)


@dataclass
class LessonControls:
    """The Lesson folder: the step list, previous and next, the lock line, who leads."""

    lesson: Lesson
    step: viser.GuiDropdownHandle[str]
    previous: viser.GuiButtonHandle
    next: viser.GuiButtonHandle
    lead: viser.GuiButtonHandle
    status: viser.GuiMarkdownHandle
    """Who leads (with ``--follow``)."""
    notice: viser.GuiMarkdownHandle

    def wire(self, a: Actions) -> None:
        labels = step_labels(self.lesson)
        guard_choice(self.step, a, label="Step", allowed="one of the lesson's steps", legal=one_of(labels),
                     current=lambda: self.step.value, act=lambda v: a.go_to_step(labels.index(v)),
                     place="lesson")  # fmt: skip
        self.previous.on_click(lambda _: a.perform(Action.PREVIOUS_STEP))
        self.next.on_click(lambda _: a.perform(Action.NEXT_STEP))
        self.lead.on_click(lambda _: a.perform(Action.LEAD))

    def show_step(self, index: int) -> None:
        label = step_labels(self.lesson)[index]
        if self.step.value != label:
            self.step.value = label
        if self.previous.disabled != (index == 0):
            self.previous.disabled = index == 0
        last = index == len(self.lesson.steps) - 1
        if self.next.disabled != last:
            self.next.disabled = last


def build_lesson_controls(gui: viser.GuiApi, lesson: Lesson, follow: bool) -> LessonControls:
    """The Lesson folder, first in the panel."""
    with gui.add_folder("Lesson", order=0.5):
        subtitle = f"<br><small>{html.escape(lesson.subtitle)}</small>" if lesson.subtitle else ""
        gui.add_html(f"<b>{html.escape(lesson.title)}</b>{subtitle}", order=0.0)
        labels = step_labels(lesson)
        step = gui.add_dropdown("Step", labels, initial_value=labels[0], hint="Go to a step (PgUp / PgDn, ← / →)")
        previous = gui.add_button("Previous step", icon=viser.Icon.ARROW_LEFT, color="gray", hint="PgUp or ←")
        nxt = gui.add_button("Next step", icon=viser.Icon.ARROW_RIGHT, hint="PgDn or →")
        hint = "Every other tab follows this tab's step (L); shown in the lecturer's tab only"
        lead = gui.add_button("Lead the other tabs", icon=viser.Icon.PRESENTATION, color="gray", hint=hint,
                              visible=False)  # fmt: skip
        status = gui.add_markdown("", visible=follow)
        notice = gui.add_markdown("", visible=False)
    return LessonControls(lesson, step, previous, nxt, lead, status, notice)


#: Where a scene's parameter controls sit in the Scene folder: after the menus, before the overlay.
PARAMETER_ORDER = 10.0


def scene_titles() -> dict[str, str]:
    """Menu title -> scene name, for every registered scene in teaching order."""
    return {d.title: kind for kind, d in rr.scene_descriptions().items()}


def build_controls(
    gui: viser.GuiApi,
    settings: Settings,
    lesson: Lesson | None = None,
    follow: bool = False,
    caption_key: str = "",
    shade: Shade = "light",
) -> Controls:
    """The control panel (right) of one tab, and its hotkeys (the lanes and the diagrams are drawn
    on the canvas). With a ``lesson``: its folder first, the lesson's keys, the caption band. The
    page script that keeps the band and the page's style (:data:`_CAPTION_JS`) is in every tab."""
    notices: dict[Place, viser.GuiMarkdownHandle] = {}
    lesson_controls = None
    if lesson is not None:
        lesson_controls = build_lesson_controls(gui, lesson, follow)
        notices["lesson"] = lesson_controls.notice
    with gui.add_folder("Scene", order=1.0):
        locks = gui.add_markdown("", visible=False, order=0.5)
        menu = preset_menu(settings)
        preset = gui.add_dropdown(
            "Paper figure",
            menu.options,
            initial_value=menu.value,
            hint="Reproduce one of the paper's figures or worked examples of this scene exactly"
            + ("" if lesson is not None else " (PgUp / PgDn)"),
            order=1.0,
        )
        scene = gui.add_dropdown("Scene", list(scene_titles()), initial_value=settings.description.title, order=2.0)
        params = parameter_controls(gui)
        overlay = gui.add_checkbox(
            "Overlay", settings.overlay, hint="Draw the comparison scene dashed over this one", order=20.0
        )
        notices["scene"] = gui.add_markdown("", visible=False, order=21.0)
    with gui.add_folder("Frame", order=2.0):
        frame = gui.add_dropdown(
            "Frame", ["lab", CUSTOM_FRAME], hint="The lower lane and the second diagram are drawn in this frame"
        )
        beta = NumberControl(
            gui, BETA, settings.beta, "Velocity of the custom frame, in (-1, 1); moving it selects the custom frame"
        )
        ride_rod = gui.add_dropdown(
            "Ride: rod", ["rod"], hint="The rod whose point the riding frame rides", visible=False
        )
        ride_point = NumberControl(
            gui,
            RIDE_POINT,
            settings.ride.fraction,
            "The riding frame: at each instant the inertial frame moving with this point of the rod "
            "(0 its left end, 1 its right); moving it selects the riding frame",
        )
        notices["frame"] = gui.add_markdown("", visible=False)
    table = LESSON_HOTKEYS if lesson is not None else HOTKEYS
    with gui.add_folder("Playback", order=3.0):
        play = gui.add_button("Play", icon=viser.Icon.PLAYER_PLAY, hint="Space")
        clock = "Playback clock: the lab lane shows t = this, the frame lane t′ = this" + (
            "" if lesson is not None else " (← → one frame)"
        )
        time = NumberControl(gui, time_entry((-1.0, 1.0), 0.001), 0.0, clock)
        speed = NumberControl(gui, SPEED, 1.0, "Multiple of the normal pace")
        notices["playback"] = gui.add_markdown("", visible=False)
        loop = gui.add_checkbox("Loop", True)
        fit = gui.add_checkbox("Auto-fit view", True, hint="Refit the camera when the scene or the frame changes")
        reset_view = gui.add_button(
            "Reset view", icon=viser.Icon.FOCUS_CENTERED, color="gray", hint="Back to the scene's default camera (R)"
        )
        presenter = gui.add_button(
            "Presenter mode", icon=viser.Icon.PRESENTATION, color="gray",
            hint="Hide this panel; larger text and thicker lines for a projector. F again brings it back (F)",
        )  # fmt: skip
        dark = gui.add_checkbox(
            "Dark theme", shade == "dark", hint="Light on black for a projector, the panel dark too (T)"
        )
        gui.add_markdown(f"<small>{key_line(table)}</small>")
    with gui.add_folder("Layers", order=3.5):
        layers = {
            layer: gui.add_checkbox(label, layer in settings.layers, hint=f"Draw the {label.lower()} ({layer.value})")
            for layer, label in LAYER_LABELS.items()
        }
        cone = gui.add_dropdown(
            "Light cone of",
            [NO_CONE],
            hint="Draw this event's light cone (future and past) in both diagrams",
        )
    with gui.add_folder("Scenario", order=3.8):
        scenario_shown = gui.add_html(scenario_html(""))
        scenario_box = gui.add_text(
            "Load", "", hint="A scenario string, as rigidrel serve SCENE ... takes it: the scene, then its options"
        )
        scenario_load = gui.add_button("Load scenario", icon=viser.Icon.UPLOAD, color="gray")
        notices["scenario"] = gui.add_markdown("", visible=False)
    readout = gui.add_markdown("", order=4.0)
    band = caption_installer(caption_key)
    numbers = [*params.values(), beta, ride_point, time, speed]
    gui.add_html(hidden_box_css(numbers) + ARROWS_STAY_IN_SLIDERS + PANEL_NAMED + band, order=5.0)
    gui.main_panel.dock_right()
    gui.main_panel.set_width(CONTROL_PX)
    commands = tuple((h, gui.add_command(h.label, hotkey=h.key, description=f"key: {h.shown}")) for h in table)
    controls = Controls(
        gui, preset, scene, params, overlay, notices, frame, beta, ride_rod, ride_point, play, time, speed, loop, fit,
        reset_view, presenter, dark, readout, commands, layers, cone, scenario_shown, scenario_box, scenario_load,
        lesson_controls, locks, look=(shade, False),
    )  # fmt: skip
    return controls


def one_of(options: Sequence[str]) -> Callable[[str], bool]:
    """One of a dropdown's options."""
    return lambda v: isinstance(v, str) and v in options


def on_or_off(value: bool) -> bool:
    """A checkbox's value (viser casts whatever a client sends to a bool)."""
    return isinstance(value, bool)


def notice_place(old: Settings, new: Settings) -> Place:
    """Where the notice for ``new`` (refused by the scene, keeping ``old`` on screen) shows: the Frame
    folder if only the frame changed, else the Scene folder."""
    if new.scene == old.scene and (new.frame, new.beta, new.ride) != (old.frame, old.beta, old.ride):
        return "frame"
    return "scene"
