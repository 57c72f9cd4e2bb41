"""Export a scene for a lecture: offline pages and a GIF, written without a server or a browser.

Fig. 4's collision (M1 = 2 M2) in the barycentric frame: a 3-D recording of both lanes that
plays from disk, a diagram page with two sliders, and a GIF for slides. ``rigidrel export``
writes these and the PNG, SVG and MP4 too (those need Chromium and ffmpeg).
"""

import sys
import tempfile
from pathlib import Path

import rigidrel_core as rr
from rigidrel_app.backends.raster import write_gif
from rigidrel_app.export.diagram_html import diagram_html
from rigidrel_app.export.recording import playback_times, record_lanes_html
from rigidrel_app.view.scene_view import build_drawing
from rigidrel_app.view.state import Resolved, settings_for


def export(out: Path) -> list[Path]:
    scene = rr.build_scene("rod-collision", mass2=0.5)  # Fig. 4: M1 = 2 M2
    frame = scene.frame("barycentric")
    drawn = build_drawing(Resolved(scene, frame))
    lanes = out / "fig4-3d.html"
    lanes.write_text(record_lanes_html(drawn, seconds=6.0, fps=20.0), encoding="utf-8")
    page = out / "fig4-diagram.html"
    page.write_text(diagram_html(settings_for(scene, frame)), encoding="utf-8")
    gif = write_gif(drawn, out / "fig4-lanes.gif", playback_times(drawn, 6.0, 10.0), 10.0, width=720)
    return [lanes, page, gif]


def main() -> None:
    out = Path(sys.argv[1]) if len(sys.argv) > 1 else Path(tempfile.mkdtemp(prefix="rigidrel-"))
    out.mkdir(parents=True, exist_ok=True)
    for path in export(out):
        print(f"{path}  {path.stat().st_size / 1e6:.2f} MB")


if __name__ == "__main__":
    main()
