"""A model recognised as a four-bar, and its varied parameters mapped to the four-bar's numbers.

The fast path of synthesis works on the closed-form four-bar (`fourbar`): its ten numbers
W = (O2x, O2y, O4x, O4y, r2, r3, r4, cx, cy, φ0) and the branch σ, φ0 being the crank's
absolute angle as drawn. A model is a four-bar when its moving loop is a crank driven at
its pivot followed by an RRR dyad closing on the frame (`metrics.linkage_roles`); its
parameters reach W through its own constructions, so W is read off the drawn points the
model's constructions give (`engine.array_positions`, over arrays of designs):

    r2 = |A − O2|, r3 = |B − A|, r4 = |B − O4|, c = (P − A) conj(B − A) / r3,
    φ0 = arg(A − O2), σ = sign((O4 − A) × (B − A)),

and the derivatives of W with respect to the parameters by central differences of those
points (`ModelMap`). When each of W's numbers, in one of the usual coordinates — the ground
pivot O4 by (x, y) or by (r1, θ0) from O2, the crank's drawn angle absolute or from the
ground line — is a constant or a multiple of one varied parameter plus a constant (a model
written with its link lengths, pivots and coupler point as parameters, as the papers pose
their problems), the map is written in closed form (`CarriedMap`), found by probing the
constructions and checked again on the designs that are written.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Optional

import numpy as np

from ...algebra.arrays import Arrays
from ...algebra.vectors import Space
from ...engine.array_positions import array_positions
from ...engine.instant import Instant, _parameters
from ...errors import KinematikaError
from ...joints.capabilities import Coordinate as JointCoordinate
from ...model.model import Model
from ...structure.assur import assur_groups
from ...sweep.batch import model_with_symbols
from ..metrics import linkage_roles

W_NAMES = ("o2x", "o2y", "o4x", "o4y", "r2", "r3", "r4", "cx", "cy", "phi0")
NW = len(W_NAMES)
FD_STEP = 1e-6          # central differences: relative step on a parameter (its scale at least 1)


@dataclass(frozen=True)
class Roles:
    """The four-bar's points and bodies in the model, and its crank's joint: the sweep's
    coordinate turns the crank by `sign` × the increment (the coordinate is the joint's second
    body relative to its first)."""

    o2: str
    a: str
    b: str
    o4: str
    crank: str
    coupler: str
    rocker: str
    joint: str
    sign: float


def four_bar_roles(model: Model) -> Optional[Roles]:
    """The model's four-bar, or None when its moving loop is not a crank and an RRR dyad."""
    if model.dimension != 2 or len(model.drivers) != 1:
        return None
    groups = assur_groups(model)
    roles = linkage_roles(model, groups)
    if groups is None or roles is None or roles["kind"] != "four-bar":
        return None
    joint = model.joint(groups[0].joints[0])
    if joint.kind.coordinate is not JointCoordinate.ANGLE:
        return None
    sign = 1.0 if joint.a == model.frame else -1.0
    return Roles(roles["O2"], roles["A"], roles["B"], roles["O4"], roles["crank"], roles["coupler"],
                 roles["output"], joint.id, sign)


class Drawn:
    """The drawn points of many designs of a model at once (NaN where a design cannot be
    drawn), from arrays of the varied parameters' values."""

    def __init__(self, model: Model, varied: list[str]) -> None:
        self.model = model
        self.varied = list(varied)
        self.symbols = model_with_symbols(model, self.varied)

    def points(self, values: np.ndarray) -> dict[str, np.ndarray]:
        """Each point as complex (D,), for the designs `values` (D, len(varied))."""
        values = np.atleast_2d(np.asarray(values, dtype=float))
        size = len(values)
        arrays = Arrays({n: values[:, i] for i, n in enumerate(self.varied)})
        with np.errstate(all="ignore"):
            env, _ = _parameters(self.symbols, arrays, False)
            inst = Instant(self.symbols, arrays, Space(2), env, {}, {})
            try:
                xy = array_positions(inst)
            except KinematikaError:
                return {name: np.full(size, np.nan + 0j) for name in self.model.points}
        return {name: np.broadcast_to(np.asarray(p[0], dtype=float), (size,))
                + 1j * np.broadcast_to(np.asarray(p[1], dtype=float), (size,)) for name, p in xy.items()}


def line_of(model: Model, body: str) -> tuple[str, str]:
    """A body's line: from its first point to its second (as `motion_error` measures a pose)."""
    points = model.bodies[body].points
    if len(points) < 2:
        raise KinematikaError("usage", "body-needs-two-points", "--output", body=body)
    return points[0], points[1]


@dataclass
class Canon:
    """The four-bar numbers of D designs: W (D, NW), the branch σ (D,), and what some tasks
    read besides: the coupler's and the rocker's lines' angles from A→B and O4→B (κ3, κ4),
    and the coupler's size ρ (its largest distance between two points)."""

    w: np.ndarray
    sigma: np.ndarray
    kappa3: np.ndarray
    kappa4: np.ndarray
    rho: np.ndarray

    def take(self, index) -> "Canon":
        """The designs `index` only."""
        return Canon(self.w[index], self.sigma[index], self.kappa3[index], self.kappa4[index],
                     self.rho[index])


def canon_of(points: dict[str, np.ndarray], roles: Roles, point: Optional[str], model: Model) -> Canon:
    """The four-bar numbers of designs from their drawn points (`point` on the coupler: the
    path's point; None: A)."""
    o2, a, b, o4 = (points[k] for k in (roles.o2, roles.a, roles.b, roles.o4))
    p = points[point] if point is not None else a
    u = b - a
    r3 = np.abs(u)
    c = (p - a) * np.conj(u) / r3
    w = np.stack([o2.real, o2.imag, o4.real, o4.imag, np.abs(a - o2), r3, np.abs(b - o4), c.real, c.imag,
                  np.angle(a - o2)], axis=1)
    d = o4 - a
    sigma = np.sign(d.real * u.imag - d.imag * u.real)
    q1, q2 = line_of(model, roles.coupler)
    kappa3 = np.angle((points[q2] - points[q1]) / u)
    r1, r2 = line_of(model, roles.rocker)
    kappa4 = np.angle((points[r2] - points[r1]) / (b - o4))
    names = model.bodies[roles.coupler].points
    rho = np.zeros(len(o2))
    for i, m in enumerate(names):
        for n in names[i + 1:]:
            rho = np.maximum(rho, np.abs(points[m] - points[n]))
    return Canon(w, sigma, kappa3, kappa4, rho)


class ModelMap:
    """Varied parameters → four-bar numbers through the model's own constructions."""

    carried = False

    def __init__(self, model: Model, roles: Roles, varied: list[str], point: Optional[str]) -> None:
        self.model, self.roles, self.point = model, roles, point
        self.varied = list(varied)
        self.drawn = Drawn(model, varied)

    def canon(self, values: np.ndarray) -> Canon:
        """The numbers of the designs `values` (D, n)."""
        return canon_of(self.drawn.points(values), self.roles, self.point, self.model)

    def jacobian(self, values: np.ndarray) -> tuple[Canon, np.ndarray, np.ndarray]:
        """At each design (D, n): its numbers, dW/dp (D, NW, n) and d(κ3, κ4, ρ)/dp (D, 3, n),
        by central differences of the drawn points (angles differenced on the circle)."""
        values = np.atleast_2d(values)
        size, n = values.shape
        h = FD_STEP * np.maximum(1.0, np.abs(values))                       # (D, n)
        steps = h[:, :, None] * np.eye(n)[None]                             # (D, n, n)
        plus = (values[:, None, :] + steps).reshape(-1, n)
        minus = (values[:, None, :] - steps).reshape(-1, n)
        both = self.canon(np.concatenate([values, plus, minus]))
        here = both.take(slice(0, size))
        up, down = both.take(slice(size, size + size * n)), both.take(slice(size + size * n, None))
        dw = up.w - down.w
        dw[:, -1] = np.angle(np.exp(1j * dw[:, -1]))
        jw = (dw.reshape(size, n, NW) / (2 * h[:, :, None])).transpose(0, 2, 1)
        extra_up = np.stack([up.kappa3, up.kappa4, up.rho], axis=1)
        extra_down = np.stack([down.kappa3, down.kappa4, down.rho], axis=1)
        de = extra_up - extra_down
        de[:, :2] = np.angle(np.exp(1j * de[:, :2]))
        je = (de.reshape(size, n, 3) / (2 * h[:, :, None])).transpose(0, 2, 1)
        return here, jw, je


# the closed-form map --------------------------------------------------------------------------
# Each of W's numbers in one of its coordinates: a quantity read off the drawn points.
QUANTITIES = ("o2x", "o2y", "o4x", "o4y", "r1", "theta0", "r2", "r3", "r4", "cx", "cy", "phi0", "phi0_rel")
ANGLES = {"theta0", "phi0", "phi0_rel"}
SYSTEMS = [("o2x", "o2y", g1, g2, "r2", "r3", "r4", "cx", "cy", f)
           for g1, g2 in (("o4x", "o4y"), ("r1", "theta0")) for f in ("phi0", "phi0_rel")]
PROBES = 5
AFFINE_TOL = 1e-9


def quantities(c: Canon) -> dict[str, np.ndarray]:
    """Every quantity of `QUANTITIES` for the designs of `c`."""
    w = c.w
    o2, o4 = w[:, 0] + 1j * w[:, 1], w[:, 2] + 1j * w[:, 3]
    theta0 = np.angle(o4 - o2)
    out = {k: w[:, i] for i, k in enumerate(W_NAMES) if k != "phi0"}
    out.update(r1=np.abs(o4 - o2), theta0=theta0, phi0=w[:, 9], phi0_rel=np.angle(np.exp(1j * (w[:, 9] - theta0))))
    return out


@dataclass
class Coordinate:
    """One coordinate of W: a constant (`param` None) or `scale` × parameter + `offset`."""

    name: str
    param: Optional[int]
    scale: float
    offset: float


class CarriedMap:
    """W in closed form from the varied parameters: each coordinate a constant or an affine
    function of one parameter (a model written by its dimensions); the branch σ and the
    lines' angles κ constant."""

    carried = True

    def __init__(self, system: tuple[str, ...], coordinates: list[Coordinate], sigma: float,
                 kappa3: float, kappa4: float, varied: list[str]) -> None:
        self.system, self.coordinates, self.sigma = system, coordinates, sigma
        self.kappa3, self.kappa4 = kappa3, kappa4
        self.varied = varied
        self.polar = "r1" in system
        self.relative = "phi0_rel" in system

    def values(self, params: np.ndarray) -> np.ndarray:
        """The coordinates (D, 10) of the designs `params` (D, n)."""
        params = np.atleast_2d(params)
        return np.stack([c.offset + c.scale * params[:, c.param] if c.param is not None
                         else np.full(len(params), c.offset) for c in self.coordinates], axis=1)

    def w_of(self, u: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """W (D, NW) from coordinates u (D, 10), and dW/du (D, NW, 10)."""
        size = len(u)
        w = u.copy()
        dw = np.broadcast_to(np.eye(NW), (size, NW, NW)).copy()
        theta0 = u[:, 3]
        if self.polar:
            r1 = u[:, 2]
            e = np.exp(1j * theta0)
            w[:, 2] = u[:, 0] + r1 * e.real
            w[:, 3] = u[:, 1] + r1 * e.imag
            dw[:, 2, :] = 0.0
            dw[:, 3, :] = 0.0
            dw[:, 2, 0] = dw[:, 3, 1] = 1.0
            dw[:, 2, 2], dw[:, 3, 2] = e.real, e.imag
            dw[:, 2, 3], dw[:, 3, 3] = -r1 * e.imag, r1 * e.real
        if self.relative:
            if self.polar:
                w[:, 9] = u[:, 9] + theta0
                dw[:, 9, 3] = 1.0
            else:
                dx, dy = u[:, 2] - u[:, 0], u[:, 3] - u[:, 1]
                d2 = dx * dx + dy * dy
                w[:, 9] = u[:, 9] + np.arctan2(dy, dx)
                # d atan2(dy, dx) = (dx ddy − dy ddx) / d2
                dw[:, 9, 0], dw[:, 9, 1] = dy / d2, -dx / d2
                dw[:, 9, 2], dw[:, 9, 3] = -dy / d2, dx / d2
        return w, dw

    def du_dp(self) -> np.ndarray:
        """(10, n): each coordinate's derivative with respect to each parameter."""
        out = np.zeros((NW, len(self.varied)))
        for i, c in enumerate(self.coordinates):
            if c.param is not None:
                out[i, c.param] = c.scale
        return out

    def canon(self, params: np.ndarray) -> Canon:
        """The numbers of the designs `params` (D, n)."""
        w, _ = self.w_of(self.values(params))
        size = len(w)
        return Canon(w, np.full(size, self.sigma), np.full(size, self.kappa3), np.full(size, self.kappa4),
                     np.full(size, np.nan))

    def jacobian(self, params: np.ndarray) -> tuple[Canon, np.ndarray, np.ndarray]:
        """Numbers, dW/dp (D, NW, n) and (zero) d(κ3, κ4, ρ)/dp of the designs `params`."""
        params = np.atleast_2d(params)
        w, dw = self.w_of(self.values(params))
        jw = dw @ self.du_dp()
        size = len(w)
        c = Canon(w, np.full(size, self.sigma), np.full(size, self.kappa3), np.full(size, self.kappa4),
                  np.full(size, np.nan))
        return c, jw, np.zeros((size, 3, len(self.varied)))

    def parameters(self, u: np.ndarray) -> np.ndarray:
        """The parameters (D, n) whose coordinates are u (D, 10) (those the coordinates carry;
        a parameter that carries none is NaN)."""
        out = np.full((len(u), len(self.varied)), np.nan)
        for i, c in enumerate(self.coordinates):
            if c.param is not None:
                out[:, c.param] = (u[:, i] - c.offset) / c.scale
        return out

    def coordinate_bounds(self, low: np.ndarray, high: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Each coordinate's interval from its parameter's (a constant's is itself)."""
        lo, hi = np.zeros(NW), np.zeros(NW)
        for i, c in enumerate(self.coordinates):
            if c.param is None:
                lo[i] = hi[i] = c.offset
            else:
                ends = sorted((c.offset + c.scale * low[c.param], c.offset + c.scale * high[c.param]))
                lo[i], hi[i] = ends
        return lo, hi


def carried_map(model_map: ModelMap, low: np.ndarray, high: np.ndarray, seed: int = 0) -> Optional[CarriedMap]:
    """The closed-form map of a model written by its dimensions, found by probing its
    constructions at a few designs of the box: each coordinate must be constant or affine in
    one parameter (the same slope and offset at every probe), no parameter carrying two, and
    the branch and lines' angles constant. None when no coordinate system fits."""
    n = len(low)
    rng = np.random.default_rng(seed)
    span = np.where(high > low, high - low, 0.0)
    candidates = low + rng.random((64 * PROBES, n)) * span
    candidates[0] = low + 0.5 * span
    drawable = np.isfinite(model_map.canon(candidates).w).all(axis=1)
    if drawable.sum() < PROBES:
        return None
    probes = candidates[drawable][:PROBES]
    c = model_map.canon(probes)
    if np.ptp(c.sigma) > 0 or np.ptp(np.angle(np.exp(1j * (c.kappa3 - c.kappa3[0])))) > AFFINE_TOL \
            or np.ptp(np.angle(np.exp(1j * (c.kappa4 - c.kappa4[0])))) > AFFINE_TOL:
        return None
    values = quantities(c)
    slopes = _slopes(model_map, probes, values)
    found: dict[str, Coordinate] = {}
    for name in QUANTITIES:
        coordinate = _coordinate(name, values[name], slopes[name], probes)
        if coordinate is not None:
            found[name] = coordinate
    for system in SYSTEMS:
        if all(q in found for q in system):
            used = [found[q].param for q in system if found[q].param is not None]
            if len(set(used)) == len(used):
                return CarriedMap(system, [found[q] for q in system], float(c.sigma[0]), float(c.kappa3[0]),
                                  float(c.kappa4[0]), model_map.varied)
    return None


def _slopes(model_map: ModelMap, probes: np.ndarray, values: dict[str, np.ndarray]) -> dict[str, np.ndarray]:
    """Each quantity's derivatives (PROBES, n) by central differences."""
    size, n = probes.shape
    h = FD_STEP * np.maximum(1.0, np.abs(probes))
    steps = h[:, :, None] * np.eye(n)[None]
    up = quantities(model_map.canon((probes[:, None, :] + steps).reshape(-1, n)))
    down = quantities(model_map.canon((probes[:, None, :] - steps).reshape(-1, n)))
    out = {}
    for name in QUANTITIES:
        d = up[name] - down[name]
        if name in ANGLES:
            d = np.angle(np.exp(1j * d))
        out[name] = d.reshape(size, n) / (2 * h)
    return out


def _coordinate(name: str, value: np.ndarray, slope: np.ndarray, probes: np.ndarray) -> Optional[Coordinate]:
    """The quantity as a constant or an affine function of one parameter, if it is one."""
    scale = max(1.0, float(np.max(np.abs(value))))
    big = np.abs(slope) > 1e-7
    columns = np.flatnonzero(big.any(axis=0))
    if len(columns) == 0:
        spread = value - value[0]
        if name in ANGLES:
            spread = np.angle(np.exp(1j * spread))
        return Coordinate(name, None, 0.0, float(value[0])) if np.max(np.abs(spread)) <= AFFINE_TOL * scale else None
    if len(columns) > 1:
        return None
    j = int(columns[0])
    k0 = float(np.median(slope[:, j]))
    if np.max(np.abs(slope[:, j] - k0)) > 1e-6 * max(1.0, abs(k0)):
        return None
    # the slope and offset fitted to the values themselves (exact, where differences are not)
    x = probes[:, j]
    if name in ANGLES:
        value = value[0] + np.angle(np.exp(1j * (value - value[0] - k0 * (x - x[0])))) + k0 * (x - x[0])
    k, offset = np.polyfit(x, value, 1)
    if np.max(np.abs(k * x + offset - value)) > 1e-9 * scale or abs(k - k0) > 1e-6 * max(1.0, abs(k)):
        return None
    return Coordinate(name, j, float(k), float(offset))
