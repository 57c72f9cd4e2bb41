"""What a view can show, layer by layer: the names lessons, the app's toggles and the exports share."""

from __future__ import annotations

from enum import StrEnum


class Layer(StrEnum):
    """A layer of the drawings that can be shown or hidden as a whole."""

    WORLD_TUBE = "world-tube"
    """The rods' world tubes and their end worldlines in the diagrams."""
    INTERIOR_LINES = "interior-lines"
    """Worldlines of interior material points (f = 1/4, 1/2, 3/4)."""
    LIGHT_CONE = "light-cone"
    """The light cone of the scene's origin event."""
    SIGNALS = "signals"
    """Light from the key event to each far end and back, its future cone, the pulses in the lanes."""
    SIMULTANEITY = "simultaneity"
    """The 'now' lines: each frame's line of simultaneity at the time shown."""
    OTHER_AXES = "other-axes"
    """The other frame's t and x axes drawn in each diagram."""
    LENGTH_PANEL = "length-panel"
    """The equal-time length chart."""


#: What a view shows unless told otherwise (the light signals are asked for).
DEFAULT_LAYERS = frozenset(Layer) - {Layer.SIGNALS}
