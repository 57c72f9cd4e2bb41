"""The page a tab gets: viser's client page with the app's cover in it (``live/cover.py``), there
before any of viser's code runs, and served in place of viser's own page."""

from __future__ import annotations

import re
import urllib.request
from typing import Any

import pytest

from rigidrel_app.backends import _viser
from rigidrel_app.backends._viser import PageServer, client_page, page_with
from rigidrel_app.live.cover import COVERED, GROUND, TITLE, cover_colors, cover_page
from rigidrel_app.view.vocabulary import Shade, rgb

#: The inline loader that unpacks viser's bundle: the one script of viser's page.
LOADER = "<script data-p="


def relative_luminance(color: str) -> float:
    def channel(c: int) -> float:
        x = c / 255.0
        return x / 12.92 if x <= 0.04045 else ((x + 0.055) / 1.055) ** 2.4

    r, g, b = (channel(c) for c in rgb(color))
    return 0.2126 * r + 0.7152 * g + 0.0722 * b


def contrast(a: str, b: str) -> float:
    """WCAG 2's contrast ratio of two colours."""
    la, lb = sorted((relative_luminance(a), relative_luminance(b)), reverse=True)
    return (la + 0.05) / (lb + 0.05)


@pytest.mark.parametrize("shade", ["light", "dark"])
def test_the_cover_is_in_the_page_before_anything_of_viser(shade: Shade) -> None:
    page = cover_page(shade)
    head, body = page.split("<body>", 1)
    # the html element is covered from the start (the style hides the rest of the body under it)
    assert re.search(rf'<html lang="en" class="{COVERED}">', head)
    # the cover's style comes before the loader that unpacks and runs viser's bundle
    assert head.index(f"html.{COVERED} body > :not(#rigidrel-cover)") < head.index(LOADER)
    assert f"<title>{TITLE}</title>" in head and "<title>Viser</title>" not in page
    # the cover is the body's first element, and its script runs before viser's root is parsed
    assert body.lstrip().startswith('<div id="rigidrel-cover" role="status" aria-live="polite">')
    assert body.index("Loading the scene…") < body.index("window.rigidrelCover = {") < body.index('<div id="root">')
    assert f"background: {GROUND[shade]};" in head


def test_the_pages_are_viser_s_page_and_the_cover_only() -> None:
    """Nothing of viser's page is lost or changed: taking out what was put in gives it back."""
    viser_page = client_page()
    page = page_with("<style>HEAD</style>", "<p>BODY</p>", "TITLE", "CLASS")
    put_back = (
        page.replace(' class="CLASS"', "", 1)
        .replace("<style>HEAD</style>", "", 1)
        .replace("<p>BODY</p>", "", 1)
        .replace("<title>TITLE</title>", "<title>Viser</title>", 1)
    )
    assert put_back == viser_page
    assert page.count(LOADER) == 1 == viser_page.count(LOADER)


def test_what_goes_in_is_not_searched_for_the_places_it_goes() -> None:
    """A style that names ``<body>`` (in a comment) is not taken for the page's body."""
    page = page_with("<style>/* everything else in <body> */</style>", "<p>BODY</p>", "t", "c")
    assert "<body><p>BODY</p>" in page and "in <body> */" in page


def test_a_viser_page_laid_out_otherwise_is_refused(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(_viser, "client_page", lambda: '<html lang="en"><head><meta charset="utf-8" /></head>')
    with pytest.raises(RuntimeError, match=r"viser's page has no .*title.*_viser\.py is out of date"):
        page_with("", "", "t", "c")


@pytest.mark.parametrize("shade", ["light", "dark"])
def test_the_cover_reads_at_7_to_1_in_both_themes(shade: Shade) -> None:
    colors = cover_colors(shade)
    assert contrast(colors["ink"], colors["ground"]) >= 7.0
    # the bar is decoration (aria-hidden), but it still shows against the ground: 3:1, as a UI part
    assert contrast(colors["accent"], colors["ground"]) >= 3.0


def test_the_cover_speaks_politely_and_its_bar_is_decoration() -> None:
    page = cover_page("light")
    assert '<div class="rr-cover-bar" aria-hidden="true">' in page
    assert "@media (prefers-reduced-motion: reduce)" in page
    assert "rigidrel needs JavaScript" in page  # what a page without scripts says


def served(url: str) -> str:
    with urllib.request.urlopen(url, timeout=30) as response:
        return response.read().decode("utf-8")


@pytest.mark.slow  # a viser server starts
def test_the_page_server_serves_its_page_and_removes_it_when_it_stops() -> None:
    page = page_with("<style>/* ours */</style>", "<p>ours</p>", "ours", "ours")
    server = PageServer(page, host="127.0.0.1", port=0, verbose=False)
    folder = server._page_folder  # pyright: ignore[reportPrivateUsage]
    try:
        url = f"http://127.0.0.1:{server.get_port()}"
        assert served(url) == page
        assert served(url + "/index.html") == page
        assert folder.is_dir()
    finally:
        server.stop()
    assert not folder.exists()


@pytest.mark.slow  # an app server starts
@pytest.mark.parametrize("shade", ["light", "dark"])
def test_the_app_serves_the_cover_in_the_theme_its_tabs_open_in(shade: Shade) -> None:
    from rigidrel_app.live.server import App

    app: Any = App(host="127.0.0.1", port=0, shade=shade)
    try:
        assert served(app.url) == cover_page(shade)
    finally:
        app.stop()
