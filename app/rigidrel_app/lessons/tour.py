"""A lesson given live, as pure values: which step a tab shows, what arriving at it sets, what it locks.

The live app (:mod:`rigidrel_app.live`) only assigns what these functions return; nothing here
draws or talks to a browser.
"""

from __future__ import annotations

import html
import re
from dataclasses import dataclass, replace

from markdown_it import MarkdownIt

from ..view.layers import Layer
from ..view.state import Settings
from ..view.vocabulary import names_html
from .lesson import Lesson, Step

_MARKDOWN = MarkdownIt("commonmark", {"html": False, "typographer": False})
_CODE = re.compile(r"(<code>.*?</code>)", re.DOTALL)


def caption_body_html(markdown: str) -> str:
    """A caption's Markdown as HTML (raw HTML in it escaped), every event name written with its
    subscript as the canvas draws it (:func:`~..view.vocabulary.names_html`), except inside code
    (```T_1'``` as typed on a command line)."""
    parts = _CODE.split(_MARKDOWN.render(markdown))
    return "".join(part if part.startswith("<code>") else names_html(part) for part in parts)


#: The layer toggles' labels, in the panel's order.
LAYER_LABELS: dict[Layer, str] = {
    Layer.WORLD_TUBE: "World tube",
    Layer.INTERIOR_LINES: "Interior worldlines",
    Layer.LIGHT_CONE: "Light cone",
    Layer.SIGNALS: "Light signals",
    Layer.SIMULTANEITY: "Lines of simultaneity",
    Layer.OTHER_AXES: "Other frame's axes",
    Layer.LENGTH_PANEL: "Length panel",
}


@dataclass(frozen=True)
class Arrival:
    """What a tab sets when it arrives at a step."""

    settings: Settings
    """The step's scene, frame and layers."""
    window: tuple[float, float] | None
    """The step's time window (None: the scene's own)."""
    start: float | None
    """The time shown first (None: the playback clock's usual start)."""
    autoplay: bool
    locked: frozenset[str]
    """Controls the step fixes: parameter names and any of ``scene``, ``frame``, ``time``."""


def arrival(step: Step) -> Arrival:
    """The state a step opens on (its layers as the lesson file's reader settled them; a riding
    step's lower lane rides its point)."""
    settings = replace(step.scenario.settings, layers=step.layers)
    return Arrival(settings, step.window, step.start, step.autoplay, step.locked)


def clamp_step(lesson: Lesson, index: int) -> int:
    """A step index (from 0) kept inside the lesson: PageDown on the last step stays there."""
    return min(max(index, 0), len(lesson.steps) - 1)


def step_label(lesson: Lesson, index: int) -> str:
    """The step list's entry: ``3/15 · The equal-time length (Fig. 2)``."""
    return f"{index + 1}/{len(lesson.steps)} · {lesson.steps[index].title}"


def step_labels(lesson: Lesson) -> tuple[str, ...]:
    return tuple(step_label(lesson, k) for k in range(len(lesson.steps)))


def control_names(settings: Settings) -> dict[str, str]:
    """Lockable control -> its name in the panel: the scene's parameters by label, then scene, frame, time."""
    names = {p.name: p.label for p in settings.description.parameters}
    names |= {"scene": "Scene", "frame": "Frame", "time": "t, t'"}
    return names


def locked_changes(locked: frozenset[str], old: Settings, new: Settings) -> tuple[str, ...]:
    """The locked controls that ``new`` would change from ``old`` (empty: ``new`` is allowed)."""
    changed: list[str] = []
    if "scene" in locked and (new.scene != old.scene or new.overlay != old.overlay):
        changed.append("scene")
    if new.scene == old.scene:
        changed += [name for name, value in new.values if name in locked and old.chosen(name) != value]
    if "frame" in locked and (new.frame, new.beta, new.ride) != (old.frame, old.beta, old.ride):
        changed.append("frame")
    return tuple(changed)


def lock_reason(lesson: Lesson, index: int, settings: Settings) -> str:
    """The line under the step list that says what this step fixes and why ("" if nothing)."""
    step = lesson.steps[index]
    if not step.locked:
        return ""
    names = control_names(settings)
    shown = ", ".join(names.get(n, n) for n in sorted(step.locked, key=list(names).index))
    return f"**Locked by step {index + 1}**: {shown} (the lesson shows them this way; another step frees them)."


def lock_notice(lesson: Lesson, index: int, settings: Settings, changed: tuple[str, ...]) -> str:
    """The notice for a refused change of locked controls."""
    names = control_names(settings)
    shown = ", ".join(names.get(n, n) for n in changed)
    return f"{shown} is locked by step {index + 1} of the lesson; nothing changed. Go to another step to change it."


#: Said under a caption while the tab shows another scene than its step's (loaded, or chosen).
OFF_STEP_NOTE = "(This caption is the step's; the app now shows another scene. The step list goes back.)"


def caption_html(step: Step, presenter: bool = False, off_step: bool = False) -> str:
    """The caption band over the lanes: the step's title and its caption (Markdown, numbers from the
    core) as HTML; larger in presenter mode, to be read from the back of a hall. ``off_step``: the
    tab shows another scene than the step's, and the band says so."""
    body = caption_body_html(step.caption + (f"\n\n*{OFF_STEP_NOTE}*" if off_step else ""))
    size = "presenter" if presenter else "normal"
    return f'<div class="rr-caption-{size}"><h2>{html.escape(step.title)}</h2>{body}</div>'
