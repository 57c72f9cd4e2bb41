"""One browser tab: its own controls, scene, frame, playback, 3-D lanes and diagrams.

Callbacks only replace a field of :class:`Settings` and assign what pure builders made
(``diagrams``, ``lanes``); the physics is all in :mod:`rigidrel_core`.
"""

from __future__ import annotations

import threading
import time
from dataclasses import replace
from typing import Any, cast

import plotly.graph_objects as go
import viser

import rigidrel_core as rr
from rigidrel_core import SceneKind

from .diagrams import length_now, minkowski_now
from .draw import JsonFigure
from .drawing import (
    CONTROL_PX,
    FRAME_Z,
    LAB_Z,
    LENGTH_ASPECT,
    PLAY_SECONDS,
    PLOT_ASPECT,
    PLOT_CONFIG,
    PLOT_HZ,
    PLOT_PANEL_PX,
    Drawn,
    build_drawing,
    camera_pose,
    lane_states,
    nice_step,
    readout_markdown,
)
from .lanes import lane_static
from .settings import (
    CUSTOM_FRAME,
    PRESETS,
    SCENE_LABELS,
    Preset,
    Resolved,
    Settings,
    frame_choices,
    resolve,
    with_value,
)
from .viser_scene import LaneRenderer


def _log_ratio_label(value: float) -> str:
    return f"M2/M1 = {10.0**value:.3g}"


class Session:
    """State and controls of one client; ``tick`` is called by the server's animation loop."""

    def __init__(self, client: viser.ClientHandle) -> None:
        self.client = client
        self.lock = threading.RLock()
        self.settings = Settings()
        self.playing = False
        self.loop = True
        self.speed = 1.0
        self.now = 0.0
        self._last_plot = 0.0
        self._last_slider = 0.0
        self._notice = ""
        self.closed = False
        resolved = resolve(self.settings)
        assert isinstance(resolved, Resolved)
        self.drawn: Drawn | None = None
        with client.atomic():
            self._build_gui()
            self.renderer = LaneRenderer(client.scene, (LAB_Z, FRAME_Z))
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
            self.v_slider = gui.add_slider(
                "V",
                min=0.01,
                max=0.99,
                step=0.01,
                initial_value=s.v,
                hint="Final speed V (V1 of rod 1 for a collision), c = 1",
            )
            self.a_slider = gui.add_slider(
                "a'_F L0",
                min=0.01,
                max=0.99,
                step=0.01,
                initial_value=s.a_front_length,
                hint="Front-end proper acceleration times rest length; the back end gets "
                "a'_F/(1 - a'_F L0). 1 is the impulsive limit.",
            )
            self.eps_slider = gui.add_slider(
                "ε (restitution)",
                min=0.0,
                max=1.0,
                step=0.01,
                initial_value=s.eps,
                hint="0: the rods stick (crash), 1: elastic",
            )
            self.v2_slider = gui.add_slider(
                "V2", min=-0.99, max=0.99, step=0.01, initial_value=s.v2, hint="Velocity of rod 2 (must be below V1)"
            )
            self.m_slider = gui.add_slider(
                "log10 M2/M1",
                min=-2.0,
                max=2.0,
                step=0.01,
                initial_value=s.log_mass_ratio,
                marks=((-2.0, "0.01"), (-1.0, "0.1"), (0.0, "1"), (1.0, "10"), (2.0, "100")),
                hint="Mass ratio M2/M1 on a log scale",
            )
            self.l_slider = gui.add_slider("L2/L1", min=0.1, max=5.0, step=0.05, initial_value=s.length_ratio)
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
            self.beta_slider = gui.add_slider(
                "β (custom)",
                min=-0.99,
                max=0.99,
                step=0.01,
                initial_value=s.beta,
                hint="Velocity of the custom frame; moving it selects the custom frame",
            )
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
        empty = go.Figure()
        with self.plot_panel.add_tab("Minkowski diagrams"):
            self.lab_plot = gui.add_plotly(empty, aspect=PLOT_ASPECT, config=PLOT_CONFIG)
            self.frame_plot = gui.add_plotly(empty, aspect=PLOT_ASPECT, config=PLOT_CONFIG)
        with self.plot_panel.add_tab("Lengths (Fig. 2)"):
            self.length_plot = gui.add_plotly(empty, aspect=LENGTH_ASPECT, config=PLOT_CONFIG)
        self._aspect = self.client.camera.aspect

        @self.client.camera.on_update
        def _(camera: viser.CameraHandle) -> None:
            # the docked panels change the canvas' shape after connect: refit once it is known
            if abs(camera.aspect - self._aspect) > 0.02 and self.fit_cb.value and self.drawn is not None:
                self._aspect = camera.aspect
                d = self.drawn
                self.fit_camera(d.x_range[0] / d.geometry.unit, d.x_range[1] / d.geometry.unit)

        self._wire()

    def _wire(self) -> None:
        def setting(handle: Any, field: str, transform: Any = float) -> None:
            @handle.on_update
            def _(event: viser.GuiEvent) -> None:
                if event.client is None:
                    return
                self.change(field, transform(handle.value))

        setting(self.v_slider, "v")
        setting(self.a_slider, "a_front_length")
        setting(self.eps_slider, "eps")
        setting(self.v2_slider, "v2")
        setting(self.m_slider, "log_mass_ratio")
        setting(self.l_slider, "length_ratio")
        setting(self.overlay_cb, "overlay_impulsive", bool)
        setting(self.frame_dd, "frame", str)

        @self.beta_slider.on_update
        def _(event: viser.GuiEvent) -> None:
            if event.client is None:
                return
            with self.lock:
                new = replace(self.settings, beta=float(self.beta_slider.value), frame=CUSTOM_FRAME)
                self._try(new)

        @self.scene_dd.on_update
        def _(event: viser.GuiEvent) -> None:
            if event.client is None:
                return
            kind = next(k for k, label in SCENE_LABELS.items() if label == self.scene_dd.value)
            self.change("scene", kind)

        @self.preset.on_update
        def _(event: viser.GuiEvent) -> None:
            if event.client is None:
                return
            preset = Preset(self.preset.value)
            if preset is not Preset.NONE:
                with self.lock:
                    self._try(replace(PRESETS[preset], frame=self.settings.frame), refit=True)

        @self.play_btn.on_click
        def _(_: viser.GuiEvent) -> None:
            with self.lock:
                if not self.playing and self.drawn is not None and self.now >= self.drawn.window[1]:
                    self.now = self.drawn.window[0]
                self.set_playing(not self.playing)

        @self.time_slider.on_update
        def _(event: viser.GuiEvent) -> None:
            if event.client is None:
                return
            with self.lock:
                self.set_playing(False)
                self.now = float(self.time_slider.value)
                self.draw_now(force_plots=True)

        @self.speed_slider.on_update
        def _(_: viser.GuiEvent) -> None:
            self.speed = float(self.speed_slider.value)

        @self.loop_cb.on_update
        def _(_: viser.GuiEvent) -> None:
            self.loop = bool(self.loop_cb.value)

    # ------------------------------------------------------------------ state
    def change(self, field: str, value: object) -> None:
        """A control moved: try the new settings; on failure keep the scene and explain."""
        with self.lock:
            refit = field in ("scene", "frame")
            self._try(with_value(self.settings, field, value), refit=refit)

    def _try(self, new: Settings, refit: bool = False) -> None:
        resolved = resolve(new)
        self.settings = new
        if isinstance(resolved, str):
            self._set_notice(resolved)
            return
        self._set_notice("")
        with self.client.atomic():
            self._sync_controls()
            self._apply(resolved, refit=refit or self.fit_cb.value)

    def _set_notice(self, text: str) -> None:
        self._notice = text
        self.notice_md.content = f"**⚠ {text}**" if text else ""
        self.notice_md.visible = bool(text)

    def _sync_controls(self) -> None:
        """Show the controls that apply to the scene; mirror settings changed by presets."""
        s = self.settings
        kind = s.scene
        collision = kind is SceneKind.ROD_COLLISION
        self.v_slider.label = "V1" if collision else "V"
        self.a_slider.visible = kind in (SceneKind.CONSTANT_ACCELERATION, SceneKind.DECELERATION)
        self.eps_slider.visible = kind in (SceneKind.WALL_COLLISION, SceneKind.ROD_COLLISION)
        self.v2_slider.visible = collision
        self.m_slider.visible = collision
        self.l_slider.visible = collision
        self.overlay_cb.visible = kind is SceneKind.CONSTANT_ACCELERATION
        for handle, value in (
            (self.v_slider, s.v),
            (self.a_slider, s.a_front_length),
            (self.eps_slider, s.eps),
            (self.v2_slider, s.v2),
            (self.m_slider, s.log_mass_ratio),
            (self.l_slider, s.length_ratio),
            (self.beta_slider, s.beta),
        ):
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
        name = resolved.frame.name if resolved.frame.name in choices else CUSTOM_FRAME
        if self.frame_dd.value != name:
            self.frame_dd.value = name
        self.time_slider.min, self.time_slider.max = d.window
        self.time_slider.step = nice_step(d.window[1] - d.window[0])
        self.now = min(max(self.now, d.window[0]), d.window[1])
        x0, x1 = d.x_range[0] / d.geometry.unit, d.x_range[1] / d.geometry.unit
        self.renderer.set_static([lane_static(d.geometry, r, resolved.scene.origin_event) for r in d.lane_ranges])
        if refit:
            self.fit_camera(x0, x1)
        self.readout.content = readout_markdown(resolved)
        self.draw_now(force_plots=True)

    def fit_camera(self, x0: float, x1: float) -> None:
        pose = camera_pose(x0, x1, self.client.camera.aspect)
        c = self.client.camera
        c.up_direction = pose.up
        c.fov = pose.fov
        c.position = pose.position
        c.look_at = pose.look_at

    def draw_now(self, force_plots: bool = False) -> None:
        d = self.drawn
        if d is None:
            return
        r = d.resolved
        now = self.now
        lab = rr.Frame.lab()
        states = lane_states(d, now)
        wall = time.monotonic()
        slow = force_plots or wall - self._last_plot >= 1.0 / PLOT_HZ
        with self.client.atomic():
            self.renderer.update(states, labels=slow)
            if slow:
                self._last_plot = wall
                self.lab_plot.figure = cast(
                    go.Figure, JsonFigure(d.lab_chart.with_dynamic(minkowski_now(r.scene, d.lab_view, now, d.span)))
                )
                self.frame_plot.figure = cast(
                    go.Figure, JsonFigure(d.frame_chart.with_dynamic(minkowski_now(r.scene, d.frame_view, now, d.span)))
                )
                self.length_plot.figure = cast(
                    go.Figure,
                    JsonFigure(d.length_chart.with_dynamic(length_now(r.scene, lab, r.frame, now, d.length_top))),
                )
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
                if self.loop:
                    self.now = t0 + (self.now - t1) % (t1 - t0)
                else:
                    self.now = t1
                    self.set_playing(False)
            self.draw_now()
