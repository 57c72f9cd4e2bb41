"""The rigidrel app server: one viser server, one :class:`Session` per browser tab, one animation loop."""

from __future__ import annotations

import asyncio
import contextlib
import logging
import signal
import sys
import threading
import time
import warnings
from importlib import metadata
from typing import Any

import viser

from ..view.state import Settings
from .greeting import greet
from .playback import FRAME_RATE
from .session import Session

#: 3-D lanes are redrawn at this rate per client while playing (>= 30 fps delivered, with margin).
ANIMATION_HZ = FRAME_RATE
#: Pause after each session's tick (seconds): hands the GIL to viser's sending thread.
_HANDOFF = 0.00005


def app_version() -> str:
    try:
        return metadata.version("rigidrel")
    except metadata.PackageNotFoundError:
        return "unknown"


class _OneLine(logging.Filter):
    """The websockets library logs a traceback when a client sends garbage: make it one line."""

    def filter(self, record: logging.LogRecord) -> bool:
        if record.exc_info and record.exc_info[1] is not None:
            exc = record.exc_info[1]
            record.msg = f"rigidrel: dropped a client connection ({type(exc).__name__}: {exc})"
            record.args = ()
            record.exc_info = None
            record.exc_text = None
        return True


_ONE_LINE = _OneLine()
#: Where the websockets library logs a failed connection ("connection handler failed" comes from
#: ``websockets.server``, e.g. when viser meets a message type it does not know).
_WEBSOCKET_LOGGERS = ("websockets", "websockets.server")


class App:
    """A running server. ``with App(...) as app:`` starts it; leaving the block stops it.

    Binds 127.0.0.1 unless told otherwise; viser moves to the next port when one is busy
    (``url`` has the one it got). The share button (it needs the internet) is hidden.
    """

    def __init__(
        self,
        host: str = "127.0.0.1",
        port: int = 8080,
        animation_hz: float | None = None,
        version: str | None = None,
        start: Settings | None = None,
    ) -> None:
        """``start``: the settings every new tab opens on (default: the first scene's defaults)."""
        self.animation_hz = animation_hz or ANIMATION_HZ
        self.start = start
        self.version = version or app_version()
        self.errors = 0
        """Exceptions met while ticking sessions or handling client messages (each logged in one line)."""
        for name in _WEBSOCKET_LOGGERS:  # a logger's filters see only its own records, not its children's
            logging.getLogger(name).addFilter(_ONE_LINE)
        # a tick can race a tab's disconnect; viser then warns that a message will never be
        # delivered, which is exactly right and not worth a warning
        warnings.filterwarnings("ignore", message=r"Queued a \w+ on a closed connection")
        self.server = viser.ViserServer(host=host, port=port, label="rigidrel", verbose=False)
        self.server.gui.configure_theme(
            show_share_button=False, show_logo=False, control_width="large", brand_color=(0, 114, 178)
        )
        loop = self.server.get_event_loop()
        loop.call_soon_threadsafe(loop.set_exception_handler, self._loop_exception)
        self.sessions: dict[int, Session] = {}
        self._lock = threading.Lock()
        self._stop = threading.Event()
        self.server.on_client_connect(self._connect)
        self.server.on_client_disconnect(self._disconnect)
        self._loop = threading.Thread(target=self._animate, name="rigidrel-animation", daemon=True)
        self._loop.start()

    @property
    def url(self) -> str:
        host = self.server.get_host()
        shown = "127.0.0.1" if host in ("0.0.0.0", "") else host
        return f"http://{shown}:{self.server.get_port()}"

    def _loop_exception(self, loop: asyncio.AbstractEventLoop, context: dict[str, Any]) -> None:
        """A malformed message raises inside viser's handlers: one line on stderr, not a traceback."""
        del loop
        self.errors += 1
        exc = context.get("exception")
        what = f"{type(exc).__name__}: {exc}" if exc is not None else context.get("message", "?")
        print(f"rigidrel: ignored a bad client message ({what})", file=sys.stderr)

    def _connect(self, client: viser.ClientHandle) -> None:
        session = Session(client, self.start)
        with self._lock:
            self.sessions[client.client_id] = session
        threading.Thread(
            target=greet, args=(client, self.version, lambda: session.closed), name="rigidrel-greet", daemon=True
        ).start()

    async def _disconnect(self, client: viser.ClientHandle) -> None:
        # async: it runs on viser's event loop, so it still runs while the server stops
        # (a sync callback would be submitted to viser's thread pool, already shut by then)
        with self._lock:
            session = self.sessions.pop(client.client_id, None)
        if session is not None:
            session.closed = True

    def _animate(self) -> None:
        """One loop ticks every session on an absolute schedule (no drift from the work done)."""
        period = 1.0 / self.animation_hz
        last = time.monotonic()
        deadline = last
        while not self._stop.is_set():
            now = time.monotonic()
            dt, last = now - last, now
            with self._lock:
                sessions = list(self.sessions.values())
            for s in sessions:
                try:
                    s.tick(dt)
                except Exception as exc:  # a broken tab must not stop the others
                    self.errors += 1
                    print(f"rigidrel: session {s.client.client_id}: {exc!r}", file=sys.stderr)
                # let viser's event loop (another thread, same GIL) send what was queued:
                # without this a long round starves it and every client's frames coalesce
                time.sleep(_HANDOFF)
            deadline = max(deadline + period, time.monotonic() - period)  # skip, do not burst, if behind
            self._stop.wait(max(0.0, deadline - time.monotonic()))

    def stop(self) -> None:
        self._stop.set()
        self._loop.join(timeout=2.0)
        with contextlib.redirect_stdout(sys.stderr):  # viser says "Server stopped"; keep stdout for our output
            self.server.stop()

    def __enter__(self) -> App:
        return self

    def __exit__(self, *exc: object) -> None:
        self.stop()


def serve(host: str = "127.0.0.1", port: int = 8080, start: Settings | None = None) -> int:
    """Run until Ctrl-C or SIGTERM; print the URL the server really got."""
    done = threading.Event()

    def _terminate(signum: int, _frame: object) -> None:
        done.set()

    # Both installed explicitly: a process started in the background by a non-interactive
    # shell inherits SIGINT as *ignored*, and Python then raises no KeyboardInterrupt.
    signal.signal(signal.SIGINT, _terminate)
    signal.signal(signal.SIGTERM, _terminate)
    with App(host, port, start=start) as app:
        print(f"rigidrel: serving on {app.url}  (Ctrl-C to stop)", flush=True)
        while not done.wait(0.5):
            pass
        print("rigidrel: shutting down", flush=True)
    return 0
