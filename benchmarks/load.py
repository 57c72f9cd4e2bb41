"""Load benchmark: many lightweight clients playing at once (not a test: machines are noisy).

    python -m benchmarks.load --clients 30 --seconds 60             # 30 tabs, each playing its own scene
    python -m benchmarks.load --follow --clients 200 --seconds 20   # a hall following a lesson's leader
    python -m benchmarks.load --find-max --seconds 20 --fps 30      # the most clients held at 25 fps
    python -m benchmarks.load --find-max --up-to 110 --seconds 10   # ... stopping once 110 are held
    python -m benchmarks.load --clients 30 --server-drawn           # tabs without a runtime (the server draws)
    python -m benchmarks.load --churn 10 --clients 30               # 10 rounds of 30 joining and leaving
    python -m benchmarks.load --flood --clients 20 --seconds 5      # one more sends 10,000 values a second
    python -m benchmarks.load --soak 20                             # a 20-minute lecture (30 clients)

The server runs in this process with its animation loop at ``--fps``; the clients (viser's
websocket protocol, tests/viser_client.py, no browsers) run in another process so they do
not share the server's interpreter. Each client does what a browser's playback runtime does
with the server's messages (:class:`tests.viser_client.RuntimeClient`): it says it is ready,
keeps the timelines' blocks and plays them on its own clock. A frame is a new picture the tab
shows, counted at the client: a timeline frame whose time has come and whose block has arrived
(at most one per 60 Hz refresh), or a still frame the server sent. Every client is a tab playing
Fig. 3's collision, each in a state of its own (its own restitution and V2, so that every tab
needs its own timeline; ``--same-state``: all in the figure's, the favourable case), measured once
every tab plays. The final line reports: clients, the minimum (and median) frames per second per
client, errors (client disconnects plus server-side errors), the server's CPU share (of one core)
and resident memory (the timeline recorder's process included), the received bytes per second
per client, and how long after the first press every tab was playing.

``--follow``: the app gives the built-in lesson with ``--follow``; the first tab, opened at the
lecturer's lead address, leads, and the
others follow its step (its first step autoplays). Over the window: every tab's frames per second,
the server's CPU and memory (the timeline recorder's process counted in both, and its memory also
on its own); then the leader presses Next step, and the line reports the time
until each follower shows the new step's first picture (p50, max), and how many did within 30 s.

``--server-drawn``: the clients have no runtime (as before the browser played): the server draws
and sends every tab its frames, and a frame is one that moved the rods.

``--churn``: ``--stay`` clients play throughout while each round ``--clients`` more join (they
choose Fig. 3 and press Play themselves), play ``--round-seconds`` and leave: in turn with a
close frame, by dropping the socket, or after they stopped reading. One line per round: the
server's resident memory once they are gone, sessions left (in its table, and Session objects
alive), threads, the steady clients' fps over the round (joins included), the bytes a newcomer
received until its first picture (the frame carrying the rods), errors. ``--soak MINUTES`` is a
churn of 5 clients a minute among 30. ``--flood [RATE]``: the players' fps while one more client
sends control values at RATE a second (0: a control run), and when the server dropped it.
"""

from __future__ import annotations

import argparse
import contextlib
import gc
import os
import statistics
import subprocess
import sys
import threading
import time
from collections.abc import Callable
from pathlib import Path

from rigidrel_app.live.server import App
from rigidrel_app.live.session import Session
from rigidrel_app.view.state import presets
from tests.viser_client import (
    ROOT,
    SWARM_WARMUP,
    churn_clients,
    client_swarm,
    hall_clients,
    read_line,
    swarm_result,
    tell,
    wait_until,
)

TARGET_FPS = 25.0


def rss_mb(pid: int | str = "self") -> float:
    """Resident memory of a process (this one by default), MB."""
    for line in Path(f"/proc/{pid}/status").read_text().splitlines():
        if line.startswith("VmRSS:"):
            return int(line.split()[1]) / 1024.0
    return float("nan")


def cpu_seconds(pid: int) -> float:
    """User and system CPU time of another process so far (s)."""
    fields = Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")


def run(clients: int, seconds: float, fps: float) -> dict[str, float]:
    """``clients`` tabs playing Fig. 3 for ``seconds`` (after a warm-up) with the server animating at ``fps``.

    Per client: delivered frames per second (minimum, median), a frame being one that moved the
    picture (:attr:`tests.viser_client.Stats.lane_frames`); bytes per second (median);
    for the server: errors, resident-memory growth and CPU per client over the measured window.
    """
    with App(port=0, animation_hz=fps) as app, client_swarm(app.url, clients, seconds) as child:
        wait_until(lambda: len(app.sessions) >= clients or child.poll() is not None, timeout=60.0)
        if len(app.sessions) < clients:
            raise RuntimeError(f"only {len(app.sessions)} of {clients} clients connected")
        for session in list(app.sessions.values()):
            session.asks.change(presets()["Fig. 3: collision, M2 = 2 M1"], refit=True)
            session.asks.toggle_play()
        # memory and CPU over the measured window, with every client connected at both ends
        time.sleep(SWARM_WARMUP - 0.5)
        mem0, cpu0, wall0 = rss_mb(), time.process_time(), time.perf_counter()
        time.sleep(max(0.0, seconds - 1.0))
        mem1, cpu1, wall1 = rss_mb(), time.process_time(), time.perf_counter()  # a second before the window closes
        stats = swarm_result(child, seconds)
        server_errors = app.errors
    fps_each = [s["lane_frames"] / seconds for s in stats]
    return {
        "clients": float(clients),
        "min_fps": min(fps_each),
        "median_fps": statistics.median(fps_each),
        "errors": float(sum(len(s["errors"]) for s in stats) + server_errors),
        "memory_growth_mb": mem1 - mem0,
        "cpu_percent_per_client": 100.0 * (cpu1 - cpu0) / (wall1 - wall0) / clients,
        "kbytes_per_second_per_client": statistics.median(s["bytes"] for s in stats) / seconds / 1e3,
        "seconds": seconds,
    }


def hall(clients: int, seconds: float, fps: float, follow: bool, same: bool = False) -> dict[str, float]:
    """``clients`` tabs with the playback runtime, each playing Fig. 3 or, with ``follow``, following
    the built-in lesson's leader (module docstring)."""
    from rigidrel_app.lessons import lesson_from

    lesson = lesson_from("paper") if follow else None
    with (
        App(port=0, animation_hz=fps, lesson=lesson, follow=follow) as app,
        hall_clients(app.lead_url or app.url, clients, seconds, follow, same) as child,
    ):
        joined = read_line(child, timeout=1200.0)
        wait_until(lambda: len(app.sessions) >= clients, timeout=120.0)
        tell(child, "measure")
        read_line(child, timeout=120.0)  # the window opens
        recorders = app.timelines.recorder_pids
        mem0, cpu0, wall0 = rss_mb(), time.process_time(), time.perf_counter()
        rec0 = sum(cpu_seconds(pid) for pid in recorders)
        measured = read_line(child, timeout=seconds + 120.0)
        mem1, cpu1, wall1 = rss_mb(), time.process_time(), time.perf_counter()
        rec1 = sum(cpu_seconds(pid) for pid in recorders)
        recorder_mb = sum(rss_mb(pid) for pid in recorders)
        tell(child, "step")
        stepped = read_line(child, timeout=120.0)
        server_errors = app.errors
        timelines = app.timelines.recorded
    fps_each = measured["fps"]
    latencies = [x for x in stepped["latencies"] if x is not None]
    return {
        "clients": float(clients),
        "min_fps": min(fps_each),
        "median_fps": statistics.median(fps_each),
        "errors": float(len(measured["errors"]) + server_errors),
        "server_cpu_percent": 100.0 * ((cpu1 - cpu0) + (rec1 - rec0)) / (wall1 - wall0),
        "rss_mb": max(mem0, mem1) + recorder_mb,
        "recorder_rss_mb": recorder_mb,
        "kbytes_per_second_per_client": statistics.median(measured["bytes"]) / (wall1 - wall0) / 1e3,
        "timelines_made": float(timelines),
        "step_p50_s": statistics.median(latencies) if latencies else float("nan"),
        "step_max_s": max(latencies) if latencies else float("nan"),
        "step_reached": float(len(latencies)),
        "playing_after_s": float(joined["playing_after_s"]),
        "followers": float(len(stepped["latencies"])),
        "seconds": seconds,
    }


def hall_line(r: dict[str, float], follow: bool) -> str:
    line = (
        f"{'follow' if follow else 'independent'} clients={r['clients']:.0f} min_fps={r['min_fps']:.1f} "
        f"median_fps={r['median_fps']:.1f} server_cpu_percent={r['server_cpu_percent']:.1f} rss_mb={r['rss_mb']:.0f} "
        f"(recorder {r['recorder_rss_mb']:.0f}) "
        f"kbytes_per_s_per_client={r['kbytes_per_second_per_client']:.1f} timelines_made={r['timelines_made']:.0f} "
        f"errors={r['errors']:.0f} all_playing_after_s={r['playing_after_s']:.1f}"
    )
    if follow:
        line += (
            f" step_p50_s={r['step_p50_s']:.3f} step_max_s={r['step_max_s']:.3f} "
            f"step_reached={r['step_reached']:.0f}/{r['followers']:.0f}"
        )
    return line


def live_sessions() -> int:
    """Session objects still alive anywhere in the process (not only in the server's table)."""
    gc.collect()
    return sum(isinstance(o, Session) for o in gc.get_objects())


def churn(
    rounds: int,
    clients: int,
    stay: int,
    seconds: float,
    fps: float,
    report: bool = True,
    after_round: Callable[[App, dict[str, float]], None] | None = None,
) -> list[dict[str, float]]:
    """``stay`` clients play throughout; each of ``rounds`` rounds, ``clients`` more join (choose
    Fig. 3, press Play), play ``seconds`` and leave, politely, abruptly or stalled in turn. After each
    round, once the server has let them go: its resident memory, the sessions left (in its table
    and alive in memory), its threads, the steady clients' fps over the round, the bytes each
    newcomer received until its first picture, and errors. One line per round if ``report``;
    ``after_round(app, row)`` is called after each (to look inside the server)."""
    rows: list[dict[str, float]] = []
    with App(port=0, animation_hz=fps) as app, churn_clients(app.url, clients, stay, seconds) as child:
        read_line(child, timeout=120.0)
        wait_until(lambda: len(app.sessions) == stay, timeout=60.0)
        start_mb = rss_mb()
        for k in range(1, rounds + 1):
            tell(child, "round")
            r = read_line(child, timeout=seconds + 300.0)
            settled = time.monotonic()
            with contextlib.suppress(AssertionError):  # reported below as sessions left
                wait_until(lambda: len(app.sessions) == stay and len(app.server.get_clients()) == stay, timeout=30.0)
            pictures = r["first_picture_bytes"] or [float("nan")]
            row = {
                "round": float(k),
                "rss_mb": rss_mb(),
                "start_rss_mb": start_mb,
                "sessions_left": float(len(app.sessions) - stay),
                "viser_clients_left": float(len(app.server.get_clients()) - stay),
                "session_objects_left": float(live_sessions() - stay),
                "threads": float(threading.active_count()),
                "joined": float(r["joined"]),
                "steady_min_fps": min(r["steady_fps"], default=float("nan")),
                "steady_median_fps": statistics.median(r["steady_fps"]) if r["steady_fps"] else float("nan"),
                "first_picture_kb_median": statistics.median(pictures) / 1e3,
                "first_picture_kb_max": max(pictures) / 1e3,
                "errors": float(len(r["errors"]) + app.errors),
                "settle_s": time.monotonic() - settled,
                "round_s": r["seconds"],
            }
            rows.append(row)
            if after_round is not None:
                after_round(app, row)
            if report:
                print(churn_line(row), flush=True)
        tell(child, "done")
    return rows


def churn_line(r: dict[str, float]) -> str:
    return (
        f"round={r['round']:.0f} rss_mb={r['rss_mb']:.0f} sessions_left={r['sessions_left']:.0f} "
        f"session_objects_left={r['session_objects_left']:.0f} threads={r['threads']:.0f} "
        f"joined={r['joined']:.0f} steady_min_fps={r['steady_min_fps']:.1f} "
        f"first_picture_kb={r['first_picture_kb_median']:.0f} errors={r['errors']:.0f}"
    )


def flood(clients: int, seconds: float, fps: float, rate: float = 10_000.0) -> dict[str, float]:
    """``clients`` tabs play Fig. 3 while one more sends control values at ``rate`` per second for
    ``seconds``: the players' fps over that window (minimum, median) and over its first second
    (minimum), whether and when the server dropped the flooding client, and errors."""
    with App(port=0, animation_hz=fps) as app:
        code = f"from tests.viser_client import flood_main; flood_main({app.url!r}, {clients}, {seconds}, {rate})"
        child = subprocess.Popen([sys.executable, "-c", code], cwd=ROOT, stdout=subprocess.PIPE, text=True)
        try:
            r = read_line(child, timeout=seconds + 300.0)
        finally:
            if child.poll() is None:
                child.kill()
            child.communicate(timeout=30)
        floods, server_errors = app.floods, app.errors
    return {
        "clients": float(clients),
        "rate": rate,
        "min_fps": min(r["fps"]),
        "median_fps": statistics.median(r["fps"]),
        "min_fps_first_second": min(r["fps_first_second"]),
        "sent": float(r["sent"]),
        "dropped_after_s": float("nan") if r["hung_up_after"] is None else r["hung_up_after"],
        "floods": float(floods),
        "errors": float(len(r["errors"]) + server_errors),
        "seconds": seconds,
    }


def flood_line(r: dict[str, float]) -> str:
    return (
        f"flood rate={r['rate']:.0f} clients={r['clients']:.0f} "
        f"min_fps={r['min_fps']:.1f} median_fps={r['median_fps']:.1f} "
        f"min_fps_first_second={r['min_fps_first_second']:.0f} flood_sent={r['sent']:.0f} "
        f"dropped_after_s={r['dropped_after_s']:.3f} floods={r['floods']:.0f} errors={r['errors']:.0f}"
    )


#: The long lecture: this many tabs play throughout, and every minute this many more of them leave
#: (politely, abruptly or stalled) and come back.
SOAK_STAY, SOAK_RECONNECTING = 25, 5


def soak_summary(rows: list[dict[str, float]]) -> str:
    """Memory from the end of minute 2 (the room warmed up) to the end, fps held, errors."""
    settled = rows[1:] if len(rows) > 1 else rows
    base = settled[0]["rss_mb"]
    return (
        f"soak minutes={len(rows)} clients={SOAK_STAY + SOAK_RECONNECTING} reconnecting_per_minute={SOAK_RECONNECTING} "
        f"rss_after_minute_2_mb={base:.0f} rss_max_mb={max(r['rss_mb'] for r in settled):.0f} "
        f"rss_end_mb={rows[-1]['rss_mb']:.0f} growth_from_minute_2_mb={max(r['rss_mb'] for r in settled) - base:.0f} "
        f"steady_min_fps={min(r['steady_min_fps'] for r in rows):.1f} "
        f"steady_median_fps={statistics.median(r['steady_median_fps'] for r in rows):.1f} "
        f"max_sessions_left={max(r['sessions_left'] for r in rows):.0f} errors={rows[-1]['errors']:.0f}"
    )


def churn_summary(rows: list[dict[str, float]]) -> str:
    first, last = rows[0], rows[-1]
    return (
        f"churn rounds={len(rows)} start_rss_mb={first['start_rss_mb']:.0f} after_round_1_mb={first['rss_mb']:.0f} "
        f"after_last_mb={last['rss_mb']:.0f} growth_after_round_1_mb={last['rss_mb'] - first['rss_mb']:.0f} "
        f"max_sessions_left={max(r['sessions_left'] for r in rows):.0f} "
        f"max_session_objects_left={max(r['session_objects_left'] for r in rows):.0f} "
        f"steady_min_fps={min(r['steady_min_fps'] for r in rows):.1f} "
        f"first_picture_kb_median={statistics.median(r['first_picture_kb_median'] for r in rows):.0f} "
        f"errors={last['errors']:.0f}"
    )


def line(r: dict[str, float]) -> str:
    return (
        f"clients={r['clients']:.0f} min_fps={r['min_fps']:.1f} median_fps={r['median_fps']:.1f} "
        f"errors={r['errors']:.0f} memory_growth_mb={r['memory_growth_mb']:.1f} seconds={r['seconds']:.0f}"
    )


def main() -> None:
    parser = argparse.ArgumentParser(description="rigidrel load benchmark (lightweight websocket clients)")
    parser.add_argument("--clients", type=int, default=30)
    parser.add_argument("--seconds", type=float, default=60.0)
    parser.add_argument("--fps", type=float, default=30.0, help="the server's animation rate")
    parser.add_argument("--find-max", action="store_true", help="raise the clients until one gets < 25 fps")
    parser.add_argument(
        "--up-to", type=int, default=None, metavar="N", help="find-max: stop once N clients held (a lower bound)"
    )
    parser.add_argument("--churn", type=int, metavar="ROUNDS", help="rounds of --clients that join, play and leave")
    parser.add_argument("--stay", type=int, default=5, help="churn: clients playing throughout")
    parser.add_argument("--round-seconds", type=float, default=5.0, help="churn: how long each round's clients play")
    parser.add_argument(
        "--flood",
        type=float,
        nargs="?",
        const=10_000.0,
        metavar="RATE",
        help="one more client sends RATE values per second (default 10,000; 0: sends none)",
    )
    parser.add_argument("--follow", action="store_true", help="the tabs follow a lesson's leader")
    parser.add_argument("--server-drawn", action="store_true", help="tabs without a runtime: the server draws")
    parser.add_argument("--same-state", action="store_true", help="independent tabs all in Fig. 3's own state")
    lecture = f"a long lecture: {SOAK_STAY + SOAK_RECONNECTING} clients, {SOAK_RECONNECTING} reconnecting every minute"
    parser.add_argument("--soak", type=int, metavar="MINUTES", help=lecture)
    args = parser.parse_args()
    if args.soak:
        # each minute: the newcomers join (a few seconds), play, leave, and the server is measured
        rows = churn(args.soak, SOAK_RECONNECTING, SOAK_STAY, 52.0, args.fps)
        print(soak_summary(rows), flush=True)
        return
    if args.flood is not None:
        print(flood_line(flood(args.clients, min(args.seconds, 5.0), args.fps, args.flood)), flush=True)
        return
    if args.churn:
        rows = churn(args.churn, args.clients, args.stay, args.round_seconds, args.fps)
        print(churn_summary(rows), flush=True)
        return
    if args.follow:
        print(hall_line(hall(args.clients, args.seconds, args.fps, True), True), flush=True)
        return

    def measure(n: int) -> dict[str, float]:
        if args.server_drawn:
            return run(n, args.seconds, args.fps)
        return hall(n, args.seconds, args.fps, False, args.same_state)

    def report(r: dict[str, float]) -> str:
        return line(r) if args.server_drawn else hall_line(r, False)

    if not args.find_max:
        print(report(measure(args.clients)), flush=True)
        return
    best = 0
    n = 10
    while True:
        r = measure(n)
        print(report(r), file=sys.stderr, flush=True)
        if r["min_fps"] < TARGET_FPS or r["errors"] > 0:
            break
        best = n
        if args.up_to is not None and n >= args.up_to:
            break
        n += 5 if args.server_drawn else 25
    stopped = f", stopped at --up-to {args.up_to}" if args.up_to is not None and best >= args.up_to else ""
    print(
        f"max_clients_at_{TARGET_FPS:.0f}_fps={best} (fps={args.fps:g}, seconds={args.seconds:g}{stopped})", flush=True
    )


if __name__ == "__main__":
    main()
