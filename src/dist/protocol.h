#pragma once
// Internal to the dist module: the messages of a distributed render and their bytes.
//
//   worker -> 0: kHello (agreement, threads, host) once at the start;
//   0 -> worker: kJob, enough to keep the worker's threads busy while messages travel (see
//                Coordinator::jobs_to_hold), topped up as kResults come back;
//   worker -> 0: kResult per finished job; kHeartbeat every second; kReport when told kStop;
//                kFailed with the error if something throws; kInterrupted on a signal;
//   0 -> worker: kStop when every tile is in, kAbort when the run ends early.

#include <cstdint>
#include <string>
#include <vector>

#include "raylab/dist/distributed_render.h"
#include "raylab/render/tile_renderer.h"

namespace raylab::dist::protocol {

/// Message tags.
enum Tag : int {
  kHello = 1,
  kJob,
  kResult,
  kHeartbeat,
  kStop,
  kAbort,
  kReport,
  kFailed,
  kInterrupted,
  kFrame,       // frames mode: 0 -> worker, a frame number to render
  kFrameImage,  // frames mode: worker -> 0, a rendered frame
};

/// What a worker says first.
struct Hello {
  std::uint64_t agreement = 0;  ///< hash of the scene and settings it loaded
  std::uint32_t build = 0;      ///< sizeof checks: same program, same layout
  int threads = 0;              ///< its render threads
  std::string host;             ///< its machine
};

/// A number that differs between builds whose messages would not read the same.
std::uint32_t build_signature();

std::vector<std::uint8_t> encode(const Hello& hello);
Hello decode_hello(const std::vector<std::uint8_t>& bytes);

std::vector<std::uint8_t> encode(const TileJob& job, double seconds = 0.0);
/// A job (and, in a kResult, the seconds it took).
TileJob decode_job(const std::vector<std::uint8_t>& bytes, double* seconds = nullptr);

std::vector<std::uint8_t> encode(const RankReport& report);
RankReport decode_report(const std::vector<std::uint8_t>& bytes);

std::vector<std::uint8_t> encode_text(const std::string& text);
std::string decode_text(const std::vector<std::uint8_t>& bytes);

std::vector<std::uint8_t> encode_int(int value);
int decode_int(const std::vector<std::uint8_t>& bytes);

}  // namespace raylab::dist::protocol
