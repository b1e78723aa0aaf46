// `raylab compare`, the printing half: the aligned table, the disagreements, the CSV and the
// JSON document of a CompareResult.

#include <fmt/format.h>

#include <algorithm>
#include <string>

#include "raylab/core/byte_size.h"
#include "raylab/lab/accel_compare.h"
#include "report_json.h"

namespace raylab {
namespace {

using detail::ReportJson;

std::string agreement_text(const AccelMeasure& m) {
  if (m.skipped) return "-";
  if (m.is_reference) return "reference";
  if (m.mismatch_count == 0) return "ok";
  return fmt::format("{} rays differ", m.mismatch_count);
}

std::string ray_text(const Ray& r) {
  return fmt::format("origin ({:.9g}, {:.9g}, {:.9g}) direction ({:.9g}, {:.9g}, {:.9g}) tmin {:.9g} tmax {:.9g}",
                     r.origin.x, r.origin.y, r.origin.z, r.direction.x, r.direction.y, r.direction.z, r.tmin, r.tmax);
}

std::string hit_text(const Hit& h) {
  if (!h.valid()) return "miss";
  return fmt::format("prim {} at t {:.9g} (u {:.6g}, v {:.6g})", h.prim_id, h.t, h.u, h.v);
}

// A rate with two decimals, or three significant digits when below one (brute force).
std::string rate_text(double v) { return v >= 1.0 ? fmt::format("{:.2f}", v) : fmt::format("{:.3g}", v); }

// `text` without spaces before its line breaks (centred and padded headers leave some).
std::string trim_line_ends(const std::string& text) {
  std::string out;
  for (const char c : text) {
    if (c == '\n') {
      while (!out.empty() && out.back() == ' ') out.pop_back();
    }
    out += c;
  }
  return out;
}

// Widths of the table's columns.
constexpr int kNumber = 9;
constexpr int kGroup = 3 * kNumber;

}  // namespace

std::string format_compare_table(const CompareResult& result, const std::string& scene_name) {
  std::size_t name_width = 9;
  for (const AccelMeasure& m : result.accels) name_width = std::max(name_width, m.name.size());
  const int nw = static_cast<int>(name_width) + 2;
  std::string out;
  auto put = [&out](const std::string& s) { out += s; };
  put(fmt::format("scene {}: {} primitives; rays from {}x{} pixel centres: {} primary, {} shadow, {} diffuse\n",
                  scene_name, result.primitive_count, result.width, result.height, result.rays[0], result.rays[1],
                  result.rays[2]));
  put(fmt::format(
      "{} threads; Mrays/s: median of {} passes; per-ray counts: one counted pass; build: median of the runs\n",
      result.threads, result.repeat));
  put(fmt::format("{:<{}}{:>10}{:>6}{:>12}{:>9}  {:^{}}  {:^{}}  {:^{}}\n", "", nw, "build", "", "memory", "",
                  "Mrays/s", kGroup, "nodes or cells / ray", kGroup, "primitive tests / ray", kGroup));
  put(fmt::format("{:<{}}{:>10}{:>6}{:>12}{:>9}", "structure", nw, "ms", "runs", "bytes", "B/prim"));
  for (int g = 0; g < 3; ++g) {
    put("  ");
    for (int k = 0; k < kBenchRayKinds; ++k) put(fmt::format("{:>{}}", bench_ray_kind_name(BenchRayKind(k)), kNumber));
  }
  put("  agreement\n");
  for (const AccelMeasure& m : result.accels) {
    put(fmt::format("{:<{}}", m.name, nw));
    if (m.skipped) {
      put(fmt::format("skipped (estimated {:.0f} s)\n", m.estimated_seconds));
      continue;
    }
    put(fmt::format("{:>10.3f}{:>6}{:>12}{:>9.1f}", m.build_seconds * 1e3, m.builds, human_bytes(m.info.memory_bytes),
                    m.bytes_per_primitive));
    put("  ");
    for (const KindMeasure& k : m.kinds) {
      put(fmt::format("{:>{}}", k.rays ? rate_text(k.mrays_per_second) : "-", kNumber));
    }
    for (const bool nodes : {true, false}) {
      put("  ");
      for (const KindMeasure& k : m.kinds) {
        if (!m.has_counts || k.rays == 0) {
          put(fmt::format("{:>{}}", m.has_counts ? "-" : "n/a", kNumber));
        } else {
          put(fmt::format("{:>{}.1f}", nodes ? k.nodes_per_ray : k.tests_per_ray, kNumber));
        }
      }
    }
    put("  " + agreement_text(m) + "\n");
  }
  return trim_line_ends(out);
}

std::string format_mismatches(const CompareResult& result) {
  std::string out;
  for (const AccelMeasure& m : result.accels) {
    if (m.mismatch_count == 0) continue;
    out += fmt::format("{} disagrees with {} on {} rays; the first {}:\n", m.name, result.reference, m.mismatch_count,
                       m.mismatches.size());
    for (const Mismatch& x : m.mismatches) {
      out += fmt::format("  {} ray {}: {}\n", bench_ray_kind_name(x.kind), x.index, ray_text(x.ray));
      if (x.kind == BenchRayKind::kShadow) {
        out += fmt::format("    {}: {}; {}: {}\n", result.reference, x.expected_occluded ? "occluded" : "not occluded",
                           m.name, x.found_occluded ? "occluded" : "not occluded");
      } else {
        out +=
            fmt::format("    {}: {}\n    {}: {}\n", result.reference, hit_text(x.expected), m.name, hit_text(x.found));
      }
    }
    if (m.mismatch_count > m.mismatches.size()) {
      out += fmt::format("  ... and {} more\n", m.mismatch_count - m.mismatches.size());
    }
  }
  return out;
}

std::string format_compare_csv(const CompareResult& result) {
  std::string out = "structure,skipped,estimated_s,build_ms,builds,memory_bytes,bytes_per_primitive";
  for (const char* what : {"mrays_per_s", "nodes_per_ray", "tests_per_ray"}) {
    for (int k = 0; k < kBenchRayKinds; ++k) out += fmt::format(",{}_{}", bench_ray_kind_name(BenchRayKind(k)), what);
  }
  out += ",mismatches\n";
  for (const AccelMeasure& m : result.accels) {
    out += fmt::format("{},{},{:.3f}", m.name, m.skipped ? 1 : 0, m.estimated_seconds);
    if (m.skipped) {
      out += std::string(14, ',') + "\n";
      continue;
    }
    out += fmt::format(",{:.4f},{},{},{:.2f}", m.build_seconds * 1e3, m.builds, m.info.memory_bytes,
                       m.bytes_per_primitive);
    for (const KindMeasure& k : m.kinds) out += k.rays ? fmt::format(",{:.4f}", k.mrays_per_second) : ",";
    for (const bool nodes : {true, false}) {
      for (const KindMeasure& k : m.kinds) {
        out += m.has_counts && k.rays ? fmt::format(",{:.3f}", nodes ? k.nodes_per_ray : k.tests_per_ray) : ",";
      }
    }
    out += fmt::format(",{}\n", m.mismatch_count);
  }
  return out;
}

std::string format_compare_json(const CompareResult& result, const std::string& scene_name) {
  ReportJson structures = ReportJson::array();
  for (const AccelMeasure& m : result.accels) {
    ReportJson s;
    s["name"] = m.name;
    s["skipped"] = m.skipped;
    s["estimated_seconds"] = m.estimated_seconds;
    if (!m.skipped) {
      s["build_seconds"] = m.build_seconds;
      s["builds"] = m.builds;
      s["memory_bytes"] = m.info.memory_bytes;
      s["bytes_per_primitive"] = m.bytes_per_primitive;
      s["mismatches"] = m.mismatch_count;
      ReportJson& rays = s["rays"] = ReportJson::object();
      for (int k = 0; k < kBenchRayKinds; ++k) {
        const KindMeasure& km = m.kinds[k];
        // Embree counts nothing: its counts are null, not zero.
        const auto count = [&](double v) { return m.has_counts ? ReportJson(v) : ReportJson(nullptr); };
        rays[bench_ray_kind_name(BenchRayKind(k))] = {{"rays", km.rays},
                                                      {"hits", km.hits},
                                                      {"mrays_per_second", km.mrays_per_second},
                                                      {"nodes_per_ray", count(km.nodes_per_ray)},
                                                      {"tests_per_ray", count(km.tests_per_ray)}};
      }
    }
    structures.push_back(std::move(s));
  }
  const ReportJson doc = {{"scene", scene_name},
                          {"primitives", result.primitive_count},
                          {"width", result.width},
                          {"height", result.height},
                          {"threads", result.threads},
                          {"repeat", result.repeat},
                          {"reference", result.reference},
                          {"agreed", result.agreed()},
                          {"structures", std::move(structures)}};
  return detail::report_text(doc);
}

}  // namespace raylab
