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
import subprocess
import sys
import threading
import time
from collections.abc import Callable, Coroutine, Iterator
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, TypeVar

import msgspec
import viser
import websockets
import zstandard

ROOT = Path(__file__).resolve().parents[1]

_DECOMPRESS = zstandard.ZstdDecompressor()
T = TypeVar("T")


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
    """Frames that moved the rods (a batched-mesh position update)."""
    lane_times: list[float] = field(default_factory=list)
    errors: list[str] = field(default_factory=list)


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
            props = m.get("props")
            # a control (not a folder of the same name), by its label
            if kind.startswith("Gui") and kind != "GuiFolderMessage" and isinstance(props, dict) and "label" in props:
                self.gui_uuid[str(props["label"])] = str(m["uuid"])
            if kind == "RegisterCommandMessage" and isinstance(props, dict):
                self.command_uuid[str(props["label"])] = str(m["uuid"])
            if kind == "SceneNodeUpdateMessage" and "batched_positions" in m.get("updates", {}):
                moved = True
        if moved:
            s.lane_frames += 1
            s.lane_times.append(time.monotonic())

    async def close(self) -> None:
        if self._ws is not None:
            await self._ws.close()


#: Seconds every client of a swarm reads before its measured window (playback starts meanwhile).
SWARM_WARMUP = 3.0


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
