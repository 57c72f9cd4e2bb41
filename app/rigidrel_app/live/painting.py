"""A state painted for one canvas: laid out, drawn and pictured once, shared by every tab that shows it.

A :class:`Painting` is what the server makes when a tab's state changes: the page laid out for
the tab's canvas (:func:`~rigidrel_app.view.layout.canvas_layout`, its legend given the rows it
needs and its lane titles the lines), the scene's drawing for those plot areas
(:func:`~rigidrel_app.view.scene_view.build_drawing`) and the still picture (diagrams, legend).
It depends only on the state and the canvas (:class:`PaintingKey`), so tabs in the same state on
canvases of the same size share one (:class:`PaintingCache`): a hall that follows a lecturer's
step makes it once per canvas size, not once per tab.

For a tab whose playback runtime is ready, a painting also gives the picture itself as the
runtime's payloads (the same blobs as :mod:`.timeline`'s, encoded once, sent to any number of
tabs): :meth:`Painting.page` (the still picture, drawn under
:data:`~rigidrel_app.backends.viser.SHARED_ROOT`) and :meth:`Painting.frame` (the moving parts at
one instant).
"""

from __future__ import annotations

import hashlib
import threading
from collections import OrderedDict
from dataclasses import dataclass, field, fields

import numpy as np
import numpy.typing as npt

from ..backends._viser import RecordingScene, SceneFold
from ..backends.viser import SHARED_ROOT, PageRenderer, shared_root
from ..view.canvas import PagePicture
from ..view.layout import LEGEND_ROWS, Theme
from ..view.page import Page, frame_pictures, lay_out, room
from ..view.state import Resolved, Settings
from .timeline import Mirror, as_u8, encode_payload

#: Paintings kept: the states a hall moves through, at a few canvas sizes (each ~1 MB).
CACHED_PAINTINGS = 32
#: Still frames kept per painting (a step's first instant, a few seeks).
CACHED_FRAMES = 8


@dataclass(frozen=True)
class PaintingKey:
    """What a painting depends on: the state, the canvas (CSS px) and the look (theme, shade)."""

    settings: Settings
    width: float
    height: float
    theme: Theme
    zoomed: bool = False
    """One diagram over the whole canvas (key Z, :func:`~rigidrel_app.view.scene_view.panels`)."""


@dataclass(frozen=True)
class Painting(Page):
    """A state laid out and drawn for one canvas (a :class:`~rigidrel_app.view.page.Page`, module
    docstring), with what it was made for and the runtime payloads made of it."""

    key: PaintingKey
    resolved: Resolved
    _shared: _Shared = field(default_factory=lambda: _Shared(), repr=False, compare=False)

    @property
    def id(self) -> str:
        return self._shared.id(self.key)

    def page(self) -> npt.NDArray[np.uint8]:
        """The still picture as a runtime payload (a node set of one frame, under
        :data:`~rigidrel_app.backends.viser.SHARED_ROOT`), made once."""
        shared = self._shared
        with shared.lock:
            if shared.page is None:
                recording = RecordingScene()
                renderer = PageRenderer(recording.scene, recording.scene, still_root=shared_root(self.id))
                renderer.set_static(self.layout, self.still, self.drawn.ruler_names)
                fold = SceneFold()
                for m in recording.take():
                    if getattr(m, "name", "").startswith(SHARED_ROOT):  # the still part alone
                        fold.add(m)
                header = {
                    "nodeset": f"page-{self.id}",
                    "first": 0,
                    "count": 1,
                    "total": 1,
                    "times": [0.0],
                    "nodes": list(fold.created),
                }
                shared.page = as_u8(encode_payload(header, [dict(fold.state)], list(fold.created.values())))
            return shared.page

    def frame(self, now: float) -> npt.NDArray[np.uint8]:
        """The moving parts at ``now`` as a runtime payload (a still frame with its nodes' creation,
        whatever the tab's runtime showed before), made once per instant."""
        shared = self._shared
        with shared.lock:
            blob = shared.frames.get(now)
            if blob is not None:
                shared.frames.move_to_end(now)
                return blob
            if shared.mirror is None or shared.renderer is None:
                shared.mirror = Mirror(f"paint-{self.id}")
                shared.renderer = PageRenderer(RecordingScene().scene, shared.mirror.scene, still_root=SHARED_ROOT)
                shared.renderer.set_static(self.layout, PagePicture(), self.drawn.ruler_names)
            pictures = frame_pictures(self.drawn, self.layout, self.chart_frames, np.array([now]))
            shared.renderer.reserve(*room(pictures))
            shared.renderer.update(*pictures[0])
            blob = shared.mirror.frame(now, prologue=True)
            shared.frames[now] = blob
            while len(shared.frames) > CACHED_FRAMES:
                shared.frames.popitem(last=False)
            return blob


class _Shared:
    """A painting's blobs, made on first use under its lock (the painting itself is frozen)."""

    def __init__(self) -> None:
        self.lock = threading.Lock()
        self.page: npt.NDArray[np.uint8] | None = None
        self.frames: OrderedDict[float, npt.NDArray[np.uint8]] = OrderedDict()
        self.mirror: Mirror | None = None
        self.renderer: PageRenderer | None = None
        self._id: str | None = None

    def id(self, key: PaintingKey) -> str:
        if self._id is None:
            self._id = hashlib.sha1(repr(key).encode()).hexdigest()[:16]
        return self._id


def paint(resolved: Resolved, key: PaintingKey, guess: tuple[int, int] = (LEGEND_ROWS, 1)) -> Painting:
    """``resolved`` laid out on ``key``'s canvas and drawn (:func:`~rigidrel_app.view.page.lay_out`).
    ``guess``: the legend rows and title lines to try first (a tab's last painting's: a slider's
    answer then draws once); the result does not depend on it."""
    page = lay_out(resolved, key.settings, key.width, key.height, key.theme, key.zoomed, guess)
    return Painting(**{f.name: getattr(page, f.name) for f in fields(Page)}, key=key, resolved=resolved)


class PaintingCache:
    """The paintings made lately (at most :data:`CACHED_PAINTINGS`, the least recently used go
    first), shared by every tab of a server; safe from any thread. Tabs asking for the same one
    at once each make it (the animation loop asks for a hall's in turn, so it is made once)."""

    def __init__(self, capacity: int = CACHED_PAINTINGS) -> None:
        self._capacity = capacity
        self._lock = threading.Lock()
        self._paintings: OrderedDict[PaintingKey, Painting] = OrderedDict()
        self.made = 0
        """Paintings made (not found here)."""

    def find(self, key: PaintingKey) -> Painting | None:
        """The painting of ``key`` if it is here."""
        with self._lock:
            found = self._paintings.get(key)
            if found is not None:
                self._paintings.move_to_end(key)
            return found

    def get(self, resolved: Resolved, key: PaintingKey, guess: tuple[int, int] = (LEGEND_ROWS, 1)) -> Painting:
        """The painting of ``key`` (``resolved``: its state, resolved), made if it is not here."""
        with self._lock:
            found = self._paintings.get(key)
            if found is not None:
                self._paintings.move_to_end(key)
                return found
        made = paint(resolved, key, guess)
        with self._lock:
            self.made += 1
            self._paintings[key] = made
            while len(self._paintings) > self._capacity:
                self._paintings.popitem(last=False)
        return made
