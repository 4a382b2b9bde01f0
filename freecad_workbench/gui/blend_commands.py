"""Where documents saved before the gui/ package was reorganised look for this view
provider (FreeCAD stores a view provider's module and class name in the file)."""
from .view_providers import ViewProviderBlendShape  # noqa: F401
