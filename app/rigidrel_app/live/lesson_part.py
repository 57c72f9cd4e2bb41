"""A tab's lesson: what its steps set, lock and say, or nothing at all for a tab without one.

The session holds a :class:`LessonPart` either way and asks it; a tab without a lesson has
:class:`NoLesson`, whose answers are "no step", "nothing locked" and an empty caption band, so
the session never asks whether there is a lesson.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Protocol

from ..lessons import Lesson
from ..lessons.tour import Arrival, arrival, caption_html, clamp_step, lock_notice, lock_reason
from ..view.layout import NORMAL, PRESENTER
from .controls import caption_message
from .tab_state import TabState

#: The caption message of a page that shows no band, in the light theme (as a tab opens).
BLANK_CAPTION = caption_message("", False, "light")


class LessonPart(Protocol):
    """A tab's lesson (:class:`GivenLesson`) or its absence (:class:`NoLesson`)."""

    def step(self, index: int) -> int | None:
        """Step ``index`` kept inside the lesson (PageDown on the last step stays there); None
        without a lesson."""
        ...

    def arrival(self, index: int) -> Arrival:
        """What step ``index`` (a :meth:`step`) sets."""
        ...

    def lock_notice(self, state: TabState, changed: tuple[str, ...]) -> str:
        """The notice for a refused change of the locked controls ``changed`` (never empty)."""
        ...

    def lock_reason(self, state: TabState) -> str:
        """What the current step fixes and why ("" if nothing)."""
        ...

    def caption(self, state: TabState, index: int | None = None) -> str:
        """The tab's localStorage message for the caption band and the page's style: step
        ``index``'s band (the current step's if None), or none without a lesson."""
        ...

    def said(self, state: TabState) -> str:
        """The current step's title and caption in plain words, for a screen reader ("" without a lesson)."""
        ...

    def changed_step(self, index: int) -> None:
        """Tell the server the tab went to step ``index`` by itself."""
        ...

    def lead(self) -> str | None:
        """The tab asks to lead (key L): None, or why it may not."""
        ...

    def claim(self, token: str) -> bool:
        """The tab's address carried the lead token ``token``: True if it is the lecturer's."""
        ...


class NoLesson:
    """A tab without a lesson: no steps, nothing locked, no caption band."""

    def step(self, index: int) -> int | None:
        return None

    def arrival(self, index: int) -> Arrival:
        raise LookupError("a tab without a lesson has no steps")

    def lock_notice(self, state: TabState, changed: tuple[str, ...]) -> str:
        raise LookupError("a tab without a lesson locks nothing")

    def lock_reason(self, state: TabState) -> str:
        return ""

    def caption(self, state: TabState, index: int | None = None) -> str:
        return caption_message("", False, state.shade)

    def said(self, state: TabState) -> str:
        return ""

    def changed_step(self, index: int) -> None:
        pass

    def lead(self) -> str | None:
        return None

    def claim(self, token: str) -> bool:
        return False


#: What the server is told: the tab went to a step by itself; it asks to lead (key L), and is
#: told None or why it may not; its address carried a lead token, and is told if it is the lecturer's.
StepChanged = Callable[[int], None]
Lead = Callable[[], "str | None"]
Claim = Callable[[str], bool]


class GivenLesson:
    """A tab giving ``lesson``; ``step_changed``, ``lead`` and ``claim`` ask the server."""

    def __init__(self, lesson: Lesson, step_changed: StepChanged, lead: Lead, claim: Claim) -> None:
        self.lesson = lesson
        self._step_changed, self._lead, self._claim = step_changed, lead, claim
        self._captions: dict[tuple[object, ...], str] = {}

    def step(self, index: int) -> int | None:
        return clamp_step(self.lesson, index)

    def arrival(self, index: int) -> Arrival:
        return arrival(self.lesson.steps[index])

    def lock_notice(self, state: TabState, changed: tuple[str, ...]) -> str:
        return lock_notice(self.lesson, state.step, state.settings, changed)

    def lock_reason(self, state: TabState) -> str:
        return lock_reason(self.lesson, state.step, state.settings)

    def caption(self, state: TabState, index: int | None = None) -> str:
        """The step's band; under it a note while the tab shows another scene than the step's."""
        k = state.step if index is None else index
        off_step = index is None and state.settings.scene != self.lesson.steps[k].scenario.settings.scene
        key = (k, state.presenter, off_step, state.caption_shown, state.shade)
        if key not in self._captions:  # the band's Markdown is rendered once
            band = caption_html(self.lesson.steps[k], state.presenter, off_step)
            theme = PRESENTER if state.presenter else NORMAL
            self._captions[key] = caption_message(band, state.caption_shown, state.shade, theme)
        return self._captions[key]

    def said(self, state: TabState) -> str:
        step = self.lesson.steps[state.step]
        caption = step.caption.replace("*", "").replace("`", "")  # Markdown's emphasis is not read out
        return f"Step {state.step + 1} of {len(self.lesson.steps)}: {step.title}. {caption}"

    def changed_step(self, index: int) -> None:
        self._step_changed(index)

    def lead(self) -> str | None:
        return self._lead()

    def claim(self, token: str) -> bool:
        return self._claim(token)
