"""`python -m kinematika.cli` runs the command line."""
from . import main

main()
