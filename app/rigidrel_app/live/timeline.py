"""A state's timeline: the page's moving parts at every frame, made once and played by the browser.

A tab's playback runtime (``assets/runtime.js``) draws the moving parts of the page: the lanes'
boxes, lines, clocks, titles and rulers, the diagrams' now-lines and markers. The server never
draws them frame by frame; it sends the runtime

* a **timeline** (:class:`Timeline`, :func:`record_timeline`) for a state and a canvas: every
  frame of the playback window, recorded once by the same :class:`PageRenderer` the app draws with
  (on a :class:`RecordingScene`, which sends nowhere), folded into each frame's full state and
  written as columns, in gzip blocks. Tabs in the same state and canvas share one
  (:class:`TimelineCache`, keyed by :class:`TimelineKey`);
* a **still frame** (:class:`Mirror`): one instant, drawn at once for a control's answer, a seek
  or a step, by a renderer of the tab's own that mirrors what the runtime shows.

A payload is one blob: ``[u32 header length][header JSON][pad to 8][buffers]``, every buffer at a
multiple of 8. The header holds the frames' times, the node set's id, the creation messages of
its nodes (``prologue``, viser's wire dicts) and one column per piece of node state
(:data:`~rigidrel_app.backends._viser.NodeKey`):

* ``const``: one value for every frame (arrays as viser's ``{"__binary_index", "dtype"}``);
* ``array``: a numpy value of one shape per frame, stacked (``buffer``, ``dtype``, ``size``);
* ``ragged``: numpy values of changing shapes, concatenated (``buffer``, ``offsets``: u32);
* ``table``: any other value, as an index (u32) into the column's ``values``;

with, except for ``const``, a u8 ``changed`` flag per frame (it differs from the frame before).
"""

from __future__ import annotations

import concurrent.futures
import gzip
import hashlib
import itertools
import json
import multiprocessing
import sys
import threading
from collections import OrderedDict
from collections.abc import Callable, Hashable, Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np
import numpy.typing as npt

from ..backends._viser import NodeKey, RecordingScene, SceneFold, wire_dict, wire_value
from ..backends.viser import PageRenderer
from ..view.canvas import still_picture
from ..view.layout import CanvasLayout
from ..view.page import frame_pictures, room
from ..view.scene_view import build_drawing
from ..view.state import Resolved
from ..view.state import resolve as resolve_settings
from .playback import FRAME_RATE, PLAY_SECONDS

#: Frames in one block: the first block plays while the others are on their way.
FRAMES_PER_BLOCK = 64
#: Frames of a timeline: the window at the normal pace, one frame every 1/FRAME_RATE s, both ends in.
TIMELINE_FRAMES = round(PLAY_SECONDS * FRAME_RATE) + 1
#: Timelines kept (each a few hundred kB): the states a hall moves through in a lecture.
CACHED_TIMELINES = 48


def frame_times(window: tuple[float, float], count: int = TIMELINE_FRAMES) -> npt.NDArray[np.float64]:
    """The times of a timeline's frames: ``count`` evenly over ``window`` (both ends), the step one
    frame of playback at the normal pace (:class:`~rigidrel_app.live.playback.Playback`)."""
    return np.linspace(window[0], window[1], count)  # both ends exactly


# ---------------------------------------------------------------------------- the payload
def _same(a: object, b: object) -> bool:
    if a is b:  # a folded state keeps the very value a frame did not change
        return True
    if isinstance(a, np.ndarray) or isinstance(b, np.ndarray):
        return (
            isinstance(a, np.ndarray)
            and isinstance(b, np.ndarray)
            and a.dtype == b.dtype
            and a.shape == b.shape
            and bool(np.array_equal(a, b))
        )
    return a == b


class _Buffers:
    """The payload's binary section: each buffer at a multiple of 8 bytes."""

    def __init__(self) -> None:
        self.parts: list[memoryview] = []

    def add(self, array: np.ndarray) -> int:
        self.parts.append(np.ascontiguousarray(array).data.cast("B"))
        return len(self.parts) - 1


def _column(key: NodeKey, values: Sequence[object], buffers: _Buffers) -> dict[str, Any]:
    """One piece of node state over a block's frames (module docstring)."""
    entry: dict[str, Any] = {"key": list(key)}
    first = values[0]
    if len(values) == 1 or all(_same(first, v) for v in values[1:]):
        views: list[memoryview] = buffers.parts
        entry.update(kind="const", value=wire_value(first, views))
        return entry
    changed = np.ones(len(values), np.uint8)
    changed[1:] = [not _same(a, b) for a, b in itertools.pairwise(values)]
    arrays = [v for v in values if isinstance(v, np.ndarray)]
    if len(arrays) == len(values) and all(a.dtype == arrays[0].dtype for a in arrays) and arrays[0].dtype.kind == "f":
        entry.update(_quantized(arrays, buffers), changed=buffers.add(changed))
        return entry
    if len(arrays) == len(values):
        dtype = arrays[0].dtype
        if all(a.dtype == dtype for a in arrays):
            if all(a.shape == arrays[0].shape for a in arrays):
                entry.update(kind="array", buffer=buffers.add(np.stack(arrays)), dtype=dtype.str, size=arrays[0].size)
            else:
                sizes = np.array([0] + [a.size for a in arrays], np.uint32)
                flat = np.concatenate([a.ravel() for a in arrays])
                entry.update(
                    kind="ragged",
                    buffer=buffers.add(flat),
                    dtype=dtype.str,
                    offsets=buffers.add(np.cumsum(sizes).astype(np.uint32)),
                )
            entry["changed"] = buffers.add(changed)
            return entry
    table: list[object] = []
    index = np.empty(len(values), np.uint32)
    for k, v in enumerate(values):
        for j, seen in enumerate(table):
            if _same(seen, v):
                index[k] = j
                break
        else:
            index[k] = len(table)
            table.append(v)
    views = buffers.parts
    entry.update(kind="table", values=[wire_value(v, views) for v in table], index=buffers.add(index))
    entry["changed"] = buffers.add(changed)
    return entry


#: Float arrays (page coordinates, in CSS px) go as integers of 1/QUANTUM px: 1/1024 px is far
#: below what a screen shows, and a frame's change from the last is then small integers that gzip
#: packs (a now-line's dashes all move by one vector).
QUANTUM = 1024.0


def _quantized(arrays: Sequence[np.ndarray], buffers: _Buffers) -> dict[str, Any]:
    """A float column as ``quant``: int32 values of ``round(QUANTUM x)``, each frame's the change
    from the frame before where the sizes agree (``delta`` 1) or the values themselves (0),
    concatenated (``offsets``: u32); the runtime adds them up and divides by ``QUANTUM``."""
    ints = [np.rint(a.ravel().astype(np.float64) * QUANTUM).astype(np.int64) for a in arrays]
    parts, delta = [ints[0]], [0]
    for before, now in itertools.pairwise(ints):
        same = before.size == now.size
        parts.append(now - before if same else now)
        delta.append(1 if same else 0)
    sizes = np.array([0] + [p.size for p in parts], np.uint32)
    flat = np.concatenate(parts)
    if np.abs(flat).max(initial=0) >= 2**31:
        raise ValueError("a page coordinate beyond what int32 of 1/1024 px holds")
    return {
        "kind": "quant",
        "dtype": arrays[0].dtype.str,
        "scale": QUANTUM,
        "buffer": buffers.add(flat.astype(np.int32)),
        "offsets": buffers.add(np.cumsum(sizes).astype(np.uint32)),
        "delta": buffers.add(np.array(delta, np.uint8)),
    }


#: gzip's level for what many tabs are sent (timelines, a shared painting's page and frames):
#: bytes count there, once per tab.
SHARED_LEVEL = 6
#: gzip's level for a tab's own still frame (the moving parts of a slider's answer, sent to that
#: tab alone and waited for): the fastest. For the answer's frames (about 52 kB before gzip):
#: 0.19 ms against 0.51 ms at :data:`SHARED_LEVEL`, 7.0 kB against 6.1 kB (2026-11-29).
OWN_FRAME_LEVEL = 1


def encode_payload(
    header: dict[str, Any],
    states: Sequence[dict[NodeKey, object]],
    prologue: Sequence[Any] = (),
    level: int = SHARED_LEVEL,
) -> bytes:
    """One gzip blob (at ``level``): ``header`` (JSON, with the columns of ``states`` and the wire
    dicts of the ``prologue``'s creation messages added) and its buffers (module docstring)."""
    buffers = _Buffers()
    keys = sorted(states[0], key=repr)
    head = dict(header)
    head["prologue"] = [wire_dict(m, buffers.parts) for m in prologue]
    head["columns"] = [_column(k, [s.get(k) for s in states], buffers) for k in keys]
    offsets, at = [], 0
    for part in buffers.parts:
        at += (-at) % 8
        offsets.append([at, part.nbytes])
        at += part.nbytes
    head["buffers"] = offsets
    text = json.dumps(head, allow_nan=False, separators=(",", ":")).encode()
    blob = bytearray(len(text).to_bytes(4, "little") + text)
    blob += b"\0" * ((-len(blob)) % 8)  # the buffers' offsets count from here
    base = len(blob)
    for (offset, _), part in zip(offsets, buffers.parts, strict=True):
        blob += b"\0" * (base + offset - len(blob))
        blob += part.tobytes()
    return gzip.compress(bytes(blob), compresslevel=level, mtime=0)


def as_u8(blob: bytes) -> npt.NDArray[np.uint8]:
    """A blob as the numpy bytes viser sends raw (in its binary section, copied nowhere)."""
    return np.frombuffer(blob, np.uint8)


# ---------------------------------------------------------------------------- timelines
@dataclass(frozen=True)
class TimelineKey:
    """What a timeline depends on: the state, the page it is laid out on, the playback window."""

    resolved: Hashable
    layout: CanvasLayout
    window: tuple[float, float]


@dataclass(frozen=True)
class Timeline:
    """A state's frames for one canvas (module docstring): its ``id`` (the node set's too), the
    frames' ``times`` and the gzip ``blocks`` the runtime plays."""

    id: str
    times: npt.NDArray[np.float64]
    blocks: tuple[npt.NDArray[np.uint8], ...]

    @property
    def nbytes(self) -> int:
        return sum(b.nbytes for b in self.blocks)

    def frame_of(self, t: float) -> int | None:
        """The frame whose time is ``t`` (to a billionth of the window), or None between frames."""
        times = self.times
        k = int(np.searchsorted(times, t))
        span = times[-1] - times[0]
        for j in (k - 1, k):
            if 0 <= j < len(times) and abs(times[j] - t) <= 1e-9 * max(span, 1e-300):
                return j
        return None


def timeline_id(key: TimelineKey) -> str:
    return hashlib.sha1(repr(key).encode()).hexdigest()[:16]


def record_timeline(
    key: TimelineKey, resolved: Resolved, count: int = TIMELINE_FRAMES, tid: str | None = None
) -> Timeline:
    """Every frame of ``resolved``'s playback ``key.window`` laid out as ``key.layout``, drawn by a
    :class:`PageRenderer` on a recording scene (module docstring). Pure of any tab: any thread.
    ``tid``: its id (default :func:`timeline_id`, in this process)."""
    layout = key.layout
    drawn = build_drawing(resolved, areas=layout.chart_areas, label_px=layout.theme.text_px)
    chart_frames, picture = still_picture(
        drawn.charts, layout.charts, drawn.legend(layout.panels.charts), layout.legend, layout.theme
    )
    still, moving = RecordingScene(), RecordingScene()
    renderer = PageRenderer(still.scene, moving.scene)
    renderer.set_static(layout, picture, drawn.ruler_names)
    times = frame_times(key.window, count)
    pictures = frame_pictures(drawn, layout, chart_frames, times)
    renderer.reserve(*room(pictures))  # before the first frame: no frame makes or removes a node
    fold = SceneFold()
    for m in moving.take():
        fold.add(m)
    states: list[dict[NodeKey, object]] = []
    for lanes, moving_part in pictures:
        renderer.update(lanes, moving_part)
        for m in moving.take():
            fold.add(m)
        states.append(dict(fold.state))
    still.take()
    # a node made after the first frame is hidden before it (folded states lack its pieces there)
    every = {k for s in states for k in s}
    for s in states:
        for k in every - s.keys():
            if k[0] == "visible":
                s[k] = False
    last = states[-1]
    for s in states:
        for k in every - s.keys():
            s[k] = last[k]
    tid = timeline_id(key) if tid is None else tid
    prologue = list(fold.created.values())
    # what never changes goes once, in the first block: the later blocks carry what moves
    steady = {k for k in every if all(_same(states[0][k], s[k]) for s in states[1:])}
    blocks = []
    for first in range(0, count, FRAMES_PER_BLOCK):
        part = states[first : first + FRAMES_PER_BLOCK]
        if first:
            part = [{k: v for k, v in s.items() if k not in steady} for s in part]
        header = {
            "nodeset": tid,
            "first": first,
            "count": len(part),
            "total": count,
            "times": times[first : first + len(part)].tolist(),
            "nodes": list(fold.created) if first == 0 else [],
        }
        blocks.append(as_u8(encode_payload(header, part, prologue if first == 0 else ())))
    return Timeline(tid, times, tuple(blocks))


def _record_settings(key: TimelineKey, tid: str) -> Timeline:
    """In a recorder process: the timeline of ``key``, whose ``resolved`` is the state's settings,
    with the id the server gave it (a key's repr, sets included, differs between processes)."""
    resolved = resolve_settings(key.resolved)  # type: ignore[arg-type]
    if isinstance(resolved, str):  # a state the server drew makes a scene here too
        raise ValueError(resolved)
    return record_timeline(key, resolved, tid=tid)


def _warm_up() -> None:
    """In a recorder process: nothing (importing this module brought in what recording needs)."""


class ProcessRecorder:
    """Records timelines in a process of its own (started on the first one, spawned: nothing of the
    server's threads is copied), so that the second or third of a second a timeline takes never
    holds the server's interpreter: the tabs' answers and the frames on their way keep flowing
    meanwhile. The key's ``resolved`` must be the state's :class:`~rigidrel_app.view.state.Settings`
    (they are sent, not the scene). Call :meth:`shutdown` when done."""

    def __init__(self) -> None:
        self._pool: concurrent.futures.ProcessPoolExecutor | None = None
        self._lock = threading.Lock()

    def _started(self) -> concurrent.futures.ProcessPoolExecutor:
        with self._lock:
            if self._pool is None:
                context = multiprocessing.get_context("spawn")
                self._pool = concurrent.futures.ProcessPoolExecutor(max_workers=1, mp_context=context)
            return self._pool

    def warm(self) -> None:
        """Start the process now, without waiting (it takes a few seconds to import what it needs):
        the first tab to press Play does not wait for it."""
        self._started().submit(_warm_up)

    def __call__(self, key: TimelineKey, resolved: Resolved) -> Timeline:
        del resolved  # made again in the recorder from the key's settings
        return self._started().submit(_record_settings, key, timeline_id(key)).result()

    @property
    def pids(self) -> tuple[int, ...]:
        """The recorder's process ids (none before the first timeline), for a benchmark's accounts."""
        with self._lock:
            pool = self._pool
        processes = getattr(pool, "_processes", None) or {}  # concurrent.futures keeps them by pid
        return tuple(processes)

    def shutdown(self) -> None:
        with self._lock:
            pool, self._pool = self._pool, None
        if pool is not None:
            pool.shutdown(wait=True, cancel_futures=True)


@dataclass
class _Job:
    key: TimelineKey
    resolved: Resolved
    waiting: list[Callable[[Timeline], None]] = field(default_factory=list)


class TimelineCache:
    """Timelines made once and shared: :meth:`request` one for a key, and every caller waiting for
    it is called back (on the cache's worker thread) when it is made. The most recent
    :data:`CACHED_TIMELINES` are kept."""

    def __init__(self, record: Callable[[TimelineKey, Resolved], Timeline] = record_timeline) -> None:
        """``record``: makes a timeline (in this process, or a :class:`ProcessRecorder`, which
        :meth:`stop` shuts down)."""
        self._record = record
        self._done: OrderedDict[TimelineKey, Timeline] = OrderedDict()
        self._jobs: OrderedDict[TimelineKey, _Job] = OrderedDict()
        self._lock = threading.Lock()
        self._wake = threading.Condition(self._lock)
        self._stopped = False
        self.recorded = 0
        """Timelines made (not taken from the cache)."""
        self._thread = threading.Thread(target=self._work, name="rigidrel-timelines", daemon=True)
        self._thread.start()

    def get(self, key: TimelineKey) -> Timeline | None:
        with self._lock:
            timeline = self._done.get(key)
            if timeline is not None:
                self._done.move_to_end(key)
            return timeline

    def request(self, key: TimelineKey, resolved: Resolved, then: Callable[[Timeline], None]) -> Timeline | None:
        """The timeline of ``key`` if made (``then`` is not called); else None, and ``then(timeline)``
        once it is (the newest request is made first: a slider's last value before its earlier ones)."""
        with self._lock:
            timeline = self._done.get(key)
            if timeline is not None:
                self._done.move_to_end(key)
                return timeline
            job = self._jobs.get(key)
            if job is None:
                job = self._jobs[key] = _Job(key, resolved)
            self._jobs.move_to_end(key)
            job.waiting.append(then)
            self._wake.notify()
            return None

    def forget(self, then: Callable[[Timeline], None]) -> None:
        """Stop waiting with ``then`` (a tab that left or moved on); a job nobody waits for is dropped."""
        with self._lock:
            for key, job in list(self._jobs.items()):
                job.waiting = [w for w in job.waiting if w is not then]
                if not job.waiting:
                    del self._jobs[key]

    def stop(self) -> None:
        with self._lock:
            self._stopped = True
            self._wake.notify()
        self._thread.join(timeout=5)
        if isinstance(self._record, ProcessRecorder):
            self._record.shutdown()

    def warm(self) -> None:
        """Get the recorder ready (a :class:`ProcessRecorder` starts its process); else nothing."""
        if isinstance(self._record, ProcessRecorder):
            self._record.warm()

    @property
    def recorder_pids(self) -> tuple[int, ...]:
        """The processes timelines are recorded in, besides this one (a benchmark counts them)."""
        return self._record.pids if isinstance(self._record, ProcessRecorder) else ()

    def _work(self) -> None:
        while True:
            with self._lock:
                while not self._jobs and not self._stopped:
                    self._wake.wait()
                if self._stopped:
                    return
                key, job = self._jobs.popitem(last=True)
            try:
                timeline = self._record(job.key, job.resolved)
            except Exception as exc:  # a recorder process that failed (killed, out of memory): made here
                if self._record is record_timeline:
                    raise
                print(f"rigidrel: recording a timeline in its process: {exc!r}; made in the server", file=sys.stderr)
                timeline = record_timeline(job.key, job.resolved)
            with self._lock:
                self.recorded += 1
                self._done[key] = timeline
                while len(self._done) > CACHED_TIMELINES:
                    self._done.popitem(last=False)
                waiting, job.waiting = job.waiting, []
                # a request that came while it was being made
                late = self._jobs.pop(key, None)
                if late is not None:
                    waiting += late.waiting
            for then in waiting:
                then(timeline)


# ---------------------------------------------------------------------------- a tab's still frames
class Mirror:
    """The moving parts as a tab's runtime shows them, kept by the renderer the tab draws its
    answers with (on :attr:`scene`, a recording scene): :meth:`frame` writes what it drew as one
    full frame for the runtime."""

    def __init__(self, name: str) -> None:
        self._recording = RecordingScene()
        self.scene = self._recording.scene
        self._fold = SceneFold()
        self._name = name
        self._version = 0
        self._nodes: tuple[str, ...] = ()

    @property
    def nodeset(self) -> str:
        """The id of the node set the mirror's frames draw on (changes when a node is made or removed)."""
        return f"{self._name}-{self._version}"

    def frame(self, t: float, prologue: bool, level: int = SHARED_LEVEL) -> npt.NDArray[np.uint8]:
        """The moving parts as drawn since the last frame, whole, at time ``t``: one frame (with the
        creation messages of its nodes if ``prologue``, or if a node was made since), gzip at ``level``."""
        for m in self._recording.take():
            self._fold.add(m)
        nodes = tuple(self._fold.created)
        if nodes != self._nodes:
            self._nodes, self._version = nodes, self._version + 1
            prologue = True
        header = {
            "nodeset": self.nodeset,
            "first": 0,
            "count": 1,
            "total": 1,
            "times": [t],
            "nodes": list(nodes) if prologue else [],
        }
        states = [dict(self._fold.state)]
        return as_u8(encode_payload(header, states, list(self._fold.created.values()) if prologue else (), level))
