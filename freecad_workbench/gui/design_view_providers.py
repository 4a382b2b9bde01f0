"""Where documents saved before the gui/ package was reorganised look for these view
providers (FreeCAD stores a view provider's module and class name in the file)."""
from .view_providers import (  # noqa: F401
    ViewProviderBasicCurve,
    ViewProviderDesignSpline,
    ViewProviderEditPolygon,
    ViewProviderProfileTest,
)
