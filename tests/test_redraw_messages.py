"""What a slider's redraw sends: each label's changes in one message (what the browser ends up
showing is what the handles say), and no camera message when the camera is already where the
page fits (a reset still sends it)."""

from __future__ import annotations

from collections.abc import Iterator
from typing import Any

import numpy as np
import pytest

from rigidrel_app.backends.viser import _Texts  # pyright: ignore[reportPrivateUsage]
from rigidrel_app.live.keys import Action
from rigidrel_app.live.session import Session
from rigidrel_app.view.canvas import PageText
from tests.viser_client import Recorder, recorded_tab, wait_until


@pytest.fixture
def tab() -> Iterator[tuple[Session, Recorder]]:
    with recorded_tab() as t:
        yield t


def labels_as_sent(messages: list[dict[str, Any]], prefix: str) -> dict[str, dict[str, Any]]:
    """Each label node under ``prefix`` as the browser has it after ``messages``: created, then updated."""
    nodes: dict[str, dict[str, Any]] = {}
    for m in messages:
        name = m.get("name", "")
        if not str(name).startswith(prefix):
            continue
        kind = m["type"]
        if kind == "LabelMessage":
            nodes[name] = {**m["props"], "visible": True}  # its position follows
        elif kind == "SceneNodeUpdateMessage":
            nodes[name].update(m["updates"])
        elif kind == "SetPositionMessage":
            nodes[name]["position"] = tuple(m["position"])
        elif kind == "SetSceneNodeVisibilityMessage":
            nodes[name]["visible"] = m["visible"]
        elif kind == "RemoveSceneNodeMessage":
            del nodes[name]
    return nodes


@pytest.mark.slow  # a served tab
def test_a_label_changes_in_one_message_and_the_browser_and_handle_agree(tab: tuple[Session, Recorder]) -> None:
    session, client = tab
    texts = _Texts(session.client.scene, "/test/text")
    with session.client.atomic():
        texts.set(0, ("T_B", (1.0, -8.0, 2.0), 1.25, "center-left"))
        texts.set(1, ("x′", (3.0, -8.0, 4.0), 1.5, "top-center"))
    session.client.flush()
    wait_until(lambda: len(labels_as_sent(client.messages, "/test/text/")) == 2)
    n = len(client.messages)
    with session.client.atomic():
        texts.set(0, ("T_F", (5.0, -8.0, 6.0), 1.0, "center-right"))  # all four change
        texts.set(1, ("x′", (7.0, -8.0, 8.0), 1.5, "top-center"))  # the position alone
        texts.hide(2)  # never shown: nothing
    session.client.flush()

    def settled() -> dict[str, dict[str, Any]] | None:
        sent = labels_as_sent(client.messages, "/test/text/")
        return sent if sent["/test/text/1"]["position"] == (7.0, -8.0, 8.0) else None

    sent = wait_until(settled)
    new = [m for m in client.messages[n:] if str(m.get("name", "")).startswith("/test/text/")]
    assert sorted(m["type"] for m in new) == ["SceneNodeUpdateMessage", "SetPositionMessage", "SetPositionMessage"]
    update = next(m for m in new if m["type"] == "SceneNodeUpdateMessage")
    assert update["updates"] == {"text": "T_F", "font_screen_scale": 1.0, "anchor": "center-right"}
    first = sent["/test/text/0"]
    assert (first["text"], first["position"], first["font_screen_scale"], first["anchor"]) == (
        "T_F",
        (5.0, -8.0, 6.0),
        1.0,
        "center-right",
    )
    # the handle knows what the browser shows: assigning the shown value again sends nothing,
    # assigning the old one sends it
    handle = texts._handles[0]  # pyright: ignore[reportPrivateUsage]
    assert (handle.text, handle.font_screen_scale, handle.anchor) == ("T_F", 1.0, "center-right")
    np.testing.assert_array_equal(handle.position, (5.0, -8.0, 6.0))
    n = len(client.messages)
    handle.text = "T_F"
    handle.text = "T_B"
    session.client.flush()
    wait_until(lambda: labels_as_sent(client.messages, "/test/text/")["/test/text/0"]["text"] == "T_B")
    assert [m["updates"] for m in client.messages[n:] if m.get("name") == "/test/text/0"] == [{"text": "T_B"}]


def page_texts(*labels: tuple[str, float]) -> list[PageText]:
    return [PageText(x, 0.0, text, 15.0, "center-left") for text, x in labels]


@pytest.mark.slow  # a served tab
def test_a_new_still_picture_moves_its_words_or_makes_them_anew_never_both_changed_in_place(
    tab: tuple[Session, Recorder],
) -> None:
    """A still picture's labels: a word that stays moves to its new place (one position message), a
    place that stays takes its new word, and only a new word at a new place is a new node (viser's
    client moves a label at once and changes its words later: never the old words at a new place)."""
    session, client = tab
    texts = _Texts(session.client.scene, "/test/still", renew=True)

    def shown(*labels: tuple[str, float]) -> tuple[list[str], list[str]]:
        """Show ``labels`` (text, x); the texts of the label nodes made, and the other messages' kinds."""
        n = len(client.messages)
        with session.client.atomic():
            texts.show(page_texts(*labels))
        session.client.flush()
        wanted = sorted((text, x) for text, x in labels)

        def arrived() -> bool:
            nodes = labels_as_sent(client.messages, "/test/still/").values()
            return sorted((v["text"], v["position"][0]) for v in nodes if v["visible"]) == wanted

        wait_until(arrived)
        new = [m for m in client.messages[n:] if str(m.get("name", "")).startswith("/test/still/")]
        made = {m["name"]: m["props"]["text"] for m in new if m["type"] == "LabelMessage"}
        return sorted(made.values()), sorted(m["type"] for m in new if m["name"] not in made)

    shown(("γ = 1.25", 10.0), ("T₁", 20.0), ("x′", 30.0), ("0.5", 40.0))
    # T₁ and 0.5 move, γ's value changes in place, E is a new node; nothing removed
    made, changed = shown(("T₁", 25.0), ("γ = 1.67", 10.0), ("x′", 30.0), ("E", 50.0), ("0.5", 45.0))
    assert made == ["E"] and changed == ["SceneNodeUpdateMessage", "SetPositionMessage", "SetPositionMessage"]
    # a new word at a new place, in the only label left: made anew (the old one removed), not moved
    made, changed = shown(("T₁", 25.0), ("γ = 1.67", 10.0), ("x′", 30.0), ("E", 50.0), ("c", 60.0))
    assert made == ["c"] and changed == ["RemoveSceneNodeMessage"]
    # a label hidden, then shown again with other words elsewhere: a new node too
    assert shown(("T₁", 25.0), ("γ = 1.67", 10.0), ("x′", 30.0), ("E", 50.0)) == ([], ["SetSceneNodeVisibilityMessage"])
    made, changed = shown(("T₁", 25.0), ("γ = 1.67", 10.0), ("x′", 30.0), ("E", 50.0), ("d", 70.0))
    assert made == ["d"] and changed == ["RemoveSceneNodeMessage"]


CAMERA = {
    "SetCameraPositionMessage",
    "SetCameraLookAtMessage",
    "SetCameraUpDirectionMessage",
    "SetCameraFovMessage",
    "SetCameraNearMessage",
    "SetCameraFarMessage",
}


def camera_messages_of(session: Session, client: Recorder, act: Any) -> list[str]:
    """The camera messages the browser gets for ``act()`` (flushed, then a notice as a sentinel)."""
    n = len(client.messages)
    act()
    mark = f"sentinel {n}"
    session.asks.refuse(mark)
    session.client.flush()

    def sentinel() -> int | None:
        for i, m in enumerate(client.messages[n:]):
            if mark in str(m.get("updates", {})):
                return n + i
        return None

    end = wait_until(sentinel)
    return [m["type"] for m in client.messages[n:end] if m["type"] in CAMERA]


@pytest.mark.slow  # a served tab
def test_a_redraw_with_auto_fit_sends_no_camera_when_it_fits_and_a_reset_always_does(
    tab: tuple[Session, Recorder],
) -> None:
    session, client = tab
    camera_messages_of(session, client, lambda: None)  # the tab's opening (its first fit) all arrived
    assert session.controls.fit.value  # "Auto-fit view" is on
    layout = session.painter.layout
    assert layout is not None
    pose = session.painter.renderer.pose(layout)
    camera = session.client.camera
    np.testing.assert_allclose(camera.position, pose.position, atol=1e-9)
    # a slider's redraw: the camera is where the page fits, nothing to send
    assert (
        camera_messages_of(session, client, lambda: session.asks.change(session.state.settings.with_value("v", 0.5)))
        == []
    )
    # key R: the pose is sent whatever the server last heard (the browser may have moved since)
    reset = camera_messages_of(session, client, lambda: session.perform(Action.RESET_VIEW))
    assert "SetCameraPositionMessage" in reset and "SetCameraLookAtMessage" in reset
    # the browser reports an orbit away: the next redraw brings the camera back
    with session.lock:
        camera.position = np.asarray(pose.position) + np.array([50.0, 0.0, 0.0])
    back = camera_messages_of(session, client, lambda: session.asks.change(session.state.settings.with_value("v", 0.7)))
    assert "SetCameraPositionMessage" in back
    np.testing.assert_allclose(camera.position, pose.position, atol=1e-9)
    np.testing.assert_allclose(camera.look_at, pose.look_at, atol=1e-9)
