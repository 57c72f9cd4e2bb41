"""PNG and SVG of plotly figures through kaleido and the system Chromium, one browser per export run.

Starting Chromium costs ~3 s; a figure through a running one ~0.3 s. ``ImageWriter``
starts it once and writes every figure of a run through it.
"""

from __future__ import annotations

import os
import shutil
import warnings
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path
from typing import Any

import plotly.io as pio

#: What plotly warns on every figure once kaleido's server runs (it then ignores its own options).
_KOPTS_IGNORED = "The kopts argument is ignored if using a server"


def chromium_path() -> str:
    """The system Chromium kaleido drives (never a downloaded one)."""
    for candidate in (
        os.environ.get("RIGIDREL_CHROMIUM"),
        "/usr/bin/chromium",
        shutil.which("chromium"),
        shutil.which("chromium-browser"),
        shutil.which("google-chrome"),
    ):
        if candidate and Path(candidate).exists():
            return candidate
    raise RuntimeError("PNG/SVG export needs Chromium: on Debian, apt-get install chromium (or set RIGIDREL_CHROMIUM)")


class ImageWriter:
    """Writes plotly figure dicts as PNG or SVG through one running kaleido server."""

    def write(self, figure: dict[str, Any], path: Path, width: int, height: int, scale: float = 1.0) -> Path:
        fmt = path.suffix.lstrip(".")
        if fmt not in ("png", "svg"):
            raise ValueError(f"image format must be png or svg; got {fmt!r}")
        with warnings.catch_warnings():
            warnings.filterwarnings("ignore", message=_KOPTS_IGNORED)
            pio.write_image(figure, str(path), format=fmt, width=width, height=height, scale=scale)
        return path

    def png(self, figure: dict[str, Any], width: int, height: int, scale: float = 1.0) -> bytes:
        """The PNG of ``figure`` in memory (nothing written): what ``rigidrel bench`` times."""
        with warnings.catch_warnings():
            warnings.filterwarnings("ignore", message=_KOPTS_IGNORED)
            return pio.to_image(figure, format="png", width=width, height=height, scale=scale)


def start_kaleido(timeout: float = 90.0) -> None:
    """Start kaleido's one browser (the system Chromium) for the figures that follow (about 3 s)."""
    import kaleido

    kaleido.start_sync_server(path=chromium_path(), mathjax=False, n=1, timeout=timeout, silence_warnings=True)


def stop_kaleido() -> None:
    import kaleido

    kaleido.stop_sync_server(silence_warnings=True)


@contextmanager
def image_writer() -> Iterator[ImageWriter]:
    start_kaleido()
    try:
        yield ImageWriter()
    finally:
        stop_kaleido()
