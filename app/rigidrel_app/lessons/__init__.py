"""Lessons: a lecture as a file of steps (TOML), checked whole, with captions filled in by the core.

``load_lesson(path)`` reads a file; ``builtin_lesson("paper")`` is the walk through Franklin's
paper that ships with rigidrel. The live app, the offline export and the notebook helpers all
take the same :class:`Lesson`.
"""

from __future__ import annotations

from importlib import resources

from .lesson import FIXED_CONTROLS, Lesson, LessonError, Step, load_lesson, parse_lesson

#: The lessons that ship with rigidrel, by the name ``--lesson`` accepts.
BUILTIN = ("paper",)

__all__ = ["BUILTIN", "FIXED_CONTROLS", "Lesson", "LessonError", "Step", "builtin_lesson", "lesson_from", "load_lesson"]


def builtin_lesson(name: str) -> Lesson:
    """A lesson that ships with rigidrel (see :data:`BUILTIN`)."""
    if name not in BUILTIN:
        raise LessonError(name, 1, f"no built-in lesson of that name; the built-in lessons are {', '.join(BUILTIN)}")
    text = resources.files(__name__).joinpath(f"{name}.toml").read_text(encoding="utf-8")
    return parse_lesson(text, f"built-in lesson {name!r}")


def lesson_from(name_or_path: str) -> Lesson:
    """``--lesson`` takes a built-in name or a file path."""
    return builtin_lesson(name_or_path) if name_or_path in BUILTIN else load_lesson(name_or_path)
