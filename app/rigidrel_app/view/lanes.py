"""The 3-D lanes: the rods at one instant of one frame, as drawing-vocabulary items.

Lane coordinates: ``x`` along the rods (the frame's own x, in units of the scene's
largest rest length), ``z`` up within the lane. Rods are boxes with a tick at every
tenth of their rest length (so the uneven accelerations along a Born-rigid rod show),
a proper-time clock dial on each end, the scene's objects that are not rods (drawn from their
descriptions, by role: :mod:`.objects`), a ruler of the frame's own x, and a mark at the origin
event's place. Rods of different groups (:attr:`rigidrel_core.Scene.rod_groups`: alternatives, a
comparison) get a row each in the rod band, one above the other; a tie between two rods is a thin
bar on their row, coloured by its field (:data:`.objects.FIELD_RAMP`).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field, replace
from enum import StrEnum
from typing import Literal

import numpy as np
import numpy.typing as npt

import rigidrel_core as rr

from .layout import LaneLayout, text_width
from .objects import object_style, object_words
from .vocabulary import (
    FRAME_COLOR,
    INK,
    LIGHT_COLOR,
    ROD_COLORS,
    FloatArray,
    Label,
    Segments,
    Style,
    ramp_color,
    signed,
)

#: Material points with ticks: every tenth of the rest length.
TICK_FRACTIONS = np.linspace(0.0, 1.0, 11)
#: One turn of a clock hand per this much proper time (in units of the largest rest length).
CLOCK_PERIOD = 1.0
#: The ruler's name (x, x′) is this big: a coordinate's name, read from the back of a hall.
AXIS_NAME_SIZE = 16.0
#: The right ends' dials sit this many dial radii above the left ends' ones.
DIAL_ROW_GAP = 2.4


@dataclass(frozen=True)
class Box:
    """An axis-aligned box ``[x0, x1]`` in a lane, centred on the lane's axis."""

    x0: float
    x1: float
    height: float
    color: str
    z: float = 0.0


@dataclass(frozen=True)
class LaneGeometry:
    """Sizes in lane units, fixed for a scene so nothing jumps during playback."""

    unit: float
    """Physical length of one lane unit (the largest rest length)."""
    rod_height: float = 0.14
    clock_radius: float = 0.065
    wall_height: float = 0.6

    @property
    def clock_z(self) -> float:
        return 0.5 * self.rod_height + 1.6 * self.clock_radius

    @property
    def clock_rows(self) -> tuple[float, float]:
        """Heights of the dials on the rods' left ends and on their right ends: two rows, so the two
        dials of a short rod (or of two rods in contact) never overlap."""
        return self.clock_z, self.clock_z + DIAL_ROW_GAP * self.clock_radius

    @property
    def title_z(self) -> float:
        """Height of the lane's title (frame name and clock), above the clocks."""
        return self.clock_rows[1] + 3.6 * self.clock_radius


@dataclass(frozen=True)
class LaneState:
    """What one lane shows at one instant."""

    boxes: tuple[Box, ...]
    segments: Segments
    """The ticks and the clock hands."""
    dials: FloatArray
    """Centres ``(x, z)`` of the clock dials (radius ``LaneGeometry.clock_radius``); shape ``(n, 2)``."""
    labels: tuple[Label, ...]
    """Empty unless asked for (they change at the plots' rate, not every frame)."""
    ends: FloatArray
    """The rods' end positions in the frame (physical units, not lane units); shape ``(n_rods, 2)``."""


def lane_geometry(scene: rr.Scene) -> LaneGeometry:
    """The lanes' sizes for ``scene``: a body's bar reaches from the rods' bottom to the top of the
    upper dials, never into the title above them (as :mod:`.layout` has it on the canvas)."""
    geo = LaneGeometry(unit=max(r.motion.length for r in scene.rods))
    return replace(geo, wall_height=geo.clock_rows[1] + geo.clock_radius + 0.5 * geo.rod_height)


def lane_state(
    scene: rr.Scene,
    frame: rr.Frame,
    now: float,
    geo: LaneGeometry,
    title: str,
    title_x: float,
    labels: bool = True,
    snapshot: tuple[FloatArray, FloatArray] | None = None,
) -> LaneState:
    """The rods of ``scene`` at time ``now`` of ``frame``, drawn in lane coordinates.

    One two-line label per lane, at a fixed place (only if ``labels``): ``title`` (the
    frame's name and clock) at lane x ``title_x``, and beneath it the readings of the
    proper-time clocks on the rods' ends. Each end carries a dial whose hand turns once per
    ``CLOCK_PERIOD``: the left ends' dials in one row, the right ends' in a row above
    (:attr:`LaneGeometry.clock_rows`). ``snapshot`` is ``scene.snapshot(now, frame,
    fractions=TICK_FRACTIONS)`` if the caller already has it.
    """
    u = geo.unit
    x_phys, tau = snapshot if snapshot is not None else scene.snapshot(now, frame=frame, fractions=TICK_FRACTIONS)
    x = x_phys / u
    h = geo.rod_height
    rows = bar_rows(scene.rod_groups)
    row_z = np.array([rows[g][0] * h for g in scene.rod_groups])  # each rod's row: centre and height
    row_h = np.array([rows[g][1] * h for g in scene.rod_groups])
    boxes = [
        Box(float(x[r, 0]), float(x[r, -1]), float(row_h[r]), ROD_COLORS[r % len(ROD_COLORS)], float(row_z[r]))
        for r in range(scene.n_rods)
    ]
    objects = [object_picture(scene, obj, frame, now, x, geo) for obj in scene.objects]
    for picture in objects:
        boxes.extend(picture.boxes)
    tx = x.ravel()
    tick_z = np.repeat(row_z, x.shape[1])
    tick_h = np.repeat(row_h, x.shape[1])
    cx = x[:, [0, -1]].ravel()  # the ends: (rods * 2,)
    cz = np.tile(np.array(geo.clock_rows), scene.n_rods)
    phase = 2.0 * np.pi * tau.ravel() / (CLOCK_PERIOD * u)
    hand = 0.85 * geo.clock_radius
    x0 = np.concatenate([tx, cx])
    z0 = np.concatenate([tick_z - 0.5 * tick_h, cz])
    x1 = np.concatenate([tx, cx + hand * np.sin(phase)])
    z1 = np.concatenate([tick_z + 0.5 * tick_h, cz + hand * np.cos(phase)])
    dials = np.stack([cx, cz], axis=-1)
    texts: tuple[Label, ...] = ()
    if labels:  # one two-line label per lane: each label update is a message
        text = title_text(scene, title, [p.text for p in objects], tau)
        texts = (Label(title_x, geo.title_z - 0.05, text, Style(INK), anchor="left", size=12),)
    ends = x_phys[:, [0, -1]]
    return LaneState(tuple(boxes), Segments(x0, z0, x1, z1, Style(INK, 1.5)), dials, texts, ends)


def title_text(scene: rr.Scene, title: str, object_texts: Sequence[str], tau: FloatArray) -> str:
    """A lane's two-line title: ``title`` (the frame and its clock), the objects' words
    (``object_texts``, :func:`.objects.object_words`) and the rows' key; under it the readings of
    the clocks on the rods' ends, ``tau`` (``(rods, 2)``: left and right end)."""
    readings = "    ".join(f"{rod.name}: {signed(tau[i, 0])} | {signed(tau[i, 1])}" for i, rod in enumerate(scene.rods))
    key = "   ".join(k for k in (*object_texts, rows_key(scene)) if k)
    head = f"{title}   {key}" if key else title
    return f"{head}\nclocks τ (left | right end)   {readings}"


#: Rows of the rod band when a scene's rods form several groups (:attr:`rigidrel_core.Scene.rod_groups`):
#: the share of the band between two rows, and how much thicker a row of several rods (Bell's two
#: ships, with their string) is than a row of one (the comparison rod; each of the pole-barn's poles).
ROW_GAP = 0.12
SHARED_ROW_WEIGHT = 2.0


def bar_rows(groups: Sequence[int]) -> tuple[tuple[float, float], ...]:
    """Each group's row in the rod band, top to bottom in group order: ``(centre, height)`` as shares
    of the band's height (its centre 0, its top 0.5). One group: the whole band. Several: stacked
    with :data:`ROW_GAP` between them, a row of several rods :data:`SHARED_ROW_WEIGHT` times as thick
    as a row of one."""
    n = max(groups, default=0) + 1
    if n == 1:
        return ((0.0, 1.0),)
    weights = [SHARED_ROW_WEIGHT if list(groups).count(g) > 1 else 1.0 for g in range(n)]
    unit = (1.0 - ROW_GAP * (n - 1)) / sum(weights)
    rows: list[tuple[float, float]] = []
    top = 0.5
    for w in weights:
        rows.append((top - 0.5 * w * unit, w * unit))
        top -= w * unit + ROW_GAP
    return tuple(rows)


def rows_key(scene: rr.Scene) -> str:
    """What the rows of the rod band hold, for the lane's title (empty for a scene of one group):
    ``"upper bar: ...; lower bar: ..."`` for two groups, ``"row 1: ...; ..."`` for more. A row of
    several rods (Bell's ships, thicker) goes unnamed there: the clocks' line names its rods."""
    groups = scene.rod_groups
    n = max(groups, default=0) + 1
    if n == 1:
        return ""
    heads = ("upper bar", "lower bar") if n == 2 else tuple(f"row {k + 1}" for k in range(n))
    named = [
        (head, [r.name for r, g in zip(scene.rods, groups, strict=True) if g == k]) for k, head in enumerate(heads)
    ]
    return "; ".join(f"{head}: {names[0]}" for head, names in named if len(names) == 1)


#: An open body (a door before it closes) is drawn as this top share of its closed bar: raised like
#: a barn's sliding door above the rods, which pass beneath it (their bars and clocks take the
#: lower part of the bar's height).
OPEN_SHARE = 0.2


@dataclass(frozen=True)
class ObjectPicture:
    """A scene object in a lane at one instant (:func:`object_picture`): its bars and its words."""

    boxes: tuple[Box, ...]
    value: float | None
    """Its field at the lane's time (the core's), or ``None`` (it has none)."""
    parted: bool
    """Whether its event has parted it (a broken string: two loose ends)."""
    closed: bool
    """Whether it is closed (a door after its closing event; any other object always)."""
    color: str
    text: str
    """For the lane's title (:func:`.objects.object_words`): empty for a body without a field."""


def object_picture(
    scene: rr.Scene, obj: rr.SceneObject, frame: rr.Frame, now: float, x: FloatArray, geo: LaneGeometry
) -> ObjectPicture:
    """``obj`` at time ``now`` of ``frame`` in lane units, drawn from its description alone
    (``x``: the rods' snapshot in lane units, ``(rods, TICK_FRACTIONS)``).

    A body (:data:`.objects.OBJECT_STYLES`' ``"bar"``) is a bar the height of the lane's bodies at its
    face, on the side its matter lies; a body still open (a door before it closes, in ``frame``) is
    only the top :data:`OPEN_SHARE` of that bar, raised clear of the rods' bars; a tie is a thin
    bar from its first end to its second on the row of its first end's rod, coloured on its style's
    ramp by its field from 0 (faint) to the field's full scale (strong), and once its event parts
    it, two loose ends in the strongest colour.
    """
    style = object_style(obj)
    value = None if obj.field is None else float(obj.field.values([now], frame=frame)[0])
    happened = bool(obj.happened([now], frame=frame)[0])
    parted, closed = bool(obj.parted([now], frame=frame)[0]), bool(obj.closed([now], frame=frame)[0])
    text = object_words(obj, value, happened)
    if style.glyph == "bar":
        face = _lane_x(obj.worldlines[0], frame, now, x, geo)
        x0, x1 = (face - style.width, face) if obj.side < 0 else (face, face + style.width)
        top = geo.wall_height - 0.5 * geo.rod_height  # the bar stands on the rods' lowest edge
        height = geo.wall_height if closed else OPEN_SHARE * geo.wall_height
        bar = Box(x0, x1, height, style.color, z=top - 0.5 * height)
        return ObjectPicture((bar,), value, parted, closed, style.color, text)
    first, second = (_lane_x(w, frame, now, x, geo) for w in obj.worldlines[:2])
    color = style.color
    if obj.field is not None and value is not None:
        full = obj.field.full_scale
        color = ramp_color(1.0 if parted else (value / full if full > 0 else 0.0), style.ramp)
    centre, share = _row_of(scene, obj.worldlines[0])
    z, height = centre * geo.rod_height, style.width * share * geo.rod_height
    if parted:
        loose = style.loose_end_share * (second - first)
        boxes = (Box(first, first + loose, height, color, z), Box(second - loose, second, height, color, z))
    else:
        boxes = (Box(first, second, height, color, z),)
    return ObjectPicture(boxes, value, parted, closed, color, text)


def _lane_x(
    w: rr.InertialWorldline | rr.MaterialWorldline, frame: rr.Frame, now: float, x: FloatArray, geo: LaneGeometry
) -> float:
    """Lane x of an object's worldline at ``now``: a rod's material point that the snapshot ``x`` holds
    (its ends, its first and last columns; the others if it has :data:`TICK_FRACTIONS`' columns) is read
    off it, the very number its rod is drawn at; anything else is asked of the core."""
    if isinstance(w, rr.MaterialWorldline):
        if w.fraction in (0.0, 1.0):
            return float(x[w.rod, 0 if w.fraction == 0.0 else -1])
        k = np.flatnonzero(w.fraction == TICK_FRACTIONS)
        if x.shape[1] == TICK_FRACTIONS.size and k.size:
            return float(x[w.rod, int(k[0])])
    return float(w.positions(now, frame=frame)) / geo.unit


def _row_of(scene: rr.Scene, w: rr.InertialWorldline | rr.MaterialWorldline) -> tuple[float, float]:
    """The row ``(centre, height)`` of the rod band (shares of it, :func:`bar_rows`) a tie lies on: its
    first end's rod's, or the whole band for an end on no rod."""
    if isinstance(w, rr.MaterialWorldline):
        return bar_rows(scene.rod_groups)[scene.rod_groups[w.rod]]
    return (0.0, 1.0)


def lane_static(
    geo: LaneGeometry, x_range: tuple[float, float], origin_event: rr.OriginEvent, axis: str = "x"
) -> tuple[Segments, tuple[Label, ...]]:
    """A ruler of the frame's own x below the rods, named ``axis`` (``"x"``, ``"x′"``) at its right
    end, and a mark where the origin event happens."""
    lo, hi = x_range[0] / geo.unit, x_range[1] / geo.unit
    step = _nice_step((hi - lo) / 8.0)
    marks = np.arange(np.ceil(lo / step) * step, hi + 0.5 * step, step)
    zr = -0.5 * geo.rod_height - 0.12
    xs = [np.array([lo]), marks, np.array([0.0])]
    zs0 = [np.array([zr]), np.full(marks.size, zr), np.array([zr - 0.05])]
    xe = [np.array([hi]), marks, np.array([0.0])]
    zs1 = [np.array([zr]), np.full(marks.size, zr - 0.04), np.array([geo.clock_z - 1.2 * geo.clock_radius])]
    ruler = Segments(
        np.concatenate(xs), np.concatenate(zs0), np.concatenate(xe), np.concatenate(zs1), Style(FRAME_COLOR, 1.0)
    )
    labels = tuple(
        Label(float(m), zr - 0.1, f"{m * geo.unit + 0.0:g}", Style(FRAME_COLOR), anchor="center", size=10)
        for m in marks
    )
    origin = Label(0.0, zr + 0.05, f"{origin_event.value} (origin)", Style(FRAME_COLOR), anchor="left", size=10)
    name = Label(hi, zr + 0.06, axis, Style(FRAME_COLOR), anchor="right", size=AXIS_NAME_SIZE)
    return ruler, (*labels, origin, name)


def _nice_step(raw: float) -> float:
    if not np.isfinite(raw) or raw <= 0:
        return 1.0
    e = np.floor(np.log10(raw))
    for m in (1.0, 2.0, 5.0, 10.0):
        if m * 10**e >= raw:
            return float(m * 10**e)
    return float(10 ** (e + 1))


def segments_array(seg: Segments, z_offset: float, y: float) -> npt.NDArray[np.float32]:
    """Lane segments (x, y = lane height) as viser's ``(n, 2, 3)`` points: lane x -> world x, lane y -> world z."""
    n = seg.x0.size
    pts = np.empty((n, 2, 3), dtype=np.float32)
    pts[:, 0, 0], pts[:, 0, 2] = seg.x0, seg.y0 + z_offset
    pts[:, 1, 0], pts[:, 1, 2] = seg.x1, seg.y1 + z_offset
    pts[:, :, 1] = y
    return pts


# ---------------------------------------------------------------------- the app's canvas lanes
#: Each rod spans at least this share of its lane times its rest length over the largest one: the
#: lanes zoom in when a rod contracts below that (the ruler's numbers and the titles say so).
ROD_SHARE = 0.2
#: The rods together take at most this share of the lane, so there is room around them.
FIT_SHARE = 0.8
#: Ruler ticks per lane, about.
RULER_TICKS = 6.0
#: A zoom this close to 1 (relative) is no zoom: the titles say nothing.
ZOOM_TOLERANCE = 1e-3


class LaneScale(StrEnum):
    """How the two lanes of the canvas are scaled (page px per unit of their frames' x)."""

    SHARED = "shared"
    """One scale for both lanes: a rod 0.8 long in one frame and 1.0 in the other is drawn 0.8 of its
    length there; when a rod would be too short to see in either lane, both zoom together."""
    OWN = "own"
    """Each lane fits its own rods (the two lanes' pictures are then not comparable by eye)."""


def steady_width(scene: rr.Scene, frame: rr.Frame, window: tuple[float, float]) -> float:
    """A lane's x width (the frame's x units) while no rod is too contracted to see: the rods'
    largest joint extent over the time ``window``, over :data:`FIT_SHARE`. One scale for the whole
    playback, so Lorentz contraction shows as a rod getting shorter on the screen."""
    t = np.linspace(window[0], window[1], 193)
    x = scene.positions(t, frame=frame)  # (rods, 2, t)
    extent = x.max(axis=(0, 1)) - x.min(axis=(0, 1))
    return float(extent.max()) / FIT_SHARE


@dataclass(frozen=True)
class LaneWindow:
    """The part of a frame's x axis a lane shows at one instant (the frame's x units)."""

    center: float
    width: float


@dataclass(frozen=True)
class LaneFit:
    """What one lane needs of its scale at one instant (the frame's x units)."""

    center: float
    """The lane's centre: the middle of its rods, or the point a riding lane keeps still."""
    extent: float
    """The width the rods take about :attr:`center`: the lane is never narrower than this over
    :data:`FIT_SHARE` (the rods stay inside it)."""
    zoom_width: float
    """The widest the lane may be with every rod at least :data:`ROD_SHARE` of it (times its rest
    length over the largest): ``min_r length_r * L_max / (ROD_SHARE * L_r)``."""

    @property
    def fit_width(self) -> float:
        """The narrowest the lane may be: ``extent / FIT_SHARE``."""
        return self.extent / FIT_SHARE


def lane_fit(ends: FloatArray, rest_lengths: FloatArray, center: float | None = None) -> LaneFit:
    """The fit of one lane whose rods have ``ends`` (``(rods, 2)``, the frame's x) and rest lengths
    ``rest_lengths``: centred on the rods, or on ``center`` if given (a riding lane keeps its point
    still; then extent = 2 max |x - center|)."""
    lo, hi = float(ends.min()), float(ends.max())
    unit = float(rest_lengths.max())
    lengths = ends[:, 1] - ends[:, 0]
    zoom = float(np.min(lengths * unit / (ROD_SHARE * rest_lengths)))
    if center is None:
        return LaneFit(0.5 * (lo + hi), hi - lo, zoom)
    return LaneFit(center, 2.0 * max(abs(hi - center), abs(center - lo)), zoom)


def lane_window(ends: FloatArray, rest_lengths: FloatArray, steady: float, center: float | None = None) -> LaneWindow:
    """One lane on its own (:attr:`LaneScale.OWN`): centred as :func:`lane_fit` says, at the steady
    width unless a rod would be drawn under :data:`ROD_SHARE` of the lane (scaled by its rest length):
    then narrower, just enough; never so narrow that the rods leave the lane.

    width = max(extent / FIT_SHARE, min(steady, min_r length_r * L_max / (ROD_SHARE * L_r))),
    continuous in time, so the zoom never jumps.
    """
    fit = lane_fit(ends, rest_lengths, center)
    return LaneWindow(fit.center, max(fit.fit_width, min(steady, fit.zoom_width)))


@dataclass(frozen=True)
class LaneScales:
    """The lanes' scales at one instant (:func:`lane_scales`)."""

    scales: tuple[float, ...]
    """Page px per unit of each lane's frame's x."""
    zooms: tuple[float, ...]
    """Each lane's scale over its steady one (1: the playback's scale; 2: twice as large)."""


def lane_scales(
    fits: Sequence[LaneFit], tracks: Sequence[float], steadies: Sequence[float], mode: LaneScale = LaneScale.SHARED
) -> LaneScales:
    """Page px per unit of x for each lane at one instant (``tracks``: the lanes' track widths, px;
    ``steadies``: their steady widths, :func:`steady_width`).

    :attr:`LaneScale.OWN`: each lane as :func:`lane_window` has it, ``s_i = W_i / width_i``.
    :attr:`LaneScale.SHARED`: one scale for all lanes, every lane's constraint in px per unit —

        s = min( min_i FIT_SHARE W_i / extent_i,  max( min_i W_i / steady_i,  max_i W_i / zoom_width_i ) )

    the steady scale (every lane's rods fit over the whole playback) unless a rod in some lane would be
    drawn under :data:`ROD_SHARE` of its lane (then larger, just enough, in both lanes), and never so
    large that a lane's rods leave it. Continuous in time, as each term is. The zoom is ``s`` over the
    steady scale.
    """
    if mode is LaneScale.OWN:
        widths = [max(f.fit_width, min(st, f.zoom_width)) for f, st in zip(fits, steadies, strict=True)]
        scales = tuple(w / width for w, width in zip(tracks, widths, strict=True))
        zooms = tuple(st / width for st, width in zip(steadies, widths, strict=True))
        return LaneScales(scales, zooms)
    steady = min(w / st for w, st in zip(tracks, steadies, strict=True))
    need = max(w / f.zoom_width if f.zoom_width > 0 else np.inf for w, f in zip(tracks, fits, strict=True))
    room = min(w / f.fit_width if f.fit_width > 0 else np.inf for w, f in zip(tracks, fits, strict=True))
    scale = float(min(room, max(steady, need)))
    return LaneScales((scale,) * len(fits), (scale / steady,) * len(fits))


def zoomed_title(title: str, zoom: float) -> str:
    """A lane's first line with what it says of the lanes' ``zoom`` (:func:`zoom_words`), if anything."""
    words = zoom_words(zoom)
    return f"{title}   {words}" if words else title


def zoom_words(zoom: float) -> str:
    """What a lane's title says of its zoom: ``"zoom ×2.4"`` while a contracted rod has the lanes zoomed
    in, or nothing at the playback's steady scale (within :data:`ZOOM_TOLERANCE`) or below it (a lane
    that widens a little to keep its rods inside: its ruler's numbers say so)."""
    if not np.isfinite(zoom) or zoom <= 1.0 + ZOOM_TOLERANCE:
        return ""
    return f"zoom ×{zoom:.2g}" if zoom < 10 else f"zoom ×{zoom:.0f}"


def ruler_step(width: float) -> float:
    """The ruler's tick spacing for a lane ``width`` wide: 1, 2 or 5 times a power of ten, the one
    nearest (in ratio) to :data:`RULER_TICKS` ticks across."""
    raw = width / RULER_TICKS
    if not np.isfinite(raw) or raw <= 0:
        return 1.0
    e = np.floor(np.log10(raw))
    candidates = np.array([1.0, 2.0, 5.0, 10.0]) * 10**e
    return float(candidates[np.argmin(np.abs(np.log(candidates / raw)))])


def ruler_text(value: float, step: float) -> str:
    """A ruler number with the decimals its step needs (never ``-0``)."""
    decimals = max(0, -int(np.floor(np.log10(step) + 1e-9)))
    return f"{round(value, decimals) + 0.0:.{decimals}f}"


EdgeSide = Literal[-1, 1]
"""Which edge of a lane: ``-1`` the left (toward -x), ``+1`` the right."""


@dataclass(frozen=True)
class EdgeMark:
    """A body outside the lane (a wall, a barn's door), marked at the lane's edge on its side: an
    arrow there and its name and distance beside it (:func:`edge_marks`)."""

    name: str
    side: EdgeSide
    distance: float
    """How far the body's face lies beyond the nearest rod end, in the frame's x units (> 0)."""
    x: float
    """Page x of the arrow's tip (the track's edge)."""
    z: float
    """Page z of the arrow (the rods' centre line)."""
    color: str
    text: str
    """``"wall 3.2 →"`` on the right, ``"← wall 3.2"`` on the left."""
    text_z: float
    """Page z of the text's middle (the left ends' dial row)."""
    text_x: float
    """Page x of the text's edge on the mark's side: the track's edge for the body nearest the rods
    on that side, each farther one's after the nearer one's text (they share the row)."""


@dataclass(frozen=True)
class RodName:
    """A rod's name on its bar, where it shares its row with another rod (so that colour is not all
    that tells them apart, :func:`rod_names`): its middle at page ``(x, z)``, ``px`` high."""

    text: str
    x: float
    z: float
    px: float


#: The smallest name drawn on a bar (px); a row thinner than this takes it, over its edges.
MIN_NAME_PX = 11.0


def name_on_bar(name: str, room_px: float, px: float) -> str | None:
    """``name`` if it fits on a bar ``room_px`` wide at ``px``, else its short form (its number,
    ``"2"`` of ``"rod 2"``, or its first word, ``"rear"`` of ``"rear ship"``), else None."""
    words = name.split()
    short = words[-1] if words[-1].isdigit() else words[0]
    return next((t for t in (name, short) if text_width(t, px) + px <= room_px), None)


def rod_names(scene: rr.Scene, boxes: Sequence[Box], text_px: float) -> tuple[RodName, ...]:
    """The names of the rods that share a row (:attr:`rigidrel_core.Scene.rod_groups`: the rod
    collision's two rods, Bell's two ships) on their bars, ``boxes`` (page px, clipped to the
    track, in the rods' order; empty, ``x1 <= x0``, where a rod is out of view) as
    :func:`lane_picture` draws them), at most ``text_px`` high and at least :data:`MIN_NAME_PX`."""
    groups = list(scene.rod_groups)
    out: list[RodName] = []
    for rod, group, box in zip(scene.rods, groups, boxes, strict=True):
        if groups.count(group) < 2 or box.x1 <= box.x0:
            continue
        px = min(text_px, max(MIN_NAME_PX, 0.85 * box.height))
        text = name_on_bar(rod.name, box.x1 - box.x0, px)
        if text is not None:
            out.append(RodName(text, 0.5 * (box.x0 + box.x1), box.z, px))
    return tuple(out)


@dataclass(frozen=True)
class LanePicture:
    """One lane of the app's canvas at one instant, in page pixels (:mod:`.layout`)."""

    boxes: tuple[Box, ...]
    """Rods and obstacles, clipped to the lane's track; ``Box.z`` is the box's centre height."""
    segments: tuple[Segments, ...]
    """The rods' ticks and clock hands (ink), the ruler's line and ticks (the frame's colour), the
    arrows of :attr:`edge_marks` (each in its body's colour)."""
    dials: FloatArray
    """Centres ``(x, z)`` of the clock dials inside the track, ``(n, 2)``."""
    title: str
    """The frame and its time (and the zoom, if any: :func:`zoom_words`), and the clocks' readings
    (two lines)."""
    window: LaneWindow
    scale: float
    """Page px per unit of the frame's x (one for both lanes: :attr:`LaneScale.SHARED`)."""
    origin_px: float
    """Page x of the frame's x = 0 (the ruler's numbers are at ``origin_px + value * scale``)."""
    ruler_step: float
    ends: FloatArray
    """The rods' end positions in the frame (the frame's x), ``(rods, 2)``."""
    ruler_ticks: npt.NDArray[np.int64] = field(default_factory=lambda: np.zeros(0, np.int64))
    """The ruler's ticks inside the track, as multiples ``n`` of :attr:`ruler_step` (tick ``n`` at
    page x ``origin_px + n * ruler_step * scale``)."""
    ruler_numbers: tuple[str, ...] = ()
    """Each tick's number (:func:`ruler_text`), one per :attr:`ruler_ticks`: every tick carries one."""
    zoom: float = 1.0
    """The scale over the playback's steady one (:class:`LaneScales`)."""
    edge_marks: tuple[EdgeMark, ...] = ()
    """The bodies that lie wholly outside the track (:class:`EdgeMark`)."""
    names: tuple[RodName, ...] = ()
    """The names of the rods that share a row, on their bars (:func:`rod_names`)."""


def lane_picture(
    scene: rr.Scene,
    frame: rr.Frame,
    now: float,
    scale: float,
    place: LaneLayout,
    title: str,
    fit: LaneFit,
    snapshot: tuple[FloatArray, FloatArray] | None = None,
    zoom: float = 1.0,
) -> LanePicture:
    """The rods of ``scene`` at time ``now`` of ``frame`` in the lane ``place``, at ``scale`` page px
    per unit of the frame's x (:func:`lane_scales`) about ``fit.center`` (:func:`lane_fit`), with true
    positions on a ruler of the frame's x whose every tick carries its number; dials and rods keep their
    pixel sizes at any zoom; a body outside the track is marked at its edge (:func:`edge_marks`).
    ``snapshot``: ``scene.snapshot(now, frame=frame, fractions=TICK_FRACTIONS)`` if the caller has it;
    ``zoom``: ``scale`` over the steady scale (the title says it, :func:`zoom_words`)."""
    snap = snapshot if snapshot is not None else scene.snapshot(now, frame=frame, fractions=TICK_FRACTIONS)
    rest = np.array([r.motion.length for r in scene.rods])
    ends = snap[0][:, [0, -1]]
    track = place.track
    win = LaneWindow(fit.center, track.width / scale)
    origin = 0.5 * (track.x0 + track.x1) - win.center * scale
    unit = float(rest.max())
    k = unit * scale  # px per lane unit
    geo = LaneGeometry(
        unit, rod_height=place.rod_px / k, clock_radius=place.clock_px / k, wall_height=place.wall_px / k
    )
    st = lane_state(scene, frame, now, geo, zoomed_title(title, zoom), 0.0, True, snap)

    def px(x: FloatArray | float) -> FloatArray:
        return origin + k * np.asarray(x, dtype=float)

    clipped = [
        Box(
            max(float(px(b.x0)), track.x0), min(float(px(b.x1)), track.x1), b.height * k, b.color, place.rod_z + b.z * k
        )
        for b in st.boxes
    ]
    boxes = [b for b in clipped if b.x1 > b.x0]
    seg = st.segments
    sx0, sx1 = px(seg.x0), px(seg.x1)
    # two ends at one place (the barn's two poles, a rod touching another) keep a dial each, side by side
    ends_x = px(st.dials[:, 0])
    shift = spread_dials(ends_x, st.dials[:, 1], place.clock_px) - ends_x
    hands = slice(seg.x0.size - shift.size, seg.x0.size)  # the dials' hands close the segments
    sx0[hands] += shift
    sx1[hands] += shift
    inside = (np.minimum(sx0, sx1) >= track.x0) & (np.maximum(sx0, sx1) <= track.x1)
    rods = Segments(
        sx0[inside], place.rod_z + k * seg.y0[inside], sx1[inside], place.rod_z + k * seg.y1[inside], seg.style
    )
    dx = ends_x + shift
    keep = (dx >= track.x0) & (dx <= track.x1)
    dials = np.stack([dx[keep], place.rod_z + k * st.dials[keep, 1]], axis=-1)
    step = ruler_step(win.width)
    ticks = np.arange(
        np.ceil((track.x0 - origin) / (step * scale) - 1e-9), np.floor((track.x1 - origin) / (step * scale) + 1e-9) + 1
    ).astype(np.int64)
    mx = origin + ticks * step * scale
    zr, tick = place.ruler_z, place.tick_px
    origin_tick = [origin] if track.x0 <= origin <= track.x1 else []
    rx0 = np.concatenate([[track.x0], mx, origin_tick])
    rz0 = np.concatenate([[zr], np.full(mx.size, zr), [zr] * len(origin_tick)])
    rz1 = np.concatenate([[zr], np.full(mx.size, zr - tick), [place.rod_z - 0.5 * place.rod_px] * len(origin_tick)])
    rx1 = np.concatenate([[track.x1], mx, origin_tick])
    ruler = Segments(rx0, rz0, rx1, rz1, Style(FRAME_COLOR, 1.5))
    numbers = tuple(ruler_text(float(n) * step, step) for n in ticks)
    marks = edge_marks(scene, frame, now, ends, place, origin, scale, step)
    text = st.labels[0].text if st.labels else title
    return LanePicture(
        tuple(boxes),
        (rods, ruler, *(edge_arrow(m, place) for m in marks)),
        dials,
        text,
        win,
        scale,
        origin,
        step,
        ends,
        ticks,
        numbers,
        zoom,
        marks,
        rod_names(scene, clipped[: scene.n_rods], place.text_px),
    )


#: Dials in one row are at least this many radii apart, centre to centre (:func:`spread_dials`).
DIAL_SPACING = 2.3


def spread_dials(x: FloatArray, row: FloatArray, radius: float) -> FloatArray:
    """The dials' centres (page x) moved apart where dials of one ``row`` (their rows' heights, any
    unit) would overlap: dials closer than :data:`DIAL_SPACING` radii form a group, spread about its
    members' mean, :data:`DIAL_SPACING` radii apart, in the order of the ends (the rods' order at one
    place); a group that then reaches the next dial or group takes it in. A dial with room stays on
    its end."""
    out = np.asarray(x, dtype=float).copy()
    gap = DIAL_SPACING * radius

    def laid(members: list[int]) -> FloatArray:
        offsets = (np.arange(len(members), dtype=np.float64) - 0.5 * (len(members) - 1)) * gap
        return np.asarray(float(np.mean(out[members])) + offsets, dtype=np.float64)

    for z in np.unique(row):
        idx = np.flatnonzero(row == z)
        groups: list[list[int]] = []
        for i in idx[np.argsort(out[idx], kind="stable")].tolist():
            groups.append([i])
            while len(groups) > 1 and laid(groups[-1])[0] - laid(groups[-2])[-1] < gap - 1e-9:
                groups[-2].extend(groups.pop())
        for g in groups:  # each group's places from its own members only: any order
            out[g] = laid(g)
    return out


#: Room between the names of two bodies out on the same side, in font sizes.
EDGE_TEXT_GAP_EM = 1.0
#: An edge mark's arrow: this many rod heights long, its head this share of its length.
EDGE_ARROW_RODS = 1.6
EDGE_HEAD_SHARE = 0.4


def edge_marks(
    scene: rr.Scene,
    frame: rr.Frame,
    now: float,
    ends: FloatArray,
    place: LaneLayout,
    origin: float,
    scale: float,
    step: float,
) -> tuple[EdgeMark, ...]:
    """The bodies (:data:`.objects.OBJECT_STYLES`' ``"bar"``: a wall, a barn's door) whose bar lies wholly
    outside the lane's track at time ``now`` of ``frame``: each marked at the edge on its side, with
    its name and how far its face lies beyond the nearest rod end (``ends``, the frame's x; the core's
    positions, to the ruler's decimals), e.g. ``"wall 3.20 →"``. Bodies out on the same side (the
    barn's door and its back wall) are named in a row from the edge inwards, the nearest first."""
    track = place.track
    out: list[EdgeMark] = []
    for obj in scene.objects:
        style = object_style(obj)
        if style.glyph != "bar":
            continue
        face = float(obj.worldlines[0].positions(now, frame=frame))
        far = face + obj.side * style.width * float(max(r.motion.length for r in scene.rods))
        lo_px, hi_px = sorted((origin + face * scale, origin + far * scale))
        if hi_px < track.x0:
            side: EdgeSide = -1
        elif lo_px > track.x1:
            side = 1
        else:
            continue
        distance = float(ends.min()) - face if side < 0 else face - float(ends.max())
        digits = ruler_text(abs(distance), step) if abs(distance) < 10.0 else f"{abs(distance):.0f}"
        text = f"← {obj.name} {digits}" if side < 0 else f"{obj.name} {digits} →"
        x = track.x0 if side < 0 else track.x1
        out.append(EdgeMark(obj.name, side, distance, x, place.rod_z, style.color, text, place.dial_z[0], x))
    text_x: dict[str, float] = {}
    for side in (-1, 1):
        at = track.x0 if side < 0 else track.x1
        for mark in sorted((m for m in out if m.side == side), key=lambda m: abs(m.distance)):
            text_x[mark.name] = at
            at -= side * (text_width(mark.text, place.text_px) + EDGE_TEXT_GAP_EM * place.text_px)
    return tuple(replace(m, text_x=text_x[m.name]) for m in out)


def edge_arrow(mark: EdgeMark, place: LaneLayout) -> Segments:
    """An edge mark's arrow (page px): a shaft along the rods' centre line ending at the track's edge,
    and a head, in its body's colour."""
    length = EDGE_ARROW_RODS * place.rod_px
    head = EDGE_HEAD_SHARE * length
    tip, tail = mark.x, mark.x - mark.side * length
    back = mark.x - mark.side * head
    z = mark.z
    x0 = np.array([tail, back, back])
    z0 = np.array([z, z + 0.6 * head, z - 0.6 * head])
    x1 = np.array([tip, tip, tip])
    z1 = np.array([z, z, z])
    return Segments(x0, z0, x1, z1, Style(mark.color, 2.0))


# ---------------------------------------------------------------------- light pulses in the lanes
#: A pulse is a bright bar this many CSS px wide, reaching this share of the rod's height above and below it.
PULSE_PX = 8.0
PULSE_REACH = 0.95
#: Vertical strokes per pulse bar (the lane's lines have one width: the bar is a row of them).
PULSE_STROKES = 5


def pulse_segments(
    pulses: Sequence[float], arrivals: Sequence[float], lane: LanePicture, place: LaneLayout
) -> Segments:
    """The light pulses in flight and the far ends' arrival places in one lane, in page px.

    ``pulses``: the x of each pulse at the lane's time (the frame's x, from
    :meth:`.signals.Signals.pulse_positions`): each a bright bar across the rod, ``PULSE_PX`` wide.
    ``arrivals``: the x where the light reaches each far end (the frame's x of the arrival event
    ``S``): a dashed line from the ruler to the dials, so the rod's far end can be seen to get
    there (or to have changed already) before the light does. Both clipped to the lane's track.
    Plain floats, not numpy: a handful of segments every playback frame.
    """
    track = place.track
    lo, hi = track.x0, track.x1
    x: list[float] = []
    z0: list[float] = []
    z1: list[float] = []
    bottom, top = place.rod_z - PULSE_REACH * place.rod_px, place.rod_z + PULSE_REACH * place.rod_px
    for p in pulses:
        centre = lane.origin_px + float(p) * lane.scale
        for dx in _PULSE_OFFSETS:
            if lo <= centre + dx <= hi:
                x.append(centre + dx)
                z0.append(bottom)
                z1.append(top)
    dash_top = place.dial_z[1] + place.clock_px
    step = (dash_top - place.ruler_z) / 8.0  # four dashes, four gaps
    for a in arrivals:
        ax = lane.origin_px + float(a) * lane.scale
        if lo <= ax <= hi:
            for k in range(4):
                x.append(ax)
                z0.append(place.ruler_z + 2 * k * step)
                z1.append(place.ruler_z + (2 * k + 1) * step)
    xs = np.array(x, dtype=np.float64)
    return Segments(xs, np.array(z0, dtype=np.float64), xs, np.array(z1, dtype=np.float64), Style(LIGHT_COLOR, 2.0))


#: The pulse bar's strokes, page px from its centre.
_PULSE_OFFSETS = tuple(float(v) for v in np.linspace(-0.5, 0.5, PULSE_STROKES) * (PULSE_PX - 2.0))
