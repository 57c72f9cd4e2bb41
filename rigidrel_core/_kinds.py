"""The closed vocabularies scenes are described in: what happens at the origin, what obstacles are."""

from __future__ import annotations

from enum import StrEnum


class OriginEvent(StrEnum):
    """What happens at the shared origin (t, x) = (0, 0) of every frame."""

    START = "start"
    """The rod starts accelerating there (its back end)."""
    KICK = "kick"
    """The impulse: the back end jumps to its new velocity."""
    CONTACT = "contact"
    """Two bodies touch: the rod and the wall, or the two rods."""
    REST = "rest"
    """The decelerating rod's back end comes to rest there."""
    VERTEX = "vertex"
    """A general velocity change: the origin is where the rod's left end would be at rest if its
    hyperbola were continued; nothing need happen there."""

    @property
    def phrase(self) -> str:
        """How a sentence names the event: "the contact", "the back end's stop", ..."""
        return _PHRASES[self]


_PHRASES = {
    OriginEvent.START: "the start",
    OriginEvent.KICK: "the kick",
    OriginEvent.CONTACT: "the contact",
    OriginEvent.REST: "the back end's stop",
    OriginEvent.VERTEX: "the vertex",
}


class ObstacleKind(StrEnum):
    """Things in a scene that are not rods: they have inertial worldlines and are drawn, not solved."""

    WALL = "wall"
    """A wall at rest that stops what hits it (the barn's back wall)."""
    BARN_DOOR = "barn door"
    """A barn's front door at rest: open until its closing event, closed after; nothing hits it."""
