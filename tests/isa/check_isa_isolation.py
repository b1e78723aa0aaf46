#!/usr/bin/python3
"""Checks that what a raylab library exports runs on baseline x86-64 outside its per-set kernels.

The kernel sources are compiled once per instruction set (src/CMakeLists.txt), and an inline
function they share with the rest of the library could be linked to the wider copy, which a
baseline caller would then run (SIGILL on a CPU without it). Inside the library the wider
objects come last on the link line, so the linker keeps the baseline copy of anything both
compile; and they are compiled with hidden visibility, so that nothing outside the library can
bind to a copy only they compile. This disassembles the library and fails, naming them, on the
exported functions that use an instruction beyond baseline x86-64 (anything VEX- or
EVEX-encoded, a ymm, zmm or mask register, or one of x86-64-v2/v3's non-VEX additions) without
belonging to an AVX2 or AVX-512 kernel (isa_avx2 / isa_avx512 in the demangled name).

Usage: check_isa_isolation.py LIBRARY [--expect-kernels]
With --expect-kernels it also fails when no function of either wider set is found: a build that
dropped its kernels, or compiled them at baseline, would pass the first check vacuously.
"""
import re
import subprocess
import sys

# Non-VEX instructions of x86-64-v2 and v3 that GCC emits from plain C++. TZCNT is left out:
# GCC's generic tuning writes `rep bsf`, which objdump shows as tzcnt and which runs as BSF on
# a CPU without BMI1.
EXTRA = {"popcnt", "lzcnt", "movbe", "pshufb", "pblendvb", "blendvps", "blendvpd", "ptest", "pminsd",
         "pmaxsd", "pminud", "pmaxud", "pmulld", "roundss", "roundsd", "roundps", "roundpd", "insertps",
         "extractps", "pextrd", "pinsrd", "pextrb", "pinsrb", "pmovzxbd", "pmovsxbd", "crc32", "pcmpeqq",
         "pcmpgtq", "dpps", "dppd", "packusdw", "pmovzxwd", "pmovzxdq", "pmovsxdq"}
WIDE_REGISTER = re.compile(r"%(ymm|zmm)\d+|%k[0-7]\b")
FUNCTION = re.compile(r"^[0-9a-f]+ <(.*)>:$")


def main():
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    if len(args) != 1:
        print(__doc__, file=sys.stderr)
        return 2
    expect_kernels = "--expect-kernels" in sys.argv
    exported = set()
    symbols = subprocess.run(["nm", "-D", "-C", "--defined-only", args[0]], check=True, capture_output=True,
                             text=True).stdout
    for line in symbols.splitlines():
        fields = line.split(" ", 2)
        if len(fields) == 3 and fields[1] in ("T", "W", "i"):
            exported.add(fields[2])
    dump = subprocess.run(["objdump", "-d", "-C", "--no-show-raw-insn", args[0]], check=True,
                          capture_output=True, text=True).stdout
    leaks = {}
    kernels = {"isa_avx2": 0, "isa_avx512": 0}
    function = None
    for line in dump.splitlines():
        m = FUNCTION.match(line)
        if m:
            function = m.group(1)
            continue
        if function is None or "\t" not in line:
            continue
        parts = line.split("\t")
        instruction = parts[-1].strip()
        if not instruction:
            continue
        mnemonic = instruction.split()[0]
        wide = mnemonic.startswith("v") or mnemonic in EXTRA or WIDE_REGISTER.search(instruction)
        if not wide:
            continue
        owner = next((k for k in kernels if k + "::" in function), None)
        if owner:
            kernels[owner] += 1
        elif function in exported:
            leaks.setdefault(function, instruction)
    for function, instruction in sorted(leaks.items()):
        print(f"outside the kernels: {function}: {instruction}")
    print(f"{len(leaks)} exported function(s) outside the kernels use wider instructions; "
          f"wider instructions inside them: avx2 {kernels['isa_avx2']}, avx512 {kernels['isa_avx512']}")
    if leaks:
        return 1
    if expect_kernels and (kernels["isa_avx2"] == 0 or kernels["isa_avx512"] == 0):
        print("expected AVX2 and AVX-512 kernels, found none of a set", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
