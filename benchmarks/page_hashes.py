"""Every page a slider's answer draws, hashed: proof that a speed-up changed no picture.

    python -m benchmarks.page_hashes save /tmp/pages.txt     # before the change
    python -m benchmarks.page_hashes check /tmp/pages.txt    # after it: "differing 0"
    python -m benchmarks.page_hashes save --more /tmp/pages.txt  # and check --more: 3 more canvases

One hash per value of :func:`benchmarks.bench_app.answer_values` (every linear slider of every
scene, six values each): the page :func:`~rigidrel_app.view.page.lay_out` makes on the benchmark's
960 x 720 canvas (its still picture, layout, legend rows and title lines) and the lanes and moving
parts at the window's start and middle (:func:`~rigidrel_app.view.page.frame_pictures`), every
array by its dtype and bytes; with ``--more``, also on :data:`MORE_CANVASES` (presenter mode, a
wide screen, a phone), where labels crowd otherwise (save and check alike). A script, not a test:
a change that means to change a picture changes hashes.
"""

from __future__ import annotations

import argparse
import dataclasses
import hashlib
from pathlib import Path
from typing import Any

import numpy as np

from benchmarks.bench_app import answer_values
from rigidrel_app.view.layout import NORMAL, PRESENTER, Theme
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


#: The benchmark's canvas (:func:`benchmarks.bench_app.bench_answer`'s light tab).
ANSWER_CANVAS = (960.0, 720.0, NORMAL)
#: With ``--more``: presenter mode on a projector, a wide screen and a phone, where the labels are
#: placed at other sizes and crowd otherwise.
MORE_CANVASES = ((1280.0, 720.0, PRESENTER), (1920.0, 1080.0, NORMAL), (390.0, 760.0, NORMAL))


def page_hashes(canvases: tuple[tuple[float, float, Theme], ...] = (ANSWER_CANVAS,)) -> list[str]:
    out = []
    for v in answer_values():
        r = resolve(v.settings)
        assert isinstance(r, Resolved)
        for width, height, theme in canvases:
            page = lay_out(r, v.settings, width, height, theme)
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
    parser.add_argument("--more", action="store_true", help="also on the canvases of MORE_CANVASES")
    args = parser.parse_args()
    hashes = page_hashes((ANSWER_CANVAS, *MORE_CANVASES) if args.more else (ANSWER_CANVAS,))
    if args.action == "save":
        args.path.write_text("\n".join(hashes) + "\n")
        print(f"pages {len(hashes)} saved to {args.path}")
        return
    old = args.path.read_text().split()
    differing = [k for k, (a, b) in enumerate(zip(old, hashes, strict=True)) if a != b]
    print(f"pages {len(hashes)} differing {len(differing)} {differing[:20]}")


if __name__ == "__main__":
    main()
