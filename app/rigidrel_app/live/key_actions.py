"""What each key does to a tab (:class:`~.keys.Action`, the table of keys is :mod:`.keys`)."""

from __future__ import annotations

from collections.abc import Callable

from ..view.state import event_times, preset_step
from .keys import Action
from .lesson_steps import LessonSteps
from .requests import Requests
from .tab import Tab


def key_actions(tab: Tab, asks: Requests, steps: LessonSteps) -> dict[Action, Callable[[], None]]:
    """Each action, done to ``tab`` (through its requests ``asks`` and its lesson's ``steps``) in
    the state it is in when the key is pressed."""

    def step(by: int) -> None:  # past either end of the lesson nothing happens
        index = tab.lesson.step(tab.state.step + by)
        if index is not None and index != tab.state.step:
            steps.go_to(index)

    def toggle_play() -> None:
        asks.toggle_play()
        if not tab.state.playback.playing:  # paused: the diagrams and readouts catch up with the rods
            tab.draw_now(force_plots=True)

    def frames(by: int) -> None:
        tab.set_playback(tab.state.playback.stepped(by))
        tab.draw_now(force_plots=True)

    def event(by: int) -> None:  # the next or previous named event, in the lab or the frame
        drawn = tab.painter.drawn
        if drawn is not None:
            tab.set_playback(tab.state.playback.to_event(event_times(drawn.resolved), by))
            tab.draw_now(force_plots=True)

    def figure(by: int) -> None:
        if (chosen := preset_step(tab.state.settings, by)) is not None:
            asks.change(chosen, refit=True)

    return {
        Action.TOGGLE_PLAY: toggle_play,
        Action.STEP_BACK: lambda: frames(-1),
        Action.STEP_FORWARD: lambda: frames(1),
        Action.PREVIOUS_EVENT: lambda: event(-1),
        Action.NEXT_EVENT: lambda: event(1),
        Action.PREVIOUS_FIGURE: lambda: figure(-1),
        Action.NEXT_FIGURE: lambda: figure(1),
        Action.RESET_VIEW: lambda: tab.painter.fit_camera(force=True),
        Action.TOGGLE_PRESENTER: lambda: asks.set_presenter(not tab.state.presenter),
        Action.TOGGLE_THEME: lambda: asks.set_shade("light" if tab.state.shade == "dark" else "dark"),
        Action.TOGGLE_ZOOM: lambda: asks.set_zoomed(not tab.state.zoomed),
        Action.PREVIOUS_STEP: lambda: step(-1),
        Action.NEXT_STEP: lambda: step(1),
        Action.TOGGLE_CAPTION: lambda: tab.show(tab.state.with_caption(not tab.state.caption_shown)),
        Action.LEAD: steps.lead,
        Action.DESCRIBE: lambda: tab.say(full=True),
    }
