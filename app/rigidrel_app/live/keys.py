"""The keyboard, and a presentation clicker (it sends PageUp and PageDown): which key does what.

A plain table, registered per tab with viser's command palette (``add_command``), so each
key also appears there (Ctrl+K) with what it does. viser ignores these keys while a box, menu
or checkbox has the focus, so typing a value never plays, steps or resets anything; ← and →
on a focused slider handle move only that slider (``controls.ARROWS_STAY_IN_SLIDERS``).

A tab giving a lesson (``rigidrel serve --lesson``) has its own table, :data:`LESSON_HOTKEYS`:
PageDown and → go to the next step, PageUp and ← to the previous one, C hides or shows the
caption and L makes the lecturer's tab (opened at the lead address) the one ``--follow`` tabs follow.
"""

from __future__ import annotations

import enum
from dataclasses import dataclass
from typing import Literal

#: The keys used here, as viser names them (a subset of its ``HotkeyKey``).
Key = Literal["space", "arrowleft", "arrowright", "pageup", "pagedown", "R", "F", "T", "C", "L", "N", "P", "D", "Z"]


class Action(enum.Enum):
    """What a key asks of a tab (:meth:`rigidrel_app.live.session.Session.perform`)."""

    TOGGLE_PLAY = "toggle play"
    STEP_BACK = "step back"
    STEP_FORWARD = "step forward"
    PREVIOUS_EVENT = "previous event"
    NEXT_EVENT = "next event"
    DESCRIBE = "describe"
    PREVIOUS_FIGURE = "previous figure"
    NEXT_FIGURE = "next figure"
    RESET_VIEW = "reset view"
    TOGGLE_PRESENTER = "presenter mode"
    TOGGLE_THEME = "dark theme"
    TOGGLE_ZOOM = "zoom"
    PREVIOUS_STEP = "previous step"
    NEXT_STEP = "next step"
    TOGGLE_CAPTION = "caption"
    LEAD = "lead"


@dataclass(frozen=True)
class Hotkey:
    key: Key
    action: Action
    label: str
    """The command palette's entry."""
    shown: str
    """The key as the README and the panel's key line write it."""
    brief: str
    """What it does in a word or two, for the key line (neighbours that share it are listed together)."""


HOTKEYS: tuple[Hotkey, ...] = (
    Hotkey("space", Action.TOGGLE_PLAY, "Play / pause", "Space", "play"),
    Hotkey("arrowleft", Action.STEP_BACK, "One frame back", "←", "step"),
    Hotkey("arrowright", Action.STEP_FORWARD, "One frame forward", "→", "step"),
    Hotkey("P", Action.PREVIOUS_EVENT, "The previous named event (its time in the lab or the frame)", "P", "event"),
    Hotkey("N", Action.NEXT_EVENT, "The next named event (its time in the lab or the frame)", "N", "event"),
    Hotkey("pageup", Action.PREVIOUS_FIGURE, "Previous paper figure of this scene", "PgUp", "figure"),
    Hotkey("pagedown", Action.NEXT_FIGURE, "Next paper figure of this scene", "PgDn", "figure"),
    Hotkey("R", Action.RESET_VIEW, "Reset view", "R", "reset"),
    Hotkey("F", Action.TOGGLE_PRESENTER, "Presenter mode (panel hidden, larger text) on / off", "F", "presenter"),
    Hotkey("T", Action.TOGGLE_THEME, "Dark projector theme (light on black) on / off", "T", "theme"),
    Hotkey("D", Action.DESCRIBE, "Describe the canvas in words (read by a screen reader)", "D", "describe"),
    Hotkey("Z", Action.TOGGLE_ZOOM, "Zoom: one diagram over the whole canvas / the lanes and every chart", "Z", "zoom"),
)

#: A lesson's keys: the clicker and the arrows move between steps (no frame stepping, no figures).
_SHARED = {h.action: h for h in HOTKEYS}
LESSON_HOTKEYS: tuple[Hotkey, ...] = (
    _SHARED[Action.TOGGLE_PLAY],
    Hotkey("arrowleft", Action.PREVIOUS_STEP, "Previous step of the lesson", "←", "step"),
    Hotkey("arrowright", Action.NEXT_STEP, "Next step of the lesson", "→", "step"),
    Hotkey("pageup", Action.PREVIOUS_STEP, "Previous step of the lesson (clicker)", "PgUp", "step"),
    Hotkey("pagedown", Action.NEXT_STEP, "Next step of the lesson (clicker)", "PgDn", "step"),
    _SHARED[Action.PREVIOUS_EVENT],
    _SHARED[Action.NEXT_EVENT],
    _SHARED[Action.RESET_VIEW],
    _SHARED[Action.TOGGLE_PRESENTER],
    _SHARED[Action.TOGGLE_THEME],
    _SHARED[Action.DESCRIBE],
    _SHARED[Action.TOGGLE_ZOOM],
    Hotkey("C", Action.TOGGLE_CAPTION, "Caption over the lanes hidden / shown", "C", "caption"),
    Hotkey(
        "L",
        Action.LEAD,
        "Lead: with --follow, every other tab follows this tab's step (the lecturer's tab only)",
        "L",
        "lead",
    ),
)

#: Keys kept free for what is planned but not built: no hotkey here may take them.
RESERVED: dict[str, str] = {}


def action_for(key: str, table: tuple[Hotkey, ...] = HOTKEYS) -> Action | None:
    """The action of a key (viser's name for it), or ``None`` for a key that does nothing."""
    return next((h.action for h in table if h.key == key), None)


def key_line(table: tuple[Hotkey, ...] = HOTKEYS) -> str:
    """One line for the control panel: ``Keys: Space play · ← → step · ...``."""
    groups: list[tuple[list[str], str]] = []
    for h in table:
        if groups and groups[-1][1] == h.brief:
            groups[-1][0].append(h.shown)
        else:
            groups.append(([h.shown], h.brief))
    return "Keys: " + " · ".join(f"{' '.join(keys)} {brief}" for keys, brief in groups)
