"""The instruction-set check that runs before the extension is imported (raylab/_cpu_check.py)."""

import pytest

import raylab
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


def test_this_package_passes_its_own_check():
    # The package imported, so the check let it through: it must agree when asked again.
    assert _cpu_check.missing_features(_build.ARCH) == []
    assert raylab.__version__
