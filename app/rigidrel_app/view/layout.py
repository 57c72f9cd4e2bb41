"""Where everything goes on the app's canvas: the two lanes on top, the three diagrams below.

The canvas is laid out in CSS pixels: page coordinates ``(x, z)`` with ``x`` from the
canvas' left edge and ``z`` up from its bottom edge (the camera looks along +y at this
plane, :func:`rigidrel_app.view.camera.fit_page`). Sizes come from a :class:`Theme`: the
normal one for a desk, the presenter one for a hall (larger text, thicker lines). Pure
arithmetic, no drawing library.
"""

from __future__ import annotations

import math
import re
from collections.abc import Sequence
from dataclasses import dataclass, replace
from typing import Literal

from .vocabulary import INK, Shade

ThemeName = Literal["normal", "presenter"]


@dataclass(frozen=True)
class Theme:
    """Text and line sizes (CSS px) and the ink of one look of the canvas."""

    name: ThemeName
    text_px: float
    """The smallest text on the canvas: ruler numbers, tick numbers, legend, event names."""
    title_px: float
    """Lane titles and clock readings, diagram titles."""
    line_px: float
    """The thinnest line drawn (ticks, grid excepted), and the unit the diagrams' widths scale from."""
    ink: str = INK
    grid: str = "#E4E4E4"
    """Faint grid lines of the diagrams."""
    shade: Shade = "light"
    """The ground: every colour above and in the pictures is a light-ground colour; a backend drawing on
    a dark ground shows each as :func:`~rigidrel_app.view.vocabulary.lightness_flipped` of itself."""

    @property
    def line_scale(self) -> float:
        """Diagram line widths (plotly widths, 1-5) times this, and never under :attr:`line_px`."""
        return self.line_px / 1.5


NORMAL = Theme("normal", text_px=15.0, title_px=16.0, line_px=2.0)
#: For a projector: larger text, thicker lines, pure black ink (the lanes' and the diagrams' colours
#: are the colour-blind-safe palette, dark enough on white).
PRESENTER = Theme("presenter", text_px=19.0, title_px=21.0, line_px=3.0, ink="#000000", grid="#D0D0D0")
THEMES: dict[ThemeName, Theme] = {"normal": NORMAL, "presenter": PRESENTER}

#: Text width per character, in ems (a generous average for the system sans-serif font).
CHAR_EM = 0.58


def text_width(text: str, px: float) -> float:
    """Estimated width (px) of one line of ``text`` at ``px``."""
    return max((len(line) for line in text.split("\n")), default=0) * CHAR_EM * px


@dataclass(frozen=True)
class Rect:
    """A page rectangle: ``x0 <= x <= x1``, ``z0 <= z <= z1`` (px, z up)."""

    x0: float
    z0: float
    x1: float
    z1: float

    @property
    def width(self) -> float:
        return self.x1 - self.x0

    @property
    def height(self) -> float:
        return self.z1 - self.z0


@dataclass(frozen=True)
class LaneLayout:
    """One lane: a title block, two rows of clock dials, the rods, the ruler (top to bottom)."""

    band: Rect
    track: Rect
    """Where the rods and the ruler's ticks may be: the band less a gutter for the ruler's name."""
    title_z: float
    """Top of the title (frame and time) and clock-reading lines."""
    rod_z: float
    """Centre line of the rods."""
    rod_px: float
    clock_px: float
    """Radius of a clock dial."""
    dial_z: tuple[float, float]
    """Centre heights of the dials on the rods' left ends and on their right ends (two rows, so
    the dials of a short rod never overlap)."""
    wall_px: float
    """Height of an obstacle's bar, from the rods' bottom to the top of the dials (never into the title)."""
    ruler_z: float
    """The ruler's line; its ticks hang below, their numbers below those."""
    tick_px: float
    title_lines: int = 2
    """The title block's lines: 2 (the frame and its time, then the clock readings), more where
    those are too long for the lane (:func:`wrap_title`), or, on a short canvas, 1 (both on one
    line, :func:`lane_title_text`)."""
    text_px: float = 15.0
    """The lane's text size (its ruler numbers, edge marks and the rods' names on their bars)."""
    clocks_titled: bool = True
    """Whether the title says the clocks' readings (its second line). Not on a phone held upright
    (:func:`is_portrait`), whose height holds the lanes and a diagram only if each lane's title is
    its first line (the frame, its time, the objects): the dials show the clocks."""


def title_shown(title: str, lane: LaneLayout) -> str:
    """A lane's title (two lines: the frame and its time, the clock readings) as ``lane`` shows it:
    its first line alone where the lane leaves the clocks to its dials (:attr:`LaneLayout.clocks_titled`)."""
    return title if lane.clocks_titled else title.split("\n", 1)[0]


@dataclass(frozen=True)
class ChartLayout:
    outer: Rect
    plot: Rect
    """The plot area (inside the axes)."""


@dataclass(frozen=True)
class Panels:
    """Which of the canvas' parts are shown: the lanes (the lab's, then the chosen frame's, not
    where that frame is the lab itself: the same lane twice says nothing twice; none while one
    diagram is zoomed to the whole canvas) and the charts (the lab's Minkowski diagram, the chosen
    frame's, the equal-time lengths; at least one diagram). The parts shown share the room of those
    that are not."""

    lanes: int = 2
    """The lanes shown: 2, 1 (the lab's) or 0."""
    charts: tuple[bool, bool, bool] = (True, True, True)
    """Whether each chart is shown: the lab diagram, the chosen frame's, the lengths."""

    def __post_init__(self) -> None:
        if not (self.charts[0] or self.charts[1]):
            raise ValueError(f"a canvas shows a Minkowski diagram; charts shown: {self.charts}")
        if self.lanes not in (0, 1, 2):
            raise ValueError(f"a canvas shows 0, 1 or 2 lanes; got {self.lanes}")


ALL_PANELS = Panels()


@dataclass(frozen=True)
class CanvasLayout:
    width: float
    height: float
    theme: Theme
    lanes: tuple[LaneLayout, ...]
    """The lab lane (top) and, if shown (:class:`Panels`), the chosen frame's."""
    charts: tuple[ChartLayout | None, ChartLayout | None, ChartLayout | None]
    """The lab diagram, the chosen frame's diagram, the equal-time lengths; ``None`` for one not
    shown (:class:`Panels`)."""
    legend: Rect
    panels: Panels = ALL_PANELS
    """What is shown (:class:`Panels`)."""

    @property
    def diagram(self) -> ChartLayout:
        """The first Minkowski diagram shown (the lab's, or the chosen frame's alone): its plot's
        height is what :data:`MIN_PLOT_PX` holds, and its area what the diagrams are sampled for."""
        chart = self.charts[0] or self.charts[1]
        assert chart is not None, "a canvas shows a Minkowski diagram (Panels)"
        return chart

    @property
    def shown_charts(self) -> tuple[ChartLayout, ...]:
        """The charts shown, left to right."""
        return tuple(c for c in self.charts if c is not None)

    @property
    def chart_areas(self) -> tuple[tuple[float, float], tuple[float, float]]:
        """Plot-area sizes (px) of the Minkowski diagrams and of the lengths chart (the diagrams'
        for a lengths chart not shown: nothing is drawn on it)."""
        a = self.diagram.plot
        c = a if self.charts[2] is None else self.charts[2].plot
        return (a.width, a.height), (c.width, c.height)


MARGIN = 10.0
#: The legend takes this many rows below the diagrams unless told otherwise.
LEGEND_ROWS = 2
#: One legend row is this many text heights.
LEGEND_ROW_EM = 1.45


def title_block(theme: Theme, lines: int = 2) -> float:
    """Height of a lane's title block of ``lines`` lines."""
    return (1.25 * lines) * theme.title_px


def lane_height(theme: Theme, title_lines: int = 2) -> float:
    """One lane's height: title (``title_lines`` lines), two dial rows, the rod, the ruler and its numbers."""
    r = clock_radius(theme)
    return title_block(theme, title_lines) + 4.0 + 5.0 * r + rod_height(theme) + 6.0 + 1.8 * theme.text_px + 4.0


#: The smallest text anywhere on the canvas (CSS px): what a hall reads from the back at 1280x720.
MIN_TEXT_PX = 14.0
#: The Minkowski diagrams' plot areas get at least this height (CSS px) when the canvas allows: on a
#: short canvas (a projector's 1280x720 under a lesson's caption) the lanes' titles go on one line,
#: then the text steps down to the desk theme's sizes (:func:`canvas_layout`).
MIN_PLOT_PX = 150.0
#: A canvas narrower than this and taller than wide is a phone held upright: its diagrams are
#: stacked under the lanes, each as wide as the canvas (:func:`canvas_layout`).
PORTRAIT_WIDTH = 700.0
#: On a phone, viser's panel is a sheet folded to a bar at the foot of the screen (3.5 em of its
#: 14 px text, and its shadow), over the canvas' right side: the legend starts above it.
PHONE_BAR_PX = 54.0


#: A one-line title is taken to fit only with this much room to spare (its numbers change width as
#: they play).
TITLE_SPARE = 1.08


def one_line(title: str) -> str:
    """A lane's two-line title (the frame and its time, the clock readings) on one line."""
    return "     ".join(title.split("\n"))


def titles_fit_one_line(titles: Sequence[str], layout: CanvasLayout) -> bool:
    """Whether each lane's title (two lines) fits its lane on one line at :data:`MIN_TEXT_PX`, with
    :data:`TITLE_SPARE` to spare."""
    return all(
        text_width(one_line(title_shown(t, lane)), MIN_TEXT_PX * TITLE_SPARE) <= lane.band.width
        for t, lane in zip(titles, layout.lanes, strict=False)
    )


def _title_parts(line: str) -> list[str]:
    """A title line's parts: the runs of text between gaps of three or more spaces."""
    return [part for part in re.split(r" {3,}", line.strip()) if part]


def wrap_title(title: str, width: float, px: float) -> str:
    """``title`` in lines no wider than ``width`` at ``px``: as it is if each of its lines fits;
    else its parts (the runs between gaps of three or more spaces, across its lines: the frame and
    its time, an object's words, the rows' key, each rod's clocks) filled greedily into lines,
    and a part wider than ``width`` alone broken between its words."""
    lines = title.split("\n")
    if all(text_width(line, px) <= width for line in lines):
        return title
    out: list[str] = []
    current = ""
    for part in (part for line in lines for part in _title_parts(line)):
        joined = f"{current}   {part}" if current else part
        if text_width(joined, px) <= width:
            current = joined
            continue
        if current:
            out.append(current)
        current = ""
        for word in part.split(" "):
            joined = f"{current} {word}" if current else word
            if current and text_width(joined, px) > width:
                out.append(current)
                joined = word
            current = joined
    out.append(current)
    return "\n".join(out)


#: The title sizes a lane's title steps down through (from its theme's, never under
#: :data:`MIN_TEXT_PX`) before it takes another line.
TITLE_STEP_PX = 0.5


def _title_sizes(px: float) -> list[float]:
    """``px``, then down by :data:`TITLE_STEP_PX` while not under :data:`MIN_TEXT_PX` (``px`` alone
    if it is already under)."""
    sizes = [px]
    while sizes[-1] - TITLE_STEP_PX >= MIN_TEXT_PX:
        sizes.append(sizes[-1] - TITLE_STEP_PX)
    return sizes


def title_lines_needed(titles: Sequence[str], layout: CanvasLayout) -> int:
    """The lines the lanes' titles take on ``layout``'s lanes at the smallest text
    (:func:`wrap_title` at :data:`MIN_TEXT_PX`, or the theme's title size if smaller), with
    :data:`TITLE_SPARE` to spare (a later instant's numbers may be a character longer): at
    least 2. :func:`lane_title_text` then sets them as large as those lines allow."""
    px = min(layout.theme.title_px, MIN_TEXT_PX)
    lines = [
        wrap_title(title_shown(t, lane), lane.band.width / TITLE_SPARE, px).count("\n") + 1
        for t, lane in zip(titles, layout.lanes)
    ]
    return max([2, *lines])


def lane_title_text(title: str, layout: LaneLayout, px: float) -> tuple[str, float]:
    """A lane's title (two lines: the frame and its time, the clock readings) as ``layout`` has room
    for, and its text size. Two lines put on one where the layout asks for one, at ``px`` or
    smaller down to :data:`MIN_TEXT_PX` so that it fits the lane's width (left on two if even that
    does not fit). Else broken to the lane's width (:func:`wrap_title`) at the largest size from
    ``px`` down to :data:`MIN_TEXT_PX` that takes no more lines than the layout gave it (at the
    smallest, however many it takes). On a lane that leaves the clocks to its dials, the first line
    alone (:func:`title_shown`)."""
    title = title_shown(title, layout)
    if layout.title_lines == 1 and "\n" in title:
        one = one_line(title)
        fit = px * layout.band.width / max(text_width(one, px), 1.0)
        return (one, min(px, fit)) if fit >= MIN_TEXT_PX else (title, px)
    *larger, smallest = _title_sizes(px)
    for size in larger:
        wrapped = wrap_title(title, layout.band.width, size)
        if wrapped.count("\n") < layout.title_lines:
            return wrapped, size
    return wrap_title(title, layout.band.width, smallest), smallest


def clock_radius(theme: Theme) -> float:
    return 0.6 * theme.text_px


def rod_height(theme: Theme) -> float:
    return 1.2 * theme.text_px


#: The share of the screen's pixel ratio viser's client renders its canvas at: it steps down to 0.875
#: and 0.75 while frames come slowly and back up when they come fast again. Its camera reports the
#: canvas' size in rendered pixels, so each such step looks like a smaller canvas, though the page
#: (in CSS px, where the labels are sized) has not changed.
ADAPTIVE_RESOLUTIONS = (1.0, 0.875, 0.75)
#: What one step of the client's adaptive resolution multiplies the rendered pixels by (1 first).
RESOLUTION_STEPS = (1.0, *sorted({b / a for a in ADAPTIVE_RESOLUTIONS for b in ADAPTIVE_RESOLUTIONS} - {1.0}))


@dataclass(frozen=True)
class CanvasSize:
    """A canvas' size in CSS px, and how many rendered pixels its camera reports per CSS px.

    The page measures both itself when it can (:meth:`measured_by_page`); the camera's reports in
    rendered pixels (:meth:`reported`) then only tell a new resolution from a new size. Before the
    page has spoken, one rendered pixel is taken for one CSS px.
    """

    width: float
    height: float
    resolution: float = 1.0
    measured: bool = False
    """The page measured this size itself (else it was inferred from the camera's pixels)."""

    def reported(self, pixels_wide: int, pixels_high: int) -> CanvasSize:
        """The canvas after its camera reports ``pixels_wide`` × ``pixels_high`` rendered pixels.

        The same CSS size after a step of the client's adaptive resolution (:data:`RESOLUTION_STEPS`,
        each side within 1.5 px, the browser's rounding) is a change of resolution only. Any other
        report leaves a size the page measured as it is: pixels cannot tell a new size from a new
        size at a new resolution, the page reports a new size itself (it looks four times a
        second), and a camera report may arrive after the page's.

        Without the page (before it has spoken, or a page that cannot run its script): a new width
        with the height of the same CSS size at a step of the resolution is the panel folding away
        or coming back (presenter mode) while the resolution stepped: the height is kept, the width
        read at that resolution. Anything else is a new size, read at the resolution last known.
        """
        for step in RESOLUTION_STEPS:
            r = self.resolution * step
            if abs(pixels_wide - self.width * r) <= 1.5 and abs(pixels_high - self.height * r) <= 1.5:
                return CanvasSize(self.width, self.height, r, self.measured)
        if self.measured:
            return self
        for step in RESOLUTION_STEPS:
            r = self.resolution * step
            if abs(pixels_high - self.height * r) <= 1.5:
                return CanvasSize(pixels_wide / r, self.height, r, False)
        r = self.resolution
        return CanvasSize(pixels_wide / r, pixels_high / r, r, False)

    @classmethod
    def measured_by_page(cls, width: float, height: float, resolution: float) -> CanvasSize:
        """The canvas as the page measured it: CSS px, and rendered pixels per CSS px."""
        return cls(width, height, resolution, True)


def is_portrait(width: float, height: float) -> bool:
    """Whether a ``width`` x ``height`` canvas (CSS px) is a phone held upright: narrower than
    :data:`PORTRAIT_WIDTH` and taller than wide."""
    return width < PORTRAIT_WIDTH and height > width


def canvas_layout(
    width: float,
    height: float,
    theme: Theme = NORMAL,
    legend_rows: int = LEGEND_ROWS,
    title_lines: int = 1,
    panels: Panels = ALL_PANELS,
) -> CanvasLayout:
    """The lanes across the top, the diagrams side by side below, the legend (``legend_rows`` rows) at
    the bottom; on a phone held upright (narrower than :data:`PORTRAIT_WIDTH`, taller than wide) the
    diagrams one under another, and the legend above the bar of the folded panel
    (:data:`PHONE_BAR_PX`). ``title_lines``: 1 if the lanes' titles fit one line (:func:`titles_fit_one_line`),
    else the lines they need (:func:`title_lines_needed`, at least 2). Titles that fit one line
    take two, and on a canvas too short for the diagrams' plots to get :data:`MIN_PLOT_PX`, one;
    if that is not enough (or they need two or more), the text takes the desk theme's sizes (never
    under :data:`MIN_TEXT_PX`; the lines keep their width): the first of these that gives the
    plots their height, else the last. ``panels``: the lanes and charts shown (:class:`Panels`)."""
    smaller = replace(theme, text_px=min(theme.text_px, NORMAL.text_px), title_px=min(theme.title_px, NORMAL.title_px))
    lines = max(2, title_lines)
    layout = _canvas_layout(width, height, theme, legend_rows, lines, panels)
    steps = ((theme, 1), (smaller, 1)) if title_lines == 1 else ((smaller, lines),)
    for t, n in steps:
        if layout.diagram.plot.height >= MIN_PLOT_PX:
            break
        layout = _canvas_layout(width, height, t, legend_rows, n, panels)
    return layout


def height_for_plots(theme: Theme, width: float = 1000.0, panels: Panels = ALL_PANELS) -> float:
    """The canvas height (CSS px) at which the diagrams' plots get :data:`MIN_PLOT_PX` with the lanes'
    titles on one line and the legend on :data:`LEGEND_ROWS` rows, in ``theme``: what a lesson's
    caption band leaves the canvas (:func:`rigidrel_app.live.controls.caption_message`). It hardly
    depends on ``width`` (the lanes and the plots' heights do not)."""
    tall = 4000.0
    layout = _canvas_layout(width, tall, theme, LEGEND_ROWS, 1, panels)
    return math.ceil(tall - (layout.diagram.plot.height - MIN_PLOT_PX))


#: The most of the window's height a lesson's caption band takes (:func:`caption_reserve`): at
#: 1280x720 the diagrams' need leaves it less (174 px); at 1920x1080 it is 270 px, a title and about
#: seven lines of the caption at the desk's sizes, five in presenter mode.
CAPTION_SHARE = 0.25


def caption_reserve(theme: Theme) -> int:
    """The canvas height (CSS px) a lesson's caption band leaves below it, whatever the step: what
    two lanes with one-line titles and diagrams of :data:`MIN_PLOT_PX`
    take at ``theme``'s sizes stepped down to the desk's (as
    :func:`canvas_layout` steps them on a short canvas). The page gives
    the band the rest of the viewport (at most :data:`CAPTION_SHARE` of it); a longer caption
    scrolls in its band. An exported lesson step's page does the same (its canvas this high)."""
    desk = replace(theme, text_px=min(theme.text_px, NORMAL.text_px), title_px=min(theme.title_px, NORMAL.title_px))
    return math.ceil(height_for_plots(desk))


def _canvas_layout(
    width: float, height: float, theme: Theme, legend_rows: int, title_lines: int, panels: Panels
) -> CanvasLayout:
    w, h = max(width, 320.0), max(height, 240.0)
    portrait = is_portrait(w, h)
    lane_h = lane_height(theme, title_lines)
    lanes: list[LaneLayout] = []
    top = h - MARGIN
    gutter = text_width("x′", theme.title_px) + 12.0
    for _ in range(panels.lanes):
        band = Rect(MARGIN, top - lane_h, w - MARGIN, top)
        r = clock_radius(theme)
        title_z = band.z1
        # the dial rows as :class:`~.lanes.LaneGeometry` puts them: 1.6 r above the rod, 2.4 r apart
        dial_hi = title_z - title_block(theme, title_lines) - 4.0 - r
        dial_lo = dial_hi - 2.4 * r
        rod_px = rod_height(theme)
        rod_z = dial_lo - 1.6 * r - 0.5 * rod_px
        ruler_z = rod_z - 0.5 * rod_px - 6.0
        lanes.append(
            LaneLayout(
                band=band,
                track=Rect(band.x0 + gutter, band.z0, band.x1 - 4.0, band.z1),
                title_z=title_z,
                rod_z=rod_z,
                rod_px=rod_px,
                clock_px=r,
                dial_z=(dial_lo, dial_hi),
                wall_px=(dial_hi + r) - (rod_z - 0.5 * rod_px),
                ruler_z=ruler_z,
                tick_px=0.4 * theme.text_px,
                title_lines=title_lines,
                text_px=theme.text_px,
                clocks_titled=not portrait,
            )
        )
        top = band.z0 - 4.0
    foot = MARGIN + (PHONE_BAR_PX if portrait else 0.0)
    legend_h = legend_rows * LEGEND_ROW_EM * theme.text_px
    legend = Rect(MARGIN, foot, w - MARGIN, foot + legend_h)
    charts_top, charts_bottom = top - 4.0, legend.z1 + 4.0
    gap = 12.0
    shown = panels.charts
    n = sum(shown)
    # side by side; on a phone held upright, one under another, each as wide as the canvas
    cw = (w - 2 * MARGIN - (n - 1) * gap) / n if not portrait else w - 2 * MARGIN
    ch = (charts_top - charts_bottom - (n - 1) * gap) / n if portrait else charts_top - charts_bottom
    charts: list[ChartLayout | None] = []
    x0, z1 = MARGIN, charts_top
    for k in range(3):
        if not shown[k]:
            charts.append(None)
            continue
        outer = Rect(x0, max(z1 - ch, charts_bottom), x0 + cw, max(z1, charts_bottom + 60.0))
        left = 3.6 * theme.text_px  # the time axis' numbers
        bottom = 1.5 * theme.text_px + 6.0  # the x axis' numbers
        head = 2.5 * theme.title_px  # the title, on up to two lines
        plot = Rect(outer.x0 + left, outer.z0 + bottom, outer.x1 - 6.0, max(outer.z1 - head, outer.z0 + bottom + 30.0))
        charts.append(ChartLayout(outer, plot))
        if portrait:
            z1 -= ch + gap
        else:
            x0 += cw + gap
    return CanvasLayout(w, h, theme, tuple(lanes), (charts[0], charts[1], charts[2]), legend, panels)
