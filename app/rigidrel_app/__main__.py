"""``python -m rigidrel_app``: start the app server (same as ``rigidrel serve``)."""

from __future__ import annotations

import sys

from rigidrel_app.cli import main

if __name__ == "__main__":
    raise SystemExit(main(["serve", *sys.argv[1:]]))
