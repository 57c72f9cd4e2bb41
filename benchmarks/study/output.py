"""Files of a bench run: the JSON table, and the charts as HTML and PNG (kaleido + the system Chromium).

The HTML files load plotly.js from its CDN (``include_plotlyjs="cdn"``): each is then a
few hundred kB instead of 4.7 MB. The PNGs are the offline copies, drawn by the same system
Chromium as the exports' (:mod:`rigidrel_app.export.images`); nothing is downloaded.
"""

from __future__ import annotations

import dataclasses
import enum
import json
import math
import numbers
import threading
import time
from pathlib import Path
from typing import Any

import plotly.graph_objects as go

from rigidrel_app.export.images import ImageWriter, start_kaleido, stop_kaleido

#: Deadline for the browser's first figure (it starts in about 3 s on an idle machine).
STARTUP_SECONDS = 90.0


def plain(obj: Any) -> Any:
    """Dataclasses, enums, tuples and numpy scalars as JSON values; non-finite floats as null."""
    if dataclasses.is_dataclass(obj) and not isinstance(obj, type):
        return {f.name: plain(getattr(obj, f.name)) for f in dataclasses.fields(obj)}
    if isinstance(obj, enum.Enum):
        return obj.value
    if isinstance(obj, dict):
        return {str(plain(k)): plain(v) for k, v in obj.items()}
    if isinstance(obj, list | tuple):
        return [plain(v) for v in obj]
    if isinstance(obj, bool) or obj is None or isinstance(obj, str | int):
        return obj
    if isinstance(obj, numbers.Real):
        x = float(obj)
        return x if math.isfinite(x) else None
    raise TypeError(f"cannot write {type(obj).__name__} to JSON")


def write_json(path: Path, data: Any) -> None:
    path.write_text(json.dumps(plain(data), indent=1, allow_nan=False) + "\n")


def write_html(fig: go.Figure, path: Path) -> None:
    fig.write_html(path, include_plotlyjs="cdn", full_html=True, config={"displaylogo": False})


class ChromiumUnavailable(RuntimeError):
    """kaleido could not start or use a Chromium."""


class ChartImages:
    """The run's PNGs through the exports' writer (:class:`rigidrel_app.export.images.ImageWriter`, one kaleido
    server for the whole run), plus what a bench run needs on top: a deadline for the browser's first
    figure, the first failure kept rather than raised (the JSON and HTML are written regardless), and
    render timing. Use as a context manager."""

    def __init__(self) -> None:
        self.error: str | None = None
        self.baseline_seconds: float | None = None
        """Best time to render an empty figure (kaleido's fixed cost per image)."""
        self._writer: ImageWriter | None = None

    def __enter__(self) -> ChartImages:
        try:
            start_kaleido(timeout=120.0)
        except Exception as exc:  # kaleido raises its own error types; any failure means no PNGs
            self.error = _why(exc)
            return self
        self._writer = ImageWriter()
        # Start the browser now (about 3 s) and time an empty figure: kaleido's own cost per image.
        # kaleido's sync server waits forever if its browser died, so the first call gets a deadline.
        first: list[float | None] = []
        worker = threading.Thread(
            target=lambda: first.append(self.render_seconds(go.Figure().to_dict(), 440, 352, repeats=5)), daemon=True
        )
        worker.start()
        worker.join(STARTUP_SECONDS)
        if worker.is_alive():
            self.error = _why(TimeoutError(f"Chromium did not render a figure within {STARTUP_SECONDS:g} s"))
        elif first:
            self.baseline_seconds = first[0]
        return self

    def __exit__(self, *exc: object) -> None:
        # after a failure the browser may hang, and kaleido's stop with it: the process's exit ends it
        if self._writer is not None and self.error is None:
            stop_kaleido()

    def _live(self) -> ImageWriter:
        if self._writer is None or self.error is not None:
            raise ChromiumUnavailable(self.error or "kaleido was not started")
        return self._writer

    def write_png(self, fig: go.Figure, path: Path) -> None:
        """Render ``fig`` at its layout's width and height to ``path``; raises :class:`ChromiumUnavailable`
        with the reason."""
        width, height = fig.layout.width, fig.layout.height
        if width is None or height is None:
            raise ValueError(f"{path.name}: a bench chart must set its layout width and height")
        writer = self._live()
        try:
            writer.write(fig.to_dict(), path, int(width), int(height))
        except Exception as exc:  # ChromeNotFoundError, BrowserFailedError, RuntimeError from plotly
            self.error = _why(exc)
            raise ChromiumUnavailable(self.error) from exc

    def render_seconds(self, fig: dict[str, Any], width: int, height: int, repeats: int) -> float | None:
        """Best wall time for Chromium to draw ``fig`` (plotly.js) into a PNG; None without a browser."""
        try:
            writer = self._live()
        except ChromiumUnavailable:
            return None
        best = float("inf")
        try:
            for _ in range(repeats):
                start = time.perf_counter()
                writer.png(fig, width, height)
                best = min(best, time.perf_counter() - start)
        except Exception as exc:
            self.error = _why(exc)
            return None
        return best


def _why(exc: BaseException) -> str:
    text = str(exc).strip().splitlines()
    first = text[0] if text else type(exc).__name__
    return f"PNG charts need Chromium (nothing is downloaded): {type(exc).__name__}: {first}"
