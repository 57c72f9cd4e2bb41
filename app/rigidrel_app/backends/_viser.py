"""Every use of viser's private API, in one place, for the viser this package is pinned to.

viser has no extension API: a few things the app needs reach into its internals. They are all
here, so that a new viser is checked against one list; the rest of the package imports only this
module for them. Targets viser ``>=1.1.1,<1.2`` (pyproject.toml); :func:`check_version` refuses
any other at import, with a message that says so.

Python, private to viser (inventory):

- ``viser._messages``: the message classes the app writes or recognises itself
  (``SceneNodeUpdateMessage``, ``SetPositionMessage``, ``ImageMessage`` / ``ImageProps``,
  ``RunJavascriptMessage``, and the type names of ``GuiUpdateMessage``,
  ``CommandTriggerMessage`` and ``GuiButtonHoldMessage`` that a client's message budget counts);
  ``Message`` subclassed for the playback's two server-to-browser messages.
- ``viser._image_encoding.cv2_imencode_with_fallback``: PNG bytes as viser itself encodes them.
- a handle's ``_impl`` (its ``uuid``, ``name`` and ``props``): the id the browser gives a control's
  element, and a label's props written in one message (:func:`write_label`).
- ``SceneApi._queue_scene_message``: that one message sent.
- ``ImageHandle._make`` and ``ImageHandle._data``: an image node made from encoded bytes.
- ``ClientHandle._websock_connection.queue_message``: a message to one tab only.
- ``ViserServer._websock_server``: ``on_client_connect`` (a connection before it is a client)
  and ``_live_connections`` (its websocket, whose ``recv`` the message budget wraps).
- ``viser.infra.WebsockClientConnection``: that connection's type.
- ``ViserServer._websock_server`` as viser's constructor sets it, after making its web server and
  before starting it, and that server's ``_server_thread`` (None until it starts) and
  ``_http_server_root`` (the folder it serves, read once as it starts): the live app's page served
  from a folder of our own (:class:`PageServer`).
- ``viser.SceneApi(owner, thread_executor=, event_loop=)`` on a connection of our own
  (``infra.WebsockMessageHandler`` subclassed: its buffer's ``push``, ``atomic_start``,
  ``atomic_end``, ``remove_entity_state_from_buffer``, ``sanctioned_dead_writes``), and a scene's
  ``_owner_id``: a scene that belongs to no client, recorded for the playback runtime.
- ``_messages._CreateSceneNodeMessage`` (a node's creation), ``SetOrientationMessage``,
  ``SetSceneNodeVisibilityMessage``, ``Message.as_serializable_dict(binary_buffers=)`` and
  ``infra._messages._prepare_for_serialization``: recorded messages written as viser's client
  takes them.

The browser, private to viser's client (inventory; the scripts in ``live/assets/`` use these):

- the client is one page, ``client/build/index.html``: its bundle packed into one inline
  ``<script>`` in ``<head>`` that unpacks and runs it once the document is parsed, after a
  ``<meta charset="utf-8">``; a ``<title>``; an empty ``<div id="root">`` in ``<body>``
  (:func:`page_with` adds to it). Until it connects, and for a second or two after, the page shows
  viser's own panel (its connection state "Inactive" or "Connecting...", the server's ``ws://``
  address, "Scene tree") and its "Software WebGL rendering detected" note; the live page's cover
  (``live/assets/cover.js``) keeps everything in ``<body>`` but itself hidden until the app's first
  page is drawn.
- the viewer's ``useGui`` store (found as the playback runtime finds the viewer, below): its
  ``get().websocketState`` (``"connected"``, ``"reconnecting"``, or ``"inactive"`` while a page
  without the focus does not try again) and ``subscribe(listener)``, which the cover reads.
- the same value's ``mutable.current.scene`` (the three.js scene) and its ``onAfterRender`` (three.js
  calls it after each render): viser renders on demand, so the cover leaves once the canvas has
  stopped drawing the first page (its labels' glyphs are rasterized over several frames).

- ``canvas[data-engine]``: the three.js canvas (its CSS and rendered size).
- a control's element ``id`` is its handle's uuid; a slider's own number box is its next sibling
  (``.mantine-NumberInput-root``, hidden by the live panel's style: each number control has a
  text box of its own, ``live/controls.py``); a panel is a ``[data-dock-group]`` or a
  ``.mantine-Tabs-root``.
- React's fiber tree from ``#root`` to viser's ``ViewerContext`` value (``mutable``,
  ``useSceneTree``, ``useGuiConfig``), its ``mutable.current.messageQueue`` (a plain array drained
  by the render loop), ``requestRender()`` and ``sendMessage()`` (the playback runtime); the
  wire shapes of ``SceneNodeUpdateMessage``, ``SetPositionMessage``, ``SetOrientationMessage``,
  ``SetSceneNodeVisibilityMessage`` and the creation messages, ``owner`` included, and numpy
  fields as typed arrays of their dtype.
- the panel's markup that ``backends/assets/a11y.js`` (:func:`panel_a11y_js`) names and recolours: a slider's thumb
  (``[role=slider]``) inside ``.mantine-Slider-root`` whose ``id`` is the handle's uuid, its label
  a ``label[for=uuid]`` in a ``p[unselectable=off]`` (Mantine's dimmed text), the number box
  ``.mantine-NumberInput-input`` beside it, icon buttons holding a ``tabler-icon-*`` svg, and the
  buttons' ``--button-color`` and the theme's ``--mantine-color-gray-filled`` variables under
  ``html[data-mantine-color-scheme]``; and viser's notification "Software WebGL rendering
  detected" (``BrowserWarning.tsx``: a ``.mantine-Notification-root`` with that
  ``.mantine-Notification-title``), closed by its close button; the live page's cover leaves only
  once that title has gone from the page (``live/assets/cover.js``).
- on a narrow screen, the panel as a bottom sheet (``ControlPanel/BottomPanel.tsx``): a Mantine
  ``Paper`` fixed at the bottom right, open at first, and in it the handle (a box with
  ``cursor: pointer``) whose click folds it to its bar, 3.5 em high (``live/assets/phone.js``).
- how the client lays out a label (``client/src/label/labelLayout.ts``): its text block padded by
  ``BACKGROUND_PADDING_FRACTION`` (0.2) of its line height (the font's ascent plus descent, 1.117
  em in Arial), and the padded block set at the anchor, so a left-anchored text starts a tenth of
  a line right of its anchor (:data:`LABEL_HALF_PAD_EM`).
- the same context value's ``interaction.cameraLocks.acquire(reason)`` (the lock viser's gizmo
  drags take: its camera controls disabled, keyboard movement included) and
  ``useDevSettings.setState({enableOrbitCrosshair})``: the picture kept still under the mouse.
"""

from __future__ import annotations

import asyncio
import concurrent.futures
import contextlib
import functools
import re
import shutil
import tempfile
import threading
import types
import uuid
import weakref
from dataclasses import dataclass, field
from importlib import metadata, resources
from pathlib import Path
from typing import Any

import numpy as np
import viser
from viser import _messages, infra  # pyright: ignore[reportPrivateUsage]
from viser._image_encoding import cv2_imencode_with_fallback  # pyright: ignore[reportPrivateUsage]
from viser.infra import WebsockClientConnection

__all__ = [
    "CONTROL_MESSAGE_TYPES",
    "LABEL_HALF_PAD_EM",
    "SUPPORTED_VISER",
    "Message",
    "NodeKey",
    "PageServer",
    "PlaybackMessage",
    "RecordingScene",
    "SceneFold",
    "WebsockClientConnection",
    "check_version",
    "encode_png",
    "handle_uuid",
    "live_websocket",
    "make_image",
    "on_connection",
    "page_with",
    "queue_to_client",
    "run_javascript",
    "scene_owner",
    "set_image_png",
    "wire_dict",
    "wire_value",
    "write_label",
]

#: The viser versions whose internals this module was written against (``major.minor``).
SUPPORTED_VISER = (1, 1)

Message = _messages.Message


def check_version(version: str | None = None) -> None:
    """Refuse a viser other than :data:`SUPPORTED_VISER` (``version``: the installed one)."""
    found = version if version is not None else metadata.version("viser")
    parts = tuple(int(p) for p in found.split(".")[:2] if p.isdigit())
    if parts != SUPPORTED_VISER:
        want = ".".join(map(str, SUPPORTED_VISER))
        raise RuntimeError(
            f"rigidrel needs viser {want}.x (it reaches into viser's internals, listed in "
            f"rigidrel_app/backends/_viser.py); viser {found} is installed: pip install 'viser>={want}.1,<1.2'"
        )


check_version()

#: Half of the padding viser's client puts round a label's text, per em of its font: 0.2 of the
#: line height (ascent plus descent: 1.117 em in Arial), halved. A text anchored at its left or
#: right edge is drawn this much inside its anchor.
LABEL_HALF_PAD_EM = 0.5 * 0.2 * 1.117

#: The type names, as they appear in the msgpack a client sends, of the messages that ask a tab to
#: act (a control's value, a command, a button held): a client's message budget counts them dearer.
CONTROL_MESSAGE_TYPES: tuple[bytes, ...] = tuple(
    cls.__name__.encode()
    for cls in (_messages.GuiUpdateMessage, _messages.CommandTriggerMessage, _messages.GuiButtonHoldMessage)
)


def handle_uuid(handle: Any) -> str:
    """The id viser gives a GUI handle's element in the browser (viser has no public id of a handle)."""
    return str(handle._impl.uuid)  # pyright: ignore[reportPrivateUsage]


def write_label(
    scene: viser.SceneApi,
    handle: viser.LabelHandle,
    changes: dict[str, object],
    position: tuple[float, float, float] | None,
) -> None:
    """Assign a label's changed props (``changes``: text, font_screen_scale, anchor) in one
    update message, and its new ``position`` (or ``None``) in another. The handle's own setters
    send one message per prop, each cast and compared first (about 20 us each, against 10 us
    per message here); this is their write path (the handle's state, then the message), minus
    those checks: the caller sends only what changed, in the types viser keeps."""
    impl = handle._impl  # pyright: ignore[reportPrivateUsage]
    queue = scene._queue_scene_message  # pyright: ignore[reportPrivateUsage]
    if changes:
        for name, value in changes.items():
            setattr(impl.props, name, value)
        queue(_messages.SceneNodeUpdateMessage(impl.name, changes))
    if position is not None:
        impl.position[:] = position
        queue(_messages.SetPositionMessage(impl.name, position))


def encode_png(image: np.ndarray) -> bytes:
    """``(h, w, 3)`` sRGB bytes as PNG, encoded as viser encodes its own images."""
    return cv2_imencode_with_fallback("png", np.ascontiguousarray(image), None, "rgb")


def make_image(
    scene: viser.SceneApi,
    name: str,
    png: bytes,
    size: tuple[float, float],
    wxyz: tuple[float, float, float, float],
    position: tuple[float, float, float],
) -> viser.ImageHandle:
    """An image node from PNG bytes already encoded (viser's ``add_image`` takes pixels and encodes
    them again), ``size`` = (render width, render height) in scene units."""
    message = _messages.ImageMessage(
        name=name,
        props=_messages.ImageProps(
            _format="png", _data=png, render_width=size[0], render_height=size[1],
            cast_shadow=False, receive_shadow=False, scale=1.0,
        ),
    )  # fmt: skip
    return viser.ImageHandle._make(scene, message, name, wxyz, position, True)  # pyright: ignore[reportPrivateUsage]


def set_image_png(handle: viser.ImageHandle, png: bytes) -> None:
    """Replace an image node's PNG bytes (sent as they are)."""
    handle._data = png  # pyright: ignore[reportPrivateUsage]


def queue_to_client(client: viser.ClientHandle, message: Message) -> None:
    """Send ``message`` to this tab only, in its current batch."""
    client._websock_connection.queue_message(message)  # pyright: ignore[reportPrivateUsage]


def run_javascript(client: viser.ClientHandle, source: str) -> None:
    """Run ``source`` in this tab's page (viser's client evaluates it with ``new Function``)."""
    queue_to_client(client, _messages.RunJavascriptMessage(source=source))


def on_connection(server: viser.ViserServer, callback: Any) -> None:
    """``callback(connection)`` for every new websocket connection, before it is a client."""
    server._websock_server.on_client_connect(callback)  # pyright: ignore[reportPrivateUsage]


def live_websocket(server: viser.ViserServer, client_id: int) -> Any:
    """The websocket of a live connection, or ``None`` once it has gone."""
    return server._websock_server._live_connections.get(client_id)  # pyright: ignore[reportPrivateUsage]


# ---------------------------------------------------------------------------- recording a scene
class _Keeper(infra.WebsockMessageHandler):
    """A connection that sends nowhere: every message queued on it is kept, in order."""

    def __init__(self) -> None:
        super().__init__()
        self.messages: list[Message] = []

    def get_message_buffer(self) -> Any:
        return self

    def push(self, message: Message) -> None:
        self.messages.append(message)

    def atomic_start(self) -> None:
        pass

    def atomic_end(self) -> None:
        pass

    def register_handler(self, message_cls: type[Any], callback: Any) -> None:
        del message_cls, callback  # nothing comes back from nowhere

    def unregister_handler(self, message_cls: type[Any], callback: Any = None) -> None:
        del message_cls, callback

    def remove_entity_state_from_buffer(self, entity_type: str, entity_id: str) -> None:
        del entity_type, entity_id

    def sanctioned_dead_writes(self) -> contextlib.AbstractContextManager[None]:
        return contextlib.nullcontext()


class RecordingScene:
    """A viser scene API that belongs to no client: whatever its handles send is kept, to be taken
    with :meth:`take` (the messages since the last take, in order). The playback's frames and the
    moving parts a browser's runtime draws are recorded on one (``scene``)."""

    def __init__(self) -> None:
        self._keeper = _Keeper()
        owner = types.SimpleNamespace(
            client_id=0,
            _websock_connection=self._keeper,
            _viser_server=types.SimpleNamespace(_scene_lifecycle_lock=threading.RLock()),
        )
        self.scene = viser.SceneApi(
            owner,  # pyright: ignore[reportArgumentType]
            thread_executor=_RECORDING_EXECUTOR,
            event_loop=_recording_loop(),
        )
        self.take()  # what making the API sent

    def take(self) -> list[Message]:
        messages, self._keeper.messages = self._keeper.messages, []
        return messages


_RECORDING_EXECUTOR = concurrent.futures.ThreadPoolExecutor(max_workers=1, thread_name_prefix="rigidrel-recording")


@functools.cache
def _recording_loop() -> asyncio.AbstractEventLoop:
    """An event loop that never runs: a recording scene schedules nothing (no client answers it)."""
    return asyncio.new_event_loop()


#: A piece of a scene node's state, as a fold keeps it: ``("props", name, prop)`` (one prop),
#: ``("position", name)``, ``("wxyz", name)`` or ``("visible", name)``.
NodeKey = tuple[str, ...]


@dataclass
class SceneFold:
    """The state of the scene nodes a sequence of messages made: each node's latest creation message
    (:attr:`created`) and every piece of its state since (:attr:`state`, seeded from the creation).
    Folding a recorded frame's messages into it gives the frame's full state, whatever it changed."""

    created: dict[str, Message] = field(default_factory=dict)
    state: dict[NodeKey, object] = field(default_factory=dict)

    def add(self, message: Message) -> None:
        """Fold one message in; anything but a scene node's creation, props, pose, visibility or
        removal is refused."""
        if isinstance(message, _messages._CreateSceneNodeMessage):  # pyright: ignore[reportPrivateUsage]
            name = message.name
            self.created.pop(name, None)
            self.created[name] = message  # a later creation goes after the ones it may depend on
            for prop, value in vars(message.props).items():  # pyright: ignore[reportAttributeAccessIssue]
                self.state[("props", name, prop)] = value
            self.state.setdefault(("visible", name), True)
        elif isinstance(message, _messages.SceneNodeUpdateMessage):
            for prop, value in message.updates.items():
                self.state[("props", message.name, prop)] = value
        elif isinstance(message, _messages.SetPositionMessage):
            self.state[("position", message.name)] = tuple(float(v) for v in message.position)
        elif isinstance(message, _messages.SetOrientationMessage):
            self.state[("wxyz", message.name)] = tuple(float(v) for v in message.wxyz)
        elif isinstance(message, _messages.SetSceneNodeVisibilityMessage):
            self.state[("visible", message.name)] = bool(message.visible)
        elif isinstance(message, _messages.RemoveSceneNodeMessage):  # gone: made again, or hidden, by a runtime
            self.created.pop(message.name, None)
            for key in [k for k in self.state if k[1] == message.name]:
                del self.state[key]
        else:
            raise TypeError(f"a recorded frame holds scene nodes' state only, not a {type(message).__name__}")


def wire_dict(message: Message, buffers: list[memoryview]) -> dict[str, Any]:
    """``message`` as viser's client takes it (``{"type": ..., fields}``), its arrays moved into
    ``buffers`` and replaced by ``{"__binary_index": i, "dtype": ...}`` (viser's own wire format)."""
    return message.as_serializable_dict(binary_buffers=buffers)


#: Types viser's serializer passes through as they are (a plain ``str``, ``bool``, ``int``,
#: ``float`` or ``None``: its casts give each back unchanged), so :func:`wire_value` does too.
_PLAIN_TYPES = frozenset({str, bool, int, float, type(None)})


def wire_value(value: object, buffers: list[memoryview]) -> object:
    """One piece of a node's state as :func:`wire_dict` writes it (arrays into ``buffers``); a plain
    value (:data:`_PLAIN_TYPES`) as it is, without the serializer's walk over types."""
    if type(value) in _PLAIN_TYPES:
        return value
    return infra._messages._prepare_for_serialization(value, Any, buffers)  # pyright: ignore[reportPrivateUsage]


# ---------------------------------------------------------------------------- the playback's messages
@dataclass
class PlaybackMessage(Message, include_in_scene_serialization=False):
    """Server to one tab's playback runtime (``live/assets/runtime.js``), which takes it out of
    viser's message queue before viser sees it: an ``action`` on the timeline ``timeline`` (its
    id), with a number ``value`` and, for ``"frames"``, one block of frames ``payload`` (gzip)."""

    action: str
    timeline: str
    value: float = 0.0
    payload: np.ndarray = field(default_factory=lambda: np.zeros(0, np.uint8))

    def redundancy_key(self) -> str:
        return f"rigidrel-playback-{uuid.uuid4()}"  # never merged with another


def scene_owner(client: viser.ClientHandle) -> str:
    """The owner id the tab's scene stamps on its messages (the runtime stamps its own the same)."""
    return str(client.scene._owner_id)  # pyright: ignore[reportPrivateUsage]


@functools.cache
def panel_a11y_js() -> str:
    """The page script that names viser's sliders, number boxes and icon buttons and gives its
    labels and grey buttons 4.5:1 contrast, from outside (``backends/assets/a11y.js``): for the
    live app's panel and the exported pages that carry viser's client."""
    return resources.files("rigidrel_app.backends").joinpath("assets", "a11y.js").read_text(encoding="utf-8")


# ---------------------------------------------------------------------------- the page a browser gets
def client_page() -> str:
    """viser's client as viser serves it: one page with its bundle packed inside."""
    return (Path(viser.__file__).resolve().parent / "client" / "build" / "index.html").read_text(encoding="utf-8")


def page_with(head: str, body: str, title: str, html_class: str) -> str:
    """viser's client page with ``head`` in its ``<head>`` right after the charset (so before the
    inline loader that unpacks viser's bundle), ``body`` first in its ``<body>`` (before viser's
    ``#root``), ``title`` as its title and ``html_class`` on its ``<html>``: all there at the page's
    first paint, before any of viser's code runs. Raises ``RuntimeError`` if the page is not laid
    out as the viser this module targets lays it out."""
    page = client_page()
    edits: list[tuple[re.Match[str], str]] = []
    for pattern, edit in (
        (r"<html\b([^>]*)>", lambda m: f'<html{m.group(1)} class="{html_class}">'),
        (r"<meta charset=\"utf-8\"\s*/?>", lambda m: m.group(0) + head),
        (r"<title>[^<]*</title>", lambda _: f"<title>{title}</title>"),
        (r"<body>", lambda m: m.group(0) + body),
    ):
        found = re.search(pattern, page)  # in viser's page as it is (what goes in is not searched)
        if found is None:
            raise RuntimeError(f"viser's page has no {pattern!r}: rigidrel_app/backends/_viser.py is out of date")
        edits.append((found, edit(found)))
    for found, replacement in sorted(edits, key=lambda e: e[0].start(), reverse=True):
        page = page[: found.start()] + replacement + page[found.end() :]
    return page


class PageServer(viser.ViserServer):
    """A viser server whose web server serves ``page`` (a whole HTML page, e.g. from
    :func:`page_with`) instead of viser's own client page; ``**kwargs`` are ``ViserServer``'s.

    viser serves its client from a folder that it names when it makes its web server and that the
    web server reads once, as it starts, both inside viser's constructor; no setting changes it.
    So ``page`` is written to a temporary folder of its own, and the web server is given that
    folder in between: viser sets ``_websock_server`` after making the web server and before
    starting it. The folder is removed when the server stops (or is collected)."""

    def __init__(self, page: str, **kwargs: Any) -> None:
        folder = Path(tempfile.mkdtemp(prefix="rigidrel-page-"))
        (folder / "index.html").write_text(page, encoding="utf-8")
        self._page_folder = folder
        self._remove_folder = weakref.finalize(self, shutil.rmtree, folder, True)
        try:
            super().__init__(**kwargs)
        except BaseException:
            self._remove_folder()
            raise

    @property
    def _websock_server(self) -> infra.WebsockServer:  # pyright: ignore[reportIncompatibleVariableOverride]
        return self.__dict__["_rigidrel_websock_server"]

    @_websock_server.setter
    def _websock_server(self, server: infra.WebsockServer) -> None:
        if server._server_thread is not None:  # pyright: ignore[reportPrivateUsage]
            raise RuntimeError("viser started its web server before naming it: rigidrel_app/backends/_viser.py")
        server._http_server_root = self._page_folder  # pyright: ignore[reportPrivateUsage]
        self.__dict__["_rigidrel_websock_server"] = server

    def stop(self) -> None:
        try:
            super().stop()
        finally:
            self._remove_folder()
