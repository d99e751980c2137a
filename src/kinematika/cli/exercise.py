"""`kinematika exercise` and `kinematika grade`: a class's worth of variants of a model's
problem (Moodle quiz, sheets, key), and the class's answers marked with the mistakes named."""
from __future__ import annotations

import sys
from pathlib import Path
from typing import Optional

import typer

from ..errors import Said
from .app import JsonOpt, MessagesOpt, ModelArg, app, messages
from .shared import cannot_write, guarded, output_file, print_json, writing

DEFAULT_COUNT = 30


@app.command()
def exercise(model: Path = ModelArg,
             vary: list[str] = typer.Option(..., "--vary", metavar="NAME=LOW:HIGH[:STEP]",
                                            help="a parameter varied on a grid, in the statement's "
                                                 "unit (repeat for each parameter)"),
             count: Optional[int] = typer.Option(None, "--count", min=1, help="how many variants "
                                                 "(default: one per named student, else 30)"),
             seed: int = typer.Option(0, "--seed", help="the variants' seed (the same seed, the same "
                                                        "variants)"),
             lang: str = typer.Option("en", "--lang", help="the statements' language: en, es, ca or eu"),
             output: Path = typer.Option(..., "-o", "--output", help="the folder to write"),
             students: Optional[Path] = typer.Option(None, "--students", help="the class as Moodle "
                                                     "exports it: ids in the first column, then names "
                                                     "and e-mails (one variant and sheet each)"),
             solutions: bool = typer.Option(True, "--solutions/--no-solutions",
                                            help="worked solutions in the key and the quiz's feedback"),
             pdf: bool = typer.Option(True, "--pdf/--no-pdf", help="print the sheets and the key to PDF "
                                                                   "(Chromium)"),
             split: bool = typer.Option(False, "--split", help="the Moodle quiz with a question per "
                                        "graded part (a category each)"),
             unit_penalty: Optional[float] = typer.Option(None, "--unit-penalty", min=0.0, max=1.0,
                                                          help="in the Moodle quiz, a right number in "
                                                               "another unit of its kind (mm/s for m/s) "
                                                               "loses this share of its grade"),
             ) -> None:
    """Variants of MODEL's problem for every student: a Moodle quiz, sheets, a key with worked
    solutions, variants.csv and key.csv (see docs/exercises.md)."""
    from ..exercise import make_exercise, write_exercise
    from ..exercise.moodle import QuizOptions
    from ..model.files import load_model

    def work() -> list:
        from ..exercise.roster import read_class

        _folder(output)
        roster = read_class(students) if students is not None else None
        ex = make_exercise(load_model(model), vary, count or (len(roster) if roster else DEFAULT_COUNT),
                           seed, lang, source=model, students=roster)
        with writing(output, "-o"):
            return write_exercise(ex, output, solutions, pdf, QuizOptions(split, unit_penalty), _progress)

    for note in guarded(False, work):
        print(note, file=sys.stderr)


def _progress(done: int, total: int) -> None:
    """The figures and worked solutions made so far, on a terminal's one line."""
    if sys.stderr.isatty():
        print("\r" + Said("exercise-progress", done=done, total=total).said(), end="\n" if done == total else "",
              file=sys.stderr, flush=True)


def _folder(output: Path) -> None:
    """A folder can be written at `output` (made if missing), else an `output` error."""
    if output.exists() and not output.is_dir():
        raise cannot_write(output, Said("it-is-a-file"), "-o")
    if not output.parent.is_dir():
        raise cannot_write(output, Said("no-folder", folder=str(output.parent)), "-o")


@app.command()
def grade(folder: Path = typer.Argument(..., help="the folder `kinematika exercise` wrote",
                                        show_default=False),
          answers: Path = typer.Argument(..., help="the answers: student,variant,question,value "
                                              "(, or ; separated, UTF-8 or cp1252)",
                                         show_default=False),
          as_json: bool = JsonOpt,
          gradebook: Optional[Path] = typer.Option(None, "--gradebook", help="also write a CSV Moodle's "
                                                   "gradebook imports (student,grade out of 100)"),
          carry: bool = typer.Option(True, "--carry/--no-carry", help="credit a later answer that "
                                     "follows from the student's own earlier wrong one"),
          lang: Optional[str] = MessagesOpt,
          ) -> None:
    """Mark a class's answers: right within the key's tolerance, and each wrong one named by the
    usual mistake whose value it equals (Coriolis left out, degrees as radians, ...)."""
    messages(lang, as_json)
    from ..exercise import grade as mark, load_exercise
    from ..exercise.grading import gradebook_csv, not_read, summary_text

    def work() -> dict:
        result = mark(load_exercise(folder), answers, carry)
        if gradebook is not None:
            target = output_file(gradebook, "--gradebook")
            with writing(target, "--gradebook"):
                target.write_text(gradebook_csv(result), encoding="utf-8")
        return result

    result = guarded(as_json, work)
    if as_json:
        print_json(result)
        for u in result["unreadable"]:
            print(not_read(answers.name, u), file=sys.stderr)
    else:
        sys.stdout.write(summary_text(result, answers.name))
