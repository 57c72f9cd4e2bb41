"""viser backend: the app's whole canvas (lanes and diagrams) as batched scene geometry.

:class:`PageRenderer` draws the live app's page (:mod:`rigidrel_app.view.layout`): the lanes'
boxes as one instanced mesh, their dials as another, every line of one width as one
line-segments node, dots as point clouds, text as labels. What does not move is sent once
per scene (or canvas size); per playback frame it assigns a handful of arrays (box
positions, segment points, dot positions), the lane titles and one translation per ruler,
so the lanes and the diagrams' now-lines always show one instant in one message batch.
:class:`LaneRenderer` draws the 3-D lanes of the recordings.

The still picture also has a flat form: one image of it (drawn by the raster backend), which
the live app sends while it plays and then shows alone (:meth:`PageRenderer.show_flat`,
:meth:`PageRenderer.show_vectors`). A software renderer draws one textured rectangle far
faster than hundreds of segments, thousands of fill dots and fifty labels.

The dark (projector) theme: viser draws every label as black glyphs on a white box, which no
message can change. So the page stays a light page and the browser inverts the canvas exactly
(``filter: invert(1)``, :data:`DARK_CANVAS_CSS`, put on the tab by the live app): the labels come
out white on black. Every colour this module sends on a dark page is first replaced by its
complement at equal lightness (:func:`sent_for_shade`), so that after the inversion it shows
:func:`~rigidrel_app.view.vocabulary.lightness_flipped` of itself: the same hue, dark turned light.
"""

from __future__ import annotations

import functools
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Literal

import numpy as np
import viser

from ..view import camera as cam
from ..view.canvas import PageDots, PageLines, PagePicture, PageText, color_rgb
from ..view.lanes import Box, EdgeMark, LanePicture, LaneState, segments_array
from ..view.layout import CanvasLayout, clock_radius, lane_title_text
from ..view.vocabulary import FRAME_COLOR, INK, Label, Segments, Shade, lightness_flipped, plain_text, rgb
from ._viser import LABEL_HALF_PAD_EM, encode_png, make_image, set_image_png, write_label

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


#: The CSS that turns a tab's canvas into the dark theme: its ground white, then every pixel
#: inverted exactly (``255 - v`` per channel), viser's black-on-white labels included.
DARK_CANVAS_CSS = "canvas[data-engine] { background: #ffffff; filter: invert(1); }"


def sent_for_shade(colors: np.ndarray, shade: Shade) -> np.ndarray:
    """The sRGB colours ``(..., 3)`` to send so that the page shows ``colors`` on a ``shade`` ground.
    Light: themselves. Dark: ``max(c) + min(c) - c`` (the complement at equal HSL lightness), which
    the canvas' inversion turns into ``c + 255 - max(c) - min(c)``, the colour's
    :func:`~rigidrel_app.view.vocabulary.lightness_flipped` self."""
    c = np.asarray(colors, dtype=np.uint8)
    return c if shade == "light" else 255 - lightness_flipped(c)


def sent_rgb(color: str, shade: Shade) -> tuple[int, int, int]:
    """One palette colour (``"#RRGGBB"``) as sent for a ``shade`` page (:func:`sent_for_shade`)."""
    r, g, b = (int(v) for v in sent_for_shade(np.array(rgb(color)), shade))
    return r, g, b


@functools.lru_cache(maxsize=64)
def _instance_colors(names: tuple[str, ...], shade: Shade = "light") -> np.ndarray:
    return np.array([linear_rgb(c, shade) for c in names], dtype=np.uint8)


def linear_rgb(color: str, shade: Shade = "light") -> tuple[int, int, int]:
    """An sRGB palette colour (as sent for a ``shade`` page, :func:`sent_for_shade`) as the linear
    values three.js expects for mesh instance colours."""

    def lin(c: int) -> int:
        x = c / 255.0
        y = x / 12.92 if x <= 0.04045 else ((x + 0.055) / 1.055) ** 2.4
        return round(255.0 * y)

    r, g, b = sent_rgb(color, shade)
    return lin(r), lin(g), lin(b)


class _LabelPool:
    """Label nodes under one name prefix, grown when needed and never re-added: changing a
    label costs ~60 us, creating one ~500 us. Unused nodes are hidden."""

    def __init__(self, scene: viser.SceneApi, prefix: str) -> None:
        self._scene = scene
        self._prefix = prefix
        self._handles: list[viser.LabelHandle] = []
        self._shown: list[_TextState | None] = []

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

    def __init__(self, scene: viser.SceneApi, lane_z: Sequence[float], shade: Shade = "light") -> None:
        """``shade``: the colours are sent for that ground (:func:`sent_for_shade`; a dark page also
        needs :data:`DARK_CANVAS_CSS`)."""
        self._scene = scene
        self._shade: Shade = shade
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
                "/lanes/static", pts, colors=sent_rgb(FRAME_COLOR, self._shade), thickness=1.5, thickness_units="screen"
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
                "/lanes/dynamic", pts, colors=sent_rgb(INK, self._shade), thickness=1.6, thickness_units="screen"
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
                batched_colors=np.array(linear_rgb(INK, self._shade), dtype=np.uint8),
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
        colors = _instance_colors(names, self._shade)
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


# ====================================================================== the app's page
#: Depth (page px towards the camera) of each layer: later layers are drawn over earlier ones.
_LAYER_Y = 0.4
_PAGE_ROD_DEPTH = 2.0
_LANE_LINES_Y = -_PAGE_ROD_DEPTH - 1.0
#: Depth of the page's labels: on the page itself. viser draws labels over everything (no depth
#: test), so they need no place in front; one in front would sit off its point by its share of
#: the camera's distance (at 8 px in front, 2 px at the foot of a 720 px page).
_TEXT_Y = 0.0
#: Ruler numbers per lane kept as label nodes (more than a lane ever shows).
RULER_SLOTS = 24
#: A viser screen-space label's em is 12 CSS px times its ``font_screen_scale``.
LABEL_EM_PX = 12.0
Anchor = Literal[
    "top-left", "top-center", "top-right", "center-left", "center-center", "center-right",
    "bottom-left", "bottom-center", "bottom-right",
]  # fmt: skip


def label_scale(px: float) -> float:
    """viser's ``font_screen_scale`` for text ``px`` CSS px high (its em)."""
    return px / LABEL_EM_PX


#: A label as :class:`_Texts` shows it: (text, position, font_screen_scale, anchor).
_TextState = tuple[str, tuple[float, float, float], float, str]
#: What a new label is matched on with one shown (:meth:`_Texts._slots_for`), in turn: all of it,
#: its text, its place.
_TEXT_MATCHES: tuple[Callable[[_TextState], object], ...] = (lambda s: s, lambda s: s[0], lambda s: s[1])


class _Texts:
    """Label nodes under one name prefix, grown when needed and never re-added (changing a label
    costs ~60 us, creating one ~500 us); only what changed is assigned; unused ones are hidden."""

    def __init__(self, scene: viser.SceneApi, prefix: str, renew: bool = False) -> None:
        """``renew``: a label given new text at a new place is made anew (a node of a new name, the
        old one removed) instead of updated. viser's client moves a label at once (its pose, outside
        React) but changes its text when React draws next, which in software WebGL can be frames
        later: a still picture's labels updated in place showed the old picture's words at the new
        one's places. A new node is drawn with its text and place together. Not for labels that
        move and change every frame (a lane's titles, its ruler's numbers): a recorded playback
        makes no node after its first frame."""
        self._scene = scene
        self._prefix = prefix
        self._renew = renew
        self._made = 0
        self._handles: list[viser.LabelHandle] = []
        self._shown: list[_TextState | None] = []
        self._held: list[_TextState] = []
        """What each label node holds, shown or hidden."""
        self._order: list[int] = []
        """The labels of the last :meth:`show`, in the order of its texts."""

    def show(self, texts: Sequence[PageText], y: float = _TEXT_Y) -> None:
        states: list[_TextState] = []
        for t in texts:
            if not t.text.strip():  # a blank label would stop viser drawing every label
                continue
            x = t.x
            if t.joined:  # a part of a label that touches the next: its ink at x, as in every backend
                x += LABEL_HALF_PAD_EM * t.px * (1.0 if t.anchor.endswith("-right") else -1.0)
            states.append((t.text, (x, y, t.z), label_scale(t.px), t.anchor))
        slots = self._slots_for(states) if self._renew else list(range(len(states)))
        for k, state in zip(slots, states):
            self.set(k, state)
        self._order = slots
        for k in sorted(set(range(len(self._handles))) - set(slots)):
            self.hide(k)

    def _slots_for(self, states: Sequence[_TextState]) -> list[int]:
        """The label each of ``states`` goes to, so that as few as possible are made anew: one that
        shows it already, else one showing its text (it only moves), else one at its place (only its
        text changes), else one hidden or left over (made anew), else a new one."""
        free = dict(enumerate(self._shown))
        slots: list[int | None] = [None] * len(states)
        for key in _TEXT_MATCHES:
            by_key: dict[object, list[int]] = {}
            for k, shown in free.items():
                if shown is not None:
                    by_key.setdefault(key(shown), []).append(k)
            for i, state in enumerate(states):
                found = by_key.get(key(state)) if slots[i] is None else None
                if found:
                    slots[i] = k = found.pop(0)
                    del free[k]
        rest = sorted(free, key=lambda k: free[k] is not None)  # hidden ones first
        n = len(self._handles)
        return [k if k is not None else (rest.pop(0) if rest else (n := n + 1) - 1) for k in slots]

    def set(self, k: int, state: _TextState) -> None:
        text, position, scale, anchor = state
        while k > len(self._handles):  # a ruler's slots fill out of order: the ones before wait hidden
            # (a label of only blank text stops viser 1.1.1 drawing every label: never send one)
            self.set(len(self._handles), ("0", (0.0, 1e5, 0.0), 1.0, "center-left"))
            self.hide(len(self._handles) - 1)
        if k == len(self._handles):
            name = f"{self._prefix}/{k}"
            h = self._scene.add_label(
                name,
                text,
                position=position,
                font_screen_scale=scale,
                anchor=anchor,  # type: ignore[arg-type]
            )
            self._handles.append(h)
            self._shown.append(state)
            self._held.append(state)
            return
        if state == self._shown[k]:
            return
        h, old, held = self._handles[k], self._shown[k], self._held[k]
        self._held[k] = state
        # a hidden label shown again with other words is a new one too: it appears where it is set
        # at once, its words following
        if self._renew and held[0] != text and (old is None or old[1] != position):
            h.remove()
            self._made += 1
            self._handles[k] = self._scene.add_label(
                f"{self._prefix}/{k}r{self._made}",
                text,
                position=position,
                font_screen_scale=scale,
                anchor=anchor,  # type: ignore[arg-type]
            )
            self._shown[k] = state
            return
        changes: dict[str, object] = {}
        if old is None or old[0] != text:
            changes["text"] = text
        if old is None or old[2] != scale:
            changes["font_screen_scale"] = scale
        if old is None or old[3] != anchor:
            changes["anchor"] = anchor
        write_label(self._scene, h, changes, position if old is None or old[1] != position else None)
        if old is None:
            h.visible = True
        self._shown[k] = state

    @property
    def handles(self) -> tuple[viser.LabelHandle, ...]:
        return tuple(self._handles)

    def hide(self, k: int) -> None:
        if k < len(self._handles) and self._shown[k] is not None:
            self._handles[k].visible = False
            self._shown[k] = None

    @property
    def shown(self) -> list[_TextState]:
        """What each visible label shows: (text, position, font_screen_scale, anchor); those of the
        last :meth:`show` in the order of its texts, then any other in the order of the nodes."""
        given = set(self._order)
        order = [*self._order, *(k for k in range(len(self._shown)) if k not in given)]
        return [s for k in order if (s := self._shown[k]) is not None]


# three.js' ACES filmic tone mapping (react-three-fiber's default), which viser's lines go through
_ACES_IN = np.array([[0.59719, 0.35458, 0.04823], [0.07600, 0.90834, 0.01566], [0.02840, 0.13383, 0.83777]])
_ACES_OUT = np.array([[1.60475, -0.53108, -0.07367], [-0.10208, 1.10813, -0.00605], [-0.00327, -0.07276, 1.07602]])


@functools.lru_cache(maxsize=256)
def line_rgb(color: tuple[int, int, int]) -> tuple[int, int, int]:
    """The value to give a viser line so that it shows the sRGB ``color``: three.js decodes it as
    linear, tone-maps it (ACES filmic: ``out = M_out fit(M_in x / 0.6)``, ``fit(v) = (v (v +
    0.0245786) - 0.000090537) / (v (0.983729 v + 0.432951) + 0.238081)``) and encodes to sRGB; this
    inverts both. Colours paler than ACES reaches from 1 (about 226 of 255) come out as pale as it can."""
    s = np.asarray(color, dtype=float) / 255.0
    lin = np.where(s <= 0.04045, s / 12.92, ((s + 0.055) / 1.055) ** 2.4)
    w = np.linalg.solve(_ACES_OUT, lin)
    a, b, c = 1.0 - 0.983729 * w, 0.0245786 - 0.4329510 * w, -(0.000090537 + 0.238081 * w)
    v = (-b + np.sqrt(np.maximum(b * b - 4.0 * a * c, 0.0))) / (2.0 * a)
    x = 0.6 * np.linalg.solve(_ACES_IN, v)
    r, g, bl = (round(255.0 * min(max(float(t), 0.0), 1.0)) for t in x)
    return r, g, bl


def _to_linear(colors: np.ndarray, shade: Shade = "light") -> np.ndarray:
    """sRGB colours ``(n, 3)``, as sent for a ``shade`` page (:func:`sent_for_shade`), as the values
    viser's lines take (:func:`line_rgb`)."""
    c = sent_for_shade(colors, shade).astype(np.int64)
    # each colour as one integer: a 1-d unique (a row-wise one sorts structured rows, ~10x slower)
    unique, inverse = np.unique((c[:, 0] << 16) | (c[:, 1] << 8) | c[:, 2], return_inverse=True)
    mapped = np.array([line_rgb((int(v >> 16), int((v >> 8) & 255), int(v & 255))) for v in unique], dtype=np.uint8)
    return mapped[inverse.reshape(-1)].reshape(-1, 3)


class _LineNodes:
    """Line-segments nodes keyed by (width, layer): one node per key, its points replaced in place.
    Layer ``k`` is drawn at depth ``y - k _LAYER_Y`` (the camera looks along +y: smaller is nearer)."""

    def __init__(self, scene: viser.SceneApi, prefix: str, y: float = 0.0) -> None:
        self._scene = scene
        self._prefix = prefix
        self._y = y
        self._nodes: dict[tuple[float, int], viser.LineSegmentsHandle] = {}
        self._counts: dict[tuple[float, int], int] = {}
        self.shade: Shade = "light"
        """The page's ground; colours are sent for it (:func:`sent_for_shade`)."""
        self.points = np.zeros((0, 2, 3), dtype=np.float32)
        """Every segment shown, ``(n, 2, 3)`` world (page) coordinates, as last sent."""

    @property
    def handles(self) -> tuple[viser.LineSegmentsHandle, ...]:
        return tuple(self._nodes.values())

    def show(self, lines: Sequence[PageLines]) -> None:
        groups: dict[tuple[float, int], list[PageLines]] = {}
        for ln in lines:
            if len(ln.points):
                groups.setdefault((ln.width, ln.layer), []).append(ln)
        shown: list[np.ndarray] = []
        for key, members in groups.items():
            width, layer = key
            pts2 = np.concatenate([m.points for m in members])
            cols = np.concatenate([m.colors for m in members])
            pts = np.empty((len(pts2), 2, 3), dtype=np.float32)
            pts[:, :, 0] = pts2[:, :, 0]
            pts[:, :, 1] = self._y - _LAYER_Y * layer
            pts[:, :, 2] = pts2[:, :, 1]
            shown.append(pts)
            colors = np.repeat(_to_linear(cols, self.shade)[:, None, :], 2, axis=1)
            node = self._nodes.get(key)
            if node is None:
                name = f"{self._prefix}/l{layer}w{width:g}".replace(".", "_")
                self._nodes[key] = self._scene.add_line_segments(
                    name, pts, colors, thickness=width, thickness_units="screen"
                )
            else:
                node.points = pts
                node.colors = colors
                if self._counts.get(key, 0) == 0:
                    node.visible = True
            self._counts[key] = len(pts)
        for key, node in self._nodes.items():
            if key not in groups and self._counts.get(key, 0) != 0:
                node.visible = False
                self._counts[key] = 0
        self.points = np.concatenate(shown) if shown else np.zeros((0, 2, 3), dtype=np.float32)


class _DotNodes:
    """Point clouds keyed by (shape, size, layer); diameters in page px."""

    def __init__(self, scene: viser.SceneApi, prefix: str) -> None:
        self._scene = scene
        self._prefix = prefix
        self._nodes: dict[tuple[str, float, int], viser.PointCloudHandle] = {}
        self._counts: dict[tuple[str, float, int], int] = {}
        self.shade: Shade = "light"
        """The page's ground; colours are sent for it (:func:`sent_for_shade`)."""

    @property
    def handles(self) -> tuple[viser.PointCloudHandle, ...]:
        return tuple(self._nodes.values())

    def show(self, dots: Sequence[PageDots]) -> None:
        groups: dict[tuple[str, float, int], list[PageDots]] = {}
        for d in dots:
            if len(d.xy):
                groups.setdefault((d.shape, round(d.size, 1), d.layer), []).append(d)
        for key, members in groups.items():
            shape, size, layer = key
            xy = np.concatenate([m.xy for m in members])
            pts = np.stack([xy[:, 0], np.full(len(xy), -_LAYER_Y * layer - 0.2), xy[:, 1]], -1)
            cols = sent_for_shade(np.concatenate([m.colors for m in members]).astype(np.uint8), self.shade)
            node = self._nodes.get(key)
            if node is None:
                name = f"{self._prefix}/{shape}{size:g}l{layer}".replace(".", "_")
                self._nodes[key] = self._scene.add_point_cloud(
                    name, pts, cols, point_size=size / 2.0, point_shape=shape,  # type: ignore[arg-type]
                    precision="float16" if layer == 0 else "float32", point_shading="flat",
                )  # fmt: skip
            else:
                node.points = pts
                node.colors = cols
                if self._counts.get(key, 0) == 0:
                    node.visible = True
            self._counts[key] = len(pts)
        for key, node in self._nodes.items():
            if key not in groups and self._counts.get(key, 0) != 0:
                node.visible = False
                self._counts[key] = 0


class _Ruler:
    """One lane's ruler numbers: labels under a frame node at the page x of the frame's x = 0, so
    while the lane scrolls at one scale only that node moves (one message a frame); a number is
    rewritten only when the scale or the tick spacing changes or a tick enters or leaves the lane."""

    def __init__(self, scene: viser.SceneApi, prefix: str) -> None:
        self._node = scene.add_frame(prefix, show_axes=False)
        self._texts = _Texts(scene, f"{prefix}/n")
        self._origin: float | None = None
        self._slots: dict[int, int] = {}

    @property
    def handles(self) -> tuple[viser.SceneNodeHandle, ...]:
        return (*self._texts.handles, self._node)

    def hide(self) -> None:
        """No numbers: the ruler's lane is not shown."""
        for slot in range(RULER_SLOTS):
            self._texts.hide(slot)

    def show(self, lane: LanePicture, z: float, px: float) -> None:
        """Every tick's number as the lane has it (:attr:`LanePicture.ruler_numbers`), below the
        tick at height ``z``, at ``px``; tick ``n`` in slot ``n % RULER_SLOTS``."""
        if self._origin != lane.origin_px:
            self._node.position = (lane.origin_px, 0.0, 0.0)
            self._origin = lane.origin_px
        step, scale = lane.ruler_step, lane.scale
        ticks = lane.ruler_ticks.tolist()
        assert len(ticks) <= RULER_SLOTS, f"{len(ticks)} ruler ticks, {RULER_SLOTS} slots"
        wanted = {n % RULER_SLOTS: (n, text) for n, text in zip(ticks, lane.ruler_numbers, strict=True)}
        for slot in range(RULER_SLOTS):
            tick = wanted.get(slot)
            if tick is None:
                self._texts.hide(slot)
                continue
            n, text = tick
            self._texts.set(slot, (text, (n * step * scale, _TEXT_Y, z), label_scale(px), "top-center"))


def edge_text(mark: EdgeMark, px: float) -> PageText:
    """An edge mark's words (``"wall 3.2 →"``), ending at the lane's edge on its side, at ``px``."""
    return PageText(mark.text_x, mark.text_z, mark.text, px, "center-left" if mark.side < 0 else "center-right")


#: Depth of the flat still picture: behind everything else on the page (the rods' boxes reach
#: to ``y = _PAGE_ROD_DEPTH / 2``).
_FLAT_Y = 0.5 * _PAGE_ROD_DEPTH + 0.5
#: The nodes that hold the still picture's lines, dots and labels (shown or hidden together).
#: The still picture's node groups, under a page root ("/page" for a tab's own, :data:`SHARED_ROOT`).
_VECTOR_ROOTS = ("static", "static_dots", "text")
#: Where a page shared by many tabs (:func:`record_still`) is drawn: one node, removed whole.
SHARED_ROOT = "/shared"


def shared_root(picture_id: str) -> str:
    """Where the shared still picture ``picture_id`` hangs: under :data:`SHARED_ROOT`, in a node named
    for it. Each picture's labels are then new nodes, which viser's client draws with their own text
    at their own places; nodes of the same name would be updated in place, and the client moved an
    old label to its new place frames before it changed its text (a step change showed the old
    step's event names on the new step's curves)."""
    return f"{SHARED_ROOT}/p{picture_id}"


@dataclass(frozen=True)
class FlatStill:
    """A still picture as an image to send: ``png`` bytes, covering the page px rectangle
    ``box`` = (left, bottom, right, top), for page version ``version``, at ``scale``."""

    png: bytes
    box: tuple[float, float, float, float]
    version: int
    scale: float
    """Image px per page px."""


def flat_still(image: np.ndarray, scale: float, shade: Shade, version: int) -> FlatStill | None:
    """The image ``(h, w, 3)`` of a whole page (``scale`` image px per page px, sRGB, light
    ground, :func:`rigidrel_app.backends.raster.page_image`) cut to what is not white, in the
    colours to send for a ``shade`` page (:func:`sent_for_shade`; three.js shows an image's bytes
    as they are), as PNG. ``None`` for a blank page."""
    ink = np.any(image != 255, axis=-1)
    rows, cols = np.flatnonzero(ink.any(axis=1)), np.flatnonzero(ink.any(axis=0))
    if not len(rows):
        return None
    r0, r1, c0, c1 = int(rows[0]), int(rows[-1]) + 1, int(cols[0]), int(cols[-1]) + 1
    cut = sent_for_shade(image[r0:r1, c0:c1], shade)
    png = encode_png(cut)
    rows_all = image.shape[0]
    box = (c0 / scale, (rows_all - r1) / scale, c1 / scale, (rows_all - r0) / scale)
    return FlatStill(png, box, version, scale)


class PageRenderer:
    """Draws a :class:`~rigidrel_app.view.layout.CanvasLayout` page into one client's scene: the
    diagrams' static pictures once per scene, the lanes and the moving parts every frame.

    The moving parts (the lanes' boxes, lines, clocks, titles and rulers, the diagrams' now-lines
    and markers) go into ``moving`` if given: a scene of their own, which a tab's playback runtime
    draws from (recorded, :class:`~rigidrel_app.backends._viser.RecordingScene`), not the client's."""

    def __init__(self, scene: viser.SceneApi, moving: viser.SceneApi | None = None, still_root: str = "/page") -> None:
        """``still_root``: where the still picture's nodes go (``/page`` on a tab's own scene, which
        gets its lights too; :data:`SHARED_ROOT` for a recorded page many tabs share)."""
        self._scene = scene
        moving = scene if moving is None else moving
        self._moving_scene = moving
        if still_root == "/page":
            scene.configure_environment_map(None)
            scene.configure_default_lights(enabled=False)
            scene.add_light_ambient("/page/ambient", intensity=AMBIENT)
            scene.add_light_directional("/page/front_light", intensity=FRONT, position=(0.0, -10.0, 4.0))
        else:  # one node to remove it whole, and under it one of the picture's own (:func:`shared_root`)
            scene.add_frame(SHARED_ROOT, show_axes=False)
            if still_root != SHARED_ROOT:
                scene.add_frame(still_root, show_axes=False)
        # the still picture's nodes hang under these (before any of them exists), so that one
        # message each shows or hides them all
        self._vector_roots = tuple(scene.add_frame(f"{still_root}/{name}", show_axes=False) for name in _VECTOR_ROOTS)
        self.vectors_shown = True
        """Whether the still picture shows as lines, dots and labels (else only as its image)."""
        self.still_lent = False
        """Whether the tab shows a page shared with other tabs instead of its own still picture
        (:meth:`lend_still`): its own is hidden until :meth:`set_static` draws it again."""
        self._flat: viser.ImageHandle | None = None
        self.flat_version: int | None = None
        """The page version whose image is shown (``None``: no image shown)."""
        self.flat_scale = 0.0
        """The image px per page px of the image shown."""
        self.version = 0
        """Counts :meth:`set_static` calls: an image made for an older version is not shown."""
        self.still = PagePicture()
        """The still picture as last sent: the diagrams and the legend (the rulers' names apart)."""
        self.still_at = 0.0
        """When it was sent (``time.monotonic``)."""
        self._static_lines = _LineNodes(scene, f"{still_root}/static")
        self._static_dots = _DotNodes(scene, f"{still_root}/static_dots")
        self.static_texts = _Texts(scene, f"{still_root}/text", renew=True)
        self.axis_names = _Texts(scene, f"{still_root}/axis_name", renew=True)
        self.layout: CanvasLayout | None = None
        self._make_moving(moving)

    def _make_moving(self, moving: viser.SceneApi) -> None:
        self._moving_scene = moving
        self._moving_lines = _LineNodes(moving, "/page/moving")
        self._moving_dots = _DotNodes(moving, "/page/moving_dots")
        # in front of the rods' boxes (which reach to y = -_PAGE_ROD_DEPTH / 2): the ticks, clock
        # hands and light pulses are never inside a box, where the depth test may hide them
        self._lane_lines = _LineNodes(moving, "/page/lanes", _LANE_LINES_Y)
        self.titles = _Texts(moving, "/page/title")
        self._rulers = (_Ruler(moving, "/page/ruler0"), _Ruler(moving, "/page/ruler1"))
        self._boxes: viser.BatchedMeshHandle | None = None
        self._box_capacity = 0
        self._box_state: tuple[bytes, bytes, tuple[str, ...], Shade] | None = None
        self._dials: viser.BatchedMeshHandle | None = None
        self._dial_capacity = 0
        self._dial_key: tuple[float, Shade] | None = None
        if self.layout is not None:
            for nodes in (self._moving_lines, self._moving_dots, self._lane_lines):
                nodes.shade = self.layout.theme.shade

    def draw_moving_into(self, moving: viser.SceneApi) -> None:
        """Draw the moving parts into ``moving`` from now on (a tab's runtime takes them over: the
        nodes drawn so far into the client's scene are removed, and made again where they go)."""
        for handle in self._moving_handles():
            handle.remove()
        self._make_moving(moving)

    def _moving_handles(self) -> list[viser.SceneNodeHandle]:
        handles: list[viser.SceneNodeHandle] = [
            *self._moving_lines.handles,
            *self._moving_dots.handles,
            *self._lane_lines.handles,
            *self.titles.handles,
        ]
        for ruler in self._rulers:
            handles += [*ruler.handles]
        handles += [h for h in (self._boxes, self._dials) if h is not None]
        return handles

    def moving_points(self) -> np.ndarray:
        """The diagrams' moving segments (now-lines) as last sent, ``(n, 2, 3)`` page coordinates."""
        return self._moving_lines.points

    def pose(self, layout: CanvasLayout) -> cam.CameraPose:
        return cam.fit_page(layout.width, layout.height)

    def set_static(self, layout: CanvasLayout, picture: PagePicture, axis_names: Sequence[str]) -> None:
        """What does not move: the diagrams (axes, curves, events, labels), the legend, the rulers' names.
        Every colour from here on is sent for the layout theme's ground (:func:`sent_for_shade`)."""
        self._take_layout(layout)
        self.still_lent = False  # its own again: the groups are shown below (show_vectors), the names here
        self._static_lines.show(picture.lines)
        self._static_dots.show(picture.dots)
        names = [
            PageText(lane.band.x0, lane.ruler_z, name, layout.theme.title_px, "center-left")
            for lane, name in zip(layout.lanes, axis_names)  # one lane: the lab's name only
        ]
        self.static_texts.show(picture.texts)
        self.axis_names.show(names)
        self.still, self.still_at = picture, time.monotonic()
        self.version += 1
        self.show_vectors()

    def _take_layout(self, layout: CanvasLayout) -> None:
        self.layout = layout
        for nodes in (self._static_lines, self._static_dots, self._moving_lines, self._moving_dots, self._lane_lines):
            nodes.shade = layout.theme.shade

    def lend_still(self, layout: CanvasLayout) -> None:
        """The tab shows a still picture of ``layout`` drawn by others (a shared page, sent to its
        runtime): its own is hidden (one message a group), and the moving parts are drawn for
        ``layout`` from now on. :meth:`set_static` draws its own again."""
        self._take_layout(layout)
        if not self.still_lent:
            self.still_lent = True
            if self.vectors_shown:
                for root in self._vector_roots:
                    root.visible = False
                self.vectors_shown = False
            for k in range(len(self.axis_names.handles)):
                self.axis_names.hide(k)
        if self._flat is not None and self.flat_version is not None:
            self._flat.visible = False
            self.flat_version = None
        self.version += 1  # an image of the picture it had is not shown

    def show_vectors(self) -> None:
        """The still picture as lines, dots and labels; its image, if any, taken away."""
        if not self.vectors_shown:
            for root in self._vector_roots:
                root.visible = True
            self.vectors_shown = True
        if self._flat is not None and self.flat_version is not None:
            self._flat.visible = False
            self.flat_version = None

    def show_flat(self, flat: FlatStill) -> bool:
        """Put ``flat`` (an image of the still picture) behind the picture's lines, dots and labels;
        ``False`` (nothing sent) if it was made for an older picture. :meth:`hide_vectors` then
        leaves it alone, once the browser has had time to decode it."""
        if flat.version != self.version:
            return False
        layout = self.layout
        assert layout is not None, "set_static first"
        # behind the page, scaled about the camera's axis so that it looks the page's size: each
        # image px on one canvas px (a texture drawn even slightly smaller blurs)
        pose = self.pose(layout)
        grow = (abs(pose.position[1]) + _FLAT_Y) / abs(pose.position[1])
        xc, zc = pose.look_at[0], pose.look_at[2]
        left, bottom, right, top = flat.box
        w, h = grow * (right - left), grow * (top - bottom)
        position = (xc + grow * (0.5 * (left + right) - xc), _FLAT_Y, zc + grow * (0.5 * (bottom + top) - zc))
        # the image's plane faces the camera (on -y), its first row at the top (+z)
        wxyz = (np.sqrt(0.5), -np.sqrt(0.5), 0.0, 0.0)
        if self._flat is None:
            self._flat = make_image(self._scene, "/page/flat", flat.png, (w, h), wxyz, position)
        else:
            set_image_png(self._flat, flat.png)
            if (self._flat.render_width, self._flat.render_height) != (w, h):
                self._flat.render_width, self._flat.render_height = w, h
            if tuple(self._flat.position) != position:
                self._flat.position = position
            self._flat.visible = True
        self.flat_version, self.flat_scale = flat.version, flat.scale
        return True

    def hide_vectors(self) -> None:
        """Leave the still picture to its image (:meth:`show_flat`): its lines, dots and labels hidden."""
        if self.vectors_shown and self.flat_version == self.version:
            for root in self._vector_roots:
                root.visible = False
            self.vectors_shown = False

    def update(self, lanes: Sequence[LanePicture], moving: PagePicture) -> None:
        """One instant: both lanes and the diagrams' moving parts (call inside ``atomic()``)."""
        layout = self.layout
        assert layout is not None, "set_static first"
        theme = layout.theme
        self._update_boxes([b for lane in lanes for b in lane.boxes], theme.shade)
        lines: list[PageLines] = []
        for lane in lanes:
            for seg in lane.segments:
                n = seg.x0.size
                if n == 0:
                    continue
                pts = np.stack([np.stack([seg.x0, seg.y0], -1), np.stack([seg.x1, seg.y1], -1)], axis=1)
                color = color_rgb(theme.ink if seg.style.color == INK else seg.style.color)
                lines.append(PageLines(pts, np.tile(color, (n, 1)), theme.line_px, 0))
        self._lane_lines.show(lines)
        dials = np.concatenate([lane.dials for lane in lanes]) if lanes else np.zeros((0, 2))
        self._update_dials(dials, clock_radius(theme), theme.shade)
        self.titles.show(
            [
                PageText(p.band.x0, p.title_z, *lane_title_text(lane.title, p, theme.title_px), "top-left")
                for p, lane in zip(layout.lanes, lanes)
            ]
            + [edge_text(m, theme.text_px) for lane in lanes for m in lane.edge_marks]
            + [PageText(n.x, n.z, n.text, n.px, "center-center") for lane in lanes for n in lane.names]
        )
        for k, ruler in enumerate(self._rulers):
            if k < len(lanes):
                place = layout.lanes[k]
                ruler.show(lanes[k], place.ruler_z - place.tick_px - 2.0, theme.text_px)
            else:  # a lane not shown (:class:`~rigidrel_app.view.layout.Panels`)
                ruler.hide()
        self._moving_lines.show(moving.lines)
        self._moving_dots.show(moving.dots)

    def reserve(self, boxes: int, dials: int) -> None:
        """Room for this many boxes and clock dials, made before any frame needs it (a recording
        reserves what its frames will show, so that no frame makes or removes a node)."""
        if boxes > self._box_capacity:
            self._box_capacity = boxes
            if self._boxes is not None:
                self._boxes.remove()
                self._boxes = None
        if dials > self._dial_capacity:
            self._dial_capacity = dials
            if self._dials is not None:
                self._dials.remove()
                self._dials = None

    def _update_boxes(self, boxes: Sequence[Box], shade: Shade) -> None:
        if len(boxes) > self._box_capacity or self._box_capacity == 0:  # never a mesh of no instances
            self.reserve(max(len(boxes), 4), self._dial_capacity)
        n = self._box_capacity
        positions = np.tile(np.array((0.0, 1e5, 0.0), dtype=np.float32), (n, 1))
        scales = np.full((n, 3), 1e-6, dtype=np.float32)
        for k, b in enumerate(boxes):
            positions[k] = (0.5 * (b.x0 + b.x1), 0.0, b.z)
            scales[k] = (max(b.x1 - b.x0, 0.5), _PAGE_ROD_DEPTH, b.height)
        names = tuple(b.color for b in boxes) + ("#ffffff",) * (n - len(boxes))
        colors = _instance_colors(names, shade)
        if self._boxes is None:
            self._boxes = self._moving_scene.add_batched_meshes_simple(
                "/page/boxes", _CUBE_VERTICES, _CUBE_FACES,
                batched_wxyzs=np.tile(np.array([1.0, 0.0, 0.0, 0.0], dtype=np.float32), (n, 1)),
                batched_positions=positions, batched_scales=scales, batched_colors=colors,
                flat_shading=True, lod="off", cast_shadow=False, receive_shadow=False,
            )  # fmt: skip
            self._box_state = (positions.tobytes(), scales.tobytes(), names, shade)
            return
        old = self._box_state
        if old is None or old[0] != positions.tobytes():
            self._boxes.batched_positions = positions
        if old is None or old[1] != scales.tobytes():
            self._boxes.batched_scales = scales
        if old is None or old[2:] != (names, shade):
            self._boxes.batched_colors = colors
        self._box_state = (positions.tobytes(), scales.tobytes(), names, shade)

    def _update_dials(self, centres: np.ndarray, radius: float, shade: Shade) -> None:
        n = len(centres)
        if n > self._dial_capacity:
            self.reserve(self._box_capacity, max(n, 4))
        positions = np.zeros((max(self._dial_capacity, 1), 3), dtype=np.float32)
        positions[:, 1] = 1e5  # the unused instances out of sight
        if n:
            positions[:n, 0], positions[:n, 1], positions[:n, 2] = centres[:, 0], _LANE_LINES_Y + 0.5, centres[:, 1]
        key = (radius, shade)
        if self._dials is None or key != self._dial_key:
            if self._dials is not None:
                self._dials.remove()
            vertices, faces = _ring(radius, width=0.2)
            self._dials = self._moving_scene.add_batched_meshes_simple(
                "/page/dials", vertices, faces,
                batched_wxyzs=np.tile(np.array([1.0, 0.0, 0.0, 0.0], dtype=np.float32), (len(positions), 1)),
                batched_positions=positions, batched_colors=np.array(linear_rgb(INK, shade), dtype=np.uint8),
                flat_shading=True, lod="off", cast_shadow=False, receive_shadow=False, side="double",
            )  # fmt: skip
            self._dial_key = key
        else:
            self._dials.batched_positions = positions
