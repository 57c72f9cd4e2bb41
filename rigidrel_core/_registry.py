"""The scene registry: every scene's description, by name.

The app's controls, the command line's options, the exports, the benchmarks' scene list
and the tests' strategies are all generated from these descriptions. The catalogue in
:mod:`rigidrel_core.scenes` is registered on first use; :func:`register_scene` adds one
from outside (a notebook, a lesson).
"""

from __future__ import annotations

import threading
from collections.abc import Mapping
from types import MappingProxyType

from ._description import SceneDescription
from ._frame import Frame
from ._scene import Scene
from ._validate import ParameterError
from .scenes import discover

_lock = threading.Lock()
_registry: dict[str, SceneDescription] = {}
_catalogue: frozenset[str] = frozenset()
_ordered: Mapping[str, SceneDescription] | None = None
"""The registry in teaching order, kept until a scene is registered or unregistered."""


def _ensure_loaded() -> dict[str, SceneDescription]:
    global _catalogue
    if not _catalogue:
        with _lock:
            if not _catalogue:
                found = discover()
                for d in found:
                    _registry.setdefault(d.kind, d)
                _catalogue = frozenset(d.kind for d in found)
    return _registry


def scene_descriptions() -> Mapping[str, SceneDescription]:
    """Every registered scene by name, in teaching order."""
    global _ordered
    reg = _ensure_loaded()
    ordered = _ordered
    if ordered is None:
        ordered = MappingProxyType(dict(sorted(reg.items(), key=lambda kv: (kv[1].order, kv[0]))))
        _ordered = ordered
    return ordered


def describe(kind: str | Scene) -> SceneDescription:
    """The description of the scene called ``kind`` (or of a built scene)."""
    name = kind.kind if isinstance(kind, Scene) else kind
    reg = _ensure_loaded()
    try:
        return reg[name]
    except (KeyError, TypeError):
        raise ParameterError("scene", f"one of {', '.join(reg)}", kind) from None


def register_scene(description: SceneDescription) -> SceneDescription:
    """Add a scene to the registry (``ValueError`` if its name is taken by another description)."""
    description = _checked_description(description)
    global _ordered
    reg = _ensure_loaded()
    with _lock:
        if reg.get(description.kind, description) is not description:
            raise ParameterError("description.kind", "a name no other scene has", description.kind)
        reg[description.kind] = description
        _ordered = None
    return description


def _checked_description(value: object) -> SceneDescription:
    """``value`` if it is a :class:`SceneDescription` (callers from notebooks are not type-checked)."""
    if not isinstance(value, SceneDescription):
        raise ParameterError("description", "a SceneDescription", value)
    return value


def unregister_scene(kind: str) -> SceneDescription:
    """Remove a scene that :func:`register_scene` added (the catalogue's own scenes stay)."""
    global _ordered
    reg = _ensure_loaded()
    with _lock:
        if kind in _catalogue:
            raise ParameterError("kind", "a scene added with register_scene, not one of the catalogue's", kind)
        if kind not in reg:
            raise ParameterError("kind", f"one of the registered scenes: {', '.join(reg)}", kind)
        _ordered = None
        return reg.pop(kind)


def build_scene(kind: str, **values: float | None) -> Scene:
    """Build a scene by name; missing parameters take their defaults (the paper's values)."""
    return describe(kind).build(**values)


def default_frame(scene: Scene) -> Frame:
    """The frame a lecturer compares the lab with first: the description's default, or, where that
    one is the lab itself (a rod that ends at rest), the first preset that moves."""
    preferred = scene.frame(describe(scene).default_frame)
    if not preferred.same_velocity(scene.frames["lab"]):
        return preferred
    moving = [f for name, f in scene.frames.items() if name != "lab" and not f.same_velocity(scene.frames["lab"])]
    return moving[0] if moving else preferred
