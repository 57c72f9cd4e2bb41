"""What a tab's controls ask of it, checked against the lesson's locks and taken as the tab's pure
transitions (:class:`~.tab_state.TabState`). The controls (:mod:`.controls`) have checked each
value's range first; this is where a legal value meets the tab's state: a control the lesson's
step fixes is refused in words (the GUI disables those; a client may send anything), a
control of another scene changes nothing, and a scenario line is read whole or refused whole.
"""

from __future__ import annotations

from collections.abc import Callable

import rigidrel_core as rr

from ..view.layers import Layer
from ..view.notice import Place
from ..view.state import Settings, scene_presets
from ..view.vocabulary import Shade
from .controls import notice_place
from .keys import Action
from .playback import Playback
from .tab import Tab
from .tab_state import TabState, read_scenario


class Requests:
    """The requests of ``tab``'s controls and keys (the controls' :class:`~.controls.Actions`)."""

    def __init__(self, tab: Tab) -> None:
        self.tab = tab

    @property
    def state(self) -> TabState:
        return self.tab.state

    def change(self, new: Settings, refit: bool | None = None) -> None:
        """Try ``new`` (:meth:`Session.ask`); a change of a control the step fixes is refused."""
        tab = self.tab
        with tab.lock:
            changed = tab.state.locks_against(new)
            if not changed:
                tab.ask(new, refit)
                return
            with tab.client.atomic():
                text = tab.lesson.lock_notice(tab.state, changed)
                tab.show(tab.state.refused(text, notice_place(tab.state.settings, new)), put_back=True)

    def set_parameter(self, parameter: rr.Parameter, value: float) -> None:
        """A parameter control moved; a control of another scene (hidden here) changes nothing."""
        with self.tab.lock:
            if parameter not in self.state.settings.description.parameters:
                self.refuse(f"{parameter.label} is not a control of this scene; nothing changed.")
                return
            self.change(self.state.settings.with_value(parameter.name, value))

    def choose_preset(self, label: str) -> None:
        """Show a paper figure of this scene (the menu's "—" changes nothing)."""
        chosen = scene_presets(self.state.settings.scene).get(label)
        if chosen is not None:
            self.change(chosen, refit=True)

    def set_layer(self, layer: Layer, on: bool) -> None:
        """A layer toggle: the settings' layers with ``layer`` added (``on``) or removed."""
        with self.tab.lock:
            layers = self.state.settings.layers
            self.change(self.state.settings.with_layers(layers | {layer} if on else layers - {layer}), refit=False)

    def load_scenario(self, text: str) -> None:
        """Show the state a scenario string names (:func:`read_scenario`), or say why it names none."""
        tab = self.tab
        with tab.lock:
            scenario = read_scenario(text)
            if isinstance(scenario, str):
                self.refuse(scenario, "scenario")
            elif changed := tab.state.locks_against(scenario.settings, scenario.t is not None):
                self.refuse(tab.lesson.lock_notice(tab.state, changed), "scenario")
            else:
                tab.ask(scenario.settings, refit=True)
                if scenario.t is not None and not tab.state.notice:
                    tab.set_playback(tab.state.playback.seek(scenario.t))
                    tab.draw_now(force_plots=True)

    def seek(self, now: float) -> None:
        """The clock to ``now`` (a step that fixes the time refuses it, and the clock's box shows it back)."""
        tab = self.tab
        with tab.lock:
            if "time" in tab.state.locked:
                self.refuse(tab.lesson.lock_notice(tab.state, ("time",)), "playback")
                tab.controls.show_clock(tab.state)
                return
            tab.set_playback(tab.state.playback.seek(now))
            tab.draw_now(force_plots=True)

    def toggle_play(self) -> None:
        with self.tab.lock:
            self.tab.set_playback(self.state.playback.toggled())

    def set_playback(self, playback: Playback) -> None:
        """The clock as a control sets it (speed, loop)."""
        with self.tab.lock:
            self.tab.set_playback(playback)

    def set_presenter(self, on: bool) -> None:
        """Presenter mode: the panel minimized, the projector theme on the canvas (the canvas' new
        size arrives from the browser and lays the page out again); off: both back."""
        self._relook(self.state.with_presenter(on), refit=True)

    def set_zoomed(self, on: bool) -> None:
        """Key Z: one Minkowski diagram (the chosen frame's, or the lab's in a lab step) over the
        whole canvas, drawn larger, playing on; off: the lanes and every chart back. The canvas
        keeps its size; the camera is fitted to the new page."""
        self._relook(self.state.with_zoomed(on), refit=True)

    def set_shade(self, shade: Shade) -> None:
        """The dark projector theme (light ink on black, the panel dark) or the light one; the page
        is drawn again as it is (the camera stays)."""
        if shade != self.state.shade:
            self._relook(self.state.with_shade(shade), refit=False)

    def _relook(self, state: TabState, refit: bool) -> None:
        tab = self.tab
        with tab.lock, tab.client.atomic():
            tab.show(state)
            if tab.painter.drawn is not None:
                tab.apply(tab.painter.drawn.resolved, refit=refit)

    def refuse(self, text: str, place: Place = "scene") -> None:
        """Say ``text`` in the notice at ``place``; nothing else changes."""
        with self.tab.lock:
            self.tab.show(self.state.refused(text, place))

    def perform(self, action: Action) -> None:
        self.tab.perform(action)

    def frame_choice(self) -> str:
        return self.tab.frame_choice()

    def go_to_step(self, index: int) -> None:
        self.tab.go_to_step(index)

    def checked(self, respond: Callable[[], None], newest: Callable[[], bool] = lambda: True) -> None:
        self.tab.checked(respond, newest)
