"""The order `kinematika exercise` makes its files in (`folder.made`, `printing.Printer`):
every statement figure first, then the worked solutions, each in the variants' order and
the same bytes as made one by one; the browser prints what it is handed while the caller
goes on, and says on leaving why it could not."""
from __future__ import annotations

import re

import pytest

from tests.exercise.conftest import P_PAIR, P_PAIR_VARY, make


def test_figures_then_solutions_in_order_the_same_as_one_by_one():
    from kinematika.exercise.figure import statement_figure
    from kinematika.exercise.folder import WORKERS_FROM, made
    from kinematika.exercise.solutions import solution_html

    ex = make(P_PAIR, P_PAIR_VARY, WORKERS_FROM, 5)
    with made(ex, True) as (figures, solutions):
        got_figures = list(figures)                  # all of them before any solution is read
        got_solutions = list(solutions)
    numbers = [v.number for v in ex.variants]
    assert [n for n, _ in got_figures] == numbers == [n for n, _ in got_solutions] == [1, 2, 3, 4]
    assert [png for _, png in got_figures] == [statement_figure(ex, v, ex.lang) for v in ex.variants]
    assert [html for _, html in got_solutions] == [solution_html(ex, v, ex.lang) for v in ex.variants]
    with made(ex, False) as (_, none):
        assert list(none) == []


def _pages(pdf) -> int:
    return len(re.findall(rb"/Type\s*/Page[^s]", pdf.read_bytes()))


def test_printer_prints_each_file_handed_to_it_and_raises_what_failed(tmp_path):
    from kinematika.exercise.printing import Printer, missing

    if missing() is not None:
        pytest.skip("no Playwright or Chromium here")
    two = tmp_path / "two.html"
    two.write_text('<section style="break-after:page">one</section><section>two</section>', encoding="utf-8")
    one = tmp_path / "one.html"
    one.write_text("<p>one page</p>", encoding="utf-8")
    from playwright.sync_api import Error

    # one browser (a start-up of Chromium, not two): the files handed before the one that
    # cannot be printed are printed, and leaving the block raises why that one was not
    with pytest.raises(Error, match="ERR_FILE_NOT_FOUND"), Printer() as printer:
        printer.submit(two, tmp_path / "two.pdf")
        printer.submit(one, tmp_path / "one.pdf")
        printer.submit(tmp_path / "missing" / "none.html", tmp_path / "none.pdf")
    assert (_pages(tmp_path / "two.pdf"), _pages(tmp_path / "one.pdf")) == (2, 1)
    assert not (tmp_path / "none.pdf").exists()
