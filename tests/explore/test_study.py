"""Studies in chunks: the same rows in this process, on a Dask cluster of 2 workers, through the
per-design path, and after an interruption and `--resume` (nothing lost, nothing twice)."""
from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

import kinematika.explore as ke
from kinematika.cli import app
from kinematika.explore import study as study_mod
from kinematika.explore.evaluate import Evaluator
from kinematika.explore.study import make_study, write_study

from .models import FOUR_BAR, SLIDER_CRANK

METRICS = ["grashof", "transmission", "range:rocker", "peak_speed:P", "dead_points", "time_ratio"]
VARY = ["a=1:3.5", "c=2:6"]


@pytest.fixture(scope="module")
def model(tmp_path_factory) -> Path:
    path = tmp_path_factory.mktemp("models") / "four_bar.yaml"
    path.write_text(FOUR_BAR)
    return path


@pytest.fixture(scope="module")
def cluster():
    distributed = pytest.importorskip("dask.distributed")
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None) as c:
        yield c


def test_a_cluster_of_two_workers_gives_the_rows_of_one_process(model, cluster):
    import pandas as pd           # in the tests, not at the top: every worker imports every test module
    from dask.distributed import Client

    here = ke.explore(model, VARY, METRICS, samples=100, seed=4, chunk=25, workers=1)
    with Client(cluster) as client:
        there = ke.explore(model, VARY, METRICS, samples=100, seed=4, chunk=25, scheduler=client)
    pd.testing.assert_frame_equal(here, there)           # four chunks, rows of both kinds:
    assert here["assembles"].sum() > 30 and (here["reason"] != "").sum() > 5


def test_the_command_on_a_scheduler_address_writes_the_same_rows(model, cluster, tmp_path):
    args = ["explore", str(model), "--vary", "a=1:3.5", "--vary", "c=2:6", "--grid", "12",
            "--metric", "grashof", "--metric", "transmission", "--chunk", "50"]
    for extra in (["-o", str(tmp_path / "here.parquet"), "--workers", "1"],
                  ["-o", str(tmp_path / "there.parquet"), "--scheduler", cluster.scheduler_address]):
        result = CliRunner().invoke(app, args + extra)
        assert result.exit_code == 0, result.output
    import pandas as pd
    import pyarrow.parquet as pq

    here, there = (pq.read_table(tmp_path / f).to_pandas() for f in ("here.parquet", "there.parquet"))
    pd.testing.assert_frame_equal(here, there)
    assert len(here) == 144 and list(here.columns) == ["a", "c", "assembles", "reason", "grashof",
                                                       "transmission"]


@pytest.mark.parametrize("text, vary, metrics", [
    (FOUR_BAR, VARY, METRICS + ["omega:rocker=45", "peak_alpha:coupler"]),
    (SLIDER_CRANK, ["r=0.5:2.5", "e=-1:1"], ["transmission", "time_ratio", "peak_accel:B", "dead_points",
                                              "x:B=30"]),
])
def test_the_batch_kernel_and_the_per_design_path_give_the_same_rows(text, vary, metrics):
    study = make_study(text, vary, metrics, samples=64, seed=1)
    values = study.designs.values(0, 64)
    ev = study_mod.evaluator(study)
    batch = ev.evaluate(values)
    alone = Evaluator(ev.model, ev.varied, list(study.metrics), ev.sweep)
    alone.batch.batchable = False
    single = alone.evaluate(values)
    assert (batch["assembles"] == single["assembles"]).all()
    assert list(batch["reason"]) == list(single["reason"])
    for m in metrics:
        a, b = batch[m], single[m]
        if a.dtype == object:
            assert list(a) == list(b)
        else:
            np.testing.assert_allclose(a, b, rtol=1e-9, atol=1e-9, equal_nan=True)


def test_an_interrupted_study_resumes_without_losing_or_repeating_designs(model, tmp_path, monkeypatch):
    study = make_study(model, VARY, ["grashof", "transmission"], grid=20, chunk=50)   # 400 designs, 8 chunks
    whole = tmp_path / "whole.csv"
    write_study(study, whole, workers=1)

    out = tmp_path / "study.csv"

    def stop_after_three(count: int) -> None:
        if count >= 150:
            raise KeyboardInterrupt
    with pytest.raises(KeyboardInterrupt):
        write_study(study, out, workers=1, progress=stop_after_three)
    parts = tmp_path / "study.csv.parts"
    assert sorted(p.name for p in parts.glob("part-*")) == [f"part-00000{i}.parquet" for i in range(3)]
    (parts / "tmp-000003.parquet").write_bytes(b"half a file")          # killed while writing

    with pytest.raises(Exception, match="--resume"):
        write_study(study, out, workers=1)
    computed = []
    real = study_mod.run_chunk
    monkeypatch.setattr(study_mod, "run_chunk", lambda s, i: computed.append(i) or real(s, i))
    write_study(study, out, resume=True, workers=1)
    assert computed == [3, 4, 5, 6, 7] and not parts.exists()
    assert out.read_text() == whole.read_text()
    import pandas as pd

    table = pd.read_csv(out)
    assert len(table) == 400 and not table.duplicated(["a", "c"]).any()


def test_a_resumed_study_must_be_the_same_study(model, tmp_path):
    out = tmp_path / "s.parquet"
    study = make_study(model, VARY, ["grashof"], grid=4, chunk=4)
    (tmp_path / "s.parquet.parts").mkdir()
    (tmp_path / "s.parquet.parts" / "study.json").write_text('{"signature": "another"}')
    with pytest.raises(Exception, match="different study"):
        write_study(study, out, resume=True, workers=1)


def test_command_errors_are_one_line(model, tmp_path):
    def run(*extra):
        return CliRunner().invoke(app, ["explore", str(model), *extra, "-o", str(tmp_path / "x.csv")])
    bad = run("--vary", "q=1:2", "--grid", "3")
    assert bad.exit_code == 2 and bad.output.strip() == ("error (usage): --vary: unknown parameter 'q' "
                                                         "(parameters: g, a, b, c, px, py, theta, w)")
    bad = run("--vary", "a=3:1", "--grid", "3")
    assert bad.exit_code == 2 and "LOW <= HIGH" in bad.output
    bad = run("--vary", "a=1:3", "--grid", "3", "--metric", "range:crankk")
    assert bad.exit_code == 2 and "unknown body 'crankk'" in bad.output
    bad = run("--vary", "a=1:3")
    assert bad.exit_code == 2 and "--grid N or --samples N" in bad.output
    assert not (tmp_path / "x.csv").exists()
