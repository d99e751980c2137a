"""Files, Jupyter, symbolic models and 3D projection."""
from __future__ import annotations

import xml.etree.ElementTree as ET

import numpy as np
import pytest

from kinematika import Mechanism, solve
from kinematika.draw import DrawOptions, draw, svg
from kinematika.draw.jupyter import model_svg
from kinematika.model.overrides import with_parameters
from kinematika.draw.projection import projection
from kinematika.errors import KinematikaError

from .artists import angle_between, arrow, marker
from .mechanisms import coupler_icr, four_bar_tree, xy


def test_svg_holds_the_asked_results_by_id(tmp_path):
    path = tmp_path / "four_bar.svg"
    draw(four_bar_tree([{"velocity": "B"}, {"acceleration": "P"}, {"icr": "coupler"}]), path)
    ids = {el.get("id") for el in ET.parse(path).iter() if el.get("id")}
    assert {"velocity:B@coupler", "acceleration:P@coupler", "icr:coupler"} <= ids


def test_svg_text_of_a_solution_with_options():
    """What explanations embed: the SVG of a Solution, drawn with the given options."""
    sol = solve(four_bar_tree([{"velocity": "B"}]))
    text = svg(sol, DrawOptions(centres=True, accelerations=True))
    root = ET.fromstring(text.encode())
    ids = {el.get("id") for el in root.iter() if el.get("id")}
    assert root.tag.endswith("svg")
    assert {"velocity:B@coupler", "acceleration:B@coupler", "centre:ground-coupler"} <= ids
    assert 'id="acceleration:B@coupler"' not in svg(sol)      # the default asks velocities only


def test_svg_text_is_reproducible():
    """The same figure twice is the same bytes (no date, no random clip-path ids), so that an
    explanation's HTML from the CLI and from the page's API are byte for byte equal."""
    sol = solve(four_bar_tree([{"velocity": "B"}]))
    first, second = svg(sol), svg(sol)
    assert "clip-path" in first and "<dc:date>" not in first
    assert first == second


def test_bare_svg_is_the_drawing_alone():
    """For a page that embeds the figure and says its title, legend and notes in its own
    language: no title, legend or notes, and a shorter figure."""
    sol = solve(four_bar_tree([{"velocity": "B"}]))
    full, bare = svg(sol), svg(sol, bare=True)
    assert "<!-- velocity -->" in full and "<!-- velocity -->" not in bare
    height = lambda text: float(ET.fromstring(text.encode()).get("height").rstrip("pt"))
    assert height(bare) < height(full) - 30
    assert 'id="velocity:B@coupler"' in bare


@pytest.mark.parametrize("suffix, magic", [(".png", b"\x89PNG"), (".pdf", b"%PDF")])
def test_png_and_pdf(tmp_path, suffix, magic):
    path = tmp_path / f"f{suffix}"
    draw(four_bar_tree(), path)
    assert path.read_bytes()[:4] == magic


def test_unknown_format_is_refused(tmp_path):
    with pytest.raises(ValueError, match=r"\.png, \.svg or \.pdf"):
        draw(four_bar_tree(), tmp_path / "f.bmp")


def _slider_crank_builder() -> Mechanism:
    m = Mechanism("Builder slider-crank", parameters={"w": 10})
    m.points(O=(0, 0), A=(0.1, 0.05), B=(0.4, 0))
    m.body("ground", "O"); m.body("crank", "O", "A"); m.body("rod", "A", "B"); m.body("slider", "B")
    m.revolute("ground", "crank", at="O"); m.revolute("crank", "rod", at="A")
    m.revolute("rod", "slider", at="B"); m.prismatic("ground", "slider", along=(1, 0))
    return m


def test_jupyter_shows_solutions_and_unfinished_mechanisms():
    m = _slider_crank_builder()
    unfinished = m._repr_svg_()               # no driver yet: geometry and the reason
    assert unfinished.startswith("<?xml") and "not solved" in unfinished
    m.drive_omega("crank", "w")
    assert 'id="velocity:B@rod"' in m._repr_svg_()
    assert 'id="velocity:B@rod"' in m.solve()._repr_svg_()
    assert model_svg(m.to_model()) is not None


def test_symbolic_model_is_drawn_at_its_probe_values_and_says_so():
    tree = four_bar_tree([{"icr": "coupler"}])
    tree["parameters"]["w2"] = None
    sol = solve(tree)
    fig = draw(sol)
    notes = " ".join(t.get_text() for t in fig.texts)
    assert f"w2 = {next(iter(sol.inst.probe.values())):.3g}" in notes
    assert np.allclose(marker(fig, "icr:coupler"), xy(coupler_icr()), atol=1e-9)  # geometry only


def test_set_gives_symbols_numbers():
    from kinematika.api import as_model

    tree = four_bar_tree([{"velocity": "B"}])
    tree["parameters"]["w2"] = None
    model = with_parameters(as_model(tree), {"w2": "2*5"})
    sol = solve(model)
    assert not sol.symbolic and sol.omega("crank") == pytest.approx(10.0)
    with pytest.raises(KinematikaError, match="unknown parameter 'q'"):
        with_parameters(as_model(tree), {"q": "1"})


FAN = {
    "name": "Fan", "dimension": 3,
    "points": {"B": [0, 0, 0], "C": [0.6, 0, 0], "P": [0.6, 0.3, 0]},
    "bodies": {"ground": ["B"], "shaft": ["B", "C"], "blades": ["C", "P"]},
    "joints": [{"type": "revolute", "bodies": ["ground", "shaft"], "at": "B", "axis": [0, 1, 0]},
               {"type": "revolute", "bodies": ["shaft", "blades"], "at": "C", "axis": [1, 0, 0]}],
    "drivers": [{"omega": "shaft", "value": [0, 0.1, 0]},
                {"omega": "blades", "relative_to": "shaft", "value": [0.5, 0, 0]}],
    "ask": [{"velocity": "P"}, {"velocity": "C"}],
}


@pytest.mark.parametrize("view", ["iso", "front"])
def test_3d_vectors_are_projected_like_the_drawing(view):
    """v_P = ω × BP with ω = (0.5, 0.1, 0): (0, 0, 0.09), straight up the page (z up)."""
    fig = draw(FAN, view=view)
    proj = projection(3, view)
    start, tip = arrow(fig, "velocity:P@blades")
    assert np.allclose(start, proj((0.6, 0.3, 0)), atol=1e-9)
    assert angle_between(tip - start, (0.0, 1.0)) < 1e-3
    c0, c1 = arrow(fig, "velocity:C@shaft")         # v_C = (0, 0.1, 0) × (0.6, 0, 0) = (0, 0, −0.06)
    assert angle_between(c1 - c0, (0.0, -1.0)) < 1e-3


def test_isometric_axes_are_120_degrees_apart():
    axes = projection(3, "iso").axes()
    for a, b in (("x", "y"), ("y", "z"), ("z", "x")):
        assert angle_between(axes[a], axes[b]) == pytest.approx(120.0)
    assert np.allclose(axes["z"] / np.linalg.norm(axes["z"]), (0, 1))


def test_svg_ids_do_not_depend_on_the_hash_salt():
    """matplotlib's ids hash `svg.hashsalt`, a global that another thread's rc_context can
    undo while a figure is saved (the page's server renders while a command runs): the ids
    are numbered instead, so any salt gives the same text."""
    import io

    import matplotlib

    from kinematika.draw.figure import _numbered_ids, render
    from kinematika.draw.build import build_scene

    sol = solve(four_bar_tree([{"velocity": "B"}]))
    fig = render(build_scene(sol.inst, sol, DrawOptions(centres=True)), DrawOptions(centres=True))
    texts = []
    for salt in ("one", "two"):
        out = io.StringIO()
        with matplotlib.rc_context({"svg.hashsalt": salt}):
            fig.savefig(out, format="svg", metadata={"Date": None})
        texts.append(out.getvalue())
    assert texts[0] != texts[1] and 'id="m' in texts[0]        # markers named by the salted hash
    assert _numbered_ids(texts[0]) == _numbered_ids(texts[1])
