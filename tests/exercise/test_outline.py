"""The key's bookmarks (`outline.add_outline`, `printing.bookmarks`): one per student, in the
contents' order, each opening the pages of the student's variant; added to the PDF by an
incremental update that keeps every byte Chromium wrote. The PDF is read here with a reader
of its own (objects, the last trailer, the page tree), not with the code under test."""
from __future__ import annotations

import copy
import re

import pytest

from tests.exercise.conftest import P_PAIR, P_PAIR_VARY, make


def _objects(data: bytes) -> dict[int, bytes]:
    """Each object's body, the last written winning (an incremental update replaces)."""
    return {int(m.group(1)): m.group(2) for m in re.finditer(rb"(?m)^(\d+) 0 obj\s*(.*?)\s*endobj", data, re.S)}


def _ref(body: bytes, key: bytes) -> int:
    return int(re.search(rb"/" + key + rb"\s+(\d+) 0 R", body).group(1))


def outline_of(data: bytes) -> list[tuple[str, int]]:
    """The top-level bookmarks as (title, page number from 1)."""
    objects = _objects(data)
    trailer = data[data.rindex(b"trailer"):]
    catalog = objects[_ref(trailer, b"Root")]

    def pages(n: int) -> list[int]:
        kids = re.search(rb"/Kids\s*\[([^\]]*)\]", objects[n])
        if kids is None:
            return [n]
        return [p for k in re.findall(rb"(\d+) 0 R", kids.group(1)) for p in pages(int(k))]

    order = pages(_ref(catalog, b"Pages"))
    dests = objects[_ref(catalog, b"Dests")] if re.search(rb"/Dests\s+\d+ 0 R", catalog) else catalog
    found = []
    item = re.search(rb"/First (\d+) 0 R", objects[_ref(catalog, b"Outlines")])
    while item:
        body = objects[int(item.group(1))]
        title = bytes.fromhex(re.search(rb"/Title <FEFF([0-9A-F]*)>", body).group(1).decode()).decode("utf-16-be")
        name = re.search(rb"/Dest /(\S+?)>>", body).group(1)
        page = int(re.search(rb"/" + re.escape(name) + rb"\s*\[(\d+) 0 R", dests).group(1))
        found.append((title, order.index(page) + 1))
        item = re.search(rb"/Next (\d+) 0 R", body)
    return found


def _pdf(pages: int, dests: bytes) -> bytes:
    """A PDF of `pages` blank pages laid out as Chromium writes one (classic cross-reference
    table, the destinations in the catalog), written here by hand."""
    kids = b" ".join(b"%d 0 R" % (3 + i) for i in range(pages))
    bodies = [b"<</Type /Catalog /Pages 2 0 R /Dests <<" + dests + b">>>>",
              b"<</Type /Pages /Kids [%s] /Count %d>>" % (kids, pages)]
    bodies += [b"<</Type /Page /Parent 2 0 R /MediaBox [0 0 595 842]>>"] * pages
    data, offsets = bytearray(b"%PDF-1.4\n"), []
    for n, body in enumerate(bodies, 1):
        offsets.append(len(data))
        data += b"%d 0 obj\n%s\nendobj\n" % (n, body)
    xref = len(data)
    data += b"xref\n0 %d\n0000000000 65535 f \n" % (len(bodies) + 1)
    data += b"".join(b"%010d 00000 n \n" % o for o in offsets)
    data += b"trailer\n<</Size %d /Root 1 0 R>>\nstartxref\n%d\n%%%%EOF" % (len(bodies) + 1, xref)
    return bytes(data)


def test_bookmarks_are_appended_to_what_was_written_and_point_to_the_named_pages(tmp_path):
    from kinematika.exercise.outline import add_outline

    pdf = tmp_path / "key.pdf"
    before = _pdf(3, b"/variant-1 [4 0 R /XYZ 0 842 0] /variant-2 [5 0 R /XYZ 0 842 0]")
    pdf.write_bytes(before)
    marks = [("Iñaki (ik3) — 2. aldaera", "variant-2"), ("Ane — 1. aldaera", "variant-1"), ("none", "variant-9")]
    assert add_outline(pdf, marks) == 2                   # the third names no destination
    after = pdf.read_bytes()
    assert after.startswith(before)                        # an incremental update
    assert outline_of(after) == [("Iñaki (ik3) — 2. aldaera", 3), ("Ane — 1. aldaera", 2)]
    assert b"/PageMode /UseOutlines" in after and re.search(rb"/Prev %d\b" % before.index(b"xref"), after)
    assert add_outline(pdf, marks) == 0 and pdf.read_bytes() == after     # one outline only
    pdf.write_bytes(b"%PDF-1.4\nnot laid out as Chromium writes")
    assert add_outline(pdf, marks) == 0


def test_the_printed_key_has_a_bookmark_per_student_to_their_variant(tmp_path):
    from kinematika.exercise import write_exercise
    from kinematika.exercise.printing import missing
    from kinematika.exercise.roster import Student

    if missing() is not None:
        pytest.skip("no Playwright or Chromium here")
    ex = copy.copy(make(P_PAIR, P_PAIR_VARY, 3, 7))
    names = [("u3", "Unai"), ("a1", "Ane"), ("i2", "Iñaki"), ("j4", "Jon")]
    ex.students = [Student(i, name=n, variant=v) for (i, n), v in zip(names, (3, 1, 2, 1))]
    write_exercise(ex, tmp_path, solutions=False)
    # the contents on page 1, then one page per variant (no worked solution): variant n on page n + 1
    assert outline_of((tmp_path / "key.pdf").read_bytes()) == [
        ("Ane (a1) — Variant 1", 2), ("Iñaki (i2) — Variant 2", 3), ("Jon (j4) — Variant 1", 2),
        ("Unai (u3) — Variant 3", 4)]
    assert b"/Outlines" not in (tmp_path / "sheets.pdf").read_bytes()     # the sheets ask for none
