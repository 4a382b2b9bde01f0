"""Translations (tools/update_translations.py): the committed template
translations/FairSplines.ts is what the sources give now, it is valid TS that holds every
text the extractor finds, and no user-visible text under freecad_workbench/gui/ bypasses
translate() / QT_TRANSLATE_NOOP(). Pure Python, no FreeCAD: about a second."""
import ast
import importlib.util
import os
import subprocess
import sys
import xml.etree.ElementTree as ET

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
TOOL = os.path.join(REPO, "tools", "update_translations.py")
REGENERATE = "/usr/bin/python3 tools/update_translations.py"


def _load_tool():
    spec = importlib.util.spec_from_file_location("update_translations", TOOL)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


tool = _load_tool()


def ts_messages(text):
    """{(context, source, comment)} of a TS file's text, and its root element."""
    root = ET.fromstring(text)
    found = set()
    for context in root.iter("context"):
        name = context.findtext("name")
        for message in context.iter("message"):
            found.add((name, message.findtext("source"), message.findtext("comment") or ""))
    return found, root


def test_committed_template_is_what_the_sources_give():
    """Whoever changes, adds or moves a translatable text regenerates the template."""
    messages, _ = tool.extract()
    with open(tool.TS_PATH, encoding="utf-8") as f:
        committed = f.read()
    assert committed == tool.ts_text(messages), f"translations/FairSplines.ts is out of date: run {REGENERATE}"


def test_check_mode_exits_1_when_the_template_is_out_of_date(tmp_path, monkeypatch):
    assert subprocess.run([sys.executable, TOOL, "--check"], capture_output=True, cwd=REPO).returncode == 0
    stale = tmp_path / "FairSplines.ts"
    with open(tool.TS_PATH, encoding="utf-8") as f:
        stale.write_text(f.read().replace("<source>", "<source>x", 1), encoding="utf-8")
    monkeypatch.setattr(tool, "TS_PATH", str(stale))
    assert tool.main(["--check"]) == 1
    assert tool.main([]) == 0 and tool.main(["--check"]) == 0  # regenerated


def test_template_is_ts_2_1_with_every_extracted_text():
    messages, _ = tool.extract()
    assert len(messages) > 50  # the scan found the workbench's texts
    with open(tool.TS_PATH, encoding="utf-8") as f:
        found, root = ts_messages(f.read())
    assert root.tag == "TS" and root.get("version") == "2.1"
    missing = {(m.context, m.source, m.comment) for m in messages} - found
    assert not missing, f"not in translations/FairSplines.ts: {sorted(missing)}"
    for message in root.iter("message"):
        assert message.find("translation").get("type") == "unfinished"
        for location in message.iter("location"):
            path = os.path.normpath(os.path.join(tool.TS_DIR, location.get("filename")))
            assert os.path.isfile(path) and location.get("line") is None, location.attrib  # files only


def test_extractor_takes_literals_constants_and_escapes(tmp_path):
    source = tmp_path / "sample.py"
    source.write_text(
        "import FreeCAD\n"
        "translate = FreeCAD.Qt.translate\n"
        "QT_TRANSLATE_NOOP = FreeCAD.Qt.QT_TRANSLATE_NOOP\n"
        "GROUP = 'Sample_Group'\n"
        "class Command:\n"
        "    NAME = 'Sample_Command'\n"
        "    def GetResources(self):\n"
        "        return {'MenuText': QT_TRANSLATE_NOOP(self.NAME, 'Fit & <check>'),\n"
        "                'ToolTip': QT_TRANSLATE_NOOP(GROUP, 'Say \"hi\" ' 'and it\\'s done')}\n"
        "a = translate('Ctx', 'Same')\n"
        "b = FreeCAD.Qt.translate('Ctx', 'Same')\n"
        "c = translate('Ctx', 'Same', 'other sense')\n"
        "d = 'abc'.translate({})\n"
        "e = translate('Ctx', variable)\n",
        encoding="utf-8",
    )
    messages, problems = tool.extract([str(source)])
    assert sorted(m[:3] for m in messages) == [
        ("Ctx", "Same", ""), ("Ctx", "Same", ""), ("Ctx", "Same", "other sense"),
        ("Sample_Command", "Fit & <check>", ""), ("Sample_Group", "Say \"hi\" and it's done", ""),
    ]
    assert [p.line for p in problems] == [14]
    text = tool.ts_text(messages, ts_dir=str(tmp_path))
    assert "<source>Fit &amp; &lt;check&gt;</source>" in text and "&quot;hi&quot;" in text
    assert text.count("<message>") == 4  # one message, one location, for the two "Same" of one file
    assert text.count('<location filename="sample.py"/>') == 4
    assert ts_messages(text)[0] >= {("Ctx", "Same", "other sense"), ("Sample_Group", "Say \"hi\" and it's done", "")}
    assert tool.ts_text(list(reversed(messages)), ts_dir=str(tmp_path)) == text  # deterministic


def test_no_user_visible_text_under_gui_bypasses_translate():
    problems = tool.untranslated()
    assert not problems, (
        f"{len(problems)} user-visible text(s) not passed through translate() / QT_TRANSLATE_NOOP() "
        f"(or add a non-word to ALLOWED in tools/update_translations.py):\n" + tool.format_problems(problems)
    )


def test_guard_finds_literal_texts_and_allows_non_words(tmp_path):
    source = tmp_path / "panel.py"
    source.write_text(
        "from .qt import QtWidgets\n"
        "label = QtWidgets.QLabel('Radius')\n"                        # 2: flagged
        "box.setToolTip(f'Teeth per edge: {n}')\n"                    # 3: flagged
        "rows.addRow('Scale', spin)\n"                                # 4: flagged
        "combo.addItems(['chordal', translate('C', 'uniform')])\n"    # 5: 'chordal' flagged
        "spin.setSuffix(' mm')\n"                                     # 6: allowed (unit)
        "table.setHorizontalHeaderLabels(['X', 'Y', 'Z'])\n"         # 7: allowed
        "QtWidgets.QLabel(f'u{index + 1}')\n"                         # 8: allowed (symbol)
        "button.setText('\\u2212')\n"                                 # 9: allowed (no letter)
        "box.setTitle(translate('C', 'Zebra'))\n"                     # 10: fine
        "w.setWindowTitle('Plot' if a else b)\n"                      # 11: flagged
        "class C:\n"
        "    def GetResources(self):\n"
        "        return {'Pixmap': 'icon', 'MenuText': 'Fit',\n"       # 14: flagged
        "                'ToolTip': QT_TRANSLATE_NOOP('C', 'Fit it')}\n"
        "def r():\n"
        "    return resources('Name', 'Menu', QT_TRANSLATE_NOOP('Name', 'Tip'), 'Section')\n",  # 17: flagged
        encoding="utf-8",
    )
    problems = tool.untranslated([str(source)])
    assert [p.line for p in problems] == [2, 3, 4, 5, 11, 14, 17], tool.format_problems(problems)
    assert "'chordal'" in problems[3].text and "MenuText" in problems[5].text


def test_translations_readme_says_how_to_add_a_language():
    with open(os.path.join(tool.TS_DIR, "README.md"), encoding="utf-8") as f:
        text = f.read()
    assert "FairSplines_de.ts" in text and "lrelease" in text and "update_translations.py" in text


def test_every_source_file_parses_and_is_scanned():
    paths = tool.source_files()
    assert os.path.join(REPO, "InitGui.py") in paths
    assert os.path.join(REPO, "freecad_workbench", "gui", "preferences.py") in paths
    for path in paths:
        with open(path, encoding="utf-8") as f:
            ast.parse(f.read(), filename=path)


def test_install_adds_the_translations_folder_and_reloads_the_language(monkeypatch):
    import FreeCADGui

    from freecad_workbench.gui import translations

    calls = []
    monkeypatch.setattr(FreeCADGui, "addLanguagePath", lambda path: calls.append(("path", path)), raising=False)
    monkeypatch.setattr(FreeCADGui, "updateLocale", lambda: calls.append(("update",)), raising=False)
    translations.install()
    assert calls == [("path", tool.TS_DIR), ("update",)]
    assert os.path.isfile(os.path.join(translations.TRANSLATIONS_DIR, "FairSplines.ts"))
