#include "protocol.h"

#include <type_traits>

#include "wire.h"

namespace raylab::dist::protocol {

static_assert(std::is_trivially_copyable_v<RenderStats>, "RankReport sends RenderStats as bytes");

std::uint32_t build_signature() {
  // The layouts the messages copy as bytes, and the byte order.
  const std::uint32_t one = 1;
  std::uint8_t first = 0;
  std::memcpy(&first, &one, 1);
  return static_cast<std::uint32_t>(sizeof(RenderStats) * 1000u + sizeof(Color) * 10u + first);
}

std::vector<std::uint8_t> encode(const Hello& hello) {
  wire::Writer w;
  w.put(hello.agreement).put(hello.build).put(hello.threads).put_string(hello.host);
  return w.take();
}

Hello decode_hello(const std::vector<std::uint8_t>& bytes) {
  wire::Reader r(bytes);
  Hello h;
  h.agreement = r.get<std::uint64_t>();
  h.build = r.get<std::uint32_t>();
  h.threads = r.get<int>();
  h.host = r.get_string();
  return h;
}

std::vector<std::uint8_t> encode(const TileJob& job, double seconds) {
  wire::Writer w;
  w.put(job.tile).put(job.first).put(job.end).put(seconds);
  w.put(job.sums.x0).put(job.sums.y0).put(job.sums.x1).put(job.sums.y1);
  w.put_vector(job.sums.sum).put_vector(job.sums.weight);
  return w.take();
}

TileJob decode_job(const std::vector<std::uint8_t>& bytes, double* seconds) {
  wire::Reader r(bytes);
  TileJob job;
  job.tile = r.get<int>();
  job.first = r.get<int>();
  job.end = r.get<int>();
  const auto took = r.get<double>();
  if (seconds != nullptr) *seconds = took;
  job.sums.x0 = r.get<int>();
  job.sums.y0 = r.get<int>();
  job.sums.x1 = r.get<int>();
  job.sums.y1 = r.get<int>();
  job.sums.sum = r.get_vector<Color>();
  job.sums.weight = r.get_vector<float>();
  return job;
}

std::vector<std::uint8_t> encode(const RankReport& report) {
  wire::Writer w;
  w.put(report.rank).put(report.threads).put(report.jobs).put(report.stats);
  w.put(report.busy_seconds).put(report.wall_seconds).put_string(report.host);
  return w.take();
}

RankReport decode_report(const std::vector<std::uint8_t>& bytes) {
  wire::Reader r(bytes);
  RankReport report;
  report.rank = r.get<int>();
  report.threads = r.get<int>();
  report.jobs = r.get<int>();
  report.stats = r.get<RenderStats>();
  report.busy_seconds = r.get<double>();
  report.wall_seconds = r.get<double>();
  report.host = r.get_string();
  return report;
}

std::vector<std::uint8_t> encode_text(const std::string& text) {
  wire::Writer w;
  w.put_string(text);
  return w.take();
}

std::string decode_text(const std::vector<std::uint8_t>& bytes) {
  wire::Reader r(bytes);
  return r.get_string();
}

std::vector<std::uint8_t> encode_int(int value) {
  wire::Writer w;
  w.put(value);
  return w.take();
}

int decode_int(const std::vector<std::uint8_t>& bytes) {
  wire::Reader r(bytes);
  return r.get<int>();
}

}  // namespace raylab::dist::protocol
