"""``rigidrel export``: every lecture format of one scene and frame, into one folder."""

from __future__ import annotations

import time
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

import rigidrel_core as rr

from ..backends.plotly import shaded_figure
from ..backends.raster import write_gif, write_mp4
from ..view.scene_view import build_drawing
from ..view.state import Resolved, settings_for
from ..view.vocabulary import Shade
from .diagram import slide_diagram
from .diagram_html import diagram_html
from .images import image_writer
from .recording import playback_times, record_lanes_html


@dataclass(frozen=True)
class Written:
    path: Path
    seconds: float
    """Time it took to write."""

    @property
    def megabytes(self) -> float:
        return self.path.stat().st_size / 1e6


def export_scene(
    scene: rr.Scene,
    frame: rr.Frame,
    out: Path,
    seconds: float = 10.0,
    fps: float = 30.0,
    gif_fps: float = 15.0,
    width: int = 960,
    shade: Shade = "light",
) -> list[Written]:
    """Write the 3-D HTML, the slider HTML, PNG and SVG of the diagram, a GIF and (with ffmpeg) an MP4,
    each on a ``shade`` ground (dark: the live app's dark theme, every colour lightness-flipped)."""
    out.mkdir(parents=True, exist_ok=True)
    stem = scene.kind
    drawn = build_drawing(Resolved(scene, frame, None))
    written: list[Written] = []

    def timed(path: Path, make: Callable[[Path], object]) -> None:
        t0 = time.perf_counter()
        result = make(path)
        if result is not None:
            written.append(Written(path, time.perf_counter() - t0))

    timed(
        out / f"{stem}-3d.html",
        lambda p: p.write_text(record_lanes_html(drawn, seconds, fps, shade=shade), encoding="utf-8"),
    )
    timed(
        out / f"{stem}-diagram.html",
        lambda p: p.write_text(diagram_html(settings_for(scene, frame), shade=shade), encoding="utf-8"),
    )
    fig = shaded_figure(slide_diagram(scene, frame), shade)
    with image_writer() as writer:
        timed(out / f"{stem}-diagram.png", lambda p: writer.write(fig, p, 760, 640, scale=2.0))
        timed(out / f"{stem}-diagram.svg", lambda p: writer.write(fig, p, 760, 640))
    timed(
        out / f"{stem}-lanes.gif",
        lambda p: write_gif(drawn, p, playback_times(drawn, seconds, gif_fps), gif_fps, width, shade),
    )
    timed(
        out / f"{stem}-lanes.mp4",
        lambda p: write_mp4(drawn, p, playback_times(drawn, seconds, fps), fps, width, shade),
    )
    return written
