"""Playback in the browser, on the server's side: a state's timeline holds every frame the server
would have drawn, the runtime's reports are read strictly, and tabs in one state share one timeline.

The payloads are read back here as the runtime (``live/assets/runtime.js``) reads them: each
frame's pieces of node state must be what the renderer's messages, folded, made at that frame.
"""

from __future__ import annotations

import gzip
import json
import threading
from typing import Any

import numpy as np
import pytest

from rigidrel_app.backends._viser import RecordingScene, SceneFold
from rigidrel_app.backends.viser import PageRenderer
from rigidrel_app.live.browser_player import BrowserPlayer
from rigidrel_app.live.runtime import PointerEvent, Report, RuntimeConfig, parse_report, runtime_script
from rigidrel_app.live.timeline import (
    OWN_FRAME_LEVEL,
    QUANTUM,
    SHARED_LEVEL,
    Mirror,
    Timeline,
    TimelineCache,
    TimelineKey,
    frame_times,
    record_timeline,
)
from rigidrel_app.view.canvas import moving_picture, still_picture
from rigidrel_app.view.layout import canvas_layout
from rigidrel_app.view.page import frame_pictures, room
from rigidrel_app.view.scene_view import RULER_NAMES, build_drawing
from rigidrel_app.view.state import Resolved, Settings, presets, resolve

DTYPES = {"<f2": np.float16, "<f4": np.float32, "<f8": np.float64, "|u1": np.uint8, "<u4": np.uint32, "<i4": np.int32}


def read_payload(blob: np.ndarray) -> tuple[dict[str, Any], list[dict[Any, Any]]]:
    """A payload as the runtime reads it: its header, and each frame's pieces of node state."""
    raw = gzip.decompress(blob.tobytes())
    n = int.from_bytes(raw[:4], "little")
    head = json.loads(raw[4 : 4 + n])
    base = 4 + n + (-(4 + n)) % 8
    spans = head["buffers"]

    def view(index: int, dtype: Any) -> np.ndarray:
        offset, length = spans[index]
        return np.frombuffer(raw, dtype, length // np.dtype(dtype).itemsize, base + offset)

    def arrays(value: Any) -> Any:
        if isinstance(value, list):
            return [arrays(v) for v in value]
        if isinstance(value, dict):
            if "__binary_index" in value:
                return view(value["__binary_index"], DTYPES[value["dtype"]])
            return {k: arrays(v) for k, v in value.items()}
        return value

    frames: list[dict[Any, Any]] = [{} for _ in range(head["count"])]
    for c in head["columns"]:
        key = tuple(c["key"])
        if c["kind"] == "const":
            for f in frames:
                f[key] = arrays(c["value"])
        elif c["kind"] == "table":
            table = [arrays(v) for v in c["values"]]
            for f, i in zip(frames, view(c["index"], np.uint32), strict=True):
                f[key] = table[i]
        elif c["kind"] == "quant":
            ints, at = view(c["buffer"], np.int32), view(c["offsets"], np.uint32)
            delta, total = view(c["delta"], np.uint8), None
            for k, f in enumerate(frames):
                part = ints[at[k] : at[k + 1]].astype(np.int64)
                total = part if not delta[k] or total is None else total + part
                f[key] = (total / c["scale"]).astype(DTYPES[c["dtype"]])
        else:
            data = view(c["buffer"], DTYPES[c["dtype"]])
            for k, f in enumerate(frames):
                if c["kind"] == "array":
                    f[key] = data[k * c["size"] : (k + 1) * c["size"]]
                else:
                    at = view(c["offsets"], np.uint32)
                    f[key] = data[at[k] : at[k + 1]]
    return head, frames


def same(a: Any, b: Any) -> bool:
    if isinstance(a, np.ndarray) or isinstance(b, np.ndarray):
        a, b = np.asarray(a), np.asarray(b)
        if a.dtype.kind == "f":
            return a.size == b.size and bool(
                np.all(np.abs(a.ravel() - b.ravel().astype(a.dtype)) <= 0.5 / QUANTUM + 1e-4)
            )
        return bool(np.array_equal(a.ravel(), b.ravel()))
    if isinstance(a, tuple | list):
        return len(a) == len(b) and all(same(x, y) for x, y in zip(a, b, strict=True))
    return a == b


@pytest.fixture(scope="module")
def fig3() -> tuple[TimelineKey, Resolved]:
    s = presets()["Fig. 3: collision, M2 = 2 M1"]
    r = resolve(s)
    assert isinstance(r, Resolved)
    layout = canvas_layout(960, 720)
    d = build_drawing(r, areas=layout.chart_areas, label_px=layout.theme.text_px)
    return TimelineKey(s, layout, d.window), r


def drawn_states(key: TimelineKey, r: Resolved, times: np.ndarray) -> list[dict[Any, Any]]:
    """What the app's renderer draws at each time, folded: the state each frame must hold."""
    layout = key.layout
    d = build_drawing(r, areas=layout.chart_areas, label_px=layout.theme.text_px)
    frames, picture = still_picture(d.charts, layout.charts, d.legend(), layout.legend, layout.theme)
    still, moving = RecordingScene(), RecordingScene()
    renderer = PageRenderer(still.scene, moving.scene)
    renderer.set_static(layout, picture, RULER_NAMES)
    renderer.reserve(*room(frame_pictures(d, layout, frames, frame_times(key.window))))  # as the timeline does
    fold, out = SceneFold(), []
    for lanes, moving_part in frame_pictures(d, layout, frames, times):
        renderer.update(lanes, moving_part)
        for m in moving.take():
            fold.add(m)
        out.append(dict(fold.state))
    return out


def test_every_frame_of_a_timeline_is_what_the_app_draws_then(fig3: tuple[TimelineKey, Resolved]) -> None:
    key, r = fig3
    timeline = record_timeline(key, r)
    assert timeline.times[0] == key.window[0] and timeline.times[-1] == key.window[1]  # both ends exactly
    assert len(timeline.blocks) > 1  # played as its blocks come
    heads, frames = [], []
    for block in timeline.blocks:
        head, part = read_payload(block)
        heads.append(head)
        frames += part
    assert heads[0]["prologue"] and all(not h["prologue"] for h in heads[1:])  # its nodes made once
    assert [h["first"] for h in heads] == list(range(0, len(frames), heads[0]["count"]))
    steady = {k for k in frames[0] if all(k in f for f in frames)}
    for k in (0, 37, len(frames) - 1):  # a frame of the first block, of a middle one, of the last
        expected = drawn_states(key, r, timeline.times[[k]])[0]
        got = dict(frames[0]) if k else {}
        got.update(frames[k])  # what the first block set and the frame's own block changes
        moving = [key_ for key_ in expected if key_ in got or key_ not in steady]
        assert moving, "the frame holds nothing"
        for piece in moving:
            assert same(got[piece], expected[piece]), (k, piece)


def test_a_frame_time_is_found_only_on_a_frame() -> None:
    times = frame_times((-1.0, 2.0), 321)
    timeline = Timeline("x", times, ())
    assert timeline.frame_of(float(times[17])) == 17 and timeline.frame_of(2.0) == 320
    assert timeline.frame_of(0.5 * float(times[17] + times[18])) is None


def test_tabs_in_one_state_share_one_timeline(fig3: tuple[TimelineKey, Resolved]) -> None:
    key, r = fig3
    made = threading.Event()
    calls: list[str] = []

    def slow(k: TimelineKey, res: Resolved) -> Timeline:
        made.wait(10)
        calls.append("made")
        return Timeline("one", np.zeros(2), ())

    cache = TimelineCache(slow)
    try:
        got: list[Timeline] = []
        done = threading.Event()

        def then(t: Timeline) -> None:
            got.append(t)
            if len(got) == 3:
                done.set()

        for _ in range(3):
            assert cache.request(key, r, then) is None
        made.set()
        assert done.wait(10)
        assert calls == ["made"] and len({id(t) for t in got}) == 1  # made once, the same one to all
        assert cache.request(key, r, then) is got[0]  # made: given at once
    finally:
        cache.stop()


def test_the_mirror_sends_its_nodes_once_and_every_frame_whole(fig3: tuple[TimelineKey, Resolved]) -> None:
    key, r = fig3
    layout = key.layout
    d = build_drawing(r, areas=layout.chart_areas, label_px=layout.theme.text_px)
    frames, picture = still_picture(d.charts, layout.charts, d.legend(), layout.legend, layout.theme)
    mirror = Mirror("tab")
    renderer = PageRenderer(RecordingScene().scene, mirror.scene)
    renderer.set_static(layout, picture, RULER_NAMES)
    heads = []
    for t in (0.0, 0.1, 0.1):
        lanes = d.lane_pictures(t, layout, None)
        renderer.update(lanes, moving_picture(frames, d.moving_items(t, [ln.ends for ln in lanes], None), layout.theme))
        head, (state,) = read_payload(mirror.frame(t, prologue=False))
        heads.append((head, state))
    (first, s0), (second, s1), (third, s2) = heads
    assert first["prologue"] and not second["prologue"]  # its nodes, made once
    assert first["nodeset"] == second["nodeset"] == third["nodeset"]
    assert s1.keys() == s0.keys() == s2.keys()  # whole: every piece, whatever changed
    assert all(same(s1[k], s2[k]) for k in s1)


def test_a_tab_s_own_frame_is_gzipped_fastest_and_reads_as_a_shared_one(fig3: tuple[TimelineKey, Resolved]) -> None:
    """A slider's answer waits for its tab's own still frame (sent to that tab alone): the fastest
    gzip, read back as the same frame; what many tabs are sent keeps the smaller one."""
    key, r = fig3
    layout = key.layout
    d = build_drawing(r, areas=layout.chart_areas, label_px=layout.theme.text_px)
    frames, picture = still_picture(d.charts, layout.charts, d.legend(), layout.legend, layout.theme)

    class Player(BrowserPlayer):
        def __init__(self) -> None:
            super().__init__(None, None)  # type: ignore[arg-type]  # sends nothing: kept here
            self.sent: list[np.ndarray] = []

        def send(self, action: str, timeline: str = "", value: float = 0.0, payload: np.ndarray | None = None) -> None:
            assert action == "frame" and payload is not None
            self.sent.append(payload)

    player, shared = Player(), Mirror("shared")
    player.mirror = Mirror("tab")
    for mirror in (player.mirror, shared):
        renderer = PageRenderer(RecordingScene().scene, mirror.scene)
        renderer.set_static(layout, picture, RULER_NAMES)
        lanes = d.lane_pictures(0.1, layout, None)
        moving = moving_picture(frames, d.moving_items(0.1, [ln.ends for ln in lanes], None), layout.theme)
        renderer.update(lanes, moving)
    player.own_frame(0.1)
    (own,) = player.sent
    blobs = [own, shared.frame(0.1, prologue=True)]
    # gzip's header byte 8 (XFL): 4 for the fastest level, 0 for the levels between
    assert [int(b[8]) for b in blobs] == [4, 0] and (OWN_FRAME_LEVEL, SHARED_LEVEL) == (1, 6)
    (own_head, (own_state,)), (shared_head, (shared_state,)) = (read_payload(b) for b in blobs)
    assert own_state.keys() == shared_state.keys() and all(same(own_state[k], shared_state[k]) for k in own_state)
    assert own_head["times"] == shared_head["times"] == [0.1]
    assert len(own_head["prologue"]) == len(shared_head["prologue"]) > 0


@pytest.mark.parametrize(
    ("text", "report"),
    [
        ('{"event": "ready"}', Report("ready")),
        ('{"event": "paused", "timeline": "ab", "frame": 7}', Report("paused", "ab", 7)),
        ('{"event": "ended", "timeline": "ab", "frame": 320}', Report("ended", "ab", 320)),
        ('{"event": "paused", "timeline": "ab", "frame": -1}', None),
        ('{"event": "paused", "timeline": "ab", "frame": true}', None),
        ('{"event": "paused", "frame": 3}', None),
        ('{"event": "flood"}', None),
        (
            '{"event": "pointer", "run": "r1", "events": [{"seq": 1, "phase": "down", "x": 12, "y": 30.5}, '
            '{"seq": 2, "phase": "up", "x": -3.5, "y": 0}]}',
            Report(
                "pointer", pointer=(PointerEvent(1, "down", 12.0, 30.5), PointerEvent(2, "up", -3.5, 0.0)), run="r1"
            ),
        ),
        ('{"event": "pointer", "run": "r1", "events": []}', None),
        ('{"event": "pointer", "events": [{"seq": 1, "phase": "down", "x": 1, "y": 1}]}', None),
        ('{"event": "pointer", "run": "r1", "events": [{"seq": 1, "phase": "hover", "x": 1, "y": 1}]}', None),
        ('{"event": "pointer", "run": "r1", "events": [{"seq": 0, "phase": "down", "x": 1, "y": 1}]}', None),
        ('{"event": "pointer", "run": "r1", "events": [{"seq": 1, "phase": "down", "x": "1", "y": 1}]}', None),
        ('{"event": "pointer", "run": "r1", "events": [{"seq": 1, "phase": "down", "x": true, "y": 1}]}', None),
        ('{"event": "pointer", "run": "r1", "events": [{"seq": 1, "phase": "down", "x": 1e9, "y": 1}]}', None),
        ('{"event": "pointer", "run": "r1", "events": [{"seq": 1, "phase": "down", "x": NaN, "y": 1}]}', None),
        ('{"event": "pointer", "run": "r1", "events": [{"seq": 1, "phase": "down", "x": 1}]}', None),
        ('{"event": "pointer", "run": "r1", "events": [{"seq": 1, "phase": "move", "x": 1, "y": 1}, 5]}', None),
        ("[1, 2]", None),
        ("not json", None),
        ("", None),
    ],
)
def test_a_report_is_read_strictly(text: str, report: Report | None) -> None:
    assert parse_report(text) == report


def test_the_runtime_is_sent_with_its_configuration() -> None:
    script = runtime_script(RuntimeConfig("7", "uuid-r", (("uuid-t", "number"),)))
    assert "__CONFIG__" not in script
    assert '"owner": "7"' in script and '"report": "uuid-r"' in script and '"frameRate": 40.0' in script


def test_settings_and_layout_make_the_key(fig3: tuple[TimelineKey, Resolved]) -> None:
    key, _ = fig3
    other = TimelineKey(Settings("rod-collision").with_value("v1", 0.7), key.layout, key.window)
    assert key != other and hash(key) == hash(TimelineKey(key.resolved, key.layout, key.window))


def test_a_ready_report_carries_a_lead_token_only_of_a_sane_length() -> None:
    """The lecturer's lead token rides on the runtime's ready report; anything but a short string is dropped."""
    assert parse_report('{"event": "ready", "lead": "abc"}') == Report("ready", lead="abc")
    assert parse_report('{"event": "ready", "lead": ""}') == Report("ready")
    assert parse_report('{"event": "ready", "lead": 5}') == Report("ready")
    assert parse_report(json.dumps({"event": "ready", "lead": "x" * 65})) == Report("ready")


def test_a_pointer_report_carries_at_most_its_latest_events() -> None:
    events = [{"seq": k, "phase": "move", "x": 1, "y": 1} for k in range(1, 18)]
    assert parse_report(json.dumps({"event": "pointer", "run": "r", "events": events[:16]})) is not None
    assert parse_report(json.dumps({"event": "pointer", "run": "r", "events": events})) is None
