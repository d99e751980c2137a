"""`SaidLater`: messages counted at once and made when first read (the rows' labels of a
large instant, docs/performance.md, sixth round)."""
from __future__ import annotations

import pytest

from kinematika.errors import Said, SaidLater


def _later(words: list[str], made: list[int]) -> SaidLater:
    def make() -> list[Said]:
        made.append(len(words))
        return [Said.text_of(w) for w in words]

    return SaidLater(len(words), make)


def test_nothing_is_made_until_a_message_is_read_and_then_once():
    made: list[int] = []
    later = _later(["a", "b", "c"], made)
    assert len(later) == 3 and bool(later) and made == []
    assert str(later[1]) == "b" and made == [3]
    assert [str(x) for x in later] == ["a", "b", "c"] and [str(x) for x in later[1:]] == ["b", "c"]
    assert later[0] is later[0] and made == [3]


def test_joined_and_reordered_messages_are_the_pieces_in_that_order():
    made: list[int] = []
    first, second = _later(["a", "b"], made), [Said.text_of("c")]
    joined = SaidLater.joined([first, second, _later(["d"], made)])
    assert len(joined) == 4 and made == []
    moved = (joined + [Said.text_of("e")]).reordered([4, 0, 3, 2, 1])
    assert len(moved) == 5 and made == []
    assert [str(x) for x in moved] == ["e", "a", "d", "c", "b"]
    assert moved[1] is first[0] and moved[3] is second[0]


def test_a_count_that_is_not_what_is_made_is_an_error():
    with pytest.raises(ValueError, match="2 messages made where 3 were counted"):
        SaidLater(3, lambda: [Said.text_of("a"), Said.text_of("b")])[0]
