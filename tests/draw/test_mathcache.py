"""matplotlib's formula layouts shared by every parser of the process (`draw.mathcache`):
a second figure's parser reuses the first's layout, and the layout is the one matplotlib's
own parser makes."""
from __future__ import annotations


def test_two_parsers_share_one_layout_the_same_as_matplotlibs():
    from matplotlib.font_manager import FontProperties
    from matplotlib.mathtext import MathTextParser

    from kinematika.draw import mathcache

    mathcache.shared()
    text, prop = r"$\vec{v}_{\mathrm{B}\in 3/2} = 2\,\omega \times v$", FontProperties(size=9)
    first = MathTextParser("path").parse(text, 72, prop)
    second = MathTextParser("path").parse(text, 72, prop)
    assert second is first                          # not laid out again by the second parser
    assert mathcache.ORIGINAL is not None           # matplotlib's own layout, uncached
    fresh = mathcache.ORIGINAL(MathTextParser("path"), text, 72, prop.copy(), True, first_flags())
    assert (fresh.width, fresh.height, fresh.depth) == (first.width, first.height, first.depth)
    assert [g[1:] for g in fresh.glyphs] == [g[1:] for g in first.glyphs]
    raster = MathTextParser("agg").parse(text, 72, prop)        # another kind of output, its own layout
    assert raster is not first


def first_flags():
    from matplotlib.ft2font import LoadFlags

    return LoadFlags.NO_HINTING
