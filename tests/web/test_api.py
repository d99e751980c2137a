"""The page's JSON API answers exactly what the command line prints (the contract's
section "The page's JSON API"), for every bundled example, and refuses bad requests with
the contract's error JSON."""
from __future__ import annotations

import json
import math

import pytest
from typer.testing import CliRunner

from kinematika.cli import app as cli       # the typer application, every command registered
from tests.conftest import DEEP, EXAMPLES

pytestmark = pytest.mark.early      # minutes of work: handed to a worker before the shorter files (tests/conftest.py)

EXAMPLE_FILES = sorted(EXAMPLES.glob("*.yaml"))
# an explanation is seconds of work, written twice here; a run checks one model of each
# kind of explanation (linkage, rolling, cam, vehicle, spatial, symbols: the epicyclic
# train, symbolic, is seconds more), a deep run (KINEMATIKA_DEEP=1) every example;
# tests/explain reads one of each kind in every language (every one in a deep run)
EXPLAINED = EXAMPLE_FILES if DEEP else [
    EXAMPLES / f"{name}.yaml" for name in (
        "four_bar", "seed_001_rolling_pair", "cam_roller_follower",
        "tractor_trailer", "spherical_four_bar", "fan_symbolic")]
RUNNER = CliRunner()


def run_cli(*args: str) -> tuple[int, bytes]:
    result = RUNNER.invoke(cli, list(args))
    return result.exit_code, result.stdout_bytes


def post(client, endpoint: str, **body):
    return client.post(f"/api/{endpoint}", json=body)


@pytest.mark.parametrize("path", EXPLAINED, ids=lambda p: p.stem)
def test_explanation_is_the_cli_html(client, path):
    code, printed = run_cli("explain", str(path), "--format", "html", "--lang", "eu")
    answer = post(client, "explain", model=path.read_text(encoding="utf-8"), lang="eu")
    assert code == 0 and answer.status_code == 200
    assert answer.headers["content-type"] == "text/html; charset=utf-8"
    assert answer.content == printed


def test_sweep_options_mean_what_the_cli_options_mean(client, tmp_path):
    path = EXAMPLES / "four_bar.yaml"
    code, printed = run_cli("sweep", str(path), "--json", "--by", "90", "--steps", "9", "--skip-bad")
    answer = post(client, "sweep", model=path.read_text(), by=90, steps=9, skip_bad=True)
    assert code == 0 and answer.content == printed
    rows = answer.json()
    assert rows["coordinate"] == [10.0 * k for k in range(10)]
    # the crank of length 1 turning at 10 rad/s: its pin A moves at 10, at 90° + 10k
    for k, (vx, vy) in enumerate(rows["points"]["A@crank"]["velocity"]):
        theta = 3.141592653589793 / 180 * (90 + 10 * k)
        assert vx == pytest.approx(-10 * __import__("math").sin(theta), abs=1e-9)
        assert vy == pytest.approx(10 * __import__("math").cos(theta), abs=1e-9)
    csv_path = tmp_path / "rows.csv"
    run_cli("sweep", str(path), "--by", "90", "--steps", "9", "--csv", str(csv_path))
    as_csv = post(client, "sweep", model=path.read_text(), by=90, steps=9, **{"as": "csv"})
    assert as_csv.status_code == 200 and as_csv.headers["content-type"].startswith("text/csv")
    assert as_csv.content == csv_path.read_bytes()


def test_set_gives_parameters_values_as_the_option_does(client):
    text = (EXAMPLES / "four_bar.yaml").read_text()
    answer = post(client, "solve", model=text, set={"w2": 20}).json()
    # A is at (0, 1) on the crank: v_A = ω × r = 20 · (−1, 0)
    assert answer["points"]["A@crank"]["velocity"] == [-20.0, 0.0]
    assert answer["bodies"]["crank"]["omega"] == 20.0


def test_formats_are_read_as_the_cli_reads_files(client):
    text = json.dumps({"points": {"O": [0, 0], "A": [1, 0]},
                       "bodies": {"ground": ["O"], "bar": ["O", "A"]},
                       "joints": [{"type": "revolute", "bodies": ["ground", "bar"], "at": "O"}],
                       "drivers": [{"omega": "bar", "value": 2}]})
    as_json = post(client, "solve", model=text, format="json").json()
    assert as_json["points"]["A@bar"]["velocity"] == [0.0, 2.0]
    toml = ('[points]\nO = [0, 0]\nA = [1, 0]\n[bodies]\nground = ["O"]\nbar = ["O", "A"]\n'
            '[[joints]]\ntype = "revolute"\nbodies = ["ground", "bar"]\nat = "O"\n'
            '[[drivers]]\nomega = "bar"\nvalue = 2\n')
    assert post(client, "solve", model=toml, format="toml").json() == as_json


@pytest.mark.parametrize("body, kind, where", [
    ({"model": "points: {A: [0, 0]"}, "syntax", "<text>"),
    ({"model": "points: {A: [0, 0]}\nbodies: {ground: [A]}\nfoo: 1\n"}, "schema", None),
    ({"model": "x: 1", "format": "xml"}, "usage", "format"),
    ({"model": "x: 1", "colour": "red"}, "usage", "colour"),
    ({"format": "yaml"}, "usage", "model"),
    ({"model": "x: 1", "set": [1, 2]}, "usage", "set"),
    ({"model": "x: 1", "assembly": "two"}, "usage", "assembly"),
    ({"model": "x: 1", "lang": "fr"}, "usage", "lang"),
])
def test_bad_requests_answer_400_with_the_contract_error(client, body, kind, where):
    answer = client.post("/api/solve", json=body)
    assert answer.status_code == 400
    error = answer.json()["error"]
    assert set(error) == {"kind", "message", "where"}
    assert error["kind"] == kind and error["message"]
    if where is not None:
        assert error["where"] == where


def test_a_body_over_the_limit_answers_413(client):
    from kinematika import limits

    big = json.dumps({"model": "#" * (limits.REQUEST_BYTES + 10)})
    answer = client.post("/api/solve", content=big, headers={"content-type": "application/json"})
    assert answer.status_code == 413
    assert answer.json()["error"]["kind"] == "syntax"


def test_only_json_bodies_are_read(client):
    answer = client.post("/api/solve", content=b'{"model": "x: 1"}', headers={"content-type": "text/plain"})
    assert answer.status_code == 415
    assert answer.json()["error"]["where"] == "request"


def test_draw_gives_the_scene_as_data_and_the_figure_as_svg_or_png(client):
    text = (EXAMPLES / "four_bar.yaml").read_text()
    scene = post(client, "draw", model=text, centres=True).json()
    assert scene["input"] == {"joint": "j1", "unit": "deg"}
    assert scene["bodies"]["crank"]["points"] == {"O2": [0.0, 0.0], "A": [0.0, 1.0]}
    # every centre of the four bodies: 4·3/2 = 6, the ones from Kennedy with their lines
    assert len([m for m in scene["marks"] if m["kind"] == "icr"]) == 6
    assert scene["kennedy"]
    v_b = next(v for v in scene["vectors"] if v["kind"] == "velocity" and v["relative_to"] is None)
    assert v_b["label"][:2] == [{"t": "v"}, {"sub": "B"}]
    svg = post(client, "draw", model=text, **{"as": "svg"})
    assert svg.headers["content-type"] == "image/svg+xml" and b"<svg" in svg.content
    png = post(client, "draw", model=text, **{"as": "png"})
    assert png.headers["content-type"] == "image/png" and png.content[:8] == b"\x89PNG\r\n\x1a\n"


def test_draw_and_explain_write_the_figures_numbers_in_the_asked_language(client):
    """`lang` means what `draw --lang` means: the four-bar's |v_B| = 9.252 (by hand: the
    loop closure in tests/draw/test_languages.py) is 9,25 in a Basque figure, 9.25 without
    a language; the Basque explanation embeds the figures drawn in Basque."""
    from kinematika import solve
    from kinematika.explain import build
    from kinematika.explain.render.svg import embedded
    from tests.draw.test_languages import drawings, texts

    text = (EXAMPLES / "four_bar.yaml").read_text()
    eu = post(client, "draw", model=text, lang="eu", **{"as": "svg"}).text
    plain = post(client, "draw", model=text, **{"as": "svg"}).text
    assert r"$v_{\mathrm{B}}$ = 9,25" in texts(eu) and r"$v_{\mathrm{B}}$ = 9.25" in texts(plain)
    assert "9,25" in json.dumps(post(client, "draw", model=text, lang="es").json()["vectors"], ensure_ascii=False)
    page = post(client, "explain", model=text, lang="eu").text
    first = drawings(build(solve(EXAMPLES / "four_bar.yaml")).sections)[0]
    assert embedded(first.svg("eu"), "d1") in page and embedded(first.svg("en"), "d1") not in page


def test_a_3d_scene_gives_what_it_draws_in_model_coordinates(client):
    """The spherical four-bar as stated in its file: the drawn points are the file's points,
    the scene's projection takes them to the page, and its links are arcs on the unit
    sphere about O."""
    text = (EXAMPLES / "spherical_four_bar.yaml").read_text()
    scene = post(client, "draw", model=text).json()
    c30, s30 = math.cos(math.radians(30)), math.sin(math.radians(30))
    stated = {"O": [0, 0, 0], "A": [0, s30, c30], "B": [0.738834276689, 0.673861538519, 0.005876695946],
              "D": [c30, 0, s30]}                                  # D = (sin 60°, 0, cos 60°)
    P = scene["projection"]
    assert len(P) == 2 and all(len(row) == 3 for row in P)
    assert sum(a * b for a, b in zip(*P)) == pytest.approx(0, abs=1e-12)      # orthonormal rows
    assert [math.hypot(*row) for row in P] == pytest.approx([1, 1])
    arcs = 0
    for body in scene["bodies"].values():
        for name, xyz in body["points_xyz"].items():
            assert xyz == pytest.approx(stated[name], abs=1e-9)
            assert [sum(r * x for r, x in zip(row, xyz)) for row in P] == \
                pytest.approx(body["points"][name], abs=1e-12)
        for line, page in zip(body["skeleton_xyz"], body["skeleton"], strict=True):
            assert [math.hypot(*x) for x in line] == pytest.approx([1] * len(line))
            assert len(line) == len(page)
            arcs += 1
    assert arcs >= 4
    assert "projection" not in post(client, "draw", model=(EXAMPLES / "four_bar.yaml").read_text()).json()


def four_bar_b() -> tuple[float, float]:
    """The four-bar's B by hand: |AB| = 4 from A = (0, 1), |O4B| = 3 from O4 = (4, 0), the
    upper of the two points."""
    ax, ay, ox, b, c = 0.0, 1.0, 4.0, 4.0, 3.0
    d = math.hypot(ox - ax, ay)
    along = (b * b - c * c + d * d) / (2 * d)
    h = math.sqrt(b * b - along * along)
    ux, uy = (ox - ax) / d, (0 - ay) / d
    return max(((ax + along * ux - s * h * uy, ay + along * uy + s * h * ux) for s in (1, -1)),
               key=lambda q: q[1])


def test_draw_gives_each_bodys_reference_line_as_the_sweep_measures_it(client):
    """The four-bar by hand: the crank O2A from its pivot O2 = (0, 0) to A = (0, 1), at 90°;
    the rocker from its pivot O4 = (4, 0) to B (|AB| = 4, |O4B| = 3, the upper point), not
    B → O4 as its points are listed; the coupler from its first point A (no pivot)."""
    scene = post(client, "draw", model=(EXAMPLES / "four_bar.yaml").read_text()).json()
    ax, ay, ox = 0.0, 1.0, 4.0
    bx, by = four_bar_b()
    bodies = scene["bodies"]
    assert bodies["ground"]["reference"] is None
    assert bodies["crank"]["reference"] == {"from": "O2", "to": "A", "grounded": True, "angle": pytest.approx(90.0)}
    assert bodies["rocker"]["reference"] == {"from": "O4", "to": "B", "grounded": True,
                                             "angle": pytest.approx(math.degrees(math.atan2(by, bx - ox)))}
    assert bodies["coupler"]["reference"] == {"from": "A", "to": "B", "grounded": False,
                                              "angle": pytest.approx(math.degrees(math.atan2(by - ay, bx - ax)))}


def test_draw_gives_the_picture_for_the_frame_asked(client):
    """The page's picture: the four-bar's marks (its pins at the joints' places, O2 = (0, 0)
    and A = (0, 1) by construction), and, for a frame asked around the mechanism, the far
    centre I13 (on the crank's line x = 0 and the rocker's line O4B, far above) marked by an
    arrow inside that frame, pointing at it."""
    text = (EXAMPLES / "four_bar.yaml").read_text()
    picture = post(client, "draw", model=text, centres=True).json()["picture"]
    pins = [m["points"][0] for m in picture["marks"] if m["kind"] == "dot" and m.get("id", "").startswith("joint:")]
    assert [0.0, 0.0] in pins and [0.0, 1.0] in pins
    frame = [-1.0, -1.0, 6.0, 5.0]
    asked = post(client, "draw", model=text, centres=True, frame=frame).json()["picture"]
    assert asked["frame"] == frame
    far = next(m for m in asked["marks"] if m.get("id") == "centre:ground-coupler:far")
    (x0, y0), (x1, y1) = far["points"]
    bx, by = four_bar_b()
    i13 = (0.0, 4.0 / (4.0 - bx) * by)                     # O4 + t (B − O4) where x = 0
    assert all(frame[0] < x < frame[2] for x in (x0, x1)) and all(frame[1] < y < frame[3] for y in (y0, y1))
    assert (x1 - x0) * (i13[1] - y1) - (y1 - y0) * (i13[0] - x1) == pytest.approx(0, abs=1e-9)
    assert (x1 - x0) * (i13[0] - x1) + (y1 - y0) * (i13[1] - y1) > 0
    for bad in ([0, 0, 1], [1, 0, 0, 1], [0, 0, "1", 1]):
        answer = post(client, "draw", model=text, frame=bad)
        assert answer.status_code == 400 and answer.json()["error"]["where"] == "frame"


def test_a_3d_pictures_moving_marks_have_their_places_in_space(client):
    """The spherical four-bar: each moving mark drawn at a point of the file has that point
    in space (`xyz`), which the projection takes back to the mark's place on the page."""
    scene = post(client, "draw", model=(EXAMPLES / "spherical_four_bar.yaml").read_text()).json()
    P = scene["projection"]
    lifted = [m for m in scene["picture"]["marks"] if m.get("xyz")]
    assert lifted
    for m in lifted:
        for xyz, page in zip(m["xyz"], m["points"], strict=True):
            assert [sum(r * x for r, x in zip(row, xyz)) for row in P] == pytest.approx(page, abs=1e-9)


def test_the_page_and_its_files_are_served_with_a_strict_policy(client):
    page = client.get("/")
    assert page.status_code == 200 and 'data-testid="figure"' in page.text
    assert "script-src 'self'" in page.headers["content-security-policy"]
    assert client.get("/static/js/main.js").status_code == 200
    start = client.get("/api/start").json()
    assert "four_bar.yaml" in start["examples"]
    example = client.get("/api/examples/four_bar.yaml").json()
    assert example["model"] == (EXAMPLES / "four_bar.yaml").read_text()
    assert client.get("/api/examples/..%2Fpyproject.toml").status_code == 404


def test_requests_to_another_host_name_are_refused():
    from starlette.testclient import TestClient

    from kinematika.web.server import create_app

    local = TestClient(create_app(hosts=["127.0.0.1", "localhost"]), base_url="http://127.0.0.1")
    assert local.get("/").status_code == 200
    assert local.get("/", headers={"host": "attacker.example"}).status_code == 400


def test_answers_kept_for_identical_requests_are_bounded():
    from kinematika.web.server import Answers

    kept = Answers(limit=1000)
    for k in range(30):
        kept.put(("solve", b"x" * 10 + bytes([k])), (200, "application/json", b"y" * 89))
    assert kept.size <= 1000 and len(kept.kept) == 10            # 100 bytes each: the last ten
    assert kept.get(("solve", b"x" * 10 + bytes([29]))) is not None
    assert kept.get(("solve", b"x" * 10 + bytes([0]))) is None
    kept.put(("sweep", b"z"), (200, "application/json", b"w" * 500))   # over an eighth: not kept
    assert kept.get(("sweep", b"z")) is None


def test_a_repeated_request_gets_the_same_answer(client):
    text = (EXAMPLES / "slider_crank.yaml").read_text()
    first = post(client, "sweep", model=text, steps=12)
    again = post(client, "sweep", model=text, steps=12)
    assert first.status_code == again.status_code == 200 and first.content == again.content


def test_assemblies_and_a_chosen_one_are_the_cli_answers(client):
    path = EXAMPLES / "four_bar.yaml"
    code, printed = run_cli("assemblies", str(path), "--json")
    answer = post(client, "assemblies", model=path.read_text())
    assert code == 0 and answer.content == printed
    assert [a["drawn"] for a in answer.json()["assemblies"]] == [True, False]
    # the other assembly: B mirrored in the line A O4 (A = (0, 1), O4 = (4, 0))
    code, printed = run_cli("solve", str(path), "--assembly", "2", "--json")
    crossed = post(client, "solve", model=path.read_text(), assembly=2)
    assert code == 0 and crossed.content == printed
    b = crossed.json()["points"]["B@rocker"]["position"]
    b0 = json.loads(run_cli("solve", str(path), "--json")[1])["points"]["B@rocker"]["position"]
    a, o4 = (0.0, 1.0), (4.0, 0.0)
    dx, dy = o4[0] - a[0], o4[1] - a[1]
    t = ((b0[0] - a[0]) * dx + (b0[1] - a[1]) * dy) / (dx * dx + dy * dy)
    foot = (a[0] + t * dx, a[1] + t * dy)
    assert b == pytest.approx([2 * foot[0] - b0[0], 2 * foot[1] - b0[1]], abs=1e-9)


def test_move_answers_as_the_option_does(client):
    path = EXAMPLES / "four_bar.yaml"
    for endpoint in ("solve", "centres"):
        code, printed = run_cli(endpoint, str(path), "--move", "j1=90", "--json")
        answer = post(client, endpoint, model=path.read_text(), move={"j1": 90})
        assert code == 0 and answer.content == printed
    moved = post(client, "solve", model=path.read_text(), move={"j1": 90}).json()
    # the crank turned from 90° to 180°: A = (−1, 0), v_A = 10·(0, −1)
    assert moved["points"]["A@crank"]["position"] == pytest.approx([-1.0, 0.0], abs=1e-12)
    assert moved["points"]["A@crank"]["velocity"] == pytest.approx([0.0, -10.0], abs=1e-9)
    code, printed = run_cli("explain", str(path), "--move", "j1=90", "--format", "html", "--lang", "eu")
    assert post(client, "explain", model=path.read_text(), move={"j1": 90}, lang="eu").content == printed


def test_drawing_endpoints_at_the_same_time(client):
    """matplotlib is not thread-safe (its mathtext parser fails when two threads parse at
    once): explanations and figures asked together all answer, each as asked alone."""
    from concurrent.futures import ThreadPoolExecutor

    text = (EXAMPLES / "four_bar.yaml").read_text(encoding="utf-8")
    asks = [("explain", {"lang": lang, "move": {"j1": move}}) for lang in ("en", "eu") for move in (30, 90)]
    asks += [("draw", {"as": "svg", "move": {"j1": 45}}), ("draw", {"as": "png"})]
    with ThreadPoolExecutor(len(asks)) as pool:
        answers = list(pool.map(lambda ask: post(client, ask[0], model=text, **ask[1]), asks))
    assert [a.status_code for a in answers] == [200] * len(asks)
    alone = post(client, "explain", model=text, lang="eu", move={"j1": 90})
    assert answers[3].content == alone.content


def test_the_figure_of_a_model_with_symbols_keeps_the_budget_of_solve(client, monkeypatch):
    """The page's figure of Jansen's leg in its crank angle is solved exactly within the
    budget of `solve`: past it, the same `limit` error (it was drawn without any budget).
    Jansen's leg drawn within the budget is ten seconds of exact work: a default run draws
    the four-bar in its crank angle so, a deep run the leg."""
    text = (EXAMPLES / "jansen_leg.yaml").read_text().replace("  theta: deg(90)", "  theta: null")
    monkeypatch.setenv("KINEMATIKA_SYMBOLIC_SECONDS", "0.05")
    answer = post(client, "draw", model=text, **{"as": "data"})
    assert answer.status_code == 400 and answer.json()["error"]["kind"] == "limit"
    monkeypatch.delenv("KINEMATIKA_SYMBOLIC_SECONDS")
    if not DEEP:
        text = (EXAMPLES / "four_bar.yaml").read_text().replace("  theta2: deg(90)", "  theta2: null")
        assert "theta2: null" in text
    answer = post(client, "draw", model=text, **{"as": "data"})
    assert answer.status_code == 200 and answer.json()["bodies"]


@pytest.mark.parametrize("lang", ["en", "ca"])
def test_a_figure_that_names_its_bodies_does_not_number_them(client, lang):
    """C5-1.4 names its bodies per language (`names:`): its centres are I_carrier,
    I_portador, so the page's scene numbers no body and lists no numbering."""
    text = (EXAMPLES / "seed_c5_1_4_epicyclic.yaml").read_text()
    scene = post(client, "draw", model=text, lang=lang, centres=True).json()
    assert not scene["numbered"] and scene["numbering"] == []
    assert not [n for n in scene["notes"] if n.startswith("bodies:")]


def test_a_numbered_figures_bodies_are_listed_once(client):
    """The four-bar names no body in a language: its centres are I_13, so the page's scene
    lists the numbering once (the frame 1, then the file's order), not again among its notes."""
    text = (EXAMPLES / "four_bar.yaml").read_text()
    scene = post(client, "draw", model=text, lang="en", centres=True).json()
    assert scene["numbered"] and scene["numbering"] == [[1, "ground"], [2, "crank"], [3, "coupler"], [4, "rocker"]]
    assert not [n for n in scene["notes"] if n.startswith("bodies:")]
