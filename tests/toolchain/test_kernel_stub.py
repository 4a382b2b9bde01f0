"""freecad_workbench/_kernel.pyi agrees with the compiled module (issue 14): the same exported
names, the same public members of every class, and the same parameter names, in order, as
the signatures pybind11 writes into each docstring."""
import ast
import os
import re

import pytest

from freecad_workbench import _kernel

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
STUB = os.path.join(REPO, "freecad_workbench", "_kernel.pyi")
ALIASES = {"FloatArray", "IntArray", "Capsule"}  # the stub's own type names, not exports


def _stub():
    with open(STUB, encoding="utf-8") as f:
        tree = ast.parse(f.read(), STUB)
    functions, classes = {}, {}
    for node in tree.body:
        if isinstance(node, ast.FunctionDef):
            functions[node.name] = node
        elif isinstance(node, ast.ClassDef):
            classes[node.name] = node
    aliases = {t.id for node in tree.body if isinstance(node, ast.Assign) for t in node.targets}
    return functions, classes, aliases


def _exports():
    return {name for name in dir(_kernel) if not name.startswith("_")}


def _stub_parameters(function):
    names = [a.arg for a in function.args.args]
    return names[1:] if names[:1] == ["self"] else names


def _compiled_parameters(obj, name):
    """Parameter names of the first pybind11 signature of obj's docstring, 'name(a: T, ...) -> R'."""
    line = next(line for line in (obj.__doc__ or "").splitlines() if line.startswith(name + "("))
    source = re.sub(r"<[^<>]*>", "...", line.split(" -> ")[0] if " -> " in line else line)
    call = ast.parse("def " + source + ": pass").body[0]
    return _stub_parameters(call)


def _members(cls):
    names = set()
    for klass in cls.__mro__:
        if klass.__module__ == _kernel.__name__:
            names |= {n for n in vars(klass) if not n.startswith("_")}
    return names


def _stub_members(classes, name):
    names = set()
    while name in classes:
        node = classes[name]
        for item in node.body:
            if isinstance(item, ast.FunctionDef) and not item.name.startswith("_"):
                names.add(item.name)
            elif isinstance(item, ast.AnnAssign) and isinstance(item.target, ast.Name):
                names.add(item.target.id)
        bases = [b.id for b in node.bases if isinstance(b, ast.Name)]
        name = bases[0] if bases else None
    return names


def test_the_stub_names_exactly_what_the_module_exports():
    functions, classes, aliases = _stub()
    assert aliases == ALIASES
    assert set(functions) | set(classes) == _exports()


@pytest.mark.parametrize("name", sorted(n for n in _exports() if not isinstance(getattr(_kernel, n), type)))
def test_each_function_has_the_compiled_parameters(name):
    functions, _, _ = _stub()
    assert _stub_parameters(functions[name]) == _compiled_parameters(getattr(_kernel, name), name)


@pytest.mark.parametrize("name", sorted(n for n in _exports() if isinstance(getattr(_kernel, n), type)))
def test_each_class_has_the_compiled_members_and_constructor(name):
    _, classes, _ = _stub()
    cls = getattr(_kernel, name)
    if issubclass(cls, Exception):
        assert [b.id for b in classes[name].bases] == [cls.__bases__[0].__name__]
        return
    assert _stub_members(classes, name) == _members(cls)
    init = next((i for i in classes[name].body if isinstance(i, ast.FunctionDef) and i.name == "__init__"), None)
    if "__init__" in vars(cls) and init is not None:
        assert _stub_parameters(init) == _compiled_parameters(cls.__init__, "__init__")
    else:  # made only by the kernel's functions: no constructor in the stub either
        assert init is None and "__init__(self: " + _kernel.__name__ not in (cls.__init__.__doc__ or "")
