"""The classes on the engine's side of the joint seam fill `joints.seam`'s protocols: mypy
checks this module (pyproject.toml's [tool.mypy] files), so a change to either side that
breaks the seam is a type error, not a failure at run time. Nothing here runs."""
from __future__ import annotations

from kinematika.algebra.arrays import Arrays
from kinematika.algebra.backend import Numeric, Symbolic
from kinematika.draw.context import Context
from kinematika.draw.scene import JointView
from kinematika.engine.instant import Instant
from kinematika.engine.levels import AccelerationLevel, VelocityLevel
from kinematika.engine.motion import BodyState, Motion
from kinematika.engine.terms import Terms
from kinematika.joints import seam
from kinematika.joints.base import ModelJoint
from kinematika.model.builder import Mechanism
from kinematika.model.model import Joint
from kinematika.sweep.poses import Poses, SpatialPoses


def backends(n: Numeric, s: Symbolic, a: Arrays) -> list[seam.Backend]:
    """The arithmetics an instant or a compiled sweep brings."""
    return [n, s, a]


def engine(inst: Instant, v: VelocityLevel, acc: AccelerationLevel, m: Motion, b: BodyState,
           t: Terms) -> tuple[seam.Instant, seam.Level, seam.Level, seam.Motion, seam.BodyState, seam.Terms]:
    """The instant, the two levels and the solved motion."""
    return inst, v, acc, m, b, t


def model(j: Joint, mech: Mechanism) -> tuple[ModelJoint, seam.Mechanism]:
    """The model's joint and the Python builder."""
    return j, mech


def sweeps(p: Poses, s: SpatialPoses) -> list[seam.Pose]:
    """The poses of planar and spatial sweeps."""
    return [p, s]


def figures(view: JointView, ctx: Context) -> tuple[seam.JointView, seam.DrawContext]:
    """A joint on the page and the figure it is drawn in."""
    return view, ctx
