"""A tab last used with another rigidrel version is told that the server changed under it."""

from __future__ import annotations

from collections.abc import Callable

import viser

#: The browser's localStorage key holding the version a tab last ran.
VERSION_KEY = "rigidrel_version"


def greet(client: viser.ClientHandle, version: str, closed: Callable[[], bool]) -> None:
    """Record ``version`` in the tab and, if it last ran another one, say so in a notification.

    Blocks on a browser round trip: run it in a thread of its own. A client that is not a
    browser, or that is gone (``closed()``), is left alone.
    """
    storage = client.local_storage
    try:
        seen = storage.get_item(VERSION_KEY, timeout=30.0)  # a slow machine, drawing its first page
        storage.set_item(VERSION_KEY, version)
    except (TimeoutError, RuntimeError):  # not a browser, or gone
        return
    if seen is not None and seen != version and not closed():
        client.add_notification(
            "rigidrel was updated",
            f"This page was last used with rigidrel {seen}; the server now runs {version}. The controls are "
            "back to their defaults. If anything looks out of date, reload the page (Ctrl+R).",
            color="blue",
            auto_close_seconds=20.0,
        )
