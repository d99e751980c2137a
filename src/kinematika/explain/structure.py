"""The structure of the mechanism, before any motion: bodies, joints, degrees of freedom
(by the rank of the joints' velocity conditions, as the engine counts them) and the
order of solution."""
from __future__ import annotations

from ..model.model import PointPair
from .context import Ctx
from .document import Arrow, Figure, Section, Table, Value, msg
from .order import Step


def structure_section(ctx: Ctx, steps: list[Step]) -> Section:
    model, sol = ctx.model, ctx.sol
    sec = Section(msg("sec.structure"))
    bodies = [[msg("structure.frame", body=name) if name == ctx.frame else name, ", ".join(b.points),
               [msg(f"shape.{type(s).__name__.lower()}") for s in b.shapes]]
              for name, b in model.bodies.items()]
    sec.add(Table([msg("col.body"), msg("col.points"), msg("col.shapes")], bodies))
    joints = [[j.id, msg(f"joint.{j.type}"), f"{j.a} – {j.b}", _where(j)] for j in model.joints]
    sec.add(Table([msg("col.joint"), msg("col.type"), msg("col.bodies"), msg("col.where")], joints))
    d = sol.solver.analysis.diagnosis
    sec.add(msg("structure.dof", n=str(d.n), moving=str(len(model.moving_bodies)),
                rank=str(d.n - d.dof), dof=str(d.dof), conditions=str(d.conditions)))
    if ctx.planar:
        sec.add(mechanism_figure(ctx))
    if not steps:
        return sec
    order = Section(msg("sec.order"), level=3)
    order.add(msg("order.assur" if steps and steps[0].source == "assur" else "order.blocks"))
    for i, s in enumerate(steps, 1):
        known = ", ".join(s.known) if s.known else "—"
        order.add(msg("order.item", n=str(i), kind=msg(f"kind.{s.kind}"), bodies=", ".join(s.bodies),
                      joints=", ".join(s.joints) or "—", known=known))
    sec.add(order)
    return sec


def _where(j) -> str:
    parts = []
    if j.at:
        parts.append(j.at)
    if isinstance(j.along, PointPair):
        parts.append(f"∥ {j.along.start}{j.along.end}")
    elif j.along is not None:
        parts.append("∥ (" + ", ".join(e.text for e in j.along) + ")")
    return " ".join(parts) or "—"


def mechanism_figure(ctx: Ctx) -> Figure:
    """The mechanism at the instant: bodies as lines between their points, shapes, labels."""
    fig = Figure(msg("fig.mechanism"), unit="len", sample=ctx.symbolic)
    pos = {name: ctx.num(p) for name, p in ctx.inst.points.items()}
    for name, body in ctx.model.bodies.items():
        pts = [pos[p] for p in body.points]
        if name != ctx.frame:
            if len(pts) == 2:
                fig.segments.append((pts[0], pts[1]))
            elif len(pts) > 2:
                fig.segments += [(pts[i], pts[(i + 1) % len(pts)]) for i in range(len(pts))]
        for shape in ctx.inst.shapes[name]:
            if hasattr(shape, "radius"):
                fig.circles.append((ctx.num(shape.center), float(ctx.num(shape.radius))))
            elif hasattr(shape, "direction"):
                p, d, k = ctx.num(shape.through), ctx.num(shape.direction), ctx.inst.scale
                fig.lines.append((tuple(a - k * b for a, b in zip(p, d)), tuple(a + k * b for a, b in zip(p, d))))
    grounded = set(ctx.model.bodies[ctx.frame].points)
    for name, p in pos.items():
        fig.points.append((name, p, "ground" if name in grounded else "point"))
    speeds = list(dict.fromkeys((pos[p], ctx.num(ctx.vel(name, p))) for name, body in ctx.model.bodies.items()
                                if name != ctx.frame for p in body.points))
    top = max([sum(c * c for c in v) ** 0.5 for _, v in speeds] + [0.0])
    if top > 0:
        k = 0.35 * ctx.inst.scale / top
        fig.arrows += [Arrow(p, tuple(a + k * b for a, b in zip(p, v)), None, "velocity")
                       for p, v in speeds if sum(c * c for c in v) ** 0.5 > 1e-6 * top]
    return fig


def values_table(ctx: Ctx) -> Table:
    """ω and α of every body, the solver's values."""
    rows = [[b, Value(ctx.clean(ctx.omega(b), "rate") if ctx.planar else
                      ctx.clean(tuple(ctx.omega(b)), "rate"), "rate"),
             Value(ctx.clean(ctx.alpha(b), "rate2") if ctx.planar else
                   ctx.clean(tuple(ctx.alpha(b)), "rate2"), "rate2")] for b in ctx.model.moving_bodies]
    return Table([msg("col.body"), msg("col.omega"), msg("col.alpha")], rows)
