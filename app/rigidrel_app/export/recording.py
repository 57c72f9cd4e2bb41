"""The 3-D lanes as a standalone HTML page that plays offline (viser's scene serializer).

A temporary viser server (127.0.0.1, free port, no client, no GUI and no plotly panel, so
no plotly.js is recorded) draws the lanes with the app's own renderer; each playback
frame is recorded with a timed sleep; ``as_html()`` inlines viser's client and the
recording. Nothing is fetched when the page opens.
"""

from __future__ import annotations

import contextlib
import html
import io
import re
from collections.abc import Iterator

import numpy as np
import viser

import rigidrel_core as rr

from ..backends._viser import panel_a11y_js
from ..backends.viser import DARK_CANVAS_CSS, LaneRenderer
from ..view.scene_view import LANE_Z, PLOT_HZ, Drawn, camera_pose, lane_states
from ..view.vocabulary import Shade


@contextlib.contextmanager
def quiet_server() -> Iterator[viser.ViserServer]:
    """A viser server on 127.0.0.1 whose start and stop banners stay off the console."""
    with contextlib.redirect_stdout(io.StringIO()):
        server = viser.ViserServer(host="127.0.0.1", port=0, verbose=False)
    try:
        yield server
    finally:
        with contextlib.redirect_stdout(io.StringIO()):
            server.stop()


def playback_times(drawn: Drawn, seconds: float, fps: float) -> np.ndarray:
    """Frame times of a ``seconds``-long playback of the drawing's window at ``fps``."""
    n = max(2, round(seconds * fps))
    return np.linspace(drawn.window[0], drawn.window[1], n)


def record_lanes_html(
    drawn: Drawn, seconds: float = 10.0, fps: float = 30.0, aspect: float = 16 / 9, shade: Shade = "light"
) -> str:
    """HTML of both lanes playing through the scene's window in ``seconds`` at ``fps`` frames per
    second, on a ``shade`` ground (dark: the live app's dark theme, the canvas inverted by the page)."""
    with quiet_server() as server:
        renderer = LaneRenderer(server.scene, LANE_Z, shade)
        renderer.set_static(drawn.lane_statics())
        pose = camera_pose(drawn.lane_x_range, aspect)
        server.initial_camera.position = pose.position
        server.initial_camera.look_at = pose.look_at
        server.initial_camera.up = pose.up
        server.initial_camera.fov = pose.fov
        times = playback_times(drawn, seconds, fps)
        radius = drawn.geometry.clock_radius
        renderer.update(lane_states(drawn, float(times[0])), radius)
        serializer = server.get_scene_serializer()
        label_every = max(1, round(fps / PLOT_HZ))
        for k, now in enumerate(times):
            labels = k % label_every == 0
            renderer.update(lane_states(drawn, float(now), labels=labels), radius, labels=labels)
            serializer.insert_sleep(1.0 / fps)
        page = serializer.as_html()
    if shade == "dark":
        page = page.replace("</head>", f"<style>{DARK_CANVAS_CSS} body {{ background: #000000; }}</style></head>", 1)
    # titled, named and readable for a screen reader (viser's client names neither its boxes nor its icons)
    title = html.escape(f"{rr.describe(drawn.resolved.scene).title}: the rods in the lab and in the chosen frame")
    page = re.sub(r"<title>.*?</title>", lambda _: f"<title>{title}</title>", page, count=1, flags=re.S)
    return page.replace("</body>", f"<script>{panel_a11y_js()}</script></body>", 1)
