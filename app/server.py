"""The rigidrel app server: one viser server, one :class:`Session` per browser tab, one animation loop."""

from __future__ import annotations

import contextlib
import signal
import sys
import threading
import time
from collections.abc import Iterator

import viser

from .session import Session

#: 3-D lanes are redrawn at this rate per client while playing (>= 30 fps delivered, with margin).
ANIMATION_HZ = 40.0


class App:
    """A running server. ``with App(...) as app:`` starts it; leaving the block stops it."""

    def __init__(self, host: str = "127.0.0.1", port: int = 8080) -> None:
        self.server = viser.ViserServer(host=host, port=port, label="rigidrel", verbose=False)
        self.server.gui.configure_theme(
            show_share_button=False, show_logo=False, control_width="large", brand_color=(0, 114, 178)
        )
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

    def _connect(self, client: viser.ClientHandle) -> None:
        session = Session(client)
        with self._lock:
            self.sessions[client.client_id] = session

    def _disconnect(self, client: viser.ClientHandle) -> None:
        with self._lock:
            session = self.sessions.pop(client.client_id, None)
        if session is not None:
            session.closed = True

    def _animate(self) -> None:
        """One loop ticks every session on an absolute schedule (no drift from the work done)."""
        period = 1.0 / ANIMATION_HZ
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
                    print(f"rigidrel: session {s.client.client_id}: {exc!r}", file=sys.stderr)
            deadline = max(deadline + period, time.monotonic() - period)  # skip, do not burst, if behind
            self._stop.wait(max(0.0, deadline - time.monotonic()))

    def stop(self) -> None:
        self._stop.set()
        self._loop.join(timeout=2.0)
        self.server.stop()

    def __enter__(self) -> App:
        return self

    def __exit__(self, *exc: object) -> None:
        self.stop()


@contextlib.contextmanager
def running(host: str = "127.0.0.1", port: int = 8080) -> Iterator[App]:
    app = App(host, port)
    try:
        yield app
    finally:
        app.stop()


def serve(host: str = "127.0.0.1", port: int = 8080) -> int:
    """Run until Ctrl-C or SIGTERM; print the URL the server really got."""
    done = threading.Event()

    def _terminate(signum: int, _frame: object) -> None:
        done.set()

    signal.signal(signal.SIGTERM, _terminate)
    with running(host, port) as app:
        print(f"rigidrel: serving on {app.url}  (Ctrl-C to stop)", flush=True)
        try:
            while not done.wait(0.5):
                pass
        except KeyboardInterrupt:
            pass
        print("rigidrel: shutting down", flush=True)
    return 0
