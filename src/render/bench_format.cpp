// `raylab bench`, the printing half: the text table and the JSON document of a BenchReport.

#include <fmt/format.h>

#include <string>

#include "json_text.h"
#include "raylab/render/bench.h"

namespace raylab {
namespace {

using detail::json_number;
using detail::json_string;

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

std::string figure_json(const BenchFigure& f, bool embree) {
  return fmt::format("{{\"ours\": {}, \"embree\": {}, \"ratio\": {}}}", json_number(f.ours),
                     embree ? json_number(f.embree) : "null",
                     embree && f.embree > 0.0 ? json_number(f.ratio()) : "null");
}

std::string agreement_json(const BenchAgreement& a) {
  return fmt::format("{{\"same\": {}, \"ties\": {}, \"embree_cracks\": {}, \"disagreements\": {}}}", a.same, a.ties,
                     a.embree_cracks, a.disagreements);
}

}  // namespace

std::string format_bench_table(const BenchReport& r, const std::string& scene_name) {
  std::string out = fmt::format("bench {}: {} primitives ({} triangles)", scene_name, r.primitives, r.triangles);
  if (r.width > 0) out += fmt::format("; {}x{} primary rays in 4x4 tiles", r.width, r.height);
  out += fmt::format("; {} thread{}; median of {} runs, ours and Embree interleaved\n", r.threads,
                     r.threads == 1 ? "" : "s", r.repeats);
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
  std::string out = fmt::format(
      "{{\n  \"scene\": {},\n  \"accel\": {},\n  \"primitives\": {},\n  \"triangles\": {},\n  \"user_primitives\": "
      "{},\n  \"width\": {},\n  \"height\": {},\n  \"threads\": {},\n  \"repeats\": {},\n  \"embree\": {},\n",
      json_string(scene_name), json_string(r.accel), r.primitives, r.triangles, r.user_primitives, r.width, r.height,
      r.threads, r.repeats, r.embree ? "true" : "false");
  const Vec3 p = r.light.position;
  out += fmt::format("  \"light\": {{\"position\": [{}, {}, {}], \"from_scene\": {}}},\n", json_number(p.x),
                     json_number(p.y), json_number(p.z), r.light_from_scene ? "true" : "false");
  out += fmt::format("  \"build_ms\": {},\n  \"build_mprims_per_s\": {},\n  \"bytes_per_triangle\": {},\n",
                     figure_json(r.build_ms, r.embree), figure_json(r.build_mprims, r.embree),
                     figure_json(r.bytes_per_triangle, r.embree));
  out += fmt::format("  \"sah_cost\": {},\n  \"sets\": [", figure_json(r.sah_cost, r.embree));
  for (std::size_t i = 0; i < r.sets.size(); ++i) {
    const BenchSetReport& s = r.sets[i];
    out += fmt::format(
        "{}\n    {{\"name\": {}, \"query\": \"{}\", \"rays\": {}, \"answered\": {},\n     \"single\": "
        "{{\"mrays_per_s\": "
        "{}, \"agreement\": {}}}",
        i ? "," : "", json_string(s.name), s.closest ? "closest" : "any", s.rays, s.answered,
        figure_json(s.single_mrays, r.embree), r.embree ? agreement_json(s.single) : "null");
    out += s.packets ? fmt::format(",\n     \"packet16\": {{\"mrays_per_s\": {}, \"agreement\": {}}}}}",
                                   figure_json(s.packet_mrays, r.embree), agreement_json(s.packet))
                     : ",\n     \"packet16\": null}";
  }
  out += "\n  ],\n  \"notes\": [";
  for (std::size_t i = 0; i < r.notes.size(); ++i) out += (i ? ", " : "") + json_string(r.notes[i]);
  return out + "]\n}\n";
}

}  // namespace raylab
