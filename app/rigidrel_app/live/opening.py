"""How a tab opens: the server's options for a new tab (:class:`Opening`) and the state it starts in."""

from __future__ import annotations

from dataclasses import dataclass

from ..lessons import Lesson
from ..view.state import Resolved, Settings
from ..view.state import resolve as resolve_settings
from ..view.vocabulary import Shade
from .lesson_steps import LessonHooks
from .painting import PaintingCache
from .tab_state import TabState
from .timeline import TimelineCache


@dataclass(frozen=True)
class Opening:
    """What a new tab is given by the server that serves it."""

    settings: Settings | None = None
    """The state it opens in (a scenario line's; None: the first scene's defaults)."""
    lesson: Lesson | None = None
    """The lesson it gives, opening on ``first_step`` (from 0)."""
    follow: bool = False
    """``--follow``: the lesson's leader says the step (the Lesson folder says who leads)."""
    hooks: LessonHooks | None = None
    """Where step changes and key L go (the server)."""
    first_step: int = 0
    shade: Shade = "light"
    """The theme it opens in (the app's, for new tabs)."""
    start_time: float | None = None
    """The time it opens at (a scenario line's ``--t``; not with a lesson)."""
    timelines: TimelineCache | None = None
    """Where the browser's playback comes from (None: the server draws every frame)."""
    paintings: PaintingCache | None = None
    """The server's paintings, shared by its tabs (None: the tab's own)."""
    still_image: bool = True
    """The still picture as one image while a slow canvas plays (:mod:`.still_image`)."""

    def state(self) -> tuple[TabState, Resolved, str]:
        """The tab's first state, its scene resolved, and why the settings asked for were not taken
        (empty if they were): settings from outside that make no scene open on the defaults."""
        asked = self.settings or Settings()
        resolved = resolve_settings(asked)
        notice = ""
        if isinstance(resolved, str):
            notice, asked = resolved, Settings()
            resolved = resolve_settings(asked)
            assert isinstance(resolved, Resolved)
        return TabState.opening(asked, self.shade), resolved, notice
