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

The browser, private to viser's client (inventory; the scripts in ``live/assets/`` use these):

- ``canvas[data-engine]``: the three.js canvas (its CSS and rendered size).
- a control's element ``id`` is its handle's uuid; a number box is the slider's next sibling
  (``.mantine-NumberInput-root``); a panel is a ``[data-dock-group]`` or a ``.mantine-Tabs-root``.
- React's fiber tree from ``#root`` to viser's ``ViewerContext`` value (``mutable``,
  ``useSceneTree``, ``useGuiConfig``), its ``mutable.current.messageQueue`` (a plain array drained
  by the render loop), ``requestRender()`` and ``sendMessage()`` (the playback runtime).
"""

from __future__ import annotations

from importlib import metadata
from typing import Any

import numpy as np
import viser
from viser import _messages  # pyright: ignore[reportPrivateUsage]
from viser._image_encoding import cv2_imencode_with_fallback  # pyright: ignore[reportPrivateUsage]
from viser.infra import WebsockClientConnection

__all__ = [
    "CONTROL_MESSAGE_TYPES",
    "SUPPORTED_VISER",
    "Message",
    "WebsockClientConnection",
    "check_version",
    "encode_png",
    "handle_uuid",
    "live_websocket",
    "make_image",
    "on_connection",
    "queue_to_client",
    "run_javascript",
    "set_image_png",
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
