"""FairSplines' translations: FreeCAD loads translations/FairSplines_<language>.qm for the
language chosen in Edit > Preferences > General (see translations/README.md).

    from freecad_workbench.gui import translations
    translations.install()      # once, from InitGui.py, before commands are made
"""
import os

TRANSLATIONS_DIR = os.path.join(
    os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))), "translations"
)


def install():
    """Add translations/ to FreeCAD's language paths and load the current language's file."""
    import FreeCADGui

    FreeCADGui.addLanguagePath(TRANSLATIONS_DIR)
    FreeCADGui.updateLocale()
