#!/usr/bin/python3
"""Contact sheet of the workbench icons: every icons/*.svg at 16, 24 and 64 px, with its name.

    QT_QPA_PLATFORM=offscreen /usr/bin/python3 tools/icon_sheet.py [-o out/icon-sheet.png]
        [--zoom 4] [--columns 3] [--only NAME ...] [--icons DIR]

Each cell: the 16 px and 24 px renderings blown up --zoom times (nearest neighbour, so the
pixels a toolbar shows are the pixels you see), then the 16, 24 and 64 px renderings at
their own size, then the name. All on white, as a light toolbar shows them.

Uses PySide2 (or PySide6) QtSvg directly; no FreeCAD needed.
"""
import argparse
import glob
import os
import sys

os.environ.setdefault("QT_QPA_PLATFORM", "offscreen")

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SIZES = (16, 24, 64)


def _qt():
    """QtCore, QtGui, QtSvg of the binding already loaded (two Qt libraries in one process
    crash), else of the first one installed."""
    loaded = [b for b in ("PySide6", "PySide2") if b in sys.modules]
    for binding in loaded or ("PySide2", "PySide6"):
        try:
            core = __import__(binding + ".QtCore", fromlist=["QtCore"])
            gui = __import__(binding + ".QtGui", fromlist=["QtGui"])
            svg = __import__(binding + ".QtSvg", fromlist=["QtSvg"])
            return core, gui, svg
        except ImportError:
            continue
    sys.exit("icon_sheet.py needs PySide2 or PySide6 with QtSvg")


QtCore, QtGui, QtSvg = _qt()


def render(path, size):
    """The icon at size x size px, transparent background (ARGB32 premultiplied)."""
    renderer = QtSvg.QSvgRenderer(path)
    if not renderer.isValid():
        raise ValueError("not a valid SVG: " + path)
    image = QtGui.QImage(size, size, QtGui.QImage.Format_ARGB32_Premultiplied)
    image.fill(0)
    painter = QtGui.QPainter(image)
    painter.setRenderHint(QtGui.QPainter.Antialiasing)
    painter.setRenderHint(QtGui.QPainter.SmoothPixmapTransform)
    renderer.render(painter, QtCore.QRectF(0, 0, size, size))
    painter.end()
    return image


def sheet(paths, zoom=4, columns=3):
    """One QImage with a row per icon, the rows in `columns` columns."""
    pad = 8
    big16, big24 = 16 * zoom, 24 * zoom
    row_h = max(big24, 64) + pad
    name_w = 260
    cell_w = pad + big16 + pad + big24 + pad + 16 + pad + 24 + pad + 64 + pad + name_w
    rows = -(-len(paths) // columns)
    width = cell_w * columns
    height = pad + row_h * rows
    out = QtGui.QImage(width, height, QtGui.QImage.Format_RGB32)
    out.fill(QtGui.QColor("white"))
    painter = QtGui.QPainter(out)
    font = painter.font()
    font.setPixelSize(13)
    painter.setFont(font)
    for index, path in enumerate(paths):
        column, row = divmod(index, rows)
        y = pad + row * row_h
        x = column * cell_w + pad
        if column:
            painter.setPen(QtGui.QColor("#bbbbbb"))
            painter.drawLine(x - pad, 0, x - pad, height)
        images = {size: render(path, size) for size in SIZES}
        for size, scaled in ((16, big16), (24, big24)):
            painter.drawImage(x, y, images[size].scaled(scaled, scaled, QtCore.Qt.IgnoreAspectRatio,
                                                        QtCore.Qt.FastTransformation))
            painter.setPen(QtGui.QColor("#dddddd"))
            painter.drawRect(x - 1, y - 1, scaled + 1, scaled + 1)
            x += scaled + pad
        for size in SIZES:
            painter.drawImage(x, y, images[size])
            x += size + pad
        painter.setPen(QtGui.QColor("black"))
        name = os.path.splitext(os.path.basename(path))[0]
        painter.drawText(QtCore.QRectF(x, y, name_w, row_h - pad), QtCore.Qt.AlignVCenter, name)
    painter.end()
    return out


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("-o", "--output", default=os.path.join(REPO, "out", "icon-sheet.png"))
    parser.add_argument("--icons", default=os.path.join(REPO, "icons"))
    parser.add_argument("--zoom", type=int, default=4)
    parser.add_argument("--columns", type=int, default=3)
    parser.add_argument("--only", nargs="*", help="icon names (without .svg) to show, in this order")
    args = parser.parse_args(argv)
    app = QtGui.QGuiApplication.instance() or QtGui.QGuiApplication(sys.argv[:1])  # kept alive while painting
    if args.only:
        paths = [os.path.join(args.icons, n if n.endswith(".svg") else n + ".svg") for n in args.only]
    else:
        paths = sorted(glob.glob(os.path.join(args.icons, "*.svg")))
    if not paths:
        sys.exit("no icons in " + args.icons)
    os.makedirs(os.path.dirname(os.path.abspath(args.output)), exist_ok=True)
    if not sheet(paths, args.zoom, args.columns).save(args.output):
        sys.exit("could not write " + args.output)
    print(f"{len(paths)} icons -> {args.output}")
    del app


if __name__ == "__main__":
    main()
