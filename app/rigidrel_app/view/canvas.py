"""Charts on the app's canvas: a :class:`~.vocabulary.Chart` turned into page primitives.

A backend that draws straight segments, round or diamond dots and text boxes (viser's
scene) draws a chart from these: every curve is clipped to its plot area here, dashes are
cut here, filled areas are scan lines here, and axes, ticks, numbers, names and the legend
are laid out here. Page coordinates are CSS pixels, ``z`` up (:mod:`.layout`). Pure numpy.
"""

from __future__ import annotations

import functools
import math
import re
from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from typing import Literal

import numpy as np
import numpy.typing as npt

from .layout import LEGEND_ROW_EM, MIN_TEXT_PX, ChartLayout, Rect, Theme, text_width
from .placement import AXIS_NAME_DROP_EM, AXIS_NAME_INSET_PX, place_labels, sub_px
from .vocabulary import Area, Chart, Dash, Item, Label, Points, Polyline, Segments, Style, rgb, unicode_subscript

FloatArray = npt.NDArray[np.float64]
Anchor = Literal["center-left", "center-right", "center-center", "top-left", "top-center", "top-right", "bottom-left"]
DotShape = Literal["circle", "diamond", "square"]

#: Dash patterns (on, off, on, off, ... in px at line width 2), as plotly draws them.
DASHES: dict[Dash, tuple[float, ...]] = {
    "solid": (),
    "dash": (9.0, 6.0),
    "dot": (2.5, 4.5),
    "dashdot": (9.0, 4.0, 2.5, 4.0),
}
#: Draw order, back to front: fills, grid, axes, curves, events, moving parts.
Layer = Literal[0, 1, 2, 3, 4, 5]
FILL, GRID, AXES, CURVES, EVENTS, MOVING = 0, 1, 2, 3, 4, 5
#: Filled areas are square dots on a grid this fine (px): a backend's lines may not reach pale
#: colours (viser's are tone-mapped), its dots do.
FILL_PX = 4.0


@dataclass(frozen=True)
class PageLines:
    """Straight segments of one width: ``points`` ``(n, 2, 2)`` (px, ``[x, z]``), ``colors`` ``(n, 3)``."""

    points: FloatArray
    colors: npt.NDArray[np.uint8]
    width: float
    layer: int


@dataclass(frozen=True)
class PageDots:
    xy: FloatArray
    """``(n, 2)`` centres (px)."""
    colors: npt.NDArray[np.uint8]
    size: float
    """Diameter (px)."""
    shape: DotShape
    layer: int = EVENTS


@dataclass(frozen=True)
class PageText:
    x: float
    z: float
    text: str
    px: float
    anchor: Anchor = "center-left"
    sub: bool = False
    """A subscript, drawn smaller and lower after its letter (:func:`page_texts`)."""
    joined: bool = False
    """A part of a label that touches the next one at its anchored edge (:func:`page_texts`): a
    backend that pads its texts draws this one's ink from ``x``."""


@dataclass(frozen=True)
class PagePicture:
    lines: tuple[PageLines, ...] = ()
    dots: tuple[PageDots, ...] = ()
    texts: tuple[PageText, ...] = ()

    def __add__(self, other: PagePicture) -> PagePicture:
        return PagePicture(self.lines + other.lines, self.dots + other.dots, self.texts + other.texts)


def color_rgb(color: str, opacity: float = 1.0, background: tuple[int, int, int] = (255, 255, 255)) -> np.ndarray:
    return _color_rgb(color, opacity, background).copy()


@functools.lru_cache(maxsize=512)
def _color_rgb(color: str, opacity: float, background: tuple[int, int, int]) -> np.ndarray:
    """``"#RRGGBB"`` or ``"rgba(r,g,b,a)"`` at ``opacity``, blended over ``background``: an opaque
    colour (the canvas draws no transparency, so overlaps never darken)."""
    m = re.fullmatch(r"rgba?\(([^)]*)\)", color.replace(" ", ""))
    if m:
        parts = [float(p) for p in m.group(1).split(",")]
        c = np.array(parts[:3])
        alpha = parts[3] if len(parts) > 3 else 1.0
    else:
        c = np.array(rgb(color), dtype=float)
        alpha = 1.0
    a = alpha * opacity
    return np.round(a * c + (1.0 - a) * np.asarray(background, dtype=float)).astype(np.uint8)


@dataclass(frozen=True)
class ChartFrame:
    """A chart's data ranges placed on a plot area: data -> page px."""

    plot: Rect
    x_range: tuple[float, float]
    y_range: tuple[float, float]

    def px_one(self, x: float, y: float) -> tuple[float, float]:
        """One point's page px (:meth:`px` in plain floats)."""
        (a, b), (c, d) = self.x_range, self.y_range
        p = self.plot
        return p.x0 + (float(x) - a) * (p.width / (b - a)), p.z0 + (float(y) - c) * (p.height / (d - c))

    def data_one(self, px: float, pz: float) -> tuple[float, float]:
        """The data coordinates at page px ``(px, pz)``: the inverse of :meth:`px_one`."""
        (a, b), (c, d) = self.x_range, self.y_range
        p = self.plot
        return a + (px - p.x0) * (b - a) / p.width, c + (pz - p.z0) * (d - c) / p.height

    def px(self, x: FloatArray, y: FloatArray) -> tuple[FloatArray, FloatArray]:
        (a, b), (c, d) = self.x_range, self.y_range
        p = self.plot
        return (
            p.x0 + (np.asarray(x, float) - a) * (p.width / (b - a)),
            p.z0 + (np.asarray(y, float) - c) * (p.height / (d - c)),
        )


def chart_frame(chart: Chart, plot: Rect) -> ChartFrame:
    """The chart's ranges on ``plot``; an equal-aspect chart (a Minkowski diagram) is widened along
    one axis so that one unit of x is as long as one unit of t (light at 45 degrees)."""
    (x0, x1), (y0, y1) = chart.x_range, chart.y_range
    if chart.equal_aspect and plot.width > 0 and plot.height > 0:
        per_x = plot.width / (x1 - x0)
        per_y = plot.height / (y1 - y0)
        if per_x > per_y:  # too wide: widen x
            half = 0.5 * plot.width / per_y
            c = 0.5 * (x0 + x1)
            x0, x1 = c - half, c + half
        else:
            half = 0.5 * plot.height / per_x
            c = 0.5 * (y0 + y1)
            y0, y1 = c - half, c + half
    return ChartFrame(plot, (x0, x1), (y0, y1))


def clip_segments(p0: FloatArray, p1: FloatArray, r: Rect) -> tuple[FloatArray, FloatArray]:
    """Segments ``p0 -> p1`` (``(n, 2)`` px) clipped to ``r`` (Liang-Barsky); those outside dropped."""
    a, b, _ = _clip_kept(p0, p1, r)
    return a, b


def _clip_kept(p0: FloatArray, p1: FloatArray, r: Rect) -> tuple[FloatArray, FloatArray, np.ndarray]:
    """:func:`clip_segments`, and which of the segments were kept."""
    if len(p0) <= 4:  # the moving lines, every frame: plain floats beat numpy's per-call cost
        clipped = [_clip_one(a, b, r) for a, b in zip(p0.tolist(), p1.tolist(), strict=True)]
        kept = [c for c in clipped if c is not None]
        a = np.array([c[0] for c in kept], dtype=float).reshape(-1, 2)
        b = np.array([c[1] for c in kept], dtype=float).reshape(-1, 2)
        return a, b, np.array([c is not None for c in clipped], dtype=bool)
    d = p1 - p0
    t0 = np.zeros(len(p0))
    t1 = np.ones(len(p0))
    keep = np.ones(len(p0), dtype=bool)
    for axis, lo, hi in ((0, r.x0, r.x1), (1, r.z0, r.z1)):
        for q_p, sign in ((p0[:, axis] - lo, -1.0), (hi - p0[:, axis], 1.0)):
            pp = sign * d[:, axis]
            parallel = pp == 0.0
            keep = keep & ~(parallel & (q_p < 0))
            t = q_p / np.where(parallel, 1.0, pp)
            entering = (pp < 0) & ~parallel
            leaving = (pp > 0) & ~parallel
            t0 = np.where(entering, np.maximum(t0, t), t0)
            t1 = np.where(leaving, np.minimum(t1, t), t1)
    keep = keep & (t0 <= t1)
    a = p0 + t0[:, None] * d
    b = p0 + t1[:, None] * d
    return a[keep], b[keep], keep


def _clip_one(a: list[float], b: list[float], r: Rect) -> tuple[list[float], list[float]] | None:
    """One segment clipped to ``r`` (Liang-Barsky), or None if it misses."""
    dx, dz = b[0] - a[0], b[1] - a[1]
    t0, t1 = 0.0, 1.0
    for p, q in ((-dx, a[0] - r.x0), (dx, r.x1 - a[0]), (-dz, a[1] - r.z0), (dz, r.z1 - a[1])):
        if p == 0.0:
            if q < 0.0:
                return None
            continue
        t = q / p
        if p < 0.0:
            t0 = max(t0, t)
        else:
            t1 = min(t1, t)
    if t0 > t1:
        return None
    return [a[0] + t0 * dx, a[1] + t0 * dz], [a[0] + t1 * dx, a[1] + t1 * dz]


def polyline_segments(x: FloatArray, z: FloatArray) -> tuple[FloatArray, FloatArray]:
    """A polyline (px) as its segments ``(n, 2)`` -> ``(n, 2)``, gaps (NaN) left out."""
    a, b, _ = _polyline_segments_kept(x, z)
    return a, b


def _polyline_segments_kept(x: FloatArray, z: FloatArray) -> tuple[FloatArray, FloatArray, np.ndarray]:
    """:func:`polyline_segments`, and which of the ``len(x) - 1`` segments were kept."""
    pts = np.stack([x, z], axis=-1)
    finite: npt.NDArray[np.bool_] = np.asarray(np.isfinite(pts).all(axis=-1))
    ok = finite[:-1] & finite[1:]
    return pts[:-1][ok], pts[1:][ok], ok


def dash_segments(
    a: FloatArray, b: FloatArray, pattern: tuple[float, ...], scale: float
) -> tuple[FloatArray, FloatArray]:
    """Segments ``a -> b`` (in order along a line) as they are drawn with a dash ``pattern``: all of
    them if it is empty, else cut into pieces of at most 1.5 px whose middles fall on the pattern's
    "on" parts (its lengths scaled by ``scale``, the line width over 2), measured along the line."""
    if not pattern or len(a) == 0:
        return a, b
    p0, p1, _ = _dash_lines(a, b, pattern, scale, np.arange(len(a)) == 0)
    return p0, p1


def _dash_lines(
    a: FloatArray, b: FloatArray, pattern: tuple[float, ...], scale: float, breaks: np.ndarray
) -> tuple[FloatArray, FloatArray, np.ndarray]:
    """:func:`dash_segments` of several lines at once: segment ``i`` starts a new line (its pattern
    afresh) where ``breaks[i]`` (``breaks[0]`` is true); also which segment each dash comes from."""
    seg_len = np.hypot(*(b - a).T)
    pieces = np.maximum(np.ceil(seg_len / 1.5), 1).astype(int)
    idx = np.repeat(np.arange(len(a)), pieces)
    k = np.arange(idx.size) - np.repeat(np.cumsum(pieces) - pieces, pieces)
    f0 = k / pieces[idx]
    f1 = (k + 1) / pieces[idx]
    along = np.concatenate([[0.0], np.cumsum(seg_len)[:-1]])  # from the first line's start
    start = along - along[np.maximum.accumulate(np.where(breaks, np.arange(len(a)), 0))]
    mid = start[idx] + 0.5 * (f0 + f1) * seg_len[idx]
    pat = np.asarray(pattern) * scale
    phase = np.mod(mid, pat.sum())
    on = (np.searchsorted(np.cumsum(pat), phase, side="right") % 2) == 0
    d = (b - a)[idx]
    p0 = a[idx] + f0[:, None] * d
    p1 = a[idx] + f1[:, None] * d
    # one segment per dash (per dash and original segment): consecutive "on" pieces joined
    k_on = np.flatnonzero(on)
    if k_on.size == 0:
        return p0[:0], p1[:0], idx[:0]
    new_run = np.ones(k_on.size, dtype=bool)
    new_run[1:] = (np.diff(k_on) != 1) | (idx[k_on[1:]] != idx[k_on[:-1]])
    starts = k_on[new_run]
    ends = k_on[np.append(new_run[1:], True)]
    return p0[starts], p1[ends], idx[starts]


def dashed(x: FloatArray, z: FloatArray, pattern: tuple[float, ...], scale: float) -> tuple[FloatArray, FloatArray]:
    """A polyline (px) as the segments it is drawn with in a dash ``pattern`` (:func:`dash_segments`)."""
    a, b = polyline_segments(x, z)
    return dash_segments(a, b, pattern, scale)


def fill_grid(x: FloatArray, z: FloatArray, r: Rect, step: float = FILL_PX) -> FloatArray:
    """Centres ``(n, 2)`` of ``step``-px squares that fill a closed polygon (px) inside ``r``."""
    a, b = scan_fill(x, z, r, step)
    if len(a) == 0:
        return np.zeros((0, 2))
    counts = np.maximum(np.round((b[:, 0] - a[:, 0]) / step).astype(int), 1)
    idx = np.repeat(np.arange(len(a)), counts)
    k = np.arange(idx.size) - np.repeat(np.cumsum(counts) - counts, counts)
    width = b[:, 0] - a[:, 0]
    xs = a[idx, 0] + (k + 0.5) * (width[idx] / counts[idx])
    return np.stack([xs, a[idx, 1]], -1)


def scan_fill(x: FloatArray, z: FloatArray, r: Rect, step: float = FILL_PX) -> tuple[FloatArray, FloatArray]:
    """A closed polygon (px) filled with horizontal segments every ``step`` px (even-odd rule),
    inside ``r``."""
    xs = np.append(x, x[0])
    zs = np.append(z, z[0])
    ok = np.isfinite(xs) & np.isfinite(zs)
    xs, zs = xs[ok], zs[ok]
    if xs.size < 3:
        empty = np.zeros((0, 2))
        return empty, empty
    lo, hi = max(float(zs.min()), r.z0), min(float(zs.max()), r.z1)
    rows = np.arange(math.ceil(lo / step) * step, hi, step) if hi > lo else np.zeros(0)
    if rows.size == 0:
        empty = np.zeros((0, 2))
        return empty, empty
    a0, a1 = xs[:-1], xs[1:]
    b0, b1 = zs[:-1], zs[1:]
    c = rows[:, None]  # every row against every edge at once: (rows, edges)
    cross = ((b0 <= c) & (b1 > c)) | ((b1 <= c) & (b0 > c))
    with np.errstate(divide="ignore", invalid="ignore"):
        t = (c - b0) / (b1 - b0)
    xi = np.where(cross, a0 + t * (a1 - a0), np.inf)
    xi.sort(axis=1)
    n = int(cross.sum(axis=1).max(initial=0)) // 2 * 2
    left, right = xi[:, 0:n:2], xi[:, 1:n:2]
    ok = np.isfinite(left) & np.isfinite(right)
    left, right = np.clip(left, r.x0, r.x1), np.clip(right, r.x0, r.x1)
    ok &= right > left
    zz = np.broadcast_to(c, left.shape)
    return np.stack([left[ok], zz[ok]], -1), np.stack([right[ok], zz[ok]], -1)


def _lines(p0: FloatArray, p1: FloatArray, color: np.ndarray, width: float, layer: int) -> PageLines:
    pts = np.stack([p0, p1], axis=1)
    return PageLines(pts, np.tile(color, (len(pts), 1)).astype(np.uint8), width, layer)


def line_width(style: Style, theme: Theme) -> float:
    """A diagram line's width on the canvas: its plotly width scaled by the theme, never under its thinnest."""
    return round(max(theme.line_px, style.width * theme.line_scale), 1)


def page_text(text: str) -> str:
    """Plotly's small HTML subset as plain canvas text: a subscript in Unicode subscripts where each
    of its characters has one (``T<sub>1</sub>`` -> ``T₁``), else after an underscore (``T_B``)."""

    def sub(m: re.Match[str]) -> str:
        s = m.group(1)
        t = unicode_subscript(s)
        return f"_{s}" if t is None else t

    text = re.sub(r"<sub>(.*?)</sub>", sub, text)
    return re.sub(r"</?b>", "", text)


#: Advance widths of Arial, per em: the first font of viser's label stack that Windows and Linux
#: pages have (Debian's fontconfig gives Liberation Sans, metrically the same). Used to place the
#: parts of a label around its subscript; another font's widths differ by a few per cent, which
#: moves the label by as much, never the subscript against its letter (:func:`page_texts`).
_ARIAL_EM = {
    **dict.fromkeys("0123456789", 0.556),
    **dict.fromkeys("ABEKPSVXY", 0.667),
    **dict.fromkeys("CDHNRUw", 0.722),
    **dict.fromkeys("GOQ", 0.778),
    **dict.fromkeys("FTZ", 0.611),
    **dict.fromkeys("abdeghnopqu", 0.556),
    **dict.fromkeys("cksvxyz", 0.5),
    **dict.fromkeys("fIt ,.", 0.278),
    **dict.fromkeys("ijl", 0.222),
    **dict.fromkeys("Mm", 0.833),
    **dict.fromkeys("()r", 0.333),
    **dict.fromkeys("−+=", 0.584),
    "W": 0.944,
    "J": 0.5,
    "L": 0.556,
    "′": 0.25,
    "'": 0.191,
}
_MEAN_EM = 0.556
#: A subscript's middle sits this many font sizes below its letter's (plotly's ``<sub>`` drops
#: about 0.3 em).
SUB_DROP_EM = 0.3
_RUN = re.compile(r"<sub>(.*?)</sub>")


def _width_px(text: str, px: float) -> float:
    return px * sum(_ARIAL_EM.get(ch, _MEAN_EM) for ch in text)


def page_texts(x: float, z: float, text: str, px: float, anchor: Anchor) -> tuple[PageText, ...]:
    """One line of the vocabulary's small HTML subset as canvas texts, a subscript drawn as a text of
    its own, smaller (:func:`~.placement.sub_px`) and lowered by :data:`SUB_DROP_EM`, as the paper
    and plotly write it, so that T<sub>B</sub>, T<sub>1</sub> and T′<sub>1</sub> look alike (Unicode
    has subscript digits but no subscript capitals). The first part ends where the second starts,
    both anchored at that point, so a subscript touches its letter in any font; the whole is placed
    at ``anchor`` with :data:`_ARIAL_EM` widths. A text without a subscript is one text."""
    text = re.sub(r"</?b>", "", text)
    if "<sub>" not in text or not anchor.startswith("center-"):
        return (PageText(x, z, page_text(text), px, anchor),)
    runs: list[tuple[str, bool]] = []
    at = 0
    for m in _RUN.finditer(text):
        runs += [(text[at : m.start()], False), (m.group(1), True)]
        at = m.end()
    runs.append((text[at:], False))
    parts = [(run, sub_px(px) if sub else px, z - SUB_DROP_EM * px if sub else z, sub) for run, sub in runs if run]
    widths = [_width_px(run, size) for run, size, _, _ in parts]
    start = {"center-left": x, "center-right": x - sum(widths), "center-center": x - 0.5 * sum(widths)}[anchor]
    joint = start + widths[0]
    run, size, zr, sub = parts[0]
    out = [PageText(joint, zr, run, size, "center-right", sub, joined=True)]
    for (run, size, zr, sub), w in zip(parts[1:], widths[1:], strict=True):
        out.append(PageText(joint, zr, run, size, "center-left", sub, joined=True))
        joint += w
    return tuple(out)


def _dot_shape(symbol: str) -> DotShape:
    return "diamond" if symbol.startswith("diamond") else "square" if symbol.startswith("square") else "circle"


def items_picture(items: Iterable[Item], f: ChartFrame, theme: Theme, layer: int | None = None) -> PagePicture:
    """Curves, segments, fills, dots and labels of a chart, clipped to its plot area.

    Every solid line (curves, separate segments, labels' leader lines) is stroked in one go: their
    segments gathered in the items' order, mapped to px, clipped together and cut into runs of one
    width and layer; the dashed ones are clipped together and dashed per pattern and width, each
    line's pattern running along it from its first segment kept (a separate segment's from its
    own start). The segments, colours, widths and layers, in order, are those of stroking each
    item alone."""
    curves_layer = CURVES if layer is None else layer
    events_layer = EVENTS if layer is None else layer
    strokes = _Strokes(f, theme)
    dots: list[PageDots] = []
    texts: list[PageText] = []
    for it in items:
        if isinstance(it, Polyline):
            strokes.add_polyline(it.x, it.y, it.style, curves_layer)
        elif isinstance(it, Segments):
            strokes.add_segments(it, curves_layer)
        elif isinstance(it, Area):
            x, z = f.px(it.x, it.y)
            xy = fill_grid(x, z, f.plot)
            if len(xy):
                color = color_rgb(it.style.color, it.style.opacity)
                dots.append(PageDots(xy, np.tile(color, (len(xy), 1)), FILL_PX + 0.5, "square", FILL))
        elif isinstance(it, Points):
            x, z = f.px(it.x, it.y)
            inside = (x >= f.plot.x0) & (x <= f.plot.x1) & (z >= f.plot.z0) & (z <= f.plot.z1)
            if inside.any():
                xy = np.stack([x[inside], z[inside]], -1)
                color = color_rgb(it.style.color, it.style.opacity)
                size = max(it.size * theme.line_scale * 1.2, 0.6 * theme.text_px)
                dots.append(
                    PageDots(
                        xy,
                        np.tile(color, (len(xy), 1)),
                        size,
                        _dot_shape(it.symbol),
                        events_layer,
                    )
                )
        else:
            assert isinstance(it, Label)
            xv, zv = f.px_one(it.x, it.y)
            if f.plot.x0 <= xv <= f.plot.x1 and f.plot.z0 <= zv <= f.plot.z1:
                if it.offset_px is not None:  # placed clear of the others (placement: right and up, px)
                    dx, dz = it.offset_px
                    if it.leader:
                        reach = math.hypot(dx, dz)
                        keep = max(0.0, 1.0 - 0.7 * theme.text_px / reach) if reach > 0 else 0.0
                        end = (np.array([xv, xv + keep * dx]), np.array([zv, zv + keep * dz]))
                        strokes.add_px(end[0], end[1], Style(it.style.color, 1.0), events_layer)
                    xv, zv = xv + dx, zv + dz
                offset = {"left": 0.4 * theme.text_px, "right": -0.4 * theme.text_px, "center": 0.0}[it.anchor]
                anchor: Anchor = {"left": "center-left", "right": "center-right", "center": "center-center"}[it.anchor]  # type: ignore[assignment]
                # a placed label at its own size: smaller than the theme's in a crowded plot
                px = min(it.size, theme.text_px) if it.movable else theme.text_px
                texts.extend(page_texts(xv + offset, zv, it.text, px, anchor))
    return PagePicture(strokes.lines(), tuple(dots), tuple(texts))


class _Strokes:
    """The lines of a chart's items on its page (``f``: data -> px), gathered in order and stroked
    at the end (:func:`items_picture`): the solid ones all at once, the dashed ones at once per
    pattern and width."""

    def __init__(self, f: ChartFrame, theme: Theme) -> None:
        self._f = f
        self._theme = theme
        self._solid_curves: list[tuple[FloatArray, FloatArray, int]] = []
        """Solid polylines in data coordinates (mapped to px together), each with its stroke's number."""
        self._solid: list[tuple[FloatArray, FloatArray, int]] = []
        """Solid segments already in px, ``(n, 2)`` starts and ends: separate segments, leader lines."""
        self._dashed: list[tuple[FloatArray, FloatArray, bool, int]] = []
        """Dashed segments in px, and whether each is a line of its own (else they make one line)."""
        self._styles: list[tuple[Style, int]] = []
        """Each stroke's style and layer, by number."""

    def _add(self, a: FloatArray, b: FloatArray, apart: bool, style: Style, layer: int) -> None:
        """Segments in px: one line, or (``apart``) each a line of its own."""
        self._styles.append((style, layer))
        k = len(self._styles) - 1
        if DASHES[style.dash]:
            self._dashed.append((a, b, apart, k))
        else:
            self._solid.append((a, b, k))

    def add_polyline(self, x: FloatArray, y: FloatArray, style: Style, layer: int) -> None:
        if DASHES[style.dash]:
            self._add(*polyline_segments(*self._f.px(x, y)), False, style, layer)
        else:
            self._styles.append((style, layer))
            self._solid_curves.append((np.asarray(x, float), np.asarray(y, float), len(self._styles) - 1))

    def add_px(self, x: FloatArray, z: FloatArray, style: Style, layer: int) -> None:
        """A polyline already in px (a label's leader line)."""
        self._add(*polyline_segments(x, z), False, style, layer)

    def add_segments(self, it: Segments, layer: int) -> None:
        self._add(*_segments_px(it, self._f), True, it.style, layer)

    def lines(self) -> tuple[PageLines, ...]:
        """Every stroke's segments, clipped to the plot, in the order the strokes were added, as runs
        of one width and layer."""
        f, theme = self._f, self._theme
        parts_a: list[FloatArray] = [a for a, _, _ in self._solid]
        parts_b: list[FloatArray] = [b for _, b, _ in self._solid]
        parts_k: list[np.ndarray] = [np.full(len(a), k) for a, _, k in self._solid]
        if self._solid_curves:
            curves = [f.px(cx, cy) for cx, cy, _ in self._solid_curves]
            x, z = _joined(curves)
            # each point's stroke (a gap's too: no segment starts there)
            sizes = [cx.size + 1 for cx, _ in curves]
            owner = np.repeat(np.array([k for _, _, k in self._solid_curves]), sizes)[: x.size]
            a, b, ok = _polyline_segments_kept(x, z)
            parts_a.append(a)
            parts_b.append(b)
            parts_k.append(owner[:-1][ok])
        if parts_a:
            a, b, keep = _clip_kept(np.concatenate(parts_a), np.concatenate(parts_b), f.plot)
            parts_a, parts_b, parts_k = [a], [b], [np.concatenate(parts_k)[keep]]
        if self._dashed:
            starts = np.concatenate([sa for sa, _, _, _ in self._dashed])
            ends = np.concatenate([sb for _, sb, _, _ in self._dashed])
            a, b, keep = _clip_kept(starts, ends, f.plot)
            owner = np.concatenate([np.full(len(sa), k) for sa, _, _, k in self._dashed])[keep]
            # a line starts at its first segment kept (clipping may drop its first ones); a separate
            # segment is a line of its own
            apart = np.concatenate([np.full(len(sa), own) for sa, _, own, _ in self._dashed])[keep]
            first = apart | np.concatenate([[True], owner[1:] != owner[:-1]])
            groups: dict[tuple[tuple[float, ...], float], list[int]] = {}
            for _, _, _, k in self._dashed:
                style = self._styles[k][0]
                groups.setdefault((DASHES[style.dash], line_width(style, theme)), []).append(k)
            for (pattern, width), ks in groups.items():  # each pattern and width: its lines at once
                mine = np.isin(owner, ks) if len(groups) > 1 else slice(None)
                da, db, src = _dash_lines(a[mine], b[mine], pattern, width / 2.0, first[mine])
                parts_a.append(da)
                parts_b.append(db)
                parts_k.append(owner[mine][src])
        k_all = np.concatenate(parts_k) if parts_k else np.zeros(0, int)
        if k_all.size == 0:
            return ()
        order = np.argsort(k_all, kind="stable")  # the items' order, each item's segments in theirs
        k_all = k_all[order]
        pts = np.stack([np.concatenate(parts_a)[order], np.concatenate(parts_b)[order]], axis=1)
        keys = [(line_width(st, theme), layer) for st, layer in self._styles]
        colors = np.array([color_rgb(st.color, st.opacity) for st, _ in self._styles], dtype=np.uint8)[k_all]
        key_index = {key: n for n, key in enumerate(dict.fromkeys(keys))}
        run_key = np.array([key_index[key] for key in keys])[k_all]  # each segment's width and layer
        cuts = (np.flatnonzero(run_key[1:] != run_key[:-1]) + 1).tolist()
        out: list[PageLines] = []
        for lo, hi in zip([0, *cuts], [*cuts, len(k_all)], strict=True):
            w, layer = keys[int(k_all[lo])]
            out.append(PageLines(pts[lo:hi], colors[lo:hi], w, layer))
        return tuple(out)


def _segments_px(it: Segments, f: ChartFrame) -> tuple[FloatArray, FloatArray]:
    """A Segments item's finite segments in px, ``(n, 2)`` starts and ends."""
    x0, z0 = f.px(it.x0, it.y0)
    x1, z1 = f.px(it.x1, it.y1)
    a, b = np.stack([x0, z0], -1), np.stack([x1, z1], -1)
    ok = np.isfinite(a).all(axis=-1) & np.isfinite(b).all(axis=-1)
    return a[ok], b[ok]


def _joined(curves: list[tuple[FloatArray, FloatArray]]) -> tuple[FloatArray, FloatArray]:
    """Polylines (px) as one, a NaN between each two: no segment joins them, and a solid stroke
    of it is the strokes of each, in order."""
    if len(curves) == 1:
        return curves[0]
    gap = np.array([np.nan])
    xs: list[FloatArray] = []
    zs: list[FloatArray] = []
    for x, z in curves:
        xs += [x, gap]
        zs += [z, gap]
    return np.concatenate(xs[:-1]), np.concatenate(zs[:-1])


#: Every axis of a chart carries at least this many numbered ticks (a scale is read between two
#: numbers; a third shows it is even).
MIN_AXIS_TICKS = 3
#: The round steps, 1, 2 or 5 times a power of ten, as multiples of their power of ten.
_NICE = (1.0, 2.0, 5.0, 10.0)


def nice_ticks(lo: float, hi: float, count: float, minimum: int = MIN_AXIS_TICKS) -> FloatArray:
    """Round numbers (1, 2 or 5 times a power of ten apart) in ``[lo, hi]``, about ``count`` of them
    and never fewer than ``minimum``: the step is the smallest round one at least ``(hi - lo) / count``,
    then the next smaller round step while fewer than ``minimum`` ticks fall in the range."""
    span = hi - lo
    if not (math.isfinite(span) and span > 0):
        return np.zeros(0)
    raw = span / max(count, 1.0)
    power = math.floor(math.log10(raw))
    k = next(i for i, m in enumerate(_NICE) if m * 10.0**power >= raw)
    while True:
        step = _NICE[k] * 10.0**power
        ticks = np.arange(math.ceil(lo / step) * step, hi + 1e-9 * span, step)
        if ticks.size >= minimum or step <= span * 1e-6:
            return np.round(ticks / step) * step
        k -= 1
        if k < 0:
            k, power = len(_NICE) - 2, power - 1


def tick_text(values: FloatArray) -> list[str]:
    """Tick numbers with as many decimals as their spacing needs (never ``-0``)."""
    if values.size < 2:
        return [f"{v + 0.0:g}" for v in values]
    step = float(np.min(np.diff(values)))
    decimals = max(0, -math.floor(math.log10(step) + 1e-9)) if step > 0 else 0
    return [f"{round(v, decimals) + 0.0:.{decimals}f}" for v in values]


def wrap(text: str, px: float, width: float) -> str:
    """``text`` on two lines (broken after its first ", ", or at the middle space) if one would be
    wider than ``width`` px."""
    if text_width(text, px) <= width or " " not in text:
        return text
    if ", " in text:
        head, tail = text.split(", ", 1)
        return f"{head},\n{tail}"
    words = text.split(" ")
    half = len(words) // 2
    return " ".join(words[:half]) + "\n" + " ".join(words[half:])


def axes_picture(chart: Chart, f: ChartFrame, layout: ChartLayout, theme: Theme) -> PagePicture:
    """The frame of the plot area, a faint grid at round numbers, their numbers, the axis names
    (t and x, or t′ and x′) at the axes' ends and the chart's title above. A chart without axis
    names (a hidden panel's note) gets its title only."""
    p = f.plot
    title = PageText(
        layout.outer.x0 + 2.0,
        layout.outer.z1,
        wrap(page_text(chart.title), theme.title_px, layout.outer.width),
        theme.title_px,
        "top-left",
    )
    if not chart.x_title and not chart.y_title:
        return PagePicture((), (), (title,))
    ink = color_rgb(theme.ink)
    grid = color_rgb(theme.grid)
    xt = nice_ticks(*f.x_range, p.width / (5.5 * theme.text_px))
    yt = nice_ticks(*f.y_range, p.height / (3.0 * theme.text_px))
    xs, _ = f.px(xt, np.zeros_like(xt))
    _, zs = f.px(np.zeros_like(yt), yt)
    g0 = np.concatenate([np.stack([xs, np.full(xs.size, p.z0)], -1), np.stack([np.full(zs.size, p.x0), zs], -1)])
    g1 = np.concatenate([np.stack([xs, np.full(xs.size, p.z1)], -1), np.stack([np.full(zs.size, p.x1), zs], -1)])
    box0 = np.array([[p.x0, p.z0], [p.x0, p.z0], [p.x1, p.z0], [p.x0, p.z1]])
    box1 = np.array([[p.x1, p.z0], [p.x0, p.z1], [p.x1, p.z1], [p.x1, p.z1]])
    tick = 0.35 * theme.text_px
    t0 = np.concatenate([np.stack([xs, np.full(xs.size, p.z0)], -1), np.stack([np.full(zs.size, p.x0), zs], -1)])
    t1 = np.concatenate(
        [np.stack([xs, np.full(xs.size, p.z0 - tick)], -1), np.stack([np.full(zs.size, p.x0 - tick), zs], -1)]
    )
    lines = (
        _lines(g0, g1, grid, max(1.0, 0.5 * theme.line_px), GRID),
        _lines(np.concatenate([box0, t0]), np.concatenate([box1, t1]), ink, 0.75 * theme.line_px, AXES),
    )
    texts: list[PageText] = []
    for x, s in zip(xs, tick_text(xt), strict=True):
        texts.append(PageText(float(x), p.z0 - tick - 0.1 * theme.text_px, s, theme.text_px, "top-center"))
    for z, s in zip(zs, tick_text(yt), strict=True):
        texts.append(PageText(p.x0 - tick - 3.0, float(z), s, theme.text_px, "center-right"))
    # axis names at the axes' far ends, inside the plot (where a physicist writes them; the event
    # labels are placed clear of them, placement.axis_name_boxes)
    inset, drop = AXIS_NAME_INSET_PX, AXIS_NAME_DROP_EM * theme.text_px
    texts.extend(page_texts(p.x1 - inset, p.z0 + drop, chart.x_title, theme.text_px, "center-right"))
    texts.extend(page_texts(p.x0 + inset, p.z1 - drop, chart.y_title, theme.text_px, "center-left"))
    texts.append(title)
    return PagePicture(lines, (), tuple(texts))


def chart_picture(chart: Chart, layout: ChartLayout, theme: Theme) -> tuple[ChartFrame, PagePicture]:
    """Everything of a chart that does not move with playback, and its data -> px frame."""
    f = chart_frame(chart, layout.plot)
    area = (f.plot.width, f.plot.height)
    if chart.area_px != area and any(isinstance(i, Label) and i.movable for i in chart.items):
        # the event labels placed again for this plot area (unless they were placed for it already)
        chart = place_labels(chart, area, MIN_TEXT_PX)
    return f, axes_picture(chart, f, layout, theme) + items_picture(chart.items, f, theme)


@dataclass(frozen=True)
class LegendEntry:
    name: str
    style: Style
    dot: DotShape | None = None
    """A dot's shape for a marker's entry, ``None`` for a line's."""


def legend_entries(items: Iterable[Item]) -> list[LegendEntry]:
    """Named items, each name once, in order; and each look once per body: an entry that draws as
    an earlier one of the same body does (its colour, dash and dot) is that entry again (the
    length panel's "rod 1, lab (t)", solid blue, is the diagrams' "rod 1"), so the legend keeps
    the first and the frames that differ ("rod 1, barycentric (t′)", dashed)."""
    out: dict[str, LegendEntry] = {}
    for it in items:
        if isinstance(it, Label) or it.style.name is None or it.style.name in out:
            continue
        dot = _dot_shape(it.symbol) if isinstance(it, Points) else None
        body = out.get(it.style.name.split(", ")[0])
        if body is not None and (body.style.color, body.style.dash, body.dot) == (it.style.color, it.style.dash, dot):
            continue
        out[it.style.name] = LegendEntry(it.style.name, it.style, dot)
    return list(out.values())


def legend_rows(entries: Sequence[LegendEntry], width: float, theme: Theme) -> int:
    """How many rows the legend needs across ``width`` px."""
    swatch = 2.0 * theme.text_px
    rows, x = 1, 0.0
    for e in entries:
        w = swatch + 6.0 + text_width(page_text(e.name), theme.text_px) + 1.2 * theme.text_px
        if x + w > width and x > 0:
            rows, x = rows + 1, 0.0
        x += w
    return rows


def legend_picture(entries: Sequence[LegendEntry], box: Rect, theme: Theme) -> PagePicture:
    """Entries left to right, wrapped into the rows ``box`` holds: a swatch, then the name. The same
    entries in the same box give the same picture (a slider's redraw keeps its scene's legend)."""
    return _legend_picture(tuple(entries), box, theme)


@functools.lru_cache(maxsize=32)
def _legend_picture(entries: tuple[LegendEntry, ...], box: Rect, theme: Theme) -> PagePicture:
    row_h = LEGEND_ROW_EM * theme.text_px
    swatch = 2.0 * theme.text_px
    x, z = box.x0, box.z1 - 0.5 * row_h
    lines: list[PageLines] = []
    dots: list[PageDots] = []
    texts: list[PageText] = []
    for e in entries:
        name = page_text(e.name)
        w = swatch + 6.0 + text_width(name, theme.text_px) + 1.2 * theme.text_px
        if x + w > box.x1 and x > box.x0:
            x, z = box.x0, z - row_h
        if z < box.z0:
            break
        color = color_rgb(e.style.color, e.style.opacity)
        if e.dot is not None:
            dots.append(
                PageDots(np.array([[x + 0.5 * swatch, z]]), color[None, :], 0.75 * theme.text_px, e.dot, EVENTS)
            )
        elif e.style.width <= 0:  # a filled area
            dots.append(
                PageDots(np.array([[x + 0.5 * swatch, z]]), color[None, :], 0.8 * theme.text_px, "square", FILL)
            )
        else:
            width = line_width(e.style, theme)
            a, b = dashed(np.array([x, x + swatch]), np.array([z, z]), DASHES[e.style.dash], width / 2.0)
            lines.append(_lines(a, b, color, width, CURVES))
        texts.extend(page_texts(x + swatch + 6.0, z, e.name, theme.text_px, "center-left"))
        x += w
    return PagePicture(tuple(lines), tuple(dots), tuple(texts))


def still_picture(
    charts: Sequence[Chart],
    chart_places: Sequence[ChartLayout | None],
    legend: Sequence[LegendEntry],
    box: Rect,
    theme: Theme,
) -> tuple[tuple[ChartFrame | None, ...], PagePicture]:
    """What a page shows that does not move with playback: each shown chart's picture
    (:func:`chart_picture`, on its place; a place ``None`` is a chart not shown) and the legend's
    (in ``box``); and each chart's data -> px frame, on which its moving parts are drawn
    (:func:`moving_picture`), ``None`` for a chart not shown."""
    frames: list[ChartFrame | None] = []
    picture = PagePicture()
    for chart, place in zip(charts, chart_places, strict=True):
        if place is None:
            frames.append(None)
            continue
        f, p = chart_picture(chart, place, theme)
        frames.append(f)
        picture += p
    return tuple(frames), picture + legend_picture(legend, box, theme)


def moving_picture(frames: Sequence[ChartFrame | None], items: Sequence[Iterable[Item]], theme: Theme) -> PagePicture:
    """The shown charts' moving parts at one instant (``items``: each chart's, on its frame; a
    frame ``None``: a chart not shown), in the :data:`MOVING` layer."""
    picture = PagePicture()
    for f, its in zip(frames, items, strict=True):
        if f is None:
            continue
        picture += items_picture(its, f, theme, MOVING)
    return picture
