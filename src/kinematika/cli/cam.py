"""`kinematika cam`: a cam designed from a small file — its summary, tables, outline and figures."""
from __future__ import annotations

from pathlib import Path
from typing import Any, Optional

import typer

from ..text import shown
from .app import JsonOpt, MessagesOpt, app, messages, respond
from .shared import output_file, writing

FIGURES = ("png", "svg", "pdf")


def _figure_path(path: Optional[Path], option: str) -> Optional[Path]:
    if path is not None and path.suffix.lower().lstrip(".") not in FIGURES:
        raise typer.BadParameter(f"{path.name!r}: give a file ending in .png, .svg or .pdf",
                                 param_hint=f"'{option}'")
    return path


@app.command()
def cam(
    spec: Path = typer.Argument(..., help="cam-design file (.yaml, .toml or .json; see docs/cams.md)",
                                show_default=False),
    csv: Optional[Path] = typer.Option(None, "--csv", help="write θ, s, v, a, j, pitch and profile points, "
                                       "pressure angle and radii over the cycle"),
    svg: Optional[Path] = typer.Option(None, "--svg", help="write the cam's outline at true size (SVG)"),
    dxf: Optional[Path] = typer.Option(None, "--dxf", help="write the profile for CAD/CAM (DXF; needs the "
                                       "'cad' extra)"),
    plot: Optional[Path] = typer.Option(None, "--plot", help="write the s–v–a–j diagrams (PNG, SVG, PDF)"),
    drawing: Optional[Path] = typer.Option(None, "--drawing", help="write the cam's drawing: profile, pitch "
                                           "curve, base circle, follower (PNG, SVG, PDF)"),
    as_json: bool = JsonOpt,
    lang: Optional[str] = MessagesOpt,
) -> None:
    """A cam from its motion program (or measured profile) and follower: the largest pressure
    angle, the smallest radius of curvature, undercutting, the program's jumps; files on request."""
    messages(lang, as_json)
    _figure_path(plot, "--plot")
    _figure_path(drawing, "--drawing")

    def compute() -> dict:
        from ..cams import CamAnalysis, export
        from ..draw import cam_plots as figures
        from ..draw.figure import save
        from ..model.files import load_cam as load

        targets = {opt: output_file(p, opt) for opt, p in
                   (("--csv", csv), ("--svg", svg), ("--dxf", dxf), ("--plot", plot), ("--drawing", drawing))
                   if p is not None}
        design = load(spec)
        analysis = CamAnalysis(design.cam, design.speed, design.samples)
        summary = analysis.summary()
        writers = {
            "--csv": lambda p: export.write_csv(analysis, p),
            "--svg": lambda p: export.write_svg(analysis, p, design.units),
            "--dxf": lambda p: export.write_dxf(analysis, p, design.units),
            "--plot": lambda p: save(figures.svaj_figure(analysis, design.units, design.title), p, dpi=120),
            "--drawing": lambda p: save(figures.profile_figure(analysis, design.units, design.title), p, dpi=120),
        }
        for option, path in targets.items():
            with writing(path, option):
                writers[option](path)
        out: dict[str, Any] = {"title": design.title, "units": design.units, "cam": _describe(design), **summary,
                               "written": [str(p) for p in targets.values()]}
        found = analysis.warnings(design.units)
        if found:
            out["warnings"] = [w.as_json() for w in found]
        return out

    respond(as_json, compute, _show)


def _describe(design: Any) -> dict:
    """What the file describes, in a line's worth of keys."""
    spec = design.spec
    return {"kind": spec.cam.kind, "base": design.cam.base, "rotation": spec.cam.rotation,
            "follower": {"motion": spec.follower.motion, "contact": spec.follower.contact},
            "speed": design.speed, "angular": design.angular}


def _show(data: dict) -> None:
    """The summary as a few lines of text; warnings (jumps) on standard error."""
    import warnings

    from ..errors import KinematikaWarning, Said

    u, plate = data["units"], data["cam"]["kind"] == "translating"
    at = (lambda x: f"{x:.4g} {u}") if plate else (lambda x: f"{x:.4g}°")
    cam = data["cam"]
    if data["title"]:
        print(shown(data["title"]))
    print(f"{cam['kind']} cam (base {cam['base']:.4g} {u}, {cam['rotation']}), {cam['follower']['motion']} "
          f"{cam['follower']['contact']} follower")
    phi = data["pressure_angle"]
    print(f"largest pressure angle      {phi['largest']:.2f}° at {at(phi['at'])}")
    for key, name in (("pitch_radius", "radius of curvature, pitch"), ("profile_radius", "radius of curvature, profile")):
        for side, value in data.get(key, {}).items():
            print(f"{name + ' (' + side + ')':<40}{value['smallest']:.4g} {u} at {at(value['at'])}"
                  if side == "convex" else f"{'':<12}{side}: {value['smallest']:.4g} {u} at {at(value['at'])}")
    if data["undercut"]:
        for r in data["undercut"]:
            print(f"UNDERCUT                    {at(r['start'])} to {at(r['end'])} (ρ down to {r['worst']:.4g} {u})")
    else:
        print("undercutting                none")
    if "face" in data:
        print(f"face in contact from        {data['face']['from']:.4g} to {data['face']['to']:.4g} {u} along it")
    print("jumps of v or a             " + ("none (s, v, a continuous)" if not data["jumps"] else
                                            f"{len(data['jumps'])} (see the warnings)"))
    unit = "rad" if cam["angular"] else u
    p = data["peaks"]
    print(f"peaks                       s {p['s']:.4g} {'°' if cam['angular'] else u}, v {p['v']:.4g} {unit}/s, a {p['a']:.4g} {unit}/s², "
          f"j {p['j']:.4g} {unit}/s³")
    for path in data["written"]:
        print(f"wrote {shown(path)}")
    for w in data.get("warnings", []):
        warnings.warn(KinematikaWarning(Said.text_of(w["message"]), w["where"]), stacklevel=1)
