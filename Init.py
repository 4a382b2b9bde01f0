# FairSplines start-up, console part: FreeCAD runs this in freecadcmd and in the GUI.
# Nothing to do at start: the macro API (import freecad_workbench) and the features load
# on first use, so start-up stays fast and console-safe (no GUI imports here).
