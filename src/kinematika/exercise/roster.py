"""The class: who the students are and which variant each one was given.

`kinematika exercise --students class.csv` reads the class as Moodle's participants export
writes it (or any list whose first column is the student's id): the first column is the id
`grade` matches answers by; columns named like a name (first name, surname, full name, in
the four languages) make the name printed on the sheet, and a column of e-mail addresses
the e-mail. `,` or `;` separated, UTF-8 (with or without BOM) or cp1252 (`table`).

Each student gets one variant, drawn reproducibly: the variants are shuffled by numpy's
generator seeded with the exercise's seed (a stream of its own, so that the variants
themselves do not change) and dealt to the students in the list's order; with fewer
variants than students they are dealt again in the same order. `students.csv`
(`student,variant`) records it, and `grade` checks every answer against it.
"""
from __future__ import annotations

import dataclasses
from dataclasses import dataclass
from pathlib import Path
from typing import Optional

import numpy as np

from ..errors import KinematikaError
from .table import column, csv_field, read_table

STREAM = 0x5EED              # the shuffle's stream, apart from the variants' own draw
# words of a column that holds a name, in en, es, ca, eu (and Moodle's column names)
NAME_WORDS = ("name", "nombre", "nom", "izen", "surname", "apellido", "cognom", "abizen", "first", "last")
MAIL_WORDS = ("mail", "correo", "correu", "posta")


@dataclass(frozen=True)
class Student:
    """A student of the class: the id answers are matched by, the name and e-mail printed
    on the sheet, and the variant given."""

    id: str
    name: str = ""
    email: str = ""
    variant: int = 0

    @property
    def label(self) -> str:
        """How the sheet names the student: the name and the id, or the id alone."""
        return f"{self.name} ({self.id})" if self.name and self.name != self.id else self.id


def read_class(path: Path) -> list[Student]:
    """The students of a class list (its first column the ids); a usage error naming the
    file when it names none or names one twice."""
    table = read_table(path, [])
    if not table.header or not table.header[0]:
        raise KinematikaError("usage", "students-first-column", "--students", name=path.name)
    ident = table.header[0]
    names = [h for h in table.header[1:] if any(w in h for w in NAME_WORDS) and not any(w in h for w in MAIL_WORDS)]
    mail = column(table, *MAIL_WORDS)
    out: list[Student] = []
    seen: dict[str, int] = {}
    for line in table.rows:
        sid = line.cells[ident]
        if not sid:
            continue
        if sid in seen:
            raise KinematikaError("usage", "student-twice", f"{path.name}:{line.number}", student=sid,
                                  first=seen[sid], line=line.number)
        seen[sid] = line.number
        email = line.cells.get(mail, "") if mail else next(
            (c for c in line.cells.values() if "@" in c and " " not in c.strip()), "")
        name = " ".join(line.cells[h] for h in names if line.cells[h])
        out.append(Student(sid, name, email))
    if not out:
        raise KinematikaError("usage", "students-none", "--students", name=path.name)
    return out


def assigned(students: list[Student], count: int, seed: int) -> list[Student]:
    """The students each with a variant 1…`count`: the variants shuffled with `seed` and
    dealt in the list's order (again from the start when there are more students)."""
    order = [int(k) + 1 for k in np.random.default_rng([STREAM, seed]).permutation(count)]
    return [dataclasses.replace(s, variant=order[i % count]) for i, s in enumerate(students)]


def students_csv(students: list[Student]) -> str:
    """`students.csv`: `student,variant`, one row per student."""
    return "student,variant\n" + "".join(f"{csv_field(s.id)},{s.variant}\n" for s in students)


def read_students(path: Path, count: int) -> Optional[list[Student]]:
    """The class of a folder's `students.csv` (None when there is none); a variant outside
    1…`count` is an error naming the line."""
    if not path.exists():
        return None
    table = read_table(path, ["student", "variant"])
    out = []
    for line in table.rows:
        try:
            variant = int(line.cells["variant"])
            if not 1 <= variant <= count:
                raise ValueError
        except ValueError:
            raise KinematikaError("usage", "student-variant-range", f"{path.name}:{line.number}",
                                  got=line.cells['variant'], count=count) from None
        out.append(Student(line.cells["student"], variant=variant))
    return out
