"""The app's canvas, or its 3-D lanes, as a standalone HTML page that plays offline (viser's scene
serializer).

A temporary viser server (127.0.0.1, free port, no client, no GUI and no plotly panel, so
no plotly.js is recorded) draws with the app's own renderer; each playback frame is recorded
with a timed sleep; ``as_html()`` inlines viser's client and the recording. Nothing is fetched
when the page opens.

- :func:`record_canvas_html`: the page the live app draws on its canvas (the lanes, the
  Minkowski diagrams and the length panel, the legend), laid out for one canvas size and seen
  straight on, at the app's text sizes: an exported lesson step.
- :func:`record_lanes_html`: the two lanes alone, in 3-D (``rigidrel export``'s ``-3d.html``).
"""

from __future__ import annotations

import contextlib
import html
import io
import re
from collections.abc import Iterator
from dataclasses import replace

import numpy as np
import viser

import rigidrel_core as rr

from ..backends._viser import panel_a11y_js
from ..backends.viser import DARK_CANVAS_CSS, LaneRenderer, PageRenderer
from ..view.camera import page_clip
from ..view.layout import NORMAL
from ..view.page import frame_pictures, lay_out, room
from ..view.scene_view import LANE_Z, PLOT_HZ, Drawn, camera_pose, lane_states
from ..view.state import Resolved, Settings
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


def record_canvas_html(
    resolved: Resolved,
    settings: Settings,
    width: int,
    height: int,
    seconds: float = 10.0,
    fps: float = 30.0,
    shade: Shade = "light",
) -> str:
    """HTML of the app's canvas for ``resolved`` (``settings``: its state, named in the headline),
    laid out on a ``width`` x ``height`` canvas (CSS px) at the desk's text sizes and playing through
    the scene's window in ``seconds`` at ``fps``: the same page, drawn by the same renderer, as the
    live app shows on a canvas of that size, seen straight on (one page px one CSS px when the page
    is shown at that size; larger or smaller, it scales whole). ``shade``: dark is the live app's
    dark theme (the canvas inverted by the page)."""
    page = lay_out(resolved, settings, width, height, replace(NORMAL, shade=shade))
    pictures = frame_pictures(page.drawn, page.layout, page.chart_frames, playback_times(page.drawn, seconds, fps))
    with quiet_server() as server:
        renderer = PageRenderer(server.scene)
        renderer.set_static(page.layout, page.still, page.drawn.ruler_names)
        renderer.reserve(*room(pictures))  # no frame makes or removes a node
        renderer.update(*pictures[0])
        pose = renderer.pose(page.layout)
        camera = server.initial_camera
        camera.near, camera.far = page_clip(pose)
        camera.position, camera.look_at, camera.up, camera.fov = pose.position, pose.look_at, pose.up, pose.fov
        serializer = server.get_scene_serializer()
        for lanes, moving in pictures:
            renderer.update(lanes, moving)
            serializer.insert_sleep(1.0 / fps)
        out = serializer.as_html()
    title = f"{rr.describe(resolved.scene).title}: the rods and their diagrams, in the lab and in the chosen frame"
    return _finished(out, title, shade)


def _finished(page: str, title: str, shade: Shade) -> str:
    """A recorded page in the dark theme if ``shade`` says so, titled, and its controls named for a
    screen reader (viser's client names neither its boxes nor its icons)."""
    if shade == "dark":
        page = page.replace("</head>", f"<style>{DARK_CANVAS_CSS} body {{ background: #000000; }}</style></head>", 1)
    page = re.sub(r"<title>.*?</title>", lambda _: f"<title>{html.escape(title)}</title>", page, count=1, flags=re.S)
    return page.replace("</body>", f"<script>{panel_a11y_js()}</script></body>", 1)


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
    title = f"{rr.describe(drawn.resolved.scene).title}: the rods in the lab and in the chosen frame"
    return _finished(page, title, shade)
