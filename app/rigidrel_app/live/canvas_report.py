"""The page tells the server its canvas' size in CSS px.

viser's camera reports the canvas in rendered pixels: CSS px times the screen's pixel ratio (2 on
most laptops sold today) times the client's adaptive resolution (0.75 to 1 of that while frames
are slow). The page is laid out in CSS px, the unit its labels are sized in, so on a high-density
screen a layout in rendered pixels draws the diagrams at twice the labels' scale and off the canvas.
No viser message carries the pixel ratio, so the page measures its own canvas: a hidden number box
of the panel receives ``(width * SIZE_BASE + height) * RATIO_BASE + ratio`` (CSS px, rounded, and
the rendered pixels per CSS px in thousandths, measured at the same instant) whenever that changes,
written by a small script (viser's HTML element runs no ``<script>``; an image that fails to load
runs its ``onerror``). The box lives in a panel of its own, floating and hidden, not in the control
panel: viser unmounts a minimised panel's content, and presenter mode minimises the control panel
just as it changes the canvas' size. Until the page has spoken, or if it never does, the server
infers the size from the camera's pixels (:meth:`~rigidrel_app.view.layout.CanvasSize.reported`).
"""

from __future__ import annotations

import html
from collections.abc import Callable
from dataclasses import dataclass

import viser

from ..backends._viser import handle_uuid
from ..view.layout import CanvasSize
from .runtime import page_asset
from .tab import Tab

#: ``(width * SIZE_BASE + height) * RATIO_BASE + ratio``: one number carries the two sides (each
#: below ``SIZE_BASE`` px) and the pixel ratio in thousandths (below ``RATIO_BASE``), under 2**53.
SIZE_BASE = 65536
RATIO_BASE = 8192
#: The label of the hidden box (never shown; named for the page's inspector).
LABEL = "canvas size (CSS px)"
#: How often the page looks at its canvas' size, in ms (it sends only a change).
POLL_MS = 250


@dataclass(frozen=True)
class CssSize:
    """A canvas as its page measured it."""

    width: int
    """CSS px."""
    height: int
    resolution: float
    """Rendered pixels per CSS px (the screen's pixel ratio times the client's adaptive share)."""


def encode(width: int, height: int, resolution: float) -> int:
    """What the page's script sends (the inverse of :func:`decode`)."""
    return (width * SIZE_BASE + height) * RATIO_BASE + round(resolution * 1000)


def decode(value: float) -> CssSize | None:
    """The size a page sent, or ``None`` for a value no page of ours sends (ignored)."""
    if not (isinstance(value, (int, float)) and 0 < value < SIZE_BASE * SIZE_BASE * RATIO_BASE):
        return None  # NaN fails the comparison too
    n = int(value)
    if n != value:
        return None
    size, ratio = divmod(n, RATIO_BASE)
    width, height = divmod(size, SIZE_BASE)
    if not (1 <= width < SIZE_BASE and 1 <= height < SIZE_BASE and ratio >= 100):  # a ratio of at least 0.1
        return None
    return CssSize(width, height, ratio / 1000)


def script(uuid: str) -> str:
    """The HTML that hides the box's panel (its whole window) and keeps the box up to date with the
    canvas."""
    js = page_asset("canvas-report.js", box_id=uuid, size_base=SIZE_BASE, ratio_base=RATIO_BASE, poll_ms=POLL_MS)
    # the floating window on a desktop; the panel's section of the bottom sheet on a phone
    hidden = f'div:has(> [data-dock-group] [for="{uuid}"]), .mantine-Tabs-root:has([for="{uuid}"])'
    style = f"<style>{hidden} {{ display: none !important; }}</style>"
    return f'{style}<img alt="" src="data:," style="display: none" onerror="{html.escape(js, quote=True)}">'


def add_canvas_report(gui: viser.GuiApi) -> viser.GuiNumberHandle[float]:
    """The hidden box the page writes its canvas' CSS size into (read it with :func:`decode`), in a
    floating panel of its own that the page never shows and that stays mounted while the control
    panel is minimised."""
    panel = gui.add_panel()
    with panel.add_tab(LABEL):
        box = gui.add_number(LABEL, 0.0, step=1.0)
        gui.add_html(script(handle_uuid(box)))
    panel.float(x=-1, y=-1, width=1, height=1)
    return box


def follow_canvas_size(tab: Tab, report: viser.GuiNumberHandle[float]) -> Callable[[CanvasSize], None]:
    """Lay ``tab``'s page out again whenever its canvas changes size (the docked panel, presenter
    mode, the window): as the page measures it in ``report`` (:func:`add_canvas_report`), or as
    the camera reports it until the page has spoken. The same size at another resolution (a step
    of the client's adaptive resolution) is not a new page. Returns what a new size does."""
    client = tab.client

    def resized(size: CanvasSize) -> None:
        drawn = tab.painter.drawn
        if tab.painter.resized(size) and drawn is not None:
            with client.atomic():
                tab.apply(drawn.resolved, refit=True)

    @client.camera.on_update
    def _(camera: viser.CameraHandle) -> None:
        with tab.lock:
            if not tab.closed and tab.painter.drawn is not None:
                resized(tab.painter.canvas_size.reported(camera.image_width, camera.image_height))

    @report.on_update
    def _(event: viser.GuiEvent) -> None:
        size = decode(report.value)
        if event.client is None or size is None:  # not a size any page of ours sends: ignored
            return
        with tab.lock:
            if not tab.closed:
                resized(CanvasSize.measured_by_page(size.width, size.height, size.resolution))
        client.flush()

    return resized
