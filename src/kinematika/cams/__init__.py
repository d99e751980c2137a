"""Cam design: motion laws and programs, followers, disc and translating cams, their pitch
curves and profiles (as `curves.CamProfile`), the analysis over a cycle (s–v–a–j, pressure
angle, radius of curvature, undercutting, the fundamental law), files for a workshop (CSV,
SVG, DXF). It solves nothing of the linkage engine; a cam-design file is read by
`model.files.load_cam`, drawn by `draw.cam_plots`, and the model file's cam shape and joint
reuse `spec`'s models.
"""
from __future__ import annotations

from .analysis import CamAnalysis
from .follower import Flat, Knife, Oscillating, Roller, Translating
from .laws import LAWS, Law, Polynomial
from .profile import DiscCam, PlateCam
from .program import Program, Segment, build
from .spec import CamDesign

__all__ = ["LAWS", "CamAnalysis", "CamDesign", "DiscCam", "Flat", "Knife", "Law", "Oscillating", "PlateCam",
           "Polynomial", "Program", "Roller", "Segment", "Translating", "build"]
