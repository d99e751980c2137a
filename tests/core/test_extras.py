"""Optional dependencies hidden in turn: each command that uses one either runs without it
or says in one line what to install (in the README's terms) and exits with status 2; never
an internal error. And a study stopped half way leaves only what can be resumed.

A command runs in a process of its own: a fork of this one with the modules hidden
(`without`), or, for a study in local processes, a fresh interpreter that never had dask
(`fresh_without`)."""
from __future__ import annotations

import subprocess
import sys
from contextlib import contextmanager

import pytest

from fuzz.forks import run_forked
from tests.conftest import ROOT

FAMILY = ROOT / "docs" / "explore" / "four_bar_family.yaml"
TARGETS = ROOT / "docs" / "explore" / "targets.csv"
HINT = ".venv/bin/pip install -e '.[explore]'"

# the command line with some modules made unimportable (as if not installed)
RUN = """
import sys
if __name__ == "__main__":
    for name in sys.argv[1].split(","):
        if name:
            sys.modules[name] = None
    sys.argv = ["kinematika"] + sys.argv[2:]
    from kinematika.cli import main
    main()
"""


def fresh_without(hidden: str, *args: str, cwd=ROOT) -> subprocess.CompletedProcess:
    """`kinematika ARGS` in a fresh interpreter with the modules `hidden` (comma-separated)
    not importable."""
    return subprocess.run([sys.executable, "-c", RUN, hidden, *args], cwd=cwd, capture_output=True,
                          text=True, timeout=600)


@contextmanager
def hidden_modules(hidden: str):
    """The modules `hidden` (comma-separated) and their submodules not importable in the
    block (an import of one raises ImportError, as if it were not installed)."""
    names = [n for n in hidden.split(",") if n]
    saved = {k: v for k, v in sys.modules.items() if any(k == n or k.startswith(n + ".") for n in names)}
    sys.modules.update(dict.fromkeys([*saved, *names]))
    try:
        yield
    finally:
        for n in names:
            sys.modules.pop(n, None)
        sys.modules.update(saved)


def without(hidden: str, *args: str, cwd=ROOT):
    """`kinematika ARGS` in a forked process (`fuzz.forks`) with the modules `hidden` not
    importable: its status, standard output and error."""
    with hidden_modules(hidden):
        return run_forked(list(args), cwd=cwd)


def one_line(done) -> str:
    assert done.status == 2, done.stderr
    lines = done.stderr.strip().splitlines()
    assert len(lines) == 1 and "Traceback" not in done.stderr and "internal error" not in done.stderr, done.stderr
    return lines[0]


STUDY = ["explore", str(FAMILY), "--vary", "a=1.5:3", "--vary", "c=3.5:5.5", "--grid", "12",
         "--metric", "grashof"]


@pytest.mark.parametrize("hidden", ["pyarrow", "pandas"])
def test_a_study_without_its_extra_says_what_to_install(hidden, tmp_path):
    line = one_line(without(hidden, *STUDY, "-o", str(tmp_path / "s.parquet")))
    assert line.startswith(f"error (usage): explore needs {hidden}, which is not installed") and HINT in line
    assert list(tmp_path.iterdir()) == []


def test_a_study_without_dask_runs_in_local_processes(tmp_path):
    import pyarrow.parquet as pq

    alone = without("", *STUDY, "--workers", "1", "--chunk", "40", "-o", str(tmp_path / "one.parquet"))
    pooled = fresh_without("dask,distributed", *STUDY, "--workers", "2", "--chunk", "40",
                           "-o", str(tmp_path / "two.parquet"))
    assert alone.status == 0 and pooled.returncode == 0, pooled.stderr
    one, two = pq.read_table(tmp_path / "one.parquet"), pq.read_table(tmp_path / "two.parquet")
    assert one.num_rows == 144 and one.equals(two)          # 12 × 12 designs, the same rows


def test_a_cluster_without_dask_says_what_to_install(tmp_path):
    line = one_line(without("dask,distributed", *STUDY, "-o", str(tmp_path / "s.parquet"),
                            "--scheduler", "tcp://127.0.0.1:9"))
    assert "a study on a Dask cluster needs dask" in line and HINT in line
    assert list(tmp_path.iterdir()) == []                   # nothing computed, nothing left


def test_plot_study_names_itself(tmp_path):
    """plot-study reads a study with pandas; without it one line says what to install
    (synthesize no longer needs pyarrow: it writes YAML designs)."""
    study = tmp_path / "s.csv"
    study.write_text("a,c,assembles,reason,grashof\n1.5,3.5,true,,crank-rocker\n")
    line = one_line(without("pandas", "plot-study", str(study), "--map", "a,c,grashof", "-o",
                            str(tmp_path / "map.png")))
    assert line.startswith("error (usage): plot-study needs pandas") and HINT in line


def test_a_parquet_sweep_without_pyarrow_says_what_to_install(tmp_path):
    line = one_line(without("pyarrow", "sweep", str(ROOT / "examples" / "four_bar.yaml"), "-o",
                            str(tmp_path / "rows.parquet")))
    assert "writing Parquet (or write .npz) needs pyarrow" in line and "'.[columnar]'" in line


# a study stopped half way ------------------------------------------------------------------
def _stopping_after(monkeypatch, chunks: int) -> None:
    """`compute` finishes `chunks` chunks, then meets a user error (an unreachable cluster)."""
    from kinematika.errors import KinematikaError
    from kinematika.explore import study as st

    real = st.compute

    def compute(study, pending, done, scheduler=None, workers=None):
        real(study, pending[:chunks], done, None, 1)
        raise KinematikaError("usage", "cannot reach the Dask scheduler at tcp://nowhere:8786", "--scheduler")

    monkeypatch.setattr(st, "compute", compute)


def _stopped_study(monkeypatch, tmp_path, after):
    """A study whose cluster stops after `after` chunks: the study, its file and the error."""
    from kinematika.errors import KinematikaError
    from kinematika.explore.study import make_study, write_study

    _stopping_after(monkeypatch, after)
    study = make_study(FAMILY, ["a=1.5:3", "c=3.5:5.5"], ["grashof"], grid=12, chunk=40)
    out = tmp_path / "s.parquet"
    with pytest.raises(KinematikaError) as info:
        write_study(study, out)
    return study, out, info


def test_a_study_that_computed_nothing_leaves_nothing(monkeypatch, tmp_path):
    from kinematika.explore.study import write_study

    study, out, info = _stopped_study(monkeypatch, tmp_path, 0)
    assert info.value.message == "cannot reach the Dask scheduler at tcp://nowhere:8786"
    assert list(tmp_path.iterdir()) == []
    monkeypatch.undo()
    write_study(study, out, workers=1)                       # the next run is not refused
    assert out.exists()


def test_a_study_that_computed_part_says_how_to_resume(monkeypatch, tmp_path):
    from kinematika.explore.study import write_study

    study, out, info = _stopped_study(monkeypatch, tmp_path, 2)
    assert info.value.message.endswith("; 80 designs are kept in s.parquet.parts: run again with --resume to go on")
    monkeypatch.undo()
    write_study(study, out, resume=True, workers=1)
    import pyarrow.parquet as pq

    assert pq.read_table(out).num_rows == 144 and not (tmp_path / "s.parquet.parts").exists()


def test_a_dxf_without_ezdxf_says_what_to_install(tmp_path):
    """The cam's profile for a workshop needs the `cad` extra; the rest of the command runs."""
    line = one_line(without("ezdxf", "cam", str(ROOT / "examples" / "cam_roller_follower.yaml"),
                            "--dxf", str(tmp_path / "cam.dxf")))
    assert "needs ezdxf, which is not installed" in line and "'.[cad]'" in line
    done = without("ezdxf", "cam", str(ROOT / "examples" / "cam_roller_follower.yaml"),
                   "--csv", str(tmp_path / "cam.csv"))
    assert done.status == 0 and (tmp_path / "cam.csv").exists()


def test_sheets_without_playwright_are_written_as_html_and_say_why(tmp_path):
    """The exercise's PDFs need Chromium through Playwright (the `exercise` extra): without
    it the quiz, the key and the HTML sheets are written, and one line says what to install."""
    done = without("playwright,playwright.sync_api", "exercise", str(ROOT / "examples" / "exercises" / "four_bar.yaml"),
                   "--vary", "a=40:60:5", "--count", "2", "--seed", "1", "--no-solutions", "-o", str(tmp_path / "ex"))
    assert done.status == 0, done.stderr
    assert "PDF skipped: Playwright is not installed (.venv/bin/pip install -e '.[exercise]'" in done.stdout + done.stderr
    assert {"quiz.xml", "key.csv", "sheets.html"} <= {p.name for p in (tmp_path / "ex").iterdir()}
