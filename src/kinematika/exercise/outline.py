"""Bookmarks (a PDF outline) added to a PDF Chromium printed, by an incremental update: the
file is kept as it is and a few objects are appended after it (the outline, its entries, a
new catalog naming the outline, a cross-reference section for them, a trailer pointing
back to the file's own with `/Prev`), as PDF 1.7 §7.5.6 allows any writer to.

Why not Chromium's own: `page.pdf(outline=True)` builds the outline from the tagged
structure, so without `tagged=True` it writes none, and tagging a key of 15 quick-return
variants wrote 24 500 structure elements (one per table cell and inline `<b>`, `<sub>`, …):
6.6 MB instead of 3.4 MB, 1.9 times the size (a set of 60: 20.4 MB instead of 7.9 MB), for
232 bookmarks that follow every heading and name no student. These cost about 260 bytes a
bookmark (16 kB for a set of 60).

Each bookmark points to a named destination Chromium wrote: the id of an element that a
link of the page points to (`<a href="#variant-3">` gives `/variant-3`).
"""
from __future__ import annotations

import re
from pathlib import Path

_TRAILER = re.compile(rb"trailer\s*<<(.*?)>>\s*startxref\s+(\d+)\s+%%EOF\s*$", re.S)


def add_outline(pdf: Path, marks: list[tuple[str, str]]) -> int:
    """Append to `pdf` one top-level bookmark per (title, destination id) in `marks`, in
    order, leaving out those whose destination the PDF does not name; the viewer opens with
    the bookmarks shown. The number of bookmarks written (0, and the file untouched, when
    none is left or the PDF has an outline already or is not laid out as Chromium writes)."""
    data = pdf.read_bytes()
    trailer = _TRAILER.search(data[-4096:])
    if trailer is None or b"/Outlines" in data:
        return 0
    fields, previous = trailer.group(1), int(trailer.group(2))
    root = re.search(rb"/Root\s+(\d+)\s+0\s+R", fields)
    size = re.search(rb"/Size\s+(\d+)", fields)
    if root is None or size is None:
        return 0
    number = int(root.group(1))                 # the catalog's, written again with the outline
    marks = [(title, dest) for title, dest in marks if re.search(rb"/" + _name(dest) + rb"\s*\[", data)]
    catalog = list(re.finditer(rb"\n%d 0 obj\s*<<(.*?)>>\s*endobj" % number, data, re.S))
    if not (marks and catalog):
        return 0
    first = int(size.group(1))                  # the outline's number; its entries follow
    count = len(marks)
    objects = {first: b"<</Type /Outlines /First %d 0 R /Last %d 0 R /Count %d>>" % (first + 1, first + count, count)}
    for i, (title, dest) in enumerate(marks):
        n = first + 1 + i
        links = (b" /Prev %d 0 R" % (n - 1) if i else b"") + (b" /Next %d 0 R" % (n + 1) if i < count - 1 else b"")
        objects[n] = b"<</Title %s /Parent %d 0 R%s /Dest /%s>>" % (_text(title), first, links, _name(dest))
    objects[number] = (b"<<" + catalog[-1].group(1).rstrip()
                       + b"\n/Outlines %d 0 R\n/PageMode /UseOutlines>>" % first)
    tail, offsets = bytearray(b"\n"), {}
    for n, body in objects.items():
        offsets[n] = len(data) + len(tail)
        tail += b"%d 0 obj\n%s\nendobj\n" % (n, body)
    xref = len(data) + len(tail)
    tail += b"xref\n0 1\n0000000000 65535 f \n%d 1\n%010d 00000 n \n%d %d\n" % (number, offsets[number], first, count + 1)
    tail += b"".join(b"%010d 00000 n \n" % offsets[n] for n in range(first, first + count + 1))
    rest = re.sub(rb"/(Size|Prev)\s+\d+\s*", b"", fields).strip()
    tail += b"trailer\n<</Size %d /Prev %d %s>>\nstartxref\n%d\n%%%%EOF\n" % (first + count + 1, previous, rest, xref)
    with pdf.open("ab") as out:
        out.write(bytes(tail))
    return count


def _text(title: str) -> bytes:
    """A PDF text string in UTF-16BE with its byte-order mark, as hexadecimal (any script)."""
    return b"<FEFF" + title.encode("utf-16-be").hex().upper().encode("ascii") + b">"


def _name(dest: str) -> bytes:
    """A PDF name's characters (PDF 1.7 §7.3.5): `#` and any byte outside the regular
    printable ASCII characters written `#XX`, as Chromium writes an id."""
    return b"".join(bytes([c]) if 33 <= c <= 126 and c not in b"#()<>[]{}/%" else b"#%02X" % c
                    for c in dest.encode("utf-8"))
