"""Drives FairSplines' first run in a real FreeCAD GUI, as a user would (tools/first-run-test.sh).

    FAIRSPLINES_FIRST_RUN_OUT=/tmp/out freecad tools/first_run_driver.py

Activates the FairSplines workbench (installed where the Addon Manager puts it). When the
first-run dialog opens, it records what the dialog lists, takes a screenshot, presses
"Build the kernel" when the button is enabled, waits for the build, and closes the dialog.
Then it checks that the workbench's tools are there and fits a curve. Everything lands in
$FAIRSPLINES_FIRST_RUN_OUT/result.json (and dialog.png, after.png); FreeCAD then exits.
"""
import json
import os
import time
import traceback

import FreeCAD
import FreeCADGui

OUT = os.environ.get("FAIRSPLINES_FIRST_RUN_OUT", "/tmp/fairsplines-first-run")
os.makedirs(OUT, exist_ok=True)
result = {"freecad": ".".join(FreeCAD.Version()[:3]), "dialog": False}


def _write():
    with open(os.path.join(OUT, "result.json"), "w") as f:
        json.dump(result, f, indent=1)


def _qt():
    from fairsplines_setup import dialog

    return dialog._qt()


def _drive_dialog():
    """Runs inside the dialog's modal loop (a timer started before the activation)."""
    qt = _qt()
    app = qt.QtWidgets.QApplication.instance()
    box = next((w for w in app.topLevelWidgets() if w.objectName() == "FairSplinesFirstRun" and w.isVisible()), None)
    if box is None:
        qt.QtCore.QTimer.singleShot(200, _drive_dialog)
        return
    result["dialog"] = True
    child = box.findChild
    result["reason"] = child(qt.QtWidgets.QLabel, "reason").text()
    result["requirements"] = child(qt.QtWidgets.QLabel, "requirements").text()
    command = child(qt.QtWidgets.QLineEdit, "installCommand")
    result["install_command"] = command.text() if command.isVisible() else None
    build = child(qt.QtWidgets.QPushButton, "build")
    result["build_enabled"] = build.isEnabled()
    box.grab().save(os.path.join(OUT, "dialog.png"))
    if build.isEnabled():
        build.click()
        start = time.monotonic()
        state = box.fairsplines_state
        while time.monotonic() - start < 3600:
            app.processEvents()
            time.sleep(0.05)
            if state["thread"] is None and child(qt.QtWidgets.QProgressBar, "progress").value() > 0 and (
                    state["built"] or "failed" in child(qt.QtWidgets.QLabel, "result").text()):
                break
        result["build_seconds"] = round(time.monotonic() - start, 1)
        result["built"] = state["built"]
        result["result_text"] = child(qt.QtWidgets.QLabel, "result").text()
        box.grab().save(os.path.join(OUT, "dialog-after-build.png"))
    _write()
    child(qt.QtWidgets.QPushButton, "close").click()


def _watchdog():
    result["error"] = "timed out (a modal window?)"
    _write()
    FreeCADGui.getMainWindow().grab().save(os.path.join(OUT, "timeout.png"))
    os._exit(3)


def main():
    try:
        _qt().QtCore.QTimer.singleShot(int(os.environ.get("FAIRSPLINES_FIRST_RUN_TIMEOUT", "4000")) * 1000, _watchdog)
        _qt().QtCore.QTimer.singleShot(500, _drive_dialog)
        FreeCADGui.activateWorkbench("FairSplinesWorkbench")
        FreeCADGui.updateGui()
        commands = [c for c in FreeCADGui.listCommands() if c.startswith("FairSplines_")]
        result["commands"] = len(commands)
        try:
            import numpy as np
            import freecad_workbench as fw
            from freecad_workbench import kernel

            t = np.linspace(0, 3, 9)
            curve = fw.csr_spline(np.c_[t, np.sin(t), 0 * t])
            result["fit"] = {"degree": curve.Degree, "poles": curve.NbPoles,
                             "value_at_1": tuple(curve.value(1.0))}
            result["kernel_folder"] = os.path.dirname(kernel._kernel.__file__)
            result["bridge"] = kernel.has_bridge()
        except Exception as exc:  # the workbench without a kernel
            result["fit_error"] = f"{type(exc).__name__}: {exc}"
        FreeCADGui.getMainWindow().grab().save(os.path.join(OUT, "after.png"))
    except Exception:
        result["error"] = traceback.format_exc()
    _write()
    os._exit(0)


main()
