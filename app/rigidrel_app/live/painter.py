"""A tab's canvas: its size, its page's layout and drawing, the camera, and each instant drawn.

The :class:`Painter` lays a state out for the tab's canvas (through the server's shared
:class:`~.painting.PaintingCache`), puts the page on the canvas (its own still picture, or a page
shared with the tabs on a canvas of the same size), keeps the camera on it, and draws the moving
parts at an instant: as the browser's runtime holds them (:class:`~.browser_player.BrowserPlayer`)
or drawn here. What to show comes from the tab's :class:`~.tab_state.TabState`; the drawings are
the view layer's (:func:`~rigidrel_app.view.scene_view.build_drawing`).
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import viser

from ..backends.viser import PageRenderer
from ..view import camera as cam
from ..view.canvas import ChartFrame, moving_picture
from ..view.lanes import LanePicture
from ..view.layout import LEGEND_ROWS, NORMAL, PRESENTER, CanvasLayout, CanvasSize
from ..view.scene_view import Drawn
from ..view.state import Resolved, Settings
from ..view.state import resolve as resolve_settings
from .browser_player import BrowserPlayer
from .painting import Painting, PaintingCache, PaintingKey
from .still_image import Send, StillImage
from .tab_state import TabState


class Painter:
    """One tab's canvas (``client``'s scene and camera); ``paintings``: the server's, shared by its
    tabs; ``player``: the tab's runtime; ``still_image``: the still picture as one image while a
    slow canvas plays (:mod:`.still_image`)."""

    def __init__(
        self, client: viser.ClientHandle, paintings: PaintingCache, player: BrowserPlayer, still_image: bool
    ) -> None:
        self.client = client
        self.paintings = paintings
        self.player = player
        camera = client.camera
        self.canvas_size = CanvasSize(float(camera.image_width), float(camera.image_height))
        """The canvas in CSS px, which the page is laid out in (its camera reports rendered pixels)."""
        self.renderer = PageRenderer(client.scene)
        self.layout: CanvasLayout | None = None
        self.drawn: Drawn | None = None
        self.chart_frames: tuple[ChartFrame | None, ...] = ()
        """Each diagram's data -> page px (the plot areas of this layout)."""
        self.legend_rows = LEGEND_ROWS
        """The legend's rows in the page last laid out (the first guess for the next drawing's)."""
        self.title_lines = 1
        """The title lines of the page last laid out, as :func:`~.painting.paint` guesses them (1:
        this scene's lane titles may go on one line; tried again for another scene)."""
        self.renderer_lanes: list[LanePicture] = []
        """The lanes as last drawn here."""
        self.painting: Painting | None = None
        """The painting whose shared page (and frames) the runtime shows, if any (a step the leading
        tab chose); None while the tab draws its own picture."""
        self.still_image = StillImage(still_image)

    def paint(self, settings: Settings, resolved: Resolved, state: TabState) -> Painting:
        """``settings`` (resolved as ``resolved``) laid out and drawn for this canvas in ``state``'s
        look (shared, :mod:`.painting`); the legend rows and title lines of the last one are the
        first guess."""
        key = self._key(settings, state)
        found = self.paintings.find(key)
        if found is not None:
            return found
        if self.drawn is not None and self.drawn.resolved.scene.kind != resolved.scene.kind:
            self.title_lines = 1
        return self.paintings.get(resolved, key, (self.legend_rows, self.title_lines))

    def paint_settings(self, settings: Settings, state: TabState) -> Painting | None:
        """:meth:`paint` of ``settings`` resolved here; None if they make no scene."""
        found = self.paintings.find(self._key(settings, state))
        if found is not None:
            return found
        resolved = resolve_settings(settings)
        return None if isinstance(resolved, str) else self.paint(settings, resolved, state)

    def _key(self, settings: Settings, state: TabState) -> PaintingKey:
        theme = replace(PRESENTER if state.presenter else NORMAL, shade=state.shade)
        return PaintingKey(settings, self.canvas_size.width, self.canvas_size.height, theme, state.zoomed)

    def show(self, painting: Painting, shared: bool) -> None:
        """Put ``painting``'s page on the canvas: the page shared by the tabs that show it if
        ``shared`` (and the runtime is ready), else the tab's own still picture."""
        self.layout, self.drawn = painting.layout, painting.drawn
        self.legend_rows, self.title_lines = painting.legend_rows, painting.title_lines
        self.chart_frames = painting.chart_frames
        self.painting = painting if shared and self.player.ready else None
        if self.painting is not None:
            self.lend(painting)
        else:
            self.player.drop_page()
            self.renderer.set_static(painting.layout, painting.still, painting.drawn.ruler_names)

    def lend(self, painting: Painting) -> None:
        """Show ``painting``'s shared page (sent once) instead of the tab's own still picture."""
        self.renderer.lend_still(painting.layout)
        self.player.lend_page(painting)

    def resized(self, size: CanvasSize) -> bool:
        """Take the canvas' new size (CSS px); True if the page must be laid out again. The same
        size at a lower resolution is the browser finding its frames slow (:mod:`.still_image`)."""
        resized = (size.width, size.height) != (self.canvas_size.width, self.canvas_size.height)
        if not resized and size.resolution < self.canvas_size.resolution - 1e-3:
            self.still_image.canvas_slowed()
        self.canvas_size = size
        return resized and self.drawn is not None and self.layout is not None

    def runtime_ready(self) -> None:
        """The runtime draws the moving parts from now on: drawn here into its mirror, sent as frames."""
        mirror = self.player.become_ready()
        if mirror is not None:
            self.renderer.draw_moving_into(mirror.scene)

    # ------------------------------------------------------------------ the camera
    def fit_camera(self, force: bool = False) -> None:
        """Put the camera where it shows the whole page. Nothing is sent when the camera is already
        there as far as the browser last reported (a slider's redraw with "Auto-fit view" on), unless
        ``force`` (key R: the browser may have moved it since its last report)."""
        if self.layout is None:
            return
        camera = self.client.camera
        pose = self.renderer.pose(self.layout)
        if not force and self._camera_at(pose):
            return
        camera.near, camera.far = cam.page_clip(pose)
        camera.up_direction, camera.fov = pose.up, pose.fov
        # viser skips an assignment equal to the camera state it last heard of, and that lags the
        # browser while the user orbits: step aside first, so the exact pose is always sent
        aside = np.array([0.0, 1e-3 * abs(pose.position[1]), 0.0])
        camera.position, camera.look_at = np.asarray(pose.position) + aside, np.asarray(pose.look_at) + aside
        camera.position, camera.look_at = pose.position, pose.look_at

    def _camera_at(self, pose: cam.CameraPose) -> bool:
        """Whether the camera, as the browser last reported it, has ``pose``."""
        camera = self.client.camera
        return bool(
            np.allclose(camera.position, pose.position)
            and np.allclose(camera.look_at, pose.look_at)
            and np.allclose(camera.up_direction, pose.up)
            and np.isclose(camera.fov, pose.fov)
        )

    # ------------------------------------------------------------------ one instant
    def draw(self, now: float) -> None:
        """The lanes and the diagrams' moving parts at ``now``, as one instant: a frame of the
        timeline the runtime holds, the shared painting's frame, or drawn here (and sent to the
        runtime's mirror once it is ready). Nothing while a pause is on its way back: the
        runtime's frame where it paused is the picture."""
        d, layout, player = self.drawn, self.layout, self.player
        if d is None or layout is None or (player.ready and player.pausing):
            return
        if player.seek(now):
            return
        if self.painting is not None:
            player.shared_frame(self.painting, now)
            return
        instant = d.ride_instant(now)  # the riding lane's instant (None unless it rides a point)
        self.renderer_lanes = lanes = d.lane_pictures(now, layout, instant)
        ends = [lane.ends for lane in lanes]
        self.renderer.update(lanes, moving_picture(self.chart_frames, d.moving_items(now, ends, instant), layout.theme))
        player.own_frame(now)

    def preview(self, painting: Painting, now: float) -> None:
        """``painting``'s shared page and its instant ``now``, before anything else of its state."""
        self.lend(painting)
        self.player.shared_frame(painting, now)

    def tick_still_image(self, send: Send) -> None:
        self.still_image.tick(self.renderer, self.layout, self.canvas_size.resolution, send)
