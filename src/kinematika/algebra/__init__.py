"""The algebras the one engine is written against: floats (`backend.Numeric`), exact sympy
formulas (`backend.Symbolic`), arrays of designs (`arrays.Arrays`), the fast exact field of
rational functions and square roots (`fields`), and the planar and spatial vector products
(`vectors`)."""
