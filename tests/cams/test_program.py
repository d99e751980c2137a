"""Motion programs (the fundamental law of cam design), the cam-design file and command:
errors naming their place, CSV columns, SVG, DXF read back with ezdxf."""
from __future__ import annotations

import csv
import io
import json
import math
import subprocess
import sys
import xml.etree.ElementTree as ET

import numpy as np
import pytest

from kinematika.cams import CamAnalysis, laws
from kinematika.model.files import load_cam as load
from kinematika.cams.export import COLUMNS, csv_text, svg_text, write_dxf
from kinematika.cams.program import build
from kinematika.cams.spec import design, parse
from kinematika.errors import KinematikaError

from fuzz.forks import run_forked
# what `kinematika cam` imports, imported once here: a forked command then starts without the
# seconds of importing typer, matplotlib and the plots in each child (the fork is what
# `run` tests: its own streams and exit status; a fresh process is run once, below)
import kinematika.cli
import kinematika.draw.cam_plots
import kinematika.draw.figure  # noqa: F401
from tests.conftest import ROOT

pytestmark = pytest.mark.early      # minutes of work: handed to a worker before the shorter files (tests/conftest.py)

D = math.radians
NORTON = ROOT / "examples" / "cams" / "norton-double-dwell.yaml"
SHM = ROOT / "examples" / "cams" / "norton-shm.yaml"


def test_harmonic_rise_beside_a_dwell_jumps_and_cycloidal_does_not():
    """SHM: S''(0) = π²/2, so d²s/dθ² jumps by π²h/(2β²) where it meets a dwell (Norton §8.3)."""
    h, beta = 25.0, D(90)
    shm = build([(laws.DWELL, beta, 0, "d"), (laws.HARMONIC, beta, h, "r"), (laws.DWELL, beta, 0, "d"),
                 (laws.HARMONIC, beta, -h, "r")])
    jumps = shm.jumps()
    assert [(round(math.degrees(j.at)), j.quantity) for j in jumps] == [
        (90, "acceleration"), (180, "acceleration"), (270, "acceleration"), (0, "acceleration")]
    assert [j.amount for j in jumps] == pytest.approx([1, 1, -1, -1] * np.array(math.pi**2 * h / (2 * beta**2)))
    cyc = build([(laws.DWELL, beta, 0, "d"), (laws.CYCLOIDAL, beta, h, "r"), (laws.DWELL, beta, 0, "d"),
                 (laws.POLYNOMIAL_345, beta, -h, "r")])
    assert cyc.jumps() == []


def test_uniform_velocity_beside_a_dwell_jumps_in_velocity():
    prog = build([(laws.UNIFORM, D(180), 10.0, "r"), (laws.UNIFORM, D(180), -10.0, "r")])
    found = {(j.quantity, round(j.amount, 9)) for j in prog.jumps()}
    v = 10.0 / D(180)
    assert found == {("velocity", round(-2 * v, 9)), ("velocity", round(2 * v, 9))}


def test_time_derivatives_are_the_angle_derivatives_times_powers_of_omega():
    prog = build([(laws.CYCLOIDAL, D(180), 10.0, "r"), (laws.CYCLOIDAL, D(180), -10.0, "r")])
    u = np.radians([20.0, 95.0, 200.0])
    s, ds, dds, ddds = prog.motion(u)
    got = prog.kinematics(u, 3.0)
    assert np.allclose(got, [s, 3 * ds, 9 * dds, 27 * ddds])
    # cycloidal by hand at θ = 20°: x = 1/9, s = h(x − sin 2πx/2π), ds/dθ = h(1 − cos 2πx)/β
    x = 1 / 9
    assert s[0] == pytest.approx(10 * (x - math.sin(2 * math.pi * x) / (2 * math.pi)))
    assert ds[0] == pytest.approx(10 * (1 - math.cos(2 * math.pi * x)) / D(180))


def test_a_polynomial_segment_meets_its_boundary_conditions():
    """A rise of 20 over 120° starting at ds/dθ = 0 and ending at ds/dθ = 5 (length/rad),
    accelerations zero at both ends."""
    spec = parse({"cam": {"base": 50}, "follower": {"contact": "knife"},
                  "program": [{"law": "polynomial", "over": 120, "to": 20,
                               "start": {"ds": 0, "d2s": 0}, "end": {"ds": 5, "d2s": 0}},
                              {"law": "polynomial", "over": 240, "to": 0, "start": {"ds": 5, "d2s": 0},
                               "end": {"ds": 0, "d2s": 0}}]})
    prog = design(spec).cam.program
    s, ds, dds, _ = prog.motion(np.radians([0.0, 120.0, 360.0 - 1e-9]))
    assert s == pytest.approx([0, 20, 0], abs=1e-9)
    assert ds == pytest.approx([0, 5, 0], abs=1e-7) and dds == pytest.approx([0, 0, 0], abs=1e-7)
    assert prog.jumps() == []


BAD = [
    ({"program": [{"law": "dwell", "over": 90}, {"law": "cycloidal", "over": 90, "to": 25},
                  {"law": "cycloidal", "over": 170, "to": 0}]}, "program", "span 350°"),
    ({"program": [{"law": "dwell", "over": 180}, {"law": "cycloid", "over": 180, "to": 0}]}, "program[1].law", "not one of"),
    ({"program": [{"law": "dwell", "over": 180}, {"law": "cycloidal", "over": -180, "to": 0}]}, "program[1].over", "greater than 0"),
    ({"program": [{"law": "cycloidal", "over": 180}, {"law": "cycloidal", "over": 180, "to": 0}]}, "program[0]", "needs 'to'"),
    ({"program": [{"law": "cycloidal", "over": 180, "to": 10}, {"law": "cycloidal", "over": 180, "to": 3}]},
     "program[1].to", "ends at s = 3"),
    ({"program": [{"law": "dwell", "over": 180, "to": 5}, {"law": "dwell", "over": 180}]}, "program[0].to", "dwell"),
    ({"follower": {"contact": "roller"}}, "follower", "needs 'radius'"),
    ({"follower": {"contact": "roller", "radius": 5, "offset": 60}}, "follower.offset", "smaller than"),
    ({"follower": {"motion": "oscillating", "contact": "roller", "radius": 5, "pivot": 200, "arm": 50}},
     "follower.arm", "cannot reach"),
    ({"speed": {"omega": 2, "rpm": 30}}, "speed", "once"),
    ({"colour": "red"}, "colour", "unknown key"),
    ({"cam": {"base": 40, "kind": "translating"}}, "speed.omega", "velocity"),
]


@pytest.mark.parametrize("change,where,words", BAD)
def test_a_bad_cam_file_is_one_error_naming_its_place(change, where, words):
    tree = {"cam": {"base": 40}, "follower": {"contact": "roller", "radius": 10}, "speed": {"omega": 2},
            "program": [{"law": "dwell", "over": 180}, {"law": "cycloidal", "over": 90, "to": 10},
                        {"law": "cycloidal", "over": 90, "to": 0}]}
    tree.update(change)
    with pytest.raises(KinematikaError) as err:
        design(parse(tree))
    assert err.value.where == where and words in err.value.message, (err.value.where, err.value.message)


# --- files -----------------------------------------------------------------------------------

@pytest.fixture(scope="module")
def norton():
    d = load(NORTON)
    return d, CamAnalysis(d.cam, d.speed, d.samples)


def test_the_csv_has_its_columns_and_the_programs_values(norton):
    d, an = norton
    rows = list(csv.reader(io.StringIO(csv_text(an))))
    assert tuple(rows[0]) == COLUMNS and len(rows) == 1 + d.samples
    table = np.array(rows[1:], dtype=float)
    # row at θ = 135°: the middle of the cycloidal rise (x = 1/2): s = h/2, v = 2hω/β, a = 0
    row = table[np.argmin(np.abs(table[:, 0] - 135))]
    omega, beta, h = 2 * math.pi, D(90), 25.0
    assert row[1] == pytest.approx(h / 2) and row[2] == pytest.approx(2 * h / beta * omega)
    assert row[3] == pytest.approx(0, abs=1e-9)
    # θ = 0: the roller's centre right above the cam's centre at R_p = 50, the profile at R_b = 40
    assert table[0, 5:9] == pytest.approx([0, 50, 0, 40], abs=1e-12)


def test_the_svg_is_xml_at_true_size(norton):
    _, an = norton
    root = ET.fromstring(svg_text(an, "mm"))
    assert root.get("width").endswith("mm") and len(root.findall("{http://www.w3.org/2000/svg}path")) >= 2


def test_the_dxf_reads_back_with_its_profile_on_the_cam(norton, tmp_path):
    ezdxf = pytest.importorskip("ezdxf")
    d, an = norton
    path = tmp_path / "cam.dxf"
    write_dxf(an, path, "mm")
    doc = ezdxf.readfile(str(path))
    assert doc.header["$INSUNITS"] == 4
    (profile,) = doc.modelspace().query('LWPOLYLINE[layer=="PROFILE"]')
    assert profile.closed
    pts = np.array([(p[0], p[1]) for p in profile.get_points()])
    assert len(pts) == 1440
    gaps = [np.linalg.norm(d.cam.profile.point(d.cam.profile.nearest(p)) - p) for p in pts[::60]]
    assert max(gaps) < 1e-9
    (circle,) = doc.modelspace().query("CIRCLE")
    assert circle.dxf.radius == pytest.approx(40.0)


# --- the command ------------------------------------------------------------------------------

def run(*args: str, fresh: bool = False) -> subprocess.CompletedProcess:
    """`kinematika cam ARGS` in a process of its own: a fresh `python -m kinematika` with
    `fresh`, else a fork of this process (`fuzz.forks`: the same `cli.main`, its own streams
    and exit status, without the start-up)."""
    if fresh:
        return subprocess.run([sys.executable, "-m", "kinematika", "cam", *args], capture_output=True,
                              text=True, cwd=ROOT, timeout=600)
    done = run_forked(["cam", *args], cwd=ROOT)
    return subprocess.CompletedProcess(done.args, done.status, done.stdout, done.stderr)


def test_the_command_summarises_warns_and_writes(tmp_path):
    done = run(str(SHM), "--json", "--csv", str(tmp_path / "c.csv"))
    assert done.returncode == 0, done.stderr
    data = json.loads(done.stdout)
    assert {"pressure_angle", "pitch_radius", "profile_radius", "undercut", "jumps", "warnings"} <= set(data)
    assert len(data["jumps"]) == 4 and all(w["where"].startswith("program[") for w in data["warnings"])
    # the SHM jump in time units: π²h/(2β²)·ω² = 50·4π² mm/s²
    assert abs(data["jumps"][0]["amount"]) == pytest.approx(50 * 4 * math.pi**2)
    assert (tmp_path / "c.csv").stat().st_size > 0
    # a new process prints nothing but the summary, and draws its figure
    text = run(str(NORTON), "--plot", str(tmp_path / "p.png"), fresh=True)
    assert text.returncode == 0 and "largest pressure angle" in text.stdout and text.stderr == ""
    assert (tmp_path / "p.png").read_bytes()[:4] == b"\x89PNG"


def test_the_commands_errors_are_one_line_with_status_2(tmp_path):
    bad = tmp_path / "bad.yaml"
    bad.write_text("cam: {base: 40}\nfollower: {contact: roller, radius: 10}\nprogram:\n"
                   "  - {law: dwell, over: 90}\n  - {law: cycloidal, over: 90, to: 25}\n"
                   "  - {law: 3-4-5, over: 90, to: 0}\n")
    for args, words in (([str(bad)], "error (schema): program: the segments span 270°"),
                        ([str(NORTON), "--plot", str(tmp_path / "p.txt")], "error (usage)")):
        done = run(*args)
        lines = done.stderr.strip().splitlines()
        assert done.returncode == 2 and len(lines) == 1 and lines[0].startswith(words), done.stderr
    with pytest.raises(KinematikaError) as err:
        load(tmp_path / "none.yaml")
    assert err.value.kind == "syntax" and "none.yaml" in err.value.where
