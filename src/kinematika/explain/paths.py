"""Paths known from the structure: a point at a fixed distance from a fixed point moves on
a circle about it, so the curvature of its path is read off the mechanism, not off a = aᵗ + aⁿ
(C5-1.7: "trajectòria circular de radi 3r" for the wheel's centre C; the same for a point of
a body pinned to the frame). Writing ℜ_C = v_C² / (v_C² / OC) after the step that used
a_Cⁿ = v_C² / OC would derive one result twice, and circularly."""

from __future__ import annotations

from typing import Optional

from ..model.model import PointRef
from .context import Ctx
from .kinds import by_centre_path, pins, rolls


def circle_about(ctx: Ctx, ref: PointRef) -> Optional[str]:
    """The fixed point O the structure keeps `ref` at a fixed distance from, or None: the
    centre of a wheel rolling on a fixed circle (its centre keeps its distance from the
    profile: a circle about the profile's centre), or any other point of a body pinned to
    the frame (a circle about the pin)."""
    from .group import path_centre, path_origin

    body = ref.body
    if ctx.fixed(body):
        return None
    for j in ctx.model.joints:
        for fixed, moving in ((j.a, j.b), (j.b, j.a)):
            if moving != body or not ctx.fixed(fixed):
                continue
            if rolls(j) and by_centre_path(j) and path_centre(ctx, j, body) == ref.point:
                origin = path_origin(ctx, j, fixed)
                if origin is not None:
                    return origin
            if pins(j) and j.at is not None and j.at != ref.point:
                return j.at
    return None
