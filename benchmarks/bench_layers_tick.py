"""What one playback frame costs the server with and without the light-signal layer (a script
that prints figures, not a test).

    python -m benchmarks.bench_layers_tick

Times what ``Session.draw_now`` computes before it sends anything: both lanes' pictures (with the
light pulses when the signals are shown), the diagrams' moving items and their page pictures, at
100 instants across the window, for a 1280x720 canvas. CPU time of this process (``process_time``:
steadier than wall time on a shared machine), the best and the median of 7 passes, per frame.
"""

from __future__ import annotations

import time

import numpy as np

from rigidrel_app.view.canvas import chart_picture, moving_picture
from rigidrel_app.view.layers import DEFAULT_LAYERS, Layer
from rigidrel_app.view.layout import canvas_layout
from rigidrel_app.view.scene_view import build_drawing
from rigidrel_app.view.state import Resolved, presets, resolve

SCENES = ("Sec. 5: crash into a wall, V = 0.6", "Fig. 3: collision, M2 = 2 M1")
PASSES = 7
FRAMES = 100


def per_frame_ms(preset: str, layers: frozenset[Layer]) -> tuple[float, float]:
    layout = canvas_layout(1280, 720)
    r = resolve(presets()[preset].with_layers(layers))
    assert isinstance(r, Resolved), r
    d = build_drawing(r, areas=layout.chart_areas)
    frames = [
        None if p is None else chart_picture(c, p, layout.theme)[0]
        for c, p in zip(d.charts, layout.charts, strict=True)
    ]

    def draw(now: float) -> None:
        lanes = d.lane_pictures(now, layout)
        moving_picture(frames, d.moving_items(now, [lane.ends for lane in lanes]), layout.theme)

    times = np.linspace(*d.window, FRAMES)
    for t in times[:10]:
        draw(float(t))
    passes = []
    for _ in range(PASSES):
        t0 = time.process_time()
        for t in times:
            draw(float(t))
        passes.append((time.process_time() - t0) / FRAMES * 1e3)
    return min(passes), float(np.median(passes))


def main() -> None:
    for preset in SCENES:
        for name, layers in (("default layers", DEFAULT_LAYERS), ("every layer", frozenset(Layer))):
            best, median = per_frame_ms(preset, layers)
            print(f"{preset:38s} {name:15s} best {best:.2f} ms, median {median:.2f} ms per frame")


if __name__ == "__main__":
    main()
