"""A tab's words beside its canvas: the lesson's caption band and the live region a screen reader
reads (:mod:`~rigidrel_app.view.describe`).

Both reach the page through the tab's ``local_storage``, under a key of the tab's own that the
page's script (:mod:`.controls`) watches, and only when they change: the caption when its text
does, the summary when the scene, the figure, the frame or the step does (never every frame).
"""

from __future__ import annotations

import uuid

import viser

from ..view.describe import describe
from ..view.scene_view import Drawn
from ..view.state import preset_menu
from .controls import said_message
from .lesson_part import BLANK_CAPTION, LessonPart
from .tab_state import TabState


class PageWords:
    """What one tab's page says in words; :attr:`key` is its ``local_storage`` key."""

    def __init__(self, client: viser.ClientHandle) -> None:
        self.client = client
        self.key = f"rigidrel_caption_{uuid.uuid4().hex}"
        """The caption band's key; the live region's is ``{key}-said``."""
        self._caption = BLANK_CAPTION
        self._said_of: tuple[object, ...] | None = None
        self._said = 0

    def caption(self, text: str) -> None:
        """The caption band shows ``text`` (sent if it is not what the band shows)."""
        if text != self._caption:
            self.client.local_storage.set_item(self.key, text)
            self._caption = text

    def say(self, drawn: Drawn | None, state: TabState, lesson: LessonPart, frame: str, full: bool = False) -> None:
        """The canvas in words to the live region: its summary, after the step's own words, when the
        scene, figure, ``frame`` or step changed; everything at the clock if ``full`` (key D)."""
        if drawn is None or state.shown is None:
            return
        key = (state.shown.scene, preset_menu(state.shown).value, frame, state.step)
        if not full and key == self._said_of:
            return
        self._said_of, self._said = key, self._said + 1
        words = describe(drawn.resolved, state.playback.now)
        text = " ".join(filter(None, (lesson.said(state), words.full if full else words.summary)))
        self.client.local_storage.set_item(f"{self.key}-said", said_message(text, self._said))
