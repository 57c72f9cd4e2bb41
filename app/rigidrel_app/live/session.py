"""One browser tab: its own controls, scene, frame, playback, 3-D lanes and diagrams.

Callbacks only replace a field of :class:`Settings` and assign what pure builders made
(``diagrams``, ``lanes``); the physics is all in :mod:`rigidrel_core`.
"""

from __future__ import annotations

import math
import threading
import time
from dataclasses import dataclass, replace
from typing import Any, cast

import plotly.graph_objects as go
import viser

from rigidrel_core import SceneKind

from .draw import JsonFigure
from .drawing import (
    CONTROL_PX,
    LANE_Z,
    LENGTH_ASPECT,
    PLAY_SECONDS,
    PLOT_ASPECT,
    PLOT_HZ,
    PLOT_PANEL_PX,
    Drawn,
    build_drawing,
    camera_pose,
    lane_states,
    nice_step,
    readout_markdown,
)
from .settings import (
    CUSTOM_FRAME,
    PRESETS,
    SCENE_LABELS,
    Preset,
    Resolved,
    Settings,
    frame_choice,
    frame_choices,
    resolve,
)
from .viser_scene import LaneRenderer


@dataclass(frozen=True)
class SliderSpec:
    """A slider that holds one field of :class:`Settings`; its range is also the server's check."""

    field: str
    label: str
    lo: float
    hi: float
    step: float
    hint: str
    marks: tuple[tuple[float, str], ...] | None = None
    scenes: frozenset[SceneKind] = frozenset(SceneKind)
    """The scenes the slider applies to (hidden for the others)."""


_ACCELERATIONS = frozenset({SceneKind.CONSTANT_ACCELERATION, SceneKind.DECELERATION})
_COLLISIONS = frozenset({SceneKind.WALL_COLLISION, SceneKind.ROD_COLLISION})
_ROD_COLLISION = frozenset({SceneKind.ROD_COLLISION})

SLIDERS = {
    spec.field: spec
    for spec in (
        SliderSpec("v", "V", 0.01, 0.99, 0.01, "Final speed V (V1 of rod 1 for a collision), c = 1"),
        SliderSpec(
            "a_front_length",
            "a'_F L0",
            0.01,
            0.99,
            0.01,
            "Front-end proper acceleration times rest length; the back end gets a'_F/(1 - a'_F L0). "
            "1 is the impulsive limit.",
            scenes=_ACCELERATIONS,
        ),
        SliderSpec(
            "eps", "ε (restitution)", 0.0, 1.0, 0.01, "0: the rods stick (crash), 1: elastic", scenes=_COLLISIONS
        ),
        SliderSpec("v2", "V2", -0.99, 0.99, 0.01, "Velocity of rod 2 (must be below V1)", scenes=_ROD_COLLISION),
        SliderSpec(
            "log_mass_ratio",
            "log10 M2/M1",
            -2.0,
            2.0,
            0.01,
            "Mass ratio M2/M1 on a log scale",
            ((-2.0, "0.01"), (-1.0, "0.1"), (0.0, "1"), (1.0, "10"), (2.0, "100")),
            scenes=_ROD_COLLISION,
        ),
        SliderSpec("length_ratio", "L2/L1", 0.1, 5.0, 0.05, "Rest length of rod 2 in rod 1's", scenes=_ROD_COLLISION),
        SliderSpec(
            "beta", "β (custom)", -0.99, 0.99, 0.01, "Velocity of the custom frame; moving it selects the custom frame"
        ),
    )
}


class Session:
    """State and controls of one client; ``tick`` is called by the server's animation loop."""

    def __init__(self, client: viser.ClientHandle) -> None:
        self.client = client
        self.lock = threading.RLock()
        self.settings = Settings()
        self.playing = False
        self.speed = 1.0
        """Playback speed (kept here: a refused value is put back from it)."""
        self.now = 0.0
        self._last_plot = 0.0
        self._notice = ""
        self.closed = False
        self.sliders: dict[str, viser.GuiSliderHandle[float]] = {}
        """One slider per field of :class:`Settings` it holds (:data:`SLIDERS`)."""
        resolved = resolve(self.settings)
        assert isinstance(resolved, Resolved)
        self.drawn: Drawn | None = None
        with client.atomic():
            self._build_gui()
            self.renderer = LaneRenderer(client.scene, LANE_Z)
            self._sync_controls()
            self._apply(resolved, refit=True)

    # ------------------------------------------------------------------ GUI
    def _build_gui(self) -> None:
        gui = self.client.gui
        s = self.settings
        with gui.add_folder("Scene"):
            self.preset = gui.add_dropdown(
                "Paper figure",
                [p.value for p in Preset],
                initial_value=Preset.NONE.value,
                hint="Reproduce the paper's Figs. 1, 3 and 4 exactly",
            )
            self.scene_dd = gui.add_dropdown("Scene", list(SCENE_LABELS.values()), initial_value=SCENE_LABELS[s.scene])
            for field in SLIDERS:
                if field != "beta":
                    self._setting_slider(SLIDERS[field])
            self.overlay_cb = gui.add_checkbox(
                "Fig. 1 dashed",
                s.overlay_impulsive,
                hint="Overlay the impulsive start to the same V (Fig. 1's dashed curve)",
            )
            self.notice_md = gui.add_markdown("", visible=False)
        with gui.add_folder("Frame"):
            self.frame_dd = gui.add_dropdown(
                "Frame",
                [s.frame, CUSTOM_FRAME],
                initial_value=s.frame,
                hint="The lower lane and the second diagram are drawn in this frame",
            )
            self._setting_slider(SLIDERS["beta"])
        with gui.add_folder("Playback"):
            self.play_btn = gui.add_button("Play", icon=viser.Icon.PLAYER_PLAY)
            self.time_slider = gui.add_slider(
                "t, t'",
                min=-1.0,
                max=1.0,
                step=0.001,
                initial_value=0.0,
                hint="Playback clock: the lab lane shows t = this, the frame lane t' = this",
            )
            self.speed_slider = gui.add_slider("Speed", min=0.1, max=4.0, step=0.1, initial_value=1.0)
            self.loop_cb = gui.add_checkbox("Loop", True)
            self.fit_cb = gui.add_checkbox("Auto-fit view", True)
        self.readout = gui.add_markdown("")
        gui.main_panel.dock_right()
        gui.main_panel.set_width(CONTROL_PX)
        # the diagrams, docked on the left, beside the 3-D lanes
        self.plot_panel = gui.add_panel()
        self.plot_panel.dock_left()
        self.plot_panel.set_width(PLOT_PANEL_PX)
        # no config= here: viser would re-parse every figure to merge it; the spliced JSON carries it
        empty = go.Figure()
        with self.plot_panel.add_tab("Minkowski diagrams"):
            self.lab_plot = gui.add_plotly(empty, aspect=PLOT_ASPECT)
            self.frame_plot = gui.add_plotly(empty, aspect=PLOT_ASPECT)
        with self.plot_panel.add_tab("Lengths (Fig. 2)"):
            self.length_plot = gui.add_plotly(empty, aspect=LENGTH_ASPECT)
        self._aspect = self.client.camera.aspect

        @self.client.camera.on_update
        def _(camera: viser.CameraHandle) -> None:
            # the docked panels change the canvas' shape after connect: refit once it is known
            if abs(camera.aspect - self._aspect) > 0.02 and self.fit_cb.value and self.drawn is not None:
                self._aspect = camera.aspect
                self.fit_camera(self.drawn.lane_x_range)

        self._wire()

    def _setting_slider(self, spec: SliderSpec) -> None:
        """A slider for one field of :class:`Settings` (in :attr:`sliders`)."""
        self.sliders[spec.field] = self.client.gui.add_slider(
            spec.label,
            min=spec.lo,
            max=spec.hi,
            step=spec.step,
            initial_value=float(getattr(self.settings, spec.field)),
            marks=spec.marks,
            hint=spec.hint,
        )

    def _wire(self) -> None:
        """Every control's callback. Values are checked here, on the server: a client that
        bypasses the sliders (a hostile websocket) is refused like an out-of-range slider."""

        def on_user(handle: Any, act: Any) -> None:
            @handle.on_update
            def _(event: viser.GuiEvent) -> None:
                if event.client is None:  # set by the server itself
                    return
                value = self._checked(handle)
                if value is None:
                    return
                act(value)

        def setting(handle: Any, field: str) -> None:
            on_user(handle, lambda v: self.change(field, v))

        for field, handle in self.sliders.items():
            if field != "beta":
                setting(handle, field)
        setting(self.overlay_cb, "overlay_impulsive")
        setting(self.frame_dd, "frame")

        def custom_frame(beta: float) -> None:
            with self.lock:
                self._try(replace(self.settings, beta=beta, frame=CUSTOM_FRAME))

        on_user(self.sliders["beta"], custom_frame)

        def scene(label: str) -> None:
            self.change("scene", next(k for k, name in SCENE_LABELS.items() if name == label))

        on_user(self.scene_dd, scene)

        def preset(label: str) -> None:
            chosen = Preset(label)
            if chosen is not Preset.NONE:
                with self.lock:
                    self._try(replace(PRESETS[chosen], frame=self.settings.frame))

        on_user(self.preset, preset)

        @self.play_btn.on_click
        def _(_: viser.GuiEvent) -> None:
            with self.lock:
                if not self.playing and self.drawn is not None and self.now >= self.drawn.window[1]:
                    self.now = self.drawn.window[0]
                self.set_playing(not self.playing)

        def scrub(now: float) -> None:
            with self.lock:
                self.set_playing(False)
                self.now = now
                self.draw_now(force_plots=True)

        on_user(self.time_slider, scrub)

        def speed(value: float) -> None:
            self.speed = value

        on_user(self.speed_slider, speed)
        # "Loop" and "Auto-fit view" are read where they apply; viser makes any value sent to a
        # checkbox a bool, so there is nothing to check

    def _checked(self, handle: Any) -> Any:
        """The control's new value if it is one the control can hold; else None, a notice, and the old value back.

        viser has already cast the value to the control's type (``float(...)`` for a slider), so
        what is left to check is the range, and that a dropdown's choice is one of its options."""
        value = handle.value
        if isinstance(handle, viser.GuiSliderHandle):
            ok = math.isfinite(value) and handle.min - 1e-12 <= value <= handle.max + 1e-12
            allowed = f"a number in [{handle.min:g}, {handle.max:g}]"
        elif isinstance(handle, viser.GuiDropdownHandle):
            ok = value in handle.options
            allowed = "one of the listed choices"
        else:
            return value
        if ok:
            return float(value) if isinstance(handle, viser.GuiSliderHandle) else value
        with self.lock:
            self._set_notice(
                f"{handle.label} = {value!r} refused: it must be {allowed}. The last valid scene stays on screen."
            )
            self._restore(handle)
        return None

    def _restore(self, handle: Any) -> None:
        """Put a control back to what the session holds (after a refused value)."""
        field = next((f for f, h in self.sliders.items() if h is handle), None)
        if field is not None:
            handle.value = float(getattr(self.settings, field))
        elif handle is self.frame_dd:
            assert self.drawn is not None  # a session draws its first scene before it has callbacks
            handle.value = frame_choice(self.drawn.resolved.scene, self.drawn.resolved.frame)
        else:
            handle.value = {
                id(self.scene_dd): SCENE_LABELS[self.settings.scene],
                id(self.preset): Preset.NONE.value,
                id(self.time_slider): round(self.now, 6),
                id(self.speed_slider): self.speed,
            }[id(handle)]

    def greet(self, version: str) -> None:
        """Tell a tab that was last used with another version that it now runs this one.

        Runs in its own thread: reading the browser's localStorage is a round trip.
        """
        storage = self.client.local_storage
        try:
            seen = storage.get_item("rigidrel_version", timeout=10.0)
            storage.set_item("rigidrel_version", version)
        except (TimeoutError, RuntimeError):  # not a browser, or gone
            return
        if seen is not None and seen != version and not self.closed:
            self.client.add_notification(
                "rigidrel was updated",
                f"This page was last used with rigidrel {seen}; the server now runs {version}. The controls are "
                "back to their defaults. If anything looks out of date, reload the page (Ctrl+R).",
                color="blue",
                auto_close_seconds=20.0,
            )

    # ------------------------------------------------------------------ state
    def change(self, field: str, value: object) -> None:
        """A control moved: try the new settings; on failure keep the scene and explain."""
        with self.lock:
            self._try(replace(self.settings, **{field: value}))

    def _try(self, new: Settings, refit: bool | None = None) -> None:
        """Apply ``new`` if it makes a scene; else show why. The camera refits if ``refit``,
        or, when that is None, if "Auto-fit view" is on."""
        resolved = resolve(new)
        self.settings = new
        if isinstance(resolved, str):
            self._set_notice(resolved)
            return
        self._set_notice("")
        with self.client.atomic():
            self._sync_controls()
            self._apply(resolved, refit=self.fit_cb.value if refit is None else refit)

    def _set_notice(self, text: str) -> None:
        self._notice = text
        self.notice_md.content = f"**⚠ {text}**" if text else ""
        self.notice_md.visible = bool(text)

    def _sync_controls(self) -> None:
        """Show the controls that apply to the scene; mirror settings changed by presets."""
        s = self.settings
        kind = s.scene
        self.sliders["v"].label = "V1" if kind is SceneKind.ROD_COLLISION else "V"
        self.overlay_cb.visible = kind is SceneKind.CONSTANT_ACCELERATION
        for field, handle in self.sliders.items():
            handle.visible = kind in SLIDERS[field].scenes
            value = getattr(s, field)
            if handle.value != value:
                handle.value = value
        if self.overlay_cb.value != s.overlay_impulsive:
            self.overlay_cb.value = s.overlay_impulsive
        if self.scene_dd.value != SCENE_LABELS[kind]:
            self.scene_dd.value = SCENE_LABELS[kind]

    def set_playing(self, playing: bool) -> None:
        self.playing = playing
        self.play_btn.label = "Pause" if playing else "Play"
        self.play_btn.icon = viser.Icon.PLAYER_PAUSE if playing else viser.Icon.PLAYER_PLAY

    # ------------------------------------------------------------------ drawing
    def _apply(self, resolved: Resolved, refit: bool) -> None:
        self.drawn = build_drawing(resolved)
        d = self.drawn
        choices = frame_choices(resolved.scene)
        if tuple(self.frame_dd.options) != choices:
            self.frame_dd.options = choices
        name = frame_choice(resolved.scene, resolved.frame)
        if self.frame_dd.value != name:
            self.frame_dd.value = name
        self.time_slider.min, self.time_slider.max = d.window
        self.time_slider.step = nice_step(d.window[1] - d.window[0])
        self.now = min(max(self.now, d.window[0]), d.window[1])
        self.renderer.set_static(d.lane_statics())
        if refit:
            self.fit_camera(d.lane_x_range)
        self.readout.content = readout_markdown(resolved)
        self.draw_now(force_plots=True)

    def fit_camera(self, lane_x_range: tuple[float, float]) -> None:
        pose = camera_pose(lane_x_range, self.client.camera.aspect)
        c = self.client.camera
        c.up_direction = pose.up
        c.fov = pose.fov
        c.position = pose.position
        c.look_at = pose.look_at

    def draw_now(self, force_plots: bool = False) -> None:
        d = self.drawn
        if d is None:
            return
        now = self.now
        wall = time.monotonic()
        slow = force_plots or wall - self._last_plot >= 1.0 / PLOT_HZ
        states = lane_states(d, now, labels=slow)
        with self.client.atomic():
            self.renderer.update(states, d.geometry.clock_radius, labels=slow)
            if slow:
                self._last_plot = wall
                figures = d.plot_figures(now, states)
                for plot, figure in zip((self.lab_plot, self.frame_plot, self.length_plot), figures, strict=True):
                    plot.figure = cast(go.Figure, JsonFigure(figure))
                self.time_slider.value = round(now, 6)

    def tick(self, dt: float) -> None:
        """Advance playback by ``dt`` wall seconds and redraw (called by the animation loop)."""
        with self.lock:
            d = self.drawn
            if not self.playing or d is None or self.closed:
                return
            t0, t1 = d.window
            self.now += dt * self.speed * (t1 - t0) / PLAY_SECONDS
            if self.now > t1:
                if self.loop_cb.value:
                    self.now = t0 + (self.now - t1) % (t1 - t0)
                else:
                    self.now = t1
                    self.set_playing(False)
            self.draw_now()
