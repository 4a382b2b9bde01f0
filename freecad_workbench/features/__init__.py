"""Parametric FreeCAD objects (FeaturePython proxies) and their make_<feature>(doc, ...)
factories. Headless: nothing here imports the GUI at import time; a view provider is
attached only when FreeCAD.GuiUp."""
from .basic_curve import BasicCurveFeature, make_basic_curve
from .blend_shape import BlendShape, make_blend_shape
from .csr_fit import CsrFit, make_csr_fit
from .design_spline import DesignSpline, make_design_spline
from .edit_polygon import EditPolygon, make_edit_polygon, set_pole
from .face_blend import FaceBlend, make_face_blend
from .fair_blend import FairBlend, make_fair_blend
from .monotone_blend import MonotoneBlend, make_monotone_blend
from .monotone_design import MonotoneDesign, make_monotone_design
from .profile_test import ProfileTest, make_profile_test

__all__ = [
    "BasicCurveFeature",
    "BlendShape",
    "CsrFit",
    "DesignSpline",
    "EditPolygon",
    "FaceBlend",
    "FairBlend",
    "MonotoneBlend",
    "MonotoneDesign",
    "ProfileTest",
    "make_basic_curve",
    "make_blend_shape",
    "make_csr_fit",
    "make_design_spline",
    "make_edit_polygon",
    "make_face_blend",
    "make_fair_blend",
    "make_monotone_blend",
    "make_monotone_design",
    "make_profile_test",
    "set_pole",
]
