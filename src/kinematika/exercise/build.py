"""An exercise: the model, its `exercise` section, the varied parameters and the variants,
each solved once (the key), as `kinematika exercise` writes them and `kinematika grade` and
the page read them back.

Every number comes from the one solver: a variant is the model with `--set` values
(`api.prepare`), solved by `api.solve`, and its key is `solve --json`'s answers.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from decimal import Decimal
from pathlib import Path
from typing import Any, Optional

from ..errors import KinematikaError, Num, Said
from ..model.exercise_section import ExerciseSection, Unit
from ..model.model import Model
from .key import Row, floors_of, graded, key_rows
from .stated import as_stated, is_degrees, model_expression, stated_unit
from .variants import MAX_CONDITION, Drawn, Vary, draw_variants, parse_vary

SIGNIFICANT = 12          # a parameter's value as stated, when the model gives it (not varied)


@dataclass
class Variant:
    """One student's data and its solution: `number` (1-based), the varied parameters'
    values as stated, the `--set` expressions, the solution, its answers and its key."""

    number: int
    stated: dict[str, Decimal]
    sets: dict[str, str]
    solution: Any
    answers: list[dict]
    rows: list[Row]
    mistaken: list = field(default_factory=list)             # mistakes.Mistaken, in KINDS order
    tolerances: dict[str, float] = field(default_factory=dict)  # question -> relative tolerance
    narrowed: dict[str, tuple[str, float, float]] = field(default_factory=dict)   # q3 -> (mistake, gap, tolerance)

    def tolerance_of(self, row: Row) -> float:
        """The relative tolerance of one of its rows (`margins`)."""
        return self.tolerances.get(row.question, 0.01)

    def margin(self, row: Row) -> float:
        """The absolute margin of a right answer of one of its rows."""
        return row.margin(self.tolerance_of(row))

    def all_stated(self, exercise: "Exercise") -> dict[str, Decimal]:
        """Every parameter's value as stated: the varied ones', then the model's others."""
        return {**exercise.fixed_stated(self.solution), **self.stated}


@dataclass
class Exercise:
    """A model made an exercise, with its variants."""

    model: Model
    section: ExerciseSection
    varies: list[Vary]
    seed: int
    lang: str
    variants: list[Variant] = field(default_factory=list)
    source: Optional[Path] = None
    students: list = field(default_factory=list)        # roster.Student, with their variants
    notes: list[Said] = field(default_factory=list)     # what drawing the variants skipped or narrowed

    @property
    def asks(self) -> list[int]:
        """The 1-based numbers of the graded questions: the section's `ask`, else every question
        of the model."""
        return graded(self.section.ask, len(self.model.questions))

    @property
    def title(self) -> str:
        """The exercise's title in its language: the section's, else the model's title in
        that language (`names:`), else its name."""
        return self.section.title.get(self.lang) or self.model.wording.title(self.lang, self.model.name)

    @property
    def tolerance(self) -> float:
        """The relative tolerance an answer is marked right within (the section's `tolerance`, 1
        % by default)."""
        return self.section.tolerance

    def unit_of(self, name: str) -> Optional[Unit]:
        """The unit parameter `name` is stated in: the section's, else degrees for a parameter
        the model writes `deg(x)`, else None (the model's units)."""
        return stated_unit(self.model, self.section, name)

    def sets_of(self, stated: dict[str, Decimal]) -> dict[str, str]:
        """The `--set` expressions of stated values (`deg(35)`, `450/1000`)."""
        return {name: model_expression(v, self.unit_of(name), self.section) for name, v in stated.items()}

    def fixed_stated(self, sol: Any) -> dict[str, Decimal]:
        """The values of the parameters that are not varied, as stated (from the model)."""
        varied = {v.name for v in self.varies}
        out = {}
        for name in self.model.parameters:
            if name in varied or name not in sol.inst.env:
                continue
            value = as_stated(float(sol.inst.env[name]), self.unit_of(name), self.section)
            out[name] = Decimal(f"{value:.{SIGNIFICANT}g}")
        return out

    def solve(self, stated: dict[str, Decimal]) -> Variant:
        """The variant of these stated values, solved (its number 0 until numbered)."""
        from ..report.json_answer import solution_json
        from ..sweep.posing import solved

        sets = self.sets_of(stated)
        sol = solved(self.model, set=sets)
        answers = solution_json(sol)["answers"]
        kinds = [q.kind for q in self.model.questions]
        return Variant(0, stated, sets, sol, answers, key_rows(answers, kinds, self.asks, floors_of(sol)))

    def mistakes(self, variant: Variant) -> list:
        """The usual mistakes' values for `variant` (`mistakes.Mistaken`, in `KINDS` order),
        each from the model solved again with the mistake."""
        from fractions import Fraction

        from .mistakes import World, mistakes_of

        stated = variant.all_stated(self)
        units = {name: self.unit_of(name) for name in stated}
        degrees = tuple(n for n, u in units.items() if is_degrees(u))
        millimetres = tuple(n for n, u in units.items() if u is not None and u.ratio == Fraction(1, 1000)
                            and u.kind in ("length", "speed", "accel"))
        metre = str(Fraction(1) / self.section.length.ratio)
        world = World(self.model, variant.sets, stated, degrees, millimetres, metre, self.asks,
                      variant.solution, variant.rows, _answers_and_floors)
        return mistakes_of(world)

    def judged(self, variant: Variant) -> Optional[tuple]:
        """Give `variant` its mistakes and its margins (`margins`); when it cannot tell a
        usual mistake from the right answer, why: (question, mistake, relative gap)."""
        from .margins import allowances, data_of, margins

        variant.mistaken = self.mistakes(variant)
        kinds = [q.kind for q in self.model.questions]

        def solve_with(name: str, value: float) -> list[Row]:
            from ..model.overrides import with_parameters
            from ..sweep.posing import prepare

            model = with_parameters(prepare(self.model, set=variant.sets), {name: repr(value)})
            answers, floors = _answers_and_floors(model)
            return key_rows(answers, kinds, self.asks, floors)

        allowance = allowances(variant.rows, data_of(variant.solution), solve_with)
        found = margins(variant.rows, allowance, variant.mistaken, self.tolerance)
        variant.tolerances, variant.narrowed = found.tolerance, found.narrowed
        return found.close or None

    def variant(self, number: int) -> Variant:
        """Variant `number` (1-based); a number outside 1 … count is a usage error naming the
        range."""
        if not 1 <= number <= len(self.variants):
            raise KinematikaError("usage", "variant-missing", "variant", number=number, count=len(self.variants))
        return self.variants[number - 1]


DEFAULT_SECTION = ExerciseSection()


def _answers_and_floors(model: Model, terms: Any = None) -> tuple[list[dict], dict[str, float]]:
    """A model's `solve --json` answers and its floors (`key.floors_of`), solved with
    `terms` (`engine.terms`: mechanics, or a student's mistake)."""
    from ..engine.terms import MECHANICS
    from ..report.json_answer import solution_json
    from ..solution import solve_model

    sol = solve_model(model, terms=terms or MECHANICS)
    return solution_json(sol)["answers"], floors_of(sol)


def make_exercise(model: Model, vary: list[str], count: int, seed: int, lang: str,
                  source: Optional[Path] = None, students: Optional[list] = None) -> Exercise:
    """`count` variants of `model`'s problem, drawn on the `--vary` grids with `seed`; with
    `students` (`roster.Student`), each given one of them (`roster.assigned`)."""
    from ..languages import known

    known(lang)
    section = model.exercise or DEFAULT_SECTION
    varies = [parse_vary(text) for text in vary]
    for v in varies:
        if v.name not in model.parameters:
            raise KinematikaError("usage", "vary-unknown-parameter", "--vary", name=v.name,
                                  parameters=list(model.parameters))
    ex = Exercise(model, section, varies, seed, lang, source=source)
    if not varies:
        raise KinematikaError("usage", "vary-none-step", "--vary")
    varied = {v.name for v in varies}
    if any(p.value is None and p.name not in varied for p in model.parameters.values()):
        raise KinematikaError("usage", "exercise-needs-numbers", "--vary")

    def accept(stated: dict[str, Decimal]) -> Drawn:
        try:
            variant = ex.solve(stated)
        except KinematikaError as err:
            if err.kind in ("geometry", "assembly"):
                return Drawn(reason="assembly")
            if err.kind in ("singular", "mobility"):
                return Drawn(reason="dead-point")
            raise
        condition = variant.solution.diagnosis.condition_number
        if condition > MAX_CONDITION:
            return Drawn(reason="dead-point")
        close = ex.judged(variant)
        if close is not None:
            ex.notes.append(close_note(stated, close))
            return Drawn(reason="mistake-close")
        return Drawn(kept=variant)

    for number, (_, variant) in enumerate(draw_variants(varies, count, seed, accept), start=1):
        variant.number = number
        ex.variants.append(variant)
        ex.notes += [narrowed_note(number, question, kind, gap, tolerance)
                     for question, (kind, gap, tolerance) in variant.narrowed.items()]
    if students:
        from .roster import assigned

        ex.students = assigned(students, len(ex.variants), seed)
    return ex


def close_note(stated: dict[str, Decimal], close: tuple) -> Said:
    """Why a drawn variant was left out: a mistake's answer too close to the right one (the
    gap in per cent, 2 significant figures)."""
    from .stated import plain_decimal

    question, kind, gap = close
    data = ", ".join(f"{k}={plain_decimal(v)}" for k, v in stated.items())
    if kind == "rounding":
        return Said("exercise-not-drawn-rounding", data=data, question=question, gap=Num(100 * gap, ".2g"))
    return Said("exercise-not-drawn-mistake", data=data, kind=kind, question=question, gap=Num(100 * gap, ".2g"))


def narrowed_note(number: int, question: str, kind: str, gap: float, tolerance: float) -> Said:
    """A variant whose box was narrowed to tell a mistake apart."""
    return Said("exercise-narrowed", number=number, question=question, tolerance=Num(100 * tolerance, ".2g"),
                kind=kind, gap=Num(100 * gap, ".2g"))
