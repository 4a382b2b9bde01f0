"""The first-run dialog as a designer meets it when the kernel cannot be built yet: it says
why, lists what is missing with its package, gives the one install command with a copy
button, and offers no build until the build can succeed (screenshot in out/test-artifacts/)."""
import os

from fairsplines_setup import dialog, requirements

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def _prefix_without_eigen(root):
    for rel in ("include/opencascade/Standard_Version.hxx", "include/pybind11/pybind11.h", "lib/libTKBRep.so",
                "lib/libTKTopAlgo.so", "include/python3.11/Python.h", "include/python3.13/Python.h",
                "include/python3.14/Python.h"):
        path = os.path.join(root, rel)
        os.makedirs(os.path.dirname(path), exist_ok=True)
        open(path, "w").close()
    return root


def test_the_dialog_lists_what_is_missing_and_the_command_that_installs_it(tmp_path, monkeypatch):
    prefix = _prefix_without_eigen(str(tmp_path / "usr"))
    bin_dir = tmp_path / "bin"
    bin_dir.mkdir()
    for tool in ("make", "swig", "g++"):  # no cmake
        (bin_dir / tool).write_text("#!/bin/sh\n")
        (bin_dir / tool).chmod(0o755)
    detect = requirements.detect
    monkeypatch.setattr(requirements, "detect", lambda: detect(prefixes=[prefix], path=str(bin_dir)))
    box = dialog.make_dialog("The FairSplines C++ kernel is not built for this FreeCAD (Python 3.13).",
                             parent=dialog._qt().main_window())
    qt = dialog._qt()
    box.show()
    qt.QtWidgets.QApplication.processEvents()
    child = box.findChild
    needs = child(qt.QtWidgets.QLabel, "requirements").text()
    assert "missing: CMake, package cmake" in needs and "missing: Eigen, package libeigen3-dev" in needs
    assert "found: a C++ compiler" in needs and "found: pybind11" in needs
    command = child(qt.QtWidgets.QLineEdit, "installCommand")
    assert command.isVisible() and command.text() == "sudo apt install cmake libeigen3-dev"
    assert "Python 3.13" in child(qt.QtWidgets.QLabel, "reason").text()
    assert not child(qt.QtWidgets.QPushButton, "build").isEnabled()
    child(qt.QtWidgets.QPushButton, "copyCommand").click()
    assert qt.QtWidgets.QApplication.clipboard().text() == "sudo apt install cmake libeigen3-dev"
    # the 300 px rule is for side panels; a dialog fits a small screen
    assert box.sizeHint().width() <= 800
    out = os.path.join(REPO, "out", "test-artifacts")
    os.makedirs(out, exist_ok=True)
    box.grab().save(os.path.join(out, "first_run_dialog_missing.png"))
    # Everything there now: the build is offered.
    monkeypatch.setattr(requirements, "detect", lambda: detect(prefixes=[prefix],
                                                               path=str(bin_dir)))
    os.makedirs(os.path.join(prefix, "include", "eigen3", "Eigen"))
    open(os.path.join(prefix, "include", "eigen3", "Eigen", "Core"), "w").close()
    (bin_dir / "cmake").write_text("#!/bin/sh\n")
    (bin_dir / "cmake").chmod(0o755)
    child(qt.QtWidgets.QPushButton, "checkAgain").click()
    assert child(qt.QtWidgets.QPushButton, "build").isEnabled() and not command.isVisible()
    box.close()
    box.deleteLater()  # the dialog and its Python slots go before the interpreter does
    qt.QtWidgets.QApplication.processEvents()
