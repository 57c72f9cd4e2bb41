"""Every page a slider's answer draws, hashed: proof that a speed-up changed no picture.

    python -m benchmarks.page_hashes save /tmp/pages.txt     # before the change
    python -m benchmarks.page_hashes check /tmp/pages.txt    # after it: "differing 0"

One hash per value of :func:`benchmarks.bench_app.answer_values` (every linear slider of every
scene, six values each): the page :func:`~rigidrel_app.view.page.lay_out` makes on the benchmark's
960 x 720 canvas (its still picture, layout, legend rows and title lines) and the lanes and moving
parts at the window's start and middle (:func:`~rigidrel_app.view.page.frame_pictures`), every
array by its dtype and bytes. A script, not a test: a change that means to change a picture
changes hashes.
"""

from __future__ import annotations

import argparse
import dataclasses
import hashlib
from pathlib import Path
from typing import Any

import numpy as np

from benchmarks.bench_app import answer_values
from rigidrel_app.view.layout import NORMAL
from rigidrel_app.view.page import frame_pictures, lay_out
from rigidrel_app.view.state import Resolved, resolve


def digest(value: Any, h: Any) -> None:
    """Feed ``value`` to ``h``: arrays by dtype and bytes, sequences, mappings and dataclasses by
    their parts in order, anything else by its ``repr``."""
    if isinstance(value, np.ndarray):
        h.update(str(value.dtype).encode())
        h.update(np.ascontiguousarray(value).tobytes())
    elif isinstance(value, list | tuple):
        h.update(b"[")
        for v in value:
            digest(v, h)
        h.update(b"]")
    elif dataclasses.is_dataclass(value) and not isinstance(value, type):
        h.update(type(value).__name__.encode())
        for f in dataclasses.fields(value):
            digest(getattr(value, f.name), h)
    elif isinstance(value, dict):
        for k in sorted(value, key=repr):
            digest(k, h)
            digest(value[k], h)
    else:
        h.update(repr(value).encode())


def page_hashes() -> list[str]:
    out = []
    for v in answer_values():
        r = resolve(v.settings)
        assert isinstance(r, Resolved)
        page = lay_out(r, v.settings, 960.0, 720.0, NORMAL)
        t0, t1 = page.drawn.window
        h = hashlib.sha1()
        for part in (page.still, page.layout, (page.legend_rows, page.title_lines)):
            digest(part, h)
        digest(frame_pictures(page.drawn, page.layout, page.chart_frames, np.array([t0, 0.5 * (t0 + t1)])), h)
        out.append(h.hexdigest())
    return out


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("action", choices=("save", "check"))
    parser.add_argument("path", type=Path)
    args = parser.parse_args()
    hashes = page_hashes()
    if args.action == "save":
        args.path.write_text("\n".join(hashes) + "\n")
        print(f"pages {len(hashes)} saved to {args.path}")
        return
    old = args.path.read_text().split()
    differing = [k for k, (a, b) in enumerate(zip(old, hashes, strict=True)) if a != b]
    print(f"pages {len(hashes)} differing {len(differing)} {differing[:20]}")


if __name__ == "__main__":
    main()
