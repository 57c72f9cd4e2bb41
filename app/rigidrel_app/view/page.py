"""A state laid out on one canvas and drawn: the page the app shows, as pure values.

:func:`lay_out` is what the live app paints for a tab's canvas
(:class:`~rigidrel_app.live.painting.Painting`) and what an exported lesson step records: the
layout for the canvas (its legend given the rows it needs, its lane titles the lines), the
scene's drawing for those plot areas, the still picture (diagrams, legend, the scene's headline)
and the diagrams' plot frames. :func:`frame_pictures` gives the moving parts at any instants.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from .canvas import ChartFrame, PagePicture, legend_rows, moving_picture, still_picture
from .headline import headline
from .lanes import LanePicture
from .layout import (
    LEGEND_ROWS,
    CanvasLayout,
    Theme,
    canvas_layout,
    is_portrait,
    title_lines_needed,
    titles_fit_one_line,
)
from .scene_view import Drawn, build_drawing, panels
from .state import Resolved, Settings


@dataclass(frozen=True)
class Page:
    """A state laid out and drawn for one canvas. ``legend_rows`` and ``title_lines`` are what the
    layout settled on (a next page's first guess; the lines as
    :func:`~rigidrel_app.view.layout.canvas_layout` takes them: 1 if the titles may go on one line)."""

    drawn: Drawn
    layout: CanvasLayout
    legend_rows: int
    title_lines: int
    chart_frames: tuple[ChartFrame | None, ...]
    still: PagePicture


def lay_out(
    resolved: Resolved,
    settings: Settings,
    width: float,
    height: float,
    theme: Theme,
    zoomed: bool = False,
    guess: tuple[int, int] = (LEGEND_ROWS, 1),
) -> Page:
    """Lay ``resolved`` out on a ``width`` x ``height`` canvas (CSS px) and draw it: the legend gets
    the rows it needs, the lane titles one line if they fit it on a short canvas, else the lines
    they need (two, or more for titles too long for the lane's width; the text a step down), and
    the drawing is made for the final layout's plot areas. ``settings``: the state's, named in the
    headline. ``zoomed``: one diagram over the whole canvas (key Z, :func:`.scene_view.panels`); on a
    phone held upright, the lanes and one diagram (:func:`~.layout.is_portrait`).
    ``guess``: the legend rows and title lines to try first (a tab's last page's: a slider's answer
    then draws once); the result does not depend on it."""
    shown = panels(resolved, zoomed, is_portrait(width, height))

    def layout_of(rows: int, title_lines: int) -> CanvasLayout:
        return canvas_layout(width, height, theme, rows, title_lines, shown)

    def draw(layout: CanvasLayout) -> Drawn:
        return build_drawing(resolved, areas=layout.chart_areas, label_px=layout.theme.text_px)

    rows, title_lines = guess
    layout = layout_of(rows, title_lines)
    drawn = draw(layout)
    legend = drawn.legend(shown.charts)
    rows = legend_rows(legend, layout.legend.width, layout.theme)
    tried = layout_of(rows, 1)
    # at both ends of playback: an object's words change at its event (a door open, then closed
    # with what it did to the poles), and the lines must hold the longer
    ends = [drawn.lane_titles_at(now, tried) for now in drawn.window]
    needed = max(title_lines_needed(titles, tried) for titles in ends)
    if not tried.lanes:  # one diagram zoomed to the whole canvas: no titles
        title_lines = 1
    elif tried.lanes[0].title_lines == 1:  # a short canvas: one line if they fit it
        title_lines = 1 if all(titles_fit_one_line(titles, tried) for titles in ends) else needed
    else:
        title_lines = 1 if needed == 2 else needed
    final = layout_of(rows, title_lines)
    if final.chart_areas != layout.chart_areas or final.theme.text_px != layout.theme.text_px:
        drawn = draw(final)
        legend = drawn.legend(shown.charts)
    chart_frames, picture = still_picture(drawn.charts, final.charts, legend, final.legend, final.theme)
    named = None
    if final.lanes:
        named = headline(settings, [titles[0] for titles in ends], final.lanes[0], final.theme.title_px)
    if named is not None:  # the scene and its parameters, where the lab lane's first line leaves room
        picture = picture + PagePicture(texts=(named,))
    return Page(drawn, final, rows, title_lines, tuple(chart_frames), picture)


#: The lanes and the diagrams' moving parts at one instant.
FramePicture = tuple[list[LanePicture], PagePicture]


def frame_pictures(
    drawn: Drawn, layout: CanvasLayout, chart_frames: Sequence[ChartFrame | None], times: npt.NDArray[np.float64]
) -> list[FramePicture]:
    """The lanes and the diagrams' moving parts at each of ``times`` (the app's own drawing)."""
    out: list[FramePicture] = []
    for t in times.tolist():
        instant = drawn.ride_instant(t)
        lanes = drawn.lane_pictures(t, layout, instant)
        items = drawn.moving_items(t, [lane.ends for lane in lanes], instant)
        out.append((lanes, moving_picture(chart_frames, items, layout.theme)))
    return out


def room(pictures: Sequence[FramePicture]) -> tuple[int, int]:
    """The boxes and clock dials the busiest of ``pictures`` shows (a renderer reserves them)."""
    boxes = max(sum(len(lane.boxes) for lane in lanes) for lanes, _ in pictures)
    dials = max(sum(len(lane.dials) for lane in lanes) for lanes, _ in pictures)
    return boxes, dials
