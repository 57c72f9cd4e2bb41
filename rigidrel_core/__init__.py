"""rigidrel_core: exact, Lorentz-covariant worldlines of Born-rigid rods (Franklin 2012).

Units c = 1. A frame of velocity ``beta`` has ``x' = gamma (x - beta t)``,
``t' = gamma (t - beta x)``, sharing the lab's origin. Pure numpy (plus the standard
library's ``decimal`` for the one-off scalar solution of each scene); it never imports
the app, viser or plotly.
"""

from ._boost import Boost as Boost
from ._boost import Frame as Frame
from ._budget import FourMomentumBudget as FourMomentumBudget
from ._exact import ExactVelocity as ExactVelocity
from ._exact import relative_rapidity as relative_rapidity
from ._motion import RigidMotion as RigidMotion
from ._registry import SCENE_PARAMETERS as SCENE_PARAMETERS
from ._registry import ParameterSpec as ParameterSpec
from ._registry import build_scene as build_scene
from ._registry import scene_kind as scene_kind
from ._scenes import CollisionSolution as CollisionSolution
from ._scenes import Rod as Rod
from ._scenes import Scene as Scene
from ._scenes import SceneKind as SceneKind
from ._scenes import constant_acceleration as constant_acceleration
from ._scenes import deceleration as deceleration
from ._scenes import impulsive_start as impulsive_start
from ._scenes import rod_collision as rod_collision
from ._scenes import solve_collision as solve_collision
from ._scenes import velocity_change as velocity_change
from ._scenes import wall_collision as wall_collision
from ._validate import ParameterError as ParameterError

__all__ = [
    "SCENE_PARAMETERS",
    "Boost",
    "CollisionSolution",
    "ExactVelocity",
    "FourMomentumBudget",
    "Frame",
    "ParameterError",
    "ParameterSpec",
    "RigidMotion",
    "Rod",
    "Scene",
    "SceneKind",
    "build_scene",
    "constant_acceleration",
    "deceleration",
    "impulsive_start",
    "relative_rapidity",
    "rod_collision",
    "scene_kind",
    "solve_collision",
    "velocity_change",
    "wall_collision",
]
