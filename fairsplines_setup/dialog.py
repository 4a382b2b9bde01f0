"""The first-run dialog: what the kernel build needs, the install command, the build itself.

Thin over requirements.py (what is missing), builder.py (the build, on a thread) and
record.py (why the kernel cannot be used). InitGui opens it when `freecad_workbench` cannot
be imported; afterwards the workbench imports it again (no restart) or, when a kernel was
already loaded in this session, says that FreeCAD must be restarted.
"""
from __future__ import annotations

import importlib.util
import os
import queue
import threading

from . import builder, record, requirements

CONTEXT = "FairSplines"


_QT = []


def _qt():
    """The workbench's Qt binding module (freecad_workbench/gui/qt.py), loaded by its path:
    importing the freecad_workbench package needs the kernel this dialog builds."""
    if _QT:
        return _QT[0]
    path = os.path.join(builder.SOURCE_DIR, "freecad_workbench", "gui", "qt.py")
    spec = importlib.util.spec_from_file_location("fairsplines_setup._qt", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    _QT.append(module)
    return module


def translate(context, text):
    return _qt().QtCore.QCoreApplication.translate(context, text)


def requirement_lines(reqs):
    """One line per requirement: found, or missing with its package."""
    lines = []
    for r in reqs:
        if r.found:
            lines.append(translate(CONTEXT, "found: {name}").format(name=r.name))
        elif r.optional:
            lines.append(translate(CONTEXT, "missing (optional): {name}, package {package}: {why}").format(
                name=r.name, package=r.package, why=r.why))
        else:
            lines.append(translate(CONTEXT, "missing: {name}, package {package}").format(
                name=r.name, package=r.package))
    return lines


def make_dialog(reason, kernel_loaded=False, parent=None):
    """The dialog (not shown). reason: why the kernel cannot be used (record's message).
    kernel_loaded: a kernel is already loaded in this FreeCAD, so a new one takes a restart."""
    qt = _qt()
    QtCore, QtWidgets = qt.QtCore, qt.QtWidgets
    dialog = QtWidgets.QDialog(parent)
    dialog.setObjectName("FairSplinesFirstRun")
    dialog.setWindowTitle(translate(CONTEXT, "FairSplines: build the geometry kernel"))
    dialog.setMinimumWidth(560)
    layout = QtWidgets.QVBoxLayout(dialog)

    intro = QtWidgets.QLabel(translate(
        CONTEXT, "FairSplines computes its curves and surfaces in a compiled kernel. It is not built for "
        "this FreeCAD yet. It can be built here, into your own FreeCAD folder: a few minutes on a "
        "recent computer, up to a quarter of an hour on a slow one. No administrator rights are "
        "needed for the build itself."))
    intro.setWordWrap(True)
    layout.addWidget(intro)
    why = QtWidgets.QLabel(reason.split("\nActivate the FairSplines workbench")[0])  # (this is it)
    why.setObjectName("reason")
    why.setWordWrap(True)
    why.setTextInteractionFlags(QtCore.Qt.TextSelectableByMouse)
    layout.addWidget(why)

    needs = QtWidgets.QLabel()
    needs.setObjectName("requirements")
    needs.setWordWrap(True)
    layout.addWidget(needs)
    command_row = QtWidgets.QHBoxLayout()
    command = QtWidgets.QLineEdit()
    command.setObjectName("installCommand")
    command.setReadOnly(True)
    command.setToolTip(translate(CONTEXT, "Run this in a terminal (it asks for your password), then press "
                                 "Check again"))
    copy = QtWidgets.QPushButton(translate(CONTEXT, "Copy"))
    copy.setObjectName("copyCommand")
    recheck = QtWidgets.QPushButton(translate(CONTEXT, "Check again"))
    recheck.setObjectName("checkAgain")
    command_row.addWidget(command)
    command_row.addWidget(copy)
    command_row.addWidget(recheck)
    layout.addLayout(command_row)

    bar = QtWidgets.QProgressBar()
    bar.setObjectName("progress")
    bar.setRange(0, 100)
    bar.setValue(0)
    layout.addWidget(bar)
    log = QtWidgets.QPlainTextEdit()
    log.setObjectName("log")
    log.setReadOnly(True)
    log.setMaximumBlockCount(2000)
    layout.addWidget(log)
    result = QtWidgets.QLabel()
    result.setObjectName("result")
    result.setWordWrap(True)
    result.setTextInteractionFlags(QtCore.Qt.TextSelectableByMouse)
    layout.addWidget(result)

    buttons = QtWidgets.QHBoxLayout()
    build = QtWidgets.QPushButton(translate(CONTEXT, "Build the kernel"))
    build.setObjectName("build")
    close = QtWidgets.QPushButton(translate(CONTEXT, "Close"))
    close.setObjectName("close")
    for button in (build, close, copy, recheck):  # the whole text, whatever the style's margins (Qt6)
        button.setMinimumWidth(button.fontMetrics().boundingRect(button.text()).width() + 32)
    buttons.addStretch(1)
    buttons.addWidget(build)
    buttons.addWidget(close)
    layout.addLayout(buttons)

    state = {"thread": None, "queue": queue.Queue(), "cancel": False, "built": False}
    dialog.fairsplines_state = state  # for the tests and InitGui: state["built"]

    def check():
        reqs = requirements.detect()
        lacking = requirements.missing(reqs)
        text = translate(CONTEXT, "What the build needs:") + "\n" + "\n".join(requirement_lines(reqs))
        running = record.occt_version()
        if requirements.occt_matches(reqs, running) is False:
            text += "\n" + translate(CONTEXT, "The OpenCASCADE headers are not the version FreeCAD runs ({version}): "
                                     "the kernel will hand shapes over as arrays (slower, as exact).").format(
                version=running)
        needs.setText(text)
        install = requirements.install_command(reqs)
        command.setText(install or ("" if not lacking else " ".join(sorted({r.package for r in lacking}))))
        command.setVisible(bool(lacking))
        copy.setVisible(bool(lacking))
        build.setEnabled(requirements.can_build(reqs) and state["thread"] is None)
        return reqs

    def copy_command():
        QtWidgets.QApplication.clipboard().setText(command.text())

    def start():
        build.setEnabled(False)
        log.clear()
        result.setText(translate(CONTEXT, "Building..."))

        def run():
            outcome = builder.build(lambda f, line: state["queue"].put((f, line)),
                                    cancelled=lambda: state["cancel"])
            state["queue"].put(outcome)

        state["thread"] = threading.Thread(target=run, daemon=True)
        state["thread"].start()
        timer.start(100)

    def poll():
        while True:
            try:
                item = state["queue"].get_nowait()
            except queue.Empty:
                return
            if isinstance(item, builder.BuildResult):
                timer.stop()
                state["thread"] = None
                finished(item)
                return
            fraction, line = item
            bar.setValue(int(100 * fraction))
            log.appendPlainText(line)

    def finished(outcome):
        if outcome.ok:
            state["built"] = True
            bar.setValue(100)
            if kernel_loaded:
                text = translate(CONTEXT, "The kernel is built ({seconds} s). Restart FreeCAD to use it.")
            else:
                text = translate(CONTEXT, "The kernel is built ({seconds} s). FairSplines is ready: close this "
                                 "window.")
            result.setText(text.format(seconds=int(round(outcome.seconds))))
            build.setEnabled(False)
        else:
            result.setText(translate(CONTEXT, "The build failed. The last lines of the compiler's output are "
                                     "below; the full log is {log}").format(log=outcome.log_path))
            log.appendPlainText("\n" + outcome.tail)
            check()

    def closing():
        state["cancel"] = True
        dialog.accept()

    timer = QtCore.QTimer(dialog)
    timer.timeout.connect(poll)
    copy.clicked.connect(copy_command)
    recheck.clicked.connect(check)
    build.clicked.connect(start)
    close.clicked.connect(closing)
    check()
    return dialog


def offer_build(reason, kernel_loaded=False):
    """Show the dialog over FreeCAD's main window until closed; True when a kernel was built."""
    dialog = make_dialog(reason, kernel_loaded, _qt().main_window())
    dialog.exec_() if hasattr(dialog, "exec_") else dialog.exec()
    built = dialog.fairsplines_state["built"]
    dialog.deleteLater()
    return built


COMMAND = "FairSplines_BuildKernel"


class BuildKernelCommand:
    """FairSplines > Build the kernel: the first-run dialog on demand (a rebuild after an
    update, or for FreeCAD's own OpenCASCADE). A kernel loaded in this session stays until
    FreeCAD restarts."""

    def GetResources(self):
        return {
            "MenuText": QT_TRANSLATE_NOOP("FairSplines_BuildKernel", "Build the kernel..."),
            "ToolTip": QT_TRANSLATE_NOOP(
                "FairSplines_BuildKernel",
                "Build FairSplines' compiled kernel for this FreeCAD, into your own FreeCAD folder"),
            "Pixmap": os.path.join(builder.SOURCE_DIR, "icons", "FairSplines.svg"),
        }

    def IsActive(self):
        return True

    def Activated(self):
        import sys

        loaded = "freecad_workbench._kernel" in sys.modules
        try:
            reason = "\n".join(record.locate()[1]) or translate(CONTEXT, "The kernel is built for this FreeCAD.")
        except record.KernelUnavailable as exc:
            reason = str(exc)
        if offer_build(reason, kernel_loaded=loaded) and not loaded:
            import FreeCAD

            FreeCAD.Console.PrintMessage("FairSplines: the kernel is built; restart FreeCAD to get all tools.\n")


def QT_TRANSLATE_NOOP(context, text):
    return text


def register_build_command():
    """Register FairSplines_BuildKernel (once)."""
    import FreeCADGui

    if COMMAND not in FreeCADGui.listCommands():
        FreeCADGui.addCommand(COMMAND, BuildKernelCommand())
