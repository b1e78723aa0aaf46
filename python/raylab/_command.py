"""The `raylab` command of a pip-installed raylab (the console entry point of pyproject.toml).

The wheel ships the C++ program inside the package, in raylab/bin, beside the library it runs
with (raylab/lib); this replaces the Python process with it, so that the arguments, the exit
status, the signals and the output are the program's own.
"""

import os
import pathlib
import sys


def main():
    """Runs raylab/bin/raylab with this process's arguments; returns only if it cannot start."""
    program = pathlib.Path(__file__).resolve().parent / "bin" / "raylab"
    try:
        os.execv(program, [str(program)] + sys.argv[1:])
    except OSError as error:
        sys.stderr.write(f"raylab: cannot run {program}: {error.strerror}"
                         " (this raylab package was not installed from a wheel; see docs/python.md)\n")
        return 2
