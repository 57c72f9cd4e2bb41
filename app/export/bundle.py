"""``rigidrel export``: every lecture format of one scene and frame, into one folder."""

from __future__ import annotations

import math
import time
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import rigidrel_core as rr
from rigidrel_core import SceneKind

from ..diagrams import frame_title
from ..drawing import build_drawing
from ..notebook import diagram
from ..settings import CUSTOM_FRAME, Resolved, Settings
from .diagram_html import diagram_html
from .images import image_writer
from .raster import write_gif, write_mp4
from .recording import playback_times, record_lanes_html


@dataclass(frozen=True)
class Written:
    path: Path
    seconds: float
    """Time it took to write."""

    @property
    def megabytes(self) -> float:
        return self.path.stat().st_size / 1e6


def settings_for(scene: rr.Scene, frame: rr.Frame) -> Settings:
    """The app's settings (rod 1's rest length and mass as units) for the scene's parameters."""
    p = dict(scene.parameters)
    frame_name = frame.name if frame.name in scene.frames else CUSTOM_FRAME
    common = {"frame": frame_name, "beta": frame.beta}
    kind = scene.kind
    if kind is SceneKind.ROD_COLLISION:
        return Settings(
            kind,
            v=p["v1"],
            v2=p["v2"],
            log_mass_ratio=math.log10(p["m2"] / p["m1"]),
            eps=p["eps"],
            length_ratio=p["l2"] / p["l1"],
            **common,
        )
    if kind in (SceneKind.CONSTANT_ACCELERATION, SceneKind.DECELERATION):
        return Settings(kind, v=p["v"], a_front_length=p["a_front"] * p["length"], **common)
    if kind is SceneKind.WALL_COLLISION:
        return Settings(kind, v=p["v"], eps=p["eps"], **common)
    if kind is SceneKind.IMPULSIVE_START:
        return Settings(kind, v=p["v"], **common)
    raise rr.ParameterError("scene", "one of the app's scenes (velocity-change has no slider page)", kind.value)


def export_scene(
    scene: rr.Scene,
    frame: rr.Frame,
    out: Path,
    seconds: float = 10.0,
    fps: float = 30.0,
    gif_fps: float = 15.0,
    width: int = 960,
) -> list[Written]:
    """Write the 3-D HTML, the slider HTML, PNG and SVG of the diagram, a GIF and (with ffmpeg) an MP4."""
    out.mkdir(parents=True, exist_ok=True)
    stem = scene.kind.value
    drawn = build_drawing(Resolved(scene, frame, None))
    written: list[Written] = []

    def timed(path: Path, make: Callable[[Path], object]) -> None:
        t0 = time.perf_counter()
        result = make(path)
        if result is not None:
            written.append(Written(path, time.perf_counter() - t0))

    timed(out / f"{stem}-3d.html", lambda p: p.write_text(record_lanes_html(drawn, seconds, fps), encoding="utf-8"))
    if scene.kind is not SceneKind.VELOCITY_CHANGE:
        timed(
            out / f"{stem}-diagram.html",
            lambda p: p.write_text(diagram_html(settings_for(scene, frame)), encoding="utf-8"),
        )
    fig = slide_diagram(scene, frame)
    with image_writer() as writer:
        timed(out / f"{stem}-diagram.png", lambda p: writer.write(fig, p, 760, 640, scale=2.0))
        timed(out / f"{stem}-diagram.svg", lambda p: writer.write(fig, p, 760, 640))
    timed(
        out / f"{stem}-lanes.gif",
        lambda p: write_gif(drawn, p, playback_times(drawn, seconds, gif_fps), gif_fps, width),
    )
    timed(out / f"{stem}-lanes.mp4", lambda p: write_mp4(drawn, p, playback_times(drawn, seconds, fps), fps, width))
    return written


def slide_diagram(scene: rr.Scene, frame: rr.Frame) -> dict[str, Any]:
    """The Minkowski diagram in ``frame`` with a title, for slides (PNG/SVG)."""
    fig = diagram(scene, frame, size=(760, 640)).to_dict()
    fig["layout"]["title"] = {"text": f"{scene.kind.value}: Minkowski diagram, {frame_title(frame)} frame", "x": 0.02}
    return fig
