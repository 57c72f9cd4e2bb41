"""A lightweight client that speaks viser's websocket protocol, for benchmarks and load tests.

Not a browser: it connects, announces a camera (viser counts a client as connected only
after its first camera message), decodes every window the server sends, counts frames
and learns each GUI control's id by its label (to send values, as the browser would). Wire format (viser 1.1): each
server frame is ``[u64 msgpack size][u64 zstd size][zstd(msgpack)][padding][binary
buffers]``; client messages are plain msgpack dicts with a ``"type"`` key.
"""

from __future__ import annotations

import asyncio
import contextlib
import json
import select
import subprocess
import sys
import threading
import time
import urllib.parse
from collections.abc import Callable, Coroutine, Iterator
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any, TypeVar

import msgspec
import numpy as np
import viser
import websockets
import zstandard

if TYPE_CHECKING:
    from rigidrel_app.live.server import App
    from rigidrel_app.live.session import Session

ROOT = Path(__file__).resolve().parents[1]

_DECOMPRESS = zstandard.ZstdDecompressor()
T = TypeVar("T")


def shown(part: T | None) -> T:
    """``part`` (a chart's layout or frame) of a chart the test knows is shown on its canvas."""
    assert part is not None, "a chart the canvas does not show"
    return part


def wait_until(predicate: Callable[[], T | None], timeout: float = 20.0, interval: float = 0.05) -> T:
    """Poll ``predicate`` until it returns something truthy (returned); AssertionError on timeout."""
    end = time.monotonic() + timeout
    while time.monotonic() < end:
        value = predicate()
        if value:
            return value
        time.sleep(interval)
    raise AssertionError(f"timed out after {timeout} s waiting for {getattr(predicate, '__name__', predicate)}")


class ClientLoop:
    """An asyncio event loop in a thread of its own, for clients driven from synchronous code
    (the caller's thread may already run a loop: playwright's). ``close()`` cancels what is left."""

    def __init__(self) -> None:
        self.loop = asyncio.new_event_loop()
        self._thread = threading.Thread(target=self.loop.run_forever, name="client-loop", daemon=True)
        self._thread.start()

    def run(self, coro: Coroutine[Any, Any, T], timeout: float = 60.0) -> T:
        """Run ``coro`` on the loop and wait for its result."""
        return asyncio.run_coroutine_threadsafe(coro, self.loop).result(timeout)

    def start(self, coro: Coroutine[Any, Any, T]) -> Any:
        """Run ``coro`` on the loop in the background; returns its concurrent future."""
        return asyncio.run_coroutine_threadsafe(coro, self.loop)

    def close(self) -> None:
        async def cancel_the_rest() -> None:
            tasks = [t for t in asyncio.all_tasks() if t is not asyncio.current_task()]
            for t in tasks:
                t.cancel()
            await asyncio.gather(*tasks, return_exceptions=True)

        with contextlib.suppress(Exception):  # tearing down: a task may already be gone
            self.run(cancel_the_rest(), timeout=10)
        self.loop.call_soon_threadsafe(self.loop.stop)
        self._thread.join(timeout=5)


def decode_frame(data: bytes) -> list[dict[str, Any]]:
    """The messages of one server frame (binary buffers left out)."""
    size = int.from_bytes(data[0:8], "little")
    csize = int.from_bytes(data[8:16], "little")
    inner = _DECOMPRESS.decompress(data[16 : 16 + csize], max_output_size=size)
    return list(msgspec.msgpack.decode(inner)["messages"])


def camera_message(width: int = 960, height: int = 720) -> bytes:
    return msgspec.msgpack.encode(
        {
            "type": "ViewerCameraMessage",
            "wxyz": [1.0, 0.0, 0.0, 0.0],
            "position": [0.0, -5.0, 0.0],
            "fov": 0.5,
            "near": 0.01,
            "far": 1000.0,
            "image_height": height,
            "image_width": width,
            "look_at": [0.0, 0.0, 0.0],
            "up_direction": [0.0, 0.0, 1.0],
        }
    )


@dataclass
class Stats:
    frames: int = 0
    bytes: int = 0
    lane_frames: int = 0
    """Frames that moved the picture: a scene-node update (the rods, their clocks, the lane titles or
    the now-lines). Not the rods' boxes alone: a lane follows its rods, so a rod in uniform motion
    keeps its place on the page while its ruler scrolls, and its box sends nothing."""
    lane_times: list[float] = field(default_factory=list)
    errors: list[str] = field(default_factory=list)
    first_picture_bytes: int | None = None
    """Bytes received up to and including the first frame that carries the rods' meshes (the
    first picture a browser can draw), or None before it."""


class LightClient:
    """One connection. ``await client.run(seconds)`` reads until time is up (or ``stop()``)."""

    def __init__(self, url: str, read: bool = True) -> None:
        self.url = url.replace("http://", "ws://")
        self.read = read
        self.stats = Stats()
        self.gui_uuid: dict[str, str] = {}
        self.command_uuid: dict[str, str] = {}
        """The tab's keyboard commands (viser's command palette), by label."""
        self._ws: Any = None
        self._stop = asyncio.Event()
        self._pending: set[asyncio.Task[None]] = set()

    async def connect(self) -> None:
        self._ws = await websockets.connect(
            self.url,
            subprotocols=[websockets.Subprotocol(f"viser-v{viser.__version__}")],
            max_size=None,
            open_timeout=30,
        )
        await self._ws.send(camera_message())

    async def send_raw(self, message: dict[str, Any]) -> None:
        await self._ws.send(msgspec.msgpack.encode(message))

    async def set_value(self, label: str, value: Any) -> None:
        """What the browser sends when a control labelled ``label`` is moved (or a button pressed: True)."""
        await self.send_raw({"type": "GuiUpdateMessage", "uuid": self.gui_uuid[label], "updates": {"value": value}})

    def stall(self) -> None:
        """Stop reading (the connection stays open): the server's frames pile up in the socket."""
        self.read = False

    def abort(self) -> None:
        """Drop the connection without a close frame, as a tab whose network vanished does."""
        if self._ws is not None:
            self._ws.transport.abort()

    def stop(self) -> None:
        self._stop.set()

    async def run(self, seconds: float) -> Stats:
        end = time.monotonic() + seconds
        try:
            while not self._stop.is_set():
                left = end - time.monotonic()
                if left <= 0:
                    break
                if not self.read:  # a stalled client: connected, reading nothing
                    await asyncio.sleep(min(left, 0.1))
                    continue
                try:
                    data = await asyncio.wait_for(self._ws.recv(), timeout=min(left, 1.0))
                except TimeoutError:
                    continue
                self._consume(data)
        except websockets.ConnectionClosed as exc:
            self.stats.errors.append(f"closed: {exc}")
        return self.stats

    def _consume(self, data: bytes) -> None:
        s = self.stats
        s.frames += 1
        s.bytes += len(data)
        moved = False
        for m in decode_frame(data):
            kind = m.get("type", "")
            if kind == "BatchedMeshesMessage" and s.first_picture_bytes is None:
                s.first_picture_bytes = s.bytes
            if kind == "LocalStorageGetItemRequestMessage":  # a browser answers; this one has stored nothing
                reply = {"type": "LocalStorageGetItemResponseMessage", "value": None, "error": None}
                self._answer({**reply, "request_uuid": m["request_uuid"]})
            props = m.get("props")
            # a control (not a folder of the same name), by its label
            if kind.startswith("Gui") and kind != "GuiFolderMessage" and isinstance(props, dict) and "label" in props:
                self.gui_uuid[str(props["label"])] = str(m["uuid"])
            if kind == "RegisterCommandMessage" and isinstance(props, dict):
                self.command_uuid[str(props["label"])] = str(m["uuid"])
            if kind == "SceneNodeUpdateMessage":
                moved = True
        if moved:
            s.lane_frames += 1
            s.lane_times.append(time.monotonic())

    def _answer(self, message: dict[str, Any]) -> None:
        async def send() -> None:
            with contextlib.suppress(websockets.ConnectionClosed):
                await self.send_raw(message)

        task = asyncio.get_running_loop().create_task(send())
        self._pending.add(task)
        task.add_done_callback(self._pending.discard)

    async def close(self) -> None:
        if self._ws is not None:
            await self._ws.close()


#: Seconds every client of a swarm reads before its measured window (playback starts meanwhile).
SWARM_WARMUP = 3.0


@dataclass(frozen=True)
class Tab:
    """One lightweight client of an app running in this process: the tab's session, the client, and
    the loop it reads on."""

    session: Session
    client: LightClient
    loop: ClientLoop


@contextlib.contextmanager
def light_tab(app: App, make_client: Callable[[str], LightClient] = LightClient) -> Iterator[Tab]:
    """Connect one client (``make_client(app.url)``) to ``app`` (running), read its frames in the
    background, and yield its :class:`Tab` once its session has drawn; the client is stopped and
    closed and the loop closed after, whatever happened."""
    loop = ClientLoop()
    try:
        client = make_client(app.url)
        loop.run(client.connect())
        loop.start(client.run(3600))
        session = wait_until(lambda: next(iter(app.sessions.values()), None), timeout=60)
        wait_until(lambda: session.painter.drawn is not None, timeout=60)
        yield Tab(session, client, loop)
        client.stop()
        loop.run(client.close())
    finally:
        loop.close()


class Recorder(LightClient):
    """A light client that keeps every message the server sent it, decoded."""

    def __init__(self, url: str) -> None:
        super().__init__(url)
        self.messages: list[dict[str, Any]] = []

    def _consume(self, data: bytes) -> None:
        self.messages += decode_frame(data)
        super()._consume(data)


@contextlib.contextmanager
def recorded_tab() -> Iterator[tuple[Session, Recorder]]:
    """An app of its own with one :class:`Recorder` tab, once its controls have arrived: (the
    tab's session, the client); the app stopped after, whatever happened."""
    from rigidrel_app.live.server import App

    with App(port=0) as app, light_tab(app, Recorder) as t:
        client = t.client
        assert isinstance(client, Recorder)
        wait_until(lambda: "V" in client.gui_uuid, timeout=60)
        yield t.session, client


def swarm_main(url: str, n: int, seconds: float) -> None:
    """In a child process: ``n`` clients read for SWARM_WARMUP + ``seconds``; print one JSON line.

    Per client: ``lane_frames`` (rod-moving frames inside the measured window), ``bytes`` (received,
    prorated to the window) and ``errors``.
    """

    async def main() -> list[Stats]:
        clients = [LightClient(url) for _ in range(n)]
        await asyncio.gather(*(c.connect() for c in clients))
        stats = await asyncio.gather(*(c.run(SWARM_WARMUP + seconds) for c in clients))
        for c in clients:
            await c.close()
        return stats

    start = time.monotonic()
    stats = asyncio.run(main())
    t0 = start + SWARM_WARMUP
    share = seconds / (SWARM_WARMUP + seconds)
    rows = [
        {
            "lane_frames": sum(1 for t in s.lane_times if t0 <= t < t0 + seconds),
            "bytes": s.bytes * share,
            "errors": s.errors,
        }
        for s in stats
    ]
    print(json.dumps(rows))


@contextlib.contextmanager
def client_swarm(url: str, n: int, seconds: float) -> Iterator[subprocess.Popen[str]]:
    """Start ``swarm_main`` in another interpreter (so the clients do not share the server's GIL).

    Read its result with ``swarm_result``; the child is killed on the way out whatever happened.
    """
    code = f"from tests.viser_client import swarm_main; swarm_main({url!r}, {n}, {seconds})"
    child = subprocess.Popen([sys.executable, "-c", code], cwd=ROOT, stdout=subprocess.PIPE, text=True)
    try:
        yield child
    finally:
        if child.poll() is None:
            child.kill()
            child.communicate(timeout=30)


def swarm_result(child: subprocess.Popen[str], seconds: float) -> list[dict[str, Any]]:
    out, _ = child.communicate(timeout=seconds + SWARM_WARMUP + 120.0)
    if child.returncode != 0 or not out.strip():
        raise RuntimeError(f"the client process failed (exit {child.returncode})")
    return json.loads(out.strip().splitlines()[-1])


#: How the clients of a churn round leave, in turn: with a close frame; by dropping the socket
#: without one; after they stopped reading (the server's frames piling up), dropping the socket.
CHURN_EXITS = ("polite", "abrupt", "stalled")
#: The paper figure every churn client opens and plays.
CHURN_FIGURE = "Fig. 3: collision, M2 = 2 M1"


async def join_and_play(client: LightClient, figure: str = CHURN_FIGURE, timeout: float = 60.0) -> asyncio.Task[Stats]:
    """Connect ``client`` as a student does: wait for the controls and the first picture, choose
    ``figure`` and press Play. Returns the task reading the connection (cancel it to stop)."""
    await client.connect()
    reader = asyncio.get_running_loop().create_task(client.run(3600))
    end = time.monotonic() + timeout
    while "Play" not in client.gui_uuid or client.stats.first_picture_bytes is None:
        if time.monotonic() > end or reader.done():
            reader.cancel()
            raise TimeoutError("no controls and first picture in time")
        await asyncio.sleep(0.02)
    await client.set_value("Paper figure", figure)
    await client.set_value("Play", True)
    return reader


async def _leave(client: LightClient, exit: str, reader: asyncio.Task[Stats]) -> list[str]:
    """Leave as ``exit`` says; returns the errors the client met while it was there."""
    errors = list(client.stats.errors)
    client.stop()
    if exit == "polite":
        with contextlib.suppress(Exception):
            await asyncio.wait_for(client.close(), 5.0)
    else:
        client.abort()
    reader.cancel()
    await asyncio.gather(reader, return_exceptions=True)
    return errors


def _frames_between(stats: Stats, t0: float, t1: float) -> int:
    return sum(1 for t in stats.lane_times if t0 <= t < t1)


async def _churn(url: str, clients: int, stay: int, seconds: float) -> None:
    loop = asyncio.get_running_loop()
    steady = [LightClient(url) for _ in range(stay)]
    readers = await asyncio.gather(*(join_and_play(c) for c in steady))
    print(json.dumps({"ready": stay}), flush=True)
    while (await loop.run_in_executor(None, sys.stdin.readline)).strip() == "round":
        t0 = time.monotonic()
        comers = [LightClient(url) for _ in range(clients)]
        joined = await asyncio.gather(*(join_and_play(c) for c in comers), return_exceptions=True)
        exits = [CHURN_EXITS[i % len(CHURN_EXITS)] for i in range(clients)]
        for c, exit in zip(comers, exits, strict=True):
            if exit == "stalled":
                c.stall()
        await asyncio.sleep(seconds)
        errors: list[str] = [f"join: {j!r}" for j in joined if isinstance(j, BaseException)]
        left = await asyncio.gather(
            *(_leave(c, e, j) for c, e, j in zip(comers, exits, joined, strict=True) if isinstance(j, asyncio.Task))
        )
        t1 = time.monotonic()
        errors += [e for row in left for e in row] + [e for c in steady for e in c.stats.errors]
        row = {
            "joined": sum(isinstance(j, asyncio.Task) for j in joined),
            "first_picture_bytes": [c.stats.first_picture_bytes for c in comers if c.stats.first_picture_bytes],
            "steady_fps": [_frames_between(c.stats, t0, t1) / (t1 - t0) for c in steady],
            "errors": errors,
            "seconds": t1 - t0,
        }
        print(json.dumps(row), flush=True)
    await asyncio.gather(*(_leave(c, "polite", r) for c, r in zip(steady, readers, strict=True)))


def churn_main(url: str, clients: int, stay: int, seconds: float) -> None:
    """In a child process: ``stay`` clients join and play, then print ``{"ready": stay}``. Each line
    ``round`` on stdin brings ``clients`` more that join, play for ``seconds`` and leave (in turn
    politely, abruptly, stalled; :data:`CHURN_EXITS`), then one JSON line: how many joined, the bytes
    each received until its first picture, the steady clients' rod frames per second over the
    round, and errors (the steady clients' are cumulative). Any other line ends it."""
    asyncio.run(_churn(url, clients, stay, seconds))


@contextlib.contextmanager
def churn_clients(url: str, clients: int, stay: int, seconds: float) -> Iterator[subprocess.Popen[str]]:
    """Start ``churn_main`` in another interpreter; killed on the way out whatever happened."""
    code = f"from tests.viser_client import churn_main; churn_main({url!r}, {clients}, {stay}, {seconds})"
    child = subprocess.Popen(
        [sys.executable, "-c", code], cwd=ROOT, stdin=subprocess.PIPE, stdout=subprocess.PIPE, text=True
    )
    try:
        yield child
    finally:
        if child.poll() is None:
            child.kill()
        child.communicate(timeout=30)


def read_line(child: subprocess.Popen[str], timeout: float) -> dict[str, Any]:
    """The next JSON line the child prints; RuntimeError if none comes within ``timeout`` s."""
    assert child.stdout is not None
    ready, _, _ = select.select([child.stdout], [], [], timeout)
    line = child.stdout.readline() if ready else ""
    if not line.strip():
        raise RuntimeError(f"the client process said nothing in {timeout} s (exit {child.poll()})")
    return json.loads(line)


def tell(child: subprocess.Popen[str], line: str) -> None:
    assert child.stdin is not None
    child.stdin.write(line + "\n")
    child.stdin.flush()


async def flood(client: LightClient, label: str, rate: float, seconds: float) -> tuple[int, float | None]:
    """Send values to the control ``label`` at ``rate`` per second for ``seconds`` (alternating two,
    so that each is a change; none if ``rate`` is 0). Returns how many were sent and after how many seconds the server
    hung up (None if it did not)."""
    if rate <= 0.0:  # a control run: connected, sending nothing
        await asyncio.sleep(seconds)
        return 0, None
    uuid = client.gui_uuid[label]
    encoded = [
        msgspec.msgpack.encode({"type": "GuiUpdateMessage", "uuid": uuid, "updates": {"value": v}}) for v in (0.3, 0.5)
    ]
    ws, t0, sent = client._ws, time.monotonic(), 0
    while (now := time.monotonic()) - t0 < seconds:
        try:
            for _ in range(100):
                await ws.send(encoded[sent % 2])
                sent += 1
        except websockets.ConnectionClosed:
            return sent, now - t0
        await asyncio.sleep(max(0.0, t0 + sent / rate - time.monotonic()))
    return sent, None


def flood_main(url: str, n: int, seconds: float, rate: float) -> None:
    """In a child process: ``n`` clients play Fig. 3 and one more floods "V" at ``rate`` messages per
    second for the first ``seconds`` of the measured window (after SWARM_WARMUP). Prints one JSON
    line: the players' rod frames per second over the window and over its first second, their
    errors, and the flood (messages sent, seconds until the server hung up or null)."""

    async def main() -> dict[str, Any]:
        players = [LightClient(url) for _ in range(n)]
        flooder = LightClient(url)
        readers = await asyncio.gather(*(join_and_play(c) for c in players))
        await flooder.connect()
        flooder_reader = asyncio.get_running_loop().create_task(flooder.run(3600))
        while "V" not in flooder.gui_uuid:
            await asyncio.sleep(0.02)
        await asyncio.sleep(SWARM_WARMUP)
        t0 = time.monotonic()
        sent, hung_up_after = await flood(flooder, "V", rate, seconds)
        await asyncio.sleep(max(0.0, t0 + seconds - time.monotonic()))
        errors = [e for c in players for e in c.stats.errors]
        await asyncio.gather(*(_leave(c, "polite", r) for c, r in zip(players, readers, strict=True)))
        flooder_reader.cancel()
        flooder.abort()
        return {
            "fps": [_frames_between(c.stats, t0, t0 + seconds) / seconds for c in players],
            "fps_first_second": [_frames_between(c.stats, t0, t0 + 1.0) for c in players],
            "errors": errors,
            "sent": sent,
            "hung_up_after": hung_up_after,
        }

    print(json.dumps(asyncio.run(main())), flush=True)


# ---------------------------------------------------------------------------- a tab's runtime, emulated
#: A display's refresh rate: a runtime shows at most one new picture per refresh.
DISPLAY_HZ = 60.0


@dataclass
class _Played:
    """One stretch of a runtime's playing: from frame ``frame`` at ``start`` (monotonic s) at ``speed``."""

    timeline: str
    start: float
    frame: float
    speed: float
    loop: bool
    end: float = float("inf")


class RuntimeClient(LightClient):
    """A light client that does what a browser's playback runtime (``live/assets/runtime.js``) does
    with the server's messages: it says it is ready, keeps each timeline's blocks as they arrive,
    and plays, pauses and seeks as told; it draws nothing. :meth:`pictures_between` counts the new
    pictures the runtime would show in a stretch of time: one per frame of the timeline whose time
    has come (no more than one per refresh of a :data:`DISPLAY_HZ` display) and whose block has
    arrived, and one per still frame the server sent."""

    def __init__(self, url: str, read: bool = True) -> None:
        """``url``: the app's address; with ``?lead=TOKEN`` (the lecturer's) the runtime's ready
        report carries the token, as the browser's does."""
        base, _, query = url.partition("?")
        super().__init__(base, read)
        self.lead = urllib.parse.parse_qs(query).get("lead", [None])[0]
        self.report_uuid: str | None = None
        self.frame_rate = 40.0
        self.blocks: dict[str, dict[int, float]] = {}
        """Each timeline's blocks: first frame -> when it arrived."""
        self.totals: dict[str, int] = {}
        self.played: list[_Played] = []
        self.still_frames: list[float] = []
        """When each still frame (a ``frame`` action: a state's first picture) arrived."""
        self.pages: list[tuple[float, bool]] = []
        """When each shared still picture came (True) or went (False) (a ``page`` action)."""
        self._speed, self._loop = 1.0, True

    def _consume(self, data: bytes) -> None:
        now = time.monotonic()
        for m in decode_frame(data):
            kind = m.get("type")
            if kind == "RunJavascriptMessage" and "__rigidrelPlayback" in m.get("source", ""):
                source, mark = m["source"], "const CONFIG = "
                start = source.index(mark) + len(mark)
                config = json.loads(source[start : source.index(";\n", start)])
                self.report_uuid, self.frame_rate = config["report"], float(config["frameRate"])
                self._report({"event": "ready", "lead": self.lead} if self.lead else {"event": "ready"})
            elif kind == "PlaybackMessage":
                self._act(m["action"], m["timeline"], float(m["value"]), now)
        super()._consume(data)

    def _report(self, what: dict[str, Any]) -> None:
        if self.report_uuid is not None:
            self._answer({"type": "GuiUpdateMessage", "uuid": self.report_uuid, "updates": {"value": json.dumps(what)}})

    def _stop_playing(self, now: float) -> float | None:
        if self.played and self.played[-1].end == float("inf"):
            p = self.played[-1]
            p.end = now
            return self._frame_at(p, now)
        return None

    def _frame_at(self, p: _Played, t: float) -> float:
        f = p.frame + (t - p.start) * self.frame_rate * p.speed
        last = self.totals.get(p.timeline, 1) - 1
        return f % last if p.loop and last > 0 else min(f, float(last))

    def _act(self, action: str, timeline: str, value: float, now: float) -> None:
        from rigidrel_app.live.timeline import TIMELINE_FRAMES

        if action == "block":
            self.blocks.setdefault(timeline, {})[int(value)] = now
            self.totals[timeline] = TIMELINE_FRAMES
        elif action == "frame":
            self._stop_playing(now)
            self.still_frames.append(now)
        elif action == "page":
            self.pages.append((now, value != 0.0))
        elif action == "speed":
            self._speed = value
        elif action == "loop":
            self._loop = value != 0.0
        elif action == "play":
            self._stop_playing(now)
            self.played.append(_Played(timeline, now, value, self._speed, self._loop))
        elif action in ("pause", "seek", "stop"):
            frame = self._stop_playing(now)
            if action == "pause" and frame is not None:
                self._report({"event": "paused", "timeline": timeline, "frame": round(frame)})

    def pictures_between(self, t0: float, t1: float) -> int:
        """New pictures shown in ``[t0, t1)`` (class docstring)."""
        from rigidrel_app.live.timeline import FRAMES_PER_BLOCK

        shown = sum(1 for t in self.still_frames if t0 <= t < t1)
        for p in self.played:
            a, b = max(t0, p.start), min(t1, p.end)
            blocks = self.blocks.get(p.timeline, {})
            last = None
            for t in np.arange(a, b, 1.0 / DISPLAY_HZ):
                k = int(self._frame_at(p, float(t)))
                arrived = blocks.get(k - k % FRAMES_PER_BLOCK)
                if arrived is not None and arrived <= t and k != last:
                    shown += 1
                    last = k
        return shown


async def _ready_runtime(client: RuntimeClient, timeout: float = 120.0) -> None:
    """Wait until the tab's runtime has said it is ready and its first picture has come."""
    t0 = time.monotonic()
    while client.report_uuid is None or not client.still_frames:
        if time.monotonic() - t0 > timeout:
            raise TimeoutError("no runtime script or first picture")
        await asyncio.sleep(0.05)


def hall_state(k: int) -> tuple[float, float]:
    """Tab ``k``'s own state in an independent hall: Fig. 3's collision with its own restitution
    and V2 (eps, v2)."""
    return (k % 100) / 100.0, -0.01 * (k // 100)


async def _hall(url: str, n: int, seconds: float, follow: bool, same: bool = False) -> None:
    """The hall (see :func:`hall_main`)."""
    base = url.partition("?")[0]
    clients = [RuntimeClient(url)] + [RuntimeClient(base) for _ in range(n - 1)]
    readers = []
    # the first to connect leads (--follow: ``url`` is the lead address); the others join together
    await clients[0].connect()
    readers.append(asyncio.ensure_future(clients[0].run(3600)))
    await _ready_runtime(clients[0])
    for batch in range(1, n, 25):  # as a hall comes in: a few dozen at a time
        part = clients[batch : batch + 25]
        await asyncio.gather(*(c.connect() for c in part))
        readers += [asyncio.ensure_future(c.run(3600)) for c in part]
    await asyncio.gather(*(_ready_runtime(c) for c in clients))
    t_play = time.monotonic()
    if not follow:  # each tab chooses Fig. 3, unless ``same`` its own state of it, and plays it
        for k, c in enumerate(clients):
            while "Play" not in c.gui_uuid or "Paper figure" not in c.gui_uuid:
                await asyncio.sleep(0.02)
            await c.set_value("Paper figure", CHURN_FIGURE)
            if not same:  # the scenario box: the sliders' labels are shared with other scenes' controls
                eps, v2 = hall_state(k)
                await c.set_value("Load", f"rod-collision --v1 0.6 --mass2 2 --eps {eps:g} --v2 {v2:g}")
                await c.set_value("Load scenario", True)
            await c.set_value("Play", True)
    # every tab playing its timeline (made once per state, in the recorder's process)
    while time.monotonic() - t_play < 900 and not all(
        c.played and c.blocks.get(c.played[-1].timeline) for c in clients
    ):
        await asyncio.sleep(0.05)
    print(json.dumps({"phase": "joined", "clients": n, "playing_after_s": time.monotonic() - t_play}), flush=True)
    loop = asyncio.get_running_loop()
    await loop.run_in_executor(None, sys.stdin.readline)  # "measure"
    await asyncio.sleep(SWARM_WARMUP)
    t0 = time.monotonic()
    print(json.dumps({"phase": "window"}), flush=True)
    await asyncio.sleep(seconds)
    t1 = time.monotonic()
    fps = [c.pictures_between(t0, t1) / (t1 - t0) for c in clients]
    errors = [e for c in clients for e in c.stats.errors]
    print(
        json.dumps({"phase": "measured", "fps": fps, "errors": errors, "bytes": [c.stats.bytes for c in clients]}),
        flush=True,
    )
    latencies: list[float | None] = []
    if follow:
        await loop.run_in_executor(None, sys.stdin.readline)  # "step"
        followers = clients[1:]
        before = [len(c.still_frames) for c in followers]
        t_step = time.monotonic()
        await clients[0].set_value("Next step", True)
        deadline = t_step + 30.0
        while time.monotonic() < deadline and any(
            len(c.still_frames) == b for c, b in zip(followers, before, strict=True)
        ):
            await asyncio.sleep(0.01)
        latencies = [
            (c.still_frames[b] - t_step) if len(c.still_frames) > b else None
            for c, b in zip(followers, before, strict=True)
        ]
    print(json.dumps({"phase": "stepped", "latencies": latencies}), flush=True)
    for c in clients:
        c.stop()
    await asyncio.gather(*(c.close() for c in clients), return_exceptions=True)
    for r in readers:
        r.cancel()


def hall_main(url: str, n: int, seconds: float, follow: bool, same: bool = False) -> None:
    """In a child process: ``n`` tabs with the playback runtime (:class:`RuntimeClient`) join; with
    ``follow`` they follow the first (a lesson's leader), else each plays Fig. 3 in a state of its
    own (:func:`hall_state`; with ``same`` all in the figure's). Prints JSON lines: ``joined`` once
    every tab plays its timeline (``playing_after_s``: how long after the first press); after a
    ``measure`` line on stdin and :data:`SWARM_WARMUP` s, ``window`` at the start of the measured
    window and ``measured`` after ``seconds`` (each tab's new pictures per second, errors, bytes);
    with ``follow``, after a ``step`` line the leader presses Next step and ``stepped`` says when
    each follower's first picture of the new step came (s after the press, or null if not within 30 s)."""
    asyncio.run(_hall(url, n, seconds, follow, same))


@contextlib.contextmanager
def hall_clients(url: str, n: int, seconds: float, follow: bool, same: bool = False) -> Iterator[subprocess.Popen[str]]:
    """Start ``hall_main`` in another interpreter; killed on the way out whatever happened."""
    code = f"from tests.viser_client import hall_main; hall_main({url!r}, {n}, {seconds}, {follow}, {same})"
    child = subprocess.Popen(
        [sys.executable, "-c", code], cwd=ROOT, stdin=subprocess.PIPE, stdout=subprocess.PIPE, text=True
    )
    try:
        yield child
    finally:
        if child.poll() is None:
            child.kill()
        child.communicate(timeout=30)
