"""What a tab's parts may ask of the tab itself (:class:`~.session.Session` is the one): its state,
its lock and client, the parts that show a state, and the few moves that change what is on screen.
The parts (:mod:`.requests`, :mod:`.lesson_steps`, :mod:`.playing`, :mod:`.key_actions`) hold a
``Tab`` and never the session's module, so nothing in this package imports its way back.
"""

from __future__ import annotations

from collections.abc import Callable
from contextlib import AbstractContextManager
from typing import Any, Protocol

import viser

from ..view.scene_view import Drawn
from ..view.state import Resolved, Settings
from .browser_player import BrowserPlayer
from .controls import Controls
from .keys import Action
from .lesson_part import LessonPart
from .page_words import PageWords
from .painter import Painter
from .playback import Playback
from .tab_state import TabState


class Tab(Protocol):
    """One tab, as its parts see it."""

    state: TabState
    """What the tab shows and asked for (a frozen value; a part takes a new one by transition)."""

    @property
    def lock(self) -> AbstractContextManager[Any]: ...
    @property
    def client(self) -> viser.ClientHandle: ...
    @property
    def closed(self) -> bool: ...
    @property
    def lesson(self) -> LessonPart: ...
    @property
    def controls(self) -> Controls: ...
    @property
    def painter(self) -> Painter: ...
    @property
    def player(self) -> BrowserPlayer: ...
    @property
    def words(self) -> PageWords: ...

    def show(self, state: TabState, drawn: Drawn | None = None, put_back: bool = False) -> None:
        """Take ``state``: the panel, the caption band and the page's style show it."""
        ...

    def ask(self, new: Settings, refit: bool | None, shared: bool = False, draw: bool = True) -> None:
        """Draw ``new`` if it makes a scene, else keep the last valid one on screen and say why."""
        ...

    def apply(self, resolved: Resolved, refit: bool, shared: bool | None = None, draw: bool = True) -> None:
        """Put ``resolved`` on screen."""
        ...

    def set_playback(self, playback: Playback) -> None:
        """The clock, shown on the play button and followed by the browser's runtime."""
        ...

    def draw_now(self, force_plots: bool = False) -> None:
        """The canvas at the clock, in one batch."""
        ...

    def say(self, full: bool = False) -> None:
        """The canvas in words to the page's live region."""
        ...

    def frame_choice(self) -> str: ...
    def perform(self, action: Action) -> None: ...
    def go_to_step(self, index: int, report: bool = True) -> None: ...
    def checked(self, respond: Callable[[], None], newest: Callable[[], bool] = ...) -> None: ...
