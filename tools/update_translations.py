#!/usr/bin/python3
"""Write translations/FairSplines.ts, the template translators start from, from the sources.

    /usr/bin/python3 tools/update_translations.py            # (re)write the template
    /usr/bin/python3 tools/update_translations.py --check    # exit 1 if it is out of date
    /usr/bin/python3 tools/update_translations.py --untranslated   # user-visible texts not
                                                             # passed through translate()

It reads every .py under freecad_workbench/, fairsplines_setup/ and InitGui.py with Python's ast module (no
pylupdate or lupdate needed, the same result on every machine) and takes each call
    translate("Context", "text")                 FreeCAD.Qt.translate, QCoreApplication.translate
    QT_TRANSLATE_NOOP("Context", "text")         texts FreeCAD translates later (GetResources)
    QT_TRANSLATE_NOOP3("Context", "text", "comment")
whose context and text are string literals, or names of module or class constants that
are (GROUP, self.NAME). Other calls (a variable text, an f-string) cannot be extracted:
they are listed on stderr, and their texts need a QT_TRANSLATE_NOOP where they are written.

The output is Qt's TS 2.1 format, as lupdate writes it: contexts sorted by name,
messages by text, each with every place it occurs (file relative to translations/, line).
`--untranslated` lists literal texts handed to Qt widgets, and GetResources entries that
are not QT_TRANSLATE_NOOP, under freecad_workbench/gui/ (tests/toolchain/test_translations.py
fails on them).
"""
import argparse
import ast
import os
import re
import sys
from collections import namedtuple
from xml.sax.saxutils import escape

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
TS_DIR = os.path.join(REPO, "translations")
TS_PATH = os.path.join(TS_DIR, "FairSplines.ts")
GUI_DIR = os.path.join(REPO, "freecad_workbench", "gui")

Message = namedtuple("Message", "context source comment path line")
Problem = namedtuple("Problem", "path line text")
Problem.__doc__ = "Something at path:line the scan could not take, or a text that is not translated."

# name of the called function -> (index of the context, of the text, of the comment or None)
TRANSLATE_CALLS = {
    "translate": (0, 1, 2),
    "QT_TRANSLATE_NOOP": (0, 1, None),
    "QT_TRANSLATE_NOOP3": (0, 1, 2),
}


def source_files(repo=REPO):
    """The files scanned: InitGui.py and every .py under freecad_workbench/ and
    fairsplines_setup/ (the first-run dialog), sorted."""
    paths = [os.path.join(repo, "InitGui.py")]
    for package in ("freecad_workbench", "fairsplines_setup"):
        for folder, dirs, files in os.walk(os.path.join(repo, package)):
            dirs[:] = sorted(d for d in dirs if d != "__pycache__")
            paths.extend(os.path.join(folder, f) for f in files if f.endswith(".py"))
    return sorted(p for p in paths if os.path.isfile(p))


def relative(path, start=REPO):
    return os.path.relpath(path, start).replace(os.sep, "/")


def _name(func):
    """The called name: translate for translate(...), FreeCAD.Qt.translate(...), ..."""
    if isinstance(func, ast.Name):
        return func.id
    if isinstance(func, ast.Attribute):
        return func.attr
    return None


def _string_constants(body):
    """{name: text} of the `NAME = "text"` assignments in a module or class body, for
    names assigned exactly once there."""
    found, counts = {}, {}
    for node in body:
        if isinstance(node, ast.Assign):
            targets = [t.id for t in node.targets if isinstance(t, ast.Name)]
        elif isinstance(node, ast.AnnAssign) and isinstance(node.target, ast.Name) and node.value is not None:
            targets = [node.target.id]
        else:
            continue
        for target in targets:
            counts[target] = counts.get(target, 0) + 1
            if isinstance(node.value, ast.Constant) and isinstance(node.value.value, str):
                found[target] = node.value.value
    return {name: text for name, text in found.items() if counts[name] == 1}


class _Scope(ast.NodeVisitor):
    """Walks a module, knowing the string constants of the module and of the class it is in."""

    def __init__(self, tree):
        self.module_constants = _string_constants(tree.body)
        self.classes = []  # (class name, its constants), innermost last

    def visit_ClassDef(self, node):
        self.classes.append((node.name, _string_constants(node.body)))
        self.generic_visit(node)
        self.classes.pop()

    def literal(self, node):
        """The string a node always is, or None: literals, "a" "b", "a" + "b", constants."""
        if isinstance(node, ast.Constant) and isinstance(node.value, str):
            return node.value
        if isinstance(node, ast.BinOp) and isinstance(node.op, ast.Add):
            left, right = self.literal(node.left), self.literal(node.right)
            return left + right if left is not None and right is not None else None
        if isinstance(node, ast.Name):
            return self.module_constants.get(node.id)
        if isinstance(node, ast.Attribute) and isinstance(node.value, ast.Name) and self.classes:
            owner, constants = self.classes[-1]
            if node.value.id in ("self", "cls", owner):
                return constants.get(node.attr)
        return None


class _Extractor(_Scope):
    def __init__(self, tree, path):
        super().__init__(tree)
        self.path = path
        self.messages, self.problems = [], []

    def visit_Call(self, node):
        where = TRANSLATE_CALLS.get(_name(node.func))
        if where is not None and len(node.args) >= 2:  # str.translate(table) has one argument
            context_at, text_at, comment_at = where
            context, text = self.literal(node.args[context_at]), self.literal(node.args[text_at])
            comment = ""
            if comment_at is not None and len(node.args) > comment_at:
                comment = self.literal(node.args[comment_at])
            if context is None or text is None or comment is None:
                self.problems.append(Problem(self.path, node.lineno, "not extracted (not a literal): "
                                             + ast.unparse(node)[:120]))
            else:
                self.messages.append(Message(context, text, comment, self.path, node.lineno))
        self.generic_visit(node)


def extract(paths=None):
    """(messages, problems) of the files (default: source_files())."""
    messages, problems = [], []
    for path in source_files() if paths is None else paths:
        with open(path, encoding="utf-8") as f:
            tree = ast.parse(f.read(), filename=path)
        extractor = _Extractor(tree, path)
        extractor.visit(tree)
        messages.extend(extractor.messages)
        problems.extend(extractor.problems)
    return messages, problems


_FORBIDDEN = re.compile(r"[\x00-\x08\x0b\x0c\x0e-\x1f]")


def _xml(text, message=None):
    if _FORBIDDEN.search(text):
        where = f" ({relative(message.path)}:{message.line})" if message else ""
        raise ValueError(f"control character in a translatable text{where}: {text!r}")
    return escape(text, {'"': "&quot;", "'": "&apos;"})


def ts_text(messages, ts_dir=TS_DIR):
    """The TS file of these messages: contexts by name, messages by text and comment, each
    message once with the files it is in (relative to ts_dir; no line numbers, so that an
    edit elsewhere in a file does not make the template stale)."""
    grouped = {}
    for m in messages:
        grouped.setdefault(m.context, {}).setdefault((m.source, m.comment), []).append(m)
    out = ['<?xml version="1.0" encoding="utf-8"?>', "<!DOCTYPE TS>", '<TS version="2.1">']
    for context in sorted(grouped):
        out += ["<context>", f"    <name>{_xml(context)}</name>"]
        for (source, comment), places in sorted(grouped[context].items()):
            out.append("    <message>")
            for filename in sorted(set(relative(p.path, ts_dir) for p in places)):
                out.append(f'        <location filename="{_xml(filename)}"/>')
            out.append(f"        <source>{_xml(source, places[0])}</source>")
            if comment:
                out.append(f"        <comment>{_xml(comment, places[0])}</comment>")
            out.append('        <translation type="unfinished"></translation>')
            out.append("    </message>")
        out.append("</context>")
    out.append("</TS>")
    return "\n".join(out) + "\n"


# --- user-visible texts that do not go through translate() ------------------------------

# Qt call -> which arguments are user-visible texts ("list": every item of a list argument).
TEXT_ARGUMENTS = {
    "QLabel": (0,), "QPushButton": (0,), "QCheckBox": (0,), "QRadioButton": (0,), "QGroupBox": (0,),
    "setText": (0,), "setToolTip": (0,), "setWindowTitle": (0,), "setTitle": (0,),
    "setPlaceholderText": (0,), "setStatusTip": (0,), "setWhatsThis": (0,),
    "setSuffix": (0,), "setPrefix": (0,), "addRow": (0,), "addItem": (0,),
    "addItems": ("list",), "setHorizontalHeaderLabels": ("list",), "setVerticalHeaderLabels": ("list",),
}
RESOURCE_KEYS = ("MenuText", "ToolTip", "WhatsThis", "StatusTip")
# gui/commands/common.py: resources(name, menu_text, tool_tip, ...) builds GetResources.
RESOURCE_HELPERS = {"resources": (1, 2)}
# Texts that are not words: coordinates, parameter names, units. Texts without any letter
# once their placeholders ({}, %d) are taken out (numbers, " °", "u{}") are allowed too.
ALLOWED = frozenset({"X", "Y", "Z", "x", "y", "z", "u", "v", "mm"})
_LETTER = re.compile(r"[^\W\d_]")
_PLACEHOLDER = re.compile(r"\{[^{}]*\}|%[-+ #0]*\d*(?:\.\d+)?[sdifgGeExX]")


class _Untranslated(_Scope):
    def __init__(self, tree, path):
        super().__init__(tree)
        self.path = path
        self.problems = []
        self.in_resources = 0

    def text_of(self, node):
        """The literal text a node shows, or None if it is not written as a literal
        (a translate() call, a variable). f-strings and "...".format() count as literals."""
        if isinstance(node, ast.Constant) and isinstance(node.value, str):
            return node.value
        if isinstance(node, ast.JoinedStr):
            return "".join(v.value if isinstance(v, ast.Constant) else "{}" for v in node.values)
        if isinstance(node, ast.BinOp) and isinstance(node.op, (ast.Add, ast.Mod)):
            parts = [self.text_of(node.left), self.text_of(node.right) if isinstance(node.op, ast.Add) else ""]
            parts = [p for p in parts if p is not None]
            return "".join(parts) if parts else None
        if isinstance(node, ast.IfExp):
            parts = [p for p in (self.text_of(node.body), self.text_of(node.orelse)) if p is not None]
            return " | ".join(parts) if parts else None
        if isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute) and node.func.attr == "format":
            return self.text_of(node.func.value)
        if isinstance(node, (ast.Name, ast.Attribute)):
            return self.literal(node)  # a string constant of the module or class
        return None

    def flag(self, node, text, what):
        if text is None:
            return
        words = _PLACEHOLDER.sub("", text).strip()
        if words not in ALLOWED and _LETTER.search(words):
            self.problems.append(Problem(self.path, node.lineno, f"{what}: {text!r}"))

    def visit_FunctionDef(self, node):
        resources = node.name == "GetResources"
        self.in_resources += resources
        self.generic_visit(node)
        self.in_resources -= resources

    visit_AsyncFunctionDef = visit_FunctionDef

    def visit_Dict(self, node):
        if self.in_resources:
            for key, value in zip(node.keys, node.values):
                if isinstance(key, ast.Constant) and key.value in RESOURCE_KEYS:
                    self.flag(value, self.text_of(value), f'GetResources "{key.value}" without QT_TRANSLATE_NOOP')
        self.generic_visit(node)

    def visit_Call(self, node):
        name = _name(node.func)
        if self.in_resources and name == "dict":
            for keyword in node.keywords:
                if keyword.arg in RESOURCE_KEYS:
                    self.flag(keyword.value, self.text_of(keyword.value),
                              f'GetResources "{keyword.arg}" without QT_TRANSLATE_NOOP')
        for index in RESOURCE_HELPERS.get(name, ()):
            if len(node.args) > index:
                self.flag(node.args[index], self.text_of(node.args[index]), f"{name}() text without QT_TRANSLATE_NOOP")
        for index in TEXT_ARGUMENTS.get(name, ()):
            if index == "list":
                if node.args and isinstance(node.args[0], (ast.List, ast.Tuple)):
                    for item in node.args[0].elts:
                        self.flag(item, self.text_of(item), f"{name}() item")
            elif len(node.args) > index:
                self.flag(node.args[index], self.text_of(node.args[index]), f"{name}()")
        self.generic_visit(node)


def untranslated(paths=None):
    """Problems: user-visible literal texts under freecad_workbench/gui/ (default) that do
    not go through translate() or QT_TRANSLATE_NOOP()."""
    if paths is None:
        paths = [p for p in source_files() if p.startswith(GUI_DIR + os.sep)]
    problems = []
    for path in paths:
        with open(path, encoding="utf-8") as f:
            tree = ast.parse(f.read(), filename=path)
        scan = _Untranslated(tree, path)
        scan.visit(tree)
        problems.extend(scan.problems)
    return problems


def format_problems(problems):
    return "\n".join(f"{relative(p.path)}:{p.line}: {p.text}" for p in problems)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    mode = parser.add_mutually_exclusive_group()
    mode.add_argument("--check", action="store_true", help="exit 1 if translations/FairSplines.ts is out of date")
    mode.add_argument("--untranslated", action="store_true",
                      help="list user-visible texts under freecad_workbench/gui/ not passed through translate()")
    args = parser.parse_args(argv)
    try:
        return _run(args)
    except SyntaxError as exc:  # a source file that does not parse: say which, no traceback
        print(f"{relative(exc.filename or '?')}:{exc.lineno}: {exc.msg}", file=sys.stderr)
        return 2


def _run(args):
    if args.untranslated:
        problems = untranslated()
        if problems:
            print(format_problems(problems))
        return 1 if problems else 0
    messages, problems = extract()
    if problems:
        print(format_problems(problems), file=sys.stderr)
    text = ts_text(messages)
    current = None
    if os.path.exists(TS_PATH):
        with open(TS_PATH, encoding="utf-8") as f:
            current = f.read()
    name = relative(TS_PATH)
    if args.check:
        if current != text:
            print(f"{name} is out of date: run /usr/bin/python3 tools/update_translations.py", file=sys.stderr)
            return 1
        print(f"{name} is up to date ({len(set(m[:3] for m in messages))} texts)")
        return 0
    if current != text:
        os.makedirs(TS_DIR, exist_ok=True)
        with open(TS_PATH, "w", encoding="utf-8", newline="\n") as f:
            f.write(text)
    print(f"{name}: {len(set(m[:3] for m in messages))} texts in {len(set(m.context for m in messages))} contexts")
    return 0


if __name__ == "__main__":
    sys.exit(main())
