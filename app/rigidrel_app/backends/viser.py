"""viser backend for the lanes: one batched mesh for every box, one line-segments node per layer.

Per playback frame it assigns a handful of arrays (box positions and scales, segment
points) and the labels' texts; it never creates nodes except when a scene's shape changes.
"""

from __future__ import annotations

import functools
from collections.abc import Sequence
from typing import Literal

import numpy as np
import plotly.graph_objects as go
import viser

from ..view.lanes import Box, LaneState, segments_array
from ..view.vocabulary import FRAME_COLOR, INK, Label, Segments, plain_text, rgb

_CUBE_VERTICES = np.array([[x, y, z] for x in (-0.5, 0.5) for y in (-0.5, 0.5) for z in (-0.5, 0.5)], dtype=np.float32)
_CUBE_FACES = np.array(
    [
        [0, 1, 3],
        [0, 3, 2],
        [4, 6, 7],
        [4, 7, 5],
        [0, 4, 5],
        [0, 5, 1],
        [2, 3, 7],
        [2, 7, 6],
        [0, 2, 6],
        [0, 6, 4],
        [1, 5, 7],
        [1, 7, 3],
    ],
    dtype=np.uint32,
)
ROD_DEPTH = 0.14
#: Box instances per lane the mesh starts with (two rods and a wall); it grows when a scene has
#: more. Unused instances are shrunk out of sight, so the node is rarely re-added.
BOXES_PER_LANE = 3
_HIDDEN = (0.0, 1e4, 0.0)
_ANCHOR: dict[str, Literal["center-left", "center-right", "center-center"]] = {
    "left": "center-left",
    "right": "center-right",
    "center": "center-center",
}
AMBIENT = 1.2
FRONT = 2.0
_FRONT = -0.5 * ROD_DEPTH - 0.004  # segments just in front of the boxes' faces
_LABEL_Y = _FRONT - 0.01


def _ring(radius: float, width: float = 0.13, n: int = 32) -> tuple[np.ndarray, np.ndarray]:
    """A flat annulus in the x-z plane (facing the camera on -y): a clock dial."""
    a = np.linspace(0.0, 2.0 * np.pi, n, endpoint=False)
    outer = np.stack([radius * np.cos(a), np.zeros(n), radius * np.sin(a)], axis=-1)
    inner = outer * (1.0 - width)
    vertices = np.concatenate([outer, inner]).astype(np.float32)
    k = np.arange(n)
    k1 = (k + 1) % n
    faces = np.concatenate([np.stack([k, k1, n + k], -1), np.stack([k1, n + k1, n + k], -1)]).astype(np.uint32)
    return vertices, faces


@functools.lru_cache(maxsize=64)
def _instance_colors(names: tuple[str, ...]) -> np.ndarray:
    return np.array([linear_rgb(c) for c in names], dtype=np.uint8)


def linear_rgb(color: str) -> tuple[int, int, int]:
    """An sRGB palette colour as the linear values three.js expects for mesh instance colours."""

    def lin(c: int) -> int:
        x = c / 255.0
        y = x / 12.92 if x <= 0.04045 else ((x + 0.055) / 1.055) ** 2.4
        return round(255.0 * y)

    r, g, b = rgb(color)
    return lin(r), lin(g), lin(b)


class _LabelPool:
    """Label nodes under one name prefix, grown when needed and never re-added: changing a
    label costs ~60 us, creating one ~500 us. Unused nodes are hidden."""

    def __init__(self, scene: viser.SceneApi, prefix: str) -> None:
        self._scene = scene
        self._prefix = prefix
        self._handles: list[viser.LabelHandle] = []
        self._shown: list[tuple[str, tuple[float, float, float], float, str] | None] = []

    def show(self, placed: Sequence[tuple[Label, float]]) -> None:
        """Show ``(label, lane z)`` pairs; assign only what changed (each assignment is a message)."""
        for k, (lab, z) in enumerate(placed):
            text, position = plain_text(lab.text), (lab.x, _LABEL_Y, lab.y + z)
            scale, anchor = lab.size / 13.0, _ANCHOR[lab.anchor]
            state = (text, position, scale, anchor)
            if k == len(self._handles):
                name = f"{self._prefix}/{k}"
                h = self._scene.add_label(name, text, position=position, anchor=anchor, font_screen_scale=scale)
                self._handles.append(h)
                self._shown.append(state)
            elif state != self._shown[k]:
                h = self._handles[k]
                h.text = text
                h.position = position
                h.font_screen_scale = scale
                h.anchor = anchor
                h.visible = True
                self._shown[k] = state
        for k in range(len(placed), len(self._handles)):
            if self._shown[k] is not None:
                self._handles[k].visible = False
                self._shown[k] = None


class LaneRenderer:
    """Draws :class:`LaneState` s of several lanes (stacked in z) into one client's scene."""

    def __init__(self, scene: viser.SceneApi, lane_z: Sequence[float]) -> None:
        self._scene = scene
        self.lane_z = tuple(lane_z)
        self._boxes: viser.BatchedMeshHandle | None = None
        self._box_capacity = BOXES_PER_LANE * len(self.lane_z)
        self._box_colors: tuple[str, ...] = ()
        self._box_positions = np.zeros((0, 3), dtype=np.float32)
        self._box_scales = np.zeros((0, 3), dtype=np.float32)
        # flat, true colours: no environment map, an even ambient light and one from the camera
        scene.configure_environment_map(None)
        scene.configure_default_lights(enabled=False)
        scene.add_light_ambient("/lanes/ambient", intensity=AMBIENT)
        scene.add_light_directional("/lanes/front_light", intensity=FRONT, position=(0.0, -10.0, 4.0))
        self._dynamic: viser.LineSegmentsHandle | None = None
        self._static: viser.LineSegmentsHandle | None = None
        self._labels = _LabelPool(scene, "/lanes/label")
        self._static_labels = _LabelPool(scene, "/lanes/static_label")
        self._dials: viser.BatchedMeshHandle | None = None
        self._dial_count = -1
        self._dial_radius = 0.0

    # ------------------------------------------------------------------ per scene
    def set_static(self, rulers: Sequence[tuple[Segments, Sequence[Label]]]) -> None:
        """Per-lane static geometry (rulers, origin marks): redrawn only when the scene changes."""
        pts = np.concatenate([segments_array(seg, z, _FRONT) for (seg, _), z in zip(rulers, self.lane_z, strict=True)])
        if self._static is None:
            self._static = self._scene.add_line_segments(
                "/lanes/static", pts, colors=rgb(FRAME_COLOR), thickness=1.5, thickness_units="screen"
            )
        else:
            self._static.points = pts
        self._static_labels.show(
            [(lab, z) for (_, labels), z in zip(rulers, self.lane_z, strict=True) for lab in labels]
        )

    # ------------------------------------------------------------------ per frame
    def update(self, states: Sequence[LaneState], radius: float, labels: bool = True) -> None:
        """Move the rods and clocks (every frame); rewrite the labels if the states carry them."""
        boxes = [(b, z) for st, z in zip(states, self.lane_z, strict=True) for b in st.boxes]
        self._update_boxes(boxes)
        pts = np.concatenate(
            [segments_array(st.segments, z, _FRONT) for st, z in zip(states, self.lane_z, strict=True)]
        )
        if self._dynamic is None:
            self._dynamic = self._scene.add_line_segments(
                "/lanes/dynamic", pts, colors=rgb(INK), thickness=1.6, thickness_units="screen"
            )
        else:
            self._dynamic.points = pts
        self._update_dials(states, radius)
        if not labels or not any(st.labels for st in states):
            return
        self._labels.show([(lab, z) for st, z in zip(states, self.lane_z, strict=True) for lab in st.labels])

    def _update_dials(self, states: Sequence[LaneState], radius: float) -> None:
        """One ring mesh, instanced at every clock: positions only change per frame."""
        centres = [(st.dials, z) for st, z in zip(states, self.lane_z, strict=True)]
        n = sum(c.shape[0] for c, _ in centres)
        positions = np.zeros((n, 3), dtype=np.float32)
        k = 0
        for c, z in centres:
            positions[k : k + c.shape[0], 0] = c[:, 0]
            positions[k : k + c.shape[0], 1] = _FRONT
            positions[k : k + c.shape[0], 2] = c[:, 1] + z
            k += c.shape[0]
        if self._dials is None or n != self._dial_count or radius != self._dial_radius:
            vertices, faces = _ring(radius)
            self._dials = self._scene.add_batched_meshes_simple(
                "/lanes/dials",
                vertices,
                faces,
                batched_wxyzs=np.tile(np.array([1.0, 0.0, 0.0, 0.0], dtype=np.float32), (n, 1)),
                batched_positions=positions,
                batched_colors=np.array(linear_rgb(INK), dtype=np.uint8),
                flat_shading=True,
                lod="off",
                cast_shadow=False,
                receive_shadow=False,
                side="double",
            )
            self._dial_count = n
            self._dial_radius = radius
        else:
            self._dials.batched_positions = positions

    def _update_boxes(self, boxes: Sequence[tuple[Box, float]]) -> None:
        if len(boxes) > self._box_capacity:  # a scene with more bodies: a bigger mesh, once
            self._box_capacity = len(boxes)
            if self._boxes is not None:
                self._boxes.remove()
                self._boxes = None
        n = self._box_capacity
        positions = np.tile(np.array(_HIDDEN, dtype=np.float32), (n, 1))
        scales = np.full((n, 3), 1e-6, dtype=np.float32)
        for k, (b, z) in enumerate(boxes):
            positions[k] = (0.5 * (b.x0 + b.x1), 0.0, z + b.z)
            scales[k] = (max(b.x1 - b.x0, 1e-4), ROD_DEPTH, b.height)
        names = tuple(b.color for b, _ in boxes) + ("#ffffff",) * (n - len(boxes))
        colors = _instance_colors(names)
        if self._boxes is None:
            self._boxes = self._scene.add_batched_meshes_simple(
                "/lanes/boxes",
                _CUBE_VERTICES,
                _CUBE_FACES,
                batched_wxyzs=np.tile(np.array([1.0, 0.0, 0.0, 0.0], dtype=np.float32), (n, 1)),
                batched_positions=positions,
                batched_scales=scales,
                batched_colors=colors,
                flat_shading=True,
                lod="off",
                cast_shadow=False,
                receive_shadow=False,
            )
        else:
            # skip what did not change (the boxes' lengths are constant while the rods coast):
            # each assignment costs a message and a wake-up of viser's event loop
            if not np.array_equal(positions, self._box_positions):
                self._boxes.batched_positions = positions
            if not np.array_equal(scales, self._box_scales):
                self._boxes.batched_scales = scales
            if names != self._box_colors:
                self._boxes.batched_colors = colors
        self._box_colors = names
        self._box_positions, self._box_scales = positions, scales


class _FigureJson(go.Figure):
    """A figure that is nothing but its JSON text: viser's plotly handle calls only ``to_json``.

    ``go.Figure.__init__`` is skipped on purpose: it would validate every trace again (tens of
    milliseconds) for a text the plotly backend has already built.
    """

    def __init__(self, text: str) -> None:  # pyright: ignore[reportMissingSuperCall]
        self._rigidrel_json = text

    def to_json(self, *args: object, **kwargs: object) -> str:
        return self._rigidrel_json


def show_figure_json(handle: viser.GuiPlotlyHandle, text: str) -> None:
    """Send a plotly figure's JSON (``{"data": ..., "layout": ..., "config": ...}``) to a plotly panel."""
    handle.figure = _FigureJson(text)
