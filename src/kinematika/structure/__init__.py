"""Structure of a mechanism: its decomposition into inputs and Assur groups, and the
classical linkages recognised in it (four-bar, slider-crank)."""
