"""kinematika: kinematic analysis of mechanisms, exactly as a careful textbook solution would.

    >>> from kinematika import solve
    >>> sol = solve("examples/four_bar.yaml")
    >>> sol.velocity("B@rocker")

Everything goes through one engine: a model (file, dict or `Mechanism`) is parsed once into
a `Model`, evaluated on numbers or symbols, and its velocity and acceleration systems
solved; views (CLI, JSON, tables, figures, explanations) read the `Solution`.
"""
from .api import answers, as_model, solve
from .errors import KinematikaError
from .model.builder import Mechanism
from .model.files import load_model
from .solution import Solution

__version__ = "0.1.0"
__all__ = ["solve", "answers", "as_model", "load_model", "Mechanism", "Solution",
           "KinematikaError", "__version__"]
