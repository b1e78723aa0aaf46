#!/usr/bin/python3
"""Times two commands against each other: whole processes, alternating which goes first, median
of RUNS each (docs/performance.md quotes it for before/after comparisons of one program).

usage: scripts/time-two-commands.py RUNS -- COMMAND_A ... -- COMMAND_B ...
Prints the two medians in milliseconds and A / B. Output of the commands is discarded; a command
that fails stops the comparison (exit 1).
"""
import os
import statistics
import sys
import time


def main(argv):
    if len(argv) < 5 or not argv[1].isdigit() or argv[2] != "--" or "--" not in argv[3:]:
        print(__doc__.strip(), file=sys.stderr)
        return 2
    runs = int(argv[1])
    rest = argv[3:]
    split = rest.index("--")
    commands = [rest[:split], rest[split + 1:]]
    if not commands[0] or not commands[1] or runs < 1:
        print(__doc__.strip(), file=sys.stderr)
        return 2
    times = [[], []]
    devnull = os.open(os.devnull, os.O_WRONLY)
    for run in range(runs):
        for side in ((0, 1) if run % 2 == 0 else (1, 0)):
            command = commands[side]
            start = time.perf_counter()
            pid = os.posix_spawnp(command[0], command, os.environ,
                                  file_actions=[(os.POSIX_SPAWN_DUP2, devnull, 1), (os.POSIX_SPAWN_DUP2, devnull, 2)])
            _, status = os.waitpid(pid, 0)
            times[side].append(time.perf_counter() - start)
            if os.waitstatus_to_exitcode(status) != 0:
                print(f"time-two-commands: {' '.join(command)} failed", file=sys.stderr)
                return 1
    a, b = (statistics.median(t) * 1e3 for t in times)
    print(f"A {a:.2f} ms  B {b:.2f} ms  A/B {a / b:.3f}  (median of {runs} each)")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
