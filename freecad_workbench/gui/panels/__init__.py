"""The task panels, one module each; form.py holds what they share (a form that fits the
300 px side panel, the status line, live editing inside one undo step)."""
