"""Parametric FreeCAD objects (FeaturePython proxies) and their make_<feature>(doc, ...)
factories. Headless: nothing here imports the GUI at import time; a view provider is
attached only when FreeCAD.GuiUp."""
from .csr_fit import CsrFit, make_csr_fit

__all__ = ["CsrFit", "make_csr_fit"]
