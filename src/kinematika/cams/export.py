"""A cam's cycle and shape written for other programs: CSV (a table over the cycle), SVG (the
outline at true size) and DXF (for a workshop's CAD/CAM, through ezdxf, the `cad` extra).

CSV columns, one row per sample (units: the file's length unit L, seconds, degrees):
theta (deg of cam angle; a translating cam: its travel, L), s (L; an oscillating follower:
deg), v (L/s; rad/s), a (L/s²; rad/s²), j (L/s³; rad/s³), pitch_x, pitch_y, profile_x,
profile_y (L, in the cam's frame: centre at the origin, at θ = 0), pressure_angle (deg),
rho_pitch, rho_profile (L, positive where convex; inf where straight).
"""
from __future__ import annotations

import csv
import io
import math
from pathlib import Path

import numpy as np

from ..errors import Said
from ..extras import need
from .analysis import CamAnalysis

COLUMNS = ("theta", "s", "v", "a", "j", "pitch_x", "pitch_y", "profile_x", "profile_y",
           "pressure_angle", "rho_pitch", "rho_profile")


def table(analysis: CamAnalysis) -> np.ndarray:
    """The CSV's columns (`COLUMNS`) as an (n, 12) array."""
    s, v, a, j = analysis.svaj
    if analysis.cam.follower.angular:
        s = np.degrees(s)
    return np.column_stack([analysis.angle, s, v, a, j, analysis.pitch, analysis.profile,
                            np.degrees(analysis.pressure_angle), analysis.pitch_radius,
                            analysis.profile_radius])


def csv_text(analysis: CamAnalysis) -> str:
    """The table as CSV text (header row, then numbers written with repr's precision)."""
    out = io.StringIO()
    writer = csv.writer(out, lineterminator="\n")
    writer.writerow(COLUMNS)
    for row in table(analysis):
        writer.writerow([repr(float(x)) if math.isfinite(x) else ("inf" if x > 0 else "-inf") for x in row])
    return out.getvalue()


def write_csv(analysis: CamAnalysis, path: Path) -> None:
    """Write the CSV."""
    Path(path).write_text(csv_text(analysis), encoding="utf-8")


def _outline(analysis: CamAnalysis, n: int = 1441) -> tuple[np.ndarray, np.ndarray]:
    """The profile and pitch curve finely (n points; closed curves end where they begin)."""
    a, b = analysis.cam.profile.domain
    u = np.linspace(a, b, n)
    return analysis.cam.profile.point(u), analysis.cam.pitch.point(u)


def svg_text(analysis: CamAnalysis, units: str = "mm") -> str:
    """The cam at true size (1 user unit = 1 `units`): profile (solid), pitch curve (dashed),
    base circle (thin), the centre's cross. y grows upwards as in the cam's frame."""
    profile, pitch = _outline(analysis)
    pts = np.vstack([profile, pitch, [[0.0, 0.0]]])
    lo, hi = pts.min(axis=0), pts.max(axis=0)
    pad = 0.05 * float(np.max(hi - lo)) + 1.0
    x0, y0, w, h = lo[0] - pad, -(hi[1] + pad), hi[0] - lo[0] + 2 * pad, hi[1] - lo[1] + 2 * pad
    closed = analysis.cam.profile.closed
    stroke = 0.002 * max(w, h)

    def path(p: np.ndarray) -> str:
        body = " L ".join(f"{x:.6f} {-y:.6f}" for x, y in p)
        return f"M {body}" + (" Z" if closed else "")

    parts = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{w:.4f}{_svg_unit(units)}" '
             f'height="{h:.4f}{_svg_unit(units)}" viewBox="{x0:.4f} {y0:.4f} {w:.4f} {h:.4f}">',
             f'<path d="{path(profile)}" fill="none" stroke="black" stroke-width="{stroke:.4f}"/>',
             f'<path d="{path(pitch)}" fill="none" stroke="#1f77b4" stroke-width="{stroke / 2:.4f}" '
             f'stroke-dasharray="{4 * stroke:.4f} {2 * stroke:.4f}"/>']
    if closed:
        parts.append(f'<circle cx="0" cy="0" r="{analysis.cam.base:.6f}" fill="none" stroke="#888" '
                     f'stroke-width="{stroke / 2:.4f}"/>')
        c = 0.05 * analysis.cam.base
        parts.append(f'<path d="M {-c:.4f} 0 L {c:.4f} 0 M 0 {-c:.4f} L 0 {c:.4f}" stroke="black" '
                     f'stroke-width="{stroke / 2:.4f}"/>')
    parts.append("</svg>\n")
    return "\n".join(parts)


def _svg_unit(units: str) -> str:
    return units if units in ("mm", "cm", "in", "pt", "pc", "px") else ""


def write_svg(analysis: CamAnalysis, path: Path, units: str = "mm") -> None:
    """Write the SVG outline."""
    Path(path).write_text(svg_text(analysis, units), encoding="utf-8")


DXF_UNITS = {"mm": 4, "cm": 5, "m": 6, "in": 1, "ft": 2}      # $INSUNITS codes


def write_dxf(analysis: CamAnalysis, path: Path, units: str = "mm") -> None:
    """A DXF (R2010) with the profile as a closed LWPOLYLINE of 1 440 points (layer PROFILE;
    chord error R(1 − cos(π/1440)) ≈ 2.4e-6·R), the pitch curve (PITCH), the base circle and
    the centre (BASE): a workshop's CAD opens it at true size. Needs ezdxf (the `cad` extra)."""
    ezdxf = need("ezdxf", Said("writing-dxf"), "--dxf", extra="cad")
    doc = ezdxf.new("R2010")
    doc.header["$INSUNITS"] = DXF_UNITS.get(units, 0)
    for name, colour in (("PROFILE", 7), ("PITCH", 5), ("BASE", 8)):
        doc.layers.add(name, color=colour)
    msp = doc.modelspace()
    profile, pitch = _outline(analysis)
    closed = analysis.cam.profile.closed
    if closed:
        profile, pitch = profile[:-1], pitch[:-1]
    msp.add_lwpolyline(profile.tolist(), close=closed, dxfattribs={"layer": "PROFILE"})
    msp.add_lwpolyline(pitch.tolist(), close=closed, dxfattribs={"layer": "PITCH"})
    if closed:
        msp.add_circle((0.0, 0.0), analysis.cam.base, dxfattribs={"layer": "BASE"})
        msp.add_point((0.0, 0.0), dxfattribs={"layer": "BASE"})
    doc.saveas(str(path))
