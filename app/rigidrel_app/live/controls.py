"""One tab's controls, generated from the scene registry, and the server-side check of every value.

Every control a client can move is *guarded*: the value a client sends is checked on the
server against the control's own range (a hostile websocket client can send anything), a
legal value goes to the session, a refused one is put back and explained in a notice that
names the control and its range. Parameter controls are keyed by the core's
:class:`~rigidrel_core.Parameter`, so scenes that share a parameter share its control.
"""

from __future__ import annotations

import functools
import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass, replace
from typing import Protocol, TypeVar

import plotly.graph_objects as go
import viser

import rigidrel_core as rr

from ..view.scene_view import CONTROL_PX, LENGTH_ASPECT, PLOT_ASPECT, PLOT_PANEL_PX
from ..view.state import CUSTOM_BETA, CUSTOM_FRAME, NO_PRESET, Settings, preset_of, presets
from .playback import Playback

T = TypeVar("T")
Refuse = Callable[[str], None]


def guard(
    handle: viser.GuiInputHandle[T],
    *,
    label: str,
    allowed: str,
    legal: Callable[[T], bool],
    current: Callable[[], T],
    act: Callable[[T], None],
    refuse: Refuse,
    handled: Callable[[], None] = lambda: None,
) -> None:
    """Check every value a client sends to ``handle``: ``act`` on a legal one; put a refused one back
    (``current()``) and ``refuse`` with a notice naming ``label`` and what is ``allowed``; then
    ``handled()``, whatever happened.

    Values the server sets itself are not checked (they are the session's own)."""

    @handle.on_update
    def _(event: viser.GuiEvent) -> None:
        if event.client is None:
            return
        try:
            value = handle.value
            if legal(value):
                act(value)
                return
            refuse(f"{label} = {value!r} refused: it must be {allowed}. The last valid scene stays on screen.")
            handle.value = current()
        finally:
            handled()


def within(lo: float, hi: float) -> Callable[[float], bool]:
    """A finite number in ``[lo, hi]`` (what a slider may hold)."""
    return lambda v: isinstance(v, (int, float)) and math.isfinite(v) and lo - 1e-12 <= v <= hi + 1e-12


class ParameterControl:
    """The control of one scene parameter: a slider, or for a log-scale parameter a slider over
    ``log10`` of the value beside a box where the value itself is shown and typed (a mass ratio of 2)."""

    def __init__(self, gui: viser.GuiApi, parameter: rr.Parameter) -> None:
        slider = parameter.slider
        assert slider is not None
        self.parameter = parameter
        value = float(parameter.default) if parameter.default is not None else slider.hi
        hint = f"{parameter.help}; {parameter.allowed()}"
        self.slider: viser.GuiSliderHandle[float]
        self.box: viser.GuiNumberHandle[float] | None = None
        if slider.scale == "log":
            lo, hi = math.log10(slider.lo), math.log10(slider.hi)
            marks = tuple((float(k), f"{10.0**k:g}") for k in range(math.ceil(lo), math.floor(hi) + 1))
            self.box = gui.add_number(parameter.label, value, step=slider.lo, hint=hint)
            self.slider = gui.add_slider(
                f"log₁₀ {parameter.label}", lo, hi, slider.step, math.log10(value), marks=marks, hint=hint
            )
        else:
            self.slider = gui.add_slider(parameter.label, slider.lo, slider.hi, slider.step, value, hint=hint)

    @property
    def handles(self) -> tuple[viser.GuiInputHandle[float], ...]:
        return (self.slider,) if self.box is None else (self.box, self.slider)

    def show(self, visible: bool, value: float | None, order: float | None = None) -> None:
        """Show or hide the control; a shown one holds ``value`` and sits at ``order`` in its folder."""
        for k, h in enumerate(self.handles):
            if h.visible != visible:
                h.visible = visible
            if order is not None and h.order != order + 0.001 * k:
                h.order = order + 0.001 * k
        if value is None:
            return
        if self.box is None:
            if self.slider.value != value:
                self.slider.value = value
            return
        if self.box.value != value:
            self.box.value = value
        log_value = math.log10(value)
        if abs(self.slider.value - log_value) > 1e-9:
            self.slider.value = log_value

    def wire(
        self,
        current: Callable[[], float | None],
        act: Callable[[float], None],
        refuse: Refuse,
        handled: Callable[[], None] = lambda: None,
    ) -> None:
        """Guard both handles; either one sets the parameter."""
        slider = self.parameter.slider
        assert slider is not None
        p = self.parameter
        allowed = f"a number in [{slider.lo:g}, {slider.hi:g}]"

        def now() -> float:
            v = current()
            return float(p.default or 0.0) if v is None else v

        if self.box is None:
            guard(self.slider, label=p.label, allowed=allowed, legal=within(slider.lo, slider.hi), current=now, act=act,
                  refuse=refuse, handled=handled)  # fmt: skip
            return
        lo, hi = math.log10(slider.lo), math.log10(slider.hi)
        guard(self.box, label=p.label, allowed=allowed, legal=within(slider.lo, slider.hi), current=now, act=act,
              refuse=refuse, handled=handled)  # fmt: skip
        guard(
            self.slider,
            label=self.slider.label,
            allowed=f"a number in [{lo:g}, {hi:g}] (a ratio in [{slider.lo:g}, {slider.hi:g}])",
            legal=within(lo, hi),
            current=lambda: math.log10(now()),
            act=lambda k: act(float(f"{10.0**k:.12g}")),
            refuse=refuse,
            handled=handled,
        )


def parameter_controls(gui: viser.GuiApi) -> dict[rr.Parameter, ParameterControl]:
    """One control per distinct slider parameter of every registered scene, in teaching order."""
    out: dict[rr.Parameter, ParameterControl] = {}
    for d in rr.scene_descriptions().values():
        for p in d.parameters:
            if p.slider is not None and p not in out:
                out[p] = ParameterControl(gui, p)
    return out


class Actions(Protocol):
    """What the controls ask of a session (:class:`~rigidrel_app.live.session.Session`)."""

    settings: Settings
    playback: Playback

    def change(self, new: Settings, refit: bool | None = None) -> None: ...
    def set_parameter(self, parameter: rr.Parameter, value: float) -> None: ...
    def choose_preset(self, label: str) -> None: ...
    def seek(self, now: float) -> None: ...
    def set_playback(self, playback: Playback) -> None: ...
    def toggle_play(self) -> None: ...
    def refuse(self, text: str) -> None: ...
    def handled(self) -> None: ...
    def frame_choice(self) -> str: ...


@dataclass
class Controls:
    """Every handle of one tab, built once; the session wires and updates them."""

    preset: viser.GuiDropdownHandle[str]
    scene: viser.GuiDropdownHandle[str]
    parameters: dict[rr.Parameter, ParameterControl]
    overlay: viser.GuiCheckboxHandle
    notice: viser.GuiMarkdownHandle
    frame: viser.GuiDropdownHandle[str]
    beta: viser.GuiSliderHandle[float]
    play: viser.GuiButtonHandle
    time: viser.GuiSliderHandle[float]
    speed: viser.GuiSliderHandle[float]
    loop: viser.GuiCheckboxHandle
    fit: viser.GuiCheckboxHandle
    readout: viser.GuiMarkdownHandle
    plots: tuple[viser.GuiPlotlyHandle, viser.GuiPlotlyHandle, viser.GuiPlotlyHandle]
    """The lab diagram, the chosen frame's diagram, the equal-time lengths."""

    def control_for(self, settings: Settings, name: str) -> ParameterControl | None:
        return self.parameters.get(settings.description.parameter(name))

    def wire(self, a: Actions) -> None:
        """Guard every control a client can move, and send what passes to ``a``."""
        checked = functools.partial(guard, refuse=a.refuse, handled=a.handled)
        for param, control in self.parameters.items():
            control.wire(
                current=lambda name=param.name: a.settings.parameters().get(name),
                act=lambda v, p=param: a.set_parameter(p, v),
                refuse=a.refuse,
                handled=a.handled,
            )
        titles = scene_titles()
        checked(self.scene, label="Scene", allowed="one of the listed scenes", legal=one_of(list(titles)),
                current=lambda: a.settings.description.title,
                act=lambda title: a.change(a.settings.with_scene(titles[title])))  # fmt: skip
        checked(self.preset, label="Paper figure", allowed="one of the listed figures",
                legal=one_of([NO_PRESET, *presets()]), current=lambda: preset_of(a.settings),
                act=a.choose_preset)  # fmt: skip
        checked(self.overlay, label="Overlay", allowed="on or off", legal=on_or_off,
                current=lambda: a.settings.overlay,
                act=lambda v: a.change(replace(a.settings, overlay=v)))  # fmt: skip
        checked(self.frame, label="Frame", allowed="one of the listed frames", legal=lambda v: v in self.frame.options,
                current=a.frame_choice, act=lambda v: a.change(replace(a.settings, frame=v)))  # fmt: skip
        checked(self.beta, label="β (custom)", allowed="a number in [{:g}, {:g}]".format(*CUSTOM_BETA),
                legal=within(*CUSTOM_BETA),
                current=lambda: a.settings.beta,
                act=lambda b: a.change(replace(a.settings, frame=CUSTOM_FRAME, beta=b)))  # fmt: skip
        checked(self.time, label="t, t'", allowed="a time inside the window",
                legal=lambda v: within(*a.playback.window)(v), current=lambda: round(a.playback.now, 6),
                act=a.seek)  # fmt: skip
        checked(self.speed, label="Speed", allowed="a number in [0.1, 4]", legal=within(0.1, 4.0),
                current=lambda: a.playback.speed,
                act=lambda v: a.set_playback(replace(a.playback, speed=v)))  # fmt: skip
        checked(self.loop, label="Loop", allowed="on or off", legal=on_or_off, current=lambda: a.playback.loop,
                act=lambda v: a.set_playback(replace(a.playback, loop=v)))  # fmt: skip
        self.play.on_click(lambda _: a.toggle_play())

    def show_settings(self, s: Settings) -> None:
        """Show the controls of ``s``'s scene with its values, in its description's order; hide the others."""
        d = s.description
        mine = {p: k for k, p in enumerate(d.parameters) if p.slider is not None}
        for p, control in self.parameters.items():
            shown = p in mine
            control.show(shown, s.value(p.name) if shown else None, PARAMETER_ORDER + 0.01 * mine[p] if shown else None)
        if self.overlay.visible != (d.overlay is not None):
            self.overlay.visible = d.overlay is not None
        if d.overlay is not None and self.overlay.label != d.overlay.label:
            self.overlay.label = d.overlay.label
        if self.overlay.value != s.overlay:
            self.overlay.value = s.overlay
        if self.scene.value != d.title:
            self.scene.value = d.title


#: Where a scene's parameter controls sit in the Scene folder: after the menus, before the overlay.
PARAMETER_ORDER = 10.0


def scene_titles() -> dict[str, str]:
    """Menu title -> scene name, for every registered scene in teaching order."""
    return {d.title: kind for kind, d in rr.scene_descriptions().items()}


def build_controls(gui: viser.GuiApi, settings: Settings) -> Controls:
    """The control panel (right) and the diagram panel (left) of one tab."""
    with gui.add_folder("Scene"):
        preset = gui.add_dropdown(
            "Paper figure",
            [NO_PRESET, *presets()],
            initial_value=NO_PRESET,
            hint="Reproduce one of the paper's figures or worked examples exactly",
            order=1.0,
        )
        scene = gui.add_dropdown("Scene", list(scene_titles()), initial_value=settings.description.title, order=2.0)
        params = parameter_controls(gui)
        overlay = gui.add_checkbox(
            "Overlay", settings.overlay, hint="Draw the comparison scene dashed over this one", order=20.0
        )
        notice = gui.add_markdown("", visible=False, order=21.0)
    with gui.add_folder("Frame"):
        frame = gui.add_dropdown(
            "Frame", ["lab", CUSTOM_FRAME], hint="The lower lane and the second diagram are drawn in this frame"
        )
        beta = gui.add_slider(
            "β (custom)",
            *CUSTOM_BETA,
            0.01,
            settings.beta,
            hint="Velocity of the custom frame, in (-1, 1); moving it selects the custom frame",
        )
    with gui.add_folder("Playback"):
        play = gui.add_button("Play", icon=viser.Icon.PLAYER_PLAY)
        time = gui.add_slider(
            "t, t'", -1.0, 1.0, 0.001, 0.0, hint="Playback clock: the lab lane shows t = this, the frame lane t' = this"
        )
        speed = gui.add_slider("Speed", 0.1, 4.0, 0.1, 1.0, hint="Multiple of the normal pace")
        loop = gui.add_checkbox("Loop", True)
        fit = gui.add_checkbox("Auto-fit view", True)
    readout = gui.add_markdown("")
    gui.main_panel.dock_right()
    gui.main_panel.set_width(CONTROL_PX)
    panel = gui.add_panel()
    panel.dock_left()
    panel.set_width(PLOT_PANEL_PX)
    empty = go.Figure()
    with panel.add_tab("Minkowski diagrams"):
        lab_plot = gui.add_plotly(empty, aspect=PLOT_ASPECT)
        frame_plot = gui.add_plotly(empty, aspect=PLOT_ASPECT)
    with panel.add_tab("Lengths (Fig. 2)"):
        length_plot = gui.add_plotly(empty, aspect=LENGTH_ASPECT)
    return Controls(
        preset, scene, params, overlay, notice, frame, beta, play, time, speed, loop, fit, readout,
        (lab_plot, frame_plot, length_plot),
    )  # fmt: skip


def one_of(options: Sequence[str]) -> Callable[[str], bool]:
    """One of a dropdown's options."""
    return lambda v: isinstance(v, str) and v in options


def on_or_off(value: bool) -> bool:
    """A checkbox's value (viser casts whatever a client sends to a bool)."""
    return isinstance(value, bool)
