"""`kinematika exercise` and `kinematika grade` on the command line, the folder they share,
and the printable sheets and key."""
from __future__ import annotations

import csv
import json
import re

import pytest
from typer.testing import CliRunner

from kinematika.cli import app
from kinematika.exercise.catalogue import catalogue

from .conftest import COUNT, FOUR_BAR, P_PAIR

runner = CliRunner()


def test_the_folder_holds_the_contracts_files(folders, p_pair_exercise):
    folder = folders["p_pair"]
    names = {p.name for p in folder.iterdir()}
    assert {"variants.csv", "key.csv", "quiz.xml", "sheets.html", "key.html", "exercise.json",
            "p_pair_coriolis.yaml", "figures"} <= names
    assert len(list((folder / "figures").glob("variant-*.png"))) == COUNT
    info = json.loads((folder / "exercise.json").read_text())
    assert info == {"model": "p_pair_coriolis.yaml", "vary": ["s=300:500:10", "beta=20:40:1", "w=2:6:0.5"],
                    "count": COUNT, "seed": 7, "lang": "en"}


def test_grade_reads_the_folder_back_and_prints_the_contracts_json(folders, p_pair_exercise, tmp_path):
    v = p_pair_exercise.variants[4]
    rows = {r.question: r.value for r in v.rows}
    answers = tmp_path / "answers.csv"
    answers.write_text("student,variant,question,value\n"
                       f"ana,5,q1,{rows['q1']}\nana,5,q2,{-rows['q2']}\nbo,5,q3.x,{rows['q3.y']}\n"
                       f"bo,5,q3.y,{rows['q3.x']}\n", encoding="utf-8")
    book = tmp_path / "grades.csv"
    done = runner.invoke(app, ["grade", str(folders["p_pair"]), str(answers), "--json", "--gradebook", str(book)])
    assert done.exit_code == 0, done.output
    result = json.loads(done.stdout)
    ana = result["students"]["ana"]
    assert ana["score"] == pytest.approx(1 / 6, abs=1e-6)          # q1 of six questions that weigh the same
    assert ana["answers"][0] == {"variant": 5, "question": "q1", "typed": str(rows["q1"]), "value": rows["q1"],
                                 "correct": True, "diagnosis": None}
    assert ana["answers"][1]["correct"] is False
    assert [a["diagnosis"] for a in result["students"]["bo"]["answers"]] == ["components-swapped"] * 2
    assert list(csv.reader(book.read_text().splitlines())) == [["student", "grade"], ["ana", "16.67"], ["bo", "0"]]
    text = runner.invoke(app, ["grade", str(folders["p_pair"]), str(answers)])
    assert text.exit_code == 0 and re.search(r"q3.x +1 +0 +0  components-swapped ×1", text.stdout)


def test_an_edited_key_is_refused(folders, tmp_path):
    import shutil

    copy = tmp_path / "copy"
    shutil.copytree(folders["four_bar"], copy)
    key = (copy / "key.csv").read_text().splitlines()
    key[1] = key[1].rsplit(",", 2)[0] + ",123.0,0.01"
    (copy / "key.csv").write_text("\n".join(key) + "\n")
    answers = tmp_path / "a.csv"
    answers.write_text("student,variant,question,value\nx,1,q1,1\n")
    done = runner.invoke(app, ["grade", str(copy), str(answers)])
    assert done.exit_code == 2 and "key.csv does not match" in done.output


@pytest.mark.parametrize("args, message", [
    (["--vary", "nothere=1:2"], "unknown parameter"),
    (["--vary", "s=300"], "NAME=LOW:HIGH"),
    (["--vary", "s=300:310:10", "--count", "5"], "fewer than --count 5"),
    (["--vary", "s=300:500:10", "--lang", "xx"], "unknown language"),
])
def test_exercise_errors_are_one_line(tmp_path, args, message):
    done = runner.invoke(app, ["exercise", str(P_PAIR), "-o", str(tmp_path / "out"), "--no-pdf", *args])
    assert done.exit_code == 2 and message in done.output and len(done.output.strip().splitlines()) == 1


def test_the_class_gets_its_variants_and_its_names_on_the_sheets(tmp_path):
    from kinematika.exercise.roster import Student, assigned

    names = tmp_path / "class.csv"
    names.write_bytes("Número de ID;Nombre;Apellido(s);Dirección de correo\n101;Ane;Etxeberria;ane@x.eus\n"
                      "102;Jon;Agirre;jon@x.eus\n103;Miren;Lasa;miren@x.eus\n".encode("cp1252"))
    out = tmp_path / "out"
    done = runner.invoke(app, ["exercise", str(FOUR_BAR), "--vary", "a=25:35:1", "--count", "2",
                               "--students", str(names), "--lang", "ca", "--no-pdf", "--no-solutions",
                               "-o", str(out)])
    assert done.exit_code == 0, done.output
    dealt = assigned([Student(i) for i in ("101", "102", "103")], 2, 0)
    assert (out / "students.csv").read_text() == "student,variant\n" + "".join(
        f"{s.id},{s.variant}\n" for s in dealt)
    sheets = (out / "sheets.html").read_text(encoding="utf-8")
    assert sheets.count('<section class="sheet">') == 3
    assert all(n in sheets for n in ("Ane Etxeberria", "Jon Agirre", "Miren Lasa"))
    assert "Quadrilàter articulat" in sheets and catalogue("ca").format("sheet-find") in sheets
    # grade reads the class back: 103 has no row (0), 999 is not on the list, 101 answers
    # another's variant; the file as Excel saves it in Catalan (; and cp1252)
    other = next(s.variant for s in dealt if s.id == "102")
    mine = next(s.variant for s in dealt if s.id == "101")
    answers = tmp_path / "answers.csv"
    answers.write_bytes((f"student;variant;question;value\n101;{3 - mine};q1;1,5\n102;{other};q1;2\n"
                         f"999;{other};q1;2\n").encode("cp1252"))
    graded = runner.invoke(app, ["grade", str(out), str(answers), "--json"])
    assert graded.exit_code == 0, graded.output
    result = json.loads(graded.stdout)
    assert result["unknown"] == ["999"] and result["unreadable"] == []
    assert set(result["students"]) == {"101", "102", "103"} and result["students"]["103"]["score"] == 0
    assert result["students"]["101"]["answers"][0]["diagnosis"] == "wrong-variant"

def test_each_sheet_states_its_variants_data_and_asks_every_number(folders, p_pair_exercise):
    sheets = (folders["p_pair"] / "sheets.html").read_text(encoding="utf-8")
    pages = sheets.split('<section class="sheet">')[1:]
    assert len(pages) == COUNT
    for page, v in zip(pages, p_pair_exercise.variants):
        s = f"{v.stated['s'].normalize():f}"
        assert f"AB = {s}\u00a0mm" in page and f"β = {v.stated['beta'].normalize():f}°" in page
        assert re.findall(r'<td class="box" data-q="([^"]+)">', page) == [r.question for r in v.rows]
        assert page.count("data:image/png;base64,") == 1


def test_the_key_lists_every_value_and_its_margin(folders, four_bar_exercise):
    key = (folders["four_bar"] / "key.html").read_text(encoding="utf-8")
    pages = key.split('<section class="sheet variant"')[1:]
    assert len(pages) == COUNT
    first = pages[0]
    for r in four_bar_exercise.variants[0].rows:
        assert f"<code class=\"id\">{r.question}</code>" in first
    # the contents: every variant linked to its pages
    contents = key.split('<section class="sheet" id="contents">')[1].split("</section>")[0]
    assert re.findall(r'href="#variant-(\d+)"', contents) == [str(n) for n in range(1, COUNT + 1)]
