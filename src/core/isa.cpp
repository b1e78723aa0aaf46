#include "raylab/core/isa.h"

#include <array>
#include <atomic>
#include <cstdlib>
#include <stdexcept>

#include "cpu_feature_table.h"
#include "raylab/simd/isa_namespace.h"

namespace raylab {

namespace {

using cpu::Feature;

// What the kernels of each set are compiled to use (their -march level, src/CMakeLists.txt).
constexpr std::array kAvx2Features = {cpu::kSse3, cpu::kSsse3, cpu::kSse41, cpu::kSse42, cpu::kPopcnt,
                                      cpu::kAvx,  cpu::kAvx2,  cpu::kFma,   cpu::kBmi,   cpu::kBmi2,
                                      cpu::kF16c, cpu::kMovbe, cpu::kLzcnt};
constexpr std::array kAvx512Features = {cpu::kAvx512f, cpu::kAvx512vl, cpu::kAvx512bw, cpu::kAvx512dq, cpu::kAvx512cd};

template <std::size_t N>
void add_missing(const std::array<Feature, N>& features, std::string& missing) {
  for (Feature f : features) {
    if (cpu::cpu_supports(f) && !cpu::pretended_missing(f)) continue;
    missing += missing.empty() ? "" : ", ";
    missing += cpu::feature_name(f);
  }
}

// The features `isa` needs that this CPU lacks, comma-separated (empty when it has them all).
std::string missing_features(Isa isa) {
  std::string missing;
  if (isa == Isa::baseline) return missing;
  add_missing(kAvx2Features, missing);
  if (isa == Isa::avx512) add_missing(kAvx512Features, missing);
  return missing;
}

bool built(Isa isa) {
  if (isa == kOwnKernelIsa) return true;
#ifdef RAYLAB_KERNELS_AVX2
  if (isa == Isa::avx2) return true;
#endif
#ifdef RAYLAB_KERNELS_AVX512
  if (isa == Isa::avx512) return true;
#endif
  return false;
}

constexpr std::array kAllIsas = {Isa::baseline, Isa::avx2, Isa::avx512};

// -1 until the first active_isa() or set_isa(); then the set as an int.
std::atomic<int> g_active{-1};

Isa widest_usable() {
  const std::vector<Isa> usable = usable_isas();
  return usable.back();
}

// The set RAYLAB_ISA asks for, checked; the widest usable one when it is unset or empty.
Isa isa_from_environment() {
  const char* value = std::getenv("RAYLAB_ISA");
  if (value == nullptr || *value == '\0') return widest_usable();
  return usable_isa_named(value, std::string("RAYLAB_ISA=") + value);
}

}  // namespace

const char* isa_name(Isa isa) {
  switch (isa) {
    case Isa::avx2:
      return "avx2";
    case Isa::avx512:
      return "avx512";
    case Isa::baseline:
      break;
  }
  return "baseline";
}

std::optional<Isa> parse_isa(std::string_view name) {
  for (Isa isa : kAllIsas) {
    if (name == isa_name(isa)) return isa;
  }
  return std::nullopt;
}

Isa usable_isa_named(std::string_view name, const std::string& source) {
  const std::optional<Isa> isa = parse_isa(name);
  if (!isa) throw std::invalid_argument(source + ": not an instruction set (expected baseline, avx2 or avx512)");
  const std::string reason = isa_unusable_reason(*isa);
  if (!reason.empty()) throw std::invalid_argument(source + ": " + reason);
  return *isa;
}

std::vector<Isa> built_isas() {
  std::vector<Isa> isas;
  for (Isa isa : kAllIsas) {
    if (built(isa)) isas.push_back(isa);
  }
  return isas;
}

std::vector<Isa> usable_isas() {
  std::vector<Isa> isas;
  for (Isa isa : kAllIsas) {
    if (isa_unusable_reason(isa).empty()) isas.push_back(isa);
  }
  return isas;
}

std::string isa_unusable_reason(Isa isa) {
  if (!built(isa)) return std::string("the library was built without its ") + isa_name(isa) + " kernels";
  // The library's own set always runs: the load-time check (cpu_check.cpp) refused it otherwise.
  if (isa == kOwnKernelIsa) return {};
  const std::string missing = missing_features(isa);
  if (!missing.empty()) return std::string("this CPU lacks ") + missing;
  return {};
}

Isa active_isa() {
  int active = g_active.load(std::memory_order_acquire);
  if (active < 0) {
    // Two threads may both read the environment; they store the same answer.
    active = static_cast<int>(isa_from_environment());
    int expected = -1;
    if (!g_active.compare_exchange_strong(expected, active, std::memory_order_acq_rel)) active = expected;
  }
  return static_cast<Isa>(active);
}

void set_isa(Isa isa) {
  usable_isa_named(isa_name(isa), std::string("instruction set ") + isa_name(isa));  // throws when unusable
  g_active.store(static_cast<int>(isa), std::memory_order_release);
}

ScopedIsa::ScopedIsa(Isa isa) : m_previous(active_isa()) { set_isa(isa); }

ScopedIsa::~ScopedIsa() { g_active.store(static_cast<int>(m_previous), std::memory_order_release); }

namespace {

std::string joined_names(const std::vector<Isa>& isas) {
  std::string text;
  for (Isa isa : isas) text += (text.empty() ? "" : ", ") + std::string(isa_name(isa));
  return text;
}

}  // namespace

std::string isa_summary() {
  std::string active;
  try {
    active = isa_name(active_isa());
  } catch (const std::invalid_argument& e) {
    active = std::string("none (") + e.what() + ")";
  }
  return "kernels: " + active + " (built: " + joined_names(built_isas()) +
         "; this CPU: " + joined_names(usable_isas()) + ")";
}

int native_box_width(Isa isa) { return isa == Isa::avx512 ? 16 : 8; }

}  // namespace raylab
