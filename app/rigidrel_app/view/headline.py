"""The canvas names what it shows: the scene and its parameters, on the lab lane's first title line,
at its right end, so a hall watching presenter mode (no panel) can tell what it is watching.

It takes no room of its own: it is written where the lab lane's first line leaves room at every
instant of playback (that line's widest), the whole of it if it fits, else the scene's name alone,
else nothing (a narrow canvas, or titles on one line, where the lane's own words come first).
"""

from __future__ import annotations

from collections.abc import Sequence

from .canvas import PageText
from .layout import LaneLayout, lane_title_text, text_width
from .state import Settings, format_value

#: Room kept between the lane's own first line and the headline, in ems of the title's text.
GAP_EM = 2.0


def headlines(settings: Settings) -> tuple[str, str]:
    """The headline, longest first: ``"Rod-rod collision: V1 = 0.6, M2/M1 = 2, ..."`` (each of the
    scene's controls as the panel names it, its explanation left out, at the value the scene
    uses), then the scene's name."""
    d = settings.description
    values = ", ".join(
        f"{p.label.split(' (')[0]} = {format_value(v)}"
        for p in d.parameters
        if p.slider is not None and (v := settings.value(p.name)) is not None
    )
    return (f"{d.title}: {values}" if values else d.title, d.title)


def headline(settings: Settings, lab_titles: Sequence[str], lane: LaneLayout, title_px: float) -> PageText | None:
    """The headline at the right end of the lab lane's first title line (``lab_titles``: that lane's
    titles at the instants to leave room for), at the size the line is written in; ``None`` if not
    even the scene's name fits beside it."""
    set_lines = [lane_title_text(title, lane, title_px) for title in lab_titles]
    px = min(size for _, size in set_lines)
    used = max(text_width(text.split("\n")[0], size) for text, size in set_lines)
    room = lane.band.width - used - GAP_EM * px
    for text in headlines(settings):
        if text_width(text, px) <= room:
            return PageText(lane.band.x1, lane.title_z, text, px, "top-right")
    return None
