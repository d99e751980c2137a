"""`python -m kinematika` runs the command line."""
from .cli import main

main()
