"""The page's cover: what a tab shows from its first paint until its first page is drawn.

viser's client page shows viser's own panel for a second or two before the app's arrives (its
connection state, the server's ``ws://`` address, its scene tree), and leaves it on screen, dimmed,
when the connection drops. A lecture hall sees none of it: the live server serves viser's page
with a cover in it (:func:`cover_page`, served by :class:`~rigidrel_app.backends._viser.PageServer`),
in the theme the tab opens in, with the app's name and "Loading the scene…". Its markup, style
and script are in the page itself, so it is the first thing painted, and it keeps the rest of the
page hidden until the session says that its first page is drawn (:func:`say_page_drawn`). If the
page cannot reach the server, at first or after a drop, the cover comes back and says so in
plain words. The files are ``assets/cover.html``, ``cover.css``, ``cover.js`` and
``cover-ready.js``. The page also folds viser's panel on a phone held upright (``phone.js``).
"""

from __future__ import annotations

import functools

import viser

from ..backends._viser import page_with, run_javascript
from ..view.vocabulary import INK, ROD_COLORS, Shade, rgba, shaded
from .runtime import page_asset

#: The page's title (viser's is "Viser").
TITLE = "rigidrel"
#: The class the cover keeps on ``<html>`` while it is up (everything else in ``<body>`` hidden).
COVERED = "rigidrel-covered"
#: The ground of the page in each theme: the canvas' (white; the dark theme inverts it to black).
GROUND: dict[Shade, str] = {"light": "#FFFFFF", "dark": "#000000"}


def cover_colors(shade: Shade) -> dict[str, str]:
    """The cover's colours on a ``shade`` page: its ground, its text (the app's ink) and its
    progress bar (the rods' blue, on a track of the same blue, faint), each as that theme draws it."""
    accent = shaded(ROD_COLORS[0], shade)
    return {"ground": GROUND[shade], "ink": shaded(INK, shade), "accent": accent, "track": rgba(accent, 0.25)}


@functools.cache
def cover_page(shade: Shade) -> str:
    """viser's client page with the cover in it, for tabs that open in the ``shade`` theme."""
    style = f"<style>{page_asset('cover.css', **cover_colors(shade))}</style>"
    scripts = "".join(f"<script>{page_asset(name)}</script>" for name in ("cover.js", "phone.js"))
    body = page_asset("cover.html") + scripts
    return page_with(style, body, TITLE, COVERED)


def say_page_drawn(client: viser.ClientHandle) -> None:
    """Tell the tab's cover that its first page is drawn: sent after that page's messages, so the
    cover leaves once the browser has them on screen."""
    run_javascript(client, page_asset("cover-ready.js"))
