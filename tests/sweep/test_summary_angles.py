"""One angle convention in the sweep's text summary and its plot (issue 35): a body's angle θ
is its line's from the x axis, counter-clockwise, in both; every place along the motion
(`at`, limit positions, the worst transmission angle) is the crank's angle θ, the plot's
horizontal axis; and the `at` of a steady maximum says so instead of "-".

The offset slider-crank of the page's template, by hand: crank OA = r = 0.05 at θ = 30°,
rod AB = l = 0.15, the slider's line y = −e = −0.02, B ahead. The rod's angle is
φ = −asin((r sin θ + e)/l): at θ = 90° −asin(0.07/0.15) = −27.818°, at θ = 270°
−asin(−0.03/0.15) = +11.537°. Limit positions, crank and rod in line with B on y = −0.02:
extended |OB| = l + r = 0.2, so OB points at asin(−0.02/0.2) = −5.739°, the crank too:
θ = 354.26°; folded |OB| = l − r = 0.1 at asin(−0.02/0.1) = −11.537°, the crank opposite:
θ = 168.46°. The transmission angle (between rod and slider line, 90° − |φ|) is worst
where |φ| is largest, at θ = 90°.
"""
from __future__ import annotations

import math
import re

import pytest
from typer.testing import CliRunner

from kinematika.cli import app
from kinematika.draw.plots import read_sweep
from kinematika.sweep import run_sweep
from kinematika.web.templates import template

R, L, E = 0.05, 0.15, 0.02


@pytest.fixture(scope="module")
def printed(tmp_path_factory) -> str:
    path = tmp_path_factory.mktemp("sc") / "slider_crank.yaml"
    path.write_text(template("slider_crank"))
    out = CliRunner().invoke(app, ["sweep", str(path)])
    assert out.exit_code == 0, out.output
    return out.stdout


def row(text: str, name: str) -> list[str]:
    line = next(x for x in text.splitlines() if x.startswith(name + " "))
    return re.split(r"\s{2,}", line.strip())


def test_the_summary_gives_the_plots_angles(printed):
    phi = lambda th: -math.degrees(math.asin((R * math.sin(math.radians(th)) + E) / L))
    assert (round(phi(90), 3), round(phi(270), 3)) == (-27.818, 11.537)
    assert row(printed, "rod")[1] == f"{phi(90):.5g} .. {phi(270):.5g}"
    assert row(printed, "crank")[1] == "30 .. 390"                        # θ, the plot's axis
    assert "angle θ: a body's line from the x axis, counter-clockwise" in printed
    assert "at: the crank angle θ (deg)" in printed
    import yaml

    reading = read_sweep(run_sweep(yaml.safe_load(template("slider_crank"))))
    assert reading.xlabel == "crank angle θ (deg)"
    assert (reading.x[0], reading.x[-1]) == pytest.approx((30, 390))
    rod = next(s for p in reading.panels if p.quantity == "angle" for s in p.series if s.name == "rod")
    assert (rod.values.min(), rod.values.max()) == pytest.approx((phi(90), phi(270)), abs=1e-9)
    assert next(p.ylabel for p in reading.panels if p.quantity == "angle") == "angle θ (deg)"


def test_places_along_the_motion_are_the_cranks_angle(printed):
    extended = 360 + math.degrees(math.asin(-E / (L + R)))
    folded = 180 + math.degrees(math.asin(-E / (L - R)))
    assert (round(extended, 2), round(folded, 2)) == (354.26, 168.46)
    assert f"limit position (extended): crank at θ = {extended:.4g} deg" in printed
    assert f"limit position (folded): crank at θ = {folded:.4g} deg" in printed
    assert printed.rstrip().endswith("worst 62.18 deg at 90 deg")          # 90° − 27.818°
    # B's top speed, by hand along the slider's line: ẋ_B = −rω(sin θ + cos θ tan φ), at
    # its largest on the crank's 1° grid
    speed = lambda th: abs(R * 10 * (math.sin(th) + math.cos(th) * math.tan(
        math.asin((R * math.sin(th) + E) / L))))
    best = max(range(30, 391), key=lambda d: speed(math.radians(d)))
    assert row(printed, "B@rod")[2] == str(best)


def test_a_steady_maximum_is_said_constant(printed):
    assert row(printed, "A@crank")[1:] == ["0.5", "constant", "5", "constant"]   # rω, rω²
    at_columns = [row(printed, p)[2] for p in ("O@crank", "A@crank", "B@rod")]
    assert "-" not in at_columns
