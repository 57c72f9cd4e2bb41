"""The live view's widgets: sliders and a menu (ipywidgets) and one plotly ``FigureWidget``.

Needs the ``notebook`` extra (``pip install 'rigidrel[notebook]'``: ipywidgets, and anywidget, through
which plotly >= 6 draws a ``FigureWidget``; its script ships inside the installed plotly, so the
view works with no network). Every callback asks :mod:`.live_state` for the new state and only
assigns what it built; the kernel computes, the browser draws.
"""

from __future__ import annotations

import html as html_lib
import math
from pathlib import Path
from typing import Any

import anywidget
import ipywidgets as w
import plotly.graph_objects as go

from ..view.entry import NumberEntry
from ..view.notice import notice_markup
from ..view.vocabulary import Shade
from .live_state import (
    BETA_ENTRY,
    LiveState,
    at_time,
    live_figure,
    moving_traces,
    parameter_values,
    slider_parameters,
    start,
    static_trace_count,
    with_beta,
    with_frame,
    with_parameter,
)

#: Width of a slider's label (CSS): the longest registry label ("a′_F L0", "ε (restitution)") fits.
LABEL_WIDTH = "150px"
_STYLE = {"description_width": LABEL_WIDTH}
_LAYOUT = w.Layout(width="420px")


class SliderNames(anywidget.AnyWidget):
    """Invisible: gives each slider of the view it sits in (and its readout box) an accessible name,
    its row's label (``assets/names.js``), which ipywidgets leaves out."""

    _esm = (Path(__file__).parent / "assets" / "names.js").read_text(encoding="utf-8")


def _slider(entry: NumberEntry, value: float, continuous: bool) -> w.FloatSlider | w.FloatLogSlider:
    """A slider for ``entry``: linear, or over ``log10`` of the value for a log entry (its readout
    shows the value itself: 2, not 0.301)."""
    if entry.is_log:
        lo, hi = entry.slider_range
        return w.FloatLogSlider(
            value=value,
            base=10.0,
            min=lo,
            max=hi,
            step=entry.step,
            description=entry.label,
            readout_format=".3g",
            continuous_update=continuous,
            style=_STYLE,
            layout=_LAYOUT,
        )
    digits = max(0, -math.floor(math.log10(entry.step)))
    return w.FloatSlider(
        value=value,
        min=entry.lo,
        max=entry.hi,
        step=entry.step,
        description=entry.label,
        readout_format=f".{digits}f",
        continuous_update=continuous,
        style=_STYLE,
        layout=_LAYOUT,
    )


def _show_value(slider: w.FloatSlider | w.FloatLogSlider, value: float) -> None:
    """Put ``slider`` on ``value``, widening its range if the value lies beyond it (the core and
    :meth:`LiveView.set` take more than the registry's slider range; ipywidgets would clamp)."""
    position = math.log10(value) if isinstance(slider, w.FloatLogSlider) else value
    if position > slider.max:
        slider.max = position
    if position < slider.min:
        slider.min = position
    if slider.value != value:
        slider.value = value


class LiveView(w.VBox):
    """A scene's Minkowski diagrams (lab and chosen frame) and equal-time lengths, with a slider per
    parameter, the frame menu, a β slider (the custom frame) and a time slider; every change is
    computed by the core in the kernel.

    ``state`` is the current :class:`~.live_state.LiveState`; :attr:`figure` the ``FigureWidget``;
    :attr:`sliders` the parameter sliders by parameter name; :meth:`set` sets any parameter (also
    beyond its slider's range, which the core may accept or refuse)."""

    def __init__(self, state: LiveState, continuous: bool = False) -> None:
        self._state = state
        self._syncing = False
        values = parameter_values(state)
        self.sliders: dict[str, w.FloatSlider | w.FloatLogSlider] = {
            p.name: _slider(entry, values[p.name], continuous) for p, entry in slider_parameters(state.settings.scene)
        }
        for p, _ in slider_parameters(state.settings.scene):
            self.sliders[p.name].description_allow_html = False
            self.sliders[p.name].tooltip = p.help
            self.sliders[p.name].observe(lambda c, name=p.name: self._on_parameter(name, c["new"]), "value")
        self.frame = w.Dropdown(
            options=state.frame_options, value=state.frame_value, description="frame", style=_STYLE, layout=_LAYOUT
        )
        self.frame.observe(lambda c: self._on(with_frame, c["new"]), "value")
        self.beta = _slider(BETA_ENTRY, state.beta, continuous)
        self.beta.observe(lambda c: self._on(with_beta, c["new"]), "value")
        self.time = _slider(state.time, state.now, continuous=True)
        self.time.observe(lambda c: self._on(at_time, c["new"]), "value")
        self.notice = w.HTML(layout=w.Layout(min_height="1.5em"))
        self.readout = w.HTML()
        fig = live_figure(state)
        self.figure = go.FigureWidget(fig["data"], fig["layout"])
        self._static = static_trace_count(state.drawn)
        title = w.HTML(f"<b>{html_lib.escape(state.settings.description.title)}</b> ({state.settings.scene})")
        controls = w.HBox(
            [
                w.VBox([title, *self.sliders.values()]),
                w.VBox([self.frame, self.beta, self.time]),
            ]
        )
        super().__init__([controls, self.notice, self.figure, self.readout, SliderNames()])
        self.add_class("rigidrel-live")  # where SliderNames looks for the sliders
        self._show_controls(state)

    # ------------------------------------------------------------------ what changes
    @property
    def state(self) -> LiveState:
        return self._state

    def set(self, name: str, value: float | None) -> LiveState:
        """Set parameter ``name`` to ``value`` as its slider would, but to any number the core takes
        (the slider widens to show it); a refused one leaves the picture and shows the notice.
        Returns the new state."""
        self._apply(with_parameter(self._state, name, value))
        return self._state

    def _on_parameter(self, name: str, value: float) -> None:
        if not self._syncing:
            self._apply(with_parameter(self._state, name, float(value)))

    def _on(self, step: Any, value: Any) -> None:
        if not self._syncing:
            self._apply(step(self._state, value))

    def _apply(self, new: LiveState) -> None:
        """Show ``new``: the whole figure for another scene or frame, else only the moving traces for
        another time; the controls follow the state (a refused value's slider goes back)."""
        old, self._state = self._state, new
        if new.drawn is not old.drawn:
            fig = live_figure(new)
            with self.figure.batch_update():
                self.figure.data = ()
            self.figure.add_traces(fig["data"])
            self.figure.layout = fig["layout"]
            self._static = static_trace_count(new.drawn)
        elif new.now != old.now:
            moving = moving_traces(new)
            shown: list[Any] = list(self.figure.data)[self._static :]
            with self.figure.batch_update():
                for trace, new_trace in zip(shown, moving, strict=True):
                    trace.update(x=new_trace["x"], y=new_trace["y"])
        self._show_controls(new)

    def _show_controls(self, s: LiveState) -> None:
        self._syncing = True
        try:
            for name, value in parameter_values(s).items():
                _show_value(self.sliders[name], value)
            if tuple(self.frame.options) != s.frame_options:
                self.frame.options = s.frame_options
            self.frame.value = s.frame_value
            _show_value(self.beta, s.beta)  # a preset frame may move faster than the β slider's ±0.99
            t = s.time
            if (self.time.min, self.time.max, self.time.step) != (t.lo, t.hi, t.step):
                # widen first: ipywidgets refuses a minimum above the current maximum
                self.time.max = max(self.time.max, t.hi)
                self.time.min = t.lo
                self.time.max = t.hi
                self.time.step = t.step
            self.time.value = s.now
        finally:
            self._syncing = False
        text = html_lib.escape(s.notice)
        self.notice.value = notice_markup(text, "light") if s.notice else ""
        self.readout.value = s.readout_html()


def explore(
    kind: str,
    frame: str | float | None = None,
    t: float | None = None,
    continuous: bool = False,
    *,
    theme: Shade = "light",
    **values: float | None,
) -> LiveView:
    """The live view of scene ``kind`` (a registry name: ``rr.scene_descriptions()``), opened with
    ``values`` (the rest at the registry's defaults), in ``frame`` (a frame preset's name, a
    velocity in (-1, 1), or ``None`` for the scene's default frame), at time ``t``.

    ``continuous``: redraw while a parameter slider is dragged (the time slider always does);
    off by default, as a scene is rebuilt for each value. ``theme``: ``"dark"`` draws the figure in
    the app's dark projector theme (light on black, every colour lightness-flipped), through every
    change of scene, frame and time; the controls keep the notebook's look. Values the core refuses
    here (and a ``theme`` other than ``"light"`` or ``"dark"``) raise its
    :class:`~rigidrel_core.ParameterError`; in the view they show a notice instead."""
    return LiveView(start(kind, frame, t, theme=theme, **values), continuous)
