"""The one notice a view shows: why the last value was refused, and where.

Shared by the live app's tab (:mod:`rigidrel_app.live.tab_state`) and the notebook's live view
(:mod:`rigidrel_app.notebook.live_state`): a value the core refuses leaves the last valid scene on
screen, and the notice names the parameter and its allowed range.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

from .vocabulary import Shade, shaded

Place = Literal["lesson", "scene", "frame", "playback", "scenario"]
"""The folder a notice shows in: the one holding the control whose value was refused, so it is read
where the lecturer is looking even when the panel is scrolled."""

#: A notice is dark red (and starts with ⚠ and is bold, for those who do not see the red).
NOTICE_COLOR = "#B00020"


@dataclass(frozen=True)
class Notice:
    """The notice on screen: its text ("" for none) and the folder it shows in."""

    text: str = ""
    place: Place = "scene"

    def __bool__(self) -> bool:
        return bool(self.text)


def notice_markup(literal_text: str, shade: Shade) -> str:
    """The notice as markup, ``literal_text`` already escaped for where it goes (Markdown or HTML):
    bold, after ⚠, in :data:`NOTICE_COLOR` as drawn on a ``shade`` ground."""
    return f'<span style="color: {shaded(NOTICE_COLOR, shade)}"><b>⚠ {literal_text}</b></span>'
