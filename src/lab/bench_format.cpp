// `raylab bench`, the printing half: the text table and the JSON document of a BenchReport.

#include <fmt/format.h>

#include <string>

#include "raylab/lab/bench.h"
#include "report_json.h"

namespace raylab {
namespace {

using detail::ReportJson;

// One table row: label, rays (0: none), both figures and the ratio; Embree columns blank when
// it was not measured. `digits` decimals.
std::string row(const std::string& label, std::size_t rays, const BenchFigure& f, bool embree, int digits = 2) {
  const std::string count = rays > 0 ? std::to_string(rays) : "";
  const std::string theirs = embree ? fmt::format("{:.{}f}", f.embree, digits) : "-";
  const std::string ratio = embree && f.embree > 0.0 ? fmt::format("{:.3f}", f.ratio()) : "-";
  return fmt::format("{:<28}{:>10}{:>12.{}f}{:>12}{:>13}\n", label, count, f.ours, digits, theirs, ratio);
}

std::string agreement_text(const BenchAgreement& a) {
  return fmt::format("{} same, {} ties, {} Embree edge cracks, {} disagreements", a.same, a.ties, a.embree_cracks,
                     a.disagreements);
}

// Both sides of a figure and their ratio; Embree's side and the ratio null when not measured.
ReportJson figure_json(const BenchFigure& f, bool embree) {
  return {{"ours", f.ours},
          {"embree", embree ? ReportJson(f.embree) : ReportJson(nullptr)},
          {"ratio", embree && f.embree > 0.0 ? ReportJson(f.ratio()) : ReportJson(nullptr)}};
}

ReportJson agreement_json(const BenchAgreement& a) {
  return {{"same", a.same}, {"ties", a.ties}, {"embree_cracks", a.embree_cracks}, {"disagreements", a.disagreements}};
}

}  // namespace

std::string format_bench_table(const BenchReport& r, const std::string& scene_name) {
  std::string out = fmt::format("bench {}: {} primitives ({} triangles)", scene_name, r.primitives, r.triangles);
  if (r.width > 0) out += fmt::format("; {}x{} primary rays in 4x4 tiles", r.width, r.height);
  out += fmt::format("; {} thread{}; median of {} runs, ours and Embree interleaved; our kernels: {}\n", r.threads,
                     r.threads == 1 ? "" : "s", r.repeats, r.kernels);
  out += fmt::format("{:<28}{:>10}{:>12}{:>12}{:>13}\n", "", "rays", "raylab " + r.accel, r.embree ? "embree 3" : "-",
                     "ours/embree");
  for (const BenchSetReport& s : r.sets) {
    out += row(s.name + " single Mrays/s", s.rays, s.single_mrays, r.embree);
    if (s.packets) out += row(s.name + " packet16 Mrays/s", s.rays, s.packet_mrays, r.embree);
  }
  out += row("build ms", 0, r.build_ms, r.embree);
  out += row("build Mprims/s", 0, r.build_mprims, r.embree);
  out += row("bytes/triangle", 0, r.bytes_per_triangle, r.embree, 1);
  out += row("SAH cost, binary tree", 0, r.sah_cost, r.embree);
  out += "\n";
  for (const BenchSetReport& s : r.sets) {
    out += fmt::format("{} rays: {} of {} {}", s.name, s.answered, s.rays, s.closest ? "hit" : "occluded");
    if (r.embree) out += fmt::format("; single: {}", agreement_text(s.single));
    if (s.packets) out += fmt::format("; packets{}: {}", r.embree ? "" : " vs our singles", agreement_text(s.packet));
    out += "\n";
  }
  for (const std::string& note : r.notes) out += "note: " + note + "\n";
  return out;
}

std::string format_bench_json(const BenchReport& r, const std::string& scene_name) {
  const Vec3 p = r.light.position;
  ReportJson doc = {{"scene", scene_name},        {"accel", r.accel},         {"kernels", r.kernels},
                    {"primitives", r.primitives}, {"triangles", r.triangles}, {"user_primitives", r.user_primitives},
                    {"width", r.width},           {"height", r.height},       {"threads", r.threads},
                    {"repeats", r.repeats},       {"embree", r.embree}};
  doc["light"] = {{"position", {p.x, p.y, p.z}}, {"from_scene", r.light_from_scene}};
  doc["build_ms"] = figure_json(r.build_ms, r.embree);
  doc["build_mprims_per_s"] = figure_json(r.build_mprims, r.embree);
  doc["bytes_per_triangle"] = figure_json(r.bytes_per_triangle, r.embree);
  doc["sah_cost"] = figure_json(r.sah_cost, r.embree);
  ReportJson& sets = doc["sets"] = ReportJson::array();
  for (const BenchSetReport& s : r.sets) {
    ReportJson set = {{"name", s.name},
                      {"query", s.closest ? "closest" : "any"},
                      {"rays", s.rays},
                      {"answered", s.answered},
                      {"single",
                       {{"mrays_per_s", figure_json(s.single_mrays, r.embree)},
                        {"agreement", r.embree ? agreement_json(s.single) : ReportJson(nullptr)}}}};
    set["packet16"] = s.packets ? ReportJson{{"mrays_per_s", figure_json(s.packet_mrays, r.embree)},
                                             {"agreement", agreement_json(s.packet)}}
                                : ReportJson(nullptr);
    sets.push_back(std::move(set));
  }
  doc["notes"] = r.notes;
  return detail::report_text(doc);
}

}  // namespace raylab
