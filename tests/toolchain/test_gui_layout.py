"""The shape of the gui/ package (issue 12): importing a module has no side effects,
features reach the GUI only through attach_view_provider, and no GUI module imports a
private name of another."""
import ast
import os

import pytest

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
PACKAGE = os.path.join(REPO, "freecad_workbench")


def _modules(folder):
    for root, _, files in os.walk(os.path.join(PACKAGE, folder)):
        for name in sorted(files):
            if name.endswith(".py"):
                yield os.path.join(root, name)


def _tree(path):
    with open(path, encoding="utf-8") as f:
        return ast.parse(f.read(), path)


ALLOWED_TOP = (ast.Import, ast.ImportFrom, ast.FunctionDef, ast.ClassDef, ast.Assign, ast.AnnAssign, ast.Try)


@pytest.mark.parametrize("path", list(_modules("gui")), ids=lambda p: os.path.relpath(p, PACKAGE))
def test_importing_a_gui_module_runs_nothing(path):
    """Only imports, definitions and constant assignments at module level: no call that
    registers a command or touches FreeCAD (a docstring is an expression, allowed)."""
    for node in _tree(path).body:
        if isinstance(node, ast.Expr) and isinstance(node.value, ast.Constant):
            continue
        assert isinstance(node, ALLOWED_TOP), f"{os.path.relpath(path, REPO)}:{node.lineno}: runs code on import"
        if isinstance(node, (ast.Assign, ast.AnnAssign)):
            for call in ast.walk(node):
                if isinstance(call, ast.Call):
                    name = ast.unparse(call.func)
                    assert not name.startswith(("FreeCADGui.", "Gui.")) and "register" not in name, (
                        f"{os.path.relpath(path, REPO)}:{node.lineno}: {name}() on import")


@pytest.mark.parametrize("path", list(_modules("features")), ids=lambda p: os.path.relpath(p, PACKAGE))
def test_features_do_not_import_the_gui_at_module_level(path):
    for node in _tree(path).body:
        if isinstance(node, ast.ImportFrom):
            module = ("." * node.level) + (node.module or "")
            assert "gui" not in module.split("."), f"{os.path.relpath(path, REPO)}:{node.lineno} imports {module}"
        elif isinstance(node, ast.Import):
            assert all(".gui" not in a.name and a.name != "FreeCADGui" for a in node.names)


def test_only_attach_view_provider_reaches_the_gui_from_features():
    reaching = []
    for path in _modules("features"):
        for node in ast.walk(_tree(path)):
            if isinstance(node, ast.ImportFrom) and "gui" in (node.module or "").split("."):
                reaching.append(os.path.basename(path))
    assert reaching == ["base.py"]


@pytest.mark.parametrize("path", list(_modules("gui")), ids=lambda p: os.path.relpath(p, PACKAGE))
def test_no_gui_module_imports_a_private_name_of_another(path):
    for node in ast.walk(_tree(path)):
        if isinstance(node, ast.ImportFrom) and node.level:
            private = [a.name for a in node.names if a.name.startswith("_")]
            assert not private, f"{os.path.relpath(path, REPO)}:{node.lineno} imports {private}"
