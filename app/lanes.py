"""The 3-D lanes: the rods at one instant of one frame, as drawing-vocabulary items.

Lane coordinates: ``x`` along the rods (the frame's own x, in units of the scene's
largest rest length), ``z`` up within the lane. Rods are boxes with a tick at every
tenth of their rest length (so the uneven accelerations along a Born-rigid rod show),
a proper-time clock dial on each end, the wall where there is one, a ruler of the
frame's own x, and a mark at the origin event's place.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

import rigidrel_core as rr

from .draw import FRAME_COLOR, INK, ROD_COLORS, WALL_COLOR, Label, Segments, Style

#: Material points with ticks: every tenth of the rest length.
TICK_FRACTIONS = np.linspace(0.0, 1.0, 11)
#: One turn of a clock hand per this much proper time (in units of the largest rest length).
CLOCK_PERIOD = 1.0
_DIAL = np.linspace(0.0, 2.0 * np.pi, 25)


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
    def title_z(self) -> float:
        """Height of the lane's title (frame name and clock), above the clocks."""
        return self.clock_z + 3.6 * self.clock_radius


@dataclass(frozen=True)
class LaneState:
    """What one lane shows at one instant."""

    boxes: tuple[Box, ...]
    segments: Segments
    labels: tuple[Label, ...]


def lane_geometry(scene: rr.Scene) -> LaneGeometry:
    return LaneGeometry(unit=max(r.motion.length for r in scene.rods))


def lane_state(
    scene: rr.Scene, frame: rr.Frame, now: float, geo: LaneGeometry, title: str, title_x: float
) -> LaneState:
    """The rods of ``scene`` at time ``now`` of ``frame``, drawn in lane coordinates.

    Two labels per lane, at fixed places: ``title`` (the frame's name and clock) at lane x
    ``title_x``, and beneath it the readings of the proper-time clocks on the rods' ends.
    """
    u = geo.unit
    x = scene.material_positions(TICK_FRACTIONS, np.array([now]), frame)[:, :, 0] / u  # (rods, 11)
    tau = scene.proper_times(np.array([now]), frame)[:, :, 0]  # (rods, 2)
    h = geo.rod_height
    boxes = [Box(float(x[r, 0]), float(x[r, -1]), h, ROD_COLORS[r % len(ROD_COLORS)]) for r in range(scene.n_rods)]
    if scene.has_wall:
        xw = float(scene.wall_x(np.array([now]), frame)[0]) / u
        boxes.append(Box(xw - 0.02, xw, geo.wall_height, WALL_COLOR, z=0.5 * (geo.wall_height - h)))
    # ticks across each rod's face
    tx = x.ravel()
    n = tx.size
    # a dial (24 chords) and a hand above each end: one turn per CLOCK_PERIOD of proper time
    r = geo.clock_radius
    cx = x[:, [0, -1]].ravel()  # (ends,)
    cz = geo.clock_z
    a0, a1 = np.sin(_DIAL[:-1]), np.cos(_DIAL[:-1])
    b0, b1 = np.sin(_DIAL[1:]), np.cos(_DIAL[1:])
    phase = 2.0 * np.pi * tau.ravel() / (CLOCK_PERIOD * u)
    x0 = np.concatenate([tx, (cx[:, None] + r * a0).ravel(), cx])
    z0 = np.concatenate([np.full(n, -0.5 * h), np.tile(cz + r * a1, cx.size), np.full(cx.size, cz)])
    x1 = np.concatenate([tx, (cx[:, None] + r * b0).ravel(), cx + 0.85 * r * np.sin(phase)])
    z1 = np.concatenate([np.full(n, 0.5 * h), np.tile(cz + r * b1, cx.size), cz + 0.85 * r * np.cos(phase)])
    readings = "    ".join(f"{rod.name}: {tau[i, 0]:+.3f} | {tau[i, 1]:+.3f}" for i, rod in enumerate(scene.rods))
    labels = (
        Label(title_x, geo.title_z, title, Style(INK), anchor="left", size=14),
        Label(
            title_x, geo.title_z - 0.11, f"clocks τ (left | right end)   {readings}", Style(INK), anchor="left", size=11
        ),
    )
    return LaneState(tuple(boxes), Segments(x0, z0, x1, z1, Style(INK, 1.5)), labels)


def lane_static(
    geo: LaneGeometry, x_range: tuple[float, float], origin_event: str
) -> tuple[Segments, tuple[Label, ...]]:
    """A ruler of the frame's own x below the rods, and a mark where the origin event happens."""
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
    origin = Label(0.0, zr + 0.05, f"{origin_event} (origin)", Style(FRAME_COLOR), anchor="left", size=10)
    return ruler, (*labels, origin)


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
