"""The drawing vocabulary shared by the 3-D lanes, the diagrams, the exports and the figures.

Pure data: sampled coordinates plus a :class:`Style`. Builders (:mod:`.diagrams`,
:mod:`.lanes`) produce these; backends (:mod:`rigidrel_app.backends.plotly`,
:mod:`~rigidrel_app.backends.viser`, :mod:`~rigidrel_app.backends.raster`) only translate
them. Nothing here knows any physics.
"""

from __future__ import annotations

import html
import re
from dataclasses import dataclass
from typing import Literal, get_args

import numpy as np
import numpy.typing as npt

FloatArray = npt.NDArray[np.float64]
Dash = Literal["solid", "dash", "dot", "dashdot"]
Shade = Literal["light", "dark"]
"""The canvas' ground: light (dark ink on white, for a desk) or dark (light ink on black, the projector
theme for a hall)."""
SHADES: tuple[Shade, ...] = get_args(Shade)
"""Every :data:`Shade`, light first (what a theme option allows)."""
Anchor = Literal["left", "right", "center"]

# palette: told apart under protanopia, deuteranopia and tritanopia (CIELAB ΔE ≥ 10 after Machado et
# al.'s simulation), lines at 3:1 and text at 4.5:1 or more on white and, lightness-flipped, on black
# (tests/test_palette.py): Okabe-Ito's blue, orange and green for the rods, Tol's wine for the
# frames, a deep gold for light (a brighter gold and purple were lost beside orange and blue)
ROD_COLORS = ("#0072B2", "#E8710A", "#009E73")  # a third rod: Okabe-Ito green
FRAME_COLOR = "#AA3377"
LIGHT_COLOR = "#7A6A00"
INK = "#222222"
# the colours of the scenes' objects that are not rods: the style table, :mod:`.objects`


def rgb(color: str) -> tuple[int, int, int]:
    """``"#RRGGBB"`` -> ``(r, g, b)``."""
    c = color.lstrip("#")
    return int(c[0:2], 16), int(c[2:4], 16), int(c[4:6], 16)


def lightness_flipped(colors: npt.ArrayLike) -> npt.NDArray[np.uint8]:
    """The dark theme's colour of each light-theme sRGB colour ``(..., 3)``: the same hue and HSL
    saturation at HSL lightness ``1 - L``, which is ``c + 255 - max(c) - min(c)`` per channel (exact in
    integers). White and black swap, the ink ``#222222`` becomes ``#DDDDDD``, the rods' blue
    ``#0072B2`` becomes ``#4DBFFF``; a colour mixed toward white (a faint fill) comes out mixed toward
    black, so the dark page keeps every contrast of the light one."""
    c = np.asarray(colors, dtype=np.int16)
    shift = 255 - c.max(axis=-1, keepdims=True) - c.min(axis=-1, keepdims=True)
    return (c + shift).astype(np.uint8)


def shaded(color: str, shade: Shade) -> str:
    """``color`` (``"#RRGGBB"``) as drawn on a ``shade`` ground (:func:`lightness_flipped` on dark)."""
    if shade == "light":
        return color
    r, g, b = (int(v) for v in lightness_flipped(rgb(color)))
    return f"#{r:02X}{g:02X}{b:02X}"


def rgba(color: str, alpha: float) -> str:
    r, g, b = rgb(color)
    return f"rgba({r},{g},{b},{alpha:g})"


@dataclass(frozen=True)
class Style:
    color: str = INK
    width: float = 2.0
    dash: Dash = "solid"
    opacity: float = 1.0
    name: str | None = None
    """Legend entry; ``None`` keeps the item out of the legend."""
    group: str | None = None
    """Items of one group toggle together in the legend."""


@dataclass(frozen=True)
class Polyline:
    """A curve through ``(x[i], y[i])``."""

    x: FloatArray
    y: FloatArray
    style: Style = Style()


@dataclass(frozen=True)
class Segments:
    """Separate straight segments ``(x0, y0) -> (x1, y1)``; arrays of shape ``(n,)``."""

    x0: FloatArray
    y0: FloatArray
    x1: FloatArray
    y1: FloatArray
    style: Style = Style()


@dataclass(frozen=True)
class Area:
    """A filled polygon (closed automatically)."""

    x: FloatArray
    y: FloatArray
    style: Style = Style()


@dataclass(frozen=True)
class Points:
    x: FloatArray
    y: FloatArray
    style: Style = Style()
    size: float = 8.0
    symbol: str = "circle"
    """A plotly marker symbol name: ``"circle"`` marks events, ``"diamond-open"`` the rods' ends now."""


@dataclass(frozen=True)
class Label:
    x: float
    y: float
    text: str
    """May use ``<sub>``/``<b>`` (plotly) and is rendered as plain text in 3-D."""
    style: Style = Style()
    anchor: Anchor = "left"
    size: float = 13.0
    movable: bool = False
    """Whether :func:`rigidrel_app.view.placement.place_labels` may move the text off ``(x, y)``
    (event labels); a fixed label stays where it is and the movable ones avoid it."""
    offset_px: tuple[float, float] | None = None
    """Where placement put the text: its centre this many CSS pixels (right, up) from ``(x, y)``,
    with ``anchor`` ``"center"``. ``None``: not placed, the text starts about 6 px beside
    ``(x, y)`` on the ``anchor`` side (the old behaviour)."""
    leader: bool = False
    """Draw a thin line from ``(x, y)`` to the text: placement found no free spot next to the point."""


Item = Polyline | Segments | Area | Points | Label


@dataclass(frozen=True)
class Chart:
    """A 2-D chart: items, axis titles and ranges."""

    items: tuple[Item, ...]
    x_title: str
    y_title: str
    x_range: tuple[float, float]
    y_range: tuple[float, float]
    title: str = ""
    equal_aspect: bool = False
    """Minkowski diagrams: one unit of x as long as one unit of t (light at 45 degrees)."""
    area_px: tuple[float, float] | None = None
    """The plot area (width, height, CSS pixels) the labels were placed for; ``None``: not placed."""


def event_label(name: str) -> str:
    """The paper's notation: ``T_1'`` -> ``T′<sub>1</sub>`` (the prime as the lesson writes it),
    ``-T_F`` -> ``−T<sub>F</sub>``."""
    sign = "−" if name.startswith("-") else ""
    core = name.lstrip("-")
    prime = "′" if core.endswith("'") else ""
    core = core.rstrip("'")
    if "_" in core:
        head, sub = core.split("_", 1)
        return f"<b>{sign}{head}{prime}<sub>{sub}</sub></b>"
    return f"<b>{sign}{core}{prime}</b>"


#: An event's name as the paper's source writes it in running text: ``T_B``, ``T_1'``, ``T′_1``,
#: ``-T_F`` (not inside a word, nor a caption field's ``[T_1]``).
_NAME_IN_TEXT = re.compile(r"(?<![\w'′\[])([−-]?)T(′?)_([A-Za-z0-9]+)(')?(?![\w\]])")


def names_html(text: str) -> str:
    """Running text (HTML or Markdown) with every event name written as the canvas draws it:
    ``T_B1`` -> ``T<sub>B1</sub>``, ``T_1'`` and ``T′_1`` -> ``T′<sub>1</sub>``, ``-T_F`` ->
    ``−T<sub>F</sub>`` (:func:`event_label`, not bold). A screen reader says "T B 1"."""

    def name(m: re.Match[str]) -> str:
        sign = "−" if m.group(1) else ""
        prime = "′" if m.group(2) or m.group(4) else ""
        return f"{sign}T{prime}<sub>{m.group(3)}</sub>"

    return _NAME_IN_TEXT.sub(name, text)


_SUBSCRIPTS = str.maketrans("0123456789+-=()aehijklmnoprstuvx", "₀₁₂₃₄₅₆₇₈₉₊₋₌₍₎ₐₑₕᵢⱼₖₗₘₙₒₚᵣₛₜᵤᵥₓ")


def unicode_subscript(text: str) -> str | None:
    """``text`` in Unicode subscript characters (``"12"`` -> ``"₁₂"``), or ``None`` if one of its
    characters has none (``"B1"``: the canvas then writes ``_B1``, at full size)."""
    t = text.translate(_SUBSCRIPTS)
    return t if all(ch != o for ch, o in zip(t, text, strict=True)) else None


def plain_text(text: str) -> str:
    """Strip the small HTML subset for text drawn in 3-D."""
    for tag in ("<b>", "</b>", "<sub>", "</sub>"):
        text = text.replace(tag, "")
    return text


_MARKDOWN_PUNCTUATION = re.compile(r"([\\`*_{}\[\]()#+\-.!|~])")


def signed(value: float, decimals: int = 3) -> str:
    """``value`` with its sign to ``decimals`` places; one that rounds to zero is ``+0.000``, never
    ``-0.000`` (a time a hair before an instant, or a negative zero, is shown as that instant)."""
    return f"{round(float(value), decimals) + 0.0:+.{decimals}f}"  # -0.0 + 0.0 is +0.0


def markdown_literal(text: str) -> str:
    """``text`` shown as it is in markdown (viser renders raw HTML in markdown, so a typed ``<b>``
    or ``**`` must not become markup): HTML characters as entities, markdown punctuation escaped."""
    return _MARKDOWN_PUNCTUATION.sub(r"\\\1", html.escape(text, quote=False))


def ramp_color(fraction: float, ramp: tuple[str, ...]) -> str:
    """The colour ``fraction`` (clipped to ``[0, 1]``) of the way along ``ramp``, mixed linearly in sRGB
    between its neighbouring stops and rounded to 1/50 of the ramp (a colour that changes smoothly
    during playback, yet not in every frame)."""
    f = round(min(max(float(fraction), 0.0), 1.0) * 50.0) / 50.0 * (len(ramp) - 1)
    k = min(int(f), len(ramp) - 2)
    w = f - k
    a, b = rgb(ramp[k]), rgb(ramp[k + 1])
    r, g, bl = (round((1.0 - w) * p + w * q) for p, q in zip(a, b, strict=True))
    return f"#{r:02X}{g:02X}{bl:02X}"
