"""Parametric FreeCAD objects (FeaturePython proxies) and their make_<feature>(doc, ...)
factories. Headless: nothing here imports the GUI at import time; a view provider is
attached only when FreeCAD.GuiUp."""
from .csr_fit import CsrFit, make_csr_fit
from .monotone_blend import MonotoneBlend, make_monotone_blend
from .monotone_design import MonotoneDesign, make_monotone_design

__all__ = ["CsrFit", "make_csr_fit", "MonotoneBlend", "make_monotone_blend", "MonotoneDesign", "make_monotone_design"]
