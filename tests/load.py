"""Load benchmark: many lightweight clients playing at once (not a test: machines are noisy).

    python -m tests.load --clients 30 --seconds 60 --fps 30
    python -m tests.load --find-max --seconds 20 --fps 30      # the most clients held at 25 fps

The server runs in this process with its animation loop at ``--fps``; the clients (viser's
websocket protocol, tests/viser_client.py, no browsers) run in another process so they do
not share the server's interpreter. Every client is a tab playing Fig. 3's collision. The
final line reports: clients, the minimum (and median) delivered frames per second per client,
errors (client disconnects plus server-side errors), and the growth of the server's resident
memory between the start and the end of the measurement.
"""

from __future__ import annotations

import argparse
import statistics
import sys
import time
from pathlib import Path

from rigidrel_app.live.server import App
from rigidrel_app.view.state import presets
from tests.viser_client import SWARM_WARMUP, client_swarm, swarm_result, wait_until

TARGET_FPS = 25.0


def rss_mb() -> float:
    for line in Path("/proc/self/status").read_text().splitlines():
        if line.startswith("VmRSS:"):
            return int(line.split()[1]) / 1024.0
    return float("nan")


def run(clients: int, seconds: float, fps: float) -> dict[str, float]:
    """``clients`` tabs playing Fig. 3 for ``seconds`` (after a warm-up) with the server animating at ``fps``.

    Per client: delivered rod frames per second (minimum, median), bytes per second (median);
    for the server: errors, resident-memory growth and CPU per client over the measured window.
    """
    with App(port=0, animation_hz=fps) as app, client_swarm(app.url, clients, seconds) as child:
        wait_until(lambda: len(app.sessions) >= clients or child.poll() is not None, timeout=60.0)
        if len(app.sessions) < clients:
            raise RuntimeError(f"only {len(app.sessions)} of {clients} clients connected")
        for session in list(app.sessions.values()):
            session.change(presets()["Fig. 3: collision, M2 = 2 M1"], refit=True)
            session.toggle_play()
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
    args = parser.parse_args()
    if not args.find_max:
        print(line(run(args.clients, args.seconds, args.fps)), flush=True)
        return
    best = 0
    n = 10
    while True:
        r = run(n, args.seconds, args.fps)
        print(line(r), file=sys.stderr, flush=True)
        if r["min_fps"] < TARGET_FPS or r["errors"] > 0:
            break
        best = n
        n += 5
    print(f"max_clients_at_{TARGET_FPS:.0f}_fps={best} (fps={args.fps:g}, seconds={args.seconds:g})", flush=True)


if __name__ == "__main__":
    main()
