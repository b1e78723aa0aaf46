// The load-time CPU check: a library built for x86-64-v3 (or native) on a CPU without those
// extensions would die of SIGILL at its first AVX2 instruction, far from any explanation. This
// file is compiled for baseline x86-64 (src/CMakeLists.txt) and runs before any other code of
// the library, so it can say what is missing and exit instead. It calls only C library
// functions and this file's own: see cpu_feature_table.h for why nothing inline is shared.

#include <cpuid.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "cpu_feature_table.h"

namespace raylab::cpu {

namespace {

// Bit `bit` of ECX from CPUID leaf `leaf`: for the extensions clang 14's __builtin_cpu_supports
// has no name for.
bool cpuid_ecx_bit(unsigned leaf, unsigned bit) {
  unsigned eax = 0, ebx = 0, ecx = 0, edx = 0;
  if (__get_cpuid(leaf, &eax, &ebx, &ecx, &edx) == 0) return false;
  return ((ecx >> bit) & 1u) != 0;
}

bool required(Feature f) { return ((kBuildFeatures >> f) & 1u) != 0; }

// Whether the comma- or space-separated `list` holds the word `name`.
bool listed(const char* list, const char* name) {
  const std::size_t n = std::strlen(name);
  for (const char* p = list; *p != '\0';) {
    const std::size_t word = std::strcspn(p, ", ");
    if (word == n && std::strncmp(p, name, n) == 0) return true;
    p += word;
    p += std::strspn(p, ", ");
  }
  return false;
}

// The headline of the message: the extensions people know a build by.
const char* headline() {
  if (required(kAvx512f)) return "AVX-512";
  if (required(kAvx2) && required(kFma)) return "AVX2 and FMA";
  if (required(kAvx2)) return "AVX2";
  if (required(kAvx)) return "AVX";
  return "the extensions listed";
}

}  // namespace

bool pretended_missing(Feature f) {
  const char* pretend = std::getenv("RAYLAB_CPU_CHECK_PRETEND_MISSING");
  return pretend != nullptr && listed(pretend, feature_name(f));
}

namespace {

// Runs when the library is loaded, before the constructors of its other files (priority 101
// comes first) and before the program's own. RAYLAB_CPU_CHECK_PRETEND_MISSING (a list such as
// "avx2,fma") makes it treat those extensions as missing, so that the tests can see the message.
__attribute__((constructor(101))) void check_cpu_at_load() {
  __builtin_cpu_init();  // the CPU model data may not be filled in yet this early
  const char* pretend = std::getenv("RAYLAB_CPU_CHECK_PRETEND_MISSING");
  bool any = false;
  for (int i = 0; i < kFeatureCount; ++i) {
    const auto f = static_cast<Feature>(i);
    if (!required(f)) continue;
    if (cpu_supports(f) && (pretend == nullptr || !listed(pretend, feature_name(f)))) continue;
    if (!any) {
      std::fprintf(stderr, "raylab: this build needs a CPU with %s (%s); this CPU lacks:", headline(), kBuildArch);
      any = true;
    }
    std::fprintf(stderr, " %s", feature_name(f));
  }
  if (!any) return;
  std::fputs("; rebuild with -DRAYLAB_ARCH=x86-64\n", stderr);
  std::_Exit(1);
}

}  // namespace

const char* feature_name(Feature f) {
  switch (f) {
    case kSse3:
      return "sse3";
    case kSsse3:
      return "ssse3";
    case kSse41:
      return "sse4.1";
    case kSse42:
      return "sse4.2";
    case kPopcnt:
      return "popcnt";
    case kAvx:
      return "avx";
    case kAvx2:
      return "avx2";
    case kFma:
      return "fma";
    case kBmi:
      return "bmi";
    case kBmi2:
      return "bmi2";
    case kF16c:
      return "f16c";
    case kMovbe:
      return "movbe";
    case kLzcnt:
      return "lzcnt";
    case kAvx512f:
      return "avx512f";
    case kAvx512vl:
      return "avx512vl";
    case kAvx512bw:
      return "avx512bw";
    case kAvx512dq:
      return "avx512dq";
    case kAvx512cd:
      return "avx512cd";
    case kAvx512vnni:
      return "avx512vnni";
    case kAvx512vbmi:
      return "avx512vbmi";
    case kAvx512vbmi2:
      return "avx512vbmi2";
    case kAvx512bitalg:
      return "avx512bitalg";
    case kAvx512vpopcntdq:
      return "avx512vpopcntdq";
    case kAvx512ifma:
      return "avx512ifma";
    case kAvx512bf16:
      return "avx512bf16";
    case kGfni:
      return "gfni";
    case kVpclmulqdq:
      return "vpclmulqdq";
    case kAes:
      return "aes";
    case kPclmul:
      return "pclmul";
    case kFeatureCount:
      break;
  }
  return "?";
}

bool cpu_supports(Feature f) {
  switch (f) {
    case kSse3:
      return __builtin_cpu_supports("sse3");
    case kSsse3:
      return __builtin_cpu_supports("ssse3");
    case kSse41:
      return __builtin_cpu_supports("sse4.1");
    case kSse42:
      return __builtin_cpu_supports("sse4.2");
    case kPopcnt:
      return __builtin_cpu_supports("popcnt");
    case kAvx:
      return __builtin_cpu_supports("avx");
    case kAvx2:
      return __builtin_cpu_supports("avx2");
    case kFma:
      return __builtin_cpu_supports("fma");
    case kBmi:
      return __builtin_cpu_supports("bmi");
    case kBmi2:
      return __builtin_cpu_supports("bmi2");
    case kF16c:
      return cpuid_ecx_bit(1, 29);
    case kMovbe:
      return cpuid_ecx_bit(1, 22);
    case kLzcnt:
      return cpuid_ecx_bit(0x80000001u, 5);  // ABM: LZCNT
    case kAvx512f:
      return __builtin_cpu_supports("avx512f");
    case kAvx512vl:
      return __builtin_cpu_supports("avx512vl");
    case kAvx512bw:
      return __builtin_cpu_supports("avx512bw");
    case kAvx512dq:
      return __builtin_cpu_supports("avx512dq");
    case kAvx512cd:
      return __builtin_cpu_supports("avx512cd");
    case kAvx512vnni:
      return __builtin_cpu_supports("avx512vnni");
    case kAvx512vbmi:
      return __builtin_cpu_supports("avx512vbmi");
    case kAvx512vbmi2:
      return __builtin_cpu_supports("avx512vbmi2");
    case kAvx512bitalg:
      return __builtin_cpu_supports("avx512bitalg");
    case kAvx512vpopcntdq:
      return __builtin_cpu_supports("avx512vpopcntdq");
    case kAvx512ifma:
      return __builtin_cpu_supports("avx512ifma");
    case kAvx512bf16:
      return __builtin_cpu_supports("avx512bf16");
    case kGfni:
      return __builtin_cpu_supports("gfni");
    case kVpclmulqdq:
      return __builtin_cpu_supports("vpclmulqdq");
    case kAes:
      return __builtin_cpu_supports("aes");
    case kPclmul:
      return __builtin_cpu_supports("pclmul");
    case kFeatureCount:
      break;
  }
  return false;
}

}  // namespace raylab::cpu
