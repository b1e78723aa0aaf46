#pragma once
/// \file
/// The instruction sets raylab's hot kernels are compiled for, and which one runs. The library
/// itself is compiled for baseline x86-64; the kernels (the structures' walks, the packets, the
/// triangle blocks) are compiled once more for AVX2 + FMA (x86-64-v3) and for AVX-512
/// (x86-64-v4), and an accelerator takes, when it is built, the set active at that moment: the
/// best this CPU supports, unless lowered by the RAYLAB_ISA environment variable or set_isa.
/// Every set gives the same answers bit for bit (docs/architecture.md, "Instruction sets").

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace raylab {

/// A set of kernels, from the most portable to the widest.
enum class Isa {
  baseline,  ///< any x86-64 (SSE2), or the scalar fallback in a RAYLAB_SIMD_SCALAR build
  avx2,      ///< x86-64-v3: AVX2, FMA, BMI1/2, F16C, MOVBE, LZCNT
  avx512,    ///< x86-64-v4: AVX-512 F, VL, BW, DQ, CD on top of the above
};

/// The name of `isa` as `--isa` and RAYLAB_ISA spell it: "baseline", "avx2" or "avx512".
const char* isa_name(Isa isa);

/// The set named `name` ("baseline", "avx2", "avx512"), or nothing for any other text.
std::optional<Isa> parse_isa(std::string_view name);

/// The set named `name`, checked for use here. Throws std::invalid_argument, its message starting
/// with `source` (where the name came from, such as "--isa avx512" or "RAYLAB_ISA=avx512"), when
/// `name` names no set or one this build or CPU cannot run.
Isa usable_isa_named(std::string_view name, const std::string& source);

/// The sets this library was built with, in order (always at least one).
std::vector<Isa> built_isas();

/// The sets that are built and that this CPU (and its operating system) can run, in order.
std::vector<Isa> usable_isas();

/// Why `isa` cannot be used here (not built, or the CPU lacks something it needs: the missing
/// features are named), or an empty string when it can.
std::string isa_unusable_reason(Isa isa);

/// The set new accelerators take: the widest usable one, unless RAYLAB_ISA or set_isa chose
/// another. Throws std::invalid_argument when RAYLAB_ISA names no set or one not usable here
/// (the message names the variable and what it holds).
Isa active_isa();

/// Makes `isa` the set new accelerators take (accelerators already built keep theirs). Throws
/// std::invalid_argument, naming the set and the reason, when it is not usable here.
void set_isa(Isa isa);

/// Sets `isa` for the lifetime of this object, then restores the set that was active before.
class ScopedIsa {
 public:
  /// Calls set_isa(isa).
  explicit ScopedIsa(Isa isa);
  ~ScopedIsa();
  ScopedIsa(const ScopedIsa&) = delete;
  ScopedIsa& operator=(const ScopedIsa&) = delete;

 private:
  Isa m_previous;
};

/// One line for `--version` and reports: the active set, the sets built and those this CPU
/// can run, e.g. "kernels: avx512 (built: baseline, avx2, avx512; this CPU: baseline, avx2,
/// avx512)". Where RAYLAB_ISA is invalid the line says so instead of naming an active set.
std::string isa_summary();

/// The widest box width the kernels of `isa` test with one instruction per plane: the node
/// width of the default wide BVH ("bvh"), 16 with AVX-512, else 8.
int native_box_width(Isa isa);

}  // namespace raylab
