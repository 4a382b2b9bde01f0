"""Every test here runs in the session's FreeCAD GUI (see tests/conftest.py)."""
import pytest


@pytest.fixture(autouse=True)
def _gui(gui):
    return gui
