"""The add-on files FreeCAD reads at start-up: package.xml, Init.py, InitGui.py, icons."""
import ast
import os
import re
from xml.etree import ElementTree

import FreeCAD

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def test_package_xml_describes_the_workbench_for_this_freecad():
    meta = FreeCAD.Metadata(os.path.join(REPO, "package.xml"))
    assert (meta.Name, meta.Version) == ("FairSplines", "0.1.0")
    assert meta.Description
    assert [lic["name"] for lic in meta.License] == ["LGPL-2.1-or-later"]
    assert meta.supportsCurrentFreeCAD() and meta.FreeCADMin.startswith("0.20")
    assert os.path.isfile(os.path.join(REPO, meta.Icon))
    (workbench,) = meta.Content["workbench"]
    assert workbench.Classname == "FairSplinesWorkbench"
    assert os.path.realpath(os.path.join(REPO, workbench.Subdirectory)) == os.path.realpath(REPO)
    assert os.path.isfile(os.path.join(REPO, workbench.Subdirectory, workbench.Icon))
    # 0.20's Metadata does not read pythonmin: the oldest Python tested, Debian 12's
    assert ElementTree.parse(os.path.join(REPO, "package.xml")).find("{*}pythonmin").text == "3.11"
    assert sorted(d["package"] for d in meta.Depend) == ["matplotlib", "numpy"]


def test_package_xml_lists_the_debian_packages_the_set_up_installs():
    xml = open(os.path.join(REPO, "package.xml"), encoding="utf-8").read()
    listed = re.search(r"tools/install-deps.sh installs(.*?)\(the last", xml, re.S).group(1).split()
    script = open(os.path.join(REPO, "tools", "install-deps.sh"), encoding="utf-8").read()
    installed = re.search(r"packages=\((.*?)\)", script, re.S).group(1).split()
    assert listed == installed


def _imports(path):
    tree = ast.parse(open(path, encoding="utf-8").read(), path)
    names = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            names.update(alias.name.split(".")[0] for alias in node.names)
        elif isinstance(node, ast.ImportFrom) and node.module:
            names.add(node.module.split(".")[0])
    return tree, names


def test_init_py_is_console_safe():
    tree, names = _imports(os.path.join(REPO, "Init.py"))
    assert not names & {"FreeCADGui", "PySide", "PySide2", "PySide6", "pivy", "matplotlib"}
    exec(compile(tree, "Init.py", "exec"), {})  # runs without error, as FreeCAD runs it


def test_init_gui_registers_the_workbench_class_named_in_package_xml():
    tree, names = _imports(os.path.join(REPO, "InitGui.py"))
    classes = [node.name for node in tree.body if isinstance(node, ast.ClassDef)]
    assert classes == ["FairSplinesWorkbench"]
    # only FreeCADGui at start-up: the commands are imported inside Initialize()
    top_level_imports = {
        alias.name for node in tree.body if isinstance(node, ast.Import) for alias in node.names
    } | {node.module for node in tree.body if isinstance(node, ast.ImportFrom)}
    assert top_level_imports == {"FreeCADGui"}
    assert "freecad_workbench" in names
