"""Argument checks of the study and plot scripts: a bad argument is one line naming it and exit 2, not a traceback
(the same contract as the unilag executables, apps/StudyArgs.hpp)."""
import os
import sys


def fail(message):
    print(f"{os.path.basename(sys.argv[0])}: error: {message}", file=sys.stderr)
    sys.exit(2)


def positional(count, usage, most=None, flags=()):
    """sys.argv[1:] less the `flags` given, checked: at least count arguments, at most `most` (default count), none
    an unknown option."""
    args = [a for a in sys.argv[1:] if a not in flags]
    most = count if most is None else most
    for a in args:
        if a in ("-h", "--help"):
            print(usage)
            sys.exit(0)
        if a.startswith("--"):
            fail(f"unknown option '{a}'\n{usage}")
    if not count <= len(args) <= most:
        fail(f"expected {count}{'' if most == count else f' to {most}'} arguments, found {len(args)}\n{usage}")
    return args


def number(text, what):
    try:
        return float(text)
    except ValueError:
        fail(f"{what}: '{text}' is not a number")


def input_file(folder, name):
    """folder/name, which must exist: the output of the study this script plots."""
    path = os.path.join(folder, name)
    if not os.path.isfile(path):
        fail(f"{path} not found (run the study first, or give its output folder)")
    return path
