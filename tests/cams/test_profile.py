"""Cam profiles: the follower's motion found again by placing the profile and touching it,
pressure angles and radii of curvature against the textbooks' closed forms."""
from __future__ import annotations

import math

import numpy as np
import pytest
import sympy as sp
from scipy.optimize import brentq

from kinematika.cams import CamAnalysis, DiscCam, Flat, Knife, Oscillating, PlateCam, Roller, Translating, laws
from kinematika.cams.program import build
from tests.conftest import sampled

D = math.radians
H = 25.0
PROGRAM = build([(laws.DWELL, D(60), 0, "dwell"), (laws.CYCLOIDAL, D(100), H, "rise"),
                 (laws.DWELL, D(40), 0, "dwell"), (laws.POLYNOMIAL_345, D(160), -H, "return")])
SWING = build([(laws.DWELL, D(60), 0, "dwell"), (laws.MODIFIED_SINE, D(120), D(20), "rise"),
               (laws.DWELL, D(30), 0, "dwell"), (laws.CYCLOIDAL, D(150), -D(20), "return")])
BASE = 40.0
ANGLES = np.radians([10.0, 110.0, 150.0, 230.0, 290.0])


def rotate(p: np.ndarray, a: float) -> np.ndarray:
    c, s = math.cos(a), math.sin(a)
    return np.array([c * p[0] - s * p[1], s * p[0] + c * p[1]])


def distance_to(profile, ground_point: np.ndarray, turn: float) -> float:
    """The distance from a ground point to the profile turned by `turn` (curves' nearest)."""
    local = rotate(ground_point, -turn)
    return float(np.linalg.norm(profile.point(profile.nearest(local)) - local))


def touching(gap, start: float, step: float) -> float:
    """The first coordinate, coming down from `start` in `step`s, where gap() turns ≤ 0
    (the follower reaches the cam), refined by Brent's method."""
    hi = start
    while gap(hi - step) > 0:
        hi -= step
    return brentq(gap, hi - step, hi, xtol=1e-12)


def translating_roller_s(cam: DiscCam, theta: float) -> float:
    """Lower the roller along x = e until it touches the turned profile: s = y − d."""
    f = cam.follower
    r = f.contact.radius
    d = f.lowest(cam.base)
    y = touching(lambda y: distance_to(cam.profile, np.array([f.offset, y]), cam.sense * theta) - r,
                 d + H + 3, 2.0)
    return y - d


def translating_knife_s(cam: DiscCam, theta: float) -> float:
    """The highest crossing of the turned profile with the axis x = e (curve points only)."""
    f = cam.follower
    u = np.linspace(0, 2 * math.pi, 4001)
    p = np.array([rotate(q, cam.sense * theta) for q in cam.profile.point(u)])
    gap = p[:, 0] - f.offset
    best = -np.inf
    for i in np.flatnonzero(gap[:-1] * gap[1:] <= 0):
        root = brentq(lambda v: rotate(cam.profile.point(v), cam.sense * theta)[0] - f.offset, u[i], u[i + 1],
                      xtol=1e-14)
        best = max(best, rotate(cam.profile.point(root), cam.sense * theta)[1])
    return best - f.lowest(cam.base)


def translating_flat_s(cam: DiscCam, theta: float) -> float:
    """Lower the face y = h until it meets the turned profile: the highest point, from the
    profile's points and a Newton polish on its tangent being horizontal."""
    u = np.linspace(0, 2 * math.pi, 4001)
    p = np.array([rotate(q, cam.sense * theta) for q in cam.profile.point(u)])
    v = u[np.argmax(p[:, 1])]
    for _ in range(30):       # d/dv of y_ground = 0
        d1 = rotate(cam.profile.d1(v), cam.sense * theta)[1]
        d2 = rotate(cam.profile.d2(v), cam.sense * theta)[1]
        v -= d1 / d2
    return rotate(cam.profile.point(v), cam.sense * theta)[1] - cam.base


def oscillating_roller_s(cam: DiscCam, theta: float) -> float:
    """Turn the arm down from far out until the roller (or knife edge) touches the profile."""
    f = cam.follower
    a, l, r = f.pivot, f.arm, f.contact.radius

    def centre(psi: float) -> np.ndarray:
        return np.array([a - l * math.cos(psi), l * math.sin(psi)])

    if r > 0:
        psi = touching(lambda p: distance_to(cam.profile, centre(p), cam.sense * theta) - r,
                       f.start(cam.base) + D(24), D(2))
    else:      # a knife edge: the crossing of its circle |X − A| = ℓ with the turned profile
        u = np.linspace(0, 2 * math.pi, 4001)
        gap = lambda v: np.linalg.norm(rotate(cam.profile.point(v), cam.sense * theta) - [a, 0]) - l
        turned = np.array([rotate(q, cam.sense * theta) for q in cam.profile.point(u)])
        g = np.linalg.norm(turned - [a, 0], axis=1) - l
        roots = [brentq(gap, u[i], u[i + 1], xtol=1e-14) for i in np.flatnonzero(g[:-1] * g[1:] <= 0)]
        pts = [rotate(cam.profile.point(v), cam.sense * theta) for v in roots]
        psi = max(math.atan2(q[1], a - q[0]) for q in pts)
    return psi - f.start(cam.base)


def oscillating_flat_s(cam: DiscCam, theta: float) -> float:
    """Turn the face down until no point of the turned profile is beyond it: n(ψ)·Q ≤ a sin ψ − f
    for every Q, touching (= 0) at the answer."""
    f = cam.follower
    a, face = f.pivot, f.contact.face
    u = np.linspace(0, 2 * math.pi, 8001)
    pts = np.array([rotate(q, cam.sense * theta) for q in cam.profile.point(u)])

    def clearance(psi: float) -> float:
        return float(np.min(a * math.sin(psi) - face - (pts[:, 0] * math.sin(psi) + pts[:, 1] * math.cos(psi))))

    return touching(clearance, f.start(cam.base) + D(24), D(2)) - f.start(cam.base)


CASES = {
    "knife, in line": (Translating(Knife()), PROGRAM, 1, translating_knife_s),
    "roller, in line": (Translating(Roller(10.0)), PROGRAM, 1, translating_roller_s),
    "roller, offset, clockwise": (Translating(Roller(8.0), offset=-12.0), PROGRAM, -1, translating_roller_s),
    "knife, offset": (Translating(Knife(), offset=9.0), PROGRAM, 1, translating_knife_s),
    "flat face": (Translating(Flat()), PROGRAM, 1, translating_flat_s),
    "flat face, clockwise": (Translating(Flat()), PROGRAM, -1, translating_flat_s),
    "oscillating roller": (Oscillating(Roller(10.0), pivot=110.0, arm=90.0), SWING, 1, oscillating_roller_s),
    "oscillating roller, clockwise": (Oscillating(Roller(6.0), pivot=100.0, arm=80.0), SWING, -1, oscillating_roller_s),
    "oscillating knife": (Oscillating(Knife(), pivot=100.0, arm=85.0), SWING, 1, oscillating_roller_s),
    "oscillating flat face": (Oscillating(Flat(face=5.0), pivot=120.0, arm=120.0), SWING, 1, oscillating_flat_s),
}


# one of each follower (knife, roller, flat face; translating, oscillating), an offset and the
# clockwise sense among them (every case in a deep run)
KEPT = {"knife, offset", "roller, offset, clockwise", "flat face, clockwise", "oscillating roller",
        "oscillating knife", "oscillating flat face"}


@pytest.mark.parametrize("name", sampled(list(CASES), KEPT))
def test_the_follower_touching_the_turned_profile_is_where_the_program_puts_it(name):
    follower, program, sense, find = CASES[name]
    cam = DiscCam(program, follower, BASE, sense)
    expected = program.motion(ANGLES)[0]
    got = np.array([find(cam, t) for t in ANGLES])
    tol = 1e-7 if not follower.angular else 1e-9
    if follower.contact.touches_with_face and follower.angular:
        tol = 3e-7          # the face's clearance is the least over 8 001 points of the profile
    assert np.allclose(got, expected, atol=tol), (got - expected)


def test_a_translating_cams_roller_touches_its_profile_where_the_program_says():
    cam = PlateCam(build([(laws.DWELL, 20.0, 0, "d"), (laws.CYCLOIDAL, 60.0, 15.0, "r"),
                          (laws.HARMONIC, 50.0, -15.0, "r")], periodic=False), Translating(Roller(6.0)), 10.0)
    for u in (5.0, 30.0, 55.0, 70.0, 100.0, 125.0):
        # the roller at x = 0 over the plate moved by u: lower it until it touches
        def gap(y: float, u: float = u) -> float:
            local = np.array([0.0 - u, y])
            return float(np.linalg.norm(cam.profile.point(cam.profile.nearest(local)) - local)) - 6.0

        y = touching(gap, 35.0, 2.0)
        assert y - 16.0 == pytest.approx(float(cam.program.motion(u)[0]), abs=1e-7)


# --- pressure angle and radius of curvature against the textbooks -----------------------

@pytest.mark.parametrize("offset,sense", [(0.0, 1), (12.0, 1), (-12.0, 1), (12.0, -1), (-7.0, -1)])
def test_pressure_angle_of_a_translating_roller_is_nortons(offset, sense):
    """Norton eq. 8.31: φ = arctan[(s' − σe)/(s + √(R_p² − e²))], s' = ds/dθ (length/rad)."""
    cam = DiscCam(PROGRAM, Translating(Roller(10.0), offset=offset), BASE, sense)
    an = CamAnalysis(cam, 1.0, 360)
    s, ds, _, _ = PROGRAM.motion(an.u)
    rp = BASE + 10.0
    expected = np.arctan((ds - sense * offset) / (s + math.sqrt(rp**2 - offset**2)))
    assert np.allclose(an.pressure_angle, expected, atol=1e-10)


def test_pressure_angle_of_an_oscillating_roller_from_the_instant_centre():
    """Kennedy: the cam (2) and follower (3) centre I₂₃ lies on the line of centres O–A with
    ω₂·OI = ω₃·AI; the common normal passes through I₂₃ and the roller's centre B. The pressure
    angle is the angle between BI and B's velocity (⊥ AB)."""
    f = Oscillating(Roller(10.0), pivot=110.0, arm=90.0)
    cam = DiscCam(SWING, f, BASE, 1)
    an = CamAnalysis(cam, 1.0, 360)
    s, ds, _, _ = SWING.motion(an.u)
    psi = f.start(BASE) + s
    b = np.stack([110.0 - 90.0 * np.cos(psi), 90.0 * np.sin(psi)], axis=1)
    # cam ω₂ = 1 (ccw), follower ω₃ = −ds/dθ (ψ grows clockwise): I on the x axis with
    # ω₂·x_I = ω₃·(x_I − a)  →  x_I = −ω₃·a/(ω₂ − ω₃)
    w3 = -ds
    xi = -w3 * 110.0 / (1 - w3)
    normal = np.stack([b[:, 0] - xi, b[:, 1]], axis=1)
    normal /= np.linalg.norm(normal, axis=1, keepdims=True)
    velocity = np.stack([np.sin(psi), np.cos(psi)], axis=1)        # dB/dψ direction
    expected = np.arccos(np.clip(np.abs(np.sum(normal * velocity, axis=1)), -1, 1))
    assert np.allclose(np.abs(an.pressure_angle), expected, atol=1e-9)


def test_radius_of_curvature_of_a_radial_roller_is_nortons():
    """Norton eq. 8.33 for the pitch curve of a radial follower:
    ρ = [(R_p + s)² + s'²]^{3/2} / [(R_p + s)² + 2s'² − (R_p + s)s''], and ρ_profile = ρ − R_f."""
    cam = DiscCam(PROGRAM, Translating(Roller(10.0)), BASE, 1)
    an = CamAnalysis(cam, 1.0, 360)
    s, ds, dds, _ = PROGRAM.motion(an.u)
    r = BASE + 10.0 + s
    rho = (r**2 + ds**2) ** 1.5 / (r**2 + 2 * ds**2 - r * dds)
    assert np.allclose(an.pitch_radius, rho, rtol=1e-10)
    assert np.allclose(an.profile_radius, rho - 10.0, rtol=1e-10, atol=1e-9)


def test_radius_of_curvature_of_an_offset_roller_from_sympy():
    """The pitch curve of an offset follower, P(θ) = R(−θ)·(e, d + s(θ)), differentiated by sympy
    for a cycloidal rise; κ = (x'y'' − y'x'')/|P'|³, ρ = −1/κ (the curve runs clockwise)."""
    th, e, beta, h = sp.Symbol("theta"), 12.0, D(100), H
    d = math.sqrt((BASE + 10.0) ** 2 - e**2)
    xx = (th - D(60)) / beta
    s = h * (xx - sp.sin(2 * sp.pi * xx) / (2 * sp.pi))
    x = e * sp.cos(th) + (d + s) * sp.sin(th)
    y = -e * sp.sin(th) + (d + s) * sp.cos(th)
    kappa = (sp.diff(x, th) * sp.diff(y, th, 2) - sp.diff(y, th) * sp.diff(x, th, 2)) / (
        sp.diff(x, th) ** 2 + sp.diff(y, th) ** 2) ** sp.Rational(3, 2)
    f = sp.lambdify(th, -1 / kappa, "numpy")
    cam = DiscCam(PROGRAM, Translating(Roller(10.0), offset=e), BASE, 1)
    u = np.radians(np.linspace(61, 159, 15))
    an = CamAnalysis(cam, 1.0, 360)
    got = 1 / (-cam.pitch.curvature(u))
    assert np.allclose(got, f(u), rtol=1e-9)
    assert np.allclose(an.pitch_radius[61:160:7], f(an.u[61:160:7]), rtol=1e-9)


def test_a_flat_faces_radius_is_rb_plus_s_plus_s2_and_the_profiles_own_curvature():
    """Shigley eq. 6-23: ρ = R_b + s + d²s/dθ²; the envelope curve's curvature gives the same."""
    cam = DiscCam(PROGRAM, Translating(Flat()), BASE, 1)
    an = CamAnalysis(cam, 1.0, 360)
    s, _, dds, _ = PROGRAM.motion(an.u)
    assert np.allclose(an.profile_radius, BASE + s + dds, rtol=1e-10)
    ok = np.abs(BASE + s + dds) > 1
    assert np.allclose((1 / -cam.profile.curvature(an.u))[ok], (BASE + s + dds)[ok], rtol=1e-8)
    assert np.allclose(an.pressure_angle, 0, atol=1e-12)


def test_undercutting_is_found_where_the_textbooks_say():
    """A roller larger than the pitch curve's smallest convex radius, and a flat face on a
    small base circle where R_b + s + s'' < 0."""
    steep = build([(laws.CYCLOIDAL, D(60), 30.0, "r"), (laws.DWELL, D(60), 0, "d"),
                   (laws.CYCLOIDAL, D(60), -30.0, "r"), (laws.DWELL, D(180), 0, "d")])
    roller = CamAnalysis(DiscCam(steep, Translating(Roller(20.0)), 15.0, 1), 1.0, 720)
    s, ds, dds, _ = steep.motion(roller.u)
    r = 35.0 + s
    rho = (r**2 + ds**2) ** 1.5 / (r**2 + 2 * ds**2 - r * dds)
    assert np.array_equal(roller.undercut, (rho > 0) & (rho < 20.0)) and roller.undercut.any()
    flat = CamAnalysis(DiscCam(steep, Translating(Flat()), 15.0, 1), 1.0, 720)
    assert np.array_equal(flat.undercut, 15.0 + s + dds < 0) and flat.undercut.any()
    assert flat.summary()["undercut"]


def test_the_contact_search_finds_an_eccentric_circles_motion():
    """A circle of radius R whose centre is ε from the cam's axis, given by 48 measured points:
    a radial roller's centre rises to ε sin θ + √((R + R_f)² − ε² cos² θ); a flat face to
    ε sin θ + R (ccw, the centre at (ε, 0) at θ = 0)."""
    from kinematika.cams.measured import measured_cam

    R, eps, rf = 30.0, 6.0, 8.0
    t = np.linspace(0, 2 * math.pi, 48, endpoint=False)
    pts = np.c_[eps + R * np.cos(t), R * np.sin(t)]
    th = np.radians(np.arange(0, 360, 30.0))
    roller = measured_cam(pts, Translating(Roller(rf)), 1, 360)
    y = eps * np.sin(th) + np.sqrt((R + rf) ** 2 - eps**2 * np.cos(th) ** 2)
    assert roller.base == pytest.approx(R - eps, abs=1e-3)
    assert np.allclose(roller.program.motion(th)[0], y - (R + rf - eps), atol=2e-3)
    flat = measured_cam(pts, Translating(Flat()), 1, 360)
    assert np.allclose(flat.program.motion(th)[0], eps * np.sin(th) + eps, atol=2e-3)
