"""The shape of the macro layer (issue 14): kernel.py is the only module that imports the
compiled kernel, and the modules of freecad_workbench/ import each other one way (no cycle,
so blend.py and blend_c1.py cannot lean on each other again)."""
import ast
import os

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
PACKAGE = os.path.join(REPO, "freecad_workbench")


def _tree(path):
    with open(path, encoding="utf-8") as f:
        return ast.parse(f.read(), path)


def _package_modules():
    for root, _, files in os.walk(PACKAGE):
        for name in sorted(files):
            if name.endswith(".py"):
                yield os.path.join(root, name)


def _imported(node, path):
    """The absolute module names an import statement of `path` reaches, names included
    (``from . import _kernel`` reaches freecad_workbench._kernel)."""
    package = os.path.relpath(os.path.dirname(path), REPO).replace(os.sep, ".")
    if isinstance(node, ast.Import):
        return [a.name for a in node.names]
    if node.level:
        parts = package.split(".")
        base = ".".join(parts[:len(parts) - node.level + 1])
        module = base + ("." + node.module if node.module else "")
    else:
        module = node.module or ""
    return [module] + [module + "." + a.name for a in node.names]


def test_only_kernel_py_imports_the_compiled_kernel():
    importing = set()
    for path in _package_modules():
        for node in ast.walk(_tree(path)):
            if isinstance(node, (ast.Import, ast.ImportFrom)):
                if any(name.split(".")[-1] == "_kernel" or "._kernel." in name for name in _imported(node, path)):
                    importing.add(os.path.relpath(path, PACKAGE))
    assert importing == {"kernel.py"}


def _macro_graph():
    """Module-level and function-level imports between the top-level modules of the package."""
    modules = {name[:-3] for name in os.listdir(PACKAGE) if name.endswith(".py") and name != "__init__.py"}
    graph = {}
    for module in modules:
        path = os.path.join(PACKAGE, module + ".py")
        targets = set()
        for node in ast.walk(_tree(path)):
            if isinstance(node, (ast.Import, ast.ImportFrom)):
                for name in _imported(node, path):
                    parts = name.split(".")
                    if len(parts) >= 2 and parts[0] == "freecad_workbench" and parts[1] in modules:
                        targets.add(parts[1])
        graph[module] = targets - {module}
    return graph


def test_the_macro_modules_import_each_other_one_way():
    graph = _macro_graph()
    assert "blend_c1" in graph["blend"] and "blend" not in graph["blend_c1"]
    done, path = set(), []

    def visit(module):
        assert module not in path, "import cycle: " + " -> ".join(path[path.index(module):] + [module])
        if module in done:
            return
        path.append(module)
        for target in sorted(graph[module]):
            visit(target)
        path.pop()
        done.add(module)

    for module in sorted(graph):
        visit(module)
