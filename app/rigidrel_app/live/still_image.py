"""The still picture as one image while a slow canvas plays: one seam, with an off switch.

A browser without a graphics card (software WebGL, as in a lecture hall's old PCs or a headless
test) redraws the page's still picture, hundreds of segments, thousands of fill dots and about
fifty labels, on every frame of playback. viser lowers its canvas' resolution when frames come
slower than about 38 a second; from then on (:attr:`StillImage.slow_canvas`), while the tab plays,
the still picture is sent as one image drawn by the raster backend once it has stood for
:data:`AFTER_S`, and :data:`SWAP_S` after the image went out the picture's lines, dots and labels
are hidden: the renderer draws one textured rectangle instead. Any redraw of the picture shows
them again at once (:meth:`~rigidrel_app.backends.viser.PageRenderer.set_static`), so a
control's answer never waits for the image.

Measured with playback in the browser (Fig. 3, headless Chromium with software WebGL, alternated
runs, 2026-11-28): 13.1 against 11.5 frames a second at 1280x720 with and without it, 16.4
against 10.7 in a second series, 4.8 against 4.5 at 1920x1080. It stays, behind this seam;
``rigidrel serve --no-still-image`` (``App(still_image=False)``) turns it off.
"""

from __future__ import annotations

import threading
import time
from collections.abc import Callable

from ..backends.raster import page_image
from ..backends.viser import FlatStill, PageRenderer, flat_still
from ..view.layout import CanvasLayout

#: While it plays, the still picture goes as one image once it has not changed for this long (s).
AFTER_S = 0.3
#: ... and the picture is left to the image this long (s) after sending it (the browser decodes it).
SWAP_S = 0.5


class StillImage:
    """One tab's still image (module docstring). ``enabled``: False, and nothing here ever acts."""

    def __init__(self, enabled: bool = True) -> None:
        self.enabled = enabled
        self.slow_canvas = False
        """The browser has lowered its canvas' resolution: from then on the image is used."""
        self._asked = (-1, 0.0)
        """The still-picture version and scale whose image was last asked for."""
        self._sent_at = 0.0

    def canvas_slowed(self) -> None:
        """The same canvas came back at a lower resolution: its frames are slow."""
        self.slow_canvas = self.enabled

    def tick(self, renderer: PageRenderer, layout: CanvasLayout | None, scale: float, send: Send) -> None:
        """While playing (call on every tick): have the image made once the picture has stood (in a
        thread of its own, which hands it to ``send``), and leave the picture to it once it is sent.
        ``scale``: the canvas' rendered pixels per CSS px (a texture drawn at another scale blurs)."""
        if not self.enabled or layout is None or not self.slow_canvas or renderer.still_lent:
            return
        wall = time.monotonic()
        if renderer.flat_version == renderer.version:
            if renderer.vectors_shown and wall - self._sent_at >= SWAP_S:
                renderer.hide_vectors()
            if abs(renderer.flat_scale - scale) < 1e-3:
                return
        if self._asked == (renderer.version, scale) or wall - renderer.still_at < AFTER_S:
            return
        self._asked = (renderer.version, scale)
        picture, version, shade = renderer.still, renderer.version, layout.theme.shade
        page_w, page_h = layout.width, layout.height

        def make() -> None:
            flat = flat_still(page_image(picture, page_w, page_h, scale), scale, shade, version)
            if flat is not None:
                send(lambda: self._show(renderer, flat))

        threading.Thread(target=make, name="still-image", daemon=True).start()

    def _show(self, renderer: PageRenderer, flat: FlatStill) -> None:
        if renderer.show_flat(flat):
            self._sent_at = time.monotonic()


#: How the image reaches the tab: ``send(show)`` runs ``show`` under the tab's lock, in one batch,
#: unless the tab has gone.
Send = Callable[[Callable[[], None]], None]
