"""What the controls say, as a frozen value, and the scene and frame it means.

The GUI only ever replaces one field of :class:`Settings` and asks :func:`resolve` for
the scene: invalid combinations come back as a message, never as an exception.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from enum import StrEnum

import rigidrel_core as rr
from rigidrel_core import SceneKind

#: The scenes offered in the dropdown, in teaching order.
SCENE_LABELS: dict[SceneKind, str] = {
    SceneKind.CONSTANT_ACCELERATION: "Constant acceleration",
    SceneKind.DECELERATION: "Deceleration",
    SceneKind.IMPULSIVE_START: "Impulsive start",
    SceneKind.WALL_COLLISION: "Wall crash / bounce",
    SceneKind.ROD_COLLISION: "Rod-rod collision",
}
CUSTOM_FRAME = "custom (β slider)"


class Preset(StrEnum):
    NONE = "—"
    FIG1 = "Fig. 1: acceleration to V = 0.6"
    FIG3 = "Fig. 3: collision, M2 = 2 M1"
    FIG4 = "Fig. 4: collision, M1 = 2 M2"


@dataclass(frozen=True)
class Settings:
    """Slider and dropdown values. Rod 1 has rest length L0 = 1 and mass M1 = 1."""

    scene: SceneKind = SceneKind.CONSTANT_ACCELERATION
    v: float = 0.6
    """V; V1 for a collision (c = 1)."""
    v2: float = 0.0
    log_mass_ratio: float = math.log10(2.0)
    """log10(M2/M1)."""
    eps: float = 1.0
    a_front_length: float = 0.5
    """a'_F L0 of the front end."""
    length_ratio: float = 1.0
    """L2/L1."""
    frame: str = "rod after"
    """A frame preset of the scene ("lab", "rod after", "barycentric", ...) or CUSTOM_FRAME.
    A name the scene lacks falls back to :func:`default_frame`."""
    beta: float = 0.0
    """The custom frame's velocity."""
    overlay_impulsive: bool = False
    """Draw Fig. 1's dashed impulsive curve over a constant acceleration."""


PRESETS: dict[Preset, Settings] = {
    Preset.FIG1: Settings(SceneKind.CONSTANT_ACCELERATION, v=0.6, a_front_length=0.5, overlay_impulsive=True),
    Preset.FIG3: Settings(SceneKind.ROD_COLLISION, v=0.6, v2=0.0, log_mass_ratio=math.log10(2.0), eps=1.0),
    Preset.FIG4: Settings(SceneKind.ROD_COLLISION, v=0.6, v2=0.0, log_mass_ratio=math.log10(0.5), eps=1.0),
}


@dataclass(frozen=True)
class Resolved:
    scene: rr.Scene
    frame: rr.Frame
    overlay: rr.Scene | None


def scene_parameters(s: Settings) -> dict[str, float]:
    """The core's parameters for the scene the settings describe (rod 1: rest length 1, mass 1)."""
    kind = s.scene
    if kind is SceneKind.ROD_COLLISION:
        m2, l2 = 10.0**s.log_mass_ratio, s.length_ratio
        return {"v1": s.v, "v2": s.v2, "m1": 1.0, "m2": m2, "l1": 1.0, "l2": l2, "eps": s.eps}
    if kind in (SceneKind.CONSTANT_ACCELERATION, SceneKind.DECELERATION):
        return {"v": s.v, "length": 1.0, "a_front": s.a_front_length}
    if kind is SceneKind.WALL_COLLISION:
        return {"v": s.v, "length": 1.0, "eps": s.eps}
    if kind is SceneKind.IMPULSIVE_START:
        return {"v": s.v, "length": 1.0}
    raise rr.ParameterError("scene", "one of the scenes in the dropdown", s.scene)


def build_scene(s: Settings) -> rr.Scene:
    """The scene the settings describe (raises ValueError naming the offending parameter)."""
    return rr.build_scene(s.scene, **scene_parameters(s))


def settings_for(scene: rr.Scene, frame: rr.Frame) -> Settings:
    """The inverse of :func:`scene_parameters`: the settings that show ``scene`` in ``frame``,
    in units of rod 1's rest length and mass. Only for the scenes in :data:`SCENE_LABELS`."""
    p = scene.parameters
    kind = scene.kind
    common = {"frame": frame_choice(scene, frame), "beta": frame.beta}
    if kind is SceneKind.ROD_COLLISION:
        return Settings(
            kind,
            v=p["v1"],
            v2=p["v2"],
            log_mass_ratio=math.log10(p["m2"] / p["m1"]),
            eps=p["eps"],
            length_ratio=p["l2"] / p["l1"],
            **common,
        )
    if kind in (SceneKind.CONSTANT_ACCELERATION, SceneKind.DECELERATION):
        return Settings(kind, v=p["v"], a_front_length=p["a_front"] * p["length"], **common)
    if kind is SceneKind.WALL_COLLISION:
        return Settings(kind, v=p["v"], eps=p["eps"], **common)
    if kind is SceneKind.IMPULSIVE_START:
        return Settings(kind, v=p["v"], **common)
    raise rr.ParameterError("scene", "one of the app's scenes (velocity-change has no slider page)", kind.value)


def default_frame(scene: rr.Scene) -> str:
    """The frame a lecturer compares with first: the rod's rest frame after, or the barycentre."""
    return "barycentric" if "barycentric" in scene.frames else "rod after"


def choose_frame(scene: rr.Scene, frame: rr.Frame | str | float | None) -> rr.Frame:
    """The frame a user named: ``None`` for :func:`default_frame`, a :class:`~rigidrel_core.Frame`,
    one of the scene's preset names, or a velocity in (-1, 1) (a number or its text)."""
    if frame is None:
        return scene.frames[default_frame(scene)]
    if isinstance(frame, rr.Frame):
        return frame
    if isinstance(frame, str):
        if frame in scene.frames:
            return scene.frames[frame]
        try:
            frame = float(frame)
        except ValueError:
            presets = ", ".join(repr(k) for k in scene.frames)
            raise rr.ParameterError("frame", f"a velocity in (-1, 1) or one of {presets}", frame) from None
    return rr.Frame.from_velocity(frame)


def frame_choices(scene: rr.Scene) -> tuple[str, ...]:
    return (*scene.frames.keys(), CUSTOM_FRAME)


def frame_choice(scene: rr.Scene, frame: rr.Frame) -> str:
    """The Frame dropdown's entry for ``frame``: its preset name, or the custom (β slider) entry."""
    return frame.name if frame.name in scene.frames else CUSTOM_FRAME


def resolve(s: Settings) -> Resolved | str:
    """The scene and frame, or a one-sentence notice of why they cannot be built."""
    try:
        scene = build_scene(s)
        if s.frame == CUSTOM_FRAME:
            frame = rr.Frame.from_velocity(s.beta, name="custom")
        else:
            frame = scene.frames.get(s.frame) or scene.frames[default_frame(scene)]
        overlay = None
        if s.overlay_impulsive and s.scene is SceneKind.CONSTANT_ACCELERATION:
            overlay = rr.impulsive_start(v=s.v, length=1.0)
    except ValueError as exc:
        return _explain(s, exc)
    return Resolved(scene, frame, overlay)


def _explain(s: Settings, exc: ValueError) -> str:
    name = getattr(exc, "parameter", "")
    if name == "v2":
        return (
            f"V2 = {s.v2:.3g} is not less than V1 = {s.v:.3g}: rod 1 never catches rod 2. "
            "Lower V2 or raise V1; the last valid scene stays on screen."
        )
    return f"{exc}. The last valid scene stays on screen."
