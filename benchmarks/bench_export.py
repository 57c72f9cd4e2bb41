"""Speed and size of the exports (a script that prints figures, not a test).

    python -m benchmarks.bench_export [--seconds 10] [--fps 30]

Targets: the 3-D HTML of a 10 s animation at 30 fps is written in <= 10 s and
stays under 3 MB. Also reports the slider page, PNG/SVG (one kaleido start), GIF, MP4.
"""

from __future__ import annotations

import argparse
import tempfile
import time
from pathlib import Path

import rigidrel_core as rr
from rigidrel_app.export.bundle import export_scene


def main() -> None:
    parser = argparse.ArgumentParser(description="rigidrel export speed and size")
    parser.add_argument("--seconds", type=float, default=10.0)
    parser.add_argument("--fps", type=float, default=30.0)
    args = parser.parse_args()
    for scene in (rr.rod_collision(0.6, 0.0, 1.0, 2.0, 1.0, 1.0, 1.0), rr.constant_acceleration(0.6, 1.0, 0.5)):
        frame = rr.default_frame(scene)
        with tempfile.TemporaryDirectory() as tmp:
            t0 = time.perf_counter()
            written = export_scene(scene, frame, Path(tmp), seconds=args.seconds, fps=args.fps)
            total = time.perf_counter() - t0
            print(f"{scene.kind}: {args.seconds:g} s at {args.fps:g} fps, frame {frame.name}")
            for w in written:
                print(f"  {w.path.name:34s} {w.seconds:7.2f} s {w.megabytes:8.2f} MB")
            print(f"  {'all formats':34s} {total:7.2f} s")


if __name__ == "__main__":
    main()
