"""The vocabularies scenes are described in: what happens at the origin, what their objects that are
not rods are and how every front end draws them."""

from __future__ import annotations

from dataclasses import dataclass
from enum import StrEnum
from typing import ClassVar


class OriginEvent(StrEnum):
    """What happens at the shared origin (t, x) = (0, 0) of every frame."""

    START = "start"
    """The rod starts accelerating there (its back end)."""
    KICK = "kick"
    """The impulse: the back end jumps to its new velocity."""
    CONTACT = "contact"
    """Two bodies touch: the rod and the wall, or the two rods."""
    REST = "rest"
    """The rod's left end comes to rest there (in the lab): the leading end of a rod that moves in
    toward -x and brakes, the trailing end of one that moves toward +x."""
    VERTEX = "vertex"
    """A general velocity change: the origin is where the rod's left end would be at rest if its
    hyperbola were continued; nothing need happen there."""

    @property
    def phrase(self) -> str:
        """How a sentence names the event: "the contact", "the left end's stop", ..."""
        return _PHRASES[self]


_PHRASES = {
    OriginEvent.START: "the start",
    OriginEvent.KICK: "the kick",
    OriginEvent.CONTACT: "the contact",
    OriginEvent.REST: "the left end's stop",
    OriginEvent.VERTEX: "the vertex",
}


class ObjectRole(StrEnum):
    """How every front end draws a scene object that is not a rod (a closed vocabulary: a new object
    of a known role needs no new drawing code)."""

    BARRIER = "barrier"
    """A body the rods meet (a wall, a piston): a solid bar at its face, its worldline heavy."""
    MARKER = "marker"
    """A body nothing meets (a barn's door): a thin bar at its face, its worldline dashed."""
    TIE = "tie"
    """A thread between two material points of rods (Bell's string): a thin bar between them, coloured
    by its field; its ends' worldlines are the rods', so a diagram draws nothing more."""


@dataclass(frozen=True)
class ObjectKind:
    """What a scene object is: its name and the :class:`ObjectRole` it is drawn in.

    An open vocabulary: a scene module (or a scene registered at run time) may name a kind of its
    own, ``ObjectKind("piston", ObjectRole.BARRIER)``; the catalogue's are class attributes."""

    name: str
    role: ObjectRole

    WALL: ClassVar[ObjectKind]
    """A wall at rest that stops what hits it (a wall collision's, the barn's back wall)."""
    BARN_DOOR: ClassVar[ObjectKind]
    """A barn's front door at rest: open until its closing event, closed after; nothing hits it."""
    STRING: ClassVar[ObjectKind]
    """A string joining two rods (Bell's ships), stretched by their motion, breaking at its strain."""


ObjectKind.WALL = ObjectKind("wall", ObjectRole.BARRIER)
ObjectKind.BARN_DOOR = ObjectKind("barn door", ObjectRole.MARKER)
ObjectKind.STRING = ObjectKind("string", ObjectRole.TIE)
