"""A CSV file as people and spreadsheets write it: the class list Moodle exports, the answers a
teacher types or a spreadsheet saves.

Excel in Spanish, Catalan or Basque saves `;`-separated files (the comma is the decimal
sign there) in the Windows code page cp1252; LibreOffice and Moodle write UTF-8, often with
a byte-order mark. So a file is read as UTF-8 (its BOM dropped) and, when it is not UTF-8, as
cp1252; its separator is the one of `,`, `;` or a tab that splits the header into the most
columns (a quoted field's separators do not count). The header names the columns, in any
case and with spaces around them.

A row that cannot be read is kept as an `Unreadable` with its line number, so that one bad
line does not stop the other rows from being read; only a file that cannot be read at all
(missing, a column missing) is an error.
"""
from __future__ import annotations

import codecs
import csv
import io
from dataclasses import dataclass, field
from pathlib import Path
from typing import Optional

from ..errors import KinematikaError, Said, reason

SEPARATORS = (",", ";", "\t")


@dataclass(frozen=True)
class Line:
    """One row read: its line number in the file (1-based) and its cells by column."""

    number: int
    cells: dict[str, str]


@dataclass(frozen=True)
class Unreadable:
    """A row that could not be read: its line number and why (a message of the errors'
    catalogue, said in the language in use when it is read)."""

    number: int
    message: Said

    def as_json(self) -> dict:
        """`{"line": N, "error": "..."}`, as `grade --json` lists it."""
        return {"line": self.number, "error": self.message.said()}


@dataclass
class Table:
    """A CSV read: the file's name, its header (the columns as written), the rows and the
    rows that could not be read."""

    name: str
    header: list[str]
    rows: list[Line] = field(default_factory=list)
    unreadable: list[Unreadable] = field(default_factory=list)


def decoded(data: bytes) -> str:
    """The text of a file's bytes: UTF-8 (a BOM dropped), else cp1252 (Windows), whose five
    unassigned bytes are read as Latin-1 so that no file fails to decode."""
    try:
        return data.decode("utf-8-sig")
    except UnicodeDecodeError:
        return data.decode("cp1252", errors=LATIN1)


def _latin1(err: UnicodeError) -> tuple[str | bytes, int]:
    if not isinstance(err, UnicodeDecodeError):     # registered for decoding only (`decoded`)
        raise err
    return err.object[err.start:err.end].decode("latin-1"), err.end


LATIN1 = "kinematika-latin1"
codecs.register_error(LATIN1, _latin1)


def separator(header: str) -> str:
    """The separator that splits the header line into the most fields (`,` on a tie)."""
    counts = {sep: len(next(csv.reader([header], delimiter=sep), [])) for sep in SEPARATORS}
    return max(SEPARATORS, key=lambda sep: (counts[sep], -SEPARATORS.index(sep)))


def read_table(path: Path, columns: list[str], optional: tuple[str, ...] = (),
               decimal_last: bool = False) -> Table:
    """The rows of a CSV by its header's names (lower case, trimmed). The `columns` must be
    in the header (else a one-line error naming the file); `optional` ones may be missing (then
    blank). A row with a field too many whose last two fields are digits is read as a number
    with a decimal comma split by the separator when `decimal_last` (`ane,7,q1,0,915`)."""
    try:
        text = decoded(path.read_bytes())
    except OSError as err:
        raise KinematikaError("usage", "table-unreadable", str(path), path=str(path), reason=reason(err)) from None
    lines = text.splitlines()
    first = next((i for i, line in enumerate(lines) if line.strip()), None)
    if first is None:
        raise KinematikaError("syntax", "table-empty", path.name, name=path.name)
    sep = separator(lines[first])
    reader = csv.reader(io.StringIO("\n".join(lines[first:])), delimiter=sep)
    header = [h.strip().lower() for h in next(reader)]
    lacking = [c for c in columns if c not in header]
    if lacking:
        raise KinematikaError("syntax", "table-no-column", path.name, name=path.name, column=lacking[0],
                              header=[h for h in header if h], columns=columns)
    table = Table(path.name, header)
    for cells in reader:
        number = first + reader.line_num
        if not any(c.strip() for c in cells):
            continue
        if len(cells) == len(header) + 1 and decimal_last and _digits(cells[-2]) and _digits(cells[-1]):
            cells = [*cells[:-2], f"{cells[-2]},{cells[-1]}"]
        if len(cells) > len(header) and any(c.strip() for c in cells[len(header):]):
            table.unreadable.append(Unreadable(number, Said("row-fields", count=len(cells), header=len(header))))
            continue
        row = {h: (cells[i].strip() if i < len(cells) else "") for i, h in enumerate(header)}
        for c in optional:
            row.setdefault(c, "")
        table.rows.append(Line(number, row))
    return table


def _digits(text: str) -> bool:
    t = text.strip().replace("−", "-")
    return bool(t) and t.lstrip("+-").isdigit()


def column(table: Table, *words: str) -> Optional[str]:
    """The first column of the table whose name contains one of `words` (lower case)."""
    return next((h for h in table.header if any(w in h for w in words)), None)


def csv_field(text: str) -> str:
    """`text` as one field of a CSV row, quoted as the csv module quotes it (when it holds a
    comma, a quote or a line break)."""
    buf = io.StringIO()
    csv.writer(buf, lineterminator="").writerow([text])
    return buf.getvalue()
