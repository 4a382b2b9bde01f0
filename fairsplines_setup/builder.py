"""The first-run build of the kernel: cmake, headless, with progress, a log and no root.

    result = builder.build(progress=lambda fraction, line: ...)

configures the add-on's own sources (the Python module only: no tests, no benchmarks) for
the running interpreter and builds them into the user's kernel folder (record.user_kernel_dir),
where freecad_workbench finds it at its next import. The whole output goes to a log file;
a failure returns the log's last lines. The dialog (dialog.py) runs this on a thread.
"""
from __future__ import annotations

import os
import re
import shutil
import subprocess
import sys
import time
from collections import namedtuple

from . import record

SOURCE_DIR = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
TAIL_LINES = 25
# CMake's Makefile generator prints "[ 45%] Building ..." per step.
_PERCENT = re.compile(r"^\[\s*(\d+)%\]")
CONFIGURE_SHARE = 0.05  # of the progress bar: the configure step; the rest is the compilation

BuildResult = namedtuple("BuildResult", "ok kernel_dir log_path tail seconds")
BuildResult.__doc__ = (
    "ok: the module is built; kernel_dir: where it is; log_path: the full log; "
    "tail: its last lines (the compiler's message on a failure); seconds: the build's duration."
)


def python_executable():
    """The interpreter FreeCAD embeds, as a program CMake can run (inside FreeCAD,
    sys.executable is FreeCAD itself): pythonX.Y beside sys.base_prefix, or on PATH."""
    name = f"python{sys.version_info.major}.{sys.version_info.minor}"
    for candidate in (os.path.join(sys.base_prefix, "bin", name), shutil.which(name)):
        if candidate and os.path.isfile(candidate):
            return candidate
    return sys.executable


def work_dir():
    """The folder of the build tree and the log (beside the kernel folder)."""
    return os.path.dirname(record.user_kernel_dir())


def default_jobs():
    """FAIRSPLINES_BUILD_JOBS, or every core."""
    try:
        return max(1, int(os.environ.get("FAIRSPLINES_BUILD_JOBS", "")))
    except ValueError:
        return os.cpu_count() or 1


def commands(kernel_dir, build_dir, jobs, cmake="cmake", source_dir=SOURCE_DIR):
    """The two commands of the build: configure, then compile."""
    return [
        [cmake, "-S", source_dir, "-B", build_dir, "-DCMAKE_BUILD_TYPE=Release",
         "-DPython_EXECUTABLE=" + python_executable(), "-DFAIRSPLINES_BUILD_TESTS=OFF",
         "-DFAIRSPLINES_BUILD_BENCH=OFF", "-DFAIRSPLINES_MODULE_DIR=" + kernel_dir],
        [cmake, "--build", build_dir, "-j", str(jobs)],
    ]


def tail(path, lines=TAIL_LINES):
    """The last `lines` lines of a text file."""
    try:
        with open(path, encoding="utf-8", errors="replace") as f:
            return "".join(f.readlines()[-lines:])
    except OSError:
        return ""


def build(progress=None, kernel_dir=None, jobs=None, cmake="cmake", source_dir=SOURCE_DIR, cancelled=None):
    """Build the kernel into kernel_dir (default the user's kernel folder).

    progress(fraction, line): called for every output line, fraction in [0, 1].
    cancelled(): polled between lines; True stops the build (a failed result).
    The module's old files in kernel_dir are removed first, so a failed build leaves no
    stale kernel that looks current."""
    kernel_dir = kernel_dir or record.user_kernel_dir()
    base = os.path.dirname(kernel_dir.rstrip(os.sep))
    build_dir = os.path.join(base, "build-" + os.path.basename(kernel_dir.rstrip(os.sep)))
    log_path = os.path.join(base, "build-" + os.path.basename(kernel_dir.rstrip(os.sep)) + ".log")
    os.makedirs(kernel_dir, exist_ok=True)
    for name in os.listdir(kernel_dir):
        if name.startswith(("_kernel", "occ_bridge", "_occ_bridge")):
            os.remove(os.path.join(kernel_dir, name))
    start = time.monotonic()
    report = progress or (lambda fraction, line: None)
    ok = True
    with open(log_path, "w", encoding="utf-8", buffering=1) as log:  # line by line: a crash keeps the log
        for step, command in enumerate(commands(kernel_dir, build_dir, jobs or default_jobs(), cmake, source_dir)):
            log.write("$ " + " ".join(command) + "\n")
            log.flush()
            try:
                process = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                                           errors="replace", env=dict(os.environ, LC_ALL="C"))
            except OSError as exc:  # cmake itself missing
                log.write(f"cannot run {command[0]}: {exc}\n")
                ok = False
                break
            fraction = 0.0 if step == 0 else CONFIGURE_SHARE
            for line in process.stdout:
                log.write(line)
                match = _PERCENT.match(line)
                if step == 1 and match:
                    fraction = CONFIGURE_SHARE + (1 - CONFIGURE_SHARE) * int(match.group(1)) / 100
                report(min(fraction, 1.0), line.rstrip("\n"))
                if cancelled is not None and cancelled():
                    process.terminate()
                    log.write("build cancelled\n")
                    break
            status = process.wait()
            if status != 0:
                log.write(f"exit status {status}\n")
                ok = False
                break
    ok = ok and record.module_file(kernel_dir) is not None and record.read(kernel_dir) is not None
    if ok:
        report(1.0, "built")
    return BuildResult(ok, kernel_dir, log_path, tail(log_path), time.monotonic() - start)


def main(argv=None):
    """`python3 -m fairsplines_setup.builder [KERNEL_DIR]`: the build from a shell, as the GUI
    runs it (tools/first-run-test.sh); exit status 0 when built."""
    args = sys.argv[1:] if argv is None else argv
    last = [-1]

    def show(fraction, line):
        percent = int(fraction * 100)
        if percent != last[0]:
            last[0] = percent
            print(f"[{percent:3d}%] {line}", flush=True)

    result = build(show, kernel_dir=args[0] if args else None)
    verdict = "built" if result.ok else "FAILED"
    print(f"{verdict} in {result.seconds:.0f} s: {result.kernel_dir} (log {result.log_path})")
    if not result.ok:
        print(result.tail)
    return 0 if result.ok else 1


if __name__ == "__main__":
    sys.exit(main())
