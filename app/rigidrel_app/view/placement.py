"""Labels that overprint nothing: a deterministic placement of a chart's movable labels.

Everything is worked out in the pixel space of the chart's plot area (``area_px`` CSS pixels
wide and high, y down): data ``(x, y)`` maps to ``((x - x0) / (x1 - x0) W, (y1 - y) / (y1 - y0) H)``.
A label's text is estimated as a box (:func:`text_box_px`). Each movable label, in the chart's
order, takes the first of its candidate spots (:func:`candidate_offsets`: beside, above, below and
on the diagonals of its point, then the same directions farther out, where a leader line joins
the text to its point) whose box stays in the plot area and meets no other label's box, no
marker and no drawn curve, and lies nearer its own point than any other marker (the text names the
point nearest it). When every spot meets something, the label takes the spot that meets
no label or marker and crosses the fewest curve segments, with a leader line. Fixed labels and
the axis names the canvas writes inside the plot are obstacles and never move. A plot where some
label finds no spot clear of the others is placed again with those labels first, and then, if
asked, with its labels a step smaller (:func:`place_labels`). Nothing here depends on a plotting
library: every backend draws the placed offsets.
"""

from __future__ import annotations

import dataclasses
import re
from dataclasses import dataclass, replace
from functools import lru_cache

import numpy as np

from .layout import MIN_TEXT_PX
from .vocabulary import Chart, FloatArray, Item, Label, Points, Polyline, Segments

#: Width of one character of bold text, per font size (sans-serif bold digits and capitals are
#: about 0.62 em; a safe upper bound, so that estimated boxes hold the drawn text).
CHAR_EM = 0.66
#: Subscripts are drawn at this fraction of the font size on the canvas, and never under the
#: canvas's least text size (:func:`sub_px`); plotly's ``<sub>`` is 0.7 of it, inside the estimate.
SUB_SCALE = 0.8
#: Height of a text box per font size (a line plus a subscript's drop).
LINE_EM = 1.45
#: Clear space between a point and the nearest edge of its label, CSS pixels (beyond half a marker).
GAP_PX = 6.0
#: Room kept around a box when testing it against curves and other boxes, CSS pixels.
MARGIN_PX = 3.0
#: A marker's box per its size: the app's canvas draws markers this much larger than plotly does
#: (:func:`rigidrel_app.view.canvas.items_picture`: size x line scale 4/3 x 1.2), so text clear of
#: the larger one is clear of both.
MARKER_SCALE = 1.6
#: Rings of candidate spots: the first touches the point, the others need a leader line.
RINGS = 6
#: Rings tried when none of the first :data:`RINGS` has a spot clear of labels and markers.
FAR_RINGS = 12
#: The canvas writes each axis's name inside the plot, at the axis's far end
#: (:func:`rigidrel_app.view.canvas.axes_picture`): x's at the bottom right, y's at the top left,
#: this far in from the plot's side (px), its middle this many font sizes from the bottom or top.
AXIS_NAME_INSET_PX = 4.0
AXIS_NAME_DROP_EM = 0.8


@dataclass(frozen=True)
class Box:
    """An axis-aligned box in plot-area pixels (y down)."""

    left: float
    top: float
    right: float
    bottom: float

    def grown(self, by: float) -> Box:
        return Box(self.left - by, self.top - by, self.right + by, self.bottom + by)

    def meets(self, other: Box) -> bool:
        return (
            self.left < other.right and other.left < self.right and self.top < other.bottom and other.top < self.bottom
        )

    def inside(self, width: float, height: float) -> bool:
        return self.left >= 0.0 and self.top >= 0.0 and self.right <= width and self.bottom <= height


def sub_px(size: float) -> float:
    """A subscript's font size (CSS px) after text of ``size``: :data:`SUB_SCALE` of it, and at
    least :data:`~.layout.MIN_TEXT_PX` (the least any text on the canvas is drawn at, for the back of
    a hall), never larger than the text itself."""
    return min(size, max(SUB_SCALE * size, MIN_TEXT_PX))


_TAG = re.compile(r"<sub>(.*?)</sub>|<[^>]+>")


def text_box_px(text: str, size: float) -> tuple[float, float]:
    """The (width, height) in CSS pixels that ``text`` (the vocabulary's small HTML subset) takes at
    font ``size``: ``CHAR_EM * size`` per character, subscripts at :func:`sub_px` (the
    canvas draws a subscript as a smaller text of its own, :func:`~.canvas.page_texts`)."""
    subscript = sum(len(m.group(1)) for m in _TAG.finditer(text) if m.group(1))
    width = CHAR_EM * (size * len(_TAG.sub("", text)) + sub_px(size) * subscript)
    return width, LINE_EM * size


def candidate_offsets(
    width: float, height: float, size: float, first: str = "left", rings: int = RINGS
) -> list[tuple[float, float, bool]]:
    """Where a label's centre may go relative to its point, (right, up) CSS pixels, in the order tried,
    each with whether it needs a leader line. Ring 0 touches the point: beside it, above and below
    it (centred, then starting or ending at it), on the diagonals. Rings 1.. repeat the directions
    farther out. ``first`` is the label's own anchor: ``"left"`` (text starting right of the point,
    the old default) tries the right side first, ``"right"`` the left."""
    hw, hh = 0.5 * width, 0.5 * height
    sides = [
        (1.0, 0.0),
        (-1.0, 0.0),
        (0.0, 1.0),
        (0.0, -1.0),
        (1.0, 1.0),
        (-1.0, 1.0),
        (1.0, -1.0),
        (-1.0, -1.0),
    ]
    if first == "right":
        sides = [(-sx, sy) for sx, sy in sides]
    out: list[tuple[float, float, bool]] = []
    for ring in range(rings):
        gap = GAP_PX + ring * 1.2 * size
        for sx, sy in sides:
            out.append((sx * (hw + gap), sy * (hh + gap), ring > 0))
        if ring == 0:  # above and below, the text starting or ending at the point
            for sy in (1.0, -1.0):
                for sx in (1.0, -1.0) if first != "right" else (-1.0, 1.0):
                    out.append((sx * (hw - 0.5 * size), sy * (hh + gap), False))
    return out


def _to_px(chart: Chart, area: tuple[float, float], x: FloatArray, y: FloatArray) -> tuple[FloatArray, FloatArray]:
    (x0, x1), (y0, y1) = chart.x_range, chart.y_range
    return (x - x0) / (x1 - x0) * area[0], (y1 - y) / (y1 - y0) * area[1]


def _to_px_one(chart: Chart, area: tuple[float, float], x: float, y: float) -> tuple[float, float]:
    """One point's plot-area px (:func:`_to_px` in plain floats)."""
    (x0, x1), (y0, y1) = chart.x_range, chart.y_range
    return (float(x) - x0) / (x1 - x0) * area[0], (y1 - float(y)) / (y1 - y0) * area[1]


@dataclass(frozen=True)
class Obstacles:
    """What a label must not cover, in plot-area pixels: curve segments and marker boxes."""

    sx0: FloatArray
    sy0: FloatArray
    sx1: FloatArray
    sy1: FloatArray
    markers: tuple[Box, ...]

    def crossings(self, box: Box) -> int:
        """How many curve segments enter ``box``: those whose bounding box meets it and whose line does
        not leave all four corners on one side (:meth:`_Curves.crossings` for one box)."""
        return int(_Curves.of(self).crossings(_Boxes.of([box]))[0])


def _leader_end(ax: float, ay: float, box: Box) -> tuple[float, float]:
    """Where a leader line from ``(ax, ay)`` towards the centre of ``box`` meets its edge."""
    cx, cy = 0.5 * (box.left + box.right), 0.5 * (box.top + box.bottom)
    dx, dy = cx - ax, cy - ay
    hw, hh = 0.5 * (box.right - box.left), 0.5 * (box.bottom - box.top)
    scale = max(abs(dx) / hw if hw > 0 else 0.0, abs(dy) / hh if hh > 0 else 0.0, 1e-12)
    return cx - dx / scale, cy - dy / scale


@dataclass(frozen=True)
class _Boxes:
    """Axis-aligned boxes as arrays (plot-area pixels, y down), tested against many at once."""

    left: FloatArray
    top: FloatArray
    right: FloatArray
    bottom: FloatArray

    @staticmethod
    def of(boxes: list[Box] | tuple[Box, ...]) -> _Boxes:
        a = np.array([(b.left, b.top, b.right, b.bottom) for b in boxes], float).reshape(-1, 4)
        return _Boxes(a[:, 0], a[:, 1], a[:, 2], a[:, 3])


@dataclass(frozen=True)
class _Curves:
    """Curve segments as arrays, with their bounding boxes, for the tests of many boxes at once."""

    x0: FloatArray
    y0: FloatArray
    x1: FloatArray
    y1: FloatArray
    lo_x: FloatArray
    hi_x: FloatArray
    lo_y: FloatArray
    hi_y: FloatArray

    @staticmethod
    def of(obs: Obstacles) -> _Curves:
        x0, y0, x1, y1 = obs.sx0, obs.sy0, obs.sx1, obs.sy1
        return _Curves(x0, y0, x1, y1, np.minimum(x0, x1), np.maximum(x0, x1), np.minimum(y0, y1), np.maximum(y0, y1))

    def crossings(self, boxes: _Boxes) -> np.ndarray:
        """For each box, how many segments enter it (:meth:`Obstacles.crossings`, all boxes at once):
        the pairs whose bounding boxes meet, then the corner-side test on those pairs only."""
        n = boxes.left.size
        if self.x0.size == 0 or n == 0:
            return np.zeros(n, np.int64)
        i, j = np.nonzero(
            (self.hi_x >= boxes.left[:, None])
            & (self.lo_x <= boxes.right[:, None])
            & (self.hi_y >= boxes.top[:, None])
            & (self.lo_y <= boxes.bottom[:, None])
        )
        if i.size == 0:
            return np.zeros(n, np.int64)
        x0, y0 = self.x0[j], self.y0[j]
        dx, dy = self.x1[j] - x0, self.y1[j] - y0
        sides = [
            dx * (cy[i] - y0) - dy * (cx[i] - x0)
            for cx in (boxes.left, boxes.right)
            for cy in (boxes.top, boxes.bottom)
        ]
        lo = np.minimum(np.minimum(sides[0], sides[1]), np.minimum(sides[2], sides[3]))
        hi = np.maximum(np.maximum(sides[0], sides[1]), np.maximum(sides[2], sides[3]))
        return np.bincount(i[(lo <= 0.0) & (hi >= 0.0)], minlength=n)


def obstacles(chart: Chart, area: tuple[float, float]) -> Obstacles:
    """The chart's drawn curves (polylines and segments of nonzero width) and markers, in pixels.
    Areas (light fills) are no obstacles: text may sit on them. The polylines are mapped at once
    (a NaN between each two: no segment joins them), so are the separate segments and the markers."""
    lines = [i for i in chart.items if isinstance(i, Polyline) and i.style.width > 0 and i.x.size > 1]
    separate = [i for i in chart.items if isinstance(i, Segments) and i.style.width > 0]
    points = [i for i in chart.items if isinstance(i, Points)]
    empty = np.empty(0)
    xs0, ys0, xs1, ys1 = [empty], [empty], [empty], [empty]
    if lines:
        gap = np.array([np.nan])
        x = np.concatenate([part for i in lines for part in (np.asarray(i.x, float), gap)])
        y = np.concatenate([part for i in lines for part in (np.asarray(i.y, float), gap)])
        px, py = _to_px(chart, area, x, y)
        keep = np.isfinite(px[:-1]) & np.isfinite(px[1:]) & np.isfinite(py[:-1]) & np.isfinite(py[1:])
        xs0.append(px[:-1][keep])
        ys0.append(py[:-1][keep])
        xs1.append(px[1:][keep])
        ys1.append(py[1:][keep])
    if separate:
        ax, ay = _to_px(
            chart,
            area,
            np.concatenate([np.asarray(i.x0, float) for i in separate]),
            np.concatenate([np.asarray(i.y0, float) for i in separate]),
        )
        bx, by = _to_px(
            chart,
            area,
            np.concatenate([np.asarray(i.x1, float) for i in separate]),
            np.concatenate([np.asarray(i.y1, float) for i in separate]),
        )
        xs0.append(ax)
        ys0.append(ay)
        xs1.append(bx)
        ys1.append(by)
    markers: list[Box] = []
    for item in points:
        px, py = _to_px(chart, area, np.asarray(item.x, float), np.asarray(item.y, float))
        h = 0.5 * item.size * MARKER_SCALE
        markers.extend(Box(a - h, b - h, a + h, b + h) for a, b in zip(px.tolist(), py.tolist(), strict=True))
    return Obstacles(np.concatenate(xs0), np.concatenate(ys0), np.concatenate(xs1), np.concatenate(ys1), tuple(markers))


def label_box(chart: Chart, area: tuple[float, float], label: Label) -> Box:
    """Where ``label``'s text is drawn, in plot-area pixels (placed or not)."""
    px, py = _to_px_one(chart, area, label.x, label.y)
    w, h = text_box_px(label.text, label.size)
    if label.offset_px is not None:
        cx, cy = px + label.offset_px[0], py - label.offset_px[1]
    else:  # the unplaced text starts 6 px beside its point (the backends' default shift)
        shift = {"left": 6.0 + 0.5 * w, "right": -6.0 - 0.5 * w, "center": 0.0}[label.anchor]
        cx, cy = px + shift, py
    return Box(cx - 0.5 * w, cy - 0.5 * h, cx + 0.5 * w, cy + 0.5 * h)


@dataclass(frozen=True)
class _Field:
    """A chart's obstacles as arrays, made once per placement: curve segments and marker boxes."""

    curves: _Curves
    markers: _Boxes


@dataclass(frozen=True)
class _Spots:
    """A label's candidate spots (:func:`candidate_offsets`) as arrays, made once per text size."""

    offsets: tuple[tuple[float, float, bool], ...]
    dx: FloatArray
    dy: FloatArray
    needs_leader: np.ndarray
    reach: float
    """The farthest a spot's centre lies from the point along x or y, CSS pixels."""
    n_bare: int
    """How many spots touch the point (no leader line): the first ones tried."""


@lru_cache(maxsize=256)
def _spots(width: float, height: float, size: float, first: str, rings: int) -> _Spots:
    offsets = tuple(candidate_offsets(width, height, size, first, rings))
    reach = max(max(abs(dx), abs(dy)) for dx, dy, _ in offsets)
    dx = np.array([o[0] for o in offsets], float)
    dy = np.array([o[1] for o in offsets], float)
    needs_leader = np.array([o[2] for o in offsets], bool)
    n_bare = int(np.argmax(needs_leader)) if needs_leader.any() else len(offsets)
    assert not needs_leader[:n_bare].any() and needs_leader[n_bare:].all(), "bare spots come first"
    return _Spots(offsets, dx, dy, needs_leader, reach, n_bare)


@dataclass(frozen=True)
class _Anchor:
    """A movable label to place: its index in the chart's items, its point (plot-area px), its text
    box and its candidate spots."""

    index: int
    ax: float
    ay: float
    w: float
    h: float
    spots: _Spots


@dataclass(frozen=True)
class _Table:
    """The candidate spots of some labels, with what does not depend on the order of placement, as
    arrays ``(labels, spots)``: the boxes and the boxes grown by :data:`MARGIN_PX`
    (``(labels, spots, 4)``: left, top, right, bottom), whether each spot passes the tests that do not
    depend on other movable labels (inside the area, clear of the fixed boxes and the markers, and
    for a spot touching the point, the text naming no other point), and how many curve segments
    enter its grown box (-1 where it fails those tests)."""

    row: dict[int, int]
    """Each label's row, by its index in the chart's items."""
    boxes: np.ndarray
    grown: np.ndarray
    ok: np.ndarray
    counts: np.ndarray


def _table(anchors: list[_Anchor], area: tuple[float, float], field: _Field, fixed: list[Box]) -> _Table:
    """:class:`_Table` of the spots of ``anchors`` (labels whose spots come from as many rings):
    what the search (:func:`_walk`) tests of them that no placed label changes, for every label and
    spot at once (one set of array operations per chart, not one per label), in the same arithmetic."""
    dx = np.stack([a.spots.dx for a in anchors])
    dy = np.stack([a.spots.dy for a in anchors])
    ax = np.array([a.ax for a in anchors])[:, None]
    ay = np.array([a.ay for a in anchors])[:, None]
    hw = np.array([0.5 * a.w for a in anchors])[:, None]
    hh = np.array([0.5 * a.h for a in anchors])[:, None]
    cx, cy = ax + dx, ay - dy
    boxes = np.stack([cx - hw, cy - hh, cx + hw, cy + hh], -1)
    grown = np.stack(
        [boxes[..., 0] - MARGIN_PX, boxes[..., 1] - MARGIN_PX, boxes[..., 2] + MARGIN_PX, boxes[..., 3] + MARGIN_PX],
        -1,
    )
    b, g = boxes.reshape(-1, 4), grown.reshape(-1, 4)
    ok = (b[:, 0] >= 0.0) & (b[:, 1] >= 0.0) & (b[:, 2] <= area[0]) & (b[:, 3] <= area[1])
    if fixed:
        f = np.array([(x.left, x.top, x.right, x.bottom) for x in fixed], float)
        ok &= ~np.any(
            (g[:, None, 0] < f[:, 2])
            & (f[:, 0] < g[:, None, 2])
            & (g[:, None, 1] < f[:, 3])
            & (f[:, 1] < g[:, None, 3]),
            axis=1,
        )
    m = field.markers
    if m.left.size:
        ok &= ~np.any(
            (b[:, None, 0] < m.right) & (m.left < b[:, None, 2]) & (b[:, None, 1] < m.bottom) & (m.top < b[:, None, 3]),
            axis=1,
        )
        # the text would seem to name another point (spots touching it only): a marker near enough
        # to matter (meeting the label's reach, as the full search takes them), not the label's own
        # (its centre more than 1 px away, taxicab), nearer the box than the label's point
        # (tested only where the spot touches its point and passed the tests above)
        bare = np.flatnonzero(np.tile(~anchors[0].spots.needs_leader, len(anchors)) & ok)
        if bare.size:
            reach = np.array([a.spots.reach + a.w + a.h for a in anchors])[:, None]
            px, py = np.broadcast_to(ax, dx.shape).reshape(-1)[bare], np.broadcast_to(ay, dx.shape).reshape(-1)[bare]
            r = np.broadcast_to(reach, dx.shape).reshape(-1)[bare]
            bb = b[bare]
            mx, my = 0.5 * (m.left + m.right), 0.5 * (m.top + m.bottom)
            other = (
                (m.left < (px + r)[:, None])
                & ((px - r)[:, None] < m.right)
                & (m.top < (py + r)[:, None])
                & ((py - r)[:, None] < m.bottom)
                & (np.abs(mx - px[:, None]) + np.abs(my - py[:, None]) > 1.0)
            )
            own = np.hypot(
                np.maximum(np.maximum(bb[:, 0] - px, 0.0), px - bb[:, 2]),
                np.maximum(np.maximum(bb[:, 1] - py, 0.0), py - bb[:, 3]),
            )
            dist = np.hypot(
                np.maximum(np.maximum(bb[:, 0, None] - mx, 0.0), mx - bb[:, 2, None]),
                np.maximum(np.maximum(bb[:, 1, None] - my, 0.0), my - bb[:, 3, None]),
            )
            ok[bare[np.any(other & (dist < own[:, None]), axis=1)]] = False
    counts = np.full(ok.shape, -1, np.int64)
    clear = np.flatnonzero(ok)
    counts[clear] = field.curves.crossings(_Boxes(g[clear, 0], g[clear, 1], g[clear, 2], g[clear, 3]))
    shape = dx.shape
    return _Table({a.index: k for k, a in enumerate(anchors)}, boxes, grown, ok.reshape(shape), counts.reshape(shape))


def _walk(
    anchor: _Anchor,
    table: _Table,
    taken: list[Box],
    fixed: int,
    leaders: list[tuple[float, float, float, float]],
    use_leaders: bool,
) -> tuple[int, int, float, float, bool] | None:
    """The spot a label takes among those of ``table`` (the anchor's row), as ``(crossings, order,
    dx, dy, leader)``, or ``None`` if none is clear: of the spots clear of the area's edge, of
    every label box (``taken``: the fixed ones, then the placed ones from ``fixed`` on), of the
    markers, and (if ``use_leaders``) of the ``leaders`` drawn so far, whose own leader line (if it
    needs one) enters no label box and crosses no other leader line, and whose text names no
    other point, the first of those crossing the fewest curves. The table's spots pass the tests
    no placed label changes; they are tried fewest crossings first, then in the order tried, and
    the first that also passes the rest is that spot."""
    k = table.row[anchor.index]
    spots = np.flatnonzero(table.ok[k])
    counts = table.counts[k]
    placed = taken[fixed:]
    check_leader = use_leaders and bool(leaders or taken)
    m = MARGIN_PX
    grown_taken = [(b.left - m, b.top - m, b.right + m, b.bottom + m) for b in taken] if check_leader else []
    ax, ay = anchor.ax, anchor.ay
    for spot in spots[np.lexsort((spots, counts[spots]))].tolist():
        grown = _grown_box(table, k, spot)
        if not _clear_of_placed(grown, placed, leaders if use_leaders else []):
            continue
        dx, dy, leader = anchor.spots.offsets[spot]
        if check_leader and leader:
            b = table.boxes[k, spot]
            ex, ey = _leader_end(ax, ay, Box(float(b[0]), float(b[1]), float(b[2]), float(b[3])))
            if any(_leader_enters((ax, ay, ex, ey), t) for t in grown_taken) or any(
                _cuts(segment, ax, ay, ex, ey) for segment in leaders
            ):
                continue
        return (int(counts[spot]), spot, dx, dy, leader)
    return None


def _grown_box(table: _Table, row: int, spot: int) -> tuple[float, float, float, float]:
    g = table.grown[row, spot]
    return float(g[0]), float(g[1]), float(g[2]), float(g[3])


def _clear_of_placed(
    grown: tuple[float, float, float, float], placed: list[Box], leaders: list[tuple[float, float, float, float]]
) -> bool:
    """Whether a spot's grown box meets none of the label boxes placed so far and none of the
    ``leaders``: what of a spot :func:`_table` cannot know, the placement's order deciding it."""
    return not any(_meets(grown, b) for b in placed) and not any(_leader_enters(sg, grown) for sg in leaders)


def _sign(v: float) -> int:
    return (v > 0.0) - (v < 0.0)


def _cuts(segment: tuple[float, float, float, float], ax: float, ay: float, ex: float, ey: float) -> bool:
    """Whether ``(ax, ay) -> (ex, ey)`` crosses ``segment``: each has the other's ends on opposite
    sides of its line, or one on it (orientation tests)."""
    sx0, sy0, sx1, sy1 = segment
    d1 = _sign((sx1 - sx0) * (ay - sy0) - (sy1 - sy0) * (ax - sx0))
    d2 = _sign((sx1 - sx0) * (ey - sy0) - (sy1 - sy0) * (ex - sx0))
    d3 = _sign((ex - ax) * (sy0 - ay) - (ey - ay) * (sx0 - ax))
    d4 = _sign((ex - ax) * (sy1 - ay) - (ey - ay) * (sx1 - ax))
    return d1 * d2 <= 0 and d3 * d4 <= 0


def _meets(a: tuple[float, float, float, float], b: Box) -> bool:
    return a[0] < b.right and b.left < a[2] and a[1] < b.bottom and b.top < a[3]


def _leader_enters(segment: tuple[float, float, float, float], box: tuple[float, float, float, float]) -> bool:
    """Whether a leader line enters ``box`` (:meth:`_Curves.crossings` for one segment and one box)."""
    x0, y0, x1, y1 = segment
    left, top, right, bottom = box
    if max(x0, x1) < left or min(x0, x1) > right or max(y0, y1) < top or min(y0, y1) > bottom:
        return False
    dx, dy = x1 - x0, y1 - y0
    sides = [dx * (cy - y0) - dy * (cx - x0) for cx in (left, right) for cy in (top, bottom)]
    return min(sides) <= 0.0 <= max(sides)


def place_labels(chart: Chart, area_px: tuple[float, float], smallest: float | None = None) -> Chart:
    """``chart`` with every movable label moved to a free spot (see the module docstring), for a plot
    area of ``area_px`` CSS pixels (width, height). Deterministic: the same chart and area always give
    the same placement. Labels whose point lies outside the chart's ranges are left alone.

    The axes' names, written inside the plot by the canvas at the movable labels' size, are kept
    clear too (:func:`axis_name_boxes`). The labels are placed in the chart's order; when some
    label finds no spot clear of the others (a crowded plot, where the order decides), the
    placement is made again with the labels that found none placed first, up to
    :data:`REORDERINGS` times, and the first placement with the fewest such labels is kept. If some
    are still left and ``smallest`` (CSS px) is given, the labels step down in size towards it
    (:data:`LABEL_STEP_PX`) until none is: the labels keep their size where the plot has room."""
    area = (float(area_px[0]), float(area_px[1]))
    if not (area[0] > 0 and area[1] > 0):
        raise ValueError(f"area_px must be two positive pixel sizes, got {area_px!r}")
    obs = obstacles(chart, area)
    movable = [i for i, item in enumerate(chart.items) if isinstance(item, Label) and item.movable]
    if not movable:
        return replace(chart, area_px=area)
    size = max(chart.items[i].size for i in movable)  # type: ignore[union-attr]
    names = axis_name_boxes(chart, area, size)
    best: tuple[dict[int, Item], list[int]] | None = None
    for step in _label_sizes(size, smallest):
        sized = _prepare(chart if step == size else _labels_at(chart, movable, step), area, obs, names)
        order = movable
        for _ in range(REORDERINGS + 1):  # another order changes nothing that _prepare worked out
            placed, stuck = _place(sized, order)
            if best is None or len(stuck) < len(best[1]):
                best = (placed, stuck)
            if not stuck:
                break
            order = stuck + [i for i in order if i not in stuck]
        if best is not None and not best[1]:
            break
    assert best is not None
    items = tuple(best[0].get(i, item) for i, item in enumerate(chart.items))
    return replace(chart, items=items, area_px=area)


#: How many times a crowded plot's labels are placed again in another order (see :func:`place_labels`).
REORDERINGS = 3
#: The steps (CSS px) a crowded plot's labels take down towards the smallest size allowed.
LABEL_STEP_PX = 2.0


def _label_sizes(size: float, smallest: float | None) -> list[float]:
    """``size``, then down by :data:`LABEL_STEP_PX` to ``smallest`` (itself the last) if it is smaller."""
    sizes = [size]
    if smallest is not None:
        while sizes[-1] - LABEL_STEP_PX > smallest:
            sizes.append(sizes[-1] - LABEL_STEP_PX)
        if smallest < sizes[-1]:
            sizes.append(smallest)
    return sizes


def _labels_at(chart: Chart, movable: list[int], size: float) -> Chart:
    """``chart`` with its movable labels (indices ``movable``) at font ``size``."""
    items = list(chart.items)
    for i in movable:
        items[i] = replace(items[i], size=size)  # type: ignore[type-var]
    return replace(chart, items=tuple(items))


def axis_name_boxes(chart: Chart, area: tuple[float, float], size: float) -> list[Box]:
    """Where the canvas writes the chart's axis names inside its plot area (``size`` px text): the
    x axis's at the bottom right, the y axis's at the top left (see :data:`AXIS_NAME_INSET_PX`)."""
    width, height = area
    boxes: list[Box] = []
    if chart.x_title:
        w, h = text_box_px(chart.x_title, size)
        middle = height - AXIS_NAME_DROP_EM * size
        boxes.append(
            Box(width - AXIS_NAME_INSET_PX - w, middle - 0.5 * h, width - AXIS_NAME_INSET_PX, middle + 0.5 * h)
        )
    if chart.y_title:
        w, h = text_box_px(chart.y_title, size)
        middle = AXIS_NAME_DROP_EM * size
        boxes.append(Box(AXIS_NAME_INSET_PX, middle - 0.5 * h, AXIS_NAME_INSET_PX + w, middle + 0.5 * h))
    return boxes


@dataclass(frozen=True)
class _Prepared:
    """What a chart's placement at one label size needs whatever the order of its labels: the
    obstacles as arrays, the boxes that never move (fixed labels, the axis names), each movable
    label whose point is in the plot, and their :class:`_Table` of the first :data:`RINGS`."""

    chart: Chart
    area: tuple[float, float]
    field: _Field
    fixed: tuple[Box, ...]
    anchors: dict[int, _Anchor]
    table: _Table | None
    far: dict[int, tuple[_Anchor, _Table]] = dataclasses.field(default_factory=dict, compare=False)
    """A crowded label's far rings and their table, by its index, made the first time the label
    needs them (:func:`_place`) and kept for the other orders: like :attr:`table`, what they hold
    does not depend on the order of placement."""


def _far(prepared: _Prepared, anchor: _Anchor) -> tuple[_Anchor, _Table]:
    """The far rings (:data:`FAR_RINGS`) of ``anchor`` and their table, once per :class:`_Prepared`."""
    if anchor.index not in prepared.far:
        item = prepared.chart.items[anchor.index]
        assert isinstance(item, Label)
        spots = _spots(anchor.w, anchor.h, item.size, item.anchor, FAR_RINGS)
        far = _Anchor(anchor.index, anchor.ax, anchor.ay, anchor.w, anchor.h, spots)
        prepared.far[anchor.index] = (far, _table([far], prepared.area, prepared.field, list(prepared.fixed)))
    return prepared.far[anchor.index]


def _prepare(chart: Chart, area: tuple[float, float], obs: Obstacles, reserved: list[Box]) -> _Prepared:
    """:class:`_Prepared` of ``chart`` for a plot ``area``, its obstacles ``obs``, keeping the
    ``reserved`` boxes clear too."""
    field = _Field(_Curves.of(obs), _Boxes.of(obs.markers))
    fixed = [label_box(chart, area, i) for i in chart.items if isinstance(i, Label) and not i.movable] + reserved
    anchors: dict[int, _Anchor] = {}
    for index, item in enumerate(chart.items):
        if isinstance(item, Label) and item.movable:
            ax, ay = _to_px_one(chart, area, item.x, item.y)
            if 0.0 <= ax <= area[0] and 0.0 <= ay <= area[1]:
                w, h = text_box_px(item.text, item.size)
                anchors[index] = _Anchor(index, ax, ay, w, h, _spots(w, h, item.size, item.anchor, RINGS))
    table = _table(list(anchors.values()), area, field, fixed) if anchors else None
    return _Prepared(chart, area, field, tuple(fixed), anchors, table)


def _place(prepared: _Prepared, order: list[int]) -> tuple[dict[int, Item], list[int]]:
    """The movable labels ``order`` (indices into the chart's items) placed one after the other:
    each one's placed item by index, and the indices of those that found no spot clear of labels
    and markers (kept at their point, with a leader line). Labels whose point is outside the plot
    are left alone.

    What no placed label changes is in ``prepared`` (:func:`_prepare`, once whatever the order). A
    label takes the first spot touching its point that meets nothing, not the labels and leader
    lines placed before it either (the spot :func:`_walk` would choose, without the sort); else
    :func:`_walk` over the first rings, then over the far ones, and at last over the far ones
    across leader lines."""
    chart, area, table = prepared.chart, prepared.area, prepared.table
    taken = list(prepared.fixed)
    fixed = len(taken)
    leaders: list[tuple[float, float, float, float]] = []
    out: dict[int, Item] = {}
    stuck: list[int] = []
    for index in order:
        anchor = prepared.anchors.get(index)
        if anchor is None:
            continue
        assert table is not None
        ax, ay = anchor.ax, anchor.ay
        item = chart.items[index]
        assert isinstance(item, Label)
        best: tuple[int, int, float, float, bool] | None = None
        k = table.row[index]
        free = table.ok[k, : anchor.spots.n_bare] & (table.counts[k, : anchor.spots.n_bare] == 0)
        for spot in np.flatnonzero(free).tolist():
            if _clear_of_placed(_grown_box(table, k, spot), taken[fixed:], leaders):
                dx, dy, _ = anchor.spots.offsets[spot]
                best = (0, spot, dx, dy, False)
                break
        if best is None:  # every spot of the first rings, the fewest crossings first
            best = _walk(anchor, table, taken, fixed, leaders, True)
        if best is None:  # crowded: farther out, and at last across other leader lines
            far, rings = _far(prepared, anchor)
            best = _walk(far, rings, taken, fixed, leaders, True) or _walk(far, rings, taken, fixed, leaders, False)
        if best is None:  # nowhere free of labels and markers: keep the old spot, with a leader line
            out[index] = replace(item, leader=True)
            stuck.append(index)
            continue
        _, _, dx, dy, leader = best
        placed = replace(item, anchor="center", offset_px=(dx, dy), leader=leader)
        box = label_box(chart, area, placed)
        taken.append(box)
        if leader:
            leaders.append((ax, ay, *_leader_end(ax, ay, box)))
        out[index] = placed
    return out, stuck


def overlaps(chart: Chart) -> list[tuple[str, str]]:
    """Pairs of label texts whose boxes meet in the chart's placed area (empty when all is well)."""
    if chart.area_px is None:
        raise ValueError("the chart's labels were not placed (area_px is None)")
    labels = [i for i in chart.items if isinstance(i, Label)]
    boxes = [label_box(chart, chart.area_px, lab) for lab in labels]
    return [
        (labels[i].text, labels[j].text)
        for i in range(len(boxes))
        for j in range(i + 1, len(boxes))
        if boxes[i].meets(boxes[j])
    ]
