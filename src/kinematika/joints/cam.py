"""A cam and its follower (planar `cam`): the first body carries a cam (its `cam:` shape: a
motion program or measured profile, base circle and follower, `kinematika.cams`); the
second is the follower, touching it with its point `at` (a knife edge on the profile, a
roller's centre on the pitch curve) or its `line` (a flat face on the profile).

Condition: the follower keeps touching the cam, one scalar condition — a higher pair
(`touching`: velocity (v_Jb − v_Ja)·n = 0 along the common normal, acceleration with the
curvature terms of the equivalent link). Over a cycle it reproduces the program: a
translating follower's s(θ), v = s'·θ̇, a = s''·θ̇² + s'·θ̈. The relative instant centre
of cam and follower lies on the common normal at the contact (for a roller, through its
centre); the pressure angle is that normal's angle from the follower's direction of motion.

Example: a disc cam (base circle 40) with a translating knife-edge follower, rising 20 by
simple harmonic motion over β = 90°, caught halfway (θ = 45°) while turning at ω = 3 rad/s.
By hand, s = (h/2)(1 − cos πθ/β) = 10, so the edge F is at 40 + 10 = 50, and
v = ω ds/dθ = ω (πh/2β) sin(πθ/β) = 3 × 20π/π × 1 = 60:

    >>> import numpy as np, kinematika
    >>> sol = kinematika.solve('''
    ... points: {O: [0, 0], F: [0, 50]}
    ... bodies:
    ...   ground: [O]
    ...   cam:
    ...     points: [O]
    ...     cam: {center: O, angle: deg(45), base: 40, rotation: ccw,
    ...           follower: {motion: translating, contact: knife},
    ...           program: [{law: harmonic, over: 90, to: 20}, {law: harmonic, over: 90, to: 0},
    ...                     {law: dwell, over: 180}]}
    ...   follower: [F]
    ... joints:
    ...   - {type: revolute, bodies: [ground, cam], at: O}
    ...   - {type: prismatic, bodies: [ground, follower], along: [0, 1]}
    ...   - {type: cam, bodies: [cam, follower], at: F}
    ... drivers: [{omega: cam, value: 3}]
    ... ''')
    >>> np.allclose(sol.velocity("F"), (0, 60))
    True
"""
from __future__ import annotations

from typing import TYPE_CHECKING


import numpy as np

from ..errors import KinematikaError
from ..shapes import Cam as CamShape
from ..shapes import Line
from .base import JointGeometry, ModelJoint
from .contact import Contact
from .touching import outlines

if TYPE_CHECKING:
    from . import symbols
    from .seam import DrawContext, Instant, JointView


class Cam(Contact):
    """A cam and its follower: a contact whose first outline is the cam (its profile, or
    its pitch curve for a roller) and whose second is the follower's point or face."""

    name = "cam"
    summary = "the first body's cam drives the second, its follower (knife edge or roller at `at`, or flat face)"
    condition = "the follower's (v_Jb − v_Ja)·n = 0 on the cam"
    keeps = "row-cam-touching"

    def conditions(self, dim: int) -> int:
        """One: the follower keeps touching the cam (a higher pair, planar only)."""
        return 1

    def outlines(self, inst: Instant, joint: ModelJoint, geo: JointGeometry) -> tuple[list, list]:
        """The cam's profile and the follower's flat face (its `line`), or the point `at` and
        the profile (a knife edge) or the pitch curve (a roller's centre; `geo.roller` its
        radius). A cam joint whose first body has no `cam:` shape, a flat face without a line
        or an edge without `at` is a schema error naming the joint."""
        cams = [s for s in inst.shapes[joint.a] if isinstance(s, CamShape)]
        if not cams:
            raise KinematikaError("schema", "cam-joint-first-body", joint.where, body=joint.a)
        cam = cams[0]
        contact = cam.design.follower.contact
        if contact.touches_with_face:
            faces = [s for s in inst.shapes[joint.b] if isinstance(s, Line)]
            if not faces:
                raise KinematikaError("schema", "cam-joint-face", joint.where, body=joint.b)
            return [cam.profile], faces
        if joint.at is None:
            raise KinematikaError("schema", "cam-joint-at", joint.where, roller=str(contact.radius > 0).lower())
        geo.roller = float(contact.radius)
        curve = cam.pitch if contact.radius > 0 else cam.profile
        return [curve], outlines(inst, joint, joint.b, joint.at)

    def symbol(self, view: JointView, ctx: DrawContext) -> list[symbols.Mark]:
        """The follower's roller (a circle about its centre `at`, moving with it) or knife
        edge (a pin), and the contact point."""
        from . import symbols     # drawing only (start-up)

        out = symbols.contact_dot(view, ctx)
        if view.at is None:
            return out
        if view.radius > 0:
            roller = symbols.ring(np.asarray(view.at, dtype=float), view.radius)
            return [symbols.Mark("polygon", roller, f"body:{view.b}", "white", 1.8, zorder=5,
                                 gid=f"joint:{view.id}", moves_with=view.b), *symbols.pin(view, ctx, body=view.b), *out]
        return [*symbols.pin(view, ctx, body=view.b), *out]


KIND = Cam()
