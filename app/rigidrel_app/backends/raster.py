"""The lanes as raster frames (Pillow), for animated GIF and, where ffmpeg is available, MP4.

A third backend of the drawing vocabulary: the same :class:`LaneState` s the app sends to
viser, drawn flat, as the app's camera sees them head-on.
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from functools import lru_cache
from pathlib import Path

import numpy as np
from PIL import Image, ImageDraw, ImageFont

from ..view.lanes import LaneState
from ..view.scene_view import FRAME_Z, LAB_Z, LANE_Z, Drawn, lane_states
from ..view.vocabulary import (
    DOOR_COLOR,
    FRAME_COLOR,
    INK,
    ROD_COLORS,
    STRAIN_RAMP,
    WALL_COLOR,
    Shade,
    lightness_flipped,
    plain_text,
    rgb,
)

_FONTS = (
    "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf",
    "/usr/share/fonts/truetype/liberation/LiberationSans-Regular.ttf",
)


#: Blank margin left and right, as a fraction of the lanes' x range.
_MARGIN = 0.02


@lru_cache(maxsize=8)
def _font(size: int) -> ImageFont.FreeTypeFont | ImageFont.ImageFont:
    for path in _FONTS:
        if Path(path).exists():
            return ImageFont.truetype(path, size)
    return ImageFont.load_default(size=size)


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
            for b in st.boxes:
                (u0, u1), (v0, v1) = self.px(
                    np.array([b.x0, b.x1]), np.array([z + b.z + b.height / 2, z + b.z - b.height / 2])
                )
                d.rectangle([float(u0), float(v0), max(float(u1), float(u0) + 1), float(v1)], fill=rgb(b.color))
            seg = st.segments
            self._segments(d, seg.x0, seg.y0 + z, seg.x1, seg.y1 + z, INK, 2)
            r = self.drawn.geometry.clock_radius * self.scale
            for cx, cz in st.dials.tolist():
                (u,), (v,) = self.px(np.array([cx]), np.array([cz + z]))
                d.ellipse([float(u) - r, float(v) - r, float(u) + r, float(v) + r], outline=rgb(INK), width=2)
            for lab in st.labels:
                self._text(d, lab.x, lab.y + z, plain_text(lab.text), INK, lab.size, lab.anchor)
        return img

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


#: A fixed palette for GIF frames: white, ink, the rods, the wall and the door, the frame colour, the
#: stops of a string's strain colours (a colour between two stops comes out as the nearer), greys.
_PALETTE_COLORS = [
    (255, 255, 255),
    rgb(INK),
    *(rgb(c) for c in ROD_COLORS),
    rgb(WALL_COLOR),
    rgb(DOOR_COLOR),
    rgb(FRAME_COLOR),
    *(rgb(c) for c in STRAIN_RAMP),
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
