"""Issue 30, twentieth round (f): the order of solution and the steps' titles say what each
step does — its bodies in the order its equations find them, its sources in the order they
are read, and a point shared by several known bodies credited to the body whose step found
its motion (C5-1.2's O: the bar OQ's equation found v_O, not the left wheel's)."""
from __future__ import annotations

from kinematika.explain.document import Lead, Msg, Names, Section

from .helpers import LANGS, SEEDS, explained, over, rendered

ORDER_ITEMS = ("order.item", "order.item_group", "order.item_data", "order.item_group_data", "order.item_through",
               "order.item_group_through")
TITLES = ("step.title", "step.title_group")


def _names(arg) -> list[str]:
    arg = arg.item if isinstance(arg, Lead) else arg
    return [getattr(n, "text", n) for n in arg.items] if isinstance(arg, Names) else []


def _items(name: str) -> list[tuple[list[str], list[str]]]:
    _, doc = explained(name)
    structure = next(s for s in doc.sections if s.title.key == "sec.structure")
    return [(_names(m.args.get("bodies")), _names(m.args.get("known")))
            for m in structure.leaves() if isinstance(m, Msg) and m.key in ORDER_ITEMS]


def _titles(name: str) -> list[list[str]]:
    _, doc = explained(name)
    velocities = next((s for s in doc.sections if s.title.key == "sec.velocities"), None)
    if velocities is None:
        return []
    return [_names(s.title.args.get("bodies")) for s in velocities.blocks
            if isinstance(s, Section) and s.title.key in TITLES]


def test_pulley_block_strand_before_pulley() -> None:
    """C5-1.5: steps 2 and 4 find the strand first (tangent to both pulleys: it translates),
    from the pulley above (T1 ∈ pulley 1), then the next pulley, from its axle on the
    ceiling (v_C2 = 0)."""
    items = _items("seed_c5_1_5_pulley_block")
    assert items[1] == (["strand2", "pulley2"], ["pulley1", "ground"])
    assert items[3] == (["strand4", "pulley4"], ["pulley3", "ground"])
    titles = _titles("seed_c5_1_5_pulley_block")
    assert titles[1] == ["strand2", "pulley2"] and titles[3] == ["strand4", "pulley4"]


def test_bar_on_wheels_o_credited_to_the_bar() -> None:
    """C5-1.2: O is a point of the left wheel, the bar OQ and the bar OJ; step 1's equation
    v_O = v_{I_OQ} + ω_OQ × I_{OQ}O found it as the bar OQ's, so the bar OJ is found from
    the ground (I_OJ, at rest) and the bar OQ — never the left wheel, whose ω no step has
    found yet."""
    items = _items("seed_c5_1_2_bar_on_inclined_wheels")
    assert items[1] == (["OJ"], ["ground", "OQ"])


@over(name=SEEDS)
def test_order_items_and_titles_agree(name: str) -> None:
    """Each velocity step's title names the bodies its order item names, in the same order."""
    items = [bodies for bodies, _ in _items(name)]
    titles = _titles(name)
    if titles:
        assert items == titles, (items, titles)


@over(lang=LANGS)
def test_pulley_block_order_words(lang: str) -> None:
    """The order's item 2 of C5-1.5 names strand 2 before pulley 2 in every language."""
    page = rendered("seed_c5_1_5_pulley_block", lang)
    words = {"en": ("strand 2", "pulley 2"), "es": ("tramo 2", "polea 2"),
             "ca": ("tram 2", "politja 2"), "eu": ("2. kable-zatia", "2. polea")}[lang]
    line = next(x for x in page.splitlines() if x.startswith("2. "))
    low = line.lower()
    assert words[0] in low and words[1] in low and low.index(words[0]) < low.index(words[1]), line
