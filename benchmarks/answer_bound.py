"""How short could a slider's answer be with the diagrams drawn somewhere else? The best case of
such a design, measured before building it.

    python -m benchmarks.answer_bound [--free frame,length] [--rounds 2]

The answer of :func:`benchmarks.bench_app.bench_answer` (a client's slider value in, the last frame
of the answer out, on the server's socket; the tab with the playback runtime), in rounds that
alternate: as the app makes it, and with the diagrams named in ``--free`` taken ready-made (their
drawing with the labels placed, and their still picture), as a worker process on the other core
would hand them over at no cost: no pickling, no waiting, no second process in the caches. The
ready-made diagrams are the app's own, made by a first round; a last round makes them again and
counts any that differ (none should). A bound: a worker could only do worse, so if the bound misses
a target, the design does.

The diagrams: ``lab`` (the lab's Minkowski diagram), ``frame`` (the chosen frame's), ``length``
(the equal-time lengths). A worker beside the server takes two of them at best (the server keeps
the rest of the page, its layout, lanes and legend, and one diagram); all three free is the answer
without any diagram work, the floor of every design that draws them elsewhere, the browser included.
"""

from __future__ import annotations

import argparse
import hashlib
import statistics
from dataclasses import dataclass
from typing import Any, Literal, cast, get_args

from benchmarks import bench_app
from benchmarks.page_hashes import digest
from rigidrel_app.live import painting
from rigidrel_app.view import canvas, scene_view

Diagram = Literal["lab", "frame", "length"]


class ReadyMade:
    """The app's diagrams (drawings and still pictures) kept from a recording round, handed back in
    later rounds for those named ``free``."""

    def __init__(self) -> None:
        self.mode: Literal["off", "record", "free", "check"] = "off"
        self.free: set[Diagram] = set()
        self.page: tuple[Any, ...] | None = None
        self.kept: dict[tuple[Any, ...], Any] = {}
        self._diagram_of: dict[int, tuple[Any, Diagram]] = {}
        """The page's diagrams by the identity of their drawing (held here), for their pictures."""
        self.missed = 0
        self.checked = 0
        self.differing = 0
        self._lay_out = painting.lay_out
        self._minkowski = scene_view.minkowski_static
        self._length = scene_view.length_static
        self._chart_picture = canvas.chart_picture

    def install(self) -> None:
        painting.lay_out = self.lay_out  # type: ignore[assignment]
        scene_view.minkowski_static = self.minkowski_static  # type: ignore[assignment]
        scene_view.length_static = self.length_static  # type: ignore[assignment]
        canvas.chart_picture = self.chart_picture  # type: ignore[assignment]

    def uninstall(self) -> None:
        painting.lay_out = self._lay_out
        scene_view.minkowski_static = self._minkowski
        scene_view.length_static = self._length
        canvas.chart_picture = self._chart_picture

    def lay_out(self, resolved: Any, settings: Any, width: float, height: float, theme: Any, *rest: Any) -> Any:
        self.page = (settings, width, height, theme, *rest[:1])
        self._diagram_of.clear()
        return self._lay_out(resolved, settings, width, height, theme, *rest)

    def _made(self, diagram: Diagram, key: tuple[Any, ...], make: Any) -> Any:
        key = (self.page, diagram, *key)
        if self.mode == "record":
            self.kept[key] = made = make()
            return made
        if self.mode == "free" and diagram in self.free:
            if key in self.kept:
                return self.kept[key]
            self.missed += 1
        made = make()
        if self.mode == "check" and key in self.kept:  # what a free round hands back is what is made
            self.checked += 1
            self.differing += _digest(made) != _digest(self.kept[key])
        return made

    def _drawing(self, diagram: Diagram, key: tuple[Any, ...], make: Any) -> Any:
        chart = self._made(diagram, key, make)
        self._diagram_of[id(chart)] = (chart, diagram)
        return chart

    def minkowski_static(self, scene: Any, view: Any, *args: Any) -> Any:
        diagram: Diagram = "lab" if view.prime == "" else "frame"  # the lab's axes are unprimed
        return self._drawing(diagram, (args[-4], args[-1]), lambda: self._minkowski(scene, view, *args))

    def length_static(self, *args: Any) -> Any:
        return self._drawing("length", (args[4], args[-1]), lambda: self._length(*args))

    def chart_picture(self, chart: Any, place: Any, theme: Any) -> Any:
        found = self._diagram_of.get(id(chart))
        if found is None:  # a drawing changed after it was made (a light cone added): made here
            self.missed += 1
            return self._chart_picture(chart, place, theme)
        return self._made(found[1], ("picture", place), lambda: self._chart_picture(chart, place, theme))


def _digest(value: Any) -> str:
    h = hashlib.sha1()
    digest(value, h)
    return h.hexdigest()


@dataclass(frozen=True)
class Bound:
    """What :func:`answer_bound` measured."""

    rounds: dict[str, list[float]]
    """The answer's median and p90 (ms) in each round, as made (``off``) and with diagrams free."""
    missed: int
    """Diagrams made in a round that should have found them ready-made (0 when all went well)."""
    checked: int
    differing: int
    """Of the diagrams made again in the last round, how many differ from the ready-made ones (0)."""


def answer_bound(free: set[Diagram], rounds: int = 2) -> Bound:
    """The flushed answer with the runtime, median and p90 in ms, as made and with ``free`` ready-made,
    alternated ``rounds`` times after a recording round; then a round that makes every diagram again
    and counts those that differ from the ready-made ones."""
    ready = ReadyMade()
    ready.install()
    out: dict[str, list[float]] = {}
    try:
        ready.mode = "record"
        bench_app.bench_answer(runtime=True)
        ready.free = free
        modes: tuple[Literal["off"], Literal["free"]] = ("off", "free")
        for _ in range(rounds):
            for mode in modes:
                ready.mode = mode
                r = bench_app.bench_answer(runtime=True)
                for stat in ("median", "p90"):
                    out.setdefault(f"answer_ms_{stat}[{mode}]", []).append(r[f"answer_ms_{stat}[flushed, runtime]"])
        ready.mode = "check"
        bench_app.bench_answer(runtime=True)
    finally:
        ready.uninstall()
    return Bound(out, ready.missed, ready.checked, ready.differing)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--free", default="frame,length", help="diagrams taken ready-made: lab, frame, length")
    parser.add_argument("--rounds", type=int, default=2)
    args = parser.parse_args()
    free = {d.strip() for d in args.free.split(",") if d.strip()}
    if not free or not free <= set(get_args(Diagram)):
        parser.error(f"--free takes one or more of lab, frame and length, got {args.free!r}")
    bound = answer_bound(cast("set[Diagram]", free), args.rounds)
    for k, v in bound.rounds.items():
        print(f"{k:30s} {statistics.median(v):8.2f}   each round: {', '.join(f'{x:.2f}' for x in v)}")
    print(f"ready-made missed {bound.missed}, checked {bound.checked}, differing {bound.differing}")


if __name__ == "__main__":
    main()
