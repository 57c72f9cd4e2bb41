"""The rigidrel app server: one viser server, one :class:`Session` per browser tab, one animation loop."""

from __future__ import annotations

import asyncio
import contextlib
import ctypes
import hmac
import logging
import secrets
import signal
import sys
import threading
import time
import warnings
from dataclasses import dataclass
from importlib import metadata
from typing import Any

import viser

from ..backends._viser import (
    CONTROL_MESSAGE_TYPES,
    PageServer,
    WebsockClientConnection,
    live_websocket,
    on_connection,
)
from ..lessons import Lesson
from ..view.scenario import Scenario
from ..view.state import Settings
from ..view.vocabulary import Shade
from .controls import configure_panel
from .cover import cover_page
from .greeting import greet
from .opening import Opening
from .painting import PaintingCache
from .playback import FRAME_RATE
from .session import Session
from .tab import Tab
from .timeline import ProcessRecorder, TimelineCache

#: 3-D lanes are redrawn at this rate per client while playing (>= 30 fps delivered, with margin).
ANIMATION_HZ = FRAME_RATE
#: Pause after each session's tick (seconds): hands the GIL to viser's sending thread.
_HANDOFF = 0.00005
#: Blocks of at least this many bytes get pages of their own from the C allocator (see :func:`limit_heap_growth`).
MMAP_THRESHOLD_BYTES = 128 * 1024
#: glibc's ``mallopt`` parameter number for that threshold (``M_MMAP_THRESHOLD`` in malloc.h).
_M_MMAP_THRESHOLD = -3


def limit_heap_growth() -> bool:
    """Keep the C heap from growing with every connection (Linux with glibc; elsewhere a no-op, False).

    A connection passes a few megabytes through short-lived blocks (the first picture's
    messages, serialised and compressed). glibc serves a block above its mmap threshold
    (128 KiB) with pages of its own and gives them back when it is freed, but once such a
    block is freed it raises the threshold to that size, so the next ones come from the
    per-thread heaps, which keep the freed memory. Measured with 20 clients joining and
    leaving per round: resident memory 400-460 MB with the heaps holding ~400 MB free, against
    ~110 MB (flat) with the threshold fixed. Fixing it (``mallopt(M_MMAP_THRESHOLD, ...)``)
    turns that growth off for the whole process. Returns whether it was set.
    """
    if not sys.platform.startswith("linux"):
        return False
    try:
        libc = ctypes.CDLL(None)  # the C library this process already runs on
        libc.gnu_get_libc_version  # noqa: B018 -- glibc only (AttributeError on musl)
        return bool(libc.mallopt(_M_MMAP_THRESHOLD, MMAP_THRESHOLD_BYTES))
    except (OSError, AttributeError):
        return False


@dataclass(frozen=True)
class MessageBudget:
    """How many messages a tab may send: a token bucket of ``burst`` tokens refilled at ``rate`` per second.

    A control's value (or a key, or a button) costs ``control_cost`` tokens, any other message
    (the camera moving) one. viser's browser client sends a control's value at most every 50 ms
    and the camera at most every 20 ms, i.e. <= 20 x 2 + 50 = 90 tokens per second from one
    hand moving one control while orbiting; a tab that spends the bucket is dropped (a
    browser reconnects, to a new session). At the default rate a tab can ask for at most 75
    redraws per second, however it is written.
    """

    rate: float = 150.0
    burst: float = 150.0
    control_cost: float = 2.0


#: Messages that ask the session to act (each may redraw the scene), as their type names appear
#: in the msgpack a client sends (the budget is spent before a message is decoded).
_CONTROL_TYPE_NAMES = CONTROL_MESSAGE_TYPES


class _Bucket:
    """One client's tokens (:class:`MessageBudget`); touched only on viser's event loop."""

    __slots__ = ("budget", "stamp", "tokens")

    def __init__(self, budget: MessageBudget) -> None:
        self.budget, self.tokens, self.stamp = budget, budget.burst, time.monotonic()

    def spend(self, raw: bytes | str) -> bool:
        """Take the tokens of one message as received; False once the bucket is spent."""
        budget, now = self.budget, time.monotonic()
        self.tokens = min(budget.burst, self.tokens + (now - self.stamp) * budget.rate)
        self.stamp = now
        control = isinstance(raw, bytes) and any(name in raw for name in _CONTROL_TYPE_NAMES)
        self.tokens -= budget.control_cost if control else 1.0
        return self.tokens >= 0.0


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


#: Said to a tab that presses L (or sends the Lead button's click) but was not opened at the lead address.
LEAD_REFUSED = (
    "Only the lecturer's tab leads: the one opened at the lead address that rigidrel serve --follow "
    "printed. This tab follows its steps."
)


class App:
    """A running server. ``with App(...) as app:`` starts it; leaving the block stops it.

    Binds 127.0.0.1 unless told otherwise; viser moves to the next port when one is busy
    (``url`` has the one it got). The share button (it needs the internet) is hidden. A tab's page
    is viser's with the app's cover in it, up from its first paint until its first page is drawn
    (:mod:`.cover`).
    """

    def __init__(
        self,
        host: str = "127.0.0.1",
        port: int = 8080,
        animation_hz: float | None = None,
        version: str | None = None,
        start: Scenario | None = None,
        budget: MessageBudget | None = None,
        lesson: Lesson | None = None,
        follow: bool = False,
        shade: Shade = "light",
        still_image: bool = True,
    ) -> None:
        """``start``: the state every new tab opens on, as a scenario line names it (default: the
        first scene's defaults);
        ``budget``: how many messages a tab may send before it is dropped; ``lesson``: every tab gives
        it, from step 1 (``start`` is then not used); ``follow``: every tab follows the leading tab's
        step (the lecturer's tab leads: one opened at :attr:`lead_url`, whose token only the server's
        console shows; a tab that joins opens on the leader's step); ``shade``: the theme every new
        tab opens in (each tab's key T changes its own);
        ``still_image``: a slow canvas plays with its still picture as one image (:mod:`.still_image`)."""
        limit_heap_growth()
        self.shade: Shade = shade
        self.still_image = still_image
        self.lesson = lesson
        self.follow = follow and lesson is not None
        self.leader: int | None = None
        """The client id of the tab the others follow (``follow``), None before a lecturer's tab connects."""
        self.lead_token = secrets.token_urlsafe(16) if self.follow else None
        """What a tab's address carries to lead (``?lead=...``, :attr:`lead_url`); None without ``follow``."""
        self.lecturers: set[int] = set()
        """The tabs opened at :attr:`lead_url`: only these lead (key L, the Lead button)."""
        self.leader_step = 0
        """The leading tab's step (from 0)."""
        self._followed = 0
        """Leader changes and leader steps not yet passed on to the other tabs (the animation loop does)."""
        self.animation_hz = animation_hz or ANIMATION_HZ
        self.budget = budget or MessageBudget()
        self.floods = 0
        """Clients dropped for sending more than :attr:`budget` allows."""
        self.start = start
        self.version = version or app_version()
        self.errors = 0
        """Exceptions met while ticking sessions or handling client messages (each logged in one line)."""
        for name in _WEBSOCKET_LOGGERS:  # a logger's filters see only its own records, not its children's
            logging.getLogger(name).addFilter(_ONE_LINE)
        # a tick can race a tab's disconnect; viser then warns that a message will never be
        # delivered, which is exactly right and not worth a warning
        warnings.filterwarnings("ignore", message=r"Queued a \w+ on a closed connection")
        # viser's page with the app's cover in it, in the theme a new tab opens in (live/cover.py)
        self.server = PageServer(cover_page(shade), host=host, port=port, label="rigidrel", verbose=False)
        configure_panel(self.server.gui, shade)
        loop = self.server.get_event_loop()
        loop.call_soon_threadsafe(loop.set_exception_handler, self._loop_exception)
        self.timelines = TimelineCache(ProcessRecorder())
        """The playback timelines the tabs' browsers play, made once per state and canvas, shared."""
        self._warmed = False
        self.paintings = PaintingCache()
        """The states laid out and drawn for a canvas, made once per state and canvas, shared."""
        self.sessions: dict[int, Session] = {}
        self._departed: set[int] = set()
        """Clients that left while their session was being built."""
        self._lock = threading.Lock()
        self._stop = threading.Event()
        self.server.on_client_connect(self._connect)
        self.server.on_client_disconnect(self._disconnect)
        # every message a client sends passes its budget as it is read off the socket, before viser
        # decodes it (a connection that never became a tab, sending no camera message, included)
        on_connection(self.server, self._guard)
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

    async def _guard(self, connection: WebsockClientConnection) -> None:
        """Give a new connection a :class:`MessageBudget`: its websocket's ``recv`` (viser's reading
        loop calls it for every message) spends the tokens, and drops the client once they are spent."""
        client_id = connection.client_id
        websocket = live_websocket(self.server, client_id)
        if websocket is None:  # gone already
            return
        budget = self.budget
        bucket, recv = _Bucket(budget), websocket.recv
        why = f"it sent more than its budget ({budget.rate:g} a second, a control's value {budget.control_cost:g})"

        async def budgeted_recv(*args: Any, **kwargs: Any) -> Any:
            raw = await recv(*args, **kwargs)
            if bucket.spend(raw):
                return raw
            self._drop(client_id, websocket, why)
            while True:  # what was read ahead is discarded; then the closed socket raises ConnectionClosed
                await recv(*args, **kwargs)

        websocket.recv = budgeted_recv

    def _drop(self, client_id: int, websocket: Any, why: str) -> None:
        """Close a client's socket now (no close handshake: a flooding client may not read one); its
        session answers nothing more (its messages already queued are counted, not acted on)."""
        self.floods += 1
        with self._lock:
            session = self.sessions.get(client_id)
        if session is not None:
            session.closed = True
        websocket.transport.abort()  # viser then runs its disconnect callbacks, ours included
        print(f"rigidrel: dropped client {client_id}: {why}", file=sys.stderr)

    def _connect(self, client: viser.ClientHandle) -> None:
        # on viser's thread pool: the tab may leave (``_disconnect``) while its session is built
        session: Session | None = None
        try:
            with self._lock:
                first = self.leader_step if self.follow else 0
            start = self.start or Scenario(Settings())
            opening = Opening(
                start.settings,
                self.lesson,
                self.follow,
                self,
                first,
                self.shade,
                start.t,
                self.timelines,
                self.paintings,
                self.still_image,
            )
            session = Session(client, opening)
        finally:
            with self._lock:
                gone = client.client_id in self._departed
                self._departed.discard(client.client_id)
                if session is not None and not gone:
                    self.sessions[client.client_id] = session
                    if self.follow:
                        self._followed += 1  # it is told who leads
        assert session is not None  # Session() returned (else its exception went on up)
        if gone:
            session.closed = True
            return
        threading.Thread(
            target=greet, args=(client, self.version, lambda: session.closed), name="rigidrel-greet", daemon=True
        ).start()
        if not self._warmed:  # the first tab: its Play should not wait for the recorder to start
            self._warmed = True
            self.timelines.warm()

    async def _disconnect(self, client: viser.ClientHandle) -> None:
        # async: it runs on viser's event loop, so it still runs while the server stops
        # (a sync callback would be submitted to viser's thread pool, already shut by then)
        with self._lock:
            session = self.sessions.pop(client.client_id, None)
            if session is None:  # its session is still being built: ``_connect`` lets it go
                self._departed.add(client.client_id)
        if session is not None:
            session.closed = True
            with self._lock:
                self.lecturers.discard(client.client_id)
                if self.leader == client.client_id:
                    self.leader = None  # the lecturer's next tab, or another of its tabs pressing L, leads
                    self._followed += 1

    # ------------------------------------------------------------------ --follow
    def step_changed(self, session: Tab, index: int) -> None:
        """A tab went to another step: if it leads, the others follow (on the animation loop's next
        round, so that no tab's lock is taken while another's is held)."""
        with self._lock:
            if self.follow and self.leader == session.client.client_id:
                self.leader_step = index
                self._followed += 1

    @property
    def lead_url(self) -> str | None:
        """The address the lecturer opens to lead (``follow``), else None."""
        return None if self.lead_token is None else f"{self.url}/?lead={self.lead_token}"

    def lecturer(self, session: Tab, token: str) -> bool:
        """A tab's address carried ``token``: if it is this server's, the tab is the lecturer's and
        leads from now on, at its own step."""
        if self.lead_token is None or not hmac.compare_digest(token.encode(), self.lead_token.encode()):
            return False
        with self._lock:
            self.lecturers.add(session.client.client_id)
            self.leader, self.leader_step = session.client.client_id, session.state.step
            self._followed += 1
        return True

    def lead(self, session: Tab) -> str | None:
        """Key L: a lecturer's tab leads from now on, at its own step; any other tab is refused (the
        reason is returned)."""
        with self._lock:
            if not self.follow:
                return None
            if session.client.client_id not in self.lecturers:
                return LEAD_REFUSED
            self.leader, self.leader_step = session.client.client_id, session.state.step
            self._followed += 1
        return None

    def _pass_on_steps(self) -> None:
        """Bring every other tab to the leading tab's step and tell each tab who leads."""
        with self._lock:
            if not self._followed:
                return
            self._followed = 0
            leader, step = self.leader, self.leader_step
            sessions = list(self.sessions.items())
        moving = [s for client_id, s in sessions if leader is not None and client_id != leader and s.state.step != step]
        for s in moving:  # the new step's picture first, to every tab (made once per canvas size) ...
            s.steps.preview(step)
        for client_id, s in sessions:  # ... then its controls, locks and playback
            if s in moving:
                s.go_to_step(step, report=False)
            s.steps.show_leader(None if leader is None else client_id == leader)
            s.client.flush()

    def _animate(self) -> None:
        """One loop ticks every session on an absolute schedule (no drift from the work done)."""
        period = 1.0 / self.animation_hz
        last = time.monotonic()
        deadline = last
        while not self._stop.is_set():
            now = time.monotonic()
            dt, last = now - last, now
            try:
                self._pass_on_steps()
            except Exception as exc:  # a broken tab must not stop the others
                self.errors += 1
                print(f"rigidrel: following the leading tab: {exc!r}", file=sys.stderr)
            with self._lock:
                sessions = list(self.sessions.values())
            for s in sessions:
                try:
                    s.playing.tick(dt)
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
        self.timelines.stop()
        with contextlib.redirect_stdout(sys.stderr):  # viser says "Server stopped"; keep stdout for our output
            self.server.stop()

    def __enter__(self) -> App:
        return self

    def __exit__(self, *exc: object) -> None:
        self.stop()


def serve(
    host: str = "127.0.0.1",
    port: int = 8080,
    start: Scenario | None = None,
    lesson: Lesson | None = None,
    follow: bool = False,
    shade: Shade = "light",
    still_image: bool = True,
) -> int:
    """Run until Ctrl-C or SIGTERM; print the URL the server really got."""
    done = threading.Event()

    def _terminate(signum: int, _frame: object) -> None:
        done.set()

    # Both installed explicitly: a process started in the background by a non-interactive
    # shell inherits SIGINT as *ignored*, and Python then raises no KeyboardInterrupt.
    signal.signal(signal.SIGINT, _terminate)
    signal.signal(signal.SIGTERM, _terminate)
    with App(host, port, start=start, lesson=lesson, follow=follow, shade=shade, still_image=still_image) as app:
        if lesson is not None:
            followed = ", every tab following the lecturer's" if app.follow else ""
            print(f"rigidrel: lesson {lesson.title!r}, {len(lesson.steps)} steps{followed}", flush=True)
        print(f"rigidrel: serving on {app.url}  (Ctrl-C to stop)", flush=True)
        if app.lead_url is not None:
            print(f"rigidrel: lead from {app.lead_url}  (the lecturer's address: do not show it)", flush=True)
        while not done.wait(0.5):
            pass
        print("rigidrel: shutting down", flush=True)
    return 0
