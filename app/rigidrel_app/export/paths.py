"""Where a command writes: the ``--out`` folder, checked once, and the one-line usage error."""

from __future__ import annotations

import os
import sys
from pathlib import Path
from typing import NoReturn

#: Exit status of a usage error (a bad argument): one line on stderr.
EXIT_USAGE = 2


def fail(prog: str, message: str) -> NoReturn:
    """One line on stderr (the first line of ``message``) and exit status 2."""
    sys.stderr.write(f"{prog}: error: {message.splitlines()[0] if message else 'failed'}\n")
    raise SystemExit(EXIT_USAGE)


def out_dir(prog: str, text: str) -> Path:
    """The folder ``--out`` names (``~`` expanded), created if missing; a one-line error and exit
    status 2 for an empty name or a folder that cannot be created or written to."""
    if not text.strip():
        fail(prog, "--out: an empty folder name")
    out = Path(text).expanduser()
    try:
        out.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        fail(prog, f"--out {text!r} cannot be created: {exc.strerror or exc}")
    if not os.access(out, os.W_OK | os.X_OK):
        fail(prog, f"--out {text!r} is not a writable folder")
    return out
