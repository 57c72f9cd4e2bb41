"""rigidrel_core: exact, Lorentz-covariant worldlines of Born-rigid rods (Franklin 2012).

Units c = 1. A frame of velocity ``beta`` has ``x' = gamma (x - beta t)``,
``t' = gamma (t - beta x)``, sharing the lab's origin. Pure numpy (each scene's one-off
scalar solution is double-double arithmetic on Python floats); it never imports the app,
viser or plotly.

    import rigidrel_core as rr
    scene = rr.build_scene("rod-collision", mass2=2.0)          # Fig. 3, case I
    frame = scene.frame("barycentric")
    x = scene.positions([0.0, 0.5], frame=frame)              # ends of both rods in that frame
    events_frame = frame @ [[t, x] for t, x in scene.events.values()]
"""

from ._budget import FourMomentumBudget as FourMomentumBudget
from ._budget import PhysicalSystem as PhysicalSystem
from ._budget import SystemBudget as SystemBudget
from ._description import EventDescription as EventDescription
from ._description import Interval as Interval
from ._description import Overlay as Overlay
from ._description import Parameter as Parameter
from ._description import PresetFigure as PresetFigure
from ._description import SceneDescription as SceneDescription
from ._description import ScenePreset as ScenePreset
from ._description import Slider as Slider
from ._exact import ExactVelocity as ExactVelocity
from ._frame import LAB as LAB
from ._frame import Frame as Frame
from ._kinds import ObjectKind as ObjectKind
from ._kinds import ObjectRole as ObjectRole
from ._kinds import OriginEvent as OriginEvent
from ._motion import RigidMotion as RigidMotion
from ._objects import InertialWorldline as InertialWorldline
from ._objects import MaterialWorldline as MaterialWorldline
from ._objects import ObjectEvent as ObjectEvent
from ._objects import ObjectField as ObjectField
from ._objects import SceneObject as SceneObject
from ._plastic import PlasticMotion as PlasticMotion
from ._registry import build_scene as build_scene
from ._registry import default_frame as default_frame
from ._registry import describe as describe
from ._registry import register_scene as register_scene
from ._registry import scene_descriptions as scene_descriptions
from ._registry import unregister_scene as unregister_scene
from ._scene import ENDS as ENDS
from ._scene import EventSpec as EventSpec
from ._scene import Rod as Rod
from ._scene import Scene as Scene
from ._signals import CausalRelation as CausalRelation
from ._signals import ChangeVerdict as ChangeVerdict
from ._signals import causal_relation as causal_relation
from ._validate import ParameterError as ParameterError
from ._words import event_in_words as event_in_words
from ._words import event_shown as event_shown
from ._words import frame_in_words as frame_in_words
from ._words import shown as shown
from .scenes.acceleration import constant_acceleration as constant_acceleration
from .scenes.acceleration import deceleration as deceleration
from .scenes.acceleration import velocity_change as velocity_change
from .scenes.bell import BellScene as BellScene
from .scenes.bell import bell_spaceships as bell_spaceships
from .scenes.collision import CollisionSolution as CollisionSolution
from .scenes.collision import rod_collision as rod_collision
from .scenes.collision import solve_collision as solve_collision
from .scenes.impulse import impulsive_start as impulsive_start
from .scenes.pole_barn import DoorOrder as DoorOrder
from .scenes.pole_barn import DoorOutcome as DoorOutcome
from .scenes.pole_barn import PoleBarnScene as PoleBarnScene
from .scenes.pole_barn import PoleVerdict as PoleVerdict
from .scenes.pole_barn import pole_barn as pole_barn
from .scenes.wall import wall_collision as wall_collision

__all__ = [
    "ENDS",
    "LAB",
    "BellScene",
    "CausalRelation",
    "ChangeVerdict",
    "CollisionSolution",
    "DoorOrder",
    "DoorOutcome",
    "EventDescription",
    "EventSpec",
    "ExactVelocity",
    "FourMomentumBudget",
    "Frame",
    "InertialWorldline",
    "Interval",
    "MaterialWorldline",
    "ObjectEvent",
    "ObjectField",
    "ObjectKind",
    "ObjectRole",
    "OriginEvent",
    "Overlay",
    "Parameter",
    "ParameterError",
    "PhysicalSystem",
    "PlasticMotion",
    "PoleBarnScene",
    "PoleVerdict",
    "PresetFigure",
    "RigidMotion",
    "Rod",
    "Scene",
    "SceneDescription",
    "SceneObject",
    "ScenePreset",
    "Slider",
    "SystemBudget",
    "bell_spaceships",
    "build_scene",
    "causal_relation",
    "constant_acceleration",
    "deceleration",
    "default_frame",
    "describe",
    "event_in_words",
    "event_shown",
    "frame_in_words",
    "impulsive_start",
    "pole_barn",
    "register_scene",
    "rod_collision",
    "scene_descriptions",
    "shown",
    "solve_collision",
    "unregister_scene",
    "velocity_change",
    "wall_collision",
]
