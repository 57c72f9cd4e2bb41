"""Raster pictures (Pillow): the lanes as frames for animated GIF and, where ffmpeg is available,
MP4; and a canvas page's still picture as one image, which the live app shows in place of its
diagrams' lines, dots and labels while it plays (:func:`page_image`).

A third backend of the drawing vocabulary: the same :class:`LaneState` s and
:class:`~rigidrel_app.view.canvas.PagePicture` s the app sends to viser, drawn flat, as the app's
camera sees them head-on.
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from functools import lru_cache
from pathlib import Path

import numpy as np
from PIL import Image, ImageDraw, ImageFont

from ..view.canvas import PagePicture, PageText
from ..view.lanes import Box, LaneState, rod_names
from ..view.objects import OBJECT_STYLES
from ..view.scene_view import FRAME_Z, LAB_Z, LANE_Z, Drawn, lane_states
from ..view.vocabulary import (
    FRAME_COLOR,
    INK,
    ROD_COLORS,
    Shade,
    lightness_flipped,
    plain_text,
    rgb,
)

#: The page's text as the browser draws viser's labels (Arial, which Debian's fontconfig gives
#: as Liberation Sans), then DejaVu Sans for what Liberation Sans lacks (sub- and superscripts).
_PAGE_FONTS = (
    "/usr/share/fonts/truetype/liberation/LiberationSans-Regular.ttf",
    "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf",
)
_FONTS = (
    "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf",
    "/usr/share/fonts/truetype/liberation/LiberationSans-Regular.ttf",
)


#: Blank margin left and right, as a fraction of the lanes' x range.
_MARGIN = 0.02


@lru_cache(maxsize=64)
def _first_font(paths: tuple[str, ...], size: int) -> ImageFont.FreeTypeFont | ImageFont.ImageFont:
    """The first of the font files ``paths`` this machine has, at ``size`` px; else Pillow's own."""
    for path in paths:
        if Path(path).exists():
            return ImageFont.truetype(path, size)
    return ImageFont.load_default(size=size)


def _font(size: int) -> ImageFont.FreeTypeFont | ImageFont.ImageFont:
    return _first_font(_FONTS, size)


class LaneRaster:
    """Maps lane coordinates (x, z) to pixels with one scale for both axes (true proportions)."""

    def __init__(self, drawn: Drawn, width: int) -> None:
        x0, x1 = drawn.lane_x_range
        margin = _MARGIN * (x1 - x0)  # lane titles start at the ruler's left end: keep them off the edge
        self.x0, self.x1 = x0 - margin, x1 + margin
        self.z0, self.z1 = FRAME_Z - 0.45, LAB_Z + 0.6
        self.width = width
        self.scale = width / (self.x1 - self.x0)
        self.height = round((self.z1 - self.z0) * self.scale) // 2 * 2  # even, for video encoders
        self.drawn = drawn
        self._static = drawn.lane_statics()

    def px(self, x: np.ndarray | float, z: np.ndarray | float) -> tuple[np.ndarray, np.ndarray]:
        return (np.asarray(x) - self.x0) * self.scale, (self.z1 - np.asarray(z)) * self.scale

    def frame(self, states: Sequence[LaneState]) -> Image.Image:
        img = Image.new("RGB", (self.width, self.height), "white")
        d = ImageDraw.Draw(img)
        for (ruler, labels), z in zip(self._static, LANE_Z, strict=True):
            self._segments(d, ruler.x0, ruler.y0 + z, ruler.x1, ruler.y1 + z, FRAME_COLOR, 1)
            for lab in labels:
                self._text(d, lab.x, lab.y + z, plain_text(lab.text), FRAME_COLOR, lab.size, lab.anchor)
        for st, z in zip(states, LANE_Z, strict=True):
            bars = [self._bar_px(b, z) for b in st.boxes]
            for b in bars:
                d.rectangle([b.x0, b.z - b.height / 2, max(b.x1, b.x0 + 1), b.z + b.height / 2], fill=rgb(b.color))
            seg = st.segments
            self._segments(d, seg.x0, seg.y0 + z, seg.x1, seg.y1 + z, INK, 2)
            r = self.drawn.geometry.clock_radius * self.scale
            for cx, cz in st.dials.tolist():
                (u,), (v,) = self.px(np.array([cx]), np.array([cz + z]))
                d.ellipse([float(u) - r, float(v) - r, float(u) + r, float(v) + r], outline=rgb(INK), width=2)
            for lab in st.labels:
                self._text(d, lab.x, lab.y + z, plain_text(lab.text), INK, lab.size, lab.anchor)
            self._names(d, bars[: self.drawn.resolved.scene.n_rods])
        return img

    def _bar_px(self, b: Box, z: float) -> Box:
        """A lane's box ``b`` (the lane at height ``z``) in pixels: x to the right, its centre ``z``
        and its height in pixels down the image."""
        (u0, u1), (v0, v1) = self.px(np.array([b.x0, b.x1]), z + b.z + np.array([0.5, -0.5]) * b.height)
        return Box(float(u0), float(u1), float(v1 - v0), b.color, 0.5 * float(v0 + v1))

    def _names(self, d: ImageDraw.ImageDraw, rods: Sequence[Box]) -> None:
        """The names of the rods that share a row on their bars ``rods`` (pixels), ink on a white box
        (as the app's)."""
        for name in rod_names(self.drawn.resolved.scene, rods, max(9, round(12 * self.width / 1100))):
            font = _font(round(name.px))
            box = d.textbbox((name.x, name.z), name.text, font=font, anchor="mm")
            d.rectangle((box[0] - 2, box[1] - 1, box[2] + 2, box[3] + 1), fill=(255, 255, 255))
            d.text((name.x, name.z), name.text, fill=rgb(INK), font=font, anchor="mm")

    def _segments(
        self,
        d: ImageDraw.ImageDraw,
        x0: np.ndarray,
        z0: np.ndarray,
        x1: np.ndarray,
        z1: np.ndarray,
        color: str,
        width: int,
    ) -> None:
        u0, v0 = self.px(x0, z0)
        u1, v1 = self.px(x1, z1)
        c = rgb(color)
        for a, b, e, f in zip(u0.tolist(), v0.tolist(), u1.tolist(), v1.tolist(), strict=True):
            d.line([(a, b), (e, f)], fill=c, width=width)

    def _text(
        self, d: ImageDraw.ImageDraw, x: float, z: float, text: str, color: str, size: float, anchor: str
    ) -> None:
        u, v = self.px(x, z)
        pil_anchor = {"left": "lm", "right": "rm", "center": "mm"}[anchor]
        d.text(
            (float(u), float(v)),
            text,
            fill=rgb(color),
            font=_font(max(9, round(size * self.width / 1100))),
            anchor=pil_anchor,
        )


def shaded_frame(img: Image.Image, shade: Shade) -> Image.Image:
    """A light frame as shown on a ``shade`` ground: on dark, every pixel lightness-flipped (the
    same hue; the live app's dark theme, :func:`~rigidrel_app.view.vocabulary.lightness_flipped`)."""
    return img if shade == "light" else Image.fromarray(lightness_flipped(np.asarray(img.convert("RGB"))))


def lane_frames(
    drawn: Drawn, times: Iterable[float], width: int = 960, shade: Shade = "light"
) -> Iterable[Image.Image]:
    raster = LaneRaster(drawn, width)
    for now in times:
        yield shaded_frame(raster.frame(lane_states(drawn, float(now))), shade)


#: A fixed palette for GIF frames: white, ink, the rods, every object role's colour (the bodies': a
#: wall's, a door's), the frame colour, the stops of the objects' field ramps (a string's strain: a
#: colour between two stops comes out as the nearer), greys.
_PALETTE_COLORS = [
    (255, 255, 255),
    rgb(INK),
    *(rgb(c) for c in ROD_COLORS),
    *(rgb(s.color) for s in OBJECT_STYLES.values() if not s.ramp),
    rgb(FRAME_COLOR),
    *(rgb(c) for s in OBJECT_STYLES.values() for c in s.ramp),
    (128, 128, 128),
    (200, 200, 200),
    (64, 64, 64),
]


def _palette_image(shade: Shade = "light") -> Image.Image:
    pal = Image.new("P", (1, 1))
    colors = np.array(_PALETTE_COLORS, dtype=np.uint8)
    flat = [int(v) for v in (colors if shade == "light" else lightness_flipped(colors)).ravel()]
    pal.putpalette(flat + [0] * (768 - len(flat)))
    return pal


def write_gif(
    drawn: Drawn, path: Path, times: np.ndarray, fps: float, width: int = 960, shade: Shade = "light"
) -> Path:
    pal = _palette_image(shade)
    frames = [f.quantize(palette=pal, dither=Image.Dither.NONE) for f in lane_frames(drawn, times, width, shade)]
    frames[0].save(
        path, save_all=True, append_images=frames[1:], duration=round(1000 / fps), loop=0, optimize=False, disposal=1
    )
    return path


def write_mp4(
    drawn: Drawn, path: Path, times: np.ndarray, fps: float, width: int = 960, shade: Shade = "light"
) -> Path | None:
    """H.264 MP4 through the ffmpeg of ``imageio-ffmpeg`` (PyPI); ``None`` if it is not installed."""
    try:
        import imageio_ffmpeg
    except ImportError:
        return None
    raster = LaneRaster(drawn, width)
    writer = imageio_ffmpeg.write_frames(
        str(path),
        (raster.width, raster.height),
        fps=fps,  # pyright: ignore[reportArgumentType]  (ffmpeg takes fractional rates)
        codec="libx264",
        pix_fmt_out="yuv420p",
        quality=7,
        macro_block_size=2,
    )
    writer.send(None)
    for now in times:
        writer.send(shaded_frame(raster.frame(lane_states(drawn, float(now))), shade).tobytes())
    writer.close()
    return path


# ---------------------------------------------------------------------------------------------
# A page's still picture


#: Samples per image px along each axis for the lines and dots (anti-aliasing by supersampling).
PAGE_SUPERSAMPLE = 3
#: viser's label: black text on a box of white at this opacity, padded by this many em.
LABEL_BOX_ALPHA = 0.85
LABEL_BOX_PAD_EM = 0.15
#: Line spacing of a label of several lines, in em (viser's label layout).
LABEL_LINE_EM = 1.2
#: Coverage -> opacity of a label's glyph edges: viser's labels (distance fields re-thresholded
#: over one pixel) ink a glyph's edge pixels more than FreeType's coverage does.
LABEL_INK_GAMMA = 0.6
_INK_WEIGHT = [round(255.0 * (v / 255.0) ** LABEL_INK_GAMMA) for v in range(256)]
_ANCHORS = {
    "top-left": "la", "top-center": "ma", "top-right": "ra",
    "center-left": "lm", "center-center": "mm", "center-right": "rm",
    "bottom-left": "ld", "bottom-center": "md", "bottom-right": "rd",
}  # fmt: skip


def _page_font(size: int, fallback: bool) -> ImageFont.FreeTypeFont | ImageFont.ImageFont:
    return _first_font(_PAGE_FONTS[1:] if fallback else _PAGE_FONTS, size)


def _needs_fallback(ch: str) -> bool:
    """Characters the first page font lacks: super- and subscripts (U+2070 to U+209F)."""
    return "\u2070" <= ch <= "\u209f"


def page_image(picture: PagePicture, width: float, height: float, scale: float = 1.0) -> np.ndarray:
    """The still ``picture`` of a ``width`` x ``height`` page (page px: x right, z up from the
    bottom) as an sRGB image ``(round(height scale), round(width scale), 3)`` on white, ``scale``
    image px per page px (the canvas' rendered pixels per CSS px: its texels then fall on the
    rendered pixels, unblurred), as viser draws it: each layer's lines (round ends) and then its dots, the
    lower layers first, all anti-aliased (drawn at :data:`PAGE_SUPERSAMPLE` times the size and
    averaged down); then the labels, black on a :data:`LABEL_BOX_ALPHA` white box."""
    s = scale * PAGE_SUPERSAMPLE
    w, h = round(width * scale), round(height * scale)
    big = Image.new("RGB", (w * PAGE_SUPERSAMPLE, h * PAGE_SUPERSAMPLE), (255, 255, 255))
    d = ImageDraw.Draw(big)
    layers = sorted({ln.layer for ln in picture.lines} | {dt.layer for dt in picture.dots})
    for layer in layers:
        for ln in picture.lines:
            if ln.layer != layer or not len(ln.points):
                continue
            u = ln.points[:, :, 0] * scale
            v = (height - ln.points[:, :, 1]) * scale
            # a level or upright line's edges on pixel edges, as a GPU fills it (not two grey pixels)
            half = 0.5 * ln.width * scale
            level, upright = v[:, 0] == v[:, 1], u[:, 0] == u[:, 1]
            v[level] = np.round(v[level] - half) + half
            u[upright] = np.round(u[upright] - half) + half
            u, v = u * PAGE_SUPERSAMPLE - 0.5, v * PAGE_SUPERSAMPLE - 0.5  # Pillow: integers are pixel centres
            lw = max(1, round(ln.width * s))
            r = 0.5 * ln.width * s
            for (a, b), (e, f), color in zip(u.tolist(), v.tolist(), ln.colors.tolist(), strict=True):
                fill = (color[0], color[1], color[2])
                d.line([(a, e), (b, f)], fill=fill, width=lw)
                if lw > 2:  # round ends, as viser's lines have (the joints of a curve too)
                    d.ellipse([a - r, e - r, a + r, e + r], fill=fill)
                    d.ellipse([b - r, f - r, b + r, f + r], fill=fill)
        for dt in picture.dots:
            if dt.layer != layer or not len(dt.xy):
                continue
            r = 0.5 * dt.size * s
            u = dt.xy[:, 0] * s - 0.5
            v = (height - dt.xy[:, 1]) * s - 0.5
            for x, z, color in zip(u.tolist(), v.tolist(), dt.colors.tolist(), strict=True):
                fill = (color[0], color[1], color[2])
                if dt.shape == "square":
                    d.rectangle([x - r, z - r, x + r, z + r], fill=fill)
                elif dt.shape == "diamond":
                    d.polygon([(x, z - r), (x + r, z), (x, z + r), (x - r, z)], fill=fill)
                else:
                    d.ellipse([x - r, z - r, x + r, z + r], fill=fill)
    img = big.reduce(PAGE_SUPERSAMPLE)
    for t in picture.texts:
        if t.text.strip():
            _page_label(img, t, height, scale)
    return np.asarray(img)


def _runs(text: str) -> list[tuple[str, bool]]:
    """``text`` cut into runs of one font: (characters, whether the fallback font draws them)."""
    runs: list[tuple[str, bool]] = []
    for ch in text:
        fb = _needs_fallback(ch)
        if runs and runs[-1][1] == fb:
            runs[-1] = (runs[-1][0] + ch, fb)
        else:
            runs.append((ch, fb))
    return runs


def _page_label(img: Image.Image, t: PageText, height: float, scale: float) -> None:
    """One label onto ``img``: its lines' runs measured, the box laid at the anchor, then drawn."""
    size = max(1, round(t.px * scale))
    lines = t.text.split("\n")
    fonts = (_page_font(size, False), _page_font(size, True))
    ascent, descent = fonts[0].getmetrics() if isinstance(fonts[0], ImageFont.FreeTypeFont) else (size, 0)
    step = LABEL_LINE_EM * size
    widths = [sum(fonts[fb].getlength(run) for run, fb in _runs(line)) for line in lines]
    box_w, box_h = max(widths), step * (len(lines) - 1) + ascent + descent
    x, y = t.x * scale, (height - t.z) * scale
    horizontal, vertical = _ANCHORS[t.anchor]
    across = {"l": 0.0, "m": 0.5, "r": 1.0}[horizontal]  # the share of a line's width left of x
    left = x - across * box_w
    top = y - {"a": 0.0, "m": 0.5, "d": 1.0}[vertical] * box_h
    pad = LABEL_BOX_PAD_EM * size
    box = (round(left - pad), round(top - pad), round(left + box_w + pad), round(top + box_h + pad))
    region = img.crop(box)
    img.paste(Image.blend(region, Image.new("RGB", region.size, (255, 255, 255)), LABEL_BOX_ALPHA), box[:2])
    ink = Image.new("L", region.size, 0)
    d = ImageDraw.Draw(ink)
    for k, (line, lw) in enumerate(zip(lines, widths, strict=True)):
        u = left - box[0] + across * (box_w - lw)
        for run, fb in _runs(line):
            d.text((u, top - box[1] + k * step + ascent), run, fill=255, font=fonts[fb], anchor="ls")
            u += fonts[fb].getlength(run)
    img.paste((0, 0, 0), box[:2], ink.point(_INK_WEIGHT))
