"""kinematika: kinematic analysis of mechanisms, exactly as a careful textbook solution would."""
__version__ = "0.1.0"
