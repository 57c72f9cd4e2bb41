"""Every exported diagram page (the scene's own and each page where labels once overprinted) on both
screens, 1280x720 and 1920x1080: no two labels overlap, text and lines sized for a projector.

The suite checks every page at 1280x720 and the scene's own page at 1920x1080. Needs Debian's
chromium. Run from the repository's root::

    python -m tests.sweeps.export_pages
"""

from tests.sweeps import run

if __name__ == "__main__":
    raise SystemExit(run("tests/browser/test_export_browser.py::test_diagram_page_labels_do_not_overprint"))
