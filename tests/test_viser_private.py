"""Every use of viser's private API is in ``rigidrel_app/backends/_viser.py``, and it refuses a viser
its internals were not written against."""

from __future__ import annotations

import re
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from rigidrel_app.backends import _viser

APP = Path(__file__).resolve().parents[1] / "app" / "rigidrel_app"
#: What reaching into viser looks like in Python: its private modules, a handle's or a server's
#: private attributes.
PRIVATE = re.compile(
    r"from viser\._|import viser\._|from viser import _|viser\.infra|\._impl\b|\._websock|_queue_scene_message"
    r"|_live_connections|\._make\(|_image_encoding|_messages\."
)


def test_no_module_but_one_reaches_into_viser() -> None:
    offenders = [
        f"{path.relative_to(APP)}:{n}: {line.strip()}"
        for path in sorted(APP.rglob("*.py"))
        if path.name != "_viser.py"
        for n, line in enumerate(path.read_text().splitlines(), 1)
        if PRIVATE.search(line)
    ]
    assert offenders == []


def test_the_scan_finds_a_private_access() -> None:
    assert PRIVATE.search("uuid = box._impl.uuid") and PRIVATE.search("from viser import _messages")
    assert not PRIVATE.search("import viser") and not PRIVATE.search("handle_uuid(box)")


@pytest.mark.parametrize("version", ["1.1.1", "1.1.9"])
def test_the_pinned_viser_is_taken(version: str) -> None:
    _viser.check_version(version)


@pytest.mark.parametrize("version", ["1.2.0", "1.0.3", "2.0"])
def test_another_viser_is_refused_naming_the_pin(version: str) -> None:
    with pytest.raises(RuntimeError, match=rf"viser 1\.1\.x .* viser {re.escape(version)} is installed"):
        _viser.check_version(version)


@pytest.mark.parametrize(
    "value",
    ["T₁", "", True, False, 0, -3, 2.5, float("-0.0"), None, np.float32(0.25), np.int64(7), np.bool_(True), (1.0, 2)],
)
def test_a_piece_of_node_state_is_written_as_viser_writes_it(value: object) -> None:
    """The playback payloads write plain values without viser's serializer: the same wire value,
    of the same type (numpy scalars and tuples still go through it)."""
    ours, theirs = _viser.wire_value(value, []), _viser.infra._messages._prepare_for_serialization(value, Any, [])  # pyright: ignore[reportPrivateUsage]
    assert ours == theirs and type(ours) is type(theirs)


def test_an_array_in_node_state_goes_to_the_buffers_as_viser_puts_it() -> None:
    ours: list[memoryview] = []
    theirs: list[memoryview] = []
    a = np.arange(6, dtype=np.float32).reshape(2, 3)
    assert _viser.wire_value(a, ours) == _viser.infra._messages._prepare_for_serialization(a, Any, theirs)  # pyright: ignore[reportPrivateUsage]
    assert [bytes(b) for b in ours] == [bytes(b) for b in theirs] == [a.tobytes()]
