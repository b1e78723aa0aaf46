"""The instruction-set check that runs before the extension is imported (raylab/_cpu_check.py)."""

import subprocess
import sys

import pytest

from raylab import _build, _cpu_check

V2_FLAGS = "fpu sse sse2 ssse3 sse4_1 sse4_2 popcnt cx16"
V3_FLAGS = V2_FLAGS + " avx avx2 fma bmi1 bmi2 f16c movbe"


def cpuinfo(tmp_path, flags):
    """A /proc/cpuinfo of one processor with these flags."""
    path = tmp_path / "cpuinfo"
    path.write_text(f"processor\t: 0\nmodel name\t: test\nflags\t\t: {flags}\n\n", encoding="ascii")
    return path


def test_baseline_build_needs_nothing(tmp_path):
    assert _cpu_check.missing_features("x86-64", cpuinfo(tmp_path, "fpu sse sse2")) == []


def test_avx2_build_on_an_older_cpu_names_what_is_missing(tmp_path):
    path = cpuinfo(tmp_path, V2_FLAGS)
    assert _cpu_check.missing_features("x86-64-v3", path) == ["avx", "avx2", "fma", "bmi1", "bmi2", "f16c", "movbe"]
    with pytest.raises(ImportError, match=r"built for x86-64-v3 and this CPU lacks avx, avx2, fma"):
        _cpu_check.require_cpu("x86-64-v3", path)


def test_avx512_build_on_an_avx2_cpu_names_only_avx512(tmp_path):
    missing = _cpu_check.missing_features("x86-64-v4", cpuinfo(tmp_path, V3_FLAGS))
    assert missing == ["avx512f", "avx512vl", "avx512bw", "avx512dq", "avx512cd"]


def test_unknown_arch_is_held_to_avx2(tmp_path):
    # A "native" build: at least what x86-64-v3 needs.
    assert _cpu_check.missing_features("native", cpuinfo(tmp_path, V3_FLAGS)) == []
    assert "avx2" in _cpu_check.missing_features("native", cpuinfo(tmp_path, V2_FLAGS))


def test_unreadable_cpuinfo_blocks_nothing(tmp_path):
    assert _cpu_check.missing_features("x86-64-v4", tmp_path / "absent") == []


def test_the_package_runs_the_check_before_the_extension():
    # A check that refuses (a stand-in for a CPU without the build's features) must stop the
    # import with its ImportError before the compiled module is loaded.
    script = (
        "import sys, types\n"
        "stub = types.ModuleType('raylab._cpu_check')\n"
        "def refuse(arch):\n"
        "    raise ImportError('refused for ' + arch)\n"
        "stub.require_cpu = refuse\n"
        "sys.modules['raylab._cpu_check'] = stub\n"
        "try:\n"
        "    import raylab\n"
        "except ImportError as error:\n"
        "    print(error)\n"
        "    print('extension loaded' if 'raylab._raylab' in sys.modules else 'extension not loaded')\n"
    )
    out = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, check=True).stdout
    assert out.splitlines() == [f"refused for {_build.ARCH}", "extension not loaded"], out
