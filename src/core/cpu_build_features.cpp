// What the library's own -march lets the compiler use. Compiled with the library's options and
// nothing else: it only defines constants from the predefined macros, so that the load-time
// check (compiled for baseline x86-64) can read them without running any code built for the
// CPU it is checking for.

#include "cpu_feature_table.h"

namespace raylab::cpu {

namespace {
constexpr std::uint64_t bit(Feature f) { return std::uint64_t{1} << f; }
}  // namespace

const std::uint64_t kBuildFeatures = 0
#ifdef __SSE3__
                                     | bit(kSse3)
#endif
#ifdef __SSSE3__
                                     | bit(kSsse3)
#endif
#ifdef __SSE4_1__
                                     | bit(kSse41)
#endif
#ifdef __SSE4_2__
                                     | bit(kSse42)
#endif
#ifdef __POPCNT__
                                     | bit(kPopcnt)
#endif
#ifdef __AVX__
                                     | bit(kAvx)
#endif
#ifdef __AVX2__
                                     | bit(kAvx2)
#endif
#ifdef __FMA__
                                     | bit(kFma)
#endif
#ifdef __BMI__
                                     | bit(kBmi)
#endif
#ifdef __BMI2__
                                     | bit(kBmi2)
#endif
#ifdef __F16C__
                                     | bit(kF16c)
#endif
#ifdef __MOVBE__
                                     | bit(kMovbe)
#endif
#ifdef __LZCNT__
                                     | bit(kLzcnt)
#endif
#ifdef __AVX512F__
                                     | bit(kAvx512f)
#endif
#ifdef __AVX512VL__
                                     | bit(kAvx512vl)
#endif
#ifdef __AVX512BW__
                                     | bit(kAvx512bw)
#endif
#ifdef __AVX512DQ__
                                     | bit(kAvx512dq)
#endif
#ifdef __AVX512CD__
                                     | bit(kAvx512cd)
#endif
#ifdef __AVX512VNNI__
                                     | bit(kAvx512vnni)
#endif
#ifdef __AVX512VBMI__
                                     | bit(kAvx512vbmi)
#endif
#ifdef __AVX512VBMI2__
                                     | bit(kAvx512vbmi2)
#endif
#ifdef __AVX512BITALG__
                                     | bit(kAvx512bitalg)
#endif
#ifdef __AVX512VPOPCNTDQ__
                                     | bit(kAvx512vpopcntdq)
#endif
#ifdef __AVX512IFMA__
                                     | bit(kAvx512ifma)
#endif
#ifdef __AVX512BF16__
                                     | bit(kAvx512bf16)
#endif
#ifdef __GFNI__
                                     | bit(kGfni)
#endif
#ifdef __VPCLMULQDQ__
                                     | bit(kVpclmulqdq)
#endif
#ifdef __AES__
                                     | bit(kAes)
#endif
#ifdef __PCLMUL__
                                     | bit(kPclmul)
#endif
    ;

// src/CMakeLists.txt defines RAYLAB_ARCH_NAME for this file alone.
const char kBuildArch[] = RAYLAB_ARCH_NAME;

}  // namespace raylab::cpu
