#include "packet_tracing.h"

#include <cassert>

namespace raylab::detail {

int packet_block_side(int spp) {
  if (spp <= 1) return 4;
  if (spp <= 4) return 2;
  return 1;
}

PrimaryPacketTracer::PrimaryPacketTracer(const TraceContext& ctx, bool replace_nonfinite)
    : m_ctx(ctx), m_replace_nonfinite(replace_nonfinite) {
  const std::vector<Light>& lights = ctx.scene.lights;
  for (std::size_t l = 0; l < lights.size(); ++l) {
    if (WhittedIntegrator::is_single_sample(lights[l])) m_single_lights.push_back(l);
  }
  m_answers.resize(kPacketSize * lights.size());
}

void PrimaryPacketTracer::trace(std::span<const Ray> rays, std::span<const std::uint64_t> seeds, std::span<Color> out) {
  assert(rays.size() <= kPacketSize && seeds.size() == rays.size() && out.size() == rays.size());
  const std::size_t n = rays.size();
  const Scene& scene = m_ctx.scene;
  std::copy(rays.begin(), rays.end(), m_rays.begin());
  std::fill_n(m_hits.begin(), n, Hit{});
  if (m_ctx.count_traversal) {
    for (std::size_t i = 0; i < n; ++i) m_ctx.accel.intersect_counted(m_rays[i], m_hits[i], m_ctx.stats.traversal);
  } else {
    m_ctx.accel.intersect(std::span<Ray>(m_rays.data(), n), std::span<Hit>(m_hits.data(), n));
  }
  // A lane hit something exactly when the accelerator filled its record (a miss leaves it as is).
  for (std::size_t i = 0; i < n; ++i) {
    const bool found = m_hits[i].valid();
    m_ctx.stats.count(RayKind::kPrimary, found);
    if (found) m_surfaces[i] = shading_surface_at(scene, m_rays[i], m_hits[i]);
  }
  // Once per hit: for every light's shadow ray and for shading.
  for (std::size_t i = 0; i < n; ++i) {
    if (m_hits[i].valid()) m_points[i] = WhittedIntegrator::shading_point(m_surfaces[i], m_ctx.shadow_facing);
  }

  const std::size_t light_count = scene.lights.size();
  // Only the answers: a sample is read only where its answer is decided.
  for (std::size_t k = 0; k < n * light_count; ++k) m_answers[k].answer = ShadowAnswer::kTrace;
  for (std::size_t light : m_single_lights) trace_shadows(light, n);

  for (std::size_t i = 0; i < n; ++i) {
    if (!m_hits[i].valid()) {
      out[i] = handed_on(WhittedIntegrator::background(scene.settings, m_rays[i].direction));
      continue;
    }
    Pcg32 rng(seeds[i]);
    const std::span<const DecidedShadow> answers(m_answers.data() + i * light_count, light_count);
    out[i] = handed_on(WhittedIntegrator::shade(m_ctx, m_rays[i], m_surfaces[i], m_points[i], 1, rng, answers));
  }
}

void PrimaryPacketTracer::trace_shadows(std::size_t light, std::size_t lanes) {
  const Light& l = m_ctx.scene.lights[light];
  const std::size_t light_count = m_ctx.scene.lights.size();
  std::size_t count = 0;
  for (std::size_t i = 0; i < lanes; ++i) {
    if (!m_hits[i].valid()) continue;
    if (!WhittedIntegrator::single_sample_shadow_ray(l, m_points[i], m_shadow_rays[count],
                                                     m_answers[i * light_count + light].sample)) {
      continue;
    }
    m_shadow_lane[count++] = static_cast<std::uint8_t>(i);
  }
  if (count == 0) return;
  if (m_ctx.count_traversal) {
    for (std::size_t k = 0; k < count; ++k) {
      m_blocked[k] = m_ctx.accel.occluded_counted(m_shadow_rays[k], m_ctx.stats.traversal) ? 1 : 0;
    }
  } else {
    m_ctx.accel.occluded(std::span<const Ray>(m_shadow_rays.data(), count),
                         std::span<std::uint8_t>(m_blocked.data(), count));
  }
  for (std::size_t k = 0; k < count; ++k) {
    const bool blocked = m_blocked[k] != 0;
    m_ctx.stats.count(RayKind::kShadow, blocked);
    m_answers[m_shadow_lane[k] * light_count + light].answer =
        blocked ? ShadowAnswer::kBlocked : ShadowAnswer::kVisible;
  }
}

TilePacketTracer::TilePacketTracer(const TraceContext& ctx, const Camera& camera, const PixelSampler& sampler,
                                   int first_sample, int end_sample)
    : m_camera(camera), m_sampler(sampler), m_first_sample(first_sample), m_end_sample(end_sample), m_tracer(ctx) {}

std::vector<PixelRect> TilePacketTracer::units(const PixelRect& tile) const {
  std::vector<PixelRect> out;
  if (sample_count() >= kPacketSize) {
    for (int py = tile.y0; py < tile.y1; ++py) {
      for (int px = tile.x0; px < tile.x1; ++px) out.push_back({px, py, px + 1, py + 1});
    }
    return out;
  }
  const int side = packet_block_side(sample_count());
  for (int y = tile.y0; y < tile.y1; y += side) out.push_back({tile.x0, y, tile.x1, std::min(y + side, tile.y1)});
  return out;
}

void TilePacketTracer::trace_unit(const PixelRect& unit) {
  const int count = sample_count();
  const int side = packet_block_side(count);
  const int width = unit.x1 - unit.x0;
  m_colors.resize(std::size_t(width) * (unit.y1 - unit.y0) * count);
  // Blocks left to right; within a block, pixels row-major and each pixel's samples in order. A
  // packet takes the next kPacketSize samples of that sequence, so it may span two blocks.
  for (int bx = unit.x0; bx < unit.x1; bx += side) {
    for (int py = unit.y0; py < unit.y1; ++py) {
      for (int px = bx; px < std::min(bx + side, unit.x1); ++px) {
        for (int i = m_first_sample; i < m_end_sample; ++i) {
          const Sample2 u = m_sampler.sample(px, py, i);
          m_rays[m_count] = m_camera.generate(static_cast<float>(px) + u.x, static_cast<float>(py) + u.y);
          m_seeds[m_count] = sample_path_seed(m_sampler.seed(), px, py, i);
          m_slots[m_count] = (std::size_t(py - unit.y0) * width + (px - unit.x0)) * count + (i - m_first_sample);
          if (++m_count == kPacketSize) flush();
        }
      }
    }
  }
  flush();
}

void TilePacketTracer::flush() {
  if (m_count == 0) return;
  const std::size_t n = static_cast<std::size_t>(m_count);
  m_tracer.trace(std::span<const Ray>(m_rays.data(), n), std::span<const std::uint64_t>(m_seeds.data(), n),
                 std::span<Color>(m_out.data(), n));
  for (std::size_t k = 0; k < n; ++k) m_colors[m_slots[k]] = m_out[k];
  m_count = 0;
}

}  // namespace raylab::detail
